"""Problem files (graphmethods.kinematics.case) and ``graphmethods kinematics`` (through cli.main)."""

import json
import math
import pathlib

import numpy as np
import pytest

from graphmethods import cli
from graphmethods.errors import AssemblyError, InputError
from graphmethods.kinematics import (
    FourBar,
    FourBarCase,
    Shaper,
    ShaperCase,
    SliderCrank,
    SliderCrankCase,
    SlottedLever,
    SlottedLeverCase,
    case_from_dict,
    read_case,
)

DATA = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data"
PRESS = {"r": 0.1, "l": 0.4, "e": 0.02, "l_AS2": 0.13, "m2": 8.0, "J_S2": 0.12, "m3": 12.0, "J1": 0.5,
         "F0": 5000.0, "force_from": 0.05, "force_to": 0.95, "n_rpm": 300.0, "delta": 0.04}


@pytest.fixture
def run(capsys):
    """``graphmethods kinematics ...`` through cli.main: (exit code, stdout, stderr)."""

    def _run(*argv):
        rc = cli.main(["kinematics", *map(str, argv)])
        out, err = capsys.readouterr()
        return rc, out, err
    return _run


def press_closed_form(phi, r, l, e, l_AS2, omega):
    """Offset slider-crank velocities written out by hand (independent of the package)."""
    s, c = np.sin(phi), np.cos(phi)
    q = e - r * s
    w = np.sqrt(l * l - q * q)
    v_B = omega * (-r * s + q * r * c / w)
    omega_2 = omega * (-r * c / w)
    v_S2x = omega * (-r * s) + l_AS2 * omega_2 * (-q / l)
    v_S2y = omega * (r * c) + l_AS2 * omega_2 * (w / l)
    return v_B, omega_2, np.hypot(v_S2x, v_S2y)


# ------------------------------------------------------------------ case files
def test_press_file_read_as_it_is(press_case_path):
    case = read_case(press_case_path)
    assert isinstance(case, SliderCrankCase) and case.kind == "slider_crank"
    mech = case.mechanism
    assert isinstance(mech, SliderCrank) and (mech.r, mech.l, mech.e) == (0.1, 0.4, 0.02)
    assert case.m2 == 8.0 and case.F0 == 5000.0 and case.delta == 0.04 and case.n_rpm == 300.0
    assert case.omega_m == pytest.approx(10 * math.pi)
    assert [(i.link, i.point, i.m, i.J) for i in case.inertias] == [("OA", "O", 0.0, 0.5), ("AB", "S2", 8.0, 0.12),
                                                                     (None, "B", 12.0, 0.0)]
    assert (case.load.kind, case.load.at, case.load.magnitude, case.load.start, case.load.end) == \
        ("force", "B", 5000.0, 0.05, 0.95)
    assert case.name == "offset slider-crank press"


@pytest.mark.parametrize("fname, cls, mcls", [("four_bar_rocker.json", FourBarCase, FourBar),
                                              ("slotted_lever.json", SlottedLeverCase, SlottedLever),
                                              ("shaper.json", ShaperCase, Shaper)])
def test_example_problem_files(fname, cls, mcls):
    case = read_case(DATA / fname)
    assert isinstance(case, cls) and isinstance(case.mechanism, mcls)
    plan = case.mechanism.velocity_plans(12, omega_1=case.omega_m)
    for inertia in case.inertias:                       # every mass has its point and link in the plan
        assert plan.speed(inertia.point).shape == (13,)
        if inertia.link is not None:
            assert plan.omega(inertia.link).shape == (13,)
    assert case.load.at in plan.vectors or case.load.at in plan.omegas


def test_fractions_and_options_accepted():
    case = case_from_dict({**PRESS, "delta": "1/25", "sense": "cw", "assembly": -1, "kind": "slider_crank"})
    assert case.delta == 0.04 and case.mechanism.sense == -1 and case.mechanism.assembly == -1


@pytest.mark.parametrize("change, err, match", [
    ({"r": None}, InputError, "key 'r' is missing"),
    ({"r": "abc"}, InputError, "key 'r' .* is not a number"),
    ({"r": "nan"}, InputError, "not finite"),
    ({"r": True}, InputError, "key 'r' .* must be a number"),
    ({"r": [0.1]}, InputError, "must be a number"),
    ({"r": -0.1}, InputError, "key 'r' .* must be > 0"),
    ({"m2": -1}, InputError, "key 'm2' .* must be ≥ 0"),
    ({"delta": 1.5}, InputError, "key 'delta' .* between 0 and 1"),
    ({"force_from": 0.9, "force_to": 0.1}, InputError, "force_from = 0.9 must be less than force_to"),
    ({"l_AS2": 0.5}, InputError, "l_AS2 = 0.5 m lies beyond the link"),
    ({"rr": 0.1}, InputError, "unknown key 'rr'"),
    ({"kind": "cam"}, InputError, "unknown kind 'cam'"),
    ({"name": 3}, InputError, "key 'name' must be text"),
    ({"sense": "left"}, InputError, 'must be "ccw" or "cw"'),
    ({"l": 0.1}, AssemblyError, r"<dict>: slider-crank: rod l = 0.1 m is shorter than crank r \+ \|e\| = 0.12 m"),
])
def test_bad_problem_data(change, err, match):
    data = {**PRESS, **change}
    data = {k: v for k, v in data.items() if v is not None}
    with pytest.raises(err, match=match):
        case_from_dict(data)


def test_bad_files(tmp_path):
    with pytest.raises(InputError, match="no such file"):
        read_case(tmp_path / "missing.json")
    bad = tmp_path / "bad.json"
    bad.write_text('{"r": 0.1,', encoding="utf-8")
    with pytest.raises(InputError, match=r"bad.json: not valid JSON \(line 1"):
        read_case(bad)
    bad.write_text("[1, 2]", encoding="utf-8")
    with pytest.raises(InputError, match="one JSON object"):
        read_case(bad)
    fb = json.loads((DATA / "four_bar_rocker.json").read_text(encoding="utf-8"))
    fb["l2"] = 0.2                                            # the crank can no longer turn
    with pytest.raises(AssemblyError, match="cannot make a full turn"):
        case_from_dict(fb)


# ------------------------------------------------------------------ the command
def test_cli_json_press_matches_closed_form(run, press_case_path):
    rc, out, err = run(press_case_path, "--positions", 12, "--json")
    assert rc == 0 and err == ""
    res = json.loads(out)
    rows = res["positions"]
    assert len(rows) == 13 and [r_["position"] for r_ in rows] == list(range(13))
    omega = 300 * math.pi / 30
    phi0 = math.atan2(0.02, math.sqrt(0.5 ** 2 - 0.02 ** 2))            # far dead centre
    phi = phi0 + 2 * math.pi * np.arange(13) / 12
    np.testing.assert_allclose([r_["phi_deg"] for r_ in rows], np.degrees(phi) % 360, atol=1e-10)
    v_B, omega_2, v_S2 = press_closed_form(phi, 0.1, 0.4, 0.02, 0.13, omega)
    np.testing.assert_allclose([r_["v_B"] for r_ in rows], v_B, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose([r_["omega_2"] for r_ in rows], omega_2, rtol=1e-12)
    np.testing.assert_allclose([r_["v_S2"] for r_ in rows], v_S2, rtol=1e-12)
    assert rows[0]["v_B"] == 0.0 and rows[12]["v_B"] == 0.0 and rows[3]["v_B"] < 0   # works toward O
    assert res["K"] == pytest.approx(res["working_angle_deg"] / res["return_angle_deg"])
    assert res["stroke_H"] == pytest.approx(math.sqrt(0.25 - 4e-4) - math.sqrt(0.09 - 4e-4))


def test_cli_text_table(run, press_case_path):
    rc, out, _ = run(press_case_path, "-m", 6)
    assert rc == 0
    lines = out.splitlines()
    head = next(i for i, ln in enumerate(lines) if ln.strip().startswith("position"))
    assert "v_B [m/s]" in lines[head] and "omega_2 [rad/s]" in lines[head] and "phi_deg [°]" in lines[head]
    body = lines[head + 1: head + 8]
    assert [int(ln.split()[0]) for ln in body] == list(range(7))
    assert lines[-1] == "position 6 = position 0"


@pytest.mark.parametrize("fname, keys", [("four_bar_rocker.json", ["omega_2", "omega_3", "v_B", "v_S3"]),
                                         ("slotted_lever.json", ["omega_3", "v_A3", "v_A3A2", "v_B"]),
                                         ("shaper.json", ["omega_4", "v_C", "v_S4", "s_C"])])
def test_cli_other_kinds(run, fname, keys):
    rc, out, _ = run(DATA / fname, "--json", "-m", 24)
    assert rc == 0
    res = json.loads(out)
    assert len(res["positions"]) == 25 and all(k in res["positions"][5] for k in keys)
    case = read_case(DATA / fname)
    plan = case.mechanism.velocity_plans(24, omega_1=case.omega_m)
    last = max(case.mechanism.link_numbers)
    np.testing.assert_allclose([r_[f"omega_{last}"] for r_ in res["positions"]], plan.omega(last), rtol=1e-15)


@pytest.mark.parametrize("content, match", [
    ('{"r": 0.1}', "key 'l' is missing"),
    ('{"r": "x"}', "is not a number"),
    ("{", "not valid JSON"),
    (json.dumps({**PRESS, "l": 0.1}), "rod l = 0.1 m is shorter than crank"),
])
def test_cli_bad_file_exits_2_with_one_line(run, tmp_path, content, match):
    path = tmp_path / "case.json"
    path.write_text(content, encoding="utf-8")
    rc, out, err = run(path, "--json")
    assert rc == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and err.startswith("graphmethods kinematics: error: ")
    assert match in err


def test_cli_too_few_positions(run, press_case_path):
    rc, _, err = run(press_case_path, "--positions", 2)
    assert rc == 2 and "at least 3" in err
