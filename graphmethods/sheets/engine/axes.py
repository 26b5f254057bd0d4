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

import math
from dataclasses import dataclass

from graphmethods.errors import InputError
from graphmethods.scene.primitives import AXIS, XY, Path, Primitive

#: the steps of the nice-number rule (× 10ᵏ), as MaxNLocator's default ``steps``
STEPS = (1.0, 2.0, 2.5, 5.0, 10.0)


def _clean(v: float) -> float:
    """A tick value without the round-off of its multiplication (and never −0)."""
    r = float(f"{v:.12g}")
    return 0.0 if r == 0 else r


def _tick_indices(lo: float, hi: float, step: float) -> tuple[int, int]:
    """The first and last multiples of ``step`` covering [lo, hi], forgiving only round-off.

    A value within 1e-9 of a multiple, relative to the value (and absolute below 1, unless the whole
    range is smaller), counts as on it: ``0.30000000000000004`` and a noise of 1e-15 about 0 add no
    interval, a real 1.2e-7 above 0 does.

    >>> _tick_indices(-101.0, 1.2e-7, 200.0), _tick_indices(-17.3, 6.8e-16, 5.0)
    ((-1, 1), (-4, 0))
    """
    span = hi - lo

    def slack(v: float) -> float:
        return 1e-9 * min(max(1.0, abs(v)), max(abs(v), span))

    return math.floor((lo + slack(lo)) / step), math.ceil((hi - slack(hi)) / step)


def nice_step(lo: float, hi: float, max_n: int) -> float:
    """The step of :func:`nice_ticks`: the smallest 1, 2, 2.5, 5 × 10ᵏ covering [lo, hi] in ≤ max_n intervals.

    >>> nice_step(0.0, 1.0, 5), nice_step(-60.0, 20.0, 4)
    (0.2, 20.0)
    """
    lo, hi = float(lo), float(hi)
    if not (math.isfinite(lo) and math.isfinite(hi)):
        raise InputError(f"axis range {lo!r}…{hi!r} is not finite; fix the data it comes from")
    if isinstance(max_n, bool) or int(max_n) != max_n or max_n < 1:
        raise InputError(f"max_n = {max_n!r}: give a whole number of intervals ≥ 1")
    if hi < lo:
        lo, hi = hi, lo
    if hi - lo < 1e-300:             # equal values, or closer than a normal float can step (subnormal)
        span = max(abs(hi), abs(lo), 1e-300) if (hi or lo) else 1.0
        lo, hi = lo - span / 2, hi + span / 2
    raw = (hi - lo) / max_n
    k = math.floor(math.log10(raw))
    for e in (k - 1, k, k + 1):
        for m in STEPS:
            step = float(f"{m!r}e{e}")
            first, last = _tick_indices(lo, hi, step)
            if last - first <= max_n and step >= raw * (1 - 1e-12):
                return step
    return float(f"1e{k + 2}")                       # pragma: no cover - 10^(k+1) always fits


def nice_ticks(lo: float, hi: float, max_n: int = 6) -> tuple[float, ...]:
    """Tick values covering [lo, hi] at a nice step, at most ``max_n`` intervals: every one to be labelled.

    Parameters
    ----------
    lo, hi : float
        The data range (any order; equal values get a range around them).
    max_n : int
        Most intervals between ticks (MaxNLocator's ``nbins``; data on both sides of 0 need 2).

    Returns
    -------
    tuple of float
        From the largest multiple of the step at or below ``lo`` to the smallest at or above ``hi``;
        no repeats, no round-off (``0.3``, never ``0.30000000000000004``).

    Examples
    --------
    >>> nice_ticks(0.02, 0.97, 5)
    (0.0, 0.2, 0.4, 0.6, 0.8, 1.0)
    >>> nice_ticks(-770.0, 0.0, 4)
    (-800.0, -600.0, -400.0, -200.0, 0.0)
    """
    step = nice_step(lo, hi, max_n)
    lo, hi = min(lo, hi), max(lo, hi)
    if lo == hi:
        span = abs(hi) or 1.0
        lo, hi = lo - span / 2, hi + span / 2
    first, last = _tick_indices(lo, hi, step)
    return tuple(_clean(i * step) for i in range(first, last + 1))


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
