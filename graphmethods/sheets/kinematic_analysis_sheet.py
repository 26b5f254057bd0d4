"""The course project's first sheet: the kinematic analysis of a linkage, on A1.

Top left: the kinematic scheme in m positions (:func:`~graphmethods.sheets.kinematics.kinematic_scheme`);
top right: the velocity plans of every position (:func:`~graphmethods.sheets.kinematics.velocity_plan_grid`);
below: the acceleration plan of each chosen position with every construction line
(:func:`~graphmethods.sheets.acceleration.acceleration_plan`; by default two: the fullest plan of the
working stroke and the middle of the return stroke), and at the right the slider's kinematic diagrams
s(φ), v(φ), a(φ) when the linkage has a slider (:func:`~graphmethods.sheets.calculus.kinematic_diagrams`).
Each part keeps its own scales, written under it; the title block names the scheme's.

>>> from graphmethods.problems import builtin
>>> s = kinematic_analysis_sheet(builtin.case("press"))
>>> [e.name for e in s.elements][1:]
['scheme', 'velocity-plans', 'acceleration-plan-1', 'acceleration-plan-9', 'kinematic-diagrams']
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.problems.reference_cases import title_of
from graphmethods.scene import Page, Scale, Scene, Table, notation as get_notation
from graphmethods.scene.elements import Group
from graphmethods.sheets.composition import inset, region_page
from graphmethods.sheets.engine.lettering import lettered_by_page
from graphmethods.sheets.force_analysis_sheet import _case, sheet_page as _sheet_page
from graphmethods.sheets.layout import Sheet
from graphmethods.sheets.sheet_fill import clashes, filled

#: most acceleration plans one sheet draws (each needs a readable share of the lower row)
MAX_PLANS = 4


@dataclass(frozen=True)
class AnalysisSheetLayout:
    """The A1 sheet's divisions into its parts (shares of the content box, mm between the parts).

    Each share is a short list of candidates: the sheet draws its parts for each (row by row) and keeps
    the division whose drawings fill the most of the sheet (:func:`~graphmethods.sheets.sheet_fill.filled`):
    a long linkage takes a wide scheme, tall velocity plans a narrow one.
    """

    gap_mm: float = 8.0                 # between the parts
    #: the upper row (scheme, velocity plans) of the height
    upper_shares: tuple[float, ...] = (0.52, 0.58)
    #: the scheme of the upper row's width
    scheme_shares: tuple[float, ...] = (0.36, 0.45)
    #: the slider's diagrams (the table of velocities) of the lower row's width
    diagrams_shares: tuple[float, ...] = (0.4, 0.5)
    table_pad_mm: float = 4.0           # beside the table of velocities


ANALYSIS_SHEET_LAYOUT = AnalysisSheetLayout()


def _plan_positions(case: Any, m: int, plan_positions: Sequence[int] | None) -> list[int]:
    """The positions whose acceleration plans are drawn: given (checked) or :func:`default_plan_positions`."""
    if plan_positions is None:
        plan_positions = default_plan_positions(case, m)
    ks = list(plan_positions)
    if not 1 <= len(ks) <= MAX_PLANS:
        raise InputError(f"plan positions {ks!r}: give 1 to {MAX_PLANS} positions for the acceleration plans")
    for k in ks:
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or not 0 <= int(k) < m:
            raise InputError(f"plan position {k!r}: give position numbers 0…{m - 1}")
    if len(set(ks)) != len(ks):
        raise InputError(f"plan positions {ks!r}: each position once")
    return [int(k) for k in ks]


def default_plan_positions(case: Any, m: int = 12) -> tuple[int, int]:
    """Two positions whose acceleration plans the sheet draws: on the working stroke the one whose velocity
    plan is the fullest figure, and the middle position of the return stroke (extreme positions left out);
    a linkage without extreme positions: the quarter and three quarters of the turn.

    >>> from graphmethods.problems import builtin
    >>> default_plan_positions(builtin.case("press"))
    (1, 9)
    """
    from graphmethods.sheets.kinematics import fullest_position

    mech = case.mechanism
    pos = mech.positions(m=m)
    if pos.working is None or pos.extreme is None:
        return (m // 4, (3 * m) // 4)
    work = fullest_position(mech.velocity_plans(pos, omega_1=case.omega_m))
    back = [k for k in range(m) if not pos.working[k] and not pos.extreme[k]]
    if not back:
        back = [k for k in range(m) if k != work]
    return (int(work), int(back[len(back) // 2]))


@lettered_by_page("A1")
def kinematic_analysis_sheet(subject: Any, *, m: int = 12, plan_positions: Sequence[int] | None = None,
                             page: str | Page = "A1", notation: Any = "en", title: str | None = None,
                             title_block: bool = True, name: str = "kinematic-analysis") -> Scene:
    """The kinematic-analysis sheet (see the module docstring).

    Parameters
    ----------
    subject : Case or Study
        A linkage problem (``builtin.case("shaper")``).
    m : int
        Positions per turn (12 as the books draw them).
    plan_positions : sequence of int, optional
        The positions (0…m−1) whose acceleration plans are drawn, 1 to 4 of them; by default
        :func:`default_plan_positions`.
    page : "A1" or Page
        A1 landscape with a frame (A2 leaves the slider's diagrams and the acceleration plans too little
        room: refused).
    notation : {"en", "ru", "zh"}

    Raises
    ------
    InputError
        A plan position outside 0…m−1, repeated, more than four; a page other than A1.
    """
    case = _case(subject)
    nt = get_notation(notation)
    lay = ANALYSIS_SHEET_LAYOUT
    ks = _plan_positions(case, m, plan_positions)
    if not isinstance(page, Page) and str(page).upper() != "A1":
        raise InputError(f"page {page!r}: the kinematic-analysis sheet holds four parts (scheme, velocity plans, "
                         f"acceleration plans, the slider's diagrams) and is drawn on A1")
    pg = _sheet_page(page, "kinematic-analysis")
    sheet = Sheet(nt=nt, page=None, title=title or nt.word("kinematics.analysis"), problem=title_of(case),
                  title_block=title_block, default_page=pg)
    x0, _, x1, _ = sheet.box
    top, bottom = sheet.top, sheet.caption_y + 1.0
    best: tuple[tuple[int, int], list[tuple[Scene, str]]] | None = None
    for u in lay.upper_shares:
        split_y = top + u * (bottom - top)
        upper = _fullest([partial(_upper_row, case, nt, m, pg, (x0, top, x1, split_y), s, lay)
                          for s in lay.scheme_shares], pg)
        lower = _fullest([partial(_lower_row, case, nt, m, pg, (x0, split_y + lay.gap_mm, x1, bottom), ks, d, lay)
                          for d in lay.diagrams_shares], pg)
        if upper is None or lower is None:
            continue
        parts = upper[1] + lower[1]
        rank = (-clashes([sc for sc, _ in parts]) - _overflowing(parts), int((upper[2] | lower[2]).sum()))
        if best is None or rank > best[0]:
            best = (rank, parts)
    if best is None:                    # no division fits: the first one says why
        _upper_row(case, nt, m, pg, (x0, top, x1, top + lay.upper_shares[0] * (bottom - top)),
                   lay.scheme_shares[0], lay)
        _lower_row(case, nt, m, pg, (x0, top + lay.upper_shares[0] * (bottom - top) + lay.gap_mm, x1, bottom), ks,
                   lay.diagrams_shares[0], lay)
        raise InputError("the kinematic-analysis sheet's parts do not fit on this page; give a larger page")
    return _assembled(sheet, best[1], name)


def _fullest(candidates: list[Callable[[], list[tuple[Scene, str]]]],
             pg: Page) -> tuple[tuple[int, int], list[tuple[Scene, str]], np.ndarray] | None:
    """Of the candidate divisions of one row (each drawing its parts), the parts with the fewest clashing
    labels (:func:`~graphmethods.sheets.sheet_fill.clashes`) and parts leaving their region, whose ink fills
    the most cells of the sheet (the first of equals), with its rank (−faults, cells filled) and the cells it
    fills; None when none fits."""
    best: tuple[tuple[int, int], list[tuple[Scene, str]], np.ndarray] | None = None
    for draw in candidates:
        try:
            parts = draw()
        except InputError:              # too small a share for a part: the other candidates
            continue
        used = filled([sc for sc, _ in parts], pg)
        rank = (-clashes([sc for sc, _ in parts]) - _overflowing(parts), int(used.sum()))
        if best is None or rank > best[0]:
            best = (rank, parts, used)
    return best


def _overflowing(parts: list[tuple[Scene, str]]) -> int:
    """How many pairs of the parts overlap (a line of text too long for its region runs into the next part)."""
    boxes = [box for sc, nm in parts if (box := inset(sc, nm)[0].bbox()) is not None]
    out = 0
    for i, A in enumerate(boxes):
        out += sum(1 for B in boxes[i + 1:] if not (A[2] <= B[0] or B[2] <= A[0] or A[3] <= B[1] or B[3] <= A[1]))
    return out


def _upper_row(case: Any, nt: Any, m: int, pg: Page, box: tuple[float, float, float, float], share: float,
               lay: AnalysisSheetLayout) -> list[tuple[Scene, str]]:
    """The upper row: the kinematic scheme (``share`` of the width) and the velocity plans beside it."""
    from graphmethods.sheets.kinematics import kinematic_scheme, velocity_plan_grid

    x0, top, x1, split_y = box
    split_x = x0 + share * (x1 - x0)
    gap = lay.gap_mm
    s_scheme = kinematic_scheme(case, notation=nt, title_block=False, m=m,
                                page=region_page(pg, (x0, top, split_x - gap / 2, split_y)))
    s_vel = velocity_plan_grid(case, notation=nt, title_block=False, m=m,
                               page=region_page(pg, (split_x + gap / 2, top, x1, split_y)))
    return [(s_scheme, "scheme"), (s_vel, "velocity-plans")]


def _lower_row(case: Any, nt: Any, m: int, pg: Page, box: tuple[float, float, float, float], ks: list[int],
               share: float, lay: AnalysisSheetLayout) -> list[tuple[Scene, str]]:
    """The lower row: the acceleration plans of positions ``ks`` side by side, and at the right the slider's
    diagrams (``share`` of the width) or the tables (:func:`_right_part`)."""
    from graphmethods.sheets.acceleration import acceleration_plan

    x0, y0, x1, y1 = box
    gap = lay.gap_mm
    beside, right = _right_part(case, nt, m, pg, box, share, lay)
    w = (right - x0 - gap * (len(ks) - 1)) / len(ks)
    parts = []
    for j, k in enumerate(ks):
        left = x0 + j * (w + gap)
        cell = region_page(pg, (left, y0, left + w, y1))
        parts.append((acceleration_plan(case, k, notation=nt, title_block=False, m=m, page=cell),
                      f"acceleration-plan-{k}"))
    return parts + beside


def _right_part(case: Any, nt: Any, m: int, pg: Page, box: tuple[float, float, float, float], share: float,
                lay: AnalysisSheetLayout) -> tuple[list[tuple[Scene, str]], float]:
    """The lower row's right part: the slider's kinematic diagrams (their share of the width), or without a
    slider the tables of velocities and of accelerations per position, one above the other (as wide as they
    are); and where the acceleration plans end (mm). Nothing when neither can be drawn."""
    from graphmethods.sheets.acceleration import acceleration_table
    from graphmethods.sheets.calculus import kinematic_diagrams
    from graphmethods.sheets.kinematics import velocity_table

    x0, y0, x1, y1 = box
    left = x1 - share * (x1 - x0)
    try:
        return ([(kinematic_diagrams(case, notation=nt, title_block=False, m=m,
                                     page=region_page(pg, (left, y0, x1, y1))), "kinematic-diagrams")],
                left - lay.gap_mm)
    except InputError:                  # no slider: the tables in its place
        pass
    tables = ((velocity_table, "velocity-table"), (acceleration_table, "acceleration-table"))
    for n in (2, 1):
        h = (y1 - y0 - (n - 1) * lay.gap_mm) / n
        rows = [(y0 + i * (h + lay.gap_mm), y0 + i * (h + lay.gap_mm) + h) for i in range(n)]
        try:
            probes = [fn(case, notation=nt, title_block=False, m=m, page=region_page(pg, (left, a, x1, b)))
                      for (fn, _), (a, b) in zip(tables, rows)]
        except InputError:              # too wide or too long: one table, or none
            continue
        widths = [t.width_mm for p in probes for t in p.elements if isinstance(t, Table)]
        left = max(left, x1 - max(widths) - 2 * lay.table_pad_mm)
        return ([(fn(case, notation=nt, title_block=False, m=m, page=region_page(pg, (left, a, x1, b))), nm)
                 for (fn, nm), (a, b) in zip(tables, rows)], left - lay.gap_mm)
    return [], x1


def _assembled(sheet: Sheet, parts: list[tuple[Scene, str]], name: str) -> Scene:
    """The parts as insets of the sheet, each with its own scales and notes; the title block names the
    scheme's scales (the first part's)."""
    groups: list[Group] = []
    scales: tuple[Scale, ...] = ()
    for scene, nm in parts:
        g, sc = inset(scene, nm)
        groups.append(g)
        scales += sc
    notes = tuple(f"{nm}: {note}" for scene, nm in parts for note in scene.notes)
    return Scene(sheet.page(parts[0][0].scales()), (sheet.header(), *groups), title=sheet.title,
                 notation=sheet.nt.code, name=name, extra_scales=scales, notes=notes)


__all__ = ["default_plan_positions", "kinematic_analysis_sheet"]
