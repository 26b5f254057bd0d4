"""The combined diagram of an oscillating (rocker) follower: the smallest base radius, drawn.

The textbook's construction (Артоболевский; 孙桓 《机械原理》, 摆动从动件凸轮基圆半径的图解): keep the
rocker's pivot A still and draw the arc of the roller centre's positions B_k (radius l, the arm). On
each arm line A–B_k lay off from B_k the analogue of B's velocity, l·dψ/dφ, away from A where the arm
swings forward (dψ/dφ > 0) and towards A where it swings back: the points K_k = A + (1 + dψ/dφ)·(B_k − A).
The normal to the pitch curve at B_k passes through K_k and the cam centre O (the relative pole of cam and
rocker lies on the line O–A), so the pressure angle at B_k is the angle at K_k between K_k–O and the
direction of B_k's velocity (⟂ the arm). A cam centre keeps |α| ≤ [α] at B_k when it lies in the angle of
half-opening [α] at K_k about that direction, behind it: the intersection of these angles over the rise
(at [α]) and over the return (at [α]_return) is the admissible zone, bounded by the two tangent lines
through the binding points. With the pivot distance a given, O lies on the circle of radius a about A; the
zone's boundary point on it is the cam centre of the smallest base radius, r₀ = |O B₀|.

The construction works in the follower's frame of :mod:`graphmethods.kinematics.cam.geometry` (O at the
origin, A = (a, 0), B = A + l·(−cos θ, sin θ), θ = ψ₀ + ψ) at the designed ψ₀; a cam centre turned about A
by δ stands for the base radius whose ψ₀ is ψ₀ + δ (the same relative position), so
:func:`zone_boundary_r0` finds the boundary point by bisection on δ independently of
:func:`graphmethods.kinematics.cam.design` and must give the designed r₀.

>>> from graphmethods.kinematics.cam import design
>>> from graphmethods.problems.builtin import cam_problem
>>> cam = design(cam_problem("oscillating-cam"))
>>> abs(zone_boundary_r0(cam) - cam.pitch_base_radius) < 1e-9
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from graphmethods.kinematics.cam import CamDesign
from graphmethods.kinematics.cam.design import made_once, psi_0_rows, smallest_admissible
from graphmethods.kinematics.cam.extrema import maximize_rows
from graphmethods.kinematics.cam.geometry import psi_0
from graphmethods.scene import Line, Point, Polyline, Region, Scale, Text, pick_scale
from graphmethods.scene.elements import Element
from graphmethods.scene.notation import Notation
from graphmethods.scene.primitives import DASHED, MAIN, THIN
from graphmethods.sheets.layout import Box, Occupancy
from graphmethods.sheets.styles import CENTRE_LINE as CENTRES, LEVEL, PROJECTION

Array = NDArray[np.float64]


def _limits(cam: CamDesign) -> dict[str, float]:
    p = cam.problem
    return {"rise": math.radians(p.alpha_max_deg or 30.0), "return": math.radians(p.alpha_return_max_deg)}


@dataclass(frozen=True)
class Rocker:
    """The rocker's positions in the follower's frame (m) at the designed ψ₀."""

    A: Array                  # the pivot (a, 0)
    arm: float
    psi0: float               # ψ₀ of the designed base radius, rad

    def B(self, psi: Array) -> Array:
        th = self.psi0 + np.asarray(psi, dtype=float)
        return np.stack((self.A[0] - self.arm * np.cos(th), self.arm * np.sin(th)), 1)

    def K(self, psi: Array, dpsi: Array) -> Array:
        """The points K = A + (1 + dψ/dφ)(B − A): l·dψ/dφ laid off from B along the arm."""
        return self.A + (1.0 + np.asarray(dpsi, dtype=float))[:, None] * (self.B(psi) - self.A)

    def u(self, psi: Array) -> Array:
        """The unit direction of B's velocity when the arm swings forward (⟂ the arm)."""
        th = self.psi0 + np.asarray(psi, dtype=float)
        return np.stack((np.sin(th), np.cos(th)), 1)


def rocker(cam: CamDesign) -> Rocker:
    """The rocker of a designed oscillating cam: its pivot A = (a, 0), arm l and ψ₀ at the designed base radius.

    Parameters
    ----------
    cam : CamDesign
        A designed cam with an oscillating follower (a, l in m).

    Returns
    -------
    Rocker
        Pivot (m), arm (m) and the arm's angle ψ₀ from the line of centres (rad) at the lowest position.

    Examples
    --------
    >>> from graphmethods.kinematics.cam import design
    >>> from graphmethods.problems.builtin import cam_problem
    >>> rk = rocker(design(cam_problem("oscillating-cam")))
    >>> rk.A.tolist(), round(rk.psi0, 4)
    ([0.15, 0.0], 0.1803)
    """
    p = cam.problem
    return Rocker(np.array([p.pivot, 0.0]), p.arm, psi_0(cam.pitch_base_radius, p.arm, p.pivot))


def pressure_angle(rk: Rocker, O: Array, psi: Array, dpsi: Array) -> Array:
    """|α| (rad) at the rocker's positions for a cam centre O: the angle at K between K–O and B's velocity;
    π where O is in front of K (no admissible angle).

    ``O`` is one point (2,) or one per row of ``psi`` and ``dpsi`` (shape (rows, 1, 2)). The operations of
    :meth:`Rocker.K` and :meth:`Rocker.u` in their order (the same bits), the arm's cosine and sine taken once.
    """
    th = rk.psi0 + np.asarray(psi, dtype=float)
    cs, sn = np.cos(th), np.sin(th)
    A_x, A_y = float(rk.A[0]), float(rk.A[1])
    grow = 1.0 + np.asarray(dpsi, dtype=float)
    d_x = (A_x + grow * ((A_x - rk.arm * cs) - A_x)) - O[..., 0]
    d_y = (A_y + grow * (rk.arm * sn - A_y)) - O[..., 1]
    dot = d_x * sn + d_y * cs
    cross = np.abs(d_x * cs - d_y * sn)
    return np.where(dot > 0.0, np.arctan2(cross, dot), math.pi)


def excess(cam: CamDesign, rk: Rocker, O: Array, *, settle: bool = False) -> Array:
    """max over the rises and returns of (|α| − its limit), rad, exact per smooth piece of each phase, for each
    cam centre of ``O`` (shape (rows, 2)).

    With ``settle`` only the sign is asked: a positive value is returned as soon as a grid shows |α| over its
    limit (:func:`~graphmethods.kinematics.cam.extrema.maximize_rows`'s ``stop_above``), unrefined; a value
    ≤ 0 is exact as without it.
    """
    lim = _limits(cam)
    O = np.asarray(O, dtype=float)[:, None, :]
    worst = np.full(len(O), -math.inf)
    for ph in cam.problem.phases:
        if ph.kind not in lim:
            continue
        for lo, hi in ph.pieces():
            left = hi < 1.0

            def g(x: Array, ph: Any = ph, left: bool = left) -> Array:
                s, s1, _, _ = ph.values(x, left=left)
                return pressure_angle(rk, O, s, s1)
            top = maximize_rows(g, lo, hi, len(O), stop_above=lim[ph.kind] if settle else None)[1]
            worst = np.maximum(worst, top - lim[ph.kind])
    return worst


def centre_at(rk: Rocker, delta: float) -> Array:
    """The cam centre turned about A by δ (rad): it stands for ψ₀ + δ (the arm's start turned the other way)."""
    c, s = math.cos(delta), math.sin(delta)
    v = -rk.A                                        # O − A at δ = 0
    return rk.A + np.array([c * v[0] + s * v[1], -s * v[0] + c * v[1]])


def zone_boundary_r0(cam: CamDesign) -> float:
    """r₀ = |O B₀| of the zone's boundary point on the circle of radius a about A (bisection on δ), m."""
    return float(np.hypot(*(boundary_centre(cam) - rocker(cam).B(np.zeros(1))[0])))


#: the zone's boundary point of each design drawn in this process (a sheet and its A4 figure draw it twice)
_CENTRES: dict[CamDesign, tuple[float, ...]] = {}


def boundary_centre(cam: CamDesign) -> Array:
    """The cam centre on the circle of radius a about A where the admissible zone begins, nearest B₀ (m).

    Found once per design in a process (a :class:`CamDesign` is frozen; a fresh array is returned each time).
    """
    return np.array(made_once(_CENTRES, cam, lambda c: tuple(_boundary_centre(c).tolist())))


def _boundary_centre(cam: CamDesign) -> Array:
    """:func:`boundary_centre` without the process's cache: a k-section on δ (see the module's docstring)."""
    p = cam.problem
    rk = rocker(cam)
    B0 = rk.B(np.zeros(1))[0]
    lo_r, hi_r = abs(p.pivot - p.arm), p.pivot + p.arm

    def delta_of(r0: float) -> float:                # the turn of O that gives |O B0| = r0
        return rk.psi0 - psi_0(r0, p.arm, p.pivot)

    def inside(r0: Array) -> NDArray[np.bool_]:      # only the sign of the excess counts
        psi0, ok = psi_0_rows(r0, p.arm, p.pivot)
        ok &= psi0 + p.stroke < math.pi
        O = np.array([centre_at(rk, rk.psi0 - q) for q in psi0.tolist()])
        return ok & (excess(cam, rk, O, settle=True) <= 0.0)
    hi = smallest_admissible(lo_r, hi_r, inside)
    assert hi is not None                            # the designed centre itself is admissible
    O = centre_at(rk, delta_of(hi))
    assert abs(float(np.hypot(*(O - B0))) - hi) < 1e-9 * max(hi, 1.0)
    return O


@dataclass(frozen=True)
class RockerDiagram:
    """What the diagram draws (m, follower frame): see the module docstring."""

    rocker: Rocker
    B_k: Array
    K_k: Array
    B_arc: Array
    K_curve: Array
    tangents: list[tuple[str, Array, Array]]       # (phase kind, binding K, unit direction of the edge)
    O: Array

    def extent(self) -> tuple[float, float, float, float]:
        pts = np.vstack((self.B_arc, self.K_curve, self.rocker.A[None, :], self.O[None, :], self.K_k))
        return float(pts[:, 0].min()), float(pts[:, 1].min()), float(pts[:, 0].max()), float(pts[:, 1].max())


def rocker_diagram_data(cam: CamDesign, phi_k_deg: Array) -> RockerDiagram:
    """The construction's points at the division points and densely, and the binding tangent lines."""
    p = cam.problem
    rk = rocker(cam)
    s, s1, _, _ = p.motion(np.asarray(phi_k_deg, dtype=float))
    phi = np.linspace(0.0, 360.0, 1441)
    S, S1, _, _ = p.motion(phi)
    O = boundary_centre(cam)
    tangents = []
    for kind, lim in _limits(cam).items():
        mask = np.zeros(phi.shape, dtype=bool)
        for ph in p.phases:
            if ph.kind == kind:
                mask |= (phi >= ph.start_deg) & (phi <= ph.end_deg)
        if mask.any():
            tangents += [(kind, K, e) for K, e in _binding_edges(rk, O, S[mask], S1[mask], lim)]
    return RockerDiagram(rk, rk.B(s), rk.K(s, s1), rk.B(np.linspace(S.min(), S.max(), 61)), rk.K(S, S1),
                         tangents, O)


def _binding_edges(rk: Rocker, O: Array, s: Array, s1: Array, lim: float) -> list[tuple[Array, Array]]:
    """Of the lines at [α] to B's velocity through the points K of a phase (two per point, one each side of
    the direction), the one of each side that passes nearest the cam centre O on the admissible side; those
    that pass through O (both when O is a corner of the zone), else the nearer: (K, unit direction away from
    K, behind it)."""
    K, u = rk.K(s, s1), rk.u(s)
    found: list[tuple[float, Array, Array]] = []
    for sign in (1.0, -1.0):
        c, sn = math.cos(sign * lim), math.sin(sign * lim)
        e = np.stack((-(c * u[:, 0] - sn * u[:, 1]), -(sn * u[:, 0] + c * u[:, 1])), 1)
        n = np.stack((-e[:, 1], e[:, 0]), 1)
        n *= np.sign(-(n[:, 0] * u[:, 0] + n[:, 1] * u[:, 1]))[:, None]      # towards the angle's axis −u
        gap = (O[0] - K[:, 0]) * n[:, 0] + (O[1] - K[:, 1]) * n[:, 1]
        i = int(np.argmin(gap))
        found.append((float(gap[i]), K[i], e[i]))
    tol = 1e-3 * float(np.hypot(*(rk.A - O)))
    near = min(g for g, _, _ in found)
    return [(k, e) for g, k, e in found if g <= max(tol, near)]


def zone_polygon(cam: CamDesign, rk: Rocker, box: tuple[float, float, float, float]) -> Array | None:
    """The admissible zone inside ``box`` (x0, y0, x1, y1, m): the intersection of the angles at K over the
    working phases (shapely), or None when it misses the box."""
    from shapely.geometry import Polygon, box as sbox

    p = cam.problem
    lim = _limits(cam)
    far = 4.0 * max(box[2] - box[0], box[3] - box[1])
    zone: Any = sbox(*box)
    for ph in p.phases:
        if ph.kind not in lim:
            continue
        x = np.linspace(0.0, 1.0, 121)
        s, s1, _, _ = ph.values(x)
        K, u = rk.K(s, s1), rk.u(s)
        c, sn = math.cos(lim[ph.kind]), math.sin(lim[ph.kind])
        for k in range(len(x)):
            bx, by = -u[k]                                   # the angle's axis, behind K
            left = np.array([c * bx - sn * by, sn * bx + c * by])
            right = np.array([c * bx + sn * by, -sn * bx + c * by])
            zone = zone.intersection(Polygon([tuple(K[k]), tuple(K[k] + far * left), tuple(K[k] + far * right)]))
            if zone.is_empty:
                return None
    if zone.geom_type != "Polygon":
        return None
    return np.asarray(zone.exterior.coords, dtype=float)


def rocker_diagram(cam: CamDesign, box: Box, occ: Occupancy, nt: Notation, *, phi_k_deg: Array,
                   heading_share: float = 0.9) -> tuple[list[Element], Scale]:
    """The rocker's combined diagram in ``box`` at the largest convenient length scale μ′_l (see the module
    docstring): the arc of B, the arm lines with K_k, the curve of K, the tangent lines at [α] and
    [α]_return, the zone hatched, the circle of the cam centre about A and O on the zone's edge with r₀."""
    from graphmethods.sheets.cam_diagrams import TEXT_MM, heading, register_ink

    p = cam.problem
    els, top = heading(box, nt.word("cam.combined_rocker"), occ, "c", share=heading_share)
    d = rocker_diagram_data(cam, phi_k_deg)
    x_lo, y_lo, x_hi, y_hi = d.extent()
    pad = 0.08 * max(x_hi - x_lo, y_hi - y_lo)
    x_lo, y_lo, x_hi, y_hi = x_lo - pad, y_lo - pad, x_hi + pad, y_hi + pad
    bx0, _, bx1, by1 = box
    mu = pick_scale(max((x_hi - x_lo) / (bx1 - bx0 - 8.0), (y_hi - y_lo) / (by1 - top - 8.0)), 1.0,
                    symbol="μ′_l", unit="m")
    cx = (bx0 + bx1) / 2.0 - mu.to_mm((x_lo + x_hi) / 2.0)
    cy = (top + by1) / 2.0 + mu.to_mm((y_lo + y_hi) / 2.0)
    half_w, half_h = mu.to_value((bx1 - bx0) / 2.0 - 2.0), mu.to_value((by1 - top) / 2.0 - 2.0)
    mx, my = (x_lo + x_hi) / 2.0, (y_lo + y_hi) / 2.0
    clip = (mx - half_w, my - half_h, mx + half_w, my + half_h)

    def P(xy: Array) -> tuple[tuple[float, float], ...]:
        xy = np.atleast_2d(xy)
        return tuple(zip((cx + xy[:, 0] / mu.per_mm).tolist(), (cy - xy[:, 1] / mu.per_mm).tolist()))
    rk = d.rocker
    body: list[Element] = []
    zone = zone_polygon(cam, rk, clip)
    if zone is not None:
        body.append(Region(P(zone), hatch_angle_deg=45.0, hatch_spacing_mm=4.0, name="c-zone"))
    ang = np.linspace(0.0, 2.0 * math.pi, 361)
    locus = rk.A + p.pivot * np.stack((np.cos(ang), np.sin(ang)), 1)
    inside = ((locus[:, 0] >= clip[0]) & (locus[:, 0] <= clip[2]) & (locus[:, 1] >= clip[1])
              & (locus[:, 1] <= clip[3]))
    for k, run in enumerate(_runs(locus, inside)):
        body.append(Polyline(P(run), CENTRES, name=f"c-locus-{k}"))
    body.append(Polyline(P(d.B_arc), CENTRES, name="c-arc-B"))
    body += [Line(P(rk.A)[0], P(K)[0], PROJECTION, name=f"c-arm-{i}") for i, K in enumerate(d.K_k)]
    body += [Line(P(B)[0], P(K)[0], THIN, name=f"c-analogue-{i}") for i, (B, K) in enumerate(zip(d.B_k, d.K_k))]
    body.append(Polyline(P(d.K_curve), MAIN, name="c-curve"))
    for k, (kind, K, edge) in enumerate(d.tangents):
        t = _to_clip(K, edge, clip)
        body.append(Line(P(K)[0], P(K + t * edge)[0], DASHED, name=f"c-tangent-{kind}-{k}"))
    B0 = d.B_k[0]
    body += [Line(P(d.O)[0], P(B0)[0], LEVEL, name="c-r0"), Line(P(d.O)[0], P(rk.A)[0], THIN, name="c-a"),
             Point(P(d.O)[0], radius_mm=1.0, name="c-O"), Point(P(rk.A)[0], radius_mm=1.0, name="c-A")]
    body += [Point(q, radius_mm=0.5, name=f"c-K-{i}") for i, q in enumerate(P(d.K_k))]
    register_ink(occ, *body)
    els += body
    r0 = f"O: {nt.sym('cam.r_0')} = {nt.number(cam.pitch_base_radius, sig=4)} {nt.unit('m')}"
    for text, at, dirs, name in ((r0, P(d.O)[0], ("w", "sw", "nw", "s", "n", "e", "se", "ne"), "c-O-name"),
                                 ("A", P(rk.A)[0], ("e", "ne", "se", "n", "s", "w"), "c-A-name"),
                                 ("B_0", P(B0)[0], ("n", "nw", "ne", "w", "e", "s"), "c-B0-name")):
        lab, leader = occ.place_label_with_leader(at, text, dirs, size_mm=TEXT_MM, within=box)
        els.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name=name))
        if leader is not None:
            els.append(Line(leader[0], leader[1], THIN, name=f"{name}-leader"))
    return els, mu


def _runs(points: Array, keep: NDArray[np.bool_]) -> list[Array]:
    """The stretches of consecutive kept points (two at least)."""
    out, start = [], None
    for i, k in enumerate([*keep.tolist(), False]):
        if k and start is None:
            start = i
        elif not k and start is not None:
            if i - start >= 2:
                out.append(points[start:i])
            start = None
    return out


def _to_clip(P0: Array, d: Array, clip: tuple[float, float, float, float]) -> float:
    """How far from P0 along d the clip rectangle ends (m; 0 when P0 is outside)."""
    ts = []
    for k, (lo, hi) in enumerate(((clip[0], clip[2]), (clip[1], clip[3]))):
        if d[k] > 0:
            ts.append((hi - P0[k]) / d[k])
        elif d[k] < 0:
            ts.append((lo - P0[k]) / d[k])
    return max(min(ts), 0.0) if ts else 0.0


__all__ = ["Rocker", "RockerDiagram", "boundary_centre", "pressure_angle", "rocker", "rocker_diagram",
           "rocker_diagram_data", "zone_boundary_r0", "zone_polygon"]
