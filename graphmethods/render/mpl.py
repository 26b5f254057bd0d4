"""PNG output (and figures for notebooks) through matplotlib's Agg canvas.

matplotlib is imported when a function here is called, never at import time, and
no global state is touched: figures are built with ``matplotlib.figure.Figure``
and the Agg canvas directly (no pyplot, no ``matplotlib.use``). PNG output is
deterministic (no software or date metadata). PDF is written by
:mod:`graphmethods.render.pdf`; both take their fonts from
:mod:`graphmethods.render.fonts` (DejaVu Sans; the Simplified Chinese face of a CJK
font for Chinese). Text that no font can draw is refused with
:class:`~graphmethods.errors.MissingFontError` before any file is written.

>>> from graphmethods.scene import Scene, Page, Text
>>> png = to_png_bytes(Scene(Page("A4"), (Text((20, 20), "ψ_{max} = 30°; M_д"),)), dpi=30)
>>> png[:8] == b"\\x89PNG\\r\\n\\x1a\\n"
True
"""

from __future__ import annotations

import functools
import io
import os
import pathlib
from collections.abc import Sequence
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from graphmethods.render.base import draw
from graphmethods.render.files import write_atomic
from graphmethods.render.fonts import check_drawable, check_scene, families, find_cjk_font  # noqa: F401
from graphmethods.scene.markup import SCRIPT_SCALE, baseline_shift_mm
from graphmethods.scene.primitives import XY, Label, Style
from graphmethods.scene.scene import Scene

if TYPE_CHECKING:                      # matplotlib is imported only when a figure is drawn
    from matplotlib.axes import Axes
    from matplotlib.backend_bases import RendererBase
    from matplotlib.figure import Figure
    from matplotlib.font_manager import FontProperties

PT_PER_MM = 72.0 / 25.4

@functools.cache
def _font(size_pt: float, family: tuple[str, ...], weight: str) -> FontProperties:
    """FontProperties, one object per (size, family, weight): matplotlib caches its fonts by them."""
    from matplotlib.font_manager import FontProperties

    return FontProperties(family=list(family), size=size_pt, weight=weight)


_EXTENTS: dict[tuple[str, float, str, int], tuple[float, float, float]] = {}


def _extent(renderer: RendererBase, text: str, prop: FontProperties) -> tuple[float, float, float]:
    """(width, height, descent) of plain text in the renderer's units, cached per renderer kind and dpi."""
    key = (type(renderer).__name__, getattr(renderer, "dpi", 72.0), text, id(prop))
    got = _EXTENTS.get(key)
    if got is None:
        w, h, d = renderer.get_text_width_height_descent(text, prop, ismath=False)
        got = _EXTENTS[key] = (float(w), float(h), float(d))
    return got


@functools.cache
def _label_batch_class() -> Any:                   # the Artist subclass below, made on first use
    """An Artist drawing many labels straight through ``renderer.draw_text``.

    matplotlib's Text artist lays out each string anew (about 1 ms a label); the labels of a
    scene need none of that: one line, baseline-anchored, no rotation, no mathtext. A batch
    keeps the painter's order: a new one starts after any other primitive.
    """
    from matplotlib.artist import Artist

    class LabelBatch(Artist):
        def __init__(self, *, zorder: float) -> None:
            super().__init__()
            self.set_zorder(zorder)
            self.items: list[tuple[float, float, str, FontProperties, str, str]] = []

        def draw(self, renderer: RendererBase) -> None:
            if not self.get_visible() or not self.items:
                return
            assert self.axes is not None             # added to the page's axes before drawing
            trans = self.axes.transData
            xy = trans.transform([(x, y) for x, y, *_ in self.items])
            if renderer.flipy():               # Agg counts y down from the top, as Text.draw does
                xy[:, 1] = renderer.get_canvas_width_height()[1] - xy[:, 1]
            gc = renderer.new_gc()
            try:
                for (_x, _y, text, prop, color, ha), (px, py) in zip(self.items, xy):
                    if ha != "left":
                        w = _extent(renderer, text, prop)[0]
                        px -= w if ha == "right" else w / 2.0
                    gc.set_foreground(color)
                    renderer.draw_text(gc, px, py, text, prop, 0.0, ismath=False)
            finally:
                gc.restore()

    return LabelBatch


class MplRenderer:
    """A :class:`~graphmethods.render.base.Renderer` drawing onto a matplotlib Figure in mm."""

    def __init__(self, *, dpi: float = 150.0):
        self.dpi = float(dpi)
        self.fig: Figure                  # set by begin()
        self.ax: Axes
        self._renderer: RendererBase
        self._z = 0
        self._labels: Any = None       # the batch of labels being filled (None after other primitives)
        # consecutive paths, drawn as one LineCollection: points, width (pt), colour, dashes
        self._lines: list[tuple[list[XY], float, str, str | tuple[float, tuple[float, ...]]]] = []
        self._lines_z = 0

    def begin(self, width_mm: float, height_mm: float, *, title: str, name: str) -> None:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        self.fig = Figure(figsize=(width_mm / 25.4, height_mm / 25.4), dpi=self.dpi)
        canvas = FigureCanvasAgg(self.fig)       # the figure's canvas from here on
        self.ax = self.fig.add_axes((0, 0, 1, 1))
        self.ax.set_xlim(0, width_mm)
        self.ax.set_ylim(height_mm, 0)
        self.ax.set_axis_off()
        # matplotlib leaves FigureCanvasAgg.get_renderer unannotated (it returns a RendererAgg)
        self._renderer = canvas.get_renderer()  # type: ignore[no-untyped-call]

    def begin_group(self, id: str) -> None:
        pass

    def end_group(self) -> None:
        pass

    def _zorder(self) -> int:
        self._z += 1
        self._labels = None            # whatever comes next is drawn above this primitive
        return self._z

    @staticmethod
    def _dashes(style: Style) -> str | tuple[float, tuple[float, ...]]:
        lw = max(style.width_mm * PT_PER_MM, 1e-6)
        if not style.dash:
            return "solid"
        # matplotlib scales dash patterns by the line width: undo that so dashes are in mm
        return (0, tuple(d * PT_PER_MM / lw for d in style.dash))

    def path(self, points: tuple[XY, ...], style: Style, closed: bool) -> None:
        if not style.stroke or style.width_mm <= 0:
            return
        pts = list(points) + ([points[0]] if closed else [])
        if not self._lines:
            self._lines_z = self._zorder()
        self._lines.append((pts, style.width_mm * PT_PER_MM, style.stroke, self._dashes(style)))

    def _flush_lines(self) -> None:
        """Draw the paths gathered so far as one LineCollection (one artist, not one per path)."""
        if not self._lines:
            return
        from matplotlib.collections import LineCollection

        segs, widths, colors, styles = zip(*self._lines)
        self.ax.add_collection(LineCollection(list(segs), linewidths=list(widths), colors=list(colors),
                                              linestyles=list(styles),
                                              capstyle="butt", joinstyle="round", zorder=self._lines_z),
                               autolim=False)
        self._lines = []

    def polygon(self, points: tuple[XY, ...], style: Style) -> None:
        from matplotlib.patches import Polygon

        self._flush_lines()
        stroke = style.stroke if (style.stroke and style.width_mm > 0) else "none"
        patch = Polygon(points, closed=True, facecolor=style.fill or "none", edgecolor=stroke,
                        linewidth=style.width_mm * PT_PER_MM if stroke != "none" else 0.0, zorder=self._zorder())
        self.ax.add_patch(patch)

    def circle(self, cx: float, cy: float, r: float, style: Style) -> None:
        from matplotlib.patches import Circle

        self._flush_lines()
        stroke = style.stroke if (style.stroke and style.width_mm > 0) else "none"
        patch = Circle((cx, cy), r, facecolor=style.fill or "none", edgecolor=stroke,
                       linewidth=style.width_mm * PT_PER_MM if stroke != "none" else 0.0, zorder=self._zorder())
        self.ax.add_patch(patch)

    def _width_mm(self, text: str, size_mm: float, bold: bool, family: Sequence[str]) -> float:
        prop = _font(size_mm * PT_PER_MM, tuple(family), "bold" if bold else "normal")
        return _extent(self._renderer, text, prop)[0] / self.dpi * 25.4

    def _add_label(self, x: float, y: float, text: str, size_mm: float, family: Sequence[str], weight: str,
                   color: str, ha: str) -> None:
        self._flush_lines()
        if self._labels is None:
            self._labels = _label_batch_class()(zorder=self._zorder())
            self.ax.add_artist(self._labels)
        self._labels.items.append((x, y, text, _font(size_mm * PT_PER_MM, tuple(family), weight), color, ha))

    def text(self, label: Label) -> None:
        if label.stretch != 1.0:
            # matplotlib's text has no horizontal scale: the PNG preview sets condensed lettering smaller
            # to the same width (SVG, PDF and DXF condense it at its height)
            label = replace(label, size_mm=label.size_mm * label.stretch, stretch=1.0)
        for chunk, _ in label.runs:
            check_drawable(chunk, label.bold)
        family = families(label.text)
        # CJK fonts rarely ship a bold face; a half-bold line (Latin bold, CJK regular) looks wrong
        weight = "bold" if label.bold and len(family) == 1 else "normal"
        runs = label.runs
        if len(runs) == 1 and runs[0][1] == 0:
            self._add_label(label.x, label.y, runs[0][0], label.size_mm, family, weight, label.color,
                            {"start": "left", "middle": "center", "end": "right"}[label.anchor])
            return
        sizes = [label.size_mm * (1.0 if s == 0 else SCRIPT_SCALE) for _, s in runs]
        widths = [self._width_mm(t, sz, weight == "bold", family) for (t, _), sz in zip(runs, sizes)]
        total = sum(widths)
        x = label.x - {"start": 0.0, "middle": total / 2, "end": total}[label.anchor]
        for (chunk, shift), sz, w in zip(runs, sizes, widths):
            dy = baseline_shift_mm(shift, label.size_mm)
            self._add_label(x, label.y + dy, chunk, sz, family, weight, label.color, "left")
            x += w

    def end(self) -> Figure:
        self._flush_lines()
        return self.fig


def figure(scene: Scene, *, dpi: float = 150.0) -> Figure:
    """The scene drawn on a matplotlib ``Figure`` (page size in inches = mm / 25.4).

    Raises
    ------
    MissingFontError
        If a label has characters no font draws (e.g. Chinese without a CJK font).
    """
    fig: Figure = draw(scene, MplRenderer(dpi=dpi))
    return fig


def to_png_bytes(scene: Scene, *, dpi: float = 200.0) -> bytes:
    """PNG of ``scene`` at ``dpi`` (deterministic; no software or date metadata)."""
    fig = figure(scene, dpi=dpi)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi, metadata={"Software": None})
    return buf.getvalue()


def save_png(scene: Scene, path: str | os.PathLike[str], *, dpi: float = 200.0,
             overwrite: bool = False) -> pathlib.Path:
    """Write ``scene`` as PNG atomically; refuses to replace a file unless ``overwrite``."""
    return write_atomic(path, to_png_bytes(scene, dpi=dpi), overwrite=overwrite)
