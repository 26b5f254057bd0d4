"""``graphmethods forces``: the contract keys, agreement with the library and the kinematics
command, the text table in three languages, bad input as one line and exit 2."""

import json
import math

import numpy as np
import pytest

from graphmethods import cli
from graphmethods.dynamics.forces import case_forces
from graphmethods.problems import builtin


@pytest.fixture
def run(capsys):
    def _run(*argv):
        rc = cli.main(["forces", *map(str, argv)])
        out, err = capsys.readouterr()
        return rc, out, err
    return _run


@pytest.mark.parametrize("name", ["press", "shaper", "four-bar", "slotted-lever", "six-bar-press", "two-slider"])
def test_contract_keys_by_position(run, name):
    rc, out, err = run(name, "--position", 4, "--json", "--gravity")
    assert rc == 0 and err == ""
    res = json.loads(out)
    case = builtin.case(name)
    lk = case.linkage
    assert set(res["links"]) == set(lk.links)
    for d in res["links"].values():
        assert len(d["F_i"]) == 2 and isinstance(d["M_i"], float)
    assert "R_01" in res["reactions"] and all(k.startswith("R_") for k in res["reactions"])
    assert all(len(v) == 2 for v in res["reactions"].values())
    # every moving link appears in some pair; pairs = 3 per group + the crank's
    assert len(res["reactions"]) == 3 * len(lk.groups) + 1
    fa = case_forces(case, m=12, gravity=True)
    assert res["M_balance"] == pytest.approx(float(fa.M_balance[4]), rel=1e-12)
    assert res["M_balance_lever"] == pytest.approx(res["M_balance"], rel=1e-9)
    assert res["M_balance_power"] == pytest.approx(res["M_balance"], rel=1e-9)
    for key, v in res["reactions"].items():
        assert complex(*v) == pytest.approx(complex(fa.reactions[key].R[4]), rel=1e-12, abs=1e-9)
    assert res["gravity"] == 9.81 and res["position"] == 4


def test_phi_deg_n_and_epsilon_follow_the_kinematics_command(run, capsys):
    rc, out, _ = run("press", "--phi-deg", "37.5", "--n", "150", "--epsilon-1", "12.5", "--json")
    assert rc == 0
    res = json.loads(out)
    assert res["phi_deg"] == pytest.approx(37.5) and res["omega_1"] == pytest.approx(150 * math.pi / 30)
    rc = cli.main(["kinematics", "press", "--phi-deg", "37.5", "--n", "150", "--epsilon-1", "12.5", "--json"])
    kin = json.loads(capsys.readouterr().out)["positions"][0]
    a_B = np.array(kin["points"]["B"]["a"])
    case = builtin.case("press")
    m3 = next(it.m for it in case.inertias if it.point == "B")
    # the slider's inertia force is −m·a_B of the kinematics command
    assert res["links"]["3"]["F_i"] == pytest.approx(list(-m3 * a_B), rel=1e-12, abs=1e-9)
    # the crank's inertia moment is −J1·ε1
    J1 = next(it.J for it in case.inertias if it.point == "O")
    assert res["links"]["1"]["M_i"] == pytest.approx(-J1 * 12.5)


@pytest.mark.parametrize("lang, word", [("en", "Balancing moment"), ("ru", "Уравновешивающий"), ("zh", "平衡力矩")])
def test_text_table_in_three_languages(run, lang, word):
    rc, out, err = run("four-bar", "--position", 2, "--lang", lang)
    assert rc == 0 and err == "" and word in out and "R_12" in out


@pytest.mark.parametrize("argv, says", [
    (("press",), "one of the arguments --phi-deg --position is required"),
    (("press", "--position", 13), "--position 13"),
    (("press", "--position", -1), "--position -1"),
    (("press", "--phi-deg", "nan"), "--phi-deg"),
    (("press", "--phi-deg", "10", "--position", "2"), "not allowed with"),
    (("press", "--position", 1, "--n", "-5"), "--n"),
    (("press", "--position", 1, "--epsilon-1", "inf"), "--epsilon-1"),
    (("press", "--position", 1, "--positions", 2), "--positions"),
    (("nothing-here", "--position", 1), "no such problem file"),
    (("W1", "--position", 1), "cycle problem"),
])
def test_bad_input_is_one_line_and_exit_2(run, argv, says):
    # argparse refuses these itself (exit 2, one line): a missing or conflicting option, and a number the
    # shared number type refuses (issue 28: one policy on every numeric option)
    by_argparse = "required" in says or "not allowed" in says or argv[-1] in ("nan", "inf")
    with pytest.raises(SystemExit) if by_argparse else _nothing():
        rc, out, err = run(*argv)
        assert rc == 2 and out == ""
        assert len(err.strip().splitlines()) == 1 and says in err and "Traceback" not in err


class _nothing:
    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


def test_argparse_errors_are_one_line(capsys):
    with pytest.raises(SystemExit) as ex:
        cli.main(["forces", "press"])
    assert ex.value.code == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "--position" in err


def test_a_negative_angle_is_an_angle(run):
    rc, out, _ = run("press", "--phi-deg", "-30", "--json")
    assert rc == 0 and json.loads(out)["phi_deg"] == pytest.approx(330.0)
