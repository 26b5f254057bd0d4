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

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import (
    Axis,
    Dimension,
    Frame,
    Line,
    Point,
    Polyline,
    Region,
    Scale,
    Scene,
    SignMark,
    Table,
    Text,
    Vector,
    markup,
    nice_ticks,
    notation as get_notation,
    pi_ticks,
)
from graphmethods.scene.elements import Element, Group, label_bbox
from graphmethods.scene.primitives import DASHED, MAIN, THIN, Label, Style
from graphmethods.sheets.layout import (
    TEXT_MM,
    Occupancy,
    Sheet,
    angle_deg_text,
    given_angle_scale,
    given_scale,
    problem_title,
)

SMALL_MM = 2.8          # tick labels, values beside vectors
TABLE_MM = 3.8          # the excess-work table
OPEN_MARK = Style(width_mm=0.25, fill="#ffffff")


# ----------------------------------------------------------------------------- common parts

def _cycle(obj, nt):
    """(ExcessWork, problem text in the notation's language) from a cycle or a problem that has one."""
    if hasattr(obj, "E") and hasattr(obj, "work"):
        return obj, ""
    cyc = getattr(obj, "excess_work", None)
    if cyc is not None and hasattr(cyc, "E"):
        return cyc, problem_title(obj, nt)
    raise InputError(f"expected an excess-work cycle (graphmethods.dynamics.excess_work) or a problem with one, "
                     f"got {type(obj).__name__}")


def _clear_ticks(axis: Axis, *curves) -> Axis:
    """The axis with the tick labels that a curve runs through left out (the tick marks stay)."""
    from dataclasses import replace

    from graphmethods.scene.primitives import Label as PLabel

    occ = Occupancy(pad_mm=0.3)
    for c in curves:
        occ.add_line(c.points)
    labels = list(axis.tick_labels) if axis.tick_labels is not None else None
    texts = [p for p in axis.primitives() if isinstance(p, PLabel)][:len(axis.ticks)]
    if labels is None:
        labels = [t.text for t in texts]
    shown = [i for i, v in enumerate(axis.ticks) if labels[i] and not (axis.skip_zero_label and v == 0)]
    for i, lab in zip(shown, texts):
        if not occ.is_free(label_bbox(lab)):
            labels[i] = ""
    return replace(axis, tick_labels=tuple(labels))


def _register(occ: Occupancy, *elements) -> None:
    for e in elements:
        occ.add_primitives(e.primitives())


def _piece(curve, a: float, b: float) -> tuple[np.ndarray, np.ndarray]:
    """The points of a moment curve over [a, b]: right limit at a, inner knots (jumps kept), left limit at b."""
    inner = (curve.phi > a) & (curve.phi < b)
    left_b = curve.limits(np.array([b]))[0][0]
    right_a = curve.limits(np.array([a]))[1][0]
    phi = np.concatenate(([a], curve.phi[inner], [b]))
    M = np.concatenate(([right_a], curve.M[inner], [left_b]))
    return phi, M


def _curve_points(curve) -> tuple[np.ndarray, np.ndarray]:
    return np.asarray(curve.phi, dtype=float), np.asarray(curve.M, dtype=float)


def _point_value(M_d, M_r, phi: float) -> float:
    """Where to put the dot of a boundary: on the curve that is continuous there (M_d first)."""
    ld, rd = (float(v[0]) for v in M_d.limits(np.array([phi])))
    lr, rr = (float(v[0]) for v in M_r.limits(np.array([phi])))
    if ld == rd:
        return ld
    if lr == rr:
        return lr
    return rd


def _box_centres(inner, w: float, h: float, pole) -> list:
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


def _interior_candidates(poly, step: float = 1.5, limit: int = 600):
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

def moment_diagram(cycle, *, mu_M=None, mu_phi=None, notation="en", page=None, title=None, problem=None,
                   moment_unit: str = "N·m", work_unit: str = "J", title_block: bool = True,
                   name: str = "moment-diagram") -> Scene:
    """M_d and M_r over the period, the intervals between their crossings hatched and annotated.

    Each interval is hatched (/ for a gain, \\ for a loss) with its sign and its
    area f_i (mm² on this drawing) and excess work A_i written in it; the crossing
    points are labelled a, b, c, …

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
    x0, y0, x1, y1 = sheet.box
    M_d, M_r = ew.M_d, ew.M_r
    phi0, period = float(M_d.start), float(ew.period)
    M_all = np.concatenate((M_d.M, M_r.M, [0.0]))
    M_lo, M_hi = float(M_all.min()), float(M_all.max())

    phi_name = nt.quantity(nt.sym("phi"), "rad")
    px0, px1 = x0 + 16.0, x1 - 10.0 - markup.text_width_mm(phi_name, SMALL_MM + 0.5)  # tick labels, axis name
    py0, py1 = sheet.top + 9.0, sheet.caption_y - 12.0
    s_phi = given_angle_scale(mu_phi, nt.sym("mu_phi"), period, px1 - px0 - 10.0)
    s_M = given_scale(mu_M, nt.sym("mu_M"), moment_unit, M_hi - M_lo, py1 - py0, what="the moment diagram")
    origin = (px0, py0 + s_M.to_mm(M_hi))
    f = Frame(origin, s_phi, s_M)

    def P(phi, M):
        return f.pt(phi - phi0, M)

    occ = sheet.occ
    # axes
    ticks_phi, labels_phi = pi_ticks(period, s_phi, min_gap_mm=14.0)
    ax_phi = Axis(origin, s_phi, "x", min_value=0.0, max_value=period, ticks=ticks_phi, tick_labels=labels_phi,
                  label=phi_name, size_mm=SMALL_MM, name="axis-phi", skip_zero_label=M_lo < 0)
    M_ticks = nice_ticks(M_lo, M_hi, s_M, min_gap_mm=8.0)
    ax_M = Axis(origin, s_M, "y", min_value=min(M_lo, 0.0) if M_lo < 0 else 0.0, max_value=M_hi,
                ticks=M_ticks, label=nt.quantity(nt.sym("M"), nt.unit(moment_unit)), size_mm=SMALL_MM,
                decimal=nt.decimal, name="axis-M")
    # curves
    cd = Polyline(f.pts(M_d.phi - phi0, M_d.M), style=MAIN, name="curve-M_d")
    cr = Polyline(f.pts(M_r.phi - phi0, M_r.M), style=MAIN, name="curve-M_r")
    ax_phi, ax_M = _clear_ticks(ax_phi, cd, cr), _clear_ticks(ax_M, cd, cr)
    _register(occ, ax_phi, ax_M, cd, cr)

    # ordinates closing the regions where both curves are continuous but apart
    ordinates = []
    for k, ph in enumerate(ew.phi):
        ld, rd = (float(v[0]) for v in M_d.limits(np.array([ph])))
        lr, rr = (float(v[0]) for v in M_r.limits(np.array([ph])))
        if ld == rd and lr == rr and abs(ld - lr) > 1e-9 * max(1.0, abs(M_hi - M_lo)):
            ordinates.append(Line(P(ph, ld), P(ph, lr), style=THIN, name=f"ordinate-{ew.labels[k]}"))
    _register(occ, *ordinates)

    # the intervals: hatched regions with sign, area and work
    from shapely.geometry import Polygon as SPolygon, box as sbox

    outlines, polys = [], []
    for i in range(len(ew.work)):
        a, b = float(ew.phi[i]), float(ew.phi[i + 1])
        pd, md = _piece(M_d, a, b)
        pr, mr = _piece(M_r, a, b)
        outline = f.pts(np.concatenate((pd, pr[::-1])) - phi0, np.concatenate((md, mr[::-1])))
        outlines.append(outline)
        polys.append(SPolygon(outline).buffer(0))
    from shapely import union_all

    all_regions = union_all(polys)
    plot_box = (px0 + 1.0, py0 - 8.0, x1, py1 + 9.0)
    area_per_J = 1.0 / (s_M.per_mm * s_phi.per_mm)
    regions, annotations = [], []
    for i, A in enumerate(ew.work):
        poly, outline = polys[i], outlines[i]
        gain = A > 0
        f_val = f"{nt.number(float(A) * area_per_J, plus=True)} {nt.unit('mm²')}"
        A_val = f"{nt.number(float(A), plus=True)} {nt.unit(work_unit)}"
        f_sym, A_sym = f"{nt.sym('f')}_{{{i + 1}}}", f"{nt.sym('A')}_{{{i + 1}}}"
        layouts: tuple[tuple[str, ...], ...] = (
                  ("", f"{f_sym} = {f_val}", f"{A_sym} = {A_val}"),            # sign above two lines
                   ("", f"{f_sym} =", f_val, f"{A_sym} =", A_val))               # narrow: five lines
        inner = poly.buffer(-0.6)
        cands, pole = _interior_candidates(poly)
        placed, lines, size = None, layouts[0], TEXT_MM
        if pole is not None and not inner.is_empty:
            for size in (TEXT_MM, 2.6):
                for lines in layouts:
                    lmm = size * 1.35
                    w, h = occ.block_size(lines, size_mm=size, line_mm=lmm)
                    placed = occ.place_block(_box_centres(inner, w, h, pole) + cands, lines, size_mm=size,
                                             line_mm=lmm, within=plot_box, check_lines=False,
                                             inside=lambda bx, inner=inner: inner.contains(sbox(*bx)))
                    if placed is not None:
                        break
                if placed is not None:
                    break
        line_mm = size * 1.35
        leader = None
        if placed is None and pole is not None:        # no room inside: outside the regions, with a leader
            lines, size, line_mm = layouts[0], TEXT_MM, TEXT_MM * 1.35
            ring = [(pole[0] + r * math.cos(t), pole[1] - r * math.sin(t))
                    for r in (12.0, 18.0, 24.0, 32.0, 42.0, 55.0, 70.0)
                    for t in np.radians([90, 60, 120, 30, 150, 0, 180, 270, 240, 300, 210, 330])]
            placed = occ.place_block(ring, lines, size_mm=size, line_mm=line_mm, within=plot_box,
                                     inside=lambda bx: not all_regions.intersects(sbox(*bx)))
            if placed is not None:
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
        keep: tuple[tuple[float, float, float, float], ...] = ()
        if placed is not None:
            labels, bb = placed
            if leader is None:
                keep = ((bb[0] - 0.6, bb[1] - 0.6, bb[2] + 0.6, bb[3] + 0.6),)
            els: list[Element] = [SignMark(((bb[0] + bb[2]) / 2, bb[1] + line_mm / 2), "+" if gain else "−", size_mm=size * 0.9,
                            name=f"sign-{i + 1}")]
            els += [Text((lab.x, lab.y), t, size_mm=size, anchor="middle", name=f"label-{i + 1}")
                    for lab, t in zip(labels[1:], lines[1:])]
            if leader is not None:
                els += [leader, Point(pole, radius_mm=0.5, name=f"leader-dot-{i + 1}")]
            annotations.append(Group(tuple(els), name=f"annotation-{i + 1}"))
        region = Region(outline, hatch_angle_deg=45.0 if gain else 135.0, hatch_spacing_mm=2.0, keep_clear=keep,
                        name=f"region-{i + 1}")
        regions.append(region)
    for region in regions:                    # labels placed from here on keep off the hatching
        occ.add_primitives(region.primitives())

    # boundary points a, b, c …
    points = []
    for k, ph in enumerate(ew.phi):
        at = P(float(ph), _point_value(M_d, M_r, float(ph)))
        lab = occ.place_label(at, ew.labels[k], ("nw", "ne", "n", "sw", "se", "s", "w", "e"), size_mm=TEXT_MM + 0.3,
                              within=(px0 + 1, py0 - 8, x1, py1 + 10))
        points.append(Group((Point(at, radius_mm=0.6, name=f"dot-{ew.labels[k]}"),
                             Text((lab.x, lab.y), ew.labels[k], size_mm=TEXT_MM + 0.3, anchor=lab.anchor,
                                  name=f"name-{ew.labels[k]}")), name=f"point-{ew.labels[k]}"))

    # curve names at their right ends
    names = []
    for curve, key, el in ((M_d, "M_d", cd), (M_r, "M_r", cr)):
        text, size = nt.sym(key), TEXT_MM + 0.5
        spots = [(el.end, ("e",))] + [(P(phi0 + t * period, float(curve(phi0 + t * period))), ("n", "s", "nw", "sw"))
                                      for t in (0.93, 0.85, 0.75, 0.6)] + [(el.end, ("ne", "se", "n", "s"))]
        nlab: Label | None = None
        for at, dirs in spots:
            nlab = occ.first_free(at, text, dirs, (1.5, 3.0), size, (px0 + 1, py0 - 8, x1, py1 + 9))
            if nlab is not None:
                break
        if nlab is None:
            nlab = occ.place_label(el.end, text, ("e",), size_mm=size, gap_mm=1.5, register=False)
        occ.add_label(nlab)
        names.append(Text((nlab.x, nlab.y), text, size_mm=size, anchor=nlab.anchor, name=f"name-{key}"))

    scales = (s_phi, s_M)
    elements = ([sheet.header()] + regions + ordinates + [ax_phi, ax_M, cd, cr] + annotations + points + names
                + sheet.captions(scales, legend=nt.word("gain_loss")))
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 notes=(s_phi.note, s_M.note))


# ----------------------------------------------------------------------------- 2. excess-work table

def excess_work_table(cycle, *, notation="en", page=None, title=None, problem=None, work_unit: str = "J",
                      moment_unit: str = "N·m", title_block: bool = True, name: str = "excess-work-table") -> Scene:
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
                   problem=prob if problem is None else problem, title_block=title_block,
                   has_scales=has_scales)
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

    def mark(k):
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

def energy_indicator(cycle, *, mu_E=None, step_mm: float | None = None, notation="en", page=None, title=None,
                     problem=None, work_unit: str = "J", title_block: bool = True,
                     name: str = "energy-indicator") -> Scene:
    """The energy indicator diagram (能量指示图): the excess works as a staircase of vertical vectors.

    From point a, each interval's work A_i is a vector A_i/μ_E mm long, up for a
    gain and down for a loss, starting where the last one ended and shifted right by
    ``step_mm``; dashed lines carry each level across. The highest and lowest points
    are marked, ΔW_max is dimensioned between their levels, and the closure on the
    start level (or the residual of measured data) is written.

    Parameters
    ----------
    cycle : ExcessWork or problem
        Any cycle (areas, works, levels or moment curves).
    mu_E : float or Scale, optional
        Energy scale, ``work_unit`` per mm; picked when not given.
    step_mm : float, optional
        Horizontal shift between vectors; fitted to the sheet when not given.

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
    x0, y0, x1, y1 = sheet.box
    E = np.asarray(ew.E, dtype=float)
    E_hi, E_lo = float(max(E.max(), 0.0)), float(min(E.min(), 0.0))
    py0, py1 = sheet.top + 14.0, sheet.caption_y - 10.0
    s_E = given_scale(mu_E, nt.sym("mu_E"), work_unit, E_hi - E_lo, py1 - py0, what="the energy indicator")
    ax_x = x0 + 18.0
    origin = (ax_x, py0 + s_E.to_mm(E_hi))
    n = len(ew.work)
    right_room = 58.0
    first = ax_x + 14.0
    if step_mm is None:
        step_mm = min(22.0, max(6.0, (x1 - right_room - first) / max(n - 1, 1)))
    step_mm = float(step_mm)
    if first + step_mm * max(n - 1, 0) > x1 - 20.0:
        raise InputError(f"{n} vectors at {step_mm:g} mm apart do not fit across the sheet; give a smaller "
                         f"step_mm or a larger page")

    def y(v):
        return origin[1] - s_E.to_mm(float(v))

    xs = [first + k * step_mm for k in range(n)]
    x_end = xs[-1] if xs else first
    occ = sheet.occ
    ax = Axis(origin, s_E, "y", min_value=E_lo if E_lo < 0 else 0.0, max_value=max(E_hi, s_E.per_mm),
              ticks=nice_ticks(E_lo, E_hi, s_E, min_gap_mm=8.0), label=nt.quantity(nt.sym("E"), work_unit),
              size_mm=SMALL_MM, decimal=nt.decimal, name="axis-E")
    start_line = Line((ax_x, y(0.0)), (x_end + 8.0, y(0.0)), style=DASHED, name="start-level")
    vectors, levels = [], []
    for k, A in enumerate(ew.work):
        vectors.append(Vector.of((xs[k], y(E[k])), value=float(A), scale=s_E, angle_deg=90.0,
                                 name=f"vector-{ew.labels[k]}{ew.labels[k + 1]}"))
        if k + 1 < n:
            levels.append(Line((xs[k], y(E[k + 1])), (xs[k + 1], y(E[k + 1])), style=DASHED,
                               name=f"level-{ew.labels[k + 1]}"))
    # the highest and lowest points, their levels carried right to the ΔW_max dimension
    imax, imin = ew.index_E_max, ew.index_E_min

    def at_point(k):
        return (xs[max(k - 1, 0)] if k > 0 else xs[0], y(E[k]))

    x_dim = x_end + 16.0
    ext = [Line(at_point(imax), (x_dim + 2.0, y(E[imax])), style=DASHED, name="level-max"),
           Line(at_point(imin), (x_dim + 2.0, y(E[imin])), style=DASHED, name="level-min")]
    dim = Dimension((x_dim, y(E[imin])), (x_dim, y(E[imax])),
                    f"{nt.sym('delta_W_max')} = {nt.number(ew.delta_W_max)} {nt.unit(work_unit)}",
                    size_mm=TEXT_MM + 0.3, name="dimension-delta-W-max")
    _register(occ, ax, start_line, *vectors, *levels, *ext, dim)
    # labels: points a, b, …; values beside the vectors; max / min marks
    labels = []
    for k in range(n + 1):
        at = (xs[0], y(E[0])) if k == 0 else (xs[k - 1], y(E[k]))
        dirs = ("w", "nw", "sw", "n", "s") if k == 0 else ("e", "ne", "se", "w", "nw", "sw", "n", "s")
        lab = occ.place_label(at, ew.labels[k], dirs, size_mm=TEXT_MM + 0.3, gap_mm=1.0)
        labels.append(Text((lab.x, lab.y), ew.labels[k], size_mm=TEXT_MM + 0.3, anchor=lab.anchor,
                           name=f"name-{ew.labels[k]}"))
    values: list[Element] = []
    for k, vec in enumerate(vectors):
        text = nt.number(float(ew.work[k]), plus=True)
        lab = occ.place_label(vec.mid, text, ("w", "e", "nw", "sw", "ne", "se"), size_mm=SMALL_MM, gap_mm=1.2)
        values.append(Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, name=f"value-{k + 1}"))
    marks: list[Element] = []
    for k, key in ((imax, "E_max"), (imin, "E_min")):
        at = at_point(k)
        marks.append(Point(at, radius_mm=1.1, filled=False, name=f"mark-{key}"))
        occ.add_box((at[0] - 1.2, at[1] - 1.2, at[0] + 1.2, at[1] + 1.2))
        text = f"{nt.sym(key)} = {nt.number(float(E[k]))} {nt.unit(work_unit)}"
        dirs = ("n", "nw", "ne", "w", "e") if key == "E_max" else ("s", "sw", "se", "w", "e")
        lab, leader = occ.place_label_with_leader(at, text, dirs, size_mm=TEXT_MM, gap_mm=2.0, within=sheet.box)
        marks.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name=f"label-{key}"))
        if leader is not None:
            marks.append(Line(leader[0], leader[1], style=THIN, name=f"leader-{key}"))
    # closure
    res = ew.residual
    scale_total = float(np.abs(ew.work).sum()) or 1.0
    closed = abs(res) <= 1e-9 * scale_total
    text = (f"Σ{nt.sym('A')} = {nt.number(0.0 if closed else res)} {nt.unit(work_unit)} "
            f"({nt.word('closure') if closed else nt.word('residual')})")
    last = (xs[-1], y(E[-1]))
    lab, leader = occ.place_label_with_leader(last, text, ("se", "s", "ne", "e", "sw", "n", "nw", "w"),
                                              size_mm=SMALL_MM, gap_mm=3.0, within=sheet.box)
    closure = Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, name="closure")
    if leader is not None:
        values.append(Line(leader[0], leader[1], style=THIN, name="leader-closure"))
    scales = (s_E,)
    elements = ([sheet.header(), ax, start_line] + levels + ext + vectors + [dim] + marks + labels + values
                + [closure] + sheet.captions(scales, legend=nt.word("gain_loss")))
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 notes=(s_E.note,))


# ----------------------------------------------------------------------------- 4. energy graph

def energy_graph(cycle, *, mu_E=None, mu_phi=None, T0: float | None = None, J_e: float | None = None,
                 omega_0: float | None = None, notation="en", page=None, title=None, problem=None,
                 work_unit: str = "J", samples: int = 721, title_block: bool = True,
                 name: str = "energy-graph") -> Scene:
    """The energy graph ΔE(φ) (Chinese style), or T(φ) = T0 + ΔE(φ) from a given T0 (Russian style).

    The curve is exact (ΔE is piecewise quadratic between the knots). The boundary
    points a, b, … are marked on it, the positions of E_max and E_min are marked and
    projected onto the φ axis, and ΔW_max is dimensioned. Give ``T0`` (J), or
    ``J_e`` (kg·m²) with ``omega_0`` (rad/s), for the kinetic-energy graph T(φ) drawn
    from T = 0.

    Raises
    ------
    InputError
        If the cycle has no moment curves (then there is no φ to draw against).

    Examples
    --------
    >>> from math import pi
    >>> from graphmethods.dynamics import excess_work as ew
    >>> from graphmethods.dynamics.moments import MomentCurve
    >>> w4 = ew.from_moments(MomentCurve.constant(20.0), MomentCurve.points([0, pi, 2 * pi], [0, 40, 0]))
    >>> s = energy_graph(w4, J_e=0.8, omega_0=10.0, notation="ru", work_unit="kG·m")
    >>> s.element("axis-E").label, s.element("label-T_max").text
    ('T, кГ·м', 'T_{max} = 55,71 кГ·м, φ = 90°')
    """
    nt = get_notation(notation)
    ew, prob = _cycle(cycle, nt)
    if ew.M_d is None or ew.phi is None:
        raise InputError("energy_graph draws ΔE against φ and needs the moment curves; this cycle was given as "
                         "areas, works or levels, which fix no angles. Draw energy_indicator instead")
    if T0 is None and (J_e is not None or omega_0 is not None):
        if J_e is None or omega_0 is None:
            raise InputError("give T0 (J), or both J_e (kg·m²) and omega_0 (rad/s), for the kinetic-energy graph")
        T0 = 0.5 * float(J_e) * float(omega_0) ** 2
    kinetic = T0 is not None
    if T0 is not None and not (math.isfinite(T0) and T0 > 0):
        raise InputError(f"T0 = {T0!r} must be a positive kinetic energy in {work_unit}")
    base = float(T0) if T0 is not None else 0.0
    phi, dE = ew.energy_curve(samples)
    phi0, period = float(ew.phi[0]), float(ew.period)
    Y = dE + base
    if kinetic and (Y <= 0).any():
        raise InputError(f"T0 = {T0:g} {work_unit} is too small: T = T0 + ΔE falls to {Y.min():.4g}; the machine "
                         f"would stop. Give a larger T0 or omega_0")
    lo = 0.0 if kinetic else float(min(Y.min(), 0.0))
    hi = float(max(Y.max(), 0.0))
    sym = nt.sym("T") if kinetic else nt.sym("dE")
    ttl = title or (f"{nt.word('kinetic_energy_graph')} {sym}(φ)" if kinetic else f"{nt.word('energy_graph')} {sym}(φ)")
    sheet = Sheet(nt=nt, page=page, title=ttl, problem=prob if problem is None else problem,
                   title_block=title_block)
    x0, y0, x1, y1 = sheet.box
    phi_name = nt.quantity(nt.sym("phi"), "rad")
    dim_text = f"{nt.sym('delta_W_max')} = {nt.number(ew.delta_W_max)} {nt.unit(work_unit)}"
    right = 6.0 + 1.5 + markup.text_width_mm(phi_name, SMALL_MM + 0.5) + 5.0   # arrow, axis name, gap
    px0, px1 = x0 + 18.0, x1 - right - 3.0 - markup.text_width_mm(dim_text, TEXT_MM + 0.3)
    py0, py1 = sheet.top + 14.0, sheet.caption_y - 16.0
    s_phi = given_angle_scale(mu_phi, nt.sym("mu_phi"), period, px1 - px0)
    s_E = given_scale(mu_E, nt.sym("mu_T") if kinetic else nt.sym("mu_E"), work_unit, hi - lo, py1 - py0,
                 what="the energy graph")
    origin = (px0, py0 + s_E.to_mm(hi))
    f = Frame(origin, s_phi, s_E)

    def P(ph, v):
        return f.pt(float(ph) - phi0, float(v))

    occ = sheet.occ
    ticks_phi, labels_phi = pi_ticks(period, s_phi, min_gap_mm=14.0)
    ax_phi = Axis(origin, s_phi, "x", min_value=0.0, max_value=period, ticks=ticks_phi, tick_labels=labels_phi,
                  label=phi_name, size_mm=SMALL_MM, name="axis-phi", skip_zero_label=lo < 0,
                  labels_side="above" if -lo > hi else "below")
    room = s_E.to_value(9.0) if -lo > hi else s_E.per_mm   # tick labels above the φ axis need room
    ax_E = Axis(origin, s_E, "y", min_value=lo if lo < 0 else 0.0, max_value=max(hi, room),
                ticks=nice_ticks(lo, hi, s_E, min_gap_mm=8.0), label=nt.quantity(sym, work_unit),
                size_mm=SMALL_MM, decimal=nt.decimal, name="axis-E")
    curve = Polyline(f.pts(phi - phi0, Y), style=MAIN, name="curve-E")
    ax_phi, ax_E = _clear_ticks(ax_phi, curve), _clear_ticks(ax_E, curve)
    _register(occ, ax_phi, ax_E, curve)
    # extremes: marks, projections to the φ axis, ΔW_max between their levels
    imax, imin = ew.index_E_max, ew.index_E_min
    k_max, k_min = ("T_max", "T_min") if kinetic else ("E_max", "E_min")
    ext_pts = {k_max: (float(ew.phi[imax]), float(ew.E[imax]) + base),
               k_min: (float(ew.phi[imin]), float(ew.E[imin]) + base)}
    x_dim = f.pt(period, 0.0)[0] + right
    guides = []
    for key, (ph, v) in ext_pts.items():
        at = P(ph, v)
        guides.append(Line(at, (at[0], origin[1]), style=DASHED, name=f"projection-{key}"))
        guides.append(Line(at, (x_dim + 2.0, at[1]), style=DASHED, name=f"level-{key}"))
    dim = Dimension((x_dim, P(*ext_pts[k_min])[1]), (x_dim, P(*ext_pts[k_max])[1]), dim_text,
                    size_mm=TEXT_MM + 0.3, name="dimension-delta-W-max")
    _register(occ, *guides, dim)
    marks: list[Element] = []
    for key, (ph, v) in ext_pts.items():
        at = P(ph, v)
        marks.append(Point(at, radius_mm=1.1, filled=False, name=f"mark-{key}"))
        occ.add_box((at[0] - 1.3, at[1] - 1.3, at[0] + 1.3, at[1] + 1.3))
    points = []
    for k, ph in enumerate(ew.phi):
        at = P(ph, float(ew.E[k]) + base)
        lab = occ.place_label(at, ew.labels[k], ("nw", "ne", "sw", "se", "n", "s", "w", "e"), size_mm=TEXT_MM + 0.3,
                              gap_mm=1.0, within=(px0 + 1, py0 - 10, x1, y1))
        points.append(Group((Point(at, radius_mm=0.6, name=f"dot-{ew.labels[k]}"),
                             Text((lab.x, lab.y), ew.labels[k], size_mm=TEXT_MM + 0.3, anchor=lab.anchor,
                                  name=f"name-{ew.labels[k]}")), name=f"point-{ew.labels[k]}"))
    for key, (ph, v) in ext_pts.items():
        at = P(ph, v)
        text = (f"{nt.sym(key)} = {nt.number(v)} {nt.unit(work_unit)}, "
                f"{nt.sym('phi')} = {angle_deg_text(ph - phi0, nt)}")
        dirs = ("ne", "nw", "n", "e", "w") if key.endswith("max") else ("se", "sw", "s", "e", "w")
        lab, leader = occ.place_label_with_leader(at, text, dirs, size_mm=TEXT_MM, gap_mm=2.0,
                                                  within=(px0 + 1, py0 - 10, x1, y1))
        marks.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name=f"label-{key}"))
        if leader is not None:
            marks.append(Line(leader[0], leader[1], style=THIN, name=f"leader-{key}"))
    extra = []
    if kinetic:
        at = P(phi0, base)
        text = f"{nt.sym('T_0')} = {nt.number(base)} {nt.unit(work_unit)}"
        lab = occ.place_label(at, text, ("ne", "se", "e", "n"), size_mm=TEXT_MM, gap_mm=2.5)
        extra.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name="label-T0"))
    scales = (s_phi, s_E)
    elements = ([sheet.header(), ax_phi, ax_E] + guides + [curve, dim] + points + marks + extra
                + sheet.captions(scales))
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 notes=(s_phi.note, s_E.note))
