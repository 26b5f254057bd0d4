"""A teacher's second review of the A1 sheets, the A4 figures and the worksheets (issue 26, session 10): one
named test per defect found, each checking what is drawn (the scene's elements by name, their text and
place), not pixels.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from graphmethods.problems import builtin
from graphmethods.scene import Scale, Table, markup
from graphmethods.scene.elements import Axis, label_bbox
from graphmethods.scene.primitives import Label, walk
from graphmethods.scene.title_blocks import FormBlock
from graphmethods.sheets.acceleration import acceleration_plan
from graphmethods.sheets.calculus import kinematic_diagrams
from graphmethods.sheets.kinematics import kinematic_scheme
from graphmethods.sheets.layout import main_scale


def _texts(scene) -> list[str]:
    return [markup.plain(p.text) for p in walk(e for el in scene.elements for e in el.primitives())
            if isinstance(p, Label)]


def _element_texts(scene) -> list[str]:
    out = []
    for el in scene.elements:
        if el.name == "title-block":
            continue
        out += [markup.plain(p.text) for p in walk(el.primitives()) if isinstance(p, Label)]
    return out


@pytest.fixture(scope="module")
def shaper_diagrams():
    return {lang: kinematic_diagrams(builtin.case("shaper"), notation=lang, title_block=False)
            for lang in ("en", "ru", "zh")}


# ----------------------------------------------------------------------------- 1. the slider's diagrams

@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_slider_diagrams_state_each_scale_once(shaper_diagrams, lang):
    """μ_s, μ_φ, μ_t (and μ_v, μ_a) were written beside their graphs and again on the captions line."""
    scene = shaper_diagrams[lang]
    texts = _element_texts(scene)
    for s in scene.scales():
        symbol = markup.plain(s.symbol)
        stated = [t for t in texts if t.startswith(symbol + " = ")]
        assert len(stated) == 1, (lang, symbol, stated)


def test_slider_velocity_axis_labels_every_tick(shaper_diagrams):
    """v_C's axis left its +0.5 tick unlabelled (the pole's rays crossed it): the rays give way instead."""
    for lang, scene in shaper_diagrams.items():
        for name in ("axis-v", "axis-a", "axis-s"):
            ax = scene.element(name)
            assert all(ax.tick_labels), (lang, name, ax.tick_labels)
        rays = [e for e in scene.elements if e.name.startswith("ray-v-")]
        boxes = [label_bbox(p) for p in scene.element("axis-v").primitives() if isinstance(p, Label)]
        for r in rays:             # no ray through a value
            xs, ys = np.linspace(r.start[0], r.end[0], 60), np.linspace(r.start[1], r.end[1], 60)
            for b in boxes:
                assert not ((xs > b[0]) & (xs < b[2]) & (ys > b[1]) & (ys < b[3])).any(), (lang, r.name)


@pytest.mark.parametrize("problem", ["shaper", "press", "six-bar-press"])
def test_slider_diagrams_keep_every_position_number(problem):
    """a(φ) dropped the position numbers 0–2 (and v(φ) 1–6) where the projection lines ran under the axis."""
    scene = kinematic_diagrams(builtin.case(problem), title_block=False)
    names = {e.name: e for e in scene.elements}
    for band in ("s", "v", "a"):
        ax = names[f"axis-phi-{band}"]
        have = {lab for lab in ax.tick_labels if lab}
        have |= {e.text for n, e in names.items() if n.startswith(f"pos-{band}-")}
        assert {str(k) for k in range(13)} <= have, (problem, band, sorted(have, key=int))


# ----------------------------------------------------------------------------- 2. the main inscription

def _form(scene) -> dict:
    tb = scene.page.title_block
    assert tb is not None and tb.form in ("gost", "gb")
    return dict(tb.fields)


def test_gost_and_gb_blocks_state_the_sheets_main_scale():
    """The ГОСТ 2.104 block's Масштаб cell (and GB/T 10609.1's 比例) were empty."""
    from graphmethods.dynamics.study import Study
    from graphmethods.sheets.dynamic_analysis_sheet import dynamic_analysis_sheet
    from graphmethods.sheets.kinematic_analysis_sheet import kinematic_analysis_sheet

    case = builtin.case("shaper")
    for lang in ("ru", "zh"):
        sheet = kinematic_analysis_sheet(case, notation=lang)
        mu_l = next(s for s in sheet.scales() if markup.plain(s.symbol) == "μl")      # the scheme's
        ratio = mu_l.per_mm * 1000.0
        want = f"1:{ratio:g}".replace(".", "," if lang == "ru" else ".")
        assert _form(sheet)["scale"] == want
        block = sheet.page.title_block.table(841.0, 594.0)
        assert isinstance(block, FormBlock) and want in [p.text for p in walk([block.draw()])
                                                         if isinstance(p, Label)]
    dyn = dynamic_analysis_sheet(Study(case, positions=12), notation="ru")
    assert _form(dyn)["scale"] == "—"                # diagrams only, each at its own μ


def test_main_scale_writes_the_gost_series():
    assert [main_scale([Scale("μ_l", "m", v)], "en") for v in (0.001, 0.002, 0.004, 0.05, 0.00025)] == \
        ["1:1", "1:2", "1:4", "1:50", "4:1"]


# ----------------------------------------------------------------------------- 3. a slider's numbers

@pytest.mark.parametrize("problem", ["whitworth", "shaper", "slotting-machine", "press"])
def test_slider_numbers_and_name_stay_on_the_free_side_of_the_guide(problem):
    """Whitworth's ram: the numbers 2, 3, 0 (12) and the name C stood beyond the guide's hatching."""
    from graphmethods.sheets.kinematic_symbols import Guide

    scene = kinematic_scheme(builtin.case(problem))
    for guide in (e for e in scene.elements if isinstance(e, Guide)):
        joint = guide.name.removeprefix("guide-")
        gs, ge = np.asarray(guide.start, float), np.asarray(guide.end, float)
        u = (ge - gs) / np.hypot(*(ge - gs))
        left = np.array([u[1], -u[0]])                        # +1 side on paper (y down)
        hatched = guide.side * left
        ours = [e for e in scene.elements if e.name.startswith("number-out-") or e.name == f"name-{joint}"]
        if not any(e.name.startswith("number-out-") for e in ours):
            continue
        for e in ours:
            b = label_bbox(next(p for p in e.primitives() if isinstance(p, Label)))
            centre = np.array([(b[0] + b[2]) / 2, (b[1] + b[3]) / 2])
            # measured from the guide's line: never beyond the hatched surface
            assert float((centre - gs) @ hatched) < guide.offset_mm, (problem, e.name, e.text)


# ----------------------------------------------------------------------------- 4. one μ_a for one problem

def test_triad_acceleration_plan_one_scale_in_every_language():
    """The triad six-bar's A4 plan was at μ_a 0.2 in English, 0.1 in Russian and Chinese (the English table's
    headings were 3.6 mm wider): the headings go on two rows when that draws the plan larger."""
    case = builtin.case("triad-six-bar")
    scenes = {lang: acceleration_plan(case, notation=lang) for lang in ("en", "ru", "zh")}
    mus = {lang: s.scales()[0].per_mm for lang, s in scenes.items()}
    assert len(set(mus.values())) == 1 and mus["en"] == pytest.approx(0.1), mus
    table = scenes["en"].element("table")
    assert isinstance(table, Table) and table.header_rows == 2
    assert table.rows[0][2] == "Acceleration," and table.rows[1][2] == "m/s²"


# ----------------------------------------------------------------------------- 5. worksheets

def test_wittenbauer_key_keeps_every_J_e_value():
    """The key dropped the J_e value 0.6 where its ray and curve ran; a position number took its place."""
    from graphmethods.sheets import worksheets

    for lang in ("en", "ru", "zh"):
        sheet = worksheets.worksheet("wittenbauer", variants=2, seed=7, notation=lang)
        for page in sheet.scenes:
            ax = next(e for e in page.elements if isinstance(e, Axis) and e.name == "axis-J")
            shown = [lab for t, lab in zip(ax.ticks, ax.tick_labels) if t != 0]
            assert all(shown), (lang, page.name, ax.tick_labels)
            row = [label_bbox(p) for p in ax.primitives() if isinstance(p, Label)
                   and markup.plain(p.text) != markup.plain(ax.label)]
            lo, hi = min(b[0] for b in row), max(b[2] for b in row)
            top, bottom = min(b[1] for b in row), max(b[3] for b in row)
            for e in page.elements:              # no position number in the row of values
                if re.fullmatch(r"key-pos-\d+", e.name):
                    b = label_bbox(next(p for p in e.primitives() if isinstance(p, Label)))
                    assert b[2] <= lo or b[0] >= hi or b[3] <= top or b[1] >= bottom, (lang, e.name)


def test_russian_cam_worksheet_writes_S_as_every_russian_output():
    """The ru cam worksheet's table said s_k and its solution s_0, ds/dφ while its diagram said S, dS/dφ."""
    from graphmethods.sheets import worksheets

    sheet = worksheets.worksheet("cam", variants=1, seed=7, notation="ru")
    texts = [t for page in sheet.scenes for t in _texts(page)]
    assert any(t.startswith("Sk, мм") for t in texts) and any(t.startswith("S0 = max(|dS/dφ − e|") for t in texts)
    assert not [t for t in texts if re.search(r"\bs[k0]\b|ds/dφ|\bs\b", t)]


# ----------------------------------------------------------------------------- 6. plans fill their cells

def test_shaper_velocity_plans_fill_cells_as_wide_as_they_are():
    """The shaper's A1 velocity plans were 50–60 % of equal cells (μ_v 0.02 for a need of 0.0112): cells as
    wide as their plans take μ_v 0.01, and each plan fills most of its cell's width or height."""
    from graphmethods.sheets.kinematic_analysis_sheet import kinematic_analysis_sheet

    sheet = kinematic_analysis_sheet(builtin.case("shaper"))
    mu_v = {round(s.per_mm, 9) for s in sheet.scales() if markup.plain(s.symbol) == "μv"}
    assert 0.01 in mu_v and 0.02 not in mu_v, mu_v            # the plans' (the slider's diagrams have their own)


def test_plan_grid_cells_as_wide_as_their_plans():
    """In the shaper's A1 region (508 × 242 mm) equal cells needed 0.0112 (m/s)/mm, so 0.02; cells sized to
    their plans fit 0.01, every plan inside its own cell."""
    from graphmethods.sheets.layout import Sheet
    from graphmethods.sheets.velocity_plans import PLAN_GRID_LAYOUT, _plan_grid

    class _Region:                     # what _plan_grid reads of a sheet
        box = (317.36, 27.0, 826.0, 291.16)
        top, caption_y = 39.0, 291.16

    spans = np.array([(0.2, 0.66), (0.4, 0.67), (0.64, 0.5), (0.75, 0.2), (0.75, 0.16), (0.66, 0.47),
                      (0.44, 0.66), (0.22, 0.67), (0.55, 0.65), (1.23, 0.34), (1.29, 0.28), (0.63, 0.63)])
    assert Sheet                                           # the real one has these attributes too
    grid = _plan_grid(_Region(), spans, np.ones(12, dtype=bool), None, PLAN_GRID_LAYOUT)
    assert grid.shares and grid.need <= 0.01
    for k, (sx, sy) in enumerate(spans):
        _, inner = grid.cell(k, PLAN_GRID_LAYOUT)
        assert sx / 0.01 <= inner[2] - inner[0] + 1e-6 and sy / 0.01 <= inner[3] - inner[1] + 1e-6
    equal = _plan_grid(_Region(), spans, np.ones(12, dtype=bool), 4, PLAN_GRID_LAYOUT)
    assert not equal.shares and equal.need > 0.011


# ----------------------------------------------------------------------------- found afresh

def test_dynamic_sheet_states_each_scale_once():
    """The dynamic sheet wrote μ_φ, μ_M, μ_T, μ_J in its result table and again on a captions line."""
    from graphmethods.dynamics.study import Study
    from graphmethods.sheets.dynamic_analysis_sheet import dynamic_analysis_sheet

    scene = dynamic_analysis_sheet(Study(builtin.case("shaper"), positions=12), notation="ru")
    texts = _element_texts(scene)
    assert not [e for e in scene.elements if e.name == "scale-captions"]
    for s in scene.scales():
        symbol = markup.plain(s.symbol)
        assert len([t for t in texts if t.startswith(symbol + " = ")]) == 1, symbol


def test_russian_slider_diagrams_write_v_as_the_plans_do():
    """The Russian kinematic sheet wrote V_C and μ_V in the slider's diagrams, v and μ_v in its plans and tables."""
    scene = kinematic_diagrams(builtin.case("shaper"), notation="ru", title_block=False)
    texts = _element_texts(scene)
    assert any(t.startswith("μv = μS/(μt·H1)") for t in texts) and any(t.startswith("vC, м/с") for t in texts)
    assert not [t for t in texts if "μV" in t or re.search(r"\bVC\b", t)]
