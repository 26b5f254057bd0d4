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
    """The maximum of ``f`` on [lo, hi]: ``(x_max, f(x_max))``.

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
    x = np.linspace(lo, hi, n)
    v = np.asarray(f(x), dtype=float)
    if stop_above is not None and bool(np.any(v > stop_above)):
        k = int(np.argmax(v))
        return float(x[k]), float(v[k])
    left = np.concatenate(([-np.inf], v[:-1]))
    right = np.concatenate((v[1:], [-np.inf]))
    peaks = np.flatnonzero((v >= left) & (v >= right))
    peaks = peaks[np.argsort(-v[peaks], kind="stable")][:keep]
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
    cand_x = np.concatenate((x[peaks], c, d, [lo, hi]))
    cand_v = np.concatenate((v[peaks], fc, fd, [v[0], v[-1]]))
    k = int(np.argmax(cand_v))
    return float(cand_x[k]), float(cand_v[k])
