"""One truth: a number a sheet prints is the number the command line prints for the same problem,
positions and method.

The dynamic A1 sheet (``study P --sheet``) and the Wittenbauer steps (slides, HTML stepper) print
M_d and the Wittenbauer J_F; ``study P --json`` prints ``M_d`` and ``J_F_wittenbauer``. Both come
from one :class:`~graphmethods.dynamics.study.Study`: M_r drawn through its ordinates at the
positions and at the load's switching positions, with the jumps (the course's construction), so
the drawn M_d is the work balance's.
"""

from __future__ import annotations

import re

import pytest

from graphmethods.dynamics.study import Study
from graphmethods.problems import builtin
from graphmethods.render.recording import record
from graphmethods.scene.notation import get as notation
from graphmethods.sheets import steps
from graphmethods.sheets.dynamic_analysis_sheet import dynamic_analysis_sheet

LINKAGES = sorted(builtin.LINKAGES)


def _texts(scene) -> list[str]:
    return [c.data.text for c in record(scene).calls if c.kind == "text"]


def _printed(value: float, lang: str) -> str:
    return notation(lang).number(value)


def _json(name: str) -> dict:
    return Study(builtin.case(name), positions=12).summary(exact=False)


def dynamic_sheet_truth_faults(name: str, scene) -> list[str]:
    """What a dynamic-analysis sheet of problem ``name`` prints otherwise than ``study NAME --json``:
    M_d and the Wittenbauer J_F, each as the sheet's notation writes the JSON's number (the hook of
    ``tests/test_figure_quality.py``)."""
    js = _json(name)
    nt = notation(scene.notation)
    texts = _texts(scene)
    faults = []
    M_d = nt.number(abs(js["M_d"]))                 # an engine prints the resisting constant, |M_d|
    if not any(re.search(rf"= {re.escape(M_d)} {re.escape(nt.unit('N·m'))}$", t) for t in texts):
        faults.append(f"M_d: the sheet does not print study --json's {M_d} {nt.unit('N·m')}")
    J_F = nt.number(js["J_F_wittenbauer"])
    if not any(t.startswith("=") and re.search(rf"= {re.escape(J_F)} ", t) for t in texts):
        faults.append(f"J_F: the sheet does not print study --json's J_F_wittenbauer {J_F}")
    return faults


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
@pytest.mark.parametrize("name", LINKAGES)
def test_the_dynamic_sheet_prints_the_studys_M_d_and_J_F(name: str, lang: str) -> None:
    study = Study(builtin.case(name), positions=12)
    assert dynamic_sheet_truth_faults(name, dynamic_analysis_sheet(study, page="A1", notation=lang)) == []


@pytest.mark.parametrize("name", ["press", "six-bar-press", "engine"])
def test_the_wittenbauer_steps_print_the_studys_J_F(name: str) -> None:
    js = _json(name)
    bu = steps.build(name, "wittenbauer", notation="en")
    captions = " ".join(str(s.caption) for s in bu.steps) + " " + " ".join(_texts(bu.figure))
    assert f"= {_printed(js['J_F_wittenbauer'], 'en')} kg·m²" in captions


def test_the_drawn_M_r_keeps_the_loads_jumps_and_balances_to_the_work() -> None:
    study = Study(builtin.case("press"), positions=12)
    M_d, M_r = study.moments
    on, off = study.switch_angles
    left, right = M_r.limits([on, off])
    assert left[0] == 0.0 and right[0] > 100.0          # the load switches on: a jump up
    assert left[1] > 100.0 and right[1] == 0.0          # and off: a jump down
    assert M_d.mean() == pytest.approx(study.M_d, rel=1e-4)


@pytest.mark.parametrize("name", ["press", "engine", "two-slider", "shaper"])
def test_the_slides_and_the_json_print_the_a1_sheets_tan_psi_kl_and_J_F(name: str) -> None:
    """The A1 sheet, the Wittenbauer slides (and so the HTML stepper) and ``study --json``'s ``"sheet"`` give the
    same tan ψ_max, tan ψ_min, kl and J_F: the slides draw at the sheet's scales (or both c times larger)."""
    from graphmethods.sheets.dynamic_analysis_sheet import sheet_construction

    study = Study(builtin.case(name), positions=12)
    c = sheet_construction(study)
    sheet = " ".join(_texts(dynamic_analysis_sheet(study, page="A1", notation="en")))
    bu = steps.build(name, "wittenbauer", notation="en")
    slides = " ".join(str(s.caption) for s in bu.steps)
    for key in ("tan_psi_max", "tan_psi_min"):
        printed = _printed(c[key], "en")
        assert f"= {printed}," in sheet and f"= {printed}," in slides, key
    kl = _printed(c["kl_mm"], "en")
    assert f"kl = {kl} mm" in sheet and (f"kl = {kl} mm" in slides or f"kl = {kl} mm there" in slides)
    assert f"= {_printed(c['J_F'], 'en')} kg·m²" in slides
    assert c["J_F"] == pytest.approx(_json(name)["J_F_wittenbauer"], rel=1e-9)


def test_study_json_carries_the_sheets_construction(capsys) -> None:
    import json

    from graphmethods.cli import main
    from graphmethods.sheets.dynamic_analysis_sheet import sheet_construction

    assert main(["study", "press", "--json", "--no-exact"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["sheet"] == pytest.approx(sheet_construction(Study(builtin.case("press"), positions=12)))
