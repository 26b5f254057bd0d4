"""DXF output through ezdxf: 1 drawing unit = 1 mm at 1:1, layers by role, real text. The only module
importing ezdxf.

A scene becomes model-space entities in millimetres, the page's bottom-left corner at (0, 0) and y up
(a CAD drawing's convention; the scene's y runs down, so y becomes ``height − y``). Several scenes are
laid side by side, 20 mm apart. Each primitive goes on the layer of its role (:data:`LAYERS`),
derived from the names of the groups around it and its style (:func:`role_of`):

* paths become LWPOLYLINEs with the stroke's lineweight and, when dashed, a linetype of the same
  dash pattern in mm, under a standard name (:data:`STANDARD_LINETYPES`) so that LibreCAD dashes it
  too; filled triangles (arrowheads) SOLIDs; other filled polygons and filled
  circles solid HATCHes; circles CIRCLEs;
* text becomes TEXT in a style of :data:`TEXT_STYLES` (Arial, and Noto Sans CJK for Chinese; each style
  named after the LibreCAD font that draws it there), its height the capital height of the scene's
  font size; a label
  with sub/superscripts becomes one TEXT per run, shifted and scaled as in SVG;
* black is ByLayer (colour 7: black on a white background, white on a black one), other colours
  true colours; white fills (the open circles of joints and marks) are left unfilled;
* each element's entities form a DXF GROUP named after the element's id (``vector-pa``), so a
  CAD user selects a construction whole and a program finds a vector by name.

The output is deterministic: handles are given in drawing order, and the header's dates and GUIDs
($TDCREATE, $TDUPDATE, $FINGERPRINTGUID, $VERSIONGUID) are fixed, so the same scenes give the same bytes.

>>> from graphmethods.scene import Scene, Page, Scale, Vector
>>> mu = Scale("μ_v", "m/s", 0.05)
>>> data = to_bytes(Scene(Page("A4"), (Vector.of((50, 100), value=2.0, scale=mu, angle_deg=90, name="vector-pa"),)))
>>> data[:20] == to_bytes(Scene(Page("A4"), (Vector.of((50, 100), value=2.0, scale=mu, angle_deg=90,
...                                           name="vector-pa"),)))[:20], b"VECTORS-KNOWN" in data
(True, True)
"""

from __future__ import annotations

import io
import math
import os
import pathlib
import re
from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

from graphmethods.errors import InputError
from graphmethods.render.base import draw
from graphmethods.render.files import write_atomic
from graphmethods.scene.elements import CAP
from graphmethods.scene.markup import SCRIPT_SCALE, baseline_shift_mm, text_width_mm
from graphmethods.scene.primitives import XY, Label, Style
from graphmethods.scene.scene import Scene
from graphmethods.units import input_file

if TYPE_CHECKING:                      # ezdxf is imported only when a DXF is written or read
    from ezdxf.document import Drawing
    from ezdxf.entities import DXFGraphic

#: Most entities a drawing read may give once its blocks are expanded, every copy counted (a student's plan:
#: a few hundred; a course sheet with its title block: a few thousand)
MAX_DXF_ENTITIES = 200_000
#: Deepest nesting of block references a drawing read may have
MAX_DXF_DEPTH = 8
#: DXF release written: AutoCAD 2010 (AC1024), read by AutoCAD, KOMPAS, nanoCAD, LibreCAD, BricsCAD, QCAD
DXF_VERSION = "R2010"
#: the GUIDs written in the header (ezdxf would make random ones)
FIXED_GUID = "{00000000-0000-0000-0000-000000000000}"
#: the dates written in the header: 2000-01-01 as a Julian date (ezdxf would write the time now)
FIXED_JULIAN_DATE = 2451545.0
#: gap between pages when several scenes go into one file, mm
PAGE_GAP_MM = 20.0

#: role -> (layer name, ACI colour, description); every file defines all of them, in this order
LAYERS = {
    "frame": ("FRAME", 7, "frame, title block and tables"),
    "axes": ("AXES", 7, "axes, ticks, grid, scale bars"),
    "construction": ("CONSTRUCTION", 7, "construction lines, levels, projections, dimensions, points"),
    "known": ("VECTORS-KNOWN", 7, "vectors known before the construction (drawn solid)"),
    "found": ("VECTORS-FOUND", 7, "vectors found by the construction (drawn dashed)"),
    "curves": ("CURVES", 7, "the curves and main lines a figure is about"),
    "hatching": ("HATCHING", 7, "hatching of areas (excess work)"),
    "text": ("TEXT", 7, "labels, numbers, captions"),
}

#: text styles: name -> (font file, family, bold). A CAD program (AutoCAD, nanoCAD, BricsCAD, KOMPAS, ezdxf's
#: viewer) finds a style's font by its file name: Arial is on every Windows and macOS (ezdxf on Linux falls back to
#: DejaVu Sans); Chinese is drawn with Noto Sans CJK, the file Debian, Ubuntu, Fedora and Arch install
#: (fonts-noto-cjk) and the one graphmethods' PNG/PDF use; a Windows CAD program without it substitutes its own.
#: LibreCAD takes a text's style NAME for its own (.lff) font, so each style is named after the LibreCAD font that
#: draws it: OpenGostTypeB (Latin, Greek, Cyrillic: the ГОСТ 2.304 type B letters) and kst32b (with Chinese).
TEXT_STYLES = {
    "OpenGostTypeB-Regular": ("arial.ttf", "Arial", False),
    "lc_opengost-br": ("arialbd.ttf", "Arial", True),
    "kst32b": ("NotoSansCJK-Regular.ttc", "Noto Sans CJK SC", False),
}
STYLE_SANS, STYLE_BOLD, STYLE_CJK = TEXT_STYLES

#: dash patterns (mm, on and off) -> the standard linetype name each is written under. LibreCAD draws only the
#: linetypes it knows by name (any other prints solid), in its own pattern of that family; AutoCAD, ezdxf's viewer
#: and the others draw the pattern the file defines (ours). So each pattern of the figures has a standard name of
#: its family (dashes, dots, dash-dots), the shortest dashes the "2" (half) names; a pattern not listed keeps a
#: name of its own (GM-DASH-…), exact everywhere but LibreCAD.
STANDARD_LINETYPES = {
    (1.2, 0.8): "DASHED2", (2.0, 1.0): "HIDDEN2", (2.5, 1.2): "DASHED", (3.0, 1.0): "HIDDEN",
    (3.0, 1.2): "ACAD_ISO02W100", (4.0, 1.5): "DASHEDX2", (0.8, 0.8): "DOT", (0.5, 1.0): "DOT2",
    (6.0, 1.2, 1.0, 1.2): "DASHDOT", (6.0, 1.5, 1.0, 1.5): "CENTER", (5.0, 1.2, 1.0, 1.2): "DASHDOT2",
}
_LINETYPE_NOTE = "graphmethods dash "

#: DXF lineweights (1/100 mm) a CAD program accepts
_LINEWEIGHTS = (0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120, 140, 158, 200, 211)
_CJK = re.compile("[\u2e80-\u9fff\u3000-\u303f\uff00-\uffef]")

_FRAME_WORDS = ("page", "title-block", "table", "row", "header", "result", "cell", "heading")
_AXIS_WORDS = ("axis", "grid", "ruler", "tick")
_HATCH_WORDS = ("region", "hatch")
_CURVE_WORDS = ("curve", "chords", "lever", "thick", "moments-M")
_CONSTRUCTION_WORDS = ("line-", "ray", "level", "projection", "ordinate", "mean-", "position-", "extreme", "path-",
                       "guide", "psi-", "dimension", "leader", "pole", "start", "mark", "dot", "point", "vertex",
                       "tangency", "image", "joint", "pivot")


def lineweight(width_mm: float) -> int:
    """The DXF lineweight (1/100 mm) nearest to a stroke width in mm.

    >>> lineweight(0.35), lineweight(0.18), lineweight(0.5), lineweight(0.13)
    (35, 18, 50, 13)
    """
    w = max(0.0, float(width_mm)) * 100.0
    return min(_LINEWEIGHTS, key=lambda v: (abs(v - w), v))


def _words_in(ids: tuple[str, ...], words: Iterable[str]) -> bool:
    return any(w in gid for gid in ids for w in words)


def role_of(groups: tuple[str, ...], kind: str, style: Style | None) -> str:
    """The role (a key of :data:`LAYERS`) of a primitive, from the ids of the groups around it (outermost
    first), its kind (``path``, ``polygon``, ``circle``, ``text``) and its style.

    Vectors are known when their shaft is solid, found when dashed (the role of their head is decided by
    the renderer from the shaft's).

    >>> role_of(("page", "title-block"), "path", Style())
    'frame'
    >>> role_of(("vector-pb",), "path", Style(width_mm=0.35, dash=(2.5, 1.2)))
    'found'
    >>> role_of(("region-1",), "path", Style(width_mm=0.18)), role_of(("curve-M_d",), "path", Style(width_mm=0.5))
    ('hatching', 'curves')
    >>> role_of(("name-a",), "text", None)
    'text'
    """
    if kind == "text":
        return "text"
    ids = tuple(str(g).lower() for g in groups)
    if "page" in ids or _words_in(ids, ("title-block",)):
        return "frame"
    if _words_in(ids, ("vector", "force-")):
        return "found" if (style is not None and style.dash) else "known"
    if _words_in(ids, _HATCH_WORDS):
        return "hatching"
    if _words_in(ids, _AXIS_WORDS):
        return "axes"
    if _words_in(ids, _CURVE_WORDS):
        return "curves"
    if _words_in(ids, _FRAME_WORDS):
        return "frame"
    if _words_in(ids, _CONSTRUCTION_WORDS):
        return "construction"
    if style is not None and style.width_mm >= 0.5 and not style.dash:
        return "curves"
    return "construction"


def _rgb(color: str | None) -> int | None:
    """``#rrggbb`` as a 24-bit int; None for black or no colour (drawn ByLayer)."""
    if color is None or color == "none":
        return None
    c = color.strip().lstrip("#")
    if len(c) == 3:
        c = "".join(ch * 2 for ch in c)
    try:
        value = int(c, 16)
        if len(c) != 6:
            raise ValueError
    except ValueError:
        raise InputError(f"cannot draw the colour {color!r} in DXF: give it as #rrggbb") from None
    return None if value == 0 else value


def _is_white(color: str | None) -> bool:
    return color is not None and color.strip().lower() in ("#fff", "#ffffff", "white")


def _num(v: float) -> float:
    """A coordinate rounded to a micrometre (no −0, no float noise in the file)."""
    r = round(float(v), 6)
    return r + 0.0 if r != 0 else 0.0


@dataclass
class _Page:
    offset_x: float
    width: float
    height: float
    name: str


class DxfRenderer:
    """A :class:`~graphmethods.render.base.Renderer` adding one page's entities to an ezdxf document.

    Several renderers (one per page) share a document; each page is placed right of the previous one.
    """

    def __init__(self, doc: Drawing, offset_x_mm: float = 0.0, *, prefix: str = ""):
        self.doc = doc
        self.msp = doc.modelspace()
        self.offset_x = float(offset_x_mm)
        self.prefix = prefix
        self._stack: list[str] = []
        self._entities: list[list[DXFGraphic]] = []    # entities of each open top-level group
        self._vector_role: dict[tuple[str, ...], str] = {}
        self.page: _Page | None = None

    # -- coordinates and attributes
    def _xy(self, x: float, y: float) -> tuple[float, float]:
        assert self.page is not None
        return (_num(self.offset_x + x), _num(self.page.height - y))

    def _attribs(self, role: str, style: Style | None = None, color: str | None = None) -> dict[str, Any]:
        attrs: dict[str, Any] = {"layer": LAYERS[role][0]}
        rgb = _rgb(color if color is not None else (style.stroke if style is not None else None))
        if rgb is not None:
            attrs["true_color"] = rgb
        if style is not None:
            attrs["lineweight"] = lineweight(style.width_mm)
            if style.dash:
                attrs["linetype"] = self._linetype(style.dash)
        return attrs

    def _linetype(self, dash: tuple[float, ...]) -> str:
        """The linetype of a dash pattern (mm), defined in the file on first use: its standard name
        (:data:`STANDARD_LINETYPES`) unless the drawing already has that name for another pattern."""
        parts = [float(d) for d in dash]
        if len(parts) % 2:
            parts = parts * 2
        note = _LINETYPE_NOTE + " ".join(f"{d:g}" for d in parts) + " mm"
        name = STANDARD_LINETYPES.get(tuple(round(d, 3) for d in parts))
        if name is None or (name in self.doc.linetypes and self.doc.linetypes.get(name).dxf.description != note):
            name = "GM-DASH-" + "-".join(f"{d:g}".replace(".", "p") for d in parts)
        if name not in self.doc.linetypes:
            pattern = [sum(parts)] + [d if i % 2 == 0 else -d for i, d in enumerate(parts)]
            self.doc.linetypes.add(name, pattern=pattern, description=note)
        return name

    def _keep(self, entity: DXFGraphic) -> None:
        if self._entities:
            self._entities[-1].append(entity)

    def _role(self, kind: str, style: Style | None) -> str:
        stack = tuple(self._stack)
        role = role_of(stack, kind, style)
        if role in ("known", "found"):
            key = stack
            if kind == "path":
                self._vector_role.setdefault(key, role)
            role = self._vector_role.get(key, role)
        return role

    # -- Renderer protocol
    def begin(self, width_mm: float, height_mm: float, *, title: str, name: str) -> None:
        self.page = _Page(self.offset_x, float(width_mm), float(height_mm), name)

    def begin_group(self, id: str) -> None:
        self._stack.append(id)
        if len(self._stack) == 1:
            self._entities.append([])

    def end_group(self) -> None:
        gid = self._stack.pop()
        if not self._stack:
            entities = self._entities.pop()
            if entities:
                name = (self.prefix + gid)[:255]
                if name not in self.doc.groups:
                    group = self.doc.groups.new(name)
                    group.extend(entities)

    def path(self, points: tuple[XY, ...], style: Style, closed: bool) -> None:
        if len(points) < 2 or not style.stroke or style.stroke == "none":
            return
        attrs = self._attribs(self._role("path", style), style)
        pts = [self._xy(x, y) for x, y in points]
        self._keep(self.msp.add_lwpolyline(pts, close=bool(closed), dxfattribs=attrs))

    def polygon(self, points: tuple[XY, ...], style: Style) -> None:
        if len(points) < 2:
            return
        role = self._role("polygon", style)
        pts = [self._xy(x, y) for x, y in points]
        if style.fill and style.fill != "none" and not _is_white(style.fill) and len(points) >= 3:
            attrs = self._attribs(role, None, style.fill)
            if len(pts) == 3:
                self._keep(self.msp.add_solid(pts, dxfattribs=attrs))
            else:
                hatch = self.msp.add_hatch(dxfattribs=attrs)
                hatch.paths.add_polyline_path(pts, is_closed=True)
                self._keep(hatch)
        if style.stroke and style.stroke != "none" and style.width_mm > 0:
            attrs = self._attribs(role, style)
            self._keep(self.msp.add_lwpolyline(pts, close=True, dxfattribs=attrs))

    def circle(self, cx: float, cy: float, r: float, style: Style) -> None:
        role = self._role("circle", style)
        c = self._xy(cx, cy)
        if style.fill and style.fill != "none" and not _is_white(style.fill):
            hatch = self.msp.add_hatch(dxfattribs=self._attribs(role, None, style.fill))
            edges = hatch.paths.add_edge_path()
            edges.add_arc(c, _num(r), 0.0, 360.0)
            self._keep(hatch)
        if style.stroke and style.stroke != "none" and style.width_mm > 0:
            self._keep(self.msp.add_circle(c, _num(r), dxfattribs=self._attribs(role, style)))

    def text(self, label: Label) -> None:
        from ezdxf.enums import TextEntityAlignment

        runs = [(t, s) for t, s in label.runs if t]
        if not runs:
            return
        attrs = self._attribs("text", None, label.color)
        cjk = any(_CJK.search(t) for t, _ in runs)
        style = STYLE_CJK if cjk else (STYLE_BOLD if label.bold else STYLE_SANS)
        size = label.size_mm
        if label.stretch != 1.0:                  # condensed lettering: the TEXT's width factor
            attrs = dict(attrs, width=_num(label.stretch))
        if len(runs) == 1 and runs[0][1] == 0:
            text, _ = runs[0]
            align = {"start": TextEntityAlignment.LEFT, "middle": TextEntityAlignment.CENTER,
                     "end": TextEntityAlignment.RIGHT}[label.anchor]
            e = self.msp.add_text(text, height=_num(size * CAP), dxfattribs=dict(attrs, style=style))
            e.set_placement(self._xy(label.x, label.y), align=align)
            self._keep(e)
            return
        widths = [text_width_mm(t, size * (1.0 if s == 0 else SCRIPT_SCALE)) * label.stretch for t, s in runs]
        x = label.x - {"start": 0.0, "middle": sum(widths) / 2.0, "end": sum(widths)}[label.anchor]
        for (chunk, shift), w in zip(runs, widths):
            h = size * (1.0 if shift == 0 else SCRIPT_SCALE)
            dy = baseline_shift_mm(shift, size)
            e = self.msp.add_text(chunk, height=_num(h * CAP), dxfattribs=dict(attrs, style=style))
            e.set_placement(self._xy(x, label.y + dy), align=TextEntityAlignment.LEFT)
            self._keep(e)
            x += w

    def end(self) -> _Page | None:
        return self.page


def _new_document() -> Drawing:
    import ezdxf  # the only import of ezdxf in graphmethods
    from ezdxf import units

    doc = ezdxf.new(DXF_VERSION, setup=False)
    doc.units = units.MM
    doc.header["$MEASUREMENT"] = 1            # metric
    doc.header["$LWDISPLAY"] = 1              # show lineweights
    doc.header["$LTSCALE"] = 1.0
    doc.header["$TEXTSTYLE"] = STYLE_SANS
    for _role, (name, color, description) in LAYERS.items():
        layer = doc.layers.add(name, color=color)
        layer.description = description
    for name, (font, family, bold) in TEXT_STYLES.items():
        style = doc.styles.add(name, font=font)
        style.set_extended_font_data(family=family, italic=False, bold=bold)
    return doc


class _FixedMetadata:
    """While open, ezdxf writes fixed dates, GUIDs and its marker without a time (its option for
    reproducible files); the option is put back as it was on leaving."""

    def __enter__(self) -> _FixedMetadata:
        import ezdxf

        self.saved = ezdxf.options.write_fixed_meta_data_for_testing
        ezdxf.options.write_fixed_meta_data_for_testing = True
        return self

    def __exit__(self, *exc: object) -> Literal[False]:
        import ezdxf

        ezdxf.options.write_fixed_meta_data_for_testing = self.saved
        return False


def _fixed_write(doc: Drawing) -> bytes:
    """The document as DXF bytes with fixed dates and GUIDs (ezdxf stamps the time on every write)."""
    with _FixedMetadata():
        for var in ("$TDCREATE", "$TDUCREATE", "$TDUPDATE", "$TDUUPDATE"):
            doc.header[var] = FIXED_JULIAN_DATE
        for var in ("$TDINDWG", "$TDUSRTIMER"):
            doc.header[var] = 0.0
        doc.header["$FINGERPRINTGUID"] = FIXED_GUID
        doc.header["$VERSIONGUID"] = FIXED_GUID
        # the CLASSES section: ezdxf adds a class per entity type in use in the order of a set (which
        # changes with the process's hash seed); add them now and sort them, and the write keeps the order
        doc.classes.add_required_classes(doc.dxfversion)
        ordered = sorted(doc.classes.classes.items())
        doc.classes.classes.clear()
        doc.classes.classes.update(ordered)
        stream = io.StringIO()
        doc.write(stream)
    return doc.encode(stream.getvalue())


def document(scenes: Scene | Iterable[Scene]) -> Drawing:
    """An ezdxf document of ``scenes`` (one or several, laid left to right).

    Returns
    -------
    ezdxf.document.Drawing
    """
    if isinstance(scenes, Scene):
        scenes = [scenes]
    with _FixedMetadata():
        doc = _new_document()
    x = 0.0
    pages = []
    for i, scene in enumerate(scenes):
        if not isinstance(scene, Scene):
            raise InputError(f"DXF: page {i + 1} is {type(scene).__name__}, not a Scene")
        page = draw(scene, DxfRenderer(doc, x, prefix="" if i == 0 else f"p{i + 1}-"))
        pages.append(page)
        x += page.width + PAGE_GAP_MM
    if not pages:
        raise InputError("a DXF needs at least one figure: no scenes were given")
    width = x - PAGE_GAP_MM
    height = max(p.height for p in pages)
    doc.header["$EXTMIN"] = (0.0, 0.0, 0.0)
    doc.header["$EXTMAX"] = (width, height, 0.0)
    doc.header["$LIMMIN"] = (0.0, 0.0)
    doc.header["$LIMMAX"] = (width, height)
    doc.set_modelspace_vport(height=height * 1.05, center=(width / 2.0, height / 2.0))
    return doc


def to_bytes(scenes: Scene | Iterable[Scene]) -> bytes:
    """DXF (R2010, UTF-8) of one scene or several; the same scenes give the same bytes.

    Examples
    --------
    >>> from graphmethods.scene import Scene, Page, Text
    >>> data = to_bytes(Scene(Page("A4"), (Text((10, 10), "ψ_{max}"),)))
    >>> b"AC1024" in data, data.rstrip().endswith(b"EOF")
    (True, True)
    """
    return _fixed_write(document(scenes))


def save(scenes: Scene | Iterable[Scene], path: str | os.PathLike[str], *,
         overwrite: bool = False) -> pathlib.Path:
    """Write one scene or several as DXF atomically; refuses to replace a file unless ``overwrite``.

    Raises
    ------
    OutputExistsError
        If ``path`` exists and ``overwrite`` is false.
    """
    return write_atomic(path, to_bytes(scenes), overwrite=overwrite)


# ----------------------------------------------------------------------------- reading a drawing made in CAD

@dataclass(frozen=True)
class CadText:
    """A text of a drawing: its plain characters, the centre of its box (mm, y up) and its height (mm)."""

    text: str
    x: float
    y: float
    height: float


@dataclass(frozen=True)
class CadDrawing:
    """What a drawing holds, flattened, in mm with y up: straight segments, filled polygons (arrowheads,
    hatches, SOLIDs, tapered polyline segments), circles (x, y, r) and texts."""

    segments: tuple[tuple[tuple[float, float], tuple[float, float]], ...]
    fills: tuple[tuple[tuple[float, float], ...], ...]
    circles: tuple[tuple[float, float, float], ...]
    texts: tuple[CadText, ...]
    source: str = ""


def _text_centre(x: float, y: float, height: float, text: str, halign: int, valign: int) -> tuple[float, float]:
    w = 0.65 * height * len(text)                 # about the width of a sans font's letters, cap height h
    cx = {0: x + w / 2, 1: x, 2: x - w / 2, 4: x}.get(halign, x + w / 2)
    cy = {0: y + height / 2, 1: y + height / 2, 2: y, 3: y - height / 2}.get(valign, y + height / 2)
    return cx, cy


def read_drawing(source: str | os.PathLike[str] | bytes | bytearray) -> CadDrawing:
    """Read a DXF drawing (a path, or the file's bytes) into a :class:`CadDrawing`.

    LINE, LWPOLYLINE and 2D POLYLINE give segments (a segment of changing width, AutoCAD's way of
    drawing an arrowhead, gives a filled triangle); SOLID, TRACE, 3DFACE and HATCH boundaries give
    filled polygons; CIRCLE circles; TEXT and MTEXT texts; blocks (INSERT) are exploded. Model space only.

    Raises
    ------
    InputError
        If the file cannot be read as DXF.

    Examples
    --------
    >>> from graphmethods.scene import Scene, Page, Scale, Vector, Text
    >>> d = read_drawing(to_bytes(Scene(Page("A4"), (Vector((20, 100), (60, 100), name="v"), Text((10, 10), "p")))))
    >>> len(d.segments), len(d.fills), [t.text for t in d.texts]
    (1, 1, ['p'])
    """
    doc, name = _read_document(source)
    reader = _DxfReader()
    try:
        for entity in doc.modelspace():
            reader.visit(entity)
    except InputError as exc:
        raise InputError(f"{name}: {exc}") from None
    except (ValueError, TypeError, ZeroDivisionError, IndexError, KeyError, AttributeError, OverflowError,
            RecursionError) as exc:          # an entity ezdxf read but cannot give (a broken block reference)
        raise InputError(f"{name}: not a readable DXF drawing ({exc.__class__.__name__}: {_one_line(exc)})") from None
    return reader.drawing(name, _to_mm(doc))


def _read_document(source: str | os.PathLike[str] | bytes | bytearray) -> tuple[Drawing, str]:
    """The DXF document and the name to give it in messages; an InputError saying why it cannot be read."""
    import ezdxf
    from ezdxf.lldxf.const import DXFError

    name = str(source) if not isinstance(source, (bytes, bytearray)) else "<dxf>"
    if not isinstance(source, (bytes, bytearray)):
        input_file(source, missing="no such drawing")       # a regular file within the size cap, before ezdxf
    try:
        if isinstance(source, (bytes, bytearray)):
            doc = ezdxf.read(io.StringIO(bytes(source).decode("utf-8", errors="replace")))
        else:
            doc = ezdxf.readfile(str(source))
    except OSError as exc:
        if isinstance(source, (bytes, bytearray)) or pathlib.Path(source).is_file():     # ezdxf: "is not a DXF file"
            raise InputError(f"{name}: not a readable DXF drawing ({_one_line(exc)})") from None
        raise InputError(f"{name}: cannot read it ({exc.__class__.__name__}: {_one_line(exc)})") from None
    except (DXFError, ValueError, TypeError, IndexError, KeyError, AttributeError, UnicodeDecodeError, StopIteration,
            EOFError, RecursionError, OverflowError) as exc:   # ezdxf on a cut or malformed file
        raise InputError(f"{name}: not a readable DXF drawing ({exc.__class__.__name__}: {_one_line(exc)})") from None
    return doc, name


def _decoded(text: str) -> str:
    """A DXF text with ezdxf's own decoding of the ``\\U+03BC`` escapes older DXF versions store (μ, Δ, ω)."""
    from ezdxf.lldxf.encoding import decode_dxf_unicode, has_dxf_unicode

    return decode_dxf_unicode(text) if has_dxf_unicode(text) else text


def _one_line(exc: BaseException) -> str:
    """An exception's message as one line (a parser's message may quote a line of the file, newline and all)."""
    return " ".join(str(exc).split())[:200]


def _xy(v: Any) -> tuple[float, float]:           # an ezdxf Vec2/Vec3 or a point tuple
    return (float(v[0]), float(v[1]))


class _DxfReader:
    """Collects a DXF's model space as segments, filled polygons, circles and texts (drawing units).

    TEXT entities are gathered as runs first: a run written just after another, of another size, is the
    sub- or superscript of the same label (as :func:`to_bytes` writes them) and joins it.
    """

    def __init__(self) -> None:
        self.segs: list[tuple[XY, XY]] = []
        self.fills: list[tuple[XY, ...]] = []
        self.circles: list[tuple[float, float, float]] = []
        self.texts: list[CadText] = []
        # TEXT entities: (text, x, y, height, left-aligned, last run's height, its x, its text, halign, valign)
        self.runs: list[tuple[Any, ...]] = []
        self.count = 0                 # entities visited, every copy of a block's entity counted

    def visit(self, entity: Any, depth: int = 0) -> None:    # any DXF entity (its attributes differ by type)
        t = entity.dxftype()
        self.count += 1
        if self.count > MAX_DXF_ENTITIES:
            raise InputError(f"more than {MAX_DXF_ENTITIES} entities once its blocks are expanded "
                             f"(MAX_DXF_ENTITIES, counted in copies); explode fewer blocks or draw the entities")
        if t == "INSERT":
            if depth >= MAX_DXF_DEPTH:
                raise InputError(f"blocks inserted more than {MAX_DXF_DEPTH} levels deep (MAX_DXF_DEPTH)")
            block = entity.block()
            copies = int(getattr(entity, "mcount", 1) or 1) * (len(block) if block is not None else 0)
            if self.count + copies > MAX_DXF_ENTITIES:
                raise InputError(f"more than {MAX_DXF_ENTITIES} entities once its blocks are expanded "
                                 f"(MAX_DXF_ENTITIES, counted in copies: block {entity.dxf.name!r} adds "
                                 f"{copies}); explode fewer blocks or draw the entities")
            for e in entity.virtual_entities():
                self.visit(e, depth + 1)
        elif t == "LINE":
            self.segs.append((_xy(entity.dxf.start), _xy(entity.dxf.end)))
        elif t in ("LWPOLYLINE", "POLYLINE"):
            self.polyline(entity, t)
        elif t in ("SOLID", "TRACE", "3DFACE"):
            self.solid(entity, t)
        elif t == "HATCH":
            self.hatch(entity)
        elif t == "CIRCLE":
            self.circles.append((float(entity.dxf.center[0]), float(entity.dxf.center[1]),
                                 float(entity.dxf.radius)))
        elif t == "TEXT":
            self.text(entity)
        elif t == "MTEXT":
            h = float(entity.dxf.get("char_height", 2.5))
            text = _decoded(entity.plain_text(split=False)).strip()
            ap = int(entity.dxf.get("attachment_point", 1))      # 1 top left … 9 bottom right
            col, row = (ap - 1) % 3, (ap - 1) // 3
            at = entity.dxf.insert
            cx = float(at[0]) + {0: 0.65 * h * len(text) / 2, 1: 0.0, 2: -0.65 * h * len(text) / 2}[col]
            cy = float(at[1]) + {0: -h / 2, 1: 0.0, 2: h / 2}[row]
            self.texts.append(CadText(text, cx, cy, h))

    def polyline(self, entity: Any, t: str) -> None:
        """Its segments; a segment of changing width (an arrowhead) as a filled triangle."""
        if t == "LWPOLYLINE":
            pts = [(float(x), float(y), float(s), float(e)) for x, y, s, e in entity.get_points("xyse")]
            closed = bool(entity.closed)
        else:
            if entity.is_3d_polyline or entity.is_poly_face_mesh or entity.is_polygon_mesh:
                return
            pts = [(float(v.dxf.location[0]), float(v.dxf.location[1]), float(v.dxf.get("start_width", 0.0)),
                    float(v.dxf.get("end_width", 0.0))) for v in entity.vertices]
            closed = bool(entity.is_closed)
        n = len(pts)
        for i in range(n if closed else n - 1):
            (x0, y0, s0, e0), (x1, y1, _, _) = pts[i], pts[(i + 1) % n]
            if abs(s0 - e0) > 1e-9 and math.hypot(x1 - x0, y1 - y0) > 1e-9:
                ux, uy = (x1 - x0) / math.hypot(x1 - x0, y1 - y0), (y1 - y0) / math.hypot(x1 - x0, y1 - y0)
                tip, base, w = ((x1, y1), (x0, y0), s0) if e0 < s0 else ((x0, y0), (x1, y1), e0)
                self.fills.append((tip, (base[0] - uy * w / 2, base[1] + ux * w / 2),
                                   (base[0] + uy * w / 2, base[1] - ux * w / 2)))
            else:
                self.segs.append(((x0, y0), (x1, y1)))

    def solid(self, entity: Any, t: str) -> None:
        """A SOLID, TRACE or 3DFACE as a filled polygon (repeated corners dropped)."""
        vs = [_xy(entity.dxf.get(f"vtx{i}")) for i in range(4) if entity.dxf.hasattr(f"vtx{i}")]
        if t != "3DFACE" and len(vs) == 4:
            vs = [vs[0], vs[1], vs[3], vs[2]]          # SOLID's corner order
        out: list[tuple[float, float]] = []
        for v in vs:
            if not out or math.dist(v, out[-1]) > 1e-9:
                out.append(v)
        if len(out) > 1 and math.dist(out[0], out[-1]) <= 1e-9:
            out.pop()
        if len(out) >= 3:
            self.fills.append(tuple(out))

    def hatch(self, entity: Any) -> None:
        """A HATCH's boundaries as filled polygons (its arc edges as circles)."""
        for path in entity.paths:
            corners: list[tuple[float, float]] = []
            if hasattr(path, "vertices"):
                corners = [_xy(v) for v in path.vertices]
            else:
                for edge in path.edges:
                    if hasattr(edge, "start") and hasattr(edge, "end") and not hasattr(edge, "radius"):
                        corners.append(_xy(edge.start))   # a line edge
                    elif hasattr(edge, "center") and hasattr(edge, "radius"):
                        self.circles.append((float(edge.center[0]), float(edge.center[1]), float(edge.radius)))
            if len(corners) >= 3:
                self.fills.append(tuple(corners))

    def text(self, entity: Any) -> None:
        """A TEXT as a run of its label (joined to the previous run when it is that label's sub/superscript)."""
        h = float(entity.dxf.height)
        text = _decoded(entity.plain_text() if hasattr(entity, "plain_text") else entity.dxf.text)
        halign, valign = int(entity.dxf.get("halign", 0)), int(entity.dxf.get("valign", 0))
        aligned = (halign or valign) and entity.dxf.hasattr("align_point")
        at = entity.dxf.align_point if aligned else entity.dxf.insert
        x, y = float(at[0]), float(at[1])
        runs = self.runs
        last = runs[-1] if runs else None
        if (last is not None and text and halign == valign == 0 and last[4]
                and abs(h - last[5]) > 0.2 * max(h, last[5])          # a change of size: a sub/superscript
                and last[6] + 0.2 * last[5] * len(last[7]) - 0.1 <= x
                <= last[6] + 1.3 * last[5] * len(last[7]) + 0.6 * last[5]
                and abs(y - last[2]) <= 0.7 * max(h, last[3])):
            # the next run of one label, written as its own TEXT (as render.dxf writes sub/superscripts)
            y0, h0 = (y, h) if h > last[3] else (last[2], last[3])
            runs[-1] = (last[0] + text, last[1], y0, h0, True, h, x, text, 0, 0)
        else:
            runs.append((text, x, y, h, halign == valign == 0, h, x, text, halign, valign))

    def drawing(self, name: str, f: float) -> CadDrawing:
        """What was read, in mm (``f``: mm per drawing unit), the TEXT runs as texts after the MTEXTs."""
        texts = list(self.texts)
        for text, x, y, h, *_, halign, valign in self.runs:
            cx, cy = _text_centre(x, y, h, text, halign, valign)
            texts.append(CadText(text, cx, cy, h))
        segs, fills, circles = self.segs, self.fills, self.circles
        if f != 1.0:                          # a drawing in cm, m or inches: everything in mm
            def s(p: XY) -> XY:
                return (p[0] * f, p[1] * f)
            segs = [(s(a), s(b)) for a, b in segs]
            fills = [tuple(s(p) for p in poly) for poly in fills]
            circles = [(x * f, y * f, r * f) for x, y, r in circles]
            texts = [CadText(t.text, t.x * f, t.y * f, t.height * f) for t in texts]
        return CadDrawing(tuple(segs), tuple(fills), tuple(circles), tuple(texts), source=name)


def _to_mm(doc: Drawing) -> float:
    """The factor from the drawing's units ($INSUNITS) to mm; 1 when unitless or mm (CAD's default in
    metric drawings)."""
    from ezdxf import units

    u = int(doc.header.get("$INSUNITS", 0) or 0)
    if u in (0, units.MM):
        return 1.0
    try:
        return float(units.conversion_factor(units.InsertUnits(u), units.InsertUnits(units.MM)))
    except (KeyError, ValueError, IndexError):
        raise InputError(f"the drawing's units ($INSUNITS = {u}) are not a length: draw in mm") from None


class _OntoRenderer(DxfRenderer):
    """Draws a scene into an existing drawing: every entity on one layer, page mm shifted to drawing mm."""

    def __init__(self, doc: Drawing, *, layer: str, shift: tuple[float, float]):
        super().__init__(doc, 0.0, prefix=f"{layer}-")
        self.layer, self.shift = layer, shift

    def _xy(self, x: float, y: float) -> tuple[float, float]:
        assert self.page is not None
        return (_num(x + self.shift[0]), _num(self.page.height - y + self.shift[1]))

    def _attribs(self, role: str, style: Style | None = None, color: str | None = None) -> dict[str, Any]:
        attrs = super()._attribs(role, style, color)
        attrs["layer"] = self.layer
        return attrs


def overlay_onto(source: str | os.PathLike[str], scene: Scene, *, shift: tuple[float, float] = (0.0, 0.0),
                 layer: str = "CHECK") -> bytes:
    """A DXF drawing (path) with ``scene`` added on the layer ``layer`` (red): page mm (y down) become the
    drawing's mm as ``(x + shift_x, height − y + shift_y)``. The student's entities are kept as they are.

    Raises
    ------
    InputError
        If the drawing cannot be read.
    """
    import ezdxf
    from ezdxf.lldxf.const import DXFError

    input_file(source, missing="no such drawing")
    try:
        doc = ezdxf.readfile(str(source))
    except (OSError, DXFError, ValueError, TypeError, IndexError, KeyError, AttributeError, UnicodeDecodeError,
            StopIteration, EOFError, RecursionError, OverflowError) as exc:
        raise InputError(f"{source}: not a readable DXF drawing ({exc.__class__.__name__}: {_one_line(exc)})") from None
    if layer not in doc.layers:
        doc.layers.add(layer, color=1)                  # red
    for name, (font, family, bold) in TEXT_STYLES.items():
        if name not in doc.styles:
            doc.styles.add(name, font=font).set_extended_font_data(family=family, italic=False, bold=bold)
    draw(scene, _OntoRenderer(doc, layer=layer, shift=shift))
    return _fixed_write(doc)
