"""Links with three or more joints drawn as plates (ГОСТ 2.770: a ternary link is a rigid triangle, its
outline a main line, its interior hatched), shared by the figures that draw a linkage in a position.

:func:`triangles` finds the plates of a linkage drawn as segments between points (three points joined
pairwise: a triad's basic link); :func:`plate` draws one.

>>> triangles([("B", "C"), ("C", "D"), ("B", "D"), ("A", "B")])
[('B', 'C', 'D')]
>>> [e.name for e in plate([(0.0, 0.0), (30.0, 0.0), (10.0, 20.0)], name="plate-BCD")]
['plate-BCD-hatch', 'plate-BCD']
>>> plate([(0.0, 0.0), (10.0, 0.0), (20.0, 0.0)], name="p")       # joints in a line: a bar, not a plate
[]

The kinematic scheme draws a linkage in many positions from its mechanism: :func:`link_bodies` lists each
link's joints (the joints only: centres of mass are points marked on a link, not joints of it),
:func:`body_outline` orders a body's corners on paper (joints in line: the one line from end to end, so a
rocker O₂B extended to C stands on C), and :class:`Plate` is the element of one position (hatched in the
thick position through :func:`plate`, outlined only in the thin ones).

>>> from graphmethods.problems import builtin
>>> link_bodies(builtin.case("six-bar-press").mechanism)["3"]
('B', 'O2', 'C')
>>> is_plate(((0.0, 0.0), (10.0, 0.0), (20.0, 0.0))), is_plate(((0.0, 0.0), (10.0, 0.0), (5.0, 6.0)))
(False, True)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.scene import Element, Polyline
from graphmethods.scene.elements import Region
from graphmethods.scene.primitives import Primitive, Style

#: the plate's outline: a main line, as the links (ГОСТ 2.303)
OUTLINE = Style(width_mm=0.6)
#: the smallest area (mm²) a plate's outline must enclose: three joints nearly in a line draw as a bar
MIN_AREA_MM2 = 4.0


def triangles(segments: Sequence[tuple[str, str]]) -> list[tuple[str, str, str]]:
    """The triples of points joined pairwise by ``segments`` (each sorted, the list sorted): the plates."""
    pairs = {frozenset(s) for s in segments if s[0] != s[1]}
    names = sorted({p for s in segments for p in s})
    out = []
    for a_i, a in enumerate(names):
        for b_i in range(a_i + 1, len(names)):
            b = names[b_i]
            if frozenset((a, b)) not in pairs:
                continue
            out += [(a, b, c) for c in names[b_i + 1:] if frozenset((a, c)) in pairs and frozenset((b, c)) in pairs]
    return out


def plate(points: Sequence[tuple[float, float]], *, name: str, spacing_mm: float = 3.0,
          fill: str | None = None) -> list[Element]:
    """A plate through ``points`` (mm, in order round it): its interior hatched at 45° (thin lines
    ``spacing_mm`` apart, over ``fill`` when given: "white" hides what lies under the plate) and its outline
    a main line; none when the points enclose no area.

    Parameters
    ----------
    points : sequence of (x, y), mm
        The joints of the link, in order round it.
    name : str
        The outline's element name; the hatching is ``name + "-hatch"``.
    """
    pts = [(float(x), float(y)) for x, y in points]
    area = 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1])))
    if len(pts) < 3 or area < MIN_AREA_MM2:
        return []
    return [Region(tuple(pts), hatch_angle_deg=45.0, hatch_spacing_mm=spacing_mm, fill=fill, name=f"{name}-hatch"),
            Polyline(tuple(pts), style=OUTLINE, closed=True, name=name)]


#: corners closer to a line than this share of the body's longest side: the joints are in line
IN_LINE = 0.02


def link_bodies(mech: Any) -> dict[str, tuple[str, ...]]:
    """Each moving link's joints (textbook number -> joint names, in the mechanism's joint order).

    A link listed by two joints in ``mech.link_joints`` gains the joints on it that other links hang on
    (a lever's end C, a triad's third inner joint). Mechanisms without a :class:`~graphmethods.
    kinematics.linkage.Linkage` (the classic ones) have binary links only.

    Parameters
    ----------
    mech : Mechanism
        The mechanism (``case.mechanism()``).

    Returns
    -------
    dict
        Link number (str) -> its joints; the crank and every link with two joints or more.
    """
    lk = getattr(mech, "linkage", None)
    canon = getattr(mech, "_canon", None)
    if lk is None or canon is None:
        return {str(k): tuple(v) for k, v in enumerate(mech.link_joints.values(), start=1)}
    joints = set(mech.joints)
    out: dict[str, list[str]] = {}
    for number, name in canon.items():
        if name in mech.link_joints:
            out[number] = list(mech.link_joints[name])
    for g in lk.groups:
        if getattr(g, "cls", 2) == 3 and g.links[0] in out:       # a triad's basic link: its three inner joints
            out[g.links[0]] += [j for j in g.inner if j not in out[g.links[0]]]
    for p in lk.points:
        if p.name in joints and p.link in out and p.name not in out[p.link]:
            out[p.link].append(p.name)
    order = {j: k for k, j in enumerate(mech.joints)}
    return {k: tuple(sorted(v, key=lambda j: order.get(j, len(order)))) for k, v in out.items()}


def is_plate(corners: Sequence[tuple[float, float]] | np.ndarray) -> bool:
    """Whether a body's joints (at least three, any unit) span an area: not all on one line."""
    pts = np.asarray(corners, dtype=float).reshape(-1, 2)
    if len(pts) < 3:
        return False
    d = pts[:, None, :] - pts[None, :, :]
    span = float(np.hypot(d[..., 0], d[..., 1]).max())
    if span == 0.0:
        return False
    a, b = np.unravel_index(int(np.argmax(np.hypot(d[..., 0], d[..., 1]))), d.shape[:2])
    u = (pts[b] - pts[a]) / span
    off = np.abs((pts - pts[a]) @ np.array([-u[1], u[0]]))
    return bool(off.max() > IN_LINE * span)


def body_outline(corners: Sequence[tuple[float, float]]) -> tuple[tuple[float, float], ...]:
    """The body as it is drawn: for a plate its corners in turn around their centre (a convex polygon
    through every joint), for joints in line the two ends of the line.

    >>> body_outline(((0, 0), (10, 0), (5, 0)))
    ((0.0, 0.0), (10.0, 0.0))
    >>> body_outline(((0, 0), (10, 10), (10, 0)))
    ((0.0, 0.0), (10.0, 0.0), (10.0, 10.0))
    """
    pts = np.asarray(corners, dtype=float).reshape(-1, 2)
    if not is_plate(pts):
        if len(pts) < 2:
            return tuple((float(x), float(y)) for x, y in pts)
        d = np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))
        a, b = np.unravel_index(int(np.argmax(d)), d.shape)
        lo, hi = sorted((int(a), int(b)))
        return ((float(pts[lo, 0]), float(pts[lo, 1])), (float(pts[hi, 0]), float(pts[hi, 1])))
    c = pts.mean(axis=0)
    ang = [math.atan2(float(q[1] - c[1]), float(q[0] - c[0])) for q in pts]
    order = sorted(range(len(pts)), key=lambda k: (round(ang[k], 9), k))
    return tuple((float(pts[k, 0]), float(pts[k, 1])) for k in order)


@dataclass(frozen=True)
class Plate(Element):
    """A ternary (or higher) link in one position of a scheme: :func:`plate` (hatched) or its outline alone.

    Parameters
    ----------
    corners : sequence of (float, float), mm
        The joints, in turn around the plate (:func:`body_outline`).
    outline_style : Style
        The outline (a main line for the drawn position, thin or dashed for the others).
    hatch : bool
        Hatch the inside (the thick position); the thin positions are outlines only.
    hatch_spacing_mm : float, mm
        Distance between hatching lines.
    fill : str, optional
        Under the hatching ("white" in a scheme's thick position: the plate is one clean body over the thin
        positions drawn under it).

    >>> [type(p).__name__ for p in Plate(((0, 0), (30, 0), (15, 20)), hatch=False).primitives()]
    ['Path']
    """

    corners: tuple[tuple[float, float], ...]
    outline_style: Style = OUTLINE
    hatch: bool = True
    hatch_spacing_mm: float = 2.0
    fill: str | None = None
    name: str = "plate"

    def parts(self) -> list[Element]:
        """What draws it: the hatching and the outline (:func:`plate`), or the outline alone."""
        if self.hatch:
            drawn = plate(self.corners, name=self.name, spacing_mm=self.hatch_spacing_mm, fill=self.fill)
            if drawn:
                return [*drawn[:-1], Polyline(self.corners, style=self.outline_style, closed=True, name=self.name)]
        return [Polyline(self.corners, style=self.outline_style, closed=True, name=self.name)]

    def primitives(self) -> tuple[Primitive, ...]:
        return tuple(p for e in self.parts() for p in e.primitives())


__all__ = ["OUTLINE", "Plate", "body_outline", "is_plate", "link_bodies", "plate", "triangles"]
