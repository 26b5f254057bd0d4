"""An independent reference for the bench: the exact flywheel of the course linkages.

Written apart from the toolkit's own solver, to time it against and to check its answer: each
linkage in closed form (the offset slider-crank press, the four-bar, the slotted lever, the sine
mechanism, the shaper, the six-bar press, the Whitworth mechanism, the slotting machine, the
two-slider), read from its problem file, ΔE(φ) = ∫ M_e dφ by scipy's DOP853 integrator split at the load's
switch angles (rtol 1e-13), the support-line intercepts max/min of ΔE − a·J_e on a grid polished by
``scipy.optimize.minimize_scalar``, and J_F = (b_max − b_min)/(δ ω_m²) (domain.md §7).

It needs scipy, which the toolkit itself does not: ``pip install 'graphmethods[bench]'``.

>>> import json, pathlib
>>> case = json.loads((pathlib.Path(__file__).parent / "problems/data/slider_crank_press.json").read_text())
>>> round(press_flywheel(case), 2)                                   # doctest: +SKIP
13.94
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np


def _slider_crank(case: Mapping[str, Any]):
    """Closed forms of x_B, its analogue dx_B/dφ and J_e(φ) for the press file's linkage."""
    r, l, e, k = case["r"], case["l"], case["e"], case["l_AS2"] / case["l"]
    m2, J_S2, m3, J1 = case["m2"], case["J_S2"], case["m3"], case["J1"]

    def x_B(phi):
        q = e - r * np.sin(phi)
        return r * np.cos(phi) + np.sqrt(l * l - q * q)

    def analogues(phi):
        c, s = np.cos(phi), np.sin(phi)
        q = e - r * s
        w = np.sqrt(l * l - q * q)
        vB = -r * s + q * r * c / w                  # dx_B/dφ
        w2 = -r * c / w                               # ω2/ω1
        vSx = -r * s + k * (vB + r * s)
        vSy = r * c - k * r * c
        return vB, w2, vSx, vSy

    def J_e(phi):
        vB, w2, vSx, vSy = analogues(phi)
        return J1 + m2 * (vSx * vSx + vSy * vSy) + J_S2 * w2 * w2 + m3 * vB * vB

    return x_B, analogues, J_e


def _support_line_flywheel(J_e: Callable[[np.ndarray], np.ndarray],
                           pieces: Sequence[tuple[float, float, Callable[[float], float]]], *, omega_m: float,
                           delta: float, atol: float, rtol: float, grid: int) -> float:
    """J_F = (b_max − b_min)/(δ ω_m²) from J_e(φ) and M_e given on the pieces (a, b, M_e) of one period, in
    order from position 0: ΔE by DOP853 on each piece (its dense output), the intercepts b = max/min of
    ΔE − a·J_e on a grid of each piece polished by ``minimize_scalar`` (domain.md §7)."""
    from scipy.integrate import solve_ivp
    from scipy.optimize import minimize_scalar

    solutions, E_start = [], 0.0
    for a, b, M_e in pieces:
        def rhs(p: float, y: np.ndarray, M_e: Callable[[float], float] = M_e) -> list[float]:
            return [M_e(p)]
        sol = solve_ivp(rhs, (a, b), [E_start], method="DOP853", rtol=rtol, atol=atol, dense_output=True)
        solutions.append((a, b, sol.sol))
        E_start = float(sol.y[0, -1])

    def E(p: np.ndarray) -> np.ndarray:
        p = np.atleast_1d(p)
        out = np.empty_like(p)
        for a, b, f in solutions:
            inside = (p >= a) & (p <= b)
            if inside.any():
                out[inside] = f(p[inside])[0]
        return out

    def support(alpha: float, sense: int) -> float:
        def g(p: np.ndarray) -> np.ndarray:
            return sense * (E(p) - alpha * J_e(p))
        best = -math.inf
        for a, b, _ in solutions:                             # the switch angles are candidates too
            x = np.linspace(a, b, max(8, int(grid * (b - a) / (2 * math.pi))))
            gx = g(x)
            i = int(np.argmax(gx))
            best = max(best, float(gx[i]))
            lo, hi = x[max(i - 1, 0)], x[min(i + 1, x.size - 1)]
            if hi > lo:
                res = minimize_scalar(lambda p: -float(g(np.array([p]))[0]), bounds=(lo, hi), method="bounded",
                                      options={"xatol": 1e-12})
                best = max(best, -float(res.fun))
        return sense * best

    a_max = 0.5 * (omega_m * (1 + delta / 2)) ** 2
    a_min = 0.5 * (omega_m * (1 - delta / 2)) ** 2
    return (support(a_max, +1) - support(a_min, -1)) / (delta * omega_m**2)


def press_flywheel(case: Mapping[str, Any], *, rtol: float = 1e-13, grid: int = 2000) -> float:
    """J_F (kg·m²) of a slider-crank press file (the format of shared/cases/slider_crank_press.json).

    Position 0 is the far dead centre; the force F0 opposes the slider on the working stroke
    (toward O) between ``force_from`` and ``force_to`` of the stroke; M_d balances it over a turn.
    """
    from scipy.optimize import brentq

    r, l, e = case["r"], case["l"], case["e"]
    F0, f_from, f_to = case["F0"], case["force_from"], case["force_to"]
    x_B, analogues, J_e = _slider_crank(case)
    phi0 = math.asin(e / (l + r))                    # far dead centre
    phi1 = math.pi + math.asin(e / (l - r))          # near dead centre
    x0 = float(x_B(phi0))
    H = x0 - float(x_B(phi1))
    on = brentq(lambda p: x_B(p) - (x0 - f_from * H), phi0, phi1, xtol=1e-15, rtol=1e-15)
    off = brentq(lambda p: x_B(p) - (x0 - f_to * H), phi0, phi1, xtol=1e-15, rtol=1e-15)
    M_d = F0 * H * (f_to - f_from) / (2 * math.pi)

    def free(p: float) -> float:
        return M_d

    def loaded(p: float) -> float:
        return M_d + F0 * float(analogues(p)[0])

    pieces = [(phi0, on, free), (on, off, loaded), (off, phi0 + 2 * math.pi, free)]
    return _support_line_flywheel(J_e, pieces, omega_m=math.pi * case["n_rpm"] / 30.0, delta=case["delta"],
                                  atol=1e-12 * F0 * H, rtol=rtol, grid=grid)


def _four_bar(case: Mapping[str, Any]) -> tuple[Callable[[Any], tuple[Any, ...]], float]:
    """The crank-rocker four-bar in closed form (real arithmetic on x, y, so that a complex step gives its
    derivatives exactly): φ ↦ (A, B, S2, S3) as (x, y) pairs, and the branch sign that puts B above O1O2."""
    l1, l2, l3, l4 = case["l1"], case["l2"], case["l3"], case["l4"]
    g = math.radians(case.get("ground_angle_deg", 0.0))
    O2x, O2y = l1 * math.cos(g), l1 * math.sin(g)
    k2, k3 = case["l_AS2"] / l3, case["l_O2S3"] / l4

    def points(phi: Any, branch: float) -> tuple[Any, ...]:
        Ax, Ay = l2 * np.cos(phi), l2 * np.sin(phi)
        dx, dy = O2x - Ax, O2y - Ay
        D2 = dx * dx + dy * dy
        D = np.sqrt(D2)
        ca = (l3 * l3 + D2 - l4 * l4) / (2 * l3 * D)
        sa = branch * np.sqrt(1 - ca * ca)
        ux, uy = dx / D, dy / D
        Bx, By = Ax + l3 * (ux * ca - uy * sa), Ay + l3 * (uy * ca + ux * sa)
        return (Ax, Ay), (Bx, By), (Ax + k2 * (Bx - Ax), Ay + k2 * (By - Ay)), \
            (O2x + k3 * (Bx - O2x), O2y + k3 * (By - O2y))

    # B above the ground line where the crank is along it, past O2's side
    (_, (Bx, By), _, _) = points(g, 1.0)
    branch = 1.0 if (-math.sin(g) * Bx + math.cos(g) * By) > 0 else -1.0
    return (lambda phi: points(phi, branch)), branch


def _roots(f: Callable[[float], float]) -> list[float]:
    """The roots of f over one turn [0, 2π): sign changes on a 1/2° grid, polished by brentq."""
    from scipy.optimize import brentq

    xs = np.linspace(0.0, 2 * math.pi, 721)
    fs = np.array([f(x) for x in xs])
    return [float(brentq(f, xs[i], xs[i + 1], xtol=1e-15, rtol=1e-15))
            for i in np.flatnonzero(np.sign(fs[:-1]) != np.sign(fs[1:]))]


def _moment_on_rocker(case: Mapping[str, Any], *, extremes: tuple[float, float], rocker_angle: Callable[[float], float],
                      omega_rocker: Callable[[float], float], J_e: Callable[[np.ndarray], np.ndarray], rtol: float,
                      grid: int) -> float:
    """J_F of a crank turning counterclockwise and a rocker that swings between the crank angles ``extremes``:
    position 0 starts the slow (working) swing, the larger crank angle; M3 resists the rocker's rotation on
    it between ``moment_from`` and ``moment_to`` of the swing; M_d balances it over a turn."""
    from scipy.optimize import brentq

    p1, p2 = extremes
    swing = (p2 - p1) % (2 * math.pi)
    phi0, work = (p1, swing) if swing > math.pi else (p2, 2 * math.pi - swing)
    psi0 = rocker_angle(phi0)
    psi_max = abs(rocker_angle(phi0 + work) - psi0)

    def psi(p: float) -> float:
        return abs(rocker_angle(p) - psi0)

    M3, f_from, f_to = case["M3"], case["moment_from"], case["moment_to"]
    on = phi0 if f_from == 0 else brentq(lambda p: psi(p) - f_from * psi_max, phi0, phi0 + work, xtol=1e-15)
    off = phi0 + work if f_to == 1 else brentq(lambda p: psi(p) - f_to * psi_max, phi0, phi0 + work, xtol=1e-15)
    M_d = M3 * psi_max * (f_to - f_from) / (2 * math.pi)

    def free(p: float) -> float:
        return M_d

    def loaded(p: float) -> float:
        return M_d - M3 * abs(omega_rocker(p))

    pieces = [(a, b, f) for a, b, f in ((phi0, on, free), (on, off, loaded), (off, phi0 + 2 * math.pi, free))
              if b > a]
    return _support_line_flywheel(J_e, pieces, omega_m=math.pi * case["n_rpm"] / 30.0, delta=case["delta"],
                                  atol=1e-3 * rtol * M3 * psi_max, rtol=rtol, grid=grid)


#: the complex step of the velocity analogues (exact derivatives of a closed form written in real arithmetic)
_H = 1e-30


def four_bar_flywheel(case: Mapping[str, Any], *, rtol: float = 1e-13, grid: int = 2000) -> float:
    """J_F (kg·m²) of a crank-rocker four-bar file (``four_bar_rocker.json``), the load on the rocker's slow
    swing (:func:`_moment_on_rocker`); velocity analogues by complex steps of the closed form."""
    l1, l3, l4 = case["l1"], case["l3"], case["l4"]
    g = math.radians(case.get("ground_angle_deg", 0.0))
    points, _ = _four_bar(case)
    O2 = (l1 * math.cos(g), l1 * math.sin(g))

    def rocker_angle(phi: float) -> float:
        (_, (Bx, By), _, _) = points(phi)
        return math.atan2(By - O2[1], Bx - O2[0])

    def analogues(phi: Any) -> tuple[Any, ...]:
        (Ax, Ay), (Bx, By), (S2x, S2y), (S3x, S3y) = points(np.asarray(phi) + 1j * _H)
        vS2x, vS2y, vS3x, vS3y = (c.imag / _H for c in (S2x, S2y, S3x, S3y))
        ex, ey = (Bx - Ax).real, (By - Ay).real
        w3 = (ex * (By - Ay).imag - ey * (Bx - Ax).imag) / _H / (l3 * l3)
        fx, fy = Bx.real - O2[0], By.real - O2[1]
        w4 = (fx * By.imag - fy * Bx.imag) / _H / (l4 * l4)
        return vS2x, vS2y, vS3x, vS3y, w3, w4

    def J_e(phi: np.ndarray) -> np.ndarray:
        vS2x, vS2y, vS3x, vS3y, w3, w4 = analogues(np.atleast_1d(phi))
        J: np.ndarray = (case["J1"] + case["m2"] * (vS2x**2 + vS2y**2) + case["J_S2"] * w3**2
                         + case["m3"] * (vS3x**2 + vS3y**2) + case["J_S3"] * w4**2)
        return J

    def in_line(p: float) -> float:                          # crank and coupler in line: A, B on a ray from O1
        (Ax, Ay), (Bx, By), _, _ = points(p)
        return float(Ax * By - Ay * Bx)

    def stretched(p: float) -> bool:
        (Ax, Ay), (Bx, By), _, _ = points(p)
        return bool(Ax * Bx + Ay * By > 0)

    roots = _roots(in_line)
    extremes = (next(p for p in roots if stretched(p)), next(p for p in roots if not stretched(p)))
    return _moment_on_rocker(case, extremes=extremes, rocker_angle=rocker_angle,
                             omega_rocker=lambda p: float(analogues(p)[5]), J_e=J_e, rtol=rtol, grid=grid)


def slotted_lever_flywheel(case: Mapping[str, Any], *, rtol: float = 1e-13, grid: int = 2000) -> float:
    """J_F (kg·m²) of a crank and oscillating slotted lever file (``slotted_lever.json``): the block at the
    crank pin A slides along the lever O3B; the load M3 on the lever's slow swing (:func:`_moment_on_rocker`).
    The lever's angle is that of O3A; its rate in closed form, ω3/ω1 = r (r − d·cos(φ − θ_O3)) / |O3A|²
    (d = O1O3), derived apart from the toolkit's vector loop."""
    r, d = case["r"], case["l_O1O3"]
    t3 = math.radians(case["theta_O3_deg"])
    O3 = (d * math.cos(t3), d * math.sin(t3))

    def rocker_angle(phi: float) -> float:
        return math.atan2(r * math.sin(phi) - O3[1], r * math.cos(phi) - O3[0])

    def w3(phi: Any) -> Any:
        q2 = r * r + d * d - 2 * r * d * np.cos(phi - t3)    # |O3A|²
        return r * (r - d * np.cos(phi - t3)) / q2

    def J_e(phi: np.ndarray) -> np.ndarray:
        w = w3(np.atleast_1d(phi))
        J: np.ndarray = (case["J1"] + case["m2"] * r * r
                         + (case["J_S3"] + case["m3"] * case["l_O3S3"] ** 2) * w * w)
        return J

    def tangent(p: float) -> float:                           # the lever touches the crank circle: O1A ⟂ O3A
        return float(r * r - r * (O3[0] * math.cos(p) + O3[1] * math.sin(p)))

    p1, p2 = _roots(tangent)
    return _moment_on_rocker(case, extremes=(p1, p2), rocker_angle=rocker_angle, omega_rocker=lambda p: float(w3(p)),
                             J_e=J_e, rtol=rtol, grid=grid)


def scotch_yoke_flywheel(case: Mapping[str, Any], *, rtol: float = 1e-13, grid: int = 2000) -> float:
    """J_F (kg·m²) of the sine mechanism file (``scotch_yoke_pump.json``): the yoke at x_C = r cos φ carries
    the force F against it on one stroke (``from``…``to`` of it), the block at A turns with the crank pin:
    J_e = J1 + m2 r² + m3 r² sin²φ. J_e repeats every half turn, so which stroke is loaded does not change J_F.
    """
    from scipy.optimize import brentq

    r = case["crank"]["r"]
    masses, load = case["masses"], case["load"]
    J1, m2, m3 = masses["1"]["J"], masses["2"]["m"], masses["3"]["m"]
    F, f_from, f_to = load["force"], load["from"], load["to"]

    def J_e(phi: np.ndarray) -> np.ndarray:
        s = np.sin(np.atleast_1d(phi))
        J: np.ndarray = J1 + m2 * r * r + m3 * r * r * s * s
        return J

    def stroke(p: float) -> float:                            # the fraction of the stroke from x = r
        return (1 - math.cos(p)) / 2
    on = 0.0 if f_from == 0 else brentq(lambda p: stroke(p) - f_from, 0.0, math.pi, xtol=1e-15)
    off = math.pi if f_to == 1 else brentq(lambda p: stroke(p) - f_to, 0.0, math.pi, xtol=1e-15)
    M_d = F * 2 * r * (f_to - f_from) / (2 * math.pi)

    def free(p: float) -> float:
        return M_d

    def loaded(p: float) -> float:
        return M_d - F * r * abs(math.sin(p))

    pieces = [(a, b, f) for a, b, f in ((0.0, on, free), (on, off, loaded), (off, 2 * math.pi, free)) if b > a]
    return _support_line_flywheel(J_e, pieces, omega_m=math.pi * case["n_rpm"] / 30.0, delta=case["delta"],
                                  atol=1e-3 * rtol * F * r, rtol=rtol, grid=grid)


# --------------------------------------------------------------------- the slider (ram) linkages
#: a point in real arithmetic (x, y): floats, arrays, or complex-stepped arrays
XY = tuple[Any, Any]



def _sqrt(x: Any) -> Any:
    """√x of a scalar in Python arithmetic (one step along the ODE: numpy's 0-d arrays cost ~1 µs an operation),
    else numpy's."""
    return cmath.sqrt(x) if type(x) is complex else math.sqrt(x) if type(x) is float else np.sqrt(x)


def _cos(x: Any) -> Any:
    """cos x, as :func:`_sqrt` chooses."""
    return cmath.cos(x) if type(x) is complex else math.cos(x) if type(x) is float else np.cos(x)


def _sin(x: Any) -> Any:
    """sin x, as :func:`_sqrt` chooses."""
    return cmath.sin(x) if type(x) is complex else math.sin(x) if type(x) is float else np.sin(x)


def _crank_pin(case: Mapping[str, Any], phi: Any, centre: XY = (0.0, 0.0)) -> XY:
    """The crank pin A = O1 + r·e^{iφ} (the crank turns counterclockwise from +x)."""
    r = case["crank"]["r"] if "crank" in case else case["r"]
    return centre[0] + r * _cos(phi), centre[1] + r * _sin(phi)


def _along(P: XY, Q: XY, distance: float, *, length: Any = None, angle: float = 0.0) -> XY:
    """The point ``distance`` from P along P→Q turned by ``angle`` (rad); ``length`` is |PQ| when known."""
    dx, dy = Q[0] - P[0], Q[1] - P[1]
    n = _sqrt(dx * dx + dy * dy) if length is None else length
    c, s = math.cos(angle), math.sin(angle)
    return P[0] + distance * (c * dx - s * dy) / n, P[1] + distance * (s * dx + c * dy) / n


def _slider_on_line(P: XY, through: XY, angle: float, l: float, branch: float) -> XY:
    """The slider C on the line through ``through`` at ``angle`` (rad) joined to P by a rod of length l:
    C = F + σ·√(l² − h²)·u with F the foot of P, h its distance from the line, σ the branch (+1 ahead).

    >>> tuple(round(c, 12) for c in _slider_on_line((0.0, 0.3), (0.0, 0.0), 0.0, 0.5, 1.0))   # 3-4-5 triangle
    (0.4, 0.0)
    """
    ux, uy = math.cos(angle), math.sin(angle)
    Rx, Ry = P[0] - through[0], P[1] - through[1]
    h = ux * Ry - uy * Rx
    s = ux * Rx + uy * Ry + branch * _sqrt(l * l - h * h)
    return through[0] + s * ux, through[1] + s * uy


def _dyad_rrr(P: XY, Q: XY, l_PC: float, l_QC: float, branch: float) -> XY:
    """The joint C of links P–C and Q–C (two circles), on the left of P→Q for branch +1.

    >>> tuple(round(float(c), 12) for c in _dyad_rrr((0.0, 0.0), (2.0, 0.0), 1.25, 1.25, 1.0))
    (1.0, 0.75)
    """
    dx, dy = Q[0] - P[0], Q[1] - P[1]
    D2 = dx * dx + dy * dy
    D = _sqrt(D2)
    a = (l_PC * l_PC - l_QC * l_QC + D2) / (2 * D)
    h = branch * _sqrt(l_PC * l_PC - a * a)
    ex, ey = dx / D, dy / D
    return P[0] + a * ex - h * ey, P[1] + a * ey + h * ex


def _point_analogues(points: Callable[[Any], dict[str, XY]], phi: Any) -> dict[str, tuple[Any, Any, Any, Any]]:
    """Every point's (x, y, dx/dφ, dy/dφ) at ``phi``: one evaluation of the closed form at φ + i·h."""
    P = points(complex(phi, _H) if isinstance(phi, float) else np.asarray(phi, dtype=float) + 1j * _H)
    return {k: (x.real, y.real, x.imag / _H, y.imag / _H) for k, (x, y) in P.items()}


def _reduced_inertia(points: Callable[[Any], dict[str, XY]], J1: float,
                     parts: Sequence[tuple[str, tuple[str, str] | None, float, float]]
                     ) -> Callable[[np.ndarray], np.ndarray]:
    """J_e(φ) = J1 + Σ m·v_S² + J·ω² (per ω1²) for parts (S, (P, Q) whose direction is the link's or None,
    m, J): ω/ω1 of a link is (e × de/dφ)/|e|² of its vector e = Q − P."""
    def J_e(phi: np.ndarray) -> np.ndarray:
        one = np.size(phi) == 1                              # the polish asks one angle at a time: Python scalars
        p = _point_analogues(points, float(np.ravel(phi)[0]) if one else np.atleast_1d(phi))
        J: Any = float(J1)
        for S, link, m, J_S in parts:
            _, _, vx, vy = p[S]
            J = J + m * (vx * vx + vy * vy)
            if link is not None and J_S:
                x0, y0, vx0, vy0 = p[link[0]]
                x1, y1, vx1, vy1 = p[link[1]]
                ex, ey, dex, dey = x1 - x0, y1 - y0, vx1 - vx0, vy1 - vy0
                w = (ex * dey - ey * dex) / (ex * ex + ey * ey)
                J = J + J_S * w * w
        return np.full(1, J) if one else np.asarray(J)
    return J_e


def _turn_roots(f: Callable[[Any], Any]) -> list[float]:
    """The roots over one turn [0, 2π) of a vectorised f: sign changes on a 1/4° grid (one call), brentq."""
    from scipy.optimize import brentq

    xs = np.linspace(0.0, 2 * math.pi, 1441)
    fs = np.asarray(f(xs))
    exact = [float(xs[i]) for i in np.flatnonzero(fs[:-1] == 0)]     # a root on the grid (symmetric linkages)
    return sorted(exact + [float(brentq(lambda p: float(f(p)), xs[i], xs[i + 1], xtol=1e-15, rtol=1e-15))
                           for i in np.flatnonzero(fs[:-1] * fs[1:] < 0)])


def _force_on_slider(points: Callable[[Any], dict[str, XY]], *, out: str, axis: tuple[float, float],
                     J_e: Callable[[np.ndarray], np.ndarray], load: tuple[float, float, float], stroke: str,
                     n_rpm: float, delta: float, rtol: float, grid: int) -> float:
    """J_F of a counterclockwise crank driving the slider ``out`` along the guide direction ``axis``; the
    load (F, from, to) opposes it on the working stroke (``"slow"``: the one of the larger crank angle;
    ``"toward_crank"``: from the far dead centre) between those fractions of the stroke; M_d balances it."""
    from scipy.optimize import brentq

    def s(p: Any) -> Any:                                   # the slider's coordinate along its guide
        x, y = points(float(p) if np.ndim(p) == 0 else np.asarray(p, dtype=float))[out]
        return axis[0] * x + axis[1] * y

    def ds(p: Any) -> Any:                                  # its analogue ds/dφ
        x, y, vx, vy = _point_analogues(points, float(p) if np.ndim(p) == 0 else p)[out]
        return axis[0] * vx + axis[1] * vy

    p1, p2 = _turn_roots(ds)
    if stroke == "slow":
        start = p1 if (p2 - p1) % (2 * math.pi) > math.pi else p2
    else:                                                   # toward the crank: from the farther dead centre

        def far(p: float) -> float:
            x, y = points(float(p))[out]
            return float(x * x + y * y)
        start = p1 if far(p1) > far(p2) else p2
    end = p2 if start == p1 else p1
    work = (end - start) % (2 * math.pi)
    s0 = float(s(start))
    H = abs(float(s(end)) - s0)
    sign = 1.0 if float(s(end)) > s0 else -1.0
    F, f_from, f_to = load

    def frac(p: float) -> float:
        return sign * (float(s(p)) - s0) / H

    on = start if f_from == 0 else brentq(lambda p: frac(p) - f_from, start, start + work, xtol=1e-15, rtol=1e-15)
    off = start + work if f_to == 1 else brentq(lambda p: frac(p) - f_to, start, start + work, xtol=1e-15,
                                                rtol=1e-15)
    M_d = F * H * (f_to - f_from) / (2 * math.pi)

    def free(p: float) -> float:
        return M_d

    def loaded(p: float) -> float:
        return M_d - F * abs(float(ds(p)))

    pieces = [(a, b, f) for a, b, f in ((start, on, free), (on, off, loaded), (off, start + 2 * math.pi, free))
              if b > a]
    return _support_line_flywheel(J_e, pieces, omega_m=math.pi * n_rpm / 30.0, delta=delta,
                                  atol=1e-3 * rtol * F * H, rtol=rtol, grid=grid)


def shaper_flywheel(case: Mapping[str, Any], *, rtol: float = 1e-13, grid: int = 2000) -> float:
    """J_F (kg·m²) of a shaper file (``shaper.json``): the block at the crank pin A slides along the lever
    O3B (B = O3 + l_O3B·(A − O3)/|O3A|), the link BC drives the ram C on y = y_guide ahead of B's foot
    (x_C = x_B + √(l_BC² − (y_guide − y_B)²)); F0 on C over the slow stroke (``force_from``…``force_to``)."""
    d, t3 = case["l_O1O3"], math.radians(case.get("theta_O3_deg", -90.0))
    O3 = (d * math.cos(t3), d * math.sin(t3))
    branch = float(case.get("assembly", 1))

    def points(phi: Any) -> dict[str, XY]:
        A = _crank_pin(case, phi)
        B = _along(O3, A, case["l_O3B"])
        C = _slider_on_line(B, (0.0, case["y_guide"]), 0.0, case["l_BC"], branch)
        return {"O1": (0.0 * phi, 0.0 * phi), "O3": (0.0 * phi + O3[0], 0.0 * phi + O3[1]), "A": A, "B": B, "C": C,
                "S3": _along(O3, A, case["l_O3S3"]), "S4": _along(B, C, case["l_BS4"], length=case["l_BC"])}

    J_e = _reduced_inertia(points, case["J1"], [("A", None, case["m2"], 0.0),
                                                ("S3", ("O3", "B"), case["m3"], case["J_S3"]),
                                                ("S4", ("B", "C"), case["m4"], case["J_S4"]),
                                                ("C", None, case["m5"], 0.0)])
    return _force_on_slider(points, out="C", axis=(1.0, 0.0), J_e=J_e,
                            load=(case["F0"], case["force_from"], case["force_to"]),
                            stroke=case.get("working_stroke", "slow"), n_rpm=case["n_rpm"], delta=case["delta"],
                            rtol=rtol, grid=grid)


def _file_point(case: Mapping[str, Any], name: str, P: dict[str, XY], origin_to: str) -> XY:
    """An extra point of a linkage file (``points``: link, from, distance, angle_deg) from its origin along the
    link's direction origin → ``origin_to`` (for these linkages the link's own direction)."""
    p = case["points"][name]
    return _along(P[p["from"]], P[origin_to], p["distance"], angle=math.radians(p.get("angle_deg", 0.0)))


def _guide(group: Mapping[str, Any]) -> tuple[XY, float, float, float]:
    """An RRP group's guide of a linkage file: (a point on it, its angle in rad, the rod's length, the branch)."""
    g = group["guide"]
    return ((g["through"][0], g["through"][1]), math.radians(g.get("angle_deg", 0.0)),
            group["l"], float(group.get("branch", 1)))


def _file_slider_flywheel(case: Mapping[str, Any], points: Callable[[Any], dict[str, XY]],
                          links: Mapping[str, tuple[str, str] | None], *, rtol: float, grid: int) -> float:
    """J_F of a linkage file whose load is a force on a slider (the output): the masses of the file's links
    (``links`` gives each link's direction as a pair of points, None for a slider or block), its load and
    working stroke, the crank counterclockwise."""
    masses, load = case["masses"], case["load"]
    parts = [(mass["at"], links[k], mass.get("m", 0.0), mass.get("J", 0.0)) for k, mass in masses.items()
             if k != "1"]
    J_e = _reduced_inertia(points, masses["1"]["J"], parts)
    out = load["on"]
    group = next(g for g in case["groups"] if g.get("C") == out)
    angle = math.radians(group["guide"].get("angle_deg", 0.0))
    return _force_on_slider(points, out=out, axis=(math.cos(angle), math.sin(angle)), J_e=J_e,
                            load=(load["force"], load["from"], load["to"]),
                            stroke=case.get("working_stroke", "slow"), n_rpm=case["n_rpm"], delta=case["delta"],
                            rtol=rtol, grid=grid)


def _const(phi: Any, P: Sequence[float]) -> XY:
    """A fixed point shaped like φ."""
    return 0.0 * phi + P[0], 0.0 * phi + P[1]


def six_bar_press_flywheel(case: Mapping[str, Any], *, rtol: float = 1e-13, grid: int = 2000) -> float:
    """J_F (kg·m²) of the six-bar press file (``six_bar_press.json``): crank O1A, coupler AB and rocker O2B
    (B the meeting of two circles, left of A→O2), the rocker's arm O2C, link CD and the ram D on its guide."""
    rrr, rrp = case["groups"]
    O1, O2 = case["fixed"]["O1"], case["fixed"]["O2"]
    through, angle, l, branch = _guide(rrp)

    def points(phi: Any) -> dict[str, XY]:
        P = {"O1": _const(phi, O1), "O2": _const(phi, O2), "A": _crank_pin(case, phi, tuple(O1))}
        P["B"] = _dyad_rrr(P["A"], P["O2"], rrr["l_PC"], rrr["l_QC"], float(rrr.get("branch", 1)))
        P["C"] = _file_point(case, "C", P, "B")
        P["D"] = _slider_on_line(P["C"], through, angle, l, branch)
        P.update(S2=_file_point(case, "S2", P, "B"), S3=_file_point(case, "S3", P, "B"),
                 S4=_file_point(case, "S4", P, "D"))
        return P

    return _file_slider_flywheel(case, points, {"2": ("A", "B"), "3": ("O2", "B"), "4": ("C", "D"), "5": None},
                                 rtol=rtol, grid=grid)


def _slotted_lever_ram(case: Mapping[str, Any], rtol: float, grid: int) -> float:
    """J_F of a crank, a block at A in the slot of the lever O3 (its direction O3→A), a link from the lever's
    point B to the ram C on its guide: the Whitworth and slotting-machine files."""
    _, rrp = case["groups"]
    O1, O3 = case["fixed"]["O1"], case["fixed"]["O3"]
    through, angle, l, branch = _guide(rrp)

    def points(phi: Any) -> dict[str, XY]:
        P = {"O1": _const(phi, O1), "O3": _const(phi, O3), "A": _crank_pin(case, phi, tuple(O1))}
        P["B"] = _file_point(case, "B", P, "A")
        P["C"] = _slider_on_line(P["B"], through, angle, l, branch)
        P.update(S3=_file_point(case, "S3", P, "A"), S4=_file_point(case, "S4", P, "C"))
        return P

    return _file_slider_flywheel(case, points, {"2": None, "3": ("O3", "A"), "4": ("B", "C"), "5": None},
                                 rtol=rtol, grid=grid)


def whitworth_flywheel(case: Mapping[str, Any], *, rtol: float = 1e-13, grid: int = 2000) -> float:
    """J_F (kg·m²) of the Whitworth file (``whitworth_quick_return.json``): the crank longer than O1O3 turns
    the slotted link fully; its arm O3B (opposite the slot) drives the ram by the link BC."""
    return _slotted_lever_ram(case, rtol, grid)


def slotting_machine_flywheel(case: Mapping[str, Any], *, rtol: float = 1e-13, grid: int = 2000) -> float:
    """J_F (kg·m²) of the slotting-machine file (``slotting_machine.json``): an oscillating slotted lever
    O3B and the link BC driving the ram C on the vertical guide."""
    return _slotted_lever_ram(case, rtol, grid)


def two_slider_flywheel(case: Mapping[str, Any], *, rtol: float = 1e-13, grid: int = 2000) -> float:
    """J_F (kg·m²) of the two-slider file (``two_slider_compressor.json``): rods AB and AC from the one crank
    pin to the pistons B and C on their guides; the force on the piston the load names."""
    g1, g2 = case["groups"]
    O = case["fixed"][case["crank"]["centre"]]

    def points(phi: Any) -> dict[str, XY]:
        P = {"A": _crank_pin(case, phi, tuple(O))}
        for g in (g1, g2):
            through, angle, l, branch = _guide(g)
            P[g["C"]] = _slider_on_line(P["A"], through, angle, l, branch)
        P.update(S2=_file_point(case, "S2", P, g1["C"]), S4=_file_point(case, "S4", P, g2["C"]))
        return P

    return _file_slider_flywheel(case, points, {"2": ("A", g1["C"]), "3": None, "4": ("A", g2["C"]), "5": None},
                                 rtol=rtol, grid=grid)
