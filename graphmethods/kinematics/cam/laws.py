"""The laws of follower motion over one phase, in closed form with their derivatives.

A rise of lift h over the cam angle Φ follows ``s = h·f(x)`` with ``x = φ/Φ`` in [0, 1]; a return
of the same law is ``s = h·(1 − f(x))`` (domain.md §8c). The derivatives with respect to the cam
angle (the *analogues*, аналоги; 类速度, 类加速度) are ``ds/dφ = h·f'(x)/Φ``,
``d²s/dφ² = h·f''(x)/Φ²`` and ``d³s/dφ³ = h·f'''(x)/Φ³``; at a cam speed ω the follower's
velocity, acceleration and jerk are ω·ds/dφ, ω²·d²s/dφ², ω³·d³s/dφ³.

=================  ==========================  ===================  ==========================
law                f(x)                        ru                   zh
=================  ==========================  ===================  ==========================
``uniform``        x                           равномерный          等速
``parabolic``      2x² (x ≤ ½), 1 − 2(1 − x)²  равноускоренный      等加速等减速
``harmonic``       (1 − cos πx)/2              косинусоидальный     余弦加速度 (简谐)
``cycloidal``      x − sin(2πx)/(2π)           синусоидальный       正弦加速度 (摆线)
``polynomial_345`` 10x³ − 15x⁴ + 6x⁵           полиномиальный 3-4-5 3-4-5 多项式
=================  ==========================  ===================  ==========================

The uniform law's velocity jumps at the ends of the phase (the acceleration is infinite there: a
hard, rigid impact); the parabolic and harmonic laws' accelerations jump (soft impacts; the
parabolic one also at x = ½); the cycloidal and 3-4-5 laws have none.

>>> f = unit_law("cycloidal", [0.0, 0.25, 0.5])
>>> [round(float(v), 12) for v in f[0]]
[0.0, 0.090845056908, 0.5]
>>> [round(float(v), 12) for v in unit_law("harmonic", [0.5])[1]]
[1.570796326795]
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: The laws a rise or a return may follow (the problem file's ``law``).
LAWS = ("uniform", "parabolic", "harmonic", "cycloidal", "polynomial_345")

#: Where inside a phase (x in (0, 1)) a law is only piecewise smooth: its second derivative jumps.
BREAKS: dict[str, tuple[float, ...]] = {"parabolic": (0.5,)}

Array = NDArray[np.float64]


def unit_law(law: str, x: ArrayLike, *, left: bool = False) -> tuple[Array, Array, Array, Array]:
    """f(x), f'(x), f''(x), f'''(x) of a normalised rise (f(0) = 0, f(1) = 1) at x in [0, 1].

    Parameters
    ----------
    law : str
        One of :data:`LAWS`.
    x : array_like
        Fractions of the phase, 0 ≤ x ≤ 1 (dimensionless).
    left : bool
        At a break inside the phase (the parabolic law's x = ½) take the limit from the left
        instead of from the right.

    Returns
    -------
    tuple of four arrays
        The normalised displacement and its first three derivatives with respect to x.

    Examples
    --------
    >>> [float(v[0]) for v in unit_law("parabolic", [0.5])]
    [0.5, 2.0, -4.0, 0.0]
    >>> [float(v[0]) for v in unit_law("parabolic", [0.5], left=True)]
    [0.5, 2.0, 4.0, 0.0]
    """
    x = np.asarray(x, dtype=float)
    zero = np.zeros_like(x)
    if law == "uniform":
        return x.copy(), zero + 1.0, zero, zero.copy()
    if law == "parabolic":
        first = x <= 0.5 if left else x < 0.5
        y = 1.0 - x
        f = np.where(first, 2.0 * x * x, 1.0 - 2.0 * y * y)
        d1 = np.where(first, 4.0 * x, 4.0 * y)
        d2 = np.where(first, 4.0, -4.0) + zero
        return f, d1, d2, zero.copy()
    if law == "harmonic":
        c, s = np.cos(math.pi * x), np.sin(math.pi * x)
        return ((1.0 - c) / 2.0, math.pi * s / 2.0, math.pi ** 2 * c / 2.0, -math.pi ** 3 * s / 2.0)
    if law == "cycloidal":
        c, s = np.cos(2.0 * math.pi * x), np.sin(2.0 * math.pi * x)
        return (x - s / (2.0 * math.pi), 1.0 - c, 2.0 * math.pi * s, 4.0 * math.pi ** 2 * c)
    if law == "polynomial_345":
        x2 = x * x
        return (x2 * x * (10.0 - 15.0 * x + 6.0 * x2), 30.0 * x2 * (1.0 - 2.0 * x + x2),
                60.0 * x * (1.0 - 3.0 * x + 2.0 * x2), 60.0 - 360.0 * x + 360.0 * x2)
    raise ValueError(f"unknown law {law!r}; give one of {', '.join(LAWS)}")


#: The impacts a law causes: (where inside the phase, kind), kind ``hard`` (velocity jumps,
#: infinite acceleration) or ``soft`` (acceleration jumps), when the phase joins dwells at both ends.
def law_impacts(law: str) -> tuple[tuple[float, str], ...]:
    """Where a law alone, between two dwells, causes impacts: ``((x, "hard"|"soft"), ...)``.

    >>> law_impacts("parabolic")
    ((0.0, 'soft'), (0.5, 'soft'), (1.0, 'soft'))
    >>> law_impacts("cycloidal")
    ()
    """
    if law == "uniform":
        return ((0.0, "hard"), (1.0, "hard"))
    if law == "parabolic":
        return ((0.0, "soft"), (0.5, "soft"), (1.0, "soft"))
    if law == "harmonic":
        return ((0.0, "soft"), (1.0, "soft"))
    return ()
