"""A mechanism as it is drawn: the structure found by the program, both forms of every built-in linkage
alike, every dyad kind against differences of its positions, slides, swinging drivers, loads anywhere
with the power balance, refusals with their reasons, and random drawn mechanisms (Hypothesis)."""

import json
import math
import pathlib

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from graphmethods import cli
from graphmethods.dynamics.forces import case_forces
from graphmethods.errors import InputError
from graphmethods.kinematics import case_from_dict, read_case
from graphmethods.kinematics.drawn import drawn_case, link_angles, slide_kinematics

DATA = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data"
BUILTIN = ["slider_crank_press.json", "shaper.json", "four_bar_rocker.json", "slotted_lever.json",
           "scotch_yoke_pump.json", "single_cylinder_engine.json", "six_bar_press.json", "slotting_machine.json",
           "two_slider_compressor.json", "whitworth_quick_return.json", "triad_six_bar.json"]


def drawn(joints, links, slides=(), driver=None, **extra):
    return {"kind": "linkage", "joints": joints, "links": links, "slides": list(slides),
            "driver": driver or {"link": 1, "about": "O"}, "omega_1": extra.pop("omega_1", 10.0), **extra}


FOUR_BAR = drawn({"O": [0, 0], "A": [0.08, 0.0], "B": [0.2, 0.22], "D": [0.3, 0.0], "S2": [0.14, 0.11]},
                 {"0": ["O", "D"], "1": ["O", "A"], "2": ["A", "B", "S2"], "3": ["D", "B"]})
SLIDER = drawn({"O": [0, 0], "A": [0.0, 0.1], "B": [0.38, 0.03]},
               {"0": ["O"], "1": ["O", "A"], "2": ["A", "B"], "3": ["B"]},
               [{"block": 3, "on": 0, "at": "B", "angle_deg": 0}])
SLOTTED = drawn({"O": [0, 0], "A": [0.1, 0.0], "O3": [0.0, -0.3], "B": [0.25, 0.45]},
                {"0": ["O", "O3"], "1": ["O", "A"], "2": ["A"], "3": ["O3", "B"]},
                [{"block": 2, "on": 3, "at": "A", "angle_deg": math.degrees(math.atan2(0.3, 0.1))}])
YOKE = drawn({"O": [0, 0], "A": [0.06, 0.08], "C": [0.06, -0.1]},
             {"0": ["O"], "1": ["O", "A"], "2": ["A"], "3": ["C"]},
             [{"block": 2, "on": 3, "at": "A", "angle_deg": 90}, {"block": 3, "on": 0, "at": "C", "angle_deg": 0}])
PRP = drawn({"O": [0, 0], "A": [0.1, 0.0], "C": [0.1, 0.05]},
            {"0": ["O"], "1": ["O", "A"], "2": ["C"], "3": ["C"]},
            [{"block": 2, "on": 1, "at": "C", "angle_deg": 90}, {"block": 3, "on": 0, "at": "C", "angle_deg": 0}],
            driver={"link": 1, "about": "O", "range_deg": [-60, 60]})
TRIAD = json.loads((DATA / "drawn" / "example_six_bar_triad.json").read_text(encoding="utf-8"))
KINDS = {"RRR": FOUR_BAR, "RRP": SLIDER, "RPR": SLOTTED, "RPP": YOKE, "PRP": PRP, "triad": TRIAD}


# ----------------------------------------------------------------------------------------------- both forms
def test_every_builtin_linkage_ships_in_the_drawn_form():
    from graphmethods.problems import builtin

    assert sorted(BUILTIN) == sorted(builtin.LINKAGES.values())
    for name in builtin.LINKAGES:
        assert builtin.case_path(f"drawn/{name}").parent.name == "drawn"


@pytest.mark.parametrize("name", BUILTIN)
def test_every_builtin_linkage_in_both_forms_gives_the_same_results(name):
    group, draw = read_case(DATA / name), read_case(DATA / "drawn" / name)
    assert draw.drawn.structure.formula == group.linkage.structure().formula
    for kw in ({"m": 12}, {"phi": np.radians([7.0, 133.0, 301.5])}):
        a = group.linkage.motion(**kw, omega_1=group.omega_m, epsilon_1=3.0)
        b = draw.linkage.motion(**kw, omega_1=draw.omega_m, epsilon_1=3.0)
        scale = max(1.0, max(float(np.abs(a.a_[k]).max()) for k in a.points))
        for k in a.points:
            for x, y in ((a.z, b.z), (a.v_, b.v_), (a.a_, b.a_)):
                assert np.abs(np.asarray(x[k]) - np.asarray(y[k])).max() <= 1e-12 * scale, (name, k)
        for k in group.linkage.links:
            assert np.abs(a.omega[k] - b.omega[k]).max() <= 1e-12 * scale
            assert np.abs(a.epsilon[k] - b.epsilon[k]).max() <= 1e-12 * scale
    fa = case_forces(group, phi_deg=[41.0, 222.0], gravity=True, epsilon_1=2.0)
    fb = case_forces(draw, phi_deg=[41.0, 222.0], gravity=True, epsilon_1=2.0)
    ref = float(np.abs(fa.M_balance).max()) + 1.0
    assert np.abs(fa.M_balance - fb.M_balance).max() <= 1e-12 * ref
    big = max(float(np.abs(r.R).max()) for r in fa.reactions.values()) + 1.0
    for key, r in fa.reactions.items():
        assert np.abs(r.R - fb.reactions[key].R).max() <= 1e-12 * big, key


@pytest.mark.parametrize("name", ["slider_crank_press.json", "six_bar_press.json"])
def test_the_study_of_both_forms_is_the_same(name):
    from graphmethods.dynamics.study import Study

    a = Study(read_case(DATA / name), positions=24).summary()
    b = Study(read_case(DATA / "drawn" / name), positions=24).summary()
    for key in ("M_d", "delta_W_max", "J_F_energy", "J_F_wittenbauer", "J_F_exact", "J_e_min", "J_e_max"):
        assert b[key] == pytest.approx(a[key], rel=1e-9, abs=1e-12), key


# ----------------------------------------------------------------------------------------------- every dyad kind
@pytest.mark.parametrize("kind", sorted(KINDS))
def test_each_dyad_kind_velocities_and_accelerations_are_the_derivatives_of_positions(kind):
    case = drawn_case(KINDS[kind])
    assert [g.kind for g in case.drawn.structure.groups] == [kind]
    lk = case.linkage
    phi = np.radians(np.arange(5.0, 360.0, 23.0) if lk.swing is None else np.linspace(-55.0, 55.0, 9))
    w = 1.0
    mo = lk.motion(phi=phi, omega_1=w)
    h = 1e-5
    ds = lk.sense
    plus, minus = lk.solve(phi + ds * h, omega_1=w), lk.solve(phi - ds * h, omega_1=w)
    coincident = {g.coincident for g in lk.groups if g.kind in ("RPR", "RPP")}   # a point of the slotted link
    for k in mo.points:                                                          # under the block, at one instant
        if k in coincident:
            continue
        scale = max(1.0, float(np.abs(mo.a_[k]).max()))
        v_fd = (plus.z[k] - minus.z[k]) / (2 * h)
        a_fd = (plus.v[k] - minus.v[k]) / (2 * h)
        assert np.abs(v_fd - mo.v_[k]).max() <= 1e-7 * scale, k
        assert np.abs(a_fd - mo.a_[k]).max() <= 1e-7 * scale, k
    for s, sl in zip(slide_kinematics(case.drawn, mo), case.drawn.slides):   # v_rel, a_rel: derivatives of
        def coord(state, sl=sl):                                              # the slide's coordinate
            if sl.on == "0":
                return (state.z[sl.at] * np.exp(-1j * sl.angle)).real
            u = np.exp(1j * np.asarray(state.theta[sl.on])) * sl.turn
            return ((state.z[sl.at] - state.z[sl.ref]) * np.conj(u)).real
        c0, cp, cm = coord(lk.solve(phi, level=0)), coord(plus), coord(minus)
        assert np.abs((cp - cm) / (2 * h) - s["v_rel"]).max() <= 1e-7
        assert np.abs((cp - 2 * c0 + cm) / h**2 - s["a_rel"]).max() <= 1e-4


def test_slotted_lever_coriolis_against_the_closed_form():
    """Crank r at φ, pivot O3 below O1: the block's relative motion along the lever and a^k = 2ω₃v_rel."""
    case = drawn_case(SLOTTED)
    phi = np.radians([10.0, 100.0, 250.0])
    w1, e1 = 10.0, 4.0
    mo = case.linkage.motion(phi=phi, omega_1=w1, epsilon_1=e1)
    s = slide_kinematics(case.drawn, mo)[0]
    A = 0.1 * np.exp(1j * phi)
    R = A - (-0.3j)
    rho = np.abs(R)
    u = R / rho
    vA = 1j * w1 * A
    v_rel = (vA * np.conj(u)).real                   # d|O3A|/dt
    w3 = (vA * np.conj(1j * u)).real / rho
    assert np.allclose(s["v_rel"], v_rel, atol=1e-12)
    assert np.allclose(mo.omega["3"], w3, atol=1e-12)
    assert np.allclose(s["a_cor"], 2j * w3 * v_rel * u, atol=1e-12)
    angles = link_angles(case.drawn, mo)
    assert np.allclose(angles["3"], np.degrees(np.angle(u)) % 360, atol=1e-10)


# ----------------------------------------------------------------------------------------------- forces
def test_power_balance_with_load_vectors_moments_and_gravity():
    data = json.loads(json.dumps(FOUR_BAR))
    data["masses"] = {"1": {"J": 0.02}, "2": {"m": 2.0, "J": 0.01, "at": "S2"}, "3": {"m": 1.5, "J": 0.004,
                                                                                     "at": [0.25, 0.1]}}
    data["loads"] = [{"force": [50, 25], "link": 2, "at": "B"}, {"moment": -7.0, "link": 3},
                     {"force": [0, -30], "link": 3, "at": [0.28, 0.05]}]
    case = drawn_case(data)
    fa = case_forces(case, phi_deg=[20.0, 150.0, 275.0], gravity=True, epsilon_1=2.5)
    mo = fa.motion
    g = 9.81
    power = np.zeros(mo.n)
    for it in case.inertias:
        v, a = mo.v_[it.point], mo.a_[it.point]
        F = -it.m * a - 1j * it.m * g
        power += (F * np.conj(v)).real - it.J * mo.epsilon[it.link] * mo.omega[it.link]
    for ld in case.drawn.loads:
        if ld.kind == "force":
            power += (ld.F * np.conj(mo.v_[ld.at])).real
        else:
            power += ld.M * mo.omega[ld.link]
    M_b = -power / mo.omega["1"]
    assert np.allclose(fa.M_balance, M_b, rtol=1e-10, atol=1e-10)
    assert np.allclose(fa.M_balance_lever, M_b, rtol=1e-10, atol=1e-10)


# ----------------------------------------------------------------------------------------------- swinging drivers
LEVER = drawn({"O": [0, 0], "A": [0.1, 0.0], "B": [0.45, 0.1]},
              {"0": ["O"], "1": ["O", "A"], "2": ["A", "B"], "3": ["B"]},
              [{"block": 3, "on": 0, "at": "B", "angle_deg": 0}],
              driver={"link": 1, "about": "O", "range_deg": [-30, 60]})


def test_a_swinging_driver_spreads_its_positions_over_the_range_and_refuses_angles_outside(capsys):
    case = drawn_case(LEVER)
    mo = case.linkage.motion(m=9, omega_1=1.0)
    assert np.allclose(np.degrees(mo.phi), np.arange(-30.0, 61.0, 10.0))
    assert case.linkage.strokes() is None
    with pytest.raises(InputError, match="outside its range"):
        case.linkage.motion(phi=np.radians([90.0]))
    assert np.allclose(np.degrees(case.linkage.motion(phi=np.radians([350.0])).phi), [-10.0])


def test_the_command_line_prints_a_swinging_driver_s_angles_as_the_range_gives_them(tmp_path, capsys):
    f = tmp_path / "lever.json"
    f.write_text(json.dumps(LEVER))
    assert cli.main(["kinematics", str(f), "--positions", "3", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["positions"]
    assert [r["phi_deg"] for r in rows] == [-30.0, 0.0, 30.0, 60.0]
    assert cli.main(["kinematics", str(f), "--phi-deg", "350", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["positions"][0]["phi_deg"] == -10.0
    assert cli.main(["kinematics", str(f), "--phi-deg", "90"]) == 2
    assert "outside its range" in capsys.readouterr().err
    assert cli.main(["forces", str(f), "--phi-deg", "-20", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["phi_deg"] == -20.0


def test_a_range_that_reaches_a_toggle_is_refused_with_its_angle():
    data = drawn({"O": [0, 0], "A": [0.1, 0.0], "B": [0.1, 0.25], "D": [0.3, 0.25]},
                 {"0": ["O", "D"], "1": ["O", "A"], "2": ["A", "B"], "3": ["D", "B"]},
                 driver={"link": 1, "about": "O", "range_deg": [0, 180]})
    with pytest.raises(InputError, match=r"toggle.*φ = "):
        drawn_case(data)


def test_a_slotted_lever_whose_lever_turns_fully_runs_kinematics_and_forces(capsys):
    data = drawn({"O": [0, 0], "A": [0.2, 0.0], "O3": [0.0, -0.1], "B": [-0.1, -0.15]},
                 {"0": ["O", "O3"], "1": ["O", "A"], "2": ["A"], "3": ["O3", "B"]},
                 [{"block": 2, "on": 3, "at": "A", "angle_deg": math.degrees(math.atan2(0.1, 0.2))}],
                 masses={"3": {"m": 3.0, "J": 0.02, "at": "O3"}})
    case = drawn_case(data)
    fa = case_forces(case, phi_deg=[30.0], gravity=True)
    assert np.allclose(fa.M_balance, fa.M_balance_power, rtol=1e-9)


# ----------------------------------------------------------------------------------------------- refusals
REFUSED = {
    "truss": (drawn({"O": [0, 0], "A": [0.1, 0], "B": [0.05, 0.1]},
                    {"0": ["O", "B"], "1": ["O", "A"], "2": ["A", "B"]}), "W = 3n − 2p₅ − p₄ = 3·2 − 2·3 − 0 = 0"),
    "two inputs": (drawn({"O": [0, 0], "A": [0.1, 0], "B": [0.3, 0.1], "C": [0.4, 0.3], "D": [0.6, 0]},
                         {"0": ["O", "D"], "1": ["O", "A"], "2": ["A", "B"], "3": ["B", "C"], "4": ["C", "D"]}),
                   "W = .* = 2: it needs 2 inputs"),
    "no pair": (drawn({"O": [0, 0], "A": [0.1, 0], "B": [0.3, 0.2], "D": [0.4, 0], "X": [1, 1]},
                      {"0": ["O", "D"], "1": ["O", "A"], "2": ["A", "B"], "3": ["D", "B"], "4": ["X"]}),
                "link 4 has no pair"),
    "PPP": (drawn({"O": [0, 0], "A": [0.1, 0], "P2": [0.1, 0.05], "C": [0.2, 0.1]},
                  {"0": ["O"], "1": ["O", "A"], "2": ["P2"], "3": ["C"]},
                  [{"block": 2, "on": 1, "at": "P2", "angle_deg": 90},
                   {"block": 2, "on": 3, "at": "P2", "angle_deg": 0},
                   {"block": 3, "on": 0, "at": "C", "angle_deg": 45}]), r"three prismatic pairs \(PPP\)"),
    "pin on a slide": (drawn({"O": [0, 0], "A": [0.1, 0.0], "O3": [0.0, -0.3]},
                             {"0": ["O", "O3"], "1": ["O", "A"], "2": ["A"], "3": ["O3", "A"]},
                             [{"block": 2, "on": 3, "at": "A", "angle_deg": 60}]), "listed on both link 2 and link 3"),
    "driver off the frame": (drawn({"O": [0, 0], "A": [0.1, 0], "B": [0.3, 0.2], "D": [0.4, 0]},
                                   {"0": ["D"], "1": ["O", "A"], "2": ["A", "B"], "3": ["D", "B"]}),
                             "must be a joint of the frame"),
    "drawn at a toggle": (drawn({"O": [0, 0], "A": [0.1, 0], "B": [0.3, 0.0], "D": [0.5, 0]},
                                {"0": ["O", "D"], "1": ["O", "A"], "2": ["A", "B"], "3": ["D", "B"]}),
                          "drawn at a toggle"),
    "class IV": (drawn({"O": [0, 0], "A": [0.1, 0], "X1": [0.25, 0.15], "X2": [0.3, -0.05], "Q": [0.6, 0.05],
                        "Y1": [0.5, 0.2], "Y2": [0.5, -0.1]},
                       {"0": ["O", "Q"], "1": ["O", "A"], "2": ["A", "X1", "X2"], "3": ["Q", "Y1", "Y2"],
                        "4": ["X1", "Y1"], "5": ["X2", "Y2"]}),
                 "links 2, 3, 4, 5 form no Assur group of class II or III"),
    "passive constraint": (drawn({"O1": [0, 0], "A": [0.0, 0.1], "B": [0.3, 0.1], "O2": [0.3, 0], "C": [0.15, 0.1],
                                  "O3": [0.15, 0]},
                                 {"0": ["O1", "O2", "O3"], "1": ["O1", "A"], "2": ["A", "C", "B"], "3": ["O2", "B"],
                                  "4": ["O3", "C"]}, driver={"link": 1, "about": "O1"}), "passive"),
}


@pytest.mark.parametrize("name", sorted(REFUSED))
def test_refused_structures_name_their_reason(name):
    data, msg = REFUSED[name]
    with pytest.raises(InputError) as exc:
        drawn_case(data)
    if msg is not None:
        assert exc.match(msg)
    assert "\n" not in str(exc.value)


def test_a_triad_is_found_solved_as_drawn_and_its_forces_balance():
    """The six-bar with a class III group: found as III(2,3,4,5), kept in its drawn assembly, and its force
    analysis with loads anywhere and gravity agrees with the power balance and the lever."""
    case = drawn_case(TRIAD)
    assert case.drawn.structure.formula == "I(0,1) → III(2,3,4,5)"
    assert case.drawn.structure.as_json()["groups"] == [{"class": 3, "links": [2, 3, 4, 5], "type": "triad"}]
    fa = case_forces(case, phi_deg=[0.0, 100.0, 250.0], gravity=True, epsilon_1=3.0)
    assert np.allclose(fa.M_balance, fa.M_balance_power, rtol=1e-9, atol=1e-9)
    assert np.allclose(fa.M_balance, fa.M_balance_lever, rtol=1e-9, atol=1e-9)


# ----------------------------------------------------------------------------------------------- command line
def test_kinematics_json_of_a_drawn_file_follows_the_contract(tmp_path, capsys):
    f = tmp_path / "slotted.json"
    f.write_text(json.dumps(SLOTTED))
    assert cli.main(["kinematics", str(f), "--phi-deg", "10,100", "--epsilon-1", "4", "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    assert res["structure"] == {"formula": "I(0,1) → II(2,3)", "dof": 1, "n": 3, "p5": 4, "p4": 0, "class": 2,
                                "groups": [{"class": 2, "links": [2, 3], "type": "RPR"}]}
    row = res["positions"][1]
    assert row["phi_deg"] == 100.0 and set(row["links"]["3"]) == {"omega", "epsilon", "angle_deg"}
    (sl,) = row["slides"]
    assert set(sl) == {"block", "on", "at", "v_rel", "a_rel", "a_cor"} and sl["block"] == 2 and sl["on"] == 3


def test_forces_json_lists_the_loads_and_a_missing_key_is_named_in_one_line(tmp_path, capsys):
    data = json.loads(json.dumps(SLIDER))
    data["loads"] = [{"force": [-200, 10], "link": 3, "at": "B"}]
    f = tmp_path / "slider.json"
    f.write_text(json.dumps(data))
    assert cli.main(["forces", str(f), "--phi-deg", "60", "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    assert res["loads"][0]["force"] == [-200.0, 10.0] and res["loads"][0]["link"] == 3
    assert cli.main(["study", str(f)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "delta, load" in err[0]


def test_the_group_form_still_reads(capsys):
    assert case_from_dict(json.loads((DATA / "six_bar_press.json").read_text())).linkage.structure().dof == 1


# ----------------------------------------------------------------------------------------------- random drawings
@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(pts=st.lists(st.tuples(st.floats(-0.5, 0.5), st.floats(-0.5, 0.5)), min_size=4, max_size=4),
       kind=st.sampled_from(["RRR", "RRP", "RPR", "RRR+RRP"]), ang=st.floats(-180, 180),
       swing=st.one_of(st.none(), st.tuples(st.floats(-200, 200), st.floats(1, 360))))
def test_random_drawn_mechanisms_assemble_as_drawn_or_are_refused_with_a_reason(pts, kind, ang, swing):
    (ox, oy), (ax, ay), (bx, by), (dx, dy) = pts
    driver = None if swing is None else {"link": 1, "about": "O", "range_deg": [swing[0], swing[0] + swing[1]]}
    if kind == "RRP":
        data = drawn({"O": [ox, oy], "A": [ax, ay], "B": [bx, by]},
                     {"0": ["O"], "1": ["O", "A"], "2": ["A", "B"], "3": ["B"]},
                     [{"block": 3, "on": 0, "at": "B", "angle_deg": ang}], driver=driver)
    elif kind == "RPR":
        data = drawn({"O": [ox, oy], "A": [ax, ay], "D": [dx, dy]},
                     {"0": ["O", "D"], "1": ["O", "A"], "2": ["A"], "3": ["D"]},
                     [{"block": 2, "on": 3, "at": "A", "angle_deg": ang}], driver=driver)
    elif kind == "RRR+RRP":
        data = drawn({"O": [ox, oy], "A": [ax, ay], "B": [bx, by], "D": [dx, dy], "E": [bx + 0.3, by]},
                     {"0": ["O", "D"], "1": ["O", "A"], "2": ["A", "B"], "3": ["D", "B"], "4": ["B", "E"],
                      "5": ["E"]}, [{"block": 5, "on": 0, "at": "E", "angle_deg": ang}], driver=driver)
    else:
        data = drawn({"O": [ox, oy], "A": [ax, ay], "B": [bx, by], "D": [dx, dy]},
                     {"0": ["O", "D"], "1": ["O", "A"], "2": ["A", "B"], "3": ["D", "B"]}, driver=driver)
    try:
        case = drawn_case(data)
    except InputError as exc:
        assert str(exc) and "\n" not in str(exc)
        return
    st0 = case.linkage.solve(np.array([case.drawn.phi_0]), level=0)
    for name, xy in data["joints"].items():             # the drawn assembly kept: never a mirror
        assert abs(complex(st0.z[name][0]) - complex(*xy)) <= 1e-9 * max(1.0, abs(complex(*xy)))
