"""The smaller flywheel formulas of the lectures: J_F from the work between the two extreme
positions (the lecture's formula (90)), the J_F–[δ] hyperbola, Artobolevsky's χ ≈ 2δ/Δφ and
tan μ = ε/ω².

Formula (90). Let φ_j be the position of ω_min and φ_k that of ω_max, A_jk = ∫_{φ_j}^{φ_k} M_e dφ the
work of the reduced moment between them (J), J_j, J_k the mechanism's reduced inertia there. The
kinetic energy theorem gives A_jk = ½(J_F + J_k)ω_max² − ½(J_F + J_j)ω_min², and with the textbook
mean ω_max,min = ω_m(1 ± δ/2), ω_max² − ω_min² = 2δω_m² exactly, so

    J_F = (A_jk − ½J_k ω_max² + ½J_j ω_min²) / (δ ω_m²).

For a constant J_e (J_j = J_k = J_e) this is A_jk/(δω_m²) − J_e, and A_jk is then ΔW_max: the
approximate method's J_F = ΔW_max/(ω_m²[δ]) − J_e. W1 (ΔW_max = 575 J, 600 rev/min, [δ] = 1/300):

>>> import math
>>> w = 600 * math.pi / 30
>>> round(flywheel_from_work(575.0, J_j=0.0, J_k=0.0, omega_m=w, delta=1 / 300), 2)
43.69
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from graphmethods.errors import InputError
from graphmethods.units import finite_result, real


def flywheel_from_work(A_jk: float, *, J_j: float, J_k: float, omega_m: float, delta: float) -> float:
    """J_F (kg·m²) by the lecture's formula (90) from the work A_jk (J) between the position of
    ω_min (J_e = J_j) and that of ω_max (J_e = J_k), for ω_m (rad/s) and [δ].

    >>> round(flywheel_from_work(100.0, J_j=2.0, J_k=2.0, omega_m=10.0, delta=0.1), 6)
    8.0
    """
    A = real(A_jk, "A_jk", tiny_ok=True)
    Jj = real(J_j, "J_j", lo=0.0, tiny_ok=True)
    Jk = real(J_k, "J_k", lo=0.0, tiny_ok=True)
    w = real(omega_m, "omega_m", lo=0.0, lo_open=True)
    d = real(delta, "delta", lo=0.0, lo_open=True, hi=2.0, hi_open=True)
    w_max, w_min = w * (1.0 + d / 2.0), w * (1.0 - d / 2.0)
    return finite_result((A - 0.5 * Jk * w_max**2 + 0.5 * Jj * w_min**2) / (d * w**2), "J_F", unit="kg·m²")


def hyperbola(delta_W_max: float, *, omega_m: float, J_e: float, deltas: ArrayLike) -> NDArray[np.float64]:
    """J_F = ΔW_max/(ω_m²δ) − J_e (kg·m²) at each δ of ``deltas``: the J_F–[δ] hyperbola.

    >>> [round(float(v), 3) for v in hyperbola(100.0, omega_m=10.0, J_e=0.5, deltas=[0.1, 0.2])]
    [9.5, 4.5]
    """
    W = real(delta_W_max, "delta_W_max", lo=0.0, lo_open=True)
    w = real(omega_m, "omega_m", lo=0.0, lo_open=True)
    Je = real(J_e, "J_e", lo=0.0, tiny_ok=True)
    d = np.asarray(deltas, dtype=float)
    if d.size == 0 or not np.all(np.isfinite(d)) or not np.all((d > 0) & (d < 1)):
        raise InputError("hyperbola: every δ must be a number between 0 and 1")
    return np.asarray(W / (w**2 * d) - Je, dtype=float)


def chi_artobolevsky(delta: float, delta_phi: float) -> float:
    """Artobolevsky's estimate of the dynamic coefficient χ ≈ 2δ/Δφ (Δφ in rad, the angle from the
    position of ω_min to that of ω_max): the mean ε over Δφ, (ω_max² − ω_min²)/(2Δφ), over ω_m².

    >>> round(chi_artobolevsky(0.05, 3.141592653589793 / 2), 6)
    0.063662
    """
    d = real(delta, "delta", lo=0.0, lo_open=True)
    dphi = real(delta_phi, "delta_phi", lo=0.0, lo_open=True, hint="the angle from ω_min to ω_max, rad")
    return 2.0 * d / dphi


def tan_mu(epsilon: ArrayLike, omega: ArrayLike) -> NDArray[np.float64]:
    """tan μ = ε/ω²: the angle μ between a point's total acceleration and the radius to it.

    >>> [float(x) for x in tan_mu([2.0, -4.0], [2.0, 2.0])]
    [0.5, -1.0]
    """
    e, w = np.asarray(epsilon, dtype=float), np.asarray(omega, dtype=float)
    if np.any(w == 0):
        raise InputError("tan μ = ε/ω² is not defined where ω = 0")
    return np.asarray(e / w**2, dtype=float)


def lecture_formulas(model: Any, exact: Any) -> dict[str, float]:
    """Formula (90), χ ≈ 2δ/Δφ, the exact χ and tan μ for a reduced model and its exact flywheel.

    Parameters
    ----------
    model : ReducedModel
        J_e(φ), M_e(φ) over one period.
    exact : FlywheelResult
        From :func:`graphmethods.dynamics.motion.exact_flywheel` for that model: its positions of
        ω_min (φ_j) and ω_max (φ_k) are the exact extreme positions.

    Returns
    -------
    dict
        ``A_jk`` (J, ∫M_e dφ from φ_j to φ_k, the period's balanced ΔE), ``J_e_j``, ``J_e_k``
        (kg·m²), ``J_F_formula_90`` (kg·m²: equals the exact J_F), ``delta_phi_deg`` (°, from φ_j
        forward to φ_k), ``chi_artobolevsky`` (2δ/Δφ), ``chi_exact`` (|ε|_max/ω_m² of the exact
        motion), ``tan_mu_max`` (max |ε|/ω² of that motion) and ``mu_max_deg`` (°).

    >>> from graphmethods.dynamics.motion import ReducedModel, exact_flywheel
    >>> model = ReducedModel(J_e=1.0, M_e=lambda p: 100.0 * np.sin(p))
    >>> ex = exact_flywheel(model, omega_m=10.0, delta=0.05)
    >>> out = lecture_formulas(model, ex)
    >>> abs(out["J_F_formula_90"] - ex.J_F) < 1e-6 * ex.J_F
    True
    """
    from graphmethods.dynamics.motion import _balanced_energy

    E = _balanced_energy(model, 1e-6)
    a, L = float(model.phi_0), float(model.phi_T)
    phi_j, phi_k = float(exact.phi_omega_min), float(exact.phi_omega_max)

    def wrap(x: float) -> float:
        return a + float(np.mod(x - a, L))

    E_j, E_k = (float(v) for v in E(np.array([wrap(phi_j), wrap(phi_k)])))
    A_jk = E_k - E_j                              # ΔE is periodic: the work forward from φ_j to φ_k
    J_j, J_k = (float(v) for v in np.asarray(model.J_e_at(np.array([phi_j, phi_k])), dtype=float).ravel())
    J_F = flywheel_from_work(A_jk, J_j=J_j, J_k=J_k, omega_m=exact.omega_m, delta=exact.delta)
    dphi = float(np.mod(phi_k - phi_j, L))
    motion = exact.motion
    tmu = np.abs(tan_mu(motion.epsilon, motion.omega))
    return {
        "A_jk": A_jk, "J_e_j": J_j, "J_e_k": J_k, "J_F_formula_90": J_F,
        "delta_phi_deg": float(np.degrees(dphi)),
        "chi_artobolevsky": chi_artobolevsky(exact.delta, dphi),
        "chi_exact": float(motion.chi),
        "tan_mu_max": float(tmu.max()),
        "mu_max_deg": float(np.degrees(np.arctan(tmu.max()))),
    }
