"""The translating equivalent link: equivalent mass m_e and force F_e (domain.md §2, §8a).

A machine of one degree of freedom may be reduced to a link that translates (a slider, a ram, the
yoke of a sine mechanism) instead of one that turns. Keeping the kinetic energy and the power:

``m_e = Σ [ m_i (v_Si/v)² + J_Si (ω_i/v)² ]``,  ``F_e = Σ [ F_i cos α_i (v_Fi/v) ± M_i (ω_i/v) ]``,

v the velocity of the equivalent link along its guide. The ratios are velocity analogues (they
depend on position only), so with v_q = v/ω₁ (m/rad) the two reductions are one:
``m_e = J_e / v_q²`` and ``F_e = M_e / v_q`` (J_e, M_e reduced to the crank). The equations of
motion in its terms, s the link's displacement (both Chinese chapters give all three forms):

* energy form: ``½ m_e(s) v² − ½ m_e(s0) v0² = ∫_{s0}^{s} F_e ds``;
* force form: ``m_e dv/dt + ½ v² dm_e/ds = F_e`` (:func:`translating_acceleration`);
* with m_e and F_e constant: ``a = F_e/m_e``, ``v = v0 + a t``.

At a dead centre of the link (v = 0 while ω₁ ≠ 0) m_e and F_e are not defined; those positions are
reported, never given a value.

>>> import numpy as np
>>> t = from_rotating(J_e=[0.2, 0.3], M_e=[10.0, -5.0], v_q=[-0.1, 0.05])
>>> t.m_e.round(6).tolist(), t.F_e.round(6).tolist()
([20.0, 120.0], [-100.0, -100.0])
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from graphmethods.errors import InputError

#: |v_q| below this fraction of its largest value counts as a dead centre (v = 0).
DEAD_CENTRE_RTOL = 1e-9


@dataclass(frozen=True, eq=False)
class TranslatingLink:
    """m_e and F_e of a translating equivalent link at the positions where it moves.

    Attributes
    ----------
    index : ndarray of int
        The positions (of those given) where the link moves (v ≠ 0).
    phi : ndarray or None
        Their crank angles, rad (when given).
    v_q : ndarray
        v/ω₁ there, m/rad (signed along the link's direction).
    m_e : ndarray
        Equivalent mass, kg.
    F_e : ndarray
        Equivalent force, N, positive in the sense of positive v.
    dead_centres : ndarray of int
        The positions left out: v = 0 there, m_e and F_e undefined.
    """

    index: np.ndarray
    phi: np.ndarray | None
    v_q: np.ndarray
    m_e: np.ndarray
    F_e: np.ndarray
    dead_centres: np.ndarray

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: the lists and the dead centres (their angles in degrees when known)."""
        out: dict[str, Any] = {"positions": self.index.tolist(), "v_q": self.v_q.tolist(),
                               "m_e": self.m_e.tolist(), "F_e": self.F_e.tolist(),
                               "dead_centre_positions": self.dead_centres.tolist()}
        if self.phi is not None:
            out["phi_deg"] = np.degrees(self.phi).tolist()
        return out


def _ro(a: ArrayLike) -> np.ndarray:
    b = np.array(a, dtype=float)
    b.setflags(write=False)
    return b


def _moving(v_q: np.ndarray) -> np.ndarray:
    if v_q.ndim != 1 or v_q.size == 0 or not np.all(np.isfinite(v_q)):
        raise InputError("v_q (v/ω₁, m/rad) must be a non-empty list of finite numbers")
    top = float(np.abs(v_q).max())
    if top == 0.0:
        raise InputError("the equivalent link does not move at any position (v = 0 everywhere): choose a link "
                         "that translates as the crank turns")
    moving: np.ndarray = np.abs(v_q) > DEAD_CENTRE_RTOL * top
    return moving


def from_rotating(*, J_e: ArrayLike, M_e: ArrayLike, v_q: ArrayLike, phi: ArrayLike | None = None) -> TranslatingLink:
    """m_e = J_e/v_q² and F_e = M_e/v_q from the crank's J_e (kg·m²) and M_e (N·m).

    Parameters
    ----------
    J_e, M_e : array_like
        Reduced inertia and moment on the crank at the positions, kg·m² and N·m.
    v_q : array_like
        The equivalent link's velocity analogue v/ω₁ there, m/rad.
    phi : array_like, optional
        The crank angles, rad (kept for the report).

    Returns
    -------
    TranslatingLink

    Examples
    --------
    >>> t = from_rotating(J_e=[1.0, 1.0, 1.0], M_e=[0.0, 2.0, 0.0], v_q=[0.0, 0.5, 0.0])
    >>> t.index.tolist(), t.m_e.tolist(), t.F_e.tolist(), t.dead_centres.tolist()
    ([1], [4.0], [4.0], [0, 2])
    """
    J = np.asarray(J_e, dtype=float)
    M = np.asarray(M_e, dtype=float)
    v = np.asarray(v_q, dtype=float)
    if J.shape != v.shape or M.shape != v.shape:
        raise InputError(f"J_e, M_e and v_q must have one value per position; got {J.shape}, {M.shape}, {v.shape}")
    if not (np.all(np.isfinite(J)) and np.all(np.isfinite(M))):
        raise InputError("J_e and M_e must be finite numbers (kg·m², N·m)")
    ok = _moving(v)
    idx = np.flatnonzero(ok)
    ph = None if phi is None else _ro(np.asarray(phi, dtype=float)[idx])
    return TranslatingLink(index=idx, phi=ph, v_q=_ro(v[ok]), m_e=_ro(J[ok] / v[ok] ** 2), F_e=_ro(M[ok] / v[ok]),
                           dead_centres=np.flatnonzero(~ok))


def link_direction(plans: Any, point: str) -> np.ndarray:
    """The unit vector along which ``point`` moves (the principal direction of its velocity
    analogues), turned so that it moves forward just after position 0 (the working stroke's start).

    Raises InputError when the point does not move along a straight line (it does not translate).
    """
    a = np.asarray(plans.analogue(point), dtype=float)
    if not np.any(a):
        raise InputError(f"point {point} does not move; the equivalent link must translate as the crank turns")
    _, s, vt = np.linalg.svd(a, full_matrices=False)
    if s.size > 1 and s[1] > 1e-9 * s[0]:
        raise InputError(f"point {point} does not move along one straight line (its velocities turn); a translating "
                         f"equivalent link is a slider, a ram or a yoke: give its point")
    u = vt[0]
    speed = a @ u
    first = int(np.flatnonzero(np.abs(speed) > DEAD_CENTRE_RTOL * np.abs(speed).max())[0])
    if speed[first] < 0:
        u = -u
    direction: np.ndarray = u
    return direction


def equivalent_mass(plans: Any, inertias: Iterable[Any], *, point: str,
                    direction: ArrayLike | None = None) -> TranslatingLink:
    """m_e = Σ[m (v_S/v)² + J_S (ω_i/v)²] of the link at ``point``, straight from the velocity plans.

    F_e is not part of this sum (it is reported as 0); :meth:`graphmethods.dynamics.study.Study.translating`
    adds it from the reduced moment.

    Parameters
    ----------
    plans : VelocityPlans
        The plans at the positions (any ω₁: analogues are used).
    inertias : iterable of Inertia
        ``(link, point, m, J)`` as for :func:`~graphmethods.dynamics.reduction.reduced_inertia`.
    point : str
        A point of the translating equivalent link (keyword-only).
    direction : array_like, optional
        Its unit direction; by default :func:`link_direction`.
    """
    u = link_direction(plans, point) if direction is None else np.asarray(direction, dtype=float)
    v = np.asarray(plans.analogue(point), dtype=float) @ u
    ok = _moving(v)
    m_e = np.zeros(int(ok.sum()))
    for it in inertias:
        if it.m:
            vs = np.asarray(plans.analogue(it.point), dtype=float)[ok]
            m_e = m_e + it.m * (vs[:, 0] ** 2 + vs[:, 1] ** 2) / v[ok] ** 2
        if it.J:
            m_e = m_e + it.J * (np.asarray(plans.omega_ratio(it.link), dtype=float)[ok] / v[ok]) ** 2
    return TranslatingLink(index=np.flatnonzero(ok), phi=None, v_q=_ro(v[ok]), m_e=_ro(m_e),
                           F_e=_ro(np.zeros_like(m_e)), dead_centres=np.flatnonzero(~ok))


def translating_acceleration(*, m_e: float, dm_e_ds: float, F_e: float, v: float) -> float:
    """The force form of the equation of motion solved for a = dv/dt, m/s².

    ``m_e dv/dt + ½ v² dm_e/ds = F_e``. Parameters: m_e in kg, dm_e/ds in kg/m, F_e in N, v in m/s.

    >>> translating_acceleration(m_e=10.0, dm_e_ds=0.0, F_e=30.0, v=2.0)   # constant mass: a = F/m
    3.0
    >>> translating_acceleration(m_e=10.0, dm_e_ds=4.0, F_e=30.0, v=2.0)
    2.2
    """
    if not (np.isfinite(m_e) and m_e > 0):
        raise InputError(f"m_e = {m_e!r}: the equivalent mass must be a positive number of kg")
    return float((F_e - 0.5 * v * v * dm_e_ds) / m_e)
