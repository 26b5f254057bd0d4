"""PDF output written directly: vector paths in millimetres and real text in embedded, subset fonts.

A page is one content stream drawn in page millimetres (one ``cm`` maps them to
points, y down as on paper). Text is text: each font face used (DejaVu Sans regular
and bold, the CJK face; see :mod:`graphmethods.render.fonts`) becomes one Type 0 font
with Identity-H encoding, whose 2-byte codes are the face's glyph indices (TrueType
outlines: CIDFontType2, ``FontFile2``) or CIDs (CFF outlines, as in Noto Sans CJK:
CIDFontType0, ``FontFile3 /CIDFontType0C``). The program embedded is a subset of the
font file with only the glyphs used (fontTools), named ``ABCDEF+DejaVuSans`` with a
tag hashed from its glyphs; a ``W`` array gives the widths and a ToUnicode map the
characters, so every viewer shows, searches and copies the words, and the kerning of
the font is kept in ``TJ`` arrays. There are no dates or ids, so the same scenes give
the same bytes.

Why not matplotlib's PDF backend: it lays out every string anew through its text
engine, about 0.12 s a worksheet page; here a page takes a few milliseconds, and a
class set of 60 pages is written in about a second.

>>> from graphmethods.scene import Scene, Page, Text
>>> pdf = to_bytes([Scene(Page("A4"), (Text((20, 20), "ψ_{max} = 30°; M_д"),))])
>>> pdf[:8], pdf.rstrip().endswith(b"%%EOF")
(b'%PDF-1.4', True)
"""

from __future__ import annotations

import functools
import hashlib
import math
import os
import pathlib
import zlib
from collections.abc import Iterable

from graphmethods.errors import InputError
from graphmethods.render.base import draw
from graphmethods.render.files import write_atomic
from graphmethods.render.fonts import Face, check_drawable, faces
from graphmethods.scene.markup import SCRIPT_SCALE, baseline_shift_mm, plain
from graphmethods.scene.numbers import format_mm as fmt
from graphmethods.scene.primitives import XY, Label, Style
from graphmethods.scene.scene import Scene

PT_PER_MM = 72.0 / 25.4
_KAPPA = 4.0 * (math.sqrt(2.0) - 1.0) / 3.0      # cubic Bézier control distance of a quarter circle


@functools.lru_cache(maxsize=256)
def _rgb(color: str) -> str:
    c = color.strip().lstrip("#")
    if len(c) == 3:
        c = "".join(ch * 2 for ch in c)
    try:
        r, g, b = (int(c[i:i + 2], 16) / 255.0 for i in (0, 2, 4))
        if len(c) != 6:
            raise ValueError
    except ValueError:
        raise InputError(f"cannot draw the colour {color!r} in PDF: give it as #rrggbb") from None
    return " ".join(f"{v:.4f}".rstrip("0").rstrip(".") or "0" for v in (r, g, b))


def _pdf_string(text: str) -> str:
    """A PDF text string: UTF-16BE with its byte-order mark, in hex."""
    return "<FEFF" + text.encode("utf-16-be").hex().upper() + ">"


class _Font:
    """One face in the document, as one Type 0 font: 2-byte codes (Identity-H) that are the face's glyph codes
    (glyph indices, or CIDs in a CID-keyed CFF font), and the first character each code showed."""

    def __init__(self, face: Face, name: str):
        self.face, self.name = face, name
        self.used: dict[int, tuple[int, str]] = {}       # code -> (glyph index, the character it shows)


class _Fonts:
    """The glyphs a document uses, shared by its pages: which font and code draws each."""

    def __init__(self) -> None:
        self.fonts: list[_Font] = []
        self._by_face: dict[int, _Font] = {}     # id(face) -> its font
        self._runs: dict[tuple[str, bool], tuple[float, tuple[tuple[str, str], ...]]] = {}

    def font(self, face: Face) -> _Font:
        got = self._by_face.get(id(face))
        if got is None:
            got = self._by_face[id(face)] = _Font(face, f"F{len(self.fonts) + 1}")
            self.fonts.append(got)
        return got

    def run(self, text: str, bold: bool) -> tuple[float, tuple[tuple[str, str], ...]]:
        """``text`` laid out, cached: its width in em, and per font its name and ``TJ`` array (the glyph
        codes with the kerning between them).

        Raises
        ------
        MissingFontError
            If a character has no glyph in any face (e.g. Chinese without a CJK font).
        """
        key = (text, bold)
        got = self._runs.get(key)
        if got is not None:
            return got
        fs = faces(text, bold=bold)
        width = 0.0
        shows: list[tuple[str, str]] = []
        parts: list[str] = []
        current: _Font | None = None
        prev: int | None = None
        for ch in text:
            hit = next(((f, g) for f in fs if (g := f.glyph(ch)) is not None), None)
            if hit is None:
                check_drawable(text, bold)          # raises, naming the characters no face has
                raise AssertionError(f"no glyph for {ch!r}")
            face, gid = hit
            font = self.font(face)
            code = face.code(gid)
            font.used.setdefault(code, (gid, ch))
            kern = 0
            if font is not current:              # another font: no kerning across it
                if current is not None:
                    shows.append((current.name, f"[{''.join(parts)}>]"))
                current, parts = font, ["<"]
            elif prev is not None:
                kern = face.kerning(prev, gid)
                if kern:
                    parts.append(f"> {-1000.0 * kern / face.units_per_em:.1f} <".replace(".0 ", " "))
            parts.append(f"{code:04X}")
            width += (kern + face.advance(gid)) / face.units_per_em
            prev = gid
        if current is not None:
            shows.append((current.name, f"[{''.join(parts)}>]"))
        got = self._runs[key] = (width, tuple(shows))
        return got


class PdfRenderer:
    """A :class:`~graphmethods.render.base.Renderer` writing one page's content stream in mm.

    Pages share a font registry (``fonts``), so a document embeds each glyph once.
    """

    def __init__(self, fonts: _Fonts):
        self.fonts = fonts
        self.ops: list[str] = []

    def begin(self, width_mm: float, height_mm: float, *, title: str, name: str) -> None:
        self.size_mm = (float(width_mm), float(height_mm))
        h_pt = f"{height_mm * PT_PER_MM:.4f}"
        self.ops = [f"{PT_PER_MM:.6f} 0 0 {-PT_PER_MM:.6f} 0 {h_pt} cm 0 J 1 j"]
        self._state: dict[str, str] = {}

    def begin_group(self, id: str) -> None:
        pass

    def end_group(self) -> None:
        pass

    def _set(self, op: str, value: str) -> None:
        if self._state.get(op) != value:
            self._state[op] = value
            self.ops.append(f"{value} {op}")

    def _stroke_style(self, style: Style) -> bool:
        if not style.stroke or style.stroke == "none" or style.width_mm <= 0:
            return False
        self._set("RG", _rgb(style.stroke))
        self._set("w", fmt(style.width_mm))
        self._set("d", f"[{' '.join(fmt(d) for d in style.dash or ())}] 0")
        return True

    def _fill_style(self, style: Style) -> bool:
        if not style.fill or style.fill == "none":
            return False
        self._set("rg", _rgb(style.fill))
        return True

    @staticmethod
    def _outline(points: tuple[XY, ...], closed: bool) -> str:
        (x0, y0), *rest = points
        ops = [f"{fmt(x0)} {fmt(y0)} m"] + [f"{fmt(x)} {fmt(y)} l" for x, y in rest]
        if closed:
            ops.append("h")
        return " ".join(ops)

    def _paint(self, outline: str, style: Style, closed: bool) -> None:
        fill = closed and self._fill_style(style)
        stroke = self._stroke_style(style)
        if fill or stroke:
            self.ops.append(f"{outline} {'B' if fill and stroke else 'f' if fill else 'S'}")

    def path(self, points: tuple[XY, ...], style: Style, closed: bool) -> None:
        if len(points) >= 2:
            self._paint(self._outline(points, closed), style, closed=False)

    def polygon(self, points: tuple[XY, ...], style: Style) -> None:
        if len(points) >= 2:
            self._paint(self._outline(points, True), style, closed=True)

    def circle(self, cx: float, cy: float, r: float, style: Style) -> None:
        k = _KAPPA * r
        quarter = ((cx + r, cy), (cx + r, cy + k), (cx + k, cy + r), (cx, cy + r))
        ops = [f"{fmt(cx + r)} {fmt(cy)} m"]
        for turn in range(4):                 # four quarter arcs, each the previous one turned 90°
            pts: tuple[tuple[float, float], ...] = quarter[1:]
            for _ in range(turn):
                pts = tuple((cx - (y - cy), cy + (x - cx)) for x, y in pts)
            ops.append(" ".join(f"{fmt(x)} {fmt(y)}" for x, y in pts) + " c")
        self._paint(" ".join(ops) + " h", style, closed=True)

    def text(self, label: Label) -> None:
        laid = []
        for chunk, shift in label.runs:
            size = label.size_mm * (1.0 if shift == 0 else SCRIPT_SCALE)
            width_em, shows = self.fonts.run(chunk, label.bold)
            laid.append((size, width_em * size * label.stretch, shows, shift))
        total = sum(w for _, w, _, _ in laid)
        x = label.x - {"start": 0.0, "middle": total / 2.0, "end": total}[label.anchor]
        self._set("rg", _rgb(label.color))
        parts = ["BT"]
        for size, width, shows, shift in laid:
            dy = baseline_shift_mm(shift, label.size_mm)
            parts.append(f"{fmt(label.stretch)} 0 0 -1 {fmt(x)} {fmt(label.y + dy)} Tm")   # stretch: condensed
            parts += [f"/{name} {fmt(size)} Tf {array} TJ" for name, array in shows]
            x += width
        parts.append("ET")
        self.ops.append(" ".join(parts))

    def end(self) -> tuple[tuple[float, float], bytes]:
        return self.size_mm, "\n".join(self.ops).encode("ascii")


class _Writer:
    """Numbered objects and the cross-reference table of one PDF file."""

    def __init__(self) -> None:
        self.bodies: list[bytes | None] = []

    def reserve(self) -> int:
        self.bodies.append(None)
        return len(self.bodies)

    def put(self, num: int, body: str | bytes) -> int:
        self.bodies[num - 1] = body.encode("latin-1") if isinstance(body, str) else body
        return num

    def add(self, body: str | bytes) -> int:
        return self.put(self.reserve(), body)

    def stream(self, data: bytes, extra: str = "", num: int | None = None, *, reused: bool = False) -> int:
        """A Flate stream object; ``reused`` data (a font program, the same bytes in many documents) is
        compressed once."""
        packed = _deflate(data) if reused else zlib.compress(data, 6)
        head = f"<< /Length {len(packed)} /Filter /FlateDecode{extra} >>\nstream\n".encode("latin-1")
        body = head + packed + b"\nendstream"
        return self.put(num, body) if num else self.add(body)

    def finish(self, root: int, info: int) -> bytes:
        out = bytearray(b"%PDF-1.4\n%\xe2\xe3\xcf\xd3\n")
        offsets = []
        for i, body in enumerate(self.bodies, start=1):
            assert body is not None, f"object {i} was reserved and never written"
            offsets.append(len(out))
            out += f"{i} 0 obj\n".encode("latin-1") + body + b"\nendobj\n"
        xref = len(out)
        out += f"xref\n0 {len(self.bodies) + 1}\n0000000000 65535 f \n".encode("latin-1")
        out += b"".join(f"{o:010d} 00000 n \n".encode("latin-1") for o in offsets)
        out += (f"trailer\n<< /Size {len(self.bodies) + 1} /Root {root} 0 R /Info {info} 0 R >>\n"
                f"startxref\n{xref}\n%%EOF\n").encode("latin-1")
        return bytes(out)


@functools.lru_cache(maxsize=16)
def _deflate(data: bytes) -> bytes:
    return zlib.compress(data, 6)


def _to_unicode(pairs: list[tuple[int, str]]) -> bytes:
    """A ToUnicode CMap: 2-byte codes to the characters they show."""
    lines = ["/CIDInit /ProcSet findresource begin", "12 dict begin", "begincmap",
             "/CIDSystemInfo << /Registry (Adobe) /Ordering (UCS) /Supplement 0 >> def",
             "/CMapName /Adobe-Identity-UCS def", "/CMapType 2 def",
             "1 begincodespacerange", "<0000> <FFFF>", "endcodespacerange"]
    for start in range(0, len(pairs), 100):
        block = pairs[start:start + 100]
        lines.append(f"{len(block)} beginbfchar")
        lines += [f"<{code:04X}> <{ch.encode('utf-16-be').hex().upper()}>" for code, ch in block]
        lines.append("endbfchar")
    lines += ["endcmap", "CMapName currentdict /CMap defineresource pop", "end", "end"]
    return "\n".join(lines).encode("ascii")


def _num(x: float) -> str:
    s = f"{x:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def subset_tag(ps_name: str, codes: Iterable[int]) -> str:
    """Six capital letters naming a font subset, from a hash of the font's name and the codes it keeps (the
    same glyphs give the same tag, so the same document gives the same bytes).

    >>> a = subset_tag("DejaVuSans", [36, 37])
    >>> len(a) == 6 and a.isupper(), a == subset_tag("DejaVuSans", [37, 36]), a == subset_tag("DejaVuSans", [36, 38])
    (True, True, False)
    """
    digest = hashlib.sha256(f"{ps_name}:{','.join(map(str, sorted(codes)))}".encode("ascii")).digest()
    return "".join(chr(ord("A") + b % 26) for b in digest[:6])


def _widths(font: _Font) -> str:
    """The W array: runs of consecutive codes with their advance widths (1/1000 em)."""
    face, out, run = font.face, [], []
    codes = sorted(font.used)
    for i, code in enumerate(codes):
        run.append(_num(1000.0 * face.advance(font.used[code][0]) / face.units_per_em))
        if i + 1 == len(codes) or codes[i + 1] != code + 1:
            out.append(f"{code - len(run) + 1} [{' '.join(run)}]")
            run = []
    return " ".join(out)


def _type0(w: _Writer, font: _Font) -> int:
    """Embed ``font``: its subset program, descriptor, CID font (widths) and Type 0 font (ToUnicode)."""
    face = font.face
    m = face.pdf_metrics()
    base = f"{subset_tag(m.ps_name, font.used)}+{m.ps_name}"
    program = face.subset(gid for gid, _ in font.used.values())
    if m.outlines == "TrueType":
        ref, subtype = f"/FontFile2 {w.stream(program, f' /Length1 {len(program)}', reused=True)} 0 R", "CIDFontType2"
    else:
        ref, subtype = f"/FontFile3 {w.stream(program, ' /Subtype /CIDFontType0C', reused=True)} 0 R", "CIDFontType0"
    desc = w.add(f"<< /Type /FontDescriptor /FontName /{base} /Flags 4 /FontBBox [{' '.join(map(_num, m.bbox))}] "
                 f"/ItalicAngle {_num(m.italic_angle)} /Ascent {_num(m.ascent)} /Descent {_num(m.descent)} "
                 f"/CapHeight {_num(m.cap_height)} /StemV 80 {ref} >>")
    registry, ordering, supplement = m.ros
    cid = w.add(f"<< /Type /Font /Subtype /{subtype} /BaseFont /{base} /CIDSystemInfo << /Registry ({registry}) "
                f"/Ordering ({ordering}) /Supplement {supplement} >> /FontDescriptor {desc} 0 R /DW 1000 "
                f"/W [{_widths(font)}]{' /CIDToGIDMap /Identity' if subtype == 'CIDFontType2' else ''} >>")
    unicode_map = w.stream(_to_unicode([(code, font.used[code][1]) for code in sorted(font.used)]))
    # the Type 0 font's name: the CID font's, with "-Identity-H" after a CFF-based one (PDF 32000-1, 9.7.6.1)
    type0_name = base if subtype == "CIDFontType2" else f"{base}-Identity-H"
    return w.add(f"<< /Type /Font /Subtype /Type0 /BaseFont /{type0_name} /Encoding /Identity-H "
                 f"/DescendantFonts [{cid} 0 R] /ToUnicode {unicode_map} 0 R >>")


def to_bytes(scenes: Scene | Iterable[Scene]) -> bytes:
    """PDF with one page per scene, in order (a single scene is allowed); the same scenes give the same bytes.

    ``scenes`` may be any iterable (it is read once, page by page, so a caller can report progress).

    Examples
    --------
    >>> from graphmethods.scene import Scene, Page, Text
    >>> page = Scene(Page("A4"), (Text((10, 10), "Мд, ψ_{max}"),))
    >>> to_bytes([page, page]).count(b"/Type /Page ")
    2
    """
    if isinstance(scenes, Scene):
        scenes = [scenes]
    fonts = _Fonts()
    w = _Writer()
    catalog, pages, info, resources = (w.reserve() for _ in range(4))
    kids, title = [], ""
    for scene in scenes:
        (width, height), content = draw(scene, PdfRenderer(fonts))
        title = title or scene.title
        contents = w.stream(content)
        kids.append(w.add(f"<< /Type /Page /Parent {pages} 0 R /MediaBox [0 0 {width * PT_PER_MM:.4f} "
                          f"{height * PT_PER_MM:.4f}] /Resources {resources} 0 R /Contents {contents} 0 R >>"))
    if not kids:
        raise InputError("a PDF needs at least one page: no scenes were given")
    fonts_dict = " ".join(f"/{font.name} {_type0(w, font)} 0 R" for font in fonts.fonts)
    w.put(resources, f"<< /Font << {fonts_dict} >> >>")
    w.put(pages, f"<< /Type /Pages /Kids [{' '.join(f'{k} 0 R' for k in kids)}] /Count {len(kids)} >>")
    w.put(catalog, f"<< /Type /Catalog /Pages {pages} 0 R >>")
    w.put(info, f"<< /Creator (graphmethods) /Title {_pdf_string(plain(title))} >>")
    return w.finish(catalog, info)


def save(scenes: Scene | Iterable[Scene], path: str | os.PathLike[str], *, overwrite: bool = False) -> pathlib.Path:
    """Write one scene or several (one page each) as PDF atomically; refuses to replace a file unless
    ``overwrite``."""
    return write_atomic(path, to_bytes(scenes), overwrite=overwrite)
