"""Textbook symbols of kinematic schemes, built from the scene's primitives (paper mm, y down).

The symbols students draw on a scheme of a linkage (ГОСТ 2.770, ISO 3952 in spirit):
:class:`PinJoint` (a small circle), :class:`FixedPivot` (a pin joint on a triangle standing on
a hatched ground line), :class:`Guide` (the line of a slider's motion and the hatched guide
surface beside it), :class:`SliderBlock` (a rectangle around its pin) and
:class:`RotationArrow` (the arc arrow of the crank's sense of rotation, ω₁). Each is a frozen
:class:`~graphmethods.scene.Element` placed by page points, like the scene's own elements.

Angles are as seen on paper: counterclockwise from the +x direction (right), so 90° points up
the page and 270° down.

>>> piv = FixedPivot((50.0, 40.0))
>>> [type(p).__name__ for p in piv.primitives()][:3]
['Path', 'Path', 'Path']
>>> round(piv.ground_line[0][1] - 40.0, 3)       # the ground line is height_mm below the joint
5.0
>>> SliderBlock((10.0, 10.0), angle_deg=0.0).corners()[0]
(5.0, 13.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import Element, Region
from graphmethods.scene.elements import lettered_size, make_label
from graphmethods.scene.primitives import THIN, Circle, Path, Polygon, Style

XY = tuple[float, float]

#: a pin joint: white inside, a firm outline
JOINT = Style(width_mm=0.3, fill="#ffffff")
#: the ground line and guide surface
GROUND = Style(width_mm=0.4)
#: the line of a slider's motion (chain line)
CHAIN = Style(width_mm=0.18, dash=(6.0, 1.2, 1.0, 1.2))
#: a slider block
BLOCK = Style(width_mm=0.5, fill="#ffffff")


def _unit(angle_deg: float) -> np.ndarray:
    """Unit vector on paper (y down) at ``angle_deg`` counterclockwise from +x."""
    a = math.radians(angle_deg)
    return np.array([math.cos(a), -math.sin(a)])


def _xy(p) -> XY:
    try:
        x, y = (float(v) for v in p)
    except (TypeError, ValueError):
        raise InputError(f"expected a point (x_mm, y_mm), got {p!r}") from None
    if not (math.isfinite(x) and math.isfinite(y)):
        raise InputError(f"point {p!r} is not finite; a symbol cannot be placed there")
    return (x, y)


def _t(a) -> XY:
    return (float(a[0]), float(a[1]))


def arrowhead(tip: XY, direction, *, length_mm: float = 2.5, width_mm: float = 0.9) -> Polygon:
    """A filled arrowhead whose first point is the ``tip``, pointing along ``direction`` (paper)."""
    d = np.asarray(direction, dtype=float)
    d = d / float(np.hypot(*d))
    n = np.array([-d[1], d[0]])
    t = np.asarray(tip, dtype=float)
    base = t - d * length_mm
    return Polygon((_t(t), _t(base + n * width_mm), _t(base - n * width_mm)),
                   Style(stroke=None, width_mm=0.0, fill="#000000"))


@dataclass(frozen=True)
class PinJoint(Element):
    """A pin (revolute) joint: a small circle, white inside.

    >>> PinJoint((5, 5), radius_mm=1.0).primitives()[0].r
    1.0
    """

    at: XY
    radius_mm: float = 1.0
    style: Style = JOINT
    name: str = "joint"

    def primitives(self):
        x, y = _xy(self.at)
        return (Circle(x, y, self.radius_mm, self.style),)


@dataclass(frozen=True)
class FixedPivot(Element):
    """A pin joint on the frame: the circle, two legs down to a ground line, hatching behind it.

    Parameters
    ----------
    at : (float, float), mm
        The joint's centre.
    direction_deg : float
        Where the ground lies, seen from the joint (270: below).
    height_mm, width_mm : float, mm
        Height of the support triangle and width of its base.
    ground_mm, hatch_mm : float, mm
        Length of the ground line and depth of the hatched strip behind it.
    """

    at: XY
    direction_deg: float = 270.0
    radius_mm: float = 1.2
    height_mm: float = 5.0
    width_mm: float = 6.0
    ground_mm: float = 11.0
    hatch_mm: float = 2.2
    name: str = "fixed-pivot"

    def _frame(self):
        c = np.asarray(_xy(self.at))
        d = _unit(self.direction_deg)
        n = np.array([-d[1], d[0]])
        return c, d, n

    @property
    def ground_line(self) -> tuple[XY, XY]:
        """The ground line's two ends, mm."""
        c, d, n = self._frame()
        g = c + d * self.height_mm
        return _t(g - n * self.ground_mm / 2), _t(g + n * self.ground_mm / 2)

    def outline(self) -> tuple[XY, ...]:
        """The support's outline (page mm): from the joint to the ground line and round its hatched strip.
        Nothing else is drawn inside it (the ω₁ arrow keeps out).

        >>> [tuple(round(v, 1) for v in p) for p in FixedPivot((0.0, 0.0)).outline()]
        [(0.0, 0.0), (5.5, 5.0), (5.5, 7.2), (-5.5, 7.2), (-5.5, 5.0)]
        """
        c, d, n = self._frame()
        g = c + d * self.height_mm
        h = g + d * self.hatch_mm
        half = n * self.ground_mm / 2
        return (_t(c), _t(g - half), _t(h - half), _t(h + half), _t(g + half))

    def hatch_region(self) -> Region:
        """The hatched strip behind the ground line (built once per support: its region clips its hatching
        once, however often the support is drawn, registered or measured)."""
        found: Region | None = self.__dict__.get("_hatch_region")
        if found is None:
            c, d, n = self._frame()
            g = c + d * self.height_mm
            h = g + d * self.hatch_mm
            half = n * self.ground_mm / 2
            outline = (_t(g - half), _t(g + half), _t(h + half), _t(h - half))
            found = Region(outline, hatch_angle_deg=self.direction_deg + 135.0, hatch_spacing_mm=1.3,
                           name=f"{self.name}-hatch")
            object.__setattr__(self, "_hatch_region", found)
        return found

    def primitives(self):
        c, d, n = self._frame()
        g = c + d * self.height_mm
        prims = []
        for s in (-1.0, 1.0):                       # the legs, from the circle to the base corners
            corner = g + s * n * self.width_mm / 2
            u = (corner - c) / float(np.hypot(*(corner - c)))
            prims.append(Path((_t(c + u * self.radius_mm), _t(corner)), GROUND))
        prims.append(Path(self.ground_line, GROUND))
        prims.extend(self.hatch_region().primitives())
        prims.append(Circle(c[0], c[1], self.radius_mm, JOINT))
        return tuple(prims)


@dataclass(frozen=True)
class Guide(Element):
    """A slider's guide: the line of its motion (chain line) and the hatched guide surface beside it.

    Parameters
    ----------
    start, end : (float, float), mm
        The ends of the line of motion drawn.
    offset_mm : float, mm
        Distance from the line of motion to the guide surface (half the block's height).
    side : {+1, -1}
        Which side the surface lies on: +1 left of start→end as seen on paper, −1 right
        (for a guide drawn left to right: +1 above, −1 below).
    hatch_mm : float, mm
        Depth of the hatched strip behind the surface.
    """

    start: XY
    end: XY
    offset_mm: float = 3.0
    side: int = -1
    hatch_mm: float = 2.2
    axis: bool = True
    name: str = "guide"

    def _frame(self):
        p, q = np.asarray(_xy(self.start)), np.asarray(_xy(self.end))
        L = float(np.hypot(*(q - p)))
        if L <= 0:
            raise InputError(f"{self.name}: a guide needs two distinct ends")
        u = (q - p) / L
        left = np.array([u[1], -u[0]])             # left of u on paper (y down)
        return p, q, u, left * (1.0 if self.side >= 0 else -1.0)

    @property
    def surface(self) -> tuple[XY, XY]:
        """The guide surface's two ends, mm."""
        p, q, _, n = self._frame()
        return _t(p + n * self.offset_mm), _t(q + n * self.offset_mm)

    def _hatch_region(self) -> Region:
        """The hatched strip behind the surface, built once per guide (its hatching clipped once)."""
        found: Region | None = self.__dict__.get("_hatch")
        if found is None:
            p, q, u, n = self._frame()
            a, b = p + n * self.offset_mm, q + n * self.offset_mm
            c, d = a + n * self.hatch_mm, b + n * self.hatch_mm
            angle = math.degrees(math.atan2(-u[1], u[0])) + 45.0
            found = Region((_t(a), _t(b), _t(d), _t(c)), hatch_angle_deg=angle, hatch_spacing_mm=1.3,
                           name=f"{self.name}-hatch")
            object.__setattr__(self, "_hatch", found)
        return found

    def primitives(self):
        p, q, u, n = self._frame()
        a, b = p + n * self.offset_mm, q + n * self.offset_mm
        prims = []
        if self.axis:
            prims.append(Path((_t(p), _t(q)), CHAIN))
        prims.extend(self._hatch_region().primitives())
        prims.append(Path((_t(a), _t(b)), GROUND))
        return tuple(prims)


@dataclass(frozen=True)
class SliderBlock(Element):
    """A slider block: a rectangle centred on its pin, its long side along ``angle_deg``.

    >>> SliderBlock((0.0, 0.0), length_mm=10.0, height_mm=6.0).corners()
    ((-5.0, 3.0), (5.0, 3.0), (5.0, -3.0), (-5.0, -3.0))
    """

    at: XY
    angle_deg: float = 0.0
    length_mm: float = 10.0
    height_mm: float = 6.0
    pin: bool = True
    style: Style = BLOCK
    name: str = "slider"

    def corners(self) -> tuple[XY, ...]:
        """The rectangle's corners, mm (the side below the line of motion first)."""
        c = np.asarray(_xy(self.at))
        u = _unit(self.angle_deg)
        n = np.array([u[1], -u[0]])                 # left of u on paper
        hl, hh = self.length_mm / 2, self.height_mm / 2
        pts = (c - u * hl - n * hh, c + u * hl - n * hh, c + u * hl + n * hh, c - u * hl + n * hh)
        return tuple((round(float(x), 12) + 0.0, round(float(y), 12) + 0.0) for x, y in pts)

    def primitives(self):
        prims = [Polygon(self.corners(), self.style)]
        if self.pin:
            x, y = _xy(self.at)
            prims.append(Circle(x, y, 0.9, JOINT))
        return tuple(prims)


@dataclass(frozen=True)
class RotationArrow(Element):
    """The sense of rotation of a link: an arc about ``centre`` with an arrowhead, and its label.

    Parameters
    ----------
    centre : (float, float), mm
        Centre of the arc (the link's pivot).
    radius_mm : float, mm
    start_deg, sweep_deg : float
        Where the arc starts and how far it turns (positive: counterclockwise on paper); the
        arrowhead is at the end.
    label : str
        Markup written beyond the middle of the arc (``"ω_1"``).
    """

    centre: XY
    radius_mm: float = 8.0
    start_deg: float = 150.0
    sweep_deg: float = 60.0
    label: str = ""
    size_mm: float = 3.2
    name: str = "rotation"

    def __post_init__(self) -> None:
        object.__setattr__(self, "size_mm", lettered_size(self.size_mm))

    def arc_points(self) -> tuple[XY, ...]:
        c = np.asarray(_xy(self.centre))
        n = max(8, int(abs(self.sweep_deg) / 4))
        a = np.radians(self.start_deg + np.linspace(0.0, self.sweep_deg, n + 1))
        return tuple((float(c[0] + self.radius_mm * math.cos(t)), float(c[1] - self.radius_mm * math.sin(t)))
                     for t in a)

    def primitives(self):
        pts = self.arc_points()
        hl = min(2.5, 0.4 * self.radius_mm * math.radians(abs(self.sweep_deg)))
        end = math.radians(self.start_deg + self.sweep_deg)
        s = 1.0 if self.sweep_deg >= 0 else -1.0
        tangent = np.array([-math.sin(end), -math.cos(end)]) * s    # d/dθ of (cos, −sin), on paper
        # stop the shaft where the head starts
        back = math.degrees(hl / self.radius_mm) * s
        shaft = RotationArrow(self.centre, self.radius_mm, self.start_deg, self.sweep_deg - back).arc_points()
        prims = [Path(shaft, Style(width_mm=0.3)), arrowhead(pts[-1], tangent, length_mm=hl, width_mm=0.8)]
        if self.label:
            mid = math.radians(self.start_deg + self.sweep_deg / 2)
            r = self.radius_mm + 1.0 + 0.5 * self.size_mm
            c = _xy(self.centre)
            at = (c[0] + r * math.cos(mid), c[1] - r * math.sin(mid))
            prims.append(make_label(at, self.label, size_mm=self.size_mm, anchor="middle", valign="middle"))
        return tuple(prims)


__all__ = ["PinJoint", "FixedPivot", "Guide", "SliderBlock", "RotationArrow", "arrowhead", "JOINT", "GROUND",
           "CHAIN", "BLOCK", "THIN"]
