"""A uniform grid over the page: which registered segments and boxes may touch a box, without looking at all.

Label placement asks, thousands of times a figure, whether a candidate box is clear of everything drawn.
:class:`InkIndex` answers the question "which items could touch this box?" with a superset: every
segment is filed under the grid cells its path crosses (fattened by :data:`MARGIN_MM`, far above any
rounding), every box under the cells it covers. The decision itself stays with the exact tests of
:mod:`graphmethods.sheets.layout` (the bounding-box prefilter and the Liang–Barsky clipping), applied to the
candidates only, so the answers are those of testing every item, to the bit.

>>> idx = InkIndex()
>>> idx.add_segment(0, 0.0, 10.0, 100.0, 10.0)      # a long horizontal line
>>> idx.add_segment(1, 50.0, 50.0, 52.0, 52.0)      # a short stroke far below it
>>> sorted(idx.segments_near((40.0, 8.0, 60.0, 12.0)))
[0]
>>> idx.add_box(0, (45.0, 48.0, 55.0, 51.0))
>>> sorted(idx.boxes_near((40.0, 8.0, 60.0, 12.0))), sorted(idx.boxes_near((50.0, 50.0, 51.0, 51.0)))
([], [0])
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

#: the grid's cell (mm): about a label's size, so a candidate box looks at one to four cells
CELL_MM = 8.0
#: how far (mm) beyond its path an item is filed: far above the rounding of page coordinates (1e-13 mm),
#: far above the prefilter's slack (1e-6 mm), so no item that can touch a box is missed
MARGIN_MM = 1e-3
#: an item covering more cells than this (a panel kept clear, a title band, a line across the sheet) is
#: kept in a list tested always; a query covering more looks at everything
_BIG_CELLS = 512


class InkIndex:
    """Segments and boxes by grid cell (items are numbered by the caller; see the module docstring)."""

    def __init__(self, cell_mm: float = CELL_MM) -> None:
        self.cell = cell_mm
        self._seg_cells: dict[tuple[int, int], list[int]] = {}
        self._box_cells: dict[tuple[int, int], list[int]] = {}
        self._seg_always: list[int] = []
        self._box_always: list[int] = []
        self._seg_all: list[int] = []
        self._box_all: list[int] = []

    def _span(self, lo: float, hi: float) -> range:
        c = self.cell
        return range(math.floor((lo - MARGIN_MM) / c), math.floor((hi + MARGIN_MM) / c) + 1)

    def add_segment(self, k: int, x0: float, y0: float, x1: float, y1: float) -> None:
        """File segment number ``k`` (page mm) under the cells its path crosses, row by row."""
        self._seg_all.append(k)
        cells, c, m, floor = self._seg_cells, self.cell, MARGIN_MM, math.floor
        xl, xh = (x0, x1) if x0 <= x1 else (x1, x0)
        yl, yh = (y0, y1) if y0 <= y1 else (y1, y0)
        if not (math.isfinite(xh - xl) and math.isfinite(yh - yl)) or (xh - xl + yh - yl) > _BIG_CELLS * c:
            self._seg_always.append(k)
            return
        r0, r1 = floor((yl - m) / c), floor((yh + m) / c)
        q0, q1 = floor((xl - m) / c), floor((xh + m) / c)
        if r0 == r1 or q0 == q1 or y0 == y1:        # within one row or one column: its box's cells
            for r in range(r0, r1 + 1):
                for q in range(q0, q1 + 1):
                    cells.setdefault((q, r), []).append(k)
            return
        dx, dy = x1 - x0, y1 - y0
        for r in range(r0, r1 + 1):             # the part of the segment within each row's band (fattened)
            ta, tb = (r * c - m - y0) / dy, ((r + 1) * c + m - y0) / dy
            ta, tb = max(min(ta, tb), 0.0), min(max(ta, tb), 1.0)
            xa, xb = x0 + ta * dx, x0 + tb * dx
            if xa > xb:
                xa, xb = xb, xa
            for q in range(floor((xa - m) / c), floor((xb + m) / c) + 1):
                cells.setdefault((q, r), []).append(k)

    def add_segments(self, first: int, seg: np.ndarray) -> None:
        """File segments ``first``, ``first`` + 1, … (the rows ``x0, y0, x1, y1`` of ``seg``, page mm) as
        :meth:`add_segment` does one by one: the many that lie within one cell are filed together (the same
        cell by the same arithmetic), the others one by one.

        >>> idx = InkIndex()
        >>> idx.add_segments(0, np.array([[0.0, 10.0, 100.0, 10.0], [50.0, 50.0, 52.0, 52.0]]))
        >>> sorted(idx.segments_near((40.0, 8.0, 60.0, 12.0))), sorted(idx.segments_near((50.0, 50.0, 51.0, 51.0)))
        ([0], [1])
        """
        seg = np.asarray(seg, dtype=float).reshape(-1, 4)
        if len(seg) < 16:                       # a few: one by one is quicker than numpy's set-up
            for k, (x0, y0, x1, y1) in enumerate(seg.tolist(), first):
                self.add_segment(k, x0, y0, x1, y1)
            return
        c, m = self.cell, MARGIN_MM
        with np.errstate(invalid="ignore", over="ignore"):
            xl, xh = np.minimum(seg[:, 0], seg[:, 2]), np.maximum(seg[:, 0], seg[:, 2])
            yl, yh = np.minimum(seg[:, 1], seg[:, 3]), np.maximum(seg[:, 1], seg[:, 3])
            q0, q1 = np.floor((xl - m) / c), np.floor((xh + m) / c)
            r0, r1 = np.floor((yl - m) / c), np.floor((yh + m) / c)
            one = (q0 == q1) & (r0 == r1) & np.isfinite(q0) & np.isfinite(r0)
        # one cell: its box's cell, as add_segment files it (NaN corners never compare equal: one by one)
        ks = np.flatnonzero(one)
        self._seg_all.extend((ks + first).tolist())
        if ks.size:
            q, r = q0[ks].astype(np.int64), r0[ks].astype(np.int64)
            order = np.lexsort((ks, r, q))
            q, r, kk = q[order], r[order], ks[order] + first
            cut = np.flatnonzero((np.diff(q) != 0) | (np.diff(r) != 0)) + 1
            cells = self._seg_cells
            starts = [0, *cut.tolist()]
            for i, j, qq, rr in zip(starts, [*starts[1:], len(kk)], q[starts].tolist(), r[starts].tolist()):
                cells.setdefault((qq, rr), []).extend(kk[i:j].tolist())
        rest = np.flatnonzero(~one)
        for k, (x0, y0, x1, y1) in zip((rest + first).tolist(), seg[rest].tolist()):
            self.add_segment(k, x0, y0, x1, y1)

    def add_box(self, k: int, box: tuple[float, float, float, float]) -> None:
        """File box number ``k`` (page mm) under the cells it covers."""
        self._box_all.append(k)
        if not (math.isfinite(box[2] - box[0]) and math.isfinite(box[3] - box[1])) or \
                (box[2] - box[0]) * (box[3] - box[1]) > _BIG_CELLS * self.cell ** 2:
            self._box_always.append(k)
            return
        cols, rows = self._span(box[0], box[2]), self._span(box[1], box[3])
        if len(cols) * len(rows) > _BIG_CELLS:
            self._box_always.append(k)
            return
        cells = self._box_cells
        for r in rows:
            for q in cols:
                cells.setdefault((q, r), []).append(k)

    def _near(self, cells: dict[tuple[int, int], list[int]], always: list[int], every: list[int], box) -> set[int]:
        c, m, floor = self.cell, MARGIN_MM, math.floor
        x0, x1 = (box[0], box[2]) if box[0] <= box[2] else (box[2], box[0])     # an inverted box as its extent
        y0, y1 = (box[1], box[3]) if box[1] <= box[3] else (box[3], box[1])
        w, h = x1 - x0, y1 - y0
        if not (math.isfinite(w) and math.isfinite(h)) or (w + c) * (h + c) > _BIG_CELLS * c * c:
            return set(every)
        out = set(always)
        cols = range(floor((x0 - m) / c), floor((x1 + m) / c) + 1)
        for r in range(floor((y0 - m) / c), floor((y1 + m) / c) + 1):
            for q in cols:
                found = cells.get((q, r))
                if found:
                    out.update(found)
        return out

    def segments_near(self, box) -> set[int]:
        """The numbers of the segments that may touch ``box`` (a superset of those that do)."""
        return self._near(self._seg_cells, self._seg_always, self._seg_all, box)

    def boxes_near(self, box) -> set[int]:
        """The numbers of the boxes that may touch or overlap ``box`` (a superset of those that do)."""
        return self._near(self._box_cells, self._box_always, self._box_all, box)


def union_box(boxes: Iterable[tuple[float, float, float, float]]) -> tuple[float, float, float, float]:
    """The smallest box holding every one of ``boxes`` (at least one).

    >>> union_box([(0.0, 1.0, 2.0, 3.0), (-1.0, 2.0, 1.0, 5.0)])
    (-1.0, 1.0, 2.0, 5.0)
    """
    it = iter(boxes)
    x0, y0, x1, y1 = next(it)
    for b in it:
        x0, y0 = (b[0] if b[0] < x0 else x0), (b[1] if b[1] < y0 else y0)
        x1, y1 = (b[2] if b[2] > x1 else x1), (b[3] if b[3] > y1 else y1)
    return (x0, y0, x1, y1)
