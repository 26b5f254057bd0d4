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

import numpy as np

from graphmethods.dynamics import graphical_calculus as gc
from graphmethods.errors import InputError
from graphmethods.scene import (
    Axis,
    Dimension,
    Frame,
    Line,
    Page,
    Point,
    Polyline,
    Scale,
    Scene,
    Table,
    Text,
    format_value,
    in_language,
    markup,
    nice_ticks,
    notation as get_notation,
    pick_angle_scale,
    pick_scale,
)
from graphmethods.scene.elements import label_bbox
from graphmethods.scene.primitives import MAIN, THIN, Style
from graphmethods.sheets.layout import TEXT_MM, TIE_MM, Occupancy, Sheet, problem_title

SMALL_MM = 2.6          # tick labels, position numbers
TABLE_MM = 2.9          # the accuracy tables
RAY = Style(width_mm=0.13)                       # rays from the poles: the finest construction lines
PROJECTION = Style(width_mm=0.13, dash=(1.2, 0.8))
CHORD = Style(width_mm=0.18, stroke="#000000")
RESULT = MAIN
TWO_PI = 2.0 * math.pi

# ----------------------------------------------------------------------------- words of this module

#: notation words this module needs that scene/notation.py lacks (en, ru, zh)
WORDS = {
    "kinematic_title": ("Kinematic diagrams of the slider", "Кинематические диаграммы ползуна", "滑块运动线图"),
    "work_title": ("Work diagrams by graphical integration", "Диаграммы работ (графическое интегрирование)",
                   "功线图（图解积分法）"),
    "construction": ("Construction", "Построение", "作图"),
    "against": ("compared with", "сравнение с", "比较对象"),
    "largest": ("max. difference", "расхождение", "最大误差"),
    "on_sheet": ("on the sheet", "на чертеже", "图上"),
    "analytic": ("analytic", "аналитически", "解析解"),
    "plans": ("velocity plans", "планы скоростей", "速度图"),
    "acc_plans": ("acceleration plans", "планы ускорений", "加速度图"),
    "accuracy_work": ("Accuracy against the exact integrals", "Точность относительно точных интегралов",
                      "相对精确积分的作图误差"),
    "at_mid": ("at mid-intervals", "в серединах", "区间中点"),
    "at_positions": ("at the positions", "в положениях", "各位置"),
    "at_ends": ("at interval ends", "на концах участков", "区间端点"),
    "inside": ("inside the chords", "внутри хорд", "弦内"),
    "picked": ("picked to fit", "выбрано по месту", "自动选取"),
    "given": ("given", "задано", "给定"),
    "positions": ("positions", "положения", "位置"),
    "drawn": ("{M} drawn through the positions", "{M} построен по точкам положений", "{M}按各位置绘制"),
    "closure": ("closure", "замыкание", "闭合"),
    "comparison": ("Largest differences from the velocity and acceleration plans and the analytic values",
                   "Наибольшие расхождения с планами скоростей, ускорений и аналитическим расчётом",
                   "与速度图、加速度图及解析解的最大误差"),
}

#: symbols (markup) of this module, en / ru / zh
SYMBOLS = {
    "s": ("s", "S", "s"),
    "v": ("v", "V", "v"),
    "a": ("a", "a", "a"),
    "mu_s": ("μ_s", "μ_S", "μ_s"),
    "mu_v": ("μ_v", "μ_V", "μ_v"),
    "mu_a": ("μ_a", "μ_a", "μ_a"),
    "mu_t": ("μ_t", "μ_t", "μ_t"),
    "A_d": ("A_d", "A_д", "W_d"),
    "A_r": ("A_r", "A_с", "W_r"),
    "mu_A": ("μ_A", "μ_A", "μ_W"),
    "P": ("P", "P", "P"),
}

#: units the profiles lack (ru); the others pass through
UNITS_RU = {"m/s": "м/с", "m/s²": "м/с²", "m/rad": "м/рад", "m/rad²": "м/рад²", "s": "с", "m": "м", "J": "Дж",
            "N·m": "Н·м", "rad": "рад", "mm": "мм", "kG·m": "кГ·м"}


def word(nt, key: str) -> str:
    """A word of this module in the profile of ``nt``."""
    return in_language(WORDS[key], nt)


def sym(nt, key: str) -> str:
    """A symbol of this module in the profile of ``nt``."""
    return in_language(SYMBOLS[key], nt)


def unit(nt, u: str) -> str:
    """A unit as the profile writes it."""
    return UNITS_RU.get(u, u) if nt.code == "ru" else nt.unit(u)


def _scale_unit(nt, u: str) -> str:
    """A unit for a scale caption: compound units in brackets, ``(m/s)/mm``."""
    t = unit(nt, u)
    return f"({t})" if "/" in t else t


# ----------------------------------------------------------------------------- drawing helpers

def smooth_through(x, y, *, period: float | None = None, per_interval: int = 12) -> tuple[np.ndarray, np.ndarray]:
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


def _periodic_points(x, y, period: float, lo: float, hi: float, extra: int = 0):
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


def _clip_curve(X, Y, lo: float, hi: float):
    """The polyline (X, Y) cut to lo ≤ X ≤ hi (ends interpolated)."""
    inside = (X > lo) & (X < hi)
    xs = np.concatenate(([lo], X[inside], [hi]))
    ys = np.concatenate(([np.interp(lo, X, Y)], Y[inside], [np.interp(hi, X, Y)]))
    return xs, ys


def _register(occ: Occupancy, *elements) -> None:
    for e in elements:
        occ.add_primitives(e.primitives())


def _clear_tick_labels(axis: Axis, occ: Occupancy, *, keep_values: bool = False) -> Axis:
    """The axis with the tick labels that would cover something already drawn left out (marks stay).

    With ``keep_values`` (a value axis) an axis is never left without values: when every label
    on its side would cover something, they go on the other side; when that is full too, the
    labels that cover no text stay (a thin line may run through a number).
    """
    from dataclasses import replace

    from graphmethods.scene.primitives import Label as PLabel

    labels = list(axis.tick_labels) if axis.tick_labels is not None else \
        [format_value(v, decimal=axis.decimal) for v in axis.ticks]
    shown = [i for i, v in enumerate(axis.ticks) if labels[i] and not (axis.skip_zero_label and v == 0)]

    def kept(ax: Axis, lines: bool) -> list[str]:
        texts = [p for p in replace(ax, label="").primitives() if isinstance(p, PLabel)]
        out = list(labels)
        for i, lab in zip(shown, texts):
            if not occ.is_free(label_bbox(lab), lines=lines):
                out[i] = ""
        return out

    out = kept(axis, True)
    if keep_values and shown and not any(out[i] for i in shown):
        other = replace(axis, labels_side="right") if axis.direction == "y" and axis.labels_side in ("", "left") \
            else axis
        out = kept(other, True)
        if any(out[i] for i in shown):
            return replace(other, tick_labels=tuple(out))
        out = kept(axis, False)
    return replace(axis, tick_labels=tuple(out))


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


class _Band:
    """One graph of a stacked sheet: a horizontal strip with its φ axis and value axis."""

    def __init__(self, *, x0: float, top: float, height: float, s_phi: Scale, s_y: Scale, lo: float, hi: float,
                 period: float, align: str = "middle"):
        lo = 0.0 if s_y.to_mm(-lo) < TIE_MM else lo         # a last bit below zero is zero (numpy versions differ)
        self.lo, self.hi = min(lo, 0.0), max(hi, 0.0)
        self.top, self.height = top, height
        used = s_y.to_mm(self.hi - self.lo)
        free = max(height - used, 0.0)
        lead = {"top": 0.0, "middle": free / 2, "bottom": free}[align]
        self.origin = (x0, top + lead + s_y.to_mm(self.hi))
        self.frame = Frame(self.origin, s_phi, s_y)
        self.s_phi, self.s_y, self.period = s_phi, s_y, period

    def pt(self, phi, y):
        return self.frame.pt(phi, y)

    def pts(self, phi, y):
        return self.frame.pts(phi, y)

    def mm(self, dx_mm: float, dy_mm: float):
        """A page point dx mm right of and dy mm above the origin."""
        return (self.origin[0] + dx_mm, self.origin[1] - dy_mm)

    def axes(self, *, nt, y_label: str, m: int, name: str, y_ticks: bool = True):
        step_mm = self.s_phi.to_mm(self.period / m)
        phi_ticks = tuple(self.period * k / m for k in range(m + 1))
        ax_phi = Axis(self.origin, self.s_phi, "x", min_value=0.0, max_value=self.period, ticks=phi_ticks,
                      tick_labels=_number_labels(m, step_mm), label=nt.sym("phi"), size_mm=SMALL_MM,
                      skip_zero_label=self.lo < 0, name=f"axis-phi-{name}")
        room = self.s_y.per_mm * 2.0
        ticks = nice_ticks(self.lo, self.hi, self.s_y, min_gap_mm=7.0) if y_ticks else ()
        ax_y = Axis(self.origin, self.s_y, "y", min_value=self.lo if self.lo < 0 else 0.0,
                    max_value=max(self.hi, room), ticks=ticks, label=y_label, size_mm=SMALL_MM,
                    decimal=nt.decimal, skip_zero_label=True, name=f"axis-{name}")
        return ax_phi, ax_y


def _pole(band: _Band, H_mm: float, label: str, name: str, occ: Occupancy):
    """The pole on the extension of the φ axis, H mm left of the origin, named."""
    at = band.mm(-H_mm, 0.0)
    line = Line(at, band.origin, style=THIN, name=f"{name}-axis-extension")
    dot = Point(at, radius_mm=0.7, name=f"{name}-point")
    _register(occ, line, dot)
    lab = occ.place_label(at, label, ("nw", "w", "sw", "n"), size_mm=TEXT_MM, gap_mm=1.0)
    text = Text((lab.x, lab.y), label, size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-label")
    return [line, dot, text]


def _fan_side(ordinates_mm) -> bool:
    """True when the fan of rays is narrower below the axis (the dimension of H goes there)."""
    ords = np.asarray(ordinates_mm, dtype=float)
    return float(max(-ords.min(), 0.0)) <= float(max(ords.max(), 0.0))


def _h_dimension(band: _Band, H_mm: float, ordinates_mm, text: str, name: str, occ: Occupancy):
    """Dimension of the pole distance H, clear of the fan of rays: beyond its narrower side."""
    p, q = band.mm(-H_mm, 0.0), band.origin
    ords = np.asarray(ordinates_mm, dtype=float)
    up, down = float(max(ords.max(), 0.0)), float(max(-ords.min(), 0.0))
    below = _fan_side(ords)
    depth = (down if below else up) + 5.0
    # the normal of p→q (rightwards on paper) is (0, 1): a positive offset is below the axis
    dim = Dimension(p, q, "", offset_mm=depth if below else -depth, name=f"dimension-{name}")
    _register(occ, dim)
    lab = occ.place_label(dim.mid, text, ("s", "n") if below else ("n", "s"), size_mm=SMALL_MM, gap_mm=0.8)
    return [dim, Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, name=f"dimension-{name}-text")]


def _side_block(x: float, y: float, lines, name: str, occ: Occupancy):
    """Lines of text in the right column (scale formulas of one graph)."""
    els = []
    for k, t in enumerate(lines):
        els.append(Text((x, y + k * (TEXT_MM * 1.45)), t, size_mm=TEXT_MM if k == 0 else SMALL_MM + 0.2,
                        name=f"{name}-{k + 1}"))
    _register(occ, *els)
    return els


def _table(rows, *, align: str, name: str, right: float | None = None, left: float | None = None,
           top: float | None = None, bottom: float | None = None) -> Table:
    """A table whose columns fit their texts (bold headings measured wide), placed by one corner."""
    rows = tuple(tuple(r) for r in rows)
    pad = 1.5
    widths = tuple(max(markup.text_width_mm(r[j], TABLE_MM) * (1.16 if i == 0 else 1.0) for i, r in enumerate(rows))
                   + 2 * pad + 1.0 for j in range(len(rows[0])))
    w, h = sum(widths), 6.0 * len(rows)
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
    return Table((x, y), rows, col_widths_mm=widths, align=align, size_mm=TABLE_MM, row_height_mm=6.0,
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


def _titled_table(table: Table, title: str, name: str, *, bold: bool = False) -> list:
    """A table with its title above it, wrapped to the table's width."""
    lines = _wrap(title, table.width_mm, TABLE_MM + 0.2)
    n = len(lines)
    return [Text((table.at[0], table.at[1] - 2.0 - (n - 1 - k) * TABLE_MM * 1.35), t, size_mm=TABLE_MM + 0.2,
                 bold=bold, name=f"{name}-{k + 1}") for k, t in enumerate(lines)]


def _fmt(nt, value: float, sig: int = 3) -> str:
    return nt.number(float(value), sig=sig)


# ----------------------------------------------------------------------------- 1. kinematic diagrams

def _comparison_rows(nt, sd, sym_v: str, sym_a: str):
    rows = [(word(nt, "construction"), word(nt, "against"), word(nt, "largest"), word(nt, "on_sheet"))]
    what = {"mid-intervals": word(nt, "at_mid"), "positions": word(nt, "at_positions")}
    against = {"analytic": word(nt, "analytic"), "velocity plans": word(nt, "plans"),
               "acceleration plans": word(nt, "acc_plans")}
    for r in sd.comparison():
        q = sym_v if r["quantity"] == "v" else sym_a
        rows.append((f"{q}, {what[r['where']]}", against[r["against"]],
                     f"{_fmt(nt, r['error'])} {unit(nt, r['unit'])}", f"{_fmt(nt, r['error_mm'], 2)} {unit(nt, 'mm')}"))
    return rows


def _column_width(rows, *lines) -> float:
    """Width of the right column: the table's, or the widest line of text beside it."""
    table = _table(rows, align="l" * len(rows[0]), name="probe", left=0.0, top=0.0)
    return max([table.width_mm] + [markup.text_width_mm(t, TEXT_MM) for t in lines]) + 2.0


def _slider_subject(subject, nt):
    """(mechanism, omega_1, problem text in the notation's language) from a Case or a mechanism."""
    if hasattr(subject, "mechanism") and hasattr(subject, "omega_m"):
        return subject.mechanism, float(subject.omega_m), problem_title(subject, nt)
    if hasattr(subject, "positions") and hasattr(subject, "guides"):
        return subject, None, ""
    raise InputError(f"kinematic_diagrams needs a linkage problem (graphmethods.kinematics.read_case) or a "
                     f"linkage with a slider, got {type(subject).__name__}")


def kinematic_diagrams(subject, *, m: int = 12, omega_1: float | None = None, analogues: bool = False,
                       mu_phi=None, mu_s=None, H1_mm: float | None = None, H2_mm: float | None = None,
                       notation="en", page=None, title=None, problem=None, title_block: bool = True,
                       name: str = "kinematic-diagrams") -> Scene:
    """The slider's s(φ), v(φ), a(φ) by graphical differentiation, with poles, rays and chords.

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
        Pole distances of the v and a diagrams; picked when not given (the largest convenient
        values whose diagrams fit their strips and whose poles fit left of them).

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> s = kinematic_diagrams(SliderCrank(r=0.1, l=0.4), m=12, notation="ru")
    >>> s.title, [sc.symbol for sc in s.scales()]
    ('Кинематические диаграммы ползуна', ['μ_φ', 'μ_S', 'μ_V', 'μ_a'])
    """
    nt = get_notation(notation)
    mech, omega_case, prob = _slider_subject(subject, nt)
    if omega_1 is None:
        omega_1 = omega_case
    if analogues:
        omega_1 = None
    sheet = Sheet(nt=nt, page=page, default_page=Page("A3", "landscape", frame=True), top_gap_mm=6.0,
                  title=title or word(nt, "kinematic_title"),
                   problem=prob if problem is None else problem, title_block=title_block)
    x0, _, x1, _ = sheet.box
    motion = gc.slider_motion(mech, np.linspace(0.0, TWO_PI, 721))
    point = motion.point

    # ---- layout: three strips left, the right column for the formulas and the comparison table
    pole_room = 44.0
    probe = gc.slider_diagrams(mech, m, mu_phi=1.0, mu_s=1.0, omega_1=omega_1, H1_mm=1.0, H2_mm=1.0)
    right_col = _column_width(_comparison_rows(nt, probe, "v_B", "a_B"), "μ_a = μ_v/(μ_t·H_2) = 0.0001234 (m/s²)/mm")
    gx0 = x0 + pole_room + 12.0
    gx1 = x1 - right_col - 16.0
    top = sheet.top + 4.0
    bottom = sheet.caption_y - 9.0
    gap = 13.0
    band_h = (bottom - top - 2 * gap) / 3.0
    if mu_phi is None:
        s_phi = pick_angle_scale(TWO_PI, gx1 - gx0, symbol=nt.sym("mu_phi"))
    else:
        s_phi = mu_phi if isinstance(mu_phi, Scale) else Scale(nt.sym("mu_phi"), "rad", mu_phi)
        if s_phi.to_mm(TWO_PI) > gx1 - gx0 + 1e-9:
            raise InputError(f"the crank turn at {markup.plain(s_phi.caption())} needs {s_phi.to_mm(TWO_PI):.1f} "
                             f"mm but the sheet leaves {gx1 - gx0:.1f} mm; give a larger μ_φ or none")
    s_span = float(motion.s.max() - min(motion.s.min(), 0.0))
    if mu_s is None:
        s_s = pick_scale(s_span, band_h, symbol=sym(nt, "mu_s"), unit=unit(nt, "m"))
    else:
        s_s = mu_s if isinstance(mu_s, Scale) else Scale(sym(nt, "mu_s"), unit(nt, "m"), mu_s)
        if s_s.to_mm(s_span) > band_h + 1e-9:
            raise InputError(f"the stroke at {markup.plain(s_s.caption())} needs {s_s.to_mm(s_span):.1f} mm but "
                             f"the strip leaves {band_h:.1f} mm; give a larger μ_s or none")
    dim_room = 9.0                                  # the dimension of H beside the fan of rays
    sd = gc.slider_diagrams(mech, m, mu_phi=s_phi.per_mm, mu_s=s_s.per_mm, omega_1=omega_1, H1_mm=H1_mm,
                            H2_mm=H2_mm, band_v_mm=band_h - dim_room, band_a_mm=band_h - dim_room,
                            pole_room_mm=pole_room)
    t_per_rad = sd.time_scale
    u_v, u_a = sd.units
    s_v = Scale(sym(nt, "mu_v"), _scale_unit(nt, u_v), sd.v.mu)
    s_a = Scale(sym(nt, "mu_a"), _scale_unit(nt, u_a), sd.a.mu)
    s_t = Scale(sym(nt, "mu_t"), unit(nt, "s"), sd.mu_t) if sd.mu_t is not None else None
    for H, key, given in ((sd.v.H_mm, "H1", H1_mm), (sd.a.H_mm, "H2", H2_mm)):
        if given is not None and H > pole_room + 1e-9:
            raise InputError(f"{key} = {H:g} mm leaves no room for the pole left of its diagram ({pole_room:g} mm); "
                             f"give a smaller {key}_mm or none")
    occ = sheet.occ
    elements: list = [sheet.header()]
    P_name = sym(nt, "P")

    # ---- strip 1: s(φ), exact, with the positions and the chords
    sym_s = f"{sym(nt, 's')}_{{{point}}}"
    sym_v = f"{sym(nt, 'v')}_{{{point}}}"
    sym_a = f"{sym(nt, 'a')}_{{{point}}}"
    b_s = _Band(x0=gx0, top=top, height=band_h, s_phi=s_phi, s_y=s_s, lo=float(motion.s.min()),
                hi=float(motion.s.max()), period=TWO_PI)
    curve_s = Polyline(b_s.pts(motion.phi, motion.s), style=RESULT, name="curve-s")
    pts_s = b_s.pts(sd.phi, sd.s)
    ordinates_s = [Line(b_s.pt(p, 0.0), q, style=THIN, name=f"ordinate-s-{k}") for k, (p, q) in
                   enumerate(zip(sd.phi, pts_s)) if abs(q[1] - b_s.origin[1]) > 0.05]
    chords_s = [Line(pts_s[k], pts_s[k + 1], style=CHORD, name=f"chord-s-{k + 1}") for k in range(m)]
    dots_s = [Point(q, radius_mm=0.55, name=f"dot-s-{k}") for k, q in enumerate(pts_s)]
    ax_phi_s, ax_s = b_s.axes(nt=nt, y_label=nt.quantity(sym_s, unit(nt, "m")), m=m, name="s")
    _register(occ, curve_s, *ordinates_s, *chords_s)
    full_s = ax_phi_s
    ax_phi_s, ax_s = _clear_tick_labels(ax_phi_s, occ), _clear_tick_labels(ax_s, occ, keep_values=True)
    _register(occ, ax_phi_s, ax_s)
    pos_s = _lost_positions(full_s, ax_phi_s, occ, "pos-s")
    elements += [ax_phi_s, ax_s] + ordinates_s + chords_s + [curve_s] + dots_s + pos_s

    # ---- strip 2: v by the chords of s
    v = sd.v
    v_pts_x, v_pts_y = np.asarray(v.x) / t_per_rad, np.asarray(v.values)
    vx, vy = _periodic_points(v_pts_x, v_pts_y, TWO_PI, 0.0, TWO_PI, extra=1)
    Xs, Ys = smooth_through(vx, vy, per_interval=16)
    Xs, Ys = _clip_curve(Xs, Ys, 0.0, TWO_PI)
    v_lo = float(min(Ys.min(), v_pts_y.min()))
    v_hi = float(max(Ys.max(), v_pts_y.max()))
    ords = np.asarray(v.ordinates_mm)
    b_v = _Band(x0=gx0, top=top + band_h + gap, height=band_h, s_phi=s_phi, s_y=s_v, lo=v_lo, hi=v_hi,
                period=TWO_PI, align="top" if _fan_side(ords) else "bottom")
    targets_v = [b_v.mm(0.0, float(o)) for o in ords]
    pole_v = b_v.mm(-v.H_mm, 0.0)
    rays_v = [Line(pole_v, q, style=RAY, name=f"ray-v-{k + 1}") for k, q in enumerate(targets_v)]
    points_v = b_v.pts(v_pts_x, v_pts_y)
    proj_v = [Line(q, p, style=PROJECTION, name=f"projection-v-{k + 1}") for k, (q, p) in
              enumerate(zip(targets_v, points_v))]
    dots_v = [Point(p, radius_mm=0.55, name=f"dot-v-{k + 1}") for k, p in enumerate(points_v)]
    curve_v = Polyline(b_v.pts(Xs, Ys), style=RESULT, name="curve-v")
    # the chords of the v points (they give a): between neighbours, and across the period's ends
    cx, cy = _periodic_points(v_pts_x, v_pts_y, TWO_PI, 0.0, TWO_PI)
    chord_pts = list(zip(cx.tolist(), cy.tolist()))
    chords_v = []
    for k in range(len(chord_pts) - 1):
        (xa, ya), (xb, yb) = chord_pts[k], chord_pts[k + 1]
        xs_, ys_ = _clip_curve(np.array([xa, xb]), np.array([ya, yb]), max(xa, 0.0), min(xb, TWO_PI))
        chords_v.append(Line(b_v.pt(xs_[0], ys_[0]), b_v.pt(xs_[-1], ys_[-1]), style=CHORD,
                             name=f"chord-v-{k}"))
    ax_phi_v, ax_v = b_v.axes(nt=nt, y_label=nt.quantity(sym_v, unit(nt, u_v)), m=m, name="v")
    pole_els_v = _pole(b_v, v.H_mm, f"{P_name}_1", "pole-v", occ)
    _register(occ, curve_v, *rays_v, *proj_v, *chords_v)
    full_v = ax_phi_v
    ax_phi_v, ax_v = _clear_tick_labels(ax_phi_v, occ), _clear_tick_labels(ax_v, occ, keep_values=True)
    _register(occ, ax_phi_v, ax_v)
    pos_v = _lost_positions(full_v, ax_phi_v, occ, "pos-v")
    dim_v = _h_dimension(b_v, v.H_mm, ords, f"H_1 = {nt.number(v.H_mm)} {unit(nt, 'mm')}", "H1", occ)
    elements += ([ax_phi_v, ax_v] + rays_v + proj_v + chords_v + [curve_v] + dots_v + pole_els_v + dim_v + pos_v)

    # ---- strip 3: a by the chords of v
    a = sd.a
    a_x, a_y = np.asarray(a.x) / t_per_rad, np.asarray(a.values)
    Xa, Ya = smooth_through(a_x, a_y, period=TWO_PI, per_interval=16)
    a_lo, a_hi = float(min(Ya.min(), a_y.min())), float(max(Ya.max(), a_y.max()))
    ords_a = np.asarray(a.ordinates_mm)
    b_a = _Band(x0=gx0, top=top + 2 * (band_h + gap), height=band_h, s_phi=s_phi, s_y=s_a, lo=a_lo, hi=a_hi,
                period=TWO_PI, align="top" if _fan_side(ords_a) else "bottom")
    targets_a = [b_a.mm(0.0, float(o)) for o in ords_a]
    pole_a = b_a.mm(-a.H_mm, 0.0)
    rays_a = [Line(pole_a, q, style=RAY, name=f"ray-a-{k}") for k, q in enumerate(targets_a[:-1])]
    points_a = b_a.pts(a_x, a_y)
    proj_a = [Line(q, p, style=PROJECTION, name=f"projection-a-{k}") for k, (q, p) in
              enumerate(zip(targets_a, points_a)) if k > 0]
    dots_a = [Point(p, radius_mm=0.55, name=f"dot-a-{k}") for k, p in enumerate(points_a)]
    curve_a = Polyline(b_a.pts(Xa, Ya), style=RESULT, name="curve-a")
    ax_phi_a, ax_a = b_a.axes(nt=nt, y_label=nt.quantity(sym_a, unit(nt, u_a)), m=m, name="a")
    pole_els_a = _pole(b_a, a.H_mm, f"{P_name}_2", "pole-a", occ)
    _register(occ, curve_a, *rays_a, *proj_a)
    full_a = ax_phi_a
    ax_phi_a, ax_a = _clear_tick_labels(ax_phi_a, occ), _clear_tick_labels(ax_a, occ, keep_values=True)
    _register(occ, ax_phi_a, ax_a)
    pos_a = _lost_positions(full_a, ax_phi_a, occ, "pos-a")
    dim_a = _h_dimension(b_a, a.H_mm, ords_a, f"H_2 = {nt.number(a.H_mm)} {unit(nt, 'mm')}", "H2", occ)
    elements += ([ax_phi_a, ax_a] + rays_a + proj_a + [curve_a] + dots_a + pole_els_a + dim_a + pos_a)

    # ---- right column: the formula of each scale beside its graph, then the comparison table
    rx = x1 - right_col
    tname = sym(nt, "mu_t") if s_t is not None else nt.sym("mu_phi")
    side = [
        _side_block(rx, b_s.top + 4.0, [s_s.caption(nt), s_phi.caption(nt)]
                    + ([s_t.caption(nt) + f" = {nt.sym('mu_phi')}/ω_1"] if s_t is not None else []), "formula-s", occ),
        _side_block(rx, b_v.top + 4.0, [f"{s_v.symbol} = {s_s.symbol}/({tname}·H_1) = {nt.number(sd.v.mu)} "
                                        f"{s_v.unit}/{unit(nt, 'mm')}",
                                        f"H_1 = {nt.number(v.H_mm)} {unit(nt, 'mm')} "
                                        f"({word(nt, 'given') if H1_mm is not None else word(nt, 'picked')})"],
                    "formula-v", occ),
        _side_block(rx, b_a.top + 4.0, [f"{s_a.symbol} = {s_v.symbol}/({tname}·H_2) = {nt.number(sd.a.mu)} "
                                        f"{s_a.unit}/{unit(nt, 'mm')}",
                                        f"H_2 = {nt.number(a.H_mm)} {unit(nt, 'mm')} "
                                        f"({word(nt, 'given') if H2_mm is not None else word(nt, 'picked')})"],
                    "formula-a", occ),
    ]
    for blk in side:
        elements += blk
    rows = _comparison_rows(nt, sd, sym_v, sym_a)
    table = _table(rows, align="llrr", name="comparison-table", right=x1, bottom=b_a.top + band_h)
    elements += _titled_table(table, word(nt, "comparison"), "comparison-title") + [table]

    scales = (s_phi, s_s, s_v, s_a) + ((s_t,) if s_t is not None else ())
    elements += sheet.captions(scales)
    notes = tuple(n for n in (s_phi.note, s_s.note) if n) + (
        f"H1 = {v.H_mm:g} mm ({'given' if H1_mm is not None else 'picked: largest convenient H that fits'})",
        f"H2 = {a.H_mm:g} mm ({'given' if H2_mm is not None else 'picked: largest convenient H that fits'})")
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 extra_scales=scales, notes=notes)


# ----------------------------------------------------------------------------- 2. work diagrams

def _moment_subject(subject, m: int, nt):
    """(M_d, M_r, phi, study-or-None, problem text in the notation's language) from a Study, a Case, a
    cycle problem or a pair."""
    if hasattr(subject, "moments") and hasattr(subject, "model"):            # a Study
        M_d, M_r = subject.moments
        return M_d, M_r, np.asarray(subject.phi, dtype=float), subject, problem_title(subject.case, nt)
    if hasattr(subject, "mechanism") and hasattr(subject, "load"):           # a linkage problem
        from graphmethods.dynamics.study import Study

        return _moment_subject(Study(subject, positions=m), m, nt)
    cyc, prob = subject, ""
    if not hasattr(subject, "M_r") or getattr(subject, "M_r", None) is None or not hasattr(subject, "E"):
        ew_ = getattr(subject, "excess_work", None)
        if ew_ is not None and getattr(ew_, "M_r", None) is not None:
            cyc, prob = ew_, problem_title(subject, nt)
    if isinstance(subject, (tuple, list)) and len(subject) == 2:
        M_d, M_r = subject
    elif getattr(cyc, "M_d", None) is not None and getattr(cyc, "M_r", None) is not None:
        M_d, M_r = cyc.M_d, cyc.M_r
    else:
        raise InputError("work_diagrams needs moment curves: a linkage study or problem, a cycle problem given "
                         "by M_d and M_r, or a pair (M_d, M_r) of MomentCurves; areas or works fix no curves")
    for c in (M_d, M_r):
        if not (hasattr(c, "integral") and hasattr(c, "phi")):
            raise InputError(f"work_diagrams: expected MomentCurves, got {type(c).__name__}")
    if isinstance(m, bool) or not isinstance(m, (int, np.integer)) or m < 2:
        raise InputError(f"the number of intervals m must be an integer ≥ 2, got {m!r}")
    phi = M_r.start + np.linspace(0.0, M_r.period, int(m) + 1)
    return M_d, M_r, phi, None, prob


def _accuracy_rows(nt, wd, work_unit: str):
    wu, mm = unit(nt, work_unit), unit(nt, "mm")
    noise = 1e-9 * (float(np.abs(np.concatenate((wd.A_d.values, wd.A_r.values))).max()) or 1.0)

    def cells(value, value_mm):             # rounding noise of an exact construction is written 0
        if value is None:
            return "", ""
        exact = abs(value) <= noise
        return (f"{_fmt(nt, 0.0 if exact else value)} {wu}", f"{_fmt(nt, 0.0 if exact else value_mm, 2)} {mm}")

    rows = [(word(nt, "construction"), word(nt, "at_ends"), word(nt, "on_sheet"), word(nt, "inside"),
             word(nt, "on_sheet"))]
    symbol = {"A_d": sym(nt, "A_d"), "A_r": sym(nt, "A_r"), "ΔE": nt.sym("dE")}
    for r in wd.comparison():
        rows.append((symbol[r["quantity"]],) + cells(r["error"], r["error_mm"]) + cells(r["inside"], r["inside_mm"]))
    return rows


def _accuracy_title(nt, study) -> str:
    title = word(nt, "accuracy_work")
    if study is not None:
        drawn = word(nt, "drawn").format(M=nt.sym("M_r"))
        title += f"（{drawn}）" if nt.code == "zh" else f" ({drawn})"
    return title


def work_diagrams(subject, *, m: int = 12, H_mm: float | None = None, mu_M=None, mu_phi=None, notation="en",
                  page=None, title=None, problem=None, moment_unit: str = "N·m", work_unit: str = "J",
                  title_block: bool = True, name: str = "work-diagrams") -> Scene:
    """The moment diagram M_d, M_r integrated by the method of chords into A_d(φ), A_r(φ), and ΔE(φ).

    Each interval's mean ordinate is drawn as a step, projected onto the M axis and joined to
    the pole P, H mm left of the origin; the work diagrams are the chords parallel to those
    rays (one scale μ_A = μ_M μ_φ H for both), and ΔE = A_d − A_r is drawn from their
    difference. A table gives each construction's largest difference from the exact integral,
    at the interval ends and inside the chords, in units of work and in mm.

    Parameters
    ----------
    subject : Study, Case, cycle problem or (M_d, M_r)
        A linkage study (its positions are the intervals; M_r drawn through its values there,
        compared with the exact M_r that jumps where the load switches); a linkage problem
        (studied at ``m`` positions); a cycle problem with moment curves, or a pair of
        MomentCurves (``m`` equal intervals; the curves are exact).
    H_mm : float, optional
        Pole distance. When not given, the toolkit picks the smallest H of 1, 1.5, 2, 2.5, 3,
        4, 5 × 10^k mm whose work diagrams fit their strip (the largest drawing), and says so.
    mu_M, mu_phi : float or Scale, optional
        Scales of the moment diagram; picked when not given.

    Examples
    --------
    >>> from graphmethods import problems
    >>> s = work_diagrams(problems.w3(), notation="zh")
    >>> [sc.symbol for sc in s.scales()], s.notes[-1]
    (['μ_φ', 'μ_M', 'μ_W'], 'H = 30 mm (picked: smallest convenient H whose work diagrams fit)')
    """
    from graphmethods.units import CONVENIENT, convenient_at_least

    nt = get_notation(notation)
    M_d, M_r, phi, study, prob = _moment_subject(subject, m, nt)
    sheet = Sheet(nt=nt, page=page, default_page=Page("A3", "landscape", frame=True), top_gap_mm=6.0,
                  title=title or word(nt, "work_title"),
                   problem=prob if problem is None else problem, title_block=title_block)
    x0, _, x1, _ = sheet.box
    period = float(phi[-1] - phi[0])
    top = sheet.top + 4.0
    bottom = sheet.caption_y - 9.0
    gap = 13.0
    dim_room = 9.0
    band_h = (bottom - top - 2 * gap) / 3.0
    M_all = np.concatenate((np.asarray(M_d.M), np.asarray(M_r.M), [0.0]))
    M_lo, M_hi = float(M_all.min()), float(M_all.max())
    mu_M_given = mu_M is not None
    if mu_M is None:
        s_M = pick_scale(M_hi - M_lo, band_h - dim_room, symbol=nt.sym("mu_M"), unit=unit(nt, moment_unit))
    else:
        s_M = mu_M if isinstance(mu_M, Scale) else Scale(nt.sym("mu_M"), unit(nt, moment_unit), mu_M)
        if s_M.to_mm(M_hi - M_lo) > band_h + 1e-9:
            raise InputError(f"the moment diagram at {markup.plain(s_M.caption())} needs "
                             f"{s_M.to_mm(M_hi - M_lo):.1f} mm but the strip leaves {band_h:.1f} mm; give a larger "
                             f"μ_M or none")
    if study is not None:
        probe_wd = gc.study_work_diagrams(study, mu_phi=1.0, mu_M=1.0, H_mm=1.0)
    else:
        probe_wd = gc.work_diagrams(M_d, M_r, phi, mu_phi=1.0, mu_M=1.0, H_mm=1.0, exact_d=M_d, exact_r=M_r)
    right_col = _column_width(_accuracy_rows(nt, probe_wd, work_unit),
                              f"{sym(nt, 'A_d')}(φ_T) − {sym(nt, 'A_r')}(φ_T) = −1234 J ({word(nt, 'closure')})")

    def pick_phi(room):
        width = x1 - right_col - 16.0 - (x0 + room + 12.0)
        if mu_phi is None:
            return pick_angle_scale(period, width, symbol=nt.sym("mu_phi"))
        s = mu_phi if isinstance(mu_phi, Scale) else Scale(nt.sym("mu_phi"), "rad", mu_phi)
        if s.to_mm(period) > width + 1e-9:
            raise InputError(f"the period at {markup.plain(s.caption())} needs {s.to_mm(period):.1f} mm but the "
                             f"sheet leaves {width:.1f} mm; give a larger μ_φ or none")
        return s

    # the pole distance: given, or the smallest convenient H whose diagrams fit the strip; the
    # pole must fit left of the moment diagram (room grows up to 90 mm, then μ_M grows)
    A_span = max(float(np.ptp(np.concatenate((probe_wd.A_d.values, probe_wd.A_r.values, [0.0])))), 1e-300)
    room = 44.0
    for _ in range(8):
        s_phi = pick_phi(room)
        if H_mm is not None:
            H = float(H_mm)
            if not (math.isfinite(H) and H > 0):
                raise InputError(f"H_mm = {H_mm!r}: the pole distance must be a positive number of mm")
            break
        H = convenient_at_least(A_span / (s_M.per_mm * s_phi.per_mm * (band_h - dim_room)), gc.POLE_SERIES)
        if H + 12.0 <= room:
            break
        if room < 90.0:                     # first give the pole more room (μ_φ may grow with it) …
            room = min(H + 12.0, 90.0)
        elif not mu_M_given:                # … then draw the moments smaller
            s_M = Scale(s_M.symbol, s_M.unit, convenient_at_least(s_M.per_mm * 1.01, CONVENIENT),
                        note=s_M.note + "; enlarged so that the pole fits")
        else:
            break
    if H + 12.0 > room:
        if mu_phi is None and pick_phi(H + 12.0).per_mm != s_phi.per_mm:
            raise InputError(f"the pole at H = {H:g} mm does not fit left of the moment diagram at "
                             f"{markup.plain(s_phi.caption())}; give a smaller H_mm, a larger μ_M or a larger μ_φ")
        room = H + 12.0
    room = min(room, H + 12.0) if H + 12.0 >= 44.0 else 44.0
    width = x1 - right_col - 16.0 - (x0 + room + 12.0)
    if s_phi.to_mm(period) > width + 1e-9:
        raise InputError(f"the pole at H = {H:g} mm and the period at {markup.plain(s_phi.caption())} do not fit "
                         f"across the sheet; give a smaller H_mm or a larger μ_φ")
    if study is not None:
        wd = gc.study_work_diagrams(study, mu_phi=s_phi.per_mm, mu_M=s_M.per_mm, H_mm=H)
    else:
        wd = gc.work_diagrams(M_d, M_r, phi, mu_phi=s_phi.per_mm, mu_M=s_M.per_mm, H_mm=H, exact_d=M_d, exact_r=M_r)
    s_A = Scale(sym(nt, "mu_A"), unit(nt, work_unit), wd.mu_A)
    A_vals = np.concatenate((wd.A_d.values, wd.A_r.values, [0.0]))
    if s_A.to_mm(float(np.ptp(A_vals))) > band_h + 1e-9:
        raise InputError(f"at H = {H:g} mm the work diagrams need {s_A.to_mm(float(np.ptp(A_vals))):.1f} mm but the "
                         f"strip leaves {band_h:.1f} mm; give a larger H_mm or none to have one picked")
    gx0 = x0 + room + 12.0
    occ = sheet.occ
    elements: list = [sheet.header()]
    phi0 = float(phi[0])
    x = np.asarray(phi) - phi0
    P_name = sym(nt, "P")

    # ---- strip 1: the moment diagram with the mean ordinates, their projections, the rays
    b_M = _Band(x0=gx0, top=top, height=band_h, s_phi=s_phi, s_y=s_M, lo=M_lo, hi=M_hi, period=period,
                align="top")
    curve_d = Polyline(b_M.pts(np.asarray(M_d.phi) - phi0, M_d.M), style=RESULT, name="curve-M_d")
    curve_r = Polyline(b_M.pts(np.asarray(M_r.phi) - phi0, M_r.M), style=RESULT, name="curve-M_r")
    steps, projections, rays = [], [], []
    pole = b_M.mm(-H, 0.0)
    for key, I, curve in (("d", wd.A_d, M_d), ("r", wd.A_r, M_r)):
        means = np.asarray(I.mean_ordinate)
        flat = bool(np.ptp(np.asarray(curve.M)) <= 1e-12 * max(1.0, float(np.abs(curve.M).max())))
        seen: set = set()
        for i, ybar in enumerate(means):
            a_, b_ = b_M.pt(x[i], ybar), b_M.pt(x[i + 1], ybar)
            if not flat:
                steps.append(Polyline((b_M.pt(x[i], 0.0), a_, b_, b_M.pt(x[i + 1], 0.0)), style=THIN,
                                      name=f"mean-{key}-{i + 1}"))
            level = round(float(ybar / s_M.per_mm), 3)
            if level in seen:
                continue
            seen.add(level)
            target = b_M.pt(0.0, ybar)
            if i > 0 and abs(a_[1] - target[1]) > 1e-9:
                projections.append(Line(a_, target, style=PROJECTION, name=f"projection-{key}-{i + 1}"))
            rays.append(Line(pole, target, style=RAY if key == "r" else PROJECTION, name=f"ray-{key}-{i + 1}"))
    ax_phi_M, ax_M = b_M.axes(nt=nt, y_label=nt.quantity(nt.sym("M"), unit(nt, moment_unit)), m=len(x) - 1,
                              name="M")
    pole_els = _pole(b_M, H, P_name, "pole", occ)
    _register(occ, curve_d, curve_r, *steps, *projections, *rays)
    full_M = ax_phi_M
    ax_phi_M, ax_M = _clear_tick_labels(ax_phi_M, occ), _clear_tick_labels(ax_M, occ, keep_values=True)
    _register(occ, ax_phi_M, ax_M)
    pos_M = _lost_positions(full_M, ax_phi_M, occ, "pos-M")
    ords_M = np.concatenate((np.asarray(wd.A_r.mean_ordinate), np.asarray(wd.A_d.mean_ordinate))) / s_M.per_mm
    dim = _h_dimension(b_M, H, ords_M, f"H = {nt.number(H)} {unit(nt, 'mm')}", "H", occ)
    names_M = _curve_names(occ, ((curve_d, nt.sym("M_d"), b_M.origin[1]), (curve_r, nt.sym("M_r"), b_M.origin[1])),
                           "M")
    elements += ([ax_phi_M, ax_M] + steps + projections + rays + [curve_d, curve_r] + pole_els + dim + names_M + pos_M)

    # ---- strip 2: the work diagrams, chords parallel to the rays
    A_lo, A_hi = float(A_vals.min()), float(A_vals.max())
    b_A = _Band(x0=gx0, top=top + band_h + gap, height=band_h, s_phi=s_phi, s_y=s_A, lo=A_lo, hi=A_hi,
                period=period)
    chords_d = Polyline(b_A.pts(x, wd.A_d.values), style=RESULT, name="chords-A_d")
    chords_r = Polyline(b_A.pts(x, wd.A_r.values), style=RESULT, name="chords-A_r")
    dots_A = [Point(p, radius_mm=0.5, name=f"dot-A_r-{k}") for k, p in enumerate(chords_r.points)]
    dots_A += [Point(chords_d.points[-1], radius_mm=0.5, name="dot-A_d-end")]
    ax_phi_A, ax_A = b_A.axes(nt=nt, y_label=nt.quantity(nt.sym("A"), unit(nt, work_unit)), m=len(x) - 1, name="A")
    _register(occ, chords_d, chords_r)
    full_A = ax_phi_A
    ax_phi_A, ax_A = _clear_tick_labels(ax_phi_A, occ), _clear_tick_labels(ax_A, occ, keep_values=True)
    _register(occ, ax_phi_A, ax_A)
    pos_A = _lost_positions(full_A, ax_phi_A, occ, "pos-A")
    names_A = _curve_names(occ, ((chords_d, sym(nt, "A_d"), b_A.origin[1]), (chords_r, sym(nt, "A_r"), b_A.origin[1])),
                           "A")
    elements += [ax_phi_A, ax_A, chords_d, chords_r] + dots_A + names_A + pos_A

    # ---- strip 3: ΔE = A_d − A_r
    dE = wd.delta_E
    b_E = _Band(x0=gx0, top=top + 2 * (band_h + gap), height=band_h, s_phi=s_phi, s_y=s_A, lo=float(dE.min()),
                hi=float(dE.max()), period=period)
    curve_E = Polyline(b_E.pts(x, dE), style=RESULT, name="curve-dE")
    ordinates_E = [Line(b_E.pt(xk, 0.0), b_E.pt(xk, ek), style=THIN, name=f"ordinate-dE-{k}")
                   for k, (xk, ek) in enumerate(zip(x, dE)) if abs(s_A.to_mm(float(ek))) > 0.05]
    dots_E = [Point(p, radius_mm=0.5, name=f"dot-dE-{k}") for k, p in enumerate(curve_E.points)]
    ax_phi_E, ax_E = b_E.axes(nt=nt, y_label=nt.quantity(nt.sym("dE"), unit(nt, work_unit)), m=len(x) - 1,
                              name="dE")
    _register(occ, curve_E, *ordinates_E)
    full_E = ax_phi_E
    ax_phi_E, ax_E = _clear_tick_labels(ax_phi_E, occ), _clear_tick_labels(ax_E, occ, keep_values=True)
    _register(occ, ax_phi_E, ax_E)
    pos_E = _lost_positions(full_E, ax_phi_E, occ, "pos-E")
    elements += [ax_phi_E, ax_E] + ordinates_E + [curve_E] + dots_E + pos_E

    # ---- right column: formulas and the accuracy of each construction
    rx = x1 - right_col
    picked = word(nt, "given") if H_mm is not None else word(nt, "picked")
    elements += _side_block(rx, b_M.top + 4.0, [s_M.caption(nt), s_phi.caption(nt)], "formula-M", occ)
    elements += _side_block(rx, b_A.top + 4.0, [f"{s_A.symbol} = {s_M.symbol}·{nt.sym('mu_phi')}·H = "
                                                f"{nt.number(wd.mu_A)} {unit(nt, work_unit)}/{unit(nt, 'mm')}",
                                                f"H = {nt.number(H)} {unit(nt, 'mm')} ({picked})"], "formula-A", occ)
    closure = f"{sym(nt, 'A_d')}({nt.sym('phi')}_{{T}}) − {sym(nt, 'A_r')}({nt.sym('phi')}_{{T}}) = " \
              f"{nt.number(wd.closure if abs(wd.closure) > 1e-9 * max(1.0, A_hi) else 0.0)} {unit(nt, work_unit)} " \
              f"({word(nt, 'closure')})"
    elements += _side_block(rx, b_E.top + 4.0, [f"{nt.sym('dE')} = {sym(nt, 'A_d')} − {sym(nt, 'A_r')};  "
                                                f"{s_A.symbol} = {nt.number(wd.mu_A)} {unit(nt, work_unit)}/"
                                                f"{unit(nt, 'mm')}", closure], "formula-dE", occ)
    rows = _accuracy_rows(nt, wd, work_unit)
    table = _table(rows, align="lrrrr", name="accuracy-table", right=x1, bottom=b_E.top + band_h)
    head = _titled_table(table, _accuracy_title(nt, study), "accuracy-title")
    elements += head + [table]
    scales = (s_phi, s_M, s_A)
    elements += sheet.captions(scales)
    notes = tuple(n for n in (s_phi.note, s_M.note) if n) + (
        f"H = {H:g} mm ({'given' if H_mm is not None else 'picked: smallest convenient H whose work diagrams fit'})",)
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 extra_scales=scales, notes=notes)


def _curve_names(occ: Occupancy, pairs, band: str):
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
        for at, dirs in spots:
            lab = occ.first_free(at, text, dirs, (1.5, 3.0), TEXT_MM + 0.3, None)
            if lab is not None:
                break
        if lab is None:
            lab = occ.place_label(pts[-1], text, ("e",), size_mm=TEXT_MM + 0.3, register=False)
        occ.add_label(lab)
        out.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM + 0.3, anchor=lab.anchor,
                        name=f"name-{band}-{markup.plain(text)}"))
    return out
