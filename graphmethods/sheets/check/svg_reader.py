"""Reading a student's SVG drawing as browsers and CAD programs write it, through svgelements.

svgelements resolves what a drawing program may write: style sheets (``<style>`` with classes),
units (``x="56.6mm"``, ``width="8.5in"``), ``<use>``, every transform (skew too), the whole path
syntax (compact arc flags ``a5 5 0 106 6``), and the viewBox. Before it sees the file, the file is
checked here under named limits, so that a hostile file is refused in one line naming the file and
the place (line and column):

* a regular file of at most :data:`graphmethods.units.MAX_INPUT_BYTES`, read once;
* no entity declarations (``<!ENTITY``: the XML attacks of external entities and entity expansion);
* elements nested at most :data:`MAX_SVG_DEPTH` deep, and at most :data:`MAX_SVG_ELEMENTS` elements
  once every ``<use>`` is expanded (copies counted, not only depth);
* numbers where the drawing needs numbers (coordinates, sizes, the viewBox, font sizes).

The drawing is returned as a :class:`graphmethods.render.dxf.CadDrawing` in mm with y up, as a DXF
is read: segments, filled polygons (arrowheads; a ``marker-end``/``marker-start`` gives one at that
end of its path), texts (the characters of a ``<text>`` and its ``<tspan>``s as one text).

>>> import pathlib
>>> d = read_svg(pathlib.Path(__file__).parents[2] / "problems" / "data" / "drawings" / "w1_mistakes.svg")
>>> len(d.segments) > 10, sorted(t.text for t in d.texts)[1:4]
(True, ['a', 'b', 'c'])
"""

from __future__ import annotations

import io
import math
import os
import re
import xml.etree.ElementTree as ET
from xml.parsers import expat

import numpy as np

from graphmethods.errors import InputError
from graphmethods.render.dxf import CadDrawing, CadText
from graphmethods.scene.elements import CAP
from graphmethods.units import read_bytes

#: Deepest nesting of elements an SVG drawing may have (Inkscape's layers and groups: under 20).
MAX_SVG_DEPTH = 200
#: Most elements an SVG drawing may hold once every ``<use>`` is expanded (a student's plan: a few hundred).
MAX_SVG_ELEMENTS = 50_000
#: mm per px: svgelements gives every coordinate in px (1/96 in) of the outermost viewport, and converts mm
#: with its own 0.0393701 in/mm; its inverse gives a drawing in mm back exactly.
MM_PER_PX = 1.0 / (96.0 * 0.0393701)

_SVG_NS = "{http://www.w3.org/2000/svg}"
_XLINK = "{http://www.w3.org/1999/xlink}href"
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_LENGTH = re.compile(rf"^\s*{_NUMBER}\s*(?:mm|cm|in|px|pt|pc|em|ex|%|Q)?\s*$")
_LENGTH_LIST = re.compile(rf"^\s*(?:{_NUMBER}\s*(?:mm|cm|in|px|pt|pc|em|ex|%|Q)?[\s,]*)*$")
#: attributes that must hold a length (or a list of them), by attribute name
_LENGTHS = ("x", "y", "x1", "y1", "x2", "y2", "cx", "cy", "r", "rx", "ry", "width", "height", "font-size",
            "stroke-width")


def _local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1]


def _scan(data: bytes, name: str) -> None:
    """Refuse, with the line and column, what svgelements must not be given (see the module's limits)."""
    parser = expat.ParserCreate()
    depth = [0]
    count = [0]

    def where() -> str:
        return f"{name}, line {parser.CurrentLineNumber}, column {parser.CurrentColumnNumber + 1}"

    def start(tag: str, attrs: dict) -> None:
        depth[0] += 1
        count[0] += 1
        if depth[0] > MAX_SVG_DEPTH:
            raise InputError(f"{where()}: elements nested more than {MAX_SVG_DEPTH} deep (MAX_SVG_DEPTH); a "
                             f"drawing's groups are a few levels deep")
        if count[0] > MAX_SVG_ELEMENTS:
            raise InputError(f"{where()}: more than {MAX_SVG_ELEMENTS} elements (MAX_SVG_ELEMENTS)")
        local = _local(tag)
        for key in _LENGTHS:
            v = attrs.get(key)
            if v is not None and not (_LENGTH_LIST if key in ("x", "y") and local in ("text", "tspan")
                                      else _LENGTH).match(v):
                raise InputError(f"{where()}: <{local} {key}={v[:30]!r}> is not a length; write a number, "
                                 f"optionally with a unit (mm, px, …)")
        vb = attrs.get("viewBox")
        if vb is not None:
            parts = [p for p in re.split(r"[\s,]+", vb.strip()) if p]
            ok = len(parts) == 4 and all(re.fullmatch(_NUMBER, p) for p in parts)
            if not ok or float(parts[2]) <= 0 or float(parts[3]) <= 0:
                raise InputError(f"{where()}: viewBox={vb[:40]!r} is not four numbers with a positive width and "
                                 f"height")

    def end(tag: str) -> None:
        depth[0] -= 1

    def entity(*_args: object) -> None:
        raise InputError(f"{where()}: the drawing declares XML entities (<!ENTITY>); they are refused (external "
                         f"files, entity expansion): save the drawing without a DOCTYPE")

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.EntityDeclHandler = entity
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
    try:
        parser.Parse(data, True)
    except expat.ExpatError as exc:
        raise InputError(f"{name}: not a readable SVG drawing (line {exc.lineno}, column {exc.offset + 1}: "
                         f"{expat.ErrorString(exc.code)})") from None


def _expanded_size(root: ET.Element, name: str) -> None:
    """Refuse a drawing whose ``<use>`` elements expand to more than :data:`MAX_SVG_ELEMENTS` elements."""
    by_id = {el.get("id"): el for el in root.iter() if el.get("id")}
    sizes: dict[int, int] = {}
    for el in _post_order(root):
        n = 1 + sum(sizes[id(c)] for c in el)
        if _local(el.tag) == "use":
            ref = (el.get(_XLINK) or el.get("href") or "").lstrip("#")
            target = by_id.get(ref)
            if target is not None:
                n += sizes.get(id(target), 0) or _size_of(target, sizes, by_id)
        sizes[id(el)] = min(n, MAX_SVG_ELEMENTS + 1)
        if n > MAX_SVG_ELEMENTS:
            raise InputError(f"{name}: more than {MAX_SVG_ELEMENTS} elements once its <use> copies are expanded "
                             f"(MAX_SVG_ELEMENTS, at <use href={el.get(_XLINK) or el.get('href')!r}> or inside "
                             f"id {el.get('id')!r}); draw the elements themselves")


def _size_of(target: ET.Element, sizes: dict[int, int], by_id: dict) -> int:
    """The expanded size of an element referenced before it appears (a forward ``<use>``): counted plainly,
    its own forward references (a cycle among them) counted as the limit."""
    n = 0
    for el in target.iter():
        n += 1
        if _local(el.tag) == "use" and el is not target:
            n += MAX_SVG_ELEMENTS
        if n > MAX_SVG_ELEMENTS:
            break
    return n


def _post_order(root: ET.Element) -> list[ET.Element]:
    """The elements children first (without recursion: the depth is bounded, but not by Python's stack)."""
    out: list[ET.Element] = []
    stack = [(root, False)]
    while stack:
        el, seen = stack.pop()
        if seen:
            out.append(el)
        else:
            stack.append((el, True))
            stack.extend((c, False) for c in reversed(list(el)))
    return out


def _flatten_texts(root: ET.Element) -> None:
    """Each ``<text>`` as one run of characters placed where its first ``<tspan>`` with a position is (as a
    drawing program writes a label: ``v<tspan baseline-shift="sub">B</tspan> = 3.03``), its style merged
    with that tspan's."""
    for el in list(root.iter(_SVG_NS + "text")) + list(root.iter("text")):
        chars = "".join(el.itertext()).strip()
        first = next((c for c in el.iter() if c is not el and _local(c.tag) == "tspan"), None)
        if first is not None:
            for key in ("x", "y"):
                if first.get(key) is not None:
                    el.set(key, first.get(key, ""))
            if first.get("style") and "font-size" in first.get("style", ""):
                el.set("style", f"{el.get('style') or ''};{first.get('style')}")
            if first.get("font-size") and not el.get("font-size"):
                el.set("font-size", first.get("font-size", ""))
        for child in list(el):
            el.remove(child)
        el.text = chars


def read_svg(source: str | os.PathLike[str]) -> CadDrawing:
    """Read an SVG drawing into a :class:`~graphmethods.render.dxf.CadDrawing` (mm, y up, as a DXF is read).

    Parameters
    ----------
    source : path
        The drawing (Inkscape's, a browser's, a CAD program's SVG export): any units, style sheets,
        ``<use>``, transforms.

    Returns
    -------
    CadDrawing
        Lines, polylines, polygons and paths as segments (closed filled shapes as filled polygons, a
        marker at an end as an arrowhead there); texts at the centre of their box with their cap height.

    Raises
    ------
    InputError
        When the file is not a readable SVG drawing, or exceeds a limit of this module (the message names
        the file, the place and the limit).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> p = pathlib.Path(tempfile.mkdtemp()) / "plan.svg"
    >>> _ = p.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 100 50">'
    ...                  '<style>.v{fill:none;stroke:#000}</style><path class="v" d="M10 40 H60"/></svg>')
    >>> read_svg(p).segments
    (((10.0, 10.0), (60.0, 10.0)),)
    """
    name = str(source)
    data = read_bytes(source, missing="no such drawing")
    _scan(data, name)
    try:
        root = ET.fromstring(data)
    except ET.ParseError as exc:
        raise InputError(f"{name}: not a readable SVG drawing ({exc})") from None
    if _local(root.tag) != "svg":
        raise InputError(f"{name}: not an SVG drawing (its root is <{_local(root.tag)}>)")
    _expanded_size(root, name)
    _flatten_texts(root)
    return _walk(ET.tostring(root), name)


def _walk(data: bytes, name: str) -> CadDrawing:
    """The drawing through svgelements, its elements reified (coordinates in px of the outer viewport)."""
    import svgelements as se

    try:
        svg = se.SVG.parse(io.BytesIO(data), reify=True, ppi=se.DEFAULT_PPI)
        height_px = float(svg.height) if svg.height else 0.0
        reader = _Collector(height_px)
        for el in svg.elements():
            reader.add(el, se)
    except InputError:
        raise
    except (ValueError, TypeError, ZeroDivisionError, IndexError, KeyError, AttributeError, OverflowError,
            RecursionError) as exc:
        raise InputError(f"{name}: not a readable SVG drawing ({exc.__class__.__name__}: {str(exc)[:80]})") from None
    return CadDrawing(tuple(reader.segs), tuple(reader.fills), (), tuple(reader.texts), source=name)


class _Collector:
    """Segments, filled polygons and texts of svgelements' reified elements, in mm with y up."""

    def __init__(self, height_px: float) -> None:
        self.H = height_px
        self.segs: list = []
        self.fills: list = []
        self.texts: list = []

    def mm(self, x: float, y: float) -> tuple[float, float]:
        X, Y = float(x) * MM_PER_PX, (self.H - float(y)) * MM_PER_PX
        if not (math.isfinite(X) and math.isfinite(Y)):
            raise InputError("a coordinate of the drawing is not finite")
        return (round(X, 6), round(Y, 6))

    def add(self, el, se) -> None:
        if isinstance(el, se.Text):
            self.text(el)
        elif isinstance(el, se.Shape) and not isinstance(el, se.Use):
            values = getattr(el, "values", {}) or {}
            if values.get("visibility") == "hidden" or values.get("display") == "none":
                return
            path = el if isinstance(el, se.Path) else se.Path(el)
            filled = el.fill is not None and el.fill.value is not None and float(el.fill.opacity or 0) > 0
            self.shape(path, se, filled, values)

    def shape(self, path, se, filled: bool, values: dict) -> None:
        subs: list[list[tuple[float, float]]] = []
        closed: list[bool] = []
        for seg in path:
            if isinstance(seg, se.Move):
                subs.append([self.mm(seg.end.x, seg.end.y)])
                closed.append(False)
            elif seg.end is not None and subs:
                if isinstance(seg, se.Close):
                    closed[-1] = True
                subs[-1].append(self.mm(seg.end.x, seg.end.y))
        for pts, is_closed in zip(subs, closed):
            if filled and is_closed and len(pts) >= 4:
                self.fills.append(tuple(pts[:-1] if math.dist(pts[0], pts[-1]) < 1e-6 else pts))
                continue
            for a, b in zip(pts, pts[1:]):
                if math.dist(a, b) > 1e-9:
                    self.segs.append((a, b))
            for key, end, prev in (("marker-end", -1, -2), ("marker-start", 0, 1)):
                if str(values.get(key, "none")).strip() not in ("none", "") and len(pts) >= 2:
                    self.head(np.array(pts[end]), np.array(pts[prev]))

    def head(self, tip: np.ndarray, back: np.ndarray) -> None:
        """An arrowhead of a marker: a triangle 2.5 mm long, 1 mm wide at the end ``tip``."""
        u = (tip - back) / max(float(np.hypot(*(tip - back))), 1e-9)
        base = tip - 2.5 * u
        n = np.array([-u[1], u[0]]) * 0.5
        self.fills.append((tuple(map(float, tip)), tuple(map(float, base + n)), tuple(map(float, base - n))))

    def text(self, el) -> None:
        chars = (el.text or "").strip()
        if not chars:
            return
        size = float(el.font_size or 16.0)
        m = el.transform
        scale = math.sqrt(abs(m.a * m.d - m.b * m.c)) if m is not None else 1.0
        anchor = str((el.values or {}).get("text-anchor", "start"))
        w = 0.6 * size * len(chars)
        cx = float(el.x) + {"start": w / 2, "middle": 0.0, "end": -w / 2}.get(anchor, w / 2)
        cy = float(el.y) - 0.36 * size
        X, Y = (m.point_in_matrix_space((cx, cy)) if m is not None else (cx, cy))
        x_mm, y_mm = self.mm(X, Y)
        self.texts.append(CadText(chars, x_mm, y_mm, size * CAP * scale * MM_PER_PX))
