"""Small unit helpers shared by every layer: parsing numbers and fractions, rev/min <-> rad/s.

>>> parse_number("1/300")
0.0033333333333333335
>>> round(omega_from_n(600.0), 4)
62.8319
"""

from __future__ import annotations

import math
from fractions import Fraction

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
