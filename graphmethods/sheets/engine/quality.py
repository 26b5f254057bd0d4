"""The figure-quality measure: what a teacher checks on a printed sheet, measured from the rendered output.

:func:`measure` draws a scene into the recording renderer (the primitives every backend receives) and
measures, with the texts' real extents (the font's advance widths, :func:`~graphmethods.scene.elements.
label_bbox`):

- ``empty_share``: the share of the 20 mm cells inside the frame that no ink touches (a course sheet
  should be filled: at most 50 % empty on A1/A2; a 16:9 slide, framed or not, inside its margins alike);
- ``min_text_mm``: the smallest font size of a text, the title block's included (sub- and superscripts are
  drawn smaller and exempt; a condensed text, :attr:`~graphmethods.scene.primitives.Label.stretch`, is
  measured at its height and its condensed width);
- ``crossed``: the labels a line, an arrow, a hatch line or a circle passes through (through the glyphs:
  the band from the baseline to the capitals' height, 0.1 mm in from the ends);
- ``overlaps``: pairs of texts set one on another (by more than 0.3 mm both ways);
- ``noise``: numbers printed as a power of ten more than 10⁹ times smaller than the numbers beside them
  (round-off printed as working: ``4,47·10⁻¹⁵²``).

:func:`faults` turns a measure into the list of what breaks the standard for the page's format. Its count of
inked cells, :func:`ink_cells`, is public: the sheets that choose between layouts count by it
(:mod:`graphmethods.sheets.sheet_fill`); it and the crossing test :func:`boxes_crossed` look only at the
segments near each cell or label, with the decisions of testing every pair.

>>> from graphmethods.scene import Page, Scene, Text, Line
>>> page = Page("A4", "landscape", frame=True)
>>> q = measure(Scene(page, (Text((50, 50), "M_d = 10", size_mm=3.5, name="a"),
...                          Line((40, 49), (90, 49), name="l"))))
>>> q.min_text_mm, q.crossed
(3.5, ('Md = 10',))
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from graphmethods.render.recording import RecordingRenderer, record
from graphmethods.scene import markup
from graphmethods.scene.elements import CAP, label_bbox
from graphmethods.scene.primitives import Label
from graphmethods.scene.scene import Scene
from graphmethods.sheets.engine.lettering import is_course_sheet, is_slide, lettering
from graphmethods.sheets.layout import pairs_hit, segments_hit_boxes
from graphmethods.units import ROUNDOFF

#: the cell of the empty-space measure (mm)
CELL_MM = 20.0
#: most empty share of a course sheet's cells
EMPTY_MAX = 0.5
#: two texts overlap when they share more than this both across and down (mm)
OVERLAP_MM = 0.3
#: how far (mm) beyond its extent an item is filed in the buckets of :func:`boxes_crossed`: far above the
#: rounding of page coordinates and the prefilter's slack, so no pair that can touch is missed
_BUCKET_SLACK_MM = 1e-3
#: a circle's 16-gon (:func:`~graphmethods.sheets.engine.labels.circle_points`, the same arithmetic)
_COS16 = np.array([math.cos(2 * math.pi * k / 16) for k in range(17)])
_SIN16 = np.array([math.sin(2 * math.pi * k / 16) for k in range(17)])
#: a power of ten this much smaller than its neighbours is round-off printed as working (the core's
#: and the formatter's round-off share, one definition)
NOISE_RATIO = ROUNDOFF


@dataclass(frozen=True)
class Quality:
    """What :func:`measure` found on one sheet or figure."""

    page_size: str
    empty_share: float
    min_text_mm: float
    crossed: tuple[str, ...]
    overlaps: tuple[str, ...]
    noise: tuple[str, ...]
    n_texts: int


def segments_marked(rec: RecordingRenderer, groups: Sequence[str] = ()) -> tuple[np.ndarray, np.ndarray]:
    """The line segments of a recorded drawing (paths, polygons, circles as 16-gons, in the order drawn) as an
    (n, 4) array of ``x0, y0, x1, y1`` (mm), and which of them are drawn inside any of the ``groups``
    (``"page"``: the frame and title block).

    >>> from graphmethods.scene import Line, Page, Scene
    >>> seg, marked = segments_marked(record(Scene(Page("A4"), (Line((0, 0), (10, 0), name="l"),))), ("l",))
    >>> seg.tolist(), marked.tolist()
    ([[0.0, 0.0, 10.0, 0.0]], [True])
    """
    pts_all: list[tuple[float, float]] = []     # every run's points, one after another
    lens: list[int] = []
    marks: list[bool] = []
    circles: list[tuple[int, float, float, float]] = []      # (where its 17 points go, cx, cy, r)
    ring = [(0.0, 0.0)] * len(_COS16)
    for c in rec.calls:
        kind = c.kind
        if kind == "path":
            pts, closed = c.data
            k = len(pts)
            if closed and k:
                pts = (*pts, pts[0])
                k += 1
        elif kind == "polygon":
            pts = c.data
            k = len(pts)
            if k:
                pts = (*pts, pts[0])
                k += 1
        elif kind == "circle":
            circles.append((len(pts_all), *c.data))
            pts, k = ring, len(ring)
        else:
            continue
        if k > 1:
            pts_all.extend(pts)
            lens.append(k)
            marks.append(bool(groups) and any(g in groups for g in c.groups))
    if not lens:
        return np.empty((0, 4)), np.empty(0, dtype=bool)
    n = np.array(lens)
    flat = np.array(pts_all, dtype=float).reshape(-1, 2)
    for at, cx, cy, r in circles:               # a circle as its 16-gon
        flat[at:at + len(_COS16)] = np.column_stack((cx + r * _COS16, cy + r * _SIN16))
    keep = np.ones(len(flat), dtype=bool)
    keep[np.cumsum(n) - 1] = False              # the last point of a run starts no segment
    first = np.flatnonzero(keep)
    return np.column_stack((flat[first], flat[first + 1])), np.repeat(np.array(marks), n - 1)


def _spans(lo: np.ndarray, hi: np.ndarray, grid_mm: float) -> tuple[np.ndarray, np.ndarray]:
    """The first and last bucket (of ``grid_mm``) each interval ``[lo, hi]`` reaches, widened by
    :data:`_BUCKET_SLACK_MM` so no rounding loses a bucket."""
    return (np.floor((lo - _BUCKET_SLACK_MM) / grid_mm).astype(np.int64),
            np.floor((hi + _BUCKET_SLACK_MM) / grid_mm).astype(np.int64))


def _buckets(ext: np.ndarray, grid_mm: float) -> tuple[np.ndarray, np.ndarray]:
    """Each item of the extents ``ext`` (n × 4: x_lo, y_lo, x_hi, y_hi) under every bucket its extent
    reaches: (item numbers, bucket keys)."""
    q0, q1 = _spans(ext[:, 0], ext[:, 2], grid_mm)
    r0, r1 = _spans(ext[:, 1], ext[:, 3], grid_mm)
    nq, nr = q1 - q0 + 1, r1 - r0 + 1
    n = nq * nr
    item = np.repeat(np.arange(len(ext)), n)
    local = np.arange(int(n.sum())) - np.repeat(np.cumsum(n) - n, n)
    q = np.repeat(q0, n) + local % np.repeat(nq, n)
    r = np.repeat(r0, n) + local // np.repeat(nq, n)
    return item, (q << 32) + r


def _near_pairs(seg: np.ndarray, boxes: np.ndarray, grid_mm: float) -> tuple[np.ndarray, np.ndarray]:
    """The pairs (segment, box) whose extents come within :data:`_BUCKET_SLACK_MM` of each other, found
    through buckets of ``grid_mm`` (a superset of the pairs that can touch; a pair sharing several buckets
    comes as often)."""
    e = _BUCKET_SLACK_MM
    s_ext = np.column_stack((np.minimum(seg[:, 0], seg[:, 2]), np.minimum(seg[:, 1], seg[:, 3]),
                             np.maximum(seg[:, 0], seg[:, 2]), np.maximum(seg[:, 1], seg[:, 3])))
    s_item, s_key = _buckets(s_ext, grid_mm)
    b_item, b_key = _buckets(boxes, grid_mm)
    order = np.argsort(s_key, kind="stable")
    s_item, s_key = s_item[order], s_key[order]
    lo, hi = np.searchsorted(s_key, b_key, "left"), np.searchsorted(s_key, b_key, "right")
    n = hi - lo
    bi = np.repeat(b_item, n)
    si = s_item[np.arange(int(n.sum())) - np.repeat(np.cumsum(n) - n, n) + np.repeat(lo, n)]
    a, b = s_ext[si], boxes[bi]
    near = (a[:, 0] <= b[:, 2] + e) & (a[:, 2] >= b[:, 0] - e) & (a[:, 1] <= b[:, 3] + e) & (a[:, 3] >= b[:, 1] - e)
    return si[near], bi[near]


def boxes_crossed(seg: np.ndarray, boxes: np.ndarray, *, grid_mm: float = 10.0) -> np.ndarray:
    """Which ``boxes`` (k × 4, mm) a segment of ``seg`` (n × 4, mm) passes through or touches: a bool per box.

    The decisions of :func:`~graphmethods.sheets.layout.segments_hit_boxes` (``.any(axis=1)``), to the bit:
    the same clipping arithmetic, applied only to the pairs whose extents meet (found through a grid of
    ``grid_mm`` buckets), so a sheet's thousands of segments against its hundreds of labels cost
    milliseconds.

    >>> seg = np.array([[0.0, 10.0, 100.0, 10.0], [0.0, 0.0, 0.0, 5.0]])
    >>> boxes_crossed(seg, np.array([[40.0, 8.0, 60.0, 12.0], [40.0, 12.0, 60.0, 14.0]])).tolist()
    [True, False]
    """
    seg = np.asarray(seg, dtype=float).reshape(-1, 4)
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    out = np.zeros(len(boxes), dtype=bool)
    if not len(seg) or not len(boxes):
        return out
    if not (np.isfinite(seg).all() and np.isfinite(boxes).all()):      # no buckets for these: every pair
        for chunk in range(0, len(seg), 4000):
            out |= segments_hit_boxes(seg[chunk:chunk + 4000], boxes).any(axis=1)
        return out
    si, bi = _near_pairs(seg, boxes, grid_mm)
    out[bi[pairs_hit(seg[si], boxes[bi])]] = True
    return out


def cell_grid(inner: tuple[float, float, float, float]) -> tuple[float, float, int, int]:
    """The measure's grid of :data:`CELL_MM` cells centred in the box ``inner`` (a page's frame, mm): its
    origin (mm) and the cells across and down.

    >>> cell_grid((0.0, 0.0, 50.0, 30.0))
    (5.0, 5.0, 2, 1)
    """
    x0, y0, x1, y1 = inner
    nx, ny = int((x1 - x0) // CELL_MM), int((y1 - y0) // CELL_MM)
    return x0 + ((x1 - x0) - nx * CELL_MM) / 2, y0 + ((y1 - y0) - ny * CELL_MM) / 2, nx, ny


def _extents(ext: np.ndarray) -> np.ndarray:
    """The extents (x_lo, y_lo, x_hi, y_hi) of segments or boxes given as rows ``x0, y0, x1, y1`` (mm)."""
    return np.column_stack((np.minimum(ext[:, 0], ext[:, 2]), np.minimum(ext[:, 1], ext[:, 3]),
                            np.maximum(ext[:, 0], ext[:, 2]), np.maximum(ext[:, 1], ext[:, 3])))


def _within_one_cell(seg: np.ndarray, ox: float, oy: float, nx: int, ny: int) -> tuple[np.ndarray, np.ndarray]:
    """The segments (or boxes; n × 4, mm) that lie inside one cell of the grid (origin ``ox, oy``, ``nx × ny``
    cells of :data:`CELL_MM`) more than :data:`_BUCKET_SLACK_MM` from its edges, and those cells' numbers
    (``i·ny + j``).

    Such a segment touches its cell and no other (the clipping test cannot say otherwise: every end is inside
    the one, and the others are farther than the buckets' slack), and such a box overlaps its cell alone, so
    :func:`ink_cells` marks them without a test; most of a drawing's segments (arrowheads, hatching, circles,
    curves) and texts are this small.

    >>> inside, cell = _within_one_cell(np.array([[1.0, 1.0, 5.0, 3.0], [1.0, 1.0, 25.0, 3.0]]), 0.0, 0.0, 3, 2)
    >>> inside.tolist(), cell.tolist()
    ([True, False], [0])
    """
    e = _BUCKET_SLACK_MM
    with np.errstate(invalid="ignore"):
        i0 = np.floor((np.minimum(seg[:, 0], seg[:, 2]) - e - ox) / CELL_MM)
        i1 = np.floor((np.maximum(seg[:, 0], seg[:, 2]) + e - ox) / CELL_MM)
        j0 = np.floor((np.minimum(seg[:, 1], seg[:, 3]) - e - oy) / CELL_MM)
        j1 = np.floor((np.maximum(seg[:, 1], seg[:, 3]) + e - oy) / CELL_MM)
        inside = (i0 == i1) & (j0 == j1) & (i0 >= 0) & (i0 < nx) & (j0 >= 0) & (j0 < ny)
    return inside, (i0[inside] * ny + j0[inside]).astype(np.int64)


def _grid_pairs(ext: np.ndarray, ox: float, oy: float, nx: int, ny: int) -> tuple[np.ndarray, np.ndarray]:
    """The pairs (item, cell number ``i·ny + j``) of finite extents ``ext`` (n × 4: x_lo, y_lo, x_hi, y_hi, mm)
    and the cells of the grid (as in :func:`_within_one_cell`) that come within :data:`_BUCKET_SLACK_MM` of
    them: every cell an item can touch, and few more.

    >>> _grid_pairs(np.array([[15.0, 5.0, 25.0, 5.0]]), 0.0, 0.0, 3, 2)[1].tolist()
    [0, 2]
    """
    e = _BUCKET_SLACK_MM
    i0 = np.clip(np.floor((ext[:, 0] - e - ox) / CELL_MM), 0, nx).astype(np.int64)
    i1 = np.clip(np.floor((ext[:, 2] + e - ox) / CELL_MM), -1, nx - 1).astype(np.int64)
    j0 = np.clip(np.floor((ext[:, 1] - e - oy) / CELL_MM), 0, ny).astype(np.int64)
    j1 = np.clip(np.floor((ext[:, 3] + e - oy) / CELL_MM), -1, ny - 1).astype(np.int64)
    nq, nr = np.maximum(i1 - i0 + 1, 0), np.maximum(j1 - j0 + 1, 0)
    n = nq * nr
    item = np.repeat(np.arange(len(ext)), n)
    local = np.arange(int(n.sum())) - np.repeat(np.cumsum(n) - n, n)
    span = np.repeat(nq, n)             # ≥ 1 wherever a pair is
    return item, (np.repeat(i0, n) + local % span) * ny + np.repeat(j0, n) + local // span


def ink_cells(seg: np.ndarray, boxes: np.ndarray, inner: tuple[float, float, float, float]) -> np.ndarray:
    """Which cells of the grid in ``inner`` (:func:`cell_grid`; bool array, cells across × down) some ink
    touches: a segment of ``seg`` (n × 4, mm) passing through or touching the cell, or a text box of
    ``boxes`` (k × 4, mm) overlapping it. The one count of filled cells: :func:`measure`'s empty share is
    ``1 − ink_cells(…).mean()`` and the sheets choose their divisions by it
    (:mod:`graphmethods.sheets.sheet_fill`).

    >>> seg = np.array([[100.0, 100.0, 180.0, 100.0]])
    >>> int(ink_cells(seg, np.empty((0, 4)), (20.0, 10.0, 831.0, 584.0)).sum())
    5
    """
    ox, oy, nx, ny = cell_grid(inner)
    if nx < 1 or ny < 1:
        return np.zeros((max(nx, 0), max(ny, 0)), dtype=bool)
    cells = _cells(ox, oy, nx, ny)
    used = np.zeros(nx * ny, dtype=bool)
    seg = np.asarray(seg, dtype=float).reshape(-1, 4)
    finite = np.isfinite(seg).all(axis=1)
    if not finite.all():                        # no grid for these: every cell
        used |= boxes_crossed(seg[~finite], cells, grid_mm=CELL_MM)
        seg = seg[finite]
    inside, cell = _within_one_cell(seg, ox, oy, nx, ny)
    used[cell] = True
    seg = seg[~inside]
    si, ci = _grid_pairs(_extents(seg), ox, oy, nx, ny)        # the cells near each longer segment
    used[ci[pairs_hit(seg[si], cells[ci])]] = True
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    finite = np.isfinite(boxes).all(axis=1)
    inside, cell = _within_one_cell(boxes, ox, oy, nx, ny)      # a box inside one cell overlaps it alone
    used[cell] = True
    rest, odd = boxes[~inside & finite], boxes[~finite]
    bi, ci = _grid_pairs(_extents(rest), ox, oy, nx, ny)
    c, b = cells[ci], rest[bi]
    used[ci[(c[:, 0] < b[:, 2]) & (b[:, 0] < c[:, 2]) & (c[:, 1] < b[:, 3]) & (b[:, 1] < c[:, 3])]] = True
    if len(odd):
        used |= ((cells[:, None, 0] < odd[None, :, 2]) & (odd[None, :, 0] < cells[:, None, 2])
                 & (cells[:, None, 1] < odd[None, :, 3]) & (odd[None, :, 1] < cells[:, None, 3])).any(axis=1)
    return used.reshape(nx, ny)


@lru_cache(maxsize=8)
def _cells(ox: float, oy: float, nx: int, ny: int) -> np.ndarray:
    """The cells of a grid (:func:`cell_grid`) as boxes (nx·ny × 4, mm), cell ``(i, j)`` in row ``i·ny + j``
    (read only: shared by every count on that grid)."""
    i, j = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    cells = np.column_stack((ox + i.ravel() * CELL_MM, oy + j.ravel() * CELL_MM,
                             ox + (i.ravel() + 1) * CELL_MM, oy + (j.ravel() + 1) * CELL_MM))
    cells.flags.writeable = False
    return cells


def glyph_box(lab: Label, box: tuple[float, float, float, float] | None = None) -> tuple[float, float, float, float]:
    """The box of a label's glyphs that a line must not cross: capitals' height over the baseline (a lowered
    subscript's depth under it), 0.1 mm in from either end (``box``: the label's :func:`label_bbox`, when the
    caller has it already)."""
    x0, _, x1, _ = label_bbox(lab) if box is None else box
    sub = any(s < 0 for _, s in lab.runs)
    y0 = lab.y - CAP * lab.size_mm
    y1 = lab.y + (markup.SUB_SHIFT * lab.size_mm * 0.8 if sub else 0.0)
    return (x0 + 0.1, y0, max(x0 + 0.1, x1 - 0.1), y1)


_SUPER = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹", "0123456789")
_NUM = re.compile(r"[−-]?\d+(?:[.,]\d+)?")


def _noise(lab: Label) -> str | None:
    """The text when it prints a power of ten ≥ 10⁹ times smaller than the numbers beside it."""
    runs = list(lab.runs)
    powers: list[float] = []
    for k in range(1, len(runs)):
        t, s = runs[k]
        prev = runs[k - 1][0]
        if s > 0 and prev.endswith("10") and re.fullmatch(r"[−-]\d+", t.strip()):
            m = re.search(r"(\d+(?:[.,]\d+)?)\s*[·×]\s*10$", prev)
            mant = float(m.group(1).replace(",", ".")) if m else 1.0
            powers.append(mant * 10.0 ** (-int(t.strip()[1:])))
    for m in re.finditer(r"(\d+(?:\.\d+)?)e-(\d+)", lab.text):
        powers.append(float(m.group(1)) * 10.0 ** (-int(m.group(2))))
    for m in re.finditer(r"(?:(\d+(?:[.,]\d+)?)\s*[·×]\s*)?10⁻([⁰¹²³⁴⁵⁶⁷⁸⁹]+)", lab.text):
        mant = float(m.group(1).replace(",", ".")) if m.group(1) else 1.0
        powers.append(mant * 10.0 ** (-min(int(m.group(2).translate(_SUPER)), 300)))
    if not powers:
        return None
    plain = re.sub(r"(?:\d+(?:[.,]\d+)?\s*[·×]\s*)?10⁻[⁰¹²³⁴⁵⁶⁷⁸⁹]+", " ", "".join(t for t, s in runs if s == 0))
    others = [abs(float(x.replace("−", "-").replace(",", "."))) for x in _NUM.findall(plain)]
    ref = max([v for v in others if v > 0] + [1.0])
    return lab.text if min(powers) < NOISE_RATIO * ref else None


def measure(scene: Scene) -> Quality:
    """The quality of a scene as drawn (see the module docstring)."""
    rec = record(scene)
    labels = [c.data for c in rec.calls if c.kind == "text"]
    seg_all, in_page = segments_marked(rec, ("page",))

    glyphs = np.array([glyph_box(lab) for lab in labels], dtype=float).reshape(-1, 4)
    crossed: list[str] = []
    if len(labels) and len(seg_all):
        crossed = [labels[k].text for k in np.flatnonzero(boxes_crossed(seg_all, glyphs))]
    boxes = np.array([label_bbox(lab) for lab in labels], dtype=float).reshape(-1, 4)
    overlaps: list[str] = []
    if len(labels) > 1:
        ox = np.minimum(glyphs[:, None, 2], glyphs[None, :, 2]) - np.maximum(glyphs[:, None, 0], glyphs[None, :, 0])
        oy = np.minimum(boxes[:, None, 3], boxes[None, :, 3]) - np.maximum(boxes[:, None, 1], boxes[None, :, 1])
        for a, b in zip(*np.nonzero(np.triu((ox > OVERLAP_MM) & (oy > OVERLAP_MM), k=1))):
            overlaps.append(f"{labels[a].text!r} on {labels[b].text!r}")
    sizes = [lab.size_mm for lab in labels if any(s == 0 and t.strip() for t, s in lab.runs)]
    noise = [t for t in (_noise(lab) for lab in labels) if t]

    empty = 0.0
    if scene.page.frame or is_slide(scene.page):            # a framed sheet's frame, or a slide inside its margins
        used = ink_cells(seg_all[~in_page], boxes, scene.page.inner_box())
        empty = float(1.0 - used.mean()) if used.size else 0.0
    return Quality(scene.page.size, empty, min(sizes) if sizes else math.inf, tuple(crossed), tuple(overlaps),
                   tuple(noise), len(labels))


def faults(q: Quality) -> list[str]:
    """What breaks the standard on a measured sheet, one line each (empty: none)."""
    out: list[str] = []
    let = lettering(q.page_size)
    if (is_course_sheet(q.page_size) or is_slide(q.page_size)) and q.empty_share > EMPTY_MAX:
        out.append(f"{q.empty_share:.0%} of the {CELL_MM:g} mm cells inside the frame are empty "
                   f"(at most {EMPTY_MAX:.0%} on {q.page_size})")
    if q.min_text_mm < let.minimum_mm - 1e-9:
        out.append(f"text at {q.min_text_mm:.2f} mm, below {let.minimum_mm} mm on {q.page_size}")
    if q.crossed:
        out.append(f"{len(q.crossed)} labels crossed by ink: {', '.join(q.crossed[:8])}")
    if q.overlaps:
        out.append(f"{len(q.overlaps)} texts over texts: {'; '.join(q.overlaps[:5])}")
    if q.noise:
        out.append(f"round-off printed as working: {'; '.join(q.noise[:3])}")
    return out


__all__ = ["CELL_MM", "EMPTY_MAX", "Quality", "boxes_crossed", "cell_grid", "faults", "glyph_box", "ink_cells",
           "measure", "segments_marked"]
