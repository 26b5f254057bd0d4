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

# The primitives are frozen dataclasses (compared, hashed and printed by their fields) whose ``__init__`` is
# written out: a figure makes hundreds of thousands of them (the gallery about 200 000), and the generated
# frozen ``__init__`` sets each field through ``object.__setattr__`` (3-4 µs a Label against about 1 µs filling
# the instance's dict at once). ``tests/test_primitives_init.py`` holds each written ``__init__`` to its fields.

#: line widths in mm, as drawing standards grade them
WIDTH_THIN = 0.18      # construction, hatching, dimension and level lines
WIDTH_AXIS = 0.25      # axes, table grid
WIDTH_VECTOR = 0.35    # vectors
WIDTH_MAIN = 0.5       # the curves a figure is about


@dataclass(frozen=True, init=False)
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

    def __init__(self, stroke: str | None = "#000000", width_mm: float = WIDTH_AXIS,
                 dash: tuple[float, ...] | None = None, fill: str | None = None) -> None:
        self.__dict__.update(stroke=stroke, width_mm=width_mm, dash=dash, fill=fill)

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


@dataclass(frozen=True, init=False)
class Path:
    """A polyline through ``points`` (closed back to the first when ``closed``)."""

    points: tuple[XY, ...]
    style: Style = THIN
    closed: bool = False

    def __init__(self, points: tuple[XY, ...], style: Style = THIN, closed: bool = False) -> None:
        self.__dict__.update(points=points, style=style, closed=closed)

    def length_mm(self) -> float:
        """Drawn length in mm (including the closing segment)."""
        pts = list(self.points) + ([self.points[0]] if self.closed and self.points else [])
        return sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))


@dataclass(frozen=True, init=False)
class Polygon:
    """A closed polygon, filled with ``style.fill`` and outlined with ``style.stroke``."""

    points: tuple[XY, ...]
    style: Style = SOLID_FILL

    def __init__(self, points: tuple[XY, ...], style: Style = SOLID_FILL) -> None:
        self.__dict__.update(points=points, style=style)


@dataclass(frozen=True, init=False)
class Circle:
    """A circle of radius ``r`` mm centred at ``(cx, cy)``."""

    cx: float
    cy: float
    r: float
    style: Style = THIN

    def __init__(self, cx: float, cy: float, r: float, style: Style = THIN) -> None:
        self.__dict__.update(cx=cx, cy=cy, r=r, style=style)


@dataclass(frozen=True, init=False)
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

    def __init__(self, x: float, y: float, runs: tuple[tuple[str, int], ...], size_mm: float = 3.5,
                 anchor: str = "start", bold: bool = False, color: str = "#000000", stretch: float = 1.0) -> None:
        self.__dict__.update(x=x, y=y, runs=runs, size_mm=size_mm, anchor=anchor, bold=bold, color=color,
                             stretch=stretch)

    @property
    def text(self) -> str:
        """The characters of all runs."""
        return "".join(t for t, _ in self.runs)


@dataclass(frozen=True, init=False)
class Group:
    """A named container; ``name`` becomes the group's id in SVG output."""

    name: str
    children: tuple[Primitive, ...]

    def __init__(self, name: str, children: tuple[Primitive, ...]) -> None:
        self.__dict__.update(name=name, children=children)


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
