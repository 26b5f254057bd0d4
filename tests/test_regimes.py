"""Motion from given initial conditions (issue 18 item 1): graphmethods.dynamics.regimes.run
against closed forms, the energy form, and the periodic motion found by the toolkit's own study."""

import math

import numpy as np
import pytest

from graphmethods.dynamics.motion import ReducedModel, periodic_motion
from graphmethods.dynamics.motor import DCMotor, InductionMotor, motor_motion
from graphmethods.dynamics.regimes import Brake, ConstantDrive, run
from graphmethods.errors import InputError, MotionError
from graphmethods.problems import w4_exact


def test_gear_train_exercise_constant_moment_and_inertia():
    # J_e = 0.025 kg·m², M_e = 30 N·m from rest: ε = M/J = 1200 s⁻², ω = εt = 1800 s⁻¹ at 1.5 s
    r = run(ReducedModel(J_e=0.025, M_e=30.0), omega_0=0.0, t_end=1.5)
    assert r.ended_by == "t_end" and r.t[-1] == pytest.approx(1.5, rel=1e-15)
    np.testing.assert_allclose(r.epsilon, 1200.0, rtol=1e-12)
    np.testing.assert_allclose(r.omega, 1200.0 * r.t, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(r.phi, 600.0 * r.t**2, rtol=1e-12, atol=1e-12)      # φ = εt²/2
    assert r.omega[-1] == pytest.approx(1800.0, rel=1e-12)
    assert r.energy_residual < 1e-12


@pytest.mark.parametrize("omega_0, M_r", [(0.0, 0.0), (0.0, 30.0), (60.0, 30.0)])
def test_moment_linear_in_speed_approaches_its_limit_exponentially(omega_0, M_r):
    # J dω/dt = M_0(1 − ω/ω_n) − M_r: ω = ω_∞ + (ω0 − ω_∞) e^(−t/τ), τ = J/k, k = M_0/ω_n
    J, M0, wn = 2.0, 100.0, 50.0
    k = M0 / wn
    w_inf, tau = (M0 - M_r) / k, J / k
    r = run(ReducedModel(J_e=J, M_e=-M_r), drive=DCMotor(M_0=M0, omega_0=wn), omega_0=omega_0, t_end=5.0)
    exact = w_inf + (omega_0 - w_inf) * np.exp(-r.t / tau)
    err = np.abs(r.omega - exact).max()
    assert err < 1e-8 * w_inf
    assert err <= r.error_estimate                     # the reported estimate bounds the true error
    assert r.energy_residual < 1e-9


def test_time_to_steady_state_of_the_exponential_approach():
    J, M0, wn, tol = 2.0, 100.0, 50.0, 1e-3
    r = run(ReducedModel(J_e=J, M_e=-30.0), drive=DCMotor(M_0=M0, omega_0=wn), until_steady=True, tol=tol)
    st = r.steady
    tau = J * wn / M0
    assert r.ended_by == "steady"
    assert st.t_steady == pytest.approx(tau * math.log(1 / tol), rel=1e-6)     # |ω − ω_∞| = ω_∞ e^(−t/τ)
    assert st.omega_m == pytest.approx(35.0, rel=1e-8) and st.delta < 1e-8
    for mean in (st.omega_m_time, st.omega_m_integral):
        assert mean == pytest.approx(35.0, rel=1e-8)


def test_W4_speeds_at_the_quarter_points_from_omega_0():
    # domain.md §9 W4: J_e = 0.8, M_d = 20, triangular M_r; with exact π the areas are ±5π, so
    # ω = sqrt(ω0² + 2ΔE/J) = 10, 11.80, 10, 7.79, 10 (the lecture's π ≈ 3 drawing gives 11.73, 7.91)
    p = w4_exact()
    D = p.M_d - p.M_r
    model = ReducedModel(J_e=p.J_e, M_e=lambda x: D(x), breaks=(math.pi,))
    r = run(model, omega_0=p.omega_0, turns=2)
    quarters = np.array([0.0, 0.5, 1.0, 1.5, 2.0]) * math.pi
    at = r.at_phi(quarters)
    dE = np.array([0.0, 5 * math.pi, 0.0, -5 * math.pi, 0.0])
    np.testing.assert_allclose(at["omega"], np.sqrt(100 + 2 * dE / 0.8), rtol=1e-9)
    assert at["omega"][1] == pytest.approx(11.80, abs=0.005) and at["omega"][3] == pytest.approx(7.79, abs=0.005)
    # t(φ) against the energy form t = ∫ dφ/ω (composite Gauss–Legendre on each quarter)
    x, w = np.polynomial.legendre.leggauss(40)
    t_exact = [0.0]
    for a, b in zip(quarters[:-1], quarters[1:]):
        phi = 0.5 * (b - a) * x + 0.5 * (a + b)
        om = np.sqrt(100 + 2 * D.integral(phi) / 0.8)
        t_exact.append(t_exact[-1] + 0.5 * (b - a) * float(np.sum(w / om)))
    np.testing.assert_allclose(at["t"], t_exact, rtol=1e-9, atol=1e-12)
    # ω along the whole run from the energy form, on both turns
    phase = np.mod(r.phi, 2 * math.pi)
    np.testing.assert_allclose(r.omega, np.sqrt(100 + 2 * D.integral(phase) / 0.8), rtol=1e-8)
    assert r.energy_residual < 1e-9


def test_steady_state_from_rest_equals_the_periodic_solution_of_the_motor_study():
    m = InductionMotor(P_nom=4000.0, n_nom=1430.0, n_sync=1500.0, lam=2.0, ratio=5.0)
    model = ReducedModel(J_e=lambda p: 2.0 + 0.5 * np.cos(2 * p), M_e=lambda p: -40.0 * (1 + np.sin(p) ** 2),
                         dJ_e=lambda p: -np.sin(2 * p))
    ref = motor_motion(model, m, J_F=3.0, steps=7200)
    r = run(model, J_F=3.0, drive=m, omega_0=0.0, until_steady=True)
    st = r.steady
    assert r.ended_by == "steady" and st.t_steady > 0
    assert st.omega_max == pytest.approx(ref.omega_max, rel=1e-6)
    assert st.omega_min == pytest.approx(ref.omega_min, rel=1e-6)
    assert st.omega_m_time == pytest.approx(ref.omega_m_time, rel=1e-6)
    assert st.delta == pytest.approx(ref.delta, rel=1e-5)
    assert r.energy_residual < 1e-8
    # the three means differ only by the shape of ω(φ), each the stated definition
    assert st.omega_m_textbook == pytest.approx(0.5 * (st.omega_max + st.omega_min))


def test_steady_running_with_position_loads_is_the_exact_periodic_motion():
    # a constant M_d balancing M_r: the motion through position 0 at ω_0 is periodic at once
    model = ReducedModel(J_e=lambda p: 1.0 + 0.1 * np.cos(2 * p), M_e=lambda p: 50 * np.sin(p),
                         dJ_e=lambda p: -0.2 * np.sin(2 * p))
    per = periodic_motion(model, J_F=4.0, omega_m=20.0)
    omega_0 = float(per.omega[0])
    r = run(model, J_F=4.0, omega_0=omega_0, until_steady=True)
    assert r.steady.omega_max == pytest.approx(per.omega_max, rel=1e-9)
    assert r.steady.omega_min == pytest.approx(per.omega_min, rel=1e-9)
    assert r.steady.t_T == pytest.approx(per.t_T, rel=1e-9)
    assert r.steady.t_steady == 0.0


def test_run_down_with_a_brake_stops_at_the_closed_form_time():
    # J dω/dt = −M_b − cω from ω0 with the drive off: t_stop = (J/c) ln(1 + cω0/M_b)
    J, Mb, c, w0 = 3.0, 40.0, 2.0, 25.0
    r = run(ReducedModel(J_e=J, M_e=0.0), drive=ConstantDrive(10.0), drive_off_at=0.0,
            brake=Brake(M_b=Mb, c=c), omega_0=w0, t_end=100.0)
    assert r.ended_by == "stopped" and r.omega[-1] == 0.0
    assert r.t[-1] == pytest.approx(J / c * math.log(1 + c * w0 / Mb), rel=1e-9)
    assert r.T[0] + r.work[-1] == pytest.approx(0.0, abs=1e-8 * r.T[0])          # all energy taken by the brake


def test_drive_switched_off_mid_run_then_coasting_down():
    J, M0, wn = 2.0, 100.0, 50.0
    r = run(ReducedModel(J_e=J, M_e=-20.0), drive=DCMotor(M_0=M0, omega_0=wn), drive_off_at=1.0, t_end=50.0)
    w1 = 40.0 * (1 - math.exp(-1.0 / (J * wn / M0)))              # ω_∞ = 50(1 − 20/100) = 40
    on = r.at_time([1.0])
    assert on["omega"][0] == pytest.approx(w1, rel=1e-9)
    assert r.ended_by == "stopped" and r.t[-1] == pytest.approx(1.0 + J * w1 / 20.0, rel=1e-9)


def test_turns_end_exactly_on_the_angle():
    r = run(ReducedModel(J_e=0.5, M_e=lambda p: 5 + 2 * np.sin(p)), omega_0=3.0, turns=2.5)
    assert r.ended_by == "turns" and r.phi[-1] == pytest.approx(5 * math.pi, rel=1e-14)


def test_bad_starts_are_refused():
    with pytest.raises(MotionError, match="cannot start"):
        run(ReducedModel(J_e=1.0, M_e=-5.0), omega_0=0.0, t_end=1.0)
    with pytest.raises(InputError, match="when to stop"):
        run(ReducedModel(J_e=1.0, M_e=5.0))
    with pytest.raises(InputError, match="omega_0"):
        run(ReducedModel(J_e=1.0, M_e=5.0), omega_0=-1.0, t_end=1.0)
    with pytest.raises(InputError, match="Brake"):
        Brake(M_b=-1.0)
