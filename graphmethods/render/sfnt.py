"""A TrueType/OpenType font file read from its bytes: the tables a layout and a PDF need, and glyph subsets.

What :mod:`graphmethods.render.fonts` asks of a face, read straight from the file
(``struct`` and numpy, no font library imported): the character map (formats 4 and 12,
chosen as FreeType chooses: a full-Unicode map before the BMP one), the advance widths
(``hmtx``), the pair kerning of the ``kern`` table (format 0; what FreeType's
``FT_Get_Kerning`` reads, so the widths are those matplotlib measures), the metrics a
PDF font descriptor carries, and for TrueType outlines a subset of the font program
(:func:`subset_truetype`: the glyphs asked for and their components, glyph indices
kept, instructions dropped). CFF outlines (OpenType ``.otf`` such as Noto Sans CJK)
are subset by fontTools in :mod:`graphmethods.render.fonts`.

The file layout follows the OpenType specification (``https://learn.microsoft.com/
typography/opentype/spec/``): the table directory, ``cmap``, ``hmtx``, ``kern``,
``glyf``/``loca``, ``head``, ``hhea``, ``maxp``, ``OS/2``, ``post`` and ``name``.

>>> import importlib.util, pathlib
>>> root = pathlib.Path(importlib.util.find_spec("matplotlib").submodule_search_locations[0])
>>> font = Sfnt(str(root / "mpl-data" / "fonts" / "ttf" / "DejaVuSans.ttf"))
>>> font.units_per_em, int(font.advances[font.cmap[ord("M")]])
(2048, 1767)
"""

from __future__ import annotations

import functools
import struct
from collections.abc import Iterable

import numpy as np

#: (platform, encoding) of Unicode character maps, the full-repertoire ones first (as FreeType prefers them)
_CMAP_ORDER = ((3, 10), (0, 6), (0, 4), (3, 1), (0, 3), (0, 2), (0, 1), (0, 0))
_KERN_PAIR = np.dtype([("pair", ">u4"), ("value", ">i2")])    # left << 16 | right, then the value
_ARG_WORDS, _HAS_SCALE, _MORE, _XY_SCALE, _TWO_BY_TWO, _INSTRUCTIONS = 0x1, 0x8, 0x20, 0x40, 0x80, 0x100


class FontFormatError(ValueError):
    """The file is not a TrueType/OpenType font this module reads."""


def _checksum(data: bytes) -> int:
    padded = data + b"\0" * (-len(data) % 4)
    return int(np.frombuffer(padded, dtype=">u4").sum(dtype=np.uint64)) & 0xFFFFFFFF   # numpy 1.23: no uint64 & int


class Sfnt:
    """One face of a font file, read from its bytes.

    Parameters
    ----------
    path : str
        A ``.ttf``, ``.otf`` or ``.ttc`` file.
    index : int
        The face of a collection (0 for a single font).

    Raises
    ------
    FontFormatError
        If the file is no sfnt font or lacks a table a face needs.
    """

    def __init__(self, path: str, index: int = 0):
        with open(path, "rb") as fh:
            self.data = fh.read()
        d = self.data
        start = 0
        if d[:4] == b"ttcf":
            count = struct.unpack_from(">I", d, 8)[0]
            if not 0 <= index < count:
                raise FontFormatError(f"{path} has no face {index}")
            start = struct.unpack_from(">I", d, 12 + 4 * index)[0]
        self.sfnt_version = d[start:start + 4]
        num = struct.unpack_from(">H", d, start + 4)[0]
        self.tables: dict[str, tuple[int, int]] = {}
        for i in range(num):
            tag, _, off, length = struct.unpack_from(">4sIII", d, start + 12 + 16 * i)
            self.tables[tag.decode("latin-1")] = (off, length)
        for need in ("head", "hhea", "hmtx", "maxp", "cmap"):
            if need not in self.tables:
                raise FontFormatError(f"{path} has no {need!r} table")
        head = self.table("head")
        self.units_per_em = struct.unpack_from(">H", head, 18)[0]
        self.bbox = struct.unpack_from(">hhhh", head, 36)
        self.index_to_loc_format = struct.unpack_from(">h", head, 50)[0]
        self.num_glyphs = struct.unpack_from(">H", self.table("maxp"), 4)[0]
        hhea = self.table("hhea")
        self.ascent, self.descent = struct.unpack_from(">hh", hhea, 4)
        self.num_h_metrics = struct.unpack_from(">H", hhea, 34)[0]

    def has(self, tag: str) -> bool:
        """True when the face has table ``tag``."""
        return tag in self.tables

    def table(self, tag: str) -> bytes:
        """The bytes of table ``tag``."""
        off, length = self.tables[tag]
        return self.data[off:off + length]

    @functools.cached_property
    def advances(self) -> np.ndarray:
        """Advance width of every glyph in font units (glyphs past the last metric repeat its width)."""
        n = self.num_h_metrics
        adv = np.frombuffer(self.table("hmtx"), dtype=">u2", count=2 * n)[0::2].astype(np.int64)
        if self.num_glyphs > n:
            adv = np.concatenate([adv, np.full(self.num_glyphs - n, adv[-1], dtype=np.int64)])
        return adv

    @functools.cached_property
    def cmap(self) -> dict[int, int]:
        """Character code → glyph index, from the preferred Unicode map (format 12 or 4), glyph 0 left out."""
        cmap = self.table("cmap")
        n = struct.unpack_from(">H", cmap, 2)[0]
        subtables: dict[tuple[int, int], int] = {}
        for i in range(n):
            platform, encoding, off = struct.unpack_from(">HHI", cmap, 4 + 8 * i)
            fmt = struct.unpack_from(">H", cmap, off)[0]
            if fmt in (4, 12):
                subtables.setdefault((platform, encoding), off)
        for key in _CMAP_ORDER:
            if key in subtables:
                off = subtables[key]
                fmt = struct.unpack_from(">H", cmap, off)[0]
                codes, gids = (_cmap12 if fmt == 12 else _cmap4)(cmap, off)
                keep = gids != 0
                return dict(zip(codes[keep].tolist(), gids[keep].tolist()))
        return {}

    @functools.cached_property
    def kerning(self) -> dict[int, int]:
        """Pair kerning of the ``kern`` table's horizontal format-0 subtables, summed as FreeType sums them:
        ``(left << 16) | right`` → value in font units."""
        out: dict[int, int] = {}
        if "kern" not in self.tables:
            return out
        kern = self.table("kern")
        version, n = struct.unpack_from(">HH", kern, 0)
        if version != 0:               # Apple's 32-bit kern header: not in the fonts we embed
            return out
        pos = 4
        for _ in range(n):
            _, length, coverage = struct.unpack_from(">HHH", kern, pos)
            fmt, horizontal, minimum, cross = coverage >> 8, coverage & 1, coverage & 2, coverage & 4
            if fmt == 0 and horizontal and not minimum and not cross:
                pairs = struct.unpack_from(">H", kern, pos + 6)[0]
                rec = np.frombuffer(kern, dtype=_KERN_PAIR, count=pairs, offset=pos + 14)
                if out:
                    for key, value in zip(rec["pair"].tolist(), rec["value"].tolist()):
                        out[key] = out.get(key, 0) + value
                else:
                    out = dict(zip(rec["pair"].tolist(), rec["value"].tolist()))
            pos += length
        return out

    def name(self, name_id: int) -> str | None:
        """Entry ``name_id`` of the ``name`` table (Windows Unicode first, then Macintosh Roman), or None."""
        if "name" not in self.tables:
            return None
        t = self.table("name")
        count, strings = struct.unpack_from(">HH", t, 2)
        found: dict[int, str] = {}
        for i in range(count):
            platform, encoding, _, nid, length, off = struct.unpack_from(">HHHHHH", t, 6 + 12 * i)
            if nid != name_id:
                continue
            raw = t[strings + off:strings + off + length]
            if platform == 3 or platform == 0:
                found.setdefault(0, raw.decode("utf-16-be", errors="replace"))
            elif platform == 1 and encoding == 0:
                found.setdefault(1, raw.decode("mac-roman", errors="replace"))
        return found.get(0, found.get(1))

    def os2(self) -> tuple[int, int] | None:
        """(weight class, cap height) from ``OS/2`` (cap height 0 before version 2), or None."""
        if "OS/2" not in self.tables:
            return None
        t = self.table("OS/2")
        version, _, weight = struct.unpack_from(">HhH", t, 0)
        cap = struct.unpack_from(">h", t, 88)[0] if version >= 2 and len(t) >= 90 else 0
        return weight, cap

    def italic_angle(self) -> float:
        """The ``post`` table's italic angle in degrees (0 without one)."""
        if "post" not in self.tables:
            return 0.0
        return float(struct.unpack_from(">i", self.table("post"), 4)[0]) / 65536.0

    def _loca(self) -> np.ndarray:
        n = self.num_glyphs + 1
        if self.index_to_loc_format == 0:
            return np.frombuffer(self.table("loca"), dtype=">u2", count=n).astype(np.int64) * 2
        return np.frombuffer(self.table("loca"), dtype=">u4", count=n).astype(np.int64)


def _cmap4(cmap: bytes, off: int) -> tuple[np.ndarray, np.ndarray]:
    seg2 = struct.unpack_from(">H", cmap, off + 6)[0]
    segs = seg2 // 2
    ends = np.frombuffer(cmap, dtype=">u2", count=segs, offset=off + 14).astype(np.int64)
    starts = np.frombuffer(cmap, dtype=">u2", count=segs, offset=off + 16 + seg2).astype(np.int64)
    deltas = np.frombuffer(cmap, dtype=">u2", count=segs, offset=off + 16 + 2 * seg2).astype(np.int64)
    range_at = off + 16 + 3 * seg2
    ranges = np.frombuffer(cmap, dtype=">u2", count=segs, offset=range_at).astype(np.int64)
    codes, gids = [], []
    for i in range(segs):
        if starts[i] == 0xFFFF:
            continue
        c = np.arange(starts[i], ends[i] + 1, dtype=np.int64)
        if ranges[i] == 0:
            g = (c + deltas[i]) & 0xFFFF
        else:
            at = range_at + 2 * i + ranges[i] + 2 * (c - starts[i])
            raw = np.array([struct.unpack_from(">H", cmap, int(a))[0] for a in at], dtype=np.int64)
            g = np.where(raw != 0, (raw + deltas[i]) & 0xFFFF, 0)
        codes.append(c)
        gids.append(g)
    if not codes:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    return np.concatenate(codes), np.concatenate(gids)


def _cmap12(cmap: bytes, off: int) -> tuple[np.ndarray, np.ndarray]:
    n = struct.unpack_from(">I", cmap, off + 12)[0]
    groups = np.frombuffer(cmap, dtype=">u4", count=3 * n, offset=off + 16).reshape(n, 3).astype(np.int64)
    lengths = groups[:, 1] - groups[:, 0] + 1
    first = np.repeat(groups[:, 0], lengths)
    step = np.arange(int(lengths.sum()), dtype=np.int64) - np.repeat(np.cumsum(lengths) - lengths, lengths)
    return first + step, np.repeat(groups[:, 2], lengths) + step


def _glyph_parts(glyph: bytes) -> tuple[bytes, list[int]]:
    """A glyph's outline without its instructions, and the glyphs a composite is made of."""
    if len(glyph) < 10:
        return b"", []
    contours = struct.unpack_from(">h", glyph, 0)[0]
    if contours >= 0:                       # simple glyph: drop the instructions, keep flags and points
        at = 10 + 2 * contours
        n_instr = struct.unpack_from(">H", glyph, at)[0]
        return glyph[:at] + b"\0\0" + glyph[at + 2 + n_instr:], []
    pos, parts, flags = 10, [], _MORE
    components: list[int] = []
    while flags & _MORE:
        flags, gid = struct.unpack_from(">HH", glyph, pos)
        components.append(gid)
        size = 4 + (4 if flags & _ARG_WORDS else 2)
        size += 8 if flags & _TWO_BY_TWO else 4 if flags & _XY_SCALE else 2 if flags & _HAS_SCALE else 0
        parts.append(struct.pack(">H", flags & ~_INSTRUCTIONS) + glyph[pos + 2:pos + size])
        pos += size
    return glyph[:10] + b"".join(parts), components


def subset_truetype(font: Sfnt, gids: Iterable[int]) -> bytes:
    """A TrueType font program with only the outlines of glyphs ``gids``, their components and ``.notdef``.

    Glyph indices are kept (the glyphs left out are empty, and the font ends at the last one kept), hinting is
    dropped (``fpgm``, ``prep``, ``cvt`` and the glyphs' instructions), and only the tables a PDF viewer reads
    from an embedded ``FontFile2`` remain: ``glyf``, ``head``, ``hhea``, ``hmtx``, ``loca``, ``maxp``. The
    same glyphs give the same bytes.

    Examples
    --------
    >>> import importlib.util, pathlib
    >>> root = pathlib.Path(importlib.util.find_spec("matplotlib").submodule_search_locations[0])
    >>> font = Sfnt(str(root / "mpl-data" / "fonts" / "ttf" / "DejaVuSans.ttf"))
    >>> program = subset_truetype(font, [font.cmap[ord("M")]])
    >>> len(program) < 10_000, program[:4] == b"\\0\\1\\0\\0"
    (True, True)
    """
    if "glyf" not in font.tables or "loca" not in font.tables:
        raise FontFormatError("not a TrueType font (no glyf table): subset it as CFF")
    loca, glyf = font._loca().tolist(), font.table("glyf")
    todo = sorted({0} | {int(g) for g in gids if 0 <= int(g) < font.num_glyphs})
    outlines: dict[int, bytes] = {}
    while todo:
        gid = todo.pop()
        if gid in outlines:
            continue
        outline, components = _glyph_parts(glyf[loca[gid]:loca[gid + 1]])
        outlines[gid] = outline + b"\0" * (-len(outline) % 4)
        todo.extend(c for c in components if c not in outlines and 0 <= c < font.num_glyphs)
    count = max(outlines) + 1
    kept = sorted(outlines)
    lengths = np.zeros(count, dtype=np.int64)
    lengths[kept] = [len(outlines[g]) for g in kept]
    new_glyf = b"".join(outlines[g] for g in kept)
    new_loca = np.concatenate([[0], np.cumsum(lengths)]).astype(">u4").tobytes()
    metrics = min(font.num_h_metrics, count)
    hmtx = font.table("hmtx")
    new_hmtx = hmtx[:4 * metrics] + hmtx[4 * font.num_h_metrics:4 * font.num_h_metrics + 2 * (count - metrics)]
    head = bytearray(font.table("head"))
    struct.pack_into(">I", head, 8, 0)                  # checkSumAdjustment, set below
    struct.pack_into(">h", head, 50, 1)                 # long offsets in loca
    hhea = bytearray(font.table("hhea"))
    struct.pack_into(">H", hhea, 34, metrics)
    maxp = bytearray(font.table("maxp"))
    struct.pack_into(">H", maxp, 4, count)
    tables = {"glyf": new_glyf, "head": bytes(head), "hhea": bytes(hhea), "hmtx": new_hmtx, "loca": new_loca,
              "maxp": bytes(maxp)}
    out, at = _assemble(tables)
    adjust = (0xB1B0AFBA - _checksum(out)) & 0xFFFFFFFF
    return out[:at["head"] + 8] + struct.pack(">I", adjust) + out[at["head"] + 12:]


def _assemble(tables: dict[str, bytes]) -> tuple[bytes, dict[str, int]]:
    """An sfnt file of ``tables`` (tags sorted, each 4-byte aligned, checksums set) and each table's offset."""
    num = len(tables)
    entry = 1 << (num.bit_length() - 1)
    header = struct.pack(">IHHHH", 0x00010000, num, entry * 16, entry.bit_length() - 1, num * 16 - entry * 16)
    offset = 12 + 16 * num
    records, bodies, at = [], [], {}
    for tag in sorted(tables):
        body = tables[tag]
        records.append(struct.pack(">4sIII", tag.encode("latin-1"), _checksum(body), offset, len(body)))
        padded = body + b"\0" * (-len(body) % 4)
        bodies.append(padded)
        at[tag] = offset
        offset += len(padded)
    return header + b"".join(records) + b"".join(bodies), at
