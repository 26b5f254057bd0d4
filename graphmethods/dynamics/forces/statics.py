"""The statics of one link in the complex plane: cross products, moments about a point, the 2×2 solve of
a force plan's closing directions, and the tangential part of a reaction from a link's moments.

Plane vectors are complex numbers x + iy over the positions (arrays of shape (n,)); moments are
counterclockwise positive. :mod:`graphmethods.dynamics.forces.base` re-exports these names.

>>> import numpy as np
>>> x, y = solve2(np.array([1 + 0j]), np.array([1j]), np.array([3 + 4j]))   # 3·e1 + 4·e2
>>> float(x[0]), float(y[0])
(3.0, 4.0)
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from graphmethods.dynamics.forces.base import Force

Cx = NDArray[np.complex128]
Fl = NDArray[np.float64]


def cross(a: Cx | complex, b: Cx | complex) -> Fl:
    """z-component of a × b for complex plane vectors (Im(conj(a)·b))."""
    out: Fl = np.imag(np.conj(a) * b)
    return out


def unit(z: Cx) -> Cx:
    """z/|z| (complex plane vectors)."""
    out: Cx = z / np.abs(z)
    return out


def solve2(e1: Cx, e2: Cx, rhs: Cx) -> tuple[Fl, Fl]:
    """Real x, y with ``x·e1 + y·e2 = rhs`` (Cramer's rule, vectorised): the intersection of two
    directions in a force plan. A parallel pair gives inf/NaN: callers check first."""
    det = cross(e1, e2)
    with np.errstate(divide="ignore", invalid="ignore"):
        x: Fl = cross(rhs, e2) / det
        y: Fl = cross(e1, rhs) / det
    return x, y


def moment_about(forces: Sequence[Force], X: Cx) -> Fl:
    """Σ [(at − X) × F + M] over the forces, N·m (n,)."""
    total: Fl = np.zeros(np.shape(X), dtype=float)
    for f in forces:
        total = total + cross(f.at - X, f.F) + f.M
    return total


def tangential(forces: Sequence[Force], P: Cx, C: Cx) -> tuple[Cx, Cx]:
    """The unit direction u of a link P→C and the tangential part ``R^τ`` at P of the reaction
    that holds it, from the link's moments about C: ``(P − C) × R^τ + M_C = 0``, R^τ ⟂ PC
    (positions m, forces N).

    >>> import numpy as np
    >>> from graphmethods.dynamics.forces.base import Force, xy
    >>> f = Force("F", F=np.array([-10j]), at=np.array([0.5 + 0j]), M=np.zeros(1))   # 10 N down mid-link
    >>> u, R_t = tangential([f], np.array([0j]), np.array([1 + 0j]))
    >>> xy(u[0]), xy(R_t[0])              # half the load held at P
    ([1.0, 0.0], [0.0, 5.0])
    """
    u = unit(C - P)
    t = 1j * u
    R_t: Cx = -moment_about(forces, C) / cross(P - C, t) * t
    return u, R_t


def tangential_step(link: str, C: str, outer: str, P: str) -> str:
    """The step :func:`tangential` takes, in words: ``"link 2: ΣM_C = 0 gives R^τ_12 ⟂ AC"``.

    >>> tangential_step("2", "B", "12", "A")
    'link 2: ΣM_B = 0 gives R^τ_12 ⟂ AB'
    """
    return f"link {link}: ΣM_{C} = 0 gives R^τ_{outer} ⟂ {P}{C}"
