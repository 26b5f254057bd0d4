"""The force sheet on A2: the force (kinetostatic) analysis of one position on half an A1 sheet.

A2 is half of A1, and a course that prints on A2 keeps what the force analysis itself draws: the linkage with
every force (:func:`~graphmethods.sheets.forces.force_scheme`), Zhukovsky's lever
(:func:`~graphmethods.sheets.forces.zhukovsky_forces`), each Assur group cut from the linkage beside its force
plan and the crank's plan closed by the balancing force
(:func:`~graphmethods.sheets.force_sheet_plans.group_panel`, :func:`~graphmethods.sheets.force_sheet_plans.
plan_panel`), and at the right the balancing moment three ways, the reactions and the inertia loads; the
inertia loads worked out and M_b(φ) over the cycle where the column has room for them. The plan of
accelerations belongs to the kinematic sheet and is left out, unless no arrangement without it fills half
the sheet (a sparse linkage: the Scotch yoke's T).

The parts are the A1 sheet's, drawn by the same recipes into the boxes of an arrangement (:class:`~graphmethods.
sheets.engine.compose.Split`): a tall linkage (a shaper's rocker) in a column at the left over the lever, the
groups beside their plans in rows at its right; a flat one (a press) in a row across the top with the lever
beside it, the groups with their plans in the row below. Each part's box is at least as wide as its heading
(and the scheme's and the lever's as their line of scales), and a plan whose lettering runs out of its box is
drawn again without its working (the moment equations and the lengths laid off; its equation and the
reactions it finds stay). :func:`fullest` draws the arrangements in turn and measures each sheet
(:func:`~graphmethods.sheets.engine.quality.faults`: no label crossed, no text over text, at most half the sheet
empty): the first that meets the standard with at most :data:`AIM` empty is the sheet, else the fullest that
meets it.

>>> from graphmethods.problems import builtin
>>> from graphmethods.sheets.force_analysis_sheet import force_analysis_sheet
>>> s = force_analysis_sheet(builtin.case("press"), position=3, page="A2")
>>> [e.name for e in s.elements][1:4]
['scheme', 'lever', 'plans']
>>> "acceleration" in [e.name for e in s.elements]
False
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from graphmethods.errors import InputError
from graphmethods.scene import Element, Group, Page, Scene, Table, Text
from graphmethods.scene.markup import text_width_mm
from graphmethods.sheets import forces as SF
from graphmethods.sheets.balancing_graph import balancing_graph
from graphmethods.sheets.composition import inset, region_page
from graphmethods.sheets.engine.compose import GAP_MM, Split
from graphmethods.sheets.engine.lettering import lettering
from graphmethods.sheets.engine.quality import faults, measure
from graphmethods.sheets.force_sheet_plans import group_panel, plan_panel
from graphmethods.sheets.force_working import inertia_working
from graphmethods.sheets.layout import Box, Sheet

#: the least height (mm) of M_b(φ) under the result column's text; with less it is left out
GRAPH_MM = 60.0
#: an arrangement that meets the standard and leaves at most this share of the sheet empty is taken at once;
#: with more, the others are drawn too and the fullest taken
AIM = 0.42
#: a part's ink may leave its box by this much (mm) before it counts as running into its neighbour
SLACK_MM = 1.0


@dataclass(frozen=True)
class Column:
    """The result column's content: its tables (the balancing moment three ways, the reactions, the inertia
    loads), its notes and the inertia loads worked out (text, heading?)."""

    tables: tuple[Table, Table, Table]
    notes: tuple[str, ...]
    working: tuple[tuple[str, bool], ...]


def force_sheet_a2(case: Any, fa: Any, i: int, *, sheet: Sheet, pg: Page, nt: Any, phi_deg: float | None, m: int,
                   gravity: bool, name: str) -> Scene:
    """The A2 force sheet of position ``i`` (see the module docstring), its arrangement chosen by
    :func:`fullest`.

    Raises
    ------
    InputError
        No arrangement has room for every part (not met by a built-in problem).
    """
    column = result_column(case, fa, i, nt, pg, gravity)
    inner = pg.inner_box()
    block = sheet.probe.title_block
    tb = block.table(inner[2], inner[3]) if block is not None else None
    gap = GAP_MM.get(pg.size, 8.0)
    tb_top = inner[3] - (tb.height_mm if tb is not None else 0.0)
    col_w = column_width(column, nt, pg, tb.width_mm if tb is not None else 0.0)
    content = (sheet.box[0], sheet.top, sheet.box[2], inner[3] - 5.0)
    left = (content[0], content[1], content[2] - col_w - gap, content[3])
    right = (content[2] - col_w + 2.0, content[1], content[2], tb_top - gap)
    col_els, graph_box = column_elements(right, column, nt, pg, gap)
    tail: list[tuple[Group, tuple[Any, ...]]] = []
    if phi_deg is None and graph_box is not None:
        try:
            tail.append(inset(balancing_graph(fa, i, notation=nt, page=region_page(pg, graph_box)), "balancing"))
        except InputError:                                  # no room after all: the column without it
            pass
    heads = headings(fa, nt, pg)
    trees = arrangements(fa, i, left, gap, accelerations=phi_deg is None, least=heads)
    trees.sort(key=lambda t: not headings_fit(t.boxes(left), heads))     # a heading wider than its box: last

    def draw(boxes: dict[str, Box]) -> Scene:
        parts = draw_parts(case, fa, i, boxes, pg, nt, phi_deg=phi_deg, m=m, gravity=gravity)
        return _assemble(sheet, parts, col_els, tail, name)

    return fullest([t.boxes(left) for t in trees], draw)


def fullest(arrangements: list[dict[str, Box]], draw: Callable[[dict[str, Box]], Scene]) -> Scene:
    """The sheet ``draw`` makes of the first of the ``arrangements`` (each part's box) that meets the standard
    with at most :data:`AIM` of it empty, else of the one that meets it fullest, else of the one with the
    fewest labels crossed or overprinted and then the least empty; one with the plan of accelerations only when
    none without it meets the standard.

    Raises
    ------
    InputError
        No arrangement has room for every part (the first part's refusal).
    """
    best: tuple[tuple[bool, int, float], Scene] | None = None     # (faulty, labels clashing, empty share), sheet
    error: InputError | None = None
    for boxes in arrangements:
        if "acceleration" in boxes and best is not None and not best[0][0]:
            break
        try:
            scene = draw(boxes)
        except InputError as e:
            error = error or e
            continue
        q = measure(scene)
        found = faults(q)
        score = (bool(found), len(q.crossed) + len(q.overlaps), q.empty_share)
        if best is None or score < best[0]:
            best = (score, scene)
        if not found and q.empty_share <= AIM:
            break
    if best is None:
        raise error or InputError("the force sheet has no room for its parts on A2; draw it on A1")
    return best[1]


def _assemble(sheet: Sheet, parts: list[tuple[Scene, str]], col_els: list[Element],
              tail: list[tuple[Group, tuple[Any, ...]]], name: str) -> Scene:
    """The sheet of the drawn ``parts`` (scheme, lever, then the groups and plans), the column and the graph."""
    groups = [inset(scene, nm) for scene, nm in parts]
    plans = Group(elements=tuple(g for (g, _), (_, nm) in zip(groups, parts) if nm[:5] in ("group", "plan-")),
                  name="plans")
    scales = tuple(s for _, part_scales in groups + tail for s in part_scales)
    notes = tuple(f"{nm}: {note}" for scene, nm in parts for note in scene.notes)
    others = [g for (g, _), (_, nm) in zip(groups, parts) if nm == "acceleration"]
    return Scene(sheet.page(groups[0][1]), (sheet.header(), groups[0][0], groups[1][0], *others, plans, *col_els,
                                            *(g for g, _ in tail)),
                 title=sheet.title, notation=sheet.nt.code, name=name, extra_scales=scales, notes=notes)


def column_width(column: Column, nt: Any, pg: Page, tb_w: float) -> float:
    """The result column's width (mm): its widest table, or the reactions' and the inertia loads' tables side
    by side when the title block under them is that wide, its notes and heading; at least the title block's."""
    let = lettering(pg)
    res, react, inert = column.tables
    pair = react.width_mm + GAP_MM.get(pg.size, 8.0) + inert.width_mm
    tables = pair if pair <= tb_w - 5.0 else max(react.width_mm, inert.width_mm)
    heading = text_width_mm(nt.word("forces.sheet_result"), let.value_mm) * 1.08
    notes = max([text_width_mm(t, let.label_mm) for t in column.notes] + [0.0])
    return max(res.width_mm, tables, heading, notes, tb_w - 5.0) + 4.0


def column_elements(box: Box, column: Column, nt: Any, pg: Page, gap: float) -> tuple[list[Element], Box | None]:
    """The result column in ``box``: its heading, tables (the reactions and the inertia loads side by side when
    the box is wide enough), notes, the inertia loads worked out when they fit (at the values' size, else at the
    labels'), and the box left under them for M_b(φ) (None when under :data:`GRAPH_MM`)."""
    let = lettering(pg)
    size = let.value_mm
    x, y, x1, y1 = box
    els: list[Element] = [Text((x, y + size), nt.word("forces.sheet_result"), size_mm=size, bold=True,
                               name="result-heading")]
    y += 2.5 * size
    res, react, inert = column.tables
    side = react.width_mm + gap + inert.width_mm <= x1 - x
    spots = [(x, y), (x, y + res.height_mm + 2.0 * size)]
    spots.append((x + react.width_mm + gap, spots[1][1]) if side
                 else (x, spots[1][1] + react.height_mm + 2.0 * size))
    for tab, (tx, ty), nm in zip(column.tables, spots, ("result", "reactions", "inertia")):
        table = Table((tx, ty), tab.rows, align=tab.align, size_mm=size, row_height_mm=2.0 * size, name=nm)
        els.append(table)
        y = max(y, table.bottom_left[1] + 2.0 * size)
    els += [Text((x, y + k * 1.8 * let.label_mm), note, size_mm=let.label_mm, name=f"note-{k}")
            for k, note in enumerate(column.notes)]
    y += len(column.notes) * 1.8 * let.label_mm + gap
    for mm in (size, let.label_mm):
        lines = working_lines(column.working, x, y, mm, x1 - x)
        if lines and lines[-1].at[1] <= y1:
            els += lines
            y = lines[-1].at[1] + gap
            break
    return els, ((x - 2.0, y, x1, y1) if y1 - y >= GRAPH_MM else None)


def working_lines(working: tuple[tuple[str, bool], ...], x: float, y: float, mm: float, width: float) -> list[Text]:
    """The working's lines at ``mm`` from ``y`` down, or none when one is wider than ``width`` (mm)."""
    if any(text_width_mm(t, mm) * (1.08 if head else 1.0) > width for t, head in working):
        return []
    out = []
    for k, (line, head) in enumerate(working):
        y += (2.2 if head and k else 1.8) * mm
        out.append(Text((x, y), line, size_mm=mm, bold=head, name=f"working-{k}"))
    return out


def result_column(case: Any, fa: Any, i: int, nt: Any, pg: Page, gravity: bool) -> Column:
    """The result column of position ``i``: the A1 sheet's three tables, the notes that say what R′_01 is (and
    that the weights act), the inertia loads worked out."""
    from graphmethods.sheets.force_analysis_sheet import _inertia_rows, _result_rows

    size = lettering(pg).value_mm
    result, react, inert = _result_rows(fa, i, nt), SF._plans_results(fa, i, nt, gravity)[0], _inertia_rows(fa, i, nt)
    tables = tuple(Table((0.0, 0.0), tuple(r), align=a, size_mm=size, row_height_mm=2.0 * size)
                   for r, a in ((result, "lrr"), (react, "cr"), (inert, "crr")))
    notes = ([nt.word("forces.crank_prime", R="R′_{01}", Fb=nt.sym("forces.F_b"), Mb=nt.sym("forces.M_b"))]
             + ([nt.word("forces.weights")] if gravity else []))
    loads = inertia_working(case, fa, i, nt)
    working = [(nt.word("forces.inertia_loads"), True)] + [(t, False) for t in loads] if loads else []
    return Column(tables, tuple(notes), tuple(working))  # type: ignore[arg-type]


def headings(fa: Any, nt: Any, pg: Page) -> dict[str, float]:
    """The least width (mm) of each part, by its name: its heading (bold, at the page's title size), and for the
    scheme and the lever their line under the drawing (two scales, 10 mm apart, and the legend)."""
    let = lettering(pg)
    out = {"scheme": nt.word("forces.scheme_short"), "lever": nt.word("forces.lever_short")}
    for j, pl in enumerate(fa.plans):
        out[f"group-{j}"] = nt.word("forces.cut_group")
        out[f"plan-{j}"] = (nt.word("forces.crank", g=pl.links[0]) if pl.group.startswith("I ")
                            else nt.word("forces.group", g=pl.group))
    least = {k: text_width_mm(t, let.title_mm) * 1.08 + 2.0 for k, t in out.items()}
    scales = text_width_mm(f"μ_l = 0.001 {nt.unit('m')}/{nt.unit('mm')}  μ_F = 100 {nt.unit('N')}/{nt.unit('mm')}",
                           let.label_mm) + 20.0
    for k in ("scheme", "lever"):
        least[k] = max(least[k], scales + text_width_mm(nt.word(f"forces.{k}_legend"), let.label_mm))
    return least


def headings_fit(boxes: dict[str, Box], heads: dict[str, float]) -> bool:
    """Is every part's box as wide as its heading?"""
    return all(b[2] - b[0] >= heads.get(k, 0.0) - 0.5 for k, b in boxes.items())


def _pairs(n: int, gap: float, how: str, group: float = 0.4) -> Split:
    """The groups cut from the linkage and their plans: ``"columns"``, each group over its plan, side by side;
    ``"rows"``, each group beside its plan (``group`` of the width), one pair under another."""
    if how == "rows":
        return Split("v", tuple((Split("h", ((f"group-{j}", group), (f"plan-{j}", 1.0 - group)), gap_mm=gap), 1.0)
                                for j in range(n)), gap_mm=gap)
    return Split("h", tuple((Split("v", ((f"group-{j}", 0.45), (f"plan-{j}", 0.55)), gap_mm=gap), 1.0)
                            for j in range(n)), gap_mm=gap)


def arrangements(fa: Any, i: int, box: Box, gap: float, *, accelerations: bool = True,
                 least: dict[str, float] | None = None) -> list[Split]:
    """The arrangements of the drawings in ``box`` (mm), the likeliest first: by the linkage's shape (a tall
    linkage in a column at the left over the lever, a flat one in a row across the top with the lever beside
    it); the last, with ``accelerations``, have the plan of accelerations beside the scheme and the lever under
    it. Columns are at least as wide as their parts' ``least`` (mm, :func:`headings`)."""
    from graphmethods.sheets.force_analysis_sheet import _aspect, _pairs as a1_pairs

    mo = fa.motion
    scheme = _aspect([complex(mo.z[p][i]) for p in mo.points] + SF._guide_ends(mo, SF._links_of(mo, i)[1]))
    n = len(fa.plans)
    W, H = box[2] - box[0], box[3] - box[1]
    least = least or {}
    g_mm = max([v for k, v in least.items() if k.startswith("group")] + [0.0])

    def group(width: float) -> float:                       # the group's share of a row: its heading's width
        return min(0.6, max(0.4, (g_mm + gap / 2) / width))

    hows = ("rows", "columns") if a1_pairs(fa, i, n, gap).direction == "v" else ("columns", "rows")  # the A1 rule
    out = []
    if scheme < 1.2:                                        # a tall linkage: the scheme in a column at the left
        w_s = max(W * min(0.4, max(0.22, scheme * H / W + 0.06)), least.get("scheme", 0.0), least.get("lever", 0.0))
        rest = W - w_s - gap
        for how in ("rows", "columns"):
            out.append(Split("h", ((Split("v", (("scheme", 0.62), ("lever", 0.38)), gap_mm=gap), w_s),
                                   (_pairs(n, gap, how, group(rest)), rest)), gap_mm=gap))
    for h_s in (0.42, 0.5, 0.36):                            # a flat one (or a tall one's last resort): rows
        for how in hows:
            top = Split("h", (("scheme", 0.6), ("lever", 0.4)), gap_mm=gap)
            out.append(Split("v", ((top, h_s), (_pairs(n, gap, how, group(W)), 1.0 - h_s)), gap_mm=gap))
    if scheme > 2.0:                                        # a long one: wider and lower, the lever narrower
        w_l = max(least.get("lever", 0.0), 0.3 * W)
        for how in hows:
            top = Split("h", (("scheme", W - w_l - gap), ("lever", w_l)), gap_mm=gap)
            out.append(Split("v", ((top, 0.36), (_pairs(n, gap, how, group(W)), 0.64)), gap_mm=gap))
    if accelerations:                                       # a sparse sheet: the plan of accelerations fills it
        w_s, w_l = max(least.get("scheme", 0.0), 0.35 * W), max(least.get("lever", 0.0), 0.35 * W)
        for how in ("rows", "columns"):
            top = Split("h", (("scheme", w_s), ("acceleration", W - w_s - gap)), gap_mm=gap)
            bottom = Split("h", (("lever", w_l), (_pairs(n, gap, how, group(W - w_l)), W - w_l - gap)), gap_mm=gap)
            out.append(Split("v", ((top, 0.45), (bottom, 0.55)), gap_mm=gap))
    return out


def _inside(scene: Scene, box: Box) -> bool:
    """Does every element of ``scene`` lie in ``box`` (mm, within :data:`SLACK_MM`)?"""
    boxes = [b for b in (e.bbox() for e in scene.elements) if b is not None]
    return all(b[0] >= box[0] - SLACK_MM and b[1] >= box[1] - SLACK_MM and b[2] <= box[2] + SLACK_MM
               and b[3] <= box[3] + SLACK_MM for b in boxes)


def draw_parts(case: Any, fa: Any, i: int, boxes: dict[str, Box], pg: Page, nt: Any, *, phi_deg: float | None,
               m: int, gravity: bool) -> list[tuple[Scene, str]]:
    """The scheme, the lever and each group and plan drawn into their ``boxes``; a plan whose lettering leaves
    its box drawn again without its working.

    Raises
    ------
    InputError
        A part with no room in its box.
    """
    from graphmethods.sheets.force_analysis_sheet import _panel_layout

    at_k = i if phi_deg is None else None
    kw: dict[str, Any] = {"phi_deg": phi_deg, "m": m, "notation": nt, "title_block": False, "gravity": gravity}
    parts = [(SF.force_scheme(case, at_k, **kw, page=region_page(pg, boxes["scheme"]),
                              title=nt.word("forces.scheme_short"), layout=_panel_layout(boxes["scheme"])), "scheme"),
             (SF.zhukovsky_forces(case, at_k, **kw, page=region_page(pg, boxes["lever"]),
                                  title=nt.word("forces.lever_short"), layout=_panel_layout(boxes["lever"])),
              "lever")]
    if "acceleration" in boxes:
        from graphmethods.sheets.force_analysis_sheet import _acceleration

        accel = _acceleration(case, i, m, nt, pg, boxes["acceleration"])
        if accel is None:
            raise InputError("the plan of accelerations does not fit its box")
        parts.append((accel, "acceleration"))
    for j in range(len(fa.plans)):
        g_box, p_box = boxes[f"group-{j}"], boxes[f"plan-{j}"]
        plan = plan_panel(case, fa, i, j, nt=nt, page=region_page(pg, p_box))
        if not _inside(plan, p_box):
            plan = plan_panel(case, fa, i, j, nt=nt, page=region_page(pg, p_box), working=False)
        parts += [(group_panel(case, fa, i, j, nt=nt, page=region_page(pg, g_box)), f"group-{j}"),
                  (plan, f"plan-{j}")]
    return parts


__all__ = ["Column", "arrangements", "column_elements", "column_width", "draw_parts", "force_sheet_a2", "fullest",
           "result_column"]
