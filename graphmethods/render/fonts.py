"""Font files and their glyphs, through matplotlib's FreeType wrapper (imported lazily).

Two renderers draw text themselves: :mod:`graphmethods.render.mpl` (PNG, by family
name) and :mod:`graphmethods.render.pdf` (PDF, glyph by glyph). Both take their fonts
from here: DejaVu Sans (matplotlib's own font: Latin, Greek, Cyrillic) and, for
Chinese, a CJK font found by :func:`find_cjk_font` (``GRAPHMETHODS_CJK_FONT``, the
system's fonts, then the ``mplfonts`` package, which ships Noto Sans CJK SC under the
SIL Open Font License). When there is none, a single :class:`CJKFontWarning` says so
and how to get one, instead of silently drawing empty boxes.

A :class:`Face` gives what a PDF needs of a font file, in font units: the glyph of a
character, advance widths, pair kerning and outlines.

>>> face = faces("M_d", bold=False)[0]
>>> face.units_per_em, face.advance(face.glyph("M"))
(2048, 1767)
"""

from __future__ import annotations

import functools
import os
import pathlib
import warnings

from graphmethods.scene.markup import has_cjk

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
def cjk_family() -> str | None:
    path = find_cjk_font()
    if path is None:
        return None
    from matplotlib.font_manager import FontProperties

    return FontProperties(fname=path).get_name()


def warn_no_cjk() -> None:
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


def families(text: str) -> list[str]:
    """Font families for ``text``: DejaVu Sans, then the CJK font when the text has Chinese (or a warning)."""
    if has_cjk(text):
        fam = cjk_family()
        if fam is None:
            warn_no_cjk()
            return [BASE_FAMILY]
        return [BASE_FAMILY, fam]
    return [BASE_FAMILY]


def _flag(enum: str, member: str, old: str):
    """A FreeType flag by its matplotlib >= 3.10 enum name, or its older module constant."""
    from matplotlib import ft2font

    return getattr(getattr(ft2font, enum), member) if hasattr(ft2font, enum) else getattr(ft2font, old)


class Face:
    """One font file: glyphs of characters, advances, kerning and outlines in font units.

    Parameters
    ----------
    path : str
        A TrueType or OpenType font file.

    Examples
    --------
    >>> face = faces("AV", bold=False)[0]
    >>> a, v = face.glyph("A"), face.glyph("V")
    >>> face.kerning(a, v) < 0 < face.advance(a)          # A and V tuck together
    True
    >>> face.outline(a)[1][:4]                            # bounding box (font units, y up)
    (16, 0, 1384, 1493)
    """

    def __init__(self, path: str):
        import matplotlib
        from matplotlib import ft2font

        self.path = path
        if tuple(int(v) for v in matplotlib.__version__.split(".")[:2]) < (3, 11):
            # before 3.11 a face squeezes x by its hinting factor (8 by default): outlines, boxes, kerning
            self._ft = ft2font.FT2Font(path, hinting_factor=1)
        else:
            self._ft = ft2font.FT2Font(path)
        self.units_per_em = int(self._ft.units_per_EM)
        self._cmap = self._ft.get_charmap()
        self._no_scale = _flag("LoadFlags", "NO_SCALE", "LOAD_NO_SCALE")
        self._unscaled = _flag("Kerning", "UNSCALED", "KERNING_UNSCALED")
        self._glyphs: dict[int, tuple[int, tuple[int, int, int, int], str]] = {}
        self._kerns: dict[tuple[int, int], int] = {}

    def glyph(self, char: str) -> int | None:
        """Glyph index of ``char``, or None when the font has none."""
        return self._cmap.get(ord(char)) or None

    def _load(self, gid: int):
        got = self._glyphs.get(gid)
        if got is None:
            g = self._ft.load_glyph(gid, self._no_scale)
            verts, codes = self._ft.get_path()
            verts = verts * 64.0                      # FreeType's 26.6 fixed point back to font units
            bbox = tuple(int(b) for b in g.bbox)
            if len(verts) and abs(verts[:, 1].max() + bbox[1]) < abs(verts[:, 1].max() - bbox[3]):
                verts[:, 1] = -verts[:, 1]            # a matplotlib that hands outlines over y down
            got = self._glyphs[gid] = (int(g.horiAdvance), bbox, _outline_ops(verts, codes))
        return got

    def advance(self, gid: int) -> int:
        """Advance width of glyph ``gid`` in font units."""
        return self._load(gid)[0]

    def kerning(self, left: int, right: int) -> int:
        """Pair kerning between two glyphs in font units (0 when the font has none)."""
        key = (left, right)
        k = self._kerns.get(key)
        if k is None:
            k = self._kerns[key] = int(self._ft.get_kerning(left, right, self._unscaled))
        return k

    def outline(self, gid: int) -> tuple[str, tuple[int, int, int, int]]:
        """PDF path operators of glyph ``gid`` (font units, y up, filled non-zero) and its bounding box."""
        _, bbox, ops = self._load(gid)
        return ops, bbox


def _num(x: float) -> str:
    s = f"{x:.2f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _outline_ops(verts, codes) -> str:
    """FreeType's outline (matplotlib path codes: 1 move, 2 line, 3 quadratic, 4 cubic, 79 close)
    as PDF operators; quadratic pieces become the equal cubics."""
    out = []
    i, n = 0, len(codes)
    cur = start = (0.0, 0.0)
    while i < n:
        c = codes[i]
        if c == 1:
            cur = start = (verts[i][0], verts[i][1])
            out.append(f"{_num(cur[0])} {_num(cur[1])} m")
            i += 1
        elif c == 2:
            cur = (verts[i][0], verts[i][1])
            out.append(f"{_num(cur[0])} {_num(cur[1])} l")
            i += 1
        elif c == 3:
            (qx, qy), (x, y) = verts[i], verts[i + 1]
            c1 = (cur[0] + 2.0 / 3.0 * (qx - cur[0]), cur[1] + 2.0 / 3.0 * (qy - cur[1]))
            c2 = (x + 2.0 / 3.0 * (qx - x), y + 2.0 / 3.0 * (qy - y))
            out.append(" ".join(_num(v) for v in (*c1, *c2, x, y)) + " c")
            cur = (x, y)
            i += 2
        elif c == 4:
            pts = verts[i:i + 3]
            out.append(" ".join(_num(v) for p in pts for v in p) + " c")
            cur = (pts[2][0], pts[2][1])
            i += 3
        else:                       # CLOSEPOLY (its vertex is ignored) or STOP
            out.append("h")
            cur = start
            i += 1
    return " ".join(out)


@functools.lru_cache(maxsize=None)
def _face(path: str) -> Face:
    return Face(path)


@functools.lru_cache(maxsize=None)
def _base_path(bold: bool) -> str:
    from matplotlib.font_manager import FontProperties, findfont

    return findfont(FontProperties(family=BASE_FAMILY, weight="bold" if bold else "normal"))


def faces(text: str, *, bold: bool) -> tuple[Face, ...]:
    """The faces that draw ``text``, first choice first: DejaVu Sans (bold or regular), then the CJK font
    when the text has Chinese. CJK fonts rarely ship a bold face, so Chinese text is drawn regular."""
    if has_cjk(text):
        path = find_cjk_font()
        if path is None:
            warn_no_cjk()
            return (_face(_base_path(bold)),)
        return (_face(_base_path(False)), _face(path))
    return (_face(_base_path(bold)),)
