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

:func:`faults` turns a measure into the list of what breaks the standard for the page's format.

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

import numpy as np

from graphmethods.render.recording import RecordingRenderer, record
from graphmethods.scene import markup
from graphmethods.scene.elements import CAP, label_bbox
from graphmethods.scene.primitives import Label
from graphmethods.scene.scene import Scene
from graphmethods.sheets.engine.labels import circle_points
from graphmethods.sheets.engine.lettering import is_course_sheet, is_slide, lettering
from graphmethods.sheets.layout import segments_hit_boxes

#: the cell of the empty-space measure (mm)
CELL_MM = 20.0
#: most empty share of a course sheet's cells
EMPTY_MAX = 0.5
#: two texts overlap when they share more than this both across and down (mm)
OVERLAP_MM = 0.3
#: a power of ten this much smaller than its neighbours is round-off printed as working
NOISE_RATIO = 1e-9


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


def _segments(rec: RecordingRenderer, *, skip_groups: Sequence[str] = ()) -> np.ndarray:
    rows: list[tuple[float, float, float, float]] = []
    for c in rec.calls:
        if any(g in skip_groups for g in c.groups):
            continue
        if c.kind == "path":
            pts, closed = c.data
            pts = list(pts) + ([pts[0]] if closed and pts else [])
        elif c.kind == "polygon":
            pts = list(c.data) + [c.data[0]] if c.data else []
        elif c.kind == "circle":
            cx, cy, r = c.data
            pts = circle_points(cx, cy, r, n=16)
        else:
            continue
        rows.extend((a[0], a[1], b[0], b[1]) for a, b in zip(pts, pts[1:]))
    return np.asarray(rows, dtype=float).reshape(-1, 4)


def glyph_box(lab: Label) -> tuple[float, float, float, float]:
    """The box of a label's glyphs that a line must not cross: capitals' height over the baseline (a lowered
    subscript's depth under it), 0.1 mm in from either end."""
    x0, _, x1, _ = label_bbox(lab)
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


def _empty_share(rec: RecordingRenderer, inner: tuple[float, float, float, float], seg: np.ndarray,
                 boxes: np.ndarray) -> float:
    x0, y0, x1, y1 = inner
    nx, ny = int((x1 - x0) // CELL_MM), int((y1 - y0) // CELL_MM)
    if nx < 1 or ny < 1:
        return 0.0
    ox, oy = x0 + ((x1 - x0) - nx * CELL_MM) / 2, y0 + ((y1 - y0) - ny * CELL_MM) / 2
    i, j = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    cells = np.column_stack((ox + i.ravel() * CELL_MM, oy + j.ravel() * CELL_MM,
                             ox + (i.ravel() + 1) * CELL_MM, oy + (j.ravel() + 1) * CELL_MM))
    used = np.zeros(len(cells), dtype=bool)
    for chunk in range(0, len(seg), 4000):
        used |= segments_hit_boxes(seg[chunk:chunk + 4000], cells).any(axis=1)
    if len(boxes):
        used |= ((cells[:, None, 0] < boxes[None, :, 2]) & (boxes[None, :, 0] < cells[:, None, 2])
                 & (cells[:, None, 1] < boxes[None, :, 3]) & (boxes[None, :, 1] < cells[:, None, 3])).any(axis=1)
    return float(1.0 - used.mean())


def measure(scene: Scene) -> Quality:
    """The quality of a scene as drawn (see the module docstring)."""
    rec = record(scene)
    labels = [c.data for c in rec.calls if c.kind == "text"]
    seg_all = _segments(rec)
    frame_free = _segments(rec, skip_groups=("page",))

    glyphs = np.array([glyph_box(lab) for lab in labels], dtype=float).reshape(-1, 4)
    crossed: list[str] = []
    if len(labels) and len(seg_all):
        hit = np.zeros(len(labels), dtype=bool)
        for chunk in range(0, len(seg_all), 4000):
            hit |= segments_hit_boxes(seg_all[chunk:chunk + 4000], glyphs).any(axis=1)
        crossed = [labels[k].text for k in np.flatnonzero(hit)]
    boxes = np.array([label_bbox(lab) for lab in labels], dtype=float).reshape(-1, 4)
    overlaps: list[str] = []
    if len(labels) > 1:
        ox = np.minimum(glyphs[:, None, 2], glyphs[None, :, 2]) - np.maximum(glyphs[:, None, 0], glyphs[None, :, 0])
        oy = np.minimum(boxes[:, None, 3], boxes[None, :, 3]) - np.maximum(boxes[:, None, 1], boxes[None, :, 1])
        for a, b in zip(*np.nonzero(np.triu((ox > OVERLAP_MM) & (oy > OVERLAP_MM), k=1))):
            overlaps.append(f"{labels[a].text!r} on {labels[b].text!r}")
    sizes = [lab.size_mm for lab in labels if any(s == 0 and t.strip() for t, s in lab.runs)]
    noise = [t for t in (_noise(lab) for lab in labels) if t]

    judged = scene.page.frame or is_slide(scene.page)      # a framed sheet's frame, or a slide inside its margins
    empty = _empty_share(rec, scene.page.inner_box(), frame_free, boxes) if judged else 0.0
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


__all__ = ["CELL_MM", "EMPTY_MAX", "Quality", "faults", "glyph_box", "measure"]
