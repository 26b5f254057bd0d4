"""`graphmethods flywheel` and `graphmethods examples` through the command line."""

import json
import math
import subprocess
import sys

import pytest

from graphmethods.cli import main


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.mark.parametrize("wid", ["W1", "W2"])
def test_worked_examples_through_the_cli(capsys, worked_examples, wid):
    case = worked_examples[wid]
    areas = [str(a) for a in case["areas_J"]]
    code, out, err = run(capsys, "flywheel", "--areas", *areas, "--n", str(case["n_rpm"]),
                         "--delta", str(case["delta"]), "--J-e", str(case["J_e"]), "--json")
    assert code == 0, err
    res = json.loads(out)
    exp, tol = case["expect"], case["tol"]
    assert res["delta_W_max"] == pytest.approx(exp["delta_W_max"], rel=tol)
    assert res["J_F"] == pytest.approx(exp["J_F"], rel=tol)
    assert res["E"] == pytest.approx(exp["E"], abs=1e-9)
    assert (res["index_E_max"], res["index_E_min"]) == (exp["index_E_max"], exp["index_E_min"])


def test_areas_with_scales_and_levels(capsys, worked_examples):
    case = worked_examples["W1"]
    mu_M, mu_phi_deg = 5.0, 2.0           # 1 mm² = 5·(2π/180) J
    areas = ",".join(str(a / (mu_M * math.radians(mu_phi_deg))) for a in case["areas_J"])
    code, out, _ = run(capsys, "flywheel", "--areas", areas, "--mu-M", "5", "--mu-phi-deg", "2",
                       "--omega", str(math.pi * 600 / 30), "--delta", "1/300", "--json")
    assert code == 0 and json.loads(out)["J_F"] == pytest.approx(case["expect"]["J_F"], rel=1e-9)
    levels = [str(e) for e in case["expect"]["E"]]
    code, out, _ = run(capsys, "flywheel", "--levels", *levels, "--n", "600", "--J",
                       str(case["expect"]["J_F"]), "--json")
    assert code == 0 and json.loads(out)["delta"] == pytest.approx(1 / 300, rel=1e-9)


def test_w3_and_w4_through_the_cli(capsys, worked_examples):
    w3 = worked_examples["W3"]
    code, out, _ = run(capsys, "flywheel", "--areas", *map(str, w3["expect"]["areas_J"]), "--n", "100",
                       "--delta", "0.05", "--json")
    assert json.loads(out)["J_F"] == pytest.approx(w3["expect"]["J_F"], rel=w3["tol"])
    w4 = worked_examples["W4"]["drawing"]
    code, out, _ = run(capsys, "flywheel", "--areas", *map(str, w4["areas_mm2"]), "--mu-M", "1",
                       "--mu-phi", str(w4["mu_phi"]), "--omega", "10", "--J", "0.8", "--json")
    res = json.loads(out)
    assert code == 0 and res["delta_W_max"] == pytest.approx(30.0)       # T from 25 to 55


def test_text_output_shows_the_table(capsys):
    code, out, _ = run(capsys, "flywheel", "--areas", "-50,550,-100,125,-500,25,-50", "--n", "120", "--delta", "0.06")
    assert code == 0
    assert "a–b" in out and "ΔW_max = 575 J" in out and "J_F = 60.69 kg·m²" in out


@pytest.mark.parametrize("argv, msg", [
    (["--areas", "50,-5x0", "--n", "600", "--delta", "0.1"], "not a number"),
    (["--areas", "50,-50", "--n", "600", "--delta", "0"], "between 0 and 1"),
    (["--areas", "50,-50", "--n", "600", "--delta", "2.5"], "between 0 and 1"),
    (["--areas", "50,-50", "--n", "-600", "--delta", "0.1"], "positive"),
    (["--areas", "50,-50", "--n", "0", "--delta", "0.1"], "positive"),
    (["--areas", "50,-550", "--n", "600", "--delta", "0.1"], "does not close"),
    (["--areas", "50,nan,-50", "--n", "600", "--delta", "0.1"], "not finite"),
    (["--areas", "50,-50", "--n", "600", "--delta", "1/0"], "not a number"),
    (["--areas", "50,-50", "--mu-phi", "0.1", "--n", "600", "--delta", "0.1"], "--mu-M"),
])
def test_bad_input_is_one_line_and_nonzero(capsys, argv, msg):
    code, out, err = run(capsys, "flywheel", *argv)
    assert code == 2 and out == ""
    assert msg in err and err.count("\n") == 1 and "Traceback" not in err


def test_real_process_bad_input_no_traceback():
    proc = subprocess.run([sys.executable, "-m", "graphmethods", "flywheel", "--areas", "1", "-1", "--n", "60",
                           "--delta", "-1"], capture_output=True, text=True)
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr
    proc = subprocess.run([sys.executable, "-m", "graphmethods", "flywheel", "--n", "60"], capture_output=True,
                          text=True)
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1


def test_examples_command(capsys, worked_examples):
    code, out, _ = run(capsys, "examples", "--json")
    res = json.loads(out)
    assert code == 0 and set(res) == {"W1", "W2", "W3", "W4-drawing", "W4-exact"}
    for wid in ("W1", "W2", "W3"):
        assert res[wid]["flywheel"]["J_F"] == pytest.approx(worked_examples[wid]["expect"]["J_F"], rel=1e-6)
    assert res["W4-drawing"]["kinetic_energy"]["T"] == pytest.approx([40, 55, 40, 25, 40])
    code, out, _ = run(capsys, "examples")
    assert "60.6872" in out and "60.16" in out and "570" in out    # the right value, and what the source did
    w4 = out[out.index("== W4-drawing"):]
    assert "A, kG·m" in w4 and "ΔW_max = 30 kG·m" in w4 and "J_e = 0.8 kG·m·s²" in w4   # the problem's own units
    assert " J" not in w4.replace(" J_e", "")
    assert res["W4-drawing"]["work_unit"] == "kG·m" and res["W1"]["work_unit"] == "J"
