"""The flywheel by the approximate method (J_e taken constant), its transfer and its sizing.

``J_F = ΔW_max / (ω_m² [δ]) − J_e``; with n in rev/min, ``J_F = 900 ΔW_max / (π² n² [δ]) − J_e``.
The inverse problem gives δ for a given total inertia. Sizing turns J_F into a rim
(spoked) flywheel or a solid disc, with the rim-speed check.

W1 (diesel generator, n = 600 rev/min, [δ] = 1/300, ΔW_max = 575 J):

>>> fw = flywheel(575.0, delta=1 / 300, n_rpm=600.0)
>>> round(fw.J_F, 2)
43.69
>>> round(fluctuation(575.0, J=fw.J_total, n_rpm=600.0), 8) == round(1 / 300, 8)
True
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from graphmethods.errors import InputError
from graphmethods.units import DELTA_MAX, finite_array, finite_result, n_from_omega, omega_from_n, real

#: Rim speeds usually allowed, m/s (domain.md §6): cast iron 25–30, steel higher.
RIM_SPEED_LIMIT = {"cast iron": 25.0, "steel": 40.0}
#: Standard gravity, m/s²: 1 kgf = 9.80665 N (for the old-unit flywheel moment Q·D², kgf·m²).
G_STANDARD = 9.80665
#: One kilogram-force, N.
KGF = 9.80665
#: Densities, kg/m³.
DENSITY = {"cast iron": 7200.0, "steel": 7850.0}


def _finite(value: object, name: str, *, positive: bool = False, hint: str = "", tiny_ok: bool = False) -> float:
    # the toolkit's one policy for numbers that enter (graphmethods.units.real): no bools, finite,
    # magnitudes 1e-100 … 1e100 (only the upper bound for a numerator or a term: tiny_ok)
    return real(value, name, lo=0.0 if positive else None, lo_open=positive, hint=hint, tiny_ok=tiny_ok)


def mean_speed(*, n_rpm: float | None = None, omega_m: float | None = None) -> float:
    """ω_m in rad/s from exactly one of ``n_rpm`` (rev/min) or ``omega_m`` (rad/s).

    >>> round(mean_speed(n_rpm=120.0), 6)
    12.566371
    """
    if (n_rpm is None) == (omega_m is None):
        raise InputError("give the mean speed once: n (rev/min) or omega_m (rad/s)")
    if n_rpm is not None:
        return omega_from_n(_finite(n_rpm, "n", positive=True, hint="the mean speed in rev/min"))
    return _finite(omega_m, "omega_m", positive=True, hint="the mean angular speed in rad/s")


def check_delta(delta: float, name: str = "delta") -> float:
    """Validate a coefficient of fluctuation: 0 < δ < 1, the one rule of the command line, the
    problem files and the API (:data:`graphmethods.units.DELTA_MAX`; typical values 1/300 … 1/5).

    >>> check_delta("1/300") == 1 / 300
    True
    """
    return real(delta, name, lo=0.0, lo_open=True, hi=DELTA_MAX, hi_open=True,
                hint="the coefficient of fluctuation of steady running, typically 1/300 … 1/5")


@dataclass(frozen=True)
class Flywheel:
    """The flywheel required on a shaft for a permissible coefficient of fluctuation.

    Attributes
    ----------
    J_F : float, kg·m²
        Flywheel inertia to add (J_total − J_e); zero or negative means the machine's own
        inertia already keeps δ within [δ] and no flywheel is needed.
    J_total : float, kg·m²
        Total inertia required on the shaft, ΔW_max / (ω_m² [δ]).
    J_e, delta_W_max, delta, omega_m : the data (kg·m², J, —, rad/s).
    omega_max, omega_min : float, rad/s
        ω_m (1 ± δ/2).
    """

    J_F: float
    J_total: float
    J_e: float
    delta_W_max: float
    delta: float
    omega_m: float

    @property
    def n_rpm(self) -> float:
        """Mean speed in rev/min."""
        return n_from_omega(self.omega_m)

    @property
    def omega_max(self) -> float:
        return self.omega_m * (1 + self.delta / 2)

    @property
    def omega_min(self) -> float:
        return self.omega_m * (1 - self.delta / 2)

    @property
    def needed(self) -> bool:
        """Whether a flywheel is needed at all (J_F > 0)."""
        return self.J_F > 0

    def on_shaft(self, *, omega_i: float) -> float:
        """The same flywheel placed on a shaft turning at ω_i instead: J_F (ω_m/ω_i)², kg·m²."""
        return transfer(self.J_F, omega_from=self.omega_m, omega_to=omega_i)

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d.update(n_rpm=self.n_rpm, omega_max=self.omega_max, omega_min=self.omega_min, needed=self.needed)
        return d


def flywheel(
    delta_W_max: float,
    *,
    delta: float,
    n_rpm: float | None = None,
    omega_m: float | None = None,
    J_e: float = 0.0,
) -> Flywheel:
    """Flywheel inertia for [δ]: J_F = ΔW_max / (ω_m² [δ]) − J_e.

    Parameters
    ----------
    delta_W_max : float, J
        Maximum fluctuation of energy.
    delta : float
        Permissible coefficient of fluctuation [δ].
    n_rpm : float, rev/min, or omega_m : float, rad/s
        Mean speed of the shaft carrying the flywheel.
    J_e : float, kg·m²
        The mechanism's own (mean) reduced inertia, subtracted.

    Examples
    --------
    W2: the source prints 60.16 kg·m², an arithmetic slip:

    >>> round(flywheel(575.0, delta=0.06, n_rpm=120.0).J_F, 2)
    60.69
    """
    dW = _finite(delta_W_max, "delta_W_max", tiny_ok=True)
    if dW < 0:
        raise InputError(f"delta_W_max = {dW:g} J must not be negative (it is E_max − E_min)")
    d = check_delta(delta)
    w = mean_speed(n_rpm=n_rpm, omega_m=omega_m)
    J_e = _finite(J_e, "J_e", hint="the mechanism's reduced inertia in kg·m²", tiny_ok=True)
    if J_e < 0:
        raise InputError(f"J_e = {J_e:g} kg·m² must not be negative")
    J_total = finite_result(dW / (w * w * d), "the required inertia ΔW_max/(ω_m²[δ])", unit="kg·m²")
    return Flywheel(J_F=J_total - J_e, J_total=J_total, J_e=J_e, delta_W_max=dW, delta=d, omega_m=w)


def fluctuation(delta_W_max: float, *, J: float, n_rpm: float | None = None, omega_m: float | None = None) -> float:
    """The coefficient of fluctuation δ = ΔW_max / (ω_m² J) that a total inertia J gives.

    The result obeys the rule of :func:`check_delta`: an inertia too small for steady running
    (δ ≥ 1) is refused, as ``--delta`` refuses such a δ.

    >>> round(fluctuation(575.0, J=60.68716728577524, n_rpm=120.0), 10)
    0.06
    """
    dW = _finite(delta_W_max, "delta_W_max", tiny_ok=True)
    if dW < 0:
        raise InputError(f"delta_W_max = {dW:g} J must not be negative (it is E_max − E_min)")
    J = _finite(J, "J", positive=True, hint="the total inertia on the shaft in kg·m²")
    w = mean_speed(n_rpm=n_rpm, omega_m=omega_m)
    d = finite_result(dW / (w * w * J), "δ = ΔW_max/(ω_m² J)")
    if d >= DELTA_MAX:
        raise InputError(f"J = {J:g} kg·m² is too small for steady running: it gives δ = {d:.4g}, and δ must stay "
                         f"below {DELTA_MAX:g}; the total inertia must exceed ΔW_max/ω_m² = {dW / (w * w):.4g} kg·m²")
    return d


def level_speeds(E: ArrayLike, *, J: float, omega_m: float) -> np.ndarray:
    """ω at the energy levels of a steady cycle with a constant total inertia (the textbook mean).

    With J constant the energy form gives ω_max² − ω_min² = 2ΔW_max/J and, with the textbook mean,
    ω_max + ω_min = 2ω_m; so ω_min = ω_m − ΔW_max/(2Jω_m) and ω_k = sqrt(ω_min² + 2(E_k − E_min)/J).

    Parameters
    ----------
    E : array_like
        Energy levels at the boundaries of the cycle, J (any origin).
    J : float
        Total inertia on the shaft (J_e + J_F), kg·m², keyword-only.
    omega_m : float
        Mean speed (ω_max + ω_min)/2, rad/s.

    Returns
    -------
    ndarray
        ω at each level, rad/s.

    Examples
    --------
    >>> w = level_speeds([0.0, -50.0, 500.0, 400.0, 525.0, 25.0, 50.0, 0.0], J=43.69, omega_m=20 * np.pi)
    >>> round(float(w.max() + w.min()) / 2 / (20 * np.pi), 12), round(float(w[4] - w[1]) * 43.69 * 20 * np.pi, 6)
    (1.0, 575.0)
    """
    levels = finite_array(E, "E")
    J = _finite(J, "J", positive=True, hint="the total inertia on the shaft, kg·m²")
    omega_m = _finite(omega_m, "omega_m", positive=True, hint="rad/s")
    if levels.ndim != 1 or levels.size < 2 or not np.all(np.isfinite(levels)):
        raise InputError("the energy levels must be two or more finite numbers, J")
    dW = float(levels.max() - levels.min())
    w_min = omega_m - dW / (2.0 * J * omega_m)
    if not w_min > 0:
        raise InputError(f"with J = {J:g} kg·m² the speed would fall to zero or below (ΔW_max = {dW:g} J against "
                         f"½Jω_m² = {0.5 * J * omega_m**2:g} J); give a larger J")
    omega: np.ndarray = np.sqrt(w_min**2 + 2.0 * (levels - levels.min()) / J)
    return omega


def transfer(J_F: float, *, omega_from: float, omega_to: float) -> float:
    """A flywheel moved to another shaft: J_Fi = J_F (ω/ω_i)², kg·m².

    >>> transfer(40.0, omega_from=10.0, omega_to=20.0)     # a faster shaft needs less
    10.0
    """
    J_F = _finite(J_F, "J_F")
    w = _finite(omega_from, "omega_from", positive=True)
    wi = _finite(omega_to, "omega_to", positive=True)
    return finite_result(J_F * (w / wi) ** 2, "J_F (ω/ω_i)²", unit="kg·m²")


# --------------------------------------------------------------------- sizing
class _FlywheelMoments:
    """What every sized flywheel reports from its mass m (kg), mean diameter D (m) and rim speed
    (m/s): the speed check and the flywheel moments of the handbooks."""

    m: float
    D: float
    rim_speed: float
    speed_limit: float

    @property
    def speed_ok(self) -> bool:
        """Whether the rim speed stays within ``speed_limit``."""
        return self.rim_speed <= self.speed_limit

    @property
    def flywheel_moment(self) -> float:
        """m D², kg·m² (the "flywheel moment" GD² of older texts, in mass units)."""
        return self.m * self.D**2

    @property
    def weight_moment_kgf(self) -> float:
        """Q·D² in the old units, kgf·m² (Q the weight in kgf): numerically m·D² at standard gravity."""
        return self.m * G_STANDARD / KGF * self.D**2

    @property
    def weight_moment_N(self) -> float:
        """G·D² = m g D², N·m² (the weight in newtons, g = 9.80665 m/s²)."""
        return self.m * G_STANDARD * self.D**2


@dataclass(frozen=True)
class RimFlywheel(_FlywheelMoments):
    """A spoked flywheel whose rim carries the inertia (spokes and hub neglected).

    D is the mean rim diameter, H the radial thickness, B the width (m); mass in kg;
    ``J_rim`` = m (D1² + D2²)/8 is the rim's exact inertia, slightly above the
    design value m D²/4; ``rim_speed`` in m/s; ``speed_ok`` against ``speed_limit``.
    """

    J: float
    D: float
    m: float
    H: float
    B: float
    rho: float
    J_rim: float
    rim_speed: float
    speed_limit: float

    @property
    def D1(self) -> float:
        return self.D + self.H

    @property
    def D2(self) -> float:
        return self.D - self.H


def rim_flywheel(
    J: float,
    *,
    n_rpm: float,
    D: float | None = None,
    rho: float = DENSITY["cast iron"],
    H_over_B: float = 1.5,
    speed_limit: float = RIM_SPEED_LIMIT["cast iron"],
) -> RimFlywheel:
    """Size a rim flywheel of inertia J (kg·m²) for a shaft at n_rpm.

    The rim mass is m = 4J/D² (J ≈ m D²/4); its section A = m/(ρπD) = H·B with H/B given.
    Without D, the largest mean diameter the rim-speed limit allows is taken:
    D = 60 v / (π n).

    >>> r = rim_flywheel(43.69, n_rpm=600.0, D=0.75)
    >>> round(r.m, 1), r.speed_ok
    (310.7, True)
    """
    J = _finite(J, "J", positive=True, hint="a flywheel needs positive inertia")
    n = _finite(n_rpm, "n", positive=True)
    rho = _finite(rho, "rho", positive=True)
    k = _finite(H_over_B, "H_over_B", positive=True)
    v_lim = _finite(speed_limit, "speed_limit", positive=True)
    if D is None:
        D = 60.0 * v_lim / (math.pi * n)
    D = _finite(D, "D", positive=True)
    m = 4.0 * J / D**2
    area = m / (rho * math.pi * D)
    B = math.sqrt(area / k)
    H = k * B
    if H >= D:
        raise InputError(f"the rim would be {H:.3g} m thick for a {D:.3g} m mean diameter; choose a larger D or a disc")
    J_rim = m * ((D + H) ** 2 + (D - H) ** 2) / 8.0
    return RimFlywheel(J=J, D=D, m=m, H=H, B=B, rho=rho, J_rim=J_rim, rim_speed=math.pi * D * n / 60.0,
                       speed_limit=v_lim)


@dataclass(frozen=True)
class DiscFlywheel(_FlywheelMoments):
    """A solid disc flywheel: J = m D²/8, m = ρπD²B/4 (m, kg, m/s); ``speed_ok`` against ``speed_limit``."""

    J: float
    D: float
    B: float
    m: float
    rho: float
    rim_speed: float
    speed_limit: float = RIM_SPEED_LIMIT["steel"]


def disc_flywheel(J: float, *, D: float, n_rpm: float, rho: float = DENSITY["steel"],
                  speed_limit: float = RIM_SPEED_LIMIT["steel"]) -> DiscFlywheel:
    """Size a solid disc of diameter D for inertia J: B = 32 J / (ρ π D⁴).

    >>> d = disc_flywheel(2.0, D=0.5, n_rpm=300.0)
    >>> round(d.m, 1), round(d.B * 1000, 1)
    (64.0, 41.5)
    """
    J = _finite(J, "J", positive=True)
    D = _finite(D, "D", positive=True)
    rho = _finite(rho, "rho", positive=True)
    n = _finite(n_rpm, "n", positive=True)
    m = 8.0 * J / D**2
    B = 4.0 * m / (rho * math.pi * D**2)
    v_lim = _finite(speed_limit, "speed_limit", positive=True)
    return DiscFlywheel(J=J, D=D, B=B, m=m, rho=rho, rim_speed=math.pi * D * n / 60.0, speed_limit=v_lim)


def mass_at_radius_of_gyration(J: float, *, k: float) -> float:
    """English-style answer: the mass m = J/k² at radius of gyration k (m), kg.

    >>> mass_at_radius_of_gyration(43.69476, k=0.5)
    174.77904
    """
    return _finite(J, "J") / _finite(k, "k", positive=True) ** 2
