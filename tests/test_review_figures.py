"""What the review of the A4 figures, worksheets, check overlays and the command line's tables found
(issue 26), held: each test names the figure a teacher would not have printed."""

from __future__ import annotations

import math

import pytest

from graphmethods.problems import builtin
from graphmethods.render.recording import record
from graphmethods.scene.markup import full_width_punctuation, text_width_mm
from graphmethods.sheets.engine.quality import measure
from graphmethods.sheets.structure_diagram import structure_diagram


def _label(rec, name: str):
    return next(c.data for c in rec.calls if c.kind == "text" and any(g == name for g in c.groups))


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_the_structure_diagram_draws_its_names_where_it_placed_them(lang: str) -> None:
    """The two-slider's C was placed west of its block (anchored at its end) but drawn from its start,
    on the block's edge."""
    scene = structure_diagram(builtin.case("two-slider"), notation=lang)
    assert measure(scene).crossed == ()
    rec = record(scene)
    assert _label(rec, "name-C").anchor in ("start", "middle", "end")
    names = [c.data.runs for c in rec.calls if c.kind == "text" and any(g.startswith("name-") for g in c.groups)]
    assert (("O", 0), ("1", -1)) in names or all(not any(ch.isdigit() for ch, s in r if s == 0) for r in names)


def test_a_group_of_one_block_does_not_set_the_structure_diagrams_scale() -> None:
    """The Scotch yoke's RPP group has one joint (no size): its panel's scale (1 m/mm) made the crank a dot."""
    scene = structure_diagram(builtin.case("scotch-yoke"), notation="en")
    rec = record(scene)
    o, a = (_joint(rec, n) for n in ("pivot-O", "pin-A"))
    assert math.dist(o, a) > 40.0
    assert scene.scales()[0].per_mm < 0.01


def _joint(rec, name: str) -> tuple[float, float]:
    c = next(c for c in rec.calls if c.kind == "circle" and any(g == name for g in c.groups))
    return c.data[0], c.data[1]


def test_the_forces_table_speaks_the_language_of_its_lang_and_prints_no_round_off() -> None:
    from graphmethods.cli.forces import _text, result

    res = result(builtin.case("shaper"), position=3)
    ru = _text(res, "ru")
    assert "F_иx [Н]" in ru and "M_и [Н·м]" in ru and "рад/с" in ru and "против часовой стрелки" in ru
    assert "N·m" not in ru and "e-1" not in ru                  # no 1.35e-14 % between two exact methods
    zh = _text(res, "zh")
    assert "F_Ix [N]" in zh and "，曲柄转角" in zh and "逆时针" in zh


def test_chinese_figures_take_full_width_punctuation_whatever_joined_the_words() -> None:
    assert full_width_punctuation("ω_{3} = 1.2 rad/s, 逆时针") == "ω_{3} = 1.2 rad/s，逆时针"
    assert full_width_punctuation("II级杆组, 2阶 (RRP)") == "II级杆组，2阶 (RRP)"
    assert full_width_punctuation("φ = 30°, ω = 2: a") == "φ = 30°, ω = 2: a"           # no Chinese next to it
    from graphmethods.sheets.structure_diagram import structure_diagram as sd

    texts = record(sd(builtin.case("shaper"), notation="zh")).texts()
    assert any("结构式：" in t for t in texts) and not any("结构式:" in t for t in texts)


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_the_triads_acceleration_plan_keeps_its_equations_on_the_page(lang: str) -> None:
    """Four normal components on one line ran 60 mm past the A4 frame; the lines are split and the page
    turns upright when the plan would have no room left."""
    from graphmethods import sheets
    from graphmethods.dynamics.study import Study

    scene = sheets.acceleration_plan(Study(builtin.case("triad-six-bar"), positions=12), notation=lang)
    width = scene.page.width_mm
    for c in record(scene).calls:
        if c.kind == "text" and c.data.anchor == "start":
            assert c.data.x + text_width_mm(_markup(c.data), c.data.size_mm) <= width, c.data.text
    texts = " ".join(record(scene).texts())
    assert "Assur" not in texts or lang == "en"


def _markup(label) -> str:
    return "".join(t if s == 0 else ("_{" if s < 0 else "^{") + t + "}" for t, s in label.runs)
