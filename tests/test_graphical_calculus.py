"""Graphical integration and differentiation by the method of chords."""

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.dynamics.graphical_calculus import (
    accuracy_table,
    differentiate_by_chords,
    exact_integral,
    integrate_by_chords,
    slider_diagrams,
    slider_motion,
    work_diagrams,
)
from graphmethods.dynamics.moments import MomentCurve
from graphmethods.errors import InputError
from graphmethods.kinematics import SliderCrank

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


# ----------------------------------------------------------------------------- exact references

def test_callable_accuracy_is_measured_against_an_exact_integral_interval_by_interval():
    # regression: the reference integral of a callable was one 16-point rule over [x0, x], wrong for
    # a curve that oscillates over the whole span (it reported 0.22 at the ends for an exact 4e-15)
    x = np.linspace(0, 2 * PI, 13)
    f = lambda p: np.sin(10 * p) + 3 * np.cos(7 * p)              # noqa: E731
    F = lambda t: (1 - np.cos(10 * t)) / 10 + 3 * np.sin(7 * t) / 7   # noqa: E731
    I = integrate_by_chords(x, f, mu_x=0.03, mu_y=1, H_mm=20)
    assert I.accuracy.at_nodes < 1e-12
    np.testing.assert_allclose(I.values, F(x), atol=1e-12)
    t = np.linspace(0, 2 * PI, 20001)
    assert I.accuracy.inside == pytest.approx(np.abs(np.interp(t, x, I.values) - F(t)).max(), rel=2e-3)


def test_a_jump_of_a_callable_is_exact_when_declared_and_exact_reveals_it_when_not():
    x = np.linspace(0, 2 * PI, 13)
    step = lambda p: np.where(p < 1.0, 60.0, 10.0)                # noqa: E731
    F = lambda t: np.where(t < 1.0, 60 * t, 60 + 10 * (t - 1.0))  # noqa: E731
    declared = integrate_by_chords(x, step, mu_x=0.03, mu_y=1, H_mm=20, breaks=[1.0])
    np.testing.assert_allclose(declared.values, F(x), atol=1e-12)
    blind = integrate_by_chords(x, step, mu_x=0.03, mu_y=1, H_mm=20, exact=F)
    assert blind.accuracy.at_nodes > 0.01                          # 16 points cannot see an undeclared jump
    np.testing.assert_allclose(blind.exact_values, F(x), atol=1e-12)


@given(st.lists(st.floats(-5, 5), min_size=1, max_size=5), st.floats(-3, 3), st.floats(0.1, 6),
       st.lists(st.floats(-3, 9), max_size=3))
@settings(deadline=None, max_examples=40)
def test_exact_integral_of_polynomials_with_breaks(coeffs, a, span, breaks):
    p = np.polynomial.Polynomial(coeffs)
    x = a + span * np.array([0.0, 0.3, 1.0, 0.7])
    got = exact_integral(p, x, x0=a, breaks=breaks)
    P = p.integ()
    ref = P(x) - P(a)
    np.testing.assert_allclose(got, ref, atol=1e-12 * (1 + np.abs(ref).max() + abs(P(a))))


# ----------------------------------------------------------------------------- periodic (second) differentiation

@given(st.lists(st.floats(-2, 2), min_size=2, max_size=6), st.integers(6, 40))
@settings(deadline=None, max_examples=40)
def test_second_differentiation_is_the_periodic_second_difference(coef, m):
    x = np.linspace(0, 2 * PI, m + 1)
    Y = sum(c * np.cos((k + 1) * x + k) for k, c in enumerate(coef))
    Y[-1] = Y[0]
    D = differentiate_by_chords(x, Y, mu_x=0.02, mu_Y=0.01, H_mm=20, period=2 * PI)
    DD = differentiate_by_chords(D.x, D.values, mu_x=0.02, mu_Y=D.mu, H_mm=30, period=2 * PI, x_origin=0.0)
    h = x[1] - x[0]
    core = Y[:-1]
    second = (np.roll(core, -1) - 2 * core + np.roll(core, 1)) / h**2
    np.testing.assert_allclose(DD.values, np.append(second, second[0]), atol=1e-9 * (1 + np.abs(second).max()))
    np.testing.assert_allclose(DD.x, x, atol=1e-12)
    assert DD.values[0] == DD.values[-1]
    np.testing.assert_allclose(DD.points_mm[:, 0], x / 0.02, atol=1e-9)


def test_periodic_curves_must_repeat_and_span_one_period():
    x = np.linspace(0, 2 * PI, 7)
    with pytest.raises(InputError, match="not periodic"):
        differentiate_by_chords(x, x, mu_x=1, mu_Y=1, H_mm=1, period=2 * PI)
    with pytest.raises(InputError, match="more than one period"):
        differentiate_by_chords(x, np.sin(x), mu_x=1, mu_Y=1, H_mm=1, period=PI)


# ----------------------------------------------------------------------------- the slider

@given(st.floats(0.02, 0.2), st.floats(1.3, 5.0), st.floats(-0.4, 0.4), st.sampled_from([1, -1]),
       st.sampled_from([1, -1]))
@settings(deadline=None, max_examples=30)
def test_slider_motion_is_the_derivative_of_the_positions(r, ratio, e_frac, assembly, sense):
    e = e_frac * r
    mech = SliderCrank(r=r, l=ratio * (r + abs(e)), e=e, assembly=assembly, sense=sense)
    phi = np.linspace(0.05, 6.2, 9)
    h = 1e-5
    mo = slider_motion(mech, phi)
    s_p, s_m = slider_motion(mech, phi + h).s, slider_motion(mech, phi - h).s
    np.testing.assert_allclose(mo.ds, (s_p - s_m) / (2 * h), atol=1e-7 * r)
    ds_p, ds_m = slider_motion(mech, phi + h).ds, slider_motion(mech, phi - h).ds
    np.testing.assert_allclose(mo.d2s, (ds_p - ds_m) / (2 * h), atol=1e-6 * r)
    assert mo.s.min() >= -1e-12 and mo.s.max() <= mo.H + 1e-12


def test_slider_motion_of_a_shaper_ram_by_the_fallback_difference():
    import pathlib

    from graphmethods.kinematics import read_case
    case = read_case(pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data" / "shaper.json")
    phi = np.linspace(0.1, 6.1, 7)
    mo = slider_motion(case.mechanism, phi)
    h = 1e-5
    d = (slider_motion(case.mechanism, phi + h).ds - slider_motion(case.mechanism, phi - h).ds) / (2 * h)
    np.testing.assert_allclose(mo.d2s, d, atol=1e-7)


def test_slider_diagrams_references_agree_and_v_at_positions_is_the_central_difference():
    mech = SliderCrank(r=0.1, l=0.4, e=0.02)
    sd = slider_diagrams(mech, 12, mu_phi=PI / 90, mu_s=0.004, omega_1=20.0)
    np.testing.assert_allclose(sd.v_plans, sd.v_exact, atol=1e-12)
    t = 1 / 20.0
    s = np.asarray(sd.s)
    central = (np.roll(s[:-1], -1) - np.roll(s[:-1], 1)) / (2 * (PI / 6) * t)
    np.testing.assert_allclose(sd.v_at_positions[:-1], central, atol=1e-12)
    rows = sd.comparison()
    assert rows[0]["error"] == sd.v.accuracy.at_nodes and rows[2]["error"] == sd.a.accuracy.at_nodes
    assert rows[0]["error_mm"] == pytest.approx(rows[0]["error"] / sd.v.mu)
    assert [r["unit"] for r in rows] == ["m/s", "m/s", "m/s²", "m/s²"]
    np.testing.assert_allclose(sd.a_plans, sd.a_exact, atol=1e-12)              # the acceleration plans
    assert rows[3]["against"] == "acceleration plans" and rows[3]["error"] == pytest.approx(rows[2]["error"], abs=1e-12)
    an = slider_diagrams(mech, 12, mu_phi=PI / 90, mu_s=0.004)
    np.testing.assert_allclose(an.v.values * 20.0, sd.v.values, rtol=1e-12)      # v = ω ds/dφ
    np.testing.assert_allclose(an.a.values * 400.0, sd.a.values, rtol=1e-9)       # a = ω² d²s/dφ²
    assert an.units == ("m/rad", "m/rad²") and an.mu_t is None


# ----------------------------------------------------------------------------- work diagrams and the table

def test_work_diagrams_share_one_pole_and_close():
    M_r = MomentCurve.points([0, PI, 2 * PI], [0.0, 40.0, 0.0])
    M_d = MomentCurve.constant(M_r.mean())
    wd = work_diagrams(M_d, M_r, np.linspace(0, 2 * PI, 9), mu_phi=PI / 90, mu_M=0.5, fit_mm=80)
    assert wd.A_d.H_mm == wd.A_r.H_mm == wd.H_mm and wd.mu_A == pytest.approx(0.5 * PI / 90 * wd.H_mm)
    assert abs(wd.closure) < 1e-12 and max(np.abs(wd.A_d.values).max(), np.abs(wd.A_r.values).max()) / wd.mu_A <= 80
    np.testing.assert_allclose(wd.delta_E, (M_d - M_r).integral(wd.phi), atol=1e-12)


def test_accuracy_table_of_the_press_falls_as_h_squared_for_the_derivatives():
    import json
    import pathlib

    from graphmethods.kinematics import read_case
    case = read_case(pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data"
                     / "slider_crank_press.json")
    rows = accuracy_table(case, ms=(12, 24, 48))
    json.dumps(rows)                                                    # plain, JSON-ready
    names = sorted({r["construction"] for r in rows})
    assert names == ["A_d by chords", "A_r by chords", "a by chords of v", "v by chords of s", "ΔE by chords"]
    for name in ("v by chords of s", "a by chords of v"):
        err = [r["error"] for r in rows if r["construction"] == name]
        assert 3.7 < err[0] / err[1] < 4.3 and 3.7 < err[1] / err[2] < 4.3
    for r in rows:
        assert r["error_mm"] == pytest.approx(r["error"] / r["mu"])
    with pytest.raises(InputError, match="m ≥ 3"):
        accuracy_table(case, ms=(2,))
