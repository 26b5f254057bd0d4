"""The balancing moment over the cycle: M_b at positions 0…m from the force plans, the position analysed marked.

On the force sheet, beside the result table: the course finds M_b by the force plans (and checks it by
Zhukovsky's lever) in every position; the graph joins the ordinates M_b(φ_k) by chords, as drawn by hand,
and marks the position the sheet analyses (its ordinate a main line), its value written under the graph (the
result table's), on a dotted grid of its positions and M_b ticks (read off as on graph paper). The φ axis runs from
position 0 to m (its tick marks numbered by position), the M_b axis has nice ticks
(:func:`~graphmethods.sheets.engine.axes.nice_ticks`), every one labelled, and includes 0.

>>> from graphmethods.problems import builtin
>>> from graphmethods.scene import Page
>>> from graphmethods.sheets.forces import analysed
>>> fa, i = analysed(builtin.case("press"), position=3, phi_deg=None, m=12)
>>> s = balancing_graph(fa, i, page=Page("A4", "landscape", frame=True))
>>> len([e for e in s.elements if e.name.startswith("ordinate-") and e.name[9:].isdigit()])   # positions 0…12
13
"""

from __future__ import annotations

from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import Element, Line, Page, Point, Polyline, Scale, Text, notation as get_notation
from graphmethods.scene.primitives import DOTTED, THIN
from graphmethods.sheets.engine.axes import nice_ticks
from graphmethods.sheets.engine.lettering import lettering
from graphmethods.sheets.forces import round_off_zero
from graphmethods.sheets.layout import Sheet


def balancing_graph(fa: Any, i: int, *, notation: Any = "en", page: Page, name: str = "balancing-graph") -> Any:
    """The graph M_b(φ) of a force analysis over positions 0…m, position ``i`` marked (see the module docstring).

    Parameters
    ----------
    fa : ForceAnalysis
        ``case_forces(case, m=m)``: the balancing moment at every position (N·m).
    i : int
        The position the sheet analyses.
    page : Page
        Where to draw (a region of the sheet).

    Raises
    ------
    InputError
        A force analysis of one crank angle (no cycle to draw) or a panel too small.
    """
    nt = get_notation(notation)
    M = np.asarray(fa.M_balance, dtype=float)
    n = len(M)
    if n < 3:
        raise InputError("the balancing moment over the cycle needs the force analysis of every position")
    big = float(np.abs(M).max())
    M = np.array([round_off_zero(float(v), big) for v in M])
    M_b = nt.sym("forces.M_b")
    sheet = Sheet(nt=nt, page=page, title=nt.word("forces.mb_graph", Mb=M_b), problem="", title_block=False)
    size = lettering(page).label_mm
    ticks = nice_ticks(min(float(M.min()), 0.0), max(float(M.max()), 0.0), 6)
    label_w = max(len(nt.number(t, sig=6)) for t in ticks) * 0.62 * size + 3.0
    x0, x1 = sheet.box[0] + label_w + 2.0, sheet.box[2] - 4.0
    y0, y1 = sheet.top + 2.0 * size, sheet.caption_y - 5.5 * size
    if x1 - x0 < 30.0 or y1 - y0 < 30.0:
        raise InputError("the balancing-moment graph has no room on this page; give a larger page")
    lo, hi = ticks[0], ticks[-1]
    s_M = _scale(hi - lo, y1 - y0, nt)
    y1 = y0 + (hi - lo) / s_M.per_mm                # the graph as tall as its scale draws it, under its heading,
    sheet.caption_y = y1 + 5.5 * size               # its numbers and scale line right under it
    dx = (x1 - x0) / (n - 1)

    def at(k: float, v: float) -> tuple[float, float]:
        return (x0 + k * dx, y1 - (v - lo) / s_M.per_mm)

    zero = at(0, 0.0)[1]
    els: list[Element] = [sheet.header(),
                          Line((x0, y1), (x0, y0 - 0.5 * size), name="axis-M"),
                          Line((x0, zero), (x1 + 2.0, zero), name="axis-phi"),
                          Text((x0 + 1.5, y0 - size), f"{M_b}, {nt.unit('N·m')}", size_mm=size, name="axis-M-label")]
    for k in range(1, n):                          # the grid: a dotted line at every position and every tick
        els.append(Line(at(k, lo), at(k, hi), style=DOTTED, name=f"grid-phi-{k}"))
    for t in ticks:
        y = at(0, t)[1]
        if t != 0.0:
            els.append(Line((x0, y), (at(n - 1, t)[0], y), style=DOTTED, name=f"grid-M-{t:g}"))
        els += [Line((x0 - 1.5, y), (x0, y), name=f"tick-M-{t:g}"),
                Text((x0 - 2.5, y + 0.35 * size), nt.number(t, sig=6), size_mm=size, anchor="end",
                     name=f"tick-label-M-{t:g}")]
    for k in range(n):
        x, y = at(k, float(M[k]))
        els.append(Line((x, zero), (x, y), style=THIN, name=f"ordinate-{k}"))
        if k % max(1, (n - 1) // 12) == 0:                   # the positions' numbers in a row under the graph
            els.append(Text((x, y1 + 1.6 * size), str(k), size_mm=size, anchor="middle", name=f"position-{k}"))
    els.append(Polyline(tuple(at(k, float(M[k])) for k in range(n)), name="curve-M_b"))
    mark = at(i, float(M[i]))
    value = f"{nt.word('forces.position_value', k=i)}: {M_b} = {nt.number(float(M[i]), sig=6)} {nt.unit('N·m')}"
    els += [Point(mark, radius_mm=1.0, name="mark"),
            Line((mark[0], zero), mark, name=f"ordinate-{i}-analysed"),
            Text((sheet.box[0], y1 + 3.4 * size), value, size_mm=size, name="mark-value")]
    els += sheet.captions((s_M,), legend="")
    return sheet.scene(els, (s_M,), name=name)


def _scale(span: float, span_mm: float, nt: Any) -> Scale:
    """The M_b scale (N·m per mm): the largest convenient value that draws ``span`` within ``span_mm``."""
    from graphmethods.scene.scale import pick_scale

    return pick_scale(max(span, 1e-12), span_mm, symbol="μ_M", unit=nt.unit("N·m"))


__all__ = ["balancing_graph"]
