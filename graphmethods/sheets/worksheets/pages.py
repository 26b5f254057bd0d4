"""A worksheet's pages: the student's page (statement, data, graph paper at the stated scales, answer
boxes) and the answer key (the same page with the construction drawn and the answers filled in).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import (
    Axis,
    Scale,
    Scene,
    Table,
    Text,
    axis_ticks,
    in_language,
    markup,
    notation as get_notation,
)
from graphmethods.scene.elements import Element, Line, Point, Region, label_bbox
from graphmethods.scene.notation import Notation
from graphmethods.scene.primitives import THIN, Label, walk
from graphmethods.sheets.worksheets.constructions import (
    energy_mass_construction,
    extremes,
    moment_regions,
    slider_crank_scheme,
    staircase,
    velocity_plan,
)
from graphmethods.sheets.worksheets.elements import (
    LINE_MM,
    NBSP,
    PAGE,
    RED,
    SMALL_MM,
    TEXT_MM,
    X0,
    X1,
    ColorText,
    Grid,
    wrap,
)
from graphmethods.sheets.worksheets.texts import STATEMENTS, value_unit
from graphmethods.sheets.worksheets.variants import (
    EnergyMassVariant,
    IndicatorVariant,
    Kinds,
    PlanVariant,
    StepMomentVariant,
    Variant,
)

# ----------------------------------------------------------------------------- pages

BOTTOM = 233.0          # the answers and the solution (or the student's calculations) start here
CAPTION_ROOM = 9.0      # the scale captions under a drawing area
FOOTER_MM = 2.5         # the footer at the A4 standard's smallest lettering (ГОСТ 2.304, GB/T 14691)


def _clean(values, ref: float | None = None) -> np.ndarray:
    """Round-off (below 1e-9 of the largest magnitude) written as 0."""
    x = np.asarray(values, dtype=float)
    ref = float(np.max(np.abs(x))) if ref is None else ref
    return np.where(np.abs(x) <= 1e-9 * max(ref, 1e-300), 0.0, x)


class Sheet:
    """Builds one A4 portrait page top-down: header, statement, tables, a drawing area, answers.

    Student and key pages of a variant share every position (the key is the student's page filled
    in), so the key laid over a student's sheet lines up.
    """

    def __init__(self, v: Variant, nt, key: bool):
        self.v, self.nt, self.key = v, get_notation(nt), key
        self.els: list[Element] = []
        self.y = 35.0

    @classmethod
    def begin(cls, v: Variant, nt, key: bool) -> tuple[Sheet, Notation]:
        """A new page of variant ``v`` with its header written, and the notation it is in."""
        sh = cls(v, nt, key)
        sh.header()
        return sh, sh.nt

    def add(self, *els):
        self.els.extend(els)

    def header(self) -> None:
        nt = self.nt
        self.add(Text((X0, 19.0), self.v.title.title_in(nt.code), size_mm=4.6, bold=True, name="title"),
                 Text((X1, 19.0), f"{nt.word('worksheets.variant')} {self.v.number}", size_mm=4.6, bold=True,
                      anchor="end", name="variant"))
        if self.key:
            self.add(ColorText((X0, 26.0), nt.word("worksheets.key"), size_mm=4.0, bold=True, color=RED,
                               name="key-mark"),
                     Text((X1, 26.0), markup.literal(self.v.id), size_mm=SMALL_MM, anchor="end", name="id"))
        else:
            x = X0
            for key, length in (("name", 62.0), ("group", 30.0), ("date", 28.0)):
                text = nt.word("worksheets." + key) + ":"
                self.add(Text((x, 26.0), text, size_mm=TEXT_MM, name=f"field-{key}"))
                x += markup.text_width_mm(text, TEXT_MM) + 1.5
                self.add(Line((x, 26.8), (x + length, 26.8), style=THIN, name=f"blank-{key}"))
                x += length + 5.0
        self.add(Line((X0, 29.0), (X1, 29.0), style=THIN, name="header-rule"))

    def paragraph(self, text: str, *, indent: float = 0.0, size: float = TEXT_MM, name: str = "statement") -> None:
        for k, line in enumerate(wrap(text, X1 - X0 - indent, size)):
            self.add(Text((X0 + indent, self.y), line, size_mm=size, name=f"{name}-{k}"))
            self.y += size * 1.4
        self.y += 0.6

    def statement(self, fmt: dict) -> None:
        # each filled-in value (a scale, a number with its unit) stays on one line
        fmt = {k: v.replace(" ", NBSP) if isinstance(v, str) else v for k, v in fmt.items()}
        # one tuple of paragraphs per language, picked alike (in_language's triple of texts, without fill)
        parts: tuple[str, ...] = in_language(STATEMENTS[self.v.kind], self.nt)  # type: ignore[arg-type,assignment]
        self.paragraph(parts[0].format(**fmt), name="given")
        for k, task in enumerate(parts[1:]):
            self.paragraph(task.format(**fmt), indent=4.0, name=f"task-{k + 1}")
        self.y += 1.5

    def table(self, rows, *, align: str = "", value_rows=(), size: float = 3.0, row_mm: float = 6.5,
              value_row_mm: float = 8.5, name: str = "table", full: bool = True, width_rows=None) -> Table:
        """A table as wide as the text (``full``), fonts shrunk until it fits; ``value_rows`` are taller.

        ``width_rows`` (the key's filled-in rows) size the columns, so that the student's table with
        blank cells and the key's are the same table.
        """
        rows = tuple(tuple(r) for r in rows)
        measure = rows if width_rows is None else tuple(tuple(r) for r in width_rows)
        # down to the A4 standard's smallest lettering (2.5 mm, ГОСТ 2.304), then narrower padding (an eleven-
        # column answers table was set at 2.2 mm)
        for sz, pad in ((size, 1.5), (2.8, 1.5), (2.6, 1.5), (FOOTER_MM, 1.5), (FOOTER_MM, 1.0), (FOOTER_MM, 0.7)):
            probe = Table((X0, self.y), measure, size_mm=sz, row_height_mm=row_mm, align=align, padding_mm=pad,
                          min_col_mm=6.0)
            if probe.width_mm <= X1 - X0:
                break
        else:
            raise InputError(f"{self.v.id}: the table {name} does not fit the page width")
        widths = list(probe.column_widths())
        if full:
            extra = (X1 - X0 - sum(widths)) / max(len(widths) - 1, 1)
            widths = [widths[0]] + [w + extra for w in widths[1:]]
        tables = []
        y = self.y
        for i, row in enumerate(rows):          # rows one by one: value rows taller
            h = value_row_mm if i in value_rows else row_mm
            tables.append(Table((X0, y), (row,), col_widths_mm=tuple(widths), row_height_mm=h, size_mm=sz,
                                header_rows=1 if i == 0 else 0, align=align or "c" * len(row), padding_mm=pad,
                                bold_rows=(0,) if i == 0 else (), name=f"{name}-row-{i}"))
            y += h
        self.add(*tables)
        self.y = y + 4.0
        return tables[0]

    def drawing_box(self, bottom: float = BOTTOM) -> tuple[float, float]:
        """(top, height) of the drawing area from here down to the captions above ``bottom``."""
        top = self.y
        H = bottom - CAPTION_ROOM - top
        if H < 40.0:
            raise InputError(f"{self.v.id}: the statement and tables leave only {H:.0f} mm for the drawing")
        return top, H

    def caption(self, texts, *, y: float, name: str = "captions") -> None:
        x = X0
        for k, t in enumerate(texts):
            self.add(Text((x, y), t, size_mm=TEXT_MM, name=f"{name}-{k}"))
            x += markup.text_width_mm(t, TEXT_MM) + 8.0

    def footer(self) -> None:
        nt = self.nt
        text = (f"graphmethods worksheet {self.v.kind} --seed {self.v.seed} · {nt.word('worksheets.variant')} "
                f"{self.v.number}")
        self.add(Text((X0, 284.0), markup.literal(text), size_mm=FOOTER_MM, name="footer"))
        if self.key:
            check = markup.literal(nt.word("worksheets.check", id=self.v.id))
            # beside the seed's line, or on the line above it when the two meet (a seed of two digits)
            room = X1 - X0 - markup.text_width_mm(markup.literal(text), FOOTER_MM) - 4.0
            y = 284.0 if markup.text_width_mm(check, FOOTER_MM) <= room else 284.0 - 1.6 * FOOTER_MM
            self.add(Text((X1, y), check, size_mm=FOOTER_MM, anchor="end", name="footer-check"))

    def _clear_paper(self) -> None:
        """The graph paper cleared behind every text on it (:attr:`Grid.holes`): tick values, letters and
        lengths stand on white, not on a grid line."""
        grids = [k for k, e in enumerate(self.els) if isinstance(e, Grid)]
        if not grids:
            return
        boxes = tuple((b[0] - 0.4, b[1] - 0.3, b[2] + 0.4, b[3] + 0.3)   # tables stand off the paper, hatches
                      for e in self.els if not isinstance(e, (Grid, Table, Region))        # have no words
                      for p in walk(e.primitives()) if isinstance(p, Label) and p.text.strip()
                      for b in (label_bbox(p),))
        for k in grids:
            g = self.els[k]
            assert isinstance(g, Grid)
            x0, y0, x1, y1 = g.box
            inside = tuple(b for b in boxes if b[0] < x1 and x0 < b[2] and b[1] < y1 and y0 < b[3])
            self.els[k] = replace(g, holes=g.holes + inside)

    def scene(self, scales=()) -> Scene:
        self.footer()
        self._clear_paper()
        kind = "key" if self.key else "student"
        if self.y > 281.0:
            raise InputError(f"{self.v.id}: the {kind} page runs {self.y - 281.0:.0f} mm past its frame")
        return Scene(PAGE, tuple(self.els), title=f"{self.v.title.title_in(self.nt.code)} — "
                     f"{self.nt.word('worksheets.variant')} {self.v.number}"
                     + (f" ({self.nt.word('worksheets.key')})" if self.key else ""),
                     notation=self.nt.code, name=f"{self.v.kind}-{kind}-{self.v.number:02d}",
                     extra_scales=tuple(scales))


def answers_and_solution(sh: Sheet, heads, values, lines) -> None:
    """The answer boxes (blank on the student's page) and the worked solution (key) or room to work."""
    nt = sh.nt
    sh.y = max(sh.y, BOTTOM)
    sh.add(Text((X0, sh.y + 3.0), nt.word("worksheets.answers"), size_mm=TEXT_MM + 0.3, bold=True,
                name="answers-title"))
    sh.y += 5.5
    vals = list(values) if sh.key else [""] * len(heads)
    sh.table((heads, vals), value_rows=(1,), name="answers", value_row_mm=9.0, width_rows=(heads, values))
    sh.add(Text((X0, sh.y + 0.5), nt.word("worksheets.solution" if sh.key else "worksheets.work"),
                size_mm=TEXT_MM + 0.3, bold=True, name="solution-title"))
    sh.y += 5.0
    if not sh.key:
        return
    for k, line in enumerate(lines):
        for part in wrap(line, X1 - X0 - 4.0, TEXT_MM - 0.2):
            sh.add(Text((X0 + 4.0, sh.y), part, size_mm=TEXT_MM - 0.2, name=f"solution-{k}"))
            sh.y += LINE_MM


def _speed(v: IndicatorVariant | StepMomentVariant | EnergyMassVariant, nt: Notation) -> str:
    """The machine's speed as the statements give it: ``"300 rev/min"`` (``"300 r/min"`` in zh)."""
    return f"{nt.number(v.n_rpm)} {nt.word('worksheets.unit_rev_min')}"


def _omega_lines(v, nt) -> list[str]:
    f, om = v.flywheel, nt.sym("dynamics.omega_m")
    rs = nt.unit("rad/s")
    return [f"{om} = πn/30 = π·{nt.number(v.n_rpm)}/30 = {nt.number(f.omega_m)} {rs};  ω_{{max}} = {om}(1 + δ/2) = "
            f"{nt.number(f.omega_max)} {rs};  ω_{{min}} = {om}(1 − δ/2) = {nt.number(f.omega_min)} {rs}",
            f"{nt.sym('dynamics.J_F')} = {nt.sym('delta_W_max')}/({om}²[δ]) − {nt.sym('dynamics.J_e')} = "
            f"{nt.number(f.delta_W_max)}/({nt.number(f.omega_m)}²·{v.delta}) − {nt.number(v.J_e)} = "
            f"{nt.number(f.J_F)} {nt.unit('kg·m²')}"]


def _flywheel_heads(nt) -> list[str]:
    rs = "rad/s"
    return [nt.quantity(nt.sym("dynamics.omega_m"), rs), nt.quantity("ω_{max}", rs), nt.quantity("ω_{min}", rs)]


def _clear_tick_labels(axis: Axis, points, *, other_side: bool = False) -> Axis:
    """The axis with the tick labels that a polyline (page points) runs through left out; with ``other_side``
    (an abscissa the curve runs under) its values above it when that keeps more of them."""
    from graphmethods.sheets.layout import Occupancy, clear_tick_labels

    occ = Occupancy(pad_mm=0.4)
    occ.add_line(points)
    below = clear_tick_labels(axis, occ)
    if not other_side:
        return below
    above = clear_tick_labels(replace(axis, labels_side="above"), occ)

    def kept(a: Axis) -> int:
        return sum(1 for t in a.tick_labels or () if t)

    return above if kept(above) > kept(below) else below

def _inertia_axis(origin, s_J: Scale, J_hi: float, x_max: float, J_e_sym: str, nt: Notation, curve_pts) -> Axis:
    """The energy–mass diagram's J_e axis with a value at every tick: the nice-number rule's ticks at least
    12 mm apart, or further apart when the curve runs through a value on both sides of the axis (the values
    above the axis where the curve runs under it)."""
    best: tuple[int, Axis] | None = None
    for gap in (12.0, 16.0, 20.0, 25.0):
        ticks = data_ticks(0.0, J_hi, s_J, room=(0.0, x_max), min_gap_mm=gap)
        ax = Axis(origin, s_J, "x", min_value=0.0, max_value=max(ticks[-1], J_hi), ticks=ticks, label=J_e_sym,
                  size_mm=SMALL_MM, decimal=nt.decimal, skip_zero_label=True, name="axis-J")
        ax = _clear_tick_labels(ax, curve_pts, other_side=True)
        lost = sum(1 for t, lab in zip(ax.ticks, ax.tick_labels or ()) if t != 0 and not lab)
        if best is None or lost < best[0]:
            best = (lost, ax)
        if not lost:
            break
    assert best is not None
    return best[1]


def data_ticks(lo: float, hi: float, scale: Scale, *, room: tuple[float, float], min_gap_mm: float
               ) -> tuple[float, ...]:
    """The ticks of an axis that holds data in [``lo``, ``hi``]: the nice-number rule's ticks
    (:func:`~graphmethods.scene.axis_ticks`, at least ``min_gap_mm`` apart) over the ``room`` the page
    gives, clipped to the data: from the last tick at or below ``lo`` to the first at or above ``hi``
    (every one labelled), so an axis ends one tick past its data, not at the edge of the paper.

    >>> data_ticks(-1750.0, 600.0, Scale("μ_E", "J", 40.0), room=(-3000.0, 1400.0), min_gap_mm=10.0)
    (-2000.0, -1500.0, -1000.0, -500.0, 0.0, 500.0, 1000.0)
    """
    ticks = axis_ticks(room[0], room[1], scale, min_gap_mm=min_gap_mm)
    eps = 1e-9 * max(abs(lo), abs(hi), 1e-300)
    below = [t for t in ticks if t <= lo + eps]
    above = [t for t in ticks if t >= hi - eps]
    a, b = (below[-1] if below else ticks[0]), (above[0] if above else ticks[-1])
    return tuple(t for t in ticks if a <= t <= b)


def _indicator_page(v: IndicatorVariant, nt, key: bool) -> Scene:
    from graphmethods.sheets.layout import Occupancy

    sh, nt = Sheet.begin(v, nt, key)
    c, f = v.excess_work, v.flywheel
    s_M = Scale(nt.sym("mu_M"), nt.unit("N·m"), v.mu_M)
    s_phi = Scale(nt.sym("mu_phi"), nt.unit("rad"), v.mu_phi)
    s_E = Scale(nt.sym("mu_E"), nt.unit("J"), v.mu_E)
    sh.statement(dict(mu_M=s_M.caption(nt), mu_phi=s_phi.caption(nt), M_d=nt.sym("M_d"), M_r=nt.sym("M_r"),
                      n=_speed(v, nt), delta=v.delta,
                      J_e=f"{nt.sym('dynamics.J_e')} = {value_unit(v.J_e, 'kg·m²', nt)}", A=nt.sym("A"),
                      E=nt.sym("E"),
                      mu_E=s_E.caption(nt), step=nt.word("worksheets.step", step=nt.number(v.step_mm)),
                      dW=nt.sym("delta_W_max"), J_F_sym=nt.sym("dynamics.J_F")))
    L, n = c.labels, c.work.size
    E = _clean(c.E)
    full = [[nt.word("interval"), ""] + [f"{L[i]}–{L[i + 1]}" for i in range(n)],
            [nt.quantity("f", "mm²"), ""] + [nt.number(a, plus=True) for a in c.areas_mm2],
            [nt.quantity(nt.sym("A"), "J"), ""] + [nt.number(a, plus=True, sig=6) for a in c.work],
            [nt.word("worksheets.point_end"), L[0]] + list(L[1:]),
            [nt.quantity(nt.sym("E"), "J"), nt.number(0)] + [nt.number(e, sig=6) for e in E[1:]]]
    shown = full if key else [r if i not in (2, 4) else r[:2] + [""] * n for i, r in enumerate(full)]
    sh.table(shown, align="l" + "c" * (n + 1), value_rows=(2, 4), name="data", width_rows=full)
    # the drawing area: E axis and graph paper
    top, H = sh.drawing_box()
    ax_x = X0 + 16.0
    first = ax_x + 12.0
    E_hi, E_lo = max(float(E.max()), 0.0), min(float(E.min()), 0.0)
    y0 = top + (H - s_E.to_mm(E_hi - E_lo)) / 2 + s_E.to_mm(E_hi)
    y0 = top + 5.0 * round((y0 - top) / 5.0)              # the origin on a grid line
    sh.add(Grid((X0, top, X1, top + H), anchor=(ax_x, y0), name="grid"))
    v_top, v_bot = s_E.to_value(y0 - top - 6.0), -s_E.to_value(top + H - y0 - 2.0)
    ticks = data_ticks(E_lo, E_hi, s_E, room=(v_bot, v_top), min_gap_mm=10.0)
    axis = Axis((ax_x, y0), s_E, "y", min_value=min(ticks[0], E_lo), max_value=max(ticks[-1], E_hi),
                ticks=ticks, label=nt.quantity(nt.sym("E"), "J"),
                size_mm=SMALL_MM, decimal=nt.decimal, name="axis-E")
    sh.add(axis)
    occ = Occupancy()
    occ.add_primitives(axis.primitives())
    if key:
        sh.add(*staircase(first, y0, c.work, mu_E=v.mu_E, step_mm=v.step_mm, labels=L, nt=nt, occ=occ))
        sh.add(*extremes(first, y0, c.work, mu_E=v.mu_E, step_mm=v.step_mm, nt=nt, occ=occ))
    else:
        sh.add(Point((first, y0), label="a", label_dir="w", size_mm=TEXT_MM, gap_mm=1.5, name="start-a"))
    sh.caption([s_E.caption(nt), nt.word("worksheets.step", step=nt.number(v.step_mm))], y=top + H + 5.0)
    sh.y = top + H + CAPTION_ROOM
    i, j = c.index_E_max, c.index_E_min
    answers_and_solution(
        sh, _flywheel_heads(nt) + [nt.quantity(nt.sym("delta_W_max"), "J"),
                                   f"ω_{{max}}: {nt.word('worksheets.at_point')}",
                                   f"ω_{{min}}: {nt.word('worksheets.at_point')}",
                                   nt.quantity(nt.sym("dynamics.J_F"), "kg·m²")],
        [nt.number(f.omega_m), nt.number(f.omega_max), nt.number(f.omega_min), nt.number(c.delta_W_max),
         L[c.index_E_max], L[c.index_E_min], nt.number(f.J_F)],
        [f"{nt.sym('A')}_{{i}} = f_{{i}}·{nt.sym('mu_M')}·{nt.sym('mu_phi')} = f_{{i}}·"
         f"{nt.number(v.mu_M * v.mu_phi, sig=6)} {nt.unit('J')}/{nt.unit('mm²')};  "
         f"{nt.sym('delta_W_max')} = {nt.sym('E_max')} − {nt.sym('E_min')} = {nt.number(E[i])} − "
         f"({nt.number(E[j])}) = {nt.number(c.delta_W_max)} {nt.unit('J')}"] + _omega_lines(v, nt))
    return sh.scene((s_E,))


def _excess_work_table(sh: Sheet, v: StepMomentVariant, *, cols: int, row_mm: float) -> np.ndarray:
    """The excess-work table of a step-moment page: blank columns on the student's page, the intervals,
    angles, areas, works and levels in the key. Returns the levels E (J, round-off written 0)."""
    nt, key, c = sh.nt, sh.key, v.excess_work
    n = c.work.size
    L = c.labels
    E = _clean(c.E)
    pad = [""] * (cols - n)

    def row(values):
        return list(values) + pad

    full = [[nt.word("interval")] + row(f"{L[i]}–{L[i + 1]}" for i in range(n)),
            [nt.quantity("φ", "°")] + row(f"{nt.number(math.degrees(c.phi[i]))}…{nt.number(math.degrees(c.phi[i + 1]))}"
                                           for i in range(n)),
            [nt.quantity("f", "mm²")] + row(nt.number(a / (v.mu_M * v.mu_phi), plus=True) for a in c.work),
            [nt.quantity(nt.sym("A"), "J")] + row(nt.number(a, plus=True) for a in c.work),
            [f"{nt.quantity(nt.sym('E'), 'J')} ({nt.word('worksheets.point_end').lower()})"]
            + row(f"{nt.number(E[i + 1])} ({L[i + 1]})" for i in range(n))]
    shown = full if key else [r[:1] + [""] * cols for r in full]
    sh.table(shown, align="l" + "c" * cols, name="excess-work", row_mm=row_mm, width_rows=full)
    return E


def _step_page(v: StepMomentVariant, nt, key: bool) -> Scene:
    from graphmethods.scene.elements import Frame
    from graphmethods.sheets.layout import Occupancy

    sh, nt = Sheet.begin(v, nt, key)
    c, f = v.excess_work, v.flywheel
    s_M = Scale(nt.sym("mu_M"), nt.unit("N·m"), v.mu_M)
    s_phi = Scale(nt.sym("mu_phi"), nt.unit("rad"), v.mu_phi, alt_per_mm=v.mu_phi_deg, alt_unit="°")
    sh.statement(dict(M_r=nt.sym("M_r"), M_d=nt.sym("M_d"), shape=nt.word("worksheets.shape_" + v.shape),
                      n=_speed(v, nt), delta=v.delta,
                      J_e=f"{nt.sym('dynamics.J_e')} = {value_unit(v.J_e, 'kg·m²', nt)}", mu_M=s_M.caption(nt),
                      mu_phi=s_phi.caption(nt), A=nt.sym("A"), E=nt.sym("E"), dW=nt.sym("delta_W_max"),
                      J_F_sym=nt.sym("dynamics.J_F")))
    deg = nt.unit("°")
    if v.shape == "steps":
        st = v.steps()
        sh.table([[nt.quantity("φ", "°")] + [f"{nt.number(a)}…{nt.number(b)}" for a, b, _ in st],
                  [nt.quantity(nt.sym("M_r"), "N·m")] + [nt.number(m) for _, _, m in st]],
                 align="l" + "c" * len(st), name="data")
    else:
        sh.table([[nt.quantity("φ", "°")] + [nt.number(p) for p in v.phi_deg],
                  [nt.quantity(nt.sym("M_r"), "N·m")] + [nt.number(m) for m in v.M_r]],
                 align="l" + "c" * len(v.phi_deg), name="data")
    # the moment diagram: axes at the stated scales on graph paper
    n = c.work.size
    cols = max(n, 6)
    row_mm = 7.0
    table_h = 5 * row_mm + 4.0
    top, H = sh.drawing_box(BOTTOM - table_h)
    M_hi = max(max(v.M_r), v.M_d)
    ax_x = X0 + 16.0
    y0 = top + 5.0 * math.floor((H - 9.0) / 5.0)             # the φ axis near the bottom, on a grid line
    if s_M.to_mm(M_hi) > y0 - top - 10.0:
        raise InputError(f"{v.id}: the moment diagram at {markup.plain(s_M.caption())} does not fit its box")
    sh.add(Grid((X0, top, X1, top + H), anchor=(ax_x, y0), name="grid"))
    frame = Frame((ax_x, y0), s_phi, s_M)
    grid_deg = 45 if all(p % 45 == 0 for p in v.phi_deg) else 30
    ticks = tuple(math.radians(d) for d in range(0, 361, grid_deg))
    ax_phi = Axis((ax_x, y0), s_phi, "x", min_value=0.0, max_value=2 * math.pi, ticks=ticks,
                  tick_labels=tuple(f"{d}{deg}" for d in range(0, 361, grid_deg)), label="φ", size_mm=SMALL_MM,
                  skip_zero_label=True, name="axis-phi")
    ticks_M = data_ticks(0.0, M_hi, s_M, room=(0.0, s_M.to_value(y0 - top - 7.0)), min_gap_mm=8.0)
    ax_M = Axis((ax_x, y0), s_M, "y", min_value=0.0, max_value=max(ticks_M[-1], M_hi), ticks=ticks_M,
                label=nt.quantity("M", "N·m"), size_mm=SMALL_MM, decimal=nt.decimal, name="axis-M")
    sh.add(ax_phi, ax_M)
    if key:
        occ = Occupancy()
        for a in (ax_phi, ax_M):
            occ.add_primitives(a.primitives())
        sh.add(*moment_regions(frame, c, nt=nt, occ=occ))
    sh.caption([s_phi.caption(nt), s_M.caption(nt)], y=top + H + 5.0)
    sh.y = top + H + CAPTION_ROOM
    E = _excess_work_table(sh, v, cols=cols, row_mm=row_mm)
    if v.shape == "steps":
        md = ("(" + " + ".join(f"{nt.number(m)}·{nt.number(b - a)}" for a, b, m in v.steps())
              + f")/360 = {nt.number(v.M_d)}")
    else:
        md = f"∫{nt.sym('M_r')}dφ/2π = {nt.number(v.M_d)}"
    answers_and_solution(
        sh, [nt.quantity(nt.sym("M_d"), "N·m"), nt.quantity(nt.sym("delta_W_max"), "J"),
             nt.quantity("φ(ω_{max})", "°"), nt.quantity("φ(ω_{min})", "°"),
             nt.quantity(nt.sym("dynamics.J_F"), "kg·m²")],
        [nt.number(v.M_d), nt.number(c.delta_W_max), nt.number(math.degrees(c.phi_E_max)),
         nt.number(math.degrees(c.phi_E_min)), nt.number(f.J_F)],
        [f"{nt.sym('M_d')} = {md} {nt.unit('N·m')};  {nt.sym('A')}_{{i}} = ∫({nt.sym('M_d')} − "
         f"{nt.sym('M_r')})dφ;  {nt.sym('delta_W_max')} = {nt.number(E.max())} − ({nt.number(E.min())}) = "
         f"{nt.number(c.delta_W_max)} {nt.unit('J')}"] + _omega_lines(v, nt)[1:])
    return sh.scene((s_phi, s_M))


def _scheme_points(v: PlanVariant) -> dict:
    ph = math.radians(v.phi_deg)
    A = (v.r * math.cos(ph), v.r * math.sin(ph))
    B = (A[0] + math.sqrt(v.l ** 2 - (v.e - A[1]) ** 2), v.e)
    return {"O": (0.0, 0.0), "A": A, "B": B}


def _plan_layout(v: PlanVariant, top: float, H: float):
    """Pole position so that the plan sits in the middle of its box (the same on both pages)."""
    vec = v.vectors()
    xs = [float(p[0]) / v.mu_v for p in vec.values()]
    ys = [-float(p[1]) / v.mu_v for p in vec.values()]
    cx = (X0 + X1) / 2 - (min(xs) + max(xs)) / 2
    cy = top + H / 2 - (min(ys) + max(ys)) / 2
    return (5.0 * round(cx / 5.0), 5.0 * round(cy / 5.0))


def _plan_page(v: PlanVariant, nt, key: bool) -> Scene:
    from graphmethods.sheets.layout import Occupancy

    sh, nt = Sheet.begin(v, nt, key)
    s_l = Scale(nt.sym("worksheets.mu_l"), nt.unit("m"), v.mu_l)
    s_v = Scale(nt.sym("dynamics.mu_v"), nt.unit("(m/s)"), v.mu_v)
    sh.statement(dict(mu_l=s_l.caption(nt), mu_v=s_v.caption(nt), phi=f"{nt.number(v.phi_deg)}°",
                      r=value_unit(v.r, "m", nt), l=value_unit(v.l, "m", nt), e=value_unit(v.e, "m", nt),
                      AS2=value_unit(v.l_AS2, "m", nt), sense=nt.word("kinematics.ccw"),
                      omega_1=value_unit(v.omega_1, "rad/s", nt)))
    # the scheme at μ_l, as tall as this position needs
    pts = _scheme_points(v)
    ys = [p[1] for p in pts.values()]
    top = sh.y
    y_hi = max(max(ys) / v.mu_l, 13.0)           # above O: the highest point, or the ω₁ arrow
    y_lo = max(-min(ys) / v.mu_l, 0.0)
    O = (X0 + 6.0 + max(v.r / v.mu_l, 20.0), top + 7.0 + y_hi)
    xB = O[0] + pts["B"][0] / v.mu_l
    guide = min(40.0, 2.0 * (X1 - 1.0 - xB))
    if guide < 14.0:
        raise InputError(f"{v.id}: the scheme at {markup.plain(s_l.caption())} does not fit the page width")
    sh.add(*slider_crank_scheme(O, r=v.r, l=v.l, e=v.e, l_AS2=v.l_AS2, phi_deg=v.phi_deg, mu_l=v.mu_l, nt=nt,
                                guide_mm=guide))
    sh.add(Text((X1, top + 4.0), s_l.caption(nt), size_mm=TEXT_MM, anchor="end", name="caption-mu-l"))
    sh.y = O[1] + max(y_lo, 9.0) + 9.0
    # the plan's box
    top, H = sh.drawing_box()
    pole = _plan_layout(v, top, H)
    sh.add(Grid((X0, top, X1, top + H), anchor=pole, name="grid"))
    if key:
        occ = Occupancy()
        A = v.positions.xy("A")[0]
        B = v.positions.xy("B")[0]
        u = (B - A) / np.hypot(*(B - A))
        sh.add(*velocity_plan(pole, v.vectors(), mu_v=v.mu_v, link_dir=u, nt=nt, occ=occ))
    else:
        sh.add(Point(pole, label="p", label_dir="nw", size_mm=TEXT_MM, name="pole"))
    sh.caption([s_v.caption(nt)], y=top + H + 5.0)
    sh.y = top + H + CAPTION_ROOM
    a = v.answers()
    mm, ms = "mm", "m/s"
    sense = nt.word("kinematics." + a["omega_2_sense"])
    answers_and_solution(
        sh, [nt.quantity("pa", mm), nt.quantity("pb", mm), nt.quantity("ab", mm), nt.quantity("ps_{2}", mm),
             nt.quantity("v_{A}", ms), nt.quantity("v_{B}", ms), nt.quantity("v_{BA}", ms),
             nt.quantity("v_{S2}", ms), nt.quantity("ω_{2}", "rad/s")],
        [nt.number(a[k]) for k in ("pa_mm", "pb_mm", "ab_mm", "ps2_mm", "v_A", "v_B", "v_BA", "v_S2", "omega_2")],
        [f"v_{{A}} = ω_{{1}}·OA = {nt.number(v.omega_1)}·{nt.number(v.r)} = {nt.number(a['v_A'])} "
         f"{nt.unit('m/s')};  pa = v_{{A}}/{nt.sym('dynamics.mu_v')} = {nt.number(a['pa_mm'])} {nt.unit('mm')}",
         f"v_{{B}} = pb·{nt.sym('dynamics.mu_v')} = {nt.number(a['v_B'])} {nt.unit('m/s')};  v_{{BA}} = ab·"
         f"{nt.sym('dynamics.mu_v')} = {nt.number(a['v_BA'])} {nt.unit('m/s')};  v_{{S2}} = ps_{{2}}·"
         f"{nt.sym('dynamics.mu_v')} = {nt.number(a['v_S2'])} {nt.unit('m/s')}",
         f"ω_{{2}} = v_{{BA}}/AB = {nt.number(a['v_BA'])}/{nt.number(v.l)} = {nt.number(a['omega_2'])} "
         f"{nt.unit('rad/s')}, {sense}"])
    return sh.scene((s_l, s_v))


def _em_layout(v: EnergyMassVariant, top: float, H: float):
    """The origin (J_e = 0, ΔT = 0) of the energy–mass diagram, the same on both pages."""
    r = v.result
    T = np.asarray(v.delta_T, dtype=float)
    hi = max(float(T.max()) / v.mu_T, 0.0, r.k_mm)
    lo = min(float(T.min()) / v.mu_T, r.l_mm)
    y0 = top + 9.0 + hi + max(0.0, (H - 16.0 - (hi - lo)) / 2)
    return (X0 + 32.0, top + 5.0 * round((y0 - top) / 5.0))


def _em_page(v: EnergyMassVariant, nt, key: bool) -> Scene:

    sh, nt = Sheet.begin(v, nt, key)
    p = v.press
    J_e_sym, dT = nt.sym("dynamics.J_e"), nt.sym("E") if nt.code == "ru" else "ΔT"
    s_J = Scale(nt.sym("dynamics.mu_J"), nt.unit("kg·m²"), v.mu_J)
    s_T = Scale(nt.sym("mu_T"), nt.unit("J"), v.mu_T)
    sh.statement(dict(r=value_unit(p.get("r", 0), "m", nt), l=value_unit(p.get("l", 0), "m", nt),
                      e=value_unit(p.get("e", 0), "m", nt), F0=value_unit(p.get("F0", 0), "N", nt),
                      force_from=nt.number(p.get("force_from", 0)), force_to=nt.number(p.get("force_to", 1)),
                      n=_speed(v, nt), delta=v.delta, J_e_sym=J_e_sym, dT=dT,
                      mu_J=s_J.caption(nt), mu_T=s_T.caption(nt), J_F_sym=nt.sym("dynamics.J_F")))
    sh.table([[nt.word("kinematics.position")] + [str(k) for k in range(v.m + 1)],
              [nt.quantity(J_e_sym, "kg·m²")] + [nt.number(x) for x in v.J_e],
              [nt.quantity(dT, "J")] + [nt.number(x) for x in v.delta_T]],
             align="l" + "c" * (v.m + 1), name="data", size=2.8)
    r = v.result
    top, H = sh.drawing_box()
    origin = _em_layout(v, top, H)
    if origin[1] - r.l_mm > top + H - 3.0 or origin[1] - max(r.k_mm, max(v.delta_T) / v.mu_T) < top + 3.0:
        raise InputError(f"{v.id}: the energy–mass diagram at {markup.plain(s_T.caption())} does not fit its box")
    box = (X0, top, X1, top + H)
    sh.add(Grid(box, anchor=origin, name="grid"))
    x_max = s_J.to_value(X1 - origin[0] - 14.0)
    y_top, y_bot = s_T.to_value(origin[1] - top - 7.0), -s_T.to_value(top + H - origin[1] - 2.0)
    X = origin[0] + np.asarray(v.J_e) / v.mu_J
    Y = origin[1] - np.asarray(v.delta_T) / v.mu_T
    curve_pts = list(zip(X.tolist(), Y.tolist()))
    # the axes to their data: J_e from 0 to its largest value, ΔT over the curve and the points k and l
    J_hi = float(max(v.J_e))
    T_lo = min(float(min(v.delta_T)), r.l_mm * v.mu_T, 0.0)
    T_hi = max(float(max(v.delta_T)), r.k_mm * v.mu_T, 0.0)
    ticks_T = data_ticks(T_lo, T_hi, s_T, room=(y_bot, y_top), min_gap_mm=10.0)
    ax_J = _inertia_axis(origin, s_J, J_hi, x_max, J_e_sym, nt, curve_pts)
    ax_T = Axis(origin, s_T, "y", min_value=max(min(ticks_T[0], T_lo), y_bot), max_value=max(ticks_T[-1], T_hi),
                ticks=ticks_T,
                label=nt.quantity(dT, "J"), size_mm=SMALL_MM, decimal=nt.decimal, name="axis-T")
    # the key's rays from k and l give way to the values (broken behind them): the same axes on both pages
    ax_T = _clear_tick_labels(ax_T, curve_pts)
    sh.add(ax_J, ax_T)
    if key:
        sh.add(*energy_mass_construction(r, origin=origin, box=box, axes=(ax_J, ax_T), nt=nt))
    sh.caption([s_J.caption(nt), s_T.caption(nt)], y=top + H + 5.0)
    sh.y = top + H + CAPTION_ROOM
    tg, om = nt.sym("worksheets.tan"), nt.sym("dynamics.omega_m")
    answers_and_solution(
        sh, [f"{tg} ψ_{{max}}", f"{tg} ψ_{{min}}", nt.quantity("kl", "mm"),
             f"ω_{{max}}: {nt.word('kinematics.position').lower()}",
             f"ω_{{min}}: {nt.word('kinematics.position').lower()}",
             nt.quantity(nt.sym("dynamics.J_F"), "kg·m²")],
        [nt.number(r.tan_psi_max), nt.number(r.tan_psi_min), nt.number(r.kl_mm),
         ", ".join(str(i) for i in r.index_omega_max), ", ".join(str(i) for i in r.index_omega_min), nt.number(r.J_F)],
        [f"{om} = πn/30 = {nt.number(v.omega_m)} {nt.unit('rad/s')};  {tg} ψ_{{max}} = "
         f"{nt.number(v.mu_J)}·{nt.number(v.omega_m)}²·(1 + {v.delta}/2)²/(2·{nt.number(v.mu_T)}) = "
         f"{nt.number(r.tan_psi_max)};  {tg} ψ_{{min}} = {nt.number(r.tan_psi_min)}",
         f"{nt.sym('dynamics.J_F')} = {nt.sym('mu_T')}·kl/({om}²[δ]) = {nt.number(v.mu_T)}·{nt.number(r.kl_mm)}/"
         f"({nt.number(v.omega_m)}²·{v.delta}) = {nt.number(r.J_F)} {nt.unit('kg·m²')}"])
    return sh.scene((s_J, s_T))


PAGES: dict[str, Callable[..., Scene]] = Kinds({"indicator": _indicator_page, "step-moment": _step_page,
                                               "velocity-plan": _plan_page, "wittenbauer": _em_page})


def student_page(v: Variant, *, notation="en") -> Scene:
    """The student's page of a variant: statement, data, graph paper at the stated scales, answer boxes.

    An A4 portrait Scene; its scales (``scene.scales()``) are captioned under the drawing area.

    >>> from graphmethods.sheets.worksheets import variant
    >>> s = student_page(variant("velocity-plan", seed=7, number=1), notation="ru")
    >>> s.name, [sc.caption("ru") for sc in s.scales()]
    ('velocity-plan-student-01', ['μ_l = 0,005 м/мм', 'μ_v = 0,04 (м/с)/мм'])
    """
    return PAGES[v.kind](v, notation, False)


def key_page(v: Variant, *, notation="en") -> Scene:
    """The answer key of a variant: the student's page with the construction drawn and the answers filled in
    (the paper's lines where the student's are; each page clears them behind its own lettering).

    >>> from dataclasses import replace
    >>> from graphmethods.sheets.worksheets import variant
    >>> v = variant("indicator", seed=7, number=1)
    >>> k = key_page(v)
    >>> lines = lambda page: replace(page.element("grid"), holes=())
    >>> lines(k) == lines(student_page(v)), k.element("vector-ab").length_mm
    (True, 43.75)
    """
    return PAGES[v.kind](v, notation, True)


