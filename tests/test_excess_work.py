"""The excess-work core and the approximate flywheel against the published worked examples."""

import json
import math

import numpy as np
import pytest
from hypothesis import given, strategies as st

from graphmethods.dynamics import excess_work as ew
from graphmethods.dynamics.flywheel import disc_flywheel, fluctuation, flywheel, rim_flywheel, transfer
from graphmethods.dynamics.kinetic_energy import kinetic_energy
from graphmethods.dynamics.moments import MomentCurve
from graphmethods.errors import InputError, MotionError, UnbalancedCycleError
from graphmethods.units import parse_number

PI = math.pi


def rel(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


# ----------------------------------------------------------------- W1–W4 as the JSON gives them
@pytest.mark.parametrize("wid", ["W1", "W2"])
def test_area_examples(worked_examples, wid):
    case = worked_examples[wid]
    exp, tol = case["expect"], case["tol"]
    cyc = ew.from_work(case["areas_J"])
    assert cyc.delta_W_max == pytest.approx(exp["delta_W_max"], rel=tol)
    np.testing.assert_allclose(cyc.E, exp["E"], rtol=tol, atol=1e-9)
    assert cyc.index_E_max == exp["index_E_max"] and cyc.index_E_min == exp["index_E_min"]
    fw = flywheel(cyc.delta_W_max, delta=parse_number(case["delta"]), n_rpm=case["n_rpm"], J_e=case["J_e"])
    assert fw.J_F == pytest.approx(exp["J_F"], rel=tol)


def test_w2_reports_the_right_value_not_the_source_slip(worked_examples):
    case = worked_examples["W2"]
    J_F = flywheel(ew.from_work(case["areas_J"]).delta_W_max, delta=case["delta"], n_rpm=case["n_rpm"]).J_F
    assert round(J_F, 2) == 60.69 and round(J_F, 2) != 60.16


def test_w3_step_moment(worked_examples):
    case = worked_examples["W3"]
    exp, tol = case["expect"], case["tol"]
    M_r = MomentCurve.steps(case["M_r_steps"])
    cyc = ew.from_moments(M_r=M_r)      # M_d constant by work balance
    assert float(cyc.M_d(0.3)) == pytest.approx(exp["M_d"], rel=tol)
    np.testing.assert_allclose(cyc.work, exp["areas_J"], rtol=tol)
    assert cyc.delta_W_max == pytest.approx(exp["delta_W_max"], rel=tol)
    fw = flywheel(cyc.delta_W_max, delta=case["delta"], n_rpm=case["n_rpm"], J_e=case["J_e"])
    assert fw.J_F == pytest.approx(exp["J_F"], rel=tol)
    assert cyc.phi.tolist() == pytest.approx([0.0, PI / 4, 2 * PI])


def test_w4_drawing_and_exact(worked_examples):
    case = worked_examples["W4"]
    d, tol = case["drawing"], case["tol"]
    drawn = ew.from_areas(d["areas_mm2"], mu_M=d["mu_M"], mu_phi=d["mu_phi"])
    ke = kinetic_energy(drawn, J_e=case["J_e"], omega_0=case["omega_0"])
    exp = case["expect"]["drawing"]
    np.testing.assert_allclose(ke.T, exp["T"], rtol=tol)
    np.testing.assert_allclose(ke.omega, exp["omega"], rtol=tol)
    assert ke.omega_m == pytest.approx(exp["omega_m"], rel=tol)
    assert ke.delta == pytest.approx(exp["delta"], rel=tol)
    # the exact data: M_d = 20, triangular M_r, split at the four positions
    exact = ew.from_moments(
        M_d=MomentCurve.constant(20.0), M_r=MomentCurve.points([0, PI, 2 * PI], [0, 40, 0]),
        boundaries=[0, PI / 2, PI, 3 * PI / 2, 2 * PI],
    )
    np.testing.assert_allclose(exact.work, case["expect"]["exact"]["areas"], rtol=tol)
    ke_exact = kinetic_energy(exact, J_e=case["J_e"], omega_0=case["omega_0"])
    np.testing.assert_allclose(ke_exact.T, case["expect"]["exact"]["T"], rtol=tol)


def test_builtin_problems_match_the_reference_data(worked_examples):
    from graphmethods import problems
    assert list(problems.w1().work_J) == worked_examples["W1"]["areas_J"]
    assert list(problems.w2().work_J) == worked_examples["W2"]["areas_J"]
    assert problems.w1().delta == parse_number(worked_examples["W1"]["delta"])
    for p in problems.all_examples():
        if p.n_rpm:
            wid = p.id.split("-")[0]
            assert p.flywheel().J_F == pytest.approx(worked_examples[wid]["expect"]["J_F"], rel=1e-6)


# ----------------------------------------------------------------- the table
def test_table_outputs_are_consistent():
    cyc = ew.from_areas([10, -110, 20, -25, 100, -5, 10], mu_M=100.0, mu_phi_deg=180 / PI * 0.05)
    md = cyc.to_markdown()
    assert md.count("\n|") == 1 + 7 and "ΔW_max = 575 J" in md
    d = json.loads(json.dumps(cyc.to_dict()))
    assert d["areas_mm2"][1] == -110 and d["delta_W_max"] == pytest.approx(575.0)
    assert "f, mm²" in cyc.to_text()


def test_energy_curve_is_exact_piecewise_quadratic():
    M_r = MomentCurve.points([0, PI, 2 * PI], [0, 40, 0])
    cyc = ew.from_moments(M_d=MomentCurve.constant(20.0), M_r=M_r)
    phi, E = cyc.energy_curve(samples=101)
    # exact: on [0, π], ΔE = 20φ − 20φ²/π
    m = phi <= PI
    np.testing.assert_allclose(E[m], 20 * phi[m] - 20 * phi[m] ** 2 / PI, atol=1e-12)
    assert E.max() == pytest.approx(cyc.E_max) and E.min() == pytest.approx(cyc.E_min)


def test_callable_moment_to_tolerance():
    # M_r = 10 + 8 sin φ against its mean: crossings at 0 and π, ΔW_max = 16 exactly
    cyc = ew.from_moments(M_r=MomentCurve.function(lambda p: 10 + 8 * np.sin(p), tol=1e-10))
    assert cyc.delta_W_max == pytest.approx(16.0, rel=1e-8)
    assert cyc.phi.tolist() == pytest.approx([0, PI, 2 * PI], abs=1e-6)



def test_a_difference_within_round_off_of_zero_starts_no_interval():
    # M_d − M_r = 1e-14 at φ = 0 is the last bit of a balanced mean (its sign differs between numpy
    # versions), not a crossing 1.6e-15 rad later: the intervals are [0, π] and [π, 2π] only
    M_r = MomentCurve.points([0, PI / 2, PI, 3 * PI / 2, 2 * PI], [-1e-14, 10, 0, -10, 0])
    cyc = ew.from_moments(M_d=MomentCurve.constant(0.0), M_r=M_r)
    assert cyc.phi.tolist() == pytest.approx([0, PI, 2 * PI], abs=1e-12)
    assert cyc.work.tolist() == pytest.approx([-10 * PI / 2, 10 * PI / 2], rel=1e-12)


# ----------------------------------------------------------------- flywheel
def test_flywheel_inverse_and_transfer():
    fw = flywheel(575.0, delta=0.06, n_rpm=120.0, J_e=5.0)
    assert fw.J_total - fw.J_F == pytest.approx(5.0)
    assert fluctuation(575.0, J=fw.J_total, n_rpm=120.0) == pytest.approx(0.06)
    assert fw.omega_max**2 - fw.omega_min**2 == pytest.approx(2 * fw.delta * fw.omega_m**2)
    assert transfer(fw.J_F, omega_from=fw.omega_m, omega_to=3 * fw.omega_m) == pytest.approx(fw.J_F / 9)
    assert fw.on_shaft(omega_i=fw.omega_m / 2) == pytest.approx(4 * fw.J_F)


def test_no_flywheel_needed_when_J_e_suffices():
    fw = flywheel(10.0, delta=0.1, omega_m=10.0, J_e=5.0)
    assert fw.J_F == pytest.approx(-4.0) and not fw.needed


def test_rim_and_disc_sizing():
    r = rim_flywheel(43.69, n_rpm=600.0)          # D from the cast-iron rim-speed limit
    assert r.rim_speed == pytest.approx(25.0)
    assert r.m * r.D**2 / 4 == pytest.approx(43.69)
    assert r.H / r.B == pytest.approx(1.5)
    assert r.m == pytest.approx(r.rho * PI * r.D * r.H * r.B)
    assert r.J_rim > r.J
    fast = rim_flywheel(43.69, n_rpm=600.0, D=1.2)
    assert not fast.speed_ok
    d = disc_flywheel(2.0, D=0.5, n_rpm=300.0)
    assert d.m * d.D**2 / 8 == pytest.approx(2.0)
    assert d.m == pytest.approx(d.rho * PI * d.D**2 * d.B / 4)


@pytest.mark.parametrize("kw, msg", [
    (dict(delta=0.0, n_rpm=100), "between 0 and 1"),
    (dict(delta=2.0, n_rpm=100), "between 0 and 1"),
    (dict(delta=0.05, n_rpm=0), "positive"),
    (dict(delta=0.05, n_rpm=-5), "positive"),
    (dict(delta=float("nan"), n_rpm=100), "not finite"),
    (dict(delta=0.05), "give the mean speed once"),
])
def test_flywheel_bad_input(kw, msg):
    with pytest.raises(InputError, match=msg):
        flywheel(100.0, **kw)


def test_bad_cycle_inputs():
    with pytest.raises(InputError, match="not a finite"):
        ew.from_work([1.0, float("nan"), -1.0])
    with pytest.raises(InputError, match="give the angle scale once"):
        ew.from_areas([1, -1], mu_M=1.0)
    with pytest.raises(InputError, match="mu_M"):
        ew.from_areas([1, -1], mu_M=0, mu_phi=1)
    with pytest.raises(InputError, match="no works"):
        ew.from_work([])
    with pytest.raises(UnbalancedCycleError, match="residual|sum to"):
        ew.from_levels([0, 50, -500])
    with pytest.raises(MotionError, match="would stop"):
        kinetic_energy(ew.from_work([-50, 50]), J_e=1.0, T0=40.0)


def test_small_residual_is_reported_not_refused():
    cyc = ew.from_areas([200, -198, -203, 199], mu_M=1.0, mu_phi=0.075)
    assert cyc.residual == pytest.approx(-2 * 0.075)
    with pytest.raises(UnbalancedCycleError, match="tolerance 0.001"):
        ew.from_areas([200, -198, -203, 199], mu_M=1.0, mu_phi=0.075, closure_tol=0.001)


# ----------------------------------------------------------------- properties
closed_works = st.lists(st.floats(-1e4, 1e4, allow_nan=False), min_size=1, max_size=30).map(
    lambda xs: xs + [-math.fsum(xs)])


@given(closed_works)
def test_closed_cycle_sums_to_zero(works):
    cyc = ew.from_work(works, closure_tol=1e-9)
    assert abs(cyc.residual) <= 1e-9 * max(1.0, sum(map(abs, works)))
    assert cyc.delta_W_max == pytest.approx(max(cyc.E) - min(cyc.E))


@given(closed_works, st.floats(1e-3, 1e3), st.floats(1e-4, 1.0))
def test_delta_W_max_and_J_F_do_not_depend_on_scales(works, mu_M, mu_phi):
    ref = ew.from_work(works, closure_tol=1e-9)
    areas = [w / (mu_M * mu_phi) for w in works]
    drawn = ew.from_areas(areas, mu_M=mu_M, mu_phi=mu_phi, closure_tol=1e-9)
    assert drawn.delta_W_max == pytest.approx(ref.delta_W_max, rel=1e-9, abs=1e-9)
    if ref.delta_W_max > 0:
        a = flywheel(ref.delta_W_max, delta=0.05, n_rpm=300).J_F
        b = flywheel(drawn.delta_W_max, delta=0.05, n_rpm=300).J_F
        assert b == pytest.approx(a, rel=1e-9)


piecewise = st.lists(st.floats(-100, 100, allow_nan=False), min_size=2, max_size=25)


def _curve(values):
    phi = np.linspace(0, 2 * PI, len(values) + 1)
    return MomentCurve.points(phi, list(values) + [values[0]])


@given(piecewise)
def test_reversing_the_sign_convention_keeps_delta_W_max(values):
    M_r = _curve(values)
    a = ew.from_moments(M_r=M_r)
    M_d = MomentCurve.constant(M_r.mean())
    b = ew.from_moments(M_d=M_r, M_r=M_d)          # M_r − M_d instead of M_d − M_r
    assert b.delta_W_max == pytest.approx(a.delta_W_max, rel=1e-9, abs=1e-9)
    np.testing.assert_allclose(b.work, -a.work, atol=1e-9)


@given(piecewise, st.floats(0.01, 0.99), st.integers(0, 100))
def test_splitting_a_segment_changes_nothing(values, t, k):
    M_r = _curve(values)
    k %= M_r.phi.size - 1
    x = M_r.phi[k] + t * (M_r.phi[k + 1] - M_r.phi[k])
    split = MomentCurve(np.insert(M_r.phi, k + 1, x), np.insert(M_r.M, k + 1, float(M_r(x))))
    a, b = ew.from_moments(M_r=M_r), ew.from_moments(M_r=split)
    assert b.delta_W_max == pytest.approx(a.delta_W_max, rel=1e-9, abs=1e-9)
    assert len(b.work) == len(a.work)
    np.testing.assert_allclose(b.phi, a.phi, atol=1e-9)


@given(piecewise)
def test_signs_alternate_between_crossings(values):
    cyc = ew.from_moments(M_r=_curve(values))
    inner = np.sign(cyc.work[np.abs(cyc.work) > 1e-9])
    # the period start is a boundary too, so two neighbours may share a sign only across it
    assert (inner[1:-1][:-1] != inner[1:-1][1:]).all() if inner.size > 3 else True


@given(piecewise, st.floats(-50, 50))
def test_combining_fast_paths_agree_with_the_general_union(values, c):
    from graphmethods.dynamics.moments import _combine
    curve = _curve(values)
    const2 = MomentCurve.constant(c)                                        # single chord: fast path
    const3 = MomentCurve([0.0, 1.234, 2 * PI], [c, c, c])                   # extra knot: general path
    x = np.linspace(0, 2 * PI, 97)
    for sign in (1.0, -1.0):
        fast, slow = _combine(curve, const2, sign), _combine(curve, const3, sign)
        np.testing.assert_allclose(fast(x), slow(x), atol=1e-9)
        np.testing.assert_allclose(_combine(const2, curve, sign)(x), _combine(const3, curve, sign)(x), atol=1e-9)
    same = MomentCurve(curve.phi, curve.M * 0.5)                             # same knots: fast path
    np.testing.assert_allclose((curve - same)(x), 0.5 * curve(x), atol=1e-9)
