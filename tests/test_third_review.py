"""A teacher's third review of the kinematic and dynamic A1 sheets and the A4 figures (issue 26, lane review3):
one regression test per defect found."""

from __future__ import annotations

import re

import numpy as np
import pytest

from graphmethods import cli
from graphmethods.problems import builtin
from graphmethods.scene import Scale, markup
from graphmethods.scene.numbers import format_scale
from graphmethods.scene.primitives import Label, walk
from graphmethods.sheets.velocity_plans import PLAN_GRID_LAYOUT, _fitted_grid
from graphmethods.units import convenient_at_least

LANGS = ("en", "ru", "zh")


def _texts(scene) -> list[str]:
    return [markup.plain(p.text) for p in walk(e for el in scene.elements for e in el.primitives())
            if isinstance(p, Label)]


# ----------------------------------------------------------------------------- 1. one μ_v in every language

def test_six_bar_press_velocity_plans_one_scale_in_every_language():
    """The six-bar press's A1 kinematic sheet drew its velocity plans at μ_v = 0.01 in en and 0.02 in ru/zh: the
    taller ГОСТ / GB title blocks left the upper row 7 mm lower, the plan grid's equal-height rows then needed
    0.0103 (→ 0.02), and the sheet's division chooser trusted a stretched prediction. Now each row is as tall as
    its plans and the best division of each upper share is drawn: one μ_v, the larger plans, in every language."""
    from graphmethods.sheets.kinematic_analysis_sheet import kinematic_analysis_sheet

    mu_v = {}
    for lang in LANGS:
        sheet = kinematic_analysis_sheet(builtin.case("six-bar-press"), notation=lang)
        mu_v[lang] = sorted({s.per_mm for s in sheet.scales() if s.symbol == "μ_v" and s.per_mm in (0.01, 0.02)})
    assert mu_v["en"] == mu_v["ru"] == mu_v["zh"] == [0.01], mu_v


def test_plan_grid_rows_are_as_tall_as_their_plans():
    """Rows of the fitted plan grid take their height from their tallest plan (the slack shared), so a row of
    flat plans does not cost the tall ones their scale; the rows fill the area exactly."""
    spans = np.array([[0.3, 0.2]] * 4 + [[0.3, 0.9]] * 4)
    area = (0.0, 0.0, 400.0, 160.0)
    grid = _fitted_grid(area, spans, np.ones(8, dtype=bool), PLAN_GRID_LAYOUT, np.zeros(8))
    assert grid is not None and grid.rows
    heights = [h for _, h in grid.rows]
    assert sum(heights) == pytest.approx(160.0)
    assert grid.columns == 4 and heights[1] > heights[0]      # the tall plans' row is the taller
    equal_rows_need = 0.9 / (160.0 / 2 - PLAN_GRID_LAYOUT.head_mm - 2 * PLAN_GRID_LAYOUT.pad_y_mm)
    assert convenient_at_least(grid.need) == 0.01 < convenient_at_least(equal_rows_need)
    for idx in range(8):                        # every plan fits its cell at the scale drawn
        _, inner = grid.cell(idx, PLAN_GRID_LAYOUT)
        assert spans[idx, 1] / 0.01 <= inner[3] - inner[1] + 1e-6


# ----------------------------------------------------------------------------- 2. a scale as a draftsman writes it

@pytest.mark.parametrize(("value", "decimal", "text"), [(2e-5, ".", "0.00002"), (2.5e-5, ",", "0,000025"),
                                                        (0.001, ".", "0.001"), (2.5, ",", "2,5"),
                                                        (1000.0, ".", "1000"), (4e-6, ".", "0.000004")])
def test_a_scale_is_a_plain_decimal(value, decimal, text):
    assert format_scale(value, decimal=decimal) == text
    assert Scale("μ_J", "kg·m²", value).caption("ru" if decimal == "," else "en").split(" = ")[1].startswith(text)


@pytest.mark.parametrize("lang", LANGS)
def test_engine_dynamic_sheet_writes_mu_J_without_a_power_of_ten(lang):
    """The engine's μ_J = 2·10⁻⁵ kg·m²/mm was printed as a power of ten on the dynamic sheet (captions, the
    result table, the title block): a scale reads 0.00002 kg·m²/mm, as the text output prints it."""
    from graphmethods.sheets.dynamic_analysis_sheet import dynamic_analysis_sheet

    sheet = dynamic_analysis_sheet(builtin.case("engine"), notation=lang)
    scale_texts = [t for t in _texts(sheet) if "μ" in t]
    assert scale_texts
    assert not [t for t in scale_texts if re.search(r"·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]", t)], scale_texts
    sep = "," if lang == "ru" else "."
    assert any(f"0{sep}00002" in t for t in scale_texts)


def test_study_text_writes_the_sheet_scales_as_the_sheet(capsys):
    cli.main(["study", "engine"])
    sheet_line = next(line for line in capsys.readouterr().out.splitlines() if line.startswith("sheet"))
    assert "0.00002" in sheet_line and "10⁻" not in sheet_line.split("J_0")[0]


# ----------------------------------------------------------------------------- 3. the kinematic sheet is A1 only

def test_kinematic_sheet_on_A2_is_one_clear_line_and_exit_2(capsys, tmp_path):
    target = tmp_path / "k.svg"
    with pytest.raises(SystemExit) as exc:
        cli.main(["kinematics", "press", "--sheet", str(target), "--page", "A2"])
    assert exc.value.code == 2
    out, err = capsys.readouterr()
    lines = [x for x in err.splitlines() if x.strip()]
    assert len(lines) == 1 and "A1 only" in lines[0] and "Traceback" not in err
    assert not target.exists() and out == ""


# ----------------------------------------------------------------------------- 4. the dynamic sheet: one set of scales

@pytest.mark.parametrize("problem", ["shaper", "engine", "press"])
def test_dynamic_sheet_scales_are_one_in_every_language_and_the_json(problem):
    """The shaper's dynamic sheet drew μ_M = 4, μ_φ = 1.5°/mm in en and 5, 2°/mm in ru and zh (their title
    blocks are 13 mm taller); the engine's μ_J was 1·10⁻⁵ in en, 2·10⁻⁵ in ru (a wider result table). Each scale
    is now the largest the three languages pick, and study --json's sheet numbers are the sheet's."""
    from graphmethods.dynamics.study import Study
    from graphmethods.sheets.dynamic_analysis_sheet import dynamic_analysis_sheet, sheet_construction

    study = Study(builtin.case(problem), positions=12)
    scales = {lang: tuple(s.per_mm for s in dynamic_analysis_sheet(study, notation=lang).scales()[:4])
              for lang in LANGS}
    assert scales["en"] == scales["ru"] == scales["zh"], scales
    c = sheet_construction(study)
    assert (c["mu_T"], c["mu_J"]) == scales["en"][2:]


# ----------------------------------------------------------------------------- 5. the drive scheme's labels

@pytest.mark.parametrize("lang", LANGS)
def test_drive_scheme_labels_carry_units_and_no_stray_index(lang):
    """The drive scheme wrote c₁ = 2000 without its unit beside c'₁ = 72000 N·m/rad, J₁ = 0.08 without
    kg·m², and an unnamed disc's number ("1") under J₁ = …, which already says 1."""
    from graphmethods.dynamics.multimass import Mass, Shaft, reduce_chain
    from graphmethods.scene import notation
    from graphmethods.sheets.drive_scheme import drive_scheme

    nt = notation(lang)
    chain = reduce_chain([Mass("1", 0.08, 6.0), Mass("2", 0.5, 2.0), Mass("3", 12.0, 1.0)],
                         [Shaft("1", 2000.0, 6.0), Shaft("2", 40000.0, 1.0)])
    scene = drive_scheme(chain, notation=lang)
    labels = {e.name: markup.plain(e.text) for e in scene.elements if hasattr(e, "text")}
    for name, text in labels.items():
        if "-label-c-" in name:
            assert nt.unit("N·m/rad") in text, text
        if "-label-J-" in name:
            assert nt.unit("kg·m²") in text, text
    assert not [n for n in labels if n.startswith("label-name-")]
