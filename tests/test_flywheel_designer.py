"""The flywheel as a designer sees it (issue 18, items 6-7): the table of recommended [δ], --machine,
the J_F–[δ] hyperbola, Q·D², formula (90), χ ≈ 2δ/Δφ and tan μ."""

import json
import math
import pathlib
import re

import numpy as np
import pytest

from graphmethods.cli import main
from graphmethods.dynamics import permissible_delta as pd
from graphmethods.dynamics.flywheel import flywheel
from graphmethods.dynamics.flywheel_formulas import chi_artobolevsky, flywheel_from_work, hyperbola, tan_mu
from graphmethods.errors import InputError

DOMAIN = pathlib.Path("/work/shared/domain.md")
W1 = ["--areas", "-50", "550", "-100", "125", "-500", "25", "-50", "--n", "600"]


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def _domain_rows():
    """The [δ] paragraph of domain.md §4, parsed independently of the module: name -> (lenient, strict)."""
    text = DOMAIN.read_text(encoding="utf-8")
    para = text.split("Typical permissible [δ]:", 1)[1].split("\n\n", 1)[0]
    rows = {}
    for part in " ".join(para.split()).rstrip(".").split(";"):
        m = re.fullmatch(r"\s*(.+?) 1/(\d+)–1/(\d+)\s*", part)
        assert m, part
        rows[m.group(1)] = (int(m.group(2)), int(m.group(3)))
    return rows


@pytest.mark.skipif(not DOMAIN.exists(), reason="the shared domain.md is not on this machine")
def test_table_is_domain_md_section_4():
    rows = _domain_rows()
    assert len(rows) == len(pd.TABLE)
    for row in pd.TABLE:
        assert row.names[0] in rows, row.names[0]
        assert (row.lenient_denominator, row.strict_denominator) == rows[row.names[0]]


def test_machine_lookup_in_three_languages_and_ends():
    assert pd.machine_row("shears").key == "press-shears"
    assert pd.machine_row("прокатный стан").key == "rolling-mill"
    assert pd.machine_row("纺纱机").key == "spinning-machine"
    assert pd.permissible_delta("stone-crusher") == pytest.approx(1 / 20)
    assert pd.permissible_delta("stone-crusher", "lenient") == pytest.approx(1 / 5)
    for row in pd.TABLE:
        assert row.strict < row.lenient          # the strict end is the smaller δ
    with pytest.raises(InputError, match="delta-table"):
        pd.machine_row("windmill")
    with pytest.raises(InputError):
        pd.permissible_delta("press", "middle")


def test_delta_table_cli(capsys):
    code, out, _ = run(capsys, "flywheel", "--delta-table", "--json")
    assert code == 0
    data = json.loads(out)
    assert "domain.md" in data["source"] and data["default_end"] == "strict"
    assert [m["key"] for m in data["machines"]] == [r.key for r in pd.TABLE]
    code, out, _ = run(capsys, "flywheel", "--delta-table", "--lang", "ru")
    assert code == 0 and "генераторы переменного тока" in out and "1/200 … 1/300" in out


@pytest.mark.parametrize("end,denominator", [("strict", 300), ("lenient", 200)])
def test_machine_gives_the_same_flywheel_as_its_delta(capsys, end, denominator):
    code, out, err = run(capsys, "flywheel", *W1, "--machine", "ac-generator", "--machine-end", end, "--json")
    assert code == 0, err
    res = json.loads(out)
    code, out2, _ = run(capsys, "flywheel", *W1, "--delta", f"1/{denominator}", "--json")
    ref = json.loads(out2)
    assert res["delta"] == pytest.approx(1 / denominator, rel=1e-12)
    assert res["J_F"] == pytest.approx(ref["J_F"], rel=1e-12)
    assert res["machine"]["end"] == end


@pytest.mark.parametrize("argv,needle", [
    (["--machine", "windmill"], "not in the table"),
    (["--delta", "0.1", "--machine-end", "lenient"], "--machine only"),
    (["--J", "50", "--hyperbola", "x.svg"], "--hyperbola"),
    (["--delta", "0.1", "--hyperbola", "x.gif"], ".svg, .pdf, .png or .dxf"),     # every renderer format (issue 28)
])
def test_bad_input_one_line_exit_2(capsys, tmp_path, monkeypatch, argv, needle):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, "flywheel", *W1, *argv)
    assert code == 2 and needle in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert not list(tmp_path.iterdir())


def test_missing_goal_and_speed_are_input_errors(capsys):
    code, _, err = run(capsys, "flywheel", "--areas", "50", "-50", "--n", "600")
    assert code == 2 and "--machine" in err
    code, _, err = run(capsys, "flywheel", "--areas", "50", "-50", "--delta", "0.1")
    assert code == 2 and "--n" in err


def test_hyperbola_formula_and_constant_J_e_form_of_formula_90():
    W, w, Je = 575.0, 600 * math.pi / 30, 1.5
    deltas = np.array([1 / 300, 1 / 50, 0.2])
    J = hyperbola(W, omega_m=w, J_e=Je, deltas=deltas)
    for d, j in zip(deltas, J):
        assert j == pytest.approx(flywheel(W, delta=float(d), omega_m=w, J_e=Je).J_F, rel=1e-12)
        # the lecture's formula (90) with J_j = J_k = J_e and A_jk = ΔW_max is the same J_F
        assert flywheel_from_work(W, J_j=Je, J_k=Je, omega_m=w, delta=float(d)) == pytest.approx(j, rel=1e-12)
    with pytest.raises(InputError):
        hyperbola(W, omega_m=w, J_e=Je, deltas=[0.0])


def test_hyperbola_figure_is_to_scale():
    from graphmethods.scene.elements import Point, Polyline
    from graphmethods.sheets.flywheel_hyperbola import flywheel_hyperbola

    W, w, Je = 579.3, 31.4159, 0.57
    s = flywheel_hyperbola(W, omega_m=w, J_e=Je, machine="press", notation="ru")
    ax_d, ax_J = s.element("axis-delta"), s.element("axis-J")
    ox, oy = ax_d.origin
    curve = s.element("hyperbola")
    assert isinstance(curve, Polyline)
    # the abscissa is 1/[δ] (the hyperbola J_F = W/(ω_m²·[δ]) − J_e drawn against it is a straight line)
    x = (np.array([p[0] for p in curve.points]) - ox) * ax_d.scale.per_mm
    y = (oy - np.array([p[1] for p in curve.points])) * ax_J.scale.per_mm
    assert x.min() == pytest.approx(5) and x.max() == pytest.approx(300)
    assert np.allclose(y, W * x / w**2 - Je, rtol=1e-9, atol=1e-9)
    chosen = s.element("chosen")
    assert isinstance(chosen, Point)
    inv_d = (chosen.at[0] - ox) * ax_d.scale.per_mm
    assert inv_d == pytest.approx(10)              # the press row's strict end, [δ] = 1/10
    assert (oy - chosen.at[1]) * ax_J.scale.per_mm == pytest.approx(W * inv_d / w**2 - Je)


def test_hyperbola_cli_writes_once(capsys, tmp_path):
    f = tmp_path / "h.svg"
    code, out, err = run(capsys, "flywheel", *W1, "--machine", "ac-generator", "--hyperbola", str(f))
    assert code == 0, err
    assert f.read_text(encoding="utf-8").lstrip().startswith("<") and "wrote" in out
    first = f.read_bytes()
    code, _, err = run(capsys, "flywheel", *W1, "--machine", "ac-generator", "--hyperbola", str(f))
    assert code == 2 and "--force" in err and f.read_bytes() == first
    code, _, err = run(capsys, "flywheel", *W1, "--machine", "ac-generator", "--hyperbola", str(f), "--force")
    assert code == 0 and f.read_bytes() == first              # deterministic
    g = tmp_path / "h.pdf"
    code, _, err = run(capsys, "flywheel", *W1, "--delta", "1/50", "--hyperbola", str(g))
    assert code == 0 and g.read_bytes().startswith(b"%PDF")


@pytest.mark.parametrize("design", [["--rim", "0.75"], ["--disc", "0.6"]])
def test_old_unit_flywheel_moment(capsys, design):
    code, out, err = run(capsys, "flywheel", *W1, "--delta", "1/300", *design, "--json")
    assert code == 0, err
    d = json.loads(out)["rim" if design[0] == "--rim" else "disc"]
    weight_N = d["m"] * 9.80665                      # the weight Q of m kg at standard gravity
    assert d["mD2"] == pytest.approx(d["m"] * d["D"] ** 2)
    assert d["QD2_kgf_m2"] == pytest.approx(weight_N / 9.80665 * d["D"] ** 2)
    assert d["GD2_N_m2"] == pytest.approx(weight_N * d["D"] ** 2)
    code, out, _ = run(capsys, "flywheel", *W1, "--delta", "1/300", *design)
    assert "QD² = " in out and "mD² = " in out and "GD² = " in out     # the text names them as the figure does


def test_chi_and_tan_mu_small():
    assert chi_artobolevsky(0.1, math.pi) == pytest.approx(0.2 / math.pi)
    assert list(tan_mu([3.0], [3.0])) == [pytest.approx(1 / 3)]
    with pytest.raises(InputError):
        tan_mu([1.0], [0.0])


@pytest.fixture(scope="module")
def press_study():
    from graphmethods.dynamics.study import Study
    from graphmethods.problems import builtin

    return Study(builtin.case("press"))


def test_formula_90_reproduces_the_exact_flywheel_on_the_press(press_study):
    ex = press_study.exact
    out = press_study.summary(exact=True)
    assert out["J_F_formula_90"] == pytest.approx(ex.J_F, rel=1e-9)
    # the inertias at the exact extreme positions, taken from the model independently
    J_j, J_k = (float(v) for v in press_study.model.J_e_at(np.array([ex.phi_omega_min, ex.phi_omega_max])))
    assert out["J_e_j"] == pytest.approx(J_j) and out["J_e_k"] == pytest.approx(J_k)
    # the kinetic-energy theorem between φ_j and φ_k of the exact motion: A_jk = T_k − T_j
    T_k = 0.5 * (ex.J_F + J_k) * ex.omega_max**2
    T_j = 0.5 * (ex.J_F + J_j) * ex.omega_min**2
    assert out["A_jk"] == pytest.approx(T_k - T_j, rel=1e-8)
    dphi = (out["phi_omega_max_deg"] - out["phi_omega_min_deg"]) % 360.0
    assert out["delta_phi_deg"] == pytest.approx(dphi, abs=1e-6)
    assert out["chi_artobolevsky"] == pytest.approx(2 * out["delta"] / math.radians(dphi))
    assert out["chi_exact"] == pytest.approx(ex.motion.chi)
    d = out["delta"]           # |ε|/ω² with ω within ω_m(1 ± δ/2)
    assert out["chi_exact"] / (1 + d / 2) ** 2 <= out["tan_mu_max"] * (1 + 1e-12)
    assert out["tan_mu_max"] <= out["chi_exact"] / (1 - d / 2) ** 2 * (1 + 1e-12)
    assert math.tan(math.radians(out["mu_max_deg"])) == pytest.approx(out["tan_mu_max"])
    md = press_study.to_markdown(exact=True)
    assert "| J_F_formula_90 |" in md and "| chi_artobolevsky |" in md


def test_an_existing_hyperbola_file_keeps_the_figure_unwritten_too(capsys, tmp_path, monkeypatch):
    """Two files asked for, the second exists: refused before either is written (no half a set)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "h.svg").write_text("mine")
    code, _, err = run(capsys, "flywheel", *W1, "--delta", "0.1", "--rim", "--figure", "f.svg", "--hyperbola", "h.svg")
    assert code == 2 and "h.svg exists" in err and len(err.strip().splitlines()) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["h.svg"] and (tmp_path / "h.svg").read_text() == "mine"
    code, _, err = run(capsys, "flywheel", *W1, "--delta", "0.1", "--rim", "--figure", "f.svg", "--hyperbola", "h.svg",
                       "--force")
    assert code == 0, err
    assert (tmp_path / "f.svg").read_bytes().startswith(b"<?xml") and (tmp_path / "h.svg").read_text() != "mine"
