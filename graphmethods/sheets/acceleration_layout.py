"""Where an acceleration plan, its table, its ε and its equations go on a page or in a panel's box.

A plan drawn large (:func:`~graphmethods.sheets.acceleration.acceleration_plan`) has four parts: the plan,
the table of its vectors, the angular accelerations ε of the links and the vector equations with their
known values. A dyad's fit on an A4 page in one way; a triad's (class III: the Assur-point equation, some
twenty lines of equations and a table of twenty vectors) or a small panel of an A1 sheet need another. This
module lists the arrangements a draftsman uses and takes the one that gives the plan the largest convenient
scale with no text set on another text or under the table:

- ``under``: the table (and ε) in a column beside the plan, the equations under the plan (the full width
  where the column has ended above them, else the plan's width);
- ``beside``: the equations in the column under the table, the plan the whole height;
- ``wide``: the plan under the column, as wide as the page, the equations under it;
- ``two``: on a slide, the equations in two columns under the plan.

Each arrangement is tried with ε in the column and with ε after the equations, and with the known values
on the equation's line or each on a line of its own; a line still wider than its room is broken at an
"=" (the continuation set under the first "=", as a textbook writes a system) or after a comma. The
rectangles are computed from the texts' real widths (:func:`~graphmethods.scene.markup.text_width_mm`)
before anything is drawn, so the choice is deterministic.

>>> lines = wrap("a_{K3} = a_{A} + a^{n}_{BA} = a_{E} + a^{n}_{CE} (Assur's point)", 40.0, 3.2)
>>> [t for t, _ in lines]
['a_{K3} = a_{A} + a^{n}_{BA}', "= a_{E} + a^{n}_{CE} (Assur's point)"]
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.scene import markup
from graphmethods.sheets.layout import TEXT_MM
from graphmethods.units import convenient_at_least

#: one line of text: (element name, markup, indent in mm); consecutive lines of one name are one text broken
Line_ = tuple[str, str, float]
Block = list[Line_]
Box = tuple[float, float, float, float]
#: the plan's area may reach this near (mm) the column of its table, when that gives it a larger scale
CLOSE_GAP_MM = 0.5


def _width(t: str) -> float:
    return markup.text_width_mm(t, TEXT_MM)


def wrap(text: str, width: float, size_mm: float = TEXT_MM) -> list[tuple[str, float]]:
    """A line of markup broken to ``width`` mm: (text, indent mm) per line, at " = " (the next line starting
    with "=" under the first "=") or after ", " (the next line indented); one line when it fits or cannot
    be broken.

    >>> [t for t, _ in wrap("ε_{3} = 7.4/0.2 = 35.9 rad/s², clockwise", 54.0)]
    ['ε_{3} = 7.4/0.2 = 35.9 rad/s²,', 'clockwise']
    """
    if markup.text_width_mm(text, size_mm) <= width:
        return [(text, 0.0)]
    commas = [c.strip() for c in text.split(", ")]
    by_comma = [p + ("," if j < len(commas) - 1 else "") for j, p in enumerate(commas)]
    if all(markup.text_width_mm(p, size_mm) <= width - 6.0 for p in by_comma):      # after the commas alone
        return _fill(by_comma, width, 6.0, size_mm)
    pieces: list[str] = []
    for i, side in enumerate(text.split(" = ")):
        parts = [p.strip() for p in side.split(", ")]
        for j, p in enumerate(parts):
            pieces.append(("= " if i and not j else "") + p + ("," if j < len(parts) - 1 else ""))
    eq_dx = markup.text_width_mm(text.split(" = ")[0] + " ", size_mm) if " = " in text else 6.0
    return _fill(pieces, width, eq_dx if eq_dx < width / 3 else 6.0, size_mm)


def _fill(pieces: list[str], width: float, dx: float, size_mm: float) -> list[tuple[str, float]]:
    """The pieces of a text set greedily on lines ``width`` mm wide, every line after the first ``dx`` in."""
    out: list[tuple[str, float]] = []
    cur = ""
    for p in pieces:
        trial = f"{cur} {p}" if cur else p
        room = width - (dx if out else 0.0)
        if cur and markup.text_width_mm(trial, size_mm) > room:
            out.append((cur, dx if out else 0.0))
            cur = p
        else:
            cur = trial
    out.append((cur, dx if out else 0.0))
    return out


def text_blocks(phi: str, eqs: list[tuple[str, str]], eps: list[tuple[str, str]], *, split_values: bool,
                eps_in_text: bool, width: float) -> list[Block]:
    """The blocks of text under (or beside) the plan: φ, each equation with its known values under it (on a
    line of their own, or each on its own line when ``split_values``), then ε of the links when
    ``eps_in_text``; every line broken to ``width`` mm (:func:`wrap`)."""
    def lines(name: str, text: str, dx: float) -> Block:
        return [(name, t, dx + d) for t, d in wrap(text, width - dx)]

    blocks: list[Block] = [lines("equation-phi", phi, 0.0)]
    dx = 6.0
    for j, (a, b) in enumerate(eqs):
        block = lines(f"equation-{j}", a, 0.0)
        long = bool(b) and _width(b) + dx > width                        # too wide on one line: split it
        vals = (b.split(";  ") if split_values or long else [b]) if b else []
        for i, t in enumerate(vals):
            block += lines(f"values-{j}" + (f"-{i}" if i else ""), t, dx)
        blocks.append(block)
    if eps_in_text:
        blocks.append([ln for link, t in eps for ln in lines(f"epsilon-{link}", t, 0.0)])
    return blocks


@dataclass(frozen=True)
class Arrangement:
    """Where the parts of one acceleration plan go (mm).

    Attributes
    ----------
    kind : str
        ``"under"``, ``"beside"``, ``"wide"`` or ``"two"`` (see the module docstring).
    area : Box
        The plan's area.
    split : float
        Where the column of the table begins (the table at ``split`` + the column's inset).
    columns : list of list of Block
        The text under or beside the plan, in one column or two.
    origins : list of (float, float)
        Where each column's first line begins (its baseline's start).
    eps_in_column : bool
        ε of the links under the table (else at the end of the text).
    column_bottom : float
        How far down the table and ε may reach.
    need : float
        The convenient μ_a per mm the plan gets in ``area`` (smaller: a larger plan).
    """

    kind: str
    area: Box
    split: float
    columns: list[list[Block]]
    origins: list[tuple[float, float]]
    eps_in_column: bool
    column_bottom: float
    need: float


def plan_need(area: Box, arr: np.ndarray, margin_mm: float) -> float:
    """The convenient μ (per mm) a plan of points ``arr`` (n, 2) gets in ``area`` within its margins (inf when
    the area has no room).

    >>> plan_need((0, 0, 120, 120), np.array([[0.0, 0.0], [10.0, 5.0]]), 10.0)
    0.1
    """
    aw, ah = area[2] - area[0] - 2 * margin_mm, area[3] - area[1] - 2 * margin_mm
    span = np.ptp(arr, axis=0)
    if aw <= 0 or ah <= 0 or max(span) <= 0:
        return math.inf
    return convenient_at_least(max(float(span[0]) / aw, float(span[1]) / ah))


@dataclass(frozen=True)
class Parts:
    """What is to be arranged: the sheet's room, the table's size, the texts, the plan's points."""

    box: Box                  # the sheet's content box
    top: float                # where the drawing may begin
    bottom: float             # where the plan or its text must end (above the captions)
    table_w: float
    table_h: float
    phi: str
    eqs: list[tuple[str, str]]
    eps: list[tuple[str, str]]
    arr: np.ndarray           # the plan's points (n, 2), m/s²
    slide: bool               # a slide: the text may go in two columns


def _column(parts: Parts, lay, eps_in_column: bool) -> tuple[float, float]:
    """The column's width and bottom (mm) with or without ε under the table."""
    eps_w = [_width(t) for _, t in parts.eps] if eps_in_column else []
    w = max([parts.table_w, 60.0] + eps_w)
    bottom = parts.top + lay.column_x_mm + parts.table_h + (
        lay.after_table_mm + lay.line_mm * len(parts.eps) if eps_in_column else 0.0)
    return w, bottom


def _height(col: list[Block], lay) -> float:
    return sum(len(b) for b in col) * lay.equation_mm + 2.0


def _clear_of(col: list[Block], at: tuple[float, float], right: float, column_bottom: float, lay) -> bool:
    """No line of ``col`` set from ``at`` reaches past ``right`` (mm) above ``column_bottom``."""
    row = 0
    for b in col:
        for _, t, dx in b:
            y = at[1] + row * lay.equation_mm
            if y - TEXT_MM < column_bottom and at[0] + dx + _width(t) > right:
                return False
            row += 1
    return True


def _two_columns(blocks: list[Block]) -> list[list[Block]]:
    n, count = sum(len(b) for b in blocks), 0
    for i, b in enumerate(blocks):
        count += len(b)
        if count >= n / 2:
            return [blocks[:i + 1], blocks[i + 1:]]
    return [blocks]


@dataclass(frozen=True)
class _Try:
    """One way of setting the text (ε in the column or not, values split or not) against one column."""

    parts: Parts
    lay: Any
    blocks: Callable[[float], list[Block]]      # the text broken to a width (mm)
    split: float
    col_w: float
    col_bottom: float
    eps_in_column: bool
    gap: float                                   # between the plan's area and the split (mm)

    def make(self, kind: str, area: Box, columns: list[list[Block]], origins, split: float | None = None):
        return Arrangement(kind, area, self.split if split is None else split, columns, origins, self.eps_in_column,
                           self.col_bottom, plan_need(area, self.parts.arr, self.lay.margin_mm))


def _under(t: _Try) -> list[Arrangement]:
    """The text under the plan: the full width (clear of the column) or the plan's own."""
    lay, x0, x1 = t.lay, t.parts.box[0], t.parts.box[2]
    right = t.split - t.gap
    out = []
    for width in (x1 - x0, right - x0):
        col = t.blocks(width)
        area = (x0, t.parts.top - lay.above_mm, right, t.parts.bottom - _height(col, lay))
        at = (x0, area[3] + lay.equations_below_mm)
        if area[3] - area[1] >= lay.min_plan_mm and _clear_of(col, at, right, t.col_bottom, lay):
            out.append(t.make("under", area, [col], [at]))
    return out


def _two(t: _Try) -> list[Arrangement]:
    """The text in two columns under the plan, below the column (a slide, a triad's many equations)."""
    lay, x0, x1 = t.lay, t.parts.box[0], t.parts.box[2]
    if not (t.parts.slide or len(t.parts.eqs) > 4):
        return []
    half = (x1 - x0) / 2 - 4.0
    cols = _two_columns(t.blocks(half))
    area = (x0, t.parts.top - lay.above_mm, t.split - t.gap,
            t.parts.bottom - max(_height(c, lay) for c in cols))
    if area[3] - area[1] < lay.min_plan_mm or area[3] < t.col_bottom:
        return []
    y = area[3] + lay.equations_below_mm
    return [t.make("two", area, cols, [(x0, y), (x0 + half + lay.equation_columns_gap_mm, y)])]


def _flow(t: _Try) -> list[Arrangement]:
    """The text run in two columns: under the plan in its width, then on under the table (a triad's many
    equations on an upright page), as little under the plan as the room under the table allows."""
    lay, x0, x1 = t.lay, t.parts.box[0], t.parts.box[2]
    wa, xb = t.split - t.gap - x0, t.split + lay.column_x_mm
    wb, top_b = x1 - xb, t.col_bottom + lay.equations_below_mm
    in_a, in_b = t.blocks(wa), t.blocks(wb)
    if wb < 40.0:
        return []
    for cut in range(1, len(in_a)):
        col_b = in_b[cut:]
        if top_b + _height(col_b, lay) - 2.0 > t.parts.bottom or any(dx + _width(s) > wb for b in col_b
                                                                      for _, s, dx in b):
            continue
        col_a = in_a[:cut]
        area = (x0, t.parts.top - lay.above_mm, t.split - t.gap, t.parts.bottom - _height(col_a, lay))
        if area[3] - area[1] < lay.min_plan_mm:
            return []
        return [t.make("flow", area, [col_a, col_b], [(x0, area[3] + lay.equations_below_mm), (xb, top_b)])]
    return []


def _beside(t: _Try, split_of) -> list[Arrangement]:
    """The text in the column under the table, the plan the whole height."""
    lay, x0, x1 = t.lay, t.parts.box[0], t.parts.box[2]
    col = t.blocks(x1 - split_of(t.col_w) - lay.column_x_mm)
    widest = max(dx + _width(s) for b in col for _, s, dx in b)
    split_b = split_of(max(t.col_w, widest + lay.column_x_mm))
    top_b = t.col_bottom + lay.equations_below_mm
    if split_b + lay.column_x_mm + max(widest, t.col_w) > x1 + 1e-6 or \
            top_b + _height(col, lay) - 2.0 > t.parts.bottom:
        return []
    area = (x0, t.parts.top - lay.above_mm, split_b - lay.plan_gap_mm, t.parts.bottom)
    return [t.make("beside", area, [col], [(split_b + lay.column_x_mm, top_b)], split=split_b)]


def _wide(t: _Try) -> list[Arrangement]:
    """The plan under the column, the whole width; the text under it."""
    lay, x0, x1 = t.lay, t.parts.box[0], t.parts.box[2]
    col = t.blocks(x1 - x0)
    area = (x0, t.col_bottom + lay.plan_gap_mm, x1, t.parts.bottom - _height(col, lay))
    if area[3] - area[1] < lay.min_plan_mm:
        return []
    return [t.make("wide", area, [col], [(x0, area[3] + lay.equations_below_mm)])]


def _tries(parts: Parts, lay, split_of, gap: float) -> list[_Try]:
    out = []
    for eps_in_column in (True, False):
        col_w, col_bottom = _column(parts, lay, eps_in_column)
        split = split_of(col_w)
        if split + lay.column_x_mm + col_w > parts.box[2] + 1e-6 or col_bottom > parts.bottom:
            continue
        for split_values in (False, True):
            def blocks(width: float, sv: bool = split_values, ec: bool = eps_in_column) -> list[Block]:
                return text_blocks(parts.phi, parts.eqs, parts.eps, split_values=sv, eps_in_text=not ec, width=width)

            out.append(_Try(parts, lay, blocks, split, col_w, col_bottom, eps_in_column, gap))
    return out


def _candidates(parts: Parts, lay, split_of) -> list[Arrangement]:
    """Every arrangement that fits, in the order of preference when two give the plan the same scale; last,
    the plan's area reaching nearer the table (only taken when that gives a larger scale)."""
    out: list[Arrangement] = []
    for t in _tries(parts, lay, split_of, lay.plan_gap_mm):
        out += _under(t) + _two(t) + _beside(t, split_of) + _wide(t)
    for t in _tries(parts, lay, split_of, lay.plan_gap_mm):
        out += _flow(t)
    for t in _tries(parts, lay, split_of, CLOSE_GAP_MM):
        out += _under(t) + _two(t) + _flow(t)
    return out


def arrange(parts: Parts, lay, split_of) -> Arrangement | None:
    """The arrangement that gives the plan the largest convenient scale (the first listed among equals), or
    None when none fits (``split_of(width)``: where the plan's share ends for a column ``width`` mm wide)."""
    best: Arrangement | None = None
    for a in _candidates(parts, lay, split_of):
        if best is None or a.need < best.need * (1 - 1e-9):
            best = a
    return best


__all__ = ["Arrangement", "Parts", "arrange", "plan_need", "text_blocks", "wrap"]
