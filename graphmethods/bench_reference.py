"""An independent reference for the bench: the exact flywheel of an offset slider-crank press.

Written apart from the toolkit's own solver, to time it against and to check its answer: the
slider-crank in closed form, ΔE(φ) = ∫ M_e dφ by scipy's DOP853 integrator split at the load's
switch angles (rtol 1e-13), the support-line intercepts max/min of ΔE − a·J_e on a grid polished by
``scipy.optimize.minimize_scalar``, and J_F = (b_max − b_min)/(δ ω_m²) (domain.md §7).

It needs scipy, which the toolkit itself does not: ``pip install 'graphmethods[bench]'``.

>>> import json, pathlib
>>> case = json.loads((pathlib.Path(__file__).parent / "problems/data/slider_crank_press.json").read_text())
>>> round(press_flywheel(case), 2)                                   # doctest: +SKIP
13.94
"""

from __future__ import annotations

import math
from collections.abc import Mapping
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


def press_flywheel(case: Mapping[str, Any], *, rtol: float = 1e-13, grid: int = 2000) -> float:
    """J_F (kg·m²) of a slider-crank press file (the format of shared/cases/slider_crank_press.json).

    Position 0 is the far dead centre; the force F0 opposes the slider on the working stroke
    (toward O) between ``force_from`` and ``force_to`` of the stroke; M_d balances it over a turn.
    """
    from scipy.integrate import solve_ivp
    from scipy.optimize import brentq, minimize_scalar

    r, l, e = case["r"], case["l"], case["e"]
    F0, f_from, f_to = case["F0"], case["force_from"], case["force_to"]
    omega_m = math.pi * case["n_rpm"] / 30.0
    delta = case["delta"]
    x_B, analogues, J_e = _slider_crank(case)
    phi0 = math.asin(e / (l + r))                    # far dead centre
    phi1 = math.pi + math.asin(e / (l - r))          # near dead centre
    x0 = float(x_B(phi0))
    H = x0 - float(x_B(phi1))
    on = brentq(lambda p: x_B(p) - (x0 - f_from * H), phi0, phi1, xtol=1e-15, rtol=1e-15)
    off = brentq(lambda p: x_B(p) - (x0 - f_to * H), phi0, phi1, xtol=1e-15, rtol=1e-15)
    M_d = F0 * H * (f_to - f_from) / (2 * math.pi)

    pieces = [(phi0, on, False), (on, off, True), (off, phi0 + 2 * math.pi, False)]
    solutions, E_start = [], 0.0
    for a, b, loaded in pieces:
        def rhs(p, y, loaded=loaded):
            return [M_d + (F0 * analogues(p)[0] if loaded else 0.0)]
        sol = solve_ivp(rhs, (a, b), [E_start], method="DOP853", rtol=rtol, atol=1e-12 * F0 * H,
                        dense_output=True)
        solutions.append((a, b, sol.sol))
        E_start = float(sol.y[0, -1])

    def E(p):
        p = np.atleast_1d(p)
        out = np.empty_like(p)
        for a, b, f in solutions:
            inside = (p >= a) & (p <= b)
            if inside.any():
                out[inside] = f(p[inside])[0]
        return out

    def support(alpha, sense):
        g = lambda p: sense * (E(p) - alpha * J_e(p))          # noqa: E731
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
