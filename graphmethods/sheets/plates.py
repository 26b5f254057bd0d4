"""Links as the scheme draws them: a binary link as a line, a ternary (or higher) link as a plate.

A link that carries three or more joints is one rigid body. ГОСТ 2.770 and the textbooks draw it as a
plate: the polygon through its joints, its outline as thick as the links and its inside hatched, so
that it cannot be read as a chain of binary links. When the joints of a link lie on one line (a rocker
O₂B extended to C) the link is the one line from end to end, so that every joint stands on it.

:func:`link_bodies` lists each link's joints from a mechanism (the joints only: centres of mass are
points marked on a link, not joints of it); :func:`body_outline` orders a body's corners on paper;
:class:`Plate` draws one. The kinematic scheme and the force sheet both draw their links through here.

>>> from graphmethods.problems import builtin
>>> link_bodies(builtin.case("six-bar-press").mechanism)["3"]
('B', 'O2', 'C')
>>> is_plate(((0.0, 0.0), (10.0, 0.0), (20.0, 0.0))), is_plate(((0.0, 0.0), (10.0, 0.0), (5.0, 6.0)))
(False, True)
>>> [type(p).__name__ for p in Plate(((0, 0), (20, 0), (10, 12))).primitives()][-1]
'Path'
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.scene import Element, Region
from graphmethods.scene.primitives import Primitive, Style

XY = tuple[float, float]

#: a plate's outline: as thick as the links of the thick position
PLATE_OUTLINE = Style(width_mm=0.6)
#: its hatching
PLATE_HATCH = Style(width_mm=0.18)
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


def is_plate(corners: Sequence[XY] | np.ndarray) -> bool:
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


def body_outline(corners: Sequence[XY]) -> tuple[XY, ...]:
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
    """A ternary (or higher) link: the polygon through its joints, outlined and hatched (paper mm).

    Parameters
    ----------
    corners : sequence of (float, float), mm
        The joints, in turn around the plate (:func:`body_outline`).
    outline_style : Style
        The outline (thick for the drawn position, thin for the others).
    hatch : bool
        Hatch the inside (the thick position); the thin positions are outlines only.
    hatch_spacing_mm : float, mm
        Distance between hatching lines.

    >>> p = Plate(((0, 0), (30, 0), (15, 20)), hatch=False)
    >>> len(p.primitives())
    1
    """

    corners: tuple[XY, ...]
    outline_style: Style = PLATE_OUTLINE
    hatch: bool = True
    hatch_spacing_mm: float = 2.0
    name: str = "plate"

    def region(self) -> Region:
        """The plate as a hatched region with its outline."""
        return Region(self.corners, hatch_angle_deg=45.0 if self.hatch else None,
                      hatch_spacing_mm=self.hatch_spacing_mm, style=PLATE_HATCH, outline_style=self.outline_style,
                      name=self.name)

    def primitives(self) -> tuple[Primitive, ...]:
        return self.region().primitives()


__all__ = ["PLATE_HATCH", "PLATE_OUTLINE", "Plate", "body_outline", "is_plate", "link_bodies"]
