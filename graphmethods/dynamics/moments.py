"""Moment curves M(φ) over one period: point lists, steps with jumps, constants, functions.

A :class:`MomentCurve` is piecewise linear in the crank angle φ (rad). A jump is
two consecutive knots at the same φ: the first holds the value just before, the
second the value just after. Every form of input (points, steps, constant,
callable) becomes this one representation, so the excess-work core treats them
all exactly alike.

>>> from math import pi
>>> M_r = MomentCurve.steps([(0, pi / 4, 60.0), (pi / 4, 2 * pi, 10.0)])
>>> round(M_r.work(), 4)
102.1018
>>> float(M_r(pi / 4)), float(M_r(pi / 8))        # right-continuous at the jump
(10.0, 60.0)
>>> M_d = MomentCurve.constant(M_r.mean(), period=2 * pi)
>>> float(M_d(1.0))
16.25
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from graphmethods.errors import InputError
from graphmethods.units import MAGNITUDE_MAX, finite_array, real

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True, eq=False)
class MomentCurve:
    """A moment M(φ) in N·m over one period, piecewise linear with possible jumps.

    Parameters
    ----------
    phi : array of float, rad
        Knots, non-decreasing, spanning one period ``phi[0] .. phi[-1]``. A repeated
        value is a jump.
    M : array of float, N·m
        The moment at each knot.
    approx_error : float, N·m
        Largest deviation of the straight chords from the true curve (0 for exact
        input; the sampling tolerance met for :meth:`function`).

    Examples
    --------
    >>> c = MomentCurve.points([0, 3.141592653589793, 6.283185307179586], [0, 40, 0])
    >>> round(c.work(), 6), float(c(1.5707963267948966))
    (125.663706, 20.0)
    """

    phi: np.ndarray
    M: np.ndarray
    approx_error: float = 0.0

    def __post_init__(self) -> None:
        phi = finite_array(self.phi, "phi")
        M = finite_array(self.M, "M")
        if phi.size != M.size:
            raise InputError(f"phi has {phi.size} values but M has {M.size}; give one moment per angle")
        if phi.size < 2:
            raise InputError("a moment curve needs at least two points (start and end of the period)")
        steps = np.diff(phi)
        if (steps < 0).any():
            i = int(np.flatnonzero(steps < 0)[0])
            raise InputError(
                f"phi must not decrease: phi[{i}] = {phi[i]:g} > phi[{i + 1}] = {phi[i + 1]:g} rad; sort the points"
            )
        if phi[-1] <= phi[0]:
            raise InputError("the curve spans no angle: its period phi[-1] - phi[0] must be positive")
        phi.setflags(write=False)
        M.setflags(write=False)
        object.__setattr__(self, "phi", phi)
        object.__setattr__(self, "M", M)

    # ----------------------------------------------------------------- constructors
    @classmethod
    def _valid(cls, phi: np.ndarray, M: np.ndarray, approx_error: float = 0.0) -> MomentCurve:
        """A curve on knots already validated (those of another curve): only M is checked."""
        if not np.isfinite(M).all():
            raise InputError("the moments overflow: the sum or difference of the curves is not finite")
        M.setflags(write=False)
        curve = object.__new__(cls)
        for name, value in (("phi", phi), ("M", M), ("approx_error", approx_error)):
            object.__setattr__(curve, name, value)
        return curve

    @classmethod
    def points(cls, phi: Sequence[float] | np.ndarray, M: Sequence[float] | np.ndarray, *,
               period: float | None = None) -> MomentCurve:
        """Piecewise-linear curve through the points (φ_k, M_k).

        If ``period`` is given and the points stop short of ``phi[0] + period``, the curve
        is closed by a straight line back to the first value (the curve is periodic).
        """
        x = finite_array(phi, "phi")
        y = finite_array(M, "M")
        if period is not None:
            if not period > 0:
                raise InputError(f"period = {period!r} rad must be positive (2π for one turn, 4π for two)")
            end = x[0] + period
            if x.size and x[-1] > end * (1 + 1e-12):
                raise InputError(f"the points run to {x[-1]:g} rad, past the period end {end:g} rad")
            if x.size and x[-1] < end:
                x = np.append(x, end)
                y = np.append(y, y[0])
        return cls(x, y)

    @classmethod
    def steps(cls, steps: Iterable[Sequence[float]]) -> MomentCurve:
        """Piecewise-constant curve from ``[(phi_start, phi_end, M), ...]`` (contiguous, in order)."""
        if isinstance(steps, (str, bytes)) or not hasattr(steps, "__iter__"):
            raise InputError(f"steps: give a list of (phi_start, phi_end, M) steps, got {steps!r}")
        try:
            rows = [tuple(s) for s in steps]
        except TypeError:
            raise InputError(f"steps: each step is (phi_start, phi_end, M), got {steps!r}") from None
        if not rows:
            raise InputError("steps: give at least one (phi_start, phi_end, M) step")
        phi: list[float] = []
        M: list[float] = []
        for i, row in enumerate(rows):
            if len(row) != 3:
                raise InputError(f"steps[{i}] = {row!r}: each step is (phi_start, phi_end, M)")
            a, b, m = (real(v, f"steps[{i}][{j}]", tiny_ok=True) for j, v in enumerate(row))
            if not b > a:
                raise InputError(f"steps[{i}]: phi_end {b:g} must exceed phi_start {a:g}")
            if i and abs(a - phi[-1]) > 1e-12 * max(1.0, abs(a)):
                raise InputError(f"steps[{i}] starts at {a:g} rad but the previous step ended at {phi[-1]:g}; "
                                 "steps must be contiguous")
            phi += [a, b]
            M += [m, m]
        return cls(np.array(phi), np.array(M))

    @classmethod
    def constant(cls, M: float, *, period: float = TWO_PI, start: float = 0.0) -> MomentCurve:
        """A constant moment over one period."""
        M, start = real(M, "M", tiny_ok=True), real(start, "start", tiny_ok=True)
        period = real(period, "period", lo=0.0, lo_open=True)
        return cls(np.array([start, start + period]), np.array([M, M]))

    @classmethod
    def function(
        cls,
        f: Callable[[np.ndarray], np.ndarray],
        *,
        period: float = TWO_PI,
        start: float = 0.0,
        tol: float = 1e-9,
        max_points: int = 2**21,
    ) -> MomentCurve:
        """Sample a callable ``f(phi) -> M`` (vectorised over numpy arrays) into chords.

        Intervals are halved until the chord's midpoint is within ``tol`` (relative to the
        largest |M|) of the function, so the chords stand for the function to that
        tolerance; the deviation met is stored in ``approx_error``. A jump in ``f`` is
        resolved to the tolerance in φ that the point budget allows.

        >>> import numpy as np
        >>> c = MomentCurve.function(lambda p: 10 + 5 * np.sin(p), tol=1e-6)
        >>> round(c.mean(), 6), c.approx_error < 1e-4
        (10.0, True)
        """
        if not period > 0:
            raise InputError(f"period = {period!r} rad must be positive")
        phi = np.linspace(start, start + period, 65)
        M = cls._call(f, phi)
        scale = max(float(np.abs(M).max()), 1e-300)
        err = 0.0
        while True:
            mid = 0.5 * (phi[:-1] + phi[1:])
            M_mid = cls._call(f, mid)
            dev = np.abs(M_mid - 0.5 * (M[:-1] + M[1:]))
            scale = max(scale, float(np.abs(M_mid).max()))
            # an interval already too narrow to halve (a jump of f) is left as it is
            split = (dev > tol * scale) & (np.diff(phi) > 1e-13 * period)
            err = float(dev[~split].max()) if (~split).any() else err
            if not split.any():
                break
            if phi.size + int(split.sum()) > max_points:
                err = float(dev.max())
                break
            phi_new = np.empty(phi.size + int(split.sum()))
            M_new = np.empty_like(phi_new)
            # interleave the new midpoints after the left end of each split interval
            counts = np.ones(phi.size, dtype=int)
            counts[:-1] += split
            pos = np.cumsum(counts) - counts
            phi_new[pos] = phi
            M_new[pos] = M
            pos_mid = pos[:-1][split] + 1
            phi_new[pos_mid] = mid[split]
            M_new[pos_mid] = M_mid[split]
            phi, M = phi_new, M_new
        return cls(phi, M, approx_error=err)

    @staticmethod
    def _call(f: Callable[[NDArray[np.float64]], ArrayLike], phi: NDArray[np.float64]) -> NDArray[np.float64]:
        M = np.asarray(f(phi), dtype=float)
        if M.shape != phi.shape:
            M = np.broadcast_to(M, phi.shape).astype(float)
        bad = ~np.isfinite(M) | (np.abs(M) > MAGNITUDE_MAX)
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise InputError(f"the moment function gave {M[i]!r} at phi = {phi[i]:g} rad; it must be finite and "
                             f"within ±{MAGNITUDE_MAX:g} N·m over the whole period")
        return M

    # ----------------------------------------------------------------- queries
    @property
    def period(self) -> float:
        """The angle the curve spans, rad."""
        return float(self.phi[-1] - self.phi[0])

    @property
    def start(self) -> float:
        """φ at the start of the period, rad."""
        return float(self.phi[0])

    def work(self) -> float:
        """∫ M dφ over the period, J."""
        return float(np.sum(0.5 * (self.M[1:] + self.M[:-1]) * np.diff(self.phi)))

    def integral(self, phi: ArrayLike) -> NDArray[np.float64]:
        """∫ M dφ from the start of the period to each φ (J), exact for the chords.

        >>> c = MomentCurve.points([0.0, 2.0], [0.0, 4.0])
        >>> c.integral([0.0, 1.0, 2.0]).tolist()
        [0.0, 1.0, 4.0]
        """
        x = np.asarray(phi, dtype=float)
        if ((x < self.phi[0]) | (x > self.phi[-1])).any():
            raise InputError(f"phi outside the period {self.phi[0]:g}..{self.phi[-1]:g} rad")
        p, M = self.phi, self.M
        E = np.concatenate(([0.0], np.cumsum(0.5 * (M[1:] + M[:-1]) * np.diff(p))))
        j = np.clip(np.searchsorted(p, x, side="right") - 1, 0, p.size - 2)
        h = p[j + 1] - p[j]
        t = x - p[j]
        with np.errstate(invalid="ignore", divide="ignore"):
            slope = np.where(h > 0, (M[j + 1] - M[j]) / np.where(h > 0, h, 1.0), 0.0)
        out: NDArray[np.float64] = E[j] + M[j] * t + 0.5 * slope * t * t
        return out

    def with_knots(self, phi: ArrayLike) -> MomentCurve:
        """The same curve with extra knots at the given angles (no change to its values)."""
        x = np.unique(np.clip(np.asarray(phi, dtype=float), self.phi[0], self.phi[-1]))
        zero = MomentCurve(np.concatenate(([self.phi[0]], x, [self.phi[-1]])), np.zeros(x.size + 2))
        return _combine(self, zero, +1.0)

    def mean(self) -> float:
        """The mean moment over the period, N·m (the constant with the same work)."""
        return self.work() / self.period

    def limits(self, x: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Left and right limits M(x−), M(x+) at angles x inside the period (they differ at jumps)."""
        p = self.phi
        xs = np.asarray(x, dtype=float)
        n = p.size
        j = np.clip(np.searchsorted(p, xs, side="right") - 1, 0, n - 2)   # last knot <= x
        i = np.clip(np.searchsorted(p, xs, side="left"), 1, n - 1)        # first knot >= x
        right = self._interp(j, j + 1, xs)
        left = self._interp(i - 1, i, xs)
        return left, right

    def _interp(self, a: NDArray[np.intp], b: NDArray[np.intp], x: NDArray[np.float64]) -> NDArray[np.float64]:
        p, M = self.phi, self.M
        h = p[b] - p[a]
        with np.errstate(invalid="ignore", divide="ignore"):
            t = np.where(h > 0, (x - p[a]) / np.where(h > 0, h, 1.0), 0.0)
        out: NDArray[np.float64] = M[a] + t * (M[b] - M[a])
        return out

    def __call__(self, phi: ArrayLike) -> NDArray[np.float64]:
        """M(φ), right-continuous at jumps; φ is taken modulo the period."""
        x = np.asarray(phi, dtype=float)
        x = self.start + np.mod(x - self.start, self.period)
        return self.limits(x)[1]

    def __add__(self, other: MomentCurve) -> MomentCurve:
        return _combine(self, other, +1.0)

    def __sub__(self, other: MomentCurve) -> MomentCurve:
        return _combine(self, other, -1.0)

    def __neg__(self) -> MomentCurve:
        return MomentCurve(self.phi, -self.M, self.approx_error)


def knots_union(*curves: MomentCurve) -> np.ndarray:
    """Sorted distinct knots of several curves over the same period."""
    return np.unique(np.concatenate([c.phi for c in curves]))


def _combine(a: MomentCurve, b: MomentCurve, sign: float) -> MomentCurve:
    if abs(a.start - b.start) > 1e-12 * max(1.0, a.period) or abs(a.period - b.period) > 1e-9 * a.period:
        raise InputError(
            f"the curves cover different periods ({a.start:g}..{a.start + a.period:g} and "
            f"{b.start:g}..{b.start + b.period:g} rad); give both over the same period"
        )
    if a.phi.size == b.phi.size and np.array_equal(a.phi, b.phi):       # same knots: no union needed
        return MomentCurve._valid(a.phi, a.M + sign * b.M, a.approx_error + b.approx_error)
    for x, y, s in ((a, b, sign), (b, a, sign)):                         # y a single chord (a constant)
        if y.phi.size == 2:
            t = (x.phi - y.phi[0]) / (y.phi[1] - y.phi[0])
            line = y.M[0] + t * (y.M[1] - y.M[0])
            M = x.M + s * line if x is a else line + s * x.M
            return MomentCurve._valid(x.phi, M, a.approx_error + b.approx_error)
    u = knots_union(a, b)
    la, ra = a.limits(u)
    lb, rb = b.limits(u)
    left, right = la + sign * lb, ra + sign * rb
    # each knot contributes its left value, then its right value when they differ (a jump)
    jump = left != right
    jump[0] = jump[-1] = False
    phi = np.repeat(u, 1 + jump)
    M = np.empty(phi.size)
    pos = np.cumsum(1 + jump) - (1 + jump)
    M[pos] = np.where(jump, left, right)
    M[pos[0]] = right[0]
    M[pos[-1]] = left[-1]
    M[pos[jump] + 1] = right[jump]
    return MomentCurve(phi, M, a.approx_error + b.approx_error)


def balance(M_d: MomentCurve | None = None, M_r: MomentCurve | None = None) -> tuple[MomentCurve, MomentCurve]:
    """Complete a pair of moment curves: the missing one is the constant that balances the work.

    >>> from math import pi
    >>> M_d, M_r = balance(M_r=MomentCurve.steps([(0, pi / 4, 60.0), (pi / 4, 2 * pi, 10.0)]))
    >>> round(float(M_d(0.0)), 10)
    16.25
    """
    if M_d is None and M_r is None:
        raise InputError("give M_d, M_r or both")
    if M_d is None:
        assert M_r is not None
        M_d = MomentCurve.constant(M_r.mean(), period=M_r.period, start=M_r.start)
    elif M_r is None:
        M_r = MomentCurve.constant(M_d.mean(), period=M_d.period, start=M_d.start)
    return M_d, M_r
