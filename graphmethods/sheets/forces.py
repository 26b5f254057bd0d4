"""The force plans of one position: each group's polygon at one μ_F, and the results beside them.

For each Assur group, in the order they are solved (the last group first), the group's force
plan as the course draws it: the known forces laid head to tail (solid; the tangential parts
found first from the moments about the middle joint, the inertia forces, weights, the load, the
reactions of the groups solved before), closed by the unknowns (dashed) along their directions
(thin lines through the ends), and on it each link's own polygon closed by the inner reaction
(``R_12 + F_i2 + R_32 = 0``: R_12 and R_32 dashed between the group polygon's vertices); then the
crank's polygon closed by R_01. One scale μ_F for every
polygon, a convenient value picked to fit (reported). Beside them: every reaction's magnitude
and the balancing moment from the force plans, Zhukovsky's lever and the power balance, with
their differences in per cent.

>>> from graphmethods.problems import builtin
>>> s = force_plans(builtin.case("press"), position=3, notation="ru")
>>> s.title
'Планы сил, положение 3'
>>> sorted(e.name for e in s.elements if e.name.startswith("closing-"))[:2]
['closing-0-0', 'closing-0-1']
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.problems.reference_cases import title_of
from graphmethods.scene import Element, Line, Page, Scale, Scene, Table, Text, Vector, markup, notation as get_notation
from graphmethods.scene.notation import Notation
from graphmethods.scene.numbers import round_off_zero
from graphmethods.scene.primitives import THIN
from graphmethods.scene.scale import pick_scale
from graphmethods.sheets import force_working as FW
from graphmethods.sheets.force_fit import arm_lines, drawn_tip
from graphmethods.sheets.force_linkage import (  # noqa: F401  (LINK, plates: used by force_sheet_plans through here)
    LINK,
    ToMm,
    _directions,
    _drawn,
    _guide_ends,
    _linkage,
    _links_of,
    _moment_arc,
    clear_direction,
    plates,
)
from graphmethods.sheets.force_panels import lever_texts, scheme_texts
from graphmethods.sheets.force_slides import column_texts as _column, fills_slide, plan_caption, slide_column, wrapped
from graphmethods.sheets.force_symbols import force_symbol as _markup  # moved down: force_working uses it too
from graphmethods.sheets.layout import TEXT_MM, Occupancy, Sheet, given_scale

SMALL_MM = 2.8
TABLE_MM = 3.2

def analysed(case, *, position: int | None, phi_deg: float | None, m: int, gravity: bool = False):
    """The force analysis a force figure draws and the index of its position in it: position
    ``position`` of 0…m (default 2), or the one crank angle ``phi_deg`` (degrees) when given."""
    from graphmethods.dynamics.forces import case_forces

    if phi_deg is not None:
        return case_forces(case, phi_deg=[float(phi_deg)], gravity=gravity), 0
    k = 2 if position is None else position
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or not 0 <= int(k) <= m:
        raise InputError(f"position {position!r}: give a position number 0…{m}")
    return case_forces(case, m=m, gravity=gravity), int(k)


def percent_text(d: float, nt: Notation) -> str:
    """A difference of two balancing moments in per cent, as a course project prints it: three
    decimals (round-off, some 1e-14 %, prints 0.000 on every machine), the notation's decimal mark."""
    text = f"{abs(d):.3f}"
    return text.replace(".", nt.decimal)


def _inner_sides(poly, inner, pts: np.ndarray, i: int) -> list:
    """The sides of a link's own polygon (the inner reaction's: ``R_12 + F_i2 + R_32 = 0``) not already drawn
    in its group's polygon, laid on that polygon: the first force they share is made to coincide, so the
    inner reaction closes between two of the group polygon's vertices, as the books draw it. Each side is
    ``((label, F), z_start, z_end)`` in N (complex). None when the two share no force after the first side.

    >>> from graphmethods.problems import builtin
    >>> from graphmethods.dynamics.forces import case_forces
    >>> pl = case_forces(builtin.case("press"), m=12).plans[0]
    >>> pts = np.cumsum([0j] + [complex(F[3]) for _, F in pl.polygons[0].known]
    ...                 + [complex(F[3]) for _, _, F in pl.polygons[0].closing])
    >>> [lbl for (lbl, _), _, _ in _inner_sides(pl.polygons[0], pl.polygons[1], pts, 3)]
    ['R_12', 'R_32']
    """
    main = [lbl for lbl, _ in poly.known]
    drawn = set(main) | {lbl for lbl, _, _ in poly.closing}
    sides = [(lbl, F) for lbl, F in inner.known] + [(lbl, F) for lbl, _, F in inner.closing]
    for q, (lbl, _) in enumerate(sides):
        if q > 0 and lbl in main:
            z = complex(pts[main.index(lbl)]) - sum(complex(F[i]) for _, F in sides[:q])
            out = []
            for lb, F in sides:
                z1 = z + complex(F[i])
                if lb not in drawn:
                    out.append(((lb, F), z, z1))
                z = z1
            return out
    return []


Box = tuple[float, float, float, float]
#: a label to place: the point it belongs to (mm), its text, its element name
LabelSpec = tuple[tuple[float, float], str, str]


@dataclass(frozen=True)
class ForceFigureLayout:
    """The millimetre constants of a force figure: the drawing area left of a column of texts.

    >>> PLANS_LAYOUT.within((10.0, 20.0, 110.0, 90.0))
    (6.0, 18.0, 114.0, 94.0)
    """

    left_mm: float = 4.0            # the drawing area's inset from the content box's left side
    top_mm: float = 4.0             # ... below the sheet's top (the title's line)
    bottom_mm: float = 8.0          # ... above the scale captions' baseline
    column_gap_mm: float = 6.0      # the drawing area, the split, the text column: this apart
    reach_mm: float = 4.0           # labels may leave the drawing area by this much
    reach_top_mm: float = 4.0       # ... and upward by this much
    text_pitch_mm: float = 6.0      # line pitch of the text column
    text_mm: float = TEXT_MM        # the text column's size, and on a slide (force_slides.slide_column) its
    column_share: float | None = None   # statements wrapped to this share of the width, this much more between
    paragraph_mm: float = 0.0       # two of them, and the scales fitted together as on a course sheet
    fitted: bool = False
    head_mm: float = 2.5            # arrowheads
    min_mm: float = 0.3             # a shorter vector is not drawn
    largest_force_mm: float = 30.0  # the largest force's length (lever, scheme)
    margin_mm: float = 34.0         # room kept round the linkage (the lever) for its forces
    plan_gap_mm: float = 8.0        # between two force plans side by side
    row_gap_mm: float = 10.0        # between two rows of force plans (the lower row's captions)
    overhang_mm: float = 6.0        # a direction line beyond the ends of its side
    caption_rise_mm: float = 4.0    # a plan's caption above the drawing area
    row_mm: float = 6.0             # table rows
    results_gap_mm: float = 7.0     # the results under the table
    moment_mm: float = 6.0          # radius of a moment's arc
    balance_mm: float = 9.0         # radius of M_b's arc at the crank's centre

    def within(self, area: Box) -> Box:
        """Where the labels of a drawing in ``area`` may go."""
        return (area[0] - self.reach_mm, area[1] - self.reach_top_mm, area[2] + self.reach_mm,
                area[3] + self.reach_mm)


PLANS_LAYOUT = ForceFigureLayout(left_mm=2.0, top_mm=8.0, bottom_mm=10.0, reach_top_mm=2.0, text_pitch_mm=5.6)
LEVER_LAYOUT = ForceFigureLayout(largest_force_mm=28.0, margin_mm=32.0)
SCHEME_LAYOUT = ForceFigureLayout()


# ----------------------------------------------------------------------------- shared steps

def title_text(nt: Notation, family: str, i: int, phi_deg: float | None) -> str:
    """A force figure's title: ``family`` (plans, lever, scheme, sheet) in position ``i`` or at ``phi_deg``.

    >>> title_text(get_notation("ru"), "plans", 3, None), title_text(get_notation("en"), "lever", 0, 30.0)
    ('Планы сил, положение 3', "Zhukovsky's lever with every force, φ = 30°")
    """
    if phi_deg is None:
        return nt.word(f"forces.{family}_title", k=i)
    return nt.word(f"forces.{family}_title_phi", phi=nt.number(float(phi_deg), sig=5))


def _sheet(case: Any, nt: Notation, family: str, i: int, phi_deg: float | None, *, page: Any, title: str | None,
           title_block: bool) -> Sheet:
    """The A3 sheet a force figure is drawn on (unless ``page``), with its title."""
    return Sheet(nt=nt, page=page, title=title or title_text(nt, family, i, phi_deg), problem=title_of(case),
                 title_block=title_block, default_page=Page("A3", "landscape", frame=True))


def _split(sheet: Sheet, column_mm: float, L: ForceFigureLayout) -> tuple[float, Box]:
    """Where the text column (``column_mm`` wide) begins, and the drawing area left of it."""
    x0, _, x1, _ = sheet.box
    split = x1 - column_mm - L.column_gap_mm
    return split, (x0 + L.left_mm, sheet.top + L.top_mm, split - L.column_gap_mm, sheet.caption_y - L.bottom_mm)


def _arranged(sheet: Sheet, texts: Sequence[str], L: ForceFigureLayout,
              fit: Callable[[Box], tuple[Scale, ToMm]]) -> tuple[Box, list[Element], Scale, ToMm]:
    """The drawing area, the texts, the scale and the map of a figure drawn by ``fit``: the texts in a column
    beside the drawing (right) or in lines above it, whichever draws it larger (beside it on a tie: a
    tall region, such as the A1 sheet's left column, gets its texts above).

    Raises
    ------
    InputError
        When the drawing fits neither (a given scale too small): the error of the column beside it.
    """
    x0, _, x1, _ = sheet.box
    names, texts = wrapped(texts, L, x1 - x0)
    split, beside = _split(sheet, max(markup.text_width_mm(t, L.text_mm) for t in texts), L)
    tall = _column(texts, 0.0, 0.0, L, names=names)[-1].at[1] + L.text_pitch_mm + L.reach_top_mm   # n pitches
    above = (x0 + L.left_mm, sheet.top + 2.0 + tall, x1 - L.left_mm, sheet.caption_y - L.bottom_mm)
    options: list[tuple[float, int, Box, tuple[float, float], Scale, ToMm]] = []
    error: InputError | None = None
    for n_o, (area, corner) in enumerate(((beside, (split + 2.0, sheet.top + 2.0)),
                                          (above, (x0 + L.left_mm, sheet.top + 2.0)))):
        if min(area[2] - area[0], area[3] - area[1]) <= 2 * L.margin_mm + 10.0:
            continue                                  # the texts leave no room for a drawing beside them
        try:
            s_l, at = fit(area)
        except InputError as e:
            error = error or e
            continue
        options.append((s_l.per_mm, n_o, area, corner, s_l, at))
    if not options:
        raise error or InputError("the figure's texts leave no room for its drawing on this page; give a larger page")
    _, _, area, (tx, ty), s_l, at = min(options, key=lambda o: (o[0], o[1]))
    return area, list[Element](_column(texts, tx, ty, L, names=names)), s_l, at


def _finish(sheet: Sheet, els: list[Element], scales: tuple[Scale, ...], legend: str, name: str) -> Scene:
    """The scale captions and the legend under the drawing, and the finished scene."""
    els += sheet.captions(scales, legend=legend, reserve=True)
    return sheet.scene(els, scales, name=name, notes=tuple(s.note for s in scales if s.note))


def _fit(cloud: np.ndarray, area: Box, L: ForceFigureLayout, mu_l: Any, nt: Notation, what: str) -> tuple[Scale, ToMm]:
    """μ_l for the points ``cloud`` (m, complex) to fit ``area`` with ``L.margin_mm`` round them for the
    forces, and the map from a point (m) to the page (mm) centring them."""
    room_x, room_y = area[2] - area[0] - 2 * L.margin_mm, area[3] - area[1] - 2 * L.margin_mm
    span = max(float(np.ptp(cloud.real)) * room_y / room_x, float(np.ptp(cloud.imag)), 1e-12)
    s_l = (pick_scale(span, room_y, symbol="μ_l", unit=nt.unit("m")) if mu_l is None
           else given_scale(mu_l, "μ_l", nt.unit("m"), span, room_y, what=what))
    cx = (area[0] + area[2]) / 2 - (float(cloud.real.min()) + float(cloud.real.max())) / 2 / s_l.per_mm
    cy = (area[1] + area[3]) / 2 + (float(cloud.imag.min()) + float(cloud.imag.max())) / 2 / s_l.per_mm

    def at(z: complex) -> tuple[float, float]:
        return (cx + z.real / s_l.per_mm, cy - z.imag / s_l.per_mm)

    return s_l, at


def _scaled(sheet: Sheet, texts: Sequence[str], L: ForceFigureLayout, cloud: np.ndarray,
            arrows: Sequence[tuple[complex, complex]], mu_l: Any, mu_F: Any, nt: Notation, what: str,
            page: Any) -> tuple[Box, list[Element], Scale, Scale, ToMm]:
    """The drawing area, the texts, μ_l, μ_F and the map of a drawing of ``cloud`` (m) carrying ``arrows``
    ((point m, force N)). On a course sheet (A1, A2) with neither scale given, both are chosen together
    so the drawing and its forces fill the area (:func:`~graphmethods.sheets.force_fit.fit_forces`);
    otherwise μ_F draws the largest force ``L.largest_force_mm`` long and μ_l fits the drawing with
    ``L.margin_mm`` round it."""
    from graphmethods.sheets.force_fit import fit_forces

    if _on_course(page, mu_l, mu_F) or (L.fitted and mu_l is None and mu_F is None):
        picked: dict[Box, Scale] = {}

        def fit(box: Box) -> tuple[Scale, ToMm]:
            s_l, picked[box], at = fit_forces(list(cloud), arrows, box, nt, pad_mm=lettering_pad(page))
            return s_l, at

        area, column, s_l, at = _arranged(sheet, texts, L, fit)
        return area, column, s_l, picked[area], at
    s_F = given_scale(mu_F, "μ_F", nt.unit("N"), max(abs(F) for _, F in arrows), L.largest_force_mm,
                      what=f"the largest force on {what}")
    area, column, s_l, at = _arranged(sheet, texts, L, lambda box: _fit(cloud, box, L, mu_l, nt, what))
    return area, column, s_l, s_F, at


def _on_course(page: Any, mu_l: Any, mu_F: Any) -> bool:
    """A force figure drawn into a course sheet (A1, A2) with its scales left to it: its scales are fitted
    together, a force too short to draw is drawn at the least arrow, the lever's arms are drawn."""
    from graphmethods.sheets.engine.lettering import is_course_sheet

    return mu_l is None and mu_F is None and page is not None and is_course_sheet(page)


def lettering_pad(page: Any) -> float:
    """The room (mm) kept round a drawing for its labels: two label heights of the page's lettering."""
    from graphmethods.sheets.engine.lettering import lettering

    return 2.0 * lettering(page).label_mm


#: where a label goes when nothing beside its point is free, with a leader: the rings of
#: :meth:`~graphmethods.sheets.layout.Occupancy.place_label_with_leader` (above the point, then below), then,
#: where a dense figure (a lever's images, a plan's lines of action) leaves them taken, farther out every 15°
_UP, _DOWN = (45, 135, 20, 160, 65, 115, 90, 0, 180), (315, 225, 340, 200, 295, 245, 270)
LEADER_RINGS = (tuple((r, side) for side in (_UP, _DOWN) for r in (8.0, 12.0, 16.0, 21.0, 28.0, 36.0, 48.0))
                + tuple((r, tuple(range(0, 360, 15))) for r in (10.0, 14.0, 18.0, 24.0, 32.0, 40.0, 56.0, 64.0)))


def _label(occ: Occupancy, where: tuple[float, float], text: str, name: str, *, within: Box) -> list[Element]:
    """A label beside its point, or further off with a leader line (:data:`LEADER_RINGS`) when nothing beside it
    is free; set over the ink, beside the point, only when no ring has room."""
    lab = occ.first_free(where, text, ("ne", "nw", "se", "sw", "n", "s", "e", "w"), (1.2, 3.2), SMALL_MM, within)
    leader = None
    if lab is None:
        found = next((f for r, angles in LEADER_RINGS
                      if (f := occ.try_leaders(where, text, r, angles, size_mm=SMALL_MM, within=within)) is not None),
                     None)
        lab, leader = found if found is not None else (occ.place_label(where, text, ("ne",), size_mm=SMALL_MM), None)
    else:
        occ.add_label(lab)
    out: list[Element] = [Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, name=name)]
    if leader is not None:
        out.append(Line(leader[0], leader[1], style=THIN, name=f"leader-{name}"))
    return out


def _labels(occ: Occupancy, specs: Sequence[LabelSpec], within: Box) -> list[Element]:
    """Every label of ``specs`` placed in turn (each keeps off the ones before)."""
    return [el for where, text, nm in specs for el in _label(occ, where, text, nm, within=within)]


# ----------------------------------------------------------------------------- the force plans

def _plans_results(fa: Any, i: int, nt: Notation, gravity: bool) -> tuple[list[tuple[str, str]], list[str]]:
    """The table of reactions (rows) and the lines of M_b by the three methods beside the force plans."""
    rows = [(nt.word("forces.pair"), nt.quantity("|R|", "N"))]
    big = max([float(abs(r.R[i])) for r in fa.reactions.values()] + [0.0])
    for key, r in sorted(fa.reactions.items(), key=lambda kv: (len(kv[0]), kv[0])):
        rows.append((_markup(key), nt.number(round_off_zero(float(abs(r.R[i])), big), sig=5)))
    Mb = float(fa.M_balance[i])
    M_b = nt.sym("forces.M_b")
    res_lines = [f"{nt.word('forces.Mb_plans', Mb=M_b)} = {nt.number(Mb, sig=6)} {nt.unit('N·m')}"]
    for key, other in (("lever", fa.M_balance_lever), ("power", fa.M_balance_power)):
        d = float(fa.difference_percent(other)[i])
        value = f"{nt.number(float(other[i]), sig=6)} {nt.unit('N·m')}"
        res_lines.append(f"{nt.word('forces.Mb_' + key, Mb=M_b)} = {value}")
        res_lines.append(f"    {nt.word('forces.diff')} {percent_text(d, nt)} %")
    if gravity:
        res_lines.append(nt.word("forces.weights"))
    return rows, res_lines


def _polygon(poly: Any, i: int) -> np.ndarray:
    """The vertices of a group's force polygon (N, complex): the known forces end to end, then the unknowns."""
    pts = [0j]
    for _, F in poly.known:
        pts.append(pts[-1] + complex(F[i]))
    for _, _, F in poly.closing:
        pts.append(pts[-1] + complex(F[i]))
    return np.array(pts)


def _plans_scale(paths: Sequence[np.ndarray], pw: float, ph: float, mu_F: Any, nt: Notation) -> Scale:
    """One μ_F for every polygon, each in its ``pw`` × ``ph`` mm cell."""
    need = max(max(float(np.ptp(p.real)) / pw, float(np.ptp(p.imag)) / ph) for p in paths)
    if need <= 0:
        raise InputError("every force is zero in this position; there is no force plan to draw")
    biggest = max(max(float(np.ptp(p.real)), float(np.ptp(p.imag) * pw / ph)) for p in paths)
    return given_scale(mu_F, "μ_F", nt.unit("N"), biggest, pw - 2.0, what="the force plans")


def _grid(paths: Sequence[np.ndarray], area: Box, L: ForceFigureLayout, mu_F: Any,
          nt: Notation) -> tuple[int, float, float, Scale]:
    """How the force plans share ``area``: the number of columns (the rows follow), each cell's width and
    height, mm, and the one μ_F, chosen to draw them largest (one row when that is as large). Long flat
    polygons, such as a slider-crank's, go one under the other rather than side by side.

    Raises
    ------
    InputError
        When no arrangement fits (every force zero, a given μ_F too small): one row's error.

    Examples
    --------
    >>> flat = [np.array([0, 100 + 1j, 200]), np.array([0, 150 + 0.5j])]
    >>> cols, pw, ph, s_F = _grid(flat, (0.0, 0.0, 208.0, 100.0), PLANS_LAYOUT, None, get_notation("en"))
    >>> cols, pw, ph, s_F.per_mm
    (1, 208.0, 45.0, 1.0)
    """
    n_p = len(paths)
    best: tuple[float, int, float, float, Scale] | None = None
    error: InputError | None = None
    for cols in range(n_p, 0, -1):
        rows = -(-n_p // cols)
        pw = (area[2] - area[0] - L.plan_gap_mm * (cols - 1)) / cols
        ph = (area[3] - area[1] - L.row_gap_mm * (rows - 1)) / rows
        if pw <= 2.0 or ph <= 0:
            continue
        try:
            s_F = _plans_scale(paths, pw, ph, mu_F, nt)
        except InputError as e:
            error = error or e
            continue
        if best is None or s_F.per_mm < best[0] * (1 - 1e-9):
            best = (s_F.per_mm, cols, pw, ph, s_F)
    if best is None:
        raise error or InputError("the force plans have no room on this page; give a larger page")
    return best[1], best[2], best[3], best[4]


def _cell(pts: np.ndarray, cell: Box, s_F: Scale) -> ToMm:
    """The map from the polygon's plane (N) to the page (mm) centring it in ``cell`` (left, top, width, height)."""
    left, top, pw, ph = cell
    lo = np.array([pts.real.min(), pts.imag.min()]) / s_F.per_mm
    hi = np.array([pts.real.max(), pts.imag.max()]) / s_F.per_mm
    cx = left + pw / 2 - (lo[0] + hi[0]) / 2
    cy = top + ph / 2 + (lo[1] + hi[1]) / 2

    def at(z: complex) -> tuple[float, float]:
        return (cx + z.real / s_F.per_mm, cy - z.imag / s_F.per_mm)

    return at


def _group_plan(j: int, pl: Any, pts: np.ndarray, i: int, at: ToMm, nt: Notation, occ: Occupancy,
                L: ForceFigureLayout) -> tuple[list[Element], list[LabelSpec]]:
    """Group ``j``'s force polygon: the known sides (solid), the unknown ones (dashed) with their lines of
    action, each link's own polygon closed by the inner reaction; and the labels its sides want."""
    poly = pl.polygons[0]
    els: list[Element] = []
    labels: list[LabelSpec] = []
    sides = [(lbl, True, None) for lbl, _F in poly.known] + [(lbl, False, dirs) for lbl, dirs, _F in poly.closing]
    for s, (lbl, known, direction) in enumerate(sides):
        a, b = at(complex(pts[s])), at(complex(pts[s + 1]))
        kind = "known" if known else "closing"
        if math.dist(a, b) >= L.min_mm:
            v = _drawn(occ, Vector(a, b, known=known, head_length_mm=L.head_mm,
                                   name=f"{kind}-{j}-{s - (0 if known else len(poly.known))}"))
            els.append(v)
            labels.append((v.mid, _markup(lbl, nt), f"label-{j}-{s}"))
        if direction is not None:
            u = complex(direction[i])
            e = np.array([u.real, -u.imag])
            A, B = np.array(a), np.array(b)
            far = tuple((B + L.overhang_mm * e).tolist()) if math.dist(a, b) >= L.min_mm else \
                tuple((A + L.overhang_mm * e).tolist())
            els.append(_drawn(occ, Line(tuple((A - L.overhang_mm * e).tolist()), far, style=THIN,
                                        name=f"direction-{j}-{s}")))
    for t, inner in enumerate(pl.polygons[1:]):
        for (lbl, _F), z0, z1 in _inner_sides(poly, inner, pts, i):
            a, b = at(z0), at(z1)
            if math.dist(a, b) >= L.min_mm:
                v = _drawn(occ, Vector(a, b, known=False, head_length_mm=L.head_mm, name=f"inner-{j}-{t}-{lbl}"))
                els.append(v)
                labels.append((v.mid, _markup(lbl, nt), f"label-inner-{j}-{t}-{lbl}"))
    return els, labels


def force_plans(case: Any, position: int | None = None, *, phi_deg: float | None = None, m: int = 12,
                gravity: bool = False, mu_F: Any = None, notation: Any = "en", page: Any = None,
                title: str | None = None, title_block: bool = True, name: str = "force-plans") -> Scene:
    """The force plans of every group and of the crank in one position (see the module docstring).

    Parameters
    ----------
    case : Case
        A problem file (``builtin.case("shaper")``).
    position : int, optional
        Position 0…m (default 2); or ``phi_deg``, the crank angle in degrees.
    gravity : bool
        Add the weights.
    mu_F : float or Scale, optional
        N per mm of every polygon; a convenient value is picked to fit when not given.
    notation : {"en", "ru", "zh"}

    Raises
    ------
    InputError
        A position outside 0…m, or a given μ_F at which a polygon does not fit.
    """
    L = PLANS_LAYOUT
    nt = get_notation(notation)
    fa, i = analysed(case, position=position, phi_deg=phi_deg, m=m, gravity=gravity)
    sheet = _sheet(case, nt, "plans", i, phi_deg, page=page, title=title, title_block=title_block)
    rows, res_lines = _plans_results(fa, i, nt, gravity)   # the table beside the plans sets the column
    probe = Table((0.0, 0.0), tuple(rows), align="cr", size_mm=TABLE_MM, row_height_mm=L.row_mm)
    split, area = _split(sheet, max([probe.width_mm] + [markup.text_width_mm(t, TEXT_MM) for t in res_lines]), L)
    paths = [_polygon(pl.polygons[0], i) for pl in fa.plans]
    cols, pw, ph, s_F = _grid(paths, area, L, mu_F, nt)
    els: list[Element] = [sheet.header()]
    labels: list[LabelSpec] = []
    for j, (pl, pts) in enumerate(zip(fa.plans, paths)):
        left = area[0] + (j % cols) * (pw + L.plan_gap_mm)
        top = area[1] + (j // cols) * (ph + L.row_gap_mm)
        cap = (nt.word("forces.crank", g=pl.links[0]) if pl.group.startswith("I ")
               else nt.word("forces.group", g=pl.group))
        drawn, wanted = _group_plan(j, pl, pts, i, _cell(pts, (left, top, pw, ph), s_F), nt, sheet.occ, L)
        els.append(plan_caption(cap, (left, top, pw), drawn, L, f"caption-{j}"))
        els += drawn
        labels += wanted
    els += _labels(sheet.occ, labels, L.within(area))
    tx = split + 2.0
    table = Table((tx, sheet.top + 2.0), tuple(rows), align="cr", size_mm=TABLE_MM, row_height_mm=L.row_mm,
                  name="table")
    els.append(table)
    els += _column(res_lines, tx, table.bottom_left[1] + L.results_gap_mm, L, prefix="result")
    return _finish(sheet, els, (s_F,), nt.word("forces.plans_legend"), name)


# ----------------------------------------------------------------------------- Zhukovsky's lever

def zhukovsky_forces(case: Any, position: int | None = None, *, phi_deg: float | None = None, m: int = 12,
                     gravity: bool = False, mu_l: Any = None, mu_F: Any = None, notation: Any = "en",
                     page: Any = None, title: str | None = None, title_block: bool = True,
                     name: str = "zhukovsky-forces", layout: ForceFigureLayout | None = None) -> Scene:
    """Zhukovsky's lever with every force of the force analysis (inertia forces, couples as pairs of
    forces, weights, the load) at the images of their points, and the balancing force F_b at the
    image of the crank pin; M_b = F_b·l_{{OA}} beside the force plans' value.

    The plan of analogues v/ω₁ (m) turned 90° counterclockwise is drawn to μ_l (m per mm), the
    forces to μ_F (N per mm); both picked as convenient values when not given.

    Examples
    --------
    >>> from graphmethods.problems import builtin
    >>> s = zhukovsky_forces(builtin.case("four-bar"), position=2)
    >>> [e.name for e in s.elements if e.name == "F_b"]
    ['F_b']
    """
    from graphmethods.scene import Point

    L = slide_column(layout or LEVER_LAYOUT, page) if fills_slide(page, mu_l, mu_F) else layout or LEVER_LAYOUT
    nt = get_notation(notation)
    fa, i = analysed(case, position=position, phi_deg=phi_deg, m=m, gravity=gravity)
    mo, lev = fa.motion, fa.lever
    sheet = _sheet(case, nt, "lever", i, phi_deg, page=page, title=title, title_block=title_block)
    texts, working = lever_texts(fa, i, nt), (FW.lever_working(fa, i, nt) if _on_course(page, mu_l, mu_F) else [])
    fixed = set(mo.linkage.ground)
    images = {p: 1j * complex(mo.v_[p][i]) / mo.omega_1 for p in mo.points if p not in fixed}
    items = [(f.label, complex(f.image[i]), complex(f.F[i])) for f in lev.forces if abs(f.F[i]) > 0]
    items.append(("F_b", complex(lev.image_pin[i]), complex(lev.F_balance[i])))
    cloud = np.array([0j] + list(images.values()) + [z for _, z, _ in items])
    try:                                                # the moment equation when the panel has room for it
        area, column, s_l, s_F, at = _scaled(sheet, texts + working, L, cloud, [(w, F) for _, w, F in items],
                                             mu_l, mu_F, nt, "the lever", page)
    except InputError:
        if not working:
            raise
        area, column, s_l, s_F, at = _scaled(sheet, texts, L, cloud, [(w, F) for _, w, F in items], mu_l, mu_F,
                                             nt, "the lever", page)
    occ = sheet.occ
    pole = at(0j)
    els: list[Element] = [sheet.header(), _drawn(occ, Point(pole, radius_mm=0.7, name="pole"))]
    els += [_drawn(occ, Line(pole, at(z), style=THIN, name=f"ray-{p}")) for p, z in images.items()
            if abs(z) / s_l.per_mm >= L.min_mm]
    vec_labels: list[LabelSpec] = []
    course = _on_course(page, mu_l, mu_F)
    for j, (label, z, F) in enumerate(items):
        a = at(z)
        b, _ = drawn_tip(a, F, s_F, least=course)
        els.append(_drawn(occ, Vector(a, b, known=True, head_length_mm=L.head_mm,
                                      name="F_b" if label == "F_b" else f"force-{j}")))
        els += [_drawn(occ, Line(p, q, style=THIN, name=f"arm-{j}-{k}"))
                for k, (p, q) in enumerate(arm_lines(pole, a, b, within=area) if course and label[0] != "M" else [])]
        vec_labels.append((b, _markup(label, nt), f"label-force-{j}"))
    names = [(at(z), markup.lowered_digits(p.lower() if len(p) == 1 else p[0].lower() + p[1:]), f"image-{p}")
             for p, z in images.items()]
    els += _labels(occ, [(pole, "p", "label-pole"), *names, *vec_labels], L.within(area))
    els += column
    return _finish(sheet, els, (s_l, s_F), nt.word("forces.lever_legend"), name)


# ----------------------------------------------------------------------------- the forces on the linkage

def _applied(forces: Sequence[tuple[str, complex, complex, float]], at: ToMm, s_F: Scale, nt: Notation,
             occ: Occupancy, L: ForceFigureLayout,
             around: Callable[[complex], list[float]], *,
             least: bool = False) -> tuple[list[Element], list[LabelSpec]]:
    """Each applied force drawn to μ_F from its point (``least``: one too short to draw at the least arrow,
    :func:`~graphmethods.sheets.force_fit.drawn_tip`); each moment as an arc in its sense, on the side of its
    point away from the links there (``around``) and its force; their labels."""

    els: list[Element] = []
    labels: list[LabelSpec] = []
    n_f = 0                                    # the forces drawn (one too short to draw is left out)
    for label, F, where, M in forces:
        start = at(where)
        if abs(F) / s_F.per_mm >= (0.0 if least else L.min_mm) and abs(F) > 0.0:
            tip, _ = drawn_tip(start, F, s_F, least=least)        # too short to draw to scale: the least arrow
            els.append(_drawn(occ, Vector(start, tip, head_length_mm=L.head_mm, name=f"force-{n_f}")))
            n_f += 1
            labels.append((tip, f"{_markup(label, nt)} = {nt.number(abs(F), sig=4)} {nt.unit('N')}",
                           f"label-{label}"))
        if M != 0.0:
            mlabel = "M" + label[1:] if label.startswith("F") else label
            avoid = around(where) + ([math.degrees(cmath.phase(F))] if abs(F) > 0 else [])
            arc = _drawn(occ, _moment_arc(start, L.moment_mm, 100.0 if M > 0 else -100.0, avoid,
                                          name=f"moment-{mlabel}"))
            els.append(arc)
            mid = math.radians(clear_direction(avoid))
            labels.append(((start[0] + L.moment_mm * math.cos(mid), start[1] - L.moment_mm * math.sin(mid)),
                           f"{_markup(mlabel, nt)} = {nt.number(M, sig=4)} {nt.unit('N·m')}", f"label-{mlabel}"))
    return els, labels


def force_scheme(case: Any, position: int | None = None, *, phi_deg: float | None = None, m: int = 12,
                 gravity: bool = False, mu_l: Any = None, mu_F: Any = None, notation: Any = "en", page: Any = None,
                 title: str | None = None, title_block: bool = True, name: str = "force-scheme",
                 layout: ForceFigureLayout | None = None) -> Scene:
    """The linkage in one position with every applied force: the inertia forces at the centres of
    mass, the weights (``gravity``), the working load, each drawn to μ_F from its point; the
    inertia and load moments as arcs in their sense; the balancing moment on the crank. The
    scheme is drawn to μ_l (m per mm); both scales convenient values picked to fit.

    Examples
    --------
    >>> from graphmethods.problems import builtin
    >>> s = force_scheme(builtin.case("press"), position=3)
    >>> sorted(e.name for e in s.elements if e.name.startswith("force-"))
    ['force-0', 'force-1', 'force-2']
    """

    L = layout or SCHEME_LAYOUT
    nt = get_notation(notation)
    fa, i = analysed(case, position=position, phi_deg=phi_deg, m=m, gravity=gravity)
    mo = fa.motion
    sheet = _sheet(case, nt, "scheme", i, phi_deg, page=page, title=title, title_block=title_block)
    Mb = float(fa.M_balance[i])
    texts = scheme_texts(fa, i, nt)
    z = {p: complex(mo.z[p][i]) for p in mo.points}
    forces = [(f.label, complex(f.F[i]), complex(f.at[i]), float(f.M[i])) for fs in fa.applied.values() for f in fs]
    F_max = max([abs(F) for _, F, _, _ in forces] + [0.0])
    M_size = F_max * float(max(np.ptp(np.real(list(z.values()))), np.ptp(np.imag(list(z.values())))))
    forces = [(lbl, F, at_, round_off_zero(M, M_size)) for lbl, F, at_, M in forces]
    if F_max == 0.0:
        raise InputError("no force acts in this position; there is nothing to draw")
    cloud = np.array(list(z.values()) + _guide_ends(mo, _links_of(mo, i)[1], i))
    area, column, s_l, s_F, at = _scaled(sheet, texts, L, cloud, [(w, F) for _, F, w, _ in forces], mu_l, mu_F, nt,
                                         "the scheme", page)
    occ = sheet.occ
    els: list[Element] = [sheet.header(), *_linkage(mo, i, z, at, occ, area)]
    labels: list[LabelSpec] = [(at(z[p]), markup.lowered_digits(p), f"point-{p}") for p in sorted(z)]
    segs, _blocks = _links_of(mo, i)

    pivots = [z[p] for p in mo.linkage.ground]

    def around(w: complex) -> list[float]:
        """The links at ``w``, and a fixed pivot's symbol (below it)."""
        below = [240.0, 270.0, 300.0] if any(abs(w - q) <= 1e-12 for q in pivots) else []
        return _directions(w, z, segs) + below

    drawn, wanted = _applied(forces, at, s_F, nt, occ, L, around, least=_on_course(page, mu_l, mu_F))
    els += drawn
    labels += wanted
    cr = mo.linkage.crank
    # the labels keep off M_b's arc and its name
    centre = at(z[cr.centre])
    els.append(_drawn(occ, _moment_arc(centre, L.balance_mm, 110.0 if Mb > 0 else -110.0, around(z[cr.centre]),
                                       name="M_b")))
    mid = math.radians(clear_direction(around(z[cr.centre])))     # its name placed as every label is
    labels.append(((centre[0] + L.balance_mm * math.cos(mid), centre[1] - L.balance_mm * math.sin(mid)),
                   nt.sym("forces.M_b"), "label-M_b"))
    els += _labels(occ, labels, L.within(area))
    els += column
    return _finish(sheet, els, (s_l, s_F), nt.word("forces.scheme_legend"), name)
