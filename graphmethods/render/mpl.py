"""PDF and PNG output through matplotlib (Agg), the only module importing matplotlib.

matplotlib is imported when a function here is called, never at import time, and
no global state is touched: figures are built with ``matplotlib.figure.Figure``
and the Agg/PDF canvases directly (no pyplot, no ``matplotlib.use``). PDF output is
deterministic (no creation date, same bytes twice); several scenes make a
multi-page PDF.

Fonts: Greek and Cyrillic draw with matplotlib's default DejaVu Sans. Chinese needs
a CJK font; :func:`find_cjk_font` looks for one (``GRAPHMETHODS_CJK_FONT``, the
system's fonts, then the ``mplfonts`` package, which ships Noto Sans CJK SC under the
SIL Open Font License). When there is none, a single :class:`CJKFontWarning` says so
and how to get one, instead of silently drawing empty boxes.

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
import warnings

from graphmethods.render.base import draw
from graphmethods.render.files import write_atomic
from graphmethods.scene.markup import SCRIPT_SCALE, SUB_SHIFT, SUP_SHIFT, has_cjk

PT_PER_MM = 72.0 / 25.4
BASE_FAMILY = "DejaVu Sans"

#: CJK families tried first, by name (the system's, Windows', macOS')
CJK_FAMILIES = (
    "Noto Sans CJK SC", "Noto Sans SC", "Source Han Sans SC", "Source Han Sans CN", "Noto Sans CJK JP",
    "WenQuanYi Zen Hei", "WenQuanYi Micro Hei", "Microsoft YaHei", "SimHei", "PingFang SC", "Heiti SC",
    "Hiragino Sans GB", "Droid Sans Fallback", "AR PL UMing CN", "AR PL UKai CN",
)
_PROBE = "盈亏功能量指示图"

_warned = False


class CJKFontWarning(UserWarning):
    """No font with Chinese characters was found; Chinese text would draw as empty boxes."""


def _covers(path: str) -> bool:
    from matplotlib import ft2font

    try:
        cmap = ft2font.FT2Font(path).get_charmap()
    except Exception:  # unreadable font file: not ours to fix
        return False
    if not all(ord(c) in cmap for c in _PROBE):
        return False
    # a last-resort font maps every character of a block to one placeholder glyph
    return len({cmap[ord(c)] for c in _PROBE}) == len(set(_PROBE))


@functools.lru_cache(maxsize=1)
def find_cjk_font() -> str | None:
    """Path of a font that covers Chinese, or None; registered with matplotlib's font manager.

    Looks, in order, at the environment variable ``GRAPHMETHODS_CJK_FONT`` (a font
    file), the system's fonts known to matplotlib (by family name, then by the
    characters they cover), and the font shipped by the ``mplfonts`` package
    (``pip install 'graphmethods[cjk]'``; Noto Sans CJK SC, SIL OFL).
    """
    from matplotlib import font_manager

    candidates = []
    env = os.environ.get("GRAPHMETHODS_CJK_FONT", "").strip()
    if env:
        candidates.append(env)
    entries = list(font_manager.fontManager.ttflist)
    by_name = {}
    for e in entries:
        by_name.setdefault(e.name, e.fname)
    candidates += [by_name[n] for n in CJK_FAMILIES if n in by_name]
    candidates += sorted({e.fname for e in entries if e.name not in by_name or by_name[e.name] == e.fname})
    try:
        import importlib.util

        spec = importlib.util.find_spec("mplfonts")
    except (ImportError, ValueError):
        spec = None
    if spec is not None and spec.submodule_search_locations:
        for loc in spec.submodule_search_locations:
            candidates.append(str(pathlib.Path(loc) / "fonts" / "NotoSansCJKsc-Regular.otf"))
    if env and not (os.path.isfile(env) and _covers(env)):
        warnings.warn(f"graphmethods: GRAPHMETHODS_CJK_FONT={env} is not a font file with Chinese characters; "
                      f"looking for another", CJKFontWarning, stacklevel=2)
    for path in candidates:
        if path and os.path.isfile(path) and _covers(path):
            font_manager.fontManager.addfont(path)
            return path
    return None


@functools.lru_cache(maxsize=1)
def _cjk_family() -> str | None:
    path = find_cjk_font()
    if path is None:
        return None
    from matplotlib.font_manager import FontProperties

    return FontProperties(fname=path).get_name()


def _warn_no_cjk() -> None:
    global _warned
    if _warned:
        return
    _warned = True
    warnings.warn(
        "graphmethods: no font with Chinese characters was found, so the Chinese text of this figure cannot be "
        "drawn in PNG/PDF (it would show as empty boxes). Get one with `pip install 'graphmethods[cjk]'` (mplfonts: Noto Sans CJK SC, "
        "SIL Open Font License), or install your system's Noto CJK fonts (Debian/Ubuntu: fonts-noto-cjk), or set "
        "GRAPHMETHODS_CJK_FONT=/path/to/font.otf. SVG output is not affected: the viewer chooses the font.",
        CJKFontWarning, stacklevel=3)


@functools.lru_cache(maxsize=None)
def _font(size_pt: float, family: tuple, weight: str):
    """FontProperties, one object per (size, family, weight): matplotlib caches its fonts by them."""
    from matplotlib.font_manager import FontProperties

    return FontProperties(family=list(family), size=size_pt, weight=weight)


_EXTENTS: dict = {}


def _extent(renderer, text: str, prop) -> tuple[float, float, float]:
    """(width, height, descent) of plain text in the renderer's units, cached per renderer kind and dpi."""
    key = (type(renderer).__name__, getattr(renderer, "dpi", 72.0), text, id(prop))
    got = _EXTENTS.get(key)
    if got is None:
        got = _EXTENTS[key] = renderer.get_text_width_height_descent(text, prop, ismath=False)
    return got


@functools.lru_cache(maxsize=None)
def _label_batch_class():
    """An Artist drawing many labels straight through ``renderer.draw_text``.

    matplotlib's Text artist lays out each string anew (about 1 ms a label); the labels of a
    scene need none of that: one line, baseline-anchored, no rotation, no mathtext. A batch
    keeps the painter's order: a new one starts after any other primitive.
    """
    from matplotlib.artist import Artist

    class LabelBatch(Artist):
        def __init__(self, *, zorder):
            super().__init__()
            self.set_zorder(zorder)
            self.items = []

        def draw(self, renderer):
            if not self.get_visible() or not self.items:
                return
            trans = self.axes.transData
            xy = trans.transform([(x, y) for x, y, *_ in self.items])
            if renderer.flipy():               # Agg counts y down from the top, as Text.draw does
                xy[:, 1] = renderer.get_canvas_width_height()[1] - xy[:, 1]
            gc = renderer.new_gc()
            try:
                for (x, y, text, prop, color, ha), (px, py) in zip(self.items, xy):
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
        self.fig = self.ax = None
        self._z = 0
        self._renderer = None
        self._families = [BASE_FAMILY]
        self._labels = None            # the batch of labels being filled (None after other primitives)
        self._lines: list = []         # consecutive paths, drawn as one LineCollection
        self._lines_z = 0

    def begin(self, width_mm, height_mm, *, title, name):
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        self.fig = Figure(figsize=(width_mm / 25.4, height_mm / 25.4), dpi=self.dpi)
        FigureCanvasAgg(self.fig)
        self.ax = self.fig.add_axes((0, 0, 1, 1))
        self.ax.set_xlim(0, width_mm)
        self.ax.set_ylim(height_mm, 0)
        self.ax.set_axis_off()
        self._renderer = self.fig.canvas.get_renderer()

    def begin_group(self, id):
        pass

    def end_group(self):
        pass

    def _zorder(self) -> int:
        self._z += 1
        self._labels = None            # whatever comes next is drawn above this primitive
        return self._z

    @staticmethod
    def _dashes(style):
        lw = max(style.width_mm * PT_PER_MM, 1e-6)
        if not style.dash:
            return "solid"
        # matplotlib scales dash patterns by the line width: undo that so dashes are in mm
        return (0, tuple(d * PT_PER_MM / lw for d in style.dash))

    def path(self, points, style, closed):
        if not style.stroke or style.width_mm <= 0:
            return
        pts = list(points) + ([points[0]] if closed else [])
        if not self._lines:
            self._lines_z = self._zorder()
        self._lines.append((pts, style.width_mm * PT_PER_MM, style.stroke, self._dashes(style)))

    def _flush_lines(self):
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

    def polygon(self, points, style):
        from matplotlib.patches import Polygon

        self._flush_lines()
        stroke = style.stroke if (style.stroke and style.width_mm > 0) else "none"
        patch = Polygon(points, closed=True, facecolor=style.fill or "none", edgecolor=stroke,
                        linewidth=style.width_mm * PT_PER_MM if stroke != "none" else 0.0, zorder=self._zorder())
        self.ax.add_patch(patch)

    def circle(self, cx, cy, r, style):
        from matplotlib.patches import Circle

        self._flush_lines()
        stroke = style.stroke if (style.stroke and style.width_mm > 0) else "none"
        patch = Circle((cx, cy), r, facecolor=style.fill or "none", edgecolor=stroke,
                       linewidth=style.width_mm * PT_PER_MM if stroke != "none" else 0.0, zorder=self._zorder())
        self.ax.add_patch(patch)

    def _family(self, text: str):
        if has_cjk(text):
            fam = _cjk_family()
            if fam is None:
                _warn_no_cjk()
                return [BASE_FAMILY]
            return [BASE_FAMILY, fam]
        return [BASE_FAMILY]

    def _width_mm(self, text: str, size_mm: float, bold: bool, family) -> float:
        prop = _font(size_mm * PT_PER_MM, tuple(family), "bold" if bold else "normal")
        return _extent(self._renderer, text, prop)[0] / self.dpi * 25.4

    def _add_label(self, x, y, text, size_mm, family, weight, color, ha):
        self._flush_lines()
        if self._labels is None:
            self._labels = _label_batch_class()(zorder=self._zorder())
            self.ax.add_artist(self._labels)
        self._labels.items.append((x, y, text, _font(size_mm * PT_PER_MM, tuple(family), weight), color, ha))

    def text(self, label):
        family = self._family(label.text)
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
            dy = {0: 0.0, -1: SUB_SHIFT * label.size_mm, 1: -SUP_SHIFT * label.size_mm}[shift]
            self._add_label(x, label.y + dy, chunk, sz, family, weight, label.color, "left")
            x += w

    def end(self):
        self._flush_lines()
        return self.fig


def figure(scene, *, dpi: float = 150.0):
    """The scene drawn on a matplotlib ``Figure`` (page size in inches = mm / 25.4)."""
    with warnings.catch_warnings():
        # one clear CJKFontWarning replaces matplotlib's warning per missing glyph
        warnings.filterwarnings("ignore", message=r"Glyph \d+ .*missing from", category=UserWarning)
        return draw(scene, MplRenderer(dpi=dpi))


_PDF_METADATA = {"CreationDate": None, "ModDate": None, "Producer": None, "Creator": "graphmethods"}


def to_png_bytes(scene, *, dpi: float = 200.0) -> bytes:
    """PNG of ``scene`` at ``dpi`` (deterministic; no software or date metadata)."""
    fig = figure(scene, dpi=dpi)
    buf = io.BytesIO()
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=r"Glyph \d+ .*missing from", category=UserWarning)
        fig.savefig(buf, format="png", dpi=dpi, metadata={"Software": None})
    return buf.getvalue()


def to_pdf_bytes(scenes) -> bytes:
    """PDF with one page per scene (a single scene is allowed); deterministic bytes."""
    from matplotlib.backends.backend_pdf import PdfPages

    if not isinstance(scenes, (list, tuple)):
        scenes = [scenes]
    buf = io.BytesIO()
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=r"Glyph \d+ .*missing from", category=UserWarning)
        with PdfPages(buf, metadata=dict(_PDF_METADATA)) as pdf:
            for sc in scenes:
                pdf.savefig(figure(sc))
    return buf.getvalue()


def save_png(scene, path, *, dpi: float = 200.0, overwrite: bool = False):
    """Write ``scene`` as PNG atomically; refuses to replace a file unless ``overwrite``."""
    return write_atomic(path, to_png_bytes(scene, dpi=dpi), overwrite=overwrite)


def save_pdf(scenes, path, *, overwrite: bool = False):
    """Write one scene or several (one page each) as PDF atomically; refuses to replace unless ``overwrite``."""
    return write_atomic(path, to_pdf_bytes(scenes), overwrite=overwrite)
