"""Graphical integration and differentiation by the method of chords (метод хорд), exactly as drawn.

**Integration.** Split the curve y(x), drawn to μ_y and μ_x, into intervals; replace each by its
mean ordinate ȳ_i (equal area); project ȳ_i onto the ordinate axis; join the projection to a
pole P at distance H mm left of the origin; draw the integral curve as chords parallel to those
rays, one per interval. Across interval i the chord rises (ȳ_i/μ_y)(Δx_i/μ_x)/H mm, so the
integral curve's scale is ``μ = μ_y μ_x H`` and its ordinates at the interval ends are the exact
integral whenever ȳ_i is the exact mean (the error lies only inside the intervals).

**Differentiation** is the reverse: chords between neighbouring points of the curve Y(x), rays
through the pole parallel to them, cutting the ordinate axis at H·(slope) mm; these are the
derivative's ordinates, placed at mid-interval, to the scale ``μ_Y / (μ_x H)``.

>>> import numpy as np
>>> x = np.linspace(0, np.pi, 7)
>>> I = integrate_by_chords(x, np.sin, mu_x=np.pi / 60, mu_y=0.02, H_mm=25)
>>> round(I.mu, 6), round(float(I.values[-1]), 12)        # ∫₀^π sin = 2, exact at the ends
(0.02618, 2.0)
>>> D = differentiate_by_chords(x, -np.cos(x), mu_x=np.pi / 60, mu_Y=0.02, H_mm=20)
>>> bool(abs(D.values - np.sin(D.x)).max() < 0.03)
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from graphmethods.errors import InputError
from graphmethods.units import convenient_at_least, convenient_at_most
#: Gauss–Legendre nodes for the mean ordinate of a callable over an interval.
_GL_X, _GL_W = np.polynomial.legendre.leggauss(16)


def _nodes(x, name="x") -> np.ndarray:
    x = np.asarray(x, dtype=float)
    if x.ndim != 1 or x.size < 2:
        raise InputError(f"{name}: give at least two interval ends")
    if not np.isfinite(x).all():
        raise InputError(f"{name}: the interval ends must be finite numbers")
    if (np.diff(x) <= 0).any():
        i = int(np.flatnonzero(np.diff(x) <= 0)[0])
        raise InputError(f"{name} must increase: {name}[{i}] = {x[i]:g}, {name}[{i + 1}] = {x[i + 1]:g}")
    return x


def _positive(v, name):
    if v is None or not (float(v) > 0 and math.isfinite(float(v))):
        raise InputError(f"{name} = {v!r} must be a positive number")
    return float(v)


@dataclass(frozen=True, eq=False)
class Accuracy:
    """How far a construction is from the exact result.

    ``at_nodes`` is the largest difference at the construction points (interval ends for an
    integral, mid-intervals for a derivative); ``inside`` the largest over the drawn chords
    (integration only, None otherwise). Physical units of the result; ``*_mm`` the same on paper.
    """

    at_nodes: float
    inside: float | None
    at_nodes_mm: float
    inside_mm: float | None


@dataclass(frozen=True, eq=False)
class ChordIntegral:
    """A graphical integration, with everything a figure needs to draw it.

    Attributes
    ----------
    x : ndarray
        Interval ends (physical units of x).
    mean_ordinate : ndarray
        ȳ_i of each interval (units of y).
    values : ndarray
        The integral at the interval ends, from 0 at x[0] (units of y·x).
    mu_x, mu_y : float
        Scales of the given curve (units per mm); ``H_mm`` the pole distance;
        ``mu = mu_y mu_x H_mm`` the integral curve's scale.
    accuracy : Accuracy or None
        Against the exact integral when the curve is known exactly.
    """

    x: np.ndarray
    mean_ordinate: np.ndarray
    values: np.ndarray
    mu_x: float
    mu_y: float
    H_mm: float
    accuracy: Accuracy | None = None

    @property
    def mu(self) -> float:
        """Scale of the integral curve, (y·x units) per mm."""
        return self.mu_y * self.mu_x * self.H_mm

    @property
    def pole_mm(self) -> tuple[float, float]:
        """The pole P, mm from the origin of the given curve's axes: (−H, 0)."""
        return (-self.H_mm, 0.0)

    @property
    def ray_targets_mm(self) -> np.ndarray:
        """Projections of the mean ordinates on the ordinate axis, (n, 2) mm: (0, ȳ_i/μ_y)."""
        return np.column_stack((np.zeros(self.mean_ordinate.size), self.mean_ordinate / self.mu_y))

    @property
    def chords_mm(self) -> np.ndarray:
        """The integral curve's vertices, (n+1, 2) mm: (x/μ_x, value/μ)."""
        return np.column_stack(((self.x - self.x[0]) / self.mu_x, self.values / self.mu))


@dataclass(frozen=True, eq=False)
class ChordDerivative:
    """A graphical differentiation: derivative ordinates at mid-intervals."""

    x: np.ndarray            # mid-interval abscissae (units of x)
    values: np.ndarray       # derivative there (units of Y per unit of x)
    x_nodes: np.ndarray
    Y_nodes: np.ndarray
    mu_x: float
    mu_Y: float
    H_mm: float
    accuracy: Accuracy | None = None

    @property
    def mu(self) -> float:
        """Scale of the derivative curve, (Y/x units) per mm: μ_Y / (μ_x H)."""
        return self.mu_Y / (self.mu_x * self.H_mm)

    @property
    def pole_mm(self) -> tuple[float, float]:
        return (-self.H_mm, 0.0)

    @property
    def ordinates_mm(self) -> np.ndarray:
        """Where the rays parallel to the chords cut the ordinate axis: H·slope, mm."""
        return self.values / self.mu

    @property
    def points_mm(self) -> np.ndarray:
        """The derivative's points, (n, 2) mm: (x/μ_x, value/μ)."""
        return np.column_stack(((self.x - self.x_nodes[0]) / self.mu_x, self.ordinates_mm))


def _mean_ordinates(x: np.ndarray, y) -> tuple[np.ndarray, Callable | None, Callable | None]:
    """ȳ_i and, when the curve is exact, the exact antiderivative F (F(x0)=0) and the curve."""
    if hasattr(y, "integral") and hasattr(y, "phi"):          # a MomentCurve: exact
        lo, hi = float(y.phi[0]), float(y.phi[-1])
        if x[0] < lo - 1e-12 or x[-1] > hi + 1e-12:
            raise InputError(f"the intervals {x[0]:g}..{x[-1]:g} leave the curve's range {lo:g}..{hi:g}")
        xc = np.clip(x, lo, hi)
        F0 = y.integral(xc[0])
        F = lambda t: y.integral(np.clip(t, lo, hi)) - F0
        return np.diff(F(xc)) / np.diff(x), F, y
    if callable(y):
        half = 0.5 * np.diff(x)
        mid = 0.5 * (x[:-1] + x[1:])
        pts = mid[:, None] + half[:, None] * _GL_X[None, :]
        vals = np.asarray(y(pts), dtype=float)
        if not np.isfinite(vals).all():
            raise InputError("the curve gave a non-finite value inside the intervals")
        means = (vals * _GL_W[None, :]).sum(axis=1) / 2.0

        def F(t):
            t = np.atleast_1d(np.asarray(t, dtype=float))
            out = np.empty_like(t)
            for k, tk in enumerate(t):     # only used for the accuracy report, on modest grids
                a = x[0]
                h = 0.5 * (tk - a)
                out[k] = h * float((np.asarray(y(a + h + h * _GL_X)) * _GL_W).sum()) if tk > a else 0.0
            return out

        return means, F, y
    yy = np.asarray(y, dtype=float)
    if yy.shape != x.shape:
        raise InputError(f"give one ordinate per interval end: {yy.size} ordinates for {x.size} ends")
    if not np.isfinite(yy).all():
        raise InputError("the ordinates must be finite numbers")
    return 0.5 * (yy[:-1] + yy[1:]), None, None


def integrate_by_chords(
    x,
    y,
    *,
    mu_x: float,
    mu_y: float,
    H_mm: float | None = None,
    fit_mm: float | None = None,
    inside_samples: int = 16,
) -> ChordIntegral:
    """Integrate y(x) by the method of chords.

    Parameters
    ----------
    x : array, units of x (e.g. rad)
        Interval ends (the positions, or any increasing sequence).
    y : MomentCurve, callable, or array of ordinates at ``x``
        The curve. A MomentCurve (exact, jumps included) or a callable gives the exact mean
        ordinates; an array gives the trapezoid means of its chords.
    mu_x, mu_y : float
        Scales of the drawn curve, units per mm.
    H_mm : float, optional
        Pole distance. When omitted, the largest convenient H (1, 2, 2.5, 4, 5 × 10^k mm) is
        chosen for which the integral curve stays within ``fit_mm`` (default 100 mm) of its axis.

    Examples
    --------
    A moment with a jump: the integral is exact at the interval ends, the error only inside:

    >>> from math import pi
    >>> from graphmethods.dynamics.moments import MomentCurve
    >>> M = MomentCurve.steps([(0, 1.0, 60.0), (1.0, 2 * pi, 10.0)])
    >>> I = integrate_by_chords(np.linspace(0, 2 * pi, 7), M, mu_x=pi / 120, mu_y=1.0, H_mm=40)
    >>> I.accuracy.at_nodes < 1e-12, round(I.accuracy.inside, 3)
    (True, 2.254)
    """
    x = _nodes(x)
    mu_x, mu_y = _positive(mu_x, "mu_x"), _positive(mu_y, "mu_y")
    means, F, curve = _mean_ordinates(x, y)
    values = np.concatenate(([0.0], np.cumsum(means * np.diff(x))))
    if H_mm is None:
        span = float(np.abs(values).max())
        fit = 100.0 if fit_mm is None else _positive(fit_mm, "fit_mm")
        # the integral's largest ordinate value/(μ_y μ_x H) must fit: H ≥ span/(μ_y μ_x fit)
        need = span / (mu_y * mu_x * fit) if span > 0 else 1.0
        H_mm = convenient_at_least(need)
    H_mm = _positive(H_mm, "H_mm")
    mu = mu_y * mu_x * H_mm
    acc = None
    if F is not None:
        exact_nodes = F(x)
        t = np.linspace(0.0, 1.0, inside_samples + 1)[1:-1]
        xs = (x[:-1, None] + np.diff(x)[:, None] * t[None, :]).ravel()
        if hasattr(curve, "phi"):           # the curve's own kinks, where the error peaks
            xs = np.concatenate((xs, curve.phi[(curve.phi > x[0]) & (curve.phi < x[-1])]))
        chord = np.interp(xs, x, values)
        inside = float(np.abs(chord - F(xs)).max()) if xs.size else 0.0
        at_nodes = float(np.abs(values - exact_nodes).max())
        acc = Accuracy(at_nodes=at_nodes, inside=inside, at_nodes_mm=at_nodes / mu, inside_mm=inside / mu)
    for arr in (x, means, values):
        arr.setflags(write=False)
    return ChordIntegral(x=x, mean_ordinate=means, values=values, mu_x=mu_x, mu_y=mu_y, H_mm=H_mm, accuracy=acc)


def differentiate_by_chords(
    x,
    Y,
    *,
    mu_x: float,
    mu_Y: float,
    H_mm: float | None = None,
    fit_mm: float | None = None,
    exact: Callable | None = None,
) -> ChordDerivative:
    """Differentiate a curve given by its points (x_k, Y_k) by the method of chords.

    Each chord's slope becomes the derivative at mid-interval, drawn H·slope mm high (scale
    μ_Y/(μ_x H)). With ``exact`` (the true derivative as a callable), the accuracy at the
    mid-intervals is reported. Without ``H_mm``, the largest convenient H is chosen for which
    the derivative's largest ordinate stays within ``fit_mm`` (default 100 mm).

    >>> x = np.linspace(0, 2 * np.pi, 13)
    >>> D = differentiate_by_chords(x, np.sin(x), mu_x=np.pi / 60, mu_Y=0.02, exact=np.cos)
    >>> D.H_mm, round(D.accuracy.at_nodes, 4)
    (40.0, 0.011)
    """
    x = _nodes(x)
    Y = np.asarray(Y, dtype=float)
    if Y.shape != x.shape or not np.isfinite(Y).all():
        raise InputError(f"give one finite ordinate per point: {Y.size} ordinates for {x.size} points")
    mu_x, mu_Y = _positive(mu_x, "mu_x"), _positive(mu_Y, "mu_Y")
    slope = np.diff(Y) / np.diff(x)
    mid = 0.5 * (x[:-1] + x[1:])
    if H_mm is None:
        fit = 100.0 if fit_mm is None else _positive(fit_mm, "fit_mm")
        peak = float(np.abs(slope).max())
        # ordinate_mm = slope·μ_x·H/μ_Y ≤ fit: the largest convenient H that fits
        H_mm = convenient_at_most(fit * mu_Y / (peak * mu_x)) if peak > 0 else 20.0
    H_mm = _positive(H_mm, "H_mm")
    mu = mu_Y / (mu_x * H_mm)
    acc = None
    if exact is not None:
        err = float(np.abs(slope - np.asarray(exact(mid), dtype=float)).max())
        acc = Accuracy(at_nodes=err, inside=None, at_nodes_mm=err / mu, inside_mm=None)
    for arr in (mid, slope, x, Y):
        arr.setflags(write=False)
    return ChordDerivative(x=mid, values=slope, x_nodes=x, Y_nodes=Y, mu_x=mu_x, mu_Y=mu_Y, H_mm=H_mm, accuracy=acc)
