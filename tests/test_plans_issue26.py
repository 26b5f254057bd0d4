"""Issue 26, lane "plans": the acceleration plan of the class III triad clean on its A4 page and in any box
(the A1 force sheet's panel), its long equations broken as a textbook sets a system, and the Scotch yoke's
yoke drawn as a link in the structure diagram. Each test failed on main before the fix."""

import pytest

from graphmethods.dynamics.study import Study
from graphmethods.problems import builtin
from graphmethods.scene import Page
from graphmethods.sheets.acceleration import acceleration_plan
from graphmethods.sheets.acceleration_layout import wrap
from graphmethods.sheets.composition import region_page
from graphmethods.sheets.engine.quality import faults, measure
from graphmethods.sheets.structure_diagram import structure_diagram

_study: dict = {}


def _triad():
    if "t" not in _study:
        _study["t"] = Study(builtin.case("triad-six-bar"), positions=12)
    return _study["t"]


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_triad_acceleration_plan_has_no_equation_over_the_table_or_eps(lang):
    """The Assur-point equation ran under the ε column and φ under the table (main: 1–5 crossed, 1–3 overlaps)."""
    q = measure(acceleration_plan(_triad(), notation=lang))
    assert q.crossed == () and q.overlaps == ()


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_triad_acceleration_plan_is_clean_in_the_force_sheets_panel_box(lang):
    """The box the A1 force sheet gives its acceleration panel (position 3): main crossed φ, the Assur-point
    equation and the image labels b, s₄ with construction lines and leaders."""
    box = (444.9137718802936, 27.0, 632.0, 254.64)
    pg = Page("A1", "landscape", frame=True)
    scene = acceleration_plan(builtin.case("triad-six-bar"), 3, m=12, notation=lang, page=region_page(pg, box),
                              title_block=False)
    q = measure(scene)
    assert q.crossed == () and q.overlaps == ()
    inside = [b for b in (e.bbox() for e in scene.elements) if b is not None]
    assert all(b[0] >= box[0] - 1 and b[2] <= box[2] + 1 and b[3] <= box[3] + 1 for b in inside)


def test_the_assur_point_equation_is_set_as_a_system_under_its_first_equals_sign():
    eq = "a_{K3} = a_{A} + a^{n}_{BA} + a^{n}_{K3B} + a^{τ} = a_{E} + a^{n}_{CE} + a^{n}_{K3C} + a^{τ} (Assur's point)"
    lines = wrap(eq, 90.0)
    assert [t.split(" ")[0] for t, _ in lines] == ["a_{K3}", "="]
    assert lines[1][1] > 0                              # the continuation indented under the "="
    assert wrap("ε_{2} = 1", 90.0) == [("ε_{2} = 1", 0.0)]


def test_a_line_of_speeds_breaks_after_its_comma_not_inside_an_equation():
    lines = wrap("φ = 30° (φ от положения 0),  ω_{1} = 12,57 рад/с, ε_{1} = 0 рад/с²", 75.0)
    assert all(t.endswith(",") for t, _ in lines[:-1]) and lines[-1][0].startswith(("ω", "ε"))


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_scotch_yoke_structure_diagram_draws_the_yoke_with_its_number_off_the_block(lang):
    """Main drew the group II(2,3) as one block on a guide: the yoke (link 3) missing, "3" on the block."""
    s = structure_diagram(builtin.case("scotch-yoke"), notation=lang)
    names = {e.name for g in s.elements for e in getattr(g, "elements", (g,))}
    assert {"yoke-3-slot", "yoke-3-rod", "yoke-3-block", "guide-3", "block-A"} <= names
    part = s.element("part-II(2,3)")
    els = {e.name: e for e in part.elements}
    n3, blk = els["number-3"].bbox(), els["block-A"].bbox()
    assert n3[2] <= blk[0] or n3[0] >= blk[2] or n3[3] <= blk[1] or n3[1] >= blk[3]     # not on the block
    assert faults(measure(s)) == []
