"""Linkages, positions and velocity plans: the construction against the analytic derivative."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

from graphmethods.errors import AssemblyError, GraphmethodsError, InputError
from graphmethods.kinematics import (
    FourBar,
    Positions,
    Shaper,
    SliderCrank,
    SlottedLever,
    VelocityPlans,
    convenient_scale,
)

REL = 1e-12  # the plans must agree with the analytic derivative to 1e-12 of each quantity's cycle maximum


def assert_plan_matches_derivative(mech, pos, plan, rel=REL):
    """Every plan vector and angular velocity equals sense·ω₁·(d/dφ of the position equations).

    "Relative" means: the error is at most ``rel`` times the quantity's maximum over the whole
    cycle, and at most 1e-14 of the crank pin's speed (ω₁ for angular velocities): a point that
    (nearly) stands still, e.g. a centre of mass placed on a pivot, is found from the velocities
    of its link's joints, so its rounding error is a few ulp of those.
    """
    d_xy, d_th = mech.derivatives(pos.phi)
    cyc_xy, cyc_th = mech.derivatives(np.linspace(0.0, 2 * np.pi, 361))
    Om = mech.sense * plan.omega_1
    floor = 1e-2 * abs(Om) * np.abs(cyc_xy[mech.crank_pin]).max()
    for name, v in plan.vectors.items():
        exact = Om * d_xy[name]
        scale = max(abs(Om) * np.abs(cyc_xy[name]).max(), np.abs(exact).max(), floor)
        err = np.abs(v - exact).max()
        assert err <= rel * scale, f"{name}: plan differs from the derivative by {err:.3e} (scale {scale:.3e})"
    for link, w in plan.omegas.items():
        exact = Om * d_th[link]
        scale = max(abs(Om) * np.abs(cyc_th[link]).max(), np.abs(exact).max(), 1e-2 * abs(Om))
        err = np.abs(w - exact).max()
        assert err <= rel * scale, f"ω {link}: error {err:.3e} (scale {scale:.3e})"


def fd_check(mech, phi, names, rel=1e-7):
    """The analytic derivative agrees with central differences of the positions (checks the formulas)."""
    h = 1e-6
    d_xy, d_th = mech.derivatives(phi)
    pp = mech.positions(phi=phi + h)
    pm = mech.positions(phi=phi - h)
    for name in names:
        fd = (pp.xy(name) - pm.xy(name)) / (2 * h)
        assert np.abs(fd - d_xy[name]).max() <= rel * max(np.abs(d_xy[name]).max(), 1e-300), name
    for link in pp.theta:
        fd = np.mod(pp.theta[link] - pm.theta[link] + np.pi, 2 * np.pi) - np.pi
        assert np.abs(fd / (2 * h) - d_th[link]).max() <= rel * np.abs(d_th[link]).max(), link


def min_transmission_sin(mech):
    pos = mech.positions(phi=np.linspace(0, 2 * np.pi, 721))
    return float(mech.velocity_plans(pos, sin_threshold=0.0).sin_min.min())


# ---------------------------------------------------------------------------------- strategies
@st.composite
def slider_cranks(draw):
    r = draw(st.floats(1e-3, 10.0))
    e = r * draw(st.floats(-1.0, 1.0))
    l = (r + abs(e)) * draw(st.floats(1.05, 8.0))
    return SliderCrank(r=r, l=l, e=e, assembly=draw(st.sampled_from([1, -1])), sense=draw(st.sampled_from([1, -1])),
                       working_stroke=draw(st.sampled_from(["toward_crank", "away_from_crank", "slow", "fast"])),
                       points={"S2": ("AB", l * draw(st.floats(0.0, 1.0)), draw(st.floats(-3.0, 3.0))),
                               "K": ("OA", r * draw(st.floats(0.0, 1.5)), draw(st.floats(-3.0, 3.0)))})


@st.composite
def four_bars(draw):
    """Crank-rockers and double cranks built to turn fully: l_long + l_short < l3 + l4 and
    l_long − l_short > |l3 − l4| (the ground and crank are the long and short of the pair)."""
    long_ = draw(st.floats(0.01, 5.0))
    short = long_ * draw(st.floats(0.05, 0.6))
    l4 = long_ * draw(st.floats(0.7, 1.8)) * short / long_ + long_ * draw(st.floats(0.0, 1.2))
    lo = max(long_ + short - l4, l4 - long_ + short)
    hi = l4 + long_ - short
    assume(hi > lo)
    l3 = lo + (hi - lo) * draw(st.floats(0.1, 0.9))
    l1, l2 = (long_, short) if draw(st.booleans()) else (short, long_)
    fb = FourBar(l1=l1, l2=l2, l3=l3, l4=l4, ground_angle=draw(st.floats(-3.2, 3.2)),
                 assembly=draw(st.sampled_from([1, -1])), sense=draw(st.sampled_from([1, -1])),
                 working_stroke=draw(st.sampled_from(["slow", "fast"])),
                 points={"S2": ("AB", l3 * draw(st.floats(0.0, 1.0)), draw(st.floats(-3.0, 3.0))),
                         "S3": ("BO2", l4 * draw(st.floats(0.0, 1.0)), 0.0)})
    assert fb.turns_fully
    assume(min_transmission_sin(fb) > 0.02)   # keep away from toggles (those are the hard cases)
    return fb


@st.composite
def slotted_levers(draw):
    d = draw(st.floats(0.01, 10.0))
    r = d * draw(st.floats(0.02, 0.95))
    L = (d + r) * draw(st.floats(1.0, 2.0))
    return SlottedLever(r=r, l_O1O3=d, l_O3B=L, theta_O3=draw(st.floats(-3.2, 3.2)),
                        sense=draw(st.sampled_from([1, -1])), working_stroke=draw(st.sampled_from(["slow", "fast"])),
                        points={"S3": ("O3B", L * draw(st.floats(0.0, 1.0)), draw(st.floats(-1.0, 1.0)))})


@st.composite
def shapers(draw):
    d = draw(st.floats(0.05, 5.0))
    r = d * draw(st.floats(0.05, 0.8))
    L = (d + r) * draw(st.floats(1.0, 1.8))
    th = -math.pi / 2 + draw(st.floats(-0.5, 0.5))
    l_BC = L * draw(st.floats(0.1, 1.0))
    top = d * math.sin(th) + L                     # roughly the top of B's arc
    y_guide = top + l_BC * draw(st.floats(-0.8, 0.6))
    try:
        return Shaper(r=r, l_O1O3=d, l_O3B=L, l_BC=l_BC, y_guide=y_guide, theta_O3=th,
                      assembly=draw(st.sampled_from([1, -1])), sense=draw(st.sampled_from([1, -1])),
                      points={"S4": ("BC", l_BC * draw(st.floats(0.0, 1.0)), 0.0)})
    except AssemblyError:
        assume(False)


# ---------------------------------------------------------------------------------- the main property
@settings(deadline=None, max_examples=40)
@given(mech=slider_cranks(), m=st.integers(3, 60), omega_1=st.floats(0.1, 300.0))
def test_slider_crank_plan_equals_derivative(mech, m, omega_1):
    pos = mech.positions(m=m)
    assert_plan_matches_derivative(mech, pos, mech.velocity_plans(pos, omega_1=omega_1))


@settings(deadline=None, max_examples=40)
@given(mech=four_bars(), m=st.integers(3, 60))
def test_four_bar_plan_equals_derivative(mech, m):
    pos = mech.positions(m=m)
    plan = mech.velocity_plans(pos)
    assert not plan.ill_conditioned.any()
    assert_plan_matches_derivative(mech, pos, plan)


@settings(deadline=None, max_examples=40)
@given(mech=slotted_levers(), m=st.integers(3, 60))
def test_slotted_lever_plan_equals_derivative(mech, m):
    pos = mech.positions(m=m)
    assert_plan_matches_derivative(mech, pos, mech.velocity_plans(pos, omega_1=2.0))


@settings(deadline=None, max_examples=40)
@given(mech=shapers(), m=st.integers(3, 60))
def test_shaper_plan_equals_derivative(mech, m):
    pos = mech.positions(m=m)
    assert_plan_matches_derivative(mech, pos, mech.velocity_plans(pos))


@settings(deadline=None, max_examples=25)
@given(mech=st.one_of(slider_cranks(), four_bars(), slotted_levers(), shapers()),
       phi=st.lists(st.floats(-20.0, 20.0), min_size=1, max_size=30))
def test_plan_equals_derivative_at_any_angles(mech, phi):
    pos = mech.positions(phi=phi)
    assert_plan_matches_derivative(mech, pos, mech.velocity_plans(pos))


@pytest.mark.parametrize("mech, names", [
    (SliderCrank(r=0.1, l=0.4, e=0.02, points={"S2": ("AB", 0.13, 0.3)}), ["A", "B", "S2"]),
    (SliderCrank(r=0.1, l=0.3, e=-0.05, assembly=-1, sense=-1, points={"S2": ("BA", 0.1, -0.4)}), ["B", "S2"]),
    (FourBar(l1=0.3, l2=0.08, l3=0.25, l4=0.2, ground_angle=0.4, points={"K": ("AB", 0.1, 0.7)}), ["A", "B", "K"]),
    (FourBar(l1=0.3, l2=0.08, l3=0.25, l4=0.2, assembly=-1), ["B"]),
    (FourBar(l1=0.05, l2=0.2, l3=0.25, l4=0.22), ["B"]),                      # double crank
    (SlottedLever(r=0.1, l_O1O3=0.3, l_O3B=0.5, theta_O3=0.3, points={"S3": ("O3B", 0.2, 0.1)}), ["A", "B", "S3"]),
    (Shaper(r=0.11, l_O1O3=0.38, l_O3B=0.54, l_BC=0.135, y_guide=0.1484, points={"S4": ("BC", 0.07, 0.2)}),
     ["B", "C", "S4"]),
    (Shaper(r=0.11, l_O1O3=0.38, l_O3B=0.54, l_BC=0.3, y_guide=0.05, assembly=-1, sense=-1), ["B", "C"]),
])
def test_analytic_derivative_agrees_with_finite_differences(mech, names):
    # A3 is the rocker's point under A: its velocity is not the derivative of A's coordinates
    fd_check(mech, np.linspace(0.05, 2 * np.pi, 97), names)


# ---------------------------------------------------------------------------------- plan geometry
def test_slider_crank_plan_closes_and_similarity():
    mech = SliderCrank(r=0.1, l=0.4, e=0.02, points={"S2": ("AB", 0.13, 0.5)})
    pos = mech.positions(m=36)
    plan = mech.velocity_plans(pos, omega_1=31.4)
    a, b, s = plan.v("A"), plan.v("B"), plan.v("S2")
    A, B, S = pos.xy("A"), pos.xy("B"), pos.xy("S2")
    assert np.all(b[:, 1] == 0.0)                                  # b on the guide line through p
    assert np.abs(np.sum((b - a) * (B - A), axis=1)).max() < 1e-12  # v_BA ⟂ AB
    w2 = plan.omega("AB")
    ws = np.stack([-w2 * (S - A)[:, 1], w2 * (S - A)[:, 0]], axis=1)
    np.testing.assert_allclose(s - a, ws, atol=1e-12)              # similarity: v_SA = ω₂ × AS
    np.testing.assert_allclose(plan.speed("A"), 31.4 * 0.1, rtol=1e-14)
    for ln in plan.lines("B"):                                     # b lies on both construction lines
        rel = b - ln.point
        assert np.abs(rel[:, 0] * ln.direction[:, 1] - rel[:, 1] * ln.direction[:, 0]).max() < 1e-12
    assert [ln.label for ln in plan.lines("B")] == ["⟂ AB", "∥ guide"]
    assert plan.constructions["S2"].method == "similarity" and plan.label("S2") == "s2" and plan.label("O") == "p"


def test_four_bar_plan_lines_and_rocker():
    mech = FourBar(l1=0.3, l2=0.08, l3=0.25, l4=0.2)
    pos = mech.positions(m=24)
    plan = mech.velocity_plans(pos)
    b, B, O2 = plan.v("B"), pos.xy("B"), pos.xy("O2")
    assert np.abs(np.sum(b * (B - O2), axis=1)).max() < 1e-14       # v_B ⟂ O2B
    for ln in plan.lines("B"):
        rel = b - ln.point
        assert np.abs(rel[:, 0] * ln.direction[:, 1] - rel[:, 1] * ln.direction[:, 0]).max() < 1e-14
    np.testing.assert_allclose(plan.speed("B"), np.abs(plan.omega(3)) * 0.2, atol=1e-15)


def test_slotted_lever_proportion_and_relative_velocity():
    mech = SlottedLever(r=0.1, l_O1O3=0.3, l_O3B=0.5)
    pos = mech.positions(m=24)
    plan = mech.velocity_plans(pos, omega_1=5.0)
    O3A = pos.xy("A") - pos.xy("O3")
    rho = np.hypot(O3A[:, 0], O3A[:, 1])
    np.testing.assert_allclose(plan.v("B"), plan.v("A3") * (0.5 / rho)[:, None], atol=1e-15)
    rel = plan.v_rel("A3", "A")                                     # v_A3A2 ∥ rocker
    assert np.abs(rel[:, 0] * O3A[:, 1] - rel[:, 1] * O3A[:, 0]).max() < 1e-14
    np.testing.assert_array_equal(plan.omega(2), plan.omega(3))
    assert plan.constructions["B"].method == "proportion"


# ---------------------------------------------------------------------------------- positions and strokes
@settings(deadline=None, max_examples=30)
@given(mech=st.one_of(slider_cranks(), four_bars(), slotted_levers(), shapers()), m=st.integers(3, 48))
def test_numbering_from_the_working_stroke(mech, m):
    pos = mech.positions(m=m)
    st_ = pos.strokes
    assert st_ is not None or isinstance(mech, FourBar)
    assert pos.n == m + 1 and list(pos.index) == list(range(m + 1))
    assert pos.phi[m] == pos.phi[0]
    np.testing.assert_allclose(pos.phi_from_start, 2 * np.pi * np.arange(m + 1) / m, rtol=0, atol=1e-15)
    steps = np.mod(mech.sense * np.diff(pos.phi), 2 * np.pi)
    np.testing.assert_allclose(steps[:-1], 2 * np.pi / m, atol=1e-12)
    if st_ is None:
        return
    assert abs(pos.phi[0] - st_.phi_start) < 1e-15
    assert pos.extreme[0] and pos.extreme[m]
    assert math.isclose(st_.working_angle + st_.return_angle, 2 * np.pi)
    assert math.isclose(st_.K, st_.working_angle / st_.return_angle)
    slow = mech.working_stroke in ("slow",)
    if slow:
        assert st_.working_angle >= np.pi - 1e-12
    expected = pos.phi_from_start <= st_.working_angle + 1e-13
    expected[m] = True                                              # position m is position 0
    np.testing.assert_array_equal(pos.working, expected)


@settings(deadline=None, max_examples=30)
@given(mech=st.one_of(slider_cranks(), four_bars(), slotted_levers(), shapers()))
def test_extreme_positions_are_exact(mech):
    st_ = mech.strokes()
    assume(st_ is not None)
    out = next(iter(mech.guides), "B")        # the slider, else the rocker's end B
    d_xy, _ = mech.derivatives([st_.phi_start, st_.phi_end])
    scale = np.abs(mech.derivatives(np.linspace(0, 2 * np.pi, 361))[0][out]).max()
    assert np.abs(d_xy[out]).max() <= 1e-12 * scale                # the output stands still there
    pos = mech.positions(phi=np.linspace(0, 2 * np.pi, 3001))
    if pos.s is not None:
        assert pos.s.min() >= -1e-12 * pos.H and pos.s.max() <= pos.H * (1 + 1e-12)
    if pos.psi is not None:
        assert pos.psi.min() >= -1e-12 and pos.psi.max() <= pos.psi_max + 1e-12
    plan = mech.velocity_plans(mech.positions(phi=[st_.phi_start, st_.phi_end]))
    assert np.all(plan.v(out) == 0.0)


def test_slider_crank_strokes_closed_form():
    mech = SliderCrank(r=0.1, l=0.4, e=0.02)
    st_ = mech.strokes()
    far = math.atan2(0.02, math.sqrt(0.5 ** 2 - 0.02 ** 2))
    near = math.atan2(-0.02, -math.sqrt(0.3 ** 2 - 0.02 ** 2)) % (2 * math.pi)
    # the core finds the dead centres by Newton on the slider's velocity: a few ulp of the closed form
    assert st_.phi_start == pytest.approx(far, abs=4e-15) and st_.phi_end == pytest.approx(near, abs=4e-15)
    assert st_.working_angle == pytest.approx(near - far, rel=1e-14)
    pos = mech.positions(m=12)
    assert pos.H == pytest.approx(math.sqrt(0.25 - 4e-4) - math.sqrt(0.09 - 4e-4), rel=1e-14)
    assert np.hypot(*pos.xy("B")[0]) == pytest.approx(0.5, rel=1e-15)      # far dead centre
    away = SliderCrank(r=0.1, l=0.4, e=0.02, working_stroke="away_from_crank").positions(m=12)
    assert np.hypot(*away.xy("B")[0]) == pytest.approx(0.3, rel=1e-15)
    assert away.strokes.K == pytest.approx(1 / st_.K, rel=1e-14)
    centred = SliderCrank(r=0.1, l=0.4).positions(m=12)
    assert centred.K == 1.0 and centred.H == pytest.approx(0.2) and centred.extreme[6]


def test_slotted_lever_and_four_bar_closed_forms():
    sl = SlottedLever(r=0.1, l_O1O3=0.3, l_O3B=0.5)
    theta = 2 * math.asin(0.1 / 0.3)
    assert sl.strokes().K == pytest.approx((math.pi + theta) / (math.pi - theta), rel=1e-14)
    assert sl.positions(m=6).psi_max == pytest.approx(theta, rel=1e-14)
    fast = SlottedLever(r=0.1, l_O1O3=0.3, l_O3B=0.5, working_stroke="fast").strokes()
    assert fast.working_angle == pytest.approx(math.pi - theta, rel=1e-14)
    fb = FourBar(l1=0.3, l2=0.08, l3=0.25, l4=0.2)
    pos = fb.positions(phi=np.linspace(0, 2 * np.pi, 200001))
    st_ = fb.strokes()
    i, j = np.argmin(pos.psi), np.argmax(pos.psi)
    assert abs(pos.phi[i] - st_.phi_start) < 1e-4 and abs(pos.phi[j] - st_.phi_end) < 1e-4
    assert fb.grashof == "crank-rocker" and FourBar(l1=0.05, l2=0.2, l3=0.25, l4=0.22).grashof == "double-crank"


def test_clockwise_crank_is_the_mirror_image():
    ccw = SliderCrank(r=0.1, l=0.35, e=-0.03, points={"S2": ("AB", 0.1, 0.2)})
    cw = SliderCrank(r=0.1, l=0.35, e=0.03, sense=-1, points={"S2": ("AB", 0.1, -0.2)})
    p1, p2 = ccw.positions(m=12), cw.positions(m=12)
    np.testing.assert_allclose(np.mod(-p1.phi, 2 * np.pi) % (2 * np.pi), p2.phi % (2 * np.pi), atol=1e-13)
    v1, v2 = ccw.velocity_plans(p1), cw.velocity_plans(p2)
    for k in ("A", "B", "S2"):
        np.testing.assert_allclose(v1.v(k) * [1, -1], v2.v(k), atol=1e-14)
    np.testing.assert_allclose(v1.omega(2), -v2.omega(2), atol=1e-14)


def test_positions_by_phi_from_start_and_s():
    mech = SliderCrank(r=0.1, l=0.4, e=0.02)
    a = mech.positions(m=8)
    b = mech.positions(phi_from_start=np.arange(9) * np.pi / 4)
    np.testing.assert_allclose(a.xy("B"), b.xy("B"), atol=1e-15)
    assert a.s[0] == 0.0 and np.all(a.s >= 0) and a.stroke_direction.tolist() == [-1.0, 0.0]
    assert b.m is None and b.index is None


def test_velocity_plans_at_a_speed_scale_linearly():
    mech = FourBar(l1=0.3, l2=0.08, l3=0.25, l4=0.2, points={"S2": ("AB", 0.1, 0.0)})
    pos = mech.positions(m=12)
    p1, p2 = mech.velocity_plans(pos), mech.velocity_plans(pos, omega_1=7.5)
    np.testing.assert_allclose(p2.v("S2"), 7.5 * p1.v("S2"), rtol=1e-14, atol=1e-16)
    np.testing.assert_allclose(p2.analogue("S2"), p1.v("S2"), rtol=1e-14, atol=1e-16)
    np.testing.assert_allclose(p2.omega_ratio("AB"), p1.omega("AB"), rtol=1e-14, atol=1e-16)


# ---------------------------------------------------------------------------------- API and errors
def test_plan_api():
    mech = SliderCrank(r=0.1, l=0.4, points={"S2": ("AB", 0.13)})
    plan = mech.velocity_plans(12)
    assert isinstance(plan, VelocityPlans) and isinstance(plan.positions, Positions)
    np.testing.assert_array_equal(plan.omega(2), plan.omega("BA"))
    np.testing.assert_array_equal(plan.v_along_guide("B"), plan.v("B")[:, 0])
    assert plan.order == ("O", "A", "B", "S2")
    assert plan.mu_v(pa_mm=50.0) == 0.002 and plan.mu_v(pa_mm=60.0) == 0.002
    assert plan.mu_v(pa_mm=60.0, convenient=False) == pytest.approx(0.1 / 60)
    with pytest.raises(InputError, match="exactly one"):
        plan.mu_v()
    with pytest.raises(InputError, match="no point 'Z'"):
        plan.v("Z")
    with pytest.raises(InputError, match="does not move along a guide"):
        plan.v_along_guide("A")
    with pytest.raises(InputError, match="unknown link"):
        plan.omega("XY")
    with pytest.raises(InputError, match="no link number 5"):
        plan.omega(5)
    with pytest.raises(ValueError):          # read-only results
        plan.v("B")[0, 0] = 1.0
    assert convenient_scale(0.0213) == 0.025 and convenient_scale(1e-7) == 1e-7


@pytest.mark.parametrize("make, match", [
    (lambda: SliderCrank(r=-0.1, l=0.4), "r must be > 0"),
    (lambda: SliderCrank(r=float("nan"), l=0.4), "r must be finite"),
    (lambda: SliderCrank(r="0.1", l=0.4), "r must be a number"),
    (lambda: SliderCrank(r=0.1, l=0.4, assembly=2), "assembly must be"),
    (lambda: SliderCrank(r=0.1, l=0.4, sense=0), "sense must be"),
    (lambda: SliderCrank(r=0.1, l=0.4, working_stroke="up"), "working_stroke must be one of"),
    (lambda: SliderCrank(r=0.1, l=0.4, points={"S2": ("BC", 0.1)}), "unknown link 'BC'"),
    (lambda: SliderCrank(r=0.1, l=0.4, points={"A": ("AB", 0.1)}), "clashes with a joint"),
    (lambda: SliderCrank(r=0.1, l=0.4, points={"S2": ("AB", -0.1)}), "distance must be ≥ 0"),
    (lambda: SliderCrank(r=0.1, l=0.4, points={"S2": 0.1}), "give \\(link, distance_m\\)"),
    (lambda: SliderCrank(r=0.1, l=0.4).positions(m=2), "integer ≥ 3"),
    (lambda: SliderCrank(r=0.1, l=0.4).positions(m=3.5), "integer ≥ 3"),
    (lambda: SliderCrank(r=0.1, l=0.4).positions(phi=[0.0, float("inf")]), "angle #1"),
    (lambda: SliderCrank(r=0.1, l=0.4).positions(phi=[]), "at least one"),
    (lambda: SliderCrank(r=0.1, l=0.4).positions(m=4, phi=[0.0]), "only one"),
    (lambda: SliderCrank(r=0.1, l=0.4).velocity_plans(omega_1=-1.0), "must be > 0"),
    (lambda: SliderCrank(r=0.1, l=0.4).velocity_plans(SliderCrank(r=0.1, l=0.5).positions(4)), "same linkage"),
    (lambda: SlottedLever(r=0.3, l_O1O3=0.3, l_O3B=0.7), "pass through the rocker's pivot"),
    (lambda: SlottedLever(r=0.1, l_O1O3=0.3, l_O3B=0.35), "the pin would leave the slot"),
])
def test_bad_input_is_a_clear_error(make, match):
    with pytest.raises(GraphmethodsError, match=match):
        make()
