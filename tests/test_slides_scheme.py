"""The kinematic scheme's slide (issue 26, lane slides): composed as a lecturer fills a wide slide, one test per
cause.

- The two-slider compressor (cylinders at 90°) is a tall linkage: at the largest μ_l that fits its height it left
  55 % of the slide empty. Beside it now stands the table of the output's positions (φ and s per position), the
  numbers ``graphmethods kinematics P`` prints, where the table costs the drawing nothing (same μ_l).
- The slotting machine dimensions its stroke beside its steep guide, right of the linkage: "H = 400 mm" ran into
  the table; such a scheme keeps its width and goes without the table.
- The note "drawn z : 1" was judged only against the figure's lines: on the six-bar press's ru slide it stood over
  the stroke's value "H = 270,8 мм".
"""

import json

import pytest

from graphmethods.cli import main
from graphmethods.scene import notation
from graphmethods.sheets import steps
from graphmethods.sheets.engine.quality import faults, measure

TALL = ("two-slider", "six-bar-press", "slotting-machine", "shaper")


def _table(bu):
    e = next((e for e in bu.figure.elements if e.name == "positions-table"), None)
    return getattr(e, "element", e)                 # on the slide, the table enlarged z : 1


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_the_two_sliders_scheme_slide_is_filled_by_its_positions_table(lang):
    bu = steps.build("two-slider", "kinematic-scheme", notation=lang)
    assert _table(bu) is not None
    assert faults(measure(bu.slide(len(bu)))) == []


@pytest.mark.parametrize("problem", ["two-slider", "six-bar-press", "shaper"])
def test_the_positions_table_prints_the_command_lines_displacements(problem, capsys):
    assert main(["kinematics", problem, "--json"]) in (0, None)
    rows = json.loads(capsys.readouterr().out)["positions"]
    key = next(k for k in rows[0] if k.startswith("s_"))
    table = _table(steps.build(problem, "kinematic-scheme", notation="en"))
    assert table is not None and table.rows[0][2].startswith(f"s_{{{key[2:]}}}")
    nt = notation("en")
    expected = nt.column([r[key] for r in rows], sig=4, reference=max(abs(r[key]) for r in rows))
    assert [r[2] for r in table.rows[1:]] == expected
    assert [int(r[0]) for r in table.rows[1:]] == [r["position"] for r in rows]


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
@pytest.mark.parametrize("problem", TALL)
def test_every_tall_linkages_scheme_slide_meets_the_slide_standard(problem, lang):
    bu = steps.build(problem, "kinematic-scheme", notation=lang)
    assert faults(measure(bu.slide(len(bu)))) == []


def test_the_slotting_machines_stroke_keeps_clear_of_a_table():
    bu = steps.build("slotting-machine", "kinematic-scheme", notation="zh")
    assert _table(bu) is None          # with it, "H = 400 mm" ran into the table


def test_the_positions_table_enters_with_the_stroke():
    bu = steps.build("two-slider", "kinematic-scheme", notation="en")
    k = next(i for i, c in enumerate(bu.captions(), start=1) if "stroke" in c)
    assert "displacement" in bu.captions()[k - 1]
    names = {e.name for e in bu.figure.elements}
    assert "positions-table" in names
