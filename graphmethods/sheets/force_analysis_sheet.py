"""The course project's second sheet: the force (kinetostatic) analysis of one position, on A1 or A2.

The linkage in that position with every force (:func:`~graphmethods.sheets.forces.force_scheme`), large;
Zhukovsky's lever with every force (:func:`~graphmethods.sheets.forces.zhukovsky_forces`); for each Assur
group, and for the crank, two panels side by side: the group cut from the linkage with its forces and the
reactions of the links it was cut from (:func:`~graphmethods.sheets.force_sheet_plans.group_panel`), and its
force plan at its own convenient μ_F filling its panel, with its vector equation and the reactions it finds
(:func:`~graphmethods.sheets.force_sheet_plans.plan_panel`; the crank's plan closed by the balancing force
F_b and R′_01); the plan of accelerations of the position, where the inertia forces' a_S and ε come from
(:func:`~graphmethods.sheets.acceleration.acceleration_plan`, left out when its equations do not fit its
panel). At the right, above the title block: the balancing moment from the force plans, from the lever and
from the power balance with their differences in per cent, every reaction's magnitude, the inertia loads,
the inertia loads worked out (F_и = m·a_S = …, M_и = J_S·ε = …, h = M_и/F_и, :mod:`~graphmethods.sheets.force_working`)
and M_b(φ) over the cycle with the position marked (:mod:`~graphmethods.sheets.balancing_graph`; across under
the drawings of a dyad and the crank, under a larger tall linkage in its column, or under a flat one's
lever). Each group's plan writes above its polygon the moment equations that give its R^τ with the numbers,
then its vector equation. Each part keeps its own scales, written under it; the title block names
the scheme's.

>>> from graphmethods.problems import builtin
>>> s = force_analysis_sheet(builtin.case("press"), position=3, page="A1")
>>> [e.name for e in s.elements][1:9]
['scheme', 'lever', 'acceleration', 'plans', 'result-heading', 'result', 'reactions', 'inertia']
>>> [e.name for e in s.elements][-3:]
['working-11', 'cycle', 'balancing']
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.problems.reference_cases import title_of
from graphmethods.scene import Group, Page, Scene, Table, Text, notation as get_notation
from graphmethods.scene.markup import text_width_mm
from graphmethods.sheets import forces as SF
from graphmethods.sheets.acceleration import acceleration_plan
from graphmethods.sheets.balancing_graph import balancing_graph
from graphmethods.sheets.composition import inset, region_page
from graphmethods.sheets.engine.compose import GAP_MM, Split
from graphmethods.sheets.engine.lettering import lettered_by_page, lettering
from graphmethods.sheets.engine.quality import ink_cells
from graphmethods.sheets.force_sheet_plans import group_panel, moments_fit, plan_panel
from graphmethods.sheets.force_tables import cycle_rows, inertia_rows, load_rows, reaction_rows
from graphmethods.sheets.force_working import inertia_working, power_working
from graphmethods.sheets.layout import Box, Sheet
from graphmethods.sheets.sheet_fill import PartInk


def _case(subject: Any) -> Any:
    """The problem Case of a Case or a Study."""
    case = getattr(subject, "case", subject)
    if not hasattr(case, "linkage"):
        raise InputError(f"expected a linkage problem (graphmethods.kinematics.read_case or a built-in name's "
                         f"case), got {type(subject).__name__}")
    return case


#: the least room (mm) for M_b(φ) under the result column's text; with less, it goes among the drawings
GRAPH_MM = 90.0


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
        On A2 the sheet is composed by :func:`~graphmethods.sheets.force_sheet_a2.force_sheet_a2`.
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
    case = _case(subject)
    nt = get_notation(notation)
    fa, i = SF.analysed(case, position=position, phi_deg=phi_deg, m=m, gravity=gravity)
    head = SF.title_text(nt, "sheet", i, phi_deg)
    pg = sheet_page(page, "force-analysis")
    sheet = Sheet(nt=nt, page=None, title=title or head, problem=title_of(case), title_block=title_block,
                  default_page=pg)
    if pg.size == "A2":                             # half of A1: its own composition, without the plan of accelerations
        from graphmethods.sheets.force_sheet_a2 import force_sheet_a2

        return force_sheet_a2(case, fa, i, sheet=sheet, pg=pg, nt=nt, phi_deg=phi_deg, m=m, gravity=gravity, name=name)
    size = lettering(pg).value_mm                  # the tables' values (ГОСТ 2.304: 5 mm on A1/A2)
    note_mm = lettering(pg).label_mm
    tables = _tables(fa, i, nt, size)
    notes_text = ([nt.word("forces.crank_prime", R="R′_{01}", Fb=nt.sym("forces.F_b"), Mb=nt.sym("forces.M_b"))]
                  + ([nt.word("forces.weights")] if gravity else []))
    loads = inertia_working(case, fa, i, nt)             # the inertia loads and M_b by the power balance worked out
    working = ([(nt.word("forces.inertia_loads"), True)] + [(t, False) for t in loads] if loads else [])
    n_loads = len(working)                          # the power balance's working only where the column has room
    working += ([(nt.word("forces.Mb_power", Mb=nt.sym("forces.M_b")), True)]
                + [(t, False) for t in power_working(fa, i, nt)])
    work_mm = size if max([text_width_mm(t, size) for t, _ in working] + [0.0]) <= 190.0 else note_mm
    block = sheet.probe.title_block
    inner = pg.inner_box()
    tb = block.table(inner[2], inner[3]) if block is not None else None
    col_w = max([t.width_mm for t in tables] + ([tb.width_mm - 5.0] if tb is not None else [])
                + [text_width_mm(t, note_mm) for t in notes_text]
                + [text_width_mm(t, work_mm) for t, _ in working]
                + [text_width_mm(nt.word("forces.sheet_result"), size) * 1.08]) + 4.0
    gap = GAP_MM.get(pg.size, 8.0)
    tb_top = inner[3] - (tb.height_mm if tb is not None else 0.0)
    content: Box = (sheet.box[0], sheet.top, sheet.box[2], inner[3] - 5.0)
    free = tb_top - gap - content[1] - _result_column(0.0, 0.0, tables, notes_text, working, nt,
                                                      sizes=(size, note_mm, work_mm, gap))[1]
    graph_below = phi_deg is not None or free >= 3.0 * GRAPH_MM  # M_b(φ) under the column's text, or in the drawings'
    parts_in = _Parts(case, fa, i, nt, pg, phi_deg, m, gravity, tables, notes_text, (working, working[:n_loads]),
                      (size, note_mm, work_mm, gap), name)
    fit = (content, col_w, tb_top - gap)
    if phi_deg is not None:                         # one crank angle: no cycle to draw
        return _composed(parts_in, sheet, fit, graph_below=True)
    # a dyad and the crank (three moving links, two force plans) leave room for M_b(φ) in a wide box across
    # under the drawings; more links keep it among them (under a tall linkage, beside a flat one's lever) and
    # give their force plans the room. Where that leaves much of the sheet empty, or a label crossed, the other
    # arrangement is tried too and the better kept: the fewer labels crossed or overprinted, then the fuller
    wide_first = sum(len(plan.links) for plan in fa.plans) <= 3
    scene = _composed(parts_in, sheet, fit, graph_below=graph_below, wide_graph=wide_first)
    score = _score(scene, pg)
    if score[0] or score[1] > FILL_AIM:
        other = _composed(parts_in, sheet, fit, graph_below=graph_below, wide_graph=not wide_first)
        scene = other if _score(other, pg) < score else scene
    return scene


#: the least and the most of the drawings' height M_b(φ) takes in a wide box across under them
WIDE_GRAPH = (0.2, 0.34)

#: the empty share of 20 mm cells (issue 26: at most 50 %) above which the sheet tries its other arrangement
FILL_AIM = 0.47


@dataclass(frozen=True)
class _Parts:
    """What the A1 force sheet draws, computed once for every arrangement tried: the analysis of position
    ``i``, the result column's tables, notes and workings (the fullest first) and the lettering sizes (mm:
    values, notes, working, the gap between parts)."""

    case: Any
    fa: Any
    i: int
    nt: Any
    pg: Page
    phi_deg: float | None
    m: int
    gravity: bool
    tables: tuple[Table, ...]
    notes_text: list[str]
    workings: tuple[list[tuple[str, bool]], ...]
    sizes: tuple[float, float, float, float]
    name: str
    #: the result column's ink by variant, recorded once for every arrangement (the column is the same in each)
    inks: dict[tuple[int, float, int], PartInk] = field(default_factory=dict, compare=False, repr=False)


def _wide_share(p: _Parts, left: Box) -> float:
    """The share of the drawings' height (``left``, mm) that M_b(φ) across under them takes: as tall as it is
    drawn at the finest convenient μ_M that fits in the most (:data:`WIDE_GRAPH`), the box shaped to it."""
    gap = p.sizes[3]
    H = left[3] - left[1] - gap
    room = (left[0], left[1], left[2], left[1] + WIDE_GRAPH[1] * H)
    ink = balancing_graph(p.fa, p.i, notation=p.nt, page=region_page(p.pg, room)).bbox()
    tall = (ink[3] - left[1] + 1.0) / H if ink is not None else WIDE_GRAPH[1]
    return min(WIDE_GRAPH[1], max(WIDE_GRAPH[0], tall))


def _score(scene: Scene, pg: Page) -> tuple[int, float]:
    """How many of the sheet's labels are crossed by ink or set on another, and the share of its 20 mm cells
    inside the frame no ink touches (the figure-quality measure's counts): the less the better."""
    ink = PartInk.of(scene, pg)
    return int(ink.crossed.sum()) + ink.overlaps, 1.0 - float(ink.cells.mean())


def _composed(p: _Parts, sheet: Sheet, fit: tuple[Box, float, float], *, graph_below: bool,
              wide_graph: bool = False) -> Scene:
    """The A1 sheet's parts drawn in their boxes (:func:`force_sheet_boxes`; ``fit``: the drawings' region,
    the result column's width and its bottom, mm) with the result column chosen to fill it."""
    case, fa, i, nt, pg, phi_deg, m = p.case, p.fa, p.i, p.nt, p.pg, p.phi_deg, p.m
    content, col_w, bottom = fit
    gap = p.sizes[3]
    graph = not graph_below
    share = _wide_share(p, (content[0], content[1], content[2] - col_w - gap, content[3])) if wide_graph else 0.0
    boxes = force_sheet_boxes(fa, i, content, col_w, gap_mm=gap, column_bottom=bottom, graph=graph,
                              wide_graph=share)
    accel = _acceleration(case, i, m, nt, pg, boxes["acceleration"], phi_deg)
    if accel is None and phi_deg is None and graph_below and not wide_graph and "balancing" in boxes:
        # beside a tall linkage the plan of accelerations may take the lever's room, the lever the graph's
        wide = force_sheet_boxes(fa, i, content, col_w, gap_mm=gap, column_bottom=bottom, lever_under=True)
        accel = _acceleration(case, i, m, nt, pg, wide["acceleration"], phi_deg)
        boxes = wide if accel is not None else boxes
    if accel is None:                               # the plan of accelerations does not fit: the others take its room
        boxes = force_sheet_boxes(fa, i, content, col_w, gap_mm=gap, column_bottom=bottom, acceleration=False,
                                  graph=graph, wide_graph=share)
    at_k = i if phi_deg is None else None
    kw: dict[str, Any] = {"phi_deg": phi_deg, "m": m, "notation": nt, "title_block": False, "gravity": p.gravity}
    parts = [(SF.force_scheme(case, at_k, **kw, page=region_page(pg, boxes["scheme"]),
                              title=nt.word("forces.scheme_short"), layout=_panel_layout(boxes["scheme"])), "scheme"),
             (SF.zhukovsky_forces(case, at_k, **kw, page=region_page(pg, boxes["lever"]),
                                  title=nt.word("forces.lever_short"), layout=_panel_layout(boxes["lever"])), "lever")]
    if accel is not None:
        parts.append((accel, "acceleration"))
    for j in range(len(fa.plans)):
        g_page = region_page(pg, boxes[f"group-{j}"])
        beside = moments_fit(fa, i, j, nt, g_page)             # the moment equations beside the group cut
        parts += [(group_panel(case, fa, i, j, nt=nt, page=g_page, moments=beside), f"group-{j}"),
                  (plan_panel(case, fa, i, j, nt=nt, page=region_page(pg, boxes[f"plan-{j}"]), with_moments=not beside),
                   f"plan-{j}")]
    groups = [inset(scene, nm) for scene, nm in parts]
    plans = Group(elements=tuple(g for (g, _), (_, nm) in zip(groups, parts) if nm[:5] in ("group", "plan-")),
                  name="plans")
    others = [g for (g, _), (_, nm) in zip(groups, parts) if nm == "acceleration"]
    drawn = [b for g, _ in groups if (b := g.bbox()) is not None]          # the drawings' ink boxes, mm
    column, y = _best_column(fa, nt, pg, boxes, drawn, p.tables, p.notes_text, p.workings,
                             cycle=phi_deg is None, sizes=p.sizes, inks=p.inks)
    if phi_deg is None:                             # M_b over the cycle: its table and its graph
        column += _cycle_parts(fa, i, nt, pg, boxes, (y, drawn), groups, size=p.sizes[0], gap=gap)
    scales = tuple(scale for _, part_scales in groups for scale in part_scales)
    notes = tuple(f"{nm}: {note}" for scene, nm in parts for note in scene.notes)
    # the title block names the scheme's scales (the sheet's drawing scale); every part writes its own under it
    return Scene(sheet.page(groups[0][1]), (sheet.header(), groups[0][0], groups[1][0], *others, plans, *column),
                 title=sheet.title, notation=nt.code, name=p.name, extra_scales=scales, notes=notes)


def _best_column(fa: Any, nt: Any, pg: Page, boxes: dict[str, Box], drawn: list[Box], tables: tuple[Table, ...],
                 notes_text: list[str], workings: tuple[list[tuple[str, bool]], ...], *, cycle: bool,
                 sizes: tuple[float, float, float, float],
                 inks: dict[tuple[int, float, int], PartInk] | None = None) -> tuple[list[Any], float]:
    """The result column (:func:`_result_column`) that ends above the column's bottom and, with the M_b table
    under it where that has room (``cycle``; kept off the ``drawn`` boxes), inks the most cells of the sheet
    (:class:`~graphmethods.sheets.sheet_fill.PartInk`): with or without the external loads' table (the
    fourth), the working at the values' size or at 3.5 mm; the fullest of ``workings`` that fits, the
    shortest column when none ends above the bottom. ``inks``: each variant's ink, kept for the next call
    with the same column (another arrangement of the drawings); the M_b table's cells are those its box
    covers (its rules are at most 2 size apart)."""
    size, note_mm, work_mm, gap = sizes
    x, top = boxes["result"][0] + 2.0, boxes["result"][1]
    inks = {} if inks is None else inks
    best: tuple[tuple[bool, int, float], list[Any], float] | None = None
    variants = [(k, wk, t, w) for k, wk in enumerate(workings) for w in dict.fromkeys((work_mm, note_mm))
                for t in dict.fromkeys((tables, tables[:3]))]
    width = boxes["result"][2] - x - 2.0
    for k, work, tabs, w_mm in variants:
        column, y = _result_column(x, top, tabs, notes_text, work, nt, sizes=(size, note_mm, w_mm, gap), width=width)
        inside = y - gap <= boxes["result"][3]
        if best is not None and best[0][:2] > (inside, -k if inside else 0):
            continue                                # a fuller working already fits: this one cannot win
        if not inside:
            score: tuple[bool, int, float] = (False, 0, -y)
        else:
            key = (k, w_mm, len(tabs))
            if key not in inks:
                inks[key] = PartInk.of(Scene(pg, tuple(column)), pg)
            cells = inks[key].cells
            table = _cycle_table(fa, nt, size, (x, y), _floor(boxes), drawn, width=width) if cycle else None
            box = table.bbox() if table is not None else None
            if box is not None:
                cells = cells | ink_cells(np.empty((0, 4)), np.array([box]), pg.inner_box())
            score = (True, -k, float(cells.sum()))
        if best is None or score > best[0]:
            best = (score, column, y)
    assert best is not None
    return best[1], best[2]


def _floor(boxes: dict[str, Box]) -> float:
    """How far down (mm) the M_b table may run in the result column: to its bottom, or the graph's room above it."""
    return boxes["result"][3] - (0.0 if "balancing" in boxes else GRAPH_MM)


def _cycle_parts(fa: Any, i: int, nt: Any, pg: Page, boxes: dict[str, Box], at: tuple[float, list[Box]],
                 groups: list[Any], *, size: float, gap: float) -> list[Any]:
    """M_b over the cycle: its table under the result column's text (``at``: its y, mm, and the drawings' ink
    boxes it keeps off) where it has room, and the graph (in its box among the drawings, or under the table;
    appended to ``groups`` with its scales)."""
    res = boxes["result"]
    y, inks = at
    out: list[Any] = []
    cycle = _cycle_table(fa, nt, size, (res[0] + 2.0, y), _floor(boxes), inks, width=res[2] - res[0] - 4.0)
    graph_box = boxes.get("balancing", (res[0], y, res[2], res[3]))
    if cycle is not None:
        out.append(cycle)
        if "balancing" not in boxes:
            graph_box = (res[0], cycle.bottom_left[1] + gap, res[2], res[3])
    if graph_box[3] - graph_box[1] > 60.0:
        graph, g_scales = inset(balancing_graph(fa, i, notation=nt, page=region_page(pg, graph_box)), "balancing")
        out.append(graph)
        groups.append((graph, g_scales))
    return out


def _widths_across(table: Table, width: float) -> tuple[float, ...] | None:
    """The column widths (mm) that stretch ``table`` across ``width`` mm (its fitted widths, each widened in
    proportion), or None (the fitted widths) where it is as wide already: the result column's tables are
    ruled to the column's width, as a course sheet's are."""
    fitted = table.column_widths()
    k = width / sum(fitted) if fitted else 1.0
    return tuple(w * k for w in fitted) if k > 1.0 else None


def _result_column(tx: float, ty: float, tables: tuple[Table, ...], notes_text: list[str],
                   working: list[tuple[str, bool]], nt: Any, *, sizes: tuple[float, float, float, float],
                   width: float = 0.0) -> tuple[list[Any], float]:
    """The result column from (tx, ty): its heading, the balancing moment's, the reactions' and the inertia
    loads' tables (ruled ``width`` mm wide where they are narrower), the notes and the inertia loads worked
    out; and the y (mm) under its last line."""
    size, note_mm, work_mm, gap = sizes
    names = ("result", "reactions", "inertia", "loads")
    column: list[Any] = [Text((tx, ty + size), nt.word("forces.sheet_result"), size_mm=size, bold=True,
                              name="result-heading")]
    y = ty + 2.5 * size
    for tab, nm in zip(tables, names):
        table = Table((tx, y), tab.rows, align=tab.align, size_mm=size, row_height_mm=2.0 * size, name=nm,
                      col_widths_mm=_widths_across(tab, width))
        column.append(table)
        y = table.bottom_left[1] + 2.0 * size
    column += [Text((tx, y + k * 1.8 * note_mm), note, size_mm=note_mm, name=f"note-{k}")
               for k, note in enumerate(notes_text)]
    y += len(notes_text) * 1.8 * note_mm + gap
    for k, (line, head_) in enumerate(working):
        y += (2.2 if head_ and k else 1.8) * work_mm
        column.append(Text((tx, y), line, size_mm=work_mm, bold=head_, name=f"working-{k}"))
    return column, y + gap


def _tables(fa: Any, i: int, nt: Any, size: float) -> tuple[Table, ...]:
    """The A1 result column's tables at ``size`` mm: M_b three ways, the reactions, the inertia loads and the
    external loads, with the components as ``forces`` prints them."""
    react, inertia, loads = reaction_rows(fa, i, nt), inertia_rows(fa, i, nt), load_rows(fa, i, nt)
    return tuple(Table((0.0, 0.0), tuple(rows), align=align[:len(rows[0])], size_mm=size, row_height_mm=2.0 * size)
                 for rows, align in ((_result_rows(fa, i, nt), "lrr"), (react, "crrr"), (inertia, "crrrrr"),
                                     (loads, "cc" + "r" * 6)) if rows)


def _cycle_table(fa: Any, nt: Any, size: float, at: tuple[float, float], bottom: float,
                 inks: list[Box], width: float = 0.0) -> Table | None:
    """The table of M_b at every position (:func:`~graphmethods.sheets.force_tables.cycle_rows`) from ``at``
    (mm) or as little under it as keeps it off the drawings' ink (``inks``, mm); None when it would run below
    ``bottom`` (mm)."""
    rows = tuple(cycle_rows(fa, nt))
    for mm in (size, 0.8 * size, 0.7 * size):                   # at the values' size where it has room
        y = at[1]
        while True:
            table = Table((at[0], y + 1.5 * size), rows, align="rrrr", size_mm=mm, row_height_mm=1.8 * mm,
                          name="cycle")
            table = replace(table, col_widths_mm=_widths_across(table, width))
            box = table.bbox()
            if table.bottom_left[1] > bottom or box is None:
                break
            if not any(min(box[2], b[2]) > max(box[0], b[0]) and min(box[3], b[3]) > max(box[1], b[1])
                       for b in inks):
                return table
            y += 5.0
    return None


def _panel_layout(box: Box) -> SF.ForceFigureLayout:
    """The scheme's or the lever's layout in a panel of the sheet: its largest force about a sixth of the
    panel's smaller side (30…60 mm), room kept round the drawing for it."""
    F = min(80.0, max(30.0, (min(box[2] - box[0], box[3] - box[1])) / 4.0))
    return SF.ForceFigureLayout(largest_force_mm=F, margin_mm=0.6 * F + 6.0)


def _left_of(boxes: dict[str, Box], name: str) -> list[str]:
    """The parts whose boxes end left of ``name``'s on its first line (their headings may run into it)."""
    b = boxes[name]
    return [k for k, o in boxes.items() if k != name and o[2] <= b[0] and o[1] <= b[1] < o[3]]


def _inertia_rows(fa: Any, i: int, nt: Any) -> list[tuple[str, str, str]]:
    """The inertia loads of position ``i``: each moving link's |F_i| (N) and M_i (N·m), round-off as 0."""
    rows = [(nt.word("forces.link"), nt.quantity("|F_{" + nt.word("forces.sub_inertia") + "}|", "N"),
             nt.quantity("M_{" + nt.word("forces.sub_inertia") + "}", "N·m"))]
    loads = [f for fs in fa.applied.values() for f in fs if f.label.startswith("F_i")]
    big_F = max([float(abs(f.F[i])) for f in loads] + [0.0])
    big_M = big_F * float(np.ptp(np.abs([complex(fa.motion.z[p][i]) for p in fa.motion.points])) or 1.0)
    for f in loads:
        F, M = SF.round_off_zero(float(abs(f.F[i])), big_F), SF.round_off_zero(float(f.M[i]), big_M)
        rows.append((f.label[3:], nt.number(F, sig=5), nt.number(M, sig=5)))
    return rows


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


def _acceleration(case: Any, i: int, m: int, nt: Any, pg: Page, box: Box,
                  phi_deg: float | None = None) -> Scene | None:
    """The plan of accelerations of position ``i`` (or at the crank angle ``phi_deg``, degrees) in ``box``
    (where the inertia forces' a_S and ε come from), or None when it cannot be drawn there or its equations
    run out of the box."""
    from graphmethods.dynamics.study import AngleStudy

    at_angle = phi_deg is not None
    subject, title = case, None
    if phi_deg is not None:                         # the plan at that crank angle, titled by it
        subject = AngleStudy(case, [float(phi_deg) % 360.0])
        title = nt.word("acceleration.plan_at", phi=nt.number(float(phi_deg) % 360.0, sig=6))
    try:
        scene = acceleration_plan(subject, 0 if at_angle else i, m=None if at_angle else m, notation=nt,
                                  page=region_page(pg, box), title=title, title_block=False)
    except InputError:
        return None
    boxes = [b for b in (e.bbox() for e in scene.elements) if b is not None]
    inside = all(b[0] >= box[0] - 1.0 and b[1] >= box[1] - 1.0 and b[2] <= box[2] + 1.0 and b[3] <= box[3] + 1.0
                 for b in boxes)
    return scene if inside else None


def _lever_width(aspect: float, height: float, room: float) -> float:
    """The width (mm) of the lever's panel ``height`` mm high: its drawing's width at the height it can have,
    room for its forces either side, and its lines of text (at least 130 mm, at most 45 % of ``room``)."""
    return min(0.45 * room, max(130.0, aspect * max(height - 100.0, 40.0) + 110.0))


def _pairs(fa: Any, i: int, n: int, gap_mm: float) -> Split:
    """The groups cut from the linkage and their force plans: side by side in columns, each group over its
    plan, when the drawings are tall; one pair under another, each group beside its plan, when they are flat
    (a slider-crank's group and its long polygon)."""
    clouds = _pair_clouds(fa, i)
    plans = [_aspect(c) for c in clouds[1::2]]
    if sum(a > 2.0 for a in plans) * 2 > len(plans) or all(_aspect(c) > 1.3 for c in clouds):
        rows = tuple((Split("h", ((f"group-{j}", 0.4), (f"plan-{j}", 0.6)), gap_mm=gap_mm), 1.0) for j in range(n))
        return Split("v", rows, gap_mm=gap_mm)
    cols = tuple((Split("v", ((f"group-{j}", 0.45), (f"plan-{j}", 0.55)), gap_mm=gap_mm), 1.0) for j in range(n))
    return Split("h", cols, gap_mm=gap_mm)


def _pair_clouds(fa: Any, i: int) -> list[list[complex]]:
    """The points of each group's cut drawing (m) and of each force polygon (N): their shapes."""
    from graphmethods.sheets.force_sheet_plans import group_cloud, plan_sides

    out = []
    for j in range(len(fa.plans)):
        out.append(group_cloud(fa, j, i))
        out.append(list(np.cumsum([0j] + [F for _, F, _ in plan_sides(fa, j, i)])))
    return out


def force_sheet_boxes(fa: Any, i: int, box: Box, col_w: float, *, gap_mm: float = 10.0,
                      column_bottom: float | None = None, acceleration: bool = True,
                      graph: bool = False, lever_under: bool = False, wide_graph: float = 0.0) -> dict[str, Box]:
    """Where the parts of the force sheet go (mm): the scheme, Zhukovsky's lever, each force plan
    (``plan-0``, ``plan-1``, …, the crank's last) and the result column (``result``), arranged by the shapes
    of the drawings (:class:`~graphmethods.sheets.engine.compose.Split`).

    The result column (``col_w`` wide) stands at the right, down to ``column_bottom`` (the title block's
    top). Left of it, a tall linkage (a shaper's rocker) takes a column the height of the sheet, the lever
    a column beside it, and the force plans one over another in a third; a flat linkage (a press) takes a
    row across the top with the lever beside it, and the plans share the row below side by side. ``graph``:
    M_b(φ) gets a box among the drawings (``balancing``; a tall linkage's column always has it);
    ``lever_under``: beside a tall linkage the plan of accelerations takes the whole upper row and the lever
    goes under the linkage (when the plan does not fit beside the lever); ``wide_graph``: M_b(φ) in a box
    across under the drawings, that share of their height (:func:`_wide_share`).

    >>> from graphmethods.problems import builtin
    >>> from graphmethods.sheets.forces import analysed
    >>> fa, i = analysed(builtin.case("press"), position=3, phi_deg=None, m=12)
    >>> sorted(force_sheet_boxes(fa, i, (25.0, 27.0, 826.0, 579.0), 150.0))
    ['acceleration', 'group-0', 'group-1', 'lever', 'plan-0', 'plan-1', 'result', 'scheme']
    """
    mo = fa.motion
    scheme = _aspect([complex(mo.z[p][i]) for p in mo.points] + SF._guide_ends(mo, SF._links_of(mo, i)[1]))
    lever = _aspect([0j] + [1j * complex(mo.v_[p][i]) / mo.omega_1 for p in mo.points if p not in mo.linkage.ground])
    x0, y0, x1, y1 = box
    out = {"result": (x1 - col_w, y0, x1, y1 if column_bottom is None else column_bottom)}
    left = (x0, y0, x1 - col_w - gap_mm, y1)
    W, H = left[2] - left[0], left[3] - left[1]
    n = len(fa.plans)
    if scheme < 1.2:                                            # a tall linkage: columns
        w_s = min(0.4, max(0.22, scheme * H / W + 0.1))
        rest = W * (1.0 - w_s)
        w_l = _lever_width(lever, 0.42 * H, rest)
        top = (Split("h", (("lever", w_l), ("acceleration", rest - w_l - gap_mm)), gap_mm=gap_mm) if acceleration
               else Split("h", (("lever", 1.0),), gap_mm=gap_mm))
        under = "balancing"
        if lever_under:                                         # the lever under the linkage, M_b(φ) in the column
            top, under = Split("h", (("acceleration", 1.0),), gap_mm=gap_mm), "lever"
        right = Split("v", ((top, 0.42), (_pairs(fa, i, n, gap_mm), 0.58)), gap_mm=gap_mm)
        left_col = Split("v", (("scheme", 0.62), (under, 0.38)), gap_mm=gap_mm)
        if wide_graph and not lever_under:                      # M_b(φ) across under the drawings
            left_col = Split("v", (("scheme", 1.0),), gap_mm=gap_mm)
        tree = Split("h", ((left_col, w_s), (right, 1.0 - w_s)), gap_mm=gap_mm)
    else:                                                       # a flat linkage: rows
        h_s = min(0.45, max(0.3, W * 0.6 / scheme / H + 0.1))
        graph = graph and not wide_graph
        top = Split("h", (("scheme", 0.6), ("acceleration", 0.4)) if acceleration else (("scheme", 1.0),),
                    gap_mm=gap_mm)
        w_l = _lever_width(lever, (1.0 - h_s) * H, W)
        lever_col = Split("v", (("lever", 0.5), ("balancing", 0.5)), gap_mm=gap_mm) if graph else "lever"
        bottom = Split("h", ((lever_col, w_l), (_pairs(fa, i, n, gap_mm), W - w_l - gap_mm)), gap_mm=gap_mm)
        tree = Split("v", ((top, h_s), (bottom, 1.0 - h_s)), gap_mm=gap_mm)
    if wide_graph and not lever_under:
        tree = Split("v", ((tree, 1.0 - wide_graph), ("balancing", wide_graph)), gap_mm=gap_mm)
    out.update(tree.boxes(left))
    return out


__all__ = ["force_analysis_sheet", "force_sheet_boxes", "sheet_page"]
