"""The dynamics figures of a linkage study: J_e(φ), M_d and M_r(φ), ΔT(φ) or T(φ), ω(φ), ε(φ), the Zhukovsky lever.

Each function takes a :class:`~graphmethods.dynamics.study.Study` (or a problem
:class:`~graphmethods.kinematics.case.Case`, studied at 12 positions) and returns a
:class:`~graphmethods.scene.Scene` on an A4 sheet with a frame and a title block.
Scales are keyword arguments; any not given is picked (a convenient value that fills
the sheet) and every scale drawn is captioned under the figure. ``notation="en" | "ru"
| "zh"`` switches every symbol and word. A figure asks the lazy study only for what it
draws: :func:`moment_graph` never computes J_e, and only :func:`speed_graph`,
:func:`acceleration_graph` and ``delta_T_graph(kinetic=True)`` solve the exact motion.

- :func:`inertia_graph` J_e(φ) and its parts; ``turned=True`` draws it turned 90°
  (φ down the page, J_e to the right), ready for the Wittenbauer construction;
- :func:`moment_graph` M_d and M_r(φ) as drawn through the positions;
- :func:`delta_T_graph` ΔT(φ) of the drawn moments, or the exact T(φ);
- :func:`speed_graph`, :func:`acceleration_graph` ω(φ) and ε(φ) of the exact motion;
- :func:`zhukovsky_lever` the velocity plan turned 90° as a lever, with the load at its image.

The building blocks (:func:`phi_graph_elements`, :func:`turned_inertia_elements`,
:class:`DownAxis`, :class:`FastOccupancy`) are shared with :mod:`graphmethods.sheets.wittenbauer`.

>>> import pathlib
>>> from graphmethods.dynamics.study import Study
>>> from graphmethods.kinematics import read_case
>>> press = read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json")
>>> study = Study(press, positions=12)
>>> scene = moment_graph(study, notation="ru")
>>> [s.caption("ru") for s in scene.scales()], "inertia" in study.computed
(['μ_φ = 0,03491 рад/мм (2°/мм)', 'μ_M = 5 Н·м/мм'], False)
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.dynamics.study import Study
from graphmethods.errors import InputError
from graphmethods.scene import markup, notation as get_notation
from graphmethods.scene.elements import Axis, Element, Frame, Line, Point, Polyline, Text, label_bbox, make_label
from graphmethods.scene.notation import Notation
from graphmethods.scene.numbers import format_value
from graphmethods.scene.page import Page
from graphmethods.scene.primitives import AXIS, MAIN, THIN, Label, Path, Polygon, Style
from graphmethods.scene.scale import Scale
from graphmethods.scene.scene import Scene
from graphmethods.scene.ticks import axis_ticks
from graphmethods.sheets.frame import FastOccupancy, SheetFrame  # SheetFrame re-exported for cycle_panels, motion
from graphmethods.sheets.layout import TEXT_MM, Box, clear_tick_labels, given_angle_scale, given_scale, problem_title
from graphmethods.sheets.styles import LEVEL, PART

SMALL_MM = 2.8          # tick labels, position numbers
TWO_PI = 2.0 * math.pi

# ----------------------------------------------------------------------------- words of these figures
# Every word, symbol and unit is the notation's (scene/vocabulary/dynamics.toml: nt.sym("dynamics.J_e")).


def value_text(nt, value: float, u: str, *, sig: int = 4) -> str:
    """``"31.42 rad/s"`` in the profile's number style and units."""
    nt = get_notation(nt)
    sep = "" if u == "°" else " "
    return f"{nt.number(value, sig=sig)}{sep}{nt.unit(u)}" if u else nt.number(value, sig=sig)


# ----------------------------------------------------------------------------- layout helpers

@dataclass(frozen=True)
class DownAxis(Axis):
    """An axis whose values grow down the page: the φ axis of a graph turned 90° clockwise.

    Tick marks and labels are on its left; its name is under the arrow.

    >>> ax = DownAxis((20, 30), Scale("μ_φ", "rad", 0.025), "y", max_value=2.0, ticks=(0.0, 1.0))
    >>> ax.pos(1.0), ax.tip
    ((20.0, 70.0), (20.0, 116.0))
    """

    def pos(self, value: float):
        mm = self.scale.to_mm(float(value))
        return (self.origin[0], self.origin[1] + mm)

    @property
    def tip(self):
        x, y = self.pos(self.max_value)
        return (x, y + self.arrow_mm)

    @property
    def end(self):
        return self.tip

    def primitives(self):
        tx, ty = self.tip
        prims = [Path((self.start, self.tip), AXIS),
                 Polygon(((tx, ty), (tx - 0.55, ty - 3.0), (tx + 0.55, ty - 3.0)))]
        labels = self.tick_labels
        if labels is None:
            labels = tuple(format_value(v, decimal=self.decimal) for v in self.ticks)
        for v, text in zip(self.ticks, labels):
            x, y = self.pos(v)
            prims.append(Path(((x - self.tick_mm, y), (x, y)), AXIS))
            if text and not (self.skip_zero_label and v == 0):
                prims.append(make_label((x - self.tick_mm - 0.8, y), text, size_mm=self.size_mm, anchor="end",
                                        valign="middle"))
        if self.label:
            prims.append(make_label((tx, ty + 1.0), self.label, size_mm=self.size_mm + 0.5, anchor="middle",
                                    valign="top"))
        return tuple(prims)


def position_labels(m: int, spacing_mm: float, *, min_gap_mm: float = 5.0) -> tuple[str, ...]:
    """Position numbers 0…m for the ticks of a φ axis, every n-th one when they would crowd.

    >>> position_labels(12, 20.0)[:3], position_labels(72, 3.0)[:5]
    (('0', '1', '2'), ('0', '', '2', '', '4'))
    """
    step = max(1, math.ceil(min_gap_mm / max(spacing_mm, 1e-9)))
    return tuple(str(k) if k % step == 0 or k == m else "" for k in range(m + 1))


def as_study(obj, positions: int = 12):
    """A Study from a Study or a problem Case (studied at ``positions``)."""

    if isinstance(obj, Study):
        return obj
    if hasattr(obj, "mechanism") and hasattr(obj, "inertias") and hasattr(obj, "load"):
        return Study(obj, positions=positions)
    raise InputError(f"expected a Study (graphmethods.dynamics.study) or a problem read with "
                     f"graphmethods.kinematics.read_case, got {type(obj).__name__}")


def require_step_load(study, figure: str) -> None:
    """Refuse a figure that draws the load as one working-stroke force (the Zhukovsky lever) when the
    problem gives its load as force diagrams (an engine's indicator diagram)."""
    if getattr(study.case.load, "kind", None) == "diagram":
        raise InputError(f"{figure}: this problem's load is given as force diagrams (an indicator diagram); the "
                         f"figure applies one working-stroke force and does not draw diagram loads yet; the moment "
                         f"graph, the energy–mass diagram, the dynamic-analysis sheet and the study's numbers "
                         f"(graphmethods study --json) are available")


def problem_text(study, nt="en") -> str:
    """The problem's title (its kind when it has none) and the number of positions, in the notation's language.

    Parameters
    ----------
    study : Study
        A linkage study; its problem file's title (translated for a reference case, see
        :func:`graphmethods.problems.reference_cases.title_of`) and its ``m``.
    nt : str or Notation
        The figure's notation.

    Returns
    -------
    str
        ``"<title>, m = <m>"`` (Chinese: a full-width comma).

    Examples
    --------
    >>> from graphmethods.dynamics.study import Study
    >>> from graphmethods.problems.builtin import case
    >>> st = Study(case("press"))
    >>> problem_text(st, "ru"), problem_text(st, "zh")
    ('дезаксиальный кривошипно-ползунный пресс, m = 12', '偏置曲柄滑块压力机，m = 12')
    """
    name = problem_title(study.case, nt) or getattr(study.case, "kind", "")
    return f"{name}{'，' if get_notation(nt).code == 'zh' else ', '}m = {study.m}"


def fine_angles(m: int, per_interval: int = 30) -> np.ndarray:
    """Angles 0…2π for drawing curves: every position, and ``per_interval`` steps between them."""
    return np.linspace(0.0, TWO_PI, m * per_interval + 1)


def inertia_curve(study, phi: np.ndarray):
    """J_e and its parts at the angles ``phi`` from position 0 (rad), kg·m² (the exact reduction)."""
    from graphmethods.dynamics.reduction import reduced_inertia

    mech = study.mechanism
    return reduced_inertia(mech.velocity_plans(mech.positions(phi_from_start=phi)), study.case.inertias)


def suppressed_base(lo: float, hi: float, scale: Scale, *, zero: bool | None = None) -> float:
    """Where a value axis starts: 0, or (for a small variation far from 0) a round tick below ``lo``.

    >>> suppressed_base(30.8, 32.0, Scale("μ", "rad/s", 0.01))
    30.7
    >>> suppressed_base(0.54, 0.70, Scale("μ", "kg·m²", 0.005), zero=True)
    0.0
    """
    if zero is None:
        zero = not (lo > 0 and (hi - lo) < 0.35 * hi)
    if zero or not hi > lo:          # a constant (J_e of masses on the crank only): the axis from 0 shows it
        return 0.0
    ticks = axis_ticks(lo - (hi - lo), hi, scale, min_gap_mm=8.0)
    below = [t for t in ticks if t <= lo - 0.02 * (hi - lo)]
    return float(below[-1]) if below else (float(ticks[0]) if ticks else 0.0)


# ----------------------------------------------------------------------------- the φ graph

@dataclass(frozen=True)
class CurveSpec:
    """A curve of a φ graph: values at angles (rad from position 0), its style and name label."""

    key: str
    phi: np.ndarray
    values: np.ndarray
    style: Style = MAIN
    label: str = ""


@dataclass(frozen=True)
class MarkSpec:
    """An extreme marked on a φ graph: a small circle and its text (above or below)."""

    key: str
    phi: float
    value: float
    text: str
    up: bool = True


#: a curve's name keeps this far (mm) beside an axis's name (above and below it, 1.5 mm)
AXIS_NAME_CLEAR_MM = 6.0


def phi_graph_elements(*, origin, s_phi: Scale, s_Y: Scale, m: int, phi_k: np.ndarray, curves, nt, occ,
                       y_from: float, y_to: float, axis_level: float, y_label: str, dots=None, marks=(),
                       levels=(), prefix: str = "", within=None, labels_side: str | None = None,
                       phi_label: str = "") -> list:
    """The elements of a graph against φ (axes with position numbers, curves, dots, marks, levels).

    Parameters
    ----------
    origin : (float, float), mm
        Page point of φ = 0 and value 0 (may lie off the page when the value axis starts at
        ``y_from`` > 0).
    s_phi, s_Y : Scale
        The φ scale (rad/mm) and the value scale.
    m, phi_k
        Number of intervals and the angles of positions 0…m, rad from position 0.
    curves : sequence of CurveSpec
        Drawn in order; the first is the graph's main curve.
    y_from, y_to : float
        The drawn range of the value axis; ``axis_level`` is where the φ axis crosses it.
    dots : (phi, values) or None
        Points marked at the positions.
    marks : sequence of MarkSpec
        Extremes marked with a circle and a text.
    levels : sequence of (value, text, key)
        Dashed horizontal levels across the graph, their text at the right end.
    prefix : str
        Prepended to element names (several graphs on one sheet).
    """
    if not y_to > y_from:    # every value the same (e.g. no load: M_d = M_r = 0): an axis 10 mm long
        y_from, y_to = y_from - 5.0 * s_Y.per_mm, y_to + 5.0 * s_Y.per_mm
    f = Frame(origin, s_phi, s_Y)
    period = float(phi_k[-1] - phi_k[0])
    x_axis_y = f.pt(0.0, axis_level)[1]
    y0_page = f.pt(0.0, y_from)[1]
    spacing = s_phi.to_mm(period / m)
    below = any(float(np.max(c.values)) < axis_level or
                float(np.mean(c.values < axis_level)) > 0.5 for c in curves[:1])
    side = labels_side if labels_side is not None else ("above" if below else "below")
    ax_phi = Axis((origin[0], x_axis_y), s_phi, "x", min_value=0.0, max_value=period, ticks=tuple(phi_k - phi_k[0]),
                  tick_labels=("",) * (m + 1), label=phi_label or nt.sym("phi"), size_mm=SMALL_MM,
                  name=f"{prefix}axis-phi", labels_side=side)
    ticks = tuple(t for t in axis_ticks(y_from, y_to, s_Y, min_gap_mm=8.0) if y_from <= t <= y_to)
    ax_Y = Axis(origin, s_Y, "y", min_value=y_from, max_value=y_to, ticks=ticks, label=y_label, size_mm=SMALL_MM,
                decimal=get_notation(nt).decimal, name=f"{prefix}axis-Y", skip_zero_label=(axis_level == 0 and
                                                                                        y_from < 0))
    lines = [Polyline(f.pts(c.phi, c.values), style=c.style, name=f"{prefix}curve-{c.key}") for c in curves]
    lvl = []
    x_end = f.pt(period, 0.0)[0]
    for value, _text, key in levels:
        y = f.pt(0.0, value)[1]
        lvl.append(Line((origin[0], y), (x_end + 2.0, y), style=LEVEL, name=f"{prefix}level-{key}"))
    occ.register(*lines, *lvl)
    occ.add_box((origin[0] - 0.5, min(y0_page, x_axis_y) - 0.5, origin[0] + 0.5, max(y0_page, x_axis_y) + 0.5))
    occ.add_line((ax_phi.start, ax_phi.tip))
    occ.add_line((ax_Y.start, ax_Y.tip))
    ax_phi, ax_Y = clear_tick_labels(ax_phi, occ), clear_tick_labels(ax_Y, occ)
    occ.register(ax_phi, ax_Y)
    for ax in (ax_phi, ax_Y):        # keep curve names well clear of the axis names: a name on the same line
        name = [p for p in ax.primitives() if isinstance(p, Label)][-1:]     # 3 mm on reads as one text
        if name and ax.label:            # ("M, N·m  M_d")
            b = label_bbox(name[0])
            occ.add_box((b[0] - AXIS_NAME_CLEAR_MM, b[1] - 1.5, b[2] + AXIS_NAME_CLEAR_MM, b[3] + 1.5))
    els: list[Element] = [ax_phi, ax_Y, *lvl, *lines]
    els += _position_numbers(ax_phi, phi_k, m, spacing, occ, side, prefix)
    if dots is not None:
        pts = f.pts(*dots)
        els += [Point(p, radius_mm=0.6, name=f"{prefix}dot-{k}") for k, p in enumerate(pts)]
        for p in pts:
            occ.add_box((p[0] - 0.7, p[1] - 0.7, p[0] + 0.7, p[1] + 0.7))
    for value, text, key in levels:
        y = f.pt(0.0, value)[1]
        lab = occ.place_label((x_end + 2.0, y), text, ("ne", "e", "se", "n", "s"), size_mm=TEXT_MM, gap_mm=1.0,
                              within=within)
        els.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name=f"{prefix}label-{key}"))
    els += _mark_elements(marks, f, occ, prefix, within)
    els += _curve_names(curves, lines, occ, axis_level, prefix, within)
    return els


def _position_numbers(ax_phi: Axis, phi_k: np.ndarray, m: int, spacing: float, occ: FastOccupancy, side: str,
                      prefix: str) -> list[Element]:
    """Position numbers under (or over) the φ axis ticks, on the other side where a curve runs through."""
    els: list[Element] = []
    order = ("n", "s") if side == "above" else ("s", "n")
    for k, text in enumerate(position_labels(m, spacing)):
        if not text:
            continue
        at = ax_phi.pos(float(phi_k[k] - phi_k[0]))
        lab = occ.first_free(at, text, order + ("se", "ne", "sw", "nw"), (2.3, 3.5), SMALL_MM, None)
        if lab is None:
            lab = occ.place_label(at, text, order[:1], size_mm=SMALL_MM, gap_mm=2.3, register=False)
        occ.add_label(lab)
        els.append(Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, valign="baseline",
                        name=f"{prefix}pos-{k}"))
    return els


def _mark_elements(marks: Sequence[MarkSpec], f: Frame, occ: FastOccupancy, prefix: str,
                   within: Box | None) -> list[Element]:
    """Extremes marked with an open circle and their text (with a leader when crowded)."""
    els: list[Element] = []
    for mk in marks:
        at = f.pt(mk.phi, mk.value)
        els.append(Point(at, radius_mm=1.1, filled=False, name=f"{prefix}mark-{mk.key}"))
        occ.add_box((at[0] - 1.3, at[1] - 1.3, at[0] + 1.3, at[1] + 1.3))
        up, down = ("n", "ne", "nw", "e", "w"), ("s", "se", "sw", "e", "w")
        lab, leader = occ.place_label_with_leader(at, mk.text, up + down if mk.up else down + up, size_mm=TEXT_MM,
                                                  gap_mm=2.0, within=within)
        els.append(Text((lab.x, lab.y), mk.text, size_mm=TEXT_MM, anchor=lab.anchor, name=f"{prefix}label-{mk.key}"))
        if leader is not None:
            els.append(Line(leader[0], leader[1], style=THIN, name=f"{prefix}leader-{mk.key}"))
    return els


def _curve_names(curves: Sequence[CurveSpec], lines: Sequence[Polyline], occ: FastOccupancy, axis_level: float,
                 prefix: str, within: Box | None) -> list[Element]:
    """Each named curve's name at its end, else along it, else with a leader (its peak first when it ends
    on the axis)."""
    els: list[Element] = []
    for c, line in zip(curves, lines):
        if not c.label:
            continue
        size = TEXT_MM + 0.4
        n = len(line.points)
        spots: list[tuple[tuple[float, float], tuple[str, ...]]] = [(line.end, ("e", "ne", "se"))] + [
            (line.points[int(n * t)], ("n", "s", "ne", "se", "nw", "sw"))
            for t in (0.93, 0.85, 0.7, 0.55, 0.4, 0.25, 0.1)]
        far = int(np.argmax(np.abs(np.asarray(c.values, dtype=float) - axis_level)))
        if abs(float(c.values[-1]) - axis_level) < 0.05 * abs(float(c.values[far]) - axis_level):
            spots.insert(0, (line.points[far], ("ne", "nw", "n", "e", "w")))   # it ends on the axis: name its peak
        lab = None
        for at, dirs in spots:
            lab = occ.first_free(at, c.label, dirs, (1.2, 2.5), size, within)
            if lab is not None:
                break
        if lab is None:
            lab, leader = occ.place_label_with_leader(line.points[n // 2], c.label, size_mm=size, within=within)
            if leader is not None:
                els.append(Line(leader[0], leader[1], style=THIN, name=f"{prefix}leader-{c.key}"))
        else:
            occ.add_label(lab)
        els.append(Text((lab.x, lab.y), c.label, size_mm=size, anchor=lab.anchor, name=f"{prefix}name-{c.key}"))
    return els


def phi_graph(study: Any, *, nt: Notation, title: str, name: str, curves: Sequence[CurveSpec], y_lo: float,
              y_hi: float, y_symbol: str, y_unit: str, scale_symbol: str, what: str, page: Page | None = None,
              title_block: bool = True, mu_Y: Any = None, mu_phi: Any = None,
              dots: tuple[Any, Any] | None = None, marks: Sequence[MarkSpec] = (), levels: Sequence[Any] = (),
              legend: str = "", zero: bool | None = None, extra_notes: Sequence[str] = ()) -> Scene:
    """A whole figure of graphs against the crank angle φ over one turn (A4 landscape unless ``page``).

    The toolkit's φ-graph, which the standalone graphs (J_e, M, ΔT, ω, ε, m_e) are built on: the
    frame with its title and problem, μ_φ and the value scale chosen to fill the plot (or given),
    the φ axis with the positions 0…m, the value axis with its values (a suppressed zero when the
    values lie far from 0, said in the notes), the curves, dots, marks and levels, and the scale
    captions.

    Parameters
    ----------
    study : Study
        Gives the positions (``study.phi``, ``study.m``) and the problem's title.
    nt : Notation
        The notation the texts are written in.
    title, name : str
        The figure's title (drawn) and its scene name (element ids).
    curves : sequence of CurveSpec
        ``CurveSpec(name, phi_rad, values, style, label)``, values in ``y_unit``.
    y_lo, y_hi : float
        The value range to fit, in ``y_unit``.
    y_symbol, y_unit, scale_symbol : str
        The value axis's symbol and unit (``nt.quantity`` writes them) and its scale's symbol (μ_M ...).
    what : str
        What the values are, for the message when a given scale cannot hold them.
    mu_Y, mu_phi : Scale, float or None
        Given scales (units per mm; μ_φ in rad/mm); ``None`` picks them.
    dots : (phi, values), optional
        Values marked with dots (the study's positions).
    zero : bool or None
        ``True`` keeps 0 on the value axis, ``False`` suppresses it, ``None`` decides by the range.

    Returns
    -------
    Scene

    Examples
    --------
    >>> import numpy as np
    >>> from graphmethods.dynamics.study import Study
    >>> from graphmethods.problems.builtin import case
    >>> from graphmethods.scene import notation
    >>> study = Study(case("press"), positions=12)
    >>> phi = np.linspace(0.0, 2 * np.pi, 73)
    >>> scene = phi_graph(study, nt=notation("en"), title="sin φ", name="sine", y_lo=-1.0, y_hi=1.0,
    ...                   curves=[CurveSpec("s", phi, np.sin(phi), MAIN, "sin φ")], y_symbol="y", y_unit="",
    ...                   scale_symbol="μ_y", what="sin φ")
    >>> scene.name, scene.element("curve-s").name
    ('sine', 'curve-s')
    """

    sheet = SheetFrame(nt=nt, page=page, title=title, problem=problem_text(study, nt), title_block=title_block,
                       default_page=Page("A4", "landscape", frame=True))
    x0, y0, x1, y1 = sheet.box
    y_label = nt.quantity(y_symbol, y_unit)
    right = 8.0 + markup.text_width_mm(nt.sym("phi"), SMALL_MM + 0.5) + 26.0
    px0, px1 = x0 + 20.0, x1 - right
    py0, py1 = sheet.top + 12.0, sheet.caption_y - 14.0
    s_phi = given_angle_scale(mu_phi, nt.sym("mu_phi"), TWO_PI, px1 - px0)
    u = nt.unit(y_unit)
    u = f"({u})" if "/" in u else u
    suppressed = zero is False or (zero is None and y_lo > 0 and (y_hi - y_lo) < 0.35 * y_hi)
    if suppressed:
        s_Y = given_scale(mu_Y, scale_symbol, u, y_hi - y_lo, py1 - py0 - 14.0, what=what)
        base = suppressed_base(y_lo, y_hi, s_Y, zero=False)
    else:
        lo = min(y_lo, 0.0)
        s_Y = given_scale(mu_Y, scale_symbol, u, max(y_hi, 0.0) - lo, py1 - py0, what=what)
        base = lo
    axis_level = 0.0 if base <= 0.0 <= y_hi else base
    origin = (px0, py0 + s_Y.to_mm(max(y_hi, 0.0) if base <= 0 else y_hi))
    within = (px0 - 18.0, sheet.top, x1, sheet.caption_y - 5.0)
    m = study.m
    els = phi_graph_elements(origin=origin, s_phi=s_phi, s_Y=s_Y, m=m, phi_k=np.asarray(study.phi, dtype=float),
                             curves=curves, nt=nt, occ=sheet.occ, y_from=base, y_to=y_hi, axis_level=axis_level,
                             y_label=y_label, dots=dots, marks=marks, levels=levels, within=within)
    notes = [s_phi.note, s_Y.note, *extra_notes]
    if suppressed:
        notes.append(f"the value axis starts at {base:g} {y_unit} (a suppressed zero)")
    scales = (s_phi, s_Y)
    elements = [sheet.header()] + els + sheet.captions(scales, legend=legend)
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=sheet.nt.code, name=name,
                 notes=tuple(notes))


# ----------------------------------------------------------------------------- 1. J_e(φ)

def _part_label(key: str) -> str:
    """``"m (S2)"`` -> ``"m_{S2}"``, ``"J (OA)"`` -> ``"J_{OA}"`` (markup)."""
    mt = re.fullmatch(r"(\w+) \((.+)\)", key)
    return f"{mt.group(1)}_{{{mt.group(2)}}}" if mt else markup.literal(key)


def inertia_graph(study, *, mu_J=None, mu_phi=None, turned: bool = False, parts: bool = True, notation="en",
                  page=None, title=None, title_block: bool = True, name: str = "inertia-graph") -> Scene:
    """The reduced moment of inertia J_e(φ) over one crank turn, with its parts; or turned 90°.

    The curve is the exact reduction (drawn through 30 steps per interval); the
    positions 0…m are marked and numbered on the φ axis. ``turned=True`` draws the graph
    turned 90° clockwise on an A4 portrait sheet: J_e to the right from 0 (the abscissa of
    the energy–mass diagram) and φ down the page, ready for projecting J_e values up or
    down onto the Wittenbauer diagram.

    Parameters
    ----------
    study : Study or Case
    mu_J : float or Scale, optional
        kg·m² per mm; picked when not given.
    mu_phi : float or Scale, optional
        rad per mm; picked (a round number of degrees per mm) when not given.
    parts : bool
        Also draw each moving mass's share (not when turned).

    Examples
    --------
    >>> import pathlib
    >>> from graphmethods.kinematics import read_case
    >>> press = read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json")
    >>> s = inertia_graph(press, turned=True)
    >>> s.page.orientation, [a.name for a in s.axes()]
    ('portrait', ['axis-J', 'axis-phi'])
    """
    study = as_study(study)
    nt = get_notation(notation)
    phi = fine_angles(study.m)
    red = inertia_curve(study, phi)
    J_k = np.asarray(study.J_e, dtype=float)
    phi_k = np.asarray(study.phi, dtype=float)
    J_sym = nt.sym("dynamics.J_e")
    if turned:
        return _turned_inertia_scene(study, nt=nt, phi=phi, J=red.J_e, J_k=J_k, phi_k=phi_k, mu_J=mu_J,
                                     mu_phi=mu_phi, page=page, title=title, title_block=title_block, name=name)
    curves = [CurveSpec("J_e", phi, red.J_e, MAIN, J_sym)]
    if parts:
        for key, values in red.parts.items():
            if np.ptp(values) > 0 or values[0] > 0:
                curves.append(CurveSpec(re.sub(r"\W+", "", key), phi, values, PART, _part_label(key)))
    y_hi = float(max(red.J_e.max(), J_k.max()))
    legend = f"{J_sym} = Σ[m_i(v_{{Si}}/ω_1)² + J_{{Si}}(ω_i/ω_1)²]"
    return phi_graph(study, nt=nt, title=title or f"{nt.word('dynamics.inertia_graph')} {J_sym}(φ)", page=page,
                        title_block=title_block, name=name, curves=curves, y_lo=0.0, y_hi=y_hi, y_symbol=J_sym,
                        y_unit="kg·m²", scale_symbol=nt.sym("dynamics.mu_J"), mu_Y=mu_J, mu_phi=mu_phi,
                        what="the J_e graph", dots=(phi_k, J_k), legend=legend, zero=True)


def axis_break(at: tuple[float, float], name: str) -> Polyline:
    """The mark of a suppressed zero on a horizontal axis: a short zigzag across it at ``at`` (mm).

    >>> axis_break((10.0, 50.0), "break").points[:2]
    ((8.5, 50.0), (9.25, 48.5))
    """
    x, y = at
    return Polyline(((x - 1.5, y), (x - 0.75, y - 1.5), (x + 0.75, y + 1.5), (x + 1.5, y)), style=THIN, name=name)


def same_decimals(values, nt) -> tuple[str, ...]:
    """Tick values written with one number of decimals, the fewest that write each of them exactly (to six
    significant digits), in the notation's decimal mark and minus.

    >>> from graphmethods.scene import notation
    >>> same_decimals([0.25, 0.5, 1.0], notation("ru")), same_decimals([-50.0, 0.0, 50.0], notation("en"))
    (('0,25', '0,50', '1,00'), ('−50', '0', '50'))
    >>> same_decimals([0.0, 0.5, 1.0], notation("en"))
    ('0', '0.5', '1.0')
    """
    nt = get_notation(nt)
    texts = [nt.number(float(v), sig=6) for v in values]
    decimals = max((len(t.split(nt.decimal)[1]) for t in texts if nt.decimal in t and "·" not in t), default=0)
    def fixed(v: float) -> str:                 # the origin is written 0, as the books write it
        return "0" if v == 0.0 else f"{float(v):.{decimals}f}".replace(".", nt.decimal).replace("-", "−")

    return tuple(t if "·" in t else fixed(v) for v, t in zip(values, texts))


#: the least distance between the J_e axis's ticks (mm): the turned J_e graph and the energy–mass diagram under
#: it, which share μ_J, take the same ticks
J_TICK_GAP_MM = 14.0


def inertia_ticks(J_from: float, J_to: float, s_J: Scale, nt, *, min_gap_mm: float = J_TICK_GAP_MM
                  ) -> tuple[tuple[float, ...], tuple[str, ...], str]:
    """The J_e axis's ticks (kg·m²), their labels and the axis's name, readable: a small J_e is written in
    10⁻³ kg·m² (no "0.05225" five-digit jam), the ticks stand at least a label's width apart, and every
    value has the same number of decimals (0.169, 0.170, 0.171; never 0.17 among them).

    >>> from graphmethods.scene import notation
    >>> t, labels, name = inertia_ticks(0.0517, 0.0552, Scale("μ_J", "kg·m²", 2e-5), notation("en"))
    >>> labels[:3], name
    (('52.0', '52.5', '53.0'), 'J_e, 10⁻³ kg·m²')
    >>> inertia_ticks(0.168, 0.171, Scale("μ_J", "kg·m²", 4e-5), notation("ru"))[1]
    ('0,168', '0,169', '0,170', '0,171')
    """
    nt = get_notation(nt)
    top = max(abs(J_from), abs(J_to))
    exp = 3 * math.floor(math.log10(top) / 3) if 0.0 < top < 0.1 else 0
    f = 10.0 ** -exp
    gap = min_gap_mm
    for _ in range(6):
        ticks = tuple(t for t in axis_ticks(J_from, J_to, s_J, min_gap_mm=gap) if J_from <= t <= J_to)
        labels = same_decimals([t * f for t in ticks], nt)
        need = max((markup.text_width_mm(lab, SMALL_MM) for lab in labels), default=0.0) + 4.0
        if need <= gap:
            break
        gap = need
    sup = str(exp).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
    unit = f"10{sup} {nt.unit('kg·m²')}" if exp else "kg·m²"
    return ticks, labels, nt.quantity(nt.sym("dynamics.J_e"), unit) if exp else nt.quantity(
        nt.sym("dynamics.J_e"), "kg·m²")


def turned_inertia_elements(*, origin, s_J: Scale, s_phi: Scale, m: int, phi: np.ndarray, J: np.ndarray,
                            phi_k: np.ndarray, J_k: np.ndarray, nt, occ, J_to: float, prefix: str = "J-",
                            within=None, J_from: float = 0.0) -> list:
    """The J_e(φ) graph turned 90° clockwise: J_e axis to the right from ``origin``, φ axis down from it.

    Page point of (φ, J) is ``(origin_x + (J − J_from)/μ_J, origin_y + φ/μ_φ)``: the J_e axis starts
    at ``J_from`` (0, or a suppressed zero marked by :func:`axis_break`). Returns the axes, the
    curve and the dots ``{prefix}dot-k`` at positions 0…m−1.
    """
    ox, oy = origin
    period = float(phi_k[-1] - phi_k[0])
    ticks_J, labels_J, name_J = inertia_ticks(J_from, J_to, s_J, nt)
    ax_J = Axis((ox - s_J.to_mm(J_from), oy), s_J, "x", min_value=J_from, max_value=J_to, ticks=ticks_J,
                tick_labels=labels_J, label=name_J, size_mm=SMALL_MM,
                decimal=get_notation(nt).decimal, labels_side="above", skip_zero_label=True, name=f"{prefix}axis-J")
    spacing = s_phi.to_mm(period / m)
    ax_phi = DownAxis(origin, s_phi, "y", min_value=0.0, max_value=period, ticks=tuple(phi_k - phi_k[0]),
                      tick_labels=position_labels(m, spacing), label=nt.sym("phi"), size_mm=SMALL_MM,
                      name=f"{prefix}axis-phi")
    pts = tuple(zip((ox + s_J.to_mm(J - J_from)).tolist(), (oy + s_phi.to_mm(phi - phi_k[0])).tolist()))
    curve = Polyline(pts, style=MAIN, name=f"{prefix}curve-J_e")
    breaks = [axis_break((ox + 5.0, oy), f"{prefix}axis-J-break")] if J_from > 0.0 else []
    occ.register(curve, *breaks)
    occ.add_line((ax_J.start, ax_J.tip))
    occ.add_line((ax_phi.start, ax_phi.tip))
    ax_J, ax_phi = clear_tick_labels(ax_J, occ), clear_tick_labels(ax_phi, occ)
    occ.register(ax_J, ax_phi)
    dots = []
    for k in range(m):
        p = (ox + s_J.to_mm(float(J_k[k]) - J_from), oy + s_phi.to_mm(float(phi_k[k] - phi_k[0])))
        dots.append(Point(p, radius_mm=0.6, name=f"{prefix}dot-{k}"))
        occ.add_box((p[0] - 0.7, p[1] - 0.7, p[0] + 0.7, p[1] + 0.7))
    name_lab = occ.place_label(pts[len(pts) // 4], nt.sym("dynamics.J_e"), ("e", "ne", "se", "w"),
                               size_mm=TEXT_MM + 0.4,
                               gap_mm=2.0, within=within)
    label = Text((name_lab.x, name_lab.y), nt.sym("dynamics.J_e"), size_mm=TEXT_MM + 0.4, anchor=name_lab.anchor,
                 name=f"{prefix}name-J_e")
    return [ax_J, *breaks, ax_phi, curve] + dots + [label]


def _turned_inertia_scene(study, *, nt, phi, J, J_k, phi_k, mu_J, mu_phi, page, title, title_block, name):
    from graphmethods.scene import Page

    J_sym = nt.sym("dynamics.J_e")
    sheet = SheetFrame(nt=nt, page=page, title=title or f"{nt.word('dynamics.inertia_turned')}: {J_sym}(φ)",
                       problem=problem_text(study, nt), title_block=title_block,
                       default_page=Page("A4", "portrait", frame=True))
    x0, y0, x1, y1 = sheet.box
    ox, oy = x0 + 16.0, sheet.top + 16.0
    J_to = float(max(J.max(), J_k.max()))
    label_w = markup.text_width_mm(nt.quantity(J_sym, "kg·m²"), SMALL_MM + 0.5)
    s_J = given_scale(mu_J, nt.sym("dynamics.mu_J"), nt.unit("kg·m²"), J_to, x1 - ox - 12.0 - label_w,
                      what="the J_e axis")
    s_phi = given_angle_scale(mu_phi, nt.sym("mu_phi"), TWO_PI, sheet.caption_y - 22.0 - oy)
    els = turned_inertia_elements(origin=(ox, oy), s_J=s_J, s_phi=s_phi, m=study.m, phi=phi, J=J, phi_k=phi_k,
                                  J_k=J_k, nt=nt, occ=sheet.occ, J_to=J_to, prefix="", within=sheet.box)
    scales = (s_J, s_phi)
    elements = [sheet.header()] + els + sheet.captions(scales)
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 notes=(s_J.note, s_phi.note))


# ----------------------------------------------------------------------------- 2. M_d and M_r(φ)

def moment_curves(study) -> tuple[np.ndarray, np.ndarray, float]:
    """M_r as drawn (its ordinates at the positions and the switching positions, the smooth curve
    between them: :attr:`~graphmethods.dynamics.study.Study.moments`), its knots (rad) and the balancing M_d, N·m."""
    M_d, M_r = study.moments
    return np.asarray(M_r.M, dtype=float), np.asarray(M_r.phi, dtype=float), float(M_d.mean())


@dataclass(frozen=True)
class DrawnMoments:
    """The reduced moments as a graph draws them: one curve through the positions (straight chords)
    and one constant from the work balance. For a working machine the curve is M_r and the constant
    M_d; for an engine (:attr:`graphmethods.dynamics.study.Study.is_engine`) the curve is the driving
    moment M_d of the indicator diagram (negative on the compression stroke) and the constant the
    resistance M_r."""

    curves: tuple
    dots: tuple
    lo: float
    hi: float
    constant_key: str
    constant: float


def drawn_moments(study, nt) -> DrawnMoments:
    """:class:`DrawnMoments` of a study in the notation ``nt`` (its curve names)."""
    M_r, phi_k, M_d = moment_curves(study)
    ends = np.array([0.0, TWO_PI])
    sign = -1.0 if study.is_engine else 1.0
    curve, cv = sign * M_r, sign * M_d
    ck, key = ("M_r", "M_d") if study.is_engine else ("M_d", "M_r")
    curves = (CurveSpec(key, phi_k, curve, MAIN, nt.sym(key)),
              CurveSpec(ck, ends, np.array([cv, cv]), MAIN, nt.sym(ck)))
    dots = (np.asarray(study.phi, dtype=float), sign * np.asarray(study.M_r, dtype=float))   # the ordinates
    return DrawnMoments(curves, dots, float(min(curve.min(), cv, 0.0)), float(max(curve.max(), cv)), ck, float(cv))


def moment_graph(study, *, mu_M=None, mu_phi=None, notation="en", page=None, title=None, title_block: bool = True,
                 name: str = "moment-graph") -> Scene:
    """The reduced moments M_d and M_r against φ, as the graphical method draws them.

    M_r is drawn through its values at positions 0…m (straight chords, as by hand);
    M_d is the constant that balances its work over the turn. Their difference is
    M_e = M_d − M_r; the areas between them are the excess works whose running sum is ΔT.

    Examples
    --------
    >>> import pathlib
    >>> from graphmethods.kinematics import read_case
    >>> press = read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json")
    >>> s = moment_graph(press, mu_M=5.0)
    >>> round(s.element("axis-phi").origin[1] - s.element("curve-M_d").points[0][1], 6)   # 143.4 N·m at 5 N·m/mm
    28.685531
    """
    study = as_study(study)
    nt = get_notation(notation)
    dm = drawn_moments(study, nt)
    legend = f"{nt.sym(dm.constant_key)} = {value_text(nt, dm.constant, 'N·m')} ({nt.word('dynamics.work_balance')})"
    ttl = f"{nt.word('dynamics.moment_graph')} {nt.sym('M_d')}, {nt.sym('M_r')}"
    return phi_graph(study, nt=nt, title=title or ttl,
                        page=page, title_block=title_block, name=name, curves=list(dm.curves), y_lo=dm.lo,
                        y_hi=dm.hi, y_symbol=nt.sym("M"), y_unit="N·m",
                        scale_symbol=nt.sym("mu_M"), mu_Y=mu_M, mu_phi=mu_phi, what="the moment graph",
                        dots=dm.dots, legend=legend, zero=True)


# ----------------------------------------------------------------------------- 3. ΔT(φ) or T(φ)

def delta_T_curve(study, phi: np.ndarray) -> np.ndarray:
    """ΔT at the angles ``phi`` (rad from position 0): the integral of the drawn M_d − M_r, J."""
    M_d, M_r = study.moments
    return np.asarray((M_d - M_r).integral(phi), dtype=float)


def _extremes(phi, values):
    i, j = int(np.argmax(values)), int(np.argmin(values))
    return (float(phi[i]), float(values[i])), (float(phi[j]), float(values[j]))


def delta_T_graph(study, *, mu_T=None, mu_phi=None, kinetic: bool = False, notation="en", page=None, title=None,
                  title_block: bool = True, name: str = "delta-T-graph") -> Scene:
    """ΔT(φ), the increment of kinetic energy from position 0; or the kinetic energy T(φ) of the exact motion.

    ΔT is the integral of the drawn moments (M_d − M_r through the positions), exact for
    them; its values at the positions are the ordinates of the energy–mass diagram. With
    ``kinetic=True`` the curve is T(φ) of the exact steady motion with the exact flywheel
    (this solves the exact motion).

    Examples
    --------
    >>> import pathlib
    >>> from graphmethods.kinematics import read_case
    >>> from graphmethods.dynamics.study import Study
    >>> st = Study(read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json"))
    >>> s = delta_T_graph(st, notation="zh")
    >>> s.element("axis-Y").label, "exact" in st.computed
    ('ΔE/J', False)
    """
    study = as_study(study)
    nt = get_notation(notation)
    phi = fine_angles(study.m)
    if kinetic:
        mo = study.exact.motion
        phi, Y = np.asarray(mo.phi, dtype=float) - float(mo.phi[0]), np.asarray(mo.T, dtype=float)
        key, kmax, kmin, dots = "T", "T_max", "T_min", None
        ttl = f"{nt.word('dynamics.kinetic_graph')} {nt.sym('T')}(φ)"
        legend = f"{nt.sym('dynamics.J_F')} = {value_text(nt, study.exact.J_F, 'kg·m²')} ({nt.word('dynamics.exact')})"
    else:
        Y = delta_T_curve(study, phi)
        key, kmax, kmin = "dT", "dT_max", "dT_min"
        dots = (np.asarray(study.phi, dtype=float), np.asarray(study.delta_T, dtype=float))
        ttl = f"{nt.word('dynamics.delta_T_graph')} {nt.sym('dynamics.dT')}(φ)"
        legend = ""
    family = "" if kinetic else "dynamics."  # T, T_max of the notation; ΔT, ΔT_max of the dynamics figures
    (p1, v1), (p2, v2) = _extremes(phi, Y)
    marks = [MarkSpec(kmax, p1, v1, f"{nt.sym(family + kmax)} = {value_text(nt, v1, 'J')}, φ = "
                                    f"{get_notation(nt).number(math.degrees(p1), sig=4)}°", True),
             MarkSpec(kmin, p2, v2, f"{nt.sym(family + kmin)} = {value_text(nt, v2, 'J')}, φ = "
                                    f"{get_notation(nt).number(math.degrees(p2), sig=4)}°", False)]
    return phi_graph(study, nt=nt, title=title or ttl, page=page, title_block=title_block, name=name,
                        curves=[CurveSpec(key, phi, Y, MAIN, "")], y_lo=float(Y.min()), y_hi=float(Y.max()),
                        y_symbol=nt.sym(family + key), y_unit="J", scale_symbol=nt.sym("mu_T"), mu_Y=mu_T,
                        mu_phi=mu_phi,
                        what="the energy graph", dots=dots, marks=marks, legend=legend,
                        zero=None if kinetic else True)


__all__ = [
    "inertia_graph", "moment_graph", "delta_T_graph",
    "phi_graph_elements", "turned_inertia_elements", "axis_break", "DownAxis", "FastOccupancy", "SheetFrame",
    "CurveSpec",
    "MarkSpec", "value_text", "phi_graph",
]
