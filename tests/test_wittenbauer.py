"""The Wittenbauer energy–mass construction (graphmethods.dynamics.wittenbauer)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphmethods.dynamics.motion import ReducedModel, exact_flywheel
from graphmethods.dynamics.wittenbauer import wittenbauer, wittenbauer_from_model
from graphmethods.errors import InputError, MotionError, UnbalancedCycleError


def ellipse(m=12, *, J0=2.0, dJ=0.4, T=300.0, lag=0.7):
    """A smooth closed curve: J_e = J0 + dJ cos(φ + lag), ΔT = T sin φ, positions 0…m."""
    phi = np.linspace(0, 2 * np.pi, m + 1)
    return J0 + dJ * np.cos(phi + lag), T * np.sin(phi), phi


def test_curve_points_are_the_data_over_the_scales():
    J, dT, phi = ellipse()
    res = wittenbauer(J_e=J, delta_T=dT, omega_m=20.0, delta=0.05, mu_J=0.01, mu_T=5.0)
    np.testing.assert_allclose(res.x_mm, J / 0.01)
    np.testing.assert_allclose(res.y_mm, dT / 5.0)
    np.testing.assert_allclose(res.phi, phi)
    assert res.m == 12
    assert res.x_mm[-1] == pytest.approx(res.x_mm[0]) and res.y_mm[-1] == pytest.approx(res.y_mm[0], abs=1e-12)


def test_rays_bound_every_point_and_touch_at_the_reported_vertices():
    J, dT, _ = ellipse(36)
    res = wittenbauer(J_e=J, delta_T=dT, omega_m=20.0, delta=0.05, mu_J=0.01, mu_T=5.0)
    upper = res.k_mm + res.tan_psi_max * res.x_mm
    lower = res.l_mm + res.tan_psi_min * res.x_mm
    tol = 1e-9 * np.ptp(res.y_mm)
    assert np.all(res.y_mm <= upper + tol) and np.all(res.y_mm >= lower - tol)
    for i in res.index_omega_max:
        assert res.y_mm[i] == pytest.approx(upper[i], abs=tol)
    for i in res.index_omega_min:
        assert res.y_mm[i] == pytest.approx(lower[i], abs=tol)
    assert res.kl_mm == pytest.approx(res.k_mm - res.l_mm, rel=1e-12)


def test_tangents_and_flywheel_formulae():
    J, dT, _ = ellipse()
    w, d, muJ, muT = 20.0, 0.05, 0.01, 5.0
    res = wittenbauer(J_e=J, delta_T=dT, omega_m=w, delta=d, mu_J=muJ, mu_T=muT)
    assert res.tan_psi_max == pytest.approx(muJ / (2 * muT) * w**2 * (1 + d / 2) ** 2)
    assert res.tan_psi_min == pytest.approx(muJ / (2 * muT) * w**2 * (1 - d / 2) ** 2)
    assert res.psi_max == pytest.approx(math.atan(res.tan_psi_max))
    assert res.J_F == pytest.approx(muT * res.kl_mm / (w**2 * d), rel=1e-12)
    tb = wittenbauer(J_e=J, delta_T=dT, omega_m=w, delta=d, mu_J=muJ, mu_T=muT, tangents="textbook")
    assert tb.tan_psi_max == pytest.approx(muJ / (2 * muT) * w**2 * (1 + d))
    assert tb.J_F == pytest.approx(res.J_F_other_tangents, rel=1e-14)
    assert res.J_F == pytest.approx(tb.J_F_other_tangents, rel=1e-14)
    assert res.tangents_difference == pytest.approx((tb.J_F - res.J_F) / res.J_F)
    assert abs(res.tangents_difference) < d                   # the forms differ at O(δ²)


def test_O1_and_the_speeds_along_its_rays():
    J, dT, _ = ellipse(24)
    w, d, muJ, muT = 20.0, 0.05, 0.01, 5.0
    res = wittenbauer(J_e=J, delta_T=dT, omega_m=w, delta=d, mu_J=muJ, mu_T=muT)
    x1, y1 = res.O1_mm
    # O1 lies on both rays ...
    assert y1 == pytest.approx(res.k_mm + res.tan_psi_max * x1, rel=1e-9)
    assert y1 == pytest.approx(res.l_mm + res.tan_psi_min * x1, rel=1e-9)
    assert x1 == pytest.approx(-res.J_F / muJ)
    # ... and the slope of the ray from O1 to each point gives ω there
    tan_psi = (res.y_mm - y1) / (res.x_mm - x1)
    np.testing.assert_allclose(res.omega, np.sqrt(2 * muT / muJ * tan_psi), rtol=1e-9)
    assert res.omega.max() == pytest.approx(w * (1 + d / 2), rel=1e-12)
    assert res.omega.min() == pytest.approx(w * (1 - d / 2), rel=1e-12)
    assert int(np.argmax(res.omega)) in res.index_omega_max


def test_from_model_converges_to_the_exact_flywheel_for_a_smooth_curve():
    model = ReducedModel(J_e=lambda p: 2 + 0.4 * np.cos(p + 0.7), M_e=lambda p: 300 * np.cos(p))
    exact = exact_flywheel(model, omega_m=20.0, delta=0.05)
    previous = -np.inf
    for m in (12, 24, 72, 360):
        res = wittenbauer_from_model(model, positions=m, omega_m=20.0, delta=0.05, mu_J=0.01, mu_T=5.0)
        assert previous - 1e-12 <= res.J_F <= exact.J_F * (1 + 1e-12)
        assert 0 <= exact.J_F - res.J_F <= res.error_estimate * (1 + 1e-9) + 1e-12
        previous = res.J_F
    assert res.J_F == pytest.approx(exact.J_F, rel=1e-4)       # O(h²) for a smooth touch
    assert res.phi_omega_max[0] == pytest.approx(exact.phi_omega_max, abs=2 * np.pi / 360)


def test_data_only_equals_the_model_construction():
    model = ReducedModel(J_e=lambda p: 2 + 0.4 * np.cos(p + 0.7), M_e=lambda p: 300 * np.cos(p))
    a = wittenbauer_from_model(model, positions=24, omega_m=20.0, delta=0.05, mu_J=0.01, mu_T=5.0)
    J, dT, _ = ellipse(24)
    b = wittenbauer(J_e=J, delta_T=dT, omega_m=20.0, delta=0.05, mu_J=0.01, mu_T=5.0)
    assert a.J_F == pytest.approx(b.J_F, rel=1e-10)
    assert a.index_omega_max == b.index_omega_max and a.index_omega_min == b.index_omega_min


def test_two_separate_touching_points_are_both_reported():
    # ΔT with two equal maxima (at positions 3 and 9 of 12) and constant J_e
    phi = np.linspace(0, 2 * np.pi, 13)
    dT = 100 * np.cos(2 * phi - np.pi)       # maxima at φ = π/2, 3π/2; minima at 0, π
    res = wittenbauer(J_e=np.full(13, 1.0), delta_T=dT, omega_m=10.0, delta=0.1, mu_J=0.01, mu_T=1.0)
    assert res.index_omega_max == (3, 9)
    assert [t.kind for t in res.upper] == ["point", "point"]
    assert res.index_omega_min == (0, 6)
    assert res.phi_omega_min == pytest.approx((0.0, np.pi))


def test_a_vertex_at_the_closing_point_is_one_position_not_two():
    phi = np.linspace(0, 2 * np.pi, 13)
    res = wittenbauer(J_e=np.full(13, 1.0), delta_T=100 * np.cos(phi), omega_m=10.0, delta=0.1,
                      mu_J=0.01, mu_T=1.0)
    assert res.index_omega_max == (0,)


def test_a_curve_that_does_not_close_is_refused():
    J, dT, _ = ellipse()
    dT[-1] += 1.0
    with pytest.raises(UnbalancedCycleError, match="does not close"):
        wittenbauer(J_e=J, delta_T=dT, omega_m=20.0, delta=0.05, mu_J=0.01, mu_T=5.0)
    # a hand-measured curve may be accepted with a looser tolerance
    res = wittenbauer(J_e=J, delta_T=dT, omega_m=20.0, delta=0.05, mu_J=0.01, mu_T=5.0, closure_rtol=0.01)
    assert res.J_F > 0


@pytest.mark.parametrize("kwargs, error, match", [
    (dict(mu_J=0.0), InputError, "mu_J"),
    (dict(delta=2.0), InputError, "below 1"),
    (dict(tangents="approx"), InputError, "tangents"),
    (dict(J_e=[1.0, 2.0]), InputError, "columns"),
    (dict(J_e=[1.0, -1.0, 1.0, 1.0]), InputError, "negative"),
    (dict(J_e=[1.0, 1.0, 1.0, 1.0], delta_T=[0.0, 0.0, 0.0, 0.0]), MotionError, "no flywheel is needed"),
])
def test_bad_input_is_refused(kwargs, error, match):
    args = dict(J_e=[1.0, 1.2, 0.8, 1.0], delta_T=[0.0, 10.0, -10.0, 0.0], omega_m=20.0, delta=0.05,
                mu_J=0.01, mu_T=1.0)
    args.update(kwargs)
    with pytest.raises(error, match=match):
        wittenbauer(**args)


def test_abscissa_with_only_the_variable_part_of_J_e_gives_J_F_plus_the_constant_part():
    J, dT, _ = ellipse(36, J0=5.0)
    full = wittenbauer(J_e=J, delta_T=dT, omega_m=20.0, delta=0.05, mu_J=0.01, mu_T=5.0)
    part = wittenbauer(J_e=J - 4.0, delta_T=dT, omega_m=20.0, delta=0.05, mu_J=0.01, mu_T=5.0)
    assert part.J_F == pytest.approx(full.J_F + 4.0, rel=1e-12)
