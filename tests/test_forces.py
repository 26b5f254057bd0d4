"""The force (kinetostatic) analysis: equilibrium of every link, closed force polygons, the balancing
moment three ways, an independent global solve, a textbook engine example, hard cases."""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphmethods.dynamics.forces import Force, Mass, case_forces, kinetostatics
from graphmethods.dynamics.reduction import load_switch_angles, resisting_moment
from graphmethods.errors import InputError
from graphmethods.kinematics.linkage_file import linkage_case
from graphmethods.kinematics.presets import slider_crank
from graphmethods.problems import builtin

G = 9.81


def _scotch_yoke():
    """RPP: crank 1, block 2 at A in the vertical slot of yoke 3 that slides along x."""
    return linkage_case({
        "kind": "linkage", "fixed": {"O": [0, 0]}, "crank": {"centre": "O", "pin": "A", "r": 0.1},
        "groups": [{"type": "RPP", "links": [2, 3], "P": "A", "R": "C", "point": "A3",
                    "guide": {"link": 0, "through": [0, 0.05], "angle_deg": 0}, "slot_angle_deg": 80, "e": 0.01}],
        "points": {"S3": {"link": 3, "from": "C", "distance": 0.2, "angle_deg": 0}},
        "masses": {"1": {"J": 0.02}, "2": {"m": 0.4, "J": 0.001, "at": "A"}, "3": {"m": 5.0, "J": 0.04, "at": "S3"}},
        "load": {"force": 300, "on": "C", "from": 0.1, "to": 0.9}, "n_rpm": 200, "delta": 0.05}, source="<yoke>")


def _tangent_mechanism():
    """RPR then PRP: a slotted lever 3 about O3; slider 4 on the lever pinned at C to slider 5 on a
    horizontal guide of the frame (C is where the lever's line meets the guide)."""
    return linkage_case({
        "kind": "linkage", "fixed": {"O1": [0, 0], "O3": [0, -0.3]},
        "crank": {"centre": "O1", "pin": "A", "r": 0.1},
        "groups": [{"type": "RPR", "links": [2, 3], "P": "A", "Q": "O3", "point": "A3", "branch": 1},
                   {"type": "PRP", "links": [4, 5], "C": "C",
                    "guide_1": {"link": 3, "through": "O3", "angle_deg": 0},
                    "guide_2": {"link": 0, "through": [0, 0.25], "angle_deg": 0}}],
        "points": {"S3": {"link": 3, "from": "O3", "distance": 0.25}},
        "masses": {"1": {"J": 0.05}, "2": {"m": 0.5, "J": 0.003, "at": "A"}, "3": {"m": 4.0, "J": 0.05, "at": "S3"},
                   "4": {"m": 0.6, "J": 0.002, "at": "C"}, "5": {"m": 8.0, "at": "C"}},
        "load": {"force": 500, "on": "C", "from": 0.0, "to": 1.0}, "n_rpm": 120, "delta": 0.05}, source="<tangent>")


CASES = {name: (lambda n=name: builtin.case(n)) for name in builtin.LINKAGES}
CASES["scotch-yoke (RPP)"] = _scotch_yoke
CASES["tangent (RPR, PRP)"] = _tangent_mechanism


def _all(name, gravity=True, epsilon_1=1.3, m=36):
    return case_forces(CASES[name](), m=m, gravity=gravity, epsilon_1=epsilon_1)


def test_every_dyad_type_is_covered():
    kinds = {g.kind for make in CASES.values() for g in make().linkage.groups}
    assert kinds == {"RRR", "RRP", "RPR", "PRP", "RPP", "triad"}          # triad-six-bar: a class III group


def _link_sums(fa, link):
    """Σ F and Σ M about the origin on ``link``: applied forces, every reaction on it, M_b on the crank."""
    n = fa.n
    F = np.zeros(n, complex)
    M = np.zeros(n)
    for f in fa.applied[link]:
        F += f.F
        M += np.imag(np.conj(f.at) * f.F) + f.M
    for r in fa.reactions.values():
        for side, sign in ((r.on, 1.0), (r.by, -1.0)):
            if side == link:
                F += sign * r.R
                M += sign * (np.imag(np.conj(r.at) * r.R) + r.M)
    if link == fa.motion.linkage.crank.link:
        M += fa.M_balance
    return F, M


@pytest.mark.parametrize("name", list(CASES))
def test_every_link_is_in_equilibrium(name):
    fa = _all(name)
    scale_F = max(float(np.max(np.abs(r.R))) for r in fa.reactions.values())
    span = max(float(np.max(np.abs(z))) for z in fa.motion.z.values())
    for link in fa.motion.linkage.links:
        F, M = _link_sums(fa, link)
        assert np.max(np.abs(F)) <= 1e-12 * scale_F, (link, np.max(np.abs(F)))
        assert np.max(np.abs(M)) <= 1e-12 * scale_F * span, (link, np.max(np.abs(M)))


@pytest.mark.parametrize("name", list(CASES))
def test_prismatic_reactions_are_normal_to_their_guides(name):
    fa = _all(name)
    for r in fa.reactions.values():
        if r.kind == "P":
            along = np.real(np.conj(r.guide) * r.R)
            assert np.max(np.abs(along)) <= 1e-12 * max(1.0, float(np.max(np.abs(r.R))))


@pytest.mark.parametrize("name", list(CASES))
def test_force_polygons_close(name):
    fa = _all(name)
    for plan in fa.plans:
        for poly in plan.polygons:
            scale = max([1.0] + [float(np.max(np.abs(F))) for _, F in poly.known])
            assert np.max(poly.residual) <= 1e-12 * scale, (plan.group, poly.links)
            for label, direction, F in poly.closing:
                if direction is not None:          # a closing side lies on its line
                    assert np.max(np.abs(np.imag(np.conj(direction) * F))) <= 1e-12 * scale, label


@pytest.mark.parametrize("gravity", [False, True])
@pytest.mark.parametrize("name", list(CASES))
def test_balancing_moment_three_ways(name, gravity):
    """Force plans, Zhukovsky's lever, power balance: 1e-9 relative in every position."""
    fa = _all(name, gravity=gravity)
    Mb = fa.M_balance
    floor = 1e-6 * float(np.max(np.abs(Mb)))       # where M_b passes through zero
    for other in (fa.M_balance_lever, fa.M_balance_power):
        rel = np.abs(Mb - other) / np.maximum(np.abs(Mb), floor)
        assert np.max(rel) <= 1e-9, float(np.max(rel))


@pytest.mark.parametrize("name", list(CASES))
def test_global_least_squares_gives_the_same_reactions(name):
    """All links' equilibrium equations as one linear system per position (numpy.linalg.lstsq): the
    unknowns are the two components of each revolute reaction, the normal force and couple of each
    prismatic pair, and M_b. The applied loads are built here from the masses, accelerations and g."""
    case = CASES[name]()
    fa = case_forces(case, m=12, gravity=True, epsilon_1=-0.8)
    mo, lk = fa.motion, fa.motion.linkage
    links = list(lk.links)
    row = {k: 3 * i for i, k in enumerate(links)}
    pairs = list(fa.reactions.values())
    ncol = sum(2 for _ in pairs) + 1
    from graphmethods.dynamics.forces.problem import link_number, working_load
    masses = [(link_number(case, it.link, it.point), it) for it in case.inertias]
    loads = working_load(case, mo, case.mechanism.positions(m=12))
    for i in range(mo.n):
        A = np.zeros((3 * len(links), ncol))
        b = np.zeros(3 * len(links))

        def add(A, b, link, Fx, Fy, M, col=None, coeff=None):
            if link == "0":
                return
            r0 = row[link]
            if col is None:
                b[r0] -= Fx
                b[r0 + 1] -= Fy
                b[r0 + 2] -= M
            else:
                A[r0, col] += coeff[0]
                A[r0 + 1, col] += coeff[1]
                A[r0 + 2, col] += coeff[2]

        for link, it in masses:                      # d'Alembert: −m a, −J ε, weight
            S, a = mo.z[it.point][i], mo.a_[it.point][i]
            F = -it.m * a - 1j * it.m * G
            add(A, b, link, F.real, F.imag, S.real * F.imag - S.imag * F.real - it.J * mo.epsilon[link][i])
        for link, f in loads:
            F, S = f.F[i], f.at[i]
            add(A, b, link, F.real, F.imag, S.real * F.imag - S.imag * F.real + f.M[i])
        for k, r in enumerate(pairs):
            P = r.at[i]
            if r.kind == "R":
                cols = [(1.0, 0.0), (0.0, 1.0)]
                for c, (ux, uy) in enumerate(cols):    # unit force along x / y at P on link "on"
                    m = P.real * uy - P.imag * ux
                    add(A, b, r.on, 0, 0, 0, 2 * k + c, (ux, uy, m))
                    add(A, b, r.by, 0, 0, 0, 2 * k + c, (-ux, -uy, -m))
            else:
                nrm = 1j * r.guide[i]
                m = P.real * nrm.imag - P.imag * nrm.real
                add(A, b, r.on, 0, 0, 0, 2 * k, (nrm.real, nrm.imag, m))
                add(A, b, r.by, 0, 0, 0, 2 * k, (-nrm.real, -nrm.imag, -m))
                add(A, b, r.on, 0, 0, 0, 2 * k + 1, (0.0, 0.0, 1.0))
                add(A, b, r.by, 0, 0, 0, 2 * k + 1, (0.0, 0.0, -1.0))
        add(A, b, lk.crank.link, 0, 0, 0, ncol - 1, (0.0, 0.0, 1.0))
        assert A.shape[0] == A.shape[1]                      # statically determinate: W = 1
        x, *_ = np.linalg.lstsq(A, b, rcond=None)
        scale = max(float(np.max(np.abs(x[:-1]))), 1.0)
        for k, r in enumerate(pairs):
            if r.kind == "R":
                got = complex(x[2 * k], x[2 * k + 1])
                assert abs(got - r.R[i]) <= 1e-9 * scale, (r.key, i, got, r.R[i])
            else:
                N = float(np.imag(np.conj(r.guide[i]) * r.R[i]))
                assert abs(x[2 * k] - N) <= 1e-9 * scale, (r.key, i)
                assert abs(x[2 * k + 1] - r.M[i]) <= 1e-9 * scale * 1.0, (r.key, i)
        assert abs(x[-1] - fa.M_balance[i]) <= 1e-9 * scale, (i, x[-1], fa.M_balance[i])


def test_the_working_load_has_the_power_of_the_resisting_moment():
    """The load placed on the linkage does the work the reduced model counts: F·v = −M_r·ω₁."""
    for name in builtin.LINKAGES:
        case = builtin.case(name)
        fa = case_forces(case, m=24)
        pos = case.mechanism.positions(m=24)
        plans = case.mechanism.velocity_plans(pos, omega_1=fa.motion.omega_1)
        Mr = resisting_moment(pos, plans, case.load)
        power = np.zeros(fa.n)
        for link, forces in fa.applied.items():
            for f in forces:
                if f.label.startswith(("F_c", "M_c")):
                    th = fa.motion.omega[link]
                    v = next(fa.motion.v_[p] for p in fa.motion.points if np.allclose(fa.motion.z[p], f.at)) \
                        if np.any(f.F) else 0
                    power = power + np.real(np.conj(v) * f.F) + f.M * th
        assert np.allclose(power, -Mr * fa.motion.omega_1, rtol=1e-12, atol=1e-9 * float(np.max(np.abs(Mr)) or 1))


# ---------------------------------------------------------------------- a textbook engine
def test_horizontal_engine_textbook_example():
    """A horizontal engine as in Khurmi & Gupta, Theory of Machines, ch. 15 (forces on the
    reciprocating parts): r = 300 mm, l = 1.2 m, bore 0.5 m, reciprocating mass 250 kg, net pressure
    0.35 N/mm², 250 rev/min, crank 60° from the inner dead centre. The book's printed answers could
    not be checked against the book here, so they are not asserted; the classic formulas
    N = F_P·tan β, S = F_P/cos β, T = F_P·r·sin(θ + β)/cos β (F_P the piston effort with the exact
    piston acceleration) are, to 1e-6."""
    r, l, m3 = 0.3, 1.2, 250.0
    omega = 2 * math.pi * 250 / 60
    theta = math.radians(60)
    F_L = 0.35e6 * math.pi / 4 * 0.5 ** 2
    lk = slider_crank(r=r, l=l)
    mo = lk.motion(phi=[theta], omega_1=omega)
    gas = Force("F_g", F=np.array([-F_L + 0j]), at=mo.z["B"], M=np.zeros(1))
    fa = kinetostatics(mo, masses=[Mass("3", "B", m3, 0.0)], loads=[("3", gas)])
    # the piston's acceleration by differentiating x(θ) = r cos θ + √(l² − r² sin² θ) twice
    def x(t):
        return r * math.cos(t) + math.sqrt(l * l - (r * math.sin(t)) ** 2)

    h = 1e-4
    a = omega ** 2 * (x(theta + h) - 2 * x(theta) + x(theta - h)) / h ** 2
    F_P = F_L + m3 * a                         # gas force toward the crank less the inertia force
    beta = math.asin(r * math.sin(theta) / l)
    N, S, T = F_P * math.tan(beta), F_P / math.cos(beta), F_P * r * math.sin(theta + beta) / math.cos(beta)
    assert abs(abs(fa.reactions["R_03"].R[0]) - N) <= 1e-6 * N
    assert abs(abs(fa.reactions["R_23"].R[0]) - S) <= 1e-6 * S
    assert abs(-fa.M_balance[0] - T) <= 1e-6 * T               # M_b balances the driving moment


# ---------------------------------------------------------------------- hard cases
def test_dead_centre_the_load_gives_no_balancing_moment():
    """At a dead centre of a centred slider-crank the rod passes through O: a piston force loads
    the bearing, not the crank; R_12 lies along the rod and M_b = 0 (no crank inertia)."""
    lk = slider_crank(r=0.1, l=0.4)
    for phi in (0.0, math.pi):
        mo = lk.motion(phi=[phi], omega_1=20.0)
        push = Force("P", F=np.array([-2000 + 0j]), at=mo.z["B"], M=np.zeros(1))
        fa = kinetostatics(mo, masses=[Mass("3", "B", 3.0, 0.0), Mass("2", "B", 0.0, 0.0)], loads=[("3", push)])
        assert abs(fa.M_balance[0]) <= 1e-12 * 2000 * 0.1
        assert abs(fa.reactions["R_12"].R[0].imag) <= 1e-9
        assert abs(fa.M_balance_lever[0]) <= 1e-12 * 2000 * 0.1
        assert abs(fa.reactions["R_03"].R[0]) <= 1e-9


def test_gravity_on_and_off_differ_by_the_power_of_the_weights():
    case = builtin.case("six-bar-press")
    on = case_forces(case, m=12, gravity=True)
    off = case_forces(case, m=12, gravity=False)
    mo = on.motion
    power = sum(-it.m * G * mo.v_[it.point].imag for it in case.inertias)   # G·v, G = −m g ŷ
    Omega = mo.linkage.sense * mo.omega_1
    assert np.allclose(on.M_balance - off.M_balance, -power / Omega, rtol=1e-10, atol=1e-9)
    assert not np.allclose(on.M_balance, off.M_balance)
    # the frame carries the whole weight on average over a turn
    assert on.gravity == G and off.gravity == 0.0


def test_the_load_switches_on_inside_the_stroke():
    """Just before the switch-on angle the load is absent, just after it the balancing moment grows
    by F0·|v|/ω₁ (the resisting moment of the reduced model)."""
    case = builtin.case("press")
    lk = case.linkage
    on, _ = load_switch_angles(case.mechanism, case.load)
    start = lk.strokes().phi_start
    phis = [math.degrees(start + lk.sense * (on + d)) for d in (-1e-7, 1e-7)]
    fa = case_forces(case, phi_deg=phis)
    before, after = fa.applied["3"][-1].F
    assert before == 0 and abs(after) == case.load.magnitude
    pos = case.mechanism.positions(phi=np.radians(phis))
    Mr = resisting_moment(pos, case.mechanism.velocity_plans(pos, omega_1=fa.motion.omega_1), case.load)
    jump = fa.M_balance[1] - fa.M_balance[0]
    assert abs(jump - Mr[1]) <= 1e-3 * Mr[1]              # the inertia terms move by O(1e-7) only
    assert Mr[0] == 0 and Mr[1] > 0


def test_russian_form_moves_the_inertia_force_by_h():
    fa = case_forces(builtin.case("four-bar"), m=12)
    for it in fa.inertia:
        ok = np.abs(it.F_i) > 0
        d = it.shifted[ok] - np.asarray(fa.motion.z[it.at])[ok]
        assert np.allclose(np.abs(d), it.h[ok], rtol=1e-12, atol=1e-15)
        assert np.allclose(np.imag(np.conj(d) * it.F_i[ok]), it.M_i[ok], rtol=1e-9, atol=1e-12)


def test_a_group_pinned_at_a_middle_joint_is_refused_with_advice():
    data = {"kind": "linkage", "fixed": {"O": [0, 0]}, "crank": {"centre": "O", "pin": "A", "r": 0.1},
            "groups": [{"type": "RRP", "links": [2, 3], "P": "A", "C": "B", "l": 0.4,
                        "guide": {"link": 0, "through": [0, 0], "angle_deg": 0}},
                       {"type": "RRP", "links": [4, 5], "P": "B", "C": "D", "l": 0.3,
                        "guide": {"link": 0, "through": [0, 0.2], "angle_deg": 0}}],
            "masses": {"5": {"m": 1, "at": "D"}}, "load": {"force": 10, "on": "D", "from": 0, "to": 1},
            "n_rpm": 60, "delta": 0.1}
    case = linkage_case(data)
    with pytest.raises(InputError, match="extra point at distance 0"):
        case_forces(case, m=12)


def test_bad_masses_and_loads_are_refused():
    lk = slider_crank(r=0.1, l=0.4)
    mo = lk.motion(phi=[1.0], omega_1=10.0)
    with pytest.raises(InputError, match="link '7'"):
        kinetostatics(mo, masses=[Mass("7", "B", 1.0, 0.0)])
    with pytest.raises(InputError, match="no such point"):
        kinetostatics(mo, masses=[Mass("2", "Z", 1.0, 0.0)])
    with pytest.raises(InputError, match="must be finite"):
        kinetostatics(mo, masses=[Mass("2", "B", float("nan"), 0.0)])
    with pytest.raises(InputError, match="gravity"):
        kinetostatics(mo, masses=[], gravity=-1.0)
