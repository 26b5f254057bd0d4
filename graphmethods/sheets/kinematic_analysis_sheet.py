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

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cached_property, partial
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.problems.reference_cases import title_of
from graphmethods.scene import Page, Scale, Scene, Table, notation as get_notation
from graphmethods.scene.elements import Group
from graphmethods.sheets.composition import inset, region_page
from graphmethods.sheets.engine.lettering import lettered_by_page
from graphmethods.sheets.engine.quality import EMPTY_MAX
from graphmethods.sheets.force_analysis_sheet import _case, sheet_page as _sheet_page
from graphmethods.sheets.layout import Sheet
from graphmethods.sheets.sheet_fill import PartInk, clashes, filled, overflowing

#: most acceleration plans one sheet draws (each needs a readable share of the lower row)
MAX_PLANS = 4


@dataclass(frozen=True)
class AnalysisSheetLayout:
    """The A1 sheet's divisions into its parts (shares of the content box, mm between the parts).

    Each share is a short list of candidates: the sheet keeps the division whose drawings fill the most of the
    sheet with no label clashing (:func:`~graphmethods.sheets.sheet_fill.filled`): a long linkage takes a wide
    scheme, tall velocity plans a narrow one. It draws the ``probe`` division and the one its parts predict
    fullest, and every division only when neither will do (:func:`_chosen`).
    """

    gap_mm: float = 8.0                 # between the parts
    #: the upper row (scheme, velocity plans) of the height
    upper_shares: tuple[float, ...] = (0.52, 0.58)
    #: the scheme of the upper row's width
    scheme_shares: tuple[float, ...] = (0.36, 0.45)
    #: the slider's diagrams (the table of velocities) of the lower row's width
    diagrams_shares: tuple[float, ...] = (0.4, 0.5)
    table_pad_mm: float = 4.0           # beside the table of velocities
    #: the division always drawn, the one most often kept: its parts predict the others' ink
    probe: tuple[float, float, float] = (0.52, 0.36, 0.5)

    def divisions(self) -> list[tuple[float, float, float]]:
        """Every division (upper share, scheme share, right part's share), in the order ties are settled."""
        return [(u, s, d) for u in self.upper_shares for s in self.scheme_shares for d in self.diagrams_shares]


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
    parts = _Parts(case, nt, m, pg, ks, lay)

    def regions(dv: Division) -> list[Region]:
        split_y = top + dv[0] * (bottom - top)
        return (_upper_regions((x0, top, x1, split_y), dv[1], lay)
                + _lower_regions(parts, (x0, split_y + lay.gap_mm, x1, bottom), dv[2]))

    best = _chosen(parts, sheet, regions)
    if best is None:                    # no division fits: the first one says why
        for fn, nm, box in regions(lay.divisions()[0]):
            parts.draw(fn, nm, box)
        raise InputError("the kinematic-analysis sheet's parts do not fit on this page; give a larger page")
    return _assembled(sheet, [(p.scene, p.name) for p in best], name)


#: a division of the sheet: the upper row's share of the height, the scheme's of its width, the right part's of
#: the lower row's width
Division = tuple[float, float, float]
#: a part to draw: its figure function, its name on the sheet and its region (mm)
Region = tuple[Callable[..., Scene], str, tuple[float, float, float, float]]


def _chosen(parts: _Parts, sheet: Sheet, regions: Callable[[Division], list[Region]]) -> list[Part] | None:
    """The parts of the division kept. The probe division is drawn; the others are ranked by the cells their
    ink would fill, predicted from the probe's parts stretched onto their regions
    (:meth:`~graphmethods.sheets.sheet_fill.PartInk.stretched`), and drawn in that order (the parts drawn
    already are not drawn again): the best guess when it is predicted fuller than the probe by more than the
    prediction's uncertainty (:data:`PREDICTION_MARGIN`), and more while every division drawn clashes or leaves
    the sheet more than half empty (:data:`EMPTY_MAX`, the figure-quality measure's bound). Of those drawn, the
    one with the fewest clashes filling the most is kept (the first of equals); None when no division fits."""
    lay = parts.lay
    probe = _drawn(parts, regions(lay.probe))
    guesses: list[tuple[int, int, Division]] = []
    if probe is not None:
        guesses = _predicted(parts, probe, regions)
    order = [lay.probe] + [dv for _, _, dv in guesses if dv != lay.probe]
    best: tuple[tuple[int, int], list[Part]] | None = None if probe is None else (_rank(probe), probe)
    fuller = 0 if best is None else sum(1 for g in guesses if g[2] != lay.probe and -g[0] > best[0][1]
                                        + PREDICTION_MARGIN * best[1][0].ink.cells.size)
    for n, dv in enumerate(order, start=1):     # all of them drawn: the best of every division
        row = _drawn(parts, regions(dv)) if n > 1 else None          # the probe's rank is known
        if row is not None:
            rank = _rank(row)
            if best is None or rank > best[0]:
                best = (rank, row)
        if (best is not None and best[0][0] == 0 and n > min(fuller, 1)
                and _empty_share(sheet, best[1]) <= EMPTY_MAX):
            break
    return None if best is None else best[1]


#: a division is drawn beside the probe only when predicted to fill more of the sheet's cells than the probe
#: by more than this share of them (1 %, about 11 cells on A1): the stretched prediction is no surer (a part
#: drawn in another region picks another scale from the series and places its labels anew); on the 33
#: built-in sheets no division drawn for a smaller predicted gain (1–9 cells) filled more than the probe
PREDICTION_MARGIN = 0.01


def _predicted(parts: _Parts, probe: list[Part], regions: Callable[[Division], list[Region]]
               ) -> list[tuple[int, int, Division]]:
    """Every division that fits, with the cells its parts are predicted to fill (the probe's parts stretched
    onto their regions; a part in the probe's own region or one the probe has not, as drawn), best first:
    (−cells, its place, division)."""
    by_name = {p.name: p for p in probe}
    seen: dict[tuple[str, tuple[float, float, float, float]], np.ndarray] = {}

    def cells(fn: Callable[..., Scene], nm: str, box: tuple[float, float, float, float]) -> np.ndarray:
        if (nm, box) not in seen:
            p = by_name.get(nm)
            seen[nm, box] = (p.ink.stretched(p.scene.page.inner_box(), box) if p is not None
                             and not parts.drawn(nm, box) and not _rescaled(parts, p, box)
                             else parts.draw(fn, nm, box).ink.cells)
        return seen[nm, box]

    guesses: list[tuple[int, int, Division]] = []
    for j, dv in enumerate(parts.lay.divisions()):
        try:
            guesses.append((-int(np.logical_or.reduce([cells(*r) for r in regions(dv)]).sum()), j, dv))
        except InputError:          # a part that does not fit: not a candidate
            continue
    return sorted(guesses)


def _rescaled(parts: _Parts, probe: Part, box: tuple[float, float, float, float]) -> bool:
    """Would the velocity plans drawn in ``box`` take another μ_v than the probe's? A stretched prediction cannot
    see the step (the six-bar press's plans at 0.01 in a taller row, 0.02 in the probe's): such a part is drawn."""
    if probe.name != "velocity-plans":
        return False
    from graphmethods.sheets.velocity_plans import velocity_grid_scale

    mu = velocity_grid_scale(parts.case, m=parts.m, notation=parts.nt, page=region_page(parts.pg, box),
                             title_block=False)
    return not math.isclose(mu, probe.scene.scales()[0].per_mm)


def _drawn(parts: _Parts, regions: list[Region]) -> list[Part] | None:
    """The parts drawn in their regions; None when one does not fit its region."""
    try:
        return [parts.draw(fn, nm, box) for fn, nm, box in regions]
    except InputError:
        return None


def _empty_share(sheet: Sheet, row: list[Part]) -> float:
    """The share of the sheet's cells no ink touches, with the title and title block: the figure-quality
    measure of the sheet these parts make (:func:`~graphmethods.sheets.engine.quality.measure`)."""
    head = PartInk.of(Scene(sheet.page(row[0].scene.scales()), (sheet.header(),)), row[0].page)
    return float(1.0 - filled([p.ink for p in row] + [head]).mean())


@dataclass
class Part:
    """One part of the sheet as drawn in its region: the drawing, its name on the sheet, and its ink on the
    sheet ``page`` (recorded when first asked)."""

    scene: Scene
    name: str
    page: Page

    @cached_property
    def ink(self) -> PartInk:
        return PartInk.of(self.scene, self.page)


class _Parts:
    """The sheet's parts, each drawn once per region it is offered (several divisions offer the same one)."""

    def __init__(self, case: Any, nt: Any, m: int, pg: Page, ks: list[int], lay: AnalysisSheetLayout) -> None:
        self.case, self.nt, self.m, self.pg, self.ks, self.lay = case, nt, m, pg, ks, lay
        self._drawn: dict[tuple[str, tuple[float, ...]], Part | InputError] = {}
        #: whether the slider's diagrams could be drawn (None: not yet tried)
        self.slider: bool | None = None

    def drawn(self, name: str, box: tuple[float, float, float, float]) -> bool:
        """Has the part ``name`` been drawn (or refused) in ``box``?"""
        return (name, tuple(float(v) for v in box)) in self._drawn

    def draw(self, fn: Callable[..., Scene], name: str, box: tuple[float, float, float, float], **kw: Any) -> Part:
        """``fn`` (a figure function) drawn in ``box`` of the sheet as the part ``name`` (InputError when the
        region is too small for it, raised again each time it is asked)."""
        key = (name, tuple(float(v) for v in box))
        if key not in self._drawn:
            try:
                sc = fn(self.case, notation=self.nt, title_block=False, m=self.m, page=region_page(self.pg, box), **kw)
                self._drawn[key] = Part(sc, name, self.pg)
            except InputError as e:
                self._drawn[key] = e
        got = self._drawn[key]
        if isinstance(got, InputError):
            raise got
        return got


def _rank(row: list[Part]) -> tuple[int, int]:
    """A division's rank: (−clashing labels − parts overlapping, cells its ink fills); larger is better."""
    inks = [p.ink for p in row]
    return -clashes(inks) - overflowing(inks), int(filled(inks).sum())


def _upper_regions(box: tuple[float, float, float, float], share: float, lay: AnalysisSheetLayout) -> list[Region]:
    """The upper row: the kinematic scheme (``share`` of the width) and the velocity plans beside it."""
    from graphmethods.sheets.kinematics import kinematic_scheme, velocity_plan_grid

    x0, top, x1, split_y = box
    split_x = x0 + share * (x1 - x0)
    gap = lay.gap_mm
    return [(kinematic_scheme, "scheme", (x0, top, split_x - gap / 2, split_y)),
            (velocity_plan_grid, "velocity-plans", (split_x + gap / 2, top, x1, split_y))]


def _lower_regions(parts: _Parts, box: tuple[float, float, float, float], share: float) -> list[Region]:
    """The lower row: the acceleration plans of the chosen positions side by side, and at the right the
    slider's diagrams (``share`` of the width) or the tables (:func:`_right_part`)."""
    from graphmethods.sheets.acceleration import acceleration_plan

    x0, y0, x1, y1 = box
    gap, ks = parts.lay.gap_mm, parts.ks
    beside, right = _right_part(parts, box, share)
    w = (right - x0 - gap * (len(ks) - 1)) / len(ks)
    return [(partial(acceleration_plan, position=k), f"acceleration-plan-{k}",
             (x0 + j * (w + gap), y0, x0 + j * (w + gap) + w, y1)) for j, k in enumerate(ks)] + beside


def _right_part(parts: _Parts, box: tuple[float, float, float, float], share: float) -> tuple[list[Region], float]:
    """The lower row's right part: the slider's kinematic diagrams (their share of the width), or without a
    slider the tables of velocities and of accelerations per position, one above the other (as wide as they
    are, drawn to be measured); and where the acceleration plans end (mm). Nothing when neither can be drawn."""
    from graphmethods.sheets.acceleration import acceleration_table
    from graphmethods.sheets.calculus import kinematic_diagrams
    from graphmethods.sheets.kinematics import velocity_table

    x0, y0, x1, y1 = box
    gap = parts.lay.gap_mm
    left = x1 - share * (x1 - x0)
    if parts.slider is not False:
        diagrams: Region = (kinematic_diagrams, "kinematic-diagrams", (left, y0, x1, y1))
        try:
            if parts.slider is None:    # the first region offered tells whether the linkage has one slider
                parts.draw(*diagrams)
            parts.slider = True
            return [diagrams], left - gap
        except InputError:              # no slider: the tables in its place
            parts.slider = False
    tables = ((velocity_table, "velocity-table"), (acceleration_table, "acceleration-table"))
    for n in (2, 1):
        h = (y1 - y0 - (n - 1) * gap) / n
        rows = [(y0 + i * (h + gap), y0 + i * (h + gap) + h) for i in range(n)]
        try:
            probes = [parts.draw(fn, nm, (left, a, x1, b)) for (fn, nm), (a, b) in zip(tables, rows)]
        except InputError:              # too wide or too long: one table, or none
            continue
        widths = [t.width_mm for p in probes for t in p.scene.elements if isinstance(t, Table)]
        left = max(left, x1 - max(widths) - 2 * parts.lay.table_pad_mm)
        return [(fn, nm, (left, a, x1, b)) for (fn, nm), (a, b) in zip(tables, rows)], left - gap
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
