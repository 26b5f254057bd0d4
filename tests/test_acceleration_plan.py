"""The acceleration plan construction (kinematics/acceleration_plan.py): constructed, closed, textbook."""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

from graphmethods.errors import InputError
from graphmethods.kinematics import acceleration_plan as AP
from graphmethods.kinematics.acceleration_plan import acceleration_plan, acceleration_plans
from graphmethods.kinematics.groups import PRP, RPP, RPR, RRP, Guide
from graphmethods.kinematics.linkage import Crank, Linkage, Point
from graphmethods.kinematics.presets import four_bar, slider_crank, slotted_lever
from graphmethods.problems import builtin


def _core(lk: Linkage, **kw):
    return lk.motion(level=2, **kw)


def _worst(lk: Linkage, plans, mo) -> tuple[float, float]:
    """Largest |a_plan − a_core| over points and |ε_plan − ε_core|·l over links, and the largest |a|."""
    err, big = 0.0, 0.0
    n = mo.phi.shape
    for i, p in enumerate(plans):
        for pt in p.labels:
            if pt not in mo.a_:                    # a triad's special point K: a construction point only
                continue
            ref = complex(np.broadcast_to(mo.a_[pt], n)[i])
            err = max(err, abs(p.a(pt) - ref))
            big = max(big, abs(ref))
        for link, e in p.epsilon.items():
            ref_e = float(np.broadcast_to(mo.epsilon[link], n)[i])
            err = max(err, abs(e - ref_e) * p.lengths.get(link, 1.0))
    return err, big


def _odd_linkages() -> list[Linkage]:
    """A Scotch yoke (RPP) and a slotted lever driving a PRP and an RRP on its moving slot."""
    yoke = Linkage(ground={"O": (0.0, 0.0)}, crank=Crank("O", "A", r=0.1),
                   groups=[RPP(P="A", R="C", coincident="A3", guide=Guide("0", 0.05j, 0.3), slot_angle=1.2)],
                   points=[Point("S3", "3", "C", 0.1, 0.5)])
    lever = Linkage(ground={"O1": (0.0, 0.0), "O3": (0.0, -0.3)}, crank=Crank("O1", "A", r=0.1),
                    groups=[RPR(P="A", Q="O3", coincident="A3", links=("2", "3")),
                            PRP(C="D", guide_1=Guide("3", "B", 0.2), guide_2=Guide("0", 0.4j, 0.1), links=("4", "5")),
                            RRP(P="D", C="E", l=0.3, guide=Guide("3", "B", 0.0), links=("6", "7"))],
                    points=[Point("B", "3", "O3", 0.5), Point("S4", "4", "D", 0.05, 1.0),
                            Point("S7", "7", "E", 0.05, 1.0)], output="5")
    return [yoke, lever]


@pytest.mark.parametrize("name", list(builtin.LINKAGES))
@pytest.mark.parametrize("epsilon_1", [0.0, 7.3])
def test_every_builtin_problem_every_position_equals_the_core(name, epsilon_1):
    case = builtin.case(name)
    lk = case.linkage
    plans = acceleration_plans(lk, m=12, omega_1=case.omega_m, epsilon_1=epsilon_1)
    mo = _core(lk, m=12, omega_1=case.omega_m, epsilon_1=epsilon_1)
    err, big = _worst(lk, plans, mo)
    assert err <= 1e-12 * max(big, 1.0), (err, big)
    special = {g.special for g in lk.groups if g.cls == 3}          # a triad's Assur point has one too
    assert set(plans[0].labels) == set(mo.a_) | special             # every point has its image


@pytest.mark.parametrize("which", [0, 1])
def test_prp_rpp_and_guides_on_a_moving_link_equal_the_core(which):
    lk = _odd_linkages()[which]
    for eps in (0.0, -2.5):
        plans = acceleration_plans(lk, phi=np.linspace(0.1, 6.0, 9), omega_1=4.0, epsilon_1=eps)
        err, big = _worst(lk, plans, _core(lk, phi=np.linspace(0.1, 6.0, 9), omega_1=4.0, epsilon_1=eps))
        assert err <= 1e-12 * max(big, 1.0)


def test_the_plan_does_not_read_the_cores_accelerations(monkeypatch):
    """The core solved only to velocities (level=1): the accelerations are built by the plan."""
    levels = []
    real = Linkage.motion

    def spy(self, *a, **kw):
        levels.append(kw.get("level", 2))
        return real(self, *a, **kw)

    monkeypatch.setattr(Linkage, "motion", spy)
    acceleration_plans(builtin.case("shaper").linkage, m=12, omega_1=5.0)
    assert levels == [1]


@pytest.mark.parametrize("mutation", ["meet", "normal", "coriolis"])
def test_a_mutated_construction_fails_the_comparison(monkeypatch, mutation):
    lk = builtin.case("shaper").linkage                # RPR (Coriolis) + RRP
    if mutation == "meet":                             # take the line's own point, not the intersection
        monkeypatch.setattr(AP._Builder, "meet", lambda self, l1, l2, where: (l1.point, 1.0))
    elif mutation == "normal":                         # a^n away from the centre instead of toward it
        real = AP._Builder.normal
        monkeypatch.setattr(AP._Builder, "normal", lambda self, link, p, c: -real(self, link, p, c))
    else:                                              # v_rel turned against the sense of ω₃
        real_rpr = AP._Builder.rpr

        def rpr(self, g):
            self.w[g.links[1]] = -self.w[g.links[1]]
            real_rpr(self, g)
            self.w[g.links[1]] = -self.w[g.links[1]]
        monkeypatch.setattr(AP._Builder, "rpr", rpr)
    plans = acceleration_plans(lk, m=12, omega_1=5.0)
    err, big = _worst(lk, plans, _core(lk, m=12, omega_1=5.0))
    assert err > 1e-3 * big


def test_the_plan_closes_every_image_lies_on_both_lines_and_sums_hold():
    for name in ("press", "shaper", "four-bar", "slotted-lever", "six-bar-press", "triad-six-bar"):
        for p in acceleration_plans(builtin.case(name).linkage, m=12, omega_1=3.0, epsilon_1=1.5):
            for s in p.steps:
                here = p.images[s.label]
                for ln in s.lines:                     # distance of the image from each line
                    d = here - ln.point
                    assert abs(d.real * ln.direction.imag - d.imag * ln.direction.real) <= 1e-12 * max(p.largest, 1)
                for c in s.components:                 # every drawn vector joins its two images
                    assert abs(p.images[c.end] - p.images[c.start] - c.vector) <= 1e-12 * max(p.largest, 1)
                if s.method == "intersection":         # both chains of the equation reach the image
                    found = [c for c in s.components if not c.known and c.kind != "absolute"]
                    for c in found:
                        assert abs(p.images[c.end] - here) <= 1e-12 * max(p.largest, 1)


def test_normal_components_point_to_the_centre_with_length_omega_squared_l():
    lk = builtin.case("six-bar-press").linkage
    p = acceleration_plan(lk, 4, omega_1=8.0)
    mo = lk.motion(m=12, omega_1=8.0, level=1)
    z = {k: complex(v[4]) for k, v in mo.z.items()}
    seen = 0
    for s in p.steps:
        for c in s.components:
            if c.kind == "normal" and s.method == "intersection":
                point, centre = s.point, c.symbol.split("_", 1)[1][len(s.point):]
                link = next(k for k in ("2", "3", "4") if p.lengths.get(k) and
                            abs(p.lengths[k] - abs(z[point] - z[centre])) < 1e-12)
                w = p.omega[link]
                assert abs(c.magnitude - w * w * abs(z[point] - z[centre])) < 1e-12
                assert abs(cmath.phase(c.vector / (z[centre] - z[point]))) < 1e-9      # toward the centre
                seen += 1
    assert seen == 3


def test_khurmi_example_8_1_slider_crank_midpoint_of_the_rod():
    """Khurmi & Gupta, Theory of Machines, Example 8.1: crank 150 mm, rod 600 mm, 300 rev/min clockwise,
    45° from the inner dead centre. By measurement on the plan: a_D = 117 m/s² (D the rod's middle),
    α_AB = a^τ_BA/BA = 103/0.6 = 171.67 rad/s²; ω_AB = 5.67 rad/s from the velocity plan."""
    w = 300 * 2 * math.pi / 60
    lk = slider_crank(r=0.15, l=0.6, points={"D": ("AB", 0.3)}, sense=-1)
    p = acceleration_plan(lk, phi=math.radians(45.0), omega_1=w)
    assert abs(p.a("D")) == pytest.approx(117.0, rel=0.01)
    assert abs(p.epsilon["2"]) == pytest.approx(171.67, rel=0.01)
    assert abs(p.omega["2"]) == pytest.approx(5.67, rel=0.01)
    tau = next(c for c in p.steps[1].components if c.symbol == "a^τ_BA")
    assert tau.magnitude == pytest.approx(103.0, rel=0.01)
    # the image d halves ab (similarity)
    assert abs(p.a("D") - (p.a("A") + p.a("B")) / 2) < 1e-12


def test_centric_slider_crank_speeding_up_by_hand():
    """x = r cos φ + √(l² − r² sin² φ); a_B = x''·ω² + x'·ε (φ the crank angle, turning ccw)."""
    r, l, w, e = 0.1, 0.35, 12.0, 40.0
    lk = slider_crank(r=r, l=l)
    for phi in np.linspace(0.2, 6.1, 7):
        s, c = math.sin(phi), math.cos(phi)
        root = math.sqrt(l * l - r * r * s * s)
        x1 = -r * s - r * r * s * c / root
        x2 = -r * c - r * r * (c * c - s * s) / root - r ** 4 * s * s * c * c / root ** 3
        p = acceleration_plan(lk, phi=float(phi), omega_1=w, epsilon_1=e)
        assert p.a("B").real == pytest.approx(x2 * w * w + x1 * e, abs=1e-11)
        assert abs(p.a("B").imag) < 1e-12
        crank = p.steps[0]
        assert [c.symbol for c in crank.components] == ["a^n_A", "a^τ_A", "a_A"]
        tau = crank.components[1].vector
        assert abs(tau) == pytest.approx(e * r, rel=1e-13)
        assert abs(tau - 1j * e * r * cmath.exp(1j * phi)) < 1e-13      # ⟂ OA, in the sense of ε₁


def test_slotted_lever_coriolis_by_hand_in_polar_coordinates():
    """ρ = |O3A|: a_A·e_ψ = ρψ̈ + 2ρ̇ψ̇, so ε₃ = (a_A·e_ψ − 2ρ̇ψ̇)/ρ; a^k = 2ω₃v_rel along e_ψ
    (v_rel turned 90° in the sense of ω₃)."""
    r, d, w = 0.1, 0.3, 10.0
    lk = slotted_lever(r=r, l_O1O3=d, l_O3B=0.6)
    O3 = -1j * d
    for phi in np.linspace(0.3, 6.0, 6):
        A = r * cmath.exp(1j * phi)
        vA = 1j * w * A
        aA = -w * w * A
        R = A - O3
        rho = abs(R)
        er, ep = R / rho, 1j * R / rho
        rho_dot = (vA * er.conjugate()).real
        psi_dot = (vA * ep.conjugate()).real / rho
        eps3 = ((aA * ep.conjugate()).real - 2 * rho_dot * psi_dot) / rho
        p = acceleration_plan(lk, phi=float(phi), omega_1=w)
        assert p.omega["3"] == pytest.approx(psi_dot, rel=1e-12)
        assert p.epsilon["3"] == pytest.approx(eps3, rel=1e-10, abs=1e-10)
        ak = next(c for c in p.steps[1].components if c.kind == "coriolis")
        v_rel = 1j * psi_dot * R - vA                  # v_A3A2 = v_A3 − v_A2 = −ρ̇·e_ρ
        assert abs(v_rel + rho_dot * er) < 1e-12
        assert abs(ak.vector - 2j * psi_dot * v_rel) < 1e-12          # v_rel turned 90° in the sense of ω₃
        assert abs(ak.vector + 2 * psi_dot * rho_dot * ep) < 1e-12
        # a_A3 = a_A2 + a^k + a^r with a^r ∥ the slot
        ar = next(c for c in p.steps[1].components if c.kind == "relative")
        assert abs((ar.vector * er.conjugate()).imag) < 1e-12


def test_four_bar_angular_accelerations_by_finite_differences_of_positions():
    """θ₂, θ₃ of the four-bar from the positions only; ε = θ''·ω² at constant ω (Richardson)."""
    lk = four_bar(l1=0.3, l2=0.1, l3=0.35, l4=0.25)
    w = 6.0

    def theta(phi):
        mo = lk.motion(phi=[phi], level=0)
        return np.array([float(np.unwrap([mo.theta["2"][0]])[0]), float(mo.theta["3"][0])])

    for phi in (0.4, 1.9, 3.3, 5.0):
        def d2(h, phi=phi):
            return (theta(phi + h) - 2 * theta(phi) + theta(phi - h)) / h ** 2
        ref = (4 * d2(1e-3) - d2(2e-3)) / 3 * w * w
        p = acceleration_plan(lk, phi=phi, omega_1=w)
        assert p.epsilon["2"] == pytest.approx(ref[0], rel=1e-5, abs=1e-5)
        assert p.epsilon["3"] == pytest.approx(ref[1], rel=1e-5, abs=1e-5)


def test_equations_as_the_book_writes_them():
    sh = acceleration_plan(builtin.case("shaper").linkage, 2, omega_1=5.0)
    eqs = [s.equation for s in sh.steps if s.method == "intersection"]
    assert eqs[0] == "a_A3 = a_A2 + a^k_A3A2 + a^r_A3A2 = a_O3 + a^n_A3O3 + a^τ_A3O3"
    assert eqs[1] == "a_C = a_B + a^n_CB + a^τ_CB"
    fb = acceleration_plan(builtin.case("four-bar").linkage, 2, omega_1=5.0)
    assert fb.steps[1].equation == "a_B = a_A + a^n_BA + a^τ_BA = a_O2 + a^n_BO2 + a^τ_BO2"
    assert [ln.label for ln in fb.steps[1].lines] == ["⟂ AB", "⟂ O2B"]


def test_bad_input_says_what_to_do():
    lk = slider_crank(r=0.1, l=0.4)
    with pytest.raises(InputError, match="position must be an integer from 0 to m = 12"):
        acceleration_plan(lk, 13)
    with pytest.raises(InputError, match="exactly one of position"):
        acceleration_plan(lk)
    with pytest.raises(InputError, match="needs a Linkage"):
        acceleration_plans("press")                    # type: ignore[arg-type]
    with pytest.raises(InputError, match="no point 'Z'"):
        acceleration_plan(lk, 1).a("Z")
    with pytest.raises(InputError, match="omega_1"):
        acceleration_plan(lk, 1, omega_1=0.0)


@settings(max_examples=60, deadline=None, derandomize=True)
@given(kind=st.sampled_from(["slider-crank", "four-bar", "slotted-lever"]),
       a=st.floats(0.05, 0.2), ratio=st.floats(2.2, 5.0), e=st.floats(-0.5, 0.5), phi=st.floats(0.0, 6.28),
       w=st.floats(0.5, 50.0), eps=st.floats(-100.0, 100.0), sense=st.sampled_from([1, -1]))
def test_any_textbook_linkage_any_angle_is_the_core(kind, a, ratio, e, phi, w, eps, sense):
    """Property: for random dimensions, crank angle, ω₁ and ε₁ the constructed plan is the core's answer."""
    from graphmethods.errors import AssemblyError

    if kind == "slider-crank":
        lk = slider_crank(r=a, l=a * ratio, e=e * a, sense=sense, points={"S2": ("AB", a * ratio / 3, 0.4)})
    elif kind == "four-bar":
        lk = four_bar(l1=a * ratio, l2=a, l3=a * ratio * (0.9 + e / 2), l4=a * ratio * 0.7, sense=sense,
                      points={"S2": ("AB", a, 0.3)})
    else:
        lk = slotted_lever(r=a, l_O1O3=a * ratio, l_O3B=a * ratio * 2, sense=sense)
    try:
        core = lk.motion(phi=[phi], omega_1=w, epsilon_1=eps)
    except (AssemblyError, InputError):
        assume(False)
    plan = acceleration_plans(lk, phi=[phi], omega_1=w, epsilon_1=eps)
    assume(min(s.sin_between for s in plan[0].steps) > 1e-3)            # away from a toggle
    err, big = _worst(lk, plan, core)
    assert err <= 1e-9 * max(big, 1.0)
