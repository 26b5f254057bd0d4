"""The dynamics build-ups on a 16:9 slide meet the slide's standard (issue 26, lane slides): one test per cause.

- Lettering. The figure functions letter for paper (tick values 2.6 mm, labels 2.8 mm); the projector drew them
  1.0…1.2 : 1 where the layout allowed no more, so the slides' text was 2.6…3.4 mm. ``for_projector(lettered=True)``
  designs every candidate page with the slide's minimum (3.5 mm after the enlargement) as the figures' lettering.
- The energy indicator's vectors were held to 66 mm apart: a cycle of three intervals filled a third of the slide.
- The work diagrams' right column held a five-column accuracy table 165 mm wide: the three diagrams got 36…72 mm
  of a 323 mm slide; the fan of rays cleared the M values off their ticks; the dimension of H went over the title
  when the fan was narrower above the axis.
- The note "drawn z : 1" is added after the figure's labels were placed: a Wittenbauer ray ran through it.
"""

import json
import re

import pytest

from graphmethods.dynamics.study import Study
from graphmethods.problems import builtin
from graphmethods.render.recording import record
from graphmethods.sheets import dynamic_analysis_sheet, steps
from graphmethods.sheets.engine.quality import faults, measure
from graphmethods.sheets.projector import SLIDE_PAGE, for_projector

FOUR = ("shaper", "six-bar-press", "engine", "two-slider")


def _texts(scene) -> list:
    return [c.data for c in record(scene).calls if c.kind == "text"]


def test_a_figure_lettered_for_paper_is_lettered_for_the_slide():
    """W3's work diagrams write their tick values at 2.6 mm: drawn as they are, enlarged as far as the layout
    holds, the slide's text stays below 3.5 mm; lettered for the slide, every text is 3.5 mm or more."""
    from graphmethods.sheets.construction_steps import integration_steps

    case = steps.resolve_case("W3")

    def make(page):
        return integration_steps(case, notation="en", page=page)

    as_paper = for_projector(make)
    lettered = for_projector(make, lettered=True)
    assert min(t.size_mm for t in _texts(as_paper.slide(len(as_paper)))) < 3.5
    sizes = [t.size_mm for k in range(1, len(lettered) + 1) for t in _texts(lettered.slide(k))]
    assert min(sizes) >= 3.5 - 1e-9
    assert lettered.figure.page.size == "SLIDE"


@pytest.mark.parametrize("case, figure", [("press", "work-diagrams"), ("engine", "wittenbauer"),
                                          ("shaper", "wittenbauer"), ("engine", "energy-indicator"),
                                          ("slotting-machine", "energy-indicator")])
def test_every_text_of_every_step_is_35_mm_or_more(case, figure):
    bu = steps.build(case, figure, notation="en")
    for k in range(1, len(bu) + 1):
        sizes = [t.size_mm for t in _texts(bu.slide(k)) if any(s == 0 and r.strip() for r, s in t.runs)]
        assert min(sizes) >= 3.5 - 1e-9, (k, min(sizes))


def test_the_energy_indicator_spreads_over_the_slide():
    """The press's three vectors were 66 mm apart (56 % of the slide's cells empty): now they span the slide."""
    bu = steps.build("press", "energy-indicator", notation="en")
    rec = record(bu.figure)
    xs = [c.data[0][0][0] for c in rec.calls if c.kind == "path" and any(g.startswith("vector-") for g in c.groups)]
    x0, _, x1, _ = SLIDE_PAGE.inner_box()
    assert max(xs) - min(xs) > 0.5 * (x1 - x0)
    assert measure(bu.slide(len(bu))).empty_share <= 0.45


@pytest.mark.parametrize("case", ["press", "engine"])
def test_the_work_diagrams_get_the_slides_width(case):
    """On a slide the accuracy table has a column per construction (A_d, A_r, ΔE) and the diagrams span at least
    90 mm of the slide (36 mm for the press before); every M tick is written and no ray crosses a value; the
    dimension of H stays below the title."""
    bu = steps.build(case, "work-diagrams", notation="en")
    fig = bu.figure
    table = fig.element("accuracy-table").element            # the slide's elements are drawn enlarged
    assert len(table.rows[0]) == 4 and len(table.rows) == 5
    axis = fig.element("axis-phi-M").element
    assert bu.enlarged * axis.scale.to_mm(axis.max_value - axis.min_value) >= 90.0
    ax_M = fig.element("axis-M").element
    assert all(lab for t, lab in zip(ax_M.ticks, ax_M.tick_labels) if t != 0)
    q = measure(bu.slide(len(bu)))
    assert faults(q) == []
    calls = record(fig).calls
    title = max(c.data.y for c in calls if c.kind == "text" and "title" in c.groups)     # its baseline
    H = next(c.data for c in calls if c.kind == "text" and c.data.text.startswith("H = "))
    assert H.y - H.size_mm > title


def test_the_work_diagrams_on_paper_keep_one_row_per_construction():
    from graphmethods import problems
    from graphmethods.sheets.work_diagrams import work_diagrams

    table = work_diagrams(problems.w3(), notation="en").element("accuracy-table")
    assert len(table.rows[0]) == 5 and len(table.rows) == 4


def test_the_enlargement_note_is_not_crossed():
    """The scotch yoke's ray at ψ_max ran through "drawn 1.3 : 1 for the projector; …" at the slide's top right."""
    bu = steps.build("scotch-yoke", "wittenbauer", notation="en")
    q = measure(bu.slide(len(bu)))
    assert q.crossed == ()
    if bu.enlarged != 1.0:
        assert any(t.text.endswith(": 1") or ": 1 " in t.text for t in _texts(bu.slide(1)))


@pytest.mark.parametrize("case", FOUR)
def test_the_slides_print_the_a1_sheets_and_the_studys_numbers(case, capsys):
    """One truth: the Wittenbauer slides' tan ψ_max, tan ψ_min and kl are the A1 dynamic sheet's, their J_F and the
    energy indicator's ΔW_max are ``study P --json``'s."""
    from graphmethods.cli import main

    assert main(["study", case, "--json"]) == 0
    js = json.loads(capsys.readouterr().out)
    sheet = " ".join(t.text for t in _texts(dynamic_analysis_sheet(Study(builtin.case(case), positions=12),
                                                                   notation="en")))
    caps = " ".join(steps.build(case, "wittenbauer", notation="en").captions())
    for key in ("max", "min"):
        on_sheet = re.search(rf"tan ψ{key} = ([\d.]+)", sheet)
        assert on_sheet is not None and f"tan ψ_{{{key}}} = {on_sheet.group(1)}" in caps
    kl = re.search(r"kl = ([\d.]+) mm", sheet)
    assert kl is not None and f"kl = {kl.group(1)} mm" in caps
    assert f"= {float(js['J_F_wittenbauer']):.4g} kg·m²" in caps
    energy = " ".join(steps.build(case, "energy-indicator", notation="en").captions())
    assert f"= {float(js['delta_W_max']):.4g} J" in energy


@pytest.mark.parametrize("case, lang", [("two-slider", "zh"), ("press", "en")])
def test_a_curves_name_is_not_set_among_the_position_numbers(case, lang):
    """The two-slider's M_r was named between the φ axis's 6 and 7 ("6 M_r 7"): the row of the position numbers
    is kept for them."""
    from graphmethods.scene.elements import label_bbox
    from graphmethods.sheets.wittenbauer import tick_label_band

    fig = steps.build(case, "work-diagrams", notation=lang).figure
    for strip in ("M", "A"):
        x0, y0, x1, y1 = tick_label_band(fig.element(f"axis-phi-{strip}").element)
        names = [e for e in fig.elements if e.name.startswith(f"name-{strip}-")]
        assert names
        for e in names:
            for lab in e.element.primitives():
                b = label_bbox(lab)
                assert not (b[0] < x1 and x0 < b[2] and b[1] < y1 and y0 < b[3]), (strip, lab.text)


@pytest.mark.parametrize("case", ["two-slider", "press", "scotch-yoke"])
def test_the_wittenbauer_slides_write_every_value(case):
    """The two-slider's J_e axis wrote one value of five (0.166: the curve covered the others): on a slide the
    ticks are spaced wider until every one besides the origin has its value. At 1.5 : 1 the press's J_e value 0.6
    lay under the curve above the axis (free below it: the values go on the other side) and the two-slider's ΔT
    tick −150 under the ray at ψ_min where it meets the axis (the end tick left out: the ticks −100, −50, 0); the
    scotch yoke's J_e value 0.25 lay under the ray at ψ_max above the axis and under the curve below it (written
    over the ray, the ray broken behind it)."""
    fig = steps.build(case, "wittenbauer", notation="en").figure
    for name in ("axis-J", "axis-T"):
        ax = fig.element(name).element
        labels = ax.tick_labels or ()
        off = [lab for t, lab in zip(ax.ticks, labels) if t != 0 and abs(t - ax.min_value) > 1e-12]
        assert len(off) >= 2 and all(off), (name, ax.ticks, labels)


def test_a_wittenbauer_slides_rays_stop_below_its_title():
    bu = steps.build("whitworth", "wittenbauer", notation="ru")
    assert measure(bu.slide(len(bu))).crossed == ()
