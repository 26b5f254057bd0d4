"""A panel: a drawing that states its content in model units and gets the largest convenient scale that fits.

A recipe says what a panel holds (a mechanism's extent over all positions, a plan's vectors, a
diagram's data range) and the box it is given on the page; the panel picks μ from the convenient
series (1, 2, 2.5, 4, 5 × 10ᵏ: :func:`graphmethods.scene.scale.pick_scale`) so the content fills the
box (less the room kept for the panel's heading and labels) and maps model points (y up) to the page
(y down), centred in the box.

>>> p = Panel((0.0, 0.0, 200.0, 120.0), (-0.1, -0.05, 0.5, 0.2), symbol="μ_l", unit="m")
>>> p.scale.per_mm, p.to_page(0.0, 0.0)
(0.004, (50.0, 78.75))
>>> round(p.fill, 3)
0.75
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene.scale import SERIES, Scale, pick_scale

Box = tuple[float, float, float, float]


def extent_of(points: Iterable[Sequence[float]]) -> Box:
    """The model extent ``(xmin, ymin, xmax, ymax)`` of some points (a plan's tips, a linkage's joints).

    >>> extent_of([(0, 0), (0.3, -0.1), (0.1, 0.2)])
    (0.0, -0.1, 0.3, 0.2)
    """
    a = np.asarray(list(points), dtype=float).reshape(-1, 2)
    if not len(a) or not np.isfinite(a).all():
        raise InputError("a panel's content needs at least one finite point")
    return (float(a[:, 0].min()), float(a[:, 1].min()), float(a[:, 0].max()), float(a[:, 1].max()))


@dataclass(frozen=True)
class Panel:
    """A drawing in a box of the page, at the largest convenient scale its content fits.

    Parameters
    ----------
    box : (x0, y0, x1, y1), mm
        The panel's box on the page (y down).
    extent : (xmin, ymin, xmax, ymax)
        The content in model units (y up): what must be drawn inside the box.
    symbol, unit : str
        The scale's name and unit (``"μ_l"``, ``"m"``).
    margins_mm : (top, right, bottom, left), mm
        Room kept inside the box for the heading, labels and captions.
    scale_given : Scale, optional
        Use this scale instead of picking one (the content is still centred).
    series : tuple of float
        The convenient mantissas.
    """

    box: Box
    extent: Box
    symbol: str = "μ"
    unit: str = ""
    margins_mm: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    scale_given: Scale | None = None
    series: tuple[float, ...] = field(default=SERIES)

    def __post_init__(self) -> None:
        x0, y0, x1, y1 = self.drawing_box
        if not (x1 > x0 and y1 > y0):
            raise InputError(f"panel {self.box!r} mm leaves no room for a drawing inside margins "
                             f"{self.margins_mm!r} mm; give it a larger box")
        if not all(math.isfinite(v) for v in self.extent) or self.extent[2] < self.extent[0] \
                or self.extent[3] < self.extent[1]:
            raise InputError(f"panel content extent {self.extent!r} is not a finite box (xmin, ymin, xmax, ymax)")

    @property
    def drawing_box(self) -> Box:
        """The box left for the drawing, inside the margins (mm)."""
        t, r, b, left = self.margins_mm
        x0, y0, x1, y1 = self.box
        return (x0 + left, y0 + t, x1 - r, y1 - b)

    @property
    def need(self) -> float:
        """The smallest scale (units/mm) that fits the content: the larger of width/room and height/room."""
        x0, y0, x1, y1 = self.drawing_box
        w, h = self.extent[2] - self.extent[0], self.extent[3] - self.extent[1]
        return max(w / (x1 - x0), h / (y1 - y0))

    @property
    def scale(self) -> Scale:
        """The scale: given, or the smallest convenient one not below :attr:`need`."""
        if self.scale_given is not None:
            return self.scale_given
        x0, y0, x1, y1 = self.drawing_box
        w, h = self.extent[2] - self.extent[0], self.extent[3] - self.extent[1]
        span, room = (w, x1 - x0) if w / (x1 - x0) >= h / (y1 - y0) else (h, y1 - y0)
        return pick_scale(span, room, series=self.series, symbol=self.symbol, unit=self.unit)

    @property
    def fill(self) -> float:
        """The share of the drawing box's width or height the content takes (the larger; 1 is full)."""
        x0, y0, x1, y1 = self.drawing_box
        mu = self.scale.per_mm
        w, h = self.extent[2] - self.extent[0], self.extent[3] - self.extent[1]
        return max(w / mu / (x1 - x0), h / mu / (y1 - y0))

    def to_page(self, x: float, y: float) -> tuple[float, float]:
        """The page point (mm, y down) of a model point (y up), the content centred in the drawing box."""
        x0, y0, x1, y1 = self.drawing_box
        mu = self.scale.per_mm
        cx, cy = (self.extent[0] + self.extent[2]) / 2, (self.extent[1] + self.extent[3]) / 2
        return ((x0 + x1) / 2 + (float(x) - cx) / mu, (y0 + y1) / 2 - (float(y) - cy) / mu)

    def to_page_array(self, xy: np.ndarray) -> np.ndarray:
        """:meth:`to_page` of an (n, 2) array of model points."""
        a = np.asarray(xy, dtype=float).reshape(-1, 2)
        x0, y0, x1, y1 = self.drawing_box
        mu = self.scale.per_mm
        cx, cy = (self.extent[0] + self.extent[2]) / 2, (self.extent[1] + self.extent[3]) / 2
        return np.column_stack(((x0 + x1) / 2 + (a[:, 0] - cx) / mu, (y0 + y1) / 2 - (a[:, 1] - cy) / mu))


__all__ = ["Panel", "extent_of"]
