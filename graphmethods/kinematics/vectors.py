"""Angles and arrays for the frozen results: wrapped angles, read-only arrays, and the array types.

``FloatArray`` (real values over the positions: angles in rad, ω in rad/s, lengths in m) and
``ComplexArray`` (plane vectors x + iy over the positions: positions in m, velocities in m/s)
are the array types the numeric core annotates with.

>>> import numpy as np
>>> float(wrap(3 * np.pi)), frozen(np.ones(2)).flags.writeable
(-3.141592653589793, False)
"""

from __future__ import annotations

from typing import Any, TypeAlias, TypeVar

import numpy as np
from numpy.typing import NDArray

#: real values over the positions (rad, rad/s, m, ...)
FloatArray: TypeAlias = NDArray[np.float64]
#: plane vectors as complex numbers x + iy over the positions (m, m/s, m/s²)
ComplexArray: TypeAlias = NDArray[np.complexfloating[Any, Any]]

_S = TypeVar("_S", bound=np.generic)

TWO_PI = 2.0 * np.pi


def wrap(angle: float | FloatArray) -> FloatArray:
    """Angle(s) wrapped into [−π, π) (radians)."""
    out: FloatArray = np.mod(np.asarray(angle, dtype=float) + np.pi, TWO_PI) - np.pi
    return out


def frozen(a: NDArray[_S]) -> NDArray[_S]:
    """A read-only view of the array ``a`` (a copy only when needed; the dtype is kept)."""
    arr = a
    if arr.flags.writeable:
        arr = arr.copy() if arr.base is not None else arr
        arr.flags.writeable = False
    return arr
