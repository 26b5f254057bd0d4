"""The A1 / A2 dynamic-analysis sheet of a course project: M_d, M_r(φ) over ΔT(φ), J_e turned 90° over
the energy–mass diagram, the result and the ordinates (split out of :mod:`graphmethods.sheets.wittenbauer`,
whose diagram it draws; ``sheets.dynamic_analysis_sheet`` is this function)."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from graphmethods.dynamics.study import Study
from graphmethods.dynamics.wittenbauer import WittenbauerResult
from graphmethods.errors import InputError
from graphmethods.scene import Line, Page, Scale, Scene, Table, Text, markup, notation as get_notation, pick_scale
from graphmethods.scene.elements import Element, Group, label_bbox, make_label
from graphmethods.scene.notation import Notation
from graphmethods.scene.primitives import MAIN, Label, walk
from graphmethods.sheets.dynamics import (
    SMALL_MM,
    TEXT_MM,
    TWO_PI,
    CurveSpec,
    DrawnMoments,
    as_study,
    delta_T_curve,
    drawn_moments,
    fine_angles,
    given_angle_scale,
    given_scale,
    inertia_curve,
    phi_graph_elements,
    problem_text,
    turned_inertia_elements,
    value_text,
)
from graphmethods.sheets.engine.lettering import lettered, lettered_by_page
from graphmethods.sheets.frame import SheetFrame
from graphmethods.sheets.layout import Occupancy
from graphmethods.sheets.styles import PROJECTION
from graphmethods.sheets.wittenbauer import (
    TABLE_MM,
    DiagramData,
    _place_table,
    _table,
    bold_bbox,
    diagram_data,
    diagram_elements,
    inertia_origin,
    inertia_scale,
    offset_origin,
    result_rows,
    suppressed_zero,
    wide_rows,
)

# ----------------------------------------------------------------------------- 2. the A1 / A2 sheet

def _sheet_page(page) -> Page:
    if isinstance(page, Page):
        return page
    size = str(page).upper()
    if size not in ("A1", "A2", "A3"):
        raise InputError(f"page {page!r}: the dynamic-analysis sheet is drawn on A1 or A2 (or A3, tight)")
    return Page(size, "landscape", margins_mm=(10.0, 10.0, 10.0, 20.0), frame=True)


@lettered_by_page("A1")
def dynamic_analysis_sheet(study, *, page="A1", mu_J=None, mu_T=None, mu_M=None, mu_phi=None,
                           tangents: str = "exact", notation="en", title=None, title_block: bool = True,
                           name: str = "dynamic-analysis") -> Scene:
    """The dynamic-analysis sheet of a course project: flywheel by the Wittenbauer method, on A1 or A2.

    Left: the reduced moments M_d, M_r(φ) above ΔT(φ) (one φ scale, positions aligned).
    Right: J_e(φ) turned 90° above the energy–mass diagram, sharing its J_e scale; ΔT levels
    are projected horizontally from the ΔT graph and J_e values vertically from the turned
    graph, meeting at the numbered points of the curve. μ_J is picked for the diagram: its
    J axis (0…J_e max, so that k and l lie on the ordinate axis) over the width left between the
    graphs and the result table. Both rays run inside the diagram's own frame, from the
    ordinate axis (k, l) to just past the curve, with ψ_max and ψ_min marked; k, l and kl are
    dimensioned; the result table gives δ, ω_m, the scales, kl, J_F, the positions of ω_max and
    ω_min, the error estimate and O1 (named off the sheet unless it falls in the frame).

    Only the positions, velocity plans, J_e, M_r and ΔT at the m positions are computed
    (never the exact motion).

    Parameters
    ----------
    study : Study or Case
    page : {"A1", "A2"} or Page
        Landscape with a frame and a title block.
    mu_J, mu_T, mu_M, mu_phi : float or Scale, optional
        Scales (kg·m²/mm, J/mm, N·m/mm, rad/mm); picked to fill the sheet when not given.
    tangents : {"exact", "textbook"}

    Examples
    --------
    >>> import pathlib
    >>> from graphmethods.dynamics.study import Study
    >>> from graphmethods.kinematics import read_case
    >>> st = Study(read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json"))
    >>> s = dynamic_analysis_sheet(st, page="A2")
    >>> (s.page.size, s.page.orientation), "exact" in st.computed
    (('A2', 'landscape'), False)
    """
    study = as_study(study)
    nt = get_notation(notation)
    sheet = SheetFrame(nt=nt, page=None, title=title or nt.word("wittenbauer.dynamic_analysis"),
                       problem=problem_text(study, nt), title_block=title_block, default_page=_sheet_page(page))
    if mu_J is None and mu_T is None and mu_M is None and mu_phi is None:
        mu_phi, mu_M, mu_T, mu_J = common_scales(study, page=page, tangents=tangents, title_block=title_block)
    content, lay = _placed_content(sheet, _sheet_content(study, nt, tangents), nt, mu_J=mu_J, mu_T=mu_T, mu_M=mu_M,
                                   mu_phi=mu_phi)
    res = lay.result(content)
    occ = sheet.occ
    proj = _projection_lines(content, lay, res)          # the thinnest, under everything
    # the graphs' labels and tick values are placed before the projection lines are known to the occupancy:
    # the lines are broken at every text (_broken_at_texts), so a value is never dropped for one of them
    diag, turned, M_els, T_els = _sheet_graphs(sheet, content, lay, res, nt)
    occ.register(*proj)
    O1_drawn = any(e.name == "D-point-O1" for e in diag)    # else its coordinates are in the table
    rows = wide_rows(result_rows(res, nt, extra=_extra_rows(nt, content.moments, lay.s_M, lay.s_phi),
                                 on_sheet=O1_drawn, J_0=lay.J_0))
    w = _table(rows, (0, 0), size_mm=lay.table_mm).width_mm
    x1 = sheet.box[2]
    cands = [(x1 - w, y) for y in np.arange(sheet.top, sheet.caption_y - 60.0, 5.0)]
    table = _place_table(occ, rows, cands, size_mm=lay.table_mm, head_mm=8.0)      # its heading clear too
    occ.add_box((table.at[0], table.at[1] - 8.0, table.at[0] + w, table.at[1]))
    ordinates = _ordinates_table(occ, content, nt, x1, table.at[1] + table.height_mm + 14.0, sheet.caption_y, w)
    heads = _sheet_headings(sheet, content, lay, nt)
    table_head = Text((table.at[0], table.at[1] - 2.0), nt.word("wittenbauer.result"), size_mm=TEXT_MM + 0.8,
                      bold=True, name="heading-result")
    scales = (lay.s_phi, lay.s_M, lay.s_T, lay.s_J)
    # every scale is stated once, in the result table (μ_M, μ_φ, μ_J, μ_T beside their names): no captions line
    others = [sheet.header()] + M_els + T_els + turned + diag + heads + [table_head, table] + ordinates
    elements = _broken_at_texts(proj, others) + others
    J_0 = lay.J_0
    notes = tuple(s.note or f"given: {s.caption()}" for s in scales) + (
        f"J_F = {res.J_F:.6g} kg·m² from kl = {res.kl_mm:.6g} mm" + (f" and J_0 = {J_0:g} kg·m²" if J_0 else ""),)
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name, notes=notes)


def sheet_scales(study, *, page="A1", tangents: str = "exact") -> tuple[Scale, Scale, float]:
    """μ_J, μ_T and J_0 of the energy–mass diagram of ``study``'s dynamic-analysis sheet: the scales its
    construction is drawn and measured at (tan ψ, k, l, kl), the same in every language, which the slides,
    the HTML stepper and ``study --json`` use so that they print the sheet's numbers.

    Examples
    --------
    >>> from graphmethods.problems import builtin
    >>> s_J, s_T, J_0 = sheet_scales(Study(builtin.case("press"), positions=12))
    >>> s_J.per_mm, s_T.per_mm, J_0
    (0.001, 2.5, 0.5)
    """
    _, lay = _default_placement(study, page=page, tangents=tangents)
    return lay.s_J, lay.s_T, lay.J_0


def sheet_construction(study, *, page="A1", tangents: str = "exact") -> dict[str, float]:
    """The numbers of the dynamic-analysis sheet's energy–mass construction, as ``study --json`` reports them
    (``"sheet"``): μ_J (kg·m²/mm), μ_T (J/mm), J_0 (kg·m²), tan ψ_max, tan ψ_min, kl (mm) and J_F (kg·m²).

    Examples
    --------
    >>> from graphmethods.problems import builtin
    >>> c = sheet_construction(Study(builtin.case("press"), positions=12))
    >>> c["mu_J"], c["mu_T"], round(c["kl_mm"], 1), round(c["J_F"], 2)
    (0.001, 2.5, 217.6, 13.28)
    """
    content, lay = _default_placement(study, page=page, tangents=tangents)
    res = lay.result(content)
    return {"mu_J": lay.s_J.per_mm, "mu_T": lay.s_T.per_mm, "J_0": lay.J_0, "tan_psi_max": float(res.tan_psi_max),
            "tan_psi_min": float(res.tan_psi_min), "kl_mm": float(res.kl_mm), "J_F": float(res.J_F)}


def _default_placement(study, *, page, tangents: str) -> tuple[SheetContent, SheetPlacement]:
    """The content and placement of the sheet with every scale picked (:func:`common_scales`: the same in every
    language)."""
    study = as_study(study)
    mu_phi, mu_M, mu_T, mu_J = common_scales(study, page=page, tangents=tangents)
    return _placement_in(study, "en", page=page, tangents=tangents, title_block=True, mu_J=mu_J, mu_T=mu_T,
                         mu_M=mu_M, mu_phi=mu_phi)


def _placement_in(study, code: str, *, page, tangents: str, title_block: bool, **scales: object
                  ) -> tuple[SheetContent, SheetPlacement]:
    """The content and placement of the sheet in language ``code`` with the ``scales`` given (None: picked)."""
    return _Placer(study, code, page=page, tangents=tangents, title_block=title_block).placed(**scales)


class _Placer:
    """The sheet's frame and content in one language, placed at any scales asked (the content computed once)."""

    def __init__(self, study, code: str, *, page, tangents: str, title_block: bool) -> None:
        self.nt = nt = get_notation(code)
        self.page = page if hasattr(page, "size") else str(page).upper()
        with lettered(self.page):
            self.sheet = SheetFrame(nt=nt, page=None, title=nt.word("wittenbauer.dynamic_analysis"),
                                    problem=problem_text(study, nt), title_block=title_block,
                                    default_page=_sheet_page(page))
        self.content = _sheet_content(study, nt, tangents)

    def placed(self, **scales: object) -> tuple[SheetContent, SheetPlacement]:
        with lettered(self.page):
            return _placed_content(self.sheet, self.content, self.nt, **scales)

    def fits(self, mu_phi: float, mu_M: float, mu_T: float, mu_J: float) -> bool:
        try:
            return self.placed(mu_phi=mu_phi, mu_M=mu_M, mu_T=mu_T, mu_J=mu_J)[1].fits
        except InputError:
            return False


#: the languages of a sheet: its scales are the same in all of them
SHEET_LANGUAGES = ("en", "ru", "zh")


def common_scales(study, *, page="A1", tangents: str = "exact", title_block: bool = True
                  ) -> tuple[float, float, float, float]:
    """μ_φ (rad/mm), μ_M (N·m/mm), μ_T (J/mm) and μ_J (kg·m²/mm) of the dynamic-analysis sheet in every language.

    A sheet's room differs with its language (the ГОСТ and GB title blocks, the width of the result table), and
    one problem is drawn to one set of scales unless its text truly does not fit: of the sets the sheet picks in
    en, ru and zh, the one that fits every language, picked by the most languages and, of those, drawing largest
    (the least product of the scales); when none fits all, each scale the largest of the three (each room grows
    as the other scales grow, so that set fits).

    >>> from graphmethods.problems import builtin
    >>> common_scales(Study(builtin.case("press"), positions=12))[2:]
    (2.5, 0.001)
    """
    study = as_study(study)
    placers = [_Placer(study, code, page=page, tangents=tangents, title_block=title_block)
               for code in SHEET_LANGUAGES]
    chosen: list[tuple[float, float, float, float]] = []
    for placer in placers:
        lay = placer.placed(mu_J=None, mu_T=None, mu_M=None, mu_phi=None)[1]
        chosen.append((lay.s_phi.per_mm, lay.s_M.per_mm, lay.s_T.per_mm, lay.s_J.per_mm))
    picked = list(dict.fromkeys(chosen))
    if len(picked) == 1:
        return picked[0]
    for sc in sorted(picked, key=lambda v: (-chosen.count(v), float(np.sum(np.log(v))))):
        if all(placer.fits(*sc) for placer in placers):
            return sc
    return (max(v[0] for v in picked), max(v[1] for v in picked), max(v[2] for v in picked),
            max(v[3] for v in picked))


def _placed_content(sheet: SheetFrame, content: SheetContent, nt: Notation, **scales: object
                    ) -> tuple[SheetContent, SheetPlacement]:
    """The content with its ΔT range where the ordinate axis stands, and its placement: the result table
    lettered at 5 mm when the room its width takes leaves the diagram's scale as at the smallest lettering."""
    def placed(content: SheetContent, table_mm: float) -> tuple[SheetContent, SheetPlacement]:
        if suppressed_zero(content.J_lo, content.J_to):     # the origin the placement takes, whatever its scales
            content = content.with_origin(inertia_origin(content.J_lo, content.J_to))
        lay = _sheet_placement(sheet, content, nt, table_mm=table_mm, **scales)  # type: ignore[arg-type]
        for _ in range(3):                               # k and l where the ordinate axis stands: the ΔT range
            if lay.J_0 == 0.0 or content.J_0 == lay.J_0:
                break
            content = content.with_origin(lay.J_0)
            lay = _sheet_placement(sheet, content, nt, table_mm=table_mm, **scales)  # type: ignore[arg-type]
        return content, lay

    try:
        small: tuple[SheetContent, SheetPlacement] | InputError = placed(content, RESULT_SIZES_MM[-1])
    except InputError as e:             # given scales that need the room beside the title block a wide table leaves
        small = e
    for size in RESULT_SIZES_MM[:-1]:
        try:
            large = placed(content, size)
        except InputError:
            continue
        same = isinstance(small, InputError) or \
            (large[1].s_J.per_mm, large[1].J_0) == (small[1].s_J.per_mm, small[1].J_0)
        if same and large[1].fits and sheet.top + large[1].table_h_mm + 10.0 <= _title_block_top(sheet):
            return large
    if isinstance(small, InputError):
        raise small
    return small


def _title_block_top(sheet: SheetFrame) -> float:
    """The top of the title block (the bottom of the frame when there is none), mm."""
    clip = sheet.probe.inner_box()
    if sheet.probe.title_block is None:
        return clip[3]
    return float(sheet.probe.title_block.table(clip[2], clip[3]).at[1])


def _title_block_left(sheet: SheetFrame) -> float:
    """The left edge of the title block (the right of the frame when there is none), mm."""
    clip = sheet.probe.inner_box()
    if sheet.probe.title_block is None:
        return clip[2]
    return float(sheet.probe.title_block.table(clip[2], clip[3]).at[0])


#: the lettering of the result table, largest first: 5 mm (values on A1) when the diagram keeps its scale, else
#: the A4 figure's table lettered up to 3.5 mm
RESULT_SIZES_MM = (5.0, TABLE_MM)


def _broken_at_texts(lines: list[Element], others: list[Element], gap_mm: float = 0.6) -> list[Element]:
    """Thin projection lines broken where they would run through a text (a draftsman stops a thin line at the
    text and goes on past it): each line becomes a group of its pieces, under the same name."""
    boxes = np.array([label_bbox(p) for e in others for p in walk(e.primitives()) if isinstance(p, Label)],
                     dtype=float).reshape(-1, 4)
    boxes += np.array([-gap_mm, -gap_mm, gap_mm, gap_mm])
    out: list[Element] = []
    for e in lines:
        if not isinstance(e, Line) or not len(boxes):
            out.append(e)
            continue
        p, q = np.asarray(e.start, dtype=float), np.asarray(e.end, dtype=float)
        cuts = [iv for iv in (_clip_interval(p, q, b) for b in boxes) if iv is not None]
        if not cuts:
            out.append(e)
            continue
        keep, t = [], 0.0
        for a, b in sorted(cuts):
            if a > t:
                keep.append((t, a))
            t = max(t, b)
        keep.append((t, 1.0))
        length = float(np.hypot(*(q - p)))
        pieces = tuple(replace(e, start=tuple(p + (q - p) * a), end=tuple(p + (q - p) * b), name=f"{e.name}-{i}")
                       for i, (a, b) in enumerate(k for k in keep if (k[1] - k[0]) * length > 0.3))
        out.append(Group(elements=pieces, name=e.name))
    return out


def _clip_interval(p: np.ndarray, q: np.ndarray, box: np.ndarray) -> tuple[float, float] | None:
    """The parameters (t0, t1) ⊂ [0, 1] of the part of p→q inside a box (Liang–Barsky), or None."""
    d = q - p
    t0, t1 = 0.0, 1.0
    for dk, lo, hi, pk in ((d[0], box[0], box[2], p[0]), (d[1], box[1], box[3], p[1])):
        if abs(dk) < 1e-12:
            if pk < lo or pk > hi:
                return None
            continue
        a, b = (lo - pk) / dk, (hi - pk) / dk
        t0, t1 = max(t0, min(a, b)), min(t1, max(a, b))
    return (t0, t1) if t1 > t0 else None


@dataclass(frozen=True)
class DynamicSheetLayout:
    """The millimetre constants of the A1/A2 dynamic-analysis sheet (see :func:`dynamic_analysis_sheet`)."""

    graphs_left_mm: float = 22.0          # the φ graphs' ordinate axes from the frame
    turned_axis_mm: float = 14.0          # the turned J_e graph's J axis below the top of the drawing
    diagram_bottom_mm: float = 10.0       # the diagram's lowest level above the captions
    under_turned_mm: float = 22.0         # under the turned graph's φ axis: arrow, name, gap
    min_diagram_mm: float = 40.0          # the least height of the diagram
    graphs_share: float = 0.36            # the longest φ axis, as a share of the sheet's width
    M_below_mm: float = 4.0               # the M graph's φ axis above the level of the turned graph's end (its
    #                                       numbers clear of the ΔT graph's heading)
    M_top_mm: float = 16.0                # the M graph's top below the top of the drawing
    graphs_gap_mm: float = 12.0           # right of the φ graphs
    diagram_gap_mm: float = 40.0          # between the φ graphs and the diagram's ordinate axis
    table_gap_mm: float = 12.0            # between the J axis's name and the result table
    J_name_extra_mm: float = 10.0         # beside the J axis's name
    heading_mm: float = TEXT_MM + 0.8     # the size of the headings over the parts


LAYOUT = DynamicSheetLayout()


@dataclass(frozen=True)
class SheetContent:
    """What the sheet draws, in physical units: the positions, the fine curves, the drawn moments."""

    data: DiagramData
    phi: np.ndarray                       # fine angles, rad
    J_fine: np.ndarray                    # J_e at them, kg·m²
    dT_fine: np.ndarray                   # ΔT at them, J
    moments: DrawnMoments
    J_lo: float
    J_to: float
    T_lo: float
    T_hi: float
    J_0: float = 0.0                      # where the ordinate axis stands, kg·m² (the T range's k and l)

    def with_origin(self, J_0: float) -> SheetContent:
        """The content with its ΔT range (J) from the data, the fine curve and k, l on the ordinate axis at J_0."""
        _, T_hi, T_lo = self.data.extent(J_0)
        return replace(self, T_lo=min(T_lo, float(self.dT_fine.min())), T_hi=max(T_hi, float(self.dT_fine.max())),
                       J_0=J_0)


def _sheet_content(study: Study, nt: Notation, tangents: str) -> SheetContent:
    """Positions, velocity plans, J_e, M_r and ΔT at the m positions and between them (never the exact motion)."""
    data = diagram_data(study, tangents=tangents, notation=nt)
    phi = fine_angles(study.m)
    J_fine = inertia_curve(study, phi).J_e
    dT_fine = delta_T_curve(study, phi)
    content = SheetContent(data, phi, J_fine, dT_fine, drawn_moments(study, nt),
                           J_lo=float(min(data.J_e.min(), J_fine.min())),
                           J_to=float(max(data.J_e.max(), J_fine.max())), T_lo=0.0, T_hi=0.0)
    return content.with_origin(0.0)


@dataclass(frozen=True)
class SheetPlacement:
    """The scales of the sheet and where its parts stand (page mm)."""

    s_phi: Scale
    s_M: Scale
    s_T: Scale
    s_J: Scale
    J_0: float          # where the J axes start, kg·m² (0, or a suppressed zero)
    x_L: float          # the φ graphs' ordinate axes
    x_a: float          # the diagram's ordinate axis (and the turned graph's φ axis)
    y_Jt: float         # the turned graph's J axis
    y_M0: float         # the M graph's φ axis
    y0_T: float         # the level ΔT = 0 (the ΔT graph's φ axis and the diagram's J axis)
    d_top: float        # the diagram's top
    table_mm: float = TABLE_MM   # the result table's lettering (lettered up to 3.5 mm on A1)
    table_h_mm: float = 0.0  # and its height (without the O_1 row's variants)
    fits: bool = True        # the diagram, its J axis's name and the table fit across (else the table moves down)

    def result(self, content: SheetContent) -> WittenbauerResult:
        """The construction at these scales, with its ordinate axis at J_0."""
        res = content.data.result(self.s_J.per_mm, self.s_T.per_mm)
        return offset_origin(res, self.J_0) if self.J_0 > 0.0 else res


def _phi_scale(sheet: SheetFrame, content: SheetContent, nt: Notation, mu_phi: object, mu_T: object,
               diagram_room: Callable[[float], float], lay: DynamicSheetLayout = LAYOUT) -> Scale:
    """μ_φ: given, or the one that leaves the diagram largest, then draws the graphs largest."""
    W = sheet.box[2] - sheet.box[0]
    T_span = content.T_hi - content.T_lo
    if mu_phi is not None:
        return given_angle_scale(mu_phi, nt.sym("mu_phi"), TWO_PI,
                                 min(diagram_room(0.0) - lay.min_diagram_mm, lay.graphs_share * W))
    best = None
    for c in (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 10.0):
        L = 360.0 / c
        room = diagram_room(L)
        if L > lay.graphs_share * W or room < lay.min_diagram_mm:
            continue
        tall = T_span / (pick_scale(T_span, room).per_mm if mu_T is None else
                         (mu_T.per_mm if isinstance(mu_T, Scale) else float(mu_T)))  # type: ignore[arg-type]
        if best is None or tall * L > best[0] * (1 + 1e-9):     # the diagram's height × the graphs' length
            best = (tall * L, c)
    if best is None:
        raise InputError(f"the sheet {sheet.probe.size} is too small for the dynamic-analysis layout; "
                         f"use A1 or A2")
    return Scale(nt.sym("mu_phi"), "rad", math.radians(best[1]), alt_per_mm=best[1], alt_unit="°",
                 note=f"picked: {best[1]:g}°/mm draws the graphs and the energy–mass diagram largest together")


def _sheet_placement(sheet: SheetFrame, content: SheetContent, nt: Notation, *, mu_J: object, mu_T: object,
                     mu_M: object, mu_phi: object, table_mm: float = TABLE_MM,
                     lay: DynamicSheetLayout = LAYOUT, beside_title_block: bool = True) -> SheetPlacement:
    """The scales and the places of the parts: [M graph | turned J_e graph] over [ΔT graph | diagram].

    μ_J fits the diagram's content to the width beside the graphs: 0…J_e max, or, for a J_e that
    varies little about a large mean, J_0…J_e max from a round J_0 below J_e min (a suppressed
    zero); the rays keep their true slopes and are clipped to the diagram's own frame.

    The graphs and the diagram run down beside the title block (``beside_title_block``) when the diagram and
    its J axis's name end left of it (the result table stands over the block) and that draws some ordinates
    (M, ΔT, J_e) larger; else down to its top.
    """
    x0, _, x1, _ = sheet.box
    y_Jt = sheet.top + lay.turned_axis_mm
    bottom = sheet.probe.inner_box()[3] - (sheet.box[1] - sheet.probe.inner_box()[1]) - 1.0
    d_bottom = (bottom if beside_title_block else sheet.caption_y) - lay.diagram_bottom_mm

    def diagram_room(L_phi: float) -> float:
        return d_bottom - (y_Jt + L_phi + lay.under_turned_mm)

    s_phi = _phi_scale(sheet, content, nt, mu_phi, mu_T, diagram_room, lay)
    L_phi = s_phi.to_mm(TWO_PI)
    d_top = y_Jt + L_phi + lay.under_turned_mm
    s_T = given_scale(mu_T, nt.sym("mu_T"), nt.unit("J"), content.T_hi - content.T_lo, d_bottom - d_top,
                      what="the ΔT axis")
    dm = content.moments
    s_M = given_scale(mu_M, nt.sym("mu_M"), nt.unit("N·m"), dm.hi - dm.lo,
                      y_Jt + L_phi - lay.M_below_mm - (sheet.top + lay.M_top_mm), what="the moment graph")
    x_L = x0 + lay.graphs_left_mm
    left_end = x_L + L_phi + lay.graphs_gap_mm
    probe_rows = wide_rows(result_rows(content.data.result(1.0, 1.0), nt, extra=_extra_rows(nt, dm, s_M, s_phi),
                                       J_0=1.0 if suppressed_zero(content.J_lo, content.J_to) else 0.0))
    probe_table = _table(probe_rows, (0, 0), size_mm=table_mm)
    table_w = probe_table.width_mm
    J_label_w = markup.text_width_mm(nt.quantity(nt.sym("dynamics.J_e"), f"10⁻³ {nt.unit('kg·m²')}"),
                                     SMALL_MM + 0.5) + lay.J_name_extra_mm      # the name a small J_e takes
    room_J = x1 - table_w - lay.table_gap_mm - J_label_w - (left_end + lay.diagram_gap_mm)
    s_J, J_0 = inertia_scale(mu_J, nt, content.J_lo, content.J_to, room_J)
    # the ordinate axis: the width the scale's rounding leaves over is shared on both sides of the diagram
    x_a_min = left_end + lay.diagram_gap_mm
    x_a_max = x1 - table_w - lay.table_gap_mm - J_label_w - s_J.to_mm(content.J_to - J_0)
    x_a = max(x_a_min, (x_a_min + x_a_max) / 2)
    if beside_title_block and sheet.probe.title_block is not None:
        over = x_a + s_J.to_mm(content.J_to - J_0) + J_label_w > _title_block_left(sheet)
        try:
            above = _sheet_placement(sheet, content, nt, mu_J=mu_J, mu_T=mu_T, mu_M=mu_M, mu_phi=mu_phi,
                                     table_mm=table_mm, lay=lay, beside_title_block=False)
        except InputError:      # given scales that need the room beside the block
            if over:
                raise
        else:                   # beside the block only when it draws some ordinates larger, not the φ axes alone
            if over or (above.s_M.per_mm, above.s_T.per_mm, above.s_J.per_mm) == (s_M.per_mm, s_T.per_mm,
                                                                                    s_J.per_mm):
                return above
    return SheetPlacement(s_phi, s_M, s_T, s_J, J_0, x_L=x_L, x_a=x_a, y_Jt=y_Jt,
                          y_M0=y_Jt + L_phi - lay.M_below_mm - s_M.to_mm(-dm.lo), y0_T=d_top + s_T.to_mm(content.T_hi),
                          d_top=d_top, table_mm=table_mm, table_h_mm=probe_table.height_mm,
                          fits=x_a_max >= x_a_min)


def _projection_lines(content: SheetContent, lay: SheetPlacement, res: WittenbauerResult) -> list[Element]:
    """ΔT levels projected across from the ΔT graph, J_e values down from the turned graph, to the curve."""
    J_k, dT_k, phi_k = content.data.J_e, content.data.delta_T, content.data.phi
    s_phi, s_T, s_J = lay.s_phi, lay.s_T, lay.s_J
    proj: list[Element] = []
    m = len(phi_k) - 1
    for k in range(0, m, max(1, math.ceil(m / 36))):        # every position (every n-th when m is large)
        at_T = (lay.x_L + s_phi.to_mm(float(phi_k[k] - phi_k[0])), lay.y0_T - s_T.to_mm(float(dT_k[k])))
        at_D = (lay.x_a + float(res.x_mm[k]), lay.y0_T - float(res.y_mm[k]))
        at_J = (lay.x_a + s_J.to_mm(float(J_k[k]) - lay.J_0), lay.y_Jt + s_phi.to_mm(float(phi_k[k] - phi_k[0])))
        proj.append(Line(at_T, at_D, style=PROJECTION, name=f"projection-T-{k}"))
        proj.append(Line(at_J, at_D, style=PROJECTION, name=f"projection-J-{k}"))
    return proj


def _sheet_graphs(sheet: SheetFrame, content: SheetContent, lay: SheetPlacement, res: WittenbauerResult,
                  nt: Notation) -> tuple[list[Element], list[Element], list[Element], list[Element]]:
    """The diagram (first: its rays and labels take precedence), the turned J_e graph, the M and ΔT graphs."""
    occ = sheet.occ
    x0 = sheet.box[0]
    clip = sheet.probe.inner_box()
    avoid: tuple[tuple[float, float, float, float], ...] = ()
    if sheet.probe.title_block is not None:
        tb = sheet.probe.title_block.table(clip[2], clip[3])
        avoid = ((x0 - 20.0, tb.at[1], clip[2], clip[3]),)
    data, dm, m = content.data, content.moments, len(content.data.phi) - 1
    phi_k = data.phi
    diag = diagram_elements(res, origin=(lay.x_a, lay.y0_T), nt=nt, occ=occ, clip=clip, avoid=avoid,
                            J_to=content.J_to, T_hi=content.T_hi, T_lo=content.T_lo, within=sheet.box, prefix="D-",
                            y_top_mm=lay.s_T.to_mm(content.T_hi) + 4.0, own_frame=True, J_from=lay.J_0)
    turned = turned_inertia_elements(origin=(lay.x_a, lay.y_Jt), s_J=lay.s_J, s_phi=lay.s_phi, m=m, phi=content.phi,
                                     J=content.J_fine, phi_k=phi_k, J_k=data.J_e, nt=nt, occ=occ, J_to=content.J_to,
                                     prefix="J-", within=sheet.box, J_from=lay.J_0)
    within_left = (x0, sheet.top, lay.x_a - 10.0, sheet.caption_y - 6.0)
    M_els = phi_graph_elements(origin=(lay.x_L, lay.y_M0), s_phi=lay.s_phi, s_Y=lay.s_M, m=m, phi_k=phi_k,
                               curves=list(dm.curves), nt=nt, occ=occ, y_from=dm.lo, y_to=dm.hi, axis_level=0.0,
                               y_label=nt.quantity(nt.sym("M"), "N·m"), dots=dm.dots, prefix="M-",
                               within=within_left)
    dT = content.dT_fine
    T_els = phi_graph_elements(origin=(lay.x_L, lay.y0_T), s_phi=lay.s_phi, s_Y=lay.s_T, m=m, phi_k=phi_k,
                               curves=[CurveSpec("dT", content.phi, dT, MAIN, "")], nt=nt, occ=occ,
                               y_from=min(float(dT.min()), 0.0), y_to=max(float(dT.max()), 0.0),
                               axis_level=0.0, y_label=nt.quantity(nt.sym("dynamics.dT"), "J"),
                               dots=(phi_k, data.delta_T), prefix="T-", within=within_left)
    return diag, turned, M_els, T_els


def _sheet_headings(sheet: SheetFrame, content: SheetContent, lay: SheetPlacement, nt: Notation,
                    size: float = LAYOUT.heading_mm) -> list[Element]:
    """Small bold headings over the four parts, each moved to the nearest place where it covers nothing."""
    occ = sheet.occ
    heads: list[Element] = []
    M_hi, dT_hi = content.moments.hi, max(float(content.dT_fine.max()), 0.0)
    for key, text, at in (("M", f"{nt.word('dynamics.moment_graph')} {nt.sym('M_d')}(φ), {nt.sym('M_r')}(φ)",
                           (lay.x_L + 10.0, lay.y_M0 - lay.s_M.to_mm(M_hi) - 8.0)),
                          ("T", f"{nt.word('dynamics.delta_T_graph')} {nt.sym('dynamics.dT')}(φ)",
                           (lay.x_L + 10.0, lay.y0_T - lay.s_T.to_mm(dT_hi) - 12.0)),
                          ("J", turned_heading(nt),
                           (lay.x_a + 10.0, lay.y_Jt - 9.0)),
                          ("D", nt.word("wittenbauer.wittenbauer"), (lay.x_a + 12.0, lay.d_top - 6.0))):
        lab = _free_heading(occ, at, text, size, sheet.box)
        occ.add_box(bold_bbox(lab))
        heads.append(Text((lab.x, lab.y), text, size_mm=size, bold=True, name=f"heading-{key}"))
    return heads


def turned_heading(nt: Notation) -> str:
    """The heading of the turned J_e graph: the quantity's name and symbol, then how it is turned
    ("Reduced moment of inertia J_e(φ), turned 90°": never the symbol after "turned 90°").

    >>> from graphmethods.scene import notation
    >>> turned_heading(notation("en")), turned_heading(notation("ru"))
    ('Reduced moment of inertia J_e(φ), turned 90°', 'Приведённый момент инерции J_п(φ) (повёрнут на 90°)')
    """
    name, turned = nt.word("dynamics.inertia_graph"), nt.word("wittenbauer.inertia_turned")
    J = f"{nt.sym('dynamics.J_e')}(φ)"
    if turned.startswith(name):
        return f"{name} {J}{turned[len(name):]}"
    return f"{turned} {J}"


def _free_heading(occ: Occupancy, at: tuple[float, float], text: str, size: float,
                  within: tuple[float, float, float, float]) -> Label:
    """A bold label near ``at`` free of everything; else of texts and boxes (thin lines may cross it)."""
    for lines in (True, False):
        for dx in (0.0, -10.0, -20.0, -40.0, -60.0, -80.0, -100.0, 10.0, 20.0, 40.0):
            for dy in (0.0, -4.0, 4.0, -8.0, 8.0, -12.0, 12.0):
                trial = make_label((at[0] + dx, at[1] + dy), text, size_mm=size, bold=True)
                if occ.is_free(bold_bbox(trial), within=within, lines=lines):
                    return trial
    return make_label(at, text, size_mm=size, bold=True)


def _ordinates_table(occ: Occupancy, content: SheetContent, nt: Notation, right: float, top: float,
                     bottom: float, width_mm: float = 0.0) -> list[Element]:
    """The course sheet's table of ordinates: per position k, φ, the drawn moment, ΔT and J_e, under the
    result (what the graphs were drawn from), with its heading; nothing when no place is free."""
    data, dm = content.data, content.moments
    key = "M_d" if dm.constant_key == "M_r" else "M_r"
    head = ("k", nt.quantity("φ", "°"), nt.quantity(nt.sym(key), "N·m"), nt.quantity(nt.sym("dynamics.dT"), "J"),
            nt.quantity(nt.sym("dynamics.J_e"), "kg·m²"))
    moment = dm.dots[1]
    M_ref, T_ref = float(np.abs(moment).max()), float(np.abs(data.delta_T).max())     # round-off is written 0
    # each column with one number of decimals, as a table is printed (0,05500 under 0,05178, not 0,055)
    columns = (nt.column(np.degrees(np.asarray(data.phi, dtype=float) - float(data.phi[0])), sig=4),
               nt.column(np.asarray(moment, dtype=float), sig=4, reference=M_ref),
               nt.column(np.asarray(data.delta_T, dtype=float), sig=4, reference=T_ref),
               nt.column(np.asarray(data.J_e, dtype=float), sig=4))
    rows = [head] + [(str(k), *(col[k] for col in columns)) for k in range(len(data.phi))]
    heading = nt.word("wittenbauer.ordinates")
    for size in ORDINATE_SIZES_MM:          # the largest lettering whose table fits the room under the result
        # as wide as the result (the columns share what the texts leave), rows as tall as the room allows
        row_mm = min(ORDINATE_ROW_MAX_MM, max(2.0 * size, (bottom - top - 12.0) / len(rows)))
        probe = Table((0.0, 0.0), tuple(rows), align="rrrrr", size_mm=size, row_height_mm=row_mm, name="ordinates")
        widths = np.asarray(probe.column_widths(), dtype=float)
        if width_mm > widths.sum():
            spread = widths + (width_mm - widths.sum()) / len(widths)
            probe = replace(probe, col_widths_mm=tuple(float(c) for c in spread))
        w = max(probe.width_mm, markup.text_width_mm(heading, TEXT_MM + 0.8) * 1.1)    # the bold heading fits too
        h = probe.height_mm
        for y in np.arange(top, bottom - h, 5.0):
            box = (right - w, float(y), right, float(y) + h)
            if occ.is_free((box[0], box[1] - 10.0, box[2], box[3])):
                occ.add_box((box[0], box[1] - 10.0, box[2], box[3]))
                return [Text((box[0], box[1] - 2.0), heading, size_mm=TEXT_MM + 0.8, bold=True,
                             name="heading-ordinates"), replace(probe, at=(box[0], box[1]))]
    return []


#: the lettering of the table of ordinates, largest first (ГОСТ 2.304's series; 5 mm for values on A1)
ORDINATE_SIZES_MM = (5.0, 3.5)
#: the tallest row of the table of ordinates, mm
ORDINATE_ROW_MAX_MM = 12.0


def _extra_rows(nt, dm, s_M: Scale, s_phi: Scale) -> tuple:
    n = get_notation(nt).number
    mm = get_notation(nt).unit("mm")
    k = dm.constant_key
    return ((nt.word(f"wittenbauer.{k}"), f"{nt.sym(k)} = {value_text(nt, dm.constant, 'N·m')}"),
            (nt.word("wittenbauer.scale_M"), f"{nt.sym('mu_M')} = {n(s_M.per_mm)} {nt.unit('N·m')}/{mm}"),
            (nt.word("wittenbauer.scale_phi"), s_phi.caption(nt)))      # as captioned: rad/mm (°/mm)
