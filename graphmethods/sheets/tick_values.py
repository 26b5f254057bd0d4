"""Every major tick with its value (issue 26, item 3): the choices a figure has when its own ink covers a value.

A value axis whose tick value would lie under the curve or a ray of its figure is drawn, in this order of
preference, (1) as it is when every value besides the origin is written; (2) with its values on the other side
of the axis (the press's J_e value 0.6 lay under the curve above the axis and free below it); (3) with its
ticks 2, 3 or 4 times as far apart; (4) with the unwritten ticks at the ends of its range left out, so the ticks
still run at one step and every tick drawn has its value (the two-slider's ΔT tick −150 fell where the ray at
ψ_min meets the axis, at the point l); else as it was (a tick without its value rather than irregular ticks).
The Wittenbauer slides then try, for their J_e axis, :func:`over_rays`: the values that only a thin ray covers
written, the ray broken behind them.

>>> from graphmethods.scene import Scale
>>> from graphmethods.scene.elements import Axis
>>> ax = Axis((10.0, 95.0), Scale("μ", "J", 1.0), "y", min_value=-40.0, max_value=5.0,
...           ticks=(-30.0, -20.0, -10.0, 0.0), tick_labels=("", "−20", "−10", "0"))
>>> every_value(ax, lambda k: ax).ticks
(-20.0, -10.0, 0.0)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import numpy as np

from graphmethods.scene.elements import Axis, label_bbox
from graphmethods.scene.primitives import Label
from graphmethods.sheets.layout import Box, Occupancy, clear_tick_labels


def off_origin(axis: Axis) -> list[tuple[float, str]]:
    """The ticks of ``axis`` besides its origin (0 or a suppressed zero), with their values as written.

    >>> from graphmethods.scene import Scale
    >>> ax = Axis((0.0, 0.0), Scale("μ", "J", 1.0), "x", max_value=30.0, ticks=(0.0, 10.0, 20.0),
    ...           tick_labels=("0", "10", ""))
    >>> off_origin(ax)
    [(10.0, '10'), (20.0, '')]
    """
    labels = axis.tick_labels or ("",) * len(axis.ticks)
    return [(t, lab) for t, lab in zip(axis.ticks, labels) if not _is_origin(axis, t)]


def _is_origin(axis: Axis, t: float) -> bool:
    return t == 0 or abs(t - axis.min_value) <= 1e-12


def _all_written(axis: Axis) -> bool:
    written = off_origin(axis)
    return len(written) >= 2 and all(lab for _, lab in written)


def trimmed(axis: Axis) -> Axis:
    """``axis`` without the unwritten ticks at the ends of its range (the origin and the inner ticks stay).

    >>> from graphmethods.scene import Scale
    >>> ax = Axis((0.0, 0.0), Scale("μ", "J", 1.0), "x", max_value=35.0, ticks=(0.0, 10.0, 20.0, 30.0),
    ...           tick_labels=("", "10", "20", ""))
    >>> trimmed(ax).ticks, trimmed(ax).tick_labels
    ((0.0, 10.0, 20.0), ('', '10', '20'))
    """
    pairs = list(zip(axis.ticks, axis.tick_labels or ("",) * len(axis.ticks)))
    while pairs and not pairs[-1][1] and not _is_origin(axis, pairs[-1][0]):
        pairs.pop()
    while pairs and not pairs[0][1] and not _is_origin(axis, pairs[0][0]):
        pairs.pop(0)
    return replace(axis, ticks=tuple(t for t, _ in pairs), tick_labels=tuple(lab for _, lab in pairs))


def every_value(axis: Axis, wider: Callable[[int], Axis], *, other_side: Callable[[], Axis] | None = None) -> Axis:
    """``axis`` with every tick besides the origin written, by the choices of the module docstring.

    Parameters
    ----------
    axis : Axis
        The axis as drawn, its covered values left blank (:func:`graphmethods.sheets.layout.clear_tick_labels`).
    wider : callable
        ``wider(k)``: the axis with its ticks k times as far apart, its covered values blank.
    other_side : callable, optional
        The axis with the same ticks and its values on the other side of it, its covered values blank.

    Returns
    -------
    Axis
        The first choice that writes all of at least two values, its origin labelled as ``axis`` labels it.
    """
    if _all_written(axis):
        return axis
    given = dict(zip(axis.ticks, axis.tick_labels or ()))

    def origin_as_given(alt: Axis) -> Axis:
        labels = list(alt.tick_labels or ("",) * len(alt.ticks))
        for i, t in enumerate(alt.ticks):
            if _is_origin(alt, t):
                labels[i] = given.get(t, "")
        return replace(alt, tick_labels=tuple(labels))

    choices = ([other_side] if other_side is not None else []) + [lambda k=k: wider(k) for k in (2, 3, 4)]
    for choice in choices:
        alt = choice()
        if _all_written(alt):
            return origin_as_given(alt)
    cut = trimmed(axis)
    return cut if _all_written(cut) else axis


def over_rays(axis: Axis, unrayed: Occupancy, occ: Occupancy) -> Axis:
    """``axis`` with the values written that cover nothing of ``unrayed`` (what is drawn but the thin rays, which
    are then broken behind them) and no text of ``occ`` (the scotch yoke's J_e value 0.25 lay under the ray at
    ψ_max above the axis and under the curve below it).

    >>> from graphmethods.scene import Scale
    >>> occ, unrayed = Occupancy(), Occupancy()
    >>> occ.add_line(((0.0, 97.0), (40.0, 97.0)))                   # a ray under the values
    >>> ax = Axis((10.0, 95.0), Scale("μ", "J", 1.0), "x", max_value=30.0, ticks=(0.0, 10.0, 20.0))
    >>> over_rays(ax, unrayed, occ).tick_labels
    ('0', '10', '20')
    """
    ax = clear_tick_labels(axis, unrayed)
    texts = [p for p in replace(ax, label="").primitives() if isinstance(p, Label)]
    shown = [i for i, lab in enumerate(ax.tick_labels or ()) if lab and not (ax.skip_zero_label and ax.ticks[i] == 0)]
    labels = list(ax.tick_labels or ())
    for i, lab in zip(shown, texts):
        labels[i] = labels[i] if occ.is_free(label_bbox(lab), lines=False) else ""
    return replace(ax, tick_labels=tuple(labels))


def tick_label_band(axis: Axis) -> Box | None:
    """The row (a horizontal axis) or column (a vertical one) that ``axis``'s tick values take, from its
    first tick to its last, whether each value is written or was left out; None without ticks. Nothing else
    is placed there: a number in it reads as one of the axis's values.

    >>> from graphmethods.scene import Scale
    >>> ax = Axis((10.0, 50.0), Scale("μ", "J", 1.0), "x", max_value=30.0, ticks=(0.0, 10.0, 20.0, 30.0))
    >>> [round(v, 1) for v in tick_label_band(ax)]
    [9.0, 52.3, 41.9, 55.3]
    """
    written = None if axis.tick_labels is None else tuple(lab or "0" for lab in axis.tick_labels)
    probe = replace(axis, label="", skip_zero_label=False, tick_labels=written)
    boxes = np.array([label_bbox(p) for p in probe.primitives() if isinstance(p, Label)], dtype=float)
    if not len(boxes):
        return None
    return (float(boxes[:, 0].min()), float(boxes[:, 1].min()), float(boxes[:, 2].max()), float(boxes[:, 3].max()))
