"""The worksheets' own drawing elements: graph paper, coloured text, kinematic symbols (ground, pin,
slider), arcs, text wrapping, and the page's millimetre constants.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from graphmethods.scene import Page, markup
from graphmethods.scene.elements import Element, lettered_size, make_label
from graphmethods.scene.primitives import THIN, Circle, Path, Polygon, Primitive, Style

# ----------------------------------------------------------------------------- drawing elements

GRID_MINOR = Style(stroke="#d6d6d6", width_mm=0.1)
GRID_MAJOR = Style(stroke="#aaaaaa", width_mm=0.15)
RED = "#d01818"
WRONG = Style(stroke=RED, width_mm=0.5)
THICK = Style(width_mm=0.7)
TEXT_MM, LINE_MM, SMALL_MM = 3.2, 4.5, 2.7
PAGE = Page("A4", "portrait", frame=True)
X0, X1 = 15.0, 195.0


@dataclass(frozen=True)
class Grid(Element):
    """Graph paper: thin lines every ``step_mm``, darker every ``major_every``-th line, through ``anchor``.

    Drawn as a few zig-zag paths (the joins run along the border, which is drawn anyway), so a
    page of graph paper costs a handful of primitives. ``holes`` are boxes ``(x0, y0, x1, y1)`` (mm) the
    paper leaves blank, as a printed figure clears the paper behind its lettering: a line that meets one
    is drawn in pieces around it (:meth:`Sheet.scene <graphmethods.sheets.worksheets.pages.Sheet.scene>`
    gives the boxes of the page's texts), so no tick value or letter sits on a grid line.

    >>> g = Grid((10, 10, 60, 40), anchor=(20, 30))
    >>> len(g.primitives()), g.xs()[:3]
    (5, (10.0, 15.0, 20.0))
    >>> holed = Grid((10, 10, 60, 40), anchor=(20, 30), holes=((18, 18, 22, 22),))
    >>> len(holed.primitives())            # the lines x = 20 and y = 20 in two pieces each
    9
    """

    box: tuple
    anchor: tuple | None = None
    step_mm: float = 5.0
    major_every: int = 2
    holes: tuple = ()
    name: str = "grid"

    def _pieces(self, v: float, lo: float, hi: float, vertical: bool) -> list[tuple[float, float]]:
        """The parts of the line at ``v`` (x of a vertical line, y of a horizontal one) from ``lo`` to ``hi``
        outside the holes."""
        cuts = sorted((h[1], h[3]) if vertical else (h[0], h[2]) for h in self.holes
                      if ((h[0] < v < h[2]) if vertical else (h[1] < v < h[3])))
        out, a = [], lo
        for c0, c1 in cuts:
            if c0 > a:
                out.append((a, min(c0, hi)))
            a = max(a, c1)
            if a >= hi:
                break
        if a < hi:
            out.append((a, hi))
        return [(p, q) for p, q in out if q - p > 1e-6]

    def _ks(self, lo, hi, a):
        s = self.step_mm
        return range(math.ceil((lo - a) / s - 1e-9), math.floor((hi - a) / s + 1e-9) + 1)

    def xs(self) -> tuple[float, ...]:
        x0, _, x1, _ = self.box
        a = (self.anchor or self.box[:2])[0]
        return tuple(a + k * self.step_mm for k in self._ks(x0, x1, a))

    def primitives(self):
        x0, y0, x1, y1 = (float(v) for v in self.box)
        ax, ay = self.anchor or (x0, y0)
        prims = []
        for major in (False, True):
            xs = [ax + k * self.step_mm for k in self._ks(x0, x1, ax) if (k % self.major_every == 0) == major]
            ys = [ay + k * self.step_mm for k in self._ks(y0, y1, ay) if (k % self.major_every == 0) == major]
            style = GRID_MAJOR if major else GRID_MINOR
            for vals, vertical in ((xs, True), (ys, False)):
                a, b = (y0, y1) if vertical else (x0, x1)
                pts: list[tuple[float, float]] = []
                for v in vals:
                    pieces = self._pieces(v, a, b, vertical)
                    if pieces == [(a, b)]:                  # a whole line: on the zig-zag
                        ends = (a, b) if len(pts) % 4 == 0 else (b, a)
                        pts += [(v, e) for e in ends] if vertical else [(e, v) for e in ends]
                        continue
                    for p, q in pieces:                     # a line with holes: its pieces one by one
                        prims.append(Path(((v, p), (v, q)) if vertical else ((p, v), (q, v)), style))
                if pts:
                    prims.append(Path(tuple(pts), style))
        prims.append(Path(((x0, y0), (x1, y0), (x1, y1), (x0, y1)), GRID_MAJOR, closed=True))
        return tuple(prims)


@dataclass(frozen=True)
class ColorText(Element):
    """A line of text in a colour (a wrong answer in red on an overlay)."""

    at: tuple
    text: str
    size_mm: float = TEXT_MM
    anchor: str = "start"
    valign: str = "baseline"
    bold: bool = False
    color: str = "#000000"
    markup: bool = True
    name: str = "text"

    def __post_init__(self):                # lettered as the sheet being drawn asks (3.5 mm and up on A1/A2)
        object.__setattr__(self, "size_mm", lettered_size(self.size_mm))

    def primitives(self):
        return (make_label(self.at, self.text, size_mm=self.size_mm, anchor=self.anchor, valign=self.valign,
                           bold=self.bold, markup_=self.markup, color=self.color),)


@dataclass(frozen=True)
class Shapes(Element):
    """Primitives drawn as one element (symbols built from paths and circles)."""

    prims: tuple
    name: str = "shapes"

    def primitives(self):
        return tuple(self.prims)


_CJK = "\u2e80-\u9fff\u3000-\u303f\uff00-\uffef"
_TOKEN = re.compile(rf"[ \t\n]+|[{_CJK}]|[^ \t\n{_CJK}]+")
NBSP = "\u00a0"
_NO_LINE_START = set("，。；：、）」』》！？,.;:)")


def wrap(text: str, width_mm: float, size_mm: float) -> list[str]:
    """Break markup text into lines no wider than ``width_mm`` (at spaces, and between CJK characters).

    >>> wrap("one two three four", 20.0, 3.2)
    ['one two', 'three four']
    >>> len(wrap("等效驱动力矩与等效阻抗力矩曲线", 20.0, 3.2))
    3
    """
    lines, cur, space = [], "", False
    for tok in _TOKEN.findall(text):
        if tok.strip(" \t\n") == "":
            space = bool(cur)
            continue
        cand = cur + (" " if space else "") + tok
        if cur and tok[0] not in _NO_LINE_START and markup.text_width_mm(cand, size_mm) > width_mm:
            lines.append(cur)
            cur = tok
        else:
            cur = cand
        space = False
    if cur:
        lines.append(cur)
    return lines


def ground(at, *, width_mm: float = 9.0, name: str = "ground") -> Shapes:
    """A fixed pivot: pin circle on a small triangle standing on a hatched base."""
    x, y = at
    base = y + 4.5
    prims: list[Primitive] = [Path(((x, y), (x - 2.6, base), (x + 2.6, base)), THIN.with_(width_mm=0.35), closed=True),
             Path(((x - width_mm / 2, base), (x + width_mm / 2, base)), THIN.with_(width_mm=0.35))]
    k = int(width_mm // 1.8)
    for i in range(k + 1):
        hx = x - width_mm / 2 + i * width_mm / k
        prims.append(Path(((hx, base), (hx - 1.6, base + 1.8)), THIN))
    prims.append(Circle(x, y, 1.3, THIN.with_(width_mm=0.35, fill="#ffffff")))
    return Shapes(tuple(prims), name=name)


def pin(at, *, name: str = "pin") -> Shapes:
    """A pin joint: a small white circle."""
    return Shapes((Circle(at[0], at[1], 1.2, THIN.with_(width_mm=0.35, fill="#ffffff")),), name=name)


def slider(at, *, w: float = 12.0, h: float = 7.0, guide_mm: float = 40.0, name: str = "slider") -> Shapes:
    """A slider block centred on ``at`` on a horizontal guide hatched underneath."""
    x, y = at
    g = y + h / 2
    prims = [Polygon(((x - w / 2, y - h / 2), (x + w / 2, y - h / 2), (x + w / 2, g), (x - w / 2, g)),
                     THIN.with_(width_mm=0.5, fill="#ffffff")),
             Path(((x - guide_mm / 2, g), (x + guide_mm / 2, g)), THIN.with_(width_mm=0.35))]
    for i in range(int(guide_mm // 2.5) + 1):
        hx = x - guide_mm / 2 + i * 2.5
        prims.append(Path(((hx, g), (hx - 1.6, g + 1.8)), THIN))
    prims.append(Circle(x, y, 1.2, THIN.with_(width_mm=0.35, fill="#ffffff")))
    return Shapes(tuple(prims), name=name)


def arc(centre, radius: float, a0_deg: float, a1_deg: float, *, arrow: bool = False, style: Style = THIN,
        name: str = "arc") -> Shapes:
    """An arc from ``a0_deg`` to ``a1_deg`` (counterclockwise on paper when a1 > a0), optionally with a head."""
    cx, cy = centre
    t = np.radians(np.linspace(a0_deg, a1_deg, max(8, int(abs(a1_deg - a0_deg) / 5) + 2)))
    pts = tuple(zip((cx + radius * np.cos(t)).tolist(), (cy - radius * np.sin(t)).tolist()))
    prims: list[Primitive] = [Path(pts, style)]
    if arrow:
        end = np.array(pts[-1])
        d = end - np.array(pts[-2])
        d /= np.hypot(*d)
        n = np.array([-d[1], d[0]])
        base = end - 2.2 * d
        prims.append(Polygon((tuple(end), tuple(base + 0.8 * n), tuple(base - 0.8 * n))))
    return Shapes(tuple(prims), name=name)


def clip_ray(point, slope: float, box) -> tuple | None:
    """The segment of the line through ``point`` with paper slope ``slope`` (mm up per mm right) inside
    ``box`` (x0, y0, x1, y1), or None when it misses the box."""
    x0, y0, x1, y1 = box
    px, py = point
    # y(x) = py − slope (x − px); clip x so that y0 ≤ y ≤ y1
    lo, hi = x0, x1
    if slope != 0:
        xa = px - (y0 - py) / slope
        xb = px - (y1 - py) / slope
        lo, hi = max(lo, min(xa, xb)), min(hi, max(xa, xb))
    elif not y0 <= py <= y1:
        return None
    if hi <= lo:
        return None
    return ((lo, py - slope * (lo - px)), (hi, py - slope * (hi - px)))


