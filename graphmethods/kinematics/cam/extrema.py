"""The largest value of a function on an interval, to rounding: a grid, then golden sections.

The cam's design quantities (the base radius that keeps the pressure angle within [α], the largest
pressure angle, the smallest radius of curvature) are extrema over the cam angle of closed-form
functions that are smooth on each piece of a phase. A grid of ``n`` points finds every local
maximum that is at least one grid step wide; a golden-section search on each of the best few
brackets (all of them at once, vectorised) then refines it to a bracket of ~1e-16 of the interval,
where the value is exact to rounding (the function is flat at a maximum; at an end of the interval
the search closes on the end).

>>> import numpy as np
>>> x, v = maximize(lambda t: np.sin(3.0 * t), 0.0, 1.0)
>>> round(x, 6), v
(0.523599, 1.0)
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]
_GOLD = (math.sqrt(5.0) - 1.0) / 2.0


def maximize(f: Callable[[Array], Array], lo: float, hi: float, *, n: int = 513, keep: int = 6,
             iterations: int = 90, stop_above: float | None = None) -> tuple[float, float]:
    """The maximum of ``f`` on [lo, hi]: ``(x_max, f(x_max))`` (:func:`maximize_rows` of one row).

    Parameters
    ----------
    f : callable
        Vectorised: an array of x in [lo, hi] to an array of values.
    lo, hi : float
        The interval (closed).
    n : int
        Grid points (local maxima narrower than two steps may be missed).
    keep : int
        How many of the grid's best local maxima are refined.
    iterations : int
        Golden-section steps (each shrinks the bracket by 0.618).
    stop_above : float or None
        When the grid already has a value above this, that grid point is returned unrefined (a question
        of "is the maximum above it?" is then answered; the refined maximum is never below a grid value).

    Returns
    -------
    tuple of float
        Where the maximum is and its value.

    Examples
    --------
    >>> import numpy as np
    >>> maximize(lambda t: -t, 0.0, 2.0)
    (0.0, -0.0)
    """
    x, v = maximize_rows(lambda t: np.asarray(f(t.ravel()), dtype=float).reshape(t.shape), lo, hi, 1, n=n,
                         keep=keep, iterations=iterations, stop_above=stop_above)
    return float(x[0]), float(v[0])


def maximize_rows(f: Callable[[Array], Array], lo: float, hi: float, rows: int, *, n: int = 513, keep: int = 6,
                  iterations: int = 90, stop_above: float | None = None) -> tuple[Array, Array]:
    """The maxima on [lo, hi] of ``rows`` functions at once (row r of ``f``'s values is the r-th function).

    The grid and the golden sections of :func:`maximize` for every row together: ``f`` takes an array of x of
    shape (rows, m) and returns the values of the same shape, the function of row r at row r's x. A row's
    result is what :func:`maximize` gives for that row's function alone (the same operations, element by
    element).

    Parameters
    ----------
    f : callable
        (rows, m) array of x to a (rows, m) array of values.
    lo, hi : float
        The interval (closed), the same for every row.
    rows : int
        How many functions.
    n, keep, iterations, stop_above
        As for :func:`maximize`, per row (a row whose grid is above ``stop_above`` keeps its grid maximum).

    Returns
    -------
    tuple of arrays
        Where each row's maximum is and its value, shape (rows,).

    Examples
    --------
    >>> import numpy as np
    >>> k = np.array([[1.0], [3.0]])
    >>> x, v = maximize_rows(lambda t: np.sin(k * t), 0.0, 1.0, 2)
    >>> x.round(6).tolist(), v.round(12).tolist()
    ([1.0, 0.523599], [0.841470984808, 1.0])
    """
    x = np.linspace(lo, hi, n)
    v = np.asarray(f(np.broadcast_to(x, (rows, n))), dtype=float)
    r = np.arange(rows)
    stop = np.any(v > stop_above, axis=1) if stop_above is not None else np.zeros(rows, dtype=bool)
    g = np.argmax(v, axis=1)
    if stop.all():                          # every row already above: its grid maximum, unrefined
        return x[g], v[r, g]
    edge = np.full((rows, 1), -np.inf)
    is_peak = (v >= np.concatenate((edge, v[:, :-1]), 1)) & (v >= np.concatenate((v[:, 1:], edge), 1))
    peaks = np.argsort(-np.where(is_peak, v, -np.inf), axis=1, kind="stable")[:, :keep]   # best first, then the rest
    real = np.take_along_axis(is_peak, peaks, 1)            # a row with fewer local maxima: the rest are padding
    a = x[np.maximum(peaks - 1, 0)]
    b = x[np.minimum(peaks + 1, n - 1)]
    c = b - _GOLD * (b - a)
    d = a + _GOLD * (b - a)
    fc, fd = np.asarray(f(c), dtype=float), np.asarray(f(d), dtype=float)
    for _ in range(iterations):
        up = fc >= fd                       # the maximum is in [a, d]: d becomes c's; else in [c, b]
        a, b = np.where(up, a, c), np.where(up, d, b)
        c, d, fc, fd = (np.where(up, b - _GOLD * (b - a), d), np.where(up, c, a + _GOLD * (b - a)),
                        np.where(up, fc, fd), np.where(up, fc, fd))
        new = np.where(up, c, d)            # the one new point per bracket
        fn = np.asarray(f(new), dtype=float)
        fc, fd = np.where(up, fn, fc), np.where(up, fd, fn)
    none = -np.inf
    cand_x = np.concatenate((x[peaks], c, d, np.broadcast_to([lo, hi], (rows, 2))), 1)
    cand_v = np.concatenate((np.where(real, np.take_along_axis(v, peaks, 1), none), np.where(real, fc, none),
                             np.where(real, fd, none), v[:, :1], v[:, -1:]), 1)
    k = np.argmax(cand_v, axis=1)
    x_max, v_max = cand_x[r, k], cand_v[r, k]
    return np.where(stop, x[g], x_max), np.where(stop, v[r, g], v_max)   # a row above: its grid maximum
