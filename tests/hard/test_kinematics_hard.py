"""Hard positions of the linkages: dead centres, a four-bar next to its toggle, impossible dimensions."""

import math
from decimal import Decimal, getcontext

import numpy as np
import pytest

from graphmethods.errors import AssemblyError
from graphmethods.kinematics import FourBar, Shaper, SliderCrank, SlottedLever

pytestmark = pytest.mark.hard


# ------------------------------------------------------------------ a 50-digit reference four-bar
def _sin_cos(x: float):
    getcontext().prec = 60
    x = Decimal(x)
    s, c, ts, tc, k = Decimal(0), Decimal(0), x, Decimal(1), 0
    while abs(ts) > Decimal(10) ** -58 or abs(tc) > Decimal(10) ** -58:
        s, c = s + ts, c + tc
        ts = -ts * x * x / ((2 * k + 2) * (2 * k + 3))
        tc = -tc * x * x / ((2 * k + 1) * (2 * k + 2))
        k += 1
    return s, c


def four_bar_reference(l1, l2, l3, l4, phi, sigma=1):
    """ω_coupler, ω_rocker for ω₁ = 1 (ground along +x), in 60-digit decimal arithmetic from the
    float inputs taken as exact: the circle intersection, then v_A + ω₂ × AB = ω₃ × O2B solved by
    Cramer's rule."""
    getcontext().prec = 60
    l1, l2, l3, l4 = (Decimal(v) for v in (l1, l2, l3, l4))
    s, c = _sin_cos(phi)
    Ax, Ay = l2 * c, l2 * s
    Dx, Dy = l1 - Ax, -Ay
    d = (Dx * Dx + Dy * Dy).sqrt()
    h = ((l3 + l4 - d) * (d + l4 - l3) * (d + l3 - l4) * (d + l3 + l4)).sqrt() / (2 * d)
    a = (l3 * l3 - l4 * l4 + d * d) / (2 * d)
    Bx, By = Ax + (a * Dx - sigma * h * Dy) / d, Ay + (a * Dy + sigma * h * Dx) / d
    P1x, P1y = -(By - Ay), Bx - Ax          # ⟂ AB
    P2x, P2y = -By, Bx - l1                 # ⟂ O2B
    det = -P1x * P2y + P2x * P1y            # w2·P1 − w3·P2 = −v_A,  v_A = (−Ay, Ax)
    w2 = (-Ay * P2y - P2x * Ax) / det
    w3 = (P1x * -Ax - P1y * Ay) / det
    return float(w2), float(w3)


# ------------------------------------------------------------------ dead centres of the slider-crank
@pytest.mark.parametrize("e, assembly, sense", [(0.02, 1, 1), (0.0, 1, 1), (-0.03, -1, 1), (0.02, 1, -1)])
def test_slider_crank_dead_centres_give_b_at_the_pole(e, assembly, sense):
    """At both dead centres v_B = 0 exactly (b coincides with p) and the plan has no NaN.

    There the line through a ⟂ AB passes through p (it coincides with the line of pa), so b is
    the pole itself; the rod turns at ω₂ = ∓ω₁ r/l (far / near dead centre)."""
    r, l, w1 = 0.1, 0.4, 31.4
    mech = SliderCrank(r=r, l=l, e=e, assembly=assembly, sense=sense, points={"S2": ("AB", 0.13)})
    st = mech.strokes()
    pos = mech.positions(phi=[st.phi_start, st.phi_end, st.phi_start + 2 * math.pi, st.phi_end - 2 * math.pi])
    plan = mech.velocity_plans(pos, omega_1=w1)
    assert pos.extreme.all() and not plan.ill_conditioned.any()
    assert np.all(plan.v("B") == 0.0)
    for arr in list(plan.vectors.values()) + list(plan.omegas.values()):
        assert np.isfinite(arr).all()
    Om = sense * w1
    np.testing.assert_allclose(plan.omega("AB"), [-Om * r / l, Om * r / l] * 2, rtol=1e-13)
    np.testing.assert_allclose(plan.v("A"), -plan.v_rel("B", "A"), rtol=0, atol=0)   # ab = −pa exactly
    a, line = plan.v("A"), plan.lines("B")[0]                                       # ⟂ AB through a ∥ pa
    assert np.abs(a[:, 0] * line.direction[:, 1] - a[:, 1] * line.direction[:, 0]).max() < 1e-14 * w1 * r
    full = mech.velocity_plans(mech.positions(m=12), omega_1=w1)
    assert np.all(full.v("B")[[0, 12]] == 0.0)
    if e == 0.0:
        assert np.all(full.v("B")[6] == 0.0)                                          # both dead centres at m = 12


def test_dead_centres_of_all_linkages_stop_the_output():
    cases = [(FourBar(l1=0.3, l2=0.08, l3=0.25, l4=0.2), ["B"], ["O2B"]),
             (SlottedLever(r=0.1, l_O1O3=0.3, l_O3B=0.5), ["A3", "B"], ["O3B", "block"]),
             (Shaper(r=0.11, l_O1O3=0.38, l_O3B=0.54, l_BC=0.135, y_guide=0.1484), ["A3", "B", "C"], ["O3B", "BC"])]
    for mech, points, links in cases:
        st = mech.strokes()
        plan = mech.velocity_plans(mech.positions(phi=[st.phi_start, st.phi_end]), omega_1=5.0)
        for p in points:
            assert np.all(plan.v(p) == 0.0), (mech.kind, p)
        for k in links:
            assert np.all(plan.omega(k) == 0.0), (mech.kind, k)


# ------------------------------------------------------------------ a four-bar next to its toggle
L1, L2, L3, L4 = 0.3, 0.15, 0.2, 0.2      # triple rocker: O1A swings between ±121.86°
PHI_T = math.acos((L1 ** 2 + L2 ** 2 - (L3 + L4) ** 2) / (2 * L1 * L2))   # toggle: |O2A| = l3 + l4


def test_four_bar_within_1e9_rad_of_its_toggle():
    """Lines ⟂ AB and ⟂ O2B nearly parallel: detected, marked, analytic values returned.

    The velocities (≈ 10⁴ ω₁) are as accurate as the input allows: the problem's condition
    number there is ≈ φ/(2·10⁻⁹) ≈ 10⁹, and the result is the exact answer for an angle within
    2 ulp of the one given (backward stable), about 2e-8 relative to a 60-digit reference."""
    mech = FourBar(l1=L1, l2=L2, l3=L3, l4=L4)
    phi = np.array([0.5, PHI_T - 1e-9, -(PHI_T - 1e-9), 1.0])
    pos = mech.positions(phi=phi)
    plan = mech.velocity_plans(pos)
    assert plan.ill_conditioned.tolist() == [False, True, True, False]
    assert np.all(plan.sin_min[1:3] < 1e-4) and np.all(plan.sin_min[[0, 3]] > 0.5)
    d_xy, d_th = mech.derivatives(phi)
    for i in (1, 2):                              # the analytic derivative, not the intersection
        assert plan.omega("O2B")[i] == d_th["O2B"][i] and np.all(plan.v("B")[i] == d_xy["B"][i])
    for arr in list(plan.vectors.values()) + list(plan.omegas.values()):
        assert np.isfinite(arr).all()
    for i, p in enumerate(phi):
        w2, w3 = four_bar_reference(L1, L2, L3, L4, p)
        lo = [four_bar_reference(L1, L2, L3, L4, q)[1] for q in (np.nextafter(np.nextafter(p, -9), -9),
                                                                 np.nextafter(np.nextafter(p, 9), 9))]
        got = plan.omega("O2B")[i]
        assert got == pytest.approx(w3, rel=1e-6) and plan.omega("AB")[i] == pytest.approx(w2, rel=1e-6)
        assert min(lo) <= got <= max(lo) or got == pytest.approx(w3, rel=1e-14)   # backward stable
    assert abs(plan.omega("O2B")[1]) > 1e4


def test_four_bar_at_a_toggle_is_a_clear_error():
    """Exactly at the toggle the rocker's velocity is infinite for a turning crank: an error."""
    mech = FourBar(l1=0.3, l2=0.1, l3=0.25, l4=0.15)          # change point: toggle at φ = 180°
    assert mech.grashof == "change-point"
    with pytest.raises(AssemblyError, match=r"angle #1 \(φ = 180°\).*in line \(toggle\)"):
        mech.velocity_plans(mech.positions(phi=[0.3, math.pi]))


def test_slider_crank_with_rod_just_long_enough():
    """l = r + e + 1e-9 m: at φ = 270° the rod stands almost ⟂ to the guide; marked, finite, analytic."""
    mech = SliderCrank(r=0.1, l=0.12 + 1e-9, e=0.02)
    pos = mech.positions(phi=[1.5 * math.pi, 0.3])
    plan = mech.velocity_plans(pos)
    assert plan.ill_conditioned.tolist() == [True, False]
    d_xy, _ = mech.derivatives(pos.phi)
    assert np.all(plan.v("B") == d_xy["B"])
    assert plan.v_along_guide("B")[0] == pytest.approx(0.1, rel=1e-12)   # v_B = v_A when the rod is ⟂


# ------------------------------------------------------------------ dimensions that cannot be assembled
def test_rod_shorter_than_crank_plus_offset():
    with pytest.raises(AssemblyError) as err:
        SliderCrank(r=0.1, l=0.1, e=0.02)
    msg = str(err.value)
    assert "rod l = 0.1 m is shorter than crank r + |e| = 0.12 m: the slider cannot follow a full crank turn" in msg
    assert "φ in (" in msg
    with pytest.raises(AssemblyError, match="not longer than"):
        SliderCrank(r=0.1, l=0.12, e=-0.02)


def test_four_bar_that_cannot_turn_names_grashof_and_the_range():
    with pytest.raises(AssemblyError) as err:
        FourBar(l1=L1, l2=L2, l3=L3, l4=L4).positions(m=12)
    msg = str(err.value)
    assert "cannot make a full turn" in msg and "Grashof is violated (s + l = 0.45 m > p + q = 0.4 m)" in msg
    assert "φ in (121.9°, 238.1°)" in msg
    with pytest.raises(AssemblyError, match="Grashof holds .* shortest link is the coupler AB"):
        FourBar(l1=0.3, l2=0.25, l3=0.1, l4=0.2).positions(m=12)


def test_four_bar_position_outside_its_range_is_named():
    with pytest.raises(AssemblyError, match=r"angle #1 \(φ = 171.9°\): \|O2A\| = 0.448998 m exceeds l3 \+ l4"):
        FourBar(l1=L1, l2=L2, l3=L3, l4=L4).positions(phi=[0.0, 3.0])
    with pytest.raises(AssemblyError, match="cannot close a loop"):
        FourBar(l1=0.3, l2=0.1, l3=0.1, l4=0.05)


def test_shaper_that_cannot_be_assembled():
    with pytest.raises(AssemblyError, match="cannot reach the ram's guide"):
        Shaper(r=0.11, l_O1O3=0.38, l_O3B=0.54, l_BC=0.135, y_guide=0.3)
    with pytest.raises(AssemblyError, match="comes in line with the rocker"):
        Shaper(r=0.11, l_O1O3=0.38, l_O3B=0.54, l_BC=0.135, y_guide=0.2684)
    with pytest.raises(AssemblyError, match="crank r = 0.4 m is not shorter than the centre distance"):
        Shaper(r=0.4, l_O1O3=0.38, l_O3B=0.9, l_BC=0.135, y_guide=0.2)
