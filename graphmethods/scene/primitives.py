"""The drawing primitives every element reduces to, in paper millimetres.

Page coordinates: x to the right, y **down**, origin at the top-left corner of the
page, as on a sheet of paper and in SVG. Backends draw exactly these five
primitives and nothing else: :class:`Path` (open or closed polyline),
:class:`Polygon` (filled), :class:`Circle`, :class:`Label` (text with runs) and
:class:`Group` (a named container).

>>> p = Path(((0.0, 0.0), (10.0, 0.0)), THIN)
>>> p.length_mm()
10.0
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from typing import Any

XY = tuple[float, float]

#: line widths in mm, as drawing standards grade them
WIDTH_THIN = 0.18      # construction, hatching, dimension and level lines
WIDTH_AXIS = 0.25      # axes, table grid
WIDTH_VECTOR = 0.35    # vectors
WIDTH_MAIN = 0.5       # the curves a figure is about


@dataclass(frozen=True)
class Style:
    """How a primitive is stroked and filled.

    Parameters
    ----------
    stroke : str or None
        Stroke colour (``None``: no outline).
    width_mm : float, mm
        Stroke width.
    dash : tuple of float or None, mm
        Dash pattern (on, off, ...), ``None`` for a solid line.
    fill : str or None
        Fill colour (``None``: not filled).
    """

    stroke: str | None = "#000000"
    width_mm: float = WIDTH_AXIS
    dash: tuple[float, ...] | None = None
    fill: str | None = None

    def with_(self, **changes: Any) -> Style:
        """A copy with some fields changed."""
        from dataclasses import replace

        return replace(self, **changes)


THIN = Style(width_mm=WIDTH_THIN)
AXIS = Style(width_mm=WIDTH_AXIS)
MAIN = Style(width_mm=WIDTH_MAIN)
VECTOR = Style(width_mm=WIDTH_VECTOR)
DASHED = Style(width_mm=WIDTH_THIN, dash=(2.0, 1.0))
DOTTED = Style(width_mm=WIDTH_THIN, dash=(0.5, 1.0))
SOLID_FILL = Style(stroke=None, width_mm=0.0, fill="#000000")


@dataclass(frozen=True)
class Path:
    """A polyline through ``points`` (closed back to the first when ``closed``)."""

    points: tuple[XY, ...]
    style: Style = THIN
    closed: bool = False

    def length_mm(self) -> float:
        """Drawn length in mm (including the closing segment)."""
        pts = list(self.points) + ([self.points[0]] if self.closed and self.points else [])
        return sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))


@dataclass(frozen=True)
class Polygon:
    """A closed polygon, filled with ``style.fill`` and outlined with ``style.stroke``."""

    points: tuple[XY, ...]
    style: Style = SOLID_FILL


@dataclass(frozen=True)
class Circle:
    """A circle of radius ``r`` mm centred at ``(cx, cy)``."""

    cx: float
    cy: float
    r: float
    style: Style = THIN


@dataclass(frozen=True)
class Label:
    """Text on one line, its baseline at ``y``; ``anchor`` is where ``x`` is: start, middle or end.

    ``runs`` are ``(text, shift)`` pairs (see :mod:`graphmethods.scene.markup`); the text
    is plain characters, never interpreted by a backend. ``stretch`` is the horizontal scale of the
    lettering (1: the font as it is; 0.8: condensed to 80 % of its width at the same height, as ГОСТ 2.304
    type A narrow lettering sets a heading in a narrow column); the text is condensed towards ``x``.
    """

    x: float
    y: float
    runs: tuple[tuple[str, int], ...]
    size_mm: float = 3.5
    anchor: str = "start"
    bold: bool = False
    color: str = "#000000"
    stretch: float = 1.0

    @property
    def text(self) -> str:
        """The characters of all runs."""
        return "".join(t for t, _ in self.runs)


@dataclass(frozen=True)
class Group:
    """A named container; ``name`` becomes the group's id in SVG output."""

    name: str
    children: tuple[Primitive, ...]


Primitive = Path | Polygon | Circle | Label | Group


def walk(prims: Iterable[Primitive]) -> Iterator[Primitive]:
    """Yield every primitive in ``prims`` depth-first, groups included, in drawing order.

    Parameters
    ----------
    prims : iterable of Primitive
        Primitives, some of them groups.

    Yields
    ------
    Primitive
        Each group before its children.

    Examples
    --------
    >>> [type(p).__name__ for p in walk([Group("g", (Circle(0.0, 0.0, 1.0),)), Circle(1.0, 1.0, 1.0)])]
    ['Group', 'Circle', 'Circle']
    """
    for p in prims:
        yield p
        if isinstance(p, Group):
            yield from walk(p.children)
