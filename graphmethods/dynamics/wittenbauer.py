"""The Wittenbauer energy–mass diagram: tangent rays at ψ_max, ψ_min and the flywheel from kl.

For positions 0…m the points (x_k, y_k) = (J_e(φ_k)/μ_J, ΔT(φ_k)/μ_T) (mm) form a closed curve.
From the unknown origin O1 (total inertia and total kinetic energy zero) a ray to a point makes
tan ψ = (μ_J/(2μ_T)) ω², so the speed limits give two directions (domain.md §7):

    tan ψ_max = (μ_J/(2μ_T)) ω_m² (1 + δ/2)²,   tan ψ_min = (μ_J/(2μ_T)) ω_m² (1 − δ/2)²

(or the textbook's (1 ± δ)). The upper ray at ψ_max supports the curve from above, the lower one at
ψ_min from below; they cut the segment kl on the ordinate axis (x = 0, J_e = 0), and

    J_F = μ_T · kl / (ω_m² δ).

How it is computed here
-----------------------
Exactly, as support lines of the point set, in physical units: with a = ½ω_max² (the slope of the
upper ray in J/(kg·m²)) the upper intercept is b_max = max_k [ΔT_k − a J_k]; the lower one
b_min = min_k [ΔT_k − a' J_k]. To keep the constant part of J_e out of the rounding, J_k is taken
relative to J_ref = min_k J_k, and the difference of the two slopes, a − a' = δ ω_m² for both
forms of the tangents, is used in closed form: the difference of two nearly equal tangents is
never formed, and O1 is never constructed to get J_F. For constant J_e (a vertical line) this is
literally J_F = ΔW_max/(ω_m² δ) − J_e. The result is the discrete (vertex) form of the exact
solver's support-line identity (:func:`graphmethods.dynamics.motion.exact_flywheel`), so as m grows
it converges to the exact J_F; on nested position sets it grows monotonically towards it.

If the abscissa carries only the variable part of J_e (J_e − J_c), the J_F found includes the
constant part J_c: the flywheel to add is then J_F − J_c.

>>> import numpy as np
>>> phi = np.linspace(0, 2 * np.pi, 13)
>>> res = wittenbauer(J_e=np.full(13, 2.0), delta_T=100 * np.sin(phi), omega_m=10.0, delta=0.05,
...                   mu_J=0.01, mu_T=2.0)
>>> round(res.J_F, 9)                      # ΔW_max/(ω_m² δ) − J_e = 200/5 − 2
38.0
>>> res.index_omega_max, res.index_omega_min
((3,), (9,))
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from graphmethods.dynamics.motion import TWO_PI, ReducedModel, _balanced_energy, _check_count, _check_positive, _frozen
from graphmethods.errors import InputError, NoFlywheelNeeded, UnbalancedCycleError
from graphmethods.kinematics.vectors import FloatArray
from graphmethods.units import DELTA_MAX, MAGNITUDE_MAX

__all__ = ["Tangency", "WittenbauerResult", "wittenbauer", "wittenbauer_from_model"]


@dataclass(frozen=True)
class Tangency:
    """Where a ray touches the curve: one vertex, or consecutive vertices along a straight stretch.

    Attributes
    ----------
    indices : tuple of int
        Position numbers (0…m−1) on the ray, in order along the curve.
    phi : tuple of float
        Their angles, rad.
    kind : str
        ``"point"`` (one vertex: a smooth touch or a corner) or ``"segment"`` (the ray runs along
        the chords between consecutive vertices).
    """

    indices: tuple[int, ...]
    phi: tuple[float, ...]
    kind: str


@dataclass(frozen=True, eq=False)
class WittenbauerResult:
    """The energy–mass diagram, its tangent rays and the flywheel.

    Attributes
    ----------
    x_mm, y_mm : ndarray
        The curve's points for positions 0…m (m + 1 points; the last closes on the first), mm.
    phi : ndarray
        Angles of positions 0…m, rad.
    mu_J, mu_T : float
        Scales, kg·m²/mm and J/mm.
    omega_m, delta : float
        Mean speed (rad/s) and coefficient of fluctuation [δ].
    tangents : str
        ``"exact"`` ((1 ± δ/2)²) or ``"textbook"`` ((1 ± δ)).
    tan_psi_max, tan_psi_min, psi_max, psi_min : float
        Slopes of the rays on paper and their angles to the abscissa (rad).
    k_mm, l_mm, kl_mm : float
        Ordinates where the upper and lower rays cut the axis x = 0, and the segment kl = k − l.
    J_F : float
        μ_T·kl/(ω_m² δ), kg·m²: the flywheel to add to J_e (see the module note when the abscissa
        carries only the variable part of J_e).
    upper, lower : tuple of Tangency
        Every point of tangency of the upper (ω_max) and lower (ω_min) ray.
    index_omega_max, index_omega_min : tuple of int
        Positions of ω_max and ω_min (all tangency vertices).
    phi_omega_max, phi_omega_min : tuple of float
        Their angles, rad.
    O1_mm : tuple of float
        Where the rays meet (x, y in mm): x = −J_F/μ_J, y = −T0/μ_T; for small δ many sheets away.
    T0 : float
        Kinetic energy where ΔT = 0, J.
    omega : ndarray
        ω at every position from the ray through O1: sqrt(2 (T0 + ΔT_k)/(J_F + J_e,k)), rad/s.
    J_F_other_tangents : float
        J_F with the other form of the tangents; ``tangents_difference`` is (other − J_F)/J_F.
    error_estimate : float or None
        Estimated J_F(exact) − J_F at this m (kg·m²), from sampling (not drafting) error; how it
        was made is in ``error_method``.
    tolerance_mm : float
        Distance from a ray within which a vertex counts as touching it.
    """

    x_mm: FloatArray
    y_mm: FloatArray
    phi: FloatArray
    mu_J: float
    mu_T: float
    omega_m: float
    delta: float
    tangents: str
    tan_psi_max: float
    tan_psi_min: float
    psi_max: float
    psi_min: float
    k_mm: float
    l_mm: float
    kl_mm: float
    J_F: float
    upper: tuple[Tangency, ...]
    lower: tuple[Tangency, ...]
    index_omega_max: tuple[int, ...]
    index_omega_min: tuple[int, ...]
    phi_omega_max: tuple[float, ...]
    phi_omega_min: tuple[float, ...]
    O1_mm: tuple[float, float]
    T0: float
    omega: FloatArray
    J_F_other_tangents: float
    tangents_difference: float
    error_estimate: float | None
    error_method: str
    tolerance_mm: float

    @property
    def m(self) -> int:
        """Number of intervals (positions 0…m)."""
        return self.x_mm.size - 1


#: indices of positions
_Index = NDArray[np.intp]
#: a ray's slope factor as a function of δ: (upper, lower)
_FACTORS: dict[str, tuple[Callable[[float], float], Callable[[float], float]]] = {
    "exact": (lambda d: (1 + d / 2) ** 2, lambda d: (1 - d / 2) ** 2),
    "textbook": (lambda d: 1 + d, lambda d: 1 - d),
}


def _groups(idx: _Index, m: int) -> list[list[int]]:
    """Split sorted vertex indices (0…m−1 of a closed curve) into cyclically consecutive runs."""
    runs = [[int(idx[0])]]
    for i in idx[1:]:
        if i == runs[-1][-1] + 1:
            runs[-1].append(int(i))
        else:
            runs.append([int(i)])
    if len(runs) > 1 and runs[0][0] == 0 and runs[-1][-1] == m - 1:
        runs[0] = runs.pop() + runs[0]
    return runs


def _sampling_gain(phi: FloatArray, c: FloatArray, period: float) -> float | None:
    """How much the supremum of the sampled function c (positions 0…m−1 of a closed curve at
    angles phi) may exceed max(c): the largest, over the vertices that are local maxima, of
    max_{x ∈ [x_{j−1}, x_{j+1}]} min(L(x), R(x)) − max(c), where L is the line through vertices
    j−2, j−1 and R the line through j+1, j+2. For a function concave near the touching vertex
    (a smooth touch, or the corner where a load switches on) the extended chords lie above it, so
    this bounds the gain; it is exact for a corner between straight stretches and over-estimates
    a smooth touch (O(h) instead of O(h²)).
    """
    n = c.size
    if n < 5:
        return None
    j = np.arange(n)
    x: Callable[[_Index], FloatArray] = lambda k: phi[k % n] + period * (k // n)   # noqa: E731 - cyclic abscissa
    v: Callable[[_Index], FloatArray] = lambda k: c[k % n]                          # noqa: E731
    top = float(c.max())
    loc = (c >= v(j - 1)) & (c >= v(j + 1))
    j = j[loc]
    xl2, xl1, xr1, xr2 = x(j - 2), x(j - 1), x(j + 1), x(j + 2)
    sl = (v(j - 1) - v(j - 2)) / (xl1 - xl2)
    sr = (v(j + 2) - v(j + 1)) / (xr2 - xr1)
    L: Callable[[FloatArray], FloatArray] = lambda t: v(j - 1) + sl * (t - xl1)    # noqa: E731
    R: Callable[[FloatArray], FloatArray] = lambda t: v(j + 1) + sr * (t - xr1)    # noqa: E731
    with np.errstate(divide="ignore", invalid="ignore"):
        xs = (v(j + 1) - v(j - 1) + sl * xl1 - sr * xr1) / (sl - sr)
    xs = np.clip(np.where(np.isfinite(xs), xs, xl1), xl1, xr1)
    best = np.maximum.reduce([np.minimum(L(t), R(t)) for t in (xl1, xr1, xs)])
    return max(float(best.max()) - top, 0.0)


@dataclass(frozen=True)
class _Support:
    """The two support lines (rays) of the curve in physical units: slopes ``a_max``, ``a_min``
    (J/(kg·m²)), the curve's values ``c_up``, ``c_lo`` against them (J, abscissa from ``J_ref``), their
    extremes ``up``, ``lo`` and ``D = up − lo``, the touching tolerance ``tol`` (J), the touching
    vertices ``i_up``, ``i_lo`` and the flywheel ``J_F`` (kg·m²)."""

    a_max: float
    a_min: float
    J_ref: float
    up: float
    lo: float
    D: float
    tol: float
    c_up: FloatArray
    c_lo: FloatArray
    i_up: _Index
    i_lo: _Index
    J_F: float


def _support(J: FloatArray, dT: FloatArray, omega_m: float, delta: float, tangents: str, rtol: float) -> _Support:
    """Intercepts and tangencies of the two support lines, in physical units (J, kg·m²)."""
    up_f, lo_f = _FACTORS[tangents]
    a_max = 0.5 * omega_m**2 * up_f(delta)
    a_min = 0.5 * omega_m**2 * lo_f(delta)
    J_ref = float(J.min())
    dJ = J - J_ref
    c_up = dT - a_max * dJ
    c_lo = dT - a_min * dJ
    up, lo = float(c_up.max()), float(c_lo.min())
    D = up - lo                                   # = (b_max − b_min) + δω_m² J_ref
    scale = max(float(np.max(np.abs(dT))), a_max * float(dJ.max()), D)
    tol = rtol * scale
    return _Support(a_max=a_max, a_min=a_min, J_ref=J_ref, up=up, lo=lo, D=D, tol=tol, c_up=c_up, c_lo=c_lo,
                    i_up=np.flatnonzero(c_up >= up - tol), i_lo=np.flatnonzero(c_lo <= lo + tol),
                    J_F=D / (omega_m**2 * delta) - J_ref)


def _check_arrays(J_e: ArrayLike, delta_T: ArrayLike, closure_rtol: float) -> tuple[FloatArray, FloatArray, int]:
    """J_e and ΔT as float columns for positions 0…m, checked (finite, J_e ≥ 0, the cycle closed), and m."""
    try:
        J: FloatArray = np.asarray(J_e, dtype=float)
        dT: FloatArray = np.asarray(delta_T, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise InputError(f"J_e and delta_T: give two columns of numbers (got {J_e!r:.60} and "
                         f"{delta_T!r:.60})") from None
    if np.abs(J).max(initial=0.0) > MAGNITUDE_MAX or np.abs(dT).max(initial=0.0) > MAGNITUDE_MAX:
        raise InputError(f"J_e and delta_T: values beyond ±{MAGNITUDE_MAX:g} are outside the range the construction "
                         f"computes with")
    if J.ndim != 1 or dT.shape != J.shape or J.size < 3:
        raise InputError(f"J_e and delta_T: give two 1-D columns of equal length m + 1 ≥ 3 for "
                         f"positions 0…m (got shapes {J.shape} and {dT.shape})")
    for name, v in (("J_e", J), ("delta_T", dT)):
        if not np.all(np.isfinite(v)):
            k = int(np.flatnonzero(~np.isfinite(v))[0])
            raise InputError(f"{name}: the value at position {k} is not finite")
    if np.any(J < 0):
        k = int(np.argmin(J))
        raise InputError(f"J_e: negative at position {k} ({J[k]!r} kg·m²); a moment of inertia is ≥ 0")
    m = J.size - 1
    span_T = max(float(np.ptp(dT)), float(np.max(np.abs(dT))), np.finfo(float).tiny)
    span_J = max(float(np.max(J)), np.finfo(float).tiny)
    rT, rJ = dT[m] - dT[0], J[m] - J[0]
    if abs(rT) > closure_rtol * span_T or abs(rJ) > closure_rtol * span_J:
        raise UnbalancedCycleError(
            f"the energy–mass curve does not close: position {m} differs from position 0 by "
            f"ΔT {rT:.6g} J and J_e {rJ:.6g} kg·m² (tolerance {closure_rtol:g} of the ranges "
            f"{span_T:.6g} J, {span_J:.6g} kg·m²); give positions 0…m of one steady cycle, the "
            f"last repeating the first")
    return J, dT, m


_ERROR_METHOD = (
    "sampling error J_F(exact) − J_F(m) (not drafting): each intercept re-estimated from the "
    "chords on either side of every touching vertex, extended to meet (a bound where the curve "
    "is locally concave: exact at a corner, an over-estimate for a smooth touch)")


def _construct(J: FloatArray, dT: FloatArray, phi: FloatArray, *, omega_m: float, delta: float, mu_J: float,
               mu_T: float, tangents: str, rtol: float) -> WittenbauerResult:
    """The construction on checked columns: the rays, their intercepts and tangencies, J_F and ω."""
    m = J.size - 1
    s = _support(J[:m], dT[:m], omega_m, delta, tangents, rtol)
    # D ≥ 0 always (take the vertex of least J_e in both extremes); D = 0 means the rays meet
    # on the curve itself, at its vertex of least J_e: zero total inertia there, no origin O1
    if s.D <= 1e-9 * max(float(np.max(np.abs(dT))), s.a_max * float(J.max()), 1e-300):
        raise NoFlywheelNeeded(
            f"no flywheel is needed: the rays meet on the curve (J_F + min J_e = "
            f"{s.D / (omega_m**2 * delta):.3g} kg·m²), so there is no origin O1; the machine's "
            f"own inertia keeps the fluctuation below δ = {delta:g}")
    other = "textbook" if tangents == "exact" else "exact"
    J_F_other = _support(J[:m], dT[:m], omega_m, delta, other, rtol).J_F
    J_F = s.J_F
    a_max, a_min, J_ref = s.a_max, s.a_min, s.J_ref
    period = float(phi[m] - phi[0])
    g_up = _sampling_gain(phi[:m], s.c_up, period)
    g_lo = _sampling_gain(phi[:m], -s.c_lo, period)
    estimate: float | None
    if g_up is None or g_lo is None:
        estimate, method = None, "none: fewer than 5 positions"
    else:
        estimate, method = (g_up + g_lo) / (omega_m**2 * delta), _ERROR_METHOD
    k_mm = (s.up - a_max * J_ref) / mu_T
    l_mm = (s.lo - a_min * J_ref) / mu_T
    kl_mm = (s.D - omega_m**2 * delta * J_ref) / mu_T
    T0 = a_max * (J_F + J_ref) - s.up
    J_tot = s.D / (omega_m**2 * delta) + (J - J_ref)         # J_F + J_e without cancellation
    omega = np.sqrt(2.0 * np.maximum(T0 + dT, 0.0) / J_tot)

    def tangencies(idx: _Index) -> tuple[Tangency, ...]:
        return tuple(Tangency(indices=tuple(r), phi=tuple(float(phi[i]) for i in r),
                              kind="point" if len(r) == 1 else "segment") for r in _groups(idx, m))

    upper, lower = tangencies(s.i_up), tangencies(s.i_lo)
    tan_max, tan_min = mu_J / mu_T * a_max, mu_J / mu_T * a_min
    return WittenbauerResult(
        x_mm=_frozen(J / mu_J), y_mm=_frozen(dT / mu_T), phi=_frozen(phi), mu_J=mu_J, mu_T=mu_T,
        omega_m=omega_m, delta=delta, tangents=tangents, tan_psi_max=tan_max, tan_psi_min=tan_min,
        psi_max=math.atan(tan_max), psi_min=math.atan(tan_min), k_mm=float(k_mm), l_mm=float(l_mm),
        kl_mm=float(kl_mm), J_F=float(J_F), upper=upper, lower=lower,
        index_omega_max=tuple(int(i) for i in s.i_up),
        index_omega_min=tuple(int(i) for i in s.i_lo),
        phi_omega_max=tuple(float(phi[i]) for i in s.i_up),
        phi_omega_min=tuple(float(phi[i]) for i in s.i_lo),
        O1_mm=(float(-J_F / mu_J), float(-T0 / mu_T)), T0=float(T0), omega=_frozen(omega),
        J_F_other_tangents=float(J_F_other), tangents_difference=float((J_F_other - J_F) / J_F),
        error_estimate=None if estimate is None else float(estimate), error_method=method,
        tolerance_mm=s.tol / mu_T)


def _check_common(omega_m: float, delta: float, mu_J: float, mu_T: float, tangents: str,
                  rtol: float) -> tuple[float, float, float, float, float]:
    """The construction's numbers checked (positive, finite; δ below DELTA_MAX) and the form of the tangents."""
    omega_m = _check_positive(omega_m, "omega_m")
    delta = _check_positive(delta, "delta")
    if delta >= DELTA_MAX:       # the one rule of graphmethods.units for δ
        raise InputError(f"delta = {delta!r}: the coefficient of fluctuation must be below {DELTA_MAX:g}")
    mu_J = _check_positive(mu_J, "mu_J")
    mu_T = _check_positive(mu_T, "mu_T")
    if tangents not in _FACTORS:
        raise InputError(f"tangents {tangents!r}: give 'exact' ((1 ± δ/2)²) or 'textbook' ((1 ± δ))")
    rtol = _check_positive(rtol, "rtol")
    return omega_m, delta, mu_J, mu_T, rtol


def wittenbauer(*, J_e: ArrayLike, delta_T: ArrayLike, omega_m: float, delta: float, mu_J: float, mu_T: float,
                phi: ArrayLike | None = None, phi_0: float = 0.0, phi_T: float = TWO_PI, tangents: str = "exact",
                rtol: float = 1e-9, closure_rtol: float = 1e-6) -> WittenbauerResult:
    """The Wittenbauer construction from data alone: two columns J_e and ΔT for positions 0…m.

    Parameters
    ----------
    J_e, delta_T : array_like
        J_e (kg·m²) and ΔT (J, from any origin) at positions 0…m; position m closes the cycle
        (it must repeat position 0 within ``closure_rtol`` of the ranges).
    omega_m : float
        Mean angular speed, rad/s.
    delta : float
        Coefficient of fluctuation [δ].
    mu_J, mu_T : float
        Scales of the diagram: kg·m² per mm (abscissa) and J per mm (ordinate).
    phi : array_like, optional
        Angles of positions 0…m (rad); by default φ_0 + k φ_T / m.
    tangents : {"exact", "textbook"}
        (1 ± δ/2)² (exact) or (1 ± δ) (textbook). Both are computed; the other is reported.
    rtol : float
        A vertex touches a ray when it lies within rtol × (the curve's extent in J) of it, i.e.
        ``tolerance_mm`` on paper. The default 1e-9 is far above the rounding of sampled data
        (~1e-13 relative) and far below any distance a drawing resolves (0.5 mm in ~500 mm, 1e-3),
        so exact ties (a straight stretch parallel to a ray, two symmetric touches) are all
        reported, and nothing a drawing could tell apart is merged.

    Returns
    -------
    WittenbauerResult
        ``error_estimate`` estimates the sampling error J_F(exact) − J_F(m) (the construction with
        m positions can only under-estimate: its touching vertices lie on or below the continuous
        curve's support lines). Each intercept is re-estimated by extending the chords on either
        side of every touching vertex until they meet: exact at a corner between straight
        stretches (a load switching on), an over-estimate for a smooth touch. (A Richardson
        estimate from m and m/2 or 2m positions was tried and rejected: on nested position sets
        it reads 0 whenever the touching vertex is already in the coarser set, e.g. for the press
        at m = 50 and 3600, while the true error is not 0.)

    Examples
    --------
    >>> res = wittenbauer(J_e=[1.0, 0.8, 1.0, 1.2, 1.0], delta_T=[0.0, 40.0, 0.0, -40.0, 0.0],
    ...                   omega_m=20.0, delta=0.04, mu_J=0.005, mu_T=1.0)
    >>> round(res.kl_mm, 3), round(res.J_F, 4)
    (144.032, 9.002)
    """
    omega_m, delta, mu_J, mu_T, rtol = _check_common(omega_m, delta, mu_J, mu_T, tangents, rtol)
    J, dT, m = _check_arrays(J_e, delta_T, closure_rtol)
    if phi is None:
        phi = phi_0 + phi_T * (np.arange(m + 1) / m)
    angles: FloatArray = np.asarray(phi, dtype=float)
    if angles.shape != J.shape or not np.all(np.isfinite(angles)):
        raise InputError(f"phi: give m + 1 = {m + 1} finite angles (rad), one per position")
    return _construct(J, dT, angles, omega_m=omega_m, delta=delta, mu_J=mu_J, mu_T=mu_T,
                      tangents=tangents, rtol=rtol)


def wittenbauer_from_model(model: ReducedModel, *, positions: int, omega_m: float, delta: float,
                           mu_J: float, mu_T: float, tangents: str = "exact", rtol: float = 1e-9,
                           closure_rtol: float = 1e-6) -> WittenbauerResult:
    """The Wittenbauer construction for a reduced model at positions 0…m.

    ΔT(φ_k) is ΔE(φ_k), integrated exactly (not from a drawing), so the only errors are those of
    the m positions and the straight chords between them.

    Parameters
    ----------
    model : ReducedModel
    positions : int
        m: positions 0…m, φ_k = φ_0 + k φ_T / m.
    omega_m, delta, mu_J, mu_T, tangents, rtol
        As in :func:`wittenbauer`.
    closure_rtol : float
        Tolerated |∫M_e dφ| relative to ∫|M_e| dφ (see :func:`~graphmethods.dynamics.motion.periodic_motion`).

    Returns
    -------
    WittenbauerResult
        With ``error_estimate`` as in :func:`wittenbauer`; the exact J_F is
        :func:`~graphmethods.dynamics.motion.exact_flywheel`.

    Examples
    --------
    >>> model = ReducedModel(J_e=lambda p: 1.0 + 0.2 * np.cos(p), M_e=lambda p: 40.0 * np.cos(p))
    >>> res = wittenbauer_from_model(model, positions=12, omega_m=20.0, delta=0.04, mu_J=0.005, mu_T=1.0)
    >>> round(res.J_F, 3), res.index_omega_max, res.index_omega_min
    (5.868, (5,), (10,))
    """
    omega_m, delta, mu_J, mu_T, rtol = _check_common(omega_m, delta, mu_J, mu_T, tangents, rtol)
    m = _check_count(positions, "positions", 2)
    E = _balanced_energy(model, closure_rtol)
    phi = model.positions(m)
    dT = E(phi)
    dT[0] = dT[-1] = 0.0
    return _construct(model.J_e_at(phi), dT, phi, omega_m=omega_m, delta=delta, mu_J=mu_J,
                      mu_T=mu_T, tangents=tangents, rtol=rtol)
