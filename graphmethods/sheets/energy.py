"""The excess-work figures: moment diagram, excess-work table, energy indicator, energy graph.

Each function takes a cycle (an :class:`~graphmethods.dynamics.excess_work.ExcessWork`,
or a problem with an ``excess_work`` such as :func:`graphmethods.problems.w1`) and
returns a :class:`~graphmethods.scene.Scene` on an A4 landscape sheet with a frame
and a title block. Scales are keyword arguments; any not given is picked (a
convenient value that fills the sheet) and every scale drawn is captioned under the
figure. ``notation="en" | "ru" | "zh"`` switches every symbol and word.

>>> from graphmethods.dynamics import excess_work as ew
>>> scene = energy_indicator(ew.from_work([-50, 550, -100, 125, -500, 25, -50]), notation="zh")
>>> scene.title, [s.caption("zh") for s in scene.scales()]
('能量指示图', ['μ_W = 5 J/mm'])
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import (
    Axis,
    Dimension,
    Frame,
    Line,
    Page,
    Point,
    Polyline,
    Region,
    Scale,
    Scene,
    SignMark,
    Table,
    Text,
    Vector,
    axis_ticks,
    markup,
    notation as get_notation,
    pi_ticks,
)
from graphmethods.scene.elements import Element, Group
from graphmethods.scene.notation import Notation
from graphmethods.scene.primitives import DASHED, MAIN, THIN, Label
from graphmethods.sheets.layout import (
    TEXT_MM,
    Box,
    Occupancy,
    Sheet,
    angle_deg_text,
    clear_tick_labels,
    given_angle_scale,
    given_scale,
    problem_title,
)

SMALL_MM = 2.8          # tick labels, values beside vectors
TABLE_MM = 3.8          # the excess-work table


# ----------------------------------------------------------------------------- common parts

def _cycle(obj: Any, nt: Notation) -> tuple[Any, str]:
    """(ExcessWork, problem text in the notation's language) from a cycle or a problem that has one."""
    if hasattr(obj, "E") and hasattr(obj, "work"):
        return obj, ""
    cyc = getattr(obj, "excess_work", None)
    if cyc is not None and hasattr(cyc, "E"):
        return cyc, problem_title(obj, nt)
    raise InputError(f"expected an excess-work cycle (graphmethods.dynamics.excess_work) or a problem with one, "
                     f"got {type(obj).__name__}")


def _clear_ticks(axis: Axis, *curves: Polyline) -> Axis:
    """The axis with the tick labels that a curve runs through left out (the tick marks stay); only the
    curves count, within 0.3 mm."""
    occ = Occupancy(pad_mm=0.3)
    for c in curves:
        occ.add_line(c.points)
    return clear_tick_labels(axis, occ)


def _piece(curve: Any, a: float, b: float) -> tuple[np.ndarray, np.ndarray]:
    """The points of a moment curve over [a, b]: right limit at a, inner knots (jumps kept), left limit at b."""
    inner = (curve.phi > a) & (curve.phi < b)
    left_b = curve.limits(np.array([b]))[0][0]
    right_a = curve.limits(np.array([a]))[1][0]
    phi = np.concatenate(([a], curve.phi[inner], [b]))
    M = np.concatenate(([right_a], curve.M[inner], [left_b]))
    return phi, M


def _curve_points(curve: Any) -> tuple[np.ndarray, np.ndarray]:
    return np.asarray(curve.phi, dtype=float), np.asarray(curve.M, dtype=float)


def _point_value(M_d: Any, M_r: Any, phi: float) -> float:
    """Where to put the dot of a boundary: on the curve that is continuous there (M_d first)."""
    ld, rd = (float(v[0]) for v in M_d.limits(np.array([phi])))
    lr, rr = (float(v[0]) for v in M_r.limits(np.array([phi])))
    if ld == rd:
        return ld
    if lr == rr:
        return lr
    return rd


def _box_centres(inner: Any, w: float, h: float, pole: tuple[float, float]) -> list[tuple[float, float]]:
    """Centres where a w × h box lies inside the polygon ``inner``: nearest the pole first.

    The feasible centres are the polygon eroded by the box (the intersection of the
    polygon shifted by each corner), exact for convex regions; callers still check.
    """
    from shapely import affinity
    from shapely.geometry import Point as SPoint
    from shapely.ops import nearest_points, polylabel

    feas = inner
    for dx, dy in ((-w / 2, -h / 2), (w / 2, -h / 2), (-w / 2, h / 2), (w / 2, h / 2)):
        feas = feas.intersection(affinity.translate(inner, -dx, -dy))
        if feas.is_empty:
            return []
    out = [nearest_points(feas, SPoint(pole))[0]]
    parts = list(getattr(feas, "geoms", [feas]))
    big = max(parts, key=lambda g: g.area)
    if big.geom_type == "Polygon" and big.area > 0:
        out.append(polylabel(big, tolerance=0.1))
    out.append(feas.representative_point())
    return [(p.x, p.y) for p in out]


def _interior_candidates(poly: Any, step: float = 1.5,
                         limit: int = 600) -> tuple[list[tuple[float, float]], tuple[float, float] | None]:
    """Points inside a shapely polygon, nearest its pole of inaccessibility first."""
    import shapely
    from shapely.ops import polylabel

    if poly.is_empty:
        return [], None
    if poly.geom_type == "MultiPolygon":
        poly = max(poly.geoms, key=lambda g: g.area)
    pole = polylabel(poly, tolerance=0.2)
    centroid = poly.centroid
    if poly.buffer(-1.0).contains(centroid):        # the centre of the area reads best, when well inside
        pole = centroid
    x0, y0, x1, y1 = poly.bounds
    xs = np.arange(x0, x1 + step, step)
    ys = np.arange(y0, y1 + step, step)
    X, Y = np.meshgrid(xs, ys)
    pts = np.column_stack([X.ravel(), Y.ravel()])
    inside = shapely.contains_xy(poly, pts[:, 0], pts[:, 1])
    pts = pts[inside]
    d = np.hypot(pts[:, 0] - pole.x, pts[:, 1] - pole.y)
    order = np.argsort(d, kind="stable")[:limit]
    return [(pole.x, pole.y)] + [tuple(p) for p in pts[order].tolist()], (pole.x, pole.y)


# ----------------------------------------------------------------------------- 1. moment diagram

@dataclass(frozen=True)
class MomentDiagramLayout:
    """The millimetre constants of :func:`moment_diagram` (A4 landscape: one plot with the hatched intervals)."""

    left_mm: float = 16.0           # the M axis's tick labels, left of the plot
    right_mm: float = 10.0          # right of the φ axis's name
    top_mm: float = 9.0             # below the title
    bottom_mm: float = 12.0         # above the scale captions
    phi_end_mm: float = 10.0        # the φ axis beyond the period (its arrow)
    phi_tick_gap_mm: float = 14.0   # at least between the φ values (multiples of π)
    M_tick_gap_mm: float = 8.0      # at least between the M values
    above_mm: float = 8.0           # labels may stand this far above the plot
    below_mm: float = 9.0           # … and this far below it
    text_inset_mm: float = 0.6      # an interval's text keeps this far inside its region
    line_spacing: float = 1.35      # of the interval texts, in text heights
    small_text_mm: float = 2.6      # the interval texts when TEXT_MM does not fit
    leader_rings_mm: tuple[float, ...] = (12.0, 18.0, 24.0, 32.0, 42.0, 55.0, 70.0)
    leader_angles_deg: tuple[float, ...] = (90, 60, 120, 30, 150, 0, 180, 270, 240, 300, 210, 330)


MOMENT_LAYOUT = MomentDiagramLayout()


@dataclass(frozen=True)
class _MomentGraph:
    """The scales and frame of a moment diagram and the plot's edges on the page (mm)."""

    s_phi: Scale
    s_M: Scale
    frame: Frame
    phi0: float
    period: float
    M_lo: float
    M_hi: float
    px0: float
    py0: float
    py1: float
    x1: float

    def P(self, phi: float, M: float) -> tuple[float, float]:
        """The page point of (φ, M), φ counted from the cycle's start."""
        return self.frame.pt(phi - self.phi0, M)

    def box(self, below_mm: float) -> tuple[float, float, float, float]:
        """The box labels stay in: the plot, with room above it and ``below_mm`` under it."""
        return (self.px0 + 1.0, self.py0 - MOMENT_LAYOUT.above_mm, self.x1, self.py1 + below_mm)


def _moment_graph(ew: Any, sheet: Sheet, nt: Notation, *, mu_M: Any, mu_phi: Any, moment_unit: str) -> _MomentGraph:
    """The scales fitted to the plot (or checked when given) and its frame."""
    L = MOMENT_LAYOUT
    x0, _, x1, _ = sheet.box
    M_d, M_r = ew.M_d, ew.M_r
    phi0, period = float(M_d.start), float(ew.period)
    M_all = np.concatenate((M_d.M, M_r.M, [0.0]))
    M_lo, M_hi = float(M_all.min()), float(M_all.max())
    phi_name = nt.quantity(nt.sym("phi"), "rad")
    px0, px1 = x0 + L.left_mm, x1 - L.right_mm - markup.text_width_mm(phi_name, SMALL_MM + 0.5)
    py0, py1 = sheet.top + L.top_mm, sheet.caption_y - L.bottom_mm
    s_phi = given_angle_scale(mu_phi, nt.sym("mu_phi"), period, px1 - px0 - L.phi_end_mm)
    s_M = given_scale(mu_M, nt.sym("mu_M"), moment_unit, M_hi - M_lo, py1 - py0, what="the moment diagram")
    frame = Frame((px0, py0 + s_M.to_mm(M_hi)), s_phi, s_M)
    return _MomentGraph(s_phi, s_M, frame, phi0, period, M_lo, M_hi, px0, py0, py1, x1)


def _moment_axes(g: _MomentGraph, ew: Any, nt: Notation, occ: Occupancy,
                 moment_unit: str) -> tuple[Axis, Axis, Polyline, Polyline]:
    """The φ and M axes (values a curve runs through left out) and the curves M_d, M_r."""
    L, origin = MOMENT_LAYOUT, g.frame.origin
    ticks_phi, labels_phi = pi_ticks(g.period, g.s_phi, min_gap_mm=L.phi_tick_gap_mm)
    ax_phi = Axis(origin, g.s_phi, "x", min_value=0.0, max_value=g.period, ticks=ticks_phi, tick_labels=labels_phi,
                  label=nt.quantity(nt.sym("phi"), "rad"), size_mm=SMALL_MM, name="axis-phi",
                  skip_zero_label=g.M_lo < 0)
    M_ticks = axis_ticks(g.M_lo, g.M_hi, g.s_M, min_gap_mm=L.M_tick_gap_mm)
    ax_M = Axis(origin, g.s_M, "y", min_value=min(g.M_lo, 0.0) if g.M_lo < 0 else 0.0, max_value=g.M_hi,
                ticks=M_ticks, label=nt.quantity(nt.sym("M"), nt.unit(moment_unit)), size_mm=SMALL_MM,
                decimal=nt.decimal, name="axis-M")
    cd = Polyline(g.frame.pts(ew.M_d.phi - g.phi0, ew.M_d.M), style=MAIN, name="curve-M_d")
    cr = Polyline(g.frame.pts(ew.M_r.phi - g.phi0, ew.M_r.M), style=MAIN, name="curve-M_r")
    ax_phi, ax_M = _clear_ticks(ax_phi, cd, cr), _clear_ticks(ax_M, cd, cr)
    occ.register(ax_phi, ax_M, cd, cr)
    return ax_phi, ax_M, cd, cr


def _closing_ordinates(g: _MomentGraph, ew: Any) -> list[Line]:
    """Ordinates closing the regions where both curves are continuous but apart."""
    ordinates = []
    for k, ph in enumerate(ew.phi):
        ld, rd = (float(v[0]) for v in ew.M_d.limits(np.array([ph])))
        lr, rr = (float(v[0]) for v in ew.M_r.limits(np.array([ph])))
        if ld == rd and lr == rr and abs(ld - lr) > 1e-9 * max(1.0, abs(g.M_hi - g.M_lo)):
            ordinates.append(Line(g.P(ph, ld), g.P(ph, lr), style=THIN, name=f"ordinate-{ew.labels[k]}"))
    return ordinates


Block = tuple[list[Label], tuple[float, float, float, float]]


def _block_inside(occ: Occupancy, poly: Any, layouts: tuple[tuple[str, ...], ...], plot_box: Box
                  ) -> tuple[Block | None, tuple[str, ...], float, Any]:
    """An interval's text inside its region: the first of the sizes and layouts that fits, nearest the
    region's pole of inaccessibility. Returns (placed block or None, lines, size, pole or None)."""
    from shapely.geometry import box as sbox

    inner = poly.buffer(-MOMENT_LAYOUT.text_inset_mm)
    cands, pole = _interior_candidates(poly)
    placed, lines, size = None, layouts[0], TEXT_MM
    if pole is not None and not inner.is_empty:
        for size in (TEXT_MM, MOMENT_LAYOUT.small_text_mm):
            for lines in layouts:
                lmm = size * MOMENT_LAYOUT.line_spacing
                w, h = occ.block_size(lines, size_mm=size, line_mm=lmm)
                placed = occ.place_block(_box_centres(inner, w, h, pole) + cands, lines, size_mm=size,
                                         line_mm=lmm, within=plot_box, check_lines=False,
                                         inside=lambda bx, inner=inner: inner.contains(sbox(*bx)))
                if placed is not None:
                    return placed, lines, size, pole
    return placed, lines, size, pole


def _block_outside(occ: Occupancy, pole: tuple[float, float], lines: tuple[str, ...], line_mm: float,
                   plot_box: Box, all_regions: Any, i: int) -> tuple[Block | None, Line | None]:
    """An interval's text outside all regions on rings round its pole, with a leader to the pole."""
    from shapely.geometry import box as sbox

    L = MOMENT_LAYOUT
    ring = [(pole[0] + r * math.cos(t), pole[1] - r * math.sin(t))
            for r in L.leader_rings_mm for t in np.radians(L.leader_angles_deg)]
    placed = occ.place_block(ring, lines, size_mm=TEXT_MM, line_mm=line_mm, within=plot_box,
                             inside=lambda bx: not all_regions.intersects(sbox(*bx)))
    if placed is None:
        return None, None
    bb = placed[1]
    tx = min(max(pole[0], bb[0] + 1.0), bb[2] - 1.0)
    if bb[3] <= pole[1]:                     # block above: from its bottom edge
        ty = bb[3]
    elif bb[1] >= pole[1]:                   # block below: from under the sign line
        ty = bb[1] + line_mm
    else:                                    # beside: from the middle of its near side
        tx, ty = (bb[0] if bb[0] > pole[0] else bb[2]), (bb[1] + bb[3]) / 2
    leader = Line((tx, ty), pole, style=THIN, name=f"leader-{i + 1}")
    occ.add_line((leader.start, leader.end))
    return placed, leader


def _interval(i: int, A: float, poly: Any, outline: Any, g: _MomentGraph, nt: Notation, occ: Occupancy,
              all_regions: Any, work_unit: str) -> tuple[Region, Group | None]:
    """Interval i: its hatched region (/ gain, \\ loss) and its sign, area f_i and work A_i (inside, or
    outside with a leader when the region has no room)."""
    gain = A > 0
    area_per_J = 1.0 / (g.s_M.per_mm * g.s_phi.per_mm)
    f_val = f"{nt.number(float(A) * area_per_J, plus=True)} {nt.unit('mm²')}"
    A_val = f"{nt.number(float(A), plus=True)} {nt.unit(work_unit)}"
    f_sym, A_sym = f"{nt.sym('f')}_{{{i + 1}}}", f"{nt.sym('A')}_{{{i + 1}}}"
    layouts: tuple[tuple[str, ...], ...] = (("", f"{f_sym} = {f_val}", f"{A_sym} = {A_val}"),   # sign above two lines
                                            ("", f"{f_sym} =", f_val, f"{A_sym} =", A_val))     # narrow: five lines
    plot_box = g.box(MOMENT_LAYOUT.below_mm)
    placed, lines, size, pole = _block_inside(occ, poly, layouts, plot_box)
    line_mm = size * MOMENT_LAYOUT.line_spacing
    leader = None
    if placed is None and pole is not None:        # no room inside: outside the regions, with a leader
        lines, size, line_mm = layouts[0], TEXT_MM, TEXT_MM * MOMENT_LAYOUT.line_spacing
        placed, leader = _block_outside(occ, pole, lines, line_mm, plot_box, all_regions, i)
    keep: tuple[tuple[float, float, float, float], ...] = ()
    annotation = None
    if placed is not None:
        labels, bb = placed
        if leader is None:
            keep = ((bb[0] - 0.6, bb[1] - 0.6, bb[2] + 0.6, bb[3] + 0.6),)
        els: list[Element] = [SignMark(((bb[0] + bb[2]) / 2, bb[1] + line_mm / 2), "+" if gain else "−",
                                       size_mm=size * 0.9, name=f"sign-{i + 1}")]
        els += [Text((lab.x, lab.y), t, size_mm=size, anchor="middle", name=f"label-{i + 1}")
                for lab, t in zip(labels[1:], lines[1:])]
        if leader is not None:
            els += [leader, Point(pole, radius_mm=0.5, name=f"leader-dot-{i + 1}")]
        annotation = Group(tuple(els), name=f"annotation-{i + 1}")
    region = Region(outline, hatch_angle_deg=45.0 if gain else 135.0, hatch_spacing_mm=2.0, keep_clear=keep,
                    name=f"region-{i + 1}")
    return region, annotation


def _intervals(g: _MomentGraph, ew: Any, nt: Notation, occ: Occupancy,
               work_unit: str) -> tuple[list[Region], list[Group]]:
    """The hatched regions between the crossings and their annotations (sign, area, work)."""
    from shapely import union_all
    from shapely.geometry import Polygon as SPolygon

    outlines, polys = [], []
    for i in range(len(ew.work)):
        a, b = float(ew.phi[i]), float(ew.phi[i + 1])
        pd, md = _piece(ew.M_d, a, b)
        pr, mr = _piece(ew.M_r, a, b)
        outline = g.frame.pts(np.concatenate((pd, pr[::-1])) - g.phi0, np.concatenate((md, mr[::-1])))
        outlines.append(outline)
        polys.append(SPolygon(outline).buffer(0))
    all_regions = union_all(polys)
    regions, annotations = [], []
    for i, A in enumerate(ew.work):
        region, annotation = _interval(i, A, polys[i], outlines[i], g, nt, occ, all_regions, work_unit)
        regions.append(region)
        if annotation is not None:
            annotations.append(annotation)
    for region in regions:                    # labels placed from here on keep off the hatching
        occ.add_primitives(region.primitives())
    return regions, annotations


def _boundary_points(g: _MomentGraph, ew: Any, occ: Occupancy) -> list[Group]:
    """The boundary points a, b, c … on the curve that is continuous there, named."""
    points = []
    for k, ph in enumerate(ew.phi):
        at = g.P(float(ph), _point_value(ew.M_d, ew.M_r, float(ph)))
        lab = occ.place_label(at, ew.labels[k], ("nw", "ne", "n", "sw", "se", "s", "w", "e"), size_mm=TEXT_MM + 0.3,
                              within=g.box(MOMENT_LAYOUT.below_mm + 1.0))
        points.append(Group((Point(at, radius_mm=0.6, name=f"dot-{ew.labels[k]}"),
                             Text((lab.x, lab.y), ew.labels[k], size_mm=TEXT_MM + 0.3, anchor=lab.anchor,
                                  name=f"name-{ew.labels[k]}")), name=f"point-{ew.labels[k]}"))
    return points


def _moment_names(g: _MomentGraph, ew: Any, nt: Notation, occ: Occupancy, cd: Polyline,
                  cr: Polyline) -> list[Text]:
    """The names M_d, M_r at the curves' right ends (or along them, where those are taken)."""
    names = []
    for curve, key, el in ((ew.M_d, "M_d", cd), (ew.M_r, "M_r", cr)):
        text, size = nt.sym(key), TEXT_MM + 0.5
        along = [(g.P(g.phi0 + t * g.period, float(curve(g.phi0 + t * g.period))), ("n", "s", "nw", "sw"))
                 for t in (0.93, 0.85, 0.75, 0.6)]
        spots = [(el.end, ("e",))] + along + [(el.end, ("ne", "se", "n", "s"))]
        nlab: Label | None = None
        for at, dirs in spots:
            nlab = occ.first_free(at, text, dirs, (1.5, 3.0), size, g.box(MOMENT_LAYOUT.below_mm))
            if nlab is not None:
                break
        if nlab is None:
            nlab = occ.place_label(el.end, text, ("e",), size_mm=size, gap_mm=1.5, register=False)
        occ.add_label(nlab)
        names.append(Text((nlab.x, nlab.y), text, size_mm=size, anchor=nlab.anchor, name=f"name-{key}"))
    return names


def moment_diagram(cycle: Any, *, mu_M: Any = None, mu_phi: Any = None, notation: Any = "en",
                   page: Page | None = None, title: str | None = None, problem: Any = None,
                   moment_unit: str = "N·m", work_unit: str = "J", title_block: bool = True,
                   name: str = "moment-diagram") -> Scene:
    """M_d and M_r over the period, the intervals between their crossings hatched and annotated.

    Each interval is hatched (/ for a gain, \\ for a loss) with its sign and its
    area f_i (mm² on this drawing) and excess work A_i written in it; the crossing
    points are labelled a, b, c, … Steps: the scales (:func:`_moment_graph`, laid out by
    :data:`MOMENT_LAYOUT`), the axes and curves, the intervals, the points and names.

    Parameters
    ----------
    cycle : ExcessWork or problem
        A cycle given by moment curves (``excess_work.from_moments``).
    mu_M : float or Scale, optional
        Moment scale, ``moment_unit`` per mm; picked when not given.
    mu_phi : float or Scale, optional
        Angle scale, rad/mm; picked (a round number of degrees per mm) when not given.
    notation : {'en', 'ru', 'zh'}
        Symbols and words.
    moment_unit, work_unit : str
        Units of the moments and of work (``"kG·m"`` for old-unit problems).

    Raises
    ------
    InputError
        If the cycle has no moment curves (areas or works only), or a given scale does not fit.

    Examples
    --------
    >>> from math import pi
    >>> from graphmethods.dynamics import excess_work as ew
    >>> from graphmethods.dynamics.moments import MomentCurve
    >>> w3 = ew.from_moments(M_r=MomentCurve.steps([(0, pi / 4, 60.0), (pi / 4, 2 * pi, 10.0)]))
    >>> s = moment_diagram(w3)
    >>> [sc.caption() for sc in s.scales()]
    ['μ_φ = 0.03491 rad/mm (2°/mm)', 'μ_M = 0.5 N·m/mm']
    """
    nt = get_notation(notation)
    ew, prob = _cycle(cycle, nt)
    if ew.M_d is None or ew.phi is None:
        raise InputError("moment_diagram needs the moment curves M_d and M_r; this cycle was given as areas, works "
                         "or levels, which fix no curves. Draw energy_indicator or excess_work_table instead")
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("moment_diagram"),
                  problem=prob if problem is None else problem, title_block=title_block)
    g = _moment_graph(ew, sheet, nt, mu_M=mu_M, mu_phi=mu_phi, moment_unit=moment_unit)
    occ = sheet.occ
    ax_phi, ax_M, cd, cr = _moment_axes(g, ew, nt, occ, moment_unit)
    ordinates = _closing_ordinates(g, ew)
    occ.register(*ordinates)
    regions, annotations = _intervals(g, ew, nt, occ, work_unit)
    points = _boundary_points(g, ew, occ)
    names = _moment_names(g, ew, nt, occ, cd, cr)
    scales = (g.s_phi, g.s_M)
    elements = ([sheet.header()] + regions + ordinates + [ax_phi, ax_M, cd, cr] + annotations + points + names
                + sheet.captions(scales, legend=nt.word("gain_loss")))
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 notes=(g.s_phi.note, g.s_M.note))


# ----------------------------------------------------------------------------- 2. excess-work table

def excess_work_table(cycle: Any, *, notation: Any = "en", page: Page | None = None, title: str | None = None,
                      problem: Any = None, work_unit: str = "J", moment_unit: str = "N·m", title_block: bool = True,
                      name: str = "excess-work-table") -> Scene:
    """The excess-work table drawn as a table: intervals, (angles), (areas), works, running energy.

    The rows of the highest and lowest energy are marked, and E_max, E_min and
    ΔW_max are written under the table. The same table as Markdown is
    ``cycle.to_markdown()``.

    Examples
    --------
    >>> from graphmethods.dynamics import excess_work as ew
    >>> s = excess_work_table(ew.from_work([-50, 550, -100, 125, -500, 25, -50]), notation="ru")
    >>> s.element("table").rows[0]
    ('Участок', 'Избыточная работа A, Дж', 'Точка', 'Приращение энергии ΔT, Дж', '')
    """
    nt = get_notation(notation)
    ew, prob = _cycle(cycle, nt)
    has_scales = ew.areas_mm2 is not None and ew.mu_M is not None and ew.mu_phi is not None
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("excess_work_table"),
                  problem=prob if problem is None else problem, title_block=title_block, has_scales=has_scales)
    x0, y0, x1, y1 = sheet.box
    unit = nt.unit(work_unit)
    A, E = nt.sym("A"), nt.sym("E")
    head = [nt.word("interval")]
    if ew.phi is not None:
        head.append(nt.quantity(nt.sym("phi"), "°"))
    if ew.areas_mm2 is not None:
        head.append(nt.quantity(nt.sym("f"), "mm²"))
    head += [f"{nt.word('work')} {nt.quantity(A, work_unit)}", nt.word("point"),
             f"{nt.word('level')} {nt.quantity(E, work_unit)}", ""]
    ncol = len(head)

    def mark(k: int) -> str:
        if k == ew.index_E_max:
            return nt.sym("E_max")
        if k == ew.index_E_min:
            return nt.sym("E_min")
        return ""

    rows = [tuple(head), tuple([""] * (ncol - 3) + [ew.labels[0], nt.number(0.0), mark(0)])]
    for i, work in enumerate(ew.work):
        row = [f"{ew.labels[i]}–{ew.labels[i + 1]}"]
        if ew.phi is not None:
            row.append(f"{angle_deg_text(ew.phi[i] - ew.phi[0], nt)}…{angle_deg_text(ew.phi[i + 1] - ew.phi[0], nt)}")
        if ew.areas_mm2 is not None:
            row.append(nt.number(float(ew.areas_mm2[i]), plus=True))
        row += [nt.number(float(work), plus=True), ew.labels[i + 1], nt.number(float(ew.E[i + 1])), mark(i + 1)]
        rows.append(tuple(row))
    total = ["Σ"]
    if ew.phi is not None:
        total.append("")
    if ew.areas_mm2 is not None:
        total.append(nt.number(float(np.sum(ew.areas_mm2))))
    total += [nt.number(ew.residual), "", "", ""]
    rows.append(tuple(total))
    align = "c" + ("c" if ew.phi is not None else "") + ("r" if ew.areas_mm2 is not None else "") + "rcrc"
    bold = (1 + ew.index_E_max, 1 + ew.index_E_min)
    probe = Table((0.0, 0.0), tuple(rows), align=align, size_mm=TABLE_MM, row_height_mm=9.0, bold_rows=bold)
    width = probe.width_mm
    at = ((x0 + x1) / 2 - width / 2, sheet.top + 6.0)
    table = Table(at, tuple(rows), align=align, size_mm=TABLE_MM, row_height_mm=9.0, bold_rows=bold,
                  name="table")
    ty = table.bottom_left[1] + 9.0
    imax, imin = ew.index_E_max, ew.index_E_min
    summary = [
        Text((at[0], ty), f"{nt.sym('E_max')} = {nt.number(ew.E_max)} {unit} ({ew.labels[imax]});   "
                          f"{nt.sym('E_min')} = {nt.number(ew.E_min)} {unit} ({ew.labels[imin]})",
             size_mm=TABLE_MM, name="extremes"),
        Text((at[0], ty + 8.0), f"{nt.sym('delta_W_max')} = {nt.sym('E_max')} − {nt.sym('E_min')} = "
                                f"{nt.number(ew.delta_W_max)} {unit}", size_mm=TABLE_MM + 0.4, bold=True,
             name="delta-W-max"),
    ]
    elements = [sheet.header(), table] + summary
    scales: tuple[Scale, ...] = ()
    if has_scales:
        scales = (Scale(nt.sym("mu_M"), moment_unit, ew.mu_M), Scale(nt.sym("mu_phi"), "rad", ew.mu_phi))
        elements += sheet.captions(scales)
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 extra_scales=scales)


# ----------------------------------------------------------------------------- 3. energy indicator

@dataclass(frozen=True)
class IndicatorLayout:
    """The millimetre constants of :func:`energy_indicator` (A4 landscape: a staircase of vectors)."""

    top_mm: float = 14.0            # below the title
    bottom_mm: float = 10.0         # above the scale captions
    axis_mm: float = 18.0           # the E axis right of the frame's left edge
    first_mm: float = 14.0          # the first vector right of the axis
    right_room_mm: float = 58.0     # right of the last vector: the ΔW_max dimension and its text
    step_max_mm: float = 22.0       # between vectors, when fitted
    step_min_mm: float = 6.0
    fit_mm: float = 20.0            # the last vector stays this far left of the frame's right edge
    start_beyond_mm: float = 8.0    # the start level beyond the last vector
    dim_beyond_mm: float = 16.0     # the ΔW_max dimension right of the last vector
    tick_gap_mm: float = 8.0        # at least between the E values


INDICATOR_LAYOUT = IndicatorLayout()


@dataclass(frozen=True)
class _Indicator:
    """The energy scale, the E axis's origin and the vectors' abscissae of an energy indicator (mm)."""

    s_E: Scale
    origin: tuple[float, float]
    xs: tuple[float, ...]
    first: float
    E: np.ndarray
    E_lo: float
    E_hi: float

    def y(self, v: float) -> float:
        """The page ordinate of the energy level ``v``."""
        return self.origin[1] - self.s_E.to_mm(float(v))

    def at_point(self, k: int) -> tuple[float, float]:
        """Point k of the staircase (a, b, …): the end of vector k − 1."""
        return (self.xs[max(k - 1, 0)] if k > 0 else self.xs[0], self.y(self.E[k]))

    @property
    def x_end(self) -> float:
        return self.xs[-1] if self.xs else self.first


def _indicator(ew: Any, sheet: Sheet, nt: Notation, *, mu_E: Any, step_mm: float | None,
               work_unit: str) -> _Indicator:
    """μ_E fitted to the height (or checked when given) and the step between vectors fitted to the width."""
    L = INDICATOR_LAYOUT
    x0, _, x1, _ = sheet.box
    E = np.asarray(ew.E, dtype=float)
    E_hi, E_lo = float(max(E.max(), 0.0)), float(min(E.min(), 0.0))
    py0, py1 = sheet.top + L.top_mm, sheet.caption_y - L.bottom_mm
    s_E = given_scale(mu_E, nt.sym("mu_E"), work_unit, E_hi - E_lo, py1 - py0, what="the energy indicator")
    ax_x = x0 + L.axis_mm
    n = len(ew.work)
    first = ax_x + L.first_mm
    if step_mm is None:
        step_mm = min(L.step_max_mm, max(L.step_min_mm, (x1 - L.right_room_mm - first) / max(n - 1, 1)))
    step_mm = float(step_mm)
    if first + step_mm * max(n - 1, 0) > x1 - L.fit_mm:
        raise InputError(f"{n} vectors at {step_mm:g} mm apart do not fit across the sheet; give a smaller "
                         f"step_mm or a larger page")
    return _Indicator(s_E, (ax_x, py0 + s_E.to_mm(E_hi)), tuple(first + k * step_mm for k in range(n)), first, E,
                      E_lo, E_hi)


def _staircase(ind: _Indicator, ew: Any, nt: Notation, occ: Occupancy,
               work_unit: str) -> tuple[Axis, Line, list[Vector], list[Line], list[Line], Dimension]:
    """The E axis, the start level, the vectors with the levels carried between them, the highest and
    lowest levels carried right to the ΔW_max dimension (all registered)."""
    L, y, xs, E = INDICATOR_LAYOUT, ind.y, ind.xs, ind.E
    ax = Axis(ind.origin, ind.s_E, "y", min_value=ind.E_lo if ind.E_lo < 0 else 0.0,
              max_value=max(ind.E_hi, ind.s_E.per_mm), ticks=axis_ticks(ind.E_lo, ind.E_hi, ind.s_E,
                                                                      min_gap_mm=L.tick_gap_mm),
              label=nt.quantity(nt.sym("E"), work_unit), size_mm=SMALL_MM, decimal=nt.decimal, name="axis-E")
    start_line = Line((ind.origin[0], y(0.0)), (ind.x_end + L.start_beyond_mm, y(0.0)), style=DASHED,
                      name="start-level")
    vectors, levels = [], []
    n = len(ew.work)
    for k, A in enumerate(ew.work):
        vectors.append(Vector.of((xs[k], y(E[k])), value=float(A), scale=ind.s_E, angle_deg=90.0,
                                 name=f"vector-{ew.labels[k]}{ew.labels[k + 1]}"))
        if k + 1 < n:
            levels.append(Line((xs[k], y(E[k + 1])), (xs[k + 1], y(E[k + 1])), style=DASHED,
                               name=f"level-{ew.labels[k + 1]}"))
    imax, imin = ew.index_E_max, ew.index_E_min
    x_dim = ind.x_end + L.dim_beyond_mm
    ext = [Line(ind.at_point(imax), (x_dim + 2.0, y(E[imax])), style=DASHED, name="level-max"),
           Line(ind.at_point(imin), (x_dim + 2.0, y(E[imin])), style=DASHED, name="level-min")]
    dim = Dimension((x_dim, y(E[imin])), (x_dim, y(E[imax])),
                    f"{nt.sym('delta_W_max')} = {nt.number(ew.delta_W_max)} {nt.unit(work_unit)}",
                    size_mm=TEXT_MM + 0.3, name="dimension-delta-W-max")
    occ.register(ax, start_line, *vectors, *levels, *ext, dim)
    return ax, start_line, vectors, levels, ext, dim


def _indicator_labels(ind: _Indicator, ew: Any, nt: Notation, occ: Occupancy,
                      vectors: list[Vector]) -> tuple[list[Text], list[Element]]:
    """The points a, b, … of the staircase and each vector's work beside it."""
    labels = []
    for k in range(len(ew.work) + 1):
        at = (ind.xs[0], ind.y(ind.E[0])) if k == 0 else (ind.xs[k - 1], ind.y(ind.E[k]))
        dirs = ("w", "nw", "sw", "n", "s") if k == 0 else ("e", "ne", "se", "w", "nw", "sw", "n", "s")
        lab = occ.place_label(at, ew.labels[k], dirs, size_mm=TEXT_MM + 0.3, gap_mm=1.0)
        labels.append(Text((lab.x, lab.y), ew.labels[k], size_mm=TEXT_MM + 0.3, anchor=lab.anchor,
                           name=f"name-{ew.labels[k]}"))
    values: list[Element] = []
    for k, vec in enumerate(vectors):
        text = nt.number(float(ew.work[k]), plus=True)
        lab = occ.place_label(vec.mid, text, ("w", "e", "nw", "sw", "ne", "se"), size_mm=SMALL_MM, gap_mm=1.2)
        values.append(Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, name=f"value-{k + 1}"))
    return labels, values


def _indicator_extremes(ind: _Indicator, ew: Any, nt: Notation, occ: Occupancy, box: Box,
                        work_unit: str) -> list[Element]:
    """Open circles on the highest and lowest points, with their energies (a leader when far)."""
    marks: list[Element] = []
    for k, key in ((ew.index_E_max, "E_max"), (ew.index_E_min, "E_min")):
        at = ind.at_point(k)
        marks.append(Point(at, radius_mm=1.1, filled=False, name=f"mark-{key}"))
        occ.add_box((at[0] - 1.2, at[1] - 1.2, at[0] + 1.2, at[1] + 1.2))
        text = f"{nt.sym(key)} = {nt.number(float(ind.E[k]))} {nt.unit(work_unit)}"
        dirs = ("n", "nw", "ne", "w", "e") if key == "E_max" else ("s", "sw", "se", "w", "e")
        lab, leader = occ.place_label_with_leader(at, text, dirs, size_mm=TEXT_MM, gap_mm=2.0, within=box)
        marks.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name=f"label-{key}"))
        if leader is not None:
            marks.append(Line(leader[0], leader[1], style=THIN, name=f"leader-{key}"))
    return marks


def _indicator_closure(ind: _Indicator, ew: Any, nt: Notation, occ: Occupancy, box: Box,
                       work_unit: str) -> tuple[Text, list[Element]]:
    """ΣA = 0 (closure) beside the last point, or the residual of measured data; and its leader, if any."""
    res = ew.residual
    closed = abs(res) <= 1e-9 * (float(np.abs(ew.work).sum()) or 1.0)
    text = (f"Σ{nt.sym('A')} = {nt.number(0.0 if closed else res)} {nt.unit(work_unit)} "
            f"({nt.word('closure') if closed else nt.word('residual')})")
    last = (ind.xs[-1], ind.y(ind.E[-1]))
    lab, leader = occ.place_label_with_leader(last, text, ("se", "s", "ne", "e", "sw", "n", "nw", "w"),
                                              size_mm=SMALL_MM, gap_mm=3.0, within=box)
    closure = Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, name="closure")
    return closure, ([Line(leader[0], leader[1], style=THIN, name="leader-closure")] if leader is not None else [])


def energy_indicator(cycle: Any, *, mu_E: Any = None, step_mm: float | None = None, notation: Any = "en",
                     page: Page | None = None, title: str | None = None, problem: Any = None, work_unit: str = "J",
                     title_block: bool = True, name: str = "energy-indicator") -> Scene:
    """The energy indicator diagram (能量指示图): the excess works as a staircase of vertical vectors.

    From point a, each interval's work A_i is a vector A_i/μ_E mm long, up for a
    gain and down for a loss, starting where the last one ended and shifted right by
    ``step_mm``; dashed lines carry each level across. The highest and lowest points
    are marked, ΔW_max is dimensioned between their levels, and the closure on the
    start level (or the residual of measured data) is written. Steps: the scale and step
    (:func:`_indicator`, laid out by :data:`INDICATOR_LAYOUT`), the staircase, the labels.

    Parameters
    ----------
    cycle : ExcessWork or problem
        Any cycle (areas, works, levels or moment curves).
    mu_E : float or Scale, optional
        Energy scale, ``work_unit`` per mm; picked when not given.
    step_mm : float, optional
        Horizontal shift between vectors, mm; fitted to the sheet when not given.

    Examples
    --------
    >>> from graphmethods.dynamics import excess_work as ew
    >>> from graphmethods.render.recording import record
    >>> s = energy_indicator(ew.from_work([-50, 550, -100, 125, -500, 25, -50]), mu_E=5.0)
    >>> round(record(s).vector_length_mm("vector-bc"), 6)          # 550 J at 5 J/mm
    110.0
    """
    nt = get_notation(notation)
    ew, prob = _cycle(cycle, nt)
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("energy_indicator"),
                  problem=prob if problem is None else problem, title_block=title_block)
    ind = _indicator(ew, sheet, nt, mu_E=mu_E, step_mm=step_mm, work_unit=work_unit)
    occ = sheet.occ
    ax, start_line, vectors, levels, ext, dim = _staircase(ind, ew, nt, occ, work_unit)
    labels, values = _indicator_labels(ind, ew, nt, occ, vectors)
    marks = _indicator_extremes(ind, ew, nt, occ, sheet.box, work_unit)
    closure, leader = _indicator_closure(ind, ew, nt, occ, sheet.box, work_unit)
    scales = (ind.s_E,)
    elements = ([sheet.header(), ax, start_line] + levels + ext + vectors + [dim] + marks + labels + values + leader
                + [closure] + sheet.captions(scales, legend=nt.word("gain_loss")))
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 notes=(ind.s_E.note,))
