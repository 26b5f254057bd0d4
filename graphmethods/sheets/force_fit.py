"""Scales of a drawing that carries forces: a linkage (or a lever, or a group cut from it) to μ_l and its
forces to μ_F, both from the convenient series (1, 2, 2.5, 4, 5 × 10ᵏ), chosen together so that the
drawing and its arrows fill the box they are given.

A course sheet draws the linkage large and its largest force long beside it: the largest force about
half the drawing's size (a load of 7000 N on a shaper's ram, beside inertia forces of 10 N, is the long
arrow; the small ones are drawn at :data:`LEAST_ARROW_MM` with their names, their values in the table, as
the books do). :func:`fit_forces` tries μ_F up the series and keeps the pair (μ_l, μ_F) that makes the
drawing's size times its largest force's length greatest, the force no longer than ``ratio`` of the
drawing. :func:`content_extent` states what a panel holds for a composer that sizes boxes: the points
(model units) and the fixed text (mm).

>>> from graphmethods.scene import notation
>>> s_l, s_F, at = fit_forces([0j, 0.1 + 0j, 0.1 + 0.05j], [(0.1 + 0.05j, 1000 + 0j)], (0.0, 0.0, 200.0, 120.0),
...                           notation("en"), pad_mm=10.0)
>>> s_l.per_mm, s_F.per_mm
(0.001, 20.0)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import Scale
from graphmethods.scene.notation import Notation
from graphmethods.scene.numbers import within_roundoff
from graphmethods.scene.scale import pick_scale
from graphmethods.units import convenient_at_least

Box = tuple[float, float, float, float]
ToMm = Callable[[complex], tuple[float, float]]

#: a force shorter than this (mm) at its drawing's μ_F is too short to draw to scale ...
TOO_SHORT_MM = 2.0
#: ... and is drawn with an arrow of this length and its name only (its value is in the table)
LEAST_ARROW_MM = 7.0


def next_scale(per_mm: float) -> float:
    """The next larger value of the convenient series 1, 2, 2.5, 4, 5 × 10ᵏ after ``per_mm``.

    >>> next_scale(0.002), next_scale(0.005), next_scale(0.0025)
    (0.0025, 0.01, 0.004)
    """
    return convenient_at_least(per_mm * (1 + 1e-9))


def fit_with_arrows(points: list[complex], arrows: list[tuple[complex, complex]], s_F: Scale, area: Box,
                    nt: Notation, *, pad_mm: float = 14.0) -> tuple[Scale, ToMm]:
    """The largest convenient μ_l (m per mm) at which ``points`` (m) and the ``arrows`` drawn from their points
    to μ_F (each (point m, force N)) fit ``area`` with ``pad_mm`` round them for the labels, and the map from a
    point (m) to the page (mm) centring the whole drawing in ``area``.

    >>> from graphmethods.scene import Scale, notation
    >>> s_l, at = fit_with_arrows([0j, 0.1 + 0j], [(0.1 + 0j, 100 + 0j)], Scale("μ_F", "N", 10.0),
    ...                           (0.0, 0.0, 200.0, 100.0), notation("en"))
    >>> s_l.per_mm, at(0j)
    (0.001, (45.0, 50.0))
    """
    room = (max(area[2] - area[0] - 2 * pad_mm, 1e-9), max(area[3] - area[1] - 2 * pad_mm, 1e-9))
    z = np.asarray(points, dtype=complex)
    span = max(float(np.ptp(z.real)) * room[1] / room[0], float(np.ptp(z.imag)))
    size = float(np.max(np.abs(z), initial=0.0))
    if within_roundoff(span, size):         # the points coincide (a group folded at a dead centre): a drawing
        span = max(0.01 * size, 1e-12)      # of 1 % of their distance from O, never μ_l = 10⁻¹⁴ m/mm
    first = pick_scale(span, room[1], symbol="μ_l", unit=nt.unit("m"))
    tips = np.asarray([p for p, _ in arrows], dtype=complex).reshape(-1)
    offsets = np.asarray([_drawn_length(F, s_F) for _, F in arrows], dtype=complex).reshape(-1)
    mu = first.per_mm
    for _ in range(40):                         # up the series 1, 2, 2.5, 4, 5 × 10ᵏ until the arrows fit too
        xs = np.concatenate([z.real / mu, tips.real / mu + offsets.real])
        ys = np.concatenate([z.imag / mu, tips.imag / mu + offsets.imag])
        if np.ptp(xs) <= room[0] + 1e-9 and np.ptp(ys) <= room[1] + 1e-9:
            break
        mu = next_scale(mu)
    s_l = Scale("μ_l", nt.unit("m"), mu)
    cx = (area[0] + area[2]) / 2 - (float(xs.min()) + float(xs.max())) / 2
    cy = (area[1] + area[3]) / 2 + (float(ys.min()) + float(ys.max())) / 2

    def at(w: complex) -> tuple[float, float]:
        return (cx + w.real / mu, cy - w.imag / mu)

    return s_l, at


def _drawn_length(F: complex, s_F: Scale) -> complex:
    """The arrow of force ``F`` (N) on the page (mm, y up): to μ_F, or :data:`LEAST_ARROW_MM` long when too
    short to draw to scale; nothing for a zero force."""
    n = abs(F) / s_F.per_mm
    if n == 0.0:
        return 0j
    return F / s_F.per_mm if n >= TOO_SHORT_MM else F / abs(F) * LEAST_ARROW_MM


def drawn_tip(start: tuple[float, float], F: complex, s_F: Scale, *,
              least: bool = True) -> tuple[tuple[float, float], bool]:
    """The tip (mm, page) of the arrow of ``F`` (N) drawn from ``start``, and whether it is to scale (with
    ``least`` false, always: a figure whose every arrow is to scale).

    >>> from graphmethods.scene import Scale
    >>> drawn_tip((0.0, 0.0), 100 + 0j, Scale("μ_F", "N", 10.0)), drawn_tip((0.0, 0.0), 1j, Scale("μ_F", "N", 10.0))
    (((10.0, 0.0), True), ((0.0, -7.0), False))
    """
    d = _drawn_length(F, s_F) if least else F / s_F.per_mm
    return (start[0] + d.real, start[1] - d.imag), abs(F) / s_F.per_mm >= TOO_SHORT_MM


def arm_lines(pole: tuple[float, float], a: tuple[float, float], b: tuple[float, float], *, least_mm: float = 3.0,
              within: Box | None = None) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The arm of the force drawn from ``a`` to ``b`` (mm) about ``pole`` as Zhukovsky's lever draws it: the
    perpendicular from the pole to the force's line of action, and the line of action produced to its foot
    when the foot lies off the arrow. None for a force through the pole (an arm under ``least_mm``), or whose
    foot falls outside ``within`` (mm, the drawing's area).

    >>> arm_lines((0.0, 0.0), (10.0, 5.0), (20.0, 5.0))
    [((0.0, 0.0), (0.0, 5.0)), ((10.0, 5.0), (0.0, 5.0))]
    >>> arm_lines((0.0, 0.0), (-5.0, 5.0), (5.0, 5.0))
    [((0.0, 0.0), (0.0, 5.0))]
    >>> arm_lines((0.0, 0.0), (10.0, 0.0), (20.0, 0.0))
    []
    """
    P, A, B = (np.asarray(p, dtype=float) for p in (pole, a, b))
    d = B - A
    n = float(np.hypot(*d))
    if n == 0.0:
        return []
    e = d / n
    t = float((P - A) @ e)
    foot = A + t * e
    outside = within is not None and not (within[0] <= foot[0] <= within[2] and within[1] <= foot[1] <= within[3])
    if float(np.hypot(*(foot - P))) < least_mm or outside:
        return []
    f = (float(foot[0]) + 0.0, float(foot[1]) + 0.0)
    out = [((float(P[0]), float(P[1])), f)]
    if t < 0.0:
        out.append(((float(A[0]), float(A[1])), f))
    elif t > n:
        out.append(((float(B[0]), float(B[1])), f))
    return out


def fit_forces(points: Sequence[complex], arrows: Sequence[tuple[complex, complex]], area: Box, nt: Notation, *,
               pad_mm: float = 12.0, ratio: float = 0.5, least_mm: float = 20.0) -> tuple[Scale, Scale, ToMm]:
    """μ_l, μ_F (both convenient) and the map to the page of a drawing of ``points`` (m) with its ``arrows``
    ((point m, force N)) that together fill ``area`` (mm): the drawing's size times its largest force's
    length greatest, the largest force at most ``ratio`` of the drawing's size and at least ``least_mm``
    when it can be.

    Raises
    ------
    InputError
        Every force zero.

    >>> from graphmethods.scene import notation
    >>> s_l, s_F, at = fit_forces([0j, 1j], [(1j, 500 + 0j)], (0.0, 0.0, 150.0, 150.0), notation("en"))
    >>> s_l.per_mm, s_F.per_mm
    (0.01, 10.0)
    """
    F_max = max([abs(F) for _, F in arrows] + [0.0])
    if F_max == 0.0:
        raise InputError("no force acts in this position; there is nothing to draw")
    z = np.asarray(list(points), dtype=complex)
    room = min(area[2] - area[0], area[3] - area[1]) - 2 * pad_mm
    mu_F = convenient_at_least(F_max / max(room, 1.0))
    best: tuple[tuple[float, float], Scale, Scale, ToMm] | None = None
    for _ in range(12):                         # the largest force from the whole room down to a few mm
        s_F = Scale("μ_F", nt.unit("N"), mu_F)
        s_l, at = fit_with_arrows(list(z), list(arrows), s_F, area, nt, pad_mm=pad_mm)
        size = max(float(np.ptp(z.real)), float(np.ptp(z.imag))) / s_l.per_mm
        length = F_max / mu_F
        score = (round(size * min(length, ratio * size) * (1.0 if length >= least_mm else 0.5), 6), -length)
        if best is None or score > best[0]:
            best = (score, s_l, s_F, at)
        mu_F = next_scale(mu_F)
    assert best is not None
    return best[1], best[2], best[3]


@dataclass(frozen=True)
class PanelContent:
    """What a panel holds, for a composer that sizes boxes to drawings (nothing drawn).

    Parameters
    ----------
    points : tuple of complex
        The drawing's points in model units (``unit``: m for a linkage, N for a force plan, m for the lever's
        plan of analogues v/ω₁).
    unit : str
        Their unit.
    text_mm : (width, height), mm
        The block of fixed text the panel writes above its drawing (heading, equations, results).
    below_mm : float, mm
        The room under the drawing for its scale line.
    arrows_mm : float, mm
        Room round the drawing for its forces and labels (at most; 0 for a force plan).
    """

    points: tuple[complex, ...]
    unit: str
    text_mm: tuple[float, float]
    below_mm: float
    arrows_mm: float = 0.0

    @property
    def extent(self) -> Box:
        """``(xmin, ymin, xmax, ymax)`` of the points, model units (y up).

        >>> PanelContent((0j, 2 + 1j), "N", (10.0, 5.0), 8.0).extent
        (0.0, 0.0, 2.0, 1.0)
        """
        z = np.asarray(self.points, dtype=complex)
        return (float(z.real.min()), float(z.imag.min()), float(z.real.max()), float(z.imag.max()))

    def size_mm(self, per_mm: float) -> tuple[float, float]:
        """The panel's width and height (mm) when its drawing is drawn at ``per_mm`` units per mm.

        >>> PanelContent((0j, 2 + 1j), "N", (10.0, 5.0), 8.0).size_mm(0.1)
        (20.0, 23.0)
        """
        x0, y0, x1, y1 = self.extent
        w = (x1 - x0) / per_mm + 2 * self.arrows_mm
        h = (y1 - y0) / per_mm + 2 * self.arrows_mm
        return max(w, self.text_mm[0]), h + self.text_mm[1] + self.below_mm


__all__ = ["LEAST_ARROW_MM", "TOO_SHORT_MM", "PanelContent", "arm_lines", "drawn_tip", "fit_forces",
           "fit_with_arrows", "next_scale"]
