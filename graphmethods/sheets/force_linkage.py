"""The linkage drawn with its forces: the links in one position (bars, ternary links as plates), the frame's
hatched guides along each block's stroke, the blocks, the joints and the fixed pivots; the directions in which
the links leave a point, and a moment's arc drawn clear of them. Shared by the force scheme
(:func:`graphmethods.sheets.forces.force_scheme`) and the groups cut from the linkage on the A1 force sheet
(:func:`graphmethods.sheets.force_sheet_plans.group_panel`).

>>> from graphmethods.problems import builtin
>>> from graphmethods.sheets.forces import analysed
>>> fa, i = analysed(builtin.case("press"), position=3, phi_deg=None, m=12)
>>> segs, blocks = _links_of(fa.motion, i)
>>> segs[0], [p for p, _ in blocks]
(('O', 'A'), ['B'])
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable, Sequence
from typing import Any, TypeVar

import numpy as np

from graphmethods.scene import Element, Line
from graphmethods.scene.primitives import Circle, Style, walk
from graphmethods.sheets.engine.labels import circle_points
from graphmethods.sheets.layout import Occupancy

#: the links of the linkage: a main line (ГОСТ 2.303: 0.5–1.4 mm), heavier than the forces' shafts
LINK = Style(width_mm=0.6)
#: the map from a point of the drawing's plane (m or N, complex) to the page (mm)
ToMm = Callable[[complex], tuple[float, float]]
AnElement = TypeVar("AnElement", bound=Element)


def _drawn(occ: Occupancy, el: AnElement) -> AnElement:
    """``el``, its lines and its circles (a joint, a pivot: as the polygon the figure-quality test measures) kept
    clear by the labels placed later."""
    prims = el.primitives()
    occ.add_primitives(prims)
    for p in walk(prims):
        if isinstance(p, Circle):
            occ.add_line(circle_points(p.cx, p.cy, p.r))
    return el


def _links_of(mo: Any, i: int) -> tuple[list[tuple[str, str]], list[tuple[str, complex]]]:
    """The linkage drawn in position ``i``: its links as segments between two points, and its sliders'
    blocks (the point, the guide's direction)."""
    lk = mo.linkage

    def guide(link: str) -> complex:
        return complex(np.broadcast_to(mo._state.e[link], (mo.n,))[i])

    segs: list[tuple[str, str]] = [(lk.crank.centre, lk.crank.pin)]
    blocks: list[tuple[str, complex]] = []
    for g in lk.groups:
        if g.kind == "RRR":
            segs += [(g.P, g.C), (g.Q, g.C)]
        elif g.kind == "RRP":
            segs.append((g.P, g.C))
            blocks.append((g.C, guide(g.links[1])))
        elif g.kind == "RPR":
            segs.append((g.Q, g.P))
            blocks.append((g.P, guide(g.links[1])))
        elif g.kind == "PRP":
            blocks += [(g.C, guide(ln)) for ln in g.links]
        elif g.kind == "triad":                   # the basic link as a triangle, the three binary links
            B1, B2, B3 = g.inner
            segs += [(B1, B2), (B2, B3), (B1, B3), *zip(g.outer, g.inner)]
        else:
            segs.append((g.P, g.R))
            blocks.append((g.P, guide(g.links[0])))
    segs += [(p.origin, p.name) for p in lk.points]
    return segs, blocks


def _linkage(mo: Any, i: int, z: dict[str, complex], at: ToMm, occ: Occupancy,
             box: tuple[float, float, float, float] = (-1e4, -1e4, 1e4, 1e4)) -> list[Element]:
    """The links, the fixed pivots, the sliders' blocks and the joints, kept clear by the labels; a yoke on the
    frame as its slotted crosshead with its rod and hatched guide (:func:`_yokes`), within ``box`` (mm) where it
    has room."""
    from graphmethods.sheets.kinematic_symbols import FixedPivot, PinJoint, SliderBlock

    lk = mo.linkage
    segs, blocks = _links_of(mo, i)
    yokes, slotted = _yokes(mo, i, z, at, box)
    els: list[Element] = plates(segs, z, at)
    els += [_drawn(occ, Line(at(z[a]), at(z[b]), style=LINK, name=f"link-{a}-{b}")) for a, b in segs
            if abs(z[a] - z[b]) > 0 and (a, b) not in slotted]
    els += _guides(mo, blocks, at) + yokes
    els += [FixedPivot(at(z[p]), name=f"pivot-{p}") for p in lk.ground]
    els += [SliderBlock(at(z[p]), angle_deg=math.degrees(math.atan2(u.imag, u.real)), name=f"block-{j}")
            for j, (p, u) in enumerate(blocks)]
    joints = {q for s in segs for q in s} - set(lk.ground) - {b for _, b in slotted}
    els += [PinJoint(at(z[p]), name=f"joint-{p}") for p in sorted(joints)]
    return [_drawn(occ, el) for el in els]


def _yokes(mo: Any, i: int, z: dict[str, complex], at: ToMm, box: tuple[float, float, float, float]
           ) -> tuple[list[Element], set[tuple[str, str]]]:
    """Each yoke that translates on the frame (an RPP group's slotted link, a Scotch yoke) drawn as the books draw
    it (:func:`graphmethods.sheets.yoke.yoke`): its slot as long as the block's travel in it over the cycle
    (to μ_l) and the block's length more, centred on that travel, its rod along the frame's guide; and the
    segments (block's pin, the yoke's point) it draws in place of a bare line. Only the yokes whose points are
    among ``z`` (the points drawn, m)."""
    from graphmethods.sheets.yoke import yoke

    out: list[Element] = []
    slotted: set[tuple[str, str]] = set()
    for g, centre, d in _slots(mo, i):
        if g.P not in z or g.R not in z:                                # not in this drawing (a group cut out)
            continue
        c = np.asarray(at(centre))
        half = math.dist(at(centre), at(centre + d)) + 6.0              # the block (10 mm long) inside
        u = complex(np.broadcast_to(mo._state.e[g.links[1]], (mo.n,))[i])
        others = [np.asarray(at(q)) - c for p, q in z.items() if p not in (g.P, g.R)]
        els, _ = yoke(c, float(np.angle(d)) if abs(d) else float(g.guide.angle + g.slot_angle),
                      np.array([u.real, -u.imag]) / max(abs(u), 1e-12), others, box, name=g.links[1],
                      slot_mm=(half, 3.0))
        out += els
        slotted.add((g.P, g.R))
    return out, slotted


def plates(segs: Sequence[tuple[str, str]], z: dict[str, complex], at: ToMm) -> list[Element]:
    """The links with three joints among ``segs`` (a triad's basic link) drawn as hatched plates
    (:mod:`graphmethods.sheets.plates`)."""
    from graphmethods.sheets.plates import plate, triangles

    return [el for tri in triangles([(a, b) for a, b in segs if a in z and b in z])
            for el in plate([at(z[p]) for p in tri], name="plate-" + "".join(tri))]


def _strokes(mo: Any, blocks: Sequence[tuple[str, complex]]) -> list[tuple[int, complex, complex]]:
    """The blocks that slide on the frame (along one fixed line in every position): each one's index and the
    two ends of its stroke (m, complex)."""
    out = []
    for j, (p, u) in enumerate(blocks):
        zs = np.asarray(mo.z[p], dtype=complex).reshape(-1)
        if abs(u) == 0 or np.ptp(((zs - zs[0]) * u.conjugate()).imag) > 1e-9 * (1.0 + float(np.ptp(np.abs(zs)))):
            continue                                # a guide on a moving link, or not along a fixed line
        e = u / abs(u)
        s = ((zs - zs[0]) * e.conjugate()).real
        out.append((j, complex(zs[0] + s.min() * e), complex(zs[0] + s.max() * e)))
    return out


def _guide_ends(mo: Any, blocks: Sequence[tuple[str, complex]], i: int | None = None) -> list[complex]:
    """The ends of the frame's guides (m), and in position ``i`` (when given) of the yokes' slots: the scheme is
    scaled to hold them."""
    ends = [z for _, a, b in _strokes(mo, blocks) for z in (a, b)]
    return ends if i is None else ends + [z for _, c, d in _slots(mo, i) for z in (c - d, c + d)]


def _slots(mo: Any, i: int) -> list[tuple[Any, complex, complex]]:
    """Each yoke that translates on the frame (an RPP group's slotted link, a Scotch yoke) in position ``i``: its
    group, the middle of its block's travel in the slot over the cycle (m, complex) and the half travel along the
    slot (m, complex)."""
    out = []
    for g in mo.linkage.groups:
        if g.kind != "RPP" or getattr(g.guide, "link", None) != "0":
            continue
        s = cmath.exp(1j * float(g.guide.angle + g.slot_angle))          # along the slot
        travel = ((np.asarray(mo.z[g.P], dtype=complex) - np.asarray(mo.z[g.R], dtype=complex)) * s.conjugate()).real
        lo, hi = float(travel.min()), float(travel.max())
        out.append((g, complex(mo.z[g.R][i]) + s * (lo + hi) / 2, s * (hi - lo) / 2))
    return out


def _guides(mo: Any, blocks: Sequence[tuple[str, complex]], at: ToMm) -> list[Element]:
    """The hatched guide of each block that slides on the frame (its guide's direction the same in every
    position), along the block's whole stroke and a block's length beyond either end."""
    from graphmethods.sheets.kinematic_symbols import Guide

    out: list[Element] = []
    for j, za, zb in _strokes(mo, blocks):
        a, b = at(za), at(zb)
        d = math.dist(a, b)
        if d == 0:
            continue
        e = ((b[0] - a[0]) / d, (b[1] - a[1]) / d)
        reach = 8.0                                 # mm beyond the stroke: the block's half length and more
        out.append(Guide((a[0] - reach * e[0], a[1] - reach * e[1]), (b[0] + reach * e[0], b[1] + reach * e[1]),
                         side=-1 if e[0] >= 0 else 1, name=f"guide-{j}"))
    return out


def _directions(w: complex, z: dict[str, complex], segs: Sequence[tuple[str, str]]) -> list[float]:
    """The directions (degrees, counterclockwise from +x) in which the links leave the point ``w`` (m): toward
    both ends of a link through it, toward the other end of a link ending at it.

    >>> _directions(0j, {"A": -1 + 0j, "B": 1 + 0j, "C": 1j}, [("A", "B"), ("C", "A")])
    [180.0, 0.0]
    """
    out: list[float] = []
    for a, b in segs:
        za, zb = z[a], z[b]
        d = zb - za
        if abs(d) == 0:
            continue
        t = ((w - za) * d.conjugate()).real / abs(d) ** 2
        if -1e-9 <= t <= 1 + 1e-9 and abs(w - (za + t * d)) <= 1e-9 * abs(d):     # w on the link
            out += [math.degrees(cmath.phase(e - w)) for e in (za, zb) if abs(e - w) > 1e-9 * abs(d)]
    return out


def clear_direction(avoid: Sequence[float]) -> float:
    """The direction (degrees, a multiple of 15°, straight up first) farthest from every direction of ``avoid``:
    where an arc about a joint keeps off its links and forces.

    >>> clear_direction([0.0, 180.0]), clear_direction([90.0]), clear_direction([])
    (90.0, 270.0, 90.0)
    """
    best, best_gap = 90.0, -1.0
    for mid in range(90, 450, 15):
        gap = min((abs((mid - a + 180.0) % 360.0 - 180.0) for a in avoid), default=180.0)
        if gap > best_gap + 1e-9:
            best, best_gap = float(mid % 360), gap
    return best


def _moment_arc(centre: tuple[float, float], radius_mm: float, sweep_deg: float, avoid: Sequence[float],
                **kw: Any) -> Element:
    """A moment's arc of ``sweep_deg`` (signed: its sense) about ``centre``, its middle away from ``avoid``."""
    from graphmethods.sheets.kinematic_symbols import RotationArrow

    return RotationArrow(centre, radius_mm=radius_mm, start_deg=clear_direction(avoid) - sweep_deg / 2,
                         sweep_deg=sweep_deg, **kw)
