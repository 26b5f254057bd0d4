"""The A1 force sheet at every position, not only position 3: at a dead centre (positions 0, 6, 9 of the
built-in linkages) no number of round-off size is printed (M_b, F_b, the lever's and the power balance's
working, the inertia loads, μ_l), and the sheet's M_b is the one ``graphmethods forces P --position i``
prints (text and --json). And at every position its labels are clear (issue 26): no label crossed by a line,
an arrow or a hatch (the plans' lines of action, the joints' circles and a dense lever's images were not seen by
the label placement), no text over text, no text under 3.5 mm; en at 0, 6, 9 on every linkage, ru and zh at a
position that turns with the linkage so that every position is drawn in each."""

import functools
import re

import pytest

from graphmethods.cli import forces as cli_forces
from graphmethods.problems import builtin
from graphmethods.sheets.engine.quality import EMPTY_MAX, measure
from graphmethods.sheets.force_analysis_sheet import force_analysis_sheet

LINKAGES = [p for p in builtin.names() if p not in builtin.CAMS and p not in builtin.CYCLES]
POSITIONS = (0, 6, 9)


def _walk(elements):
    for e in elements:
        yield e
        yield from _walk(getattr(e, "elements", ()) or ())


@functools.cache
def _sheet(name, i, lang="en"):
    return force_analysis_sheet(builtin.case(name), position=i, page="A1", notation=lang)


def _sheet_M_b(scene) -> float:
    """M_b as the linkage panel prints it: "balancing moment M_b = 123.456 N·m"."""
    for e in _walk(scene.elements):
        t = getattr(e, "text", None) or ""
        hit = re.match(r"balancing moment M_b = (\S+) N·m$", t)
        if hit:
            return float(hit.group(1).replace("−", "-").replace("\u2009", ""))
    raise AssertionError("no balancing moment on the sheet")


@pytest.mark.parametrize("name", LINKAGES)
@pytest.mark.parametrize("i", POSITIONS)
def test_no_round_off_printed_at_any_position(name, i):
    assert measure(_sheet(name, i)).noise == ()


@pytest.mark.parametrize("name, i, lang", [("shaper", 0, "ru"), ("slotting-machine", 6, "zh"),
                                           ("scotch-yoke", 9, "ru")])
def test_no_round_off_printed_in_ru_and_zh(name, i, lang):
    assert measure(_sheet(name, i, lang)).noise == ()


@pytest.mark.parametrize("name", LINKAGES)
@pytest.mark.parametrize("i", POSITIONS)
def test_the_sheets_M_b_is_the_command_lines(name, i):
    res = cli_forces.result(builtin.case(name), position=i)
    M_b = res["M_balance"]
    shown = _sheet_M_b(_sheet(name, i))
    assert shown == pytest.approx(M_b, rel=1e-5, abs=0.0)
    if M_b == 0.0:                                   # a dead centre: 0 everywhere, the checks agree exactly
        assert res["M_balance_lever"] == res["M_balance_power"] == 0.0
        assert res["difference_lever_percent"] == res["difference_power_percent"] == 0.0
        assert re.search(r"from the force plans +0\.000000 N·m", cli_forces._text(res, "en"))


def test_a_dead_centre_prints_M_b_as_zero():
    """The shaper at position 0: M_b was 3.2·10⁻¹⁵ N·m on the sheet and −0.000000 (115 % off) in the text."""
    res = cli_forces.result(builtin.case("shaper"), position=0)
    assert (res["M_balance"], res["M_balance_lever"], res["M_balance_power"]) == (0.0, 0.0, 0.0)
    assert _sheet_M_b(_sheet("shaper", 0)) == 0.0


@pytest.mark.parametrize("name, i", [("engine", 6), ("scotch-yoke", 0), ("two-slider", 9), ("shaper", 0)])
def test_the_force_build_up_prints_no_round_off(name, i):
    """The slides' force build-up: R_03 was 5.4·10⁻¹⁴ N at the engine's dead centre, "the table's 0" now."""
    from graphmethods.sheets import construction_steps as C

    for build in (C.force_plans_steps, C.zhukovsky_forces_steps):
        steps = build(builtin.case(name), i)
        captions = [str(getattr(s, "caption", s)) for s in getattr(steps, "steps", steps)]
        assert captions and not [c for c in captions if re.search("10⁻[¹²³⁴⁵⁶⁷⁸⁹]", c)]


#: sheets too empty at a position other than 3 where position 3 passes (the composition's, lane forcefill)
TURNING = [(name, k % 12, "ru") for k, name in enumerate(LINKAGES)] + \
          [(name, (k + 6) % 12, "zh") for k, name in enumerate(LINKAGES)]


@pytest.mark.parametrize("name, i, lang", [(n, i, "en") for n in LINKAGES for i in POSITIONS] + TURNING)
def test_labels_clear_at_every_position(name, i, lang):
    q = measure(_sheet(name, i, lang))
    assert q.crossed == () and q.overlaps == () and q.noise == ()
    assert q.min_text_mm >= 3.5 - 1e-9
    assert q.empty_share <= EMPTY_MAX


def test_the_scotch_yoke_is_drawn_as_a_yoke():
    """The sine mechanism's slotted crosshead: its slot (as long as the block's travel in it, to μ_l), its rod
    and the frame's hatched guide, on the linkage with its forces; no bare line from the crank pin to C."""
    scheme = next(e for e in _sheet("scotch-yoke", 9).elements if e.name == "scheme")
    names = {e.name for e in _walk(scheme.elements)}
    assert {"yoke-3-slot", "yoke-3-rod", "guide-3", "yoke-3-block"} <= names
    assert "link-A-C" not in names
