"""The kinetic-energy graph T(φ) of a cycle problem, from the excess work and a given starting level (split
out of :mod:`graphmethods.sheets.energy`, whose common parts it uses; ``sheets.energy_graph`` is this function)."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import markup, notation as get_notation, pi_ticks
from graphmethods.scene.elements import Axis, Dimension, Element, Frame, Group, Line, Point, Polyline, Text, label_bbox
from graphmethods.scene.notation import Notation
from graphmethods.scene.page import Page
from graphmethods.scene.primitives import DASHED, MAIN, THIN, Label
from graphmethods.scene.scale import Scale
from graphmethods.scene.scene import Scene
from graphmethods.scene.ticks import axis_ticks
from graphmethods.sheets.energy import SMALL_MM, _clear_ticks, _cycle
from graphmethods.sheets.layout import TEXT_MM, Box, Occupancy, Sheet, angle_deg_text, given_angle_scale, given_scale

# ----------------------------------------------------------------------------- 4. energy graph

@dataclass(frozen=True)
class EnergyGraphLayout:
    """The millimetre constants of :func:`energy_graph` (A4 landscape: one curve over the period)."""

    left_mm: float = 18.0           # the E axis's tick labels
    top_mm: float = 14.0            # below the title
    bottom_mm: float = 16.0         # above the scale captions
    arrow_mm: float = 6.0           # the φ axis beyond the period …
    name_gap_mm: float = 1.5        # … its name after the arrow …
    dim_gap_mm: float = 5.0         # … then the ΔW_max dimension
    text_gap_mm: float = 3.0        # the dimension's text right of it
    phi_tick_gap_mm: float = 14.0   # at least between the φ values (multiples of π)
    E_tick_gap_mm: float = 8.0      # at least between the E values
    above_mm: float = 10.0          # labels may stand this far above the plot
    values_above_mm: float = 9.0    # room for the φ values when they are written above the axis


ENERGY_GRAPH_LAYOUT = EnergyGraphLayout()


def _kinetic_base(ew: Any, T0: float | None, J_e: float | None, omega_0: float | None,
                  work_unit: str) -> float | None:
    """T0 (given, or ½ J_e ω₀²), checked positive; None for the ΔE graph."""
    if ew.M_d is None or ew.phi is None:
        raise InputError("energy_graph draws ΔE against φ and needs the moment curves; this cycle was given as "
                         "areas, works or levels, which fix no angles. Draw energy_indicator instead")
    if T0 is None and (J_e is not None or omega_0 is not None):
        if J_e is None or omega_0 is None:
            raise InputError("give T0 (J), or both J_e (kg·m²) and omega_0 (rad/s), for the kinetic-energy graph")
        T0 = 0.5 * float(J_e) * float(omega_0) ** 2
    if T0 is not None and not (math.isfinite(T0) and T0 > 0):
        raise InputError(f"T0 = {T0!r} must be a positive kinetic energy in {work_unit}")
    return T0


@dataclass(frozen=True)
class _EnergyGraph:
    """The scales, frame and plot edges of an energy graph, and the curve it draws."""

    s_phi: Scale
    s_E: Scale
    frame: Frame
    phi0: float
    period: float
    base: float
    kinetic: bool
    lo: float
    hi: float
    phi: np.ndarray
    Y: np.ndarray
    right: float
    px0: float
    py0: float
    y1: float
    x1: float

    def P(self, ph: float, v: float) -> tuple[float, float]:
        return self.frame.pt(float(ph) - self.phi0, float(v))

    @property
    def box(self) -> Box:
        """The box labels stay in."""
        return (self.px0 + 1, self.py0 - ENERGY_GRAPH_LAYOUT.above_mm, self.x1, self.y1)


def _energy_graph(ew: Any, sheet: Sheet, nt: Notation, *, T0: float | None, mu_E: Any, mu_phi: Any, samples: int,
                  dim_text: str, work_unit: str) -> _EnergyGraph:
    """The exact curve, then μ_φ and μ_E fitted to the plot (or checked when given) and its frame."""
    L = ENERGY_GRAPH_LAYOUT
    kinetic = T0 is not None
    base = float(T0) if T0 is not None else 0.0
    phi, dE = ew.energy_curve(samples)
    Y = dE + base
    if kinetic and (Y <= 0).any():
        raise InputError(f"T0 = {T0:g} {work_unit} is too small: T = T0 + ΔE falls to {Y.min():.4g}; the machine "
                         f"would stop. Give a larger T0 or omega_0")
    lo = 0.0 if kinetic else float(min(Y.min(), 0.0))
    hi = float(max(Y.max(), 0.0))
    x0, _, x1, y1 = sheet.box
    phi_name = nt.quantity(nt.sym("phi"), "rad")
    right = L.arrow_mm + L.name_gap_mm + markup.text_width_mm(phi_name, SMALL_MM + 0.5) + L.dim_gap_mm
    px0, px1 = x0 + L.left_mm, x1 - right - L.text_gap_mm - markup.text_width_mm(dim_text, TEXT_MM + 0.3)
    py0, py1 = sheet.top + L.top_mm, sheet.caption_y - L.bottom_mm
    period = float(ew.period)
    s_phi = given_angle_scale(mu_phi, nt.sym("mu_phi"), period, px1 - px0)
    s_E = given_scale(mu_E, nt.sym("mu_T") if kinetic else nt.sym("mu_E"), work_unit, hi - lo, py1 - py0,
                      what="the energy graph")
    frame = Frame((px0, py0 + s_E.to_mm(hi)), s_phi, s_E)
    return _EnergyGraph(s_phi, s_E, frame, float(ew.phi[0]), period, base, kinetic, lo, hi, phi, Y, right, px0, py0,
                        y1, x1)


def _energy_axes(g: _EnergyGraph, nt: Notation, occ: Occupancy, sym: str,
                 work_unit: str) -> tuple[Axis, Axis, Polyline]:
    """The φ axis (values above it when the curve lies mostly below), the E axis and the curve."""
    L, origin, lo, hi = ENERGY_GRAPH_LAYOUT, g.frame.origin, g.lo, g.hi
    ticks_phi, labels_phi = pi_ticks(g.period, g.s_phi, min_gap_mm=L.phi_tick_gap_mm)
    ax_phi = Axis(origin, g.s_phi, "x", min_value=0.0, max_value=g.period, ticks=ticks_phi, tick_labels=labels_phi,
                  label=nt.quantity(nt.sym("phi"), "rad"), size_mm=SMALL_MM, name="axis-phi", skip_zero_label=lo < 0,
                  labels_side="above" if -lo > hi else "below")
    room = g.s_E.to_value(L.values_above_mm) if -lo > hi else g.s_E.per_mm   # tick labels above the φ axis
    ax_E = Axis(origin, g.s_E, "y", min_value=lo if lo < 0 else 0.0, max_value=max(hi, room),
                ticks=axis_ticks(lo, hi, g.s_E, min_gap_mm=L.E_tick_gap_mm), label=nt.quantity(sym, work_unit),
                size_mm=SMALL_MM, decimal=nt.decimal, name="axis-E")
    curve = Polyline(g.frame.pts(g.phi - g.phi0, g.Y), style=MAIN, name="curve-E")
    ax_phi, ax_E = _clear_ticks(ax_phi, curve), _clear_ticks(ax_E, curve)
    occ.register(ax_phi, ax_E, curve)
    return ax_phi, ax_E, curve


def _projection_end(at: tuple[float, float], axis_y: float, ax_phi: Axis) -> tuple[float, float]:
    """Where an extreme's projection onto the φ axis stops: at the axis, or short of the tick label it would
    cross (the line stops at the text, as a draftsman draws it, when the extreme lies on the labels' side)."""
    end = axis_y
    for lab in (p for p in replace(ax_phi, label="").primitives() if isinstance(p, Label)):
        x0, y0, x1, y1 = label_bbox(lab)
        if x0 - 0.3 <= at[0] <= x1 + 0.3 and min(at[1], axis_y) <= (y0 + y1) / 2 <= max(at[1], axis_y):
            end = y1 + 0.5 if at[1] > axis_y else y0 - 0.5
    return (at[0], end)


def _energy_extremes(g: _EnergyGraph, ew: Any, occ: Occupancy, dim_text: str, ax_phi: Axis
                     ) -> tuple[dict[str, tuple[float, float]], list[Line], Dimension, list[Element]]:
    """The extremes: their points, projections to the φ axis, levels to ΔW_max's dimension, open marks."""
    imax, imin = ew.index_E_max, ew.index_E_min
    k_max, k_min = ("T_max", "T_min") if g.kinetic else ("E_max", "E_min")
    ext_pts = {k_max: (float(ew.phi[imax]), float(ew.E[imax]) + g.base),
               k_min: (float(ew.phi[imin]), float(ew.E[imin]) + g.base)}
    x_dim = g.frame.pt(g.period, 0.0)[0] + g.right
    guides = []
    for key, (ph, v) in ext_pts.items():
        at = g.P(ph, v)
        guides.append(Line(at, _projection_end(at, g.frame.origin[1], ax_phi), style=DASHED,
                           name=f"projection-{key}"))
        guides.append(Line(at, (x_dim + 2.0, at[1]), style=DASHED, name=f"level-{key}"))
    dim = Dimension((x_dim, g.P(*ext_pts[k_min])[1]), (x_dim, g.P(*ext_pts[k_max])[1]), dim_text,
                    size_mm=TEXT_MM + 0.3, name="dimension-delta-W-max")
    occ.register(*guides, dim)
    marks: list[Element] = []
    for key, (ph, v) in ext_pts.items():
        at = g.P(ph, v)
        marks.append(Point(at, radius_mm=1.1, filled=False, name=f"mark-{key}"))
        occ.add_box((at[0] - 1.3, at[1] - 1.3, at[0] + 1.3, at[1] + 1.3))
    return ext_pts, guides, dim, marks


def _energy_labels(g: _EnergyGraph, ew: Any, nt: Notation, occ: Occupancy, ext_pts: dict[str, tuple[float, float]],
                   work_unit: str) -> tuple[list[Group], list[Element], list[Text]]:
    """The points a, b, … on the curve; the extremes' values and angles (a leader when far); T_0."""
    points = []
    for k, ph in enumerate(ew.phi):
        at = g.P(ph, float(ew.E[k]) + g.base)
        lab = occ.place_label(at, ew.labels[k], ("nw", "ne", "sw", "se", "n", "s", "w", "e"), size_mm=TEXT_MM + 0.3,
                              gap_mm=1.0, within=g.box)
        points.append(Group((Point(at, radius_mm=0.6, name=f"dot-{ew.labels[k]}"),
                             Text((lab.x, lab.y), ew.labels[k], size_mm=TEXT_MM + 0.3, anchor=lab.anchor,
                                  name=f"name-{ew.labels[k]}")), name=f"point-{ew.labels[k]}"))
    marks: list[Element] = []
    for key, (ph, v) in ext_pts.items():
        at = g.P(ph, v)
        text = (f"{nt.sym(key)} = {nt.number(v)} {nt.unit(work_unit)}, "
                f"{nt.sym('phi')} = {angle_deg_text(ph - g.phi0, nt)}")
        dirs = ("ne", "nw", "n", "e", "w") if key.endswith("max") else ("se", "sw", "s", "e", "w")
        lab, leader = occ.place_label_with_leader(at, text, dirs, size_mm=TEXT_MM, gap_mm=2.0, within=g.box)
        marks.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name=f"label-{key}"))
        if leader is not None:
            marks.append(Line(leader[0], leader[1], style=THIN, name=f"leader-{key}"))
    extra = []
    if g.kinetic:
        at = g.P(g.phi0, g.base)
        text = f"{nt.sym('T_0')} = {nt.number(g.base)} {nt.unit(work_unit)}"
        lab = occ.place_label(at, text, ("ne", "se", "e", "n"), size_mm=TEXT_MM, gap_mm=2.5)
        extra.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name="label-T0"))
    return points, marks, extra


def energy_graph(cycle: Any, *, mu_E: Any = None, mu_phi: Any = None, T0: float | None = None,
                 J_e: float | None = None, omega_0: float | None = None, notation: Any = "en",
                 page: Page | None = None, title: str | None = None, problem: Any = None, work_unit: str = "J",
                 samples: int = 721, title_block: bool = True, name: str = "energy-graph") -> Scene:
    """The energy graph ΔE(φ) (Chinese style), or T(φ) = T0 + ΔE(φ) from a given T0 (Russian style).

    The curve is exact (ΔE is piecewise quadratic between the knots). The boundary
    points a, b, … are marked on it, the positions of E_max and E_min are marked and
    projected onto the φ axis, and ΔW_max is dimensioned. Give ``T0`` (J), or
    ``J_e`` (kg·m²) with ``omega_0`` (rad/s), for the kinetic-energy graph T(φ) drawn
    from T = 0. Steps: the scales (:func:`_energy_graph`, laid out by
    :data:`ENERGY_GRAPH_LAYOUT`), the axes and curve, the extremes, the labels.

    Raises
    ------
    InputError
        If the cycle has no moment curves (then there is no φ to draw against).

    Examples
    --------
    >>> from math import pi
    >>> from graphmethods.dynamics import excess_work as ew
    >>> from graphmethods.dynamics.moments import MomentCurve
    >>> w4 = ew.from_moments(MomentCurve.constant(20.0), MomentCurve.points([0, pi, 2 * pi], [0, 40, 0]))
    >>> s = energy_graph(w4, J_e=0.8, omega_0=10.0, notation="ru", work_unit="kG·m")
    >>> s.element("axis-E").label, s.element("label-T_max").text
    ('T, кГ·м', 'T_{max} = 55,71 кГ·м, φ = 90°')
    """
    nt = get_notation(notation)
    ew, prob = _cycle(cycle, nt)
    T0 = _kinetic_base(ew, T0, J_e, omega_0, work_unit)
    sym = nt.sym("T") if T0 is not None else nt.sym("dE")
    word = nt.word("kinetic_energy_graph") if T0 is not None else nt.word("energy_graph")
    sheet = Sheet(nt=nt, page=page, title=title or f"{word} {sym}(φ)", problem=prob if problem is None else problem,
                  title_block=title_block)
    dim_text = f"{nt.sym('delta_W_max')} = {nt.number(ew.delta_W_max)} {nt.unit(work_unit)}"
    g = _energy_graph(ew, sheet, nt, T0=T0, mu_E=mu_E, mu_phi=mu_phi, samples=samples, dim_text=dim_text,
                      work_unit=work_unit)
    occ = sheet.occ
    ax_phi, ax_E, curve = _energy_axes(g, nt, occ, sym, work_unit)
    ext_pts, guides, dim, marks = _energy_extremes(g, ew, occ, dim_text, ax_phi)
    points, labels, extra = _energy_labels(g, ew, nt, occ, ext_pts, work_unit)
    scales = (g.s_phi, g.s_E)
    elements = ([sheet.header(), ax_phi, ax_E] + guides + [curve, dim] + points + marks + labels + extra
                + sheet.captions(scales))
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 notes=(g.s_phi.note, g.s_E.note))
