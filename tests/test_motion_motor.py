"""Speed-dependent driving moments and the steady motion they drive (graphmethods.dynamics.motor)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphmethods.dynamics.motion import ReducedModel, periodic_motion
from graphmethods.dynamics.motor import DCMotor, InductionMotor, motor_motion
from graphmethods.errors import InputError, MotionError
from graphmethods.units import omega_from_n

# ---- characteristics ---------------------------------------------------------------------------

def test_dc_motor_line_and_its_inverse():
    m = DCMotor(M_0=300.0, omega_0=150.0, ratio=3.0)
    # on the reduced shaft: M_d(ω) = 3 · 300 (1 − 3ω/150)
    assert m(0.0) == pytest.approx(900.0)
    assert m(50.0) == pytest.approx(0.0)
    assert m.M_max == 900.0
    for M in (0.0, 123.4, 899.0):
        assert m(m.omega_at(M)) == pytest.approx(M)


def test_kloss_characteristic_passes_through_rated_and_breakdown_points():
    m = InductionMotor(P_nom=11000.0, n_nom=1460.0, n_sync=1500.0, lam=2.5)
    w_nom = omega_from_n(1460.0)
    assert m.M_nom == pytest.approx(11000.0 / w_nom)
    assert m(w_nom) == pytest.approx(m.M_nom, rel=1e-12)
    w_k = (1 - m.s_k) * m.omega_sync
    assert m(w_k) == pytest.approx(2.5 * m.M_nom, rel=1e-12)
    assert m(m.omega_sync) == 0.0
    # the breakdown torque is the maximum; the formula is odd in s (generator side)
    s = np.linspace(-1, 1, 20001)
    M = m((1 - s) * m.omega_sync)
    assert M.max() == pytest.approx(m.M_k, rel=1e-6)
    assert m((1 + 0.01) * m.omega_sync) == pytest.approx(-m((1 - 0.01) * m.omega_sync))
    for M in (-40.0, 0.0, 20.0, m.M_nom, 0.99 * m.M_k):
        w = m.omega_at(M)
        assert m(w) == pytest.approx(M, abs=1e-9)
        assert abs(1 - w / m.omega_sync) <= m.s_k                    # stable branch


def test_kloss_from_the_rated_slip_equals_from_the_synchronous_speed():
    a = InductionMotor(P_nom=4000.0, n_nom=1425.0, n_sync=1500.0, lam=2.0)
    b = InductionMotor(P_nom=4000.0, n_nom=1425.0, s_nom=0.05, lam=2.0)
    assert a.s_k == pytest.approx(b.s_k) and a.omega_sync == pytest.approx(b.omega_sync)
    assert a.s_k == pytest.approx(0.05 * (2 + math.sqrt(3)))


@pytest.mark.parametrize("kwargs, match", [
    (dict(P_nom=1.0, n_nom=1500.0, n_sync=1500.0, lam=2.0), "below the synchronous"),
    (dict(P_nom=1.0, n_nom=1400.0, n_sync=1500.0, lam=0.9), "exceed 1"),
    (dict(P_nom=1.0, n_nom=1400.0, lam=2.0), "exactly one"),
    (dict(P_nom=-1.0, n_nom=1400.0, n_sync=1500.0, lam=2.0), "P_nom"),
])
def test_bad_motor_data_is_refused(kwargs, match):
    with pytest.raises(InputError, match=match):
        InductionMotor(**kwargs)


# ---- steady motion -----------------------------------------------------------------------------

def test_constant_load_runs_at_the_characteristic_speed():
    m = DCMotor(M_0=400.0, omega_0=40.0)
    res = motor_motion(ReducedModel(J_e=2.0, M_e=-150.0), m, J_F=1.0)
    assert res.omega_m == pytest.approx(40 * (1 - 150 / 400), rel=1e-12)
    assert res.delta == pytest.approx(0.0, abs=1e-12)
    assert res.multiplier < 1


def test_dc_motor_small_fluctuation_against_the_linearised_solution():
    # J ω̄ u' = −k u − A sin φ with k = M_0/ω_0: u = C1 sin φ + C2 cos φ
    M0, w0, J, Mbar, A = 400.0, 40.0, 6.0, 200.0, 2.0
    res = motor_motion(ReducedModel(J_e=J, M_e=lambda p: -Mbar - A * np.sin(p)),
                       DCMotor(M_0=M0, omega_0=w0), J_F=0.0)
    wb, k = w0 * (1 - Mbar / M0), M0 / w0
    den = (J * wb) ** 2 + k**2
    lin = wb - A * k / den * np.sin(res.phi) + A * J * wb / den * np.cos(res.phi)
    np.testing.assert_allclose(res.omega, lin, atol=1e-5)
    assert res.delta == pytest.approx(2 * A / math.sqrt(den) / wb, rel=1e-5)
    # u = R cos(φ − φ*) with tan φ* = C1/C2: ω_max lags the load's zero crossing at φ = 0
    assert math.degrees(res.phi_omega_max) == pytest.approx(
        math.degrees(math.atan2(-A * k / den, A * J * wb / den)) % 360, abs=0.1)


def test_a_nearly_constant_torque_motor_reproduces_the_position_dependent_solution():
    # M_d ≈ const when the characteristic is very flat: the motion then approaches the exact
    # solution with M_d constant (at the speed the motor settles to).
    A = 80.0
    J_e = lambda p: 3.0 + 0.8 * np.cos(2 * p)                                   # noqa: E731
    flat = DCMotor(M_0=100.0 / (1 - 1e-3), omega_0=20.0e3)    # M_d(20) = 100, dM/dω ≈ −0.005
    res = motor_motion(ReducedModel(J_e=J_e, M_e=lambda p: -100.0 - A * np.sin(p)), flat, J_F=5.0)
    exact = periodic_motion(ReducedModel(J_e=J_e, M_e=lambda p: -A * np.sin(p)), J_F=5.0,
                            omega_m=res.omega_m)
    assert res.delta == pytest.approx(exact.delta, rel=2e-3)
    np.testing.assert_allclose(res.omega, exact.omega, rtol=2e-5)


def test_rk4_converges_at_fourth_order_and_the_state_is_periodic():
    model = ReducedModel(J_e=lambda p: 6.0 + np.cos(p), M_e=lambda p: -200 - 50 * np.sin(3 * p))
    m = DCMotor(M_0=400.0, omega_0=40.0)
    errs = []
    ref = motor_motion(model, m, J_F=0.0, steps=2880, positions=36)
    for steps in (72, 144, 288):
        r = motor_motion(model, m, J_F=0.0, steps=steps, positions=36)
        errs.append(np.max(np.abs(r.omega - ref.omega)))
    assert errs[0] / errs[1] > 12 and errs[1] / errs[2] > 12
    assert ref.omega[-1] == pytest.approx(ref.omega[0], rel=1e-13)
    assert ref.accuracy < 1e-12


def test_press_driven_by_an_induction_motor_through_a_gear():
    from test_motion_press import press_model

    p = press_model()
    model = ReducedModel(J_e=p.model.J_e, M_e=lambda x: p.model.M_e_at(x) - p.M_d,
                         phi_0=p.phi_0, breaks=p.model.breaks)
    motor = InductionMotor(P_nom=5500.0, n_nom=1440.0, n_sync=1500.0, lam=2.2, ratio=1440 / 300)
    res = motor_motion(model, motor, J_F=13.94)
    # the motor gives the mean load torque at the mean speed, near its rated speed through the gear
    assert res.omega_m_time == pytest.approx(motor.omega_at(p.M_d), rel=2e-3)
    assert 0 < res.delta < 0.04                      # a soft motor helps the flywheel
    assert res.multiplier < 1
    assert res.T[-1] == pytest.approx(res.T[0], rel=1e-12)
    assert res.accuracy < 1e-8
    assert res.method == "rk4"


def test_a_motor_too_weak_for_the_load_is_a_clear_error():
    m = DCMotor(M_0=100.0, omega_0=50.0)
    with pytest.raises(MotionError, match=r"cannot be sustained.*at most 628\.3.* short by 314\.1"):
        motor_motion(ReducedModel(J_e=1.0, M_e=-150.0), m, J_F=1.0)


def test_a_load_peak_that_stops_the_machine_is_a_clear_error():
    # mean load is within the motor's reach, but the peak is huge and the inertia tiny
    m = DCMotor(M_0=400.0, omega_0=40.0)
    model = ReducedModel(J_e=0.001, M_e=lambda p: -100.0 - 5000.0 * np.sin(p))
    with pytest.raises(MotionError, match="stops"):
        motor_motion(model, m, J_F=0.0)


def test_bad_motor_arguments():
    m = DCMotor(M_0=100.0, omega_0=50.0)
    with pytest.raises(InputError, match="multiple of positions"):
        motor_motion(ReducedModel(J_e=1.0, M_e=-10.0), m, J_F=1.0, steps=1000, positions=360)
    with pytest.raises(InputError, match="motor"):
        motor_motion(ReducedModel(J_e=1.0, M_e=-10.0), lambda w: 5.0, J_F=1.0)
