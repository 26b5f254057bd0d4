"""Layout helpers shared by the sheets: the standard page, label placement without overlaps.

A sheet places its labels through an :class:`Occupancy`: it knows the lines and
labels already drawn and puts each new label in the first free spot among the
candidates given (beside a point, inside a region), so labels never cover curves or
one another.

>>> occ = Occupancy()
>>> occ.add_line(((0, 10), (100, 10)))
>>> lab = occ.place_label((50, 10), "b", ("n", "s"))
>>> lab.y < 10                                   # above the line, not on it
True
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import TypeVar

import numpy as np

from graphmethods.errors import InputError
from graphmethods.problems.reference_cases import title_of
from graphmethods.scene import Page, Scale, Scene, TitleBlock, markup, notation as get_notation
from graphmethods.scene.elements import Axis, Element, label_bbox, make_label, place_label
from graphmethods.scene.notation import NOTATIONS
from graphmethods.scene.numbers import format_value
from graphmethods.scene.primitives import Label, Path, Polygon, walk
from graphmethods.scene.scale import pick_angle_scale, pick_scale
from graphmethods.scene.title_blocks import form_for
from graphmethods.sheets.ink_index import InkIndex, union_box
from graphmethods.titles import text_in

Box = tuple[float, float, float, float]


def _boxes_overlap(a: Box, b: Box, pad: float = 0.0) -> bool:
    return a[0] < b[2] + pad and b[0] < a[2] + pad and a[1] < b[3] + pad and b[1] < a[3] + pad


def _segment_hits_box(p, q, box: Box) -> bool:
    """Does the segment p–q pass through the box? (Liang–Barsky clipping)"""
    x0, y0, x1, y1 = box
    dx, dy = q[0] - p[0], q[1] - p[1]
    t0, t1 = 0.0, 1.0
    for pk, qk in ((-dx, p[0] - x0), (dx, x1 - p[0]), (-dy, p[1] - y0), (dy, y1 - p[1])):
        if pk == 0:
            if qk < 0:
                return False
        else:
            t = qk / pk
            if pk < 0:
                t0 = max(t0, t)
            else:
                t1 = min(t1, t)
            if t0 > t1:
                return False
    return True


def _segments_cross(p, q, a, b) -> bool:
    """Do the segments p–q and a–b cross properly (touching ends do not count)?"""
    def orient(u, v, w):
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])

    d1, d2 = orient(a, b, p), orient(a, b, q)
    d3, d4 = orient(p, q, a), orient(p, q, b)
    return d1 * d2 < 0 and d3 * d4 < 0


#: the quantum (mm) that settles geometric ties. Ties are common on a drawing (a line's label placed at the
#: line's end with a gap equal to the padding touches the line exactly); compared exactly, their outcome
#: hangs on the last bit of the arithmetic, which differs between numpy versions. So each test decides as
#: exact touching always did, for any touch closer than this: a line within it of a label's padded box
#: crosses it (as the clipping test counts touching), a box within it of another's edge is clear of it, a
#: box within it outside its region's edge is inside. A decision can still turn on the last bit only where a
#: margin falls within a last bit of 1e-9 mm, where nothing on a drawing clusters.
TIE_MM = 1e-9
#: slack (mm) of the bounding-box prefilter: a segment whose extent misses a box by more than this
#: cannot touch it; the decision itself is the exact clipping arithmetic of :func:`_segment_hits_box`
_NEAR_MM = 1e-6
#: up to this many segments near a box are tested one by one (same decisions, less overhead)
_FEW = 48
#: above this many (box, near segment) pairs :meth:`Occupancy.free` compares the extents over numpy arrays
#: (timed: a plain loop is quicker below about a thousand; 85 % of the gallery's pairs are in calls above)
_MANY_PAIRS = 1024
#: above this many segments filed near a box :meth:`Occupancy._near` compares their extents over numpy arrays
_MANY_NEAR = 96


def segments_hit_boxes(seg: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """Which segments pass through which boxes: Liang–Barsky clipping over numpy arrays.

    The same arithmetic as :func:`_segment_hits_box` (the same divisions, the same
    comparisons), so the answers are the same bit for bit, for every pair at once.

    Parameters
    ----------
    seg : ndarray, shape (n, 4), mm
        Segments as rows ``x0, y0, x1, y1``.
    boxes : ndarray, shape (k, 4), mm
        Boxes as rows ``x0, y0, x1, y1`` (page coordinates, y down).

    Returns
    -------
    ndarray of bool, shape (k, n)
        ``[i, j]`` is true when segment j passes through (or touches) box i.

    Examples
    --------
    >>> seg = np.array([[0.0, 10.0, 100.0, 10.0], [0.0, 0.0, 0.0, 5.0]])
    >>> segments_hit_boxes(seg, np.array([[40.0, 8.0, 60.0, 12.0], [40.0, 12.0, 60.0, 14.0]])).tolist()
    [[True, False], [False, False]]
    """
    seg = np.asarray(seg, dtype=float).reshape(-1, 4)
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    k, n = len(boxes), len(seg)
    return pairs_hit(np.tile(seg, (k, 1)), np.repeat(boxes, n, axis=0)).reshape(k, n)


def pairs_hit(seg: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """:func:`segments_hit_boxes` of aligned pairs: does segment ``seg[i]`` pass through box ``boxes[i]``?

    The same arithmetic pair by pair (the same divisions, the same comparisons), on 1-d arrays: the
    pairs worth testing only, not every segment against every box.

    >>> seg = np.array([[0.0, 10.0, 100.0, 10.0]] * 2)
    >>> pairs_hit(seg, np.array([[40.0, 8.0, 60.0, 12.0], [40.0, 12.0, 60.0, 14.0]])).tolist()
    [True, False]
    """
    px, py = seg[:, 0], seg[:, 1]
    dx, dy = seg[:, 2] - seg[:, 0], seg[:, 3] - seg[:, 1]
    x0, y0, x1, y1 = boxes[:, 0], boxes[:, 1], boxes[:, 2], boxes[:, 3]
    t0, t1 = np.zeros(len(seg)), np.ones(len(seg))
    hit = np.ones(len(seg), dtype=bool)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for pk, qk in ((-dx, px - x0), (dx, x1 - px), (-dy, py - y0), (dy, y1 - py)):
            zero = pk == 0
            hit &= ~(zero & (qk < 0))
            t = qk / np.where(zero, 1.0, pk)
            t0 = np.where(pk < 0, np.maximum(t0, t), t0)
            t1 = np.where(pk > 0, np.minimum(t1, t), t1)
    return hit & (t0 <= t1)


def _leader_candidate(at, text: str, r: float, ang: float, size_mm: float
                      ) -> tuple[Label, tuple[float, float], tuple[float, float]]:
    """A label ``r`` mm from ``at`` at ``ang`` degrees and its leader's start and end (not yet tested)."""
    x, y = at
    a = math.radians(ang)
    c, s = math.cos(a), math.sin(a)
    end = (x + r * c, y - r * s)
    d = "e" if c > 0.3 else "w" if c < -0.3 else ("n" if s > 0 else "s")
    return place_label(end, text, d, gap_mm=0.8, size_mm=size_mm), (x + 1.5 * c, y - 1.5 * s), end


class Occupancy:
    """What is drawn already (line segments and boxes), to place labels where nothing is.

    The free-space tests look only at the items a grid index (:class:`~graphmethods.sheets.ink_index.
    InkIndex`) files near a box, with a bounding-box prefilter; the decisions are those of the plain
    clipping test :func:`_segment_hits_box` over every registered segment, to the bit.
    """

    def __init__(self, *, pad_mm: float = 0.6):
        self.pad = pad_mm
        self.segments: list[tuple] = []
        self._flat: list[float] | None = []      # the segments' numbers in order (x0, y0, x1, y1, ...), kept by
        #                                          add_line for segment_array (None once the list is edited by hand)
        self.boxes: list[Box] = []
        self._seg = np.empty((0, 4))
        self._box = np.empty((0, 4))
        self._index = InkIndex()
        self._seg_ext: list[tuple[float, float, float, float]] = []     # x_lo, y_lo, x_hi, y_hi of each segment
        self._ext = np.empty((0, 4))            # the same as an array (filled when first compared in bulk)
        self._boxes_indexed = 0

    def add_line(self, points) -> None:
        flat = self._flat
        if isinstance(points, (list, tuple, np.ndarray)) and len(points) > 8:   # many: as float() of each, at once
            try:
                a = np.asarray(points, dtype=float).reshape(len(points), 2)
            except ValueError:
                a = None
            if a is not None:
                pts = list(map(tuple, a.tolist()))
                self.segments.extend(zip(pts, pts[1:]))
                if flat is not None:
                    flat.extend(np.concatenate((a[:-1], a[1:]), axis=1).ravel().tolist())
                return
        pts = [tuple(map(float, p)) for p in points]
        self.segments.extend(zip(pts, pts[1:]))
        if flat is not None:
            for p, q in zip(pts, pts[1:]):
                flat += (p[0], p[1], q[0], q[1])

    def add_box(self, box: Box) -> None:
        x0, y0, x1, y1 = map(float, box)
        self.boxes.append((x0, y0, x1, y1))

    def add_label(self, label: Label) -> None:
        self.add_box(label_bbox(label))

    def register(self, *elements: Element) -> None:
        """Register everything some elements draw, so labels placed later keep off it."""
        for e in elements:
            self.add_primitives(e.primitives())

    def add_primitives(self, prims) -> None:
        """Register everything some primitives draw (paths, polygons, labels)."""
        for p in walk(prims):
            if isinstance(p, Path):
                self.add_line(list(p.points) + ([p.points[0]] if p.closed else []))
            elif isinstance(p, Polygon):
                self.add_line(list(p.points) + [p.points[0]])
            elif isinstance(p, Label):
                self.add_label(p)

    def segment_array(self) -> np.ndarray:
        """The registered segments as an (n, 4) array of ``x0, y0, x1, y1`` (mm), kept up to date."""
        n, have, flat = len(self.segments), len(self._seg), self._flat
        if have != n:
            if flat is not None and len(flat) == 4 * n and have < n:
                new = np.array(flat[4 * have:]).reshape(-1, 4)
            else:                               # the list edited by hand: read from it (and from now on)
                self._flat = None
                new = np.asarray(self.segments[have:], dtype=float).reshape(-1, 4)
            self._seg = np.vstack((self._seg, new))
        return self._seg

    def box_array(self) -> np.ndarray:
        """The registered boxes as an (n, 4) array (mm), kept up to date."""
        if len(self._box) != len(self.boxes):
            new = np.asarray(self.boxes[len(self._box):], dtype=float).reshape(-1, 4)
            self._box = np.vstack((self._box, new))
        return self._box

    def _indexed(self) -> InkIndex:
        """The grid index, with every segment and box registered so far filed in it."""
        idx, ext = self._index, self._seg_ext
        if len(ext) == len(self.segments) and self._boxes_indexed == len(self.boxes):
            return idx
        if len(ext) > len(self.segments) or self._boxes_indexed > len(self.boxes):     # the lists were cut: anew
            self._index, self._boxes_indexed, self._seg = InkIndex(), 0, np.empty((0, 4))
            self._box, self._seg_ext, self._ext = np.empty((0, 4)), [], np.empty((0, 4))
            return self._indexed()
        first = len(ext)
        if first < len(self.segments):
            new = self.segment_array()[first:]
            x0, y0, x1, y1 = new.T
            # as min() and max() of two floats (NaN aside, which no free test reaches: the index files it always)
            lo_x, hi_x = np.where(x1 < x0, x1, x0), np.where(x1 > x0, x1, x0)
            lo_y, hi_y = np.where(y1 < y0, y1, y0), np.where(y1 > y0, y1, y0)
            ext.extend(map(tuple, np.column_stack((lo_x, lo_y, hi_x, hi_y)).tolist()))
            idx.add_segments(first, new)
        for k in range(self._boxes_indexed, len(self.boxes)):
            idx.add_box(k, self.boxes[k])
        self._boxes_indexed = len(self.boxes)
        return idx

    def _box_taken(self, g: Box, idx: InkIndex) -> bool:
        """Does a registered box overlap ``g`` (already grown by the padding less the tie quantum)?"""
        boxes = self.boxes
        for k in idx.boxes_near(g):
            b = boxes[k]
            if g[0] < b[2] and b[0] < g[2] and g[1] < b[3] and b[1] < g[3]:
                return True
        return False

    def _near(self, g: Box, idx: InkIndex) -> list[int]:
        """The segments whose extents come within ``_NEAR_MM`` of the box ``g``, in registration order."""
        e, ext = _NEAR_MM, self._seg_ext
        x0, y0, x1, y1 = g[0] - e, g[1] - e, g[2] + e, g[3] + e
        found = idx.segments_near(g)
        if len(found) > _MANY_NEAR:             # many: the same comparisons over the extents' array
            ks = np.fromiter(found, dtype=np.intp, count=len(found))
            ks.sort()
            lo_x, lo_y, hi_x, hi_y = self._ext_array()[ks].T
            near: list[int] = ks[(lo_x <= x1) & (hi_x >= x0) & (lo_y <= y1) & (hi_y >= y0)].tolist()
            return near
        out = []
        for k in found:
            lo_x, lo_y, hi_x, hi_y = ext[k]
            if lo_x <= x1 and hi_x >= x0 and lo_y <= y1 and hi_y >= y0:
                out.append(k)
        out.sort()
        return out

    def _ext_array(self) -> np.ndarray:
        """The segments' extents (``_seg_ext``) as an (n, 4) array, kept up to date."""
        if len(self._ext) != len(self._seg_ext):
            self._ext = np.vstack((self._ext, np.asarray(self._seg_ext[len(self._ext):], dtype=float).reshape(-1, 4)))
        return self._ext

    def _grown(self, box: Box, tie: float) -> Box:
        """The box grown by the padding and ``tie`` (±:data:`TIE_MM`)."""
        d = self.pad + tie
        return (box[0] - d, box[1] - d, box[2] + d, box[3] + d)

    def is_free(self, box: Box, *, within: Box | None = None, lines: bool = True) -> bool:
        """Nothing registered within the padding of ``box`` (boxes, and line segments unless ``lines=False``)."""
        if within is not None and not (box[0] >= within[0] - TIE_MM and box[1] >= within[1] - TIE_MM
                                       and box[2] <= within[2] + TIE_MM and box[3] <= within[3] + TIE_MM):
            return False
        index = self._indexed()
        if self._box_taken(self._grown(box, -TIE_MM), index):      # boxes: a touch within the tie quantum is clear
            return False
        if not lines:
            return True
        g = self._grown(box, TIE_MM)           # lines: a touch within it crosses
        idx = self._near(g, index)
        if len(idx) <= _FEW:           # a few near segments: the scalar test is quicker than numpy's set-up
            segs = self.segments
            return not any(_segment_hits_box(segs[i][0], segs[i][1], g) for i in idx)
        return not bool(segments_hit_boxes(self.segment_array()[idx], np.asarray(g)).any())

    def free(self, boxes, *, within: Box | None = None, lines: bool = True) -> np.ndarray:
        """:meth:`is_free` of many candidate boxes at once (a bool per box, the same decisions).

        The segments near each box are tested one by one when they are few, else in one clipping pass
        over numpy arrays, so a label's candidates, all directions at one gap, cost one call.

        >>> occ = Occupancy()
        >>> occ.add_line(((0, 10), (100, 10)))
        >>> occ.free([(40, 9, 60, 11), (40, 20, 60, 22)]).tolist()
        [False, True]
        """
        rows = np.asarray(boxes, dtype=float).reshape(-1, 4).tolist()
        ok = [True] * len(rows)
        if within is not None:
            w0, w1, w2, w3 = within[0] - TIE_MM, within[1] - TIE_MM, within[2] + TIE_MM, within[3] + TIE_MM
            ok = [b[0] >= w0 and b[1] >= w1 and b[2] <= w2 and b[3] <= w3 for b in rows]
        live = [a for a in range(len(rows)) if ok[a]]
        if not live:
            return np.array(ok, dtype=bool)
        index = self._indexed()
        d = self.pad + -TIE_MM                     # as _grown(box, -TIE_MM) (x − d is x + (−d) to the bit)
        grown = {a: (rows[a][0] + -d, rows[a][1] + -d, rows[a][2] + d, rows[a][3] + d) for a in live}
        taken = [self.boxes[k] for k in index.boxes_near(union_box(grown.values()))]
        if taken:
            for a, g in grown.items():
                if any(g[0] < b[2] and b[0] < g[2] and g[1] < b[3] and b[1] < g[3] for b in taken):
                    ok[a] = False
            live = [a for a in live if ok[a]]
        if not lines or not live or not self.segments:
            return np.array(ok, dtype=bool)
        d = self.pad + TIE_MM                      # as _grown(box, TIE_MM)
        grown = {a: (rows[a][0] + -d, rows[a][1] + -d, rows[a][2] + d, rows[a][3] + d) for a in live}
        e, ext = _NEAR_MM, self._seg_ext
        near = self._near(union_box(grown.values()), index)
        if len(near) * len(grown) > _MANY_PAIRS:
            return self._free_of_many(ok, grown, near)
        pairs: list[tuple[int, int]] = []
        near_ext = [(k, ext[k]) for k in near]
        for a, g in grown.items():              # each box against the segments near it (as _near)
            x0, y0, x1, y1 = g[0] - e, g[1] - e, g[2] + e, g[3] + e
            pairs.extend((a, k) for k, (lo_x, lo_y, hi_x, hi_y) in near_ext
                         if lo_x <= x1 and hi_x >= x0 and lo_y <= y1 and hi_y >= y0)
        if len(pairs) <= _FEW:         # a few pairs: the scalar test is quicker than numpy's set-up
            segs = self.segments
            for a, k in pairs:
                if ok[a] and _segment_hits_box(segs[k][0], segs[k][1], grown[a]):
                    ok[a] = False
        else:
            i = np.array([a for a, _ in pairs])
            hit = pairs_hit(self.segment_array()[[k for _, k in pairs]], np.array([grown[a] for a, _ in pairs]))
            for a in np.unique(i[hit]).tolist():
                ok[a] = False
        return np.array(ok, dtype=bool)

    def _free_of_many(self, ok: list[bool], grown: dict[int, Box], near: list[int]) -> np.ndarray:
        """The line test of :meth:`free` for many boxes against many near segments, over numpy arrays: the
        same prefilter (:meth:`_near`'s comparisons) and clipping, pair by pair, as the loop it replaces."""
        e = _NEAR_MM
        k = np.asarray(near)
        lo_x, lo_y, hi_x, hi_y = self._ext_array()[k].T
        gb = np.asarray(list(grown.values()))
        gx0, gy0 = (gb[:, 0] - e)[:, None], (gb[:, 1] - e)[:, None]
        gx1, gy1 = (gb[:, 2] + e)[:, None], (gb[:, 3] + e)[:, None]
        rows, cols = np.nonzero((lo_x <= gx1) & (hi_x >= gx0) & (lo_y <= gy1) & (hi_y >= gy0))
        a, k = np.asarray(list(grown))[rows], k[cols]
        if len(a) <= _FEW:
            segs = self.segments
            for i, j in zip(a.tolist(), k.tolist()):
                if ok[i] and _segment_hits_box(segs[j][0], segs[j][1], grown[i]):
                    ok[i] = False
        else:
            for i in np.unique(a[pairs_hit(self.segment_array()[k], gb[rows])]).tolist():
                ok[i] = False
        return np.array(ok, dtype=bool)

    def crossings(self, boxes) -> np.ndarray:
        """How many registered segments pass through each box grown by the padding (an int per box)."""
        rows = np.asarray(boxes, dtype=float).reshape(-1, 4).tolist()
        if not self.segments or not rows:
            return np.zeros(len(rows), dtype=int)
        d = self.pad + TIE_MM                      # a touch crosses
        grown = [(b[0] + -d, b[1] + -d, b[2] + d, b[3] + d) for b in rows]
        segs, index = self.segments, self._indexed()
        return np.array([sum(_segment_hits_box(segs[k][0], segs[k][1], g) for k in self._near(g, index))
                         for g in grown], dtype=int)

    def first_free(self, at, text, directions, gaps, size_mm, within) -> Label | None:
        """The first label beside ``at`` (directions × gaps) whose box is free; None when none is.

        The first direction alone, then the others of a gap in one :meth:`free` call (the same decisions
        as :meth:`is_free` one by one, in the same order).
        """
        directions = tuple(directions)
        if not directions:
            return None
        for k, gap in enumerate(gaps):
            if k == 0:
                lab = place_label(at, text, directions[0], gap_mm=gap, size_mm=size_mm)
                if self.is_free(label_bbox(lab), within=within):
                    return lab
            rest = directions[1:] if k == 0 else directions
            if not rest:
                continue
            labels = [place_label(at, text, d, gap_mm=gap, size_mm=size_mm) for d in rest]
            hit = np.flatnonzero(self.free([label_bbox(lab) for lab in labels], within=within))
            if len(hit):
                return labels[int(hit[0])]
        return None

    def place_label(self, at, text: str, directions=("ne", "nw", "se", "sw", "n", "s", "e", "w"), *,
                    size_mm: float = 3.5, gap_mm: float = 1.2, within: Box | None = None,
                    register: bool = True) -> Label:
        """A label beside ``at`` in the first free direction (the first one when none is free)."""
        lab = self.first_free(at, text, directions, (gap_mm, gap_mm + 2.0, gap_mm + 4.5), size_mm, within)
        if lab is None:
            lab = place_label(at, text, directions[0], gap_mm=gap_mm, size_mm=size_mm)
        if register:
            self.add_label(lab)
        return lab

    def place_label_with_leader(self, at, text: str, directions=("ne", "nw", "se", "sw", "n", "s", "e", "w"), *,
                                size_mm: float = 3.5, gap_mm: float = 1.2, within: Box | None = None
                                ) -> tuple[Label, tuple[tuple[float, float], tuple[float, float]] | None]:
        """A label beside ``at``; when nothing beside it is free, further away with a leader line.

        Returns the label and the leader ``((x0, y0), (x1, y1))`` from the label to ``at`` (or None).
        """
        lab = self.first_free(at, text, directions, (gap_mm, gap_mm + 2.0), size_mm, within)
        if lab is not None:
            self.add_label(lab)
            return lab, None
        x, y = at
        upward = directions[0][:1] != "s"              # try the side the caller asked for first
        up = (45, 135, 20, 160, 65, 115, 90, 0, 180)
        down = (315, 225, 340, 200, 295, 245, 270)
        for side in ((up, down) if upward else (down, up)):
            for r in (8.0, 12.0, 16.0, 21.0, 28.0, 36.0, 48.0):
                found = self.try_leaders(at, text, r, side, size_mm=size_mm, within=within)
                if found is not None:
                    return found
        lab = place_label(at, text, directions[0], gap_mm=gap_mm, size_mm=size_mm)
        self.add_label(lab)
        return lab, None

    def try_leader(self, at, text: str, r: float, ang: float, *, size_mm: float, within: Box | None = None,
                   strict: bool = True) -> tuple[Label, tuple[tuple[float, float], tuple[float, float]]] | None:
        """The label ``r`` mm from ``at`` at ``ang`` degrees, with its leader, registered, when it is free
        (and, ``strict``, its leader crosses no label); else None."""
        lab, start, end = _leader_candidate(at, text, r, ang, size_mm)
        if self.is_free(label_bbox(lab), within=within) and not (strict and self._line_blocked(start, end, at)):
            self.add_label(lab)
            self.add_line((start, end))
            return lab, (end, start)
        return None

    def try_leaders(self, at, text: str, r: float, angles, *, size_mm: float, within: Box | None = None,
                    strict: bool = True) -> tuple[Label, tuple[tuple[float, float], tuple[float, float]]] | None:
        """:meth:`try_leader` at each of ``angles`` in turn, the first that fits (registered), else None: the
        same decisions, the ring's free-space tests in one :meth:`free` call."""
        cands = [_leader_candidate(at, text, r, ang, size_mm) for ang in angles]
        if not cands:
            return None
        ok = self.free([label_bbox(lab) for lab, _, _ in cands], within=within)
        for (lab, start, end), free in zip(cands, ok.tolist()):
            if free and not (strict and self._line_blocked(start, end, at)):
                self.add_label(lab)
                self.add_line((start, end))
                return lab, (end, start)
        return None

    def _line_blocked(self, p, q, anchor=None) -> bool:
        """Does the segment p–q cross or touch a registered label box (within the tie quantum)? (A leader
        may cross lines; the marks around its own ``anchor`` do not block it: it must reach the point.)"""
        b = self.box_array() + np.array([-TIE_MM, -TIE_MM, TIE_MM, TIE_MM])          # a touch crosses
        if anchor is not None and len(b):
            ax, ay = anchor
            b = b[~((b[:, 0] <= ax) & (ax <= b[:, 2]) & (b[:, 1] <= ay) & (ay <= b[:, 3]))]
        seg = np.array([[p[0], p[1], q[0], q[1]]], dtype=float)
        return bool(len(b)) and bool(segments_hit_boxes(seg, b).any())

    @staticmethod
    def block_size(lines: tuple[str, ...], *, size_mm: float, line_mm: float) -> tuple[float, float]:
        """Width and height in mm of a centred block of text lines."""
        from graphmethods.scene.markup import text_width_mm

        return max(text_width_mm(t, size_mm) for t in lines) + 0.6, line_mm * len(lines)

    def place_block(self, candidates, lines: tuple[str, ...], *, size_mm: float, line_mm: float,
                    within: Box | None = None, inside=None, check_lines: bool = True
                    ) -> tuple[list[Label], Box] | None:
        """Centre a block of text lines on the first free candidate point; None when none fits.

        ``inside`` is an optional test ``box -> bool`` (e.g. the box lies inside a region);
        ``check_lines=False`` ignores registered lines (the ``inside`` test keeps it clear of them).
        """
        w, h = self.block_size(lines, size_mm=size_mm, line_mm=line_mm)
        for cx, cy in candidates:
            box = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
            if (inside is None or inside(box)) and self.is_free(box, within=within, lines=check_lines):
                labels = [make_label((cx, box[1] + line_mm * (k + 0.5)), t, size_mm=size_mm, anchor="middle",
                                     valign="middle") for k, t in enumerate(lines)]
                self.add_box(box)
                return labels, box
        return None


#: the page sizes of a course sheet, whose main inscription follows the language's standard
COURSE_SHEETS = ("A1", "A2")


def course_title_block(tb: TitleBlock, nt, *, scale: str = "") -> TitleBlock:
    """The main inscription of an A1/A2 course sheet: ГОСТ 2.104 form 1 (ru), GB/T 10609.1 (zh), or the
    simple block with the student's rows held free (en), all of a fixed height. ``scale`` fills the
    standard forms' Масштаб / 比例 cell (:func:`main_scale`).

    >>> from graphmethods.scene import TitleBlock
    >>> course_title_block(TitleBlock("Dynamic analysis", "press"), "ru").form
    'gost'
    """
    nt = get_notation(nt)
    form = form_for(nt.code)
    if form == "simple":
        rows = tuple((nt.word(k), "") for k in ("title_block.student", "worksheets.group", "title_block.sheet"))
        return replace(tb, person=rows)
    return replace(tb, form=form, fields=(("designation", tb.problem),) + ((("scale", scale),) if scale else ()))


def main_scale(scales, nt) -> str:
    """The scale of a course sheet for its main inscription (ГОСТ 2.104 graph 6, GB/T 10609.1 比例).

    A sheet of several images states the scale of its main one there, the others at their images
    (ГОСТ 2.109, GB/T 14690): the main image is the first drawn to a length scale μ_l among
    ``scales`` (the sheet's first part's), written as ГОСТ 2.302 / GB/T 14690 write it, 1 : (1000 μ_l)
    for μ_l in m/mm (every convenient μ_l, 1, 2, 2.5, 4, 5 × 10ᵏ, is a scale of those series). A sheet
    that draws no length to scale (diagrams only, each at its own μ) gets a dash.

    >>> from graphmethods.scene import Scale
    >>> main_scale([Scale("μ_l", "м", 0.0025)], "ru"), main_scale([Scale("μ_l", "m", 0.0005)], "zh")
    ('1:2,5', '2:1')
    >>> main_scale([Scale("μ_M", "N·m", 5.0)], "ru")
    '—'
    """
    nt = get_notation(nt)
    length = next((s for s in scales if markup.plain(s.symbol) == markup.plain("μ_l")
                   and s.unit == nt.unit("m")), None)
    if length is None:
        return "—"
    r = float(length.per_mm) * 1000.0          # mm of the part per mm of paper
    return f"1:{nt.number(round(r, 6))}" if r >= 1.0 - 1e-9 else f"{nt.number(round(1.0 / r, 6))}:1"


def sign_sheet(scene: Scene, *, student: str = "", group: str = "", sheet_no: str = "", sheets: str = "") -> Scene:
    """The sheet with the student's name, group and sheet number (of ``sheets``) in its main inscription.

    >>> from graphmethods.scene import Page
    >>> pg = standard_page(Page("A1", frame=True), title="T", problem="p", scales=(), nt="ru")
    >>> s = sign_sheet(Scene(page=pg), student="Иванов И. И.", group="МТ-31", sheet_no="3", sheets="4")
    >>> dict(s.page.title_block.fields)["student"], dict(s.page.title_block.fields)["organisation"]
    ('Иванов И. И.', 'МТ-31')
    """
    tb = scene.page.title_block
    if tb is None or not (student or group or sheet_no or sheets):
        return scene
    if tb.form == "simple":
        given = {0: student, 1: group, 2: f"{sheet_no}/{sheets}" if sheets else sheet_no}
        person = tuple((h, given.get(i, t) or t) for i, (h, t) in enumerate(tb.person)) or tuple(
            (h, v) for h, v in zip(("Student", "Group", "Sheet"), given.values()) if v)
        tb = replace(tb, person=person)
    else:
        fields = dict(tb.fields)
        fields.update({k: v for k, v in (("student", student), ("organisation", group), ("sheet_no", sheet_no),
                                         ("sheets", sheets)) if v})
        tb = replace(tb, fields=tuple(fields.items()))
    return replace(scene, page=scene.page.with_(title_block=tb))


def standard_page(page: Page | None, *, title: str, problem, scales: tuple[str, ...], nt,
                  title_block: bool = True, scale: str = "") -> Page:
    """The page of a sheet: A4 landscape with a frame and a title block unless ``page`` is given.

    A given page is used as it is, with the title block added when it has none and
    ``title_block`` is true. ``problem`` is text, or a :class:`~graphmethods.titles.Title` (or
    a mapping by language) shown in the notation's language.
    """
    nt = get_notation(nt)
    tb = TitleBlock(title, text_in(problem, nt.code), scales,
                    headings=(nt.word("figure"), nt.word("problem"), nt.word("scales")))
    if page is not None and page.size in COURSE_SHEETS:
        tb = course_title_block(tb, nt, scale=scale)
    if page is None:
        return Page("A4", "landscape", frame=True, title_block=tb if title_block else None)
    if page.title_block is None and title_block:
        return page.with_(title_block=tb)
    return page


def problem_title(obj, nt) -> str:
    """A problem's title in the notation's language, after its id when it has one: ``"W1: …"``.

    Parameters
    ----------
    obj : object
        A problem with a ``title`` (a :class:`~graphmethods.titles.Title`, a mapping by language
        or text) and perhaps an ``id``, such as :func:`graphmethods.problems.w1` or a problem file
        read by :func:`graphmethods.kinematics.read_case` (a reference case gets our translations,
        :func:`graphmethods.problems.reference_cases.title_of`); anything else gives ``""``.
    nt : str or Notation
        The figure's notation; its language picks the title (English when it is missing).

    Returns
    -------
    str
        Plain text (the title block draws it literally); Chinese takes a full-width colon.

    Examples
    --------
    >>> from graphmethods import problems
    >>> problem_title(problems.w3(), "ru"), problem_title(problems.w3(), "zh")
    ('W3: Ступенчатый момент сопротивления: маховик', 'W3：阶梯形阻抗力矩下的飞轮转动惯量')
    """
    code = get_notation(nt).code
    pid = str(getattr(obj, "id", "") or "")
    title = title_of(obj).title_in(code)
    if pid and title:
        return f"{pid}{'：' if code == 'zh' else ': '}{title}"
    return title or pid


def angle_deg_text(phi_rad: float, nt) -> str:
    """An angle in degrees as the profile writes numbers: ``45°``."""
    return get_notation(nt).number(math.degrees(phi_rad), sig=4) + "°"


TITLE_MM = 5.0          # title text size
TEXT_MM = 3.2           # labels, legends, captions


class Sheet:
    """The frame every figure shares: page, title, content box, the captions line, an occupancy.

    ``top`` is where the drawing may begin (``top_gap_mm`` below the title), ``caption_y`` the
    baseline of the scale captions; ``occ`` holds what is drawn so labels can keep off it.
    ``problem`` may be text or a :class:`~graphmethods.titles.Title` (or a mapping by language):
    the title block shows it in the notation's language.
    """

    def __init__(self, *, nt, page, title, problem, title_block, has_scales: bool = True,
                 default_page: Page | None = None, top_gap_mm: float = 5.0):
        self.nt, self.title, self.problem, self.title_block = nt, title, problem, title_block
        self._page_arg = default_page if page is None and default_page is not None else page
        self.probe = probe = standard_page(self._page_arg, title=title, problem=problem,
                                           scales=("μ",) if has_scales else (), nt=nt, title_block=title_block)
        self.box = probe.content_box()
        x0, y0, x1, y1 = self.box
        from graphmethods.sheets.engine.lettering import is_course_sheet, lettering

        self.title_mm = lettering(probe).title_mm if is_course_sheet(probe) else TITLE_MM   # 7 mm on A1/A2
        self.top = y0 + self.title_mm + top_gap_mm
        self.caption_y = y1 - 1.0
        self.occ = Occupancy()
        self.occ.add_box((x0, y0, x1, y0 + self.title_mm + 1.5))

    def page(self, scales):
        return standard_page(self._page_arg, title=self.title, problem=self.problem,
                             scales=tuple(s.caption(self.nt) for s in scales), nt=self.nt,
                             title_block=self.title_block, scale=main_scale(scales, self.nt))

    def header(self):
        from graphmethods.scene import Text

        x0, y0, _, _ = self.box
        return Text((x0, y0 + self.title_mm), self.title, size_mm=self.title_mm, bold=True, name="title")

    def captions(self, scales, legend: str = "", *, reserve: bool = False) -> list:
        """The scale captions at the left of the bottom line, a legend at its right; ``reserve``
        keeps later labels off that line."""
        from graphmethods.scene import ScaleCaptions, Text

        x0, _, x1, _ = self.box
        els: list[Element] = [ScaleCaptions((x0, self.caption_y), tuple(scales), notation=self.nt, size_mm=TEXT_MM,
                             name="scale-captions")]
        if legend:
            els.append(Text((x1, self.caption_y), legend, size_mm=TEXT_MM, anchor="end", name="legend"))
        if reserve:
            self.occ.add_box((x0, self.caption_y - TEXT_MM, x1, self.caption_y + 1.0))
        return els

    def scene(self, elements, scales, *, name, notes=()):
        """The finished Scene on this sheet's page."""
        from graphmethods.scene import Scene

        return Scene(self.page(scales), tuple(elements), title=self.title, notation=self.nt.code, name=name,
                     extra_scales=tuple(scales), notes=tuple(notes))



AxisT = TypeVar("AxisT", bound=Axis)


def clear_tick_labels(axis: AxisT, occ: Occupancy, *, keep_values: bool = False, other_side: bool = False) -> AxisT:
    """The axis with the tick labels that would cover something already registered left out (marks stay).

    With ``keep_values`` (a value axis) an axis is never left without values: when every label
    would cover something, they go on the other side of the axis (``other_side``), and when that
    is full too (or not asked for), the labels that cover no text stay (a thin line may run
    through a number).

    >>> from graphmethods.scene import Scale
    >>> occ = Occupancy()
    >>> occ.add_line(((5.0, 85.0), (30.0, 85.0)))                   # a line through the value 10
    >>> ax = Axis((10.0, 95.0), Scale("μ", "J", 1.0), "y", max_value=30.0, ticks=(0.0, 10.0, 20.0))
    >>> clear_tick_labels(ax, occ).tick_labels
    ('0', '', '20')
    """
    labels = list(axis.tick_labels) if axis.tick_labels is not None else \
        [format_value(v, decimal=axis.decimal) for v in axis.ticks]
    shown = [i for i, v in enumerate(axis.ticks) if labels[i] and not (axis.skip_zero_label and v == 0)]

    def kept(ax: AxisT, lines: bool) -> list[str]:
        texts = [p for p in replace(ax, label="").primitives() if isinstance(p, Label)]
        out = list(labels)
        for i, lab in zip(shown, texts):
            if not occ.is_free(label_bbox(lab), lines=lines):
                out[i] = ""
        return out

    out = kept(axis, True)
    if keep_values and shown and not any(out[i] for i in shown):
        if other_side:
            flip = {"": "right", "left": "right"} if axis.direction == "y" else \
                {"": "above", "below": "above", "above": "below"}
            other = replace(axis, labels_side=flip.get(axis.labels_side, axis.labels_side))
            out = kept(other, True)
            if any(out[i] for i in shown):
                return replace(other, tick_labels=tuple(out))
        out = kept(axis, False)
    return replace(axis, tick_labels=tuple(out))


def english_unit(u: str) -> str:
    """The unit ``u`` as the English profile writes it (callers pass units already translated; an error
    message is English and must not read "кг·м²/mm").

    >>> english_unit("кг·м²"), english_unit("kg·m²")
    ('kg·m²', 'kg·m²')
    """
    for nt in NOTATIONS.values():
        back = {local: en for en, local in nt.units.items()}
        if u in back:
            return back[u]
    return u


def given_scale(given, symbol: str, u: str, span: float, span_mm: float, *, what: str) -> Scale:
    """The scale given (a number or a Scale), checked to fit; or a convenient one picked to fit."""
    if given is None:
        return pick_scale(span, span_mm, symbol=symbol, unit=u)
    s = given if isinstance(given, Scale) else Scale(symbol, u, given)
    if s.to_mm(span) > span_mm * (1 + 1e-9):
        english = markup.plain(replace(s, unit=english_unit(s.unit)).caption())   # the message is English
        raise InputError(f"{what} at {english} needs {s.to_mm(span):.1f} mm but the sheet leaves {span_mm:.1f} mm; "
                         f"give a larger scale (more units per mm), a larger page, or none to have one picked")
    return s


def given_angle_scale(given, symbol: str, period: float, span_mm: float) -> Scale:
    """The φ scale given (rad/mm, or a Scale), checked to fit; or one picked (a round number of °/mm)."""
    if given is None:
        return pick_angle_scale(period, span_mm, symbol=symbol)
    s = given if isinstance(given, Scale) else Scale(symbol, "rad", given)
    if s.to_mm(period) > span_mm * (1 + 1e-9):
        raise InputError(f"the period at {markup.plain(s.caption())} needs {s.to_mm(period):.1f} mm but the sheet "
                         f"leaves {span_mm:.1f} mm; give a larger μ_φ, a larger page, or none to have one picked")
    return s
