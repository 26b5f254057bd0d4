"""What every linkage figure shares: the linkage asked for (a problem, a study, a mechanism, its positions or
plans), label placement on a scheme or a plan, and the steps of drawing a plan (its vectors, labels, scale,
construction lines). The figures are :mod:`~graphmethods.sheets.kinematic_scheme`,
:mod:`~graphmethods.sheets.velocity_plans`, :mod:`~graphmethods.sheets.velocity_table` and
:mod:`~graphmethods.sheets.acceleration`; :mod:`~graphmethods.sheets.kinematics` gathers them."""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.problems.reference_cases import title_of
from graphmethods.scene import Element, Frame, Line, Polyline, Scale, Text, Vector
from graphmethods.scene.primitives import THIN, Style
from graphmethods.sheets.layout import Occupancy
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
           leaders: list | None = None, ring: bool = False, ring_mm: float = math.inf,
           ring_arc_deg: float = 180.0) -> Text:
    """A label beside ``at``, in the free direction nearest ``prefer_deg`` (registered as taken).

    Free of lines and labels if possible; with ``ring`` (and ``leaders`` to collect them) further out in
    any direction within ``ring_arc_deg`` of ``prefer_deg`` (a slider's numbers: on the free side of its
    guide, never across the hatching), nearest first, at most ``ring_mm`` beyond the last gap, with a
    leader back to ``at``;
    else free of labels and of the ``hard`` lines (crossing a thin line, which the caller breaks behind
    it: :func:`broken_behind`); else the preferred spot.
    """
    from graphmethods.scene.elements import label_bbox, place_label

    dirs = tuple(dirs) if dirs else _dirs(prefer_deg)
    lab = (_first_clear(occ, hard, at, text, dirs, gaps, size_mm, within, None if ring else leaders, name)
           if avoid_lines else None)
    if lab is None and ring and leaders is not None:
        lab = _ring_clear(occ, hard, at, text, prefer_deg, gaps[-1], size_mm, within, ring_mm, arc_deg=ring_arc_deg)
        if lab is not None:
            _leader(occ, at, lab, leaders, name, start_mm=RING_START_MM)
    for gap in (gaps if lab is None else ()):     # crowded: near the point across a thin line
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
            if leaders is not None:
                ok &= np.array([_leader_clear(occ, at, c) for c in cands], dtype=bool)
            if ok.any():
                lab = cands[int(np.argmax(ok))]
                _leader(occ, at, lab, leaders, name)
                break
    if lab is None:
        lab = place_label(at, text, dirs[0], gap_mm=gaps[0], size_mm=size_mm)
    occ.add_label(lab)
    return Text((lab.x, lab.y), text, size_mm=size_mm, anchor=lab.anchor, name=name)


def _first_clear(occ: Occupancy, hard: Occupancy | None, at, text: str, dirs, gaps, size_mm: float, within,
                 leaders: list | None, name: str):
    """The first place free of every line and label: beside the point (the directions at each gap), then
    further out with a leader line back to it (when ``leaders`` collects them); None when there is none."""
    from graphmethods.scene.elements import label_bbox, place_label

    far = tuple(gaps[-1] + r for r in (2.5, 5.0, 8.0, 12.0, 17.0)) if leaders is not None else ()
    for gap in (*gaps, *far):
        cands = [place_label(at, text, d, gap_mm=gap, size_mm=size_mm) for d in dirs]
        ok = _free_of(occ, hard, [label_bbox(c) for c in cands], within=within, lines=True)
        if gap > gaps[-1]:                      # a leader must not cross a label placed before
            ok &= np.array([_leader_clear(occ, at, c) for c in cands], dtype=bool)
        if not ok.any():
            continue
        lab = cands[int(np.argmax(ok))]
        if gap > gaps[-1]:
            _leader(occ, at, lab, leaders, name)
        return lab
    return None


#: how far out (mm beyond the last gap) :func:`_ring_clear` looks for a free place, and at which angles (deg)
RING_MM = (1.5, 3.0, 5.0, 7.5, 10.5, 14.0, 18.0, 23.0, 30.0)
RING_STEP_DEG = 15
#: a ring label's leader starts this far from its point (clear of a joint's circle and the box kept round it)
RING_START_MM = 2.0


def _ring_clear(occ: Occupancy, hard: Occupancy | None, at, text: str, prefer_deg: float, gap: float,
                size_mm: float, within, reach_mm: float = math.inf, *, arc_deg: float = 180.0):
    """The nearest place on rings around ``at`` (every :data:`RING_STEP_DEG` within ``arc_deg`` of
    ``prefer_deg``, out to :data:`RING_MM` beyond ``gap`` but no further than ``reach_mm``, the angle
    nearest ``prefer_deg`` first) free of every line and label, whose leader crosses no label; None when
    there is none (deterministic: a fixed order, the first free wins)."""
    from graphmethods.scene.elements import label_bbox, place_label

    def off(a: float) -> float:
        return abs((a - prefer_deg + 180.0) % 360.0 - 180.0)

    angles = sorted((a for a in range(0, 360, RING_STEP_DEG) if off(a) <= arc_deg + 1e-9), key=lambda a: (off(a), a))
    x, y = at
    for extra in (e for e in RING_MM if e <= reach_mm):
        r = gap + extra
        for ang in angles:
            c, s = math.cos(math.radians(ang)), math.sin(math.radians(ang))
            end = (x + r * c, y - r * s)
            d = "e" if c > 0.38 else "w" if c < -0.38 else ("n" if s > 0 else "s")
            lab = place_label(end, text, d, gap_mm=0.3, size_mm=size_mm)
            b = label_bbox(lab)
            if not occ.is_free(b, within=within) or (hard is not None and not hard.is_free(b)):
                continue
            near = np.array([min(max(x, b[0]), b[2]), min(max(y, b[1]), b[3])])
            dd = near - np.asarray(at, dtype=float)
            L = float(np.hypot(*dd))
            if L <= RING_START_MM + 0.5 or not _leader_blocked(occ, at, np.asarray(at) + dd / L * RING_START_MM, near):
                return lab
    return None


#: a line stops this far (mm) short of a label it would cross
BREAK_MM = 0.4


#: the last boxes :func:`broken_behind` was given and their union (grown by :data:`BREAK_MM`): a figure breaks
#: its lines one by one behind the same boxes
_LAST_COVER: list[Any] = [None, None]


def _cover(boxes: list) -> Any:
    """The union of the ``boxes`` (mm) grown by :data:`BREAK_MM`, as a shapely geometry (the last one kept)."""
    import shapely
    from shapely.geometry import box

    key = tuple(tuple(float(v) for v in b) for b in boxes)
    if _LAST_COVER[0] != key:
        _LAST_COVER[:] = [key, shapely.union_all([box(b[0] - BREAK_MM, b[1] - BREAK_MM, b[2] + BREAK_MM,
                                                      b[3] + BREAK_MM) for b in key])]
    return _LAST_COVER[1]


def broken_behind(lines: list, boxes: list) -> list:
    """Lines interrupted where they would cross the boxes of labels (mm): a line is broken for an
    inscription (ГОСТ 2.303, 2.307) when no place clear of it is left. Each line that crosses a box
    becomes the pieces of it outside the boxes grown by :data:`BREAK_MM` (named ``name``, ``name-1``, ...);
    the others are returned as they are.

    >>> [(e.start, e.end) for e in broken_behind([Line((0, 0), (10, 0), name="l")], [(4, -1, 6, 1)])]
    [((0.0, 0.0), (3.6, 0.0)), ((6.4, 0.0), (10.0, 0.0))]

    A polyline (a crank circle, a dotted path) is broken the same way into open polylines:

    >>> [e.points for e in broken_behind([Polyline(((0, 0), (10, 0), (10, 10)), name="p")], [(4, -1, 6, 1)])]
    [((0.0, 0.0), (3.6, 0.0)), ((6.4, 0.0), (10.0, 0.0), (10.0, 10.0))]
    """
    import shapely
    from shapely.geometry import LineString

    if not boxes:
        return list(lines)
    cover = _cover(boxes)
    out: list = []
    for ln in lines:
        if isinstance(ln, Polyline):
            pts = list(ln.points) + (list(ln.points[:1]) if ln.closed else [])
            seg = LineString(pts)
        else:
            seg = LineString([ln.start, ln.end])
        if not seg.intersects(cover):
            out.append(ln)
            continue
        parts = [q for q in shapely.get_parts(shapely.line_merge(seg.difference(cover))) if q.length > 1e-6]
        for k, q in enumerate(parts):
            nm = ln.name if k == 0 else f"{ln.name}-{k}"
            if isinstance(ln, Polyline):
                out.append(replace(ln, points=tuple((float(x), float(y)) for x, y in q.coords), closed=False, name=nm))
                continue
            (x0, y0), (x1, y1) = q.coords[0], q.coords[-1]
            out.append(Line((float(x0), float(y0)), (float(x1), float(y1)), style=ln.style, name=nm))
    return out


def _leader_blocked(occ: Occupancy, at, p, q) -> bool:
    """Does a leader p–q to the point ``at`` cross a label or a box kept clear, other than the boxes round
    ``at`` itself (a joint's, a block's)?"""
    from graphmethods.sheets.layout import segments_hit_boxes

    b = occ.box_array()
    if not len(b):
        return False
    x, y = at
    b = b[~((b[:, 0] <= x) & (x <= b[:, 2]) & (b[:, 1] <= y) & (y <= b[:, 3]))]
    seg = np.array([[p[0], p[1], q[0], q[1]]], dtype=float)
    return bool(len(b)) and bool(segments_hit_boxes(seg, b).any())


def _leader_ends(at, lab, start_mm: float = 0.9) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """The leader from ``start_mm`` off ``at`` to the nearest point of the label's box (None when the label
    is within max(1.5, start_mm + 0.5) mm)."""
    from graphmethods.scene.elements import label_bbox

    b = label_bbox(lab)
    near = (min(max(at[0], b[0]), b[2]), min(max(at[1], b[1]), b[3]))
    dd = np.asarray(near) - np.asarray(at)
    L = float(np.hypot(*dd))
    if L <= max(1.5, start_mm + 0.5):
        return None
    return tuple((np.asarray(at) + dd / L * start_mm).tolist()), near


def _leader_clear(occ: Occupancy, at, lab) -> bool:
    """Does the leader a label far from ``at`` would need cross no label already placed?"""
    ends = _leader_ends(at, lab)
    return ends is None or not occ._line_blocked(*ends)


def _leader(occ: Occupancy, at, lab, leaders: list | None, name: str, *, start_mm: float = 0.9) -> None:
    """A thin leader from near ``at`` to the nearest point of the label's box, collected in ``leaders`` and
    registered (when ``leaders`` collects them and the label is more than 1.5 mm away)."""
    ends = None if leaders is None else _leader_ends(at, lab, start_mm)
    if leaders is not None and ends is not None:
        leaders.append(Line(ends[0], ends[1], style=THIN, name=f"leader-{name}"))
        occ.add_line(ends)


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
                          name=f"{prefix}name-{id_of(g[0][0])}", gaps=(0.8, 1.8, 3.0, 4.5), leaders=leaders,
                          ring=leaders is not None))
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


def _label_lines(occ: Occupancy, lines: list[Line], texts: list[str], *, hard: Occupancy, area) -> list[Element]:
    """Each construction line's label (⊥ AB, ∥ guide) at its far end, across it (or beside the line; in a
    crowd further out with a leader line)."""
    out: list[Element] = []
    within = (area[0], area[1] - 4, area[2] + 4, area[3] + 4)
    for el, text in zip(lines, texts):
        d = np.asarray(el.end) - np.asarray(el.start)
        prefer = math.degrees(math.atan2(-d[1], d[0])) + 90.0
        a, b = np.asarray(el.start, dtype=float), np.asarray(el.end, dtype=float)
        tries = [(end, gaps) for gaps in ((0.6, 1.6, 3.0), (4.5, 6.5)) for end in (el.end, el.start)]
        tries += [(tuple((a + t * (b - a)).tolist()), (0.6, 1.6)) for t in (0.8, 0.2, 0.65, 0.35)]
        for end, gaps in tries:                 # a free place at either end (near, then farther), then beside
            # the line, before crossing one
            lab = _first_clear(occ, hard, end, text, _dirs(prefer), gaps, SMALL_MM, within, None, "")
            if lab is not None:
                occ.add_label(lab)
                out.append(Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, name=f"label-{el.name}"))
                break
        else:                                   # crowded: further out with a leader to the line's end
            leaders: list[Element] = []
            out.append(_place(occ, el.end, text, prefer, size_mm=SMALL_MM, hard=hard, within=within,
                              name=f"label-{el.name}", gaps=(0.6, 1.6, 3.0), ring=True, leaders=leaders))
            out += leaders
    return out
