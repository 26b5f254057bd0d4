"""The kinematics figures: the scheme in m positions, velocity plans, the table of velocities.

Each function takes a linkage problem and returns a :class:`~graphmethods.scene.Scene` on an
A4 landscape sheet with a frame and a title block (any :class:`~graphmethods.scene.Page` may
be given instead):

- :func:`kinematic_scheme`: the linkage in its m positions on one drawing to μ_l, with the
  textbook symbols (hatched ground under fixed pivots, pin joints, slider blocks on hatched
  guides), one position drawn thick and the others thin, the position numbers 0…m at the
  crank pin and at the output point, the extreme positions marked, the stroke dimensioned.
- :func:`velocity_plan_grid`: the velocity plans of all positions on one sheet, one small
  plan per position to one common μ_v, ill-conditioned positions marked.
- :func:`velocity_plan`: one large plan with its construction lines (⟂ AB through a,
  ∥ guide through p, …), the vectors with arrowheads, a table of their drawn lengths and
  values, and the vector equations.
- :func:`velocity_table` (drawn) and :func:`velocity_table_markdown`: the velocities per
  position.

The linkage may be a problem file read by :func:`graphmethods.kinematics.read_case` (its
velocities are then at the file's mean crank speed), a lazy
:class:`~graphmethods.dynamics.study.Study` (its cached positions and plans are used), a
mechanism (velocities at ``omega_1``, default 1 rad/s: the velocity analogues), its
:class:`~graphmethods.kinematics.Positions` or its
:class:`~graphmethods.kinematics.VelocityPlans`. A figure computes only what it draws: the
scheme never builds a velocity plan. Scales not given are picked (convenient values that
fill the sheet) and every scale drawn is captioned. ``notation="en" | "ru" | "zh"``
switches every word.

>>> from graphmethods.kinematics import SliderCrank
>>> from graphmethods.render.recording import record
>>> mech = SliderCrank(r=0.1, l=0.4, e=0.02, points={"S2": ("AB", 0.13)})
>>> s = velocity_plan(mech, position=2, omega_1=10.0, mu_v=0.02)
>>> round(record(s).vector_length_mm("vector-pa") * 0.02, 9)     # |v_A| = ω₁ r = 1 m/s
1.0
>>> [sc.caption("ru") for sc in kinematic_scheme(mech, notation="ru").scales()]
['μ_l = 0,0025 м/мм']
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property
from typing import Any, cast

import numpy as np

from graphmethods.errors import AssemblyError, InputError
from graphmethods.problems.reference_cases import title_of
from graphmethods.scene import (
    Frame,
    Line,
    Point,
    Polyline,
    Scale,
    Scene,
    Table,
    Text,
    Vector,
    markup,
    notation as get_notation,
)
from graphmethods.scene.elements import Dimension, Element
from graphmethods.scene.primitives import THIN, Label, Style
from graphmethods.sheets.kinematic_symbols import FixedPivot, Guide, PinJoint, RotationArrow, SliderBlock
from graphmethods.sheets.layout import TEXT_MM, Occupancy, Sheet
from graphmethods.sheets.styles import CELL
from graphmethods.units import convenient_at_least

SMALL_MM = 2.8          # position numbers, plan labels
TABLE_MM = 3.2          # tables
THICK = Style(width_mm=0.6)
TRAJECTORY = Style(width_mm=0.18, dash=(0.8, 0.8))
EXTREME = Style(width_mm=0.25, dash=(3.0, 1.0))
CELL_ILL = Style(width_mm=0.5, dash=(2.0, 1.0))
PRIME = "′"


_SUB = re.compile(r"([A-Za-z])(\d+)")


def _sub(name: str) -> str:
    """Markup with the digits of a point or link name lowered: ``"S2"`` -> ``"S_{2}"``, ``"O3A"`` -> ``"O_{3}A"``."""
    return _SUB.sub(lambda mt: f"{mt.group(1)}_{{{mt.group(2)}}}", name)


def _num(nt, value: float, decimals: int) -> str:
    """A value with a fixed number of decimals, the profile's separator and a typographic minus."""
    v = round(float(value), decimals)
    text = f"{abs(v):.{decimals}f}".replace(".", nt.decimal)
    return ("−" + text) if v < 0 else text


# ----------------------------------------------------------------------------- the linkage asked for

class _Linkage:
    """A linkage to draw, from whatever the user gave; positions and plans built when first asked for."""

    def __init__(self, mech, *, m, omega_1, problem="", n_rpm=None, positions=None, plans=None):
        self.mech = mech
        self.m = m
        self.omega_1 = omega_1
        self.problem = problem
        self.n_rpm = n_rpm
        self._positions = positions
        self._plans = plans

    @classmethod
    def of(cls, obj, *, m=None, omega_1=None) -> _Linkage:
        from graphmethods.dynamics.study import Study
        from graphmethods.kinematics import Case, Mechanism, Positions, VelocityPlans

        if omega_1 is not None and (isinstance(omega_1, bool) or not isinstance(omega_1, (int, float))
                                    or not math.isfinite(omega_1) or omega_1 <= 0):
            raise InputError(f"omega_1 is the crank speed in rad/s and must be > 0, got {omega_1!r}")
        if isinstance(obj, Study):
            case = obj.case
            same = (m is None or m == obj.m) and (omega_1 is None or omega_1 == case.omega_m)
            return cls(case.mechanism, m=obj.m if m is None else m,
                       omega_1=case.omega_m if omega_1 is None else float(omega_1), problem=title_of(case),
                       n_rpm=case.n_rpm if omega_1 is None else None,
                       positions=(lambda: obj.positions) if same else None, plans=(lambda: obj.plans) if same else None)
        if isinstance(obj, Case):
            return cls(obj.mechanism, m=m, omega_1=obj.omega_m if omega_1 is None else float(omega_1),
                       problem=title_of(obj), n_rpm=obj.n_rpm if omega_1 is None else None)
        if isinstance(obj, VelocityPlans):
            if omega_1 is not None and omega_1 != obj.omega_1:
                raise InputError(f"these velocity plans are for ω₁ = {obj.omega_1:g} rad/s, not {omega_1:g}; "
                                 f"give the mechanism or its positions to draw them at another speed")
            plan_pos = obj.positions
            if m is not None and m != plan_pos.m:
                raise InputError(f"these velocity plans are for m = {plan_pos.m} positions, not {m}")
            return cls(plan_pos.mechanism, m=plan_pos.m, omega_1=obj.omega_1,
                       positions=lambda: plan_pos, plans=lambda: obj)
        if isinstance(obj, Positions):
            if m is not None and m != obj.m:
                raise InputError(f"these positions are for m = {obj.m}, not {m}")
            return cls(obj.mechanism, m=obj.m, omega_1=1.0 if omega_1 is None else float(omega_1),
                       positions=lambda: obj)
        if isinstance(obj, Mechanism):
            return cls(obj, m=m, omega_1=1.0 if omega_1 is None else float(omega_1))
        raise InputError(f"expected a linkage problem (read_case), a Study, a mechanism, its Positions or its "
                         f"VelocityPlans; got {type(obj).__name__}")

    @cached_property
    def positions(self):
        if self._positions is not None:
            return self._positions()
        return self.mech.positions(m=12 if self.m is None else self.m)

    @cached_property
    def plans(self):
        if self._plans is not None:
            return self._plans()
        return self.mech.velocity_plans(self.positions, omega_1=self.omega_1)

    def speed_text(self, nt) -> str:
        w = nt.number(self.omega_1, sig=4)
        if self.n_rpm is not None:
            return nt.word("kinematics.speed_n", w=w, n=nt.number(self.n_rpm, sig=4))
        return nt.word("kinematics.speed", w=w)


def _drawn(pos) -> list[int]:
    """The positions a figure draws: 0…m−1 (position m is position 0), or every given angle."""
    return list(range(pos.m)) if pos.m is not None else list(range(pos.n))


def _plans_of(linkage, *, m: int | None, omega_1: float | None) -> tuple[_Linkage, Any, Any, list[int]]:
    """What every figure of velocity plans starts from: the linkage, its plans, their positions and
    the positions drawn (:func:`_drawn`)."""
    lk = _Linkage.of(linkage, m=m, omega_1=omega_1)
    plans = lk.plans
    return lk, plans, plans.positions, _drawn(plans.positions)


def _pos_label(pos, k: int) -> str:
    return f"0 ({pos.m})" if pos.m is not None and k == 0 else str(k)


@dataclass(frozen=True)
class _Extreme:
    """The extreme position that ends the working stroke: its label, crank angle, and the numbered
    position it coincides with (None when it falls between two)."""

    label: str
    phi: float
    same_as: int | None


def _end_extreme(pos) -> _Extreme | None:
    st = pos.strokes
    if st is None or pos.m is None:
        return None
    k = st.working_angle / (2.0 * math.pi / pos.m)
    kr = round(k)
    if abs(k - kr) < 1e-9:
        return _Extreme(str(kr % pos.m), st.phi_end, kr % pos.m)
    return _Extreme(f"{math.floor(k)}{PRIME}", st.phi_end, None)


# ----------------------------------------------------------------------------- the sheet

def _dirs(prefer_deg: float) -> tuple[str, ...]:
    """The eight compass directions, nearest to ``prefer_deg`` (paper, counterclockwise from right) first."""
    def gap(d):
        a = abs((_COMPASS[d] - prefer_deg + 180.0) % 360.0 - 180.0)
        return (round(a, 6), d)
    return tuple(sorted(_COMPASS, key=gap))


_COMPASS = {"e": 0.0, "ne": 45.0, "n": 90.0, "nw": 135.0, "w": 180.0, "sw": 225.0, "s": 270.0, "se": 315.0}


def _place(occ: Occupancy, at, text: str, prefer_deg: float, *, size_mm: float, within=None, name: str,
           gaps=(0.8, 2.2, 4.0), avoid_lines: bool = True, dirs=None, hard: Occupancy | None = None,
           leaders: list | None = None) -> Text:
    """A label beside ``at``, in the free direction nearest ``prefer_deg`` (registered as taken).

    Free of lines and labels if possible; else free of labels and of the ``hard`` lines (crossing
    a thin line); else the preferred spot.
    """
    from graphmethods.scene.elements import label_bbox, place_label

    dirs = tuple(dirs) if dirs else _dirs(prefer_deg)
    lab = None
    for gap in gaps:                # near the point across a thin line rather than far from it
        cands = [place_label(at, text, d, gap_mm=gap, size_mm=size_mm) for d in dirs]
        boxes = [label_bbox(c) for c in cands]
        ok = _free_of(occ, hard, boxes, within=within, lines=False)
        if not ok.any():
            continue
        hits = _crossings(occ, boxes) if avoid_lines else np.zeros(len(boxes), dtype=int)
        best = min((i for i in range(len(cands)) if ok[i]), key=lambda i: (hits[i], i))
        if avoid_lines and hits[best] > 0 and gap != gaps[-1]:
            clean = _clean_further(occ, at, text, dirs, gaps, gap, size_mm, within, hard)
            if clean is not None:
                lab = clean
                break
        lab = cands[best]
        break
    if lab is None:                 # crowded: further out, with a leader line to the point when asked for
        for gap in (gaps[-1] + 2.0, gaps[-1] + 4.0, gaps[-1] + 6.5, gaps[-1] + 9.5, gaps[-1] + 13.0):
            cands = [place_label(at, text, d, gap_mm=gap, size_mm=size_mm) for d in dirs]
            ok = _free_of(occ, hard, [label_bbox(c) for c in cands], within=within, lines=False)
            if ok.any():
                lab = cands[int(np.argmax(ok))]
                if leaders is not None:
                    b = label_bbox(lab)
                    near = (min(max(at[0], b[0]), b[2]), min(max(at[1], b[1]), b[3]))
                    dd = np.asarray(near) - np.asarray(at)
                    L = float(np.hypot(*dd))
                    if L > 1.5:
                        start = tuple((np.asarray(at) + dd / L * 0.9).tolist())
                        leaders.append(Line(start, near, style=THIN, name=f"leader-{name}"))
                        occ.add_line((start, near))
                break
    if lab is None:
        lab = place_label(at, text, dirs[0], gap_mm=gaps[0], size_mm=size_mm)
    occ.add_label(lab)
    return Text((lab.x, lab.y), text, size_mm=size_mm, anchor=lab.anchor, name=name)


def _crossings(occ: Occupancy, boxes) -> np.ndarray:
    """How many registered line segments cross each box (:meth:`Occupancy.crossings`, vectorised)."""
    return occ.crossings(boxes)


def _clean_further(occ, at, text, dirs, gaps, gap, size_mm, within, hard):
    """The first spot free of everything at the next larger gap (None when there is none)."""
    from graphmethods.scene.elements import label_bbox, place_label

    nxt = [g for g in gaps if g > gap][:1]
    for g in nxt:
        for d in dirs:              # one at a time: the first is often free, and a label costs its text's width
            cand = place_label(at, text, d, gap_mm=g, size_mm=size_mm)
            b = label_bbox(cand)
            if occ.is_free(b, within=within) and (hard is None or hard.is_free(b)):
                return cand
    return None


def _free_of(occ: Occupancy, hard: Occupancy | None, boxes: list, *, within, lines: bool) -> np.ndarray:
    """Which candidate boxes are free in ``occ`` (of its lines too when ``lines``) and of everything in ``hard``."""
    ok = occ.free(boxes, within=within, lines=lines)
    if hard is not None and ok.any():
        ok &= hard.free(boxes)
    return ok


def _paper_deg(v) -> float:
    """Direction on paper (counterclockwise from right, y up) of a physical vector (x, y)."""
    return math.degrees(math.atan2(float(v[1]), float(v[0])))


# ----------------------------------------------------------------------------- 1. the kinematic scheme

@dataclass(frozen=True)
class _Parts:
    fixed: tuple[str, ...]
    links: tuple[tuple[str, str], ...]
    sliders: dict
    rocker_block: tuple[str, str] | None     # (block point, rocker pivot)
    output: str
    centre: str
    pin: str
    extra: tuple[str, ...]
    paths: tuple[str, ...]
    coincident: tuple[str, ...] = ()         # points of slotted links under a block's pin (A3): not drawn


def _translating_yokes(mech) -> list:
    """The RPP groups of a linkage whose yoke slides on the frame (a sine mechanism, a Scotch yoke)."""
    from graphmethods.kinematics.groups import RPP

    lk = getattr(mech, "linkage", None)
    return [g for g in getattr(lk, "groups", ()) if isinstance(g, RPP) and g.guide.link == "0"]


def _plates(mech) -> tuple[tuple[str, str], ...]:
    """The other two sides of each triad's basic (ternary) link, drawn as a triangle B1 B2 B3."""
    lk = getattr(mech, "linkage", None)
    return tuple(side for g in getattr(lk, "groups", ()) if getattr(g, "cls", 2) == 3
                 for side in ((g.inner[1], g.inner[2]), (g.inner[0], g.inner[2])))


def _parts(mech, pos) -> _Parts:
    fixed = tuple(mech.fixed_joints)
    links = tuple(mech.link_joints.values()) + _plates(mech)
    sliders = dict(mech.guides)
    pin = mech.crank_pin
    centre = next(x for x, y in links if y == pin)
    slotted = tuple(mech.slotted_links)              # (pin on the block, its point on the slotted link, pivot, ...)
    block = (slotted[0][0], slotted[0][2]) if slotted else None
    coincident = {sl[1] for sl in slotted}
    if sliders:
        output = next(iter(sliders))
    else:
        output = next(y for x, y in links if x in fixed and x != centre)
    extra = tuple(p.name for p in mech.points)
    moving = [j for j in mech.joints if j not in fixed and j != pin and j not in coincident and j not in sliders]
    return _Parts(fixed, links, sliders, block, output, centre, pin, extra, tuple(moving) + extra, tuple(coincident))


@dataclass(frozen=True)
class SchemeLayout:
    """The kinematic scheme's millimetre constants (paper mm)."""

    pad_x_mm: float = 10.0              # beside the linkage
    pad_top_mm: float = 10.0            # above it
    pad_bottom_mm: float = 14.0         # below it: the stroke's dimension
    caption_room_mm: float = 9.0        # between the drawing's area and the captions line
    guide_overrun_mm: float = 8.0       # a guide beyond the slider's extreme positions
    guide_offset_mm: float = 3.0        # its hatched surface from its line
    block_length_mm: float = 8.0        # a block on a rocker or a yoke's block
    block_height_mm: float = 4.5
    mark_mm: float = 0.45               # the points marking the crank pin and output in every position
    point_mm: float = 0.7               # the points of the thick position (centres of mass)
    hard_pad_mm: float = 0.4            # what a label must never cover: thick links, blocks
    joint_clear_mm: float = 1.3         # half the side of the square a joint or pivot keeps free
    names_pad_mm: float = 1.4           # names keep clear of the numbers ("B 3" must not read as B₃)
    pad_mm: float = 0.6                 # the occupancy's padding otherwise
    names_gaps_mm: tuple[float, ...] = (2.2, 3.4, 4.8, 6.5, 8.5)
    stroke_offset_mm: float = 4.0       # the dimension H beyond the numbers
    summary_above_mm: float = 6.5       # the line of facts above the captions


SCHEME_LAYOUT = SchemeLayout()


@dataclass(frozen=True)
class _SchemeGeometry:
    """What the scheme draws, in metres: the positions, the parts, the extreme position, the paths."""

    pos: Any
    mech: Any
    parts: _Parts
    drawn: list[int]
    thick: int | None
    ext: _Extreme | None
    ext_pos: Any                        # the extreme position when it falls between two numbered ones
    fine: Any                           # 241 positions for the dotted paths (None: not drawn)
    c_xy: np.ndarray                    # the crank's centre, m
    r: float                            # the crank's length, m


def _scheme_geometry(pos, thick: int | None, trajectories: bool) -> _SchemeGeometry:
    """Step 1: the positions the scheme draws (the extreme one and the fine paths added)."""
    mech = pos.mechanism
    drawn = _drawn(pos)
    if thick is not None and thick not in drawn:
        raise InputError(f"thick = {thick!r}: the scheme draws positions {drawn[0]}…{drawn[-1]}; give one of them "
                         f"(or None for all thin)")
    parts = _parts(mech, pos)
    ext = _end_extreme(pos)
    ext_pos = mech.positions(phi=[ext.phi]) if ext is not None and ext.same_as is None else None
    fine = None
    if trajectories and parts.paths:
        if pos.m is not None:               # a full turn
            fine_phi = pos.phi[0] + mech.sense * np.linspace(0.0, 2.0 * math.pi, 241)
        else:                               # between the angles given (where the linkage may not turn fully)
            fine_phi = np.linspace(float(pos.phi.min()), float(pos.phi.max()), 241)
        try:
            fine = mech.positions(phi=fine_phi)
        except AssemblyError:               # the angles given span a range where it cannot be assembled
            fine = None
    c_xy = pos.coords[parts.centre][0]
    r = float(np.hypot(*(pos.coords[parts.pin][0] - c_xy)))
    return _SchemeGeometry(pos, mech, parts, drawn, thick, ext, ext_pos, fine, c_xy, r)


def _scheme_scale(g: _SchemeGeometry, sheet: Sheet, mu_l, unit_l: str, lay: SchemeLayout) -> tuple[Scale, Frame]:
    """Step 2: μ_l (given, checked, or picked to fill the sheet) and the frame centring the drawing."""
    x0, _, x1, _ = sheet.box

    def coords(p, names, idx=None):
        return [p.coords[j] if idx is None else p.coords[j][idx] for j in names]

    joints = list(g.mech.joints) + list(g.parts.extra)
    pts = coords(g.pos, joints, g.drawn)
    if g.ext_pos is not None:
        pts += coords(g.ext_pos, joints)
    if g.fine is not None:
        pts += coords(g.fine, g.parts.paths)
    pts.append(np.array([g.c_xy - g.r, g.c_xy + g.r]))
    allp = np.concatenate([np.asarray(p).reshape(-1, 2) for p in pts])
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    area = (x0, sheet.top, x1, sheet.caption_y - lay.caption_room_mm)
    avail_w = area[2] - area[0] - 2 * lay.pad_x_mm
    avail_h = area[3] - area[1] - lay.pad_top_mm - lay.pad_bottom_mm
    span_x, span_y = float(hi[0] - lo[0]), float(hi[1] - lo[1])
    if mu_l is None:
        need = max(span_x / avail_w, span_y / avail_h)
        per = convenient_at_least(need)
        s_l = Scale("μ_l", unit_l, per, note=f"picked: the linkage spans {span_x:.4g} × {span_y:.4g} m in "
                                             f"{avail_w:.0f} × {avail_h:.0f} mm, needs ≥ {need:.4g} m/mm; "
                                             f"chose {per:g}")
    else:
        s_l = Scale("μ_l", unit_l, mu_l.per_mm if isinstance(mu_l, Scale) else mu_l)
        if span_x / s_l.per_mm > avail_w * (1 + 1e-9) or span_y / s_l.per_mm > avail_h * (1 + 1e-9):
            raise InputError(f"the linkage at μ_l = {s_l.per_mm:g} m/mm needs {span_x / s_l.per_mm:.0f} × "
                             f"{span_y / s_l.per_mm:.0f} mm but the sheet leaves {avail_w:.0f} × {avail_h:.0f} mm; "
                             f"give a larger μ_l (more m per mm), a larger page, or none to have one picked")
    cx = (area[0] + area[2]) / 2 - s_l.to_mm(float(lo[0] + hi[0]) / 2)
    cy = (area[1] + lay.pad_top_mm + area[3] - lay.pad_bottom_mm) / 2 + s_l.to_mm(float(lo[1] + hi[1]) / 2)
    return s_l, Frame((cx, cy), s_l, s_l)


def _scheme_links(g: _SchemeGeometry, f: Frame) -> tuple[list[Element], list[Element], list]:
    """Step 3: the thin things (paths, crank circle, thin positions, the extreme one), the thick position,
    and every link's (a, b, page points) for the choice of ground directions."""
    def P(xy) -> tuple[float, float]:
        return f.pt(xy[0], xy[1])

    thin_els: list[Element] = []
    if g.fine is not None:
        for j in g.parts.paths:
            thin_els.append(Polyline(f.pts(g.fine.coords[j][:, 0], g.fine.coords[j][:, 1]), style=TRAJECTORY,
                                     name=f"path-{j}"))
    t = np.linspace(0.0, 2.0 * math.pi, 181)
    thin_els.append(Polyline(f.pts(g.c_xy[0] + g.r * np.cos(t), g.c_xy[1] + g.r * np.sin(t)), style=THIN,
                             closed=True, name="crank-circle"))
    link_segments: list = []

    def link_lines(p, idx, style, tag) -> list[Element]:
        out: list[Element] = []
        for a, b in g.parts.links:
            A, B = P(p.coords[a][idx]), P(p.coords[b][idx])
            out.append(Line(A, B, style=style, name=f"{tag}-{a}{b}"))
            link_segments.append((a, b, A, B))
        for j in g.parts.extra:            # a point off its link line: the link drawn as a triangle
            spec = next(q for q in g.mech.points if q.name == j)
            if spec.angle != 0.0:
                x, y, _, _ = g.mech._resolve_link(spec.link)
                S = P(p.coords[j][idx])
                out += [Line(P(p.coords[x][idx]), S, style=style, name=f"{tag}-{x}{j}"),
                        Line(S, P(p.coords[y][idx]), style=style, name=f"{tag}-{j}{y}")]
        return out

    for k in g.drawn:
        if k != g.thick:
            thin_els += link_lines(g.pos, k, THIN, f"position-{k}")
    if g.ext_pos is not None:
        thin_els += link_lines(g.ext_pos, 0, EXTREME, "extreme")
    thick_els = link_lines(g.pos, g.thick, THICK, "thick") if g.thick is not None else []
    return thin_els, thick_els, link_segments


def _scheme_grounds(g: _SchemeGeometry, P, link_segments: list, lay: SchemeLayout) -> list[Element]:
    """Step 4: the sliders' guides (hatched on the side the links leave free) and the fixed pivots' ground."""
    symbol_els: list[Element] = []
    for j, (gx, gy) in g.parts.sliders.items():
        u = np.array([gx, gy], dtype=float)
        sp = np.concatenate([g.pos.coords[j][g.drawn]] + ([g.ext_pos.coords[j]] if g.ext_pos is not None else []))
        proj = sp @ u
        a_m, b_m = sp[np.argmin(proj)], sp[np.argmax(proj)]
        ua = np.array([u[0], -u[1]])       # on paper
        start = np.asarray(P(a_m)) - ua * lay.guide_overrun_mm
        end = np.asarray(P(b_m)) + ua * lay.guide_overrun_mm
        side = _free_side(start, end, link_segments, thick_dir=_thick_dir(g.pos, g.parts, j, g.thick))
        symbol_els.append(Guide(tuple(start.tolist()), tuple(end.tolist()), offset_mm=lay.guide_offset_mm, side=side,
                                name=f"guide-{j}"))
    for j in g.parts.fixed:
        at = P(g.pos.coords[j][0])
        symbol_els.append(FixedPivot(at, direction_deg=_ground_direction(at, link_segments), name=f"pivot-{j}"))
    return symbol_els


def _scheme_joints(g: _SchemeGeometry, P, lay: SchemeLayout) -> tuple[list[Element], list[Element]]:
    """Step 5: blocks, joints and points of the thick position; the marks of the crank pin and the output
    point in every other position (and in the extreme one)."""
    top_els: list[Element] = []
    parts, pos, thick = g.parts, g.pos, g.thick
    if thick is not None:
        for j, (gx, gy) in parts.sliders.items():
            top_els.append(SliderBlock(P(pos.coords[j][thick]), angle_deg=_paper_deg((gx, gy)), name=f"block-{j}"))
        if parts.rocker_block is not None:
            bp, pivot = parts.rocker_block
            d = pos.coords[bp][thick] - pos.coords[pivot][thick]
            top_els.append(SliderBlock(P(pos.coords[bp][thick]), angle_deg=_paper_deg(d), length_mm=lay.block_length_mm,
                                       height_mm=lay.block_height_mm, name=f"block-{bp}"))
        for y in _translating_yokes(g.mech):    # a yoke (RPP on the frame's guide): its slot through R, the block at P
            R_xy, P_xy = pos.coords[y.R][thick], pos.coords[y.P][thick]
            sd = np.array([math.cos(y.guide.angle + y.slot_angle), math.sin(y.guide.angle + y.slot_angle)])
            base = R_xy + y.e * np.array([-sd[1], sd[0]])
            half = 1.15 * g.r
            top_els.append(Line(P(base - sd * half), P(base + sd * half), style=THICK, name=f"yoke-{y.R}"))
            top_els.append(SliderBlock(P(P_xy), angle_deg=_paper_deg(sd), length_mm=lay.block_length_mm,
                                       height_mm=lay.block_height_mm, name=f"block-{y.P}"))
        for j in g.mech.joints:
            if (j in parts.fixed or j in parts.sliders or j in parts.coincident
                    or (parts.rocker_block and j == parts.rocker_block[0])):
                continue
            top_els.append(PinJoint(P(pos.coords[j][thick]), name=f"joint-{j}"))
        for j in parts.extra:
            top_els.append(Point(P(pos.coords[j][thick]), radius_mm=lay.point_mm, name=f"point-{j}"))
    marks: list[Element] = []
    for k in g.drawn:
        if k == thick:
            continue
        for j in (parts.pin, parts.output):
            marks.append(Point(P(pos.coords[j][k]), radius_mm=lay.mark_mm, name=f"mark-{j}-{k}"))
    if g.ext_pos is not None:
        for j in (parts.pin, parts.output):
            marks.append(Point(P(g.ext_pos.coords[j][0]), radius_mm=lay.mark_mm, name=f"mark-{j}-extreme"))
    return top_els, marks


def _scheme_keep_clear(occ: Occupancy, thick_els: list[Element], top_els: list[Element], symbol_els: list[Element],
                       lay: SchemeLayout) -> Occupancy:
    """What a label must never cover (thick links, blocks: returned), and the joints and blocks kept free."""
    hard = Occupancy(pad_mm=lay.hard_pad_mm)
    hard.register(*thick_els, *[e for e in top_els if isinstance(e, SliderBlock)])
    c = lay.joint_clear_mm
    for e in top_els + symbol_els:
        if isinstance(e, (PinJoint, FixedPivot)):
            x, y = e.at
            occ.add_box((x - c, y - c, x + c, y + c))
        elif isinstance(e, SliderBlock):
            cs = np.asarray(e.corners())
            occ.add_box((*cs.min(axis=0), *cs.max(axis=0)))
    return hard


def _scheme_numbers(g: _SchemeGeometry, P, occ: Occupancy, sheet: Sheet, symbol_els: list[Element], nt,
                    lay: SchemeLayout) -> tuple[list[Text], list[Element]]:
    """Step 6: the position numbers at the output point, the stroke H beyond them, the numbers at the crank pin."""
    parts, pos = g.parts, g.pos
    guide = next((e for e in symbol_els if isinstance(e, Guide) and e.name == f"guide-{parts.output}"), None)
    out_items = _numbered(pos, parts, g.drawn, g.ext, g.ext_pos, parts.output)
    free = None                                           # a guide at an angle: the numbers' side on paper
    out_side: str | None = None
    if guide is not None:
        out_side = "s" if guide.side > 0 else "n"
        gs, ge = np.asarray(guide.start, float), np.asarray(guide.end, float)
        ug = (ge - gs) / float(np.hypot(*(ge - gs)))
        if abs(ug[1]) > 1e-9:
            free = -guide.side * np.array([ug[1], -ug[0]])    # away from the hatched surface
            toward = math.degrees(math.atan2(-free[1], free[0]))
            dirs = tuple(d for d in _dirs(toward) if abs((_COMPASS[d] - toward + 180.0) % 360.0 - 180.0) <= 50.0)
            numbers = _output_numbers(out_items, P, occ, sheet.box, side=dirs[0], dirs=dirs, prefer=toward)
        else:
            numbers = _output_numbers(out_items, P, occ, sheet.box, side=out_side)
    else:
        pivot = next(x for x, y in parts.links if y == parts.output and x in parts.fixed)
        numbers = _output_numbers(out_items, P, occ, sheet.box, side=None, pivot=np.asarray(P(pos.coords[pivot][0])))
    dims: list[Element] = []
    if guide is not None and pos.H is not None and g.ext is not None:
        end_xy = g.ext_pos.coords[parts.output][0] if g.ext_pos is not None else pos.coords[parts.output][g.ext.same_as]
        text = nt.word("kinematics.stroke", H=nt.number(pos.H, sig=4), u=nt.unit("m"))
        dim = _stroke_dimension(P(pos.coords[parts.output][0]), P(end_xy), numbers, text, free, out_side, lay)
        dims.append(dim)
        occ.register(dim)
    numbers += _crank_numbers(_numbered(pos, parts, g.drawn, g.ext, g.ext_pos, parts.pin), P(g.c_xy), P, occ,
                              sheet.box)
    return numbers, dims


def _stroke_dimension(a, b, numbers: list[Text], text: str, free, out_side: str | None,
                      lay: SchemeLayout) -> Dimension:
    """The stroke H dimensioned between the output's extreme points ``a`` and ``b`` (page mm), beyond
    their numbers: along a guide at an angle (``free``: the unit normal toward the numbers) or level."""
    from graphmethods.scene.elements import label_bbox

    left, right = (a, b) if a[0] <= b[0] else (b, a)
    boxes = [label_bbox(cast(Label, p)) for t in numbers for p in t.primitives()]          # Text draws labels
    axis_y = a[1]
    reach = max([axis_y - bb[1] for bb in boxes] if out_side == "n" else [bb[3] - axis_y for bb in boxes]) \
        if boxes else 0.0
    off = lay.stroke_offset_mm
    if free is not None:                              # along a guide at an angle, beyond its numbers
        a_, b_ = np.asarray(a, float), np.asarray(b, float)
        corners = [np.array([x, y]) for bb in boxes for x in (bb[0], bb[2]) for y in (bb[1], bb[3])]
        reach = max([float((c - a_) @ free) for c in corners], default=0.0)
        lift = (max(reach, 2.0) + 0.8) * free
        p1, p2 = a_ + lift, b_ + lift
        if float(np.array([-(p2 - p1)[1], (p2 - p1)[0]]) @ free) < 0:
            p1, p2 = p2, p1                           # the dimension's offset goes to the free side
        return Dimension(tuple(p1.tolist()), tuple(p2.tolist()), text, offset_mm=off, size_mm=TEXT_MM,
                         name="dimension-H")
    rise = (max(reach, 2.0) + 0.8) * (-1.0 if out_side == "n" else 1.0)       # measured from beyond the numbers
    left, right = (left[0], left[1] + rise), (right[0], right[1] + rise)
    if out_side == "n":
        return Dimension(right, left, text, offset_mm=off, size_mm=TEXT_MM, name="dimension-H")
    return Dimension(left, right, text, offset_mm=off, size_mm=TEXT_MM, name="dimension-H")


def _scheme_names(g: _SchemeGeometry, P, occ: Occupancy, box, hard: Occupancy, lay: SchemeLayout) -> list[Text]:
    """Step 7: the names of the joints of the thick position (position 0 when all are thin), away from the middle."""
    labels = []
    occ.pad = lay.names_pad_mm
    ref = g.thick if g.thick is not None else 0
    centroid = np.mean([P(g.pos.coords[j][ref]) for j in g.mech.joints], axis=0)
    for j in list(g.mech.joints) + list(g.parts.extra):
        if j in g.parts.coincident:
            continue
        at = P(g.pos.coords[j][ref])
        away = np.asarray(at) - centroid
        prefer = math.degrees(math.atan2(-away[1], away[0])) if np.hypot(*away) > 1e-9 else 90.0
        if j in g.parts.fixed:
            prefer = 180.0 if at[0] <= centroid[0] else 0.0
        labels.append(_place(occ, at, _sub(j), prefer, size_mm=TEXT_MM + 0.3, within=box, name=f"name-{j}",
                             gaps=lay.names_gaps_mm, hard=hard))
    occ.pad = lay.pad_mm
    return labels


def _scheme_facts(pos, ext: _Extreme | None, nt) -> list[str]:
    """What the drawing says in words: the extreme positions, θ and K, or the rocker's swing."""
    facts = []
    st = pos.strokes
    if st is not None and ext is not None:
        facts.append(nt.word("kinematics.extremes", a="0", b=ext.label))
        facts.append(nt.word("kinematics.theta", t=nt.number(math.degrees(st.theta), sig=4) + "°"))
        facts.append(nt.word("kinematics.K", K=nt.number(st.K, sig=4)))
    if pos.psi_max is not None:
        facts.append(nt.word("kinematics.swing", p=nt.number(math.degrees(pos.psi_max), sig=4) + "°"))
    return facts


def kinematic_scheme(linkage, *, m: int | None = None, mu_l=None, thick: int | None = 0, trajectories: bool = True,
                     notation="en", page=None, title=None, problem=None, title_block: bool = True,
                     name: str = "kinematic-scheme") -> Scene:
    """The linkage in its m positions on one drawing to the length scale μ_l (план механизма).

    Position ``thick`` (0 by default, as textbooks draw it) has thick links, every other position
    thin ones; the end of the working stroke, when it falls between two numbered positions, is
    drawn dashed and numbered with a prime (``6′``). Fixed pivots stand on hatched ground, sliders
    are blocks on a hatched guide, joints are small circles; the positions are numbered 0…m at the
    crank pin and at the output point; the paths of the moving points (centres of mass, rocker
    ends) are dotted; the slider's stroke H is dimensioned between its extreme positions; the
    crank's sense of rotation is shown by the arrow ω₁.

    Parameters
    ----------
    linkage : Case, Study, Mechanism or Positions
        What to draw (see the module docstring).
    m : int, optional
        Number of positions (12 when not given by the linkage).
    mu_l : float or Scale, optional
        Length scale, m/mm; picked to fill the sheet when not given.
    thick : int or None
        The position drawn thick (None: all thin).
    trajectories : bool
        Draw the dotted paths of the moving points.
    notation : {'en', 'ru', 'zh'}
    page : Page, optional
        The sheet (A4 landscape with frame and title block by default).
    title, problem : str, optional
        Title (markup) and the problem's name in the title block (default: the problem file's name, in
        the notation's language when the file gives it in several).

    Raises
    ------
    InputError
        If ``thick`` is not a drawn position or a given μ_l does not fit the sheet.

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> s = kinematic_scheme(SliderCrank(r=0.1, l=0.4, e=0.02), mu_l=0.004, notation="zh")
    >>> s.title, s.scales()[0].caption()
    ('机构运动简图（12个位置）', 'μ_l = 0.004 m/mm')
    """
    lk = _Linkage.of(linkage, m=m)
    nt = get_notation(notation)
    lay = SCHEME_LAYOUT
    g = _scheme_geometry(lk.positions, thick, trajectories)
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("kinematics.scheme", m=len(g.drawn)),
                  problem=lk.problem if problem is None else problem, title_block=title_block)
    s_l, f = _scheme_scale(g, sheet, mu_l, nt.unit("m"), lay)

    def P(xy) -> tuple[float, float]:
        return f.pt(xy[0], xy[1])

    occ = sheet.occ
    thin_els, thick_els, link_segments = _scheme_links(g, f)
    occ.register(*thin_els, *thick_els)
    symbol_els = _scheme_grounds(g, P, link_segments, lay)
    occ.register(*symbol_els)
    top_els, marks = _scheme_joints(g, P, lay)
    occ.register(*top_els, *marks)
    hard = _scheme_keep_clear(occ, thick_els, top_els, symbol_els, lay)
    rot, rot_label = _rotation_arrow(P(g.c_xy), s_l.to_mm(g.r), g.mech.sense, occ, link_segments)
    occ.register(rot)
    numbers, dims = _scheme_numbers(g, P, occ, sheet, symbol_els, nt, lay)
    labels = _scheme_names(g, P, occ, sheet.box, hard, lay) + [rot_label(occ)]
    facts = _scheme_facts(g.pos, g.ext, nt)
    summary = [Text((sheet.box[0], sheet.caption_y - lay.summary_above_mm), ";   ".join(facts), size_mm=TEXT_MM,
                    name="summary")] if facts else []
    legend = lk.speed_text(nt) if lk.n_rpm is not None else ""
    scales = (s_l,)
    elements = ([sheet.header()] + thin_els + symbol_els + dims + thick_els + top_els + marks + [rot] + labels
                + numbers + summary)
    elements += sheet.captions(scales, legend=legend, reserve=True)
    return sheet.scene(elements, scales, name=name, notes=(s_l.note,) if s_l.note else ())


def _thick_dir(pos, parts, j, thick):
    """Direction on paper (unit) of the thick link that leaves slider point ``j``, or None."""
    if thick is None:
        return None
    for a, b in parts.links:
        if j in (a, b):
            other = b if a == j else a
            d = pos.coords[other][thick] - pos.coords[j][thick]
            L = float(np.hypot(*d))
            if L > 0:
                return np.array([d[0], -d[1]]) / L
    return None


def _free_side(start, end, segments, *, thick_dir=None) -> int:
    """The side of a guide (+1 left of start→end on paper, −1 right) for its hatched surface.

    The side the thick link leaves the slider on (the position numbers go on the other side,
    clear of it); without one, the side fewer links cross.
    """
    from shapely import intersection, length, linestrings
    from shapely.geometry import Polygon as SPolygon

    u = (end - start) / float(np.hypot(*(end - start)))
    left = np.array([u[1], -u[0]])
    if thick_dir is not None and abs(float(thick_dir @ left)) > 0.005:
        return 1 if float(thick_dir @ left) > 0 else -1
    if not segments:
        return -1
    lines = linestrings(np.array([[A, B] for _, _, A, B in segments], dtype=float))
    cost = {}
    for side in (-1, 1):
        n = left * side
        strip = SPolygon([start + n * 1.0, end + n * 1.0, end + n * 6.0, start + n * 6.0])
        cost[side] = float(length(intersection(lines, strip)).sum())
    return -1 if cost[-1] <= cost[1] + 1e-9 else 1


def _ground_direction(at, segments) -> float:
    """Where to put the ground under a fixed pivot: the direction (paper degrees, near 270° = below)
    farthest in angle from every link line that starts at it or passes close by."""
    c = np.asarray(at, dtype=float)
    dirs = []
    for _, _, A, B in segments:
        A, B = np.asarray(A), np.asarray(B)
        for p, q in ((A, B), (B, A)):
            if np.hypot(*(p - c)) < 1e-6 and np.hypot(*(q - c)) > 1e-6:
                dirs.append(math.degrees(math.atan2(-(q - p)[1], (q - p)[0])))
        d = B - A
        L = float(np.hypot(*d))
        if L > 1e-6 and np.hypot(*(A - c)) > 1e-6 and np.hypot(*(B - c)) > 1e-6:
            t = float(np.clip((c - A) @ d / (L * L), 0.0, 1.0))
            if np.hypot(*(A + t * d - c)) < 9.0:
                a = math.degrees(math.atan2(-d[1], d[0]))
                dirs += [a, a + 180.0]
    if not dirs:
        return 270.0
    dirs_a = np.asarray(dirs)

    def gap(cand):
        return float(np.abs((dirs_a - cand + 180.0) % 360.0 - 180.0).min())

    best = 270.0                                   # the ground below, as drawn by hand ...
    if gap(270.0) < 8.0:                           # ... unless a link runs straight into it
        for cand in (255.0, 285.0, 240.0, 300.0):
            if gap(cand) >= 15.0:
                best = cand
                break
    return float(best % 360.0)


def _rotation_arrow(centre, r_mm: float, sense: int, occ: Occupancy, segments):
    """The ω₁ arc arrow inside the crank circle where it crosses fewest lines, and a labeller for it."""
    from shapely import intersects, linestrings

    radius = float(min(max(0.45 * r_mm, 5.0), 9.0))
    sweep = 70.0 * sense
    lines = linestrings(np.array([[A, B] for _, _, A, B in segments], dtype=float)) if segments else None
    best: tuple[int, RotationArrow] | None = None
    for mid in np.arange(135.0, 135.0 + 360.0, 15.0):
        arr = RotationArrow(centre, radius, float(mid - sweep / 2), sweep, name="omega-1")
        if lines is None:
            best = (0, arr)
            break
        hits = int(intersects(linestrings(np.array(arr.arc_points())), lines).sum())
        if best is None or hits < best[0]:
            best = (hits, arr)
    assert best is not None                    # the loop runs at least once
    arr = best[1]

    def label(occ_):
        mid = math.radians(arr.start_deg + arr.sweep_deg / 2)
        at = (centre[0] + radius * math.cos(mid), centre[1] - radius * math.sin(mid))
        return _place(occ_, at, "ω_1", math.degrees(mid), size_mm=TEXT_MM + 0.3, name="name-omega-1",
                      gaps=(1.0, 2.2, 3.5))

    return arr, label


def _numbered(pos, parts, drawn, ext, ext_pos, j):
    """(tag, text, xy) of point ``j`` in every drawn position and the extra extreme position."""
    items = [(_tag(k), _pos_label(pos, k), pos.coords[j][k]) for k in drawn]
    if ext is not None and ext_pos is not None:
        items.append(("extreme", ext.label, ext_pos.coords[j][0]))
    return items


def _crank_numbers(items, centre, P, occ, box) -> list:
    """The position numbers at the crank pin, outside the crank circle."""
    out = []
    c = np.asarray(centre)
    for tag, text, xy in items:
        a = np.asarray(P(xy))
        radial = math.degrees(math.atan2(-(a - c)[1], (a - c)[0]))
        dirs = [d for d in _dirs(radial) if abs((_COMPASS[d] - radial + 180.0) % 360.0 - 180.0) <= 70.0]
        out.append(_place(occ, tuple(a), text, radial, size_mm=SMALL_MM, within=box, name=f"number-A-{tag}",
                          gaps=(1.0, 2.4, 4.0), dirs=dirs))
    return out


def _output_numbers(items, P, occ, box, *, side: str | None, pivot=None, dirs=None, prefer=None) -> list:
    """The position numbers at the output point: for a slider in a row on the free side of its guide
    (``side`` "n" or "s" for a horizontal guide, or the compass ``dirs`` and angle ``prefer`` (deg) of
    the free side of a guide at an angle; points closer than 2 mm share a label, "1, 11"); for a
    rocker outward from its pivot."""
    out = []
    groups: list[list] = []
    for tag, text, xy in items:
        o = np.asarray(P(xy))
        for g in groups:
            if side is not None and np.hypot(*(g[0][1] - o)) < 2.0:
                g.append((tag, o, text))
                break
        else:
            groups.append([(tag, o, text)])
    for g in groups:
        tag, o, _ = g[0]
        text = ", ".join(t for _, _, t in g)
        if side is not None:
            toward = prefer if prefer is not None else (90.0 if side == "n" else 270.0)
            out.append(_place(occ, tuple(o), text, toward, size_mm=SMALL_MM, within=box,
                              dirs=dirs or (side, side + "e", side + "w"), gaps=(1.5, 3.1, 4.7, 6.3),
                              name=f"number-out-{tag}"))
            continue
        prefer = math.degrees(math.atan2(-(o - pivot)[1], (o - pivot)[0]))
        out.append(_place(occ, tuple(o), text, prefer, size_mm=SMALL_MM, within=box, name=f"number-out-{tag}",
                          gaps=(1.0, 2.4, 4.0, 6.0)))
    return out


def _tag(k: int) -> str:
    return "extreme" if k < 0 else str(k)


# ----------------------------------------------------------------------------- plans: what each one draws

@dataclass(frozen=True)
class _PlanVector:
    """One vector of a plan: from the image ``start`` to the image ``end`` (labels like "p", "a", "s2")."""

    start: str
    end: str
    known: bool
    symbol: str          # markup of the velocity it stands for, "v_{A}", "v_{BA}"


def _rel_name(mech, x: str, y: str) -> str:
    """Name of the relative velocity of X with respect to Y (``"BA"``; ``"A3A2"`` on a slotted lever)."""
    for pin, _, _, block, _ in mech.slotted_links:
        if y == pin:
            return x + y + block
    return x + y


def _plan_layout(plans) -> tuple[list[tuple[str, str | None]], list[_PlanVector]]:
    """The images of a plan (label, point name; poles once as "p") and its vectors in construction order:
    p→x for every moving point, y→x for the relative velocity of every intersection."""
    mech = plans.positions.mechanism
    images: list[tuple[str, str | None]] = [("p", None)]
    vectors: list[_PlanVector] = []
    seen = {"p"}
    for name, c in plans.constructions.items():
        if c.method == "pole":
            continue
        if c.label not in seen:
            images.append((c.label, name))
            seen.add(c.label)
        vectors.append(_PlanVector("p", c.label, c.method == "known", f"v_{{{name}}}"))
        if c.method == "intersection":
            for ln in c.lines:
                if ln.through != "p":
                    y = next(n for n, cc in plans.constructions.items() if cc.label == ln.through)
                    vectors.append(_PlanVector(ln.through, c.label, False, f"v_{{{_rel_name(mech, name, y)}}}"))
    return images, vectors


def _image_xy(plans, images, k: int) -> dict[str, np.ndarray]:
    """Plan point (m/s) of every image at position k; the pole at the origin."""
    out = {}
    for label, name in images:
        out[label] = np.zeros(2) if name is None else np.asarray(plans.v(name)[k], dtype=float)
    return out


def _plan_markup(label: str) -> str:
    return _sub(label)


def _plan_labels(occ: Occupancy, pts_mm: dict, pole: str, rays: list[str], *, markup_of: Callable[[str], str],
                 size_mm: float, within, prefix: str, id_of: Callable[[str], str] = str, hard=None,
                 leaders=None) -> list[Text]:
    """Labels of the images of one plan (velocity or acceleration): coincident images share one label
    ("p, b"), each placed away from the ``pole``; the pole's label away from the images in ``rays``.

    ``markup_of`` writes an image's label (``"s2"`` -> ``"s_{2}"``), ``id_of`` names it in the
    element's name (π is ``pi``).
    """
    groups: list[list] = []
    for label, at in pts_mm.items():
        for g in groups:
            if math.dist(g[0][1], at) < 0.8:
                g.append((label, at))
                break
        else:
            groups.append([(label, at)])
    p = np.asarray(pts_mm[pole])
    out = []
    for g in groups:
        at = np.asarray(g[0][1])
        text = ", ".join(markup_of(lb) for lb, _ in g)
        if any(lb == pole for lb, _ in g):
            ds = [np.asarray(pts_mm[e]) - p for e in rays]
            ds = [d / np.hypot(*d) for d in ds if np.hypot(*d) > 0.8]
            mm = -np.sum(ds, axis=0) if ds else np.array([-1.0, 1.0])
            prefer = math.degrees(math.atan2(-mm[1], mm[0])) if np.hypot(*mm) > 1e-9 else 225.0
        else:
            d = at - p
            prefer = math.degrees(math.atan2(-d[1], d[0]))
        out.append(_place(occ, tuple(at), text, prefer, size_mm=size_mm, within=within, hard=hard,
                          name=f"{prefix}name-{id_of(g[0][0])}", gaps=(0.8, 1.8, 3.0, 4.5), leaders=leaders))
    return out


def _plan_vectors(pts_mm: dict, vectors, *, prefix: str, head_mm: float = 2.2) -> list:
    out = []
    for v in vectors:
        out.append(Vector(pts_mm[v.start], pts_mm[v.end], known=v.known, head_length_mm=head_mm,
                          head_width_mm=head_mm * 0.36, name=f"{prefix}vector-{v.start}{v.end}"))
    return out


def _pick_plan_scale(given, need: float, *, symbol: str, unit: str, what: str, nt) -> Scale:
    """The scale of a plan (``symbol`` μ_v or μ_a, values in ``unit``): picked (a convenient value of at
    least ``need`` per mm), or the one given, checked to be a positive number the plan fits at."""
    su = nt.unit(f"({unit})")
    if given is None:
        per = convenient_at_least(need)
        return Scale(symbol, su, per, note=f"picked: {what} needs ≥ {need:.4g} ({unit})/mm; chose {per:g}")
    per = given.per_mm if isinstance(given, Scale) else given
    if isinstance(per, bool) or not isinstance(per, (int, float)) or not math.isfinite(per) or per <= 0:
        kind = "velocity" if symbol == "μ_v" else "acceleration"
        raise InputError(f"mu_{symbol[-1]} is the {kind} scale in ({unit})/mm and must be > 0, got {given!r}")
    s = Scale(symbol, su, float(per))
    if need > s.per_mm * (1 + 1e-9):
        raise InputError(f"{what} at {symbol} = {s.per_mm:g} ({unit})/mm does not fit: it needs at least {need:.4g} "
                         f"({unit})/mm; give a larger {symbol}, a larger page, or none to have one picked")
    return s


def _pick_mu_v(mu_v, need: float, *, what: str, nt) -> Scale:
    """μ_v of a velocity plan (:func:`_pick_plan_scale`)."""
    return _pick_plan_scale(mu_v, need, symbol="μ_v", unit="m/s", what=what, nt=nt)


def _centred_frame(box, lo, hi, s: Scale) -> Frame:
    """The frame that draws a plan spanning ``lo``…``hi`` (physical units) to scale ``s``, centred in ``box`` (mm)."""
    mid = ((box[0] + box[2]) / 2, (box[1] + box[3]) / 2)
    return Frame((mid[0] - s.to_mm(float(lo[0] + hi[0]) / 2), mid[1] + s.to_mm(float(lo[1] + hi[1]) / 2)), s, s)


def _through(P0, d, X, name: str, style: Style) -> Line:
    """A construction line through ``P0`` along the unit ``d`` (page mm), 10 mm past both it and the point ``X``."""
    t = float((X - P0) @ d)
    a, b = P0 + d * (min(0.0, t) - 10.0), P0 + d * (max(0.0, t) + 10.0)
    return Line(tuple(a.tolist()), tuple(b.tolist()), style=style, name=name)


def _label_lines(occ: Occupancy, lines: list[Line], texts: list[str], *, hard: Occupancy, area) -> list[Text]:
    """Each construction line's label (⊥ AB, ∥ guide) at its far end, across it."""
    out = []
    for el, text in zip(lines, texts):
        d = np.asarray(el.end) - np.asarray(el.start)
        prefer = math.degrees(math.atan2(-d[1], d[0])) + 90.0
        out.append(_place(occ, el.end, text, prefer, size_mm=SMALL_MM, hard=hard,
                          within=(area[0], area[1] - 4, area[2] + 4, area[3] + 4), name=f"label-{el.name}",
                          gaps=(0.6, 1.6, 3.0)))
    return out


# ----------------------------------------------------------------------------- 2a. the grid of plans

@dataclass(frozen=True)
class PlanGridLayout:
    """The millimetre constants of a sheet of plans, one cell per position (velocity and acceleration)."""

    pad_x_mm: float = 6.0               # inside a cell, beside the plan
    head_mm: float = 6.0                # the cell's heading
    pad_y_mm: float = 4.5               # above and below the plan
    caption_room_mm: float = 9.0        # between the cells and the captions line
    inset_mm: float = 0.8               # a cell's frame inside its share of the sheet
    heading_x_mm: float = 1.8           # the heading from the cell's top left corner
    heading_y_mm: float = 1.5
    value_gap_mm: float = 1.4           # between the lines of values of a plan off the scale
    pole_mm: float = 0.55


PLAN_GRID_LAYOUT = PlanGridLayout()


@dataclass(frozen=True)
class _Grid:
    """The cells of a sheet of plans: the area they share, columns, a cell's width and height (mm)."""

    area: tuple[float, float, float, float]
    columns: int
    cw: float
    ch: float
    need: float                         # physical units per mm the largest plan needs in its cell

    def cell(self, idx: int, lay: PlanGridLayout) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """The frame of cell ``idx`` and the box inside it that the plan fills (mm)."""
        r, c = divmod(idx, self.columns)
        bx0, by0 = self.area[0] + c * self.cw, self.area[1] + r * self.ch
        e = lay.inset_mm
        box = (bx0 + e, by0 + e, bx0 + self.cw - e, by0 + self.ch - e)
        inner = (box[0] + lay.pad_x_mm - e, box[1] + lay.head_mm + lay.pad_y_mm - e, box[2] - lay.pad_x_mm + e,
                 box[3] - lay.pad_y_mm + e)
        return box, inner


def _plan_grid(sheet: Sheet, spans: np.ndarray, fit: np.ndarray, columns, lay: PlanGridLayout) -> _Grid:
    """The grid of n plans whose extents are ``spans`` (n, 2): the columns given, or those giving the largest
    common scale; only the plans ``fit`` (bool, n) have to fit their cells."""
    x0, _, x1, _ = sheet.box
    area = (x0, sheet.top, x1, sheet.caption_y - lay.caption_room_mm)
    W, H = area[2] - area[0], area[3] - area[1]
    n = len(spans)

    def need_for(cols: int) -> tuple[float, float, float]:
        rows = math.ceil(n / cols)
        cw, ch = W / cols, H / rows
        iw, ih = cw - 2 * lay.pad_x_mm, ch - lay.head_mm - 2 * lay.pad_y_mm
        if iw <= 5 or ih <= 5:
            return math.inf, cw, ch
        return float(max((spans[fit, 0] / iw).max(), (spans[fit, 1] / ih).max())), cw, ch

    if columns is None:
        columns = min((need_for(c)[0], c) for c in range(1, n + 1))[1]
    elif isinstance(columns, bool) or not isinstance(columns, int) or not 1 <= columns <= n:
        raise InputError(f"columns must be an integer from 1 to {n} (the number of plans), got {columns!r}")
    need, cw, ch = need_for(columns)
    if not math.isfinite(need) or need <= 0:
        raise InputError(f"{n} plans in {columns} columns do not fit on this sheet; give other columns or a "
                         f"larger page")
    return _Grid(area, columns, cw, ch, need)


def _grid_cell(box, heading: str, prefix: str, style: Style, occ: Occupancy, lay: PlanGridLayout) -> list[Element]:
    """A cell's frame and its bold heading (registered: labels keep off it)."""
    frame = Polyline(((box[0], box[1]), (box[2], box[1]), (box[2], box[3]), (box[0], box[3])), style=style,
                     closed=True, name=f"{prefix}cell")
    head = Text((box[0] + lay.heading_x_mm, box[1] + lay.heading_y_mm + TEXT_MM * 0.76), heading, size_mm=TEXT_MM,
                bold=True, name=f"{prefix}heading")
    occ.add_primitives(head.primitives())
    return [frame, head]


def velocity_plan_grid(linkage, *, m: int | None = None, omega_1: float | None = None, mu_v=None,
                       columns: int | None = None, notation="en", page=None, title=None, problem=None,
                       title_block: bool = True, name: str = "velocity-plans") -> Scene:
    """The velocity plans of all positions on one sheet: a grid of small plans to one common μ_v.

    Each cell holds the plan of one position (numbered as on the scheme): the pole p, the known
    vector pa (solid), the vectors found by construction (dashed: pb, ab, ps₂, …), the images
    labelled a, b, s₂, … (coincident images share one label, ``p, b`` at a dead centre).
    Ill-conditioned positions (construction lines nearly parallel, values from the analytic
    derivative) have a heavy dashed frame and say so; a plan too large for its cell at the common
    scale is written as values instead.

    Parameters
    ----------
    linkage : Case, Study, Mechanism, Positions or VelocityPlans
    m : int, optional
        Number of positions (12 when not given by the linkage).
    omega_1 : float, optional
        Crank speed, rad/s (the problem's mean speed, or 1: the velocity analogues).
    mu_v : float or Scale, optional
        Velocity scale, (m/s)/mm, common to all plans; picked so the largest plan fits its cell.
    columns : int, optional
        Cells per row (chosen for the largest common scale when not given).

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> s = velocity_plan_grid(SliderCrank(r=0.1, l=0.4, points={"S2": ("AB", 0.13)}), omega_1=10.0)
    >>> s.scales()[0].caption(), s.element("plan-3-vector-pa").known
    ('μ_v = 0.04 (m/s)/mm', True)
    """
    lk, plans, pos, drawn = _plans_of(linkage, m=m, omega_1=omega_1)
    nt = get_notation(notation)
    lay = PLAN_GRID_LAYOUT
    images, vectors = _plan_layout(plans)
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("kinematics.plans"),
                  problem=lk.problem if problem is None else problem, title_block=title_block)
    spans = []
    for k in drawn:
        xy = np.array(list(_image_xy(plans, images, k).values()))
        spans.append((np.ptp(xy[:, 0]), np.ptp(xy[:, 1])))
    ill = np.asarray(plans.ill_conditioned)[drawn]
    grid = _plan_grid(sheet, np.array(spans), ~ill if (~ill).any() else np.ones_like(ill), columns, lay)
    s_v = _pick_mu_v(mu_v, grid.need, what="the largest plan in its cell", nt=nt)
    occ = sheet.occ
    cells: list[Element] = []
    drawn_els: list[Element] = []
    label_els: list[Element] = []
    for idx, k in enumerate(drawn):
        box, inner = grid.cell(idx, lay)
        bad = bool(plans.ill_conditioned[k])
        prefix = f"plan-{k}-"
        head = _pos_label(pos, k) + (f" — {nt.word('kinematics.ill')}" if bad else "")
        cells += _grid_cell(box, head, prefix, CELL_ILL if bad else CELL, occ, lay)
        xy_k = _image_xy(plans, images, k)
        arr = np.array(list(xy_k.values()))
        lo, hi = arr.min(axis=0), arr.max(axis=0)
        w_mm, h_mm = s_v.to_mm(float(hi[0] - lo[0])), s_v.to_mm(float(hi[1] - lo[1]))
        if w_mm > inner[2] - inner[0] + 1e-6 or h_mm > inner[3] - inner[1] + 1e-6:
            label_els += _off_scale_values(xy_k, vectors, inner, prefix, nt, lay)
            continue
        pts = {lb: _centred_frame(inner, lo, hi, s_v).pt(*v) for lb, v in xy_k.items()}
        vecs = _plan_vectors(pts, vectors, prefix=prefix)
        pole = Point(pts["p"], radius_mm=lay.pole_mm, name=f"{prefix}pole")
        occ.register(*vecs, pole)
        drawn_els += vecs + [pole]
        label_els += _plan_labels(occ, pts, "p", [v.end for v in vectors if v.start == "p"], markup_of=_plan_markup,
                                  size_mm=SMALL_MM + 0.2, within=box, prefix=prefix, leaders=label_els)
    legend = f"{lk.speed_text(nt)};  {nt.word('kinematics.legend')}"
    if ill.any():
        legend += f";  {nt.word('kinematics.ill_frame')}"
    scales = (s_v,)
    elements = [sheet.header()] + cells + drawn_els + label_els + sheet.captions(scales, legend=legend, reserve=True)
    return sheet.scene(elements, scales, name=name, notes=(s_v.note,) if s_v.note else ())


def _off_scale_values(xy_k: dict, vectors, inner, prefix: str, nt, lay: PlanGridLayout) -> list[Element]:
    """A plan too large for its cell at the common scale, written as values: |v| of every point found."""
    lines = [nt.word("kinematics.off_scale") + ":"]
    for v in vectors:
        if v.start == "p" and not v.known:
            val = float(np.hypot(*(xy_k[v.end])))
            lines.append(f"{v.symbol} = {nt.number(val, sig=4)} {nt.unit('m/s')}")
    return [Text((inner[0], inner[1] + 4.0 + i * (SMALL_MM + lay.value_gap_mm)), t, size_mm=SMALL_MM,
                 name=f"{prefix}value-{i}") for i, t in enumerate(lines)]


# ----------------------------------------------------------------------------- 2b. one large plan

def fullest_position(plans) -> int:
    """The position to draw large by default: on the working stroke (extreme positions left out),
    the one whose plan is the fullest figure (largest area of its images' hull over the square of
    its longest vector), so that every construction line and vector reads clearly.

    >>> from graphmethods.kinematics import SliderCrank
    >>> fullest_position(SliderCrank(r=0.1, l=0.4, e=0.02).velocity_plans(12))
    1
    """
    pos = plans.positions
    drawn = _drawn(pos)
    images, _ = _plan_layout(plans)
    best, best_score = drawn[0], -1.0
    for k in drawn:
        if pos.extreme[k] or (pos.working is not None and not pos.working[k]):
            continue
        pts = np.array(list(_image_xy(plans, images, k).values()))
        big = float(np.max(np.hypot(pts[:, 0], pts[:, 1])))
        if big <= 0:
            continue
        score = _hull_area(pts) / big ** 2
        if score > best_score + 1e-12:
            best, best_score = k, score
    return int(best)


def _hull_area(pts: np.ndarray) -> float:
    """Area of the convex hull of points (n, 2) (monotone chain)."""
    p = sorted(map(tuple, np.round(pts, 15).tolist()))
    if len(p) < 3:
        return 0.0

    def half(seq):
        h = []
        for q in seq:
            while len(h) >= 2 and ((h[-1][0] - h[-2][0]) * (q[1] - h[-2][1])
                                   - (h[-1][1] - h[-2][1]) * (q[0] - h[-2][0])) <= 0:
                h.pop()
            h.append(q)
        return h
    hull = half(p)[:-1] + half(p[::-1])[:-1]
    x = np.array([q[0] for q in hull])
    y = np.array([q[1] for q in hull])
    return float(abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) / 2.0)


def _sense_word(nt, w: float) -> str:
    if abs(w) < 1e-12:
        return nt.word("kinematics.at_rest")
    return nt.word("kinematics.ccw") if w > 0 else nt.word("kinematics.cw")


def _equations(plans, k: int, nt, lk) -> list[str]:
    """The vector equations of the construction, in markup, one per line, with the values at position k."""
    mech = plans.positions.mechanism
    lines = []
    unit = nt.unit("m/s")
    for name, c in plans.constructions.items():
        v = float(plans.speed(name)[k])
        if c.method == "known":
            crank = next(ln for ln, (x, y) in mech.link_joints.items() if y == name)
            L = float(np.hypot(*(plans.positions.coords[name][k] - plans.positions.coords[crank[:-1]][k])))
            lines.append(f"v_{{{name}}} = ω_1·l_{{{crank}}} = {nt.number(lk.omega_1, sig=4)}·"
                         f"{nt.number(L, sig=4)} = {nt.number(v, sig=4)} {unit}")
        elif c.method == "intersection":
            rel = [ln for ln in c.lines if ln.through != "p"]
            y = next(n for n, cc in plans.constructions.items() if cc.label == rel[0].through) if rel else None
            parts = []
            for ln in c.lines:
                what = f"v_{{{name}}}" if ln.through == "p" or y is None else f"v_{{{_rel_name(mech, name, y)}}}"
                parts.append(f"{what} {_line_label(ln, nt)}")
            eq = f"v_{{{name}}} = v_{{{y}}} + v_{{{_rel_name(mech, name, y)}}}" if y else f"v_{{{name}}}"
            lines.append(f"{eq};  " + ",  ".join(parts))
        elif c.method == "similarity":
            x, y = next((a, b) for a, b in mech.link_joints.values() if a + b == c.on or b + a == c.on)
            if c.on == y + x:
                x, y = y, x
            ix, iy = (plans.label(x), plans.label(y))
            lo = plans.label(name)
            lines.append(f"{ix}{_sub(lo)}/{ix}{iy} = {_sub(x + name)}/{_sub(x + y)}")
        elif c.method == "proportion":
            sl = next((sl for sl in mech.slotted_links if c.on and c.on.startswith(sl[2])), None)
            lines.append(f"p{_sub(plans.label(name))} = p{_sub(plans.label(sl[1]))}·{_sub(sl[2] + name)}/"
                         f"{_sub(sl[2] + sl[0])}" if sl is not None else c.equation)
    return lines


def _omega_numbers(mech) -> list[int]:
    return [num for num in mech.link_numbers if num >= 2]


def _omega_texts(plans, k: int, nt) -> list[str]:
    """ω of every link but the crank at position k: its formula, value and sense."""
    pos = plans.positions
    mech = pos.mechanism
    out = []
    for num in _omega_numbers(mech):
        link = mech.link_numbers[num]
        w = float(plans.omega(link)[k])
        x, y = mech.link_joints.get(link, (None, None))
        if x is None:                                   # the block turns with the rocker, or translates
            other = next((nn for nn, ll in mech.link_numbers.items() if nn != num and nn >= 2), None)
            out.append(f"ω_{{{num}}} = ω_{{{other}}}" if other is not None else f"ω_{{{num}}} = 0")
            continue
        L = float(np.hypot(*(pos.coords[y][k] - pos.coords[x][k])))
        num_sym = f"v_{{{y}}}" if x in mech.fixed_joints else f"v_{{{_rel_name(mech, y, x)}}}"
        out.append(f"ω_{{{num}}} = {num_sym}/l_{{{link}}} = {nt.number(abs(w) * L, sig=4)}/{nt.number(L, sig=4)} = "
                   f"{nt.number(abs(w), sig=4)} {nt.unit('rad/s')}, {_sense_word(nt, w)}")
    return out


def _line_label(ln, nt) -> str:
    rel = "⊥" if ln.relation == "perpendicular" else "∥"       # ⊥: the glyph every font has
    return f"{rel} {nt.word('kinematics.guide') if ln.to == 'guide' else _sub(ln.to)}"


@dataclass(frozen=True)
class PlanLayout:
    """The millimetre constants of one plan drawn large with its column of equations and table."""

    margin_mm: float = 9.0              # round the plan: its labels and the lines beyond its points
    column_gap_mm: float = 6.0          # between the plan's share and the column beside it
    min_share: float = 0.45             # the plan's share of the sheet's width, at least ...
    max_share: float = 0.66             # ... and at most
    plan_gap_mm: float = 4.0            # the plan's area ends this far before the column
    above_mm: float = 2.0               # the plan may start this far above the sheet's top
    caption_room_mm: float = 7.0        # between the plan (or its equations) and the captions line
    column_x_mm: float = 2.0            # the column from the split, and from the sheet's top
    line_mm: float = 5.6                # between the lines of text in the column
    row_mm: float = 6.2                 # the table's rows
    after_table_mm: float = 6.0         # the angular velocities (accelerations) below the table
    head_mm: float = 3.0                # arrowheads
    pole_mm: float = 0.7


VELOCITY_PLAN_LAYOUT = PlanLayout()


def _plan_split(box, right_w: float, lay: PlanLayout) -> float:
    """Where the plan's share of the sheet ends and the column of ``right_w`` mm beside it begins (mm)."""
    x0, x1 = box[0], box[2]
    return min(max(x1 - right_w - lay.column_gap_mm, x0 + lay.min_share * (x1 - x0)), x0 + lay.max_share * (x1 - x0))


def _fit_plan(area, lo, hi, given, *, symbol: str, unit: str, k: int, nt, lay: PlanLayout) -> tuple[Scale, Frame]:
    """The scale of a plan spanning ``lo``…``hi`` drawn in ``area`` (within its margin), and its centred frame."""
    aw, ah = area[2] - area[0] - 2 * lay.margin_mm, area[3] - area[1] - 2 * lay.margin_mm
    need = max(float(hi[0] - lo[0]) / aw, float(hi[1] - lo[1]) / ah)
    if need <= 0:
        kind = "velocity" if symbol == "μ_v" else "acceleration"
        raise InputError(f"position {k}: every {kind} is zero; there is no plan to draw")
    s = _pick_plan_scale(given, need, symbol=symbol, unit=unit, what=f"the plan of position {k}", nt=nt)
    return s, _centred_frame(area, lo, hi, s)


def _velocity_lines(plans, k: int, pts: dict, f: Frame, nt) -> tuple[list[Line], list[str]]:
    """The construction lines of position k: through their point, past the point found, thin; and their labels."""
    lines, texts = [], []
    for cname, c in plans.constructions.items():
        if c.method != "intersection":
            continue
        X = np.asarray(pts[c.label])
        for ln in c.lines:
            d = np.array([ln.direction[k][0], -ln.direction[k][1]], dtype=float)
            d /= float(np.hypot(*d))
            lines.append(_through(np.asarray(f.pt(*ln.point[k])), d, X, f"line-{cname}-{ln.through}", THIN))
            texts.append(_line_label(ln, nt))
    return lines, texts


def _velocity_column(plans, k: int, lk: _Linkage, nt) -> tuple[str, list[str], list[str], tuple[str, str, str]]:
    """What the column beside the plan says: φ, the vector equations, ω of the links, the table's heading."""
    phi = f"φ = {nt.number(math.degrees(plans.positions.phi_from_start[k]), sig=5)}° ({nt.word('kinematics.phi_from')})"
    head = (nt.word("kinematics.vector"), nt.word("kinematics.length"),
            nt.quantity(nt.word("kinematics.value"), "m/s"))
    return phi, _equations(plans, k, nt, lk), _omega_texts(plans, k, nt), head


def _velocity_texts(plans, k: int, texts, vectors, pts: dict, s_v: Scale, at, x1: float, nt,
                    lay: PlanLayout) -> list[Element]:
    """The column beside the plan at ``at`` (mm): φ and the equations, the table of the vectors' drawn lengths
    and values, ω of the links, the note of an ill-conditioned position."""
    phi, eqs, omega_texts, head = texts
    tx, ty = at
    els: list[Element] = [Text((tx, ty + i * lay.line_mm), line, size_mm=TEXT_MM, name=f"equation-{i}")
                          for i, line in enumerate([phi] + eqs)]
    rows = [head]
    for v in vectors:
        L = math.dist(pts[v.start], pts[v.end])
        rows.append((_plan_markup(v.start) + _plan_markup(v.end), _num(nt, L, 2),
                     f"{v.symbol} = {_num(nt, L * s_v.per_mm, 3)}"))
    table = Table((tx, ty + (len(eqs) + 1) * lay.line_mm + 2.0), tuple(rows), align="crl", size_mm=TABLE_MM,
                  row_height_mm=lay.row_mm, name="table")
    if table.top_right[0] > x1 + 1e-6:
        raise InputError("the table of vectors does not fit beside the plan; give a larger page")
    els.append(table)
    wy = table.bottom_left[1] + lay.after_table_mm
    numbers = _omega_numbers(plans.positions.mechanism)
    els += [Text((tx, wy + i * lay.line_mm), t, size_mm=TEXT_MM, name=f"omega-{num}")
            for i, (num, t) in enumerate(zip(numbers, omega_texts))]
    if plans.ill_conditioned[k]:
        els.append(Text((tx, wy + len(omega_texts[:len(numbers)]) * lay.line_mm + 1.0),
                        nt.word("kinematics.ill_note"), size_mm=SMALL_MM, name="ill-conditioned"))
    return els


def velocity_plan(linkage, position: int | None = None, *, m: int | None = None, omega_1: float | None = None,
                  mu_v=None, notation="en", page=None, title=None, problem=None, title_block: bool = True,
                  name: str = "velocity-plan") -> Scene:
    """One velocity plan drawn large, with its construction.

    From the pole p: the known vector pa (solid, ⟂ OA, ω₁·l_OA long); each unknown image at the
    intersection of the two construction lines its vector equation prescribes (⟂ AB through a,
    ∥ guide through p, …), drawn thin and labelled; the vectors found (dashed) with arrowheads;
    centres of mass by similarity. Beside the plan: the vector equations, a table of every
    vector's drawn length and the velocity it stands for (length × μ_v), and the angular
    velocities of the links with their sense.

    Parameters
    ----------
    linkage : Case, Study, Mechanism, Positions or VelocityPlans
    position : int, optional
        The position drawn (default: the working-stroke position where the output moves fastest).
    m, omega_1, mu_v
        As for :func:`velocity_plan_grid`; μ_v is picked so the plan fills its half of the sheet.

    Raises
    ------
    InputError
        If ``position`` is not one of the positions, or a given μ_v does not fit.

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> s = velocity_plan(SliderCrank(r=0.1, l=0.4), position=1, omega_1=10.0, notation="ru")
    >>> s.title, [ln.name for ln in s.elements if ln.name.startswith("line-")]
    ('План скоростей, положение 1', ['line-B-a', 'line-B-p'])
    """
    lk, plans, pos, drawn = _plans_of(linkage, m=m, omega_1=omega_1)
    nt = get_notation(notation)
    lay = VELOCITY_PLAN_LAYOUT
    k = fullest_position(plans) if position is None else position
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or int(k) not in drawn:
        raise InputError(f"position {position!r}: give one of the positions {drawn[0]}…{drawn[-1]}")
    k = int(k)
    images, vectors = _plan_layout(plans)
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("kinematics.plan", k=_pos_label(pos, k)),
                  problem=lk.problem if problem is None else problem, title_block=title_block)
    x0, y0, x1, y1 = sheet.box
    # the column beside the plan first: its width decides how much of the sheet the plan gets
    texts = _velocity_column(plans, k, lk, nt)
    phi, eqs, omega_texts, head = texts
    probe = Table((0.0, 0.0), (head,) + tuple((_plan_markup(v.start) + _plan_markup(v.end), "000,00",
                                              f"{v.symbol} = 00,000") for v in vectors),
                  size_mm=TABLE_MM, row_height_mm=lay.row_mm)
    right_w = max([probe.width_mm] + [markup.text_width_mm(t, TEXT_MM) for t in [phi] + eqs + omega_texts])
    split = _plan_split(sheet.box, right_w, lay)
    area = (x0, sheet.top - lay.above_mm, split - lay.plan_gap_mm, sheet.caption_y - lay.caption_room_mm)
    xy = _image_xy(plans, images, k)
    arr = np.array(list(xy.values()))
    s_v, f = _fit_plan(area, arr.min(axis=0), arr.max(axis=0), mu_v, symbol="μ_v", unit="m/s", k=k, nt=nt, lay=lay)
    pts = {lb: f.pt(*v) for lb, v in xy.items()}
    occ = sheet.occ
    cons, cons_texts = _velocity_lines(plans, k, pts, f, nt)
    occ.register(*cons)
    vecs = _plan_vectors(pts, vectors, prefix="", head_mm=lay.head_mm)
    pole = Point(pts["p"], radius_mm=lay.pole_mm, name="pole")
    occ.register(*vecs, pole)
    hard = Occupancy(pad_mm=0.3)
    hard.register(*vecs)
    cons_labels = _label_lines(occ, cons, cons_texts, hard=hard, area=area)
    leaders: list = []
    names = _plan_labels(occ, pts, "p", [v.end for v in vectors if v.start == "p"], markup_of=_plan_markup,
                         size_mm=TEXT_MM + 0.3, within=(area[0], area[1] - 4, area[2], area[3] + 4), prefix="",
                         hard=hard, leaders=leaders)
    column = _velocity_texts(plans, k, texts, vectors, pts, s_v, (split + lay.column_x_mm, sheet.top + lay.column_x_mm),
                             x1, nt, lay)
    legend = f"{lk.speed_text(nt)};  {nt.word('kinematics.legend')}"
    scales = (s_v,)
    elements = [sheet.header()] + cons + vecs + [pole] + leaders + cons_labels + names + column
    elements += sheet.captions(scales, legend=legend, reserve=True)
    return sheet.scene(elements, scales, name=name, notes=(s_v.note,) if s_v.note else ())


# ----------------------------------------------------------------------------- 3. the table of velocities

@dataclass(frozen=True)
class VelocityTable:
    """The velocities per position as a table: column symbols (markup), units, rows of values.

    Attributes
    ----------
    columns : tuple of str
        Column keys: ``"position"``, ``"phi"`` (crank rotation from position 0, °), then
        ``"v_A"``, ``"v_B"``, …, relative velocities ``"v_BA"``, …, and ``"omega_2"``, ….
    symbols : tuple of str
        Their symbols in markup (``"v_{BA}"``, ``"ω_{2}"``).
    units : tuple of str
        Their units (``""`` for the position).
    labels : tuple of str
        The position labels (``"0 (12)"``, ``"1"``, …, ``"6′"`` for an extreme position between two).
    values : ndarray (rows, columns − 1)
        Everything but the position label: φ in °, velocities in m/s, angular velocities in rad/s
        (sliders signed along +x of their guide, other velocities magnitudes, ω counterclockwise +).
    ill_conditioned : ndarray (rows,) of bool
    omega_1 : float
        Crank speed, rad/s.
    """

    columns: tuple
    symbols: tuple
    units: tuple
    labels: tuple
    values: np.ndarray
    ill_conditioned: np.ndarray
    omega_1: float


def velocity_rows(linkage, *, m: int | None = None, omega_1: float | None = None,
                  extremes: bool = True) -> VelocityTable:
    """The velocities per position that :func:`velocity_table` draws (also as Markdown).

    Rows: positions 0…m−1 and, when the end of the working stroke falls between two numbered
    positions (``extremes``), that extreme position in its place (``6′``).

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> t = velocity_rows(SliderCrank(r=0.1, l=0.4), m=4, omega_1=10.0)
    >>> t.columns
    ('position', 'phi', 'v_A', 'v_B', 'v_BA', 'omega_2')
    >>> t.labels, [round(float(v), 6) for v in t.values[:, 2]]
    (('0 (4)', '1', '2', '3'), [0.0, -1.0, 0.0, 1.0])
    """
    lk, plans, pos, drawn = _plans_of(linkage, m=m, omega_1=omega_1)
    mech = pos.mechanism
    ext = _end_extreme(pos) if extremes else None
    plans_e = None
    if ext is not None and ext.same_as is None:
        plans_e = mech.velocity_plans(mech.positions(phi=[ext.phi]), omega_1=lk.omega_1)
    cols, syms, units, data = ["position", "phi"], ["", "φ"], ["", "°"], []

    def both(fn):
        a = np.asarray(fn(plans), dtype=float)[drawn]
        if plans_e is not None:
            a = np.concatenate([a, np.asarray(fn(plans_e), dtype=float)])
        return a

    data.append(both(lambda pl: np.degrees(pl.positions.phi_from_start)))
    rel = []
    for name, c in plans.constructions.items():
        if c.method == "pole":
            continue
        cols.append(f"v_{name}")
        syms.append(f"v_{{{name}}}")
        units.append("m/s")
        if name in mech.guides:
            data.append(both(lambda pl, n=name: pl.v_along_guide(n)))
        else:
            data.append(both(lambda pl, n=name: pl.speed(n)))
        if c.method == "intersection":
            for ln in c.lines:
                if ln.through != "p":
                    y = next(n for n, cc in plans.constructions.items() if cc.label == ln.through)
                    rel.append((name, y))
    for x, y in rel:
        r = _rel_name(mech, x, y)
        cols.append(f"v_{r}")
        syms.append(f"v_{{{r}}}")
        units.append("m/s")
        data.append(both(lambda pl, a=x, b=y: np.hypot(*pl.v_rel(a, b).T)))
    for num, link in mech.link_numbers.items():
        if num >= 2:
            cols.append(f"omega_{num}")
            syms.append(f"ω_{{{num}}}")
            units.append("rad/s")
            data.append(both(lambda pl, lk_=link: pl.omega(lk_)))
    labels = [_pos_label(pos, k) for k in drawn]
    ill = list(np.asarray(plans.ill_conditioned)[drawn])
    values = np.column_stack(data)
    if plans_e is not None:
        assert ext is not None                 # plans_e is made for ext only
        labels.append(ext.label)
        ill.append(bool(plans_e.ill_conditioned[0]))
        order = np.argsort(values[:, 0], kind="stable")
        values = values[order]
        labels = [labels[i] for i in order]
        ill = [ill[i] for i in order]
    values = np.where(np.abs(values) < 1e-12, 0.0, values)
    values.flags.writeable = False
    return VelocityTable(tuple(cols), tuple(syms), tuple(units), tuple(labels), values,
                         np.asarray(ill, dtype=bool), lk.omega_1)


def _table_cells(t: VelocityTable, nt, *, markup_: bool = True) -> list[list[str]]:
    head = [nt.word("kinematics.position")]
    for sym, u in zip(t.symbols[1:], t.units[1:]):
        s = sym if markup_ else markup.plain(sym) if "{" not in sym else sym.replace("{", "").replace("}", "")
        head.append(nt.quantity(s, u))
    rows = [head]
    for i, lab in enumerate(t.labels):
        row = [lab + (" *" if t.ill_conditioned[i] else "")]
        for j, u in enumerate(t.units[1:]):
            row.append(_num(nt, t.values[i, j], 2 if u == "°" else 3))
        rows.append(row)
    return rows


def velocity_table(linkage, *, m: int | None = None, omega_1: float | None = None, notation="en", page=None,
                   title=None, problem=None, title_block: bool = True, name: str = "velocity-table") -> Scene:
    """The table of velocities per position, drawn (the same rows as :func:`velocity_table_markdown`).

    Columns: position, φ from position 0, the velocity of every point (m/s; sliders signed along
    +x of their guide), the relative velocities of the constructions (v_BA, …) and the angular
    velocities of the links (rad/s, counterclockwise +), at the problem's mean crank speed.
    Ill-conditioned positions are starred and explained under the table.

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> s = velocity_table(SliderCrank(r=0.1, l=0.4), m=6, omega_1=10.0, notation="zh")
    >>> s.element("table").rows[0][:3]
    ('位置', 'φ/(°)', 'v_{A}/(m/s)')
    """
    lk = _Linkage.of(linkage, m=m, omega_1=omega_1)
    nt = get_notation(notation)
    t = velocity_rows(lk.plans, omega_1=None)
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("kinematics.table"),
                   problem=lk.problem if problem is None else problem, title_block=title_block)
    x0, y0, x1, y1 = sheet.box
    rows = tuple(tuple(r) for r in _table_cells(t, nt))
    notes = [lk.speed_text(nt), nt.word("kinematics.signed")]
    if t.ill_conditioned.any():
        notes.append("* " + nt.word("kinematics.ill_note"))
    avail = (sheet.caption_y - 6.0 * len(notes) - 4.0) - (sheet.top + 2.0)
    row_h = min(7.0, avail / len(rows))
    size = min(TABLE_MM, row_h * 0.5)
    if row_h < 4.0:
        raise InputError(f"{len(rows) - 1} positions do not fit on this sheet (rows would be {row_h:.1f} mm); "
                         f"give fewer positions or a larger page")
    probe = Table((0.0, 0.0), rows, align="c" + "r" * (len(rows[0]) - 1), size_mm=size, row_height_mm=row_h)
    if probe.width_mm > x1 - x0:
        raise InputError(f"the table is {probe.width_mm:.0f} mm wide but the sheet leaves {x1 - x0:.0f} mm; "
                         f"give a larger page")
    at = ((x0 + x1) / 2 - probe.width_mm / 2, sheet.top + 2.0)
    table = Table(at, rows, align="c" + "r" * (len(rows[0]) - 1), size_mm=size, row_height_mm=row_h,
                  name="table")
    below = table.bottom_left[1] + 6.0
    texts = [Text((at[0], below + i * 6.0), n_, size_mm=TEXT_MM, name=f"note-{i}") for i, n_ in enumerate(notes)]
    return sheet.scene([sheet.header(), table] + texts, (), name=name)


def velocity_table_markdown(linkage, *, m: int | None = None, omega_1: float | None = None, notation="en") -> str:
    """The table of velocities per position as Markdown (the rows :func:`velocity_table` draws).

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> print(velocity_table_markdown(SliderCrank(r=0.1, l=0.4), m=4, omega_1=10.0).splitlines()[0])
    | Position | φ, ° | v_A, m/s | v_B, m/s | v_BA, m/s | ω_2, rad/s |
    """
    lk = _Linkage.of(linkage, m=m, omega_1=omega_1)
    nt = get_notation(notation)
    t = velocity_rows(lk.plans, omega_1=None)
    rows = _table_cells(t, nt, markup_=False)
    out = ["| " + " | ".join(rows[0]) + " |", "|" + "|".join(":---:" if j == 0 else "---:" for j in
                                                            range(len(rows[0]))) + "|"]
    out += ["| " + " | ".join(r) + " |" for r in rows[1:]]
    out += ["", lk.speed_text(nt).replace("_1", "₁"), nt.word("kinematics.signed")]
    if t.ill_conditioned.any():
        out.append("* " + nt.word("kinematics.ill_note"))
    return "\n".join(out) + "\n"
