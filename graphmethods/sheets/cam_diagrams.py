"""The cam sheet's diagrams: the motion diagrams by graphical integration, the combined ds/dφ–s diagram
and the pressure angle over the cycle.

**Motion diagrams.** The acceleration analogue d²s/dφ² is drawn exactly; each rise and return is
divided into ``n_div`` equal strips (each dwell is one strip), each strip replaced by its mean
ordinate (the step drawn across it), projected on the ordinate line at φ = 0 and joined to the pole
P₁ at H₁ mm to its left; the velocity analogue is drawn as chords parallel to those rays
(:func:`graphmethods.dynamics.graphical_calculus.integrate_by_chords`, μ = μ_y·μ_φ·H), and the
displacement from it the same way with P₂, H₂. The values are written on a value axis at the right
end of each diagram (so the rays cross no number); the error of the chords against the exact s(φ)
at the nodes is returned for the results table.

**Combined diagram** (translating follower): the points (ds/dφ, s) of the whole cycle to one length
scale, the tangent lines at [α] to the rise's branch and at [α]_return to the return's, and the zone
below every point's pair of lines at [α] (hatched): a cam centre O there keeps |α| within the limits;
the designed O = (e, −s₀) sits on its edge and r₀ = |O| (:mod:`graphmethods.kinematics.cam.design`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from graphmethods.dynamics.graphical_calculus import ChordIntegral, integrate_by_chords
from graphmethods.errors import InputError
from graphmethods.kinematics.cam import CamDesign
from graphmethods.scene import Axis, Line, Point, Polyline, Region, Scale, Table, Text, Vector, pick_scale
from graphmethods.scene.elements import Element, make_label
from graphmethods.scene.notation import Notation
from graphmethods.scene.numbers import within_roundoff
from graphmethods.scene.primitives import DASHED, MAIN, THIN, Style
from graphmethods.scene.scale import pick_angle_scale
from graphmethods.sheets.calculus import CHORD, RAY
from graphmethods.sheets.engine import lettering
from graphmethods.sheets.layout import Box, Occupancy
from graphmethods.sheets.styles import LEVEL

#: lettering on the A1 cam sheet (the engine's table, ГОСТ 2.304: labels 3.5 mm, headings 5 mm)
TEXT_MM, HEAD_MM = lettering("A1").label_mm, lettering("A1").heading_mm
#: the room left of each diagram's ordinate line for its pole, mm
POLE_ROOM_MM = 45.0
#: the value axis stands this far right of φ = 2π (clear of the φ axis's arrow and name), mm
VALUE_AXIS_MM = 14.0


def register_ink(occ: Occupancy, *elements: Element) -> None:
    """Register everything the elements draw, circles (points, rollers) as 48-gons, so labels keep off it."""
    from graphmethods.scene.primitives import Circle, walk

    occ.register(*elements)
    for e in elements:
        for prim in walk(e.primitives()):
            if isinstance(prim, Circle):
                t = np.linspace(0.0, 2 * math.pi, 49)
                xs, ys = prim.cx + prim.r * np.cos(t), prim.cy + prim.r * np.sin(t)
                occ.add_line(list(zip(xs.tolist(), ys.tolist())))


def segment(points: Sequence[tuple[float, float]], style: Style, *, name: str) -> Line:
    """A :class:`Line` between the first two of ``points`` (mm)."""
    return Line(points[0], points[1], style, name=name)


def heading(box: Box, text: str, occ: Occupancy, name: str, *, share: float = 0.9) -> tuple[list[Element], float]:
    """A panel's heading at its top left, wrapped to ``share`` of its width; the elements and the y below it
    (mm)."""
    from graphmethods.sheets.calculus import _wrap

    x0, y0, x1, _ = box
    out: list[Element] = []
    y = y0
    for k, line in enumerate(_wrap(text, share * (x1 - x0), HEAD_MM)):
        y += HEAD_MM * (1.0 if k == 0 else 1.3)
        out.append(Text((x0, y), line, size_mm=HEAD_MM, bold=True, name=f"{name}-title-{k + 1}"))
        occ.add_label(make_label((x0, y), line, size_mm=HEAD_MM, bold=True))
    return out, y + 2.0


@dataclass(frozen=True)
class Construction:
    """The graphical integration's numbers: the two chord integrals and the nodes (rad)."""

    nodes: np.ndarray
    first: ChordIntegral | None    # d²s/dφ² -> ds/dφ; None when a uniform phase makes it infinite (impulses)
    second: ChordIntegral          # ds/dφ (chords, or the exact steps of the impulses' case) -> s
    error_s: float                 # largest |s_chords − s| at the nodes, m (rad)
    mu_v: float = 0.0              # the velocity analogue's scale, units per mm

    @property
    def impulses(self) -> bool:
        """A uniform phase: d²s/dφ² has impulses (hard impacts), ds/dφ is drawn exactly and integrated once."""
        return self.first is None


def nodes(cam: CamDesign, n_div: int) -> np.ndarray:
    """The division points φ (rad) of the construction: each rise and return in n_div equal parts, each
    dwell one strip; 0 … 2π."""
    pts = [0.0]
    for ph in cam.problem.phases:
        k = 1 if ph.kind == "dwell" else n_div
        pts += [math.radians(ph.start_deg + ph.angle_deg * (i + 1) / k) for i in range(k)]
    pts[-1] = 2.0 * math.pi
    return np.array(pts)


def has_impulses(cam: CamDesign) -> bool:
    """Whether a phase's law is uniform: its acceleration analogue is infinite (impulses) where it starts and
    ends, so the diagrams draw ds/dφ exactly and integrate it once (the textbook's way)."""
    return any(ph.law == "uniform" for ph in cam.problem.phases)


def construction(cam: CamDesign, n_div: int, *, mu_phi: float, mu_a: float, room_mm: float, fit_v: float,
                 fit_s: float) -> Construction:
    """Integrate the acceleration analogue twice by chords, with poles no further than ``room_mm``.

    The pole distances are round (1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10^k mm), the smallest for which the
    integral fits ``fit_v`` / ``fit_s`` mm of its diagram. With a uniform phase (:func:`has_impulses`) the
    velocity analogue is drawn exactly at the largest convenient scale that fits ``fit_v`` (its steps'
    means are exact) and integrated once.
    """
    p = cam.problem
    x = nodes(cam, n_div)
    breaks = [math.radians(ph.start_deg + ph.angle_deg * b) for ph in p.phases for b in (0.0, 0.5, 1.0)]

    def a(t: np.ndarray) -> np.ndarray:
        return p.motion(np.degrees(t))[2]

    def v(t: np.ndarray) -> np.ndarray:
        return p.motion(np.degrees(t))[1]

    def s(t: np.ndarray) -> np.ndarray:
        return p.motion(np.degrees(t))[0]

    first: ChordIntegral | None = None
    if has_impulses(cam):
        v_lo, v_hi = _span(v(np.linspace(0.0, 2 * math.pi, 1441)))
        mu_v = pick_scale(v_hi - v_lo, fit_v * max(v_hi - v_lo, 1e-300) / max(v_hi, -v_lo, 1e-300)).per_mm
        second = integrate_by_chords(x, v, mu_x=mu_phi, mu_y=mu_v, fit_mm=fit_s, breaks=breaks, exact=s)
    else:
        first = integrate_by_chords(x, a, mu_x=mu_phi, mu_y=mu_a, fit_mm=fit_v, breaks=breaks, exact=v)
        mu_v = first.mu
        second = integrate_by_chords(x, first.values + float(v(x[:1])[0]), mu_x=mu_phi, mu_y=mu_v, fit_mm=fit_s,
                                     exact=s)
    s_nodes = second.values + float(s(x[:1])[0])
    err = float(np.abs(s_nodes - s(x)).max())
    if max(first.H_mm if first is not None else 0.0, second.H_mm) > room_mm:
        raise ValueError("pole room")       # the caller picks a coarser μ and tries again
    return Construction(x, first, second, err, mu_v)


@dataclass(frozen=True)
class Band:
    """One diagram of the column: its box, the origin (φ = 0 on the zero line) and its scales."""

    box: Box
    x0: float
    y0: float
    mu_phi: Scale
    mu_y: Scale
    lo: float
    hi: float

    def pt(self, phi: Any, y: Any) -> list[tuple[float, float]]:
        X = self.x0 + np.asarray(phi) / self.mu_phi.per_mm
        Y = self.y0 - np.asarray(y) / self.mu_y.per_mm
        return list(zip(X.tolist(), Y.tolist()))


def _phi_axis(band: Band, y: float, nt: Notation, name: str) -> Axis:
    step = 30 if band.mu_phi.to_mm(math.radians(30)) >= 14.0 else 60
    ticks = tuple(math.radians(d) for d in range(0, 361, step))
    labels = tuple(f"{d}°" for d in range(0, 361, step))
    return Axis((band.x0, y), band.mu_phi, "x", 0.0, 2 * math.pi, ticks=ticks, tick_labels=labels, label="φ",
                size_mm=TEXT_MM, name=f"{name}-axis-phi")


def _value_axis(band: Band, nt: Notation, label: str, name: str) -> Axis:
    from graphmethods.scene import axis_ticks

    right = band.x0 + band.mu_phi.to_mm(2 * math.pi) + VALUE_AXIS_MM
    ticks = axis_ticks(band.lo, band.hi, band.mu_y, min_gap_mm=min(9.0, band.mu_y.to_mm(band.hi - band.lo) / 4.0))
    labels = tuple(nt.number(t, sig=3) for t in ticks)
    return Axis((right, band.y0), band.mu_y, "y", band.lo, band.hi, ticks=ticks, tick_labels=labels,
                label=label, labels_side="right", size_mm=TEXT_MM, name=f"{name}-axis-y")


def _frame_lines(band: Band, name: str) -> list[Element]:
    """The ordinate line at φ = 0 (the rays' target) and the zero line across the diagram."""
    y_top, y_bot = band.y0 - band.mu_y.to_mm(band.hi), band.y0 - band.mu_y.to_mm(band.lo)
    right = band.x0 + band.mu_phi.to_mm(2 * math.pi) + VALUE_AXIS_MM
    return [Line((band.x0, y_top), (band.x0, y_bot), THIN, name=f"{name}-ordinate"),
            Line((band.x0, band.y0), (right, band.y0), THIN, name=f"{name}-zero")]


def band_elements(band: Band, occ: Occupancy, nt: Notation, *, label: str, name: str,
                  curve: list[tuple[float, float]] | None, chords: list[tuple[float, float]] | None,
                  integral: ChordIntegral | None, k: int) -> list[Element]:
    """One diagram: frame lines, axes, the curve or chords, and (when it is integrated) the mean ordinates,
    the pole P_k with its rays and its distance H_k written beside it."""
    els: list[Element] = [*_frame_lines(band, name)]
    y_bot = band.y0 - band.mu_y.to_mm(band.lo)
    els.append(_phi_axis(band, y_bot + 6.5, nt, name))
    els.append(_value_axis(band, nt, label, name))
    if curve is not None:
        els.append(Polyline(tuple(curve), MAIN, name=f"{name}-curve"))
    if chords is not None:
        els += [Line((x, band.y0), (x, y), THIN, name=f"{name}-ordinate-{i}") for i, (x, y) in enumerate(chords)
                if abs(y - band.y0) > 0.5]
        els.append(Polyline(tuple(chords), MAIN, name=f"{name}-chords"))
        els += [Point(p, radius_mm=0.5, name=f"{name}-node-{i}") for i, p in enumerate(chords)]
    if integral is not None:
        xs, means = integral.x, integral.mean_ordinate
        for i in range(len(means)):
            (a, b) = band.pt(xs[i:i + 2], [means[i], means[i]])
            els.append(Line(a, b, CHORD, name=f"{name}-mean-{i}"))
        P = (band.x0 - integral.H_mm, band.y0)
        for i, m in enumerate(means):
            els.append(Line(P, (band.x0, band.y0 - m / band.mu_y.per_mm), RAY, name=f"{name}-ray-{i}"))
        els.append(Point(P, radius_mm=0.8, name=f"{name}-pole"))
    register_ink(occ, *els)
    if integral is not None:
        P = (band.x0 - integral.H_mm, band.y0)
        text = nt.word("cam.pole", k=k, value=nt.number(integral.H_mm, sig=3))
        lab, leader = occ.place_label_with_leader(P, text, ("w", "nw", "sw", "n", "s"), size_mm=TEXT_MM, gap_mm=1.5,
                                                  within=band.box)
        els.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-pole-name"))
        if leader is not None:
            els.append(Line(leader[0], leader[1], THIN, name=f"{name}-pole-leader"))
    return els


#: each motion diagram's room besides its plot: heading, a pad, the φ axis with its numbers (mm)
BAND_EXTRA_MM, BAND_GAP_MM = 27.0, 6.0


def _span(v: np.ndarray) -> tuple[float, float]:
    return min(float(v.min()), 0.0), max(float(v.max()), 0.0)


def _motion_scales(cam: CamDesign, box: Box, n_div: int) -> tuple[Scale, Scale, Construction]:
    """μ_φ, μ_a and the construction: the acceleration analogue takes at most a third of the column's plot
    height at its convenient scale, the two integrals share what it leaves (their poles at round distances)."""
    p = cam.problem
    x0, y0, x1, y1 = box
    mu_phi = pick_angle_scale(2 * math.pi, x1 - x0 - POLE_ROOM_MM - 44.0, symbol="μ_φ")
    s, s1, s2, _ = p.motion(np.linspace(0.0, 360.0, 1441))
    plot = y1 - y0 - 3 * BAND_EXTRA_MM - 2 * BAND_GAP_MM
    unit = "rad" if p.oscillating else "m"
    lo, hi = _a_span(cam, s1, s2)
    mu_a = pick_scale(hi - lo, plot / 3.0, symbol="μ_a", unit=unit)
    for _ in range(8):
        rest = plot - mu_a.to_mm(hi - lo)
        v_lo, v_hi = _span(s1)
        try:
            con = construction(cam, n_div, mu_phi=mu_phi.per_mm, mu_a=mu_a.per_mm, room_mm=POLE_ROOM_MM - 8.0,
                               fit_v=0.5 * rest * max(v_hi, -v_lo) / max(v_hi - v_lo, 1e-300), fit_s=0.5 * rest)
        except ValueError:
            mu_a = pick_scale(mu_a.per_mm * 1.01 * plot, plot, symbol="μ_a", unit=unit)
            continue
        rest_s = rest - (v_hi - v_lo) / con.mu_v
        if con.second.H_mm * 1.5 <= POLE_ROOM_MM - 8.0 and rest_s > 0:     # a larger s diagram where it fits
            con = _larger_s(cam, n_div, mu_phi, mu_a, rest, rest_s) or con
        return mu_phi, mu_a, con
    raise InputError("no pole distance within the sheet's room draws these motion diagrams; the data are too "
                     "uneven for the A1 cam sheet")


def _a_span(cam: CamDesign, s1: np.ndarray, s2: np.ndarray) -> tuple[float, float]:
    """The acceleration analogue's drawn range: its values and, with impulses, room for their arrows (as
    high as the largest |d²s/dφ²| or |ds/dφ| per radian, each way)."""
    lo, hi = _span(s2)
    if has_impulses(cam):
        reach = max(hi, -lo, float(np.abs(s1).max()))
        lo, hi = min(lo, -reach), max(hi, reach)
    return lo, hi


def _larger_s(cam: CamDesign, n_div: int, mu_phi: Scale, mu_a: Scale, rest: float, rest_s: float
              ) -> Construction | None:
    """The construction with the displacement diagram drawn to fill ``rest_s``, or None where its pole would
    leave the room."""
    s1 = cam.problem.motion(np.linspace(0.0, 360.0, 1441))[1]
    v_lo, v_hi = _span(s1)
    try:
        return construction(cam, n_div, mu_phi=mu_phi.per_mm, mu_a=mu_a.per_mm, room_mm=POLE_ROOM_MM - 8.0,
                            fit_v=0.5 * rest * max(v_hi, -v_lo) / max(v_hi - v_lo, 1e-300), fit_s=rest_s)
    except ValueError:
        return None


def motion_column(cam: CamDesign, box: Box, occ: Occupancy, nt: Notation, *, n_div: int
                  ) -> tuple[list[Element], list[Scale], Construction]:
    """The three motion diagrams stacked in ``box``: d²s/dφ² with its strips and pole, ds/dφ as chords with
    its pole, s as chords; their scales and the construction's numbers."""
    p = cam.problem
    x0, y0, x1, y1 = box
    mu_phi, mu_a, con = _motion_scales(cam, box, n_div)
    phi = np.linspace(0.0, 2 * math.pi, 1441)
    s, s1, s2, _ = p.motion(np.degrees(phi))
    unit = "rad" if p.oscillating else "m"
    sym = ("cam.dpsi", "cam.d2psi", "cam.psi") if p.oscillating else ("cam.ds", "cam.d2s", "calculus.s")
    scales = [mu_phi, mu_a, Scale("μ_v", unit, con.mu_v), Scale("μ_s", unit, con.second.mu)]
    imp = con.impulses
    data = [(s2, scales[1], None, con.first, nt.word("cam.d2s_title_impulses" if imp else "cam.d2s_title"),
             nt.sym(sym[1])),
            (s1, scales[2], con.first, con.second, nt.word("cam.ds_title_exact" if imp else "cam.ds_title"),
             nt.sym(sym[0])),
            (s, scales[3], con.second, None, nt.word("cam.psi_title" if p.oscillating else "cam.s_title"),
             nt.sym(sym[2]))]
    els: list[Element] = []
    top0 = y0
    spans = [_a_span(cam, s1, s2), _span(s1), _span(s)]
    spare = (y1 - y0 - 3 * BAND_EXTRA_MM - 2 * BAND_GAP_MM
             - sum(d[1].to_mm(hi - lo) for d, (lo, hi) in zip(data, spans))) / 3.0
    for i, (vals, mu, chords_of, integ, title, label) in enumerate(data):
        head, top = heading((x0, top0, x1, y1), title, occ, f"m{i}")
        els += head
        lo, hi = spans[i]
        if chords_of is not None:
            c_lo, c_hi = _span(chords_of.values + float(vals[0]))
            lo, hi = min(lo, c_lo), max(hi, c_hi)
        zero_y = top + 6.0 + max(spare, 0.0) / 2.0 + mu.to_mm(hi)
        bottom = top0 + BAND_EXTRA_MM + mu.to_mm(hi - lo) + max(spare, 0.0)
        band = Band((x0, top0, x1, bottom), x0 + POLE_ROOM_MM, zero_y, mu_phi, mu, lo, hi)
        curve = band.pt(phi, vals) if chords_of is None else None
        chords = band.pt(chords_of.x, chords_of.values + float(vals[0])) if chords_of is not None else None
        if i == 0 and imp:
            els += impulse_arrows(cam, band, occ, nt)
        els += band_elements(band, occ, nt, label=f"{label}, {nt.unit(unit)}", name=f"m{i}",
                             curve=curve, chords=chords, integral=integ, k=i + 1)
        top0 = bottom + BAND_GAP_MM
    return els, scales, con


def impulse_arrows(cam: CamDesign, band: Band, occ: Occupancy, nt: Notation) -> list[Element]:
    """The impulses of the acceleration analogue at the hard impacts: an arrow from the zero line to the edge
    of the diagram (up where ds/dφ jumps up) and "∞" at its tip; the heading names the hard impacts."""
    out: list[Element] = []
    jumps = [i for i in cam.impacts if i.kind == "hard"]
    for k, imp in enumerate(jumps):
        x = band.x0 + band.mu_phi.to_mm(math.radians(imp.phi_deg))
        tip = band.y0 - band.mu_y.to_mm(band.hi if imp.jump > 0 else band.lo)
        out.append(Vector((x, band.y0), (x, tip), head_length_mm=3.0, head_width_mm=1.2, style=MAIN,
                          name=f"m0-impulse-{k}"))
    register_ink(occ, *out)
    for k, imp in enumerate(jumps):
        x = band.x0 + band.mu_phi.to_mm(math.radians(imp.phi_deg))
        tip = band.y0 - band.mu_y.to_mm(band.hi if imp.jump > 0 else band.lo)
        lab = occ.place_label((x, tip), "∞", ("e", "w", "ne", "nw", "se", "sw"), size_mm=TEXT_MM, gap_mm=0.8,
                              within=band.box)
        out.append(Text((lab.x, lab.y), "∞", size_mm=TEXT_MM, anchor=lab.anchor, name=f"m0-infinity-{k}"))
    return out


def _clip_ray(x0: float, y0: float, dx: float, dy: float, box: tuple[float, float, float, float]
              ) -> tuple[float, float]:
    """Where the ray from (x0, y0) along (dx, dy) leaves the rectangle (x_min, y_min, x_max, y_max)."""
    xa, ya, xb, yb = box
    ts = [t for t in ((xa - x0) / dx if dx < 0 else (xb - x0) / dx if dx > 0 else math.inf,
                      (ya - y0) / dy if dy < 0 else (yb - y0) / dy if dy > 0 else math.inf) if t >= 0]
    t = min(ts)
    return x0 + t * dx, y0 + t * dy


def _zone_edge(cam: CamDesign, xg: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The admissible zone's upper edge over xg (m) and the cycle's points (s', s) with their limits tan[α]."""
    p = cam.problem
    phi = np.linspace(0.0, 360.0, 1441)
    s, s1, _, _ = p.motion(phi)
    tan = {"rise": math.tan(math.radians(p.alpha_max_deg or 30.0)),
           "return": math.tan(math.radians(p.alpha_return_max_deg))}
    t = np.full(phi.shape, np.inf)
    for ph in p.phases:
        if ph.kind in tan:
            t[(phi >= ph.start_deg) & (phi <= ph.end_deg)] = tan[ph.kind]
    keep = np.isfinite(t)
    edge = np.min(s[keep, None] - np.abs(s1[keep, None] - xg[None, :]) / t[keep, None], axis=0)
    return edge, s, s1, t


def combined_diagram(cam: CamDesign, box: Box, occ: Occupancy, nt: Notation) -> tuple[list[Element], Scale]:
    """The combined ds/dφ–s diagram of a translating follower (see the module docstring): one length scale on
    both axes (the angles at [α] are true), the diagram as wide as the box allows and the zone hatched down
    to the box's bottom."""
    p = cam.problem
    els, top = heading(box, nt.word("cam.combined"), occ, "c")
    s0 = math.sqrt(cam.pitch_base_radius ** 2 - p.offset ** 2)
    _, s, s1, t = _zone_edge(cam, np.zeros(1))
    xa, xb = min(float(s1.min()), p.offset, 0.0), max(float(s1.max()), p.offset, 0.0)
    x0, _, x1, y1 = box
    left, right, bottom = x0 + 16.0, x1 - 24.0, y1 - 10.0
    y_need = float(s.max()) + 1.3 * s0
    mu = pick_scale(max((xb - xa) * 1.1 / (right - left), y_need / (bottom - top - 16.0)), 1.0, symbol="μ′_l",
                    unit="m")
    pad = 0.5 * (mu.to_value(right - left) - (xb - xa))
    x_min, x_max = xa - pad, xb + pad
    y_hi = float(s.max())
    y_lo = y_hi - mu.to_value(bottom - top - 16.0)
    cx, cy = left - mu.to_mm(x_min), top + 10.0 + mu.to_mm(y_hi)

    def P(x: np.ndarray | float, y: np.ndarray | float) -> list[tuple[float, float]]:
        X, Y = cx + np.atleast_1d(x) / mu.per_mm, cy - np.atleast_1d(y) / mu.per_mm
        return list(zip(X.tolist(), Y.tolist()))
    xg = np.linspace(x_min, x_max, 241)
    edge = np.clip(_zone_edge(cam, xg)[0], y_lo, None)
    zone = P(xg, edge) + P(np.array([x_max, x_min]), np.array([y_lo, y_lo]))
    body: list[Element] = [Region(tuple(zone), hatch_angle_deg=45.0, hatch_spacing_mm=4.0, name="c-zone"),
                           Polyline(tuple(P(s1, s)), MAIN, name="c-curve")]
    body += _tangents(cam, s, s1, t, P, (x_min, y_lo, x_max, y_hi))
    O = P(p.offset, -s0)[0]
    gx, gy = _ticks(x_min, x_max, mu, 22.0), _ticks(y_lo, y_hi, mu, 22.0)
    body += [Axis(P(0.0, y_lo)[0], mu, "x", x_min, x_max, ticks=gx, tick_labels=tuple(nt.number(v, sig=3) for v in gx),
                  label=nt.sym("cam.ds"), size_mm=TEXT_MM, name="c-axis-ds"),
             Axis(P(x_min, 0.0)[0], mu, "y", y_lo, y_hi, ticks=gy, tick_labels=tuple(nt.number(v, sig=3) for v in gy),
                  label=nt.sym("calculus.s"), size_mm=TEXT_MM, name="c-axis-s"),
             segment(P(np.array([0.0, 0.0]), np.array([y_lo, y_hi])), THIN, name="c-follower-line"),
             segment(P(np.array([x_min, x_max]), np.array([0.0, 0.0])), THIN, name="c-zero"),
             Line(O, P(0.0, 0.0)[0], LEVEL, name="c-r0"), Point(O, radius_mm=1.0, name="c-O")]
    register_ink(occ, *body)
    els += body
    r0 = f"O: {nt.sym('cam.r_0')} = {nt.number(cam.pitch_base_radius, sig=4)} {nt.unit('m')}"
    lab, leader = occ.place_label_with_leader(O, r0, ("e", "w", "ne", "nw", "se", "sw", "n"), size_mm=TEXT_MM,
                                              within=box)
    els.append(Text((lab.x, lab.y), r0, size_mm=TEXT_MM, anchor=lab.anchor, name="c-O-name"))
    if leader is not None:
        els.append(Line(leader[0], leader[1], THIN, name="c-O-leader"))
    return els, mu


def _ticks(lo: float, hi: float, mu: Scale, gap_mm: float) -> tuple[float, ...]:
    """Ticks at a convenient step at least ``gap_mm`` apart."""
    from graphmethods.scene import axis_ticks

    return axis_ticks(lo, hi, mu, min_gap_mm=gap_mm)


def _tangents(cam: CamDesign, s: np.ndarray, s1: np.ndarray, t: np.ndarray, P: Any,
              clip: tuple[float, float, float, float]) -> list[Element]:
    """The tangent lines at [α] to the rise's branch and at [α]_return to the return's, from the point that
    binds (the largest |s' − e|/tan[α] − s) down to the edge of the drawing."""
    p = cam.problem
    out: list[Element] = []
    for kind, lim in (("rise", p.alpha_max_deg or 30.0), ("return", p.alpha_return_max_deg)):
        tn = math.tan(math.radians(lim))
        rows = [ph for ph in p.phases if ph.kind == kind]
        if not rows:
            continue
        phi = np.linspace(0.0, 360.0, len(s))
        m = np.zeros(len(s), dtype=bool)
        for ph in rows:
            m |= (phi >= ph.start_deg) & (phi <= ph.end_deg)
        i = int(np.argmax(np.abs(s1[m] - p.offset) / tn - s[m]))
        xt, yt = float(s1[m][i]), float(s[m][i])
        sign = 1.0 if xt >= p.offset else -1.0
        xe, ye = _clip_ray(xt, yt, -sign * tn, -1.0, clip)
        out.append(Line(P(xt, yt)[0], P(xe, ye)[0], DASHED, name=f"c-tangent-{kind}"))
    return out


def phi_graph(box: Box, occ: Occupancy, nt: Notation, *, values: np.ndarray, limits: list[float], title: str,
              label: str, unit: str, symbol: str, name: str) -> tuple[list[Element], list[Scale]]:
    """A quantity over the cycle (values at 0°, 0.25°, … 360°) with level lines at ``limits``, filling the box;
    its own φ scale ``μ′_φ`` (the motion diagrams' μ_φ needs more width than a graph beside them has). The
    scales returned: the quantity's, then μ′_φ."""
    els, top = heading(box, title, occ, name)
    phi = np.linspace(0.0, 2 * math.pi, len(values))
    x0, _, x1, y1 = box
    lo, hi = min(float(values.min()), *limits, 0.0), max(float(values.max()), *limits, 0.0)
    mu_y = pick_scale(hi - lo, y1 - top - 20.0, symbol=symbol, unit=unit)
    mu_phi = pick_angle_scale(2 * math.pi, x1 - x0 - 40.0, symbol="μ′_φ")
    band = Band(box, x0 + 4.0, top + 6.0 + mu_y.to_mm(hi), mu_phi, mu_y, lo, hi)
    right = band.x0 + mu_phi.to_mm(2 * math.pi) + VALUE_AXIS_MM
    body: list[Element] = [Line((band.x0, band.y0), (right, band.y0), THIN, name=f"{name}-zero"),
                           Polyline(tuple(band.pt(phi, values)), MAIN, name=f"{name}-curve")]
    for k, v in enumerate(limits):
        body.append(segment(band.pt(np.array([0.0, 2 * math.pi]), np.array([v, v])), LEVEL, name=f"{name}-lim-{k}"))
    y_bot = band.y0 - mu_y.to_mm(lo)
    body += [_phi_axis(band, y_bot + 6.5, nt, name), _value_axis(band, nt, label, name)]
    register_ink(occ, *body)
    return els + body, [mu_y, mu_phi]


def alpha_graph(cam: CamDesign, box: Box, occ: Occupancy, nt: Notation) -> tuple[list[Element], list[Scale]]:
    """The pressure angle α(φ) over the cycle, with ±[α] of the rise as level lines (and [α]_return when it
    is within the curve's range)."""
    p = cam.problem
    alpha = cam.state(np.linspace(0.0, 360.0, 1441)).alpha_deg
    lim = [v for v in (p.alpha_max_deg, -(p.alpha_max_deg or 0.0)) if v]
    if p.alpha_return_max_deg <= float(np.abs(alpha).max()) * 1.2:
        lim.append(-p.alpha_return_max_deg)
    return phi_graph(box, occ, nt, values=alpha, limits=lim, title=nt.word("cam.alpha_graph"),
                     label=f"{nt.sym('cam.alpha')}, °", unit="°", symbol=f"μ_{nt.sym('cam.alpha')}", name="alpha")


def rho_graph(cam: CamDesign, box: Box, occ: Occupancy, nt: Notation) -> tuple[list[Element], list[Scale]]:
    """The flat-faced cam's radius of curvature ρ = r_b + s + d²s/dφ² over the cycle, with ρ_min."""
    p = cam.problem
    s, _, s2, _ = p.motion(np.linspace(0.0, 360.0, 1441))
    rho = cam.base_radius + s + s2
    return phi_graph(box, occ, nt, values=rho, limits=[p.rho_min_allowed] if p.rho_min_allowed else [],
                     title=nt.word("cam.rho_graph"), label=f"{nt.sym('cam.rho')}, {nt.unit('m')}", unit="m",
                     symbol="μ_ρ", name="rho")


def fitted_table(at: tuple[float, float], rows: tuple[tuple[str, ...], ...], box: Box, *, align: str,
                 name: str, header_rows: int = 1) -> Table:
    """A table in the largest standard lettering (5 or 3.5 mm, ГОСТ 2.304) that keeps it inside ``box``."""
    x0, y0, x1, y1 = box
    table = None
    for size in (lettering("A1").value_mm, TEXT_MM):
        table = Table(at, rows, size_mm=size, row_height_mm=1.8 * size + 0.6, align=align, header_rows=header_rows,
                      name=name)
        if at[0] + table.width_mm <= x1 and at[1] + table.height_mm <= y1:
            break
    assert table is not None
    widths = table.column_widths()
    extra = (x1 - at[0] - table.width_mm) / len(widths)           # the columns share the box's width
    if extra > 0:
        table = replace(table, col_widths_mm=tuple(w + extra for w in widths))
    return table


def positions_table(cam: CamDesign, box: Box, nt: Notation, n_div: int) -> list[Element]:
    """The division points: number, φ, s (ψ), ds/dφ (dψ/dφ) and α, as the sheet's construction uses them."""
    p = cam.problem
    phi = np.degrees(nodes(cam, n_div)[:-1])
    st = cam.state(phi)
    osc = p.oscillating
    s_head = f"{nt.sym('cam.psi')}, °" if osc else f"{nt.sym('calculus.s')}, {nt.unit('m')}"
    v_head = nt.sym("cam.dpsi") if osc else f"{nt.sym('cam.ds')}, {nt.unit('m')}"
    flat = p.contact == "flat"
    head = ("k", "φ, °", s_head, v_head) + (() if flat else (f"{nt.sym('cam.alpha')}, °",))
    # a value within the round-off of its column (s, ds/dφ at a dwell: −7.9·10⁻¹⁸ m) is written 0
    s_col, v_col, a_col = (np.where([within_roundoff(v, np.abs(col).max()) for v in col], 0.0, col)
                           for col in (np.asarray(st.s), np.asarray(st.ds), np.asarray(st.alpha_deg)))
    rows = [(str(k), nt.number(f, sig=4), nt.number(math.degrees(sv) if osc else sv, sig=4), nt.number(dv, sig=4))
            + (() if flat else (nt.number(a, sig=4),)) for k, (f, sv, dv, a) in
            enumerate(zip(phi, s_col, v_col, a_col))]
    head_els, top = heading(box, nt.word("cam.positions"), Occupancy(), "positions")
    return [*head_els, fitted_table((box[0], top + 2.0), (head, *rows), box, align="r" * len(head),
                                        name="positions-table")]


__all__ = ["Construction", "alpha_graph", "combined_diagram", "construction", "motion_column", "nodes", "phi_graph",
           "positions_table", "rho_graph"]

