"""Velocity plans (планы скоростей, 速度多边形): every position's small plan at one μ_v, or one large plan.

:func:`velocity_plan_grid` draws the plans of all positions on one sheet (ill-conditioned positions
marked); :func:`velocity_plan` one large plan with its construction lines, a table of drawn lengths
and values and the vector equations.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import Frame, Line, Point, Polyline, Scale, Scene, Table, Text, markup, notation as get_notation
from graphmethods.scene.elements import Element
from graphmethods.scene.markup import MIN_TEXT_MM
from graphmethods.scene.numbers import within_roundoff
from graphmethods.scene.primitives import THIN, Style
from graphmethods.sheets.layout import TEXT_MM, Occupancy, Sheet
from graphmethods.sheets.linkage_figures import (
    CELL_ILL,
    SMALL_MM,
    TABLE_MM,
    _centred_frame,
    _drawn,
    _image_xy,
    _label_lines,
    _Linkage,
    _num,
    _pick_mu_v,
    _pick_plan_scale,
    _plan_labels,
    _plan_layout,
    _plan_markup,
    _plan_vectors,
    _plans_of,
    _pos_label,
    _rel_name,
    _sub,
    _through,
)
from graphmethods.sheets.styles import CELL
from graphmethods.units import convenient_at_least

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
    shares: tuple[tuple[float, float], ...] = ()    # each cell's (x, width) in its row when not all alike
    rows: tuple[tuple[float, float], ...] = ()      # each row's (y, height) when not all alike

    def cell(self, idx: int, lay: PlanGridLayout) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """The frame of cell ``idx`` and the box inside it that the plan fills (mm)."""
        r, c = divmod(idx, self.columns)
        bx0, by0 = self.area[0] + c * self.cw, self.area[1] + r * self.ch
        cw, ch = self.cw, self.ch
        if self.shares:
            bx0, cw = self.shares[idx]
        if self.rows:
            by0, ch = self.rows[r]
        e = lay.inset_mm
        box = (bx0 + e, by0 + e, bx0 + cw - e, by0 + ch - e)
        inner = (box[0] + lay.pad_x_mm - e, box[1] + lay.head_mm + lay.pad_y_mm - e, box[2] - lay.pad_x_mm + e,
                 box[3] - lay.pad_y_mm + e)
        return box, inner


def _shared_label_mm(xy: dict) -> float:
    """The width (mm) of a plan's longest label of coincident images ("p, k₃, d, b" at a dead point)."""
    groups: dict[tuple[float, float], list[str]] = {}
    scale = max((abs(float(c)) for v in xy.values() for c in v), default=1.0) or 1.0
    for name, v in xy.items():
        key = (round(float(v[0]) / scale, 9), round(float(v[1]) / scale, 9))
        groups.setdefault(key, []).append(name)
    return max(markup.text_width_mm(", ".join(_plan_markup(n) for n in g), SMALL_MM + 0.2) for g in groups.values())


def _plan_grid(sheet: Sheet, spans: np.ndarray, fit: np.ndarray, columns, lay: PlanGridLayout,
               label_mm: np.ndarray | None = None) -> _Grid:
    """The grid of n plans whose extents are ``spans`` (n, 2): the columns given, or those giving the largest
    common scale; only the plans ``fit`` (bool, n) have to fit their cells (``label_mm``: each plan's widest
    label, which a cell sized to its plan must hold too)."""
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

    auto = columns is None
    if columns is None:
        columns = min((need_for(c)[0], c) for c in range(1, n + 1))[1]
    elif isinstance(columns, bool) or not isinstance(columns, int) or not 1 <= columns <= n:
        raise InputError(f"columns must be an integer from 1 to {n} (the number of plans), got {columns!r}")
    need, cw, ch = need_for(columns)
    if not math.isfinite(need) or need <= 0:
        raise InputError(f"{n} plans in {columns} columns do not fit on this sheet; give other columns or a "
                         f"larger page")
    grid = _Grid(area, columns, cw, ch, need)
    if auto:                            # cells as wide as their plans, when that draws every plan larger
        fitted = _fitted_grid(area, spans, fit, lay, np.zeros(n) if label_mm is None else label_mm)
        if fitted is not None and convenient_at_least(fitted.need) < convenient_at_least(need) * (1 - 1e-9):
            return fitted
    return grid


#: a cell is never narrower than this, nor than half an equal cell (its heading, a short plan's labels: a
#: dead point's "p, k₃, d, b, c, s₃, s₄, s₅"), mm
MIN_CELL_MM = 24.0


def _fitted_grid(area, spans: np.ndarray, fit: np.ndarray, lay: PlanGridLayout, label_mm: np.ndarray) -> _Grid | None:
    """The plans in rows of cells as wide as each plan at the common scale (the positions in order), each row
    as tall as its tallest plan, the slack of a row shared among its cells and the height's slack among the
    rows: a plan fills its cell as a draftsman sizes it, where equal cells would have to take the widest and
    the tallest plan's size. The rows kept are those that give the largest convenient scale; None when no rows
    do better than infinity."""
    W, H = area[2] - area[0], area[3] - area[1]
    n = len(spans)
    sx, sy = spans[:, 0], np.where(fit, spans[:, 1], 0.0)     # every plan drawn gets its width
    best: _Grid | None = None
    for cols in range(1, n + 1):
        rows = math.ceil(n / cols)
        tall = np.array([sy[r * cols:(r + 1) * cols].max() for r in range(rows)])
        frame_h = lay.head_mm + 2 * lay.pad_y_mm
        if H - rows * frame_h <= 5 * rows:
            continue
        need = float(tall.sum() / (H - rows * frame_h))
        for r in range(rows):
            row = sx[r * cols:(r + 1) * cols]
            room = W - len(row) * 2 * lay.pad_x_mm
            if room <= 5:
                need = math.inf
                break
            need = max(need, float(row.sum() / room))
        if not math.isfinite(need) or need <= 0:
            continue
        mu = convenient_at_least(need)
        heights = np.maximum(tall / mu + frame_h, max(MIN_CELL_MM, H / rows / 2))
        if heights.sum() > H + 1e-9:
            continue
        heights = heights + (H - heights.sum()) / rows
        ys = area[1] + np.concatenate(([0.0], np.cumsum(heights)[:-1]))
        shares: list[tuple[float, float]] = []
        for r in range(rows):
            row, labels = sx[r * cols:(r + 1) * cols], label_mm[r * cols:(r + 1) * cols]
            widths = np.maximum(np.maximum(row / mu, labels) + 2 * lay.pad_x_mm, max(MIN_CELL_MM, W / cols / 2))
            if widths.sum() > W + 1e-9:
                break
            widths = widths + (W - widths.sum()) / len(widths)
            x = area[0] + np.concatenate(([0.0], np.cumsum(widths)[:-1]))
            shares += list(zip(x.tolist(), widths.tolist()))
        else:
            if best is None or mu < convenient_at_least(best.need) * (1 - 1e-9):
                best = _Grid(area, cols, W / cols, H / rows, need, tuple(shares),
                             tuple(zip(ys.tolist(), heights.tolist())))
    return best


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
    ('μ_v = 0.025 (m/s)/mm', True)
    """
    lk, plans, pos, drawn = _plans_of(linkage, m=m, omega_1=omega_1)
    nt = get_notation(notation)
    lay = PLAN_GRID_LAYOUT
    images, vectors = _plan_layout(plans)
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("kinematics.plans"),
                  problem=lk.problem if problem is None else problem, title_block=title_block)
    grid, ill = _grid_of(sheet, plans, images, drawn, columns)
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


def _grid_of(sheet: Sheet, plans, images, drawn: list[int], columns: int | None) -> tuple[_Grid, np.ndarray]:
    """The grid of the plans of positions ``drawn`` on ``sheet`` and which of them are ill-conditioned."""
    spans = []
    for k in drawn:
        xy = np.array(list(_image_xy(plans, images, k).values()))
        spans.append((np.ptp(xy[:, 0]), np.ptp(xy[:, 1])))
    ill = np.asarray(plans.ill_conditioned)[drawn]
    grid = _plan_grid(sheet, np.array(spans), ~ill if (~ill).any() else np.ones_like(ill), columns, PLAN_GRID_LAYOUT,
                      label_mm=np.array([_shared_label_mm(_image_xy(plans, images, k)) for k in drawn]))
    return grid, ill


def velocity_grid_scale(linkage, *, m: int | None = None, notation="en", page=None, title_block: bool = True
                        ) -> float:
    """μ_v, (m/s)/mm, that :func:`velocity_plan_grid` picks on ``page``, without drawing it: a sheet that stretches
    a drawn grid onto another region to predict its ink asks it, since the grid's scale steps with its room.

    >>> from graphmethods.problems import builtin
    >>> from graphmethods.scene import Page
    >>> velocity_grid_scale(builtin.case("shaper"), page=Page("A1", "landscape", frame=True))
    0.005
    """
    lk, plans, _, drawn = _plans_of(linkage, m=m, omega_1=None)
    nt = get_notation(notation)
    sheet = Sheet(nt=nt, page=page, title=nt.word("kinematics.plans"), problem=lk.problem, title_block=title_block)
    grid, _ = _grid_of(sheet, plans, _plan_layout(plans)[0], drawn, None)
    return _pick_mu_v(None, grid.need, what="the largest plan in its cell", nt=nt).per_mm


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
            ends = next(((a, b) for a, b in mech.link_joints.values() if a + b == c.on or b + a == c.on), None)
            if ends is None:             # a point of a slider or block (it translates with it): as the record says
                lines.append(c.equation)
                continue
            x, y = ends
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
        if within_roundoff(w, plans.omega_1):           # the link stands still in this position
            out.append(nt.zero(f"ω_{{{num}}}", num_sym))
            continue
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


def _velocity_texts(plans, k: int, texts, vectors, pts: dict, s_v: Scale, at, x1: float, bottom: float, nt,
                    lay: PlanLayout, omega_at=None) -> list[Element]:
    """The column beside the plan at ``at`` (mm), to end above ``bottom`` (mm): φ and the equations, the table
    of the vectors' drawn lengths and values, ω of the links (under the plan from ``omega_at`` when given: a
    column too long for the page), the note of an ill-conditioned position."""
    phi, eqs, omega_texts, head = texts
    if omega_at is not None:
        under = [Text((omega_at[0], omega_at[1] + i * lay.line_mm), t, size_mm=TEXT_MM, name=f"omega-{num}")
                 for i, (num, t) in enumerate(zip(_omega_numbers(plans.positions.mechanism), omega_texts))]
        return under + _velocity_texts(plans, k, (phi, eqs, [], head), vectors, pts, s_v, at, x1, bottom, nt, lay)
    tx, ty = at
    els: list[Element] = [Text((tx, ty + i * lay.line_mm), line, size_mm=TEXT_MM, name=f"equation-{i}")
                          for i, line in enumerate([phi] + eqs)]
    rows = [head]
    lengths = [math.dist(pts[v.start], pts[v.end]) for v in vectors]
    top = max(lengths, default=0.0) * s_v.per_mm
    for v, L in zip(vectors, lengths):      # the values as the equations write them (v_A = ω₁·l_OA = 0.6912 m/s)
        rows.append((_plan_markup(v.start) + _plan_markup(v.end), _num(nt, L, 2),
                     f"{v.symbol} = {nt.number(L * s_v.per_mm, sig=4, reference=top)}"))
    numbers = _omega_numbers(plans.positions.mechanism)
    t_top = ty + (len(eqs) + 1) * lay.line_mm + 2.0
    below = lay.after_table_mm + (len(omega_texts) + bool(plans.ill_conditioned[k])) * lay.line_mm
    # a table lettered up (a slide's) grows its rows with its text: the rows are fitted as drawn, given unscaled
    grow = max(TABLE_MM, MIN_TEXT_MM.get()) / TABLE_MM
    row = lay.row_mm * grow             # a long column (a triad's): the table's rows closer, down to 1.4 text heights
    if t_top + len(rows) * row + below > bottom:  # (a triad's 15 rows on a slide lettered at 3.5 mm: 1.42)
        row = max(TABLE_MM * grow * 1.4, (bottom - t_top - below) / len(rows))
    table = Table((tx, t_top), tuple(rows), align="crl", size_mm=TABLE_MM, row_height_mm=row / grow, name="table")
    if table.top_right[0] > x1 + 1e-6:
        raise InputError("the table of vectors does not fit beside the plan; give a larger page")
    els.append(table)
    wy = table.bottom_left[1] + lay.after_table_mm
    els += [Text((tx, wy + i * lay.line_mm), t, size_mm=TEXT_MM, name=f"omega-{num}")
            for i, (num, t) in enumerate(zip(numbers, omega_texts))]
    if plans.ill_conditioned[k]:
        els.append(Text((tx, wy + len(omega_texts[:len(numbers)]) * lay.line_mm + 1.0),
                        nt.word("kinematics.ill_note"), size_mm=SMALL_MM, name="ill-conditioned"))
    return els


def _column_mm(texts, n_rows: int, lay: PlanLayout) -> float:
    """The least height (mm) of the column beside a plan: its lines, and its table with the rows closest."""
    phi, eqs, omega_texts, head = texts
    row = max(TABLE_MM, MIN_TEXT_MM.get()) * 1.7
    return (len(eqs) + 1 + len(omega_texts)) * lay.line_mm + 2.0 + n_rows * row + lay.after_table_mm


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
    omega_at = None
    if _column_mm(texts, len(vectors) + 1, lay) > area[3] - sheet.top - lay.column_x_mm:   # ω under the plan
        area = area[:3] + (area[3] - len(omega_texts) * lay.line_mm - lay.after_table_mm,)
        omega_at = (x0, area[3] + lay.after_table_mm)
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
                             x1, min(sheet.caption_y, sheet.page((s_v,)).content_box()[3] - 1.0) - lay.caption_room_mm,
                             nt, lay, omega_at)
    legend = f"{lk.speed_text(nt)};  {nt.word('kinematics.legend')}"
    scales = (s_v,)
    elements = [sheet.header()] + cons + vecs + [pole] + leaders + cons_labels + names + column
    elements += sheet.captions(scales, legend=legend, reserve=True)
    return sheet.scene(elements, scales, name=name, notes=(s_v.note,) if s_v.note else ())
