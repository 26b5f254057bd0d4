"""Tick values by one rule, matplotlib's ``MaxNLocator`` written out (an SVG sheet loads no matplotlib): the
smallest step of 1, 2, 2.5, 5 × 10ᵏ that covers the data in at most ``max_n`` intervals (:func:`nice_ticks`),
and the same rule for an axis of a given length whose ticks stand at least ``min_gap_mm`` apart
(:func:`axis_ticks`: every tick labelled, none repeated, none beyond the drawn axis).

It lives in ``scene`` so that every figure reaches it; :mod:`graphmethods.sheets.engine.axes` adds the
draftsman's decisions on top (where an axis starts, the broken-axis mark).

>>> nice_ticks(0.0, 300.0, 6)
(0.0, 50.0, 100.0, 150.0, 200.0, 250.0, 300.0)
>>> axis_ticks(-60.0, 20.0, Scale("μ_M", "N·m", 2.0), min_gap_mm=8.0)
(-60.0, -40.0, -20.0, 0.0, 20.0)
"""

from __future__ import annotations

import math

from graphmethods.errors import InputError
from graphmethods.scene.scale import Scale

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


def axis_ticks(lo: float, hi: float, scale: Scale, *, min_gap_mm: float = 8.0) -> tuple[float, ...]:
    """The ticks of an axis drawn from ``lo`` to ``hi`` at ``scale``: :func:`nice_ticks` with as many intervals as
    the axis's length holds at ``min_gap_mm`` apart, only those on the drawn axis.

    Parameters
    ----------
    lo, hi : float
        The drawn range of the axis, in its quantity's unit.
    scale : Scale
        The axis's scale (units per mm).
    min_gap_mm : float
        The least distance between two ticks on paper, mm.

    Returns
    -------
    tuple of float
        Multiples of one step of 1, 2, 2.5, 5 × 10ᵏ within [lo, hi], at least ``min_gap_mm`` apart.

    Examples
    --------
    >>> axis_ticks(0.0, 300.0, Scale("μ_T", "J", 5.0), min_gap_mm=8.0)        # 60 mm: at most 7 intervals
    (0.0, 50.0, 100.0, 150.0, 200.0, 250.0, 300.0)
    """
    lo, hi = min(float(lo), float(hi)), max(float(lo), float(hi))
    length_mm = scale.to_mm(hi - lo)
    n0 = max(1, int(length_mm // min_gap_mm)) if math.isfinite(length_mm) else 1
    slack = 1e-9 * max(abs(lo), abs(hi), hi - lo, 1e-300)
    kept: tuple[float, ...] = ()
    # the rule counts the intervals that run past the axis's ends too; a short axis whose end intervals are
    # cut off may keep fewer than three ticks: a few more intervals, as long as the ticks stay min_gap_mm apart
    for max_n in range(n0, n0 + 4):
        if kept and scale.to_mm(nice_step(lo, hi, max_n)) < min_gap_mm * (1 - 1e-9):
            break
        kept = tuple(t for t in nice_ticks(lo, hi, max_n) if lo - slack <= t <= hi + slack)
        if len(kept) >= 3:
            break
    return kept


__all__ = ["STEPS", "axis_ticks", "nice_step", "nice_ticks"]
