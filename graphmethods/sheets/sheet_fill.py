"""How much of a course sheet its drawings fill, measured cheaply, to choose between layouts.

The figure-quality measure (:mod:`graphmethods.sheets.engine.quality`) counts the 20 mm cells inside the
frame that no ink touches. A sheet composer that can divide its page several ways draws its parts for
each division and keeps the one whose parts touch the most cells: :func:`ink_cells` finds the cells a
scene's ink touches (lines sampled every :data:`STEP_MM`, texts by their boxes) on the same grid as the
measure, fast enough to be run a few times per sheet.

>>> from graphmethods.scene import Line, Page, Scene
>>> page = Page("A1", "landscape", frame=True)
>>> s = Scene(page, (Line((100, 100), (180, 100), name="l"),))
>>> int(ink_cells(s, page).sum())
5
"""

from __future__ import annotations

import numpy as np

from graphmethods.render.recording import record
from graphmethods.scene import Page, Scene
from graphmethods.scene.elements import label_bbox
from graphmethods.sheets.engine.quality import CELL_MM, OVERLAP_MM, _segments, glyph_box
from graphmethods.sheets.layout import segments_hit_boxes

#: the spacing (mm) of the points a line is sampled at (a tenth of a cell)
STEP_MM = 2.0


def cell_grid(page: Page) -> tuple[float, float, int, int]:
    """The measure's grid of 20 mm cells inside the frame: its origin (mm) and the cells across and down."""
    x0, y0, x1, y1 = page.inner_box()
    nx, ny = int((x1 - x0) // CELL_MM), int((y1 - y0) // CELL_MM)
    return x0 + ((x1 - x0) - nx * CELL_MM) / 2, y0 + ((y1 - y0) - ny * CELL_MM) / 2, nx, ny


def ink_cells(scene: Scene, page: Page) -> np.ndarray:
    """Which cells of ``page``'s grid (:func:`cell_grid`, bool array nx × ny) the ink of ``scene`` touches."""
    ox, oy, nx, ny = cell_grid(page)
    used = np.zeros((max(nx, 0), max(ny, 0)), dtype=bool)
    if nx < 1 or ny < 1:
        return used
    rec = record(scene)
    seg = _segments(rec, skip_groups=("page",))
    if len(seg):
        n = np.maximum(np.ceil(np.hypot(seg[:, 2] - seg[:, 0], seg[:, 3] - seg[:, 1]) / STEP_MM), 1).astype(int)
        t = np.concatenate([np.linspace(0.0, 1.0, k + 1) for k in n])
        rows = np.repeat(np.arange(len(seg)), n + 1)
        x = seg[rows, 0] + t * (seg[rows, 2] - seg[rows, 0])
        y = seg[rows, 1] + t * (seg[rows, 3] - seg[rows, 1])
        i, j = np.floor((x - ox) / CELL_MM).astype(int), np.floor((y - oy) / CELL_MM).astype(int)
        ok = (i >= 0) & (i < nx) & (j >= 0) & (j < ny)
        used[i[ok], j[ok]] = True
    for c in rec.calls:
        if c.kind != "text":
            continue
        bx0, by0, bx1, by1 = label_bbox(c.data)
        i0, i1 = max(int((bx0 - ox) // CELL_MM), 0), min(int((bx1 - ox) // CELL_MM), nx - 1)
        j0, j1 = max(int((by0 - oy) // CELL_MM), 0), min(int((by1 - oy) // CELL_MM), ny - 1)
        if i0 <= i1 and j0 <= j1:
            used[i0:i1 + 1, j0:j1 + 1] = True
    return used


def clashes(scenes: list[Scene]) -> int:
    """How many texts of the ``scenes`` (parts of one sheet, together) a line crosses or another text covers
    (the measure's two faults of lettering, :func:`~graphmethods.sheets.engine.quality.measure`): a
    division that squeezes a part so that its lettering clashes is no division to keep.

    >>> from graphmethods.scene import Line, Page, Scene, Text
    >>> clashes([Scene(Page("A4"), (Text((50, 50), "M", name="t"),)), Scene(Page("A4"), (Line((40, 49), (90, 49)),))])
    1
    """
    recs = [record(s) for s in scenes]
    labels = [c.data for rec in recs for c in rec.calls if c.kind == "text"]
    if not labels:
        return 0
    glyphs = np.array([glyph_box(lab) for lab in labels], dtype=float).reshape(-1, 4)
    seg = np.concatenate([_segments(rec) for rec in recs]).reshape(-1, 4)
    hit = np.zeros(len(labels), dtype=bool)
    for chunk in range(0, len(seg), 4000):
        hit |= segments_hit_boxes(seg[chunk:chunk + 4000], glyphs).any(axis=1)
    boxes = np.array([label_bbox(lab) for lab in labels], dtype=float).reshape(-1, 4)
    ox = np.minimum(glyphs[:, None, 2], glyphs[None, :, 2]) - np.maximum(glyphs[:, None, 0], glyphs[None, :, 0])
    oy = np.minimum(boxes[:, None, 3], boxes[None, :, 3]) - np.maximum(boxes[:, None, 1], boxes[None, :, 1])
    return int(hit.sum()) + int(np.triu((ox > OVERLAP_MM) & (oy > OVERLAP_MM), k=1).sum())


def filled(scenes: list[Scene], page: Page) -> np.ndarray:
    """The cells of ``page``'s grid (bool nx × ny) the ink of the ``scenes`` (parts of one sheet) touches
    together; ``.sum()`` counts them."""
    ox, oy, nx, ny = cell_grid(page)
    used = np.zeros((max(nx, 0), max(ny, 0)), dtype=bool)
    for s in scenes:
        used |= ink_cells(s, page)
    return used


__all__ = ["STEP_MM", "cell_grid", "clashes", "filled", "ink_cells"]
