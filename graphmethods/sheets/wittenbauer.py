"""The energy–mass (Wittenbauer) diagram: the compact A4 figure and the A1/A2 dynamic-analysis sheet.

:func:`wittenbauer_diagram` draws the diagram alone: the curve through the points
(J_e(φ_k)/μ_J, ΔT(φ_k)/μ_T) of positions 0…m, each numbered; the upper ray at ψ_max that
supports it from above and the lower ray at ψ_min from below, each drawn from the edge
of the frame (their meeting point O1 is far off the sheet) to just past the curve, with
ψ_max and ψ_min marked; the intercepts k and l on the ordinate axis and the segment kl
dimensioned; and a table of the result, J_F = μ_T·kl/(ω_m²[δ]).

:func:`dynamic_analysis_sheet` is the A1 (or A2) sheet of a course project: the M_d, M_r(φ)
graph, the ΔT(φ) graph whose levels are projected horizontally onto the diagram, the
J_e(φ) graph turned 90° whose values are projected vertically onto it, the diagram with
its rays, k, l and kl, and the result table. The diagram's μ_J is picked for the diagram (its
J axis 0…J_e max over the width beside the graphs; the turned graph follows it so the
projections meet), and its rays are clipped to its own frame, from the ordinate axis to the
curve, so they never run across the other graphs; O1, almost always far off, is given in the
table. It computes only what it draws: positions,
velocity plans, J_e, M_r and ΔT at the m positions; never the exact motion.

The construction itself (support lines, tangencies, the error estimate) is
:func:`graphmethods.dynamics.wittenbauer.wittenbauer`; this module only draws it.

>>> import pathlib
>>> from graphmethods.dynamics.study import Study
>>> from graphmethods.kinematics import read_case
>>> press = read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json")
>>> study = Study(press, positions=12)
>>> scene = wittenbauer_diagram(study)
>>> [s.caption() for s in scene.scales()], "exact" in study.computed
(['μ_T = 5 J/mm', 'μ_J = 0.002 kg·m²/mm'], False)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import partial

import numpy as np

from graphmethods.dynamics.wittenbauer import WittenbauerResult, wittenbauer
from graphmethods.errors import InputError
from graphmethods.scene import markup, notation as get_notation
from graphmethods.scene.elements import Axis, Dimension, Element, Line, Point, Polyline, Table, Text, label_bbox
from graphmethods.scene.notation import Notation
from graphmethods.scene.numbers import format_scale
from graphmethods.scene.page import Page
from graphmethods.scene.primitives import MAIN, THIN, Label, Style
from graphmethods.scene.scale import Scale
from graphmethods.scene.scene import Scene
from graphmethods.scene.ticks import axis_ticks
from graphmethods.sheets.dynamics import (
    J_TICK_GAP_MM,
    SMALL_MM,
    TEXT_MM,
    as_study,
    axis_break,
    given_scale,
    inertia_ticks,
    problem_text,
    value_text,
)
from graphmethods.sheets.engine.lettering import is_slide
from graphmethods.sheets.frame import FastOccupancy, SheetFrame
from graphmethods.sheets.layout import Box, clear_tick_labels
from graphmethods.sheets.linkage_figures import broken_behind
from graphmethods.sheets.tick_values import every_value as every_tick_written, over_rays, tick_label_band

RAY = Style(width_mm=0.35)
LEADER = Style(width_mm=0.13)
TABLE_MM = 3.0

def bold_bbox(lab):
    """The box a bold label covers: bold glyphs run about 10 % wider than the estimate for regular ones."""
    x0, y0, x1, y1 = label_bbox(lab)
    return (x0, y0, x1 + 0.1 * (x1 - x0), y1)


# ----------------------------------------------------------------------------- data

@dataclass(frozen=True)
class DiagramData:
    """What the diagram needs, in SI: J_e and ΔT at positions 0…m, their angles, ω_m and [δ]."""

    J_e: np.ndarray
    delta_T: np.ndarray
    phi: np.ndarray
    omega_m: float
    delta: float
    tangents: str
    problem: str = ""
    estimate: WittenbauerResult | None = None   # a Study's result, whose error estimate comes from a finer study

    def result(self, mu_J: float, mu_T: float) -> WittenbauerResult:
        """The construction at these scales (J_F does not depend on them)."""
        res = wittenbauer(J_e=self.J_e, delta_T=self.delta_T, omega_m=self.omega_m, delta=self.delta,
                          mu_J=mu_J, mu_T=mu_T, phi=self.phi, tangents=self.tangents)
        if self.estimate is not None:
            res = replace(res, error_estimate=self.estimate.error_estimate, error_method=self.estimate.error_method)
        return res

    def extent(self, J_0: float = 0.0) -> tuple[float, float, float]:
        """(J_to, T_hi, T_lo): the abscissa's reach (kg·m²) and the ordinate's range (J), k and l included
        where the ordinate axis stands (J_e = ``J_0``, kg·m²): an axis runs to its data, not further."""
        unit_res = self.result(1.0, 1.0)
        if J_0 > 0.0:
            unit_res = offset_origin(unit_res, J_0)
        T_hi = max(float(self.delta_T.max()), unit_res.k_mm, unit_res.l_mm, 0.0)
        T_lo = min(float(self.delta_T.min()), unit_res.k_mm, unit_res.l_mm, 0.0)
        return float(self.J_e.max()), T_hi, T_lo


def diagram_data(source, *, tangents: str = "exact", notation="en") -> DiagramData:
    """DiagramData from a Study (or a problem Case), or from a WittenbauerResult (its data and tangents).

    Parameters
    ----------
    source : Study, Case or WittenbauerResult
        What to draw.
    tangents : str
        ``"exact"`` or ``"textbook"`` forms of tan ψ (a Study's source only).
    notation : str or Notation
        The language of the problem's name (:attr:`DiagramData.problem`).
    """
    if isinstance(source, WittenbauerResult):
        return DiagramData(np.asarray(source.x_mm) * source.mu_J, np.asarray(source.y_mm) * source.mu_T,
                           np.asarray(source.phi), source.omega_m, source.delta, source.tangents)
    study = as_study(source)
    return DiagramData(np.asarray(study.J_e, dtype=float), np.asarray(study.delta_T, dtype=float),
                       np.asarray(study.phi, dtype=float), float(study.omega_m), float(study.delta), tangents,
                       problem_text(study, notation), estimate=study.wittenbauer if tangents == "exact" else None)


# ----------------------------------------------------------------------------- geometry on paper

def ray_span(*, intercept_mm: float, tan: float, origin, clip, avoid=(), O1_x: float, x_from: float,
             x_to: float, y_top: float | None = None) -> tuple[float, float]:
    """The X range (mm from the ordinate axis) of a ray Y = intercept + tan·X drawn on the sheet.

    It starts at O1 when O1 is inside ``clip`` (a page box), else where it enters ``clip``,
    and ends at ``x_to`` (or where it reaches the level ``y_top``, mm above the abscissa),
    but never before ``x_from`` (its last point of tangency). A part inside an ``avoid`` box
    (the title block) is cut off on the O1 side.
    """
    ox, oy = origin

    def x_range(box):
        bx0, by0, bx1, by1 = box
        a, b = bx0 - ox, bx1 - ox                              # X within the box's columns
        ylo, yhi = oy - by1, oy - by0                          # Y within its rows
        if tan > 0:
            a, b = max(a, (ylo - intercept_mm) / tan), min(b, (yhi - intercept_mm) / tan)
        elif not (ylo <= intercept_mm <= yhi):
            return None
        return (a, b) if a <= b else None

    inside = x_range(clip)
    if inside is None:
        raise InputError("a tangent ray misses the sheet entirely; the diagram's scales do not suit this page")
    lo, hi = max(inside[0], O1_x), inside[1]
    end = x_to
    if y_top is not None and tan > 0:
        end = min(end, (y_top - intercept_mm) / tan)
    hi = max(min(hi, end), x_from)
    for box in avoid:
        r = x_range(box)
        if r is not None and r[0] < hi and r[1] > lo:
            if r[1] <= x_from:
                lo = max(lo, r[1])
            else:
                hi = min(hi, max(r[0], x_from))
    return lo, hi


def offset_origin(res: WittenbauerResult, J_0: float) -> WittenbauerResult:
    """The construction with its ordinate axis at J_e = J_0 (kg·m²) instead of 0: a suppressed zero.

    The points move J_0/μ_J mm to the left; the rays keep their slopes (tan ψ of the true J_e);
    k, l and kl become the intercepts on the new ordinate axis, kl growing by δ·ω_m²·J_0/μ_T (the
    slopes on paper differ by δω_m²μ_J/μ_T for either form of the tangents), so that
    J_F = μ_T·kl/(ω_m²[δ]) − J_0. O1 moves with the points; J_F and every angle stay.

    >>> import numpy as np
    >>> from graphmethods.dynamics.wittenbauer import wittenbauer
    >>> phi = np.linspace(0, 2 * np.pi, 13)
    >>> res = wittenbauer(J_e=2 + 0.4 * np.cos(phi + 0.7), delta_T=300 * np.sin(phi), omega_m=20.0, delta=0.05,
    ...                   mu_J=0.01, mu_T=5.0)
    >>> moved = offset_origin(res, 1.5)
    >>> float(round(moved.x_mm.min() - res.x_mm.min(), 9)), moved.tan_psi_max == res.tan_psi_max
    (-150.0, True)
    >>> round(moved.mu_T * moved.kl_mm / (moved.omega_m**2 * moved.delta) - 1.5 - res.J_F, 9)
    0.0
    """
    dx = J_0 / res.mu_J
    return replace(res, x_mm=np.asarray(res.x_mm) - dx, k_mm=res.k_mm + res.tan_psi_max * dx,
                   l_mm=res.l_mm + res.tan_psi_min * dx,
                   kl_mm=res.kl_mm + res.omega_m**2 * res.delta * J_0 / res.mu_T,
                   O1_mm=(res.O1_mm[0] - dx, res.O1_mm[1]))


def _arc(centre, radius: float, a0: float, a1: float, n: int = 24) -> tuple:
    """Points of a circular arc on paper from angle a0 to a1 (rad, counterclockwise as seen)."""
    t = np.linspace(a0, a1, n)
    return tuple(zip((centre[0] + radius * np.cos(t)).tolist(), (centre[1] - radius * np.sin(t)).tolist()))


def _compass(dx: float, dy_up: float) -> tuple[str, ...]:
    """Label directions pointing away from a centre, best first."""
    ang = math.degrees(math.atan2(dy_up, dx)) % 360
    names = ("e", "ne", "n", "nw", "w", "sw", "s", "se")
    i = round(ang / 45.0) % 8
    return tuple(names[(i + d) % 8] for d in (0, 1, -1, 2, -2, 3, -3, 4))


def diagram_elements(res: WittenbauerResult, *, origin, nt, occ, clip, avoid=(), J_to: float, T_hi: float,
                     T_lo: float, within=None, prefix: str = "", y_top_mm: float | None = None,
                     label_step: int | None = None, register_only=(), own_frame: bool = False,
                     J_from: float = 0.0, every_value: bool = False,
                     page_axes: tuple[Axis, Axis] | None = None) -> list:
    """The energy–mass diagram at ``origin`` (page point of J_e = J_from, ΔT = 0): axes, curve, rays, k, l, kl, ψ.

    Parameters
    ----------
    res : WittenbauerResult
        The construction at the scales to draw (``res.mu_J``, ``res.mu_T``).
    clip : (x0, y0, x1, y1), mm
        The rays are drawn from where they enter this box (the frame) on the O1 side.
    avoid : sequence of boxes
        Boxes the rays must not cross (the title block).
    J_to, T_hi, T_lo : float
        Reach of the abscissa (kg·m²) and range of the ordinate axis (J).
    y_top_mm : float, optional
        The rays stop where they rise this high above the abscissa (room kept above the diagram).
    page_axes : (Axis, Axis), optional
        The ΔT and J_e axes the page draws (a worksheet's grid): used instead of the diagram's own, the
        position numbers kept out of the J_e axis's row of values wherever the page wrote them.
    own_frame : bool
        Clip the rays to the diagram's own frame instead of ``clip``: from the ordinate axis
        (or just as far left of it as the marks of ψ need) to just past the curve, between the
        levels T_lo and T_hi (10 mm margin). O1 is drawn only when it lies in that frame.
    J_from : float
        Where the abscissa starts (kg·m²): 0, or a suppressed zero near J_e,min (marked by a zigzag);
        ``res`` is then the construction with its ordinate axis there (:func:`offset_origin`).
    every_value : bool
        Every tick with its value (a slide): where the curve or a ray would cover values, the values go on the
        other side of the J_e axis, or the ticks are spaced wider, or a J_e value that only a ray covers is
        written and the ray broken behind it, or the covered ticks at an end of the range are left out
        (:func:`graphmethods.sheets.tick_values.every_value`).

    Returns
    -------
    list of Element
        Named ``{prefix}axis-J``, ``{prefix}axis-T``, ``{prefix}curve``, ``{prefix}vertex-k``,
        ``{prefix}ray-max``, ``{prefix}ray-min``, ``{prefix}point-k``, ``{prefix}point-l``,
        ``{prefix}dimension-kl``, ``{prefix}psi-max``, ``{prefix}psi-min``, ``{prefix}tangency-…``,
        ``{prefix}pos-k`` …
    """
    nt = get_notation(nt)
    d = _DiagramPlace.of(res, origin, nt, J_to=J_to, T_hi=T_hi, T_lo=T_lo, J_from=J_from, prefix=prefix)
    if own_frame:        # the diagram's own frame: the rays never run across the rest of the sheet
        clip = d.own_frame()
    curve = Polyline(tuple(d.P(x, y) for x, y in zip(d.X[:-1], d.Y[:-1])), style=MAIN, closed=True,
                     name=f"{prefix}curve")
    rays = _rays(res, d, clip=clip, avoid=avoid, y_top_mm=y_top_mm)
    dim = Dimension(d.l_pt, d.k_pt, "", offset_mm=d.off * d.side * (1.0 if res.kl_mm > 0 else -1.0), size_mm=TEXT_MM,
                    name=f"{prefix}dimension-kl")
    psi_els = _psi_marks(res, d)
    if J_from > 0.0:
        psi_els.append(axis_break((d.origin[0] + 5.0, d.origin[1]), f"{prefix}axis-J-break"))
    occ.register(curve, *rays, dim, *psi_els, *register_only)
    if page_axes is None:
        unrayed = None
        if every_value:                 # what a value may not cross; a thin ray is broken behind it (ГОСТ 2.303)
            unrayed = FastOccupancy()
            unrayed.register(curve, dim, *psi_els, *register_only)
        ax_T, ax_J = _diagram_axes(d, occ, nt, every_value=every_value, unrayed=unrayed)
        if every_value:
            rays = broken_behind(rays, [label_bbox(p) for p in replace(ax_J, label="").primitives()
                                        if isinstance(p, Label)])
    else:                               # the page's own ΔT and J_e axes (a worksheet's): numbers keep off their values
        ax_T, ax_J = page_axes
        occ.register(ax_T, ax_J)
        band = tick_label_band(ax_J)
        if band is not None:
            occ.add_box(band)
    els: list[Element] = [ax_T, ax_J] + psi_els + [curve] + rays + [dim]
    els += _diagram_points(res, d, occ, within)
    els += _psi_labels(res, d, occ, nt, within)
    els += _kl_label(res, d, dim, occ, nt, within)
    els += _position_labels(res, d, occ, nt, within, label_step)
    O1 = d.P(*res.O1_mm)
    if clip[0] <= O1[0] <= clip[2] and clip[1] <= O1[1] <= clip[3]:
        els.append(Point(O1, radius_mm=0.8, name=f"{prefix}point-O1"))
        lab = occ.place_label(O1, "O_1", ("nw", "w", "sw", "n"), size_mm=TEXT_MM + 0.5, within=within)
        els.append(Text((lab.x, lab.y), "O_1", size_mm=TEXT_MM + 0.5, anchor=lab.anchor, name=f"{prefix}name-O1"))
    return els


@dataclass(frozen=True)
class DiagramLayout:
    """The millimetre constants of the energy–mass diagram (:func:`diagram_elements`)."""

    psi_radius_mm: float = 16.0      # the arcs of ψ, when right of the ordinate axis
    psi_room_mm: float = 14.0        # and the room the curve must leave there beyond them
    kl_right_mm: float = 7.0         # the kl dimension right of the axis
    kl_left_mm: float = 4.0          # or left of the axis's tick labels
    frame_mm: float = 10.0           # the diagram's own frame around its content
    ray_past_touch_mm: float = 2.0   # a ray runs at least this far past its last tangency
    ray_past_curve_mm: float = 8.0   # and ends this far past the curve's largest J


DIAGRAM = DiagramLayout()


@dataclass(frozen=True)
class _DiagramPlace:
    """Where a diagram stands: its origin, points (mm from it), the side of k, l, kl and ψ, the axes' scales."""

    origin: tuple[float, float]
    X: np.ndarray
    Y: np.ndarray
    s_J: Scale
    s_T: Scale
    ticks_T: tuple[float, ...]
    ticks_J: tuple[float, ...]
    J_from: float
    J_to: float
    T_lo: float
    T_hi: float
    right: bool          # kl and ψ right of the ordinate axis (inside the wedge of the rays), else left
    R: float             # the radius of the ψ arcs
    off: float           # the kl dimension's distance from the axis
    k_pt: tuple[float, float]
    l_pt: tuple[float, float]
    prefix: str

    @property
    def side(self) -> float:
        return 1.0 if self.right else -1.0

    def P(self, x: float, y: float) -> tuple[float, float]:
        """The page point of (x, y) mm from the origin (y up)."""
        return (self.origin[0] + float(x), self.origin[1] - float(y))

    @classmethod
    def of(cls, res: WittenbauerResult, origin: tuple[float, float], nt: Notation, *, J_to: float, T_hi: float,
           T_lo: float, J_from: float, prefix: str, lay: DiagramLayout = DIAGRAM) -> _DiagramPlace:
        """kl and the angles ψ go right of the ordinate axis when the curve leaves room there, else left
        of it (ψ then marked as the vertical angle, between the rays' lower left parts and the horizontal)."""
        s_J = Scale(nt.sym("dynamics.mu_J"), nt.unit("kg·m²"), res.mu_J)
        s_T = Scale(nt.sym("mu_T"), nt.unit("J"), res.mu_T)
        X, Y = np.asarray(res.x_mm, dtype=float), np.asarray(res.y_mm, dtype=float)
        ticks_T = tuple(t for t in axis_ticks(T_lo, T_hi, s_T, min_gap_mm=8.0) if T_lo <= t <= T_hi)
        ticks_J = inertia_ticks(J_from, J_to, s_J, nt)[0]
        R = lay.psi_radius_mm
        right = float(X[:-1].min()) >= R + lay.psi_room_mm
        tick_w = max((markup.text_width_mm(nt.number(t), SMALL_MM) for t in ticks_T), default=0.0)
        off = lay.kl_right_mm if right else tick_w + 2.3 + lay.kl_left_mm    # left: beyond the tick labels
        R = R if right else off + 10.0
        ox, oy = origin
        return cls((ox, oy), X, Y, s_J, s_T, ticks_T, ticks_J, J_from, J_to, T_lo, T_hi, right, R, off,
                   (ox, oy - float(res.k_mm)), (ox, oy - float(res.l_mm)), prefix)

    def own_frame(self, lay: DiagramLayout = DIAGRAM) -> tuple[float, float, float, float]:
        """The diagram's own frame: from the ordinate axis (or the ψ marks left of it) to past the curve."""
        ox, oy = self.origin
        return (ox if self.right else ox - (self.R + 6.0), oy - self.s_T.to_mm(self.T_hi) - lay.frame_mm,
                ox + max(float(self.X.max()), self.s_J.to_mm(self.J_to - self.J_from)) + lay.frame_mm,
                oy - self.s_T.to_mm(self.T_lo) + lay.frame_mm)


def _diagram_axes(d: _DiagramPlace, occ: FastOccupancy, nt: Notation, *, every_value: bool = False,
                  unrayed: FastOccupancy | None = None) -> tuple[Axis, Axis]:
    """The ΔT and J_e axes through the origin (J_e from ``J_from``), their tick labels kept off what is drawn;
    ``every_value``: no tick left without its value (:func:`diagram_elements`), the J_e values written over a ray
    (``unrayed``: what is drawn but the rays) when nothing else writes them all (the scotch yoke's 0.25)."""
    ox, oy = d.origin
    s_T, s_J, T_lo, T_hi = d.s_T, d.s_J, d.T_lo, d.T_hi

    def axis_T(ticks: tuple[float, ...]) -> Axis:
        return Axis(d.origin, s_T, "y", min_value=T_lo, max_value=max(T_hi, T_lo + s_T.per_mm), ticks=ticks,
                    label=nt.quantity(nt.sym("dynamics.dT"), "J"), size_mm=SMALL_MM, decimal=nt.decimal,
                    skip_zero_label=True, name=f"{d.prefix}axis-T")

    below = float(np.mean(d.Y[:-1] < 0)) > 0.5

    def axis_J(k: float) -> Axis:
        ticks, labels_J, name_J = inertia_ticks(d.J_from, d.J_to, s_J, nt, min_gap_mm=J_TICK_GAP_MM * k)
        return Axis((ox - s_J.to_mm(d.J_from), oy), s_J, "x", min_value=d.J_from, max_value=d.J_to,
                    ticks=d.ticks_J if k == 1 else ticks, tick_labels=labels_J, label=name_J, size_mm=SMALL_MM,
                    decimal=nt.decimal, labels_side="above" if below else "below", skip_zero_label=True,
                    name=f"{d.prefix}axis-J")

    ax_T, ax_J = axis_T(d.ticks_T), axis_J(1)
    occ.add_line((ax_T.start, ax_T.tip))
    occ.add_line((ax_J.start, ax_J.tip))
    ax_T = clear_tick_labels(ax_T, occ, keep_values=True)
    if every_value:
        step = d.ticks_T[1] - d.ticks_T[0] if len(d.ticks_T) > 1 else 1.0       # every k-th tick, 0 among them
        ax_T = every_tick_written(ax_T, lambda k: clear_tick_labels(axis_T(tuple(
            t for t in d.ticks_T if round(t / step) % k == 0)), occ, keep_values=True))
    occ.register(ax_T)
    ax_J = clear_tick_labels(ax_J, occ, keep_values=True, other_side=True)
    if every_value:
        flip = "below" if ax_J.labels_side == "above" else "above"
        ax_J = every_tick_written(ax_J, lambda k: clear_tick_labels(axis_J(k), occ, keep_values=True, other_side=True),
                           other_side=lambda: clear_tick_labels(replace(axis_J(1), labels_side=flip), occ))
        if unrayed is not None:
            ax_J = every_tick_written(ax_J, lambda k: ax_J, other_side=lambda: over_rays(axis_J(1), unrayed, occ))
    occ.register(ax_J)
    band = tick_label_band(ax_J)
    if band is not None:                # a position number there would read as a value ("0 1 2 1.5 2")
        occ.add_box(band)
    return ax_T, ax_J


def _rays(res: WittenbauerResult, d: _DiagramPlace, *, clip: tuple[float, float, float, float],
          avoid: tuple[tuple[float, float, float, float], ...], y_top_mm: float | None,
          lay: DiagramLayout = DIAGRAM) -> list[Element]:
    """The rays at ψ_max through k and at ψ_min through l, from the frame (or O1) to just past the curve."""
    O1x = float(res.O1_mm[0])
    rays: list[Element] = []
    for key, b, tan, idx in (("max", res.k_mm, res.tan_psi_max, res.index_omega_max),
                             ("min", res.l_mm, res.tan_psi_min, res.index_omega_min)):
        lo, hi = ray_span(intercept_mm=b, tan=tan, origin=d.origin, clip=clip, avoid=avoid, O1_x=O1x,
                          x_from=float(d.X[list(idx)].max()) + lay.ray_past_touch_mm,
                          x_to=float(d.X.max()) + lay.ray_past_curve_mm, y_top=y_top_mm)
        rays.append(Line(d.P(lo, b + tan * lo), d.P(hi, b + tan * hi), style=RAY, name=f"{d.prefix}ray-{key}"))
    return rays


def _psi_marks(res: WittenbauerResult, d: _DiagramPlace) -> list[Element]:
    """The horizontal reference and the arc of ψ_max at k and of ψ_min at l."""
    els: list[Element] = []
    for key, pt, psi in (("max", d.k_pt, res.psi_max), ("min", d.l_pt, res.psi_min)):
        els.append(Line(pt, (pt[0] + d.side * (d.R + 4.0), pt[1]), style=THIN, name=f"{d.prefix}psi-{key}-reference"))
        arc = _arc(pt, d.R, 0.0, psi) if d.right else _arc(pt, d.R, math.pi, math.pi + psi)
        els.append(Polyline(arc, style=THIN, name=f"{d.prefix}psi-{key}-arc"))
    return els


def _diagram_points(res: WittenbauerResult, d: _DiagramPlace, occ: FastOccupancy, within: Box | None) -> list[Element]:
    """The vertices, the tangencies (open circles), the points k and l and their names."""
    els: list[Element] = []
    for i in range(res.m):
        p = d.P(d.X[i], d.Y[i])
        els.append(Point(p, radius_mm=0.6, name=f"{d.prefix}vertex-{i}"))
        occ.add_box((p[0] - 0.8, p[1] - 0.8, p[0] + 0.8, p[1] + 0.8))
    for key, idx in (("max", res.index_omega_max), ("min", res.index_omega_min)):
        for i in idx:
            p = d.P(d.X[i], d.Y[i])
            els.append(Point(p, radius_mm=1.3, filled=False, name=f"{d.prefix}tangency-{key}-{i}"))
            occ.add_box((p[0] - 1.5, p[1] - 1.5, p[0] + 1.5, p[1] + 1.5))
    for key, pt in (("k", d.k_pt), ("l", d.l_pt)):
        els.append(Point(pt, radius_mm=0.7, name=f"{d.prefix}point-{key}"))
        occ.add_box((pt[0] - 0.9, pt[1] - 0.9, pt[0] + 0.9, pt[1] + 0.9))
    for key, pt in (("k", d.k_pt), ("l", d.l_pt)):        # a leader when the ray, arc and axis leave no room beside
        lab, leader = occ.place_label_with_leader(pt, key, ("w", "nw", "sw", "ne", "se") if d.right else
                                                  ("e", "ne", "se", "nw", "sw"), size_mm=TEXT_MM + 0.5, gap_mm=1.5,
                                                  within=within)
        _with_leader(els, lab, leader, key, TEXT_MM + 0.5, f"{d.prefix}name-{key}", f"{d.prefix}leader-{key}")
    return els


def _with_leader(els: list[Element], lab: Label, leader: tuple | None, text: str, size: float, name: str,
                 leader_name: str) -> None:
    """Append a placed label, and its leader line when it has one."""
    els.append(Text((lab.x, lab.y), text, size_mm=size, anchor=lab.anchor, name=name))
    if leader is not None:
        els.append(Line(leader[0], leader[1], style=LEADER, name=leader_name))


def _psi_labels(res: WittenbauerResult, d: _DiagramPlace, occ: FastOccupancy, nt: Notation,
                within: Box | None) -> list[Element]:
    """ψ_max and ψ_min beside their arcs (with a leader when the arc's middle is crowded)."""
    els: list[Element] = []
    for key, pt, psi in (("max", d.k_pt, res.psi_max), ("min", d.l_pt, res.psi_min)):
        text = nt.sym(f"dynamics.psi_{key}")
        a = psi / 2 if d.right else math.pi + psi / 2
        mid = (pt[0] + (d.R + 1.5) * math.cos(a), pt[1] - (d.R + 1.5) * math.sin(a))
        dirs: tuple[str, ...] = ("e", "ne", "se", "n", "s") if d.right else ("w", "sw", "nw", "s", "n")
        lab, leader = occ.place_label_with_leader(mid, text, dirs, size_mm=TEXT_MM, gap_mm=0.8, within=within)
        _with_leader(els, lab, leader, text, TEXT_MM, f"{d.prefix}label-psi-{key}", f"{d.prefix}leader-psi-{key}")
    return els


def _kl_label(res: WittenbauerResult, d: _DiagramPlace, dim: Dimension, occ: FastOccupancy, nt: Notation,
              within: Box | None) -> list[Element]:
    """kl written beside its dimension line, where it covers nothing."""
    els: list[Element] = []
    kl_text = f"kl = {nt.number(res.kl_mm)} {nt.unit('mm')}"
    d0, d1 = np.asarray(dim.line_start), np.asarray(dim.line_end)
    spots = [tuple((d0 + (d1 - d0) * t).tolist()) for t in (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8)]
    dirs = ("e", "w") if d.right else ("w", "e")
    lab = None
    for spot in spots:
        lab = occ.first_free(spot, kl_text, dirs, (1.2, 2.5), TEXT_MM + 0.3, within)
        if lab is not None:
            occ.add_label(lab)
            break
    if lab is None:
        lab, leader = occ.place_label_with_leader(spots[0], kl_text, dirs, size_mm=TEXT_MM + 0.3, within=within)
        if leader is not None:
            els.append(Line(leader[0], leader[1], style=LEADER, name=f"{d.prefix}leader-kl"))
    els.append(Text((lab.x, lab.y), kl_text, size_mm=TEXT_MM + 0.3, anchor=lab.anchor, name=f"{d.prefix}label-kl"))
    return els


def _position_labels(res: WittenbauerResult, d: _DiagramPlace, occ: FastOccupancy, nt: Notation, within: Box | None,
                     label_step: int | None) -> list[Element]:
    """The position numbers, away from the curve's middle, then ω_max and ω_min at their first tangencies."""
    els: list[Element] = []
    X, Y, m = d.X, d.Y, res.m
    cx, cy = float(X[:-1].mean()), float(Y[:-1].mean())
    step = label_step or max(1, math.ceil(m / 24))
    for i in range(0, m, step):
        p = d.P(X[i], Y[i])
        lab, leader = occ.place_label_with_leader(p, str(i), _compass(X[i] - cx, Y[i] - cy), size_mm=TEXT_MM,
                                                  gap_mm=1.0, within=within)
        _with_leader(els, lab, leader, str(i), TEXT_MM, f"{d.prefix}pos-{i}", f"{d.prefix}leader-pos-{i}")
    for key, idx in (("max", res.index_omega_max), ("min", res.index_omega_min)):
        i = idx[0]
        p = d.P(X[i], Y[i])
        text = nt.sym(f"dynamics.omega_{key}")
        dirs = (("ne", "n", "e", "nw", "se", "w", "sw", "s") if key == "max"
                else ("sw", "s", "se", "w", "nw", "e", "ne", "n"))
        lab, leader = occ.place_label_with_leader(p, text, dirs, size_mm=TEXT_MM, gap_mm=2.5, within=within)
        _with_leader(els, lab, leader, text, TEXT_MM, f"{d.prefix}label-omega-{key}", f"{d.prefix}leader-omega-{key}")
    return els


def O1_on_sheet(res: WittenbauerResult, origin, clip) -> bool:
    """Whether the rays' intersection O₁ falls inside the drawing's clip box.

    Parameters
    ----------
    res : WittenbauerResult
        The diagram's construction (``O1_mm``: O₁ from the origin, mm, y up).
    origin : (float, float), mm
        The diagram's origin on the page (y down).
    clip : (float, float, float, float), mm
        Left, top, right, bottom of the region the diagram may draw in.

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> O1_on_sheet(SimpleNamespace(O1_mm=(-30.0, 40.0)), (50.0, 150.0), (10.0, 20.0, 200.0, 280.0))
    True
    """
    x, y = origin[0] + res.O1_mm[0], origin[1] - res.O1_mm[1]
    return clip[0] <= x <= clip[2] and clip[1] <= y <= clip[3]


def result_rows(res: WittenbauerResult, nt, *, extra=(), on_sheet: bool = False, J_0: float = 0.0) -> tuple:
    """The result table: (quantity, value, compact) rows in the profile's words and symbols.

    ``compact`` is the row as one cell (symbol = value), for the compact A4 figure. With the
    ordinate axis at J_e = ``J_0`` > 0 (``res`` from :func:`offset_origin`), a row gives J_0 and
    J_F = μ_T·kl/(ω_m²[δ]) − J_0.
    """
    nt = get_notation(nt)
    n = nt.number
    sc = partial(format_scale, decimal=nt.decimal)      # a scale as a draftsman writes it: 0.00002, not 2·10⁻⁵
    mm = nt.unit("mm")
    pos = " ".join(str(i) for i in res.index_omega_max)
    neg = " ".join(str(i) for i in res.index_omega_min)
    tan_form = nt.word("wittenbauer.tangents_exact" if res.tangents == "exact" else "wittenbauer.tangents_textbook")
    if res.error_estimate is None:
        err = nt.word("wittenbauer.none")
    else:
        err = f"+{value_text(nt, res.error_estimate, 'kg·m²', sig=3)}".replace("+−", "−")
    O1_word = nt.word("wittenbauer.O1_on")           # drawn: its place; else said as a textbook says it
    O1 = f"({n(res.O1_mm[0])}; {n(res.O1_mm[1])}) {mm}" if on_sheet else nt.word("wittenbauer.O1_off")
    tg = "tg" if nt.code == "ru" else "tan"
    psi_max, psi_min = nt.sym("dynamics.psi_max"), nt.sym("dynamics.psi_min")
    # one digits rule for a pair of one kind: both tangents, both angles with the same decimals (7,120° by 6,946°)
    tan_max, tan_min = nt.column((res.tan_psi_max, res.tan_psi_min))
    deg_max, deg_min = nt.column((math.degrees(res.psi_max), math.degrees(res.psi_min)))
    tg_max = f"{tg} {psi_max} = {tan_max}, {psi_max} = {deg_max}°"
    tg_min = f"{tg} {psi_min} = {tan_min}, {psi_min} = {deg_min}°"
    J_F = f"{nt.sym('dynamics.J_F')} = {nt.sym('mu_T')}·kl/({nt.sym('dynamics.omega_m')}²{nt.sym('dynamics.delta')})"
    J_F_num = f"= {sc(res.mu_T)}·{n(res.kl_mm)}/({n(res.omega_m)}²·{n(res.delta)})"
    origin_rows = []
    if J_0 > 0.0:
        J_F += f" − {nt.sym('dynamics.J_0')}"
        J_F_num += f" − {n(J_0)}"
        origin_rows = [(nt.word("wittenbauer.origin"), f"{nt.sym('dynamics.J_0')} = {value_text(nt, J_0, 'kg·m²')}",
                        None)]
    J_F_num += f" = {value_text(nt, res.J_F, 'kg·m²')}"
    rows = [
        (nt.word("wittenbauer.delta"), f"{nt.sym('dynamics.delta')} = {n(res.delta)}", None),
        (nt.word("wittenbauer.omega_m"), f"{nt.sym('dynamics.omega_m')} = {value_text(nt, res.omega_m, 'rad/s')}",
         None),
        *((a, b, None) for a, b in extra),
        (nt.word("wittenbauer.scale_J"), f"{nt.sym('dynamics.mu_J')} = {sc(res.mu_J)} {nt.unit('kg·m²')}/{mm}", None),
        (nt.word("wittenbauer.scale_T"), f"{nt.sym('mu_T')} = {sc(res.mu_T)} {nt.unit('J')}/{mm}", None),
        (nt.word("wittenbauer.tan_max"), tg_max, None),
        (nt.word("wittenbauer.tan_min"), tg_min, None),
        (nt.word("wittenbauer.tangents"), tan_form, f"{nt.word('wittenbauer.tangents')}: {tan_form}"),
        *origin_rows,
        (nt.word("wittenbauer.k"), f"k = {n(res.k_mm)} {mm}", None),
        (nt.word("wittenbauer.l"), f"l = {n(res.l_mm)} {mm}", None),
        (nt.word("wittenbauer.kl"), f"kl = {n(res.kl_mm)} {mm}", None),
        (nt.word("wittenbauer.J_F"), J_F, None),
        ("", J_F_num, None),
        (nt.word("wittenbauer.at_omega_max"), pos, f"{nt.word('wittenbauer.at_omega_max')}: {pos}"),
        (nt.word("wittenbauer.at_omega_min"), neg, f"{nt.word('wittenbauer.at_omega_min')}: {neg}"),
        (nt.word("wittenbauer.error", m=res.m), err, f"{nt.word('wittenbauer.error', m=res.m)}: {err}"),
        (O1_word, O1, f"{O1_word}: {O1}"),
    ]
    return tuple((a, b, c if c is not None else b) for a, b, c in rows)


def compact_rows(rows) -> tuple:
    """The result rows as one column (symbol = value), for the compact A4 figure."""
    return tuple((c,) for _, _, c in rows)


def wide_rows(rows) -> tuple:
    """The result rows as two columns (quantity, value), for the sheet."""
    return tuple((a, b) for a, b, _ in rows)


def _table(rows, at, name="result", size_mm: float = TABLE_MM) -> Table:
    probe = Table((0.0, 0.0), rows, header_rows=0, align="l" * len(rows[0]), size_mm=size_mm, padding_mm=1.6)
    widths = tuple(w * 1.05 + 0.5 for w in probe.column_widths())       # room for the estimate's error
    return Table(at, rows, col_widths_mm=widths, header_rows=0, align="l" * len(rows[0]), size_mm=size_mm,
                 row_height_mm=5.6 * size_mm / TABLE_MM, padding_mm=1.6, name=name)


def _place_table(occ, rows, candidates, name="result", size_mm: float = TABLE_MM, head_mm: float = 0.0) -> Table:
    """The table at the first candidate top-left corner where it, and ``head_mm`` above it (its heading's room),
    covers nothing (the first otherwise)."""
    probe = _table(rows, (0.0, 0.0), size_mm=size_mm)
    w, h = probe.width_mm, probe.height_mm
    for at in candidates:
        if occ.is_free((at[0], at[1] - head_mm, at[0] + w, at[1] + h)):
            break
    else:
        at = candidates[0]
    table = _table(rows, at, name, size_mm)
    occ.add_box((at[0], at[1], at[0] + w, at[1] + h))
    return table


def inertia_origin(J_lo: float, J_hi: float) -> float:
    """The suppressed zero J_0 of a J_e varying little (kg·m²): a round value below J_e,min, the same on the
    A1 sheet, the A4 diagram, the slides and the HTML stepper (it depends on J_e alone, not on a scale).

    >>> inertia_origin(0.54395, 0.70344), inertia_origin(0.0516, 0.0552)
    (0.5, 0.051)
    """
    span = J_hi - J_lo
    raw = span / 4.0 if span > 1e-9 * abs(J_hi) else abs(J_hi) / 10.0     # a constant J_e: a tenth of it
    k = math.floor(math.log10(raw))
    step = min(m * 10.0**k for m in (1.0, 2.0, 2.5, 5.0, 10.0) if m * 10.0**k >= raw)
    J_0 = math.floor(J_lo / step) * step
    if J_0 > J_lo - 0.02 * span:
        J_0 -= step
    return float(f"{max(J_0, 0.0):.12g}")


def suppressed_zero(J_lo: float, J_hi: float) -> bool:
    """Does the J axis start near J_e,min? When J_e varies by less than 35 % of its largest value."""
    return J_lo > 0.0 and 0.0 < J_hi - J_lo < 0.35 * J_hi          # a constant J_e: its axis from 0


def inertia_scale(mu_J, nt, J_lo: float, J_hi: float, room_mm: float) -> tuple[Scale, float]:
    """μ_J of a Wittenbauer diagram and where its J axis starts (0, or a suppressed zero J_0 > 0).

    A J_e that varies by less than 35 % of its largest value (the rule of the φ graphs) gets its
    axis from a round value below J_e,min, so the curve fills the width ``room_mm``; 20 mm and
    2 % of it are kept for the step down to that value.

    >>> from graphmethods.scene import notation
    >>> s, J_0 = inertia_scale(None, notation("en"), 0.0542, 0.0682, 200.0)
    >>> s.per_mm, J_0, s.to_mm(0.0682 - J_0) <= 200.0
    (0.0001, 0.05, True)
    """
    symbol, unit = nt.sym("dynamics.mu_J"), nt.unit("kg·m²")
    if not suppressed_zero(J_lo, J_hi):
        return given_scale(mu_J, symbol, unit, J_hi, room_mm, what="the J_e axis"), 0.0
    s_J = given_scale(mu_J, symbol, unit, J_hi - J_lo, 0.98 * room_mm - 20.0, what="the J_e axis")
    return s_J, inertia_origin(J_lo, J_hi)



# ----------------------------------------------------------------------------- 1. the compact A4 figure

def wittenbauer_diagram(source, *, mu_J=None, mu_T=None, tangents: str = "exact", notation="en", page=None,
                        title=None, problem=None, title_block: bool = True, name: str = "wittenbauer",
                        J_0: float | None = None) -> Scene:
    """The Wittenbauer energy–mass diagram alone, on an A4 landscape sheet, with its result table.

    Parameters
    ----------
    source : Study, Case or WittenbauerResult
        The study of a linkage (its J_e and ΔT at positions 0…m, ω_m and [δ]), or a
        construction made from data alone (its data are redrawn to the scales here).
    mu_J, mu_T : float or Scale, optional
        kg·m² per mm (abscissa) and J per mm (ordinate); picked to fill the sheet when not given.
    tangents : {"exact", "textbook"}
        tan ψ with (1 ± δ/2)² or (1 ± δ) (a Study source only; a result keeps its own).
    J_0 : float, optional
        Where the J_e axis starts, kg·m² (0 ≤ J_0 ≤ J_e,min): the A1 sheet's, for a drawing of its
        construction; picked from the data when not given (0, or a suppressed zero).

    Returns
    -------
    Scene
        ``scene.notes`` holds the scales picked and J_F.

    Examples
    --------
    >>> import numpy as np
    >>> from graphmethods.dynamics.wittenbauer import wittenbauer
    >>> phi = np.linspace(0, 2 * np.pi, 13)
    >>> res = wittenbauer(J_e=2 + 0.4 * np.cos(phi + 0.7), delta_T=300 * np.sin(phi), omega_m=20.0, delta=0.05,
    ...                   mu_J=0.01, mu_T=5.0)
    >>> res.mu_J, res.mu_T, round(res.kl_mm, 2)
    (0.01, 5.0, 132.63)
    >>> s = wittenbauer_diagram(res, notation="zh")           # redrawn to scales that fit the sheet
    >>> s.element("label-kl").text, [sc.caption("zh") for sc in s.scales()]
    ('kl = 69.11 mm', ['μ_E = 10 J/mm', 'μ_J = 0.01 kg·m²/mm'])
    """
    nt = get_notation(notation)
    data = diagram_data(source, tangents=tangents, notation=nt)
    sheet = SheetFrame(nt=nt, page=page, title=title or nt.word("wittenbauer.wittenbauer"),
                       problem=data.problem if problem is None else problem, title_block=title_block,
                       default_page=Page("A4", "landscape", frame=True))
    x0, y0, x1, y1 = sheet.box
    J_lo = float(data.J_e.min())
    if J_0 is None:
        J_0 = inertia_origin(J_lo, float(data.J_e.max())) if suppressed_zero(J_lo, float(data.J_e.max())) else 0.0
    elif not (math.isfinite(J_0) and 0.0 <= J_0 <= J_lo):
        raise InputError(f"J_0 = {J_0!r} kg·m²: the J_e axis starts at 0 or below J_e,min = {J_lo:g} kg·m²")
    J_0 = float(J_0)
    J_to, T_hi, T_lo = data.extent(J_0)         # the J axis from J_0, as on the A1 sheet; ΔT to k and l there
    probe_res = data.result(1.0, 1.0)
    table_w = _table(compact_rows(result_rows(probe_res, nt, J_0=J_0)), (0, 0)).width_mm
    py0, py1 = sheet.top + 10.0, sheet.caption_y - 9.0
    s_T = given_scale(mu_T, nt.sym("mu_T"), nt.unit("J"), T_hi - T_lo, py1 - py0, what="the ΔT axis")
    left = 22.0
    for _ in range(2):                          # the ψ marks left of the ordinate axis need their room there
        ax_x = x0 + left
        avail_X = x1 - table_w - 8.0 - 12.0 - ax_x
        s_J = given_scale(mu_J, nt.sym("dynamics.mu_J"), nt.unit("kg·m²"), J_to - J_0,
                          avail_X - (20.0 if J_0 else 0.0), what="the J_e axis")
        res = data.result(s_J.per_mm, s_T.per_mm)
        res = offset_origin(res, J_0) if J_0 > 0.0 else res
        place = _DiagramPlace.of(res, (0.0, 0.0), nt, J_to=J_to, T_hi=T_hi, T_lo=T_lo, J_from=J_0, prefix="")
        need = 0.0 if place.right else place.R + 8.0 - (20.0 if J_0 else 0.0)
        if need <= left:
            break
        left = need
    ax_x += 20.0 if J_0 else 0.0                # room for the step down to J_0 (the broken axis)
    origin = (ax_x, py0 + s_T.to_mm(T_hi))
    page_probe = sheet.probe
    clip = page_probe.inner_box()
    tb = page_probe.title_block.table(clip[2], clip[3]) if page_probe.title_block is not None else None
    avoid = ((tb.at[0], tb.at[1], tb.at[0] + tb.width_mm, tb.at[1] + tb.height_mm),) if tb is not None else ()
    # the title block of the final page can be wider than the probe's: keep the rays off its whole row
    if tb is not None:
        avoid = ((x0 - 10.0, tb.at[1], clip[2], clip[3]),)
    if is_slide(page_probe):                    # a slide's rays stop below its title (whitworth ru crossed it)
        avoid += (sheet.header().bbox(),)
    els = diagram_elements(res, origin=origin, nt=nt, occ=sheet.occ, clip=clip, avoid=avoid, J_to=J_to,
                           T_hi=T_hi, T_lo=T_lo, within=sheet.box, J_from=J_0, every_value=is_slide(sheet.probe))
    on_sheet = O1_on_sheet(res, origin, clip)
    rows = compact_rows(result_rows(res, nt, on_sheet=on_sheet, J_0=J_0))
    if is_slide(sheet.probe):           # a slide's captions under the diagram state μ_J and μ_T: not twice
        rows = tuple(r for r in rows if not r[0].startswith((nt.sym("dynamics.mu_J"), nt.sym("mu_T"))))
    w = _table(rows, (0, 0)).width_mm
    cands = [(x1 - w, y) for y in np.arange(sheet.top, sheet.caption_y - 40.0, 4.0)]
    cands += [(x, sheet.top) for x in np.arange(x1 - w, x0, -6.0)]
    table = _place_table(sheet.occ, rows, cands)
    scales = (s_T, s_J)
    elements = [sheet.header()] + els + [table] + sheet.captions(scales)
    notes = (s_J.note or f"given: {s_J.caption()}", s_T.note or f"given: {s_T.caption()}",
             f"J_F = {res.J_F:.6g} kg·m² from kl = {res.kl_mm:.6g} mm")
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name, notes=notes)


__all__ = ["wittenbauer_diagram", "diagram_elements", "diagram_data", "DiagramData",
           "ray_span", "result_rows"]
