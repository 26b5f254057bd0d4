"""The kinematics core (linkage of Assur groups): velocities and accelerations against independent
derivatives of the positions, closed forms, structure, extreme positions and named hard cases."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

from graphmethods.errors import AssemblyError, InputError
from graphmethods.kinematics import presets
from graphmethods.kinematics.groups import GROUND, PRP, RPP, RPR, RRP, RRR, Guide
from graphmethods.kinematics.linkage import Crank, Linkage, Point

# eighth-order central differences: first and second derivative
C1 = (4 / 5, -1 / 5, 4 / 105, -1 / 280)
C2 = (8 / 5, -1 / 5, 8 / 315, -1 / 560)
C20 = -205 / 72  # = −2·ΣC2: second differences taken from X(φ) need no centre term


def _fd(solves, base, attr, order):
    """Eighth-order central difference (first or second derivative, step h = 1) of ``attr`` of
    ``solves`` = [(+1, −1), (+2, −2), ...]; angles are differenced through exp(i·Δθ)."""
    out = {}
    for k in getattr(base, attr):
        b = getattr(base, attr)[k]
        if attr == "theta":
            d = lambda s, k=k, b=b: np.angle(np.exp(1j * (s.theta[k] - b)))  # noqa: E731 - unwrapped difference
        else:
            d = lambda s, k=k, b=b: getattr(s, attr)[k] - b  # noqa: E731
        if order == 1:
            out[k] = sum(c * (d(p) - d(m)) for c, (p, m) in zip(C1, solves))
        else:
            out[k] = sum(c * (d(p) + d(m)) for c, (p, m) in zip(C2, solves))
    return out


def assert_matches_fd(lk: Linkage, phi, *, omega_1=1.7, epsilon_1=-0.6, rel=1e-9, rel2=1e-7, h=2e-3):
    """Velocities and accelerations against derivatives of the positions (Ω = sense·ω₁, E = sense·ε₁):

    - ``v = X'·Ω`` and ``ω = θ'·Ω`` with X' by 8th-order central differences of the positions, to
      ``rel`` of the largest such quantity of the sample;
    - ``a = X''·Ω² + X'·E`` (and ε) with X'' the difference of the velocities just checked (to
      ``rel``), and again with X'' the second difference of the positions themselves (to ``rel2``:
      a second difference of positions loses about eps·|X|/h² to rounding).
    """
    phi = np.asarray(phi, dtype=float)
    s = lk.solve(phi, omega_1=omega_1, epsilon_1=epsilon_1)
    # a slotted link's point under the block (A3) is a different material point at each instant: its
    # velocity is not the derivative of its (= the block's) positions; it is checked by its own relation
    coincident = {g.coincident for g in lk.groups if hasattr(g, "coincident")}
    for g in lk.groups:
        if hasattr(g, "coincident"):
            Q = g.Q if hasattr(g, "Q") else g.R
            k, k2 = g.links[1], g.coincident
            r = s.z[k2] - s.z[Q]
            vs = np.abs(s.v[g.P]).max()
            assert np.abs(s.v[k2] - s.v[Q] - 1j * s.omega[k] * r).max() <= 1e-12 * vs
    base0 = lk.solve(phi, level=0)
    Om, Ep = lk.sense * omega_1, lk.sense * epsilon_1
    # the differences with steps h (k = 1…4) and 2h (k = 2, 4, 6, 8): their disagreement bounds the
    # truncation error of the reference itself, which near a (still well-conditioned) steep position
    # can exceed ``rel``; a wrong formula gives errors far beyond both
    pos8 = [(lk.solve(phi + k * h, level=0), lk.solve(phi - k * h, level=0)) for k in range(1, 9)]
    base1 = lk.solve(phi, omega_1=1.0, level=1)
    vel8 = [(lk.solve(phi + k * h, omega_1=1.0, level=1), lk.solve(phi - k * h, omega_1=1.0, level=1))
            for k in range(1, 9)]
    pos, vel = pos8[:4], vel8[:4]
    for zkey, vkey, akey in (("z", "v", "a"), ("theta", "omega", "epsilon")):
        X1 = {k: d / h for k, d in _fd(pos, base0, zkey, 1).items()}
        X2p = {k: d / h**2 for k, d in _fd(pos, base0, zkey, 2).items()}
        X2v = {k: d / (h * lk.sense) for k, d in _fd(vel, base1, vkey, 1).items()}   # v(ω₁ = 1) = X′·sense
        X1w = {k: d / (2 * h) for k, d in _fd(pos8[1::2], base0, zkey, 1).items()}
        X2vw = {k: d / (2 * h * lk.sense) for k, d in _fd(vel8[1::2], base1, vkey, 1).items()}
        got_v, got_a = getattr(s, vkey), getattr(s, akey)
        # floors: the crank's own ω₁ and ε₁ (angles), its pin's v and a (points)
        r = lk.crank.r if zkey == "z" else 1.0
        vscale = max(max(np.abs(X1[k] * Om).max() for k in X1), r * abs(Om))
        ascale = max(max(np.abs(X2v[k] * Om**2 + X1[k] * Ep).max() for k in X1), r * math.hypot(Om**2, Ep))
        for k in X1:
            if k in coincident:
                continue
            v_ref_err = np.abs((X1[k] - X1w[k]) * Om)
            a_ref_err = np.abs((X2v[k] - X2vw[k]) * Om**2) + np.abs((X1[k] - X1w[k]) * Ep)
            assert np.all(np.abs(got_v[k] - X1[k] * Om) <= rel * vscale + v_ref_err), f"{vkey} {k}"
            assert np.all(np.abs(got_a[k] - (X2v[k] * Om**2 + X1[k] * Ep)) <= rel * ascale + a_ref_err), f"{akey} {k}"
            assert np.abs(got_a[k] - (X2p[k] * Om**2 + X1[k] * Ep)).max() <= rel2 * ascale, f"{akey} {k} (2nd diff)"
    return s


def well_conditioned(lk: Linkage, phi, floor=0.15) -> bool:
    try:
        s = lk.solve(np.asarray(phi, dtype=float), level=1)
        for d in (1, 2, 3, 4):
            lk.solve(np.asarray(phi) + d * 2e-3, level=1)
            lk.solve(np.asarray(phi) - d * 2e-3, level=1)
    except AssemblyError:
        return False
    return all(float(np.min(c)) > floor for c in s.conditioning.values())


angles = st.lists(st.floats(0.0, 2 * math.pi), min_size=1, max_size=6).map(np.array)
senses = st.sampled_from([1, -1])
branches = st.sampled_from([1, -1])


# ---------------------------------------------------------------------------------- random linkages
@st.composite
def rrr_linkages(draw):
    r = draw(st.floats(0.05, 0.2))
    O2 = (draw(st.floats(0.2, 0.6)), draw(st.floats(-0.3, 0.3)))
    l3 = draw(st.floats(0.15, 0.8))
    l4 = draw(st.floats(0.15, 0.8))
    g = RRR(P="A", Q="O2", C="B", l_PC=l3, l_QC=l4, links=("2", "3"), branch=draw(branches))
    return Linkage(ground={"O1": (0, 0), "O2": O2}, crank=Crank("O1", "A", r), groups=[g], sense=draw(senses),
                   points=[Point("S2", "2", "A", l3 * draw(st.floats(0, 1.5)), draw(st.floats(-3, 3)))])


@st.composite
def rrp_linkages(draw):
    r = draw(st.floats(0.05, 0.2))
    moving = draw(st.booleans())
    if moving:   # the slider runs on a guide fixed to the crank; the rod turns about a fixed O2
        guide = Guide("1", "A", draw(st.floats(-3, 3)))
        g = RRP(P="O2", C="C", l=draw(st.floats(0.1, 0.6)), guide=guide, links=("2", "3"), branch=draw(branches))
        ground = {"O1": (0, 0), "O2": (draw(st.floats(-0.4, 0.4)), draw(st.floats(-0.4, 0.4)))}
    else:
        guide = Guide(GROUND, complex(draw(st.floats(-0.3, 0.3)), draw(st.floats(-0.1, 0.1))),
                      draw(st.floats(-3, 3)))
        g = RRP(P="A", C="C", l=draw(st.floats(0.3, 1.0)), guide=guide, links=("2", "3"), branch=draw(branches))
        ground = {"O1": (0, 0)}
    return Linkage(ground=ground, crank=Crank("O1", "A", r), groups=[g], sense=draw(senses),
                   points=[Point("S2", "2", g.P, 0.05, draw(st.floats(-3, 3)))])


@st.composite
def rpr_linkages(draw):
    r = draw(st.floats(0.05, 0.3))
    d = draw(st.floats(0.1, 0.5))
    e = draw(st.sampled_from([0.0, draw(st.floats(-0.04, 0.04))]))
    ang = draw(st.floats(-3, 3))
    # the pin keeps away from the pivot: near it ω₃ ~ v/ρ and the differences of the test lose accuracy
    assume(abs(r - d) > 0.05 + abs(e))
    g = RPR(P="A", Q="O3", coincident="A3", e=e, links=("2", "3"), branch=draw(branches))
    return Linkage(ground={"O1": (0, 0), "O3": (d * math.cos(ang), d * math.sin(ang))}, crank=Crank("O1", "A", r),
                   groups=[g], sense=draw(senses), points=[Point("B", "3", "O3", 0.7, draw(st.floats(-0.3, 0.3)))])


@st.composite
def prp_linkages(draw):
    r = draw(st.floats(0.05, 0.3))
    g1 = Guide(GROUND, complex(draw(st.floats(-0.2, 0.2)), draw(st.floats(-0.2, 0.2))), draw(st.floats(-3, 3)))
    g2 = Guide("1", "A", draw(st.floats(-3, 3)))
    g = PRP(C="C", guide_1=g1, guide_2=g2, links=("2", "3"))
    return Linkage(ground={"O1": (0, 0)}, crank=Crank("O1", "A", r), groups=[g], sense=draw(senses))


@st.composite
def rpp_linkages(draw):
    r = draw(st.floats(0.05, 0.3))
    gd = Guide(GROUND, complex(draw(st.floats(-0.2, 0.2)), draw(st.floats(-0.2, 0.2))), draw(st.floats(-3, 3)))
    g = RPP(P="A", R="C", coincident="A3", guide=gd, slot_angle=draw(st.floats(0.4, 2.7)),
            e=draw(st.floats(-0.05, 0.05)), links=("2", "3"))
    return Linkage(ground={"O1": (0, 0)}, crank=Crank("O1", "A", r), groups=[g], sense=draw(senses),
                   points=[Point("S3", "3", "C", 0.1, 0.5)])


@st.composite
def two_group_linkages(draw):
    """A slotted lever (RPR) whose lever drives a ram (RRP) or a rocker (RRR) from its end B."""
    r = draw(st.floats(0.05, 0.12))
    d = draw(st.floats(0.2, 0.4))
    lever = RPR(P="A", Q="O3", coincident="A3", links=("2", "3"))
    L = d + r + draw(st.floats(0.05, 0.2))
    if draw(st.booleans()):
        last = RRP(P="B", C="C", l=draw(st.floats(0.4, 0.8)),
                   guide=Guide(GROUND, complex(0.0, draw(st.floats(0.0, 0.2))), 0.0), links=("4", "5"),
                   branch=draw(branches))
        ground = {"O1": (0, 0), "O3": (0, -d)}
    else:
        last = RRR(P="B", Q="O5", C="C", l_PC=draw(st.floats(0.3, 0.6)), l_QC=draw(st.floats(0.3, 0.6)),
                   links=("4", "5"), branch=draw(branches))
        ground = {"O1": (0, 0), "O3": (0, -d), "O5": (draw(st.floats(0.3, 0.6)), draw(st.floats(0.0, 0.4)))}
    return Linkage(ground=ground, crank=Crank("O1", "A", r), groups=[lever, last], sense=draw(senses),
                   points=[Point("B", "3", "O3", L), Point("S4", "4", "B", 0.1, 0.2)])


@pytest.mark.parametrize("strategy", [rrr_linkages, rrp_linkages, rpr_linkages, prp_linkages, rpp_linkages,
                                      two_group_linkages], ids=["RRR", "RRP", "RPR", "PRP", "RPP", "two-groups"])
def test_velocities_and_accelerations_are_the_derivatives_of_the_positions(strategy):
    @settings(max_examples=40, deadline=None)
    @given(strategy(), angles, st.floats(0.2, 30.0), st.floats(-50.0, 50.0))
    def check(lk, phi, omega_1, epsilon_1):
        assume(well_conditioned(lk, phi))
        assert_matches_fd(lk, phi, omega_1=omega_1, epsilon_1=epsilon_1)

    check()


# ---------------------------------------------------------------------------------- closed forms
def slider_crank_closed(r, l, e, sigma, phi, w, eps):
    c, s = np.cos(phi), np.sin(phi)
    q = e - r * s
    W = np.sqrt(l * l - q * q)
    x = r * c + sigma * W
    x1 = -r * s + sigma * q * r * c / W
    x2 = -r * c + sigma * r * ((-r * c * c - q * s) / W - q * q * r * c * c / W**3)
    return x, x1 * w, x2 * w * w + x1 * eps


@pytest.mark.parametrize("sigma", [1, -1])
@pytest.mark.parametrize("sense", [1, -1])
def test_slider_crank_against_closed_form(sigma, sense):
    r, l, e, w, eps = 0.1, 0.4, 0.03, 12.0, 5.0
    lk = presets.slider_crank(r=r, l=l, e=e, assembly=sigma, sense=sense)
    phi = np.linspace(0, 2 * np.pi, 37)
    s = lk.solve(phi, omega_1=w, epsilon_1=eps)
    x, v, a = slider_crank_closed(r, l, e, sigma, phi, sense * w, sense * eps)
    assert np.abs(s.z["B"].real - x).max() <= 1e-12 * (r + l)
    assert np.abs(s.v["B"].real - v).max() <= 1e-12 * w * r
    assert np.abs(s.a["B"].real - a).max() <= 1e-12 * w * w * r * (1 + r / l)
    assert np.abs(s.v["B"].imag).max() == 0.0 and np.abs(s.a["B"].imag).max() == 0.0


def four_bar_closed(l1, l2, l3, l4, phi, th3, th4, w2, a2):
    """Norton's closed forms (loop R2 + R3 − R4 − R1 = 0) for ω3, ω4, α3, α4."""
    w3 = l2 * w2 * np.sin(th4 - phi) / (l3 * np.sin(th3 - th4))
    w4 = l2 * w2 * np.sin(phi - th3) / (l4 * np.sin(th4 - th3))
    A, B = l4 * np.sin(th4), l3 * np.sin(th3)
    C = l2 * a2 * np.sin(phi) + l2 * w2**2 * np.cos(phi) + l3 * w3**2 * np.cos(th3) - l4 * w4**2 * np.cos(th4)
    D, E = l4 * np.cos(th4), l3 * np.cos(th3)
    F = l2 * a2 * np.cos(phi) - l2 * w2**2 * np.sin(phi) - l3 * w3**2 * np.sin(th3) + l4 * w4**2 * np.sin(th4)
    a3 = (C * D - A * F) / (A * E - B * D)
    a4 = (C * E - B * F) / (A * E - B * D)
    return w3, w4, a3, a4


@pytest.mark.parametrize("assembly", [1, -1])
def test_four_bar_against_closed_form(assembly):
    l1, l2, l3, l4 = 0.30, 0.08, 0.25, 0.20
    lk = presets.four_bar(l1=l1, l2=l2, l3=l3, l4=l4, assembly=assembly)
    phi = np.linspace(0, 2 * np.pi, 37)
    w, eps = 9.0, -4.0
    s = lk.solve(phi, omega_1=w, epsilon_1=eps)
    # positions from Freudenstein's equation, independently
    K1, K2, K3 = l1 / l2, l1 / l4, (l2**2 - l3**2 + l4**2 + l1**2) / (2 * l2 * l4)
    A_ = np.cos(phi) - K1 - K2 * np.cos(phi) + K3
    B_ = -2 * np.sin(phi)
    C_ = K1 - (K2 + 1) * np.cos(phi) + K3
    th4 = 2 * np.arctan((-B_ - assembly * np.sqrt(B_**2 - 4 * A_ * C_)) / (2 * A_))
    Bx, By = l1 + l4 * np.cos(th4), l4 * np.sin(th4)
    assert np.abs(s.z["B"] - (Bx + 1j * By)).max() <= 1e-12
    th3 = np.arctan2(By - l2 * np.sin(phi), Bx - l2 * np.cos(phi))
    w3, w4, a3, a4 = four_bar_closed(l1, l2, l3, l4, phi, th3, th4, w, eps)
    assert np.abs(s.omega["2"] - w3).max() <= 1e-12 * w
    assert np.abs(s.omega["3"] - w4).max() <= 1e-12 * w
    assert np.abs(s.epsilon["2"] - a3).max() <= 1e-12 * w * w
    assert np.abs(s.epsilon["3"] - a4).max() <= 1e-12 * w * w


@pytest.mark.parametrize("r", [0.1, 0.45])          # oscillating and rotating slotted lever
def test_slotted_lever_against_closed_form(r):
    d, w, eps = 0.3, 7.0, 3.0
    lk = presets.slotted_lever(r=r, l_O1O3=d, l_O3B=0.9)
    phi = np.linspace(0, 2 * np.pi, 37)
    s = lk.solve(phi, omega_1=w, epsilon_1=eps)
    Ax, Ay = r * np.cos(phi), r * np.sin(phi)
    th3 = np.arctan2(Ay + d, Ax)
    rho = np.hypot(Ax, Ay + d)
    w3 = r * w * np.cos(phi - th3) / rho
    rho_dot = r * w * np.sin(th3 - phi)
    e3 = (r * eps * np.cos(phi - th3) - r * w * (w - w3) * np.sin(phi - th3) - w3 * rho_dot) / rho
    assert np.abs(s.omega["3"] - w3).max() <= 1e-12 * w
    assert np.abs(s.epsilon["3"] - e3).max() <= 1e-12 * w * w
    B = 0.9 * np.exp(1j * th3) - 0.3j
    assert np.abs(s.z["B"] - B).max() <= 1e-12
    # the relative motion of the block: ṡ = ρ̇ and the Coriolis term 2ω₃·v_rel
    rel = s.relative[lk.groups[0].name]
    assert np.abs(rel["s_dot"] - rho_dot).max() <= 1e-12 * w * r
    assert np.abs(np.abs(rel["a_coriolis"]) - 2 * np.abs(w3 * rho_dot)).max() <= 1e-12 * w * w * r


# ---------------------------------------------------------------------------------- structure, extremes
def test_structure_of_the_six_bar_press():
    s = presets.six_bar_press().structure()
    assert s.formula == "I(0,1) → II(2,3) → II(4,5)"
    assert (s.n_moving, s.p_lower, s.dof) == (5, 7, 1)
    assert [g.kind for g in s.groups] == ["crank", "RRR", "RRP"]
    assert [(g.cls, g.order) for g in s.groups[1:]] == [(2, 2), (2, 2)]


def test_extremes_to_1e_12_rad_against_closed_forms():
    r, l, e = 0.1, 0.4, 0.02
    st_ = presets.slider_crank(r=r, l=l, e=e).strokes()
    far = math.atan2(e, math.sqrt((l + r) ** 2 - e * e))
    near = math.atan2(-e, -math.sqrt((l - r) ** 2 - e * e)) % (2 * math.pi)
    assert abs(st_.phi_start - far) <= 1e-12 and abs(st_.phi_end - near) <= 1e-12
    sl = presets.slotted_lever(r=0.1, l_O1O3=0.3, l_O3B=0.5).strokes()
    a = math.acos(0.1 / 0.3)
    got = sorted([sl.phi_start, sl.phi_end])
    want = sorted([(-math.pi / 2 + a) % (2 * math.pi), (-math.pi / 2 - a) % (2 * math.pi)])
    assert max(abs(x - y) for x, y in zip(got, want)) <= 1e-12
    assert abs(sl.K - (math.pi + 2 * math.asin(1 / 3)) / (math.pi - 2 * math.asin(1 / 3))) <= 1e-12
    fb = presets.four_bar(l1=0.3, l2=0.08, l3=0.25, l4=0.2).strokes()
    L = 0.25 + 0.08
    xg = (L * L - 0.04 + 0.09) / 0.6
    ext = math.atan2(math.sqrt(L * L - xg * xg), xg)
    assert min(abs(fb.phi_start - ext), abs(fb.phi_end - ext)) <= 1e-12


def test_positions_are_numbered_from_the_start_of_the_working_stroke():
    lk = presets.six_bar_press()
    mo = lk.motion(m=12, omega_1=10.0)
    st_ = mo.strokes
    assert mo.phi[0] == st_.phi_start and mo.extreme[0] and mo.extreme[-1]
    assert st_.K > 1.0                          # the slow stroke works
    assert abs(mo.s[0]) == 0.0 and np.all(mo.s >= -1e-15)
    assert np.all(mo.v("D")[mo.extreme] == 0.0)
    steps = np.mod(lk.sense * np.diff(mo.phi), 2 * np.pi)
    assert np.allclose(steps, 2 * np.pi / 12, atol=1e-13)


def test_records_meet_where_the_vectors_are():
    """Every construction record's two lines pass through the vector it finds (velocity and acceleration)."""
    for lk in (presets.six_bar_press(), presets.shaper(r=0.11, l_O1O3=0.38, l_O3B=0.54, l_BC=0.135, y_guide=0.1484),
               presets.slider_crank(r=0.1, l=0.4, e=0.02)):
        mo = lk.motion(m=12, omega_1=10.0, epsilon_1=2.0)
        recs = mo.records()
        assert {r.plan for r in recs} == {"velocity", "acceleration"}
        for rec in recs:
            for _, through, direction in rec.lines:
                off = (rec.meet - through) * np.conj(direction)
                scale = np.abs(rec.meet).max() + np.abs(through).max()
                assert np.abs(off.imag).max() <= 1e-12 * scale, (rec.point, rec.plan, rec.equation)


def test_acceleration_equations_read_as_the_book_writes_them():
    mo = presets.slotted_lever(r=0.1, l_O1O3=0.3, l_O3B=0.5).motion(m=12)
    eqs = [r.equation for r in mo.records()]
    assert "v_A3 = v_A + v_A3A" in eqs
    assert "a_A3 = a_A + a^k_A3A + a^r_A3A = a_O3 + a^n_A3O3 + a^τ_A3O3" in eqs
    eqs = [r.equation for r in presets.four_bar(l1=0.3, l2=0.08, l3=0.25, l4=0.2).motion(m=12).records()]
    assert "v_B = v_A + v_BA = v_O2 + v_BO2" in eqs


def test_bad_structure_is_refused_with_one_line():
    g = RRR(P="A", Q="X", C="B", l_PC=0.3, l_QC=0.2)
    with pytest.raises(InputError, match="needs X"):
        Linkage(ground={"O": (0, 0)}, crank=Crank("O", "A", 0.1), groups=[g])
    with pytest.raises(InputError, match="branch must be"):
        RRR(P="A", Q="X", C="B", l_PC=0.3, l_QC=0.2, branch=0)
    with pytest.raises(InputError, match="must be > 0"):
        RRR(P="A", Q="X", C="B", l_PC=-0.3, l_QC=0.2)
