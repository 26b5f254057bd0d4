"""ω(φ) and ε(φ) of a cycle problem given by moment curves (issue 18 item 2).

For a cycle problem (:class:`~graphmethods.problems.cycle.CycleProblem`) whose M_d and M_r are
curves of φ, with a constant inertia J (J_e, plus the flywheel J_F for its [δ] when it states n and
[δ]), the energy form gives the motion over the period exactly (domain.md §3):

* with a starting speed ω0 (W4): ω(φ) = sqrt(ω0² + 2ΔE(φ)/J);
* with a mean speed ω_m and [δ]: the steady motion with the textbook mean, from
  :func:`~graphmethods.dynamics.motion.periodic_motion` (ω_max, ω_min = ω_m(1 ± δ/2) with the
  approximate J_F, as the textbook's constant-J_e method promises);

and ε(φ) = (M_d − M_r)/J. A problem given only as areas or works (W1, W2) has no M(φ): between
its boundaries neither ω nor ε is defined, but at the boundaries a, b, c, … the energy levels E_k
give ω_k = sqrt(ω_min² + 2(E_k − E_min)/J) with the textbook mean (:func:`boundary_speeds`); ε needs
the moments and is refused with that reason.

>>> from graphmethods.problems import w4_exact
>>> cm = cycle_motion(w4_exact())
>>> [round(float(w), 2) for w in cm.omega_at([0, 3.141592653589793 / 2, 3.141592653589793])]
[10.0, 11.8, 10.0]
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.dynamics.motion import ReducedModel, periodic_motion
from graphmethods.errors import InputError
from graphmethods.units import is_finite


@dataclass(frozen=True, eq=False)
class CycleMotion:
    """The moments, ΔE, ω and ε of a cycle problem over its period (functions of φ, rad from its start).

    Attributes
    ----------
    problem : CycleProblem
    J : float
        The constant inertia, kg·m² (or the problem's unit).
    T0 : float
        Kinetic energy at the period's start, J.
    omega_m, delta : float or None
        The mean speed and δ of the motion (textbook mean), when the problem is a flywheel problem.
    """

    problem: Any
    J: float
    T0: float
    omega_m: float | None
    delta: float | None

    @property
    def period(self) -> float:
        return self.problem.excess_work.M_d.period

    def M_d(self, phi) -> np.ndarray:
        return np.asarray(self.problem.excess_work.M_d(np.asarray(phi, dtype=float)), dtype=float)

    def M_r(self, phi) -> np.ndarray:
        return np.asarray(self.problem.excess_work.M_r(np.asarray(phi, dtype=float)), dtype=float)

    def delta_E(self, phi) -> np.ndarray:
        """ΔE(φ) from the period's start, J (exact for the curves)."""
        return np.asarray(self.problem.excess_work.energy(np.clip(np.asarray(phi, dtype=float), 0.0, self.period)))

    def omega_at(self, phi) -> np.ndarray:
        """ω(φ), rad/s, by the energy form."""
        return np.sqrt(2.0 * (self.T0 + self.delta_E(phi)) / self.J)

    def epsilon_at(self, phi) -> np.ndarray:
        """ε(φ) = (M_d − M_r)/J, rad/s² (right-continuous at jumps)."""
        return (self.M_d(phi) - self.M_r(phi)) / self.J


def cycle_motion(problem) -> CycleMotion:
    """ω(φ), ε(φ) of a cycle problem given by moment curves (see the module docstring)."""
    ew = problem.excess_work
    if ew.M_d is None:
        raise InputError(f"problem {problem.id} is given as areas or works: ω(φ) between the boundaries needs "
                         f"the moments as curves of φ")
    J = float(problem.J_e)
    if problem.omega_0 is not None:
        if not J > 0:
            raise InputError(f"problem {problem.id}: a starting speed needs a positive J_e")
        return CycleMotion(problem, J, 0.5 * J * problem.omega_0**2, None, None)
    if problem.n_rpm is None or problem.delta is None:
        raise InputError(f"problem {problem.id} gives neither ω0 nor n and [δ]: its speed is not defined")
    fw = problem.flywheel()
    J_total = fw.J_total if fw.needed else J
    omega_m = math.pi * problem.n_rpm / 30.0
    D = ew.M_d - ew.M_r
    model = ReducedModel(J_e=J_total, M_e=lambda x: D(x), phi_T=D.period, phi_0=D.start,
                         breaks=tuple(float(v) for v in np.unique(D.phi[:-1])))
    mo = periodic_motion(model, J_F=0.0, omega_m=omega_m)
    return CycleMotion(problem, J_total, mo.T0, mo.omega_m, mo.delta)


@dataclass(frozen=True, eq=False)
class BoundarySpeeds:
    """ω at the boundaries of a cycle given as areas or works (W1, W2), J constant.

    Attributes
    ----------
    labels : tuple of str
        The boundaries a, b, c, … (the last is the period's end, equal to a).
    E : ndarray
        Energy levels at them, J (or the problem's work unit), from the first.
    omega : ndarray
        ω at them, rad/s.
    J : float
        The constant inertia J_e + J_F, kg·m² (or the problem's unit).
    omega_m, delta : float
        The mean speed (ω_max + ω_min)/2, rad/s, and δ of this motion.
    """

    labels: tuple[str, ...]
    E: np.ndarray
    omega: np.ndarray
    J: float
    omega_m: float
    delta: float

    def to_dict(self) -> dict:
        return {"labels": list(self.labels), "E": [float(v) for v in self.E],
                "omega": [float(v) for v in self.omega], "J": self.J, "omega_m": self.omega_m, "delta": self.delta}


def boundary_speeds(problem, *, J: float | None = None) -> BoundarySpeeds:
    """ω at the boundaries of a cycle problem (areas, works or curves), J constant.

    The steady motion with the textbook mean ω_m = πn/30: with J = J_e + J_F (J_F of the approximate
    method for [δ], unless ``J`` gives the total inertia) the energy form gives
    ω_max² − ω_min² = 2ΔW_max/J and ω_max + ω_min = 2ω_m, so ω_min = ω_m − ΔW_max/(2 J ω_m) and
    ω_k² = ω_min² + 2(E_k − E_min)/J.

    Parameters
    ----------
    problem : CycleProblem
        With n (rev/min) and, unless ``J`` is given, [δ].
    J : float, optional
        The total inertia on the shaft, kg·m² (keyword-only); by default J_e + J_F for [δ].

    Returns
    -------
    BoundarySpeeds

    Examples
    --------
    W1: n = 600 rev/min, [δ] = 1/300, ΔW_max = 575 J from b (lowest) to e (highest):

    >>> from graphmethods.problems import w1
    >>> b = boundary_speeds(w1())
    >>> [round(float(w), 4) for w in b.omega[[1, 4]]], round(b.delta, 6)
    ([62.7271, 62.9366], 0.003333)
    """
    ew = problem.excess_work
    if problem.n_rpm is None:
        raise InputError(f"problem {problem.id} states no speed n: the speeds at its boundaries are not defined; "
                         f"give n (rev/min)")
    omega_m = math.pi * float(problem.n_rpm) / 30.0
    if J is None:
        if problem.delta is None:
            raise InputError(f"problem {problem.id} states no [δ]: give the total inertia J (kg·m²) instead")
        fw = problem.flywheel()
        J_total = float(fw.J_total) if fw.needed else float(problem.J_e)
    else:
        J_total = float(J)
    if not (is_finite(J_total) and J_total > 0):
        raise InputError(f"problem {problem.id}: the total inertia J = {J_total!r} must be a positive number of "
                         f"kg·m²")
    from graphmethods.dynamics.flywheel import level_speeds

    E = np.asarray(ew.E, dtype=float)
    try:
        omega = level_speeds(E, J=J_total, omega_m=omega_m)
    except InputError as exc:
        raise InputError(f"problem {problem.id}: {exc}") from None
    return BoundarySpeeds(tuple(ew.labels), omega=_ro(omega), E=_ro(E), J=J_total, omega_m=omega_m,
                          delta=float((omega.max() - omega.min()) / omega_m))


def _ro(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a
