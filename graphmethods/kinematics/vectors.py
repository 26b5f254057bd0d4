"""Angles and arrays for the frozen results: wrapped angles, read-only arrays.

>>> import numpy as np
>>> float(wrap(3 * np.pi)), frozen(np.ones(2)).flags.writeable
(-3.141592653589793, False)
"""

from __future__ import annotations

import numpy as np

TWO_PI = 2.0 * np.pi


def wrap(angle: float | np.ndarray) -> np.ndarray:
    """Angle(s) wrapped into [−π, π) (radians)."""
    return np.mod(np.asarray(angle, dtype=float) + np.pi, TWO_PI) - np.pi


def frozen(a) -> np.ndarray:
    """A read-only float array (a copy only when needed)."""
    a = np.asarray(a)
    if a.flags.writeable:
        a = a.copy() if a.base is not None else a
        a.flags.writeable = False
    return a
