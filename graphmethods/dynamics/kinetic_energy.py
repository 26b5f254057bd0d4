"""The kinetic-energy graph T = T0 + ΔE (Russian practice) and the speeds it gives for constant J_e.

W4 (Russian lecture, kG·m units): four equal parts, areas 200 mm² each at μ_M = 1,
μ_φ = 0.075 (π taken as 3), J_e = 0.8, ω0 = 10 s⁻¹:

>>> from graphmethods.dynamics import excess_work as ew
>>> ke = kinetic_energy(ew.from_areas([200, -200, -200, 200], mu_M=1.0, mu_phi=0.075), J_e=0.8, omega_0=10.0)
>>> ke.T.tolist()
[40.0, 55.0, 40.0, 25.0, 40.0]
>>> round(ke.omega_m, 3), round(ke.delta, 4)
(9.816, 0.3892)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.dynamics.excess_work import ExcessWork
from graphmethods.errors import InputError, MotionError
from graphmethods.units import is_finite


@dataclass(frozen=True, eq=False)
class KineticEnergy:
    """Kinetic energy and speed at the boundaries of an excess-work table (J_e constant).

    Attributes
    ----------
    T : ndarray, J
        T0 + E at each boundary.
    omega : ndarray, rad/s
        sqrt(2T/J_e).
    J_e, T0 : kg·m², J.
    """

    excess_work: ExcessWork
    T: np.ndarray
    omega: np.ndarray
    J_e: float
    T0: float

    @property
    def omega_max(self) -> float:
        return float(self.omega.max())

    @property
    def omega_min(self) -> float:
        return float(self.omega.min())

    @property
    def omega_m(self) -> float:
        """Textbook mean speed (ω_max + ω_min)/2, rad/s."""
        return 0.5 * (self.omega_max + self.omega_min)

    @property
    def delta(self) -> float:
        """Coefficient of fluctuation (ω_max − ω_min)/ω_m."""
        return (self.omega_max - self.omega_min) / self.omega_m

    def to_dict(self) -> dict[str, Any]:
        return {"T": self.T.tolist(), "omega": self.omega.tolist(), "omega_m": self.omega_m,
                "delta": self.delta, "J_e": self.J_e, "T0": self.T0}


def kinetic_energy(ew: ExcessWork, *, J_e: float, T0: float | None = None,
                   omega_0: float | None = None) -> KineticEnergy:
    """T = T0 + E at the boundaries of the table and ω = sqrt(2T/J_e), J_e constant.

    Give the starting energy T0 (J) or the starting speed omega_0 (rad/s), T0 = J_e ω0²/2.
    """
    if not (isinstance(J_e, (int, float)) and is_finite(J_e) and J_e > 0):
        raise InputError(f"J_e = {J_e!r} must be a positive inertia in kg·m²")
    if (T0 is None) == (omega_0 is None):
        raise InputError("give the starting state once: T0 (J) or omega_0 (rad/s)")
    if T0 is None:
        assert omega_0 is not None
        if not (is_finite(omega_0) and omega_0 > 0):
            raise InputError(f"omega_0 = {omega_0!r} must be a positive speed in rad/s")
        T0 = 0.5 * J_e * omega_0**2
    T = T0 + ew.E
    if (T <= 0).any():
        i = int(np.flatnonzero(T <= 0)[0])
        raise MotionError(
            f"the kinetic energy falls to {T[i]:.6g} J at point {ew.labels[i]}: the machine would stop; "
            "start with more energy (larger T0 or omega_0) or add a flywheel"
        )
    T.setflags(write=False)
    omega = np.sqrt(2.0 * T / J_e)
    omega.setflags(write=False)
    return KineticEnergy(excess_work=ew, T=T, omega=omega, J_e=float(J_e), T0=float(T0))
