"""The layout engine (issue 26): nice ticks, axis ranges, panels at the convenient scale, the composer,
labels placed against ink, lettering per format."""

import math

import pytest
from hypothesis import example, given, strategies as st

from graphmethods.errors import InputError
from graphmethods.scene import Line, Page, Scene, Text
from graphmethods.scene.scale import SERIES
from graphmethods.sheets.engine import (
    Ink,
    Panel,
    Split,
    axis_range,
    broken_axis_mark,
    course_page,
    lettered,
    lettering,
    nice_step,
    nice_ticks,
    shares_for,
)
from graphmethods.sheets.engine.quality import measure

finite = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False, allow_infinity=False)


@given(finite, finite, st.integers(min_value=2, max_value=12))
@example(0.0, 5e-324, 2)              # a subnormal range (found on numpy 1.23's floors)
@example(1.19e-7, -101.0, 2)
def test_nice_ticks_cover_the_data_at_a_nice_step_in_at_most_max_n_intervals(a, b, n):
    lo, hi = min(a, b), max(a, b)
    t = nice_ticks(lo, hi, n)
    step = nice_step(lo, hi, n)
    assert len(t) - 1 <= n and len(set(t)) == len(t) and list(t) == sorted(t)
    if hi > lo:
        assert t[0] <= lo + 1e-9 * max(1.0, abs(lo)) and t[-1] >= hi - 1e-9 * max(1.0, abs(hi))
        assert t[1] - t[0] < (hi - lo) + step + 1e-9 * max(1.0, abs(hi))          # the axis fits its data
    mant = step / 10 ** math.floor(math.log10(step))
    assert any(abs(mant - m) < 1e-9 for m in (1.0, 2.0, 2.5, 5.0, 10.0))
    assert all(repr(v) == repr(float(f"{v:.12g}")) for v in t)                   # no round-off printed


def test_axis_range_starts_at_zero_near_it_and_breaks_far_from_it():
    assert axis_range(0.0, 300.0, 6).ticks == (0.0, 50.0, 100.0, 150.0, 200.0, 250.0, 300.0)
    r = axis_range(1.53, 1.81, 6)
    assert r.broken and r.origin == 1.5 and r.ticks[-1] >= 1.81
    assert not axis_range(-770.0, 230.0, 6).broken and axis_range(-770.0, 230.0, 6).ticks[0] == -800.0
    assert len(broken_axis_mark((10.0, 20.0), "x")) == 2
    with pytest.raises(InputError):
        nice_ticks(0.0, math.inf, 5)
    with pytest.raises(InputError):
        nice_ticks(0.0, 1.0, 0)


@given(st.floats(min_value=1e-4, max_value=1e3), st.floats(min_value=1e-4, max_value=1e3))
def test_a_panel_gets_the_largest_convenient_scale_that_fits(w, h):
    p = Panel((10.0, 20.0, 210.0, 140.0), (0.0, 0.0, w, h), margins_mm=(5.0, 5.0, 5.0, 5.0))
    mu = p.scale.per_mm
    mant = mu / 10 ** math.floor(math.log10(mu) + 1e-12)
    assert any(abs(mant - m) < 1e-9 for m in SERIES)
    x0, y0, x1, y1 = p.drawing_box
    assert w / mu <= (x1 - x0) * (1 + 1e-9) and h / mu <= (y1 - y0) * (1 + 1e-9)
    assert 0.4 <= p.fill <= 1.0 + 1e-9                     # the next convenient value is at most 2.5 × smaller
    a, b = p.to_page(0.0, 0.0), p.to_page(w, h)
    assert x0 - 1e-6 <= a[0] <= b[0] <= x1 + 1e-6 and y0 - 1e-6 <= b[1] <= a[1] <= y1 + 1e-6


def test_the_composer_divides_a_box_without_overlap():
    tree = Split("h", (("a", 1.0), (Split("v", (("b", 1.0), ("c", 3.0)), gap_mm=4.0), 2.0)), gap_mm=10.0)
    boxes = tree.boxes((0.0, 0.0, 310.0, 204.0))
    assert boxes == {"a": (0.0, 0.0, 100.0, 204.0), "b": (110.0, 0.0, 310.0, 50.0), "c": (110.0, 54.0, 310.0, 204.0)}
    assert sum(shares_for((3.0, 1.0, 0.0))) == pytest.approx(1.0)
    with pytest.raises(InputError):
        Split("x", (("a", 1.0),))
    assert course_page("A1").size == "A1" and course_page("slide").size == "SLIDE"


def test_labels_keep_off_ink_and_move_out_with_a_leader_when_boxed_in():
    ink = Ink()
    ink.add_line(((0.0, 50.0), (100.0, 50.0)))
    lab, leader = ink.place((50.0, 50.0), "B", size_mm=3.5)
    assert leader is None and measure_crossing(lab) == 0
    boxed = Ink()
    for r in (3.0,):                                          # a small square round the point
        boxed.add_line(((50 - r, 50 - r), (50 + r, 50 - r), (50 + r, 50 + r), (50 - r, 50 + r), (50 - r, 50 - r)))
    lab, leader = boxed.place((50.0, 50.0), "S_{4}", size_mm=3.5)
    assert leader is not None


def measure_crossing(lab) -> int:
    page = Page("A4", "landscape", frame=True)
    scene = Scene(page, (Line((0.0, 50.0), (100.0, 50.0), name="l"),
                         Text((lab.x, lab.y), "B", size_mm=lab.size_mm, anchor=lab.anchor, name="t")))
    return len(measure(scene).crossed)


def test_lettering_per_format_and_the_lettered_context():
    assert (lettering("A1").label_mm, lettering("A1").title_mm, lettering("A4").minimum_mm) == (3.5, 7.0, 2.5)
    with lettered("A1"):
        assert Text((0, 0), "x", size_mm=2.6).size_mm == 3.5
    with lettered("A4"):
        assert Text((0, 0), "x", size_mm=2.6).size_mm == 2.6
    assert Text((0, 0), "x", size_mm=2.6).size_mm == 2.6
