"""Class III groups (triads): positions continued from the drawing, exact velocities and accelerations,
Assur's special-point plans, and refusals with a named reason."""

import copy
import json
import math
import pathlib

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from graphmethods.errors import AssemblyError, GraphmethodsError, InputError
from graphmethods.kinematics import case_from_dict, read_case
from graphmethods.kinematics.groups import State, Triad
from graphmethods.kinematics.linkage import Crank, Linkage

DATA = pathlib.Path(__file__).parents[1] / "graphmethods" / "problems" / "data"
SIX_BAR = json.loads((DATA / "triad_six_bar.json").read_text())
DRAWN = {k: complex(*v) for k, v in SIX_BAR["groups"][0]["drawn"].items()}
R = SIX_BAR["crank"]["r"]


def six_bar() -> Linkage:
    return read_case(DATA / "triad_six_bar.json").linkage


# ---------------------------------------------------------------------- an independent solver, written here
def lengths() -> dict[str, float]:
    d = DRAWN
    e3 = (d["C"] - d["B"]) / abs(d["C"] - d["B"])
    return {"l2": abs(d["B"] - d["A"]), "l4": abs(d["C"] - d["E"]), "l5": abs(d["D"] - d["F"]),
            "c2": (d["C"] - d["B"]) / e3, "c3": (d["D"] - d["B"]) / e3}


def loops(th, phi):
    """The two closed loops O1-A-B-C-E and O1-A-B-D-F in real arithmetic (analytic in every variable,
    so a complex step goes through): th = (θ2, θ3, θ4, θ5), rad."""
    L = lengths()
    t2, t3, t4, t5 = th
    ax, ay = R * np.cos(phi), R * np.sin(phi)
    bx, by = ax + L["l2"] * np.cos(t2), ay + L["l2"] * np.sin(t2)
    out = []
    for c, l, P, t in ((L["c2"], L["l4"], DRAWN["E"], t4), (L["c3"], L["l5"], DRAWN["F"], t5)):
        cx = bx + c.real * np.cos(t3) - c.imag * np.sin(t3)
        cy = by + c.real * np.sin(t3) + c.imag * np.cos(t3)
        out += [cx - P.real - l * np.cos(t), cy - P.imag - l * np.sin(t)]
    return np.array(out)


def newton_loops(th, phi):
    """Newton on the loop equations with a central-difference Jacobian (complex-safe)."""
    th = np.array(th, dtype=complex)
    for _ in range(60):
        f = loops(th, phi)
        J = np.empty((4, 4), dtype=complex)
        for k in range(4):
            d = np.zeros(4)
            d[k] = 1e-7
            J[:, k] = (loops(th + d, phi) - loops(th - d, phi)) / 2e-7
        step = np.linalg.solve(J, -f)
        th = th + step
        if np.max(np.abs(step)) < 1e-15:
            break
    return th


def independent_track(phis_deg):
    """θ2..θ5 at the crank angles (deg, increasing from 90°), continued from the drawing 1° at a time."""
    d = DRAWN
    th = np.array([np.angle(d["B"] - d["A"]), np.angle(d["C"] - d["B"]), np.angle(d["C"] - d["E"]),
                   np.angle(d["D"] - d["F"])])
    out = {}
    phi = 90.0
    for target in phis_deg:
        while phi < target:
            phi = min(phi + 1.0, target)
            th = newton_loops(th, math.radians(phi)).real
        out[target] = th
    return out


def test_the_six_bar_is_a_class_III_mechanism():
    s = six_bar().structure()
    assert s.formula == "I(0,1) → III(2,3,4,5)"
    assert (s.dof, s.n_moving, s.p_lower, s.mechanism_class) == (1, 5, 7, 3)


def test_positions_match_a_direct_newton_solve_of_the_loops():
    lk = six_bar()
    targets = [90.0 + 7.5 * k for k in range(49)]
    ref = independent_track(targets)
    phi = np.radians(targets)
    st_ = lk.solve(phi, level=0)
    for k, t in enumerate(targets):
        got = [st_.theta[n][k] for n in ("2", "3", "4", "5")]
        assert np.allclose(np.exp(1j * np.array(got)), np.exp(1j * ref[t]), atol=1e-12, rtol=0)


def test_the_drawn_position_is_reproduced():
    lk = six_bar()
    st_ = lk.solve([math.pi / 2], level=0)
    for k in "ABCD":
        assert abs(st_.z[k][0] - DRAWN[k]) < 1e-12


@pytest.mark.parametrize("phi_deg", [0.0, 33.0, 90.0, 200.0, 271.5])
def test_velocities_are_complex_step_derivatives_of_the_positions(phi_deg):
    """dθ/dφ by a complex step through the independent loop solve equals ω at ω₁ = 1, to 1e-10."""
    lk = six_bar()
    phi = math.radians(phi_deg)
    th = independent_track([90.0 + ((phi_deg - 90.0) % 360.0)])[90.0 + ((phi_deg - 90.0) % 360.0)]
    h = 1e-20
    dth = newton_loops(th, phi + 1j * h).imag / h
    st_ = lk.solve([phi], omega_1=1.0, level=1)
    got = [st_.omega[n][0] for n in ("2", "3", "4", "5")]
    assert np.allclose(got, dth, atol=1e-9, rtol=1e-9)


def test_accelerations_are_the_derivatives_of_the_velocities():
    """With ω₁ = 1 and ε₁ = 0, a = dv/dφ and ε = dω/dφ (central differences of the core's exact velocities)."""
    lk = six_bar()
    phi = np.radians(np.arange(0.0, 360.0, 15.0))
    h = 1e-5
    s0 = lk.solve(phi, omega_1=1.0)
    sp, sm = lk.solve(phi + h, level=1), lk.solve(phi - h, level=1)
    for k in ("B", "C", "D", "S3", "S5"):
        fd = (sp.v[k] - sm.v[k]) / (2 * h)
        assert np.max(np.abs(fd - s0.a[k])) < 1e-8
        fdz = (sp.z[k] - sm.z[k]) / (2 * h)
        assert np.max(np.abs(fdz - s0.v[k])) < 1e-8
    for n in ("2", "3", "4", "5"):
        assert np.max(np.abs((sp.omega[n] - sm.omega[n]) / (2 * h) - s0.epsilon[n])) < 1e-7


def test_the_crank_acceleration_enters_exactly():
    """ε₁ ≠ 0: a(ε₁) − a(0) = ε₁·dX/dφ (linear in ε₁)."""
    lk = six_bar()
    phi = np.radians([10.0, 130.0, 250.0])
    a0 = lk.solve(phi, omega_1=3.0, epsilon_1=0.0)
    a1 = lk.solve(phi, omega_1=3.0, epsilon_1=5.0)
    v1 = lk.solve(phi, omega_1=1.0, level=1)
    for k in ("B", "C", "D"):
        assert np.max(np.abs(a1.a[k] - a0.a[k] - 5.0 * v1.v[k])) < 1e-12


def _meet(rec):
    (_, p1, d1), (_, p2, d2) = rec.lines
    det = (d1.conjugate() * d2).imag
    s = ((p2 - p1).conjugate() * d2).imag / det
    return p1 + s * d1


def test_the_special_point_construction_matches_the_core():
    """Assur's special point: each record's two lines meet where the core puts the point, to 1e-12."""
    lk = six_bar()
    mo = lk.motion(m=24, omega_1=12.0, epsilon_1=3.0)
    recs = mo.records()
    assert {r.point for r in recs} == {"K3", "B", "C", "D"}
    assert {r.plan for r in recs} == {"velocity", "acceleration"}
    st_ = mo._state
    g = lk.groups[0]
    K, (i, j, k) = g.special_point(st_)
    w, e = st_.omega["3"], st_.epsilon["3"]
    core = {"velocity": dict(mo.v_), "acceleration": dict(mo.a_)}
    core["velocity"]["K3"] = st_.v["B"] + 1j * w * (K - st_.z["B"])          # K moves with the basic link
    core["acceleration"]["K3"] = st_.a["B"] + (1j * e - w * w) * (K - st_.z["B"])
    for rec in recs:
        meet = _meet(rec)
        table = core[rec.plan]
        scale = max(np.max(np.abs(table[p])) for p in ("A", "B", "C", "D"))
        assert np.max(np.abs(meet - rec.meet)) <= 1e-12 * scale
        assert np.max(np.abs(meet - table[rec.point])) <= 1e-12 * scale
    # K is a point of the basic link on the lines of two binary links
    for x in (j, k):
        P, B = st_.z[g.outer[x]], st_.z[g.inner[x]]
        assert np.max(np.abs(((K - P).conjugate() * (B - P)).imag)) < 1e-12


def test_the_structure_is_printed_and_points_on_the_triad_links_move_rigidly():
    lk = six_bar()
    st_ = lk.solve(np.radians([0.0, 45.0]), omega_1=2.0)
    # S3 on the basic link: v_S3 = v_B + ω3 × BS3
    r = st_.z["S3"] - st_.z["B"]
    assert np.max(np.abs(st_.v["S3"] - (st_.v["B"] + 1j * st_.omega["3"] * r))) < 1e-12
    for P, B in (("A", "B"), ("E", "C"), ("F", "D")):
        d = np.abs(st_.z[B] - st_.z[P])
        assert np.max(np.abs(d - abs(DRAWN[B] - DRAWN[P]))) < 1e-13


# ---------------------------------------------------------------------- refusals, named
def _file(**change):
    data = copy.deepcopy(SIX_BAR)
    data["groups"][0].update(change)
    return data


def test_a_triad_missing_its_drawing_is_refused_by_key():
    g = copy.deepcopy(SIX_BAR["groups"][0])
    del g["drawn"]
    data = copy.deepcopy(SIX_BAR)
    data["groups"] = [g]
    with pytest.raises(InputError, match=r"groups\[0\].drawn.*is missing"):
        case_from_dict(data)
    with pytest.raises(InputError, match=r"groups\[0\].drawn.C"):
        drawn = dict(SIX_BAR["groups"][0]["drawn"])
        del drawn["C"]
        case_from_dict(_file(drawn=drawn))
    with pytest.raises(InputError, match=r"links"):
        case_from_dict(_file(links=[3, 2, 4]))


def test_outer_joints_drawn_where_the_mechanism_never_puts_them_are_refused():
    drawn = dict(SIX_BAR["groups"][0]["drawn"])
    drawn["A"] = [0.3, 0.3]
    with pytest.raises(AssemblyError, match="never puts them"):
        case_from_dict(_file(drawn=drawn))


def test_a_dead_position_on_the_way_is_refused_with_its_angle():
    drawn = dict(SIX_BAR["groups"][0]["drawn"])
    data = _file(drawn={**drawn, "B": [0.22, 0.08], "C": [0.3, 0.02], "D": [0.32, 0.14],
                        "E": [0.32, -0.18], "F": [0.5, 0.22]})
    data["fixed"].update({"E": [0.32, -0.18], "F": [0.5, 0.22]})
    with pytest.raises(AssemblyError, match=r"meet in one point at φ ≈ [0-9.]+°"):
        case_from_dict(data)


def fixed_outer(drawn):
    def upstream(phi):
        s = State(phi=np.asarray(phi, dtype=float))
        s.z.update({k: np.full(s.n, drawn[k]) for k in ("P1", "P2", "P3")})
        return s
    return upstream


pt = st.tuples(st.floats(-1, 1), st.floats(-1, 1))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(p1=pt, p2=pt, b1=pt, b2=pt, b3=pt, p3=pt, r=st.floats(0.01, 0.4))
def test_random_triads_assemble_on_their_drawing_or_are_refused_by_name(p1, p2, b1, b2, b3, p3, r):
    """A crank O–P1 drives a random triad whose other outer joints are on the frame: either every
    position lies on the drawn lengths and the drawn assembly comes back, or a named refusal."""
    pts = dict(zip(("P1", "P2", "P3", "B1", "B2", "B3"), (complex(*x) for x in (p1, p2, p3, b1, b2, b3))))
    O = pts["P1"] - r
    try:
        g = Triad(outer=("P1", "P2", "P3"), inner=("B1", "B2", "B3"), drawn=tuple(pts.items()),
                  links=("3", "2", "4", "5"))
        lk = Linkage(ground={"O": (O.real, O.imag), "P2": (p2[0], p2[1]), "P3": (p3[0], p3[1])},
                     crank=Crank("O", "P1", r=r), groups=[g])
        phi = np.linspace(0.0, 2 * np.pi, 25)
        s = lk.solve(phi)
    except (AssemblyError, InputError) as exc:
        assert "triad" in str(exc)
        return
    for n in ("B1", "B2", "B3"):
        for arr in (s.z[n], s.v[n], s.a[n]):
            assert np.all(np.isfinite(arr))
    for P, B in zip(g.outer, g.inner):
        assert np.max(np.abs(np.abs(s.z[B] - s.z[P]) - abs(pts[B] - pts[P]))) < 1e-9 * g.size
    s0 = lk.solve([0.0], level=0)           # the drawing: φ = 0 puts P1 where it is drawn
    for n in ("B1", "B2", "B3"):
        assert abs(s0.z[n][0] - pts[n]) < 1e-9 * g.size


def test_every_error_is_ours():
    """Bad triads at the API: our own exception, never a bare one."""
    for bad in (dict(outer=("A", "A", "C")), dict(drawn=(("A", 0j),)), dict(links=("2", "2", "3", "4"))):
        kw = dict(outer=("A", "E", "F"), inner=("B", "C", "D"), drawn=tuple(DRAWN.items()), links=("3", "2", "4", "5"))
        kw.update(bad)
        with pytest.raises(GraphmethodsError):
            Triad(**kw)


# ---------------------------------------------------------------------- the force analysis
def _forces(gravity=9.81, epsilon_1=4.0, m=24):
    from graphmethods.dynamics.forces.analysis import Mass, kinetostatics
    from graphmethods.dynamics.forces.base import Force

    case = read_case(DATA / "triad_six_bar.json")
    lk = case.linkage
    mo = lk.motion(m=m, omega_1=9.0, epsilon_1=epsilon_1)
    masses = [Mass(i.link, i.point, i.m, i.J) for i in case.inertias]
    n = mo.n
    load = [("5", Force("M_c5", np.zeros(n, dtype=complex), mo.z["F"], np.full(n, -150.0))),
            ("3", Force("F_3", np.full(n, 40 - 25j), mo.z["D"], np.zeros(n)))]
    return mo, kinetostatics(mo, masses=masses, loads=load, gravity=gravity)


def test_the_triad_forces_satisfy_the_power_balance_and_the_lever():
    _, fa = _forces()
    scale = np.max(np.abs(fa.M_balance))
    assert np.max(np.abs(fa.M_balance - fa.M_balance_power)) < 1e-10 * scale
    assert np.max(np.abs(fa.M_balance - fa.M_balance_lever)) < 1e-10 * scale


def test_every_link_of_the_triad_is_in_equilibrium():
    """The six reactions found together hold each of the four links (forces and moments), to rounding."""
    from graphmethods.dynamics.forces.base import on_link, resultant
    from graphmethods.dynamics.forces.statics import moment_about

    mo, fa = _forces()
    for link in ("2", "3", "4", "5"):
        forces = list(fa.applied[link]) + [on_link(r, link) for r in fa.reactions.values() if link in (r.by, r.on)]
        size = max(np.max(np.abs(f.F)) for f in forces)
        assert np.max(np.abs(resultant(forces, mo.n))) < 1e-9 * size
        assert np.max(np.abs(moment_about(forces, mo.z["B"]))) < 1e-9 * size
    assert {"R_12", "R_23", "R_34", "R_35", "R_04", "R_05", "R_01"} <= set(fa.reactions)


def test_the_forces_command_prints_the_triad_reactions():
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-m", "graphmethods", "forces", "triad-six-bar", "--phi-deg", "30",
                          "--gravity", "--json"], capture_output=True, text=True, check=True,
                         env={**__import__("os").environ, "PYTHONPATH": str(pathlib.Path(__file__).parents[1])})
    data = json.loads(out.stdout)
    assert data["structure"] == "I(0,1) → III(2,3,4,5)"
    assert abs(data["M_balance"] - data["M_balance_lever"]) < 1e-9 * abs(data["M_balance"])
    assert set(data["reactions"]) == {"R_01", "R_04", "R_05", "R_12", "R_23", "R_34", "R_35"}
