"""What differs between the supported versions of our dependencies, in one place.

numpy 2.0 renamed ``np.trapz`` to ``np.trapezoid``; the package supports numpy ≥ 1.23 (the floor
that CI tests), so it takes whichever the installed numpy has.

>>> import numpy as np
>>> float(trapezoid(np.array([0.0, 1.0, 2.0]), np.array([0.0, 1.0, 2.0])))   # ∫₀² x dx
2.0
"""

from __future__ import annotations

import numpy as np

#: the trapezoidal rule, ``trapezoid(y, x)``: numpy ≥ 2.0's ``np.trapezoid``, else ``np.trapz``
trapezoid = getattr(np, "trapezoid", None) or getattr(np, "trapz")  # noqa: B009 - np.trapz is gone from numpy 2.4

__all__ = ["trapezoid"]
