"""The course project's second sheet: the force (kinetostatic) analysis of one position, on A1 or A2.

Left, the whole height: the linkage in that position with every force
(:func:`~graphmethods.sheets.forces.force_scheme`); right, above: Zhukovsky's lever with every force
(:func:`~graphmethods.sheets.forces.zhukovsky_forces`); right, below: the force plan of each group and
of the crank, every reaction's magnitude (:func:`~graphmethods.sheets.forces.force_plans`); at the top
right corner the result table: the
balancing moment from the force plans, from the lever and from the power balance, with their
differences in per cent. Each part keeps its own scales, written under it and in the title block.

>>> from graphmethods.problems import builtin
>>> s = force_analysis_sheet(builtin.case("press"), position=3, page="A2")
>>> [e.name for e in s.elements][1:]
['scheme', 'lever', 'plans', 'result-heading', 'result']
"""

from __future__ import annotations

from typing import Any

from graphmethods.errors import InputError
from graphmethods.problems.reference_cases import title_of
from graphmethods.scene import Page, Scene, Table, Text, notation as get_notation
from graphmethods.scene.markup import text_width_mm
from graphmethods.sheets import forces as SF
from graphmethods.sheets.composition import inset, region_page
from graphmethods.sheets.engine.lettering import lettered_by_page
from graphmethods.sheets.layout import TEXT_MM, Sheet


def _case(subject: Any) -> Any:
    """The problem Case of a Case or a Study."""
    case = getattr(subject, "case", subject)
    if not hasattr(case, "linkage"):
        raise InputError(f"expected a linkage problem (graphmethods.kinematics.read_case or a built-in name's "
                         f"case), got {type(subject).__name__}")
    return case


def sheet_page(page: str | Page, what: str) -> Page:
    """A1 or A2 landscape with a frame (a left binding margin of 20 mm), or the Page given."""
    if isinstance(page, Page):
        return page
    size = str(page).upper()
    if size not in ("A1", "A2"):
        raise InputError(f"page {page!r}: the {what} sheet is drawn on A1 or A2")
    return Page(size, "landscape", margins_mm=(10.0, 10.0, 10.0, 20.0), frame=True)


@lettered_by_page("A1")
def force_analysis_sheet(subject: Any, position: int | None = None, *, phi_deg: float | None = None, m: int = 12,
                         gravity: bool = False, page: str | Page = "A1", notation: Any = "en",
                         title: str | None = None, title_block: bool = True, name: str = "force-analysis") -> Scene:
    """The force-analysis sheet of one position (see the module docstring).

    Parameters
    ----------
    subject : Case or Study
        A linkage problem (``builtin.case("shaper")``).
    position : int, optional
        Position 0…m (default 2), or ``phi_deg``, the crank angle in degrees.
    gravity : bool
        Add the weights (g = 9.81 m/s² along −y).
    page : {"A1", "A2"} or Page
    notation : {"en", "ru", "zh"}

    Returns
    -------
    Scene
        The sheet; its notes give every scale picked.

    Raises
    ------
    InputError
        A position outside 0…m, a page other than A1/A2, a problem that is not a linkage.
    """
    from graphmethods.sheets.forces import force_plans, force_scheme, zhukovsky_forces

    case = _case(subject)
    nt = get_notation(notation)
    fa, i = SF.analysed(case, position=position, phi_deg=phi_deg, m=m, gravity=gravity)
    head = SF.title_text(nt, "sheet", i, phi_deg)
    pg = sheet_page(page, "force-analysis")
    sheet = Sheet(nt=nt, page=None, title=title or head, problem=title_of(case), title_block=title_block,
                  default_page=pg)
    x0, _, x1, _ = sheet.box
    top, bottom = sheet.top, sheet.caption_y + 1.0
    # the result table, top right
    Mb = float(fa.M_balance[i])
    n = nt.number
    rows = [(nt.word("forces.method"), nt.quantity(nt.sym("forces.M_b"), "N·m"),
             nt.word("forces.diff_percent")),
            (nt.word("forces.by_plans"), n(Mb, sig=6), "—")]
    for key, other in (("lever", fa.M_balance_lever), ("power", fa.M_balance_power)):
        d = float(fa.difference_percent(other)[i])
        rows.append((nt.word(f"forces.by_{key}"), n(float(other[i]), sig=6), SF.percent_text(d, nt)))
    table = Table((0.0, 0.0), tuple(rows), align="lrr", size_mm=TEXT_MM, row_height_mm=6.5, name="result")
    tw = table.width_mm
    heading_w = text_width_mm(nt.word("forces.sheet_result"), TEXT_MM + 0.8) * 1.08
    col_w = max(tw, heading_w) + 4.0
    H = bottom - top
    gap = 8.0
    split_x = x0 + 0.42 * (x1 - x0)            # the scheme: the left column, the whole height
    split_y = top + 0.5 * H                    # the lever and the result over the force plans
    at_k = i if phi_deg is None else None
    kw: dict[str, Any] = {"phi_deg": phi_deg, "m": m, "notation": nt, "title_block": False, "gravity": gravity}
    s_scheme = force_scheme(case, at_k, **kw, page=region_page(pg, (x0, top, split_x - gap / 2, bottom)))
    s_lever = zhukovsky_forces(case, at_k, **kw,
                               page=region_page(pg, (split_x + gap / 2, top, x1 - col_w - gap, split_y)))
    s_plans = force_plans(case, at_k, **kw, page=region_page(pg, (split_x + gap / 2, split_y + gap, x1, bottom)))
    g_scheme, sc1 = inset(s_scheme, "scheme")
    g_lever, sc2 = inset(s_lever, "lever")
    g_plans, sc3 = inset(s_plans, "plans")
    tx = x1 - col_w + 4.0
    heading = Text((tx, top + 4.0), nt.word("forces.sheet_result"), size_mm=TEXT_MM + 0.8, bold=True,
                   name="result-heading")
    table = Table((tx, top + 8.0), tuple(rows), align="lrr", size_mm=TEXT_MM, row_height_mm=6.5, name="result")
    scales = sc1 + sc2 + sc3
    elements = [sheet.header(), g_scheme, g_lever, g_plans, heading, table]
    notes = tuple(f"{part_name}: {note}" for part_name, s in (("scheme", s_scheme), ("lever", s_lever),
                                                             ("plans", s_plans)) for note in s.notes)
    # the title block names the scheme's scales (the sheet's drawing scale); every part writes its own under it
    return Scene(sheet.page(sc1), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 extra_scales=scales, notes=notes)


__all__ = ["force_analysis_sheet", "sheet_page"]
