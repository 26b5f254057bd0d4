"""Font files and their glyphs: which faces draw PNG and PDF text, and the font programs a PDF embeds.

Two renderers draw text themselves: :mod:`graphmethods.render.mpl` (PNG, by family
name) and :mod:`graphmethods.render.pdf` (PDF, glyph by glyph, embedding subsets of
the font files). Both take their fonts from here:

- DejaVu Sans, matplotlib's own font (Latin, Greek, Cyrillic), regular and bold;
- for Chinese, the Simplified Chinese face of a CJK font, found by
  :func:`find_cjk_font`: the file in ``GRAPHMETHODS_CJK_FONT``, else the first of
  :data:`CJK_FAMILIES` that matplotlib knows (regular weight), else any font that
  covers Chinese, else the font of the ``mplfonts`` package
  (``pip install 'graphmethods[cjk]'``: Noto Sans CJK SC, SIL Open Font License). In a
  ``.ttc`` collection the face is chosen by name: Noto Sans CJK's first face is the
  Japanese one, whose 直, 骨, 与 differ from the Chinese.

When Chinese text is to be drawn and no font has it, matplotlib's font list is rebuilt
once (it may have been cached before the font was installed); if there is still none,
:class:`~graphmethods.errors.MissingFontError` says what to install or set. Text is
never drawn as empty boxes.

A :class:`Face` gives what a layout and a PDF need of a font face, in font units: the
glyph of a character, advance widths, pair kerning, the code a PDF shows it by, and a
subset of the font program. It reads them from the font file's bytes
(:mod:`graphmethods.render.sfnt`: the same numbers FreeType gives), once per process:
DejaVu Sans is found next to matplotlib without importing it, so a PDF of Latin, Greek
and Cyrillic text imports neither matplotlib nor fontTools; fontTools subsets CFF
outlines (Noto Sans CJK), and matplotlib's font list finds the CJK font.

>>> face = faces("M_d", bold=False)[0]
>>> face.units_per_em, face.advance(face.glyph("M"))
(2048, 1767)
"""

from __future__ import annotations

import functools
import hashlib
import io
import os
import pathlib
import re
from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from graphmethods.errors import MissingFontError
from graphmethods.render.sfnt import Sfnt, subset_truetype
from graphmethods.scene.markup import has_cjk

if TYPE_CHECKING:
    from graphmethods.scene.scene import Scene

BASE_FAMILY = "DejaVu Sans"

#: CJK families, first choice first (Linux, Windows, macOS names). Simplified Chinese faces come first;
#: the Japanese face of Noto Sans CJK is a last resort (its forms of 直, 骨, 与 are Japanese).
CJK_FAMILIES = (
    "Noto Sans CJK SC", "Noto Sans SC", "Source Han Sans SC", "Source Han Sans CN", "WenQuanYi Zen Hei",
    "WenQuanYi Micro Hei", "Microsoft YaHei", "SimHei", "PingFang SC", "Heiti SC", "Hiragino Sans GB",
    "Noto Serif CJK SC", "Source Han Serif SC", "AR PL UMing CN", "AR PL UKai CN", "Droid Sans Fallback",
    "Noto Sans CJK TC", "Noto Sans CJK HK", "Noto Sans CJK JP", "Noto Sans CJK KR",
)
_PROBE = "盈亏功能量指示图"

#: what to do when Chinese text cannot be drawn (the end of every such error message)
CJK_ADVICE = ("install a CJK font (Debian/Ubuntu: apt-get install fonts-noto-cjk; or pip install "
              "'graphmethods[cjk]'), or set GRAPHMETHODS_CJK_FONT=/path/to/font.otf; SVG output needs none")

_rebuilt = False


@dataclass(frozen=True)
class CJKFont:
    """The face that draws Chinese: a font file, the face's index in it (0 unless a ``.ttc``) and its family."""

    path: str
    index: int
    family: str


def _mpl_reads_collections() -> bool:
    """True on matplotlib >= 3.11: its font list and FreeType wrapper know every face of a ``.ttc``."""
    from matplotlib import font_manager

    return hasattr(font_manager, "FontPath")


def _sfnt(path: str, index: int = 0) -> Any:         # a fontTools TTFont (fontTools ships no types)
    """The face as a lazily read fontTools font (``index`` selects a face of a collection)."""
    from fontTools.ttLib import TTFont

    return TTFont(path, fontNumber=index, lazy=True, recalcTimestamp=False, recalcBBoxes=False)


@functools.cache
def _faces_in(path: str) -> tuple[tuple[str, int], ...]:
    """(family, weight class) of each face in a font file; () when it cannot be read."""
    from fontTools.ttLib import TTCollection

    try:
        with open(path, "rb") as fh:
            collection = fh.read(4) == b"ttcf"
        fonts = TTCollection(path, lazy=True).fonts if collection else [_sfnt(path)]
        out = []
        try:
            for f in fonts:
                name = f["name"]
                family = name.getDebugName(16) or name.getDebugName(1) or ""
                out.append((family, int(f["OS/2"].usWeightClass) if "OS/2" in f else 400))
        finally:
            fonts[0].close()              # the faces of a collection share one open file
        return tuple(out)
    except Exception:  # not a font file fontTools reads: not ours to fix, and not usable
        return ()


@functools.cache
def _usable(path: str, index: int) -> bool:
    """The face has distinct glyphs for Chinese characters and outlines a PDF can embed (TrueType or CFF)."""
    try:
        f = _sfnt(path, index)
        if "glyf" not in f and "CFF " not in f:
            return False
        cmap = f.getBestCmap() or {}
    except Exception:
        return False
    if not all(ord(c) in cmap for c in _PROBE):
        return False
    # a last-resort font maps every character of a block to one placeholder glyph
    return len({cmap[ord(c)] for c in _PROBE}) == len(set(_PROBE))


def _best_face(path: str, hint: int | None = None) -> tuple[str, int] | None:
    """The face of ``path`` to draw Chinese with: the earliest of :data:`CJK_FAMILIES`, regular weight;
    ``hint`` (the face matplotlib chose) breaks ties."""
    def rank(item: tuple[int, tuple[str, int]]) -> tuple[int, int, bool, int]:
        i, (family, weight) = item
        pos = CJK_FAMILIES.index(family) if family in CJK_FAMILIES else len(CJK_FAMILIES)
        return pos, abs(weight - 400), i != hint, i

    for i, _ in sorted(enumerate(_faces_in(path)), key=rank):
        if _usable(path, i):
            return path, i
    return None


def _covers(path: str) -> bool:
    """Quick test of the first face of a file (FreeType): has it the Chinese probe characters?"""
    from matplotlib import ft2font

    try:
        cmap = ft2font.FT2Font(path).get_charmap()
    except Exception:  # unreadable font file: not ours to fix
        return False
    return all(ord(c) in cmap for c in _PROBE)


def _lookup() -> tuple[str, int] | None:
    """(file, face index) of a CJK face, or None; no caching, no registering."""
    from matplotlib import font_manager as fm

    env = os.environ.get("GRAPHMETHODS_CJK_FONT", "").strip()
    if env:
        found = _best_face(env) if os.path.isfile(env) else None
        if found is None:
            raise MissingFontError(f"GRAPHMETHODS_CJK_FONT={env} is not a font file with Chinese characters "
                                   f"(TrueType or OpenType, .ttf/.otf/.ttc); give one, or unset it to use the "
                                   f"system's fonts")
        return found
    try:
        path = fm.findfont(fm.FontProperties(family=list(CJK_FAMILIES), weight="normal", style="normal"),
                           fallback_to_default=False)
    except ValueError:
        path = None
    if path:
        found = _best_face(str(path), getattr(path, "face_index", None))
        if found is not None:
            return found
    for fname in sorted({e.fname for e in fm.fontManager.ttflist}):
        if _covers(fname):
            found = _best_face(fname)
            if found is not None:
                return found
    shipped = _mplfonts_font()
    return (shipped, 0) if shipped is not None and _usable(shipped, 0) else None


def _mplfonts_font() -> str | None:
    """Noto Sans CJK SC as the ``mplfonts`` package ships it (``pip install 'graphmethods[cjk]'``), or None."""
    try:
        import importlib.util

        spec = importlib.util.find_spec("mplfonts")
    except (ImportError, ValueError):
        spec = None
    for loc in (spec.submodule_search_locations or []) if spec is not None else []:
        fname = pathlib.Path(loc) / "fonts" / "NotoSansCJKsc-Regular.otf"
        if fname.is_file():
            return str(fname)
    return None


def _rebuild_font_list() -> None:
    """matplotlib's font list made anew from the fonts installed now (and its cache file rewritten), in place,
    as matplotlib itself does when a cached font file has gone missing."""
    from matplotlib import font_manager as fm

    load = getattr(fm, "_load_fontmanager", None)
    new = load(try_read_cache=False) if load is not None else fm.FontManager()
    vars(fm.fontManager).update(vars(new))
    cached = getattr(fm.fontManager, "_findfont_cached", None)
    if cached is not None and hasattr(cached, "cache_clear"):
        cached.cache_clear()


def _extract_face(path: str, index: int) -> str:
    """One face of a collection as a font file of its own, in matplotlib's cache folder (made once).

    matplotlib < 3.11 reads only the first face of a ``.ttc`` (the Japanese one in Noto Sans CJK)."""
    import matplotlib

    st = os.stat(path)
    key = hashlib.sha256(f"{os.path.realpath(path)}|{st.st_size}|{st.st_mtime_ns}|{index}".encode()).hexdigest()[:12]
    font = _sfnt(path, index)
    out = pathlib.Path(matplotlib.get_cachedir()) / "graphmethods-fonts" / \
        f"{pathlib.Path(path).stem}-{index}-{key}.{'otf' if 'CFF ' in font else 'ttf'}"
    if not out.is_file():
        from graphmethods.render.files import write_atomic

        out.parent.mkdir(parents=True, exist_ok=True)
        buf = io.BytesIO()
        font.save(buf)
        write_atomic(out, buf.getvalue(), overwrite=True)   # another process may have made it meanwhile
    font.close()
    return str(out)


def _same(a: str, b: str) -> bool:
    return os.path.realpath(a) == os.path.realpath(b)


def _register(path: str, index: int) -> CJKFont:
    """Make the face known to matplotlib (so PNG text finds it by family) and return it as matplotlib resolves
    its family, so that PNG and PDF draw with the same face."""
    from matplotlib import font_manager as fm

    if index and not _mpl_reads_collections():
        path, index = _extract_face(path, index), 0

    def entries() -> list[Any]:                        # matplotlib's FontEntry records
        return [e for e in fm.fontManager.ttflist if _same(e.fname, path) and getattr(e, "index", 0) == index]

    if not entries():
        fm.fontManager.addfont(path)
    known = entries()
    family = known[0].name if known else _faces_in(path)[index][0]
    try:
        got = fm.findfont(fm.FontProperties(family=[family], weight="normal", style="normal"),
                          fallback_to_default=False)
    except ValueError:
        got = None
    if got and not (_same(str(got), path) and getattr(got, "face_index", 0) == index) \
            and _usable(str(got), getattr(got, "face_index", 0)):
        path, index = str(got), getattr(got, "face_index", 0)     # another file of the same family wins there
    return CJKFont(path, index, family)


@functools.lru_cache(maxsize=1)
def find_cjk_font() -> CJKFont | None:
    """The face that draws Chinese in PNG and PDF, registered with matplotlib; None when there is none.

    Looks, in order, at ``GRAPHMETHODS_CJK_FONT`` (a font file; in a collection, its Chinese face),
    matplotlib's fonts by the family names :data:`CJK_FAMILIES` (regular weight), any font covering Chinese,
    and the ``mplfonts`` package. When nothing is found, matplotlib's font list is rebuilt once (a cache made
    before the font was installed) and the search repeated.

    Raises
    ------
    MissingFontError
        If ``GRAPHMETHODS_CJK_FONT`` names no font file with Chinese characters.

    Examples
    --------
    >>> font = find_cjk_font()              # None on a machine without a CJK font
    >>> font is None or (os.path.isfile(font.path) and font.index >= 0)
    True
    """
    global _rebuilt
    found = _lookup()
    if found is None and not _rebuilt:
        _rebuilt = True
        _rebuild_font_list()
        found = _lookup()
    return None if found is None else _register(*found)


def require_cjk() -> CJKFont:
    """The CJK face (see :func:`find_cjk_font`), or :class:`~graphmethods.errors.MissingFontError` saying
    what to install or set."""
    font = find_cjk_font()
    if font is None:
        raise MissingFontError("no font with Chinese characters was found (matplotlib's font list was rebuilt "
                               f"and searched again), so Chinese text cannot be drawn in PNG/PDF: {CJK_ADVICE}")
    return font


def families(text: str) -> list[str]:
    """Font families for ``text``: DejaVu Sans, then the CJK face's family when the text has Chinese.

    Raises
    ------
    MissingFontError
        If the text has Chinese and no font has it.
    """
    if has_cjk(text):
        return [BASE_FAMILY, require_cjk().family]
    return [BASE_FAMILY]


@dataclass(frozen=True)
class PdfMetrics:
    """What a PDF font descriptor says of a face, in 1/1000 em: its PostScript name, the kind of outlines
    (``"TrueType"`` or ``"CFF"``), whether the CFF is CID-keyed and its (registry, ordering, supplement),
    ascent, descent, cap height, bounding box and italic angle (degrees)."""

    ps_name: str
    outlines: str
    cid_keyed: bool
    ros: tuple[str, str, int]
    ascent: float
    descent: float
    cap_height: float
    bbox: tuple[float, float, float, float]
    italic_angle: float


class Face:
    """One face of a font file: glyphs of characters, advances and kerning in font units, and for a PDF the
    code of each glyph, the font's metrics and a subset of its program.

    Parameters
    ----------
    path : str
        A TrueType or OpenType font file (``.ttf``, ``.otf``, ``.ttc``).
    index : int
        The face in a collection (0 for a single font).

    Examples
    --------
    >>> face = faces("AV", bold=False)[0]
    >>> a, v = face.glyph("A"), face.glyph("V")
    >>> face.kerning(a, v) < 0 < face.advance(a)          # A and V tuck together
    True
    >>> face.code(a) == a, face.pdf_metrics().ps_name     # a TrueType face: PDF codes are glyph indices
    (True, 'DejaVuSans')
    """

    def __init__(self, path: str, index: int = 0):
        self.path, self.index = path, int(index)
        self._font = Sfnt(path, self.index)
        self.units_per_em = int(self._font.units_per_em)
        self._cids: list[int] | None = None

    def glyph(self, char: str) -> int | None:
        """Glyph index of ``char``, or None when the font has none."""
        return self._font.cmap.get(ord(char))

    def advance(self, gid: int) -> int:
        """Advance width of glyph ``gid`` in font units."""
        return int(self._font.advances[gid])

    def kerning(self, left: int, right: int) -> int:
        """Pair kerning between two glyphs in font units (0 when the font has none)."""
        return self._font.kerning.get((left << 16) | right, 0)

    @functools.cache  # noqa: B019 - one instance per font file (the faces are cached), kept for the run
    def pdf_metrics(self) -> PdfMetrics:
        """The face's name, kind of outlines and descriptor metrics (1/1000 em), read from the file."""
        f = self._font
        em = 1000.0 / f.units_per_em
        name = f.name(6) or f.name(4) or "Font"
        ps_name = re.sub(r"[^A-Za-z0-9._-]", "", name) or "Font"
        cff = f.has("CFF ")
        cid_keyed, ros = False, ("Adobe", "Identity", 0)
        if cff:
            font = _sfnt(self.path, self.index)
            top = font["CFF "].cff.topDictIndex[0]
            if hasattr(top, "ROS"):
                cid_keyed, ros = True, (str(top.ROS[0]), str(top.ROS[1]), int(top.ROS[2]))
            font.close()
        os2 = f.os2()
        cap = os2[1] if os2 is not None else 0
        return PdfMetrics(
            ps_name=ps_name, outlines="CFF" if cff else "TrueType", cid_keyed=cid_keyed, ros=ros,
            ascent=round(f.ascent * em, 3), descent=round(f.descent * em, 3),
            cap_height=round((cap or f.ascent) * em, 3),
            bbox=(round(f.bbox[0] * em, 3), round(f.bbox[1] * em, 3), round(f.bbox[2] * em, 3),
                  round(f.bbox[3] * em, 3)),
            italic_angle=f.italic_angle())

    def code(self, gid: int) -> int:
        """The 2-byte code a PDF shows glyph ``gid`` by: its CID in a CID-keyed CFF font, else ``gid``."""
        if self._cids is None:
            if self.pdf_metrics().cid_keyed:
                f = _sfnt(self.path, self.index)
                self._cids = [0 if n == ".notdef" else int(n[3:]) for n in f.getGlyphOrder()]
                f.close()
            else:
                self._cids = []
        return self._cids[gid] if self._cids else gid

    def subset(self, gids: Iterable[int]) -> bytes:
        """The font program with only glyphs ``gids`` (and .notdef): a TrueType font (glyph indices kept) or a
        bare CFF table (CIDs kept), deterministic (no timestamps change); cached per glyph set."""
        return _subset(self.path, self.index, tuple(sorted(set(gids) | {0})))


@functools.lru_cache(maxsize=32)
def _subset(path: str, index: int, gids: tuple[int, ...]) -> bytes:
    face = _face(path, index)
    if not face._font.has("CFF "):             # TrueType: read and cut from the file's bytes
        return subset_truetype(face._font, gids)
    from fontTools import subset  # CFF outlines (Noto Sans CJK): fontTools' subsetter

    font = _sfnt(path, index)
    cff = "CFF " in font
    keep = {"head", "hhea", "hmtx", "maxp"} | ({"CFF "} if cff else {"glyf", "loca"})
    dropped = [tag for tag in font.keys() if tag not in keep and tag != "GlyphOrder"]  # noqa: SIM118 - TTFont has no __iter__
    for tag in dropped:            # before subsetting: fontTools would otherwise read the layout tables
        del font[tag]
    opts = subset.Options()
    opts.drop_tables = sorted(set(opts.drop_tables) | set(dropped))
    opts.notdef_outline = True
    opts.layout_features = []
    opts.name_IDs = []
    opts.hinting = cff             # CFF hints are small and their removal slow; TrueType hinting is dropped
    # codes are glyph indices (TrueType, name-keyed CFF) or CIDs, which a CID-keyed CFF keeps in its charset
    opts.retain_gids = not (cff and hasattr(font["CFF "].cff.topDictIndex[0], "ROS"))
    opts.recalc_timestamp = False
    opts.recalc_bounds = False
    sub = subset.Subsetter(opts)
    sub.populate(gids=list(gids))
    sub.subset(font)
    try:
        if cff:
            return bytes(font["CFF "].compile(font))
        buf = io.BytesIO()
        font.save(buf)
        return buf.getvalue()
    finally:
        font.close()


@functools.cache
def _face(path: str, index: int = 0) -> Face:
    return Face(path, index)


@functools.cache
def _base_path(bold: bool) -> str:
    """DejaVu Sans as matplotlib ships it (the file its font list resolves the family to), found without
    importing matplotlib; matplotlib's own lookup only when that file is missing."""
    import importlib.util

    spec = importlib.util.find_spec("matplotlib")
    name = "DejaVuSans-Bold.ttf" if bold else "DejaVuSans.ttf"
    for loc in (spec.submodule_search_locations or []) if spec is not None else []:
        path = pathlib.Path(loc) / "mpl-data" / "fonts" / "ttf" / name
        if path.is_file():
            return str(path)
    from matplotlib.font_manager import FontProperties, findfont

    return str(findfont(FontProperties(family=BASE_FAMILY, weight="bold" if bold else "normal")))


def faces(text: str, *, bold: bool) -> tuple[Face, ...]:
    """The faces that draw ``text``, first choice first: DejaVu Sans (bold or regular), then the CJK face
    when the text has Chinese. CJK fonts rarely ship a bold face, so a line with Chinese is drawn regular.

    Raises
    ------
    MissingFontError
        If the text has Chinese and no font has it.
    """
    if has_cjk(text):
        cjk = require_cjk()
        return (_face(_base_path(False)), _face(cjk.path, cjk.index))
    return (_face(_base_path(bold)),)


@functools.lru_cache(maxsize=16384)
def check_drawable(text: str, bold: bool = False) -> None:
    """Refuse text with characters no face draws, before anything is written.

    Raises
    ------
    MissingFontError
        Naming the characters (and, for Chinese, what to install or set).

    Examples
    --------
    >>> check_drawable("ψ_max = 30°, Мд")
    >>> check_drawable("नमस्ते")                         # Devanagari: DejaVu Sans has none
    Traceback (most recent call last):
    ...
    graphmethods.errors.MissingFontError: cannot draw 'त' (U+0924), 'न' (U+0928), ... no glyph for them; change the text or write SVG
    """  # noqa: E501 - a doctest's expected output is one line
    fs = faces(text, bold=bold)
    missing = sorted({ch for ch in text if all(f.glyph(ch) is None for f in fs)})
    if missing:
        chars = ", ".join(f"{ch!r} (U+{ord(ch):04X})" for ch in missing[:5]) + (" and more" if len(missing) > 5 else "")
        names = BASE_FAMILY + (f" and {require_cjk().family}" if len(fs) > 1 else "")
        raise MissingFontError(f"cannot draw {chars} in PNG/PDF: {names} {'have' if len(fs) > 1 else 'has'} no "
                               f"glyph for {'them' if len(missing) > 1 else 'it'}; change the text or write SVG")


def check_scene(scene: Scene) -> None:
    """:func:`check_drawable` for every label of ``scene`` (to refuse before a batch writes any file)."""
    from graphmethods.render.recording import record

    for call in record(scene).calls:
        if call.kind == "text":
            for chunk, _ in call.data.runs:
                check_drawable(chunk, call.data.bold)
