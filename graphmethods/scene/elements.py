"""Figure elements in paper millimetres: frozen, composable, with named anchors.

Every element is a frozen dataclass with a ``name`` (its id in the output) and
``primitives()``, the :mod:`~graphmethods.scene.primitives` it draws. Elements hold
no global state; they are placed by points in page millimetres (x right, y down),
and the named anchors (``.start``, ``.end``, ``.origin``, ``.tip`` ...) of one element
place the next, as in schemdraw, without a drawing stack.

A physical value reaches paper only through a :class:`~graphmethods.scene.scale.Scale`:
:class:`Frame` maps (x, y) values to page points, :meth:`Vector.of` draws a value as
a vector of length value/μ, :class:`Axis` ticks values.

>>> from graphmethods.scene.scale import Scale
>>> mu_E = Scale("μ_E", "J", 5.0)
>>> v = Vector.of((20.0, 100.0), value=50.0, scale=mu_E, angle_deg=90, name="ab")
>>> v.end, round(v.length_mm, 3)
((20.0, 90.0), 10.0)
>>> frame = Frame((30.0, 120.0), Scale("μ_φ", "rad", 0.025), Scale("μ_M", "N·m", 2.0))
>>> frame.pt(0.5, 40.0)
(50.0, 100.0)
"""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from graphmethods.errors import InputError
from graphmethods.scene import markup
from graphmethods.scene.markup import MIN_TEXT_MM
from graphmethods.scene.numbers import format_value
from graphmethods.scene.primitives import (
    AXIS,
    MAIN,
    THIN,
    VECTOR,
    XY,
    Circle,
    Group as PGroup,
    Label,
    Path,
    Polygon,
    Primitive,
    Style,
    walk,
)
from graphmethods.scene.scale import Scale
from graphmethods.units import is_finite

if TYPE_CHECKING:
    from shapely.geometry.base import BaseGeometry

    from graphmethods.scene.notation import Notation

#: vertical metrics of the default font, in em: ascent above the baseline, descent below, cap height
ASCENT, DESCENT, CAP = 0.76, 0.24, 0.73

def lettered_size(size_mm: float) -> float:
    """A font size raised to the smallest the sheet being drawn allows (:data:`MIN_TEXT_MM`).

    Parameters
    ----------
    size_mm : float, mm
        The size a figure asks for.

    Returns
    -------
    float, mm
        ``size_mm``, or the sheet's smallest lettering when that is larger (outside a sheet: unchanged).

    Examples
    --------
    >>> lettered_size(2.0)
    2.0
    """
    return max(float(size_mm), MIN_TEXT_MM.get())


def _letter(element: Any) -> None:
    """Raise a frozen element's ``size_mm`` to :func:`lettered_size` (at construction, inside the sheet)."""
    if MIN_TEXT_MM.get() > element.size_mm:
        object.__setattr__(element, "size_mm", MIN_TEXT_MM.get())


def _pt(p: Sequence[float] | NDArray[np.float64]) -> XY:
    if (type(p) is tuple and len(p) == 2 and type(p[0]) is float and type(p[1]) is float    # the common case
            and math.isfinite(p[0]) and math.isfinite(p[1])):
        return p
    try:
        x, y = p
        x, y = float(x), float(y)
    except (TypeError, ValueError):
        raise InputError(f"expected a point (x_mm, y_mm), got {p!r}") from None
    if not (is_finite(x) and is_finite(y)):
        raise InputError(f"point {p!r} is not finite; a figure cannot place it")
    return (x, y)


def _checked_points(element: object, *names: str) -> None:
    """Replace each named point field of a frozen element by its checked ``(x_mm, y_mm)`` (:func:`_pt`)."""
    for name in names:
        object.__setattr__(element, name, _pt(getattr(element, name)))


def _pts(points: ArrayLike) -> tuple[XY, ...]:
    arr = np.asarray(points, dtype=float)
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise InputError(f"expected a list of (x_mm, y_mm) points, got shape {arr.shape}")
    if not np.isfinite(arr).all():
        i = int(np.flatnonzero(~np.isfinite(arr).all(axis=1))[0])
        raise InputError(f"point {i} of a polyline is not finite ({arr[i].tolist()}); fix the data it comes from")
    return tuple(map(tuple, arr.tolist()))         # Python floats, as float() of each gives


@functools.lru_cache(maxsize=16384)
def _runs_extent(runs: tuple[tuple[str, int], ...]) -> tuple[float, float, float]:
    """(width, ascent, descent) of a label's runs in em (label placement asks for the same texts again and again)."""
    w = sum((1.0 if s == 0 else markup.SCRIPT_SCALE) * sum(markup.char_em(c) for c in t) for t, s in runs)
    descent = DESCENT + (markup.SUB_SHIFT if any(s < 0 for _, s in runs) else 0.0)
    ascent = ASCENT + (0.1 if any(s > 0 for _, s in runs) else 0.0)
    return w, ascent, descent


_NO_ANCHOR: dict[str, float] = {}          # an anchor other than start, middle, end: a KeyError, as before


def label_bbox(lab: Label) -> tuple[float, float, float, float]:
    """Estimated box ``(x0, y0, x1, y1)`` in mm that a :class:`Label` covers.

    Parameters
    ----------
    lab : Label
        A placed label (its anchor, size, stretch and markup runs count).

    Returns
    -------
    tuple of float, mm
        Left, top, right, bottom on the page (y down), from the font's estimated advance widths.

    Examples
    --------
    >>> tuple(round(v, 2) for v in label_bbox(make_label((10.0, 20.0), "v_B", size_mm=5.0)))
    (10.0, 16.2, 15.36, 22.3)
    """
    w, ascent, descent = _runs_extent(lab.runs)
    w *= lab.size_mm * lab.stretch
    a = lab.anchor
    x0 = lab.x - (0.0 if a == "start" else w / 2 if a == "middle" else w if a == "end" else _NO_ANCHOR[a])
    return (x0, lab.y - ascent * lab.size_mm, x0 + w, lab.y + descent * lab.size_mm)


def bbox(prims: Iterable[Primitive]) -> tuple[float, float, float, float] | None:
    """Box ``(x0, y0, x1, y1)`` in mm around primitives (labels estimated); None when empty.

    Parameters
    ----------
    prims : iterable of Primitive
        Paths, polygons, circles, labels and groups of them.

    Returns
    -------
    tuple of float, mm, or None
        Left, top, right, bottom around every primitive; None when there is none.

    Examples
    --------
    >>> from graphmethods.scene.primitives import Circle, Path
    >>> bbox([Circle(0.0, 0.0, 2.0), Path(((1.0, 1.0), (5.0, 3.0)))]), bbox([])
    ((-2.0, -2.0, 5.0, 3.0), None)
    """
    xs0, ys0, xs1, ys1 = [], [], [], []
    for p in walk(prims):
        if isinstance(p, (Path, Polygon)) and p.points:
            a = np.asarray(p.points)
            xs0.append(a[:, 0].min())
            xs1.append(a[:, 0].max())
            ys0.append(a[:, 1].min())
            ys1.append(a[:, 1].max())
        elif isinstance(p, Circle):
            xs0.append(p.cx - p.r)
            xs1.append(p.cx + p.r)
            ys0.append(p.cy - p.r)
            ys1.append(p.cy + p.r)
        elif isinstance(p, Label):
            b = label_bbox(p)
            xs0.append(b[0])
            ys0.append(b[1])
            xs1.append(b[2])
            ys1.append(b[3])
    if not xs0:
        return None
    return (float(min(xs0)), float(min(ys0)), float(max(xs1)), float(max(ys1)))


class Element:
    """Base of every element: a name, primitives, and a group that wraps them."""

    name: str

    def primitives(self) -> tuple[Primitive, ...]:  # pragma: no cover - every element overrides it
        raise NotImplementedError

    def draw(self) -> PGroup:
        """The element as one named :class:`~graphmethods.scene.primitives.Group`."""
        return PGroup(self.name, tuple(self.primitives()))

    def bbox(self) -> tuple[float, float, float, float] | None:
        """Estimated box ``(x0, y0, x1, y1)`` in mm the element covers."""
        return bbox(self.primitives())


# --------------------------------------------------------------------------- text

#: how far (em) the baseline lies below the point a label is aligned at, by vertical alignment
_VALIGN_SHIFT = {"baseline": 0.0, "middle": CAP / 2, "top": ASCENT, "bottom": -DESCENT}


def make_label(at: Sequence[float], text: str, *, size_mm: float = 3.5, anchor: str = "start", valign: str = "baseline",
               bold: bool = False, markup_: bool = True, color: str = "#000000") -> Label:
    """A :class:`Label` placed by its anchor and vertical alignment (baseline, middle, top, bottom).

    Parameters
    ----------
    at : (float, float), mm
        The anchor point on the page.
    text : str
        The text, in markup (``v_B``, ``ω^2``) unless ``markup_=False``.
    size_mm : float, mm
        Font size, raised to the sheet's smallest lettering (:func:`lettered_size`).
    anchor : {"start", "middle", "end"}
        Which end of the text stands at ``at``.
    valign : {"baseline", "middle", "top", "bottom"}
        Which height of the text stands at ``at``.
    bold, markup_, color
        Weight, whether ``text`` is markup, colour.

    Returns
    -------
    Label

    Raises
    ------
    InputError
        For an unknown anchor or alignment.

    Examples
    --------
    >>> lab = make_label((10.0, 20.0), "v_B", size_mm=5.0)
    >>> lab.x, lab.y, lab.anchor, lab.runs
    (10.0, 20.0, 'start', (('v', 0), ('B', -1)))
    """
    if anchor not in ("start", "middle", "end"):
        raise InputError(f"text anchor {anchor!r}: use 'start', 'middle' or 'end'")
    x, y = _pt(at)
    size_mm = max(float(size_mm), MIN_TEXT_MM.get())      # lettered_size
    try:
        shift = _VALIGN_SHIFT[valign]
    except (KeyError, TypeError):
        raise InputError(f"text valign {valign!r}: use one of {', '.join(_VALIGN_SHIFT)}") from None
    runs = markup.parse(text) if markup_ else (((text, 0),) if text else ())
    return Label(x, y + shift * size_mm, runs, size_mm, anchor, bold, color)


@dataclass(frozen=True)
class Text(Element):
    """A line of text; ``"ψ_{max}"`` markup draws a smaller, lowered subscript.

    Parameters
    ----------
    at : (float, float), mm
        The anchor point.
    text : str
        Markup (``markup=False`` for user text drawn literally).
    size_mm : float, mm
        Font size.
    anchor : {'start', 'middle', 'end'}
        Which end of the text is at ``at``.
    valign : {'baseline', 'middle', 'top', 'bottom'}
        Which height of the text is at ``at``.

    Examples
    --------
    >>> t = Text((10, 20), "ΔW_{max} = 575 J", anchor="middle")
    >>> t.primitives()[0].runs
    (('ΔW', 0), ('max', -1), (' = 575 J', 0))
    """

    at: XY
    text: str
    size_mm: float = 3.5
    anchor: str = "start"
    valign: str = "baseline"
    bold: bool = False
    markup: bool = True
    name: str = "text"

    def __post_init__(self) -> None:
        _letter(self)

    def primitives(self) -> tuple[Primitive, ...]:
        return (make_label(self.at, self.text, size_mm=self.size_mm, anchor=self.anchor, valign=self.valign,
                           bold=self.bold, markup_=self.markup),)


# --------------------------------------------------------------------------- lines

@dataclass(frozen=True)
class Line(Element):
    """A straight line from ``start`` to ``end`` (mm).

    >>> Line((0, 0), (3, 4)).mid
    (1.5, 2.0)
    """

    start: XY
    end: XY
    style: Style = THIN
    name: str = "line"

    @property
    def mid(self) -> XY:
        return ((self.start[0] + self.end[0]) / 2, (self.start[1] + self.end[1]) / 2)

    def primitives(self) -> tuple[Primitive, ...]:
        return (Path((_pt(self.start), _pt(self.end)), self.style),)


@dataclass(frozen=True)
class Polyline(Element):
    """A polyline through points in mm; a curve is a finely sampled polyline.

    >>> Polyline(((0, 0), (10, 0), (10, 5))).end
    (10.0, 5.0)
    """

    points: tuple[XY, ...]
    style: Style = MAIN
    closed: bool = False
    name: str = "curve"

    def __post_init__(self) -> None:
        object.__setattr__(self, "points", _pts(self.points))
        if len(self.points) < 2:
            raise InputError(f"{self.name}: a polyline needs at least two points, got {len(self.points)}")

    @property
    def start(self) -> XY:
        return self.points[0]

    @property
    def end(self) -> XY:
        return self.points[-1]

    def primitives(self) -> tuple[Primitive, ...]:
        return (Path(self.points, self.style, self.closed),)


Curve = Polyline


@dataclass(frozen=True)
class Frame:
    """Maps physical (x, y) values to page points through two scales; ``origin`` is (0, 0).

    Values grow to the right and upwards on paper (page y grows downwards).

    >>> f = Frame((10.0, 100.0), Scale("μ_x", "m", 0.5), Scale("μ_y", "J", 10.0))
    >>> f.pts([0, 1], [0, 100])
    ((10.0, 100.0), (12.0, 90.0))
    """

    origin: XY
    x: Scale
    y: Scale

    def pt(self, xv: float, yv: float) -> XY:
        """Page point of the values (xv, yv)."""
        return (self.origin[0] + self.x.to_mm(float(xv)), self.origin[1] - self.y.to_mm(float(yv)))

    def pts(self, xs: ArrayLike, ys: ArrayLike) -> tuple[XY, ...]:
        """Page points of arrays of values (vectorised)."""
        X = self.origin[0] + self.x.to_mm(np.asarray(xs, dtype=float))
        Y = self.origin[1] - self.y.to_mm(np.asarray(ys, dtype=float))
        return tuple(zip(X.tolist(), Y.tolist()))

    def curve(self, xs: ArrayLike, ys: ArrayLike, *, style: Style = MAIN, name: str = "curve") -> Polyline:
        """A :class:`Polyline` through the values."""
        return Polyline(self.pts(xs, ys), style=style, name=name)


# --------------------------------------------------------------------------- regions

@dataclass(frozen=True)
class Region(Element):
    """A region filled and/or hatched with explicit line segments clipped to it (shapely).

    Parameters
    ----------
    outline : sequence of (float, float), mm
        The boundary (closed implicitly); self-touching outlines are repaired.
    hatch_angle_deg : float or None
        Direction of the hatching as seen on paper (45: rising to the right); None: no hatching.
    hatch_spacing_mm : float, mm
        Distance between hatching lines (lines sit on a page-wide grid, so neighbours align).
    fill : str or None
        Fill colour drawn under the hatching.
    keep_clear : tuple of (x0, y0, x1, y1)
        Boxes in mm the hatching must not cross (room for labels).

    Examples
    --------
    >>> r = Region(((0, 0), (10, 0), (10, 10), (0, 10)), hatch_angle_deg=0, hatch_spacing_mm=2.5)
    >>> len(r.hatch_segments())
    3
    """

    outline: tuple[XY, ...]
    hatch_angle_deg: float | None = 45.0
    hatch_spacing_mm: float = 2.0
    fill: str | None = None
    keep_clear: tuple[tuple[float, float, float, float], ...] = ()
    style: Style = THIN
    outline_style: Style | None = None
    name: str = "region"

    def __post_init__(self) -> None:
        object.__setattr__(self, "outline", _pts(self.outline))
        if self.hatch_spacing_mm <= 0:
            raise InputError(f"{self.name}: hatch spacing must be positive, got {self.hatch_spacing_mm} mm")

    def shape(self) -> BaseGeometry:
        """The region as a shapely geometry (valid), without the keep-clear boxes."""
        import shapely
        from shapely.geometry import Polygon as SPolygon

        if len(self.outline) < 3:
            return SPolygon()
        return shapely.make_valid(SPolygon(self.outline)).buffer(0)

    def hatch_segments(self) -> list[tuple[XY, XY]]:
        """The hatching as explicit segments ``((x0, y0), (x1, y1))`` in mm, clipped to the region (found once
        per region: a figure registers a region's ink for label placement, then draws it)."""
        found = self.__dict__.get("_hatch")
        if found is None:
            found = tuple(self._hatch_segments())
            object.__setattr__(self, "_hatch", found)
        return list(found)

    def _hatch_segments(self) -> list[tuple[XY, XY]]:
        import shapely
        from shapely.geometry import box

        if self.hatch_angle_deg is None:
            return []
        geom = self.shape()
        for b in self.keep_clear:
            geom = geom.difference(box(*b))
        if geom.is_empty:
            return []
        a = math.radians(self.hatch_angle_deg)
        d = np.array([math.cos(a), -math.sin(a)])           # along the lines, on paper (y down)
        n = np.array([-d[1], d[0]])                          # across them
        x0, y0, x1, y1 = geom.bounds
        corners = np.array([[x0, y0], [x1, y0], [x0, y1], [x1, y1]])
        proj = corners @ n
        s = self.hatch_spacing_mm
        ks = np.arange(math.floor(proj.min() / s), math.ceil(proj.max() / s) + 1)
        reach = float(np.hypot(x1 - x0, y1 - y0)) + 1.0
        centre = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
        along = centre @ d
        base = ks[:, None] * s * n[None, :] + along * d[None, :]
        p = base - reach * d
        q = base + reach * d
        lines = shapely.linestrings(np.stack([p, q], axis=1))
        cut = np.asarray(shapely.intersection(lines, geom))     # one geometry per line (an array)
        parts = shapely.get_parts(cut[~shapely.is_empty(cut)])
        out = []
        edge = geom.boundary
        for part in parts:
            if part.geom_type != "LineString" or part.length < 1e-6:
                continue
            if edge.distance(part.interpolate(0.5, normalized=True)) < 1e-7:  # lies on an edge: drawn already
                continue
            c = np.asarray(part.coords)
            out.append(((float(c[0, 0]), float(c[0, 1])), (float(c[-1, 0]), float(c[-1, 1]))))
        return out

    def primitives(self) -> tuple[Primitive, ...]:
        prims: list[Primitive] = []
        if self.fill:
            prims.append(Polygon(self.outline, Style(stroke=None, width_mm=0.0, fill=self.fill)))
        prims.extend(Path(seg, self.style) for seg in self.hatch_segments())
        if self.outline_style is not None:
            prims.append(Path(self.outline, self.outline_style, closed=True))
        return tuple(prims)


@dataclass(frozen=True)
class SignMark(Element):
    """A sign + or − drawn with strokes (font independent), centred at ``at``.

    >>> len(SignMark((0, 0), "+").primitives()), len(SignMark((0, 0), "-").primitives())
    (2, 1)
    """

    at: XY
    sign: str = "+"
    size_mm: float = 3.0
    style: Style = Style(width_mm=0.35)
    name: str = "sign"

    def __post_init__(self) -> None:
        sign = {"+": "+", "-": "-", "−": "-"}.get(self.sign)
        if sign is None:
            raise InputError(f"{self.name}: sign must be '+' or '−', got {self.sign!r}")
        object.__setattr__(self, "sign", sign)

    def primitives(self) -> tuple[Primitive, ...]:
        x, y = _pt(self.at)
        h = self.size_mm / 2
        prims: list[Primitive] = [Path(((x - h, y), (x + h, y)), self.style)]
        if self.sign == "+":
            prims.append(Path(((x, y - h), (x, y + h)), self.style))
        return tuple(prims)


# --------------------------------------------------------------------------- vectors and points

def _arrowhead(tip: XY, direction: np.ndarray, length: float, width: float) -> Polygon:
    base = np.asarray(tip) - direction * length
    perp = np.array([-direction[1], direction[0]]) * width / 2
    pts = (tip, tuple((base + perp).tolist()), tuple((base - perp).tolist()))
    return Polygon(pts)


@dataclass(frozen=True)
class _Segment(Element):
    """An element drawn between two points ``start`` and ``end`` (mm), checked finite on construction."""

    start: XY
    end: XY

    def __post_init__(self) -> None:
        _checked_points(self, "start", "end")


@dataclass(frozen=True)
class Vector(_Segment):
    """An arrow from ``start`` to ``end`` (its tip). Solid when known, dashed when unknown.

    Drawn as a shaft (a :class:`Path` from ``start`` to the base of the head) and a
    filled head (a :class:`Polygon` whose first point is the tip), so the drawn
    length start→tip is exactly the vector's length.

    Examples
    --------
    >>> v = Vector((0, 0), (0, -20), known=False)
    >>> shaft, head = v.primitives()
    >>> shaft.style.dash is not None, head.points[0]
    (True, (0.0, -20.0))
    """

    known: bool = True
    head_length_mm: float = 3.0
    head_width_mm: float = 1.1
    style: Style = VECTOR
    name: str = "vector"

    @classmethod
    def of(cls, start: Sequence[float], *, value: float, scale: Scale, angle_deg: float = 0.0, **kw: Any) -> Vector:
        """The vector of a physical ``value`` drawn ``value/μ`` mm long at ``angle_deg``.

        The angle is as seen on paper, counterclockwise from the +x direction; a
        negative value points the opposite way.
        """
        sx, sy = _pt(start)
        length = scale.to_mm(float(value))
        a = math.radians(angle_deg)
        return cls((sx, sy), (sx + length * math.cos(a), sy - length * math.sin(a)), **kw)

    @property
    def length_mm(self) -> float:
        return math.dist(self.start, self.end)

    @property
    def tip(self) -> XY:
        return self.end

    @property
    def mid(self) -> XY:
        return ((self.start[0] + self.end[0]) / 2, (self.start[1] + self.end[1]) / 2)

    def primitives(self) -> tuple[Primitive, ...]:
        L = self.length_mm
        if L < 1e-9:
            return (Circle(self.start[0], self.start[1], 0.5, Style(stroke=None, width_mm=0, fill="#000000")),)
        d = (np.asarray(self.end) - np.asarray(self.start)) / L
        hl = min(self.head_length_mm, L * 0.6)
        hw = self.head_width_mm * hl / self.head_length_mm
        base = tuple((np.asarray(self.end) - d * hl).tolist())
        style = self.style if self.known else self.style.with_(dash=(2.5, 1.2))
        return (Path((self.start, base), style), _arrowhead(self.end, d, hl, hw))


_DIRS = {"n": (0, -1), "ne": (1, -1), "e": (1, 0), "se": (1, 1), "s": (0, 1), "sw": (-1, 1), "w": (-1, 0),
         "nw": (-1, -1)}
#: per direction: its (dx, dy), their length, and the anchor and vertical alignment a label beside a point takes
_PLACES = {d: (dx, dy, math.hypot(dx, dy), {1: "start", 0: "middle", -1: "end"}[dx],
               {1: "top", 0: "middle", -1: "bottom"}[dy]) for d, (dx, dy) in _DIRS.items()}


def place_label(at: Sequence[float], text: str, direction: str, *, gap_mm: float = 1.2, size_mm: float = 3.5,
                bold: bool = False, markup_: bool = True) -> Label:
    """A label beside the point ``at`` in compass ``direction`` (n, ne, e, ... nw), ``gap_mm`` away.

    Parameters
    ----------
    at : (float, float), mm
        The point the label names.
    text : str
        The text (markup unless ``markup_=False``).
    direction : str
        Compass direction from the point: ``"n"``, ``"ne"``, ``"e"``, ``"se"``, ``"s"``, ``"sw"``, ``"w"``,
        ``"nw"`` (page y down: ``"n"`` is above).
    gap_mm : float, mm
        Distance from the point to the label's nearest corner or side.
    size_mm, bold, markup_
        As :func:`make_label` takes them.

    Returns
    -------
    Label
        Anchored and aligned so that it grows away from the point.

    Examples
    --------
    >>> lab = place_label((10.0, 20.0), "B", "ne")
    >>> round(lab.x, 3), round(lab.y, 3), lab.anchor
    (10.849, 18.311, 'start')
    """
    try:
        dx, dy, norm, anchor, valign = _PLACES[direction]
    except (KeyError, TypeError):
        raise InputError(f"label direction {direction!r}: use one of {', '.join(_DIRS)}") from None
    x, y = _pt(at)
    x, y = x + gap_mm * dx / norm, y + gap_mm * dy / norm
    return make_label((x, y), text, size_mm=size_mm, anchor=anchor, valign=valign, bold=bold, markup_=markup_)


@dataclass(frozen=True)
class Point(Element):
    """A point (a dot, or a small circle when not filled) with an optional label beside it.

    >>> m = Point((10, 10), "a", label_dir="nw")
    >>> [type(p).__name__ for p in m.primitives()]
    ['Circle', 'Label']
    """

    at: XY
    label: str = ""
    label_dir: str = "ne"
    radius_mm: float = 0.6
    filled: bool = True
    size_mm: float = 3.5
    gap_mm: float = 1.0
    name: str = "point"

    def __post_init__(self) -> None:
        _letter(self)

    def primitives(self) -> tuple[Primitive, ...]:
        x, y = _pt(self.at)
        style = Style(stroke=None, width_mm=0.0, fill="#000000") if self.filled else THIN.with_(fill="#ffffff")
        prims: list[Primitive] = [Circle(x, y, self.radius_mm, style)]
        if self.label:
            prims.append(place_label((x, y), self.label, self.label_dir, gap_mm=self.gap_mm + self.radius_mm,
                                     size_mm=self.size_mm))
        return tuple(prims)


@dataclass(frozen=True)
class Dimension(_Segment):
    """A dimension line between two measured points, with its value written beside it.

    The line is drawn ``offset_mm`` away from the measured points along the normal
    ``(-u_y, u_x)`` of the direction ``u`` from ``start`` to ``end`` (for a vertical
    dimension measured upwards: to the right), with extension lines and arrowheads
    whose tips touch the extension lines.

    Examples
    --------
    >>> d = Dimension((0, 50), (0, 10), "ΔW_{max} = 575 J", offset_mm=5)
    >>> d.line_start, d.line_end, round(d.length_mm, 3)
    ((5.0, 50.0), (5.0, 10.0), 40.0)
    """

    text: str = ""
    offset_mm: float = 0.0
    size_mm: float = 3.5
    style: Style = THIN
    name: str = "dimension"

    def __post_init__(self) -> None:
        super().__post_init__()
        _letter(self)

    def _frame(self) -> tuple[NDArray[np.float64], NDArray[np.float64], float, NDArray[np.float64],
                              NDArray[np.float64]]:
        p1, p2 = np.asarray(self.start, dtype=float), np.asarray(self.end, dtype=float)
        L = float(np.hypot(*(p2 - p1)))
        u = (p2 - p1) / L if L > 0 else np.array([1.0, 0.0])
        n = np.array([-u[1], u[0]])
        return p1, p2, L, u, n

    @property
    def length_mm(self) -> float:
        return math.dist(self.start, self.end)

    @property
    def line_start(self) -> XY:
        p1, _, _, _, n = self._frame()
        return tuple((p1 + self.offset_mm * n).tolist())

    @property
    def line_end(self) -> XY:
        _, p2, _, _, n = self._frame()
        return tuple((p2 + self.offset_mm * n).tolist())

    @property
    def mid(self) -> XY:
        a, b = self.line_start, self.line_end
        return ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)

    def primitives(self) -> tuple[Primitive, ...]:
        p1, p2, L, u, n = self._frame()
        q1, q2 = p1 + self.offset_mm * n, p2 + self.offset_mm * n
        prims: list[Primitive] = []
        if abs(self.offset_mm) > 1e-9:
            sgn = 1.0 if self.offset_mm > 0 else -1.0
            for p, q in ((p1, q1), (p2, q2)):
                a = p + sgn * min(1.0, abs(self.offset_mm) / 2) * n
                b = q + sgn * 1.5 * n
                prims.append(Path((tuple(a.tolist()), tuple(b.tolist())), self.style))
        if L > 1e-9:
            hl, hw = 2.5, 0.9
            if L >= 2.2 * hl:  # arrows inside, tips on the extension lines
                prims.append(Path((tuple(q1.tolist()), tuple(q2.tolist())), self.style))
                prims.append(_arrowhead(tuple(q1.tolist()), -u, hl, hw))
                prims.append(_arrowhead(tuple(q2.tolist()), u, hl, hw))
            else:  # too short: arrows outside pointing in
                ends = (tuple((q1 - u * (hl + 2)).tolist()), tuple((q2 + u * (hl + 2)).tolist()))
                prims.append(Path(ends, self.style))
                prims.append(_arrowhead(tuple(q1.tolist()), u, hl, hw))
                prims.append(_arrowhead(tuple(q2.tolist()), -u, hl, hw))
        if self.text:
            mid = (q1 + q2) / 2
            if abs(u[0]) < abs(u[1]):  # mostly vertical: horizontal text beside it
                side = "e" if n[0] >= 0 else "w"
            else:
                side = "n" if n[1] <= 0 else "s"
            prims.append(place_label(tuple(mid.tolist()), self.text, side, gap_mm=1.2, size_mm=self.size_mm))
        return tuple(prims)


# --------------------------------------------------------------------------- axes

def pi_ticks(period: float, scale: Scale, *, min_gap_mm: float = 8.0) -> tuple[tuple[float, ...], tuple[str, ...]]:
    """Ticks for an angle axis at multiples of π/12, π/6, π/4, π/2 or π, labelled ``"π/2"``, ``"3π/2"``.

    >>> pi_ticks(2 * math.pi, Scale("μ_φ", "rad", 0.025), min_gap_mm=40)[1]
    ('0', 'π/2', 'π', '3π/2', '2π')
    """
    from fractions import Fraction

    for den in (12, 6, 4, 2, 1):
        if scale.to_mm(math.pi / den) >= min_gap_mm:
            break
    n = math.floor(period / (math.pi / den) + 1e-9)
    values, labels = [], []
    for i in range(n + 1):
        f = Fraction(i, den)
        if f == 0:
            text = "0"
        else:
            num = "" if f.numerator == 1 else str(f.numerator)
            text = f"{num}π" + ("" if f.denominator == 1 else f"/{f.denominator}")
        values.append(i * math.pi / den)
        labels.append(text)
    return tuple(values), tuple(labels)


@dataclass(frozen=True)
class Axis(Element):
    """A coordinate axis drawn to a scale: ticks labelled in physical units, arrow at the positive end.

    Parameters
    ----------
    origin : (float, float), mm
        Page point of the value 0.
    scale : Scale
        The axis's scale (its caption belongs under the figure).
    direction : {'x', 'y'}
        Horizontal (values grow right) or vertical (values grow up).
    min_value, max_value : float
        The drawn range, in the scale's unit; the arrow extends ``arrow_mm`` beyond ``max_value``.
    ticks : tuple of float
        Tick values (in range); ``tick_labels`` their texts (formatted numbers by default).
    label : str
        The axis name at its arrow, markup (``"M, N·m"``): right of the tip of an x axis,
        right of the top of a y axis.
    skip_zero_label : bool
        Leave the tick label at 0 out (where two axes cross).
    labels_side : {'', 'below', 'above', 'left', 'right'}
        Where tick marks and labels go: below an x axis and left of a y axis by default;
        'above' suits an x axis with the curve below it.

    Examples
    --------
    >>> ax = Axis((20, 100), Scale("μ_M", "N·m", 2.0), "y", min_value=-10, max_value=40, ticks=(0, 20, 40))
    >>> ax.pos(20), ax.tip
    ((20.0, 90.0), (20.0, 74.0))
    """

    origin: XY
    scale: Scale
    direction: str = "x"
    min_value: float = 0.0
    max_value: float = 1.0
    ticks: tuple[float, ...] = ()
    tick_labels: tuple[str, ...] | None = None
    label: str = ""
    arrow_mm: float = 6.0
    tick_mm: float = 1.5
    size_mm: float = 3.0
    decimal: str = "."
    skip_zero_label: bool = False
    labels_side: str = ""
    name: str = "axis"

    def __post_init__(self) -> None:
        allowed = {"x": ("", "below", "above"), "y": ("", "left", "right")}.get(self.direction, ())
        if self.labels_side not in allowed:
            raise InputError(f"{self.name}: labels_side {self.labels_side!r} does not suit a {self.direction} axis; "
                             f"use one of {', '.join(repr(a) for a in allowed if a)}")
        if self.direction not in ("x", "y"):
            raise InputError(f"{self.name}: axis direction must be 'x' or 'y', got {self.direction!r}")
        if not self.max_value > self.min_value:
            raise InputError(f"{self.name}: axis range {self.min_value}..{self.max_value} is empty; "
                             f"max_value must exceed min_value")
        if self.tick_labels is not None and len(self.tick_labels) != len(self.ticks):
            raise InputError(f"{self.name}: {len(self.ticks)} ticks but {len(self.tick_labels)} tick labels")
        _letter(self)
        _checked_points(self, "origin")

    def pos(self, value: float) -> XY:
        """Page point of ``value`` on the axis."""
        mm = self.scale.to_mm(float(value))
        ox, oy = self.origin
        return (ox + mm, oy) if self.direction == "x" else (ox, oy - mm)

    @property
    def start(self) -> XY:
        return self.pos(self.min_value)

    @property
    def tip(self) -> XY:
        """The arrow tip, ``arrow_mm`` beyond ``max_value``."""
        x, y = self.pos(self.max_value)
        return (x + self.arrow_mm, y) if self.direction == "x" else (x, y - self.arrow_mm)

    end = tip

    def primitives(self) -> tuple[Primitive, ...]:
        d = np.array([1.0, 0.0]) if self.direction == "x" else np.array([0.0, -1.0])
        prims: list[Primitive] = [Path((self.start, self.tip), AXIS), _arrowhead(self.tip, d, 3.0, 1.1)]
        labels = self.tick_labels
        if labels is None:
            labels = tuple(format_value(v, decimal=self.decimal) for v in self.ticks)
        flip = self.labels_side in ("above", "right")
        t = -self.tick_mm if flip else self.tick_mm
        for v, text in zip(self.ticks, labels):
            x, y = self.pos(v)
            show = text and not (self.skip_zero_label and v == 0)
            if self.direction == "x":
                prims.append(Path(((x, y), (x, y + t)), AXIS))
                if show:
                    prims.append(make_label((x, y + t + (-0.8 if flip else 0.8)), text, size_mm=self.size_mm,
                                            anchor="middle", valign="bottom" if flip else "top"))
            else:
                prims.append(Path(((x - t, y), (x, y)), AXIS))
                if show:
                    prims.append(make_label((x - t + (0.8 if flip else -0.8), y), text, size_mm=self.size_mm,
                                            anchor="start" if flip else "end", valign="middle"))
        if self.label:
            tx, ty = self.tip
            if self.direction == "x":   # right of the tip, just above the line (the line may go on)
                prims.append(make_label((tx + 1.0, ty - 1.0), self.label, size_mm=self.size_mm + 0.5,
                                        anchor="start", valign="bottom"))
            else:
                prims.append(make_label((tx + 2.5, ty), self.label, size_mm=self.size_mm + 0.5, anchor="start",
                                        valign="top"))
        return tuple(prims)


# --------------------------------------------------------------------------- tables and captions

@dataclass(frozen=True)
class Table(Element):
    """A drawn table: grid lines and cell texts; column widths fit the texts.

    Parameters
    ----------
    at : (float, float), mm
        Top-left corner.
    rows : tuple of tuple of str
        Cell texts (markup), row by row; the first ``header_rows`` rows are headings.
    align : str
        One letter per column: ``l``, ``c`` or ``r``.
    bold_rows : tuple of int
        Rows written bold (headings are always bold).

    Examples
    --------
    >>> t = Table((10, 10), (("i", "A_i, J"), ("1", "50"), ("2", "−550")), align="cr")
    >>> round(t.height_mm, 3), t.column_widths()[0] >= 8
    (21.0, True)
    """

    at: XY
    rows: tuple[tuple[str, ...], ...]
    col_widths_mm: tuple[float, ...] | None = None
    row_height_mm: float = 7.0
    size_mm: float = 3.2
    header_rows: int = 1
    align: str = ""
    bold_rows: tuple[int, ...] = ()
    padding_mm: float = 2.0
    min_col_mm: float = 8.0
    name: str = "table"

    def __post_init__(self) -> None:
        rows = tuple(tuple(str(c) for c in r) for r in self.rows)
        if not rows:
            raise InputError(f"{self.name}: a table needs at least one row")
        ncol = len(rows[0])
        for i, r in enumerate(rows):
            if len(r) != ncol:
                raise InputError(f"{self.name}: row {i} has {len(r)} cells, the first row has {ncol}")
        object.__setattr__(self, "rows", rows)
        _checked_points(self, "at")
        given = self.size_mm
        _letter(self)
        if self.size_mm > given:                 # lettered up on a course sheet: the cells grow with the text
            k = self.size_mm / given
            object.__setattr__(self, "row_height_mm", self.row_height_mm * k)
            if self.col_widths_mm is not None:
                object.__setattr__(self, "col_widths_mm", tuple(w * k for w in self.col_widths_mm))
        if self.col_widths_mm is not None and len(self.col_widths_mm) != ncol:
            raise InputError(f"{self.name}: {len(self.col_widths_mm)} column widths for {ncol} columns")

    def column_widths(self) -> tuple[float, ...]:
        """Column widths in mm (given, or fitted to the widest text plus padding)."""
        if self.col_widths_mm is not None:
            return tuple(float(w) for w in self.col_widths_mm)
        lettering = MIN_TEXT_MM.get()              # the widths measured depend on it (text_width_mm)
        memo = self.__dict__.get("_widths_memo")   # measured once per lettering (each cell asks for them)
        if memo is not None and memo[0] == lettering:
            cached: tuple[float, ...] = memo[1]
            return cached
        widths = self._fitted_widths()
        object.__setattr__(self, "_widths_memo", (lettering, widths))
        return widths

    def _fitted_widths(self) -> tuple[float, ...]:
        ncol = len(self.rows[0])
        widths = []
        for j in range(ncol):
            w = max(markup.text_width_mm(r[j], self.size_mm) * (1.08 if i < self.header_rows or i in self.bold_rows
                                                                  else 1.0)
                    for i, r in enumerate(self.rows))
            widths.append(max(self.min_col_mm, w + 2 * self.padding_mm))
        return tuple(widths)

    @property
    def width_mm(self) -> float:
        return float(sum(self.column_widths()))

    @property
    def height_mm(self) -> float:
        return self.row_height_mm * len(self.rows)

    @property
    def bottom_left(self) -> XY:
        return (self.at[0], self.at[1] + self.height_mm)

    @property
    def top_right(self) -> XY:
        return (self.at[0] + self.width_mm, self.at[1])

    def cell_box(self, i: int, j: int) -> tuple[float, float, float, float]:
        """Box (x0, y0, x1, y1) of cell (row i, column j), mm."""
        widths = self.column_widths()
        x0 = self.at[0] + sum(widths[:j])
        y0 = self.at[1] + i * self.row_height_mm
        return (x0, y0, x0 + widths[j], y0 + self.row_height_mm)

    def primitives(self) -> tuple[Primitive, ...]:
        widths = self.column_widths()
        x0, y0 = self.at
        W, H = sum(widths), self.height_mm
        prims: list[Primitive] = [Path(((x0, y0), (x0 + W, y0), (x0 + W, y0 + H), (x0, y0 + H)), AXIS, closed=True)]
        for i in range(1, len(self.rows)):
            if i < self.header_rows:        # a heading of two rows reads as one cell ("Acceleration," over "m/s²")
                continue
            y = y0 + i * self.row_height_mm
            prims.append(Path(((x0, y), (x0 + W, y)), AXIS if i == self.header_rows else THIN))
        x = x0
        for w in widths[:-1]:
            x += w
            prims.append(Path(((x, y0), (x, y0 + H)), THIN))
        align = (self.align or "c" * len(widths)).ljust(len(widths), "c")
        for i, row in enumerate(self.rows):
            bold = i < self.header_rows or i in self.bold_rows
            for j, text in enumerate(row):
                if not text:
                    continue
                bx0, by0, bx1, by1 = self.cell_box(i, j)
                a = "c" if i < self.header_rows and self.header_rows > 1 else align[j]
                x = {"l": bx0 + self.padding_mm, "c": (bx0 + bx1) / 2, "r": bx1 - self.padding_mm}[a]
                anchor = {"l": "start", "c": "middle", "r": "end"}[a]
                prims.append(make_label((x, (by0 + by1) / 2), text, size_mm=self.size_mm, anchor=anchor,
                                        valign="middle", bold=bold))
        return tuple(prims)


@dataclass(frozen=True)
class ScaleCaptions(Element):
    """The captions of the scales a figure uses, on one line under it: ``μ_M = 100 N·m/mm   μ_φ = …``.

    >>> c = ScaleCaptions((10, 200), (Scale("μ_M", "N·m", 100.0),))
    >>> c.primitives()[0].text
    'μM = 100 N·m/mm'
    """

    at: XY
    scales: tuple[Scale, ...]
    notation: Notation | str | None = None
    size_mm: float = 3.5
    gap_mm: float = 10.0
    anchor: str = "start"
    name: str = "scale-captions"

    def __post_init__(self) -> None:
        _letter(self)

    def captions(self) -> tuple[str, ...]:
        return tuple(s.caption(self.notation) for s in self.scales)

    def primitives(self) -> tuple[Primitive, ...]:
        texts = self.captions()
        widths = [markup.text_width_mm(t, self.size_mm) for t in texts]
        total = sum(widths) + self.gap_mm * max(0, len(texts) - 1)
        x, y = _pt(self.at)
        x -= {"start": 0.0, "middle": total / 2, "end": total}[self.anchor]
        prims: list[Primitive] = []
        for t, w in zip(texts, widths):
            prims.append(make_label((x, y), t, size_mm=self.size_mm, anchor="start"))
            x += w + self.gap_mm
        return tuple(prims)


@dataclass(frozen=True)
class Group(Element):
    """Elements composed under one name (one group in the output)."""

    elements: tuple[Element, ...] = ()
    name: str = "group"

    def primitives(self) -> tuple[Primitive, ...]:
        return tuple(e.draw() for e in self.elements)


__all__ = [
    "Element", "Text", "Line", "Polyline", "Curve", "Frame", "Region", "SignMark", "Vector", "Point", "Dimension",
    "Axis", "Table", "ScaleCaptions", "Group", "pi_ticks", "make_label", "place_label", "label_bbox",
    "bbox", "ASCENT", "DESCENT", "CAP",
]
