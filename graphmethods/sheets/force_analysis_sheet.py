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
from graphmethods.sheets.engine.compose import GAP_MM, Split
from graphmethods.sheets.engine.lettering import lettered_by_page, lettering
from graphmethods.sheets.layout import Box, Sheet


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
    rows = _result_rows(fa, i, nt)
    size = lettering(pg).label_mm
    table = Table((0.0, 0.0), tuple(rows), align="lrr", size_mm=size, row_height_mm=2.0 * size, name="result")
    heading_w = text_width_mm(nt.word("forces.sheet_result"), size + 0.8) * 1.08
    col_w = max(table.width_mm, heading_w) + 4.0
    boxes = force_sheet_boxes(fa, i, (sheet.box[0], sheet.top, sheet.box[2], sheet.caption_y + 1.0), col_w,
                              gap_mm=GAP_MM.get(pg.size, 8.0))
    at_k = i if phi_deg is None else None
    kw: dict[str, Any] = {"phi_deg": phi_deg, "m": m, "notation": nt, "title_block": False, "gravity": gravity}
    parts = [(force_scheme(case, at_k, **kw, page=region_page(pg, boxes["scheme"])), "scheme"),
             (zhukovsky_forces(case, at_k, **kw, page=region_page(pg, boxes["lever"])), "lever"),
             (force_plans(case, at_k, **kw, page=region_page(pg, boxes["plans"])), "plans")]
    groups = [inset(scene, nm) for scene, nm in parts]
    tx, ty = boxes["result"][0] + 4.0, boxes["result"][1] + (lettering(pg).heading_mm + 3.0 if "lever" in
                                                             _left_of(boxes, "result") else 0.0)
    heading = Text((tx, ty + 4.0), nt.word("forces.sheet_result"), size_mm=size + 0.8, bold=True,
                   name="result-heading")
    table = Table((tx, ty + 8.0), tuple(rows), align="lrr", size_mm=size, row_height_mm=2.0 * size, name="result")
    scales = tuple(scale for _, part_scales in groups for scale in part_scales)
    notes = tuple(f"{nm}: {note}" for scene, nm in parts for note in scene.notes)
    # the title block names the scheme's scales (the sheet's drawing scale); every part writes its own under it
    return Scene(sheet.page(groups[0][1]), (sheet.header(), *(g for g, _ in groups), heading, table),
                 title=sheet.title, notation=nt.code, name=name, extra_scales=scales, notes=notes)


def _left_of(boxes: dict[str, Box], name: str) -> list[str]:
    """The parts whose boxes end left of ``name``'s on its first line (their headings may run into it)."""
    b = boxes[name]
    return [k for k, o in boxes.items() if k != name and o[2] <= b[0] and o[1] <= b[1] < o[3]]


def _result_rows(fa: Any, i: int, nt: Any) -> list[tuple[str, str, str]]:
    """The result table: M_b from the force plans, from the lever and from the power balance, differences in %."""
    Mb = float(fa.M_balance[i])
    n = nt.number
    rows = [(nt.word("forces.method"), nt.quantity(nt.sym("forces.M_b"), "N·m"), nt.word("forces.diff_percent")),
            (nt.word("forces.by_plans"), n(Mb, sig=6), "—")]
    for key, other in (("lever", fa.M_balance_lever), ("power", fa.M_balance_power)):
        d = float(fa.difference_percent(other)[i])
        rows.append((nt.word(f"forces.by_{key}"), n(float(other[i]), sig=6), SF.percent_text(d, nt)))
    return rows


def _aspect(points: Any) -> float:
    """Width over height of a cloud of points (complex, m), kept between 0.2 and 5."""
    import numpy as np

    z = np.asarray(list(points), dtype=complex)
    w, h = float(np.ptp(z.real)), float(np.ptp(z.imag))
    return min(5.0, max(0.2, w / h if h > 0 else 5.0))


def force_sheet_boxes(fa: Any, i: int, box: Box, col_w: float, *, gap_mm: float = 10.0) -> dict[str, Box]:
    """Where the parts of the force sheet go (mm): the scheme, Zhukovsky's lever, the force plans and the result
    table, arranged by the shapes of the drawings (:class:`~graphmethods.sheets.engine.compose.Split`).

    A tall linkage (a shaper's rocker) takes a column the height of the sheet, as wide as its shape asks, and
    the lever a column beside it; the force plans, long and flat, share the rest under the result table. A
    flat linkage (a press) takes a row across the top beside the result table, the lever and the plans share
    the row below.
    """
    mo = fa.motion
    scheme = _aspect(complex(mo.z[p][i]) for p in mo.points)
    lever = _aspect([0j] + [1j * complex(mo.v_[p][i]) / mo.omega_1 for p in mo.points if p not in mo.linkage.ground])
    x0, y0, x1, y1 = box
    W, H = x1 - x0, y1 - y0
    if scheme < 1.2:                                            # a tall linkage: columns
        w_s = min(0.4, max(0.22, scheme * H / W + 0.1))
        w_l = min(0.3, max(0.2, lever * H / W + 0.08))
        right = Split("v", (("result", 1.0), ("plans", 6.0)), gap_mm=gap_mm)
        tree = Split("h", (("scheme", w_s), ("lever", w_l), (right, 1.0 - w_s - w_l)), gap_mm=gap_mm)
    else:                                                       # a flat linkage: rows
        h_s = min(0.55, max(0.35, (W - col_w) / scheme / H + 0.1))
        top = Split("h", (("scheme", W - col_w - gap_mm), ("result", col_w)), gap_mm=gap_mm)
        bottom = Split("h", (("lever", 0.4), ("plans", 0.6)), gap_mm=gap_mm)
        tree = Split("v", ((top, h_s), (bottom, 1.0 - h_s)), gap_mm=gap_mm)
    return tree.boxes(box)


__all__ = ["force_analysis_sheet", "force_sheet_boxes", "sheet_page"]
