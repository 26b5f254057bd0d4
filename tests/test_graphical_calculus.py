"""Graphical integration and differentiation by the method of chords."""

import math

import numpy as np
import pytest
from hypothesis import given, strategies as st

from graphmethods.dynamics.graphical_calculus import differentiate_by_chords, integrate_by_chords
from graphmethods.dynamics.moments import MomentCurve
from graphmethods.errors import InputError

PI = math.pi


def test_integral_scale_and_drawn_lengths_agree():
    x = np.linspace(0, 2 * PI, 13)
    I = integrate_by_chords(x, lambda p: 50 + 30 * np.sin(p), mu_x=PI / 90, mu_y=2.0, H_mm=30)
    assert I.mu == pytest.approx(2.0 * PI / 90 * 30)
    np.testing.assert_allclose(I.chords_mm[:, 1] * I.mu, I.values)
    # each chord is parallel to its ray from the pole (−H, 0) to (0, ȳ/μ_y)
    ray_slope = I.ray_targets_mm[:, 1] / I.H_mm
    chord_slope = np.diff(I.chords_mm[:, 1]) / np.diff(I.chords_mm[:, 0])
    np.testing.assert_allclose(chord_slope, ray_slope, rtol=1e-12)
    assert I.values[-1] == pytest.approx(100 * PI, rel=1e-12)


@pytest.mark.hard
def test_moment_with_a_jump_exact_at_interval_ends():
    M = MomentCurve.steps([(0, PI / 4 + 0.1, 60.0), (PI / 4 + 0.1, 2 * PI, 10.0)])
    for m in (6, 12, 24):
        I = integrate_by_chords(np.linspace(0, 2 * PI, m + 1), M, mu_x=PI / 120, mu_y=1.0, H_mm=40)
        assert I.accuracy.at_nodes < 1e-12
        assert I.accuracy.inside > 0.1           # the chord cuts the corner inside the jump's interval
    # the inside error shrinks with the interval containing the jump (∝ h)
    errs = [integrate_by_chords(np.linspace(0, 2 * PI, m + 1), M, mu_x=1, mu_y=1, H_mm=1).accuracy.inside
            for m in (6, 60, 600)]
    assert errs[0] > errs[1] > errs[2]


@pytest.mark.hard
def test_very_few_intervals():
    x = np.linspace(0, 2 * PI, 7)                  # m = 6
    I = integrate_by_chords(x, np.cos, mu_x=PI / 60, mu_y=0.01, H_mm=40)
    assert I.accuracy.at_nodes < 1e-12             # exact means: exact at the ends
    D = differentiate_by_chords(x, np.sin(x), mu_x=PI / 60, mu_Y=0.01, exact=np.cos)
    h = x[1] - x[0]
    # the chord's slope is sinc(h/2)·cos(mid): exact error (1 − sinc(h/2))·max|cos(mid)|
    assert D.accuracy.at_nodes == pytest.approx((1 - math.sin(h / 2) / (h / 2)) * np.abs(np.cos(D.x)).max(), rel=1e-9)


def test_sampled_input_converges_second_order():
    errs = []
    for m in (12, 24, 48):
        x = np.linspace(0, PI, m + 1)
        I = integrate_by_chords(x, np.sin(x), mu_x=1, mu_y=1, H_mm=1)
        errs.append(abs(I.values[-1] - 2.0))
    assert errs[0] / errs[1] == pytest.approx(4, rel=0.05) and errs[1] / errs[2] == pytest.approx(4, rel=0.05)


def test_differentiation_converges_second_order_at_mid_intervals():
    errs = []
    for m in (12, 24, 48):
        x = np.linspace(0, 2 * PI, m + 1)
        errs.append(differentiate_by_chords(x, np.sin(x), mu_x=1, mu_Y=1, H_mm=1, exact=np.cos).accuracy.at_nodes)
    assert errs[0] / errs[1] == pytest.approx(4, rel=0.05)


def test_pole_distance_is_picked_and_convenient():
    x = np.linspace(0, 2 * PI, 13)
    I = integrate_by_chords(x, lambda p: 100 + 0 * p, mu_x=PI / 90, mu_y=2.0, fit_mm=120)
    top = np.abs(I.chords_mm[:, 1]).max()
    assert top <= 120 + 1e-9 and I.H_mm in {1, 2, 2.5, 4, 5, 10, 20, 25, 40, 50, 100, 200, 250, 400, 500}
    D = differentiate_by_chords(x, np.sin(x), mu_x=PI / 90, mu_Y=0.01, fit_mm=60)
    assert np.abs(D.ordinates_mm).max() <= 60 + 1e-9


@given(st.floats(0.001, 100), st.floats(0.001, 100), st.floats(1, 200))
def test_values_do_not_depend_on_scales(mu_x, mu_y, H):
    x = np.linspace(0, 2 * PI, 13)
    I = integrate_by_chords(x, lambda p: 3 + np.cos(p), mu_x=mu_x, mu_y=mu_y, H_mm=H)
    ref = integrate_by_chords(x, lambda p: 3 + np.cos(p), mu_x=1, mu_y=1, H_mm=1)
    np.testing.assert_allclose(I.values, ref.values, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(I.chords_mm[:, 1] * I.mu, I.values, rtol=1e-12, atol=1e-12)
    D = differentiate_by_chords(x, np.sin(x), mu_x=mu_x, mu_Y=mu_y, H_mm=H)
    np.testing.assert_allclose(D.ordinates_mm * D.mu, D.values, rtol=1e-12, atol=1e-12)


def test_bad_input():
    with pytest.raises(InputError, match="increase"):
        integrate_by_chords([0, 2, 1], [1, 2, 3], mu_x=1, mu_y=1, H_mm=1)
    with pytest.raises(InputError, match="one ordinate per"):
        integrate_by_chords([0, 1, 2], [1, 2], mu_x=1, mu_y=1, H_mm=1)
    with pytest.raises(InputError, match="mu_x"):
        differentiate_by_chords([0, 1], [0, 1], mu_x=0, mu_Y=1)
    with pytest.raises(InputError, match="range"):
        integrate_by_chords([0, 7], MomentCurve.constant(1.0), mu_x=1, mu_y=1, H_mm=1)


def test_chord_flywheels_on_a_reduced_model():
    from graphmethods.dynamics.graphical import chord_flywheels
    from graphmethods.dynamics.motion import ReducedModel, exact_flywheel
    model = ReducedModel(J_e=lambda p: 1.0 + 0.2 * np.cos(p), M_e=lambda p: 40.0 * np.cos(p))
    exact = exact_flywheel(model, omega_m=20.0, delta=0.04).J_F
    g = chord_flywheels(model, positions=24, omega_m=20.0, delta=0.04)
    true_error = exact - g.wittenbauer.J_F
    assert 0.5 < g.wittenbauer.error_estimate / true_error < 2.0
    assert "384 positions" in g.wittenbauer.error_method
    assert abs(g.excess_work.residual) < 1e-9 and abs(g.delta_T[-1]) < 1e-9
