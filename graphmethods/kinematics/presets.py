"""The textbook linkages as :class:`~graphmethods.kinematics.linkage.Linkage` objects on the core.

The four kinds of the problem files (slider-crank, four-bar, slotted lever, shaper) with the
same frames, point names and link numbers as the problem files (:mod:`graphmethods.kinematics.classic`
gives them the checks and names of those files), and the course
mechanisms built from the same groups (six-bar press, ...). Extra points are given as
``{"S2": ("AB", 0.13, 0.0)}``: link by its joints (first joint = where the distance starts),
distance in m, angle in rad from the line first joint → second joint.

>>> sc = slider_crank(r=0.1, l=0.4, e=0.02)
>>> sc.structure().formula
'I(0,1) → II(2,3)'
>>> round(sc.strokes().K, 6)
1.017147
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from graphmethods.errors import InputError
from graphmethods.kinematics.groups import GROUND, RPR, RRP, RRR, Guide
from graphmethods.kinematics.linkage import Crank, Linkage, Point

#: extra points by name: (link by its joints, distance from the first joint in m[, angle in rad])
PointSpecs = Mapping[str, Sequence[Any]]


def _points(points: PointSpecs | None, links: Mapping[str, tuple[str, str, str, float]]) -> list[Point]:
    """Extra points ``{"S2": ("AB", d, angle)}`` -> Points; ``links`` maps "AB" -> (number, from, to, offset):
    the link's own direction is from→to turned by ``offset`` (rad)."""
    out: list[Point] = []
    for name, spec in (points or {}).items():
        if not isinstance(spec, (tuple, list)) or len(spec) not in (2, 3):
            raise InputError(f"point {name!r}: give (link, distance_m) or (link, distance_m, angle_rad)")
        key, d = spec[0], spec[1]
        ang = float(spec[2]) if len(spec) == 3 else 0.0
        for _canon, (num, x, y, off) in links.items():
            if key == x + y:
                out.append(Point(name, num, x, d, ang - off))
                break
            if key == y + x:
                out.append(Point(name, num, y, d, ang + math.pi - off))
                break
        else:
            raise InputError(f"point {name!r}: unknown link {key!r}; the moving links are {', '.join(links)}")
    return out


def slider_crank(*, r: float, l: float, e: float = 0.0, assembly: int = 1, sense: int = 1,
                 working_stroke: str = "toward_crank", points: PointSpecs | None = None) -> Linkage:
    """Offset slider-crank O–A–B, slider B on the line y = e (as
    :class:`~graphmethods.kinematics.classic.SliderCrank` builds it)."""
    g = RRP(P="A", C="B", l=l, guide=Guide(GROUND, complex(0.0, e), 0.0), links=("2", "3"), branch=assembly)
    return Linkage(ground={"O": (0.0, 0.0)}, crank=Crank("O", "A", r=r), groups=[g],
                   points=_points(points, {"OA": ("1", "O", "A", 0.0), "AB": ("2", "A", "B", 0.0)}),
                   sense=sense, output="B", working_stroke=working_stroke, name="slider-crank")


def four_bar(*, l1: float, l2: float, l3: float, l4: float, ground_angle: float = 0.0, assembly: int = 1,
             sense: int = 1, working_stroke: str = "slow", points: PointSpecs | None = None) -> Linkage:
    """Four-bar O1–A–B–O2 (as :class:`~graphmethods.kinematics.classic.FourBar` builds it): crank
    1 = O1A, coupler 2 = AB, rocker 3 = O2B."""
    O2 = (l1 * math.cos(ground_angle), l1 * math.sin(ground_angle))
    g = RRR(P="A", Q="O2", C="B", l_PC=l3, l_QC=l4, links=("2", "3"), branch=assembly)
    return Linkage(ground={"O1": (0.0, 0.0), "O2": O2}, crank=Crank("O1", "A", r=l2), groups=[g],
                   points=_points(points, {"O1A": ("1", "O1", "A", 0.0), "AB": ("2", "A", "B", 0.0),
                                           "O2B": ("3", "O2", "B", 0.0)}),
                   sense=sense, output="3", working_stroke=working_stroke, name="four-bar", start=ground_angle)


def _lever(r: float, l_O1O3: float, theta_O3: float) -> tuple[dict[str, tuple[float, float]], Crank, RPR]:
    """The fixed joints, the crank and the RPR group of a slotted lever (the slotted lever and the shaper)."""
    O3 = (l_O1O3 * math.cos(theta_O3), l_O1O3 * math.sin(theta_O3))
    return {"O1": (0.0, 0.0), "O3": O3}, Crank("O1", "A", r=r), RPR(P="A", Q="O3", coincident="A3", links=("2", "3"))


def slotted_lever(*, r: float, l_O1O3: float, l_O3B: float, theta_O3: float = -math.pi / 2, sense: int = 1,
                  working_stroke: str = "slow", points: PointSpecs | None = None) -> Linkage:
    """Crank and slotted lever O1–A, block 2, lever 3 = O3B (as
    :class:`~graphmethods.kinematics.classic.SlottedLever` builds it); r may
    exceed O1O3 (a rotating slotted lever: no extreme positions)."""
    ground, crank, g = _lever(r, l_O1O3, theta_O3)
    pts = [Point("B", "3", "O3", l_O3B)] + _points(points, {"O1A": ("1", "O1", "A", 0.0),
                                                           "O3B": ("3", "O3", "B", 0.0)})
    return Linkage(ground=ground, crank=crank, groups=[g], points=pts, sense=sense, output="3",
                   working_stroke=working_stroke, name="slotted lever")


def shaper(*, r: float, l_O1O3: float, l_O3B: float, l_BC: float, y_guide: float, theta_O3: float = -math.pi / 2,
           assembly: int = 1, sense: int = 1, working_stroke: str = "slow",
           points: PointSpecs | None = None) -> Linkage:
    """Shaper (as :class:`~graphmethods.kinematics.classic.Shaper` builds it): slotted lever, link
    4 = BC, ram 5 = C on the line y = y_guide.

    The lever's end B is an extra point of link 3; the group BC–ram is an RRP on it.
    """
    ground, crank, g = _lever(r, l_O1O3, theta_O3)
    ram = RRP(P="B", C="C", l=l_BC, guide=Guide(GROUND, complex(0.0, y_guide), 0.0), links=("4", "5"),
              branch=assembly)
    lk = Linkage(ground=ground, crank=crank, groups=[g, ram],
                     points=[Point("B", "3", "O3", l_O3B)]
                     + _points(points, {"O1A": ("1", "O1", "A", 0.0), "O3B": ("3", "O3", "B", 0.0),
                                        "BC": ("4", "B", "C", 0.0)}),
                     sense=sense, output="C", working_stroke=working_stroke, name="shaper")
    return lk


def six_bar_press(*, l_O1A: float = 0.08, l_AB: float = 0.30, l_O2B: float = 0.20,
                  O2: tuple[float, float] = (0.25, 0.10), l_O2C: float = 0.30, C_angle: float = 0.0,
                  l_CD: float = 0.35, guide_through: tuple[float, float] = (0.0, 0.42),
                  guide_angle: float = 0.0, assembly: int = 1, sense: int = 1, working_stroke: str = "slow",
                  points: PointSpecs | None = None) -> Linkage:
    """Six-bar press: crank-rocker four-bar O1–A–B–O2 whose rocker (3, O2–B extended to C, or a bell
    crank with ``C_angle``) drives the ram D (5) through the link CD (4); the ram's guide passes
    through ``guide_through`` at ``guide_angle`` (rad from +x).

    >>> press = six_bar_press()
    >>> press.structure().formula
    'I(0,1) → II(2,3) → II(4,5)'
    >>> round(press.stroke_H(), 4)
    0.2708
    """
    g1 = RRR(P="A", Q="O2", C="B", l_PC=l_AB, l_QC=l_O2B, links=("2", "3"), branch=1)
    g2 = RRP(P="C", C="D", l=l_CD, guide=Guide(GROUND, complex(*guide_through), guide_angle), links=("4", "5"),
             branch=assembly)
    return Linkage(ground={"O1": (0.0, 0.0), "O2": (float(O2[0]), float(O2[1]))}, crank=Crank("O1", "A", r=l_O1A),
                   groups=[g1, g2],
                   points=[Point("C", "3", "O2", l_O2C, C_angle)] + _points(
                       points, {"O1A": ("1", "O1", "A", 0.0), "AB": ("2", "A", "B", 0.0), "O2B": ("3", "O2", "B", 0.0),
                                "CD": ("4", "C", "D", 0.0)}),
                   sense=sense, output="D", working_stroke=working_stroke, name="six-bar press")
