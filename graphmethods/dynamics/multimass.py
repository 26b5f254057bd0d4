"""Drives of several masses: a chain of shafts, gears and masses reduced to one shaft (domain.md §2).

A drive (motor, couplings, gearbox, the machine's shaft) is modelled as a chain of rotating masses
J_1 … J_n joined by elastic shafts of torsional stiffness c_1 … c_{n−1}; each mass and each shaft
turns at its own speed ω_i = u_i·ω, u_i the speed ratio to the shaft chosen for the reduction.
Keeping the kinetic energy ½J_iω_i² and the elastic energy ½c_jΔθ_j² (Δθ_j = u_j·Δθ):

``J_i' = J_i·u_i²``,  ``c_j' = c_j·u_j²``,  ``M_i' = M_i·u_i``

(a shaft turning u times faster counts u² times more). The reduced chain is the two-, three- or
n-mass torsional model; its free vibrations have the natural frequencies ω_k² the eigenvalues of
``K x = ω² J x`` (one is 0: the drive turning as a whole). Closed forms: two masses
``ω² = c'(J_1' + J_2')/(J_1' J_2')``; three masses the roots of
``ω⁴ − ω²(c_1'/J_1' + c_1'/J_2' + c_2'/J_2' + c_2'/J_3') + c_1'c_2'(J_1' + J_2' + J_3')/(J_1'J_2'J_3') = 0``.
Taken rigid (c → ∞), the chain is one mass J_e = ΣJ_i' (:func:`~graphmethods.dynamics.reduction.reduce_drive`).

>>> d = reduce_chain([Mass("motor", 0.05, 4.0), Mass("machine", 2.0, 1.0)], [Shaft("coupling", 800.0, 4.0)])
>>> [round(float(x), 6) for x in d.J], [round(float(x), 3) for x in d.c], round(d.J_e, 6)
([0.8, 2.0], [12800.0], 2.8)
>>> round(float(d.natural_frequencies[0]), 3)    # sqrt(12800·2.8/(0.8·2))
149.666
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from graphmethods.errors import InputError
from graphmethods.units import real


@dataclass(frozen=True)
class Mass:
    """A rotating mass of the drive: J (kg·m²) on a shaft turning at ``u``·ω, with a moment M (N·m, + driving)."""

    name: str
    J: float
    u: float = 1.0
    M: float = 0.0


@dataclass(frozen=True)
class Shaft:
    """An elastic shaft between two neighbouring masses: torsional stiffness c (N·m/rad), turning at ``u``·ω."""

    name: str
    c: float
    u: float = 1.0


@dataclass(frozen=True, eq=False)
class ReducedChain:
    """A chain drive reduced to one shaft.

    Attributes
    ----------
    names, shaft_names : tuple of str
    J : ndarray
        Reduced inertias J_i' = J_i u_i², kg·m².
    c : ndarray
        Reduced stiffnesses c_j' = c_j u_j², N·m/rad.
    M : ndarray
        Reduced moments M_i' = M_i u_i, N·m.
    natural_frequencies : ndarray
        The non-zero natural frequencies, rad/s, ascending.
    modes : ndarray
        Their mode shapes (columns), the largest amplitude 1.
    J_given, u, c_given, u_shafts : ndarray
        The drive as given: inertias, their speed ratios, stiffnesses and the shafts' speed ratios.
    """

    names: tuple[str, ...]
    shaft_names: tuple[str, ...]
    J: np.ndarray
    c: np.ndarray
    M: np.ndarray
    natural_frequencies: np.ndarray
    modes: np.ndarray
    J_given: np.ndarray
    u: np.ndarray
    c_given: np.ndarray
    u_shafts: np.ndarray

    @property
    def J_e(self) -> float:
        """The rigid drive's J_e = ΣJ_i', kg·m²."""
        return float(self.J.sum())

    @property
    def M_e(self) -> float:
        """The rigid drive's M_e = ΣM_i', N·m."""
        return float(self.M.sum())

    def to_dict(self) -> dict[str, object]:
        return {"masses": list(self.names), "J": self.J.tolist(), "shafts": list(self.shaft_names),
                "c": self.c.tolist(), "M": self.M.tolist(), "J_e": self.J_e, "M_e": self.M_e,
                "natural_frequencies": self.natural_frequencies.tolist(),
                "natural_frequencies_hz": (self.natural_frequencies / (2 * math.pi)).tolist()}


def _finite(v: float, what: str, *, positive: bool) -> float:
    """A number by the toolkit's policy (finite, magnitudes 1e-100 … 1e100), positive or non-zero."""
    try:
        x = real(v, what)
    except InputError as exc:
        raise InputError(f"{exc}; give a {'positive' if positive else 'non-zero'} finite number") from None
    if x <= 0 if positive else x == 0:
        raise InputError(f"{what} = {v!r}: give a {'positive' if positive else 'non-zero'} finite number")
    return x


def reduce_chain(masses: Sequence[Mass], shafts: Sequence[Shaft]) -> ReducedChain:
    """Reduce a chain of masses and elastic shafts to one shaft, and find its natural frequencies.

    Parameters
    ----------
    masses : sequence of Mass
        The masses in their order along the drive (two or more).
    shafts : sequence of Shaft
        The shafts between them: one fewer than the masses.

    Returns
    -------
    ReducedChain
    """
    if len(masses) < 2:
        raise InputError(f"a chain drive has two masses or more; got {len(masses)} (one mass is J_e itself)")
    if len(shafts) != len(masses) - 1:
        raise InputError(f"{len(masses)} masses are joined by {len(masses) - 1} shafts; got {len(shafts)} stiffnesses")
    J = np.array([_finite(m.J, f"J of {m.name}", positive=True) * _finite(m.u, f"u of {m.name}", positive=False) ** 2
                  for m in masses])
    M = np.array([float(m.M) * m.u for m in masses])
    if not np.all(np.isfinite(M)):
        raise InputError("the moments on the masses must be finite numbers of N·m")
    c = np.array([_finite(s.c, f"c of {s.name}", positive=True) * _finite(s.u, f"u of {s.name}", positive=False) ** 2
                  for s in shafts])
    n = J.size
    K = np.zeros((n, n))
    for j, cj in enumerate(c):
        K[j, j] += cj
        K[j + 1, j + 1] += cj
        K[j, j + 1] -= cj
        K[j + 1, j] -= cj
    s = 1.0 / np.sqrt(J)
    lam, vec = np.linalg.eigh(s[:, None] * K * s[None, :])      # symmetric: J^-1/2 K J^-1/2
    order = np.argsort(lam)
    lam, vec = lam[order][1:], vec[:, order][:, 1:]             # the first is the rigid turning (0)
    modes = s[:, None] * vec
    modes = modes / np.abs(modes).max(axis=0)[None, :]
    modes = modes * np.sign(modes[0])[None, :]
    for a in (J, c, M):
        a.setflags(write=False)
    w = np.sqrt(np.maximum(lam, 0.0))
    w.setflags(write=False)
    modes.setflags(write=False)
    given = [np.array(v, dtype=float) for v in ([m.J for m in masses], [m.u for m in masses], [sh.c for sh in shafts],
                                                 [sh.u for sh in shafts])]
    for a in given:
        a.setflags(write=False)
    return ReducedChain(tuple(m.name for m in masses), tuple(sh.name for sh in shafts), J, c, M, w, modes, *given)
