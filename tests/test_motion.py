"""The exact periodic motion solver and the exact flywheel (graphmethods.dynamics.motion)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.dynamics.motion import ReducedModel, exact_flywheel, periodic_motion
from graphmethods.errors import GraphmethodsError, InputError, MotionError


def sinusoid_model(A=300.0, B=120.0, J0=2.0, J1=0.6, J2=0.25):
    """M_e = A cos φ + B sin 2φ (ΔE = A sin φ + B (1 − cos 2φ)/2), J_e = J0 + J1 cos φ + J2 sin 2φ."""
    model = ReducedModel(J_e=lambda p: J0 + J1 * np.cos(p) + J2 * np.sin(2 * p),
                         M_e=lambda p: A * np.cos(p) + B * np.sin(2 * p),
                         dJ_e=lambda p: -J1 * np.sin(p) + 2 * J2 * np.cos(2 * p))
    delta_E = lambda p: A * np.sin(p) + B * (1 - np.cos(2 * p)) / 2          # noqa: E731
    return model, delta_E


def dense_flywheel(J_e, delta_E, omega_m, delta, n=4_000_001, phi_0=0.0):
    phi = phi_0 + np.linspace(0, 2 * np.pi, n)
    E, J = delta_E(phi), J_e(phi)
    a_max, a_min = 0.5 * (omega_m * (1 + delta / 2)) ** 2, 0.5 * (omega_m * (1 - delta / 2)) ** 2
    g1, g2 = E - a_max * J, E - a_min * J
    return (g1.max() - g2.min()) / (delta * omega_m**2), phi[np.argmax(g1)], phi[np.argmin(g2)]


# ---- the input ---------------------------------------------------------------------------------

def test_constant_inputs_become_functions():
    model = ReducedModel(J_e=3.0, M_e=0.0)
    assert model.J_e_at(np.array([0.0, 1.0])).tolist() == [3.0, 3.0]
    assert model.dJ_e_at(np.array([0.5])).tolist() == [0.0]


def test_samples_linear_step_and_cubic():
    J = [1.0, 2.0, 3.0, 2.0, 1.0]
    lin = ReducedModel.from_samples(J_e=J, M_e=[0, 1, 0, -1, 0])
    assert float(lin.J_e_at(np.pi / 4)) == pytest.approx(1.5)
    assert float(lin.dJ_e_at(np.pi / 4)) == pytest.approx(1 / (np.pi / 2))
    step = ReducedModel.from_samples(J_e=J, M_e=[5, 6, 7, 8, 99], M_e_interpolation="step")
    assert step.M_e_at(np.array([0.1, 1.7, 3.2, 6.0])).tolist() == [5, 6, 7, 8]
    phi = np.linspace(0, 2 * np.pi, 25)
    cub = ReducedModel.from_samples(J_e=2 + np.cos(phi), M_e=np.sin(phi), interpolation="cubic")
    x = np.linspace(0, 2 * np.pi, 101)
    np.testing.assert_allclose(cub.J_e_at(x), 2 + np.cos(x), atol=2e-4)
    np.testing.assert_allclose(cub.dJ_e_at(x), -np.sin(x), atol=3e-3)
    np.testing.assert_allclose(cub.J_e_at(phi), 2 + np.cos(phi), atol=1e-13)   # interpolates


def test_sampled_model_flywheel_matches_the_piecewise_linear_closed_form():
    # M_e linear between samples, J_e constant: ΔE is piecewise quadratic; the solver must find
    # the exact extremes of that interpolant, not of the samples.
    M = [0.0, 100.0, 0.0, -100.0, 0.0]
    model = ReducedModel.from_samples(J_e=1.0, M_e=M)
    fw = exact_flywheel(model, omega_m=10.0, delta=0.1)
    # ΔE rises by the triangle area 100·π/2 up to φ = π, then falls: ΔW_max = 50 π
    assert fw.J_F == pytest.approx(50 * np.pi / (100 * 0.1) - 1.0, rel=1e-12)
    assert fw.phi_omega_max == pytest.approx(np.pi, abs=1e-7)


@pytest.mark.parametrize("bad, match", [
    (dict(J_e=lambda p: -1.0 + 0 * p, M_e=0.0), "negative"),
    (dict(J_e=1.0, M_e=lambda p: np.where(p > 1, 0.0, np.nan)), "not finite"),
    (dict(J_e=1.0, M_e=lambda p: math.sin(p)), "vectorised"),
    (dict(J_e=1.0, M_e=0.0, phi_T=-1.0), "positive"),
    (dict(J_e="heavy", M_e=0.0), "function of φ"),
])
def test_bad_models_are_refused_with_a_message(bad, match):
    with pytest.raises(InputError, match=match):
        ReducedModel(**bad)


def test_bad_arguments_are_refused():
    model, _ = sinusoid_model()
    with pytest.raises(InputError, match="delta"):
        exact_flywheel(model, omega_m=10.0, delta=2.5)
    with pytest.raises(InputError, match="omega_m"):
        exact_flywheel(model, omega_m=-1.0, delta=0.1)
    with pytest.raises(InputError, match="mean"):
        periodic_motion(model, J_F=5.0, omega_m=10.0, mean="median")


# ---- closed forms ------------------------------------------------------------------------------

def test_constant_J_e_against_the_closed_form():
    # J_F = ΔW_max/(ω_m² δ) − J_e, exact because ω_max² − ω_min² = 2δω_m² exactly.
    model = ReducedModel(J_e=1.5, M_e=lambda p: 200 * np.cos(p) + 50 * np.cos(3 * p))
    # ΔE = 200 sin φ + (50/3) sin 3φ; extremes at φ = π/2 (ΔE = 200 − 50/3) and 3π/2
    dW = 2 * (200 - 50 / 3)
    fw = exact_flywheel(model, omega_m=30.0, delta=0.02)
    assert fw.J_F == pytest.approx(dW / (900 * 0.02) - 1.5, rel=1e-12)
    assert fw.phi_omega_max == pytest.approx(np.pi / 2, abs=1e-7)
    assert fw.phi_omega_min == pytest.approx(3 * np.pi / 2, abs=1e-7)


def test_worked_example_W3_step_resisting_moment():
    # domain.md §9 W3: M_r = 60 on [0, π/4), 10 after; M_d = 16.25; n = 100 rev/min; [δ] = 0.05
    M_e = lambda p: 16.25 - np.where(p < np.pi / 4, 60.0, 10.0)              # noqa: E731
    model = ReducedModel(J_e=0.0, M_e=M_e)                                      # jump not declared
    fw = exact_flywheel(model, omega_m=100 * np.pi / 30, delta=0.05)
    assert fw.J_F == pytest.approx(6.266725884243379, rel=1e-10)
    assert fw.b_max - fw.b_min == pytest.approx(34.36116964863836, rel=1e-10)
    assert fw.phi_omega_min == pytest.approx(np.pi / 4, abs=1e-9)


def test_sinusoids_against_a_dense_brute_force():
    model, dE = sinusoid_model()
    fw = exact_flywheel(model, omega_m=12.0, delta=0.05)
    J_bf, p1, p2 = dense_flywheel(model.J_e_at, dE, 12.0, 0.05)
    assert fw.J_F == pytest.approx(J_bf, rel=1e-9)
    assert fw.phi_omega_max == pytest.approx(p1, abs=1e-5)
    assert fw.phi_omega_min == pytest.approx(p2, abs=1e-5)
    assert fw.rel_accuracy < 1e-8


def test_given_flywheel_reproduces_the_prescribed_delta_both_ways():
    model, _ = sinusoid_model()
    fw = exact_flywheel(model, omega_m=12.0, delta=0.05)
    assert fw.delta_check == pytest.approx(0.05, rel=1e-10)
    assert fw.motion.T0 == pytest.approx(fw.T0, rel=1e-10)
    mo = periodic_motion(model, J_F=2 * fw.J_F, omega_m=12.0)
    assert mo.delta < 0.05
    back = exact_flywheel(model, omega_m=12.0, delta=mo.delta)
    assert back.J_F == pytest.approx(2 * fw.J_F, rel=1e-10)


def test_time_mean_option():
    model, _ = sinusoid_model()
    fw = exact_flywheel(model, omega_m=12.0, delta=0.05, mean="time")
    mo = fw.motion
    assert mo.mean == "time"
    assert 2 * np.pi / mo.t_T == pytest.approx(12.0, rel=1e-12)
    assert (mo.omega_max - mo.omega_min) / 12.0 == pytest.approx(0.05, rel=1e-9)
    textbook = exact_flywheel(model, omega_m=12.0, delta=0.05)
    assert fw.J_F != pytest.approx(textbook.J_F, rel=1e-6)      # the definitions do differ ...
    assert fw.J_F == pytest.approx(textbook.J_F, rel=0.02)      # ... by O(δ)


def test_time_and_epsilon_by_independent_integration():
    model, dE = sinusoid_model()
    mo = periodic_motion(model, J_F=10.0, omega_m=12.0, positions=720)
    J = 10.0 + model.J_e_at(mo.phi)
    omega = np.sqrt(2 * (mo.T0 + dE(mo.phi)) / J)
    np.testing.assert_allclose(mo.omega, omega, rtol=1e-12)
    # t by Simpson on a much finer grid
    x = np.linspace(0, 2 * np.pi, 200_001)
    f = 1 / np.sqrt(2 * (mo.T0 + dE(x)) / (10.0 + model.J_e_at(x)))
    t_T = (x[1] - x[0]) / 3 * (f[0] + f[-1] + 4 * f[1:-1:2].sum() + 2 * f[2:-1:2].sum())
    assert mo.t_T == pytest.approx(t_T, rel=1e-12)
    eps = (model.M_e_at(mo.phi) - 0.5 * omega**2 * model.dJ_e_at(mo.phi)) / J
    np.testing.assert_allclose(mo.epsilon, eps, rtol=1e-10, atol=1e-9)
    assert abs(mo.epsilon_max) >= np.abs(mo.epsilon).max()


def test_period_other_than_one_turn_and_shifted_origin():
    # a four-stroke-like period 4π, position 0 at φ = 1 rad
    M_e = lambda p: 100 * np.sin(p / 2)                                    # noqa: E731
    model = ReducedModel(J_e=3.0, M_e=M_e, phi_T=4 * np.pi, phi_0=1.0)
    fw = exact_flywheel(model, omega_m=20.0, delta=0.1)
    # ΔE = −200 (cos(φ/2) − cos(1/2)): range 400
    assert fw.J_F == pytest.approx(400 / (400 * 0.1) - 3.0, rel=1e-12)
    assert fw.phi_omega_max == pytest.approx(2 * np.pi, abs=1e-7)
    assert 0 <= fw.phi_omega_max_from_0 < 4 * np.pi


# ---- errors ------------------------------------------------------------------------------------

def test_driving_work_less_than_resisting_is_a_clear_error():
    # M_d = 10 N·m over 2π (62.83 J), M_r = 25 N·m over π (78.54 J): short by 5π = 15.708 J
    model = ReducedModel(J_e=1.0, M_e=lambda p: 10.0 - 25.0 * (p < np.pi))
    with pytest.raises(MotionError, match=r"cannot be sustained.*less than the resisting work by 15\.70"):
        exact_flywheel(model, omega_m=10.0, delta=0.05)


def test_driving_work_exceeding_resisting_is_an_error_too():
    model = ReducedModel(J_e=1.0, M_e=lambda p: 5.0 + np.cos(p))
    with pytest.raises(MotionError, match="speeds up every cycle"):
        periodic_motion(model, J_F=1.0, omega_m=10.0)


def test_a_small_closure_residual_is_removed_and_reported():
    model = ReducedModel(J_e=1.0, M_e=lambda p: 100 * np.cos(p) + 1e-7)
    fw = exact_flywheel(model, omega_m=10.0, delta=0.05)
    assert fw.closure_residual == pytest.approx(2e-7 * np.pi, rel=1e-6)
    assert fw.J_F == pytest.approx(200 / 5 - 1, rel=1e-9)


def test_flywheel_too_small_for_the_mean_speed():
    model = ReducedModel(J_e=1.0, M_e=lambda p: 1000 * np.cos(p))
    with pytest.raises(MotionError, match="increase J_F"):
        periodic_motion(model, J_F=0.0, omega_m=1.0)


def test_negative_total_inertia_is_refused():
    model = ReducedModel(J_e=1.0, M_e=lambda p: np.cos(p))
    with pytest.raises(MotionError, match="positive"):
        periodic_motion(model, J_F=-2.0, omega_m=10.0)


def test_errors_share_the_project_base_class():
    assert issubclass(MotionError, GraphmethodsError)


# ---- invariants --------------------------------------------------------------------------------

coef = st.floats(min_value=-1.0, max_value=1.0, allow_nan=False)


@settings(deadline=None, max_examples=12)
@given(a=coef, b=coef, c=coef, shift=st.floats(min_value=-3.0, max_value=3.0),
       delta=st.floats(min_value=0.005, max_value=0.5))
def test_flywheel_does_not_depend_on_where_position_0_is(a, b, c, shift, delta):
    def parts(s):
        J = lambda p: 2.0 + 0.5 * a * np.cos(p - s) + 0.3 * c * np.sin(2 * (p - s))  # noqa: E731
        M = lambda p: 100 * (np.cos(p - s) + b * np.sin(3 * (p - s)))                # noqa: E731
        return J, M
    J0, M0 = parts(0.0)
    J1, M1 = parts(shift)
    f0 = exact_flywheel(ReducedModel(J_e=J0, M_e=M0), omega_m=15.0, delta=delta, positions=12)
    f1 = exact_flywheel(ReducedModel(J_e=J1, M_e=M1, phi_0=shift), omega_m=15.0, delta=delta,
                        positions=12)
    assert f1.J_F == pytest.approx(f0.J_F, rel=1e-9)
    assert f1.phi_omega_max_from_0 == pytest.approx(f0.phi_omega_max_from_0, abs=1e-5)
    assert f1.delta_check == pytest.approx(delta, rel=1e-9)


@settings(deadline=None, max_examples=12)
@given(a=coef, b=coef, k=st.floats(min_value=0.01, max_value=100.0))
def test_flywheel_scales_with_the_machine(a, b, k):
    J = lambda p: 1.0 + 0.4 * a * np.sin(p)                                  # noqa: E731
    M = lambda p: 50 * (np.sin(2 * p) + b * np.cos(p))                       # noqa: E731
    f1 = exact_flywheel(ReducedModel(J_e=J, M_e=M), omega_m=10.0, delta=0.04, positions=12)
    fk = exact_flywheel(ReducedModel(J_e=lambda p: k * J(p), M_e=lambda p: k * M(p)),
                        omega_m=10.0, delta=0.04, positions=12)
    assert fk.J_F == pytest.approx(k * f1.J_F, rel=1e-9)


def test_no_flywheel_needed_is_said_plainly():
    # ΔE = 50 sin φ and J_e = 2 + sin φ vary in step: with T0 = 100 J, T/J_e = 50 and ω is
    # constant without any flywheel; the identity gives J_F = −min J_e exactly.
    model = ReducedModel(J_e=lambda p: 2.0 + np.sin(p), M_e=lambda p: 50.0 * np.cos(p))
    with pytest.raises(MotionError, match="no flywheel is needed"):
        exact_flywheel(model, omega_m=10.0, delta=0.5)
    with pytest.raises(MotionError, match="no flywheel is needed"):
        exact_flywheel(ReducedModel(J_e=2.0, M_e=0.0), omega_m=10.0, delta=0.1)

    # when the machine alone runs a little below [δ], J_F comes out negative and is reported
    model = ReducedModel(J_e=lambda p: 2.0 + 0.8 * np.sin(p), M_e=lambda p: 50.0 * np.cos(p))
    assert periodic_motion(model, J_F=0.0, omega_m=10.0).delta < 0.1
    fw = exact_flywheel(model, omega_m=10.0, delta=0.1)
    assert -1.2 < fw.J_F < 0
    assert fw.delta_check == pytest.approx(0.1, rel=1e-9)


def test_sampled_J_e_must_be_periodic():
    with pytest.raises(InputError, match="periodic"):
        ReducedModel.from_samples(J_e=[1.0, 2.0, 3.0], M_e=0.0)


def test_the_exact_flywheel_calls_the_model_in_batches_not_angle_by_angle():
    """A linkage's J_e and M_e cost a kinematics run per call: the extremum search must batch its angles."""
    calls = {"J_e": 0, "M_e": 0}
    model, _ = sinusoid_model()

    def counted(name, f):
        def g(p):
            calls[name] += 1
            return f(p)
        return g

    counted_model = ReducedModel(J_e=counted("J_e", model.J_e), M_e=counted("M_e", model.M_e), dJ_e=model.dJ_e)
    fw = exact_flywheel(counted_model, omega_m=12.0, delta=0.05)
    assert fw.J_F == pytest.approx(exact_flywheel(model, omega_m=12.0, delta=0.05).J_F, rel=1e-13)
    assert calls["J_e"] + calls["M_e"] < 300          # the golden-section search made about 1 500 calls


def test_a_kink_of_the_energy_is_located_to_the_resolution_of_the_angle():
    # ΔE has a corner where a step load switches on; ω_min sits on it, so the search must not stop early
    M_e = lambda p: 16.25 - np.where((p >= 1.0) & (p < 1.0 + np.pi / 4), 60.0, 10.0)   # noqa: E731
    fw = exact_flywheel(ReducedModel(J_e=lambda p: 1.0 + 0.3 * np.cos(p), M_e=M_e, breaks=(1.0, 1.0 + np.pi / 4)),
                        omega_m=10.0, delta=0.05)
    assert abs(fw.phi_omega_min - (1.0 + np.pi / 4)) < 1e-12 or abs(fw.phi_omega_min - 1.0) < 1e-12
    assert fw.rel_accuracy < 1e-10
