"""Axes as a draftsman draws them: nice tick values, every one labelled, the axis clipped to the data.

:func:`nice_ticks` is matplotlib's ``MaxNLocator`` rule written out (an SVG sheet loads no
matplotlib): the smallest step of 1, 2, 2.5, 5 × 10ᵏ that covers the data in at most ``max_n``
intervals, ticks from the last multiple of the step at or below the data to the first at or above.
:func:`axis_range` adds the draftsman's decision about zero: an axis starts at 0 when 0 is near the
data; when the data sit far from zero (a J_e between 1.5 and 1.8 kg·m²) the axis starts at a round
value J₀ below them, and :func:`broken_axis_mark` draws the break on the axis line near its start.

>>> nice_ticks(0.0, 300.0, 6)
(0.0, 50.0, 100.0, 150.0, 200.0, 250.0, 300.0)
>>> r = axis_range(1.53, 1.81, 6)
>>> r.ticks, r.broken, r.origin
((1.5, 1.6, 1.7, 1.8, 1.9), True, 1.5)
>>> axis_range(-120.0, 430.0, 6).ticks
(-200.0, 0.0, 200.0, 400.0, 600.0)
"""

from __future__ import annotations

from dataclasses import dataclass

from graphmethods.errors import InputError
from graphmethods.scene.primitives import AXIS, XY, Path, Primitive
from graphmethods.scene.ticks import STEPS, nice_step, nice_ticks  # the rule lives in scene: every figure reaches it


@dataclass(frozen=True)
class AxisRange:
    """An axis's drawn range: its ticks, where it starts (0, or J₀ when broken) and where it ends."""

    ticks: tuple[float, ...]
    broken: bool

    @property
    def origin(self) -> float:
        """The value at the axis's start: 0, or the round value J₀ below data far from zero."""
        return self.ticks[0] if self.broken and self.ticks[0] > 0 else (
            self.ticks[-1] if self.broken else min(0.0, self.ticks[0]))

    @property
    def lo(self) -> float:
        return self.ticks[0]

    @property
    def hi(self) -> float:
        return self.ticks[-1]


def axis_range(lo: float, hi: float, max_n: int = 6, *, far: float = 1.0) -> AxisRange:
    """The ticks of an axis for data in [lo, hi]: from zero when zero is near, else broken at a round J₀.

    Zero is near when including it at most ``1 + far`` times lengthens the axis (the data's distance from
    zero is at most ``far`` times their span). Otherwise the axis is broken: it starts at the last tick below
    the data, and the figure draws :func:`broken_axis_mark` and writes that origin (J₀) at the start.

    >>> axis_range(120.0, 300.0, 6).ticks
    (0.0, 50.0, 100.0, 150.0, 200.0, 250.0, 300.0)
    >>> axis_range(-9.0, -8.2, 4).broken
    True
    """
    lo, hi = min(float(lo), float(hi)), max(float(lo), float(hi))
    span = hi - lo
    gap = lo if lo > 0 else (-hi if hi < 0 else 0.0)
    if gap > 0 and (span == 0 or gap > far * span):
        return AxisRange(nice_ticks(lo, hi, max_n), True)
    return AxisRange(nice_ticks(min(lo, 0.0), max(hi, 0.0), max_n), False)


def broken_axis_mark(at: XY, direction: str = "x", *, size_mm: float = 2.5) -> tuple[Primitive, ...]:
    """The break on an axis line at ``at`` (page mm): two short parallel strokes across it, as drawn by hand.

    >>> len(broken_axis_mark((10.0, 50.0), "y"))
    2
    """
    if direction not in ("x", "y"):
        raise InputError(f"broken_axis_mark: direction {direction!r}: use 'x' or 'y'")
    x, y = float(at[0]), float(at[1])
    h = size_mm / 2
    d = 0.8                                           # half the distance between the strokes along the axis
    if direction == "x":
        strokes = [((x + s - h / 2, y + h), (x + s + h / 2, y - h)) for s in (-d, d)]
    else:
        strokes = [((x - h, y + s + h / 2), (x + h, y + s - h / 2)) for s in (-d, d)]
    return tuple(Path(s, AXIS) for s in strokes)


__all__ = ["STEPS", "AxisRange", "axis_range", "broken_axis_mark", "nice_step", "nice_ticks"]
