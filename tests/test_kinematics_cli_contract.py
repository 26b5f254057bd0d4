"""``graphmethods kinematics`` prints the kinematics contract: points (xy, v, a), links (ω, ε),
``--phi-deg``, ``--epsilon-1``, ``--n``, for the classic kinds and for any linkage file."""

import json
import math
import pathlib

import numpy as np
import pytest

from graphmethods import cli

DATA = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data"


@pytest.fixture
def run(capsys):
    def _run(*argv):
        try:  # argparse refuses a bad option with one line and SystemExit(2), as the real command does
            rc = cli.main(["kinematics", *map(str, argv)])
        except SystemExit as exc:
            rc = exc.code
        out, err = capsys.readouterr()
        return rc, out, err
    return _run


def press_closed_form(phi, r, l, e, omega, eps):
    """Offset slider-crank written out by hand: x_B, v_B, a_B and ω₂, ε₂ (counterclockwise crank)."""
    s, c = np.sin(phi), np.cos(phi)
    q = e - r * s
    w = np.sqrt(l * l - q * q)
    x1 = -r * s + q * r * c / w
    x2 = -r * c + r * ((-r * c * c - q * s) / w - q * q * r * c * c / w**3)
    th1 = -r * c / w                                   # dθ₂/dφ, θ₂ = atan2(q, w)
    th2 = (r * s * w + r * c * (q * r * c / w)) / w**2
    return (r * c + w, x1 * omega, x2 * omega**2 + x1 * eps, th1 * omega, th2 * omega**2 + th1 * eps)


def test_press_contract_with_phi_deg_epsilon_and_n(run, press_case_path):
    rc, out, err = run(press_case_path, "--phi-deg", "0,37.5,200", "--epsilon-1", "12.5", "--n", "150", "--json")
    assert rc == 0 and err == ""
    res = json.loads(out)
    case = json.loads(pathlib.Path(press_case_path).read_text())
    omega = math.pi * 150 / 30
    assert res["omega_1"] == pytest.approx(omega, rel=1e-15)
    rows = res["positions"]
    phi = np.radians([0.0, 37.5, 200.0])
    x, v, a, w2, e2 = press_closed_form(phi, case["r"], case["l"], case["e"], omega, 12.5)
    for i, row in enumerate(rows):
        assert row["phi_deg"] == [0.0, 37.5, 200.0][i]
        B = row["points"]["B"]
        assert B["xy"] == pytest.approx([x[i], case["e"]], abs=1e-14)
        assert B["v"][0] == pytest.approx(v[i], abs=1e-12 * omega) and B["v"][1] == 0.0
        assert B["a"][0] == pytest.approx(a[i], abs=1e-12 * omega**2) and B["a"][1] == 0.0
        assert row["links"]["2"]["omega"] == pytest.approx(w2[i], abs=1e-12 * omega)
        assert row["links"]["2"]["epsilon"] == pytest.approx(e2[i], abs=1e-12 * omega**2)
        assert row["links"]["1"] == {"omega": pytest.approx(omega), "epsilon": 12.5}
        assert row["v_B"] == pytest.approx(v[i], abs=1e-12 * omega)          # the flat keys stay
        assert set(row["points"]) == {"A", "B", "S2"}
        assert row["position"] is None


def test_every_kind_prints_points_and_links(run):
    for f in sorted(DATA.glob("*.json")):
        if json.loads(f.read_text(encoding="utf-8")).get("kind") == "cam":
            continue  # a cam problem is not a linkage (graphmethods cam reads it)
        rc, out, err = run(f, "--positions", "6", "--json")
        assert rc == 0, (f, err)
        res = json.loads(out)
        row = res["positions"][2]
        assert row["points"] and all(set(p) == {"xy", "v", "a"} for p in row["points"].values())
        assert {str(k) for k in res["links"]} <= set(row["links"])
        # flat speeds agree with the points' vectors
        for key, val in row.items():
            if key.startswith("v_") and key[2:] in row["points"] and key != "v_BA":
                vec = row["points"][key[2:]]["v"]
                assert abs(abs(val) - math.hypot(*vec)) <= 1e-12 * (1 + abs(val)), (f.name, key)


def test_bad_contract_options_are_one_line_errors(run, press_case_path):
    for argv, match in ((("--phi-deg", "ten"), "--phi-deg"), (("--n", "-5"), "--n"),
                        (("--epsilon-1", "nan"), "--epsilon-1")):
        rc, out, err = run(press_case_path, *argv)
        assert rc == 2 and out == "" and match in err and err.count("\n") == 1


def test_structure_is_printed(run):
    rc, out, _ = run(DATA / "whitworth_quick_return.json", "--positions", "4", "--json")
    res = json.loads(out)
    assert res["structure"] == "I(0,1) → II(2,3) → II(4,5)" and res["dof"] == 1
    assert [g["type"] for g in res["groups"]] == ["crank", "RPR", "RRP"]
