"""Graphical calculus sheets: the slider's kinematic diagrams s, v, a and the work diagrams M → A.

:func:`kinematic_diagrams` draws the slider's displacement s(φ) over the m positions, its velocity
v by graphical differentiation of s (chords of s, rays from the pole P₁ parallel to them, the
ordinates projected to the middles of the intervals) and its acceleration a by differentiating
the v curve again (pole P₂), each graph with its scale, and a table comparing v with the velocity
plans and v, a with the analytic values. :func:`work_diagrams` integrates the moment diagram
M_d, M_r by the method of chords (mean ordinates, their projections, rays to the pole P at H mm,
chords parallel to the rays) into the work diagrams A_d(φ), A_r(φ) and ΔE(φ) = A_d − A_r, as
Russian course sheets draw them, with the accuracy of each construction.

Construction lines are thin, results thick; every scale is captioned under the figure and beside
its graph with the formula that gives it. ``notation="en" | "ru" | "zh"`` switches every symbol
and word. Pole distances are picked (convenient values that fit the sheet) unless given, and the
figure says which.

>>> import pathlib
>>> from graphmethods.kinematics import read_case
>>> case = read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json")
>>> scene = kinematic_diagrams(case)
>>> [s.symbol for s in scene.scales()]
['μ_φ', 'μ_s', 'μ_v', 'μ_a', 'μ_t']
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from graphmethods.dynamics import graphical_calculus as gc
from graphmethods.errors import InputError
from graphmethods.scene import markup, notation as get_notation
from graphmethods.scene.elements import (
    ASCENT,
    DESCENT,
    Axis,
    Dimension,
    Element,
    Frame,
    Line,
    Point,
    Polyline,
    Table,
    Text,
    label_bbox,
    lettered_size,
)
from graphmethods.scene.notation import Notation
from graphmethods.scene.page import Page
from graphmethods.scene.primitives import MAIN, THIN, Style
from graphmethods.scene.scale import Scale, pick_angle_scale, pick_scale
from graphmethods.scene.scene import Scene
from graphmethods.scene.ticks import axis_ticks
from graphmethods.sheets.layout import TEXT_MM, TIE_MM, Occupancy, Sheet, clear_tick_labels, problem_title
from graphmethods.sheets.styles import PROJECTION

SMALL_MM = 2.6          # tick labels, position numbers
TABLE_MM = 2.9          # the accuracy tables
RAY = Style(width_mm=0.13)                       # rays from the poles: the finest construction lines
CHORD = Style(width_mm=0.18, stroke="#000000")
RESULT = MAIN
TWO_PI = 2.0 * math.pi
Rows = Sequence[Sequence[str]]

def _scale_unit(nt: Notation, u: str) -> str:
    """A unit for a scale caption: compound units in brackets, ``(m/s)/mm``."""
    t = nt.unit(u)
    return f"({t})" if "/" in t else t


# ----------------------------------------------------------------------------- drawing helpers

def smooth_through(x: ArrayLike, y: ArrayLike, *, period: float | None = None,
                   per_interval: int = 12) -> tuple[np.ndarray, np.ndarray]:
    """A smooth curve through the points (x_k, y_k), as drawn with a French curve.

    Cubic Hermite pieces with Catmull–Rom tangents (central differences), closed across the
    period when ``period`` is given (the tangents at the ends then see the wrapped
    neighbours). The curve passes through every point exactly.

    >>> xs, ys = smooth_through([0.0, 1.0, 2.0], [0.0, 1.0, 0.0], per_interval=2)
    >>> xs.tolist(), ys.round(3).tolist()
    ([0.0, 0.5, 1.0, 1.5, 2.0], [0.0, 0.625, 1.0, 0.625, 0.0])
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    n = x.size
    if n < 2:
        raise InputError("a curve needs at least two points")
    if period is not None and n >= 3:
        xe = np.concatenate(([x[-2] - period if x[-1] - x[0] >= period * (1 - 1e-12) else x[-1] - period],
                             x,
                             [x[1] + period if x[-1] - x[0] >= period * (1 - 1e-12) else x[0] + period]))
        ye = np.concatenate(([y[-2] if x[-1] - x[0] >= period * (1 - 1e-12) else y[-1]], y,
                             [y[1] if x[-1] - x[0] >= period * (1 - 1e-12) else y[0]]))
        tan = (ye[2:] - ye[:-2]) / (xe[2:] - xe[:-2])
    else:
        tan = np.empty(n)
        tan[1:-1] = (y[2:] - y[:-2]) / (x[2:] - x[:-2])
        tan[0] = (y[1] - y[0]) / (x[1] - x[0])
        tan[-1] = (y[-1] - y[-2]) / (x[-1] - x[-2])
    t = np.linspace(0.0, 1.0, per_interval + 1)[:-1]
    h = np.diff(x)[:, None]
    h00, h10 = 2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t
    h01, h11 = -2 * t**3 + 3 * t**2, t**3 - t**2
    Y = h00 * y[:-1, None] + h10 * h * tan[:-1, None] + h01 * y[1:, None] + h11 * h * tan[1:, None]
    X = x[:-1, None] + h * t[None, :]
    return np.append(X.ravel(), x[-1]), np.append(Y.ravel(), y[-1])


def _periodic_points(x: ArrayLike, y: ArrayLike, period: float, lo: float, hi: float,
                     extra: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """The points of a periodic sample over [lo, hi], with the neighbour just outside each end
    (and ``extra`` more), for drawing over [lo, hi]."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    closed = x[-1] - x[0] >= period * (1 - 1e-12)
    core_x, core_y = (x[:-1], y[:-1]) if closed else (x, y)
    ext_x = np.concatenate((core_x - period, core_x, core_x + period))
    ext_y = np.concatenate((core_y, core_y, core_y))
    keep = np.zeros(ext_x.size, dtype=bool)
    i0 = max(int(np.searchsorted(ext_x, lo, side="right")) - 1 - extra, 0)
    i1 = min(int(np.searchsorted(ext_x, hi, side="left")) + extra, ext_x.size - 1)
    keep[i0:i1 + 1] = True
    return ext_x[keep], ext_y[keep]


def _clip_curve(X: np.ndarray, Y: np.ndarray, lo: float, hi: float) -> tuple[np.ndarray, np.ndarray]:
    """The polyline (X, Y) cut to lo ≤ X ≤ hi (ends interpolated)."""
    inside = (X > lo) & (X < hi)
    xs = np.concatenate(([lo], X[inside], [hi]))
    ys = np.concatenate(([np.interp(lo, X, Y)], Y[inside], [np.interp(hi, X, Y)]))
    return xs, ys


def _broken_behind(rays: list[Line], axis: Axis) -> list[Line]:
    """The rays of a pole interrupted where they would cross the value axis's tick labels (a line is broken
    for an inscription, ГОСТ 2.303): :func:`~graphmethods.sheets.linkage_figures.broken_behind`."""
    from graphmethods.sheets.linkage_figures import broken_behind

    return broken_behind(rays, _label_boxes(axis))


def _lost_positions(full: Axis, kept: Axis, occ: Occupancy, name: str) -> list:
    """The position numbers a φ axis had to leave out, set beside their ticks where there is room
    (above the axis where a curve runs below it, and the other way round)."""
    out = []
    for k, (v, want, have) in enumerate(zip(full.ticks, full.tick_labels or (), kept.tick_labels or ())):
        if not want or have or (full.skip_zero_label and v == 0):
            continue
        lab = occ.first_free(full.pos(v), want, ("s", "n", "se", "ne", "sw", "nw"), (2.3, 3.5), SMALL_MM, None)
        if lab is not None:
            occ.add_label(lab)
            out.append(Text((lab.x, lab.y), want, size_mm=SMALL_MM, anchor=lab.anchor, name=f"{name}-{k}"))
    return out


def _number_labels(m: int, step_mm: float) -> tuple[str, ...]:
    """Position numbers 0…m, every k-th when they would crowd (k so that labels are ≥ 4.5 mm apart)."""
    k = max(1, math.ceil(4.5 / max(step_mm, 1e-9)))
    return tuple(str(i) if i % k == 0 or i == m else "" for i in range(m + 1))


@dataclass(frozen=True)
class StripsLayout:
    """The millimetre constants of the calculus sheets: three strips stacked on the left (each graph
    with its pole left of it), a column of scale formulas and a table on the right.

    >>> StripsLayout().strip_tops(top=20.0, strip_mm=50.0)
    (20.0, 83.0, 146.0)
    """

    pole_room_mm: float = 44.0      # left of the graphs for the poles (the work diagrams widen it for a long H)
    graph_gap_mm: float = 12.0      # between the pole room and the graphs
    column_gap_mm: float = 16.0     # between the graphs and the right column
    top_gap_mm: float = 4.0         # below the title
    bottom_gap_mm: float = 9.0      # above the scale captions
    strip_gap_mm: float = 13.0      # between two strips
    dim_room_mm: float = 9.0        # the dimension of H beside the fan of rays
    max_pole_room_mm: float = 90.0  # the work diagrams' pole room grows up to this, then μ_M grows
    block_drop_mm: float = 4.0      # a formula block's first line below its strip's top
    tick_gap_mm: float = 7.0        # at least between a value axis's values …
    close_tick_gap_mm: float = 3.5  # … or this close in a strip too low for two values that far apart

    def strip_mm(self, sheet: Sheet) -> tuple[float, float]:
        """(top of the first strip, height of a strip) on the sheet, mm."""
        top = sheet.top + self.top_gap_mm
        bottom = sheet.caption_y - self.bottom_gap_mm
        return top, (bottom - top - 2 * self.strip_gap_mm) / 3.0

    def strip_tops(self, *, top: float, strip_mm: float) -> tuple[float, float, float]:
        """The tops of the three strips, mm."""
        gap = self.strip_gap_mm
        return top, top + strip_mm + gap, top + 2 * (strip_mm + gap)


LAYOUT = StripsLayout()


class _Band:
    """One graph of a stacked sheet: a horizontal strip with its φ axis and value axis."""

    def __init__(self, *, x0: float, top: float, height: float, s_phi: Scale, s_y: Scale, lo: float, hi: float,
                 period: float, align: str = "middle") -> None:
        lo = 0.0 if s_y.to_mm(-lo) < TIE_MM else lo         # a last bit below zero is zero (numpy versions differ)
        self.lo, self.hi = min(lo, 0.0), max(hi, 0.0)
        self.top, self.height = top, height
        used = s_y.to_mm(self.hi - self.lo)
        free = max(height - used, 0.0)
        lead = {"top": 0.0, "middle": free / 2, "bottom": free}[align]
        self.origin = (x0, top + lead + s_y.to_mm(self.hi))
        self.frame = Frame(self.origin, s_phi, s_y)
        self.s_phi, self.s_y, self.period = s_phi, s_y, period

    def pt(self, phi: float, y: float) -> tuple[float, float]:
        return self.frame.pt(phi, y)

    def pts(self, phi: ArrayLike, y: ArrayLike) -> tuple[tuple[float, float], ...]:
        return self.frame.pts(phi, y)

    def mm(self, dx_mm: float, dy_mm: float) -> tuple[float, float]:
        """A page point dx mm right of and dy mm above the origin."""
        return (self.origin[0] + dx_mm, self.origin[1] - dy_mm)

    def axes(self, *, nt: Notation, y_label: str, m: int, name: str, y_ticks: bool = True) -> tuple[Axis, Axis]:
        step_mm = self.s_phi.to_mm(self.period / m)
        phi_ticks = tuple(self.period * k / m for k in range(m + 1))
        ax_phi = Axis(self.origin, self.s_phi, "x", min_value=0.0, max_value=self.period, ticks=phi_ticks,
                      tick_labels=_number_labels(m, step_mm), label=nt.sym("phi"), size_mm=SMALL_MM,
                      skip_zero_label=self.lo < 0, name=f"axis-phi-{name}")
        room = self.s_y.per_mm * 2.0
        ticks = axis_ticks(self.lo, self.hi, self.s_y, min_gap_mm=LAYOUT.tick_gap_mm) if y_ticks else ()
        if y_ticks and not any(ticks):      # only 0, which is not written: closer values rather than none
            ticks = axis_ticks(self.lo, self.hi, self.s_y, min_gap_mm=LAYOUT.close_tick_gap_mm)
        ax_y = Axis(self.origin, self.s_y, "y", min_value=self.lo if self.lo < 0 else 0.0,
                    max_value=max(self.hi, room), ticks=ticks, label=y_label, size_mm=SMALL_MM,
                    decimal=nt.decimal, skip_zero_label=True, name=f"axis-{name}")
        return ax_phi, ax_y


def _pole(band: _Band, H_mm: float, label: str, name: str, occ: Occupancy) -> list[Element]:
    """The pole on the extension of the φ axis, H mm left of the origin, named."""
    at = band.mm(-H_mm, 0.0)
    line = Line(at, band.origin, style=THIN, name=f"{name}-axis-extension")
    dot = Point(at, radius_mm=0.7, name=f"{name}-point")
    occ.register(line, dot)
    lab = occ.place_label(at, label, ("nw", "w", "sw", "n"), size_mm=TEXT_MM, gap_mm=1.0)
    text = Text((lab.x, lab.y), label, size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-label")
    return [line, dot, text]


def _fan_side(ordinates_mm: ArrayLike) -> bool:
    """True when the fan of rays is narrower below the axis (the dimension of H goes there)."""
    ords = np.asarray(ordinates_mm, dtype=float)
    return float(max(-ords.min(), 0.0)) <= float(max(ords.max(), 0.0))


def _h_dimension(band: _Band, H_mm: float, ordinates_mm: ArrayLike, text: str, name: str,
                 occ: Occupancy) -> list[Element]:
    """Dimension of the pole distance H, clear of the fan of rays: beyond its narrower side."""
    p, q = band.mm(-H_mm, 0.0), band.origin
    ords = np.asarray(ordinates_mm, dtype=float)
    up, down = float(max(ords.max(), 0.0)), float(max(-ords.min(), 0.0))
    below = _fan_side(ords)
    depth = (down if below else up) + 5.0
    # the normal of p→q (rightwards on paper) is (0, 1): a positive offset is below the axis
    dim = Dimension(p, q, "", offset_mm=depth if below else -depth, name=f"dimension-{name}")
    occ.register(dim)
    lab = occ.place_label(dim.mid, text, ("s", "n") if below else ("n", "s"), size_mm=SMALL_MM, gap_mm=0.8)
    return [dim, Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, name=f"dimension-{name}-text")]


def _side_block(x: float, y: float, lines: list[str], name: str, occ: Occupancy) -> list[Text]:
    """Lines of text in the right column (scale formulas of one graph)."""
    els = []
    for k, t in enumerate(lines):
        els.append(Text((x, y + k * (TEXT_MM * 1.45)), t, size_mm=TEXT_MM if k == 0 else SMALL_MM + 0.2,
                        name=f"{name}-{k + 1}"))
    occ.register(*els)
    return els


def _table(rows: Rows, *, align: str, name: str, right: float | None = None, left: float | None = None,
           top: float | None = None, bottom: float | None = None) -> Table:
    """A table whose columns fit their texts (bold headings measured wide), placed by one corner."""
    cells = tuple(tuple(r) for r in rows)
    pad = 1.5
    size = lettered_size(TABLE_MM)                  # 3.5 mm and up on a course sheet
    row = 6.0 * size / TABLE_MM
    widths = tuple(max(markup.text_width_mm(r[j], size) * (1.16 if i == 0 else 1.0) for i, r in enumerate(cells))
                   + 2 * pad + 1.0 for j in range(len(cells[0])))
    w, h = sum(widths), row * len(cells)
    if left is not None:
        x = left
    else:
        assert right is not None, "a table is placed by its left or its right edge"
        x = right - w
    if top is not None:
        y = top
    else:
        assert bottom is not None, "a table is placed by its top or its bottom edge"
        y = bottom - h
    return Table((x, y), cells, col_widths_mm=widths, align=align, size_mm=size, row_height_mm=row,
                 padding_mm=pad, name=name)


def _wrap(text: str, width_mm: float, size_mm: float) -> list[str]:
    """A text in lines no wider than ``width_mm``: breaks after spaces, and between CJK characters.

    >>> _wrap("one two three", 14.0, 3.0)
    ['one two', 'three']
    """
    import re

    tokens = re.findall(r"[\u3000-\u9fff\uff00-\uffef]\s*|[^\s\u3000-\u9fff\uff00-\uffef]+\s*|\s+", text)
    lines, cur = [], ""
    for tok in tokens:
        trial = cur + tok
        if cur and markup.text_width_mm(trial.rstrip(), size_mm) > width_mm:
            lines.append(cur.rstrip())
            cur = tok.lstrip()
        else:
            cur = trial
    return lines + ([cur.rstrip()] if cur.strip() else [])


def _title_pitch(lettered: bool = False) -> float:
    """The line pitch of a table's wrapped title, mm; ``lettered``: as the page letters its text (a slide: a title
    set at 3.5 mm with a subscript needs more than the paper figure's 3.9 mm)."""
    return max(TABLE_MM * 1.35, lettered_size(TABLE_MM + 0.2) * 1.25) if lettered else TABLE_MM * 1.35


def _titled_table(table: Table, title: str, name: str, *, bold: bool = False, lettered: bool = False) -> list:
    """A table with its title above it, wrapped to the table's width."""
    lines = _wrap(title, table.width_mm, TABLE_MM + 0.2)
    n = len(lines)
    pitch = _title_pitch(lettered)
    return [Text((table.at[0], table.at[1] - 2.0 - (n - 1 - k) * pitch), t, size_mm=TABLE_MM + 0.2,
                 bold=bold, name=f"{name}-{k + 1}") for k, t in enumerate(lines)]


def _column_table(rows: Rows, title: str, *, align: str, name: str, title_name: str, right: float, bottom: float,
                  under: Sequence[Element], floor: float, lettered: bool = False) -> list[Element]:
    """The right column's table with its title, its bottom at ``bottom``, or lower (down to ``floor``) when its
    title would cover the notes above it (``under``: on a short strip, a slide); ``lettered``: the title's lines
    spaced for the page's lettering (:func:`_title_pitch`)."""
    table = _table(rows, align=align, name=name, right=right, bottom=bottom)
    title_top = _table_title_top(table, title, lettered)
    clear = _text_bottom(under)
    if title_top < clear + 1.5:
        down = min(clear + 1.5 - title_top, max(0.0, floor - bottom))
        table = replace(table, at=(table.at[0], table.at[1] + down))
    return [*_titled_table(table, title, title_name, lettered=lettered), table]


def _table_title_top(table: Table, title: str, lettered: bool = False) -> float:
    """The top of a column table's title (wrapped to the table's width), mm; ``lettered``: its lines spaced for
    the page's lettering (:func:`_title_pitch`)."""
    n = len(_wrap(title, table.width_mm, TABLE_MM + 0.2))
    return (table.at[1] - 2.0 - (n - 1) * _title_pitch(lettered)
            - ASCENT * (lettered_size(TABLE_MM + 0.2) if lettered else TABLE_MM + 0.2))


def _text_bottom(texts: Sequence[Element]) -> float:
    """The lowest descender (a subscript's included) of the texts among ``texts``, mm."""
    return max((t.at[1] + (DESCENT + markup.SUB_SHIFT) * t.size_mm for t in texts if isinstance(t, Text)),
               default=-math.inf)


def _table_shortfall(rows: Rows, title: str, *, align: str, right: float, bottom: float, under: Sequence[Element],
                     floor: float) -> float:
    """How far (mm) the texts ``under`` must rise for :func:`_column_table`'s table and title to clear them
    (0 when moving the table down to ``floor`` is enough): on a slide, lettered large, the a diagram's
    formulas stood under the comparison table's title."""
    table = _table(rows, align=align, name="probe", right=right, bottom=bottom)
    return max(0.0, _text_bottom(under) + 1.5 - _table_title_top(table, title) - max(0.0, floor - bottom))


def _fmt(nt: Notation, value: float, sig: int = 3) -> str:
    return nt.number(float(value), sig=sig)


# ----------------------------------------------------------------------------- 1. kinematic diagrams

def _comparison_rows(nt: Notation, sd: gc.SliderDiagrams, sym_v: str, sym_a: str) -> list[tuple[str, ...]]:
    rows: list[tuple[str, ...]] = [(nt.word("calculus.construction"), nt.word("calculus.against"),
                                    nt.word("calculus.largest"),
             nt.word("calculus.on_sheet"))]
    what = {"mid-intervals": nt.word("calculus.at_mid"), "positions": nt.word("calculus.at_positions")}
    against = {"analytic": nt.word("calculus.analytic"), "velocity plans": nt.word("calculus.plans"),
               "acceleration plans": nt.word("calculus.acc_plans")}
    for r in sd.comparison():
        q = sym_v if r["quantity"] == "v" else sym_a
        rows.append((f"{q}, {what[r['where']]}", against[r["against"]],
                     f"{_fmt(nt, r['error'])} {nt.unit(r['unit'])}", f"{_fmt(nt, r['error_mm'], 2)} {nt.unit('mm')}"))
    return rows


def _column_width(rows: Rows, *lines: str) -> float:
    """Width of the right column: the table's, or the widest line of text beside it."""
    table = _table(rows, align="l" * len(rows[0]), name="probe", left=0.0, top=0.0)
    return max([table.width_mm] + [markup.text_width_mm(t, TEXT_MM) for t in lines]) + 2.0


def _slider_subject(subject: Any, nt: Notation) -> tuple[Any, float | None, str]:
    """(mechanism, omega_1, problem text in the notation's language) from a Case or a mechanism."""
    if hasattr(subject, "mechanism") and hasattr(subject, "omega_m"):
        return subject.mechanism, float(subject.omega_m), problem_title(subject, nt)
    if hasattr(subject, "positions") and hasattr(subject, "guides"):
        return subject, None, ""
    raise InputError(f"kinematic_diagrams needs a linkage problem (graphmethods.kinematics.read_case) or a "
                     f"linkage with a slider, got {type(subject).__name__}")


def _free_values(axis: Axis, occ: Occupancy) -> bool:
    """Does the axis write a value other than 0 clear of what is drawn, on either side of a y axis?"""
    sides = (axis, replace(axis, labels_side="right")) if axis.labels_side in ("", "left") else (axis,)
    return any(any(lab for t, lab in zip(a.ticks, clear_tick_labels(a, occ).tick_labels or ()) if t != 0)
               for a in sides)


def _strip_axes(band: _Band, occ: Occupancy, *, nt: Notation, y_label: str, m: int, name: str, pos: str,
                rays: Sequence[Line] = (), projections: Sequence[Line] = ()
                ) -> tuple[list[Axis], list[Text], list[Line], list[Line]]:
    """A strip's φ and value axes, their tick labels that would cover what is drawn left out, and the
    position numbers that lost their place set beside their ticks (call after registering the strip).

    ``rays`` (a pole's) and ``projections`` (thin lines from the value axis to the points) are not
    registered yet: they give way to the numbers (a thin line is broken for an inscription, ГОСТ 2.303),
    the rays to the values of the value axis, the projections to every number. They come back broken,
    and registered. The values are set clear of the curve and the chords (the rays pass behind them), and
    a position number clear of every line but the projections."""
    from graphmethods.sheets.linkage_figures import broken_behind

    full_phi, ax_y = band.axes(nt=nt, y_label=y_label, m=m, name=name)
    if ax_y.ticks and not _free_values(ax_y, occ):      # every value would be crossed: closer
        for gap in np.linspace(LAYOUT.tick_gap_mm, LAYOUT.close_tick_gap_mm, 5)[1:]:   # ticks, some of them free
            closer = replace(ax_y, ticks=axis_ticks(band.lo, band.hi, band.s_y, min_gap_mm=float(gap)),
                             tick_labels=None)
            if _free_values(closer, occ):
                ax_y = closer
                break
    ax_phi, ax_y = clear_tick_labels(full_phi, occ), clear_tick_labels(ax_y, occ, keep_values=True, other_side=True)
    occ.register(ax_phi, ax_y)
    values = _label_boxes(ax_y)
    rays = broken_behind(list(rays), values)
    occ.register(*rays)
    lost = _lost_positions(full_phi, ax_phi, occ, pos)
    projections = broken_behind(list(projections), values + _label_boxes(ax_phi) + [label_bbox(_label_of(t))
                                                                                      for t in lost])
    occ.register(*projections)
    return [ax_phi, ax_y], lost, rays, projections


def _label_boxes(axis: Axis) -> list:
    """The boxes (mm) of an axis's tick labels and name as drawn."""
    from graphmethods.scene.primitives import Label

    return [label_bbox(p) for p in axis.primitives() if isinstance(p, Label)]


def _label_of(t: Text) -> Any:
    """The label primitive of a one-line text (its box as drawn)."""
    from graphmethods.scene.primitives import Label

    return next(p for p in t.primitives() if isinstance(p, Label))


@dataclass(frozen=True)
class _KinematicScales:
    """The scales of the slider's diagrams and the construction they were picked for."""

    s_phi: Scale
    s_s: Scale
    s_v: Scale
    s_a: Scale
    s_t: Scale | None
    sd: gc.SliderDiagrams
    motion: gc.SliderMotion
    gx0: float
    top: float
    strip_mm: float
    right_col: float

    def all(self) -> tuple[Scale, ...]:
        return (self.s_phi, self.s_s, self.s_v, self.s_a) + ((self.s_t,) if self.s_t is not None else ())


def _kinematic_scales(mech: Any, sheet: Sheet, nt: Notation, *, m: int, omega_1: float | None, mu_phi: Any,
                      mu_s: Any, H1_mm: float | None, H2_mm: float | None) -> _KinematicScales:
    """μ_φ and μ_s fitted to the strips (or checked when given), then the poles H₁, H₂ and μ_v, μ_a, μ_t."""
    L = LAYOUT
    x0, _, x1, _ = sheet.box
    motion = gc.slider_motion(mech, np.linspace(0.0, TWO_PI, 721))
    refs = gc.slider_references(mech, m, omega_1=omega_1)       # the kinematics once, for the probe and the sheet
    probe = gc.slider_diagrams(mech, m, mu_phi=1.0, mu_s=1.0, omega_1=omega_1, H1_mm=1.0, H2_mm=1.0, references=refs)
    right_col = _column_width(_comparison_rows(nt, probe, "v_B", "a_B"), "μ_a = μ_v/(μ_t·H_2) = 0.0001234 (m/s²)/mm")
    gx0 = x0 + L.pole_room_mm + L.graph_gap_mm
    gx1 = x1 - right_col - L.column_gap_mm
    top, band_h = L.strip_mm(sheet)
    if mu_phi is None:
        s_phi = pick_angle_scale(TWO_PI, gx1 - gx0, symbol=nt.sym("mu_phi"))
    else:
        s_phi = mu_phi if isinstance(mu_phi, Scale) else Scale(nt.sym("mu_phi"), "rad", mu_phi)
        if s_phi.to_mm(TWO_PI) > gx1 - gx0 + 1e-9:
            raise InputError(f"the crank turn at {markup.plain(s_phi.caption())} needs {s_phi.to_mm(TWO_PI):.1f} "
                             f"mm but the sheet leaves {gx1 - gx0:.1f} mm; give a larger μ_φ or none")
    s_span = float(motion.s.max() - min(motion.s.min(), 0.0))
    if mu_s is None:
        s_s = pick_scale(s_span, band_h, symbol=nt.sym("calculus.mu_s"), unit=nt.unit("m"))
    else:
        s_s = mu_s if isinstance(mu_s, Scale) else Scale(nt.sym("calculus.mu_s"), nt.unit("m"), mu_s)
        if s_s.to_mm(s_span) > band_h + 1e-9:
            raise InputError(f"the stroke at {markup.plain(s_s.caption())} needs {s_s.to_mm(s_span):.1f} mm but "
                             f"the strip leaves {band_h:.1f} mm; give a larger μ_s or none")
    sd = gc.slider_diagrams(mech, m, mu_phi=s_phi.per_mm, mu_s=s_s.per_mm, omega_1=omega_1, H1_mm=H1_mm,
                            H2_mm=H2_mm, band_v_mm=band_h - L.dim_room_mm, band_a_mm=band_h - L.dim_room_mm,
                            pole_room_mm=L.pole_room_mm, references=refs)
    for H, key, given in ((sd.v.H_mm, "H1", H1_mm), (sd.a.H_mm, "H2", H2_mm)):
        if given is not None and H > L.pole_room_mm + 1e-9:
            raise InputError(f"{key} = {H:g} mm leaves no room for the pole left of its diagram "
                             f"({L.pole_room_mm:g} mm); give a smaller {key}_mm or none")
    u_v, u_a = sd.units
    s_v = Scale(nt.sym("dynamics.mu_v"), _scale_unit(nt, u_v), sd.v.mu)
    s_a = Scale(nt.sym("calculus.mu_a"), _scale_unit(nt, u_a), sd.a.mu)
    s_t = Scale(nt.sym("calculus.mu_t"), nt.unit("s"), sd.mu_t) if sd.mu_t is not None else None
    return _KinematicScales(s_phi, s_s, s_v, s_a, s_t, sd, motion, gx0, top, band_h, right_col)


def _s_strip(ks: _KinematicScales, occ: Occupancy, nt: Notation, m: int, sym_s: str) -> tuple[_Band, list[Element]]:
    """Strip 1: s(φ), exact, with the ordinates of the positions and the chords between them."""
    motion, sd = ks.motion, ks.sd
    b_s = _Band(x0=ks.gx0, top=ks.top, height=ks.strip_mm, s_phi=ks.s_phi, s_y=ks.s_s, lo=float(motion.s.min()),
                hi=float(motion.s.max()), period=TWO_PI)
    curve_s = Polyline(b_s.pts(motion.phi, motion.s), style=RESULT, name="curve-s")
    pts_s = b_s.pts(sd.phi, sd.s)
    ordinates_s = [Line(b_s.pt(p, 0.0), q, style=THIN, name=f"ordinate-s-{k}") for k, (p, q) in
                   enumerate(zip(sd.phi, pts_s)) if abs(q[1] - b_s.origin[1]) > 0.05]
    chords_s = [Line(pts_s[k], pts_s[k + 1], style=CHORD, name=f"chord-s-{k + 1}") for k in range(m)]
    dots_s = [Point(q, radius_mm=0.55, name=f"dot-s-{k}") for k, q in enumerate(pts_s)]
    occ.register(curve_s, *ordinates_s, *chords_s)
    axes, pos_s, _, _ = _strip_axes(b_s, occ, nt=nt, y_label=nt.quantity(sym_s, nt.unit("m")), m=m, name="s",
                                    pos="pos-s")
    return b_s, [*axes, *ordinates_s, *chords_s, curve_s, *dots_s, *pos_s]


def _chords_of_points(band: _Band, px: np.ndarray, py: np.ndarray) -> list[Line]:
    """The chords between neighbouring points of a periodic sample, and across the period's ends."""
    cx, cy = _periodic_points(px, py, TWO_PI, 0.0, TWO_PI)
    chord_pts = list(zip(cx.tolist(), cy.tolist()))
    chords = []
    for k in range(len(chord_pts) - 1):
        (xa, ya), (xb, yb) = chord_pts[k], chord_pts[k + 1]
        xs_, ys_ = _clip_curve(np.array([xa, xb]), np.array([ya, yb]), max(xa, 0.0), min(xb, TWO_PI))
        chords.append(Line(band.pt(xs_[0], ys_[0]), band.pt(xs_[-1], ys_[-1]), style=CHORD, name=f"chord-v-{k}"))
    return chords


def _v_strip(ks: _KinematicScales, occ: Occupancy, nt: Notation, m: int, sym_v: str) -> tuple[_Band, list[Element]]:
    """Strip 2: v by the chords of s (rays from the pole P₁, ordinates projected to mid-intervals)."""
    v, L = ks.sd.v, LAYOUT
    v_pts_x, v_pts_y = np.asarray(v.x) / ks.sd.time_scale, np.asarray(v.values)
    vx, vy = _periodic_points(v_pts_x, v_pts_y, TWO_PI, 0.0, TWO_PI, extra=1)
    Xs, Ys = _clip_curve(*smooth_through(vx, vy, per_interval=16), 0.0, TWO_PI)
    ords = np.asarray(v.ordinates_mm)
    b_v = _Band(x0=ks.gx0, top=L.strip_tops(top=ks.top, strip_mm=ks.strip_mm)[1], height=ks.strip_mm,
                s_phi=ks.s_phi, s_y=ks.s_v, lo=float(min(Ys.min(), v_pts_y.min())),
                hi=float(max(Ys.max(), v_pts_y.max())), period=TWO_PI, align="top" if _fan_side(ords) else "bottom")
    targets_v = [b_v.mm(0.0, float(o)) for o in ords]
    pole_v = b_v.mm(-v.H_mm, 0.0)
    rays_v = [Line(pole_v, q, style=RAY, name=f"ray-v-{k + 1}") for k, q in enumerate(targets_v)]
    points_v = b_v.pts(v_pts_x, v_pts_y)
    proj_v = [Line(q, p, style=PROJECTION, name=f"projection-v-{k + 1}") for k, (q, p) in
              enumerate(zip(targets_v, points_v))]
    dots_v = [Point(p, radius_mm=0.55, name=f"dot-v-{k + 1}") for k, p in enumerate(points_v)]
    curve_v = Polyline(b_v.pts(Xs, Ys), style=RESULT, name="curve-v")
    chords_v = _chords_of_points(b_v, v_pts_x, v_pts_y)
    occ.register(curve_v, *chords_v)
    axes, pos_v, rays_v, proj_v = _strip_axes(b_v, occ, nt=nt, y_label=nt.quantity(sym_v, nt.unit(ks.sd.units[0])),
                                              m=m, name="v", pos="pos-v", rays=rays_v, projections=proj_v)
    pole_els_v = _pole(b_v, v.H_mm, f"{nt.sym('calculus.P')}_1", "pole-v", occ)
    dim_v = _h_dimension(b_v, v.H_mm, ords, f"H_1 = {nt.number(v.H_mm)} {nt.unit('mm')}", "H1", occ)
    return b_v, [*axes, *rays_v, *proj_v, *chords_v, curve_v, *dots_v, *pole_els_v, *dim_v, *pos_v]


def _a_strip(ks: _KinematicScales, occ: Occupancy, nt: Notation, m: int, sym_a: str) -> tuple[_Band, list[Element]]:
    """Strip 3: a by the chords of v (rays from the pole P₂)."""
    a, L = ks.sd.a, LAYOUT
    a_x, a_y = np.asarray(a.x) / ks.sd.time_scale, np.asarray(a.values)
    Xa, Ya = smooth_through(a_x, a_y, period=TWO_PI, per_interval=16)
    ords_a = np.asarray(a.ordinates_mm)
    b_a = _Band(x0=ks.gx0, top=L.strip_tops(top=ks.top, strip_mm=ks.strip_mm)[2], height=ks.strip_mm,
                s_phi=ks.s_phi, s_y=ks.s_a, lo=float(min(Ya.min(), a_y.min())), hi=float(max(Ya.max(), a_y.max())),
                period=TWO_PI, align="top" if _fan_side(ords_a) else "bottom")
    targets_a = [b_a.mm(0.0, float(o)) for o in ords_a]
    pole_a = b_a.mm(-a.H_mm, 0.0)
    rays_a = [Line(pole_a, q, style=RAY, name=f"ray-a-{k}") for k, q in enumerate(targets_a[:-1])]
    points_a = b_a.pts(a_x, a_y)
    proj_a = [Line(q, p, style=PROJECTION, name=f"projection-a-{k}") for k, (q, p) in
              enumerate(zip(targets_a, points_a)) if k > 0]
    dots_a = [Point(p, radius_mm=0.55, name=f"dot-a-{k}") for k, p in enumerate(points_a)]
    curve_a = Polyline(b_a.pts(Xa, Ya), style=RESULT, name="curve-a")
    occ.register(curve_a)
    axes, pos_a, rays_a, proj_a = _strip_axes(b_a, occ, nt=nt, y_label=nt.quantity(sym_a, nt.unit(ks.sd.units[1])),
                                              m=m, name="a", pos="pos-a", rays=rays_a, projections=proj_a)
    pole_els_a = _pole(b_a, a.H_mm, f"{nt.sym('calculus.P')}_2", "pole-a", occ)
    dim_a = _h_dimension(b_a, a.H_mm, ords_a, f"H_2 = {nt.number(a.H_mm)} {nt.unit('mm')}", "H2", occ)
    return b_a, [*axes, *rays_a, *proj_a, curve_a, *dots_a, *pole_els_a, *dim_a, *pos_a]


def _kinematic_column(ks: _KinematicScales, bands: tuple[_Band, _Band, _Band], x1: float, occ: Occupancy,
                      nt: Notation, *, given: tuple[bool, bool], sym_v: str, sym_a: str, floor: float) -> list[Element]:
    """The right column: the formula of each scale beside its graph, then the comparison table."""
    rx, drop, sd, mm = x1 - ks.right_col, LAYOUT.block_drop_mm, ks.sd, nt.unit("mm")
    s_s, s_v, s_a, s_t = ks.s_s, ks.s_v, ks.s_a, ks.s_t
    tname = nt.sym("calculus.mu_t") if s_t is not None else nt.sym("mu_phi")
    how = [nt.word("calculus.given") if g else nt.word("calculus.picked") for g in given]
    t_of_phi = f" = {nt.sym('mu_phi')}/ω_1 = "
    first = [s_s.caption(nt), ks.s_phi.caption(nt)] + ([s_t.caption(nt).replace(" = ", t_of_phi, 1)]
                                                       if s_t is not None else [])
    elements: list[Element] = []
    elements += _side_block(rx, bands[0].top + drop, first, "formula-s", occ)
    elements += _side_block(rx, bands[1].top + drop, [f"{s_v.symbol} = {s_s.symbol}/({tname}·H_1) = "
                                                      f"{nt.number(sd.v.mu)} {s_v.unit}/{mm}",
                                                      f"H_1 = {nt.number(sd.v.H_mm)} {mm} ({how[0]})"],
                            "formula-v", occ)
    a_lines = [f"{s_a.symbol} = {s_v.symbol}/({tname}·H_2) = {nt.number(sd.a.mu)} {s_a.unit}/{mm}",
               f"H_2 = {nt.number(sd.a.H_mm)} {mm} ({how[1]})"]
    rows, heading = _comparison_rows(nt, sd, sym_v, sym_a), nt.word("calculus.comparison")
    at_a = bands[2].top + drop
    probe = [Text((rx, at_a + k * (TEXT_MM * 1.45)), t, size_mm=TEXT_MM if k == 0 else SMALL_MM + 0.2)
             for k, t in enumerate(a_lines)]
    lift = _table_shortfall(rows, heading, align="llrr", right=x1, bottom=bands[2].top + ks.strip_mm,
                            under=probe, floor=floor)
    if lift > 0.0:                                  # the a formulas rise into the gap above their strip
        at_a -= min(lift, max(0.0, at_a - _text_bottom(elements) - 1.5 - ASCENT * TEXT_MM))
    elements += _side_block(rx, at_a, a_lines, "formula-a", occ)
    return elements + _column_table(rows, heading, align="llrr", name="comparison-table",
                                    title_name="comparison-title", right=x1, bottom=bands[2].top + ks.strip_mm,
                                    under=elements, floor=floor)


def kinematic_diagrams(subject: Any, *, m: int = 12, omega_1: float | None = None, analogues: bool = False,
                       mu_phi: Any = None, mu_s: Any = None, H1_mm: float | None = None, H2_mm: float | None = None,
                       notation: Any = "en", page: Page | None = None, title: str | None = None,
                       problem: Any = None, title_block: bool = True, name: str = "kinematic-diagrams") -> Scene:
    """The slider's s(φ), v(φ), a(φ) by graphical differentiation, with poles, rays and chords.

    Three steps: the scales (:func:`_kinematic_scales`), the strips laid out by :data:`LAYOUT`,
    the elements of each strip and of the right column.

    Parameters
    ----------
    subject : Case or SliderCrank/Shaper
        A linkage problem (its mean crank speed gives ω₁) or a linkage with one slider.
    m : int
        Number of positions over the crank turn (intervals of the construction).
    omega_1 : float, optional
        Crank speed, rad/s (default: the problem's mean speed). Derivatives are then taken with
        respect to time: μ_t = μ_φ/ω₁, μ_v = μ_s/(μ_t H₁), μ_a = μ_v/(μ_t H₂), v in m/s, a in m/s².
    analogues : bool
        Draw the analogues ds/dφ, d²s/dφ² instead (m/rad, m/rad²; μ_v = μ_s/(μ_φ H₁),
        μ_a = μ_v/(μ_φ H₂)); the default when no speed is known.
    mu_phi, mu_s : float or Scale, optional
        Scales of the s diagram (rad/mm, m/mm); picked when not given.
    H1_mm, H2_mm : float, optional
        Pole distances of the v and a diagrams, mm; picked when not given (the largest convenient
        values whose diagrams fit their strips and whose poles fit left of them).

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> s = kinematic_diagrams(SliderCrank(r=0.1, l=0.4), m=12, notation="ru")
    >>> s.title, [sc.symbol for sc in s.scales()]
    ('Кинематические диаграммы ползуна', ['μ_φ', 'μ_S', 'μ_v', 'μ_a'])
    """
    nt = get_notation(notation)
    mech, omega_case, prob = _slider_subject(subject, nt)
    omega_1 = None if analogues else (omega_case if omega_1 is None else omega_1)
    sheet = Sheet(nt=nt, page=page, default_page=Page("A3", "landscape", frame=True), top_gap_mm=6.0,
                  title=title or nt.word("calculus.kinematic_title"),
                  problem=prob if problem is None else problem, title_block=title_block)
    ks = _kinematic_scales(mech, sheet, nt, m=m, omega_1=omega_1, mu_phi=mu_phi, mu_s=mu_s, H1_mm=H1_mm, H2_mm=H2_mm)
    point = ks.motion.point
    sym_s, sym_v, sym_a = (f"{nt.sym(key)}_{{{point}}}" for key in ("calculus.s", "calculus.v", "calculus.a"))
    occ = sheet.occ
    b_s, els_s = _s_strip(ks, occ, nt, m, sym_s)
    b_v, els_v = _v_strip(ks, occ, nt, m, sym_v)
    b_a, els_a = _a_strip(ks, occ, nt, m, sym_a)
    column = _kinematic_column(ks, (b_s, b_v, b_a), sheet.box[2], occ, nt, given=(H1_mm is not None,
                               H2_mm is not None), sym_v=sym_v, sym_a=sym_a,
                               floor=sheet.caption_y - TEXT_MM - 1.5)
    scales = ks.all()
    elements = [sheet.header(), *els_s, *els_v, *els_a, *column]   # every scale stated once: in the column
    notes = tuple(n for n in (ks.s_phi.note, ks.s_s.note) if n) + (
        f"H1 = {ks.sd.v.H_mm:g} mm ({'given' if H1_mm is not None else 'picked: largest convenient H that fits'})",
        f"H2 = {ks.sd.a.H_mm:g} mm ({'given' if H2_mm is not None else 'picked: largest convenient H that fits'})")
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 extra_scales=scales, notes=notes)


def _curve_names(occ: Occupancy, pairs: Iterable[tuple[Polyline, str, float]], band: str) -> list[Text]:
    """Names of curves placed beside their right ends (or along them), where nothing is drawn."""
    out = []
    for curve, text, axis_y in pairs:
        pts = curve.points
        along = [(pts[min(int(len(pts) * f), len(pts) - 1)], ("ne", "n", "nw", "se", "s", "sw"))
                 for f in (0.85, 0.7, 0.55, 0.4, 0.25)]
        end = [(pts[-1], ("e", "ne", "se"))]
        on_axis = abs(pts[-1][1] - axis_y) < 1.0          # a curve ending on the φ axis: name it along its way
        spots = along + end if on_axis else end + along
        lab = None
        for gaps in ((1.5, 3.0), (4.5, 6.5)):           # close to the curve, else a little further off
            for at, dirs in spots:
                lab = occ.first_free(at, text, dirs, gaps, TEXT_MM + 0.3, None)
                if lab is not None:
                    break
            if lab is not None:
                break
        if lab is None:
            lab = occ.place_label(pts[-1], text, ("e",), size_mm=TEXT_MM + 0.3, register=False)
        occ.add_label(lab)
        out.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM + 0.3, anchor=lab.anchor,
                        name=f"name-{band}-{markup.plain(text)}"))
    return out
