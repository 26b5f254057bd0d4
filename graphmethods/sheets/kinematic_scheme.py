"""The kinematic scheme (кинематическая схема, 机构运动简图): the linkage in m positions on one drawing to μ_l.

The textbook symbols (hatched ground under fixed pivots, pin joints, slider blocks on hatched guides),
one position drawn thick and the others thin, the position numbers 0…m at the crank pin and at the
output point, the extreme positions marked, the stroke dimensioned. See :func:`kinematic_scheme`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, cast

import numpy as np

from graphmethods.errors import AssemblyError, InputError
from graphmethods.scene import Frame, Line, Point, Polyline, Scale, Scene, Text, notation as get_notation
from graphmethods.scene.elements import Dimension, Element, Group, label_bbox
from graphmethods.scene.primitives import THIN, Label
from graphmethods.sheets.kinematic_symbols import FixedPivot, Guide, PinJoint, RotationArrow, SliderBlock
from graphmethods.sheets.layout import TEXT_MM, Occupancy, Sheet
from graphmethods.sheets.linkage_figures import (
    _COMPASS,
    EXTREME,
    SMALL_MM,
    THICK,
    TRAJECTORY,
    _dirs,
    _drawn,
    _end_extreme,
    _Extreme,
    _Linkage,
    _paper_deg,
    _place,
    _pos_label,
    _sub,
    broken_behind,
)
from graphmethods.sheets.plates import Plate, body_outline, link_bodies
from graphmethods.sheets.scheme_slide import SLIDE_FACTS_GAP_MM, overlaps, positions_table, slide_facts
from graphmethods.units import convenient_at_least

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
    bodies: tuple[tuple[str, ...], ...] = ()  # each link's joints as drawn: a line, or a plate (ternary link)


def _translating_yokes(mech) -> list:
    """The RPP groups of a linkage whose yoke slides on the frame (a sine mechanism, a Scotch yoke)."""
    from graphmethods.kinematics.groups import RPP

    lk = getattr(mech, "linkage", None)
    return [g for g in getattr(lk, "groups", ()) if isinstance(g, RPP) and g.guide.link == "0"]


def _parts(mech, pos) -> _Parts:
    fixed = tuple(mech.fixed_joints)
    links = tuple(mech.link_joints.values())
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
    bodies = tuple(link_bodies(mech).values())
    return _Parts(fixed, links, sliders, block, output, centre, pin, extra, tuple(moving) + extra, tuple(coincident),
                  bodies)


@dataclass(frozen=True)
class SchemeLayout:
    """The kinematic scheme's millimetre constants (paper mm)."""

    pad_x_mm: float = 10.0              # beside the linkage
    pad_top_mm: float = 10.0            # above it
    pad_bottom_mm: float = 14.0         # below it: the stroke's dimension
    pad_steep_mm: float = 4.0           # above and below when the output's guide is steep (H dimensioned beside it)
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
    #: a name goes at most this far beyond its last gap (with a leader); where nothing is free that near, it
    #: stands beside its point and the thin lines under it are broken (O₁ of the six-bar press was named 40 mm off)
    names_ring_mm: float = 7.5
    stroke_offset_mm: float = 4.0       # the dimension H beyond the numbers
    summary_above_mm: float = 6.5       # the line of facts above the captions


SCHEME_LAYOUT = SchemeLayout()
#: the hatching of a ternary link's plate in the thick position (mm between lines: sparse, as the books hatch)
PLATE_HATCH_MM = 3.5


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
        if pos.m is not None and getattr(getattr(mech, "linkage", None), "swing", None) is None:   # a full turn
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


def _crank_path_angles(g: _SchemeGeometry) -> np.ndarray | None:
    """The angles (rad, 61 of them) of a swinging driver's arc: from its first position to its last, the way
    it swings (a lever or rocker given ``range_deg``); None for a crank that turns fully (its circle)."""
    if getattr(getattr(g.mech, "linkage", None), "swing", None) is None:
        return None
    d = g.pos.coords[g.parts.pin] - g.c_xy
    ang = np.unwrap(np.arctan2(d[:, 1], d[:, 0]))
    return np.linspace(float(ang.min()), float(ang.max()), 61)


def _vertical_pads(g: _SchemeGeometry, lay: SchemeLayout) -> tuple[float, float]:
    """The room (mm) above and below the linkage: for the stroke's dimension under or over a level guide; a
    steep guide (slotting machine) has its dimension beside it and needs less."""
    guide = g.parts.sliders.get(g.parts.output)
    if guide is not None and abs(float(guide[1])) > abs(float(guide[0])):
        return lay.pad_steep_mm, lay.pad_steep_mm
    return lay.pad_top_mm, lay.pad_bottom_mm


def _scheme_scale(g: _SchemeGeometry, sheet: Sheet, mu_l, unit_l: str, lay: SchemeLayout,
                  right: float | None = None) -> tuple[Scale, Frame]:
    """Step 2: μ_l (given, checked, or picked to fill the sheet left of ``right``) and the frame centring the
    drawing."""
    x0, _, x1, _ = sheet.box
    x1 = x1 if right is None else right

    def coords(p, names, idx=None):
        return [p.coords[j] if idx is None else p.coords[j][idx] for j in names]

    joints = list(g.mech.joints) + list(g.parts.extra)
    pts = coords(g.pos, joints, g.drawn)
    if g.ext_pos is not None:
        pts += coords(g.ext_pos, joints)
    if g.fine is not None:
        pts += coords(g.fine, g.parts.paths)
    t = _crank_path_angles(g)
    pts.append(np.array([g.c_xy - g.r, g.c_xy + g.r]) if t is None
               else g.c_xy + g.r * np.column_stack((np.cos(t), np.sin(t))))
    allp = np.concatenate([np.asarray(p).reshape(-1, 2) for p in pts])
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    area = (x0, sheet.top, x1, sheet.caption_y - lay.caption_room_mm)
    avail_w = area[2] - area[0] - 2 * lay.pad_x_mm
    pad_top, pad_bottom = _vertical_pads(g, lay)
    avail_h = area[3] - area[1] - pad_top - pad_bottom
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
    cy = (area[1] + pad_top + area[3] - pad_bottom) / 2 + s_l.to_mm(float(lo[1] + hi[1]) / 2)
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
    t = _crank_path_angles(g)
    full = t is None
    t = np.linspace(0.0, 2.0 * math.pi, 181) if t is None else t
    thin_els.append(Polyline(f.pts(g.c_xy[0] + g.r * np.cos(t), g.c_xy[1] + g.r * np.sin(t)), style=THIN,
                             closed=full, name="crank-circle" if full else "crank-arc"))
    link_segments: list = []

    plated = {j for body in g.parts.bodies if len(body) > 2 for j in body}

    def link_lines(p, idx, style, tag) -> list[Element]:
        out: list[Element] = []
        for body in g.parts.bodies:
            corners = body_outline([P(p.coords[j][idx]) for j in body])
            if len(corners) > 2:           # a ternary link: a plate, hatched in the thick position
                thick = style is THICK      # one clean body over the thin positions, sparsely hatched
                out.append(Plate(corners, outline_style=style, hatch=thick, fill="white" if thick else None,
                                 hatch_spacing_mm=PLATE_HATCH_MM, name=f"{tag}-{''.join(body)}"))
            else:
                out.append(Line(corners[0], corners[1], style=style, name=f"{tag}-{''.join(body)}"))
            ring = corners + corners[:1] if len(corners) > 2 else corners
            link_segments.extend(("", "", A, B) for A, B in zip(ring, ring[1:]))
        for j in g.parts.extra:            # a point off its link line: the link drawn as a triangle
            spec = next(q for q in g.mech.points if q.name == j)
            x, y, _, _ = g.mech._resolve_link(spec.link)
            if spec.angle != 0.0 and not {x, y} <= plated:
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
    """What a label must never cover (thick links, blocks, supports and guides: returned), and the joints and
    blocks kept free."""
    hard = Occupancy(pad_mm=lay.hard_pad_mm)
    hard.register(*thick_els, *[e for e in top_els if isinstance(e, SliderBlock)],
                  *[e for e in symbol_els if isinstance(e, (FixedPivot, Guide))])     # supports, hatched guides
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
                    lay: SchemeLayout, leaders: list) -> tuple[list[Text], list[Element]]:
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
            toward = _free_normal_deg(guide)
            dirs = tuple(d for d in _dirs(toward) if abs((_COMPASS[d] - toward + 180.0) % 360.0 - 180.0) <= 50.0)
            numbers = _output_numbers(out_items, P, occ, sheet.box, side=dirs[0], dirs=dirs, prefer=toward,
                                      leaders=leaders)
        else:
            numbers = _output_numbers(out_items, P, occ, sheet.box, side=out_side, leaders=leaders)
    else:
        pivot = next(x for x, y in parts.links if y == parts.output and x in parts.fixed)
        numbers = _output_numbers(out_items, P, occ, sheet.box, side=None, pivot=np.asarray(P(pos.coords[pivot][0])),
                                  leaders=leaders)
    dims: list[Element] = []
    if guide is not None and pos.H is not None and g.ext is not None:
        end_xy = g.ext_pos.coords[parts.output][0] if g.ext_pos is not None else pos.coords[parts.output][g.ext.same_as]
        text = nt.word("kinematics.stroke", H=nt.number(pos.H * 1000.0, sig=4), u=nt.unit("mm"))   # a dimension: mm
        dim = _clear_dimension(_stroke_dimension(P(pos.coords[parts.output][0]), P(end_xy), numbers, text, free,
                                                 out_side, lay), occ, sheet.box)
        dims.append(dim)
        occ.register(dim)
    numbers += _crank_numbers(_numbered(pos, parts, g.drawn, g.ext, g.ext_pos, parts.pin), P(g.c_xy), P, occ,
                              sheet.box, leaders)
    return numbers, dims


def _clear_dimension(dim: Dimension, occ: Occupancy, box) -> Dimension:
    """The dimension moved further out (its offset grown in 2 mm steps, up to 60 mm) until its value is free
    of every line and label drawn; as it was when it nowhere is."""
    from dataclasses import replace

    from graphmethods.scene.elements import label_bbox

    for extra in np.arange(0.0, 60.0, 2.0):
        trial = replace(dim, offset_mm=dim.offset_mm + float(extra))
        if all(occ.is_free(label_bbox(p), within=box) for p in trial.primitives() if isinstance(p, Label)):
            return trial
    return dim


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


def _free_normal_deg(guide: Guide) -> float:
    """The direction (deg on paper, counterclockwise from right) away from a guide's hatched surface."""
    gs, ge = np.asarray(guide.start, float), np.asarray(guide.end, float)
    ug = (ge - gs) / float(np.hypot(*(ge - gs)))
    free = -guide.side * np.array([ug[1], -ug[0]])
    return math.degrees(math.atan2(-free[1], free[0]))


def _scheme_names(g: _SchemeGeometry, P, occ: Occupancy, box, hard: Occupancy, lay: SchemeLayout,
                  leaders: list, guides: dict | None = None) -> list[Text]:
    """Step 7: the names of the joints of the thick position (position 0 when all are thin), away from the middle;
    a slider's on the free side of its guide (``guides``: the Guide of each slider joint)."""
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
        arc = 180.0
        guide = (guides or {}).get(f"guide-{j}")
        if guide is not None:                   # never across the guide's hatching
            prefer, arc = _free_normal_deg(guide), 90.0
        labels.append(_place(occ, at, _sub(j), prefer, size_mm=TEXT_MM + 0.3, within=box, name=f"name-{j}",
                             gaps=lay.names_gaps_mm, hard=hard, leaders=leaders, ring=True,
                             ring_mm=lay.names_ring_mm, ring_arc_deg=arc))
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
                     name: str = "kinematic-scheme", positions: bool = True) -> Scene:
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
    positions : bool
        On a slide, the table of the output's positions beside a linkage that leaves the room
        (:func:`graphmethods.sheets.scheme_slide.positions_table`); none when a value of the drawing would
        run into it.

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
    facts = _scheme_facts(g.pos, g.ext, nt)
    facts_column = slide_facts(facts + _link_lengths(g, nt), sheet, page,        # a slide's column right of the
                               caption_room_mm=lay.caption_room_mm)               # drawing
    table, (s_l, f) = positions_table(
        g.pos if positions else None, nt, sheet, page, min((e.at[0] - SLIDE_FACTS_GAP_MM for e in facts_column),
                                                         default=None),
        caption_room_mm=lay.caption_room_mm, scale_at=lambda right: _scheme_scale(g, sheet, mu_l, nt.unit("m"), lay,
                                                                                  right=right))
    column: list[Element] = [*facts_column, *table]

    def P(xy) -> tuple[float, float]:
        return f.pt(xy[0], xy[1])

    occ = sheet.occ
    occ.register(*column)
    thin_els, thick_els, link_segments = _scheme_links(g, f)
    occ.register(*thin_els, *thick_els)
    symbol_els = _scheme_grounds(g, P, link_segments, lay)
    occ.register(*symbol_els)
    top_els, marks = _scheme_joints(g, P, lay)
    occ.register(*top_els, *marks)
    hard = _scheme_keep_clear(occ, thick_els, top_els, symbol_els, lay)
    rot, rot_label = _rotation_arrow(P(g.c_xy), s_l.to_mm(g.r), g.mech.sense, occ, link_segments,
                                     [e for e in symbol_els if isinstance(e, FixedPivot)])
    occ.register(rot)
    leaders: list[Element] = []            # from labels that found no free place beside their point
    numbers, dims = _scheme_numbers(g, P, occ, sheet, symbol_els, nt, lay, leaders)
    hard.register(*leaders)                 # a name set across thin lines (broken behind it) never on a leader
    guides = {e.name: e for e in symbol_els if isinstance(e, Guide)}
    labels = _scheme_names(g, P, occ, sheet.box, hard, lay, leaders, guides) + [rot_label(occ, leaders)]
    values = [label_bbox(p) for e in dims + labels for p in e.primitives() if isinstance(p, Label)]
    if table and any(overlaps(table[0], e) for e in dims + labels + numbers):       # the stroke's value ran into it
        return kinematic_scheme(linkage, m=m, mu_l=mu_l, thick=thick, trajectories=trajectories, notation=notation,
                                page=page, title=title, problem=problem, title_block=title_block, name=name,
                                positions=False)
    thin_els = _broken_lines(thin_els, values)
    summary = column or ([Text((sheet.box[0], sheet.caption_y - lay.summary_above_mm), ";   ".join(facts),
                               size_mm=TEXT_MM, name="summary")] if facts else [])
    legend = lk.speed_text(nt) if lk.n_rpm is not None else ""
    scales = (s_l,)
    elements = ([sheet.header()] + thin_els + symbol_els + dims + thick_els + top_els + marks + [rot] + leaders
                + labels + numbers + summary)
    elements += sheet.captions(scales, legend=legend, reserve=True)
    return sheet.scene(elements, scales, name=name, notes=(s_l.note,) if s_l.note else ())


def _link_lengths(g: _SchemeGeometry, nt) -> list[str]:
    """The lengths the scheme is drawn from, one per link between two joints (l_{O1A} = 0.11 m), in the
    notation's numbers."""
    c = g.pos.coords
    return [f"l_{{{name}}} = {nt.number(float(np.hypot(*(c[a][0] - c[b][0]))), sig=4)} {nt.unit('m')}"
            for name, (a, b) in g.mech.link_joints.items()]


def _broken_lines(els: list[Element], boxes: list) -> list[Element]:
    """The thin lines and paths broken behind the boxes of values and names that found no clear place (ГОСТ
    2.303): a line that is broken becomes a group of its pieces under its own name (one link, one element)."""
    out: list[Element] = []
    for e in els:
        line: Element = e
        if isinstance(e, Plate) and not e.hatch and e.fill is None:     # a thin position's plate: its outline
            line = Polyline(tuple(e.corners) + tuple(e.corners[:1]), style=e.outline_style, name=e.name)
        pieces = broken_behind([line], boxes) if isinstance(line, (Line, Polyline)) else [line]
        out.append(e if len(pieces) == 1 and pieces[0] is line else Group(elements=tuple(pieces), name=e.name))
    return out


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


#: what running through a support costs the ω₁ arrow, in crossed lines (it never does while another place is left)
SUPPORT_PENALTY = 1000


def _rotation_arrow(centre, r_mm: float, sense: int, occ: Occupancy, segments, grounds: Sequence[FixedPivot] = ()):
    """The ω₁ arc arrow inside the crank circle where it crosses fewest lines, never through a pivot's support
    (``grounds``: its legs and hatching), and a labeller for it."""
    from shapely import Polygon, intersects, linestrings

    radius = float(min(max(0.45 * r_mm, 5.0), 9.0))
    sweep = 70.0 * sense
    lines = linestrings(np.array([[A, B] for _, _, A, B in segments], dtype=float)) if segments else None
    supports = [Polygon(gr.outline()) for gr in grounds]
    best: tuple[int, RotationArrow] | None = None
    for mid in np.arange(135.0, 135.0 + 360.0, 15.0):
        arr = RotationArrow(centre, radius, float(mid - sweep / 2), sweep, name="omega-1")
        if lines is None and not supports:
            best = (0, arr)
            break
        arc = linestrings(np.array(arr.arc_points()))
        hits = (int(intersects(arc, lines).sum()) if lines is not None else 0) + \
            SUPPORT_PENALTY * sum(bool(intersects(arc, sp)) for sp in supports)
        if best is None or hits < best[0]:
            best = (hits, arr)
    assert best is not None                    # the loop runs at least once
    arr = best[1]

    def label(occ_, leaders):
        mid = math.radians(arr.start_deg + arr.sweep_deg / 2)
        at = (centre[0] + radius * math.cos(mid), centre[1] - radius * math.sin(mid))
        return _place(occ_, at, "ω_1", math.degrees(mid), size_mm=TEXT_MM + 0.3, name="name-omega-1", leaders=leaders,
                      ring=True,
                      gaps=(1.0, 2.2, 3.5))

    return arr, label


def _numbered(pos, parts, drawn, ext, ext_pos, j):
    """(tag, text, xy) of point ``j`` in every drawn position and the extra extreme position."""
    items = [(_tag(k), _pos_label(pos, k), pos.coords[j][k]) for k in drawn]
    if ext is not None and ext_pos is not None:
        items.append(("extreme", ext.label, ext_pos.coords[j][0]))
    return items


def _crank_numbers(items, centre, P, occ, box, leaders: list) -> list:
    """The position numbers at the crank pin, outside the crank circle."""
    out = []
    c = np.asarray(centre)
    for tag, text, xy in items:
        a = np.asarray(P(xy))
        radial = math.degrees(math.atan2(-(a - c)[1], (a - c)[0]))
        dirs = [d for d in _dirs(radial) if abs((_COMPASS[d] - radial + 180.0) % 360.0 - 180.0) <= 70.0]
        out.append(_place(occ, tuple(a), text, radial, size_mm=SMALL_MM, within=box, name=f"number-A-{tag}",
                          leaders=leaders, ring=True,
                          gaps=(1.0, 2.4, 4.0), dirs=dirs))
    return out


#: a slider's position number goes at most this far (deg) from the normal of its guide on the free side:
#: never across the guide's hatching (a leader through the hatching reads as a number of the frame)
SLIDER_NUMBER_ARC_DEG = 75.0


def _output_numbers(items, P, occ, box, *, side: str | None, pivot=None, dirs=None, prefer=None,
                    leaders: list | None = None) -> list:
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
            out.append(_place(occ, tuple(o), text, toward, size_mm=SMALL_MM, within=box, leaders=leaders, ring=True,
                              dirs=dirs or (side, side + "e", side + "w"), gaps=(1.5, 3.1, 4.7, 6.3),
                              name=f"number-out-{tag}", ring_arc_deg=SLIDER_NUMBER_ARC_DEG))
            continue
        prefer = math.degrees(math.atan2(-(o - pivot)[1], (o - pivot)[0]))
        out.append(_place(occ, tuple(o), text, prefer, size_mm=SMALL_MM, within=box, name=f"number-out-{tag}",
                          leaders=leaders, ring=True,
                          gaps=(1.0, 2.4, 4.0, 6.0)))
    return out


def _tag(k: int) -> str:
    return "extreme" if k < 0 else str(k)
