"""Graphical integration and differentiation by the method of chords (метод хорд), exactly as drawn.

**Integration.** Split the curve y(x), drawn to μ_y and μ_x, into intervals; replace each by its
mean ordinate ȳ_i (equal area); project ȳ_i onto the ordinate axis; join the projection to a
pole P at distance H mm left of the origin; draw the integral curve as chords parallel to those
rays, one per interval. Across interval i the chord rises (ȳ_i/μ_y)(Δx_i/μ_x)/H mm, so the
integral curve's scale is ``μ = μ_y μ_x H`` and its ordinates at the interval ends are the exact
integral whenever ȳ_i is the exact mean (the error lies only inside the intervals).

**Differentiation** is the reverse: chords between neighbouring points of the curve Y(x), rays
through the pole parallel to them, cutting the ordinate axis at H·(slope) mm; these are the
derivative's ordinates, placed at mid-interval, to the scale ``μ_Y / (μ_x H)``. Differentiating
the derivative's points again (chords between neighbouring mid-interval points) puts the second
derivative back at the interval ends; for a periodic curve the chord across the period's end
closes the diagram.

**The slider's kinematic diagrams** (:func:`slider_diagrams`): s(φ) of a slider over the m
positions, v by differentiating s, a by differentiating v, checked against the velocity plans and
the analytic derivatives. **The work diagrams** (:func:`work_diagrams`): A_d(φ), A_r(φ) by
integrating the moment curves, ΔE = A_d − A_r. :func:`accuracy_table` measures how far each
construction is from the exact result as the number of intervals grows.

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
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from graphmethods.dynamics.moments import MomentCurve
from graphmethods.errors import InputError
from graphmethods.kinematics.case import Case
from graphmethods.kinematics.classic import SliderCrank
from graphmethods.kinematics.linkage_mechanism import LinkageMechanism
from graphmethods.kinematics.positions import Positions
from graphmethods.kinematics.vectors import FloatArray
from graphmethods.units import convenient_at_least, convenient_at_most, is_finite

#: Round pole distances (× 10^k mm) the sheets pick from: a length measured with a ruler.
POLE_SERIES = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)
#: Gauss–Legendre nodes for the mean ordinate of a callable over an interval.
_GL_X, _GL_W = np.polynomial.legendre.leggauss(16)
TWO_PI = 2.0 * math.pi

if TYPE_CHECKING:
    from graphmethods.dynamics.study import Study

#: a function of x, vectorised over arrays (an integrand, a derivative, an antiderivative)
Function = Callable[[FloatArray], ArrayLike]
#: a curve as the constructions take it: exact (a MomentCurve, or a function smooth between breaks), or
#: its ordinates at the interval ends
CurveLike = MomentCurve | Function | ArrayLike


def _nodes(x_given: ArrayLike, name: str = "x") -> FloatArray:
    """Interval ends: a 1-D increasing float array of two or more finite values."""
    x: FloatArray = np.array(x_given, dtype=float)
    if x.ndim != 1 or x.size < 2:
        raise InputError(f"{name}: give at least two interval ends")
    if not np.isfinite(x).all():
        raise InputError(f"{name}: the interval ends must be finite numbers")
    if (np.diff(x) <= 0).any():
        i = int(np.flatnonzero(np.diff(x) <= 0)[0])
        raise InputError(f"{name} must increase: {name}[{i}] = {x[i]:g}, {name}[{i + 1}] = {x[i + 1]:g}")
    return x


def _positive(v: object, name: str) -> float:
    """A positive finite number."""
    try:
        value = float(v)  # type: ignore[arg-type]  # any input: what float() refuses is reported
    except (TypeError, ValueError):
        raise InputError(f"{name} = {v!r} must be a positive number") from None
    if not (value > 0 and is_finite(value)):
        raise InputError(f"{name} = {v!r} must be a positive number")
    return value


def _frozen(a: ArrayLike) -> FloatArray:
    """A read-only float copy."""
    out: FloatArray = np.array(a, dtype=float)
    out.setflags(write=False)
    return out


# ----------------------------------------------------------------------------- exact integrals

def exact_integral(f: Function, x: ArrayLike, *, x0: float | None = None, breaks: Sequence[float] = (),
                   pieces: int = 4) -> FloatArray:
    """∫_{x0}^{x} f dt at every x (composite 16-point Gauss–Legendre, split at ``breaks``).

    The reference the constructions are measured against. ``f`` must be vectorised and smooth
    between the ``breaks`` (where it may jump or kink); every interval between the sorted
    points and breaks is split into ``pieces`` parts, so the result is exact to rounding for
    smooth pieces.

    Parameters
    ----------
    f : callable
        The integrand, vectorised over numpy arrays.
    x : array_like
        Upper limits (any order and shape).
    x0 : float, optional
        Lower limit (default: the first of ``x``).
    breaks : sequence of float
        Where f jumps or kinks (those inside the range are used).

    Examples
    --------
    >>> step = lambda t: np.where(t < 1.0, 60.0, 10.0)
    >>> exact_integral(step, [0.0, 0.5, 2.0], breaks=[1.0]).round(12).tolist()
    [0.0, 30.0, 70.0]
    """
    xs: FloatArray = np.asarray(x, dtype=float)
    flat = xs.ravel()
    if flat.size == 0:
        empty: FloatArray = xs.copy()
        return empty
    if not np.isfinite(flat).all():
        raise InputError("exact_integral: the limits must be finite numbers")
    start = float(flat[0]) if x0 is None else float(x0)
    b = np.asarray(breaks, dtype=float).ravel()
    lo, hi = min(start, float(flat.min())), max(start, float(flat.max()))
    b = b[(b > lo) & (b < hi)]
    edges = np.unique(np.concatenate((flat, [start], b)))
    if edges.size == 1:
        zeros: FloatArray = np.zeros_like(xs)
        return zeros
    t = np.linspace(0.0, 1.0, int(pieces) + 1)
    a_ = (edges[:-1, None] + np.diff(edges)[:, None] * t[None, :-1]).ravel()
    h_ = (np.diff(edges)[:, None] * np.diff(t)[None, :]).ravel()
    pts = a_[:, None] + 0.5 * h_[:, None] * (1.0 + _GL_X[None, :])
    vals = np.asarray(f(pts), dtype=float)
    if vals.shape != pts.shape:
        vals = np.broadcast_to(vals, pts.shape)
    if not np.isfinite(vals).all():
        raise InputError("the curve gave a non-finite value inside the intervals; it must be finite throughout")
    piece = 0.5 * h_ * (vals @ _GL_W)
    cum = np.concatenate(([0.0], np.cumsum(piece)))[:: int(pieces)]     # at the edges
    F: FloatArray = cum[np.searchsorted(edges, flat)] - cum[np.searchsorted(edges, start)]
    return F.reshape(xs.shape)


# ----------------------------------------------------------------------------- results

@dataclass(frozen=True, eq=False)
class Accuracy:
    """How far a construction is from the exact result.

    ``at_nodes`` is the largest difference at the construction points (interval ends for an
    integral, mid-intervals for a derivative, interval ends for a second derivative);
    ``inside`` the largest over the drawn chords (integration only, None otherwise). Physical
    units of the result; ``*_mm`` the same on paper.
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
        Against the exact integral when the curve is known exactly (or ``exact`` was given).
    exact_values : ndarray or None
        The exact integral at the interval ends, when known.
    """

    x: FloatArray
    mean_ordinate: FloatArray
    values: FloatArray
    mu_x: float
    mu_y: float
    H_mm: float
    accuracy: Accuracy | None = None
    exact_values: FloatArray | None = None

    @property
    def mu(self) -> float:
        """Scale of the integral curve, (y·x units) per mm."""
        return self.mu_y * self.mu_x * self.H_mm

    @property
    def pole_mm(self) -> tuple[float, float]:
        """The pole P, mm from the origin of the given curve's axes: (−H, 0)."""
        return (-self.H_mm, 0.0)

    @property
    def ray_targets_mm(self) -> FloatArray:
        """Projections of the mean ordinates on the ordinate axis, (n, 2) mm: (0, ȳ_i/μ_y)."""
        return np.column_stack((np.zeros(self.mean_ordinate.size), self.mean_ordinate / self.mu_y))

    @property
    def chords_mm(self) -> FloatArray:
        """The integral curve's vertices, (n+1, 2) mm: (x/μ_x, value/μ)."""
        return np.column_stack(((self.x - self.x[0]) / self.mu_x, self.values / self.mu))


@dataclass(frozen=True, eq=False)
class ChordDerivative:
    """A graphical differentiation: derivative ordinates at the middles of the chords.

    Attributes
    ----------
    x : ndarray
        Abscissae of the derivative's points: the chords' middles (units of x).
    values : ndarray
        The derivative there: the chords' slopes (units of Y per unit of x).
    x_nodes, Y_nodes : ndarray
        The points the chords join (for a periodic curve, extended by one period's wrap).
    mu_x, mu_Y : float
        Scales of the differentiated curve; ``H_mm`` the pole distance; ``mu = mu_Y/(mu_x H)``.
    accuracy : Accuracy or None
        Against ``exact`` at the points ``x``, when given.
    x_origin : float or None
        The abscissa at the origin of the drawing (default: the first given point).
    period : float or None
        The period of a periodic curve.
    exact_values : ndarray or None
        The exact derivative at ``x``, when given.
    """

    x: FloatArray
    values: FloatArray
    x_nodes: FloatArray
    Y_nodes: FloatArray
    mu_x: float
    mu_Y: float
    H_mm: float
    accuracy: Accuracy | None = None
    x_origin: float | None = None
    period: float | None = None
    exact_values: FloatArray | None = None

    @property
    def mu(self) -> float:
        """Scale of the derivative curve, (Y/x units) per mm: μ_Y / (μ_x H)."""
        return self.mu_Y / (self.mu_x * self.H_mm)

    @property
    def origin(self) -> float:
        """The abscissa at the origin of the drawing."""
        return float(self.x_nodes[0] if self.x_origin is None else self.x_origin)

    @property
    def pole_mm(self) -> tuple[float, float]:
        """The pole, mm from the origin of the derivative's axes: (−H, 0)."""
        return (-self.H_mm, 0.0)

    @property
    def ordinates_mm(self) -> FloatArray:
        """Where the rays parallel to the chords cut the ordinate axis: H·slope, mm."""
        return self.values / self.mu

    @property
    def points_mm(self) -> FloatArray:
        """The derivative's points, (n, 2) mm: ((x − origin)/μ_x, value/μ)."""
        return np.column_stack(((self.x - self.origin) / self.mu_x, self.ordinates_mm))

    @property
    def chords_mm(self) -> FloatArray:
        """The differentiated curve's points the chords join, (n+1, 2) mm, in its own drawing."""
        return np.column_stack(((self.x_nodes - self.origin) / self.mu_x, self.Y_nodes / self.mu_Y))


# ----------------------------------------------------------------------------- integration

def _mean_ordinates(x: FloatArray, y: CurveLike,
                    breaks: Sequence[float]) -> tuple[FloatArray, Function | None, CurveLike | None]:
    """ȳ_i and, when the curve is exact, the exact antiderivative F (F(x0) = 0) and the curve."""
    if hasattr(y, "integral") and hasattr(y, "phi"):          # a MomentCurve: exact
        lo, hi = float(y.phi[0]), float(y.phi[-1])
        if x[0] < lo - 1e-12 or x[-1] > hi + 1e-12:
            raise InputError(f"the intervals {x[0]:g}..{x[-1]:g} leave the curve's range {lo:g}..{hi:g}")
        xc = np.clip(x, lo, hi)
        F0 = y.integral(xc[0])

        def F(t: FloatArray) -> FloatArray:
            out: FloatArray = y.integral(np.clip(t, lo, hi)) - F0
            return out

        return np.diff(F(xc)) / np.diff(x), F, y
    if callable(y):
        f = y

        def G(t: FloatArray) -> FloatArray:
            return exact_integral(f, t, x0=float(x[0]), breaks=breaks)

        return np.diff(G(x)) / np.diff(x), G, y
    yy = np.asarray(y, dtype=float)
    if yy.shape != x.shape:
        raise InputError(f"give one ordinate per interval end: {yy.size} ordinates for {x.size} ends")
    if not np.isfinite(yy).all():
        raise InputError("the ordinates must be finite numbers")
    return 0.5 * (yy[:-1] + yy[1:]), None, None


def integrate_by_chords(
    x: ArrayLike,
    y: CurveLike,
    *,
    mu_x: float,
    mu_y: float,
    H_mm: float | None = None,
    fit_mm: float | None = None,
    inside_samples: int = 16,
    breaks: Sequence[float] = (),
    exact: Function | None = None,
) -> ChordIntegral:
    """Integrate y(x) by the method of chords.

    (Over 80 lines only through this docstring, which documents every parameter; the code is 52 lines.)

    Parameters
    ----------
    x : array, units of x (e.g. rad)
        Interval ends (the positions, or any increasing sequence).
    y : MomentCurve, callable, or array of ordinates at ``x``
        The curve. A MomentCurve (exact, jumps included) or a callable (smooth between
        ``breaks``) gives the exact mean ordinates; an array gives the trapezoid means of its
        chords.
    mu_x, mu_y : float
        Scales of the drawn curve, units per mm.
    H_mm : float, optional
        Pole distance. When omitted, the smallest convenient H (1, 2, 2.5, 4, 5 × 10^k mm) is
        chosen for which the integral curve stays within ``fit_mm`` (default 100 mm) of its
        axis: the largest drawing that fits.
    breaks : sequence of float
        Where a callable ``y`` jumps or kinks (its mean ordinates are then exact).
    exact : callable, optional
        The exact antiderivative (any constant): the accuracy is measured against it instead
        of against ``y`` (use it when ``y`` is a drawn approximation of a known curve).

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
    means, F, curve = _mean_ordinates(x, y, breaks)
    values = np.concatenate(([0.0], np.cumsum(means * np.diff(x))))
    if H_mm is None:
        span = float(np.abs(values).max())
        fit = 100.0 if fit_mm is None else _positive(fit_mm, "fit_mm")
        # the integral's largest ordinate value/(μ_y μ_x H) must fit: H ≥ span/(μ_y μ_x fit)
        need = span / (mu_y * mu_x * fit) if span > 0 else 1.0
        H_mm = convenient_at_least(need)
    H_mm = _positive(H_mm, "H_mm")
    mu = mu_y * mu_x * H_mm
    acc, exact_nodes = None, None
    if exact is not None:
        if not callable(exact):
            raise InputError("exact must be the exact antiderivative as a function of x")
        e0 = float(np.asarray(exact(np.array([x[0]])), dtype=float)[0])

        given = exact

        def F_given(t: FloatArray) -> FloatArray:
            out: FloatArray = np.asarray(given(np.asarray(t, dtype=float)), dtype=float) - e0
            return out
        F = F_given
    if F is not None:
        exact_nodes = np.asarray(F(x), dtype=float)
        t = np.linspace(0.0, 1.0, int(inside_samples) + 1)[1:-1]
        xs = (x[:-1, None] + np.diff(x)[:, None] * t[None, :]).ravel()
        kinks = [np.asarray(breaks, dtype=float).ravel()]
        if isinstance(curve, MomentCurve):  # the curve's own kinks, where the error peaks
            kinks.append(np.asarray(curve.phi, dtype=float))
        k = np.concatenate(kinks)
        xs = np.concatenate((xs, k[(k > x[0]) & (k < x[-1])]))
        chord = np.interp(xs, x, values)
        inside = float(np.abs(chord - np.asarray(F(xs), dtype=float)).max()) if xs.size else 0.0
        at_nodes = float(np.abs(values - exact_nodes).max())
        inside = max(inside, at_nodes)
        acc = Accuracy(at_nodes=at_nodes, inside=inside, at_nodes_mm=at_nodes / mu, inside_mm=inside / mu)
    return ChordIntegral(x=_frozen(x), mean_ordinate=_frozen(means), values=_frozen(values), mu_x=mu_x, mu_y=mu_y,
                         H_mm=H_mm, accuracy=acc, exact_values=None if exact_nodes is None else _frozen(exact_nodes))


# ----------------------------------------------------------------------------- differentiation

def differentiate_by_chords(
    x: ArrayLike,
    Y: ArrayLike,
    *,
    mu_x: float,
    mu_Y: float,
    H_mm: float | None = None,
    fit_mm: float | None = None,
    exact: Function | None = None,
    period: float | None = None,
    x_origin: float | None = None,
) -> ChordDerivative:
    """Differentiate a curve given by its points (x_k, Y_k) by the method of chords.

    (Over 80 lines only through this docstring, which documents every parameter; the code is 55 lines.)

    Each chord's slope becomes the derivative at mid-interval, drawn H·slope mm high (scale
    μ_Y/(μ_x H)). With ``exact`` (the true derivative as a callable), the accuracy at the
    mid-intervals is reported. Without ``H_mm``, the largest convenient H is chosen for which
    the derivative's largest ordinate stays within ``fit_mm`` (default 100 mm).

    Parameters
    ----------
    x, Y : array
        The points (x increasing).
    period : float, optional
        The curve repeats with this period. When the points cover the whole period (the last
        x is the first plus ``period``), Y must repeat too; when they cover less (the points of
        a derivative, at mid-intervals), the chords across the period's ends are added, so the
        derivative is known over the whole period and its first and last values coincide.
    x_origin : float, optional
        The abscissa at the drawing's origin (default: the first x), for ``points_mm``.

    Examples
    --------
    >>> x = np.linspace(0, 2 * np.pi, 13)
    >>> D = differentiate_by_chords(x, np.sin(x), mu_x=np.pi / 60, mu_Y=0.02, exact=np.cos)
    >>> D.H_mm, round(D.accuracy.at_nodes, 4)
    (40.0, 0.011)

    Differentiating the derivative's points again gives the second derivative at the positions:

    >>> DD = differentiate_by_chords(D.x, D.values, mu_x=np.pi / 60, mu_Y=D.mu, period=2 * np.pi,
    ...                              x_origin=0.0, exact=lambda t: -np.sin(t))
    >>> DD.x.size, bool(np.allclose(DD.x, x)), bool(DD.values[0] == DD.values[-1])
    (13, True, True)
    >>> round(DD.accuracy.at_nodes, 4)
    0.0226
    """
    x = _nodes(x)
    Y = np.array(Y, dtype=float)
    if Y.shape != x.shape or not np.isfinite(Y).all():
        raise InputError(f"give one finite ordinate per point: {Y.size} ordinates for {x.size} points")
    mu_x, mu_Y = _positive(mu_x, "mu_x"), _positive(mu_Y, "mu_Y")
    origin = float(x[0]) if x_origin is None else float(x_origin)
    if period is not None:
        T = _positive(period, "period")
        span = x[-1] - x[0]
        tol = 1e-9 * max(T, abs(x[0]), abs(x[-1]))
        if span > T + tol:
            raise InputError(f"the points span {span:g}, more than one period {T:g}; give one period")
        if abs(span - T) <= tol:
            scale = max(1.0, float(np.abs(Y).max()))
            if abs(Y[-1] - Y[0]) > 1e-9 * scale:
                raise InputError(f"the curve is not periodic: Y at the period's end is {Y[-1]:g}, at its start "
                                 f"{Y[0]:g}; give period=None or close the curve")
        else:
            x = np.concatenate(([x[-1] - T], x, [x[0] + T]))
            Y = np.concatenate(([Y[-1]], Y, [Y[0]]))
    else:
        T = None
    wrapped = T is not None and x[-1] - x[0] > T * (1 + 1e-12)
    slope = np.diff(Y) / np.diff(x)
    mid = 0.5 * (x[:-1] + x[1:])
    if wrapped:
        slope[-1] = slope[0]                # the two wrap chords are one chord, a period apart
        mid[-1] = mid[0] + T
    if H_mm is None:
        fit = 100.0 if fit_mm is None else _positive(fit_mm, "fit_mm")
        peak = float(np.abs(slope).max())
        # ordinate_mm = slope·μ_x·H/μ_Y ≤ fit: the largest convenient H that fits
        H_mm = convenient_at_most(fit * mu_Y / (peak * mu_x)) if peak > 0 else 20.0
    H_mm = _positive(H_mm, "H_mm")
    mu = mu_Y / (mu_x * H_mm)
    acc, ex = None, None
    if exact is not None:
        ex = np.asarray(exact(mid), dtype=float)
        err = float(np.abs(slope - ex).max())
        acc = Accuracy(at_nodes=err, inside=None, at_nodes_mm=err / mu, inside_mm=None)
    return ChordDerivative(x=_frozen(mid), values=_frozen(slope), x_nodes=_frozen(x), Y_nodes=_frozen(Y), mu_x=mu_x,
                           mu_Y=mu_Y, H_mm=H_mm, accuracy=acc, x_origin=origin, period=T,
                           exact_values=None if ex is None else _frozen(ex))


# ----------------------------------------------------------------------------- the slider's motion, exactly

@dataclass(frozen=True, eq=False)
class SliderMotion:
    """The exact motion of a linkage's slider against the crank's rotation φ from position 0.

    Attributes
    ----------
    phi : ndarray
        Crank rotation from position 0 in the crank's sense, rad.
    s : ndarray
        Displacement from the start of the working stroke, positive in the working sense, m.
    ds, d2s : ndarray
        ds/dφ (m/rad) and d²s/dφ² (m/rad²), the velocity and acceleration analogues: at a
        constant crank speed ω₁, v = ω₁ ds/dφ and a = ω₁² d²s/dφ².
    point : str
        The slider point (``"B"`` of a slider-crank, ``"C"`` of a shaper).
    H : float
        The stroke, m.
    """

    phi: FloatArray
    s: FloatArray
    ds: FloatArray
    d2s: FloatArray
    point: str
    H: float


def _slider_point(mechanism: LinkageMechanism) -> tuple[str, FloatArray]:
    """The one slider point of the linkage and its guide's unit direction."""
    guides = dict(getattr(mechanism, "guides", {}) or {})
    if len(guides) != 1:
        kind = getattr(mechanism, "kind", type(mechanism).__name__)
        raise InputError(f"{kind}: the slider's diagrams need a linkage with one slider on a guide "
                         f"(a slider-crank or a shaper); this one has {len(guides) or 'no'} slider(s)")
    (point, g), = guides.items()
    return point, np.asarray(g, dtype=float)


def _x_second_derivative(mechanism: LinkageMechanism, phi_ccw: FloatArray, point: str, guide: FloatArray) -> FloatArray:
    """d²(X·guide)/dφ² of the slider point: closed form for a slider-crank, else a 4th-order
    central difference of the analytic first derivative (error ~1e-10 of its size)."""
    if isinstance(mechanism, SliderCrank):
        r, l, e, sg = mechanism.r, mechanism.l, mechanism.e, mechanism.assembly
        c, s = np.cos(phi_ccw), np.sin(phi_ccw)
        q = e - r * s
        w = np.sqrt(l * l - q * q)
        # x_B = r cos φ + σ w, w = √(l² − q²), q = e − r sin φ
        closed: FloatArray = (-r * c + sg * r * ((-r * c * c - q * s) / w - r * q * q * c * c / w ** 3)) * guide[0]
        return closed
    h = 1e-3

    def d1(p: FloatArray) -> FloatArray:
        out: FloatArray = mechanism.derivatives(p)[0][point] @ guide
        return out

    return (-d1(phi_ccw + 2 * h) + 8 * d1(phi_ccw + h) - 8 * d1(phi_ccw - h) + d1(phi_ccw - 2 * h)) / (12 * h)


def slider_motion(mechanism: LinkageMechanism, phi: ArrayLike) -> SliderMotion:
    """s, ds/dφ and d²s/dφ² of the slider, exactly (closed form), at crank rotations φ from position 0.

    Parameters
    ----------
    mechanism : SliderCrank or Shaper
        A linkage whose output is one slider on a guide.
    phi : array_like
        Crank rotation from position 0 (the start of the working stroke), in the crank's sense, rad.

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> mo = slider_motion(SliderCrank(r=0.1, l=0.4), [0.0, np.pi / 2, np.pi])
    >>> (mo.s.round(6) + 0.0).tolist(), (mo.ds.round(6) + 0.0).tolist(), mo.d2s.round(6).tolist()
    ([0.0, 0.112702, 0.2], [0.0, 0.1, 0.0], [0.125, -0.02582, -0.075])
    """
    point, guide = _slider_point(mechanism)
    angles = np.atleast_1d(np.asarray(phi, dtype=float))
    pos = mechanism.positions(phi_from_start=angles)
    if pos.s is None or pos.H is None or pos.stroke_direction is None:
        raise InputError(f"{mechanism.kind}: no working stroke, so no slider displacement s; the slider's "
                         f"diagrams need a linkage with dead centres")
    d = float(np.dot(pos.stroke_direction, guide))            # ±1: the working sense along the guide
    dxy, _ = mechanism.derivatives(pos.phi)
    ds = mechanism.sense * d * (dxy[point] @ guide)
    d2s = d * _x_second_derivative(mechanism, np.asarray(pos.phi, dtype=float), point, guide)
    return SliderMotion(phi=_frozen(angles), s=_frozen(pos.s), ds=_frozen(ds), d2s=_frozen(d2s), point=point,
                        H=float(pos.H))


# ----------------------------------------------------------------------------- the slider's kinematic diagrams

@dataclass(frozen=True, eq=False)
class SliderDiagrams:
    """The slider's s, v, a diagrams by graphical differentiation, with the references they are checked against.

    With ``omega_1`` the derivatives are taken with respect to time (v in m/s, a in m/s²; the
    abscissa φ is also time t = φ/ω₁ to μ_t = μ_φ/ω₁, and μ_v = μ_s/(μ_t H₁),
    μ_a = μ_v/(μ_t H₂)); without, with respect to φ (the analogues, m/rad and m/rad²,
    μ_v = μ_s/(μ_φ H₁), μ_a = μ_v/(μ_φ H₂)).

    Attributes
    ----------
    point : str
        The slider point.
    omega_1 : float or None
        Crank speed, rad/s (None: analogues).
    phi : ndarray (m+1,)
        Positions 0…m, crank rotation from position 0, rad.
    s : ndarray (m+1,)
        Displacement at the positions, m.
    mu_phi, mu_s : float
        Scales of the s diagram (rad/mm, m/mm).
    v : ChordDerivative
        v at the mid-intervals (chords of s), accuracy against the analytic v there.
    a : ChordDerivative
        a at the positions 0…m (chords between the v points, closed across the period),
        accuracy against the analytic a there.
    v_plans : ndarray (m+1,)
        The velocity plans' v along the working stroke at the positions.
    v_exact, a_exact : ndarray (m+1,)
        Analytic v and a at the positions.
    a_plans : ndarray (m+1,)
        The acceleration plans' a along the working stroke at the positions
        (:mod:`graphmethods.kinematics.acceleration_plan`, constant crank speed).
    """

    point: str
    omega_1: float | None
    phi: FloatArray
    s: FloatArray
    mu_phi: float
    mu_s: float
    v: ChordDerivative
    a: ChordDerivative
    v_plans: FloatArray
    v_exact: FloatArray
    a_exact: FloatArray
    a_plans: FloatArray

    @property
    def m(self) -> int:
        """Number of intervals."""
        return int(self.phi.size - 1)

    @property
    def time_scale(self) -> float:
        """x-units per rad: 1/ω₁ (time) or 1 (analogues)."""
        return 1.0 if self.omega_1 is None else 1.0 / self.omega_1

    @property
    def mu_t(self) -> float | None:
        """The time scale of the abscissa μ_t = μ_φ/ω₁, s/mm (None for analogues)."""
        return None if self.omega_1 is None else self.mu_phi / self.omega_1

    @property
    def units(self) -> tuple[str, str]:
        """Units of v and a: ("m/s", "m/s²") or ("m/rad", "m/rad²")."""
        return ("m/s", "m/s²") if self.omega_1 is not None else ("m/rad", "m/rad²")

    @property
    def v_at_positions(self) -> FloatArray:
        """v read off the drawn v diagram at the positions: the mean of the two neighbouring
        ordinates (the chord between them), closed across the period."""
        vm = np.asarray(self.v.values)
        out = 0.5 * (np.roll(vm, 1) + vm)
        closed: FloatArray = np.append(out, out[0])
        return closed

    def comparison(self) -> list[dict[str, Any]]:
        """The largest differences from the references, in physical units and in mm on the sheet.

        Rows (dicts): ``quantity`` ("v" or "a"), ``where`` ("mid-intervals" / "positions"),
        ``against`` ("analytic" / "velocity plans"), ``error``, ``unit``, ``error_mm``, ``at``
        (the crank rotation from position 0 where it is largest, rad).
        """
        u_v, u_a = self.units
        t = self.time_scale
        rows: list[dict[str, Any]] = []
        for q, where, against, got, ref, unit, mu, x in (
                ("v", "mid-intervals", "analytic", self.v.values, self.v.exact_values, u_v, self.v.mu, self.v.x),
                ("v", "positions", "velocity plans", self.v_at_positions, self.v_plans, u_v, self.v.mu,
                 self.phi * t),
                ("a", "positions", "analytic", self.a.values, self.a_exact, u_a, self.a.mu, self.phi * t),
                ("a", "positions", "acceleration plans", self.a.values, self.a_plans, u_a, self.a.mu, self.phi * t)):
            diff = np.abs(np.asarray(got) - np.asarray(ref))
            k = int(np.argmax(diff))
            rows.append({"quantity": q, "where": where, "against": against, "error": float(diff[k]), "unit": unit,
                         "error_mm": float(diff[k] / mu), "at": float(x[k] / t)})
        return rows


def _pole_distance_fit(slope_mm_range: float, band_mm: float, room_mm: float | None) -> float:
    """The largest round pole distance (1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10^k mm) whose diagram spans
    at most ``band_mm`` and whose pole stays within ``room_mm``."""
    limit = band_mm / slope_mm_range if slope_mm_range > 0 else 20.0
    if room_mm is not None:
        limit = min(limit, room_mm)
    return convenient_at_most(limit, POLE_SERIES)


@dataclass(frozen=True, eq=False)
class SliderReferences:
    """What :func:`slider_diagrams` takes from the linkage whatever the scales: the slider, its positions and
    the velocities and accelerations of the plans and the closed form at them (see :func:`slider_references`)."""

    mechanism: Any
    m: int
    omega_1: float | None
    point: str
    guide: FloatArray
    pos: Positions
    v_plans: FloatArray
    a_plans: FloatArray
    v_exact: FloatArray
    a_exact: FloatArray


def slider_references(mechanism: LinkageMechanism, m: int = 12, *, omega_1: float | None = None) -> SliderReferences:
    """The scale-free part of :func:`slider_diagrams` (positions, plans, the closed form at the positions), so
    that diagrams of one slider at several scales compute it once (pass it as ``references``).

    >>> from graphmethods.kinematics import SliderCrank
    >>> sc = SliderCrank(r=0.1, l=0.4)
    >>> refs = slider_references(sc, 12, omega_1=10.0)
    >>> a = slider_diagrams(sc, 12, mu_phi=np.pi / 120, mu_s=0.004, omega_1=10.0, references=refs)
    >>> b = slider_diagrams(sc, 12, mu_phi=np.pi / 120, mu_s=0.004, omega_1=10.0)
    >>> bool(np.array_equal(a.a_plans, b.a_plans) and np.array_equal(a.v.values, b.v.values))
    True
    """
    if isinstance(m, bool) or not isinstance(m, (int, np.integer)) or m < 3:
        raise InputError(f"the number of positions m must be an integer ≥ 3, got {m!r}")
    m = int(m)
    if omega_1 is not None:
        omega_1 = _positive(omega_1, "omega_1")
    point, guide = _slider_point(mechanism)
    pos = mechanism.positions(m=m)
    if pos.s is None or pos.stroke_direction is None:
        raise InputError(f"{mechanism.kind}: no working stroke, so no slider displacement s")
    t = 1.0 if omega_1 is None else 1.0 / omega_1           # x-units per rad
    phi = np.asarray(pos.phi_from_start, dtype=float)
    plans = mechanism.velocity_plans(pos, omega_1=1.0 if omega_1 is None else omega_1)
    d = float(np.dot(pos.stroke_direction, guide))
    v_plans = d * plans.v_along_guide(point)
    a_plans = d * _plan_accelerations(mechanism, pos, point, guide, 1.0 if omega_1 is None else omega_1)
    motion = slider_motion(mechanism, (phi * t) / t)
    return SliderReferences(mechanism, m, omega_1, point, guide, pos, v_plans, a_plans, motion.ds / t,
                            motion.d2s / (t * t))


def slider_diagrams(mechanism: LinkageMechanism, m: int = 12, *, mu_phi: float, mu_s: float,
                    omega_1: float | None = None, H1_mm: float | None = None, H2_mm: float | None = None,
                    band_v_mm: float = 60.0,
                    band_a_mm: float = 60.0, pole_room_mm: float | None = None,
                    references: SliderReferences | None = None) -> SliderDiagrams:
    """The slider's s(φ) at m positions, v by differentiating s, a by differentiating v (chords).

    Parameters
    ----------
    mechanism : SliderCrank or Shaper
        A linkage whose output is one slider.
    m : int
        Number of positions (intervals) over the crank turn, ≥ 3.
    mu_phi, mu_s : float
        Scales of the s diagram, rad/mm and m/mm.
    omega_1 : float, optional
        Crank speed, rad/s: derivatives with respect to time (m/s, m/s²). Without it, the
        analogues ds/dφ (m/rad) and d²s/dφ² (m/rad²).
    H1_mm, H2_mm : float, optional
        Pole distances of the v and a diagrams. Picked when not given: the largest H of
        1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10^k mm whose diagram spans at most ``band_v_mm`` /
        ``band_a_mm`` from its lowest to its highest ordinate (0 included), and not more than
        ``pole_room_mm``.

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> sd = slider_diagrams(SliderCrank(r=0.1, l=0.4), 12, mu_phi=np.pi / 120, mu_s=0.004, omega_1=10.0)
    >>> sd.v.H_mm, sd.a.H_mm, round(sd.v.mu, 4), round(sd.a.mu, 4)      # μ_v in (m/s)/mm, μ_a in (m/s²)/mm
    (40.0, 40.0, 0.0382, 0.3648)
    >>> round(float(sd.a.values[0]), 3), round(float(sd.a_exact[0]), 3)   # at the far dead centre: ω²r(1 + r/l)
    (12.062, 12.5)
    >>> [(r["quantity"], r["against"], round(r["error"], 4)) for r in sd.comparison()]  # doctest: +NORMALIZE_WHITESPACE
    [('v', 'analytic', 0.014), ('v', 'velocity plans', 0.0586), ('a', 'analytic', 0.4377),
     ('a', 'acceleration plans', 0.4377)]
    """
    if isinstance(m, bool) or not isinstance(m, (int, np.integer)) or m < 3:
        raise InputError(f"the number of positions m must be an integer ≥ 3, got {m!r}")
    m = int(m)
    mu_phi, mu_s = _positive(mu_phi, "mu_phi"), _positive(mu_s, "mu_s")
    if omega_1 is not None:
        omega_1 = _positive(omega_1, "omega_1")
    if references is None or not (references.mechanism is mechanism and references.m == m
                                  and references.omega_1 == omega_1):
        references = slider_references(mechanism, m, omega_1=omega_1)
    refs = references
    point, pos = refs.point, refs.pos
    phi = np.asarray(pos.phi_from_start, dtype=float)
    s = np.asarray(pos.s, dtype=float)
    t = 1.0 if omega_1 is None else 1.0 / omega_1           # x-units per rad
    mu_x = mu_phi * t
    T = TWO_PI * t

    def exact_v(x: FloatArray) -> FloatArray:
        return slider_motion(mechanism, np.asarray(x) / t).ds / t

    def exact_a(x: FloatArray) -> FloatArray:
        return slider_motion(mechanism, np.asarray(x) / t).d2s / (t * t)

    slope_mm = np.diff(s / mu_s) / np.diff(phi / mu_phi)                 # chord slopes on paper
    if H1_mm is None:
        H1_mm = _pole_distance_fit(float(max(slope_mm.max(), 0) - min(slope_mm.min(), 0)), band_v_mm, pole_room_mm)
    v = differentiate_by_chords(phi * t, s, mu_x=mu_x, mu_Y=mu_s, H_mm=H1_mm, period=T, exact=exact_v,
                                x_origin=0.0)
    if H2_mm is None:
        vm = np.asarray(v.values)
        ext = np.concatenate(([vm[-1]], vm, [vm[0]])) / v.mu
        xs = np.concatenate(([v.x[-1] - T], v.x, [v.x[0] + T])) / mu_x
        sl = np.diff(ext) / np.diff(xs)
        H2_mm = _pole_distance_fit(float(max(sl.max(), 0) - min(sl.min(), 0)), band_a_mm, pole_room_mm)
    a = differentiate_by_chords(v.x, v.values, mu_x=mu_x, mu_Y=v.mu, H_mm=H2_mm, period=T, exact=exact_a,
                                x_origin=0.0)
    return SliderDiagrams(point=point, omega_1=omega_1, phi=_frozen(phi), s=_frozen(s), mu_phi=mu_phi, mu_s=mu_s,
                          v=v, a=a, v_plans=_frozen(refs.v_plans), v_exact=_frozen(refs.v_exact),
                          a_exact=_frozen(refs.a_exact), a_plans=_frozen(refs.a_plans))


def _plan_accelerations(mechanism: LinkageMechanism, pos: Positions, point: str, guide: FloatArray,
                        omega_1: float) -> FloatArray:
    """The slider's acceleration along ``guide`` from the acceleration plans at the positions, m/s²."""
    from graphmethods.kinematics.acceleration_plan import acceleration_plans

    lk = mechanism.linkage          # every mechanism is a linkage of the core
    plans = acceleration_plans(lk, phi=np.asarray(pos.phi, dtype=float), omega_1=omega_1)
    g = complex(float(guide[0]), float(guide[1]))
    return np.array([(p.a(point) * g.conjugate()).real for p in plans], dtype=float)


# ----------------------------------------------------------------------------- work diagrams

@dataclass(frozen=True, eq=False)
class WorkDiagrams:
    """The work diagrams A_d(φ), A_r(φ) by integrating the moment curves, and ΔE = A_d − A_r.

    Attributes
    ----------
    A_d, A_r : ChordIntegral
        The two integrals, with one pole distance H (one scale μ_A = μ_M μ_φ H).
    delta_E_exact : ndarray or None
        The exact ΔE at the interval ends, when both exact curves are known.
    """

    A_d: ChordIntegral
    A_r: ChordIntegral
    delta_E_exact: FloatArray | None = None

    @property
    def phi(self) -> FloatArray:
        """Interval ends, rad."""
        return self.A_r.x

    @property
    def H_mm(self) -> float:
        """The pole distance, mm."""
        return self.A_r.H_mm

    @property
    def mu_A(self) -> float:
        """Scale of the work diagrams, J/mm: μ_M μ_φ H."""
        return self.A_r.mu

    @property
    def delta_E(self) -> FloatArray:
        """ΔE = A_d − A_r at the interval ends, J."""
        out: FloatArray = np.asarray(self.A_d.values) - np.asarray(self.A_r.values)
        return out

    @property
    def closure(self) -> float:
        """A_d − A_r at the period's end, J (0 when the drawn curves balance)."""
        return float(self.delta_E[-1])

    def comparison(self) -> list[dict[str, Any]]:
        """Largest differences from the exact integrals at the interval ends (and inside the chords).

        Rows: ``quantity`` ("A_d", "A_r", "ΔE"), ``error`` (J), ``error_mm``, ``inside``,
        ``inside_mm`` (None for ΔE), ``at`` (rad, where the error at the ends is largest).
        """
        rows: list[dict[str, Any]] = []
        for q, I in (("A_d", self.A_d), ("A_r", self.A_r)):
            if I.accuracy is None:
                continue
            diff = np.abs(np.asarray(I.values) - np.asarray(I.exact_values))
            k = int(np.argmax(diff))
            rows.append({"quantity": q, "error": I.accuracy.at_nodes, "error_mm": I.accuracy.at_nodes_mm,
                         "inside": I.accuracy.inside, "inside_mm": I.accuracy.inside_mm, "at": float(I.x[k])})
        if self.delta_E_exact is not None:
            diff = np.abs(self.delta_E - self.delta_E_exact)
            k = int(np.argmax(diff))
            rows.append({"quantity": "ΔE", "error": float(diff[k]), "error_mm": float(diff[k] / self.mu_A),
                         "inside": None, "inside_mm": None, "at": float(self.phi[k])})
        return rows


def _antiderivative(curve: MomentCurve | Function | float | None, breaks: Sequence[float],
                    x0: float) -> Function | None:
    """The exact antiderivative of an exact curve (MomentCurve, callable or constant), F(x0) = 0."""
    if curve is None:
        return None
    if isinstance(curve, MomentCurve):
        mc = curve
        return lambda t: mc.integral(np.asarray(t, dtype=float)) - mc.integral(np.array([x0]))[0]
    if callable(curve):
        f = curve
        return lambda t: exact_integral(f, t, x0=x0, breaks=breaks)
    c = float(curve)
    return lambda t: c * (np.asarray(t, dtype=float) - x0)


def work_diagrams(M_d: CurveLike, M_r: CurveLike, phi: ArrayLike, *, mu_phi: float, mu_M: float,
                  H_mm: float | None = None, fit_mm: float | None = None,
                  exact_d: MomentCurve | Function | float | None = None,
                  exact_r: MomentCurve | Function | float | None = None, breaks: Sequence[float] = ()
                  ) -> WorkDiagrams:
    """Integrate M_d and M_r by the method of chords, with one pole: the work diagrams and ΔE.

    Parameters
    ----------
    M_d, M_r : MomentCurve, callable or array
        The moment curves as drawn (arrays: values at ``phi``), N·m.
    phi : array
        Interval ends (the positions), rad.
    mu_phi, mu_M : float
        Scales of the moment diagram.
    H_mm : float, optional
        Pole distance; picked when not given: the smallest convenient H for which both work
        diagrams stay within ``fit_mm`` (default 100 mm).
    exact_d, exact_r : MomentCurve, callable or float, optional
        The exact curves when M_d, M_r are drawn approximations (e.g. M_r through its values at
        the positions, the exact one jumping where the load switches); the accuracy is
        measured against their exact integrals. ``breaks``: where the exact curves jump.

    Examples
    --------
    >>> from math import pi
    >>> from graphmethods.dynamics.moments import MomentCurve
    >>> M_r = MomentCurve.steps([(0, pi / 4, 60.0), (pi / 4, 2 * pi, 10.0)])
    >>> M_d = MomentCurve.constant(M_r.mean())
    >>> wd = work_diagrams(M_d, M_r, np.linspace(0, 2 * pi, 13), mu_phi=pi / 120, mu_M=0.5)
    >>> wd.H_mm, round(wd.mu_A, 4), abs(wd.closure) < 1e-12
    (100.0, 1.309, True)
    >>> [(r["quantity"], r["error"] < 1e-12, r["inside"] and round(r["inside"], 3)) for r in wd.comparison()]
    [('A_d', True, 0.0), ('A_r', True, 6.545), ('ΔE', True, None)]
    """
    x = _nodes(phi, "phi")
    mu_phi, mu_M = _positive(mu_phi, "mu_phi"), _positive(mu_M, "mu_M")
    x0 = float(x[0])
    Fd, Fr = _antiderivative(exact_d, breaks, x0), _antiderivative(exact_r, breaks, x0)

    def build(H: float) -> tuple[ChordIntegral, ChordIntegral]:
        return (integrate_by_chords(x, M_d, mu_x=mu_phi, mu_y=mu_M, H_mm=H, breaks=breaks, exact=Fd),
                integrate_by_chords(x, M_r, mu_x=mu_phi, mu_y=mu_M, H_mm=H, breaks=breaks, exact=Fr))

    if H_mm is None:
        d1, r1 = build(1.0)
        span = float(max(np.abs(d1.values).max(), np.abs(r1.values).max()))
        fit = 100.0 if fit_mm is None else _positive(fit_mm, "fit_mm")
        H_mm = convenient_at_least(span / (mu_M * mu_phi * fit)) if span > 0 else 1.0
    A_d, A_r = build(_positive(H_mm, "H_mm"))
    dE = None
    if A_d.exact_values is not None and A_r.exact_values is not None:
        dE = _frozen(np.asarray(A_d.exact_values) - np.asarray(A_r.exact_values))
    return WorkDiagrams(A_d=A_d, A_r=A_r, delta_E_exact=dE)


def study_work_diagrams(study: Study, *, mu_phi: float, mu_M: float, H_mm: float | None = None,
                        fit_mm: float | None = None) -> WorkDiagrams:
    """The work diagrams of a linkage study (:class:`~graphmethods.dynamics.study.Study`).

    The drawn curves are the study's (M_r through its values at the positions, M_d balancing
    it); the exact ones are the constant M_d of the work balance and the exact M_r, which
    jumps where the load switches on and off. Nothing else of the study is computed.
    """
    M_d, M_r = study.moments
    model = study.model
    M_d_exact = float(study.M_d)

    def M_r_exact(p: FloatArray) -> FloatArray:
        out: FloatArray = M_d_exact - model.M_e_at(p)
        return out

    return work_diagrams(M_d, M_r, study.phi, mu_phi=mu_phi, mu_M=mu_M, H_mm=H_mm, fit_mm=fit_mm,
                         exact_d=M_d_exact, exact_r=M_r_exact, breaks=tuple(model.breaks))


# ----------------------------------------------------------------------------- accuracy against the number of intervals

def accuracy_table(subject: Case | LinkageMechanism | MomentCurve, ms: Sequence[int] = (6, 12, 24, 48, 96), *,
                   omega_1: float | None = None, mu_phi: float | None = None, mu_s: float | None = None,
                   mu_M: float | None = None, period: float = TWO_PI) -> list[dict[str, Any]]:
    """How far each construction is from the exact result, for each number of intervals m.

    Parameters
    ----------
    subject : Case, SliderCrank/Shaper, or MomentCurve
        A linkage problem (read with ``graphmethods.kinematics.read_case``): the slider's v and
        a (at the case's mean crank speed) and, for a problem with a load, the work diagrams
        A_d, A_r and ΔE of its study; a mechanism: the slider's v and a (``omega_1`` or the
        analogues); a moment curve (exact, jumps allowed): its integral over ``period``.
    ms : sequence of int
        Numbers of intervals (positions) to build.
    mu_phi, mu_s, mu_M : float, optional
        Drawing scales for the mm columns (default: 2π over 240 mm; s over 60 mm; M over 60 mm).
        The pole distances are picked per m as the sheets pick them.

    Returns
    -------
    list of dict
        One row per construction and m: ``construction``, ``m``, ``where`` (the construction
        points), ``error`` (largest difference there, physical units), ``unit``, ``error_mm``,
        ``inside``/``inside_mm`` (integrals: the largest over the chords), ``H_mm``, ``mu``.

    Examples
    --------
    >>> from math import pi
    >>> from graphmethods.dynamics.moments import MomentCurve
    >>> rows = accuracy_table(MomentCurve.steps([(0, 1.0, 60.0), (1.0, 2 * pi, 10.0)]), ms=(6, 60))
    >>> [(r["m"], r["error"] < 1e-12, round(r["inside"], 3)) for r in rows]
    [(6, True, 2.254), (60, True, 1.296)]
    """
    ms = [int(m) for m in ms]
    if not ms or any(m < 3 for m in ms):
        raise InputError(f"give numbers of intervals m ≥ 3, got {list(ms)!r}")
    mu_phi = mu_phi or convenient_at_least(period / 240.0)
    rows: list[dict[str, Any]] = []
    if isinstance(subject, MomentCurve):      # a moment curve
        span = float(np.abs(subject.M).max()) or 1.0
        mu_M = mu_M or convenient_at_least(span / 60.0)
        for m in ms:
            x = subject.start + np.linspace(0.0, subject.period, m + 1)
            I = integrate_by_chords(x, subject, mu_x=mu_phi, mu_y=mu_M, fit_mm=60.0)
            rows.append(_row("∫M dφ by chords", m, "interval ends", I.accuracy, "J", I.H_mm, I.mu))
        return rows
    case = subject if isinstance(subject, Case) else None
    mech = subject.mechanism if isinstance(subject, Case) else subject
    if case is not None and omega_1 is None:
        omega_1 = case.omega_m
    motion = slider_motion(mech, np.linspace(0.0, TWO_PI, 181))
    mu_s = mu_s or convenient_at_least(float(motion.s.max() - motion.s.min()) / 60.0)
    for m in ms:
        sd = slider_diagrams(mech, m, mu_phi=mu_phi, mu_s=mu_s, omega_1=omega_1, band_v_mm=60.0, band_a_mm=60.0)
        u_v, u_a = sd.units
        rows.append(_row("v by chords of s", m, "mid-intervals", sd.v.accuracy, u_v, sd.v.H_mm, sd.v.mu))
        rows.append(_row("a by chords of v", m, "positions", sd.a.accuracy, u_a, sd.a.H_mm, sd.a.mu))
    if case is not None:
        from graphmethods.dynamics.study import Study

        for m in ms:
            st = Study(case, positions=m)
            M_r = st.moments[1]
            mu = mu_M or convenient_at_least(float(max(np.abs(M_r.M).max(), abs(st.M_d))) / 60.0)
            wd = study_work_diagrams(st, mu_phi=mu_phi, mu_M=mu, fit_mm=60.0)
            for r in wd.comparison():
                acc = Accuracy(r["error"], r["inside"], r["error_mm"], r["inside_mm"])
                rows.append(_row(f"{r['quantity']} by chords", m, "interval ends", acc, "J", wd.H_mm, wd.mu_A))
    return rows


def _row(construction: str, m: int, where: str, acc: Accuracy | None, unit: str, H_mm: float,
         mu: float) -> dict[str, Any]:
    """One row of the accuracy table."""
    assert acc is not None                      # the constructions here are built with their references
    return {"construction": construction, "m": m, "where": where, "error": acc.at_nodes, "unit": unit,
            "error_mm": acc.at_nodes_mm, "inside": acc.inside, "inside_mm": acc.inside_mm, "H_mm": H_mm, "mu": mu}
