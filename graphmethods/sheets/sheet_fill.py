"""How much of a course sheet its drawings fill, and whether their lettering clashes: to choose a layout.

The figure-quality measure (:mod:`graphmethods.sheets.engine.quality`) counts the 20 mm cells inside the
frame that no ink touches. A sheet composer that can divide its page several ways draws its parts for
some divisions and keeps the one whose parts touch the most cells with no label crossed. :class:`PartInk`
records a drawn part once (its segments, its texts' boxes, the cells of the sheet's grid its ink touches,
by the measure's own count :func:`~graphmethods.sheets.engine.quality.ink_cells`); :func:`filled` and
:func:`clashes` then judge any set of parts from those records.

>>> from graphmethods.scene import Line, Page, Scene
>>> page = Page("A1", "landscape", frame=True)
>>> ink = PartInk.of(Scene(page, (Line((100, 100), (180, 100), name="l"),)), page)
>>> int(filled([ink]).sum()), clashes([ink])
(5, 0)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphmethods.render.recording import record
from graphmethods.scene import Page, Scene
from graphmethods.scene.elements import label_bbox
from graphmethods.sheets.engine.quality import OVERLAP_MM, boxes_crossed, glyph_box, ink_cells, segments_marked

Box = tuple[float, float, float, float]


@dataclass(frozen=True)
class PartInk:
    """The ink of one part of a sheet, recorded once (mm, page coordinates).

    Attributes
    ----------
    segments : ndarray (n, 4)
        Every line segment the part draws (:func:`~graphmethods.sheets.engine.quality.segments_marked`).
    glyphs, boxes : ndarray (k, 4)
        Its texts' glyph boxes (:func:`~graphmethods.sheets.engine.quality.glyph_box`) and whole boxes.
    cells : ndarray of bool (nx, ny)
        The cells of the sheet's grid its ink touches (the frame and title block left out).
    bbox : (x0, y0, x1, y1) or None
        The box around its ink (circles whole, texts by their boxes).
    crossed : ndarray of bool (k,)
        Which of its texts its own lines cross.
    overlaps : int
        How many pairs of its texts overlap.
    inked, inner : ndarray (m, 4), (x0, y0, x1, y1)
        Its segments that count for the cells (the frame and title block left out), and the frame's inside
        holding the grid of cells.
    """

    segments: np.ndarray
    glyphs: np.ndarray
    boxes: np.ndarray
    cells: np.ndarray
    bbox: Box | None
    crossed: np.ndarray
    overlaps: int
    inked: np.ndarray
    inner: Box

    @classmethod
    def of(cls, scene: Scene, page: Page) -> PartInk:
        """The ink of ``scene`` (a part drawn on a region of ``page``) on ``page``'s grid of cells."""
        rec = record(scene)
        labels = [c.data for c in rec.calls if c.kind == "text"]
        whole = [label_bbox(lab) for lab in labels]
        glyphs = np.array([glyph_box(lab, b) for lab, b in zip(labels, whole)], dtype=float).reshape(-1, 4)
        boxes = np.array(whole, dtype=float).reshape(-1, 4)
        seg, in_page = segments_marked(rec, ("page",))
        inked = seg[~in_page]
        cells = ink_cells(inked, boxes, page.inner_box())
        ext = [boxes, glyphs] + [np.array([[c.data[0] - c.data[2], c.data[1] - c.data[2], c.data[0] + c.data[2],
                                    c.data[1] + c.data[2]]]) for c in rec.calls if c.kind == "circle"]
        pts = np.concatenate([seg[:, :2], seg[:, 2:]] + [e[:, :2] for e in ext] + [e[:, 2:] for e in ext])
        bbox = None if not len(pts) else (float(pts[:, 0].min()), float(pts[:, 1].min()),
                                         float(pts[:, 0].max()), float(pts[:, 1].max()))
        return cls(seg, glyphs, boxes, cells, bbox, boxes_crossed(seg, glyphs), _overlapping(glyphs, boxes),
                   inked, page.inner_box())

    def stretched(self, src: Box, dst: Box) -> np.ndarray:
        """The cells (of the same grid) this ink would touch, were the part drawn in the region ``dst`` as it is
        in ``src`` (its lines and texts stretched from one region onto the other): a prediction, to rank
        divisions of a sheet before drawing them.

        >>> from graphmethods.scene import Line, Page, Scene
        >>> page = Page("A1", "landscape", frame=True)
        >>> ink = PartInk.of(Scene(page, (Line((100, 100), (180, 100), name="l"),)), page)
        >>> int(ink.stretched((100, 90, 180, 110), (100, 90, 260, 110)).sum())
        9
        """
        kx, ky = (dst[2] - dst[0]) / (src[2] - src[0]), (dst[3] - dst[1]) / (src[3] - src[1])
        k = np.array([kx, ky, kx, ky])
        o_src, o_dst = np.array([src[0], src[1]] * 2), np.array([dst[0], dst[1]] * 2)
        return ink_cells(o_dst + (self.inked - o_src) * k, o_dst + (self.boxes - o_src) * k, self.inner)


def filled(parts: list[PartInk]) -> np.ndarray:
    """The cells of the sheet's grid (bool nx × ny) the ink of the ``parts`` touches together; ``.sum()``
    counts them (the measure's count: ``1 − filled(…).mean()`` is the sheet's empty share when the parts are
    all it draws inside the frame)."""
    return np.logical_or.reduce([p.cells for p in parts])


def _overlapping(glyphs: np.ndarray, boxes: np.ndarray, glyphs_b: np.ndarray | None = None,
                 boxes_b: np.ndarray | None = None) -> int:
    """Pairs of texts set one on another (the measure's rule): within one set, or between two."""
    gb, bb = (glyphs, boxes) if glyphs_b is None or boxes_b is None else (glyphs_b, boxes_b)
    if not len(glyphs) or not len(gb):
        return 0
    ox = np.minimum(glyphs[:, None, 2], gb[None, :, 2]) - np.maximum(glyphs[:, None, 0], gb[None, :, 0])
    oy = np.minimum(boxes[:, None, 3], bb[None, :, 3]) - np.maximum(boxes[:, None, 1], bb[None, :, 1])
    both = (ox > OVERLAP_MM) & (oy > OVERLAP_MM)
    return int((np.triu(both, k=1) if glyphs_b is None else both).sum())


def _meet(a: Box | None, b: Box | None) -> bool:
    """Do two ink boxes meet (touching counts)?"""
    return a is not None and b is not None and a[0] <= b[2] and b[0] <= a[2] and a[1] <= b[3] and b[1] <= a[3]


def clashes(parts: list[PartInk]) -> int:
    """How many texts of the ``parts`` (of one sheet, together) a line crosses, and how many pairs of texts
    overlap (the measure's two faults of lettering, :func:`~graphmethods.sheets.engine.quality.measure`): a
    division that squeezes a part so that its lettering clashes is no division to keep. Each part's own
    faults are counted once, when it is recorded; between parts only those whose ink boxes meet are compared.

    >>> from graphmethods.scene import Line, Page, Scene, Text
    >>> pg = Page("A4")
    >>> clashes([PartInk.of(Scene(pg, (Text((50, 50), "M", name="t"),)), pg),
    ...          PartInk.of(Scene(pg, (Line((40, 49), (90, 49)),)), pg)])
    1
    """
    hit = [p.crossed.copy() for p in parts]
    pairs = sum(p.overlaps for p in parts)
    for i, A in enumerate(parts):
        for j in range(i + 1, len(parts)):
            B = parts[j]
            if not _meet(A.bbox, B.bbox):
                continue
            hit[i] |= boxes_crossed(B.segments, A.glyphs)
            hit[j] |= boxes_crossed(A.segments, B.glyphs)
            pairs += _overlapping(A.glyphs, A.boxes, B.glyphs, B.boxes)
    return int(sum(int(h.sum()) for h in hit)) + pairs


def overflowing(parts: list[PartInk]) -> int:
    """How many pairs of the parts' ink boxes overlap (a line of text too long for its region runs into the
    next part).

    >>> from graphmethods.scene import Line, Page, Scene
    >>> pg = Page("A4")
    >>> a, b = (PartInk.of(Scene(pg, (Line((x, 40), (x + 40, 60)),)), pg) for x in (10, 40))
    >>> overflowing([a, b])
    1
    """
    boxes = [p.bbox for p in parts if p.bbox is not None]
    out = 0
    for i, A in enumerate(boxes):
        out += sum(1 for B in boxes[i + 1:] if not (A[2] <= B[0] or B[2] <= A[0] or A[3] <= B[1] or B[3] <= A[1]))
    return out


__all__ = ["PartInk", "clashes", "filled", "overflowing"]
