"""Reading back the PDFs graphmethods writes, for tests: objects by the cross-reference table, content
streams, fonts with their ToUnicode maps, and the text shown (where, how large, which characters).

It knows only the subset of PDF that graphmethods.render.pdf writes (one xref section, Flate streams,
Type 0 fonts with 2-byte codes, ``Tm``/``Tf``/``TJ`` text), and fails loudly on anything else.
"""

from __future__ import annotations

import re
import zlib
from dataclasses import dataclass

_REF = re.compile(rb"(\d+) 0 R")


@dataclass
class Shown:
    """One run of text: its origin (page mm, y down), its size (mm) and its characters."""

    x: float
    y: float
    size: float
    text: str


class Pdf:
    def __init__(self, data: bytes):
        self.data = data
        tail = data[data.rindex(b"startxref"):]
        self.xref_at = int(tail.split()[1])
        assert data[self.xref_at:self.xref_at + 4] == b"xref", "startxref does not point at the xref table"
        head = data[self.xref_at:].split(b"\n", 2)
        first, count = map(int, head[1].split())
        assert first == 0
        rows = data[self.xref_at:].split(b"\n")[2:2 + count]
        self.offsets = {}
        for num, row in enumerate(rows):
            assert len(row) == 19, f"xref row {num} is not 20 bytes: {row!r}"
            if row.endswith(b" n "):
                self.offsets[num] = int(row[:10])
        for num, off in self.offsets.items():
            assert data.startswith(f"{num} 0 obj\n".encode(), off), f"object {num} is not at its xref offset"
        trailer = data[data.rindex(b"trailer"):]
        self.root = int(re.search(rb"/Root (\d+) 0 R", trailer).group(1))
        self.info = int(re.search(rb"/Info (\d+) 0 R", trailer).group(1))
        assert int(re.search(rb"/Size (\d+)", trailer).group(1)) == count

    def raw(self, num: int) -> bytes:
        off = self.offsets[num]
        start = self.data.index(b"\n", off) + 1
        return self.data[start:self.data.index(b"\nendobj\n", start)]

    def dict(self, num: int) -> bytes:
        raw = self.raw(num)
        return raw.split(b"\nstream\n", 1)[0]

    def stream(self, num: int) -> bytes:
        raw = self.raw(num)
        head, rest = raw.split(b"\nstream\n", 1)
        length = int(re.search(rb"/Length (\d+)", head).group(1))
        assert rest[length:] == b"\nendstream", f"object {num}: /Length {length} does not end the stream"
        body = rest[:length]
        return zlib.decompress(body) if b"/FlateDecode" in head else body

    def pages(self) -> list[int]:
        pages = int(re.search(rb"/Pages (\d+) 0 R", self.dict(self.root)).group(1))
        kids = re.search(rb"/Kids \[([^\]]*)\]", self.dict(pages)).group(1)
        return [int(k) for k in _REF.findall(kids)]

    def media_box(self, page: int) -> list[float]:
        return [float(v) for v in re.search(rb"/MediaBox \[([^\]]*)\]", self.dict(page)).group(1).split()]

    def content(self, page: int) -> str:
        num = int(re.search(rb"/Contents (\d+) 0 R", self.dict(page)).group(1))
        return self.stream(num).decode("ascii")

    def fonts(self, page: int) -> dict[str, int]:
        res = int(re.search(rb"/Resources (\d+) 0 R", self.dict(page)).group(1))
        fonts = re.search(rb"/Font << (.*?) >>", self.dict(res)).group(1)
        return {name.decode(): int(num) for name, num in re.findall(rb"/(\w+) (\d+) 0 R", fonts)}

    def to_unicode(self, font: int) -> dict[int, str]:
        num = int(re.search(rb"/ToUnicode (\d+) 0 R", self.dict(font)).group(1))
        cmap = self.stream(num).decode("ascii")
        out = {}
        for block in re.findall(r"beginbfchar\n(.*?)\nendbfchar", cmap, flags=re.S):
            for code, uni in re.findall(r"<([0-9A-F]{4})> <([0-9A-F]+)>", block):
                out[int(code, 16)] = bytes.fromhex(uni).decode("utf-16-be")
        return out

    def shown(self, page: int) -> list[Shown]:
        """The text runs of a page, in drawing order."""
        maps = {name: self.to_unicode(num) for name, num in self.fonts(page).items()}
        out = []
        for block in re.findall(r"BT (.*?) ET", self.content(page)):
            for run in re.split(r"(?= 1 0 0 -1 )", " " + block):
                m = re.match(r" 1 0 0 -1 (\S+) (\S+) Tm (.*)", run)
                if not m:
                    continue
                x, y, shows = float(m.group(1)), float(m.group(2)), m.group(3)
                text, size = "", None
                for name, sz, array in re.findall(r"/(\w+) (\S+) Tf \[(.*?)\] TJ", shows):
                    size = float(sz)
                    for hexes in re.findall(r"<([0-9A-F]*)>", array):
                        assert len(hexes) % 4 == 0, f"codes are 2 bytes: {hexes}"
                        text += "".join(maps[name][int(hexes[i:i + 4], 16)] for i in range(0, len(hexes), 4))
                out.append(Shown(x, y, size, text))
        return out
