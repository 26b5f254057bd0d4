"""Plane vectors as pairs of numpy arrays (x, y), vectorised over positions.

The kinematics core keeps every point as two contiguous arrays (one x, one y, shape
(n,)) while it computes, and stacks them into (n, 2) arrays only for the results:
this keeps 10⁵ positions fast.

>>> import numpy as np
>>> cross(1.0, 0.0, 0.0, 1.0)
1.0
>>> x, y, s = intersect(0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)   # y = 1 meets x = 0
>>> float(x), float(y), float(s)
(0.0, 1.0, 1.0)
"""

from __future__ import annotations

import numpy as np

TWO_PI = 2.0 * np.pi


def cross(ax, ay, bx, by):
    """z-component of a × b (= |a||b| sin of the angle from a to b, counterclockwise +)."""
    return ax * by - ay * bx


def perp(x, y):
    """The vector turned 90° counterclockwise: (x, y) -> (−y, x)."""
    return -y, x


def wrap(angle: float | np.ndarray) -> np.ndarray:
    """Angle(s) wrapped into [−π, π) (radians)."""
    return np.mod(np.asarray(angle, dtype=float) + np.pi, TWO_PI) - np.pi


def norm_angle(angle):
    """Angle(s) normalised into [0, 2π) exactly (a tiny negative angle gives 0, not 2π)."""
    a = np.mod(np.asarray(angle, dtype=float), TWO_PI)
    return np.where(a >= TWO_PI, 0.0, a) + 0.0


def travel(phi_from, phi_to, sense: int):
    """Crank rotation in radians, in [0, 2π), from ``phi_from`` to ``phi_to`` turning in ``sense``
    (+1 counterclockwise, −1 clockwise)."""
    return np.mod(sense * (np.asarray(phi_to, dtype=float) - phi_from), TWO_PI)


def intersect(p1x, p1y, d1x, d1y, p2x, p2y, d2x, d2y):
    """Intersection of the line through P1 along unit d1 with the line through P2 along unit d2.

    Returns ``(x, y, sin)`` where ``sin = d1 × d2`` is the sine of the angle between the
    lines (0 when they are parallel: then x, y are not finite; callers check ``sin`` first).
    """
    s = cross(d1x, d1y, d2x, d2y)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = cross(p2x - p1x, p2y - p1y, d2x, d2y) / s
    return p1x + t * d1x, p1y + t * d1y, s


def stack(x, y, n: int | None = None) -> np.ndarray:
    """(n, 2) float array from x and y arrays (scalars broadcast to n rows); read-only."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    if n is not None and x.ndim == 0 and y.ndim == 0:
        return np.broadcast_to(np.array([float(x), float(y)]), (n, 2))
    else:
        out = np.stack(np.broadcast_arrays(x, y), axis=-1)
    out.flags.writeable = False
    return out


def frozen(a) -> np.ndarray:
    """A read-only float array (a copy only when needed)."""
    a = np.asarray(a)
    if a.flags.writeable:
        a = a.copy() if a.base is not None else a
        a.flags.writeable = False
    return a
