"""The Scotch yoke (кулиса синусного механизма; 正弦机构的导杆) drawn as the textbooks draw it: a slotted crosshead
whose slot the crank's block slides in, its rod along the frame's guide, and the yoke's own block on that guide,
hatched. One drawing for the structure diagram (:func:`graphmethods.sheets.structure_diagram._yoke`, at fixed
sizes) and the force scheme (:func:`graphmethods.sheets.force_linkage._linkage`, the slot as long as the
block's travel in it, to μ_l).

>>> import numpy as np
>>> els, mid = yoke(np.array([50.0, 50.0]), 0.5 * np.pi, np.array([1.0, 0.0]), [], (0.0, 0.0, 200.0, 100.0),
...                 name="3")
>>> [e.name for e in els], mid
(['yoke-3-slot', 'yoke-3-rod', 'guide-3', 'yoke-3-block'], (59.1, 50.0))
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from graphmethods.scene import Element
from graphmethods.scene.elements import Line, Polyline
from graphmethods.scene.primitives import MAIN
from graphmethods.sheets.kinematic_symbols import Guide, SliderBlock

#: a yoke as drawn in the structure diagram (mm): the slot's half length and half width, the rod's length
YOKE_SLOT_MM = (12.0, 2.6)
YOKE_ROD_MM = 26.0


def _room(c: np.ndarray, d: np.ndarray, box: tuple[float, float, float, float]) -> float:
    """How far (mm) from ``c`` along the unit ``d`` the box reaches."""
    ts = [(lim - c[i]) / d[i] for i, lims in ((0, (box[0], box[2])), (1, (box[1], box[3]))) for lim in lims
          if abs(d[i]) > 1e-9]
    return min([t for t in ts if t > 0] or [0.0])


def yoke(c: np.ndarray, slot_angle: float, ud: np.ndarray, others: Sequence[np.ndarray],
         box: tuple[float, float, float, float], *, name: str, slot_mm: tuple[float, float] = YOKE_SLOT_MM,
         rod_mm: float = YOKE_ROD_MM) -> tuple[list[Element], tuple[float, float]]:
    """A yoke (a slotted crosshead, link ``name``): its slot centred at ``c`` (mm) at ``slot_angle`` (rad, from +x)
    as two parallel bars closed at the ends (``slot_mm``: half length, half width), a rod from the slot along the
    guide (the unit ``ud`` on paper, turned away from ``others``, the other joints less ``c``, mm) at most
    ``rod_mm`` long, and the yoke's block on the frame's hatched guide at the rod's far part, all within ``box``
    where it has room. Returns the elements and the middle of the rod's first quarter (mm)."""
    sd = np.array([math.cos(slot_angle), -math.sin(slot_angle)])       # on paper (y down)
    nd = np.array([-sd[1], sd[0]])
    half, w = slot_mm
    if others and sum(float(o @ ud) for o in others) > 0:                 # the rod away from the crank ...
        ud = -ud
    if _room(c, ud, box) < _room(c, -ud, box) and _room(c, ud, box) < rod_mm + 12.0:   # ... or where there
        ud = -ud                                                                    # is more room
    rod = max(12.0, min(rod_mm, (_room(c, ud, box) - w - 9.5) / 0.62))
    off = nd if float(nd @ ud) >= 0 else -nd                             # the slot's side the rod leaves from
    corners = [c - sd * half - nd * w, c + sd * half - nd * w, c + sd * half + nd * w, c - sd * half + nd * w]
    slot = Polyline(tuple((float(q[0]), float(q[1])) for q in corners), MAIN, closed=True, name=f"yoke-{name}-slot")
    start = c + off * w
    end = start + ud * rod
    bar = Line(tuple(start.tolist()), tuple(end.tolist()), MAIN, name=f"yoke-{name}-rod")
    bc = start + ud * (rod * 0.62)
    ang = math.degrees(math.atan2(-ud[1], ud[0]))
    guide = Guide(tuple((bc - ud * 9.0).tolist()), tuple((bc + ud * 9.0).tolist()), name=f"guide-{name}")
    block = SliderBlock(tuple(bc.tolist()), angle_deg=ang, length_mm=7.0, height_mm=4.0, pin=False,
                        name=f"yoke-{name}-block")
    mid = start + ud * (rod * 0.25)
    return [slot, bar, guide, block], (float(mid[0]), float(mid[1]))


__all__ = ["YOKE_ROD_MM", "YOKE_SLOT_MM", "yoke"]
