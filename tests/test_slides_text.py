"""Text on the lecture slides (issue 26, lane slides): wrapping that orphans nothing, one test per cause.

- The ru Zhukovsky lever slide wrapped "(расхождение 0,000 %)" as "… (расхождение 0,000" and "%)" alone on a
  line: a closing bracket, a per cent sign or a unit never begins a line, and a short bracketed remark stays whole.
"""

import pytest

from graphmethods.render.recording import record
from graphmethods.scene.steps import CLOSING, wrap
from graphmethods.sheets import steps


@pytest.mark.parametrize("width", [60.0, 80.0, 100.0, 120.0, 130.0, 150.0])
def test_wrapping_never_begins_a_line_with_a_closing_bracket_or_a_unit(width):
    text = "Mур = Fур·lOA = 538,423 Н·м; по планам сил: 538,423 Н·м (расхождение 0,000 %)"
    lines = wrap(text, 5.0, width)
    assert " ".join(lines) == text
    assert not any(line[0] in CLOSING for line in lines[1:]), lines
    assert not any(line.split()[0].rstrip(";,") in ("Н·м", "%", "м", "Н") for line in lines[1:]), lines


def test_a_number_keeps_its_unit_and_a_short_remark_stays_whole():
    assert wrap("a load of 538.4 N·m at 120 rad/s", 5.0, 45.0) == ["a load of", "538.4 N·m at", "120 rad/s"]
    assert wrap("a load of 538.4 N·m at 120 rad/s", 5.0, 50.0) == ["a load of 538.4 N·m", "at 120 rad/s"]
    assert wrap("discrepancy is small (0.000 %)", 5.0, 55.0) == ["discrepancy is small", "(0.000 %)"]


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_the_lever_slides_orphan_no_bracket_or_unit(lang):
    bu = steps.build("press", "zhukovsky-lever", notation=lang)
    texts = [c.data.text for c in record(bu.slide(len(bu))).calls if c.kind == "text"]
    orphans = [t for t in texts if t.strip() and (t.strip()[0] in CLOSING or t.strip() in ("%)", "%", ")"))]
    assert orphans == []


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_the_load_levers_caption_writes_the_tables_law(lang):
    """One symbol per quantity: the zh step wrote M_er = F·h·μ_v/ω_1 where its table wrote F_r·h (ru: F_пс)."""
    bu = steps.build("shaper", "zhukovsky-load", notation=lang)
    table = next(e for e in bu.figure.elements if e.name == "result")
    law = next(r[1] for r in getattr(table, "element", table).rows if "·h·" in r[1] and "=" in r[1])
    assert law.split("=", 1)[1].strip() in bu.captions()[-1]
