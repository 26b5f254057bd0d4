"""Labels placed against ink: candidates around the anchor, scored against what is drawn, first free taken.

:class:`Ink` is the registry of everything drawn on a sheet (the segments of paths and polygon outlines,
circles as polygons, filled marks such as arrowheads as boxes, texts as their boxes from the font's
advance widths, :func:`graphmethods.scene.elements.label_bbox`). :meth:`Ink.place` tries a label's
candidate places in a fixed order: the eight compass points around the anchor at two gaps, then
places along the anchor's line (when given) on either side, and takes the first whose box is free of
ink; when none is free, it moves out on a ring and draws a short leader back to the anchor
(Christensen, Marks and Shieber 1995, greedy). The tests are those of
:class:`graphmethods.sheets.layout.Occupancy`, ties settled by its ``TIE_MM`` quantum, so the outcome
is deterministic.

>>> ink = Ink()
>>> ink.add_line(((0.0, 10.0), (100.0, 10.0)))
>>> lab, leader = ink.place((50.0, 10.0), "b", size_mm=3.5)
>>> lab.y < 10.0, leader is None
(True, True)
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

from graphmethods.scene.elements import label_bbox, place_label
from graphmethods.scene.primitives import Circle, Label, Path, Polygon, Primitive, walk
from graphmethods.sheets.frame import FastOccupancy
from graphmethods.sheets.layout import Box

Point2 = tuple[float, float]
Leader = tuple[Point2, Point2]

#: the eight compass points, in the order they are tried (upper right first, as a draftsman writes)
COMPASS = ("ne", "nw", "se", "sw", "n", "s", "e", "w")
#: a filled polygon up to this area (mm²) is a mark (an arrowhead, a dot): kept clear as a box
MARK_AREA_MM2 = 40.0


def circle_points(cx: float, cy: float, r: float, n: int = 24) -> list[Point2]:
    """A circle as a closed polygon of ``n`` points (mm)."""
    return [(cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n)) for k in range(n + 1)]


def _area(points: Sequence[Point2]) -> float:
    return abs(sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(points, list(points[1:]) + [points[0]]))) / 2


class Ink(FastOccupancy):
    """What is drawn on a sheet, to place labels where nothing is (see the module docstring).

    >>> ink = Ink()
    >>> ink.add_primitives([Circle(20.0, 20.0, 5.0)])
    >>> ink.is_free((14.0, 19.0, 16.0, 21.0)), ink.is_free((40.0, 19.0, 42.0, 21.0))
    (False, True)
    """

    def add_primitives(self, prims: Iterable[Primitive]) -> None:
        """Register everything some primitives draw: paths, polygon outlines (small filled ones as boxes),
        circles, labels."""
        for p in walk(prims):
            if isinstance(p, Path):
                self.add_line(list(p.points) + ([p.points[0]] if p.closed else []))
            elif isinstance(p, Polygon):
                self.add_line(list(p.points) + [p.points[0]])
                if p.style.fill is not None and len(p.points) >= 3 and _area(p.points) <= MARK_AREA_MM2:
                    xs, ys = [q[0] for q in p.points], [q[1] for q in p.points]
                    self.add_box((min(xs), min(ys), max(xs), max(ys)))
            elif isinstance(p, Circle):
                self.add_line(circle_points(p.cx, p.cy, p.r))
            elif isinstance(p, Label):
                self.add_label(p)

    def along(self, p: Point2, q: Point2, text: str, *, size_mm: float, gap_mm: float = 1.0,
              within: Box | None = None) -> Label | None:
        """The first free place beside the segment p–q (its middle, then a third and two thirds along, the
        left side of p→q first), or None."""
        dx, dy = q[0] - p[0], q[1] - p[1]
        n = math.hypot(dx, dy)
        if n == 0:
            return None
        nx, ny = -dy / n, dx / n
        for t in (0.5, 1 / 3, 2 / 3, 0.25, 0.75):
            m = (p[0] + t * dx, p[1] + t * dy)
            for sgn in (1.0, -1.0):
                d = _direction(sgn * nx, sgn * ny)
                lab = place_label(m, text, d, gap_mm=gap_mm, size_mm=size_mm)
                if self.is_free(label_bbox(lab), within=within):
                    return lab
        return None

    def place(self, at: Point2, text: str, *, size_mm: float, directions: Sequence[str] = COMPASS,
              gap_mm: float = 1.2, line: tuple[Point2, Point2] | None = None, within: Box | None = None,
              leader: bool = True) -> tuple[Label, Leader | None]:
        """A label for the point ``at`` where no ink is, registered; with a leader when it had to move away.

        Parameters
        ----------
        at : (x, y), mm
            The anchor (a joint, a vector's tip, a line's middle).
        text : str
            Markup.
        size_mm : float, mm
            Font size (from :func:`~graphmethods.sheets.engine.lettering.lettering`).
        directions : sequence of str
            The compass points tried first, in order.
        line : ((x, y), (x, y)), optional
            The line the label names: places along it are tried after the compass points.
        within : box, optional
            The label must stay inside it (its panel).
        leader : bool
            When no near place is free, move out on a ring with a leader (else take the first direction).

        Returns
        -------
        (Label, leader or None)
            The leader is ``((x0, y0), (x1, y1))`` from the label to the anchor; draw it thin.
        """
        lab = self.first_free(at, text, directions, (gap_mm, gap_mm + 2.0), size_mm, within)
        if lab is None and line is not None:
            lab = self.along(line[0], line[1], text, size_mm=size_mm, within=within)
        if lab is not None:
            self.add_label(lab)
            return lab, None
        if leader:
            return self.place_label_with_leader(at, text, directions, size_mm=size_mm, gap_mm=gap_mm, within=within)
        lab = place_label(at, text, directions[0], gap_mm=gap_mm, size_mm=size_mm)
        self.add_label(lab)
        return lab, None


def _direction(nx: float, ny: float) -> str:
    """The compass point (page y down) nearest the direction (nx, ny)."""
    ang = math.degrees(math.atan2(-ny, nx)) % 360
    names = ("e", "ne", "n", "nw", "w", "sw", "s", "se")
    return names[int((ang + 22.5) // 45) % 8]


__all__ = ["COMPASS", "Ink", "circle_points"]
