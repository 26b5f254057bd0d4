"""Exact periodic motion of a machine reduced to one link, and the exact flywheel.

The machine is its reduced (equivalent) model over one period φ_T (domain.md §2–4): a reduced
moment of inertia J_e(φ) and a reduced moment M_e(φ) = M_d − M_r that depend on position only.
With a flywheel J_F added on the reduced shaft the total inertia is J(φ) = J_F + J_e(φ), and the
energy form of the equation of motion gives the kinetic energy

    T(φ) = T0 + ΔE(φ),   ΔE(φ) = ∫_{φ0}^{φ} M_e dφ,   ω(φ)² = 2 T(φ) / J(φ),

with T0 fixed by the mean speed: the textbook mean ω_m = (ω_max + ω_min)/2 (default) or the time
average φ_T / t_T. This module computes that steady motion (:func:`periodic_motion`), the exact
flywheel for a permissible [δ] (:func:`exact_flywheel`), and is the reference against which the
graphical methods' errors are reported. Motion under a speed-dependent driving moment (a motor
characteristic) is in :mod:`graphmethods.dynamics.motor`.

Numerical method
----------------
ΔE is integrated once, for the whole period, by a vectorised adaptive Gauss–Kronrod (7/15) rule
that bisects panels until each one meets the tolerance; a jump of M_e (a load switching on) is thus
bracketed to about 1e-12 rad even when its position is not declared (declare it in
``ReducedModel.breaks`` to save work). ΔE at any other angle is the cumulative value at the panel
start plus a 15-point Gauss–Legendre integral, so every function below is evaluated "exactly"
(to ~1e-12 relative), not read off a table. Extrema are located on a fine grid (uniform, plus all
quadrature nodes, so that the kinks of ΔE at jumps of M_e are grid points) and then refined by a
batched zoom search on the exact functions, around every grid candidate that could
hold the global extremum. Times are integrated by a composite 6-point Gauss–Legendre rule on the
same grid.

>>> import math
>>> model = ReducedModel(J_e=2.0, M_e=lambda phi: 100.0 * np.cos(phi))   # kg·m², N·m
>>> fw = exact_flywheel(model, omega_m=10.0, delta=0.05)
>>> round(fw.J_F, 6)       # ΔW_max/(ω_m² δ) − J_e = 200/(100·0.05) − 2
38.0
>>> round(math.degrees(fw.phi_omega_max), 3), round(math.degrees(fw.phi_omega_min), 3)
(90.0, 270.0)
>>> round(fw.motion.delta, 9)
0.05
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, cast

import numpy as np
import numpy.typing as npt

from graphmethods.errors import InputError, MotionError, NoFlywheelNeeded
from graphmethods.units import real

__all__ = [
    "ReducedModel",
    "MotionResult",
    "FlywheelResult",
    "periodic_motion",
    "exact_flywheel",
]

TWO_PI = 2.0 * math.pi

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.intp]
#: a vectorised function of the angle φ (rad)
PhiFunction = Callable[[FloatArray], FloatArray]
#: a piecewise-polynomial model of a function for the extremum search: (ready the grid steps given, evaluate)
StepModel = tuple[Callable[[IntArray], None], PhiFunction]
#: (φ*, ω*, spread) of ω_max and of ω_min
Extremes = tuple[tuple[float, float, float], tuple[float, float, float]]
#: J_F, T0, φ(ω_max), φ(ω_min), b_max, b_min, spread
Limits = tuple[float, float, float, float, float, float, float]
_ZOOM = 32                            # sub-steps per bracket and round of the extremum search

# Gauss–Kronrod 7/15 (QUADPACK qk15): Kronrod abscissae (positive half, 0 last) and weights,
# and the weights of the embedded 7-point Gauss rule on the odd Kronrod abscissae.
_XGK = np.array([0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                 0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                 0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                 0.207784955007898467600689403773245, 0.0])
_WGK = np.array([0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                 0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                 0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                 0.204432940075298892414161999234649, 0.209482141084727828012999174891714])
_WG = np.array([0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                0.381830050505118944950369775488975, 0.417959183673469387755102040816327])
_K15_X = np.concatenate([-_XGK[:-1], _XGK[::-1]])
_K15_W = np.concatenate([_WGK[:-1], _WGK[::-1]])
_G7_W = np.zeros(15)
_G7_W[1:7:2] = _WG[:3]            # abscissae -xgk[1], -xgk[3], -xgk[5]
_G7_W[7] = _WG[3]                 # 0
_G7_W[9:15:2] = _WG[2::-1]        # +xgk[5], +xgk[3], +xgk[1]
_GL15_X, _GL15_W = np.polynomial.legendre.leggauss(15)
_GL6_X, _GL6_W = np.polynomial.legendre.leggauss(6)


def _integration_matrix(nodes: np.ndarray) -> np.ndarray:
    """S with ∫_{-1}^{x_k} f = Σ_j S[k, j] f(x_j), exact for polynomials of degree < len(nodes).

    Built in the Legendre basis (well conditioned on Gauss nodes): S = A V⁻¹, with V[k, j] =
    P_j(x_k) and A[k, j] = ∫_{-1}^{x_k} P_j.
    """
    leg = np.polynomial.legendre
    n = nodes.size
    V = leg.legvander(nodes, n - 1)
    A = np.column_stack([leg.legval(nodes, leg.legint(np.eye(n)[j], lbnd=-1)) for j in range(n)])
    return A @ np.linalg.inv(V)


#: running integrals from the start of an interval to its 6 Gauss nodes, from f at those nodes
_GL6_S = _integration_matrix(_GL6_X)
#: f at the 6 Gauss nodes -> its interpolant's Legendre coefficients (degree 5)
_GL6_TO_LEG = np.linalg.inv(np.polynomial.legendre.legvander(_GL6_X, 5))
#: Legendre coefficients of a degree-5 polynomial -> those of its running integral from −1 (degree 6)
_LEG_INT = np.column_stack([np.polynomial.legendre.legint(np.eye(6)[j], lbnd=-1) for j in range(6)])
#: f at −1, the 6 Gauss nodes and +1 -> its interpolant's Legendre coefficients (degree 7)
_ENDS8_TO_LEG = np.linalg.inv(np.polynomial.legendre.legvander(np.concatenate([[-1.0], _GL6_X, [1.0]]), 7))


# --------------------------------------------------------------------------------------------
# The input: a periodic reduced model
# --------------------------------------------------------------------------------------------

def _as_function(value: PhiFunction | float, name: str) -> PhiFunction:
    """A vectorised function of φ from a callable or a constant."""
    if callable(value):
        return value
    try:
        c = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name}: give a function of φ (vectorised over numpy arrays) or a number, "
                         f"not {type(value).__name__}") from None
    if not math.isfinite(c):
        raise InputError(f"{name}: {value!r} is not finite")
    return lambda phi: np.full(np.shape(phi), c)


class _PeriodicSamples:
    """Values at uniformly spaced positions 0…m (position m = position 0 + φ_T), interpolated.

    kind: ``"linear"`` (straight chords), ``"step"`` (the value at position k holds on
    [φ_k, φ_{k+1}); the value at position m is not used) or ``"cubic"`` (periodic cubic spline).
    """

    def __init__(self, values: npt.ArrayLike, *, phi_0: float, phi_T: float, kind: str, name: str):
        v = np.asarray(values, dtype=float)
        if v.ndim != 1 or v.size < 3:
            raise InputError(f"{name}: give the values at positions 0…m as a 1-D sequence "
                             f"(at least 3 values; position m repeats position 0)")
        if not np.all(np.isfinite(v)):
            k = int(np.flatnonzero(~np.isfinite(v))[0])
            raise InputError(f"{name}: the value at position {k} is not finite")
        if kind not in ("linear", "step", "cubic"):
            raise InputError(f"{name}: interpolation {kind!r} is not one of 'linear', 'step', 'cubic'")
        self.m = v.size - 1
        self.h = phi_T / self.m
        self.y: FloatArray
        self.M2: FloatArray
        self.phi_0, self.phi_T, self.kind = phi_0, phi_T, kind
        if kind == "cubic":
            scale = max(float(np.max(np.abs(v))), 1e-300)
            if abs(v[-1] - v[0]) > 1e-9 * scale:
                raise InputError(f"{name}: a periodic cubic spline needs the value at position m "
                                 f"({v[-1]!r}) to repeat position 0 ({v[0]!r})")
            y = v[:-1]
            # Periodic spline: M_{k-1} + 4 M_k + M_{k+1} = 6 (y_{k+1} - 2 y_k + y_{k-1}) / h²,
            # a circulant system solved exactly by the FFT.
            rhs = 6.0 * (np.roll(y, -1) - 2.0 * y + np.roll(y, 1)) / self.h**2
            lam = 4.0 + 2.0 * np.cos(TWO_PI * np.arange(self.m) / self.m)
            M = np.real(np.fft.ifft(np.fft.fft(rhs) / lam))
            self.y = np.append(y, y[0])
            self.M2 = np.append(M, M[0])
        else:
            self.y = v

    def _locate(self, phi: npt.ArrayLike) -> tuple[IntArray, FloatArray]:
        u = np.mod(np.asarray(phi, dtype=float) - self.phi_0, self.phi_T) / self.h
        k = np.minimum(np.floor(u).astype(np.intp), self.m - 1)
        return k, (u - k) * self.h

    def __call__(self, phi: npt.ArrayLike) -> FloatArray:
        k, s = self._locate(phi)
        y0, y1, h = self.y[k], self.y[k + 1], self.h
        if self.kind == "step":
            return y0
        if self.kind == "linear":
            return y0 + (y1 - y0) * (s / h)
        M0, M1 = self.M2[k], self.M2[k + 1]
        r = h - s
        return (M0 * r**3 + M1 * s**3) / (6 * h) + (y0 / h - M0 * h / 6) * r + (y1 / h - M1 * h / 6) * s

    def derivative(self, phi: npt.ArrayLike) -> FloatArray:
        k, s = self._locate(phi)
        y0, y1, h = self.y[k], self.y[k + 1], self.h
        if self.kind == "step":
            return np.zeros_like(y0)
        if self.kind == "linear":
            return (y1 - y0) / h
        M0, M1 = self.M2[k], self.M2[k + 1]
        r = h - s
        return (-M0 * r**2 + M1 * s**2) / (2 * h) - (y0 / h - M0 * h / 6) + (y1 / h - M1 * h / 6)

    def nodes(self) -> FloatArray:
        return self.phi_0 + self.h * np.arange(self.m + 1, dtype=float)


@dataclass(frozen=True, kw_only=True, eq=False)
class ReducedModel:
    """A machine reduced to one link, periodic over φ_T: J_e(φ) and the position-dependent M_e(φ).

    Parameters
    ----------
    J_e : callable or float
        Reduced moment of inertia, kg·m², as a function of the angle φ (rad) that accepts and
        returns numpy arrays, or a constant. It must be ≥ 0 (a flywheel is added to it).
    M_e : callable or float
        Reduced moment M_d − M_r, N·m (positive where it drives), vectorised like ``J_e``. With a
        speed-dependent driving moment (:mod:`~graphmethods.dynamics.motor`) it is the
        position-dependent part only (−M_r, and any other moments depending on φ alone).
    phi_T : float
        The period, rad (2π for one crank turn, 4π for a four-stroke engine).
    phi_0 : float
        The angle of position 0, rad: the period is [φ_0, φ_0 + φ_T] and ΔE is measured from φ_0.
    dJ_e : callable, optional
        dJ_e/dφ, kg·m²/rad (used for the angular acceleration ε only); by default a central
        difference of ``J_e`` with step 1e-6·φ_T.
    breaks : sequence of float
        Angles (rad) where M_e jumps, if known. Optional: undeclared jumps are found by the
        adaptive quadrature, declared ones cost nothing.

    Examples
    --------
    >>> model = ReducedModel(J_e=lambda phi: 1.0 + 0.1 * np.cos(2 * phi), M_e=lambda phi: 50 * np.sin(phi))
    >>> float(model.J_e_at(0.0)), float(model.M_e_at(np.pi / 2))
    (1.1, 50.0)
    >>> sampled = ReducedModel.from_samples(J_e=[1.0, 2.0, 1.0], M_e=[0.0, 1.0, 0.0])
    >>> float(sampled.J_e_at(np.pi / 2))        # linear between positions 0 (φ = 0) and 1 (φ = π)
    1.5
    """

    J_e: Callable[[np.ndarray], np.ndarray] | float
    M_e: Callable[[np.ndarray], np.ndarray] | float
    phi_T: float = TWO_PI
    phi_0: float = 0.0
    dJ_e: Callable[[np.ndarray], np.ndarray] | None = None
    breaks: tuple[float, ...] = ()

    def __post_init__(self) -> None:
        for name in ("phi_T", "phi_0"):
            value = getattr(self, name)
            if not isinstance(value, (int, float)) or not math.isfinite(value):
                raise InputError(f"ReducedModel.{name}: {value!r} is not a finite number of radians")
        if self.phi_T <= 0:
            raise InputError(f"ReducedModel.phi_T: the period must be positive, got {self.phi_T!r} rad")
        object.__setattr__(self, "J_e", _as_function(self.J_e, "ReducedModel.J_e"))
        object.__setattr__(self, "M_e", _as_function(self.M_e, "ReducedModel.M_e"))
        if self.dJ_e is not None and not callable(self.dJ_e):
            raise InputError("ReducedModel.dJ_e: give a function of φ, or leave it out")
        try:
            b = np.asarray(self.breaks, dtype=float).ravel()
        except (TypeError, ValueError):
            raise InputError("ReducedModel.breaks: give a sequence of angles in rad") from None
        if not np.all(np.isfinite(b)):
            raise InputError("ReducedModel.breaks: every angle must be finite")
        b = np.unique(self.phi_0 + np.mod(b - self.phi_0, self.phi_T))
        object.__setattr__(self, "breaks", tuple(float(x) for x in b))
        # Check the functions once, on a few angles: vectorised, finite, J_e >= 0.
        probe = self.phi_0 + self.phi_T * np.array([0.0, 0.1234, 0.5, 0.8765])
        J = self.J_e_at(probe)
        if np.any(J < 0):
            raise InputError(f"ReducedModel.J_e: negative values ({J.min():.6g} kg·m²) at φ = "
                             f"{math.degrees(probe[np.argmin(J)]):.4g}°; a moment of inertia is ≥ 0")
        self.M_e_at(probe)
        if self.dJ_e is not None:
            self._call(self.dJ_e, "dJ_e", probe)

    @classmethod
    def from_samples(cls, *, J_e: npt.ArrayLike, M_e: npt.ArrayLike, phi_T: float = TWO_PI, phi_0: float = 0.0,
                     interpolation: str = "linear", M_e_interpolation: str | None = None) -> ReducedModel:
        """A model from values at uniformly spaced positions 0…m (position m = position 0 + φ_T).

        Parameters
        ----------
        J_e, M_e : array_like or float
            Values (kg·m², N·m) at positions 0…m, or a constant. J_e at position m must repeat
            position 0 for ``"cubic"``; M_e at position m is used by ``"linear"`` as the end of the
            last interval (so a jump at position 0 can be represented) and ignored by ``"step"``.
        phi_T, phi_0 : float
            Period and angle of position 0, rad.
        interpolation : {"linear", "cubic"}
            How J_e (and M_e, unless ``M_e_interpolation`` says otherwise) is interpolated between
            positions: straight chords (as drawn), or a periodic cubic spline (smooth data).
        M_e_interpolation : {"linear", "step", "cubic"}, optional
            ``"step"``: the value at position k holds on [φ_k, φ_{k+1}) (loads given per interval).

        Examples
        --------
        >>> model = ReducedModel.from_samples(J_e=1.0, M_e=[1.0, -1.0, 1.0], M_e_interpolation="step")
        >>> model.M_e_at(np.array([0.5, 4.0])).tolist()
        [1.0, -1.0]
        """
        if interpolation not in ("linear", "cubic"):
            raise InputError(f"interpolation {interpolation!r}: give 'linear' or 'cubic'")
        kinds = {"J_e": interpolation, "M_e": M_e_interpolation or interpolation}
        funcs: dict[str, PhiFunction | float] = {}
        dJ: PhiFunction | None = None
        breaks: list[float] = []
        for name, data in (("J_e", J_e), ("M_e", M_e)):
            if np.ndim(data) == 0:
                funcs[name] = cast(float, data)      # checked by _as_function
                continue
            s = _PeriodicSamples(data, phi_0=phi_0, phi_T=phi_T, kind=kinds[name], name=name)
            funcs[name] = s
            if name == "J_e":
                dJ = s.derivative
                if abs(s.y[-1] - s.y[0]) > 1e-6 * max(float(np.max(np.abs(s.y))), 1e-300):
                    raise InputError(f"J_e: the value at position m ({s.y[-1]!r}) must repeat position 0 "
                                     f"({s.y[0]!r}): J_e is periodic")
            if s.kind != "cubic":
                breaks.extend(s.nodes()[:-1])
        return cls(J_e=funcs["J_e"], M_e=funcs["M_e"], phi_T=phi_T, phi_0=phi_0, dJ_e=dJ,
                   breaks=tuple(breaks))

    # -- evaluation, with checks -------------------------------------------------------------
    def _call(self, f: PhiFunction, name: str, phi: npt.ArrayLike) -> FloatArray:
        phi = np.asarray(phi, dtype=float)
        try:
            out = np.asarray(f(phi), dtype=float)
        except (TypeError, ValueError) as exc:
            raise InputError(f"ReducedModel.{name}: calling it on a numpy array of angles failed "
                             f"({exc}); make it vectorised (use np.sin, np.where, ...)") from None
        if out.shape != phi.shape:
            try:
                out = np.broadcast_to(out, phi.shape).astype(float)
            except ValueError:
                raise InputError(f"ReducedModel.{name}: returned shape {out.shape} for angles of "
                                 f"shape {phi.shape}; it must return one value per angle") from None
        if not np.all(np.isfinite(out)):
            bad = phi[~np.isfinite(out)].ravel()[0]
            raise InputError(f"ReducedModel.{name}: not finite at φ = {bad!r} rad "
                             f"({math.degrees(bad):.6g}°); fix the function there")
        return out

    def J_e_at(self, phi: npt.ArrayLike) -> FloatArray:
        """J_e(φ), kg·m²."""
        return self._call(cast(PhiFunction, self.J_e), "J_e", phi)     # a function since __post_init__

    def M_e_at(self, phi: npt.ArrayLike) -> FloatArray:
        """M_e(φ), N·m."""
        return self._call(cast(PhiFunction, self.M_e), "M_e", phi)

    def dJ_e_at(self, phi: npt.ArrayLike) -> FloatArray:
        """dJ_e/dφ, kg·m²/rad (given, or a central difference of J_e with step 1e-6·φ_T)."""
        return self.J_e_and_slope_at(phi)[1]

    def J_e_and_slope_at(self, phi: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
        """J_e and dJ_e/dφ together: without a given dJ_e, J_e at φ − h, φ, φ + h in one call."""
        phi = np.asarray(phi, dtype=float)
        if self.dJ_e is not None:
            return self.J_e_at(phi), self._call(self.dJ_e, "dJ_e", phi)
        h = 1e-6 * self.phi_T
        lo, mid, hi = self.J_e_at(np.stack([phi - h, phi, phi + h]))
        return mid, (hi - lo) / (2 * h)

    def positions(self, m: int) -> FloatArray:
        """The angles of positions 0…m (m + 1 values, rad), uniformly spaced over the period."""
        m = _check_count(m, "positions", minimum=1)
        return self.phi_0 + self.phi_T * (np.arange(m + 1) / m)


def _check_count(m: object, name: str, minimum: int) -> int:
    if isinstance(m, bool) or not isinstance(m, (int, np.integer)) or m < minimum:
        raise InputError(f"{name}: give a whole number ≥ {minimum}, got {m!r}")
    return int(m)


def _check_positive(value: object, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise InputError(f"{name}: give a positive finite number, got {value!r}")
    # the toolkit's number policy (graphmethods.units.real): finite, magnitudes 1e-100 … 1e100
    return real(value, name, lo=0.0, lo_open=True, hint="give a positive finite number")


# --------------------------------------------------------------------------------------------
# ΔE(φ): the primitive of M_e, by vectorised adaptive Gauss–Kronrod quadrature
# --------------------------------------------------------------------------------------------

#: Most intervals the adaptive quadrature of a moment may split a period into (15 evaluations each): a moment
#: given as a formula that oscillates too fast to follow (sin(1e15·φ)) is refused instead of sampled without bound
MAX_QUADRATURE_INTERVALS = 2**18


class _Primitive:
    """The running integral F(x) = ∫_a^x f, evaluable at any x in [a, b] to ~rtol·∫|f|.

    :meth:`balance` removes the mean of f (the residual F(b)/(b − a)), so that F is periodic;
    the residual is kept in ``residual``; ``error`` bounds the error of F, ``abs_integral`` is
    ∫|f| (from the first, coarse pass).
    """

    def __init__(self, f: PhiFunction, a: float, b: float, breaks: tuple[float, ...] = (), *, n0: int = 256,
                 rtol: float = 1e-12):
        self.f, self.a, self.b = f, a, b
        L = b - a
        inner = [x for x in breaks if a < x < b]
        edges = np.unique(np.concatenate([a + L * np.arange(n0 + 1) / n0, inner]))
        edges[-1] = b
        lo, hi = edges[:-1], edges[1:]
        min_width = 1e3 * np.finfo(float).eps * max(abs(a), abs(b), L)
        keep_lo, keep_val, keep_err = [], [], []
        tol = None
        for _ in range(200):
            half = 0.5 * (hi - lo)
            pts = (0.5 * (lo + hi))[:, None] + half[:, None] * _K15_X
            fx = f(pts.ravel()).reshape(pts.shape)
            K = (fx @ _K15_W) * half
            G = (fx @ _G7_W) * half
            if tol is None:
                self.abs_integral = float(np.sum((np.abs(fx) @ _K15_W) * half))
                tol = rtol * max(self.abs_integral, np.finfo(float).tiny)
            err = np.abs(K - G)
            ok = (err <= tol * np.maximum((hi - lo) / L, 1e-3)) | (hi - lo <= min_width)
            keep_lo.append(lo[ok])
            keep_val.append(K[ok])
            keep_err.append(err[ok])
            if ok.all():
                break
            lo, hi = lo[~ok], hi[~ok]
            if sum(x.size for x in keep_lo) + 2 * lo.size > MAX_QUADRATURE_INTERVALS:
                raise InputError(f"the moment varies too fast to integrate: more than {MAX_QUADRATURE_INTERVALS} "
                                 f"intervals of φ (MAX_QUADRATURE_INTERVALS) would be needed to follow it; a moment "
                                 f"of a machine changes a few times per turn, not millions")
            mid = 0.5 * (lo + hi)
            lo, hi = np.concatenate([lo, mid]), np.concatenate([mid, hi])
        else:  # pragma: no cover - the width floor ends the bisection long before
            raise MotionError("ΔE: the adaptive quadrature of M_e did not converge; check M_e for "
                              "singularities")
        lo = np.concatenate(keep_lo)
        order = np.argsort(lo)
        self.x = np.append(lo[order], b)
        vals = np.concatenate(keep_val)[order]
        self.cum = np.concatenate([[0.0], np.cumsum(vals)])
        # |K15 − G7| summed (a pessimistic bound for smooth f) plus the rounding of the running sum
        self.error = float(np.sum(np.concatenate(keep_err))
                           + self.x.size * np.finfo(float).eps * self.abs_integral)
        self.residual = float(self.cum[-1])
        self.slope = 0.0

    def balance(self) -> None:
        """Remove the mean of f: F(x) − residual·(x − a)/(b − a)."""
        self.slope = self.residual / (self.b - self.a)

    def __call__(self, x: npt.ArrayLike) -> FloatArray:
        return self.with_integrand(x)[0]

    def with_integrand(self, x: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
        """F(x) and f(x) (balanced) from one call of f: the 15 Gauss points of each x and x itself."""
        x = np.asarray(x, dtype=float)
        flat = x.ravel()
        i = np.clip(np.searchsorted(self.x, flat, side="right") - 1, 0, self.x.size - 2)
        x0 = self.x[i]
        half = 0.5 * (flat - x0)
        pts = np.concatenate([(x0 + half)[:, None] + half[:, None] * _GL15_X, flat[:, None]], axis=1)
        fx = self.f(pts.ravel()).reshape(pts.shape)
        part = (fx[:, :-1] @ _GL15_W) * half
        out = self.cum[i] + part - self.slope * (flat - self.a)
        return out.reshape(x.shape), (fx[:, -1] - self.slope).reshape(x.shape)


# --------------------------------------------------------------------------------------------
# Extrema: fine grid, then a batched zoom search on the exact function
# --------------------------------------------------------------------------------------------

def _wrap(phi: npt.ArrayLike, a: float, L: float) -> FloatArray:
    return a + np.mod(np.asarray(phi, dtype=float) - a, L)


def _candidates(x: FloatArray, fx: FloatArray, a: float, L: float) -> tuple[IntArray, FloatArray, FloatArray]:
    """The grid points that could hold the global maximum of a periodic function sampled at x (x[0] = a,
    x[-1] = a + L): every grid local maximum within one largest grid step of the best sample, at most 64,
    with its bracket [x[c − 1], x[c + 1]] (the step before position 0 taken from the end of the period)."""
    n = x.size - 1                       # x[n] is x[0] + L
    v = fx[:n]
    left = np.concatenate([[fx[n - 1]], v[:-1]])
    right = fx[1:n + 1]
    best = float(v.max())
    margin = float(np.max(np.abs(np.diff(fx))))
    cand = np.flatnonzero((v >= left) & (v >= right) & (v >= best - margin))
    if cand.size == 0:  # pragma: no cover - the best sample is always a local maximum
        cand = np.array([int(np.argmax(v))])
    if cand.size > 64:
        cand = cand[np.argsort(v[cand])[-64:]]
    lo = np.where(cand > 0, x[np.maximum(cand - 1, 0)], x[n - 1] - L)
    return cand, lo, x[cand + 1]


def _zoom(fun: PhiFunction, lo: FloatArray, hi: FloatArray, xs: FloatArray, fs: FloatArray, *, a: float, L: float,
          resolution: float, rounding: float) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """The batched zoom search for the maxima of ``fun`` in the brackets [lo, hi] (best samples so far xs, fs):
    each round samples every bracket at ``_ZOOM`` + 1 points in one call of ``fun`` and narrows it to the two
    sub-steps around its best sample, a factor ``_ZOOM``/2 per round. Returns (xs, fs, lo, hi)."""
    s = np.linspace(0.0, 1.0, _ZOOM + 1)
    rows = np.arange(lo.size)
    for _ in range(60):
        pts = lo[:, None] + (hi - lo)[:, None] * s
        fp = fun(_wrap(pts, a, L))
        j = np.argmax(fp, axis=1)
        jl, jr = np.maximum(j - 1, 0), np.minimum(j + 1, _ZOOM)
        better = fp[rows, j] >= fs
        xs, fs = np.where(better, pts[rows, j], xs), np.where(better, fp[rows, j], fs)
        lo, hi = pts[rows, jl], pts[rows, jr]
        # done when f no longer changes across any bracket that could still hold the maximum
        # (a smooth peak: after a few rounds; a kink, where a load switches: at the angle's resolution)
        change = np.maximum(fp[rows, j] - fp[rows, jl], fp[rows, j] - fp[rows, jr])
        open_ = (change > rounding) & (fs + change >= fs.max()) & (hi - lo > resolution)
        if not open_.any():
            break
    return xs, fs, lo, hi


#: largest difference, relative to max |f| on the grid, between the piecewise-polynomial model of a
#: function and the function itself at the model's maxima before the search falls back to the function
_MODEL_RTOL = 1e-9


def _refine_max(fun: PhiFunction, x: FloatArray, fx: FloatArray, *, a: float, L: float,
                model: StepModel | None = None) -> tuple[float, float, float]:
    """The global maximum of a periodic function sampled at grid x (x[0] = a, x[-1] = a + L).

    Every grid local maximum within one largest grid step of the best sample is refined by a batched
    zoom (:func:`_zoom`). With a ``model`` (``(prepare, f_model)``: ``prepare(steps)`` readies the
    polynomial pieces of the grid steps given, ``f_model`` evaluates the piecewise-polynomial model of
    ``fun`` on those steps) the zoom runs on the model, at no cost in calls of ``fun``, and ``fun`` is
    then called once, on every candidate's maximiser together: the best of those exact values is the
    answer (the model only places the angle; at a smooth maximum an error dφ in it changes f by
    O(dφ²)). Where the model and ``fun`` differ by more than ``_MODEL_RTOL`` the zoom runs on ``fun``
    itself, a few calls of ``fun`` per round, each vectorised over every candidate.

    Returns (x*, f*, spread): spread bounds how far f* may still be from the maximum: the largest
    difference between f* and f at the ends of the final bracket, plus twice the model's error at x*
    (max f − f(x*) ≤ 2 sup |f − model| near the maximum).
    """
    n = x.size - 1
    cand, lo, hi = _candidates(x, fx, a, L)
    xs, fs = x[cand], fx[cand]
    resolution = 4 * np.finfo(float).eps * (abs(a) + L)
    scale = float(np.max(np.abs(fx)))
    rounding = 4 * np.finfo(float).eps * scale
    model_error = 0.0
    if model is not None:
        prepare, f_model = model
        prepare(np.unique(np.mod(cand[:, None] + np.arange(-1, 2), n)))   # a bracket's end may fall on the next step
        xm, fm, lo_m, hi_m = _zoom(f_model, lo, hi, xs, fs, a=a, L=L, resolution=resolution, rounding=rounding)
        fe = fun(_wrap(np.concatenate([xm, lo_m, hi_m]), a, L))
        k = int(np.argmax(fe[:xm.size]))
        model_error = float(np.max(np.abs(fe[:xm.size] - fm)))
        if model_error <= _MODEL_RTOL * scale:
            x_star, f_star = float(xm[k]), float(fe[k])
            ends = fe[[xm.size + k, 2 * xm.size + k]]
            return _never_worse(x, fx, x_star, f_star, ends, 2 * model_error, a, L)
    xs, fs, lo, hi = _zoom(fun, lo, hi, xs, fs, a=a, L=L, resolution=resolution, rounding=rounding)
    k = int(np.argmax(fs))
    ends = fun(_wrap(np.array([lo[k], hi[k]]), a, L))
    return _never_worse(x, fx, float(xs[k]), float(fs[k]), ends, 0.0, a, L)


def _never_worse(x: FloatArray, fx: FloatArray, x_star: float, f_star: float, ends: FloatArray, extra: float,
                 a: float, L: float) -> tuple[float, float, float]:
    """(x*, f*, spread) from a refined maximum, the best grid sample taking its place if it is higher."""
    v = fx[:-1]
    best = float(v.max())
    if best > f_star:
        i = int(np.argmax(v))
        x_star, f_star = float(x[i]), best
    spread = float(np.max(np.abs(ends - f_star))) + extra
    return float(_wrap(x_star, a, L)), f_star, spread


def _refine_min(fun: PhiFunction, x: FloatArray, fx: FloatArray, *, a: float, L: float,
                model: StepModel | None = None) -> tuple[float, float, float]:
    """The global minimum, as :func:`_refine_max` finds the maximum of −f."""
    neg_model: StepModel | None = None
    if model is not None:
        prepare, f_model = model
        neg_model = (prepare, lambda p: -f_model(p))
    xs, fs, spread = _refine_max(lambda p: -fun(p), x, -fx, a=a, L=L, model=neg_model)
    return xs, -fs, spread


def _brent_root(f: Callable[[float], float], a: float, b: float, fa: float, fb: float, *, xtol: float = 0.0,
                rtol: float = 4e-16, maxiter: int = 200) -> float:
    """Brent's root finder on a bracket [a, b] with f(a)·f(b) ≤ 0."""
    if fa == 0:
        return a
    if fb == 0:
        return b
    if fa * fb > 0:  # pragma: no cover - callers bracket first
        raise MotionError("internal: root not bracketed")
    c, fc = a, fa
    d = e = b - a
    for _ in range(maxiter):
        if fb * fc > 0:
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):
            a, b, c = b, c, b
            fa, fb, fc = fb, fc, fb
        tol = 2 * rtol * abs(b) + 0.5 * xtol
        m = 0.5 * (c - b)
        if abs(m) <= tol or fb == 0:
            return b
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:
                p, q = 2 * m * s, 1 - s
            else:
                q, r = fa / fc, fb / fc
                p = s * (2 * m * q * (q - r) - (b - a) * (r - 1))
                q = (q - 1) * (r - 1) * (s - 1)
            if p > 0:
                q = -q
            p = abs(p)
            if 2 * p < min(3 * m * q - abs(tol * q), abs(e * q)):
                e, d = d, p / q
            else:
                d = e = m
        else:
            d = e = m
        a, fa = b, fb
        b += d if abs(d) > tol else math.copysign(tol, m)
        fb = f(b)
    return b


# --------------------------------------------------------------------------------------------
# One period on a fine grid
# --------------------------------------------------------------------------------------------

def _balanced_energy(model: ReducedModel, closure_rtol: float) -> _Primitive:
    """ΔE(φ) = ∫_{φ0}^{φ} M_e dφ over one period, checked for closure and balanced.

    A residual ∫M_e dφ within ``closure_rtol``·∫|M_e|dφ is removed (the mean moment is subtracted
    from M_e, so ΔE is periodic); a larger one raises :class:`MotionError` naming the works.
    """
    a, L = model.phi_0, model.phi_T
    E = _Primitive(model.M_e_at, a, a + L, model.breaks)
    W, residual = E.abs_integral, E.residual
    if not abs(residual) <= closure_rtol * W:
        gains, losses = 0.5 * (W + residual), 0.5 * (W - residual)
        where = (f"over one period M_e does {residual:.6g} J of work (gains {gains:.6g} J, losses "
                 f"{losses:.6g} J; {abs(residual) / W:.3g} of ∫|M_e|dφ, tolerance {closure_rtol:g})")
        if residual < 0:
            raise MotionError(
                f"the speed cannot be sustained: {where}, so the driving work is less than the "
                f"resisting work by {-residual:.6g} J and the machine slows down every cycle. "
                f"Balance M_d against M_r (e.g. M_d = resisting work / φ_T).")
        raise MotionError(
            f"no steady motion: {where}, so the driving work exceeds the resisting work by "
            f"{residual:.6g} J and the machine speeds up every cycle. Balance M_d against M_r.")
    E.balance()
    return E


class _Cycle:
    """ΔE, J_e on a fine grid over one period, with Gauss points for time integrals."""

    def __init__(self, model: ReducedModel, *, positions: int, n_search: int, closure_rtol: float):
        self.model = model
        a, L = model.phi_0, model.phi_T
        self.a, self.L = a, L
        self.E = _balanced_energy(model, closure_rtol)
        self.residual = self.E.residual
        self.out = model.positions(positions)
        uniform = a + L * np.arange(n_search + 1) / n_search
        x = np.unique(np.concatenate([self.E.x, uniform, self.out]))
        x = x[(x >= a) & (x <= a + L)]
        x[-1] = a + L
        self.x = x
        self.out_index = np.searchsorted(x, self.out)
        h = np.diff(x)
        self._nodes = x[:-1, None] + h[:, None] * (0.5 * (_GL6_X + 1.0))
        self.wq = h[:, None] * (0.5 * _GL6_W)
        # M_e at 6 Gauss points of every grid step (steps of ~2π/n_search inside which M_e is
        # smooth: jumps are at grid points) gives ΔE on the grid and at the Gauss points (a
        # degree-5 running integral on each step), anchored at the quadrature's panel edges
        Mq = model.M_e_at(self._nodes.ravel()).reshape(self._nodes.shape) - self.E.slope
        self.Mq = Mq
        steps = np.concatenate([[0.0], np.cumsum(np.sum(Mq * self.wq, axis=1))])
        E = self.E
        panel = np.clip(np.searchsorted(E.x, x, side="right") - 1, 0, E.x.size - 2)
        start = np.searchsorted(x, E.x)                 # every panel edge is a grid point
        anchor = E.cum - E.slope * (E.x - a)
        self.Ex = anchor[panel] + steps - steps[start[panel]]
        self.Ex[0] = 0.0
        self.Ex[-1] = 0.0
        # the steps inside a panel against the panel's own Gauss–Kronrod value: their error
        self.step_error = float(np.max(np.abs(np.diff(anchor) - np.diff(steps[start]))))
        self.Eq = self.Ex[:-1, None] + (0.5 * h)[:, None] * (Mq @ _GL6_S.T)
        self.Jx = model.J_e_at(x)
        self.E_min = min(float(self.Ex.min()), float(self.Eq.min()))
        self.h = h
        # the step model: on each grid step M_e is its degree-5 interpolant at the Gauss points
        # (Legendre coefficients), ΔE that interpolant's running integral from the step's start
        self._M_leg = Mq @ _GL6_TO_LEG.T
        self._E_leg = (0.5 * h)[:, None] * (self._M_leg @ _LEG_INT.T)
        self._E_leg[:, 0] += self.Ex[:-1]
        # J_e's degree-7 interpolant through the step's ends and Gauss points, for the steps readied
        self._J_leg = np.full((h.size, 8), np.nan)

    @functools.cached_property
    def Jq(self) -> FloatArray:
        """J_e at the Gauss points of every grid step (for time integrals), kg·m²."""
        Jq: FloatArray = self.model.J_e_at(self._nodes.ravel()).reshape(self._nodes.shape)
        self._set_J_leg(np.arange(self.h.size), Jq)
        return Jq

    def _set_J_leg(self, steps: IntArray, J_nodes: FloatArray) -> None:
        values = np.column_stack([self.Jx[steps], J_nodes, self.Jx[steps + 1]])
        self._J_leg[steps] = values @ _ENDS8_TO_LEG.T

    def ready_steps(self, steps: IntArray) -> None:
        """Ready the step model of J_e on the grid steps given: J_e at their Gauss points, in one call."""
        todo = steps[np.isnan(self._J_leg[steps, 0])]
        if todo.size:
            J_nodes = self.model.J_e_at(self._nodes[todo].ravel()).reshape(todo.size, _GL6_X.size)
            self._set_J_leg(todo, J_nodes)

    def step_model(self, p: FloatArray, *,
                   slope: bool = False) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
        """ΔE, M_e (balanced), J_e and (with ``slope``, else zeros) dJ_e/dφ at angles p in [a, a + L] from the
        step model, without calling the model's functions: the polynomial pieces of the steps p falls in,
        which must have been readied (:meth:`ready_steps`).

        Inside a step of h ≈ φ_T/n_search the pieces differ from the functions by O(h⁶) (ΔE, M_e) and
        O(h⁸) (J_e) relative: enough to place an extremum, whose value is then taken from the functions.
        """
        leg = np.polynomial.legendre
        flat = np.asarray(p, dtype=float).ravel()
        k = np.clip(np.searchsorted(self.x, flat, side="right") - 1, 0, self.h.size - 1)
        t = 2.0 * (flat - self.x[k]) / self.h[k] - 1.0
        V = leg.legvander(t, 7)
        cJ = self._J_leg[k]
        E = np.einsum("ij,ij->i", self._E_leg[k], V[:, :7])
        M = np.einsum("ij,ij->i", self._M_leg[k], V[:, :6])
        J = np.einsum("ij,ij->i", cJ, V)
        if slope:
            dJ = np.einsum("ij,ij->i", leg.legder(cJ, axis=1), V[:, :7]) * (2.0 / self.h[k])
        else:
            dJ = np.zeros_like(J)
        shape = np.shape(p)
        return E.reshape(shape), M.reshape(shape), J.reshape(shape), dJ.reshape(shape)

    # exact functions of φ
    def g(self, alpha: float) -> PhiFunction:
        """φ ↦ ΔE(φ) − α J_e(φ)."""
        return lambda p: self.E(p) - alpha * self.model.J_e_at(p)

    def ratio(self, T0: float, J_F: float) -> PhiFunction:
        """φ ↦ (T0 + ΔE(φ)) / (J_F + J_e(φ)) = ω²/2."""
        return lambda p: (T0 + self.E(p)) / (J_F + self.model.J_e_at(p))

    def _model(self, f: Callable[[FloatArray, FloatArray], FloatArray]) -> StepModel:
        """The step model of φ ↦ f(ΔE(φ), J_e(φ)) for :func:`_refine_max`."""
        def evaluate(p: FloatArray) -> FloatArray:
            E, _, J, _ = self.step_model(p)
            return f(E, J)
        return self.ready_steps, evaluate

    def support(self, alpha: float, sense: int) -> tuple[float, float, float]:
        """max (sense=+1) or min (sense=−1) of ΔE − α J_e: (φ*, value, spread)."""
        fx = self.Ex - alpha * self.Jx
        refine = _refine_max if sense > 0 else _refine_min
        return refine(self.g(alpha), self.x, fx, a=self.a, L=self.L, model=self._model(lambda E, J: E - alpha * J))

    def omega_extreme(self, T0: float, J_F: float, sense: int) -> tuple[float, float, float]:
        """(φ*, ω*, spread in ω²/2) of the max (sense=+1) or min (−1) of ω."""
        fx = (T0 + self.Ex) / (J_F + self.Jx)
        refine = _refine_max if sense > 0 else _refine_min
        p, r, spread = refine(self.ratio(T0, J_F), self.x, fx, a=self.a, L=self.L,
                              model=self._model(lambda E, J: (T0 + E) / (J_F + J)))
        return p, math.sqrt(2.0 * max(r, 0.0)), spread

    def period_time(self, T0: float, J_F: float) -> float:
        u = 2.0 * np.maximum(T0 + self.Eq, 0.0) / (J_F + self.Jq)
        with np.errstate(divide="ignore"):
            return float(np.sum(self.wq / np.sqrt(u)))

    def check_inertia(self, J_F: float, *, delta: float | None = None) -> None:
        J_min = float(self.Jx.min())
        if J_F + J_min > 1e-3 * (abs(J_F) + float(self.Jx.max())):
            return       # clear on the grid: between grid points J_e dips by O(step²) at most
        J_min = min(J_min, float(self.Jq.min()))
        if delta is not None:
            # The identity always gives J_F + min J_e ≥ 0 (take φ at min J_e in both brackets);
            # equality means the machine alone already runs within [δ] at some speed profile.
            if J_F + J_min <= 1e-9 * (abs(J_F) + float(self.Jx.max())):
                raise NoFlywheelNeeded(f"no flywheel is needed: the machine's own inertia keeps δ below "
                                  f"[δ] = {delta:g} (the support-line identity gives J_F = {J_F:.6g} "
                                  f"kg·m² = −min J_e: zero total inertia where J_e is least)")
            return
        if J_F + J_min > 0:
            return
        raise MotionError(f"the total inertia J_F + J_e must be positive: J_F = {J_F:.6g} kg·m² "
                          f"and min J_e = {J_min:.6g} kg·m²; add flywheel inertia")


# --------------------------------------------------------------------------------------------
# Results
# --------------------------------------------------------------------------------------------

def _frozen(a: npt.ArrayLike) -> FloatArray:
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


class _FromPosition0:
    """Angles of ω_max and ω_min measured from position 0 (needs phi_omega_max/min, phi_0, phi_T)."""

    if TYPE_CHECKING:                   # given by the result classes that take this in
        phi_omega_max: float
        phi_omega_min: float
        phi_0: float
        phi_T: float

    @property
    def phi_omega_max_from_0(self) -> float:
        """Angle of ω_max after position 0, rad, in [0, φ_T)."""
        return float(np.mod(self.phi_omega_max - self.phi_0, self.phi_T))

    @property
    def phi_omega_min_from_0(self) -> float:
        """Angle of ω_min after position 0, rad, in [0, φ_T)."""
        return float(np.mod(self.phi_omega_min - self.phi_0, self.phi_T))


@dataclass(frozen=True, eq=False)
class MotionResult(_FromPosition0):
    """A steady periodic motion over one period, at the output positions 0…m.

    Attributes
    ----------
    phi : ndarray
        Angles of the output positions (rad), φ_0 … φ_0 + φ_T.
    omega, t, epsilon, T, delta_E, J : ndarray
        ω (rad/s), time from position 0 (s), ε (rad/s²), kinetic energy T = T0 + ΔE (J), ΔE (J),
        total inertia J_F + J_e (kg·m²) at ``phi``.
    J_F : float
        Flywheel inertia added to J_e, kg·m².
    T0 : float
        Kinetic energy at position 0, J.
    mean : str
        ``"textbook"`` (ω_m = (ω_max + ω_min)/2) or ``"time"`` (ω_m = φ_T/t_T), the mean the
        motion was fixed by (or, for a motor, the one δ refers to).
    omega_m : float
        That mean speed, rad/s; ``omega_m_textbook`` and ``omega_m_time`` are both means.
    delta : float
        (ω_max − ω_min)/ω_m with ω_m the chosen mean.
    omega_max, omega_min, phi_omega_max, phi_omega_min : float
        Extreme speeds (rad/s) and their angles (rad, absolute; ``*_from_0`` after position 0).
    epsilon_max, phi_epsilon_max : float
        The angular acceleration of largest magnitude (signed, rad/s²) and its angle.
    chi : float
        Artobolevsky's dynamic coefficient |ε|_max / ω_m².
    t_T : float
        Time of one period, s.
    closure_residual : float
        ∫ M_e dφ over the period (J) before balancing (the mean of M_e within the tolerance is
        removed).
    accuracy : float
        Estimated relative accuracy of ω_max, ω_min (and so of δ·ω_m).
    method : str
        ``"energy"`` (position-dependent loads, exact) or ``"rk4"`` (speed-dependent driving moment).
    multiplier : float or None
        For ``"rk4"``: dT(φ_T)/dT(0) of the period map at the steady state (< 1: stable).
    """

    phi: np.ndarray
    omega: np.ndarray
    t: np.ndarray
    epsilon: np.ndarray
    T: np.ndarray
    delta_E: np.ndarray
    J: np.ndarray
    J_F: float
    T0: float
    mean: str
    omega_m: float
    omega_m_textbook: float
    omega_m_time: float
    delta: float
    omega_max: float
    omega_min: float
    phi_omega_max: float
    phi_omega_min: float
    epsilon_max: float
    phi_epsilon_max: float
    chi: float
    t_T: float
    phi_0: float
    phi_T: float
    closure_residual: float
    accuracy: float
    method: str = "energy"
    multiplier: float | None = None


@dataclass(frozen=True, eq=False)
class FlywheelResult(_FromPosition0):
    """The exact flywheel for a permissible coefficient of fluctuation.

    Attributes
    ----------
    J_F : float
        Flywheel inertia to add to J_e(φ) on the reduced shaft, kg·m². Negative means the
        machine's own inertia already keeps δ below [δ] (no flywheel needed).
    delta, omega_m, mean : float, float, str
        The prescribed [δ], mean speed (rad/s) and its definition.
    omega_max, omega_min : float
        The speed limits the flywheel achieves, rad/s.
    phi_omega_max, phi_omega_min : float
        Where they occur (rad, absolute; ``*_from_0`` after position 0).
    b_max, b_min : float
        max_φ [ΔE − ½ω_max² J_e] and min_φ [ΔE − ½ω_min² J_e], J: the ordinate intercepts of the
        support lines (μ_T·k and μ_T·l on the Wittenbauer diagram).
    T0 : float
        Kinetic energy at position 0, J.
    rel_accuracy : float
        Estimated relative error of J_F: the quadrature error bound of ΔE (both intercepts) plus
        the last zoom brackets' spread, over b_max − b_min.
    closure_residual : float
        ∫ M_e dφ over the period before balancing, J.
    motion : MotionResult
        The steady motion with this J_F, solved independently (``motion.delta`` reproduces [δ]);
        solved when first asked for (it costs about twice the flywheel itself).
    """

    J_F: float
    delta: float
    omega_m: float
    mean: str
    omega_max: float
    omega_min: float
    phi_omega_max: float
    phi_omega_min: float
    b_max: float
    b_min: float
    T0: float
    rel_accuracy: float
    closure_residual: float
    phi_0: float
    phi_T: float
    solve_motion: Callable[[], MotionResult] = field(repr=False)

    @functools.cached_property
    def motion(self) -> MotionResult:
        """The steady motion with this J_F (T0 from the mean speed, then the extremes of ω)."""
        return self.solve_motion()

    @property
    def delta_check(self) -> float:
        """δ of the motion integrated with this J_F (the converse check)."""
        return self.motion.delta


# --------------------------------------------------------------------------------------------
# Steady motion for a given flywheel
# --------------------------------------------------------------------------------------------

def _check_mean(mean: object) -> str:
    if mean not in ("textbook", "time"):
        raise InputError(f"mean {mean!r}: give 'textbook' ((ω_max + ω_min)/2) or 'time' (φ_T/t_T)")
    return mean


def _solve_T0(cyc: _Cycle, J_F: float, omega_m: float, mean: str, *,
              guess: float | None = None) -> tuple[float, Extremes | None]:
    """Kinetic energy at position 0 that gives the prescribed mean speed, and (textbook mean) the
    exact extremes of ω found on the way, ``((φ_max, ω_max, spread), (φ_min, ω_min, spread))``.

    ``guess`` (from the support lines of the flywheel) replaces the bracketing stage: the Newton
    polish converges to the same root from it, in one or two steps instead of several.
    """
    T_lo = -cyc.E_min
    scale = 0.5 * (J_F + float(cyc.Jx.mean())) * omega_m**2

    if mean == "time":
        def G(T0: float) -> float:
            if T0 <= T_lo:
                return -omega_m
            return cyc.L / cyc.period_time(T0, J_F) - omega_m
    else:
        def G(T0: float) -> float:
            u = np.maximum(T0 + cyc.Ex, 0.0) / (J_F + cyc.Jx)
            return 0.5 * (math.sqrt(2 * u.max()) + math.sqrt(2 * u.min())) - omega_m

    if guess is not None and mean == "textbook" and guess > T_lo:
        T0 = float(guess)
    else:
        g_lo = G(T_lo)
        if g_lo >= 0:
            raise MotionError(
                f"with J_F = {J_F:.6g} kg·m² the speed fluctuates too much for a mean of "
                f"{omega_m:.6g} rad/s: even with ω_min → 0 the mean would be {g_lo + omega_m:.6g} rad/s; "
                f"increase J_F or the mean speed")
        T_hi = T_lo + max(scale, 1e-300)
        g_hi = G(T_hi)
        for _ in range(200):
            if g_hi > 0:
                break
            T_hi = T_lo + 2 * (T_hi - T_lo)
            g_hi = G(T_hi)
        T0 = _brent_root(G, T_lo, T_hi, g_lo, g_hi)
    if mean == "time":
        return T0, None
    # Polish with the exact extrema (Newton; dω/dT0 = 1/(ω J) at the extreme, by the envelope theorem).
    for _ in range(12):
        hi = cyc.omega_extreme(T0, J_F, +1)
        lo = cyc.omega_extreme(T0, J_F, -1)
        (p_max, w_max, _), (p_min, w_min, _) = hi, lo
        Jmax, Jmin = J_F + cyc.model.J_e_at(np.array([p_max, p_min]))
        resid = 0.5 * (w_max + w_min) - omega_m
        slope = 0.5 * (1.0 / (w_max * Jmax) + (1.0 / (w_min * Jmin) if w_min > 0 else math.inf))
        step = resid / slope
        T0 -= step
        if abs(step) <= 1e-15 * abs(T0) or resid == 0:
            break
    # the extremes at the last step's start: T0 has moved by at most 1e-15 of itself since
    return T0, (hi, lo)


def _motion_from_T0(cyc: _Cycle, J_F: float, T0: float, extremes: Extremes | None = None, *,
                    mean: str) -> MotionResult:
    model, a, L = cyc.model, cyc.a, cyc.L
    hi, lo = extremes or (cyc.omega_extreme(T0, J_F, +1), cyc.omega_extreme(T0, J_F, -1))
    (p_max, w_max, s_max), (p_min, w_min, s_min) = hi, lo
    if not w_min > 0:
        raise MotionError(f"the machine stops at φ = {math.degrees(p_min):.6g}°: the kinetic energy "
                          f"falls to zero there; increase J_F or the mean speed")
    u = 2.0 * np.maximum(T0 + cyc.Eq, 0.0) / (J_F + cyc.Jq)
    dt = np.sum(cyc.wq / np.sqrt(u), axis=1)
    t_nodes = np.concatenate([[0.0], np.cumsum(dt)])
    t_T = float(t_nodes[-1])
    omega_m_tb = 0.5 * (w_max + w_min)
    omega_m_time = L / t_T
    omega_m = omega_m_tb if mean == "textbook" else omega_m_time

    def eps_from(E: FloatArray, M: FloatArray, J_e: FloatArray, dJ_e: FloatArray) -> FloatArray:
        J = J_F + J_e
        w2 = 2.0 * np.maximum(T0 + E, 0.0) / J
        return (M - 0.5 * w2 * dJ_e) / J

    def eps(p: FloatArray) -> FloatArray:
        J_e, dJ_e = model.J_e_and_slope_at(p)
        return eps_from(*cyc.E.with_integrand(p), J_e, dJ_e)

    def eps_model(p: FloatArray) -> FloatArray:
        E, M, J_e, dJ_e = cyc.step_model(p, slope=True)
        return eps_from(E, M, J_e, dJ_e)

    # on the grid ΔE and J_e are known already
    ex = eps_from(cyc.Ex, model.M_e_at(cyc.x) - cyc.E.slope, cyc.Jx, model.dJ_e_at(cyc.x))
    p_e1, e1, _ = _refine_max(eps, cyc.x, ex, a=a, L=L, model=(cyc.ready_steps, eps_model))
    p_e2, e2, _ = _refine_min(eps, cyc.x, ex, a=a, L=L, model=(cyc.ready_steps, eps_model))
    # the larger magnitude; a tie (a symmetric machine: |ε_max| = |ε_min| within rounding) goes to the one
    # met first after position 0, not to the last bit of either
    if abs(abs(e1) - abs(e2)) <= 1e-9 * max(abs(e1), abs(e2)):
        first_max = np.mod(p_e1 - a, L) <= np.mod(p_e2 - a, L)
        eps_max, p_eps = (e1, p_e1) if first_max else (e2, p_e2)
    else:
        eps_max, p_eps = (e1, p_e1) if abs(e1) > abs(e2) else (e2, p_e2)

    idx = cyc.out_index
    phi = cyc.out
    J = J_F + cyc.Jx[idx]
    T = T0 + cyc.Ex[idx]
    omega = np.sqrt(2.0 * T / J)
    # accuracy: quadrature error of ΔE and the zoom search's spread, relative to the kinetic energy
    acc = (cyc.E.error + cyc.step_error + max(s_max, s_min) * (J_F + float(cyc.Jx.max()))) / max(T0 + cyc.E_min, 1e-300)
    return MotionResult(
        phi=_frozen(phi), omega=_frozen(omega), t=_frozen(t_nodes[idx]), epsilon=_frozen(ex[idx]),
        T=_frozen(T), delta_E=_frozen(cyc.Ex[idx]), J=_frozen(J), J_F=float(J_F), T0=float(T0),
        mean=mean, omega_m=float(omega_m), omega_m_textbook=float(omega_m_tb),
        omega_m_time=float(omega_m_time), delta=float((w_max - w_min) / omega_m),
        omega_max=float(w_max), omega_min=float(w_min), phi_omega_max=p_max, phi_omega_min=p_min,
        epsilon_max=float(eps_max), phi_epsilon_max=float(p_eps), chi=float(abs(eps_max) / omega_m**2),
        t_T=t_T, phi_0=a, phi_T=L, closure_residual=cyc.residual, accuracy=float(0.5 * acc),
        method="energy")


def periodic_motion(model: ReducedModel, *, J_F: float, omega_m: float, mean: str = "textbook",
                    positions: int = 360, n_search: int = 4096, closure_rtol: float = 1e-6) -> MotionResult:
    """The steady periodic motion with a flywheel J_F, for a prescribed mean speed.

    T(φ) = T0 + ΔE(φ), ω² = 2T/(J_F + J_e(φ)), ε = (M_e − ½ω² dJ_e/dφ)/(J_F + J_e), t = ∫dφ/ω,
    with T0 found so that the chosen mean of ω equals ``omega_m``.

    Parameters
    ----------
    model : ReducedModel
        J_e(φ) and M_e(φ) over one period.
    J_F : float
        Flywheel inertia added on the reduced shaft, kg·m² (J_F + J_e must stay positive).
    omega_m : float
        Mean angular speed, rad/s.
    mean : {"textbook", "time"}
        ω_m = (ω_max + ω_min)/2 (default) or ω_m = φ_T / t_T.
    positions : int
        Number of output intervals m: results at positions 0…m.
    n_search : int
        Uniform grid size for locating extrema (quadrature nodes are added to it).
    closure_rtol : float
        Tolerated |∫M_e dφ| over the period, relative to ∫|M_e| dφ; a residual within it is removed
        (its mean moment subtracted from M_e), a larger one raises :class:`MotionError`.

    Returns
    -------
    MotionResult

    Raises
    ------
    MotionError
        Driving and resisting work do not balance (the speed cannot be sustained, or grows), the
        total inertia is not positive, or the fluctuation is too large for the mean speed.

    Examples
    --------
    >>> model = ReducedModel(J_e=2.0, M_e=lambda phi: 100.0 * np.cos(phi))
    >>> res = periodic_motion(model, J_F=38.0, omega_m=10.0)
    >>> round(res.delta, 9), round(res.omega_max, 9), round(res.omega_min, 9)
    (0.05, 10.25, 9.75)
    """
    J_F = float(J_F)
    if not math.isfinite(J_F):
        raise InputError(f"J_F: {J_F!r} is not finite")
    omega_m = _check_positive(omega_m, "omega_m")
    mean = _check_mean(mean)
    positions = _check_count(positions, "positions", 1)
    n_search = _check_count(n_search, "n_search", 16)
    cyc = _Cycle(model, positions=positions, n_search=n_search, closure_rtol=closure_rtol)
    cyc.check_inertia(J_F)
    return _motion_from_T0(cyc, J_F, *_solve_T0(cyc, J_F, omega_m, mean), mean=mean)


# --------------------------------------------------------------------------------------------
# The exact flywheel
# --------------------------------------------------------------------------------------------

def _flywheel_for_limits(cyc: _Cycle, w_hi: float, w_lo: float) -> Limits:
    """J_F and T0 for prescribed ω_max = w_hi and ω_min = w_lo (the support-line identity)."""
    a_max, a_min = 0.5 * w_hi**2, 0.5 * w_lo**2
    p_max, b_max, s1 = cyc.support(a_max, +1)
    p_min, b_min, s2 = cyc.support(a_min, -1)
    J_F = (b_max - b_min) / (a_max - a_min)
    T0 = a_max * J_F - b_max
    return J_F, T0, p_max, p_min, b_max, b_min, s1 + s2


def _time_mean_centre(cyc: _Cycle, solve: Callable[[float], Limits], omega_m: float) -> float:
    """The centre c = (ω_max + ω_min)/2 of the speed limits c ± δω_m/2 whose flywheel gives the time-average
    mean φ_T/t_T = ω_m (secant iteration: the map c ↦ φ_T/t_T is nearly the identity)."""
    def G(c: float) -> float:
        J_F, T0 = solve(c)[:2]
        return cyc.L / cyc.period_time(T0, J_F) - omega_m
    c0, g0 = omega_m, G(omega_m)
    c1 = omega_m - g0
    g1 = G(c1)
    for _ in range(50):
        if g1 == g0 or abs(g1) <= 1e-15 * omega_m:
            return c1
        c0, c1, g0 = c1, c1 - g1 * (c1 - c0) / (g1 - g0), g1
        g1 = G(c1)
    raise MotionError("the time-average mean speed could not be matched")  # pragma: no cover - see above


def exact_flywheel(model: ReducedModel, *, omega_m: float, delta: float, mean: str = "textbook",
                   positions: int = 360, n_search: int = 1024, closure_rtol: float = 1e-6) -> FlywheelResult:
    r"""The flywheel inertia that keeps the coefficient of fluctuation at exactly [δ].

    Derivation (the support-line identity, domain.md §7). With J(φ) = J_F + J_e(φ) > 0 and
    T(φ) = T0 + ΔE(φ), ½ω² = T/J. Put a_max = ½ω_max², a_min = ½ω_min². Then

    * ω(φ) ≤ ω_max for all φ, with equality somewhere, ⇔ T0 + ΔE(φ) ≤ a_max (J_F + J_e(φ)) for
      all φ with equality somewhere ⇔ a_max J_F − T0 = max_φ [ΔE(φ) − a_max J_e(φ)] =: b_max;
    * ω(φ) ≥ ω_min likewise ⇔ a_min J_F − T0 = min_φ [ΔE(φ) − a_min J_e(φ)] =: b_min.

    Subtracting eliminates T0: (a_max − a_min) J_F = b_max − b_min. With the textbook mean,
    ω_max,min = ω_m (1 ± δ/2), so a_max − a_min = ½(ω_max² − ω_min²) = δ ω_m² exactly, and

        J_F = (b_max − b_min) / (δ ω_m²),   T0 = a_max J_F − b_max.

    In the plane (J_e, ΔE) the lines ΔE = a J_e + b at the slopes a_max, a_min support the curve
    from above and below; b_max, b_min are their intercepts at J_e = 0 (Wittenbauer's k and l
    times μ_T); they meet at O1 = (−J_F, −T0), where total inertia and total energy vanish. The
    maximiser of the first bracket is where ω = ω_max, of the second where ω = ω_min. For
    constant J_e it reduces to J_F = ΔW_max/(δ ω_m²) − J_e.

    With ``mean="time"`` (ω_m = φ_T/t_T and δ = (ω_max − ω_min)/ω_m) the same identity is used
    with ω_max,min = c ± δω_m/2, and the centre c is found so that the time average is ω_m.

    Parameters
    ----------
    model : ReducedModel
    omega_m : float
        Mean angular speed, rad/s.
    delta : float
        Permissible coefficient of fluctuation [δ] (0 < δ < 2).
    mean : {"textbook", "time"}
    positions, n_search, closure_rtol
        As in :func:`periodic_motion` (``positions``: output of the motion with this flywheel). The grid is
        coarser by default: it only brackets the extrema (placed on the step model, valued by the model's
        functions), so J_F agrees with a 4096-step grid's to about 1e-15.

    Returns
    -------
    FlywheelResult
        With the angles of ω_max and ω_min, an accuracy estimate, and the motion with this J_F
        (solved from J_F alone: ``result.delta_check`` reproduces [δ]).

    Examples
    --------
    >>> model = ReducedModel(J_e=lambda phi: 1.0 + 0.5 * np.sin(phi), M_e=lambda phi: 80.0 * np.sin(2 * phi))
    >>> fw = exact_flywheel(model, omega_m=20.0, delta=0.02)
    >>> round(fw.J_F, 4), fw.rel_accuracy < 1e-8, abs(fw.delta_check - 0.02) < 1e-10
    (25.5036, True, True)
    """
    omega_m = _check_positive(omega_m, "omega_m")
    delta = _check_positive(delta, "delta")
    if delta >= 2:
        raise InputError(f"delta = {delta!r}: the coefficient of fluctuation must be below 2 "
                         f"(ω_min = ω_m(1 − δ/2) must stay positive)")
    mean = _check_mean(mean)
    positions = _check_count(positions, "positions", 1)
    n_search = _check_count(n_search, "n_search", 16)
    cyc = _Cycle(model, positions=positions, n_search=n_search, closure_rtol=closure_rtol)
    half = 0.5 * delta * omega_m

    def solve(c: float) -> Limits:
        out = _flywheel_for_limits(cyc, c + half, c - half)
        cyc.check_inertia(out[0], delta=delta)
        return out

    c = _time_mean_centre(cyc, solve, omega_m) if mean == "time" else omega_m
    sol = solve(c)
    J_F, T0, p_max, p_min, b_max, b_min, spread = sol
    rel = (2 * (cyc.E.error + cyc.step_error) + spread) / abs(b_max - b_min) if b_max != b_min else math.inf
    # the motion with this J_F, solved from J_F alone on the same ΔE quadrature (T0 from the mean speed,
    cyc.check_inertia(J_F)    # then the extremes of ω): its δ is an independent check of the support lines
    return FlywheelResult(
        J_F=float(J_F), delta=delta, omega_m=omega_m, mean=mean, omega_max=c + half,
        omega_min=c - half, phi_omega_max=p_max, phi_omega_min=p_min, b_max=float(b_max),
        b_min=float(b_min), T0=float(T0), rel_accuracy=float(rel), closure_residual=cyc.residual,
        phi_0=cyc.a, phi_T=cyc.L,
        solve_motion=lambda: _motion_from_T0(cyc, J_F, *_solve_T0(cyc, J_F, omega_m, mean, guess=T0), mean=mean))
