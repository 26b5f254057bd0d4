"""Problem files of any linkage ("kind": "linkage"): reading, validation, and the dynamics on them."""

import copy
import json
import math
import pathlib

import numpy as np
import pytest

from graphmethods.compat import trapezoid
from graphmethods.dynamics.study import Study
from graphmethods.errors import AssemblyError, InputError
from graphmethods.kinematics import case_from_dict, read_case

DATA = pathlib.Path(__file__).parents[1] / "graphmethods" / "problems" / "data"
PRESS = json.loads((DATA / "slider_crank_press.json").read_text())


def press_as_linkage() -> dict:
    """The slider-crank press problem written in the linkage format."""
    p = PRESS
    return {
        "kind": "linkage", "name": "press as a linkage",
        "fixed": {"O": [0, 0]}, "crank": {"centre": "O", "pin": "A", "r": p["r"]},
        "groups": [{"type": "RRP", "links": [2, 3], "P": "A", "C": "B", "l": p["l"],
                    "guide": {"link": 0, "through": [0, p["e"]], "angle_deg": 0}, "branch": 1}],
        "points": {"S2": {"link": 2, "from": "A", "distance": p["l_AS2"]}},
        "output": "B", "working_stroke": "toward_crank",
        "masses": {"1": {"J": p["J1"]}, "2": {"m": p["m2"], "J": p["J_S2"], "at": "S2"},
                   "3": {"m": p["m3"], "at": "B"}},
        "load": {"force": p["F0"], "on": "B", "from": p["force_from"], "to": p["force_to"]},
        "n_rpm": p["n_rpm"], "delta": p["delta"],
    }


def test_the_press_written_as_a_linkage_gives_the_press_study():
    """The whole dynamics on the core equals the dynamics on the slider-crank class."""
    old = Study(read_case(DATA / "slider_crank_press.json"), positions=24).summary()
    new = Study(case_from_dict(press_as_linkage()), positions=24).summary()
    for key in ("M_d", "delta_W_max", "J_F_energy", "J_F_wittenbauer", "J_e_min", "J_e_max", "J_e_mean", "J_F_exact",
                "phi_omega_max_deg", "phi_omega_min_deg"):
        assert new[key] == pytest.approx(old[key], rel=1e-9, abs=1e-9), key


def test_six_bar_press_file_reduced_model_against_differences_of_positions():
    case = read_case(DATA / "six_bar_press.json")
    assert case.linkage.structure().formula == "I(0,1) → II(2,3) → II(4,5)"
    study = Study(case, positions=12)
    lk = case.linkage
    phi = np.array(study.positions.phi)
    h = 1e-5
    sp, sm = lk.solve(phi + lk.sense * h, level=0), lk.solve(phi - lk.sense * h, level=0)
    J = np.zeros_like(phi)
    for it in case.inertias:
        v = (sp.z[it.point] - sm.z[it.point]) / (2 * h)
        th = np.angle(np.exp(1j * (sp.theta[it.link] - sm.theta[it.link]))) / (2 * h)
        J += it.m * np.abs(v) ** 2 + it.J * th ** 2
    assert np.abs(study.J_e - J).max() <= 1e-7 * J.max()
    H = lk.stroke_H()
    assert study.M_d == pytest.approx(6000.0 * H * 0.8 / (2 * math.pi), rel=1e-12)
    s = study.summary()
    assert s["J_F_exact"] > 0 and abs(s["J_F_wittenbauer_rel_error"]) < 0.3


def bad(mutate):
    d = copy.deepcopy(press_as_linkage())
    mutate(d)
    return d


@pytest.mark.parametrize("mutate, match", [
    (lambda d: d.pop("crank"), r"key 'crank': is missing"),
    (lambda d: d["groups"][0].update(type="RRX"), r"key 'groups\[0\].type': must be one of"),
    (lambda d: d["groups"][0].update(l=-1), r"key 'groups\[0\].l': must be > 0"),
    (lambda d: d["groups"][0].update(branch=2), r"key 'groups\[0\].branch': must be 1 or -1"),
    (lambda d: d["groups"][0].pop("C"), r"key 'groups\[0\].C': is missing"),
    (lambda d: d["groups"][0].update(links=[2]), r"key 'groups\[0\].links'"),
    (lambda d: d["groups"][0]["guide"].update(through="X"), r"needs X"),
    (lambda d: d.update(colour=3), r"key 'colour': unknown key"),
    (lambda d: d["masses"]["2"].update(at="S9"), r"key 'masses.2.at': no point 'S9'"),
    (lambda d: d["masses"].update({"7": {"m": 1, "at": "B"}}), r"key 'masses.7': no moving link 7"),
    (lambda d: d["load"].update(on="A"), r"key 'load.on': a force acts on the output slider 'B'"),
    (lambda d: d["load"].update({"from": 0.9, "to": 0.1}), r"key 'load.from': must be less than"),
    (lambda d: d.update(delta=2), r"key 'delta': must be between 0 and 1"),
    (lambda d: d["points"]["S2"].update(link=9), r"point 'S2' is on link '9'"),
])
def test_bad_files_give_one_line_naming_the_key(mutate, match):
    with pytest.raises(InputError, match=match) as exc:
        case_from_dict(bad(mutate), source="press.json")
    assert "\n" not in str(exc.value) and str(exc.value).startswith("press.json: ")


def test_a_linkage_that_cannot_assemble_names_the_position_and_the_condition():
    d = bad(lambda d: d["groups"][0].update(l=0.1))
    with pytest.raises(AssemblyError, match=r"press.json: .*RRP \(2, 3\): cannot be assembled at angle #\d+ .*"
                                            r"from the guide of B, farther than AB = 0.1 m"):
        case_from_dict(d, source="press.json")


LINKAGE_FILES = sorted(p.name for p in DATA.glob("*.json") if json.loads(p.read_text()).get("kind") == "linkage")


def test_at_least_five_course_mechanisms_ship_as_linkage_files():
    assert {"six_bar_press.json", "slotting_machine.json", "whitworth_quick_return.json",
            "two_slider_compressor.json", "single_cylinder_engine.json"} <= set(LINKAGE_FILES)
    for name in LINKAGE_FILES:
        title = json.loads((DATA / name).read_text())["name"]
        assert set(title) == {"en", "ru", "zh"}, name


@pytest.mark.parametrize("name", LINKAGE_FILES)
def test_linkage_files_study_and_reduced_inertia(name):
    case = read_case(DATA / name)
    lk = case.linkage
    assert lk.structure().dof == 1
    study = Study(case, positions=12, estimate=False)
    phi = np.array(study.positions.phi)
    h = 1e-5
    sp, sm = lk.solve(phi + lk.sense * h, level=0), lk.solve(phi - lk.sense * h, level=0)
    J = np.zeros_like(phi)
    for it in case.inertias:
        v = (sp.z[it.point] - sm.z[it.point]) / (2 * h)
        th = np.angle(np.exp(1j * (sp.theta[it.link] - sm.theta[it.link]))) / (2 * h)
        J += it.m * np.abs(v) ** 2 + it.J * th ** 2
    assert np.abs(study.J_e - J).max() <= 1e-7 * J.max()
    ld = case.load
    if ld.kind != "diagram":        # (the engine's diagram load is checked by its own test)
        span = lk.stroke_H() if ld.kind == "force" else lk.psi_max()
        assert study.M_d == pytest.approx(ld.magnitude * span * (ld.end - ld.start) / (2 * math.pi), rel=1e-12)
    assert study.excess_work.delta_W_max > 0


def test_course_mechanisms_closed_forms():
    """Strokes and time ratios that the geometry gives by hand."""
    sm = read_case(DATA / "slotting_machine.json").linkage
    assert sm.stroke_H() == pytest.approx(2 * 0.6 * (0.10 / 0.30), rel=1e-12)          # 2·O3B·sin(ψ/2)
    beta = 2 * math.asin(0.10 / 0.30)
    assert sm.strokes().K == pytest.approx((math.pi + beta) / (math.pi - beta), rel=1e-12)
    ww = read_case(DATA / "whitworth_quick_return.json").linkage
    assert ww.strokes().K == pytest.approx(2.0, rel=1e-12)                             # asin(d/r) = 30°
    assert ww.stroke_H() == pytest.approx(2 * 0.15, rel=1e-12)
    # the lever turns fully
    assert ww.strokes() is not None and np.ptp(np.unwrap(ww.motion(m=12).theta["3"])) > 1.9 * math.pi
    vc = read_case(DATA / "two_slider_compressor.json").linkage
    assert vc.stroke_H() == pytest.approx(0.12, rel=1e-12) and vc.strokes().K == pytest.approx(1.0, abs=1e-12)


def test_single_cylinder_engine_gas_force_from_the_indicator_diagram():
    data = json.loads((DATA / "single_cylinder_engine.json").read_text())
    case = read_case(DATA / "single_cylinder_engine.json")
    study = Study(case, positions=24)
    H = case.linkage.stroke_H()
    assert H == pytest.approx(0.1, rel=1e-12)                    # 2r, centred
    exp_, comp = data["load"]["diagram"]
    area = lambda p: float(trapezoid(p["F"], p["s"]))         # noqa: E731 - work per unit stroke
    # the constant moment balances the cycle: it resists (negative) by the net gas work over a turn
    assert study.M_d == pytest.approx(-H * (area(exp_) - area(comp)) / (2 * math.pi), rel=1e-12)
    work = study.positions.working
    M_r = np.asarray(study.M_r)
    inner = ~np.asarray(study.positions.extreme)
    assert np.all(M_r[work & inner] < 0) and np.all(M_r[~work & inner] > 0)   # gas drives, then resists
    fine = Study(case, positions=192, estimate=False).summary()
    assert fine["J_F_wittenbauer"] == pytest.approx(fine["J_F_exact"], rel=0.01)


def test_bad_diagram_loads_name_the_key():
    d = json.loads((DATA / "single_cylinder_engine.json").read_text())
    d["load"]["diagram"][1]["s"][3] = 0.05
    with pytest.raises(InputError, match=r"key 'load.diagram\[1\].s': the stroke fractions must not decrease"):
        case_from_dict(d, source="engine.json")
    d = json.loads((DATA / "single_cylinder_engine.json").read_text())
    d["load"]["diagram"][0]["drives"] = "yes"
    with pytest.raises(InputError, match=r"key 'load.diagram\[0\].drives'"):
        case_from_dict(d, source="engine.json")


def test_the_four_bar_and_the_shaper_written_as_linkages_give_their_studies():
    """A rocker output with a moment load, and a slotted lever driving a ram, through the whole dynamics."""
    fb = json.loads((DATA / "four_bar_rocker.json").read_text())
    four_bar = {
        "kind": "linkage", "fixed": {"O1": [0, 0], "O2": [fb["l1"], 0]},
        "crank": {"centre": "O1", "pin": "A", "r": fb["l2"]},
        "groups": [{"type": "RRR", "links": [2, 3], "P": "A", "Q": "O2", "C": "B", "l_PC": fb["l3"], "l_QC": fb["l4"]}],
        "points": {"S2": {"link": 2, "from": "A", "distance": fb["l_AS2"]},
                   "S3": {"link": 3, "from": "O2", "distance": fb["l_O2S3"]}},
        "output": 3,
        "masses": {"1": {"J": fb["J1"]}, "2": {"m": fb["m2"], "J": fb["J_S2"], "at": "S2"},
                   "3": {"m": fb["m3"], "J": fb["J_S3"], "at": "S3"}},
        "load": {"moment": fb["M3"], "on": 3, "from": fb["moment_from"], "to": fb["moment_to"]},
        "n_rpm": fb["n_rpm"], "delta": fb["delta"]}
    sh = json.loads((DATA / "shaper.json").read_text())
    th = math.radians(sh.get("theta_O3_deg", -90.0))
    shaper = {
        "kind": "linkage", "fixed": {"O1": [0, 0], "O3": [sh["l_O1O3"] * math.cos(th), sh["l_O1O3"] * math.sin(th)]},
        "crank": {"centre": "O1", "pin": "A", "r": sh["r"]},
        "groups": [{"type": "RPR", "links": [2, 3], "P": "A", "Q": "O3", "point": "A3"},
                   {"type": "RRP", "links": [4, 5], "P": "B", "C": "C", "l": sh["l_BC"],
                    "guide": {"link": 0, "through": [0, sh["y_guide"]], "angle_deg": 0},
                    "branch": sh.get("assembly", 1)}],
        "points": {"B": {"link": 3, "from": "O3", "distance": sh["l_O3B"]},
                   "S3": {"link": 3, "from": "O3", "distance": sh["l_O3S3"]},
                   "S4": {"link": 4, "from": "B", "distance": sh["l_BS4"]}},
        "output": "C",
        "masses": {"1": {"J": sh["J1"]}, "2": {"m": sh.get("m2", 0.0), "at": "A"},
                   "3": {"m": sh["m3"], "J": sh["J_S3"], "at": "S3"}, "4": {"m": sh["m4"], "J": sh["J_S4"], "at": "S4"},
                   "5": {"m": sh["m5"], "at": "C"}},
        "load": {"force": sh["F0"], "on": "C", "from": sh["force_from"], "to": sh["force_to"]},
        "n_rpm": sh["n_rpm"], "delta": sh["delta"]}
    for fname, data in (("four_bar_rocker.json", four_bar), ("shaper.json", shaper)):
        old = Study(read_case(DATA / fname), positions=24).summary()
        new = Study(case_from_dict(data), positions=24).summary()
        for key in ("M_d", "delta_W_max", "J_F_energy", "J_F_wittenbauer", "J_e_min", "J_e_max", "J_F_exact"):
            assert new[key] == pytest.approx(old[key], rel=1e-9, abs=1e-9), (fname, key)
        for key in ("phi_omega_max_deg", "phi_omega_min_deg"):   # a flat extremum, located to the solver's tolerance
            assert new[key] == pytest.approx(old[key], abs=1e-4), (fname, key)


def test_an_indicator_diagram_draws_its_moment_figures_and_the_lever_refuses_it(tmp_path, capsys):
    from graphmethods import cli
    from graphmethods.sheets import dynamics as sd
    from graphmethods.sheets.zhukovsky_lever import zhukovsky_lever
    case = read_case(DATA / "single_cylinder_engine.json")
    study = Study(case, positions=12)
    sd.moment_graph(study)                       # the gas moment as M_d, the constant resistance as M_r
    sd.inertia_graph(study)                      # J_e does not depend on the load
    with pytest.raises(InputError, match="indicator diagram"):
        zhukovsky_lever(study)                # one working-stroke force only (left for later)
    out = tmp_path / "sheet.svg"
    rc = cli.main(["study", str(DATA / "single_cylinder_engine.json"), "--no-exact", "--sheet", str(out)])
    captured = capsys.readouterr()
    assert rc == 0, captured.err
    assert out.exists() and "curve-M_d" in out.read_text(encoding="utf-8")


def test_fixed_joints_that_are_not_an_object_are_one_line():
    """"fixed": 1.0 (a number where the joints belong) is refused naming the key, not a TypeError."""
    data = json.loads((DATA / "six_bar_press.json").read_text())
    for bad in (1.0, [0, 0], "O1"):
        with pytest.raises(InputError, match="fixed.*must be an object"):
            case_from_dict({**data, "fixed": bad}, source="f.json")
