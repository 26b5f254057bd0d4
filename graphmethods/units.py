"""Small unit helpers shared by every layer: parsing numbers and fractions, rev/min <-> rad/s.

>>> parse_number("1/300")
0.0033333333333333335
>>> round(omega_from_n(600.0), 4)
62.8319
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from graphmethods.errors import InputError


def parse_number(text: str | float | int, *, name: str = "value") -> float:
    """Parse a finite number given as ``"0.05"``, ``"1/300"``, ``"5e-3"`` or a float.

    Raises
    ------
    InputError
        If the text is not a number or fraction, or is NaN or infinite.
    """
    if isinstance(text, (int, float)) and not isinstance(text, bool):
        value = float(text)
    else:
        s = str(text).strip()
        try:
            value = float(Fraction(s)) if "/" in s else float(s)
        except (ValueError, ZeroDivisionError):
            raise InputError(f"{name}: {text!r} is not a number; write e.g. 0.05, 5e-2 or 1/20") from None
    if not math.isfinite(value):
        raise InputError(f"{name}: {text!r} is not finite; give a finite number")
    return value


def omega_from_n(n_rpm: float) -> float:
    """Angular speed in rad/s from a speed in rev/min: ω = π n / 30."""
    return math.pi * n_rpm / 30.0


def n_from_omega(omega: float) -> float:
    """Speed in rev/min from an angular speed in rad/s: n = 30 ω / π."""
    return 30.0 * omega / math.pi


#: Convenient drawing numbers, × 10^k (domain.md §1); some textbooks also allow 1.5 and 3.
CONVENIENT = (1.0, 2.0, 2.5, 4.0, 5.0)
CONVENIENT_WIDE = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0)


def _candidates(value: float, series) -> list[float]:
    if not (value > 0 and math.isfinite(value)):
        raise InputError(f"a convenient number needs a positive finite value, got {value!r}")
    k = math.floor(math.log10(value))
    # written as decimal literals, so 2.5e-2 is the float nearest 0.025 (not 2.5 × 0.01)
    return sorted(float(f"{float(c)!r}e{kk}") for kk in (k - 1, k, k + 1) for c in series)


def convenient_at_least(value: float, series=CONVENIENT) -> float:
    """The smallest convenient number (1, 2, 2.5, 4, 5 × 10^k) not below ``value``.

    >>> convenient_at_least(37.0), convenient_at_least(0.0042), convenient_at_least(2.0)
    (40.0, 0.005, 2.0)
    """
    return next(v for v in _candidates(value, series) if v >= value * (1 - 1e-12))


def convenient_at_most(value: float, series=CONVENIENT) -> float:
    """The largest convenient number (1, 2, 2.5, 4, 5 × 10^k) not above ``value``.

    >>> convenient_at_most(37.0), convenient_at_most(0.0042), convenient_at_most(2.5)
    (25.0, 0.004, 2.5)
    """
    return max(v for v in _candidates(value, series) if v <= value * (1 + 1e-12))


def finite_array(values, name: str) -> np.ndarray:
    """A flat, read-only float array of finite numbers, or an InputError naming the first bad entry.

    >>> finite_array([1, 2.5], "areas").tolist()
    [1.0, 2.5]
    """
    try:
        arr = np.array(values, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name}: expected a list of numbers, got {values!r}") from None
    if arr.ndim > 1:
        raise InputError(f"{name}: expected a flat list of numbers, got shape {arr.shape}")
    arr = arr.reshape(-1)
    bad = ~np.isfinite(arr)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise InputError(f"{name}[{i}] = {arr[i]!r} is not a finite number; remove or fix it")
    arr.setflags(write=False)
    return arr
