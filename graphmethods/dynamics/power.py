"""Power, efficiency and the choice of a motor (issue 18 item 4).

* The mean power of a machine in steady motion: ``N = M_m·ω_m`` (W), M_m the mean driving moment
  (N·m) reduced to the shaft turning at ω_m (rad/s); for a working machine M_m = M_d of the work
  balance, for an engine the constant resistance it overcomes (the generator's moment).
* Efficiency of mechanisms in series (the power passes through each in turn):
  ``η = η_1·η_2·…·η_k``; in parallel (the input power splits, a share α_i = N_i/N through each):
  ``η = Σ α_i η_i``.
* Its effect on the reduced moment: the work lost in friction is taken from the drive, so the
  resisting moment reduced to the driving shaft is ``M_r/η`` and the driving moment of the work
  balance ``M_d/η`` (power flowing from the motor to the working member).
* The motor is chosen by the mean power it must give, ``N/η`` with a reserve factor, as the next
  rated power of a series; :data:`IEC_RATED_KW` is the IEC 60072-1 series of rated outputs of
  three-phase induction motors, 0.12 to 315 kW.

>>> round(mean_power(M_m=143.43, omega_m=31.416), 1)
4506.0
>>> round(efficiency_series([0.98, 0.95, 0.9]), 5), round(efficiency_parallel([0.9, 0.8], shares=[0.5, 0.5]), 5)
(0.8379, 0.85)
>>> choose_motor(4506.0, eta=0.8379).P_rated_kW
5.5
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from graphmethods.errors import InputError
from graphmethods.units import is_finite, real

#: IEC 60072-1 rated outputs of three-phase induction motors, kW (the usual catalogue steps).
IEC_RATED_KW: tuple[float, ...] = (0.12, 0.18, 0.25, 0.37, 0.55, 0.75, 1.1, 1.5, 2.2, 3.0, 4.0, 5.5, 7.5, 11.0, 15.0,
                                   18.5, 22.0, 30.0, 37.0, 45.0, 55.0, 75.0, 90.0, 110.0, 132.0, 160.0, 200.0, 250.0,
                                   315.0)


def _eta(value: float, name: str) -> float:
    v = real(value, name, tiny_ok=True)
    if not (is_finite(v) and 0.0 < v <= 1.0):
        raise InputError(f"{name} = {value!r}: an efficiency is a number in (0, 1], e.g. 0.95")
    return v


def mean_power(*, M_m: float, omega_m: float) -> float:
    """N = M_m·ω_m, W.

    Parameters
    ----------
    M_m : float
        Mean moment on the shaft, N·m (keyword-only).
    omega_m : float
        Mean speed of that shaft, rad/s (keyword-only).
    """
    M, w = real(M_m, "M_m", unit="N·m"), real(omega_m, "omega_m", unit="rad/s")
    if not (is_finite(M) and is_finite(w) and w > 0):
        raise InputError(f"M_m = {M_m!r} N·m and ω_m = {omega_m!r} rad/s must be finite, ω_m positive")
    return abs(M) * w


def efficiency_series(etas: Sequence[float]) -> float:
    """η of mechanisms in series: the product of their efficiencies.

    >>> efficiency_series([0.96, 0.96])
    0.9216
    """
    if isinstance(etas, (str, bytes)) or not hasattr(etas, "__len__") or len(etas) == 0:
        raise InputError(f"give the efficiency of at least one mechanism as a list, got {etas!r}")
    out = 1.0
    for i, e in enumerate(etas):
        out *= _eta(e, f"η_{i + 1}")
    return out


def efficiency_parallel(etas: Sequence[float], *, shares: Sequence[float]) -> float:
    """η of mechanisms in parallel: Σ α_i η_i, α_i the share of the input power through each.

    Parameters
    ----------
    etas : sequence of float
        The efficiencies η_i.
    shares : sequence of float
        The input power's shares α_i (keyword-only); they must add up to 1.

    >>> round(efficiency_parallel([0.95, 0.85], shares=[0.25, 0.75]), 6)
    0.875
    """
    for what, seq in (("efficiencies", etas), ("shares", shares)):
        if isinstance(seq, (str, bytes)) or not hasattr(seq, "__len__"):
            raise InputError(f"give the {what} as a list, got {seq!r}")
    if len(etas) == 0 or len(etas) != len(shares):
        raise InputError(f"give one share of the input power per mechanism; got {len(etas)} efficiencies and "
                         f"{len(shares)} shares")
    a = [real(x, f"α_{i + 1}", tiny_ok=True) for i, x in enumerate(shares)]
    if any(not (is_finite(x) and x >= 0) for x in a) or abs(sum(a) - 1.0) > 1e-9:
        raise InputError(f"the shares {list(shares)} must be non-negative and add up to 1 (they add up to {sum(a):g})")
    return sum(x * _eta(e, f"η_{i + 1}") for i, (x, e) in enumerate(zip(a, etas)))


def moment_with_losses(M: float, *, eta: float) -> float:
    """A moment reduced to the driving shaft with the losses of a drive of efficiency η: M/η (N·m).

    >>> moment_with_losses(90.0, eta=0.9)
    100.0
    """
    return real(M, "M", unit="N·m", tiny_ok=True) / _eta(eta, "η")


@dataclass(frozen=True)
class MotorChoice:
    """The motor for a mean power: ``N_required`` = N/η·reserve (W) and the rated power chosen (kW)."""

    N_mean: float
    eta: float
    reserve: float
    N_required: float
    P_rated_kW: float

    def to_dict(self) -> dict[str, float]:
        return {"N_mean": self.N_mean, "eta": self.eta, "reserve": self.reserve, "N_required": self.N_required,
                "P_rated_kW": self.P_rated_kW}


def choose_motor(N_mean: float, *, eta: float = 1.0, reserve: float = 1.0,
                 series: Sequence[float] = IEC_RATED_KW) -> MotorChoice:
    """The smallest rated power (kW) of ``series`` not below N_mean/η·reserve.

    Parameters
    ----------
    N_mean : float
        Mean power the working member takes, W.
    eta : float
        Efficiency of the drive between the motor and the working member (keyword-only).
    reserve : float
        Reserve factor ≥ 1 (keyword-only; 1 by default).
    series : sequence of float
        Rated powers to choose from, kW (default :data:`IEC_RATED_KW`).
    """
    N = real(N_mean, "N_mean", unit="W", tiny_ok=True)
    if not (is_finite(N) and N >= 0):
        raise InputError(f"the mean power {N_mean!r} W must be a non-negative number")
    r = real(reserve, "reserve", tiny_ok=True)
    if not (is_finite(r) and r >= 1.0):
        raise InputError(f"reserve = {reserve!r}: a reserve factor is 1 or more, e.g. 1.1")
    e = _eta(eta, "η")
    need = N / e * r
    for P in sorted(float(x) for x in series):
        if P * 1000.0 >= need * (1 - 1e-12):
            return MotorChoice(N, e, r, need, P)
    raise InputError(f"{need / 1000:.4g} kW is more than the largest rated power of the series "
                     f"({max(series):g} kW); use several motors or a larger series")
