"""Motion in every regime: start-up, steady running and run-down, from given initial conditions.

The machine reduced to one link (domain.md §2–3, §8a) moves by

    J(φ) dω/dt + ½ ω² dJ/dφ = M(φ, ω, t),   dφ/dt = ω,   J = J_F + J_e(φ),

with the moment the sum of a position-dependent part M_e(φ) (a
:class:`~graphmethods.dynamics.motion.ReducedModel`: −M_r, gas forces, …), a drive depending on
speed (an induction motor by Kloss's formula or a DC motor from :mod:`~graphmethods.dynamics.motor`,
or a constant driving moment), which may be switched off at a given time, a :class:`Brake`, and
any moment of position, speed and time together (``extra``). :func:`run` integrates it from
φ0, ω0, t0 **in time** (from rest ω = 0 makes dt = dφ/ω singular, so φ is not the variable), with
the embedded Dormand–Prince 5(4) pair and its fourth-order dense output, written in numpy. The
state carries two integrals beside φ and ω: the work of all the moments W = ∫ M ω dt and
∫ ω dφ = ∫ ω² dt, so the energy balance ½Jω² − ½J0ω0² = W is checked along every run, and the
mean speed ∫ω dφ / φ_T is exact to the integrator's accuracy.

The run ends at a time, after a number of turns, when the machine stops (ω falls to 0), or once
the motion is steady: the speed at the start of each period φ_T of the model (the Poincaré map)
converges, and its remaining distance from the limit, estimated by Aitken's extrapolation of the
last three, is below 1e-3 of the tolerance (and below 1e-9 of ω). The last period is then the steady periodic motion;
the time to reach it is the first time after which ω(t) stays within ``tol``·ω_m of the steady ω
at the same φ.

Closed forms (tests): constant M and J: ε = M/J, ω = ω0 + εt (J_e = 0.025 kg·m², M = 30 N·m
from rest: ε = 1200 s⁻², ω = 1800 s⁻¹ at t = 1.5 s); M = M_0 − kω with constant J: ω approaches
M_0/k as an exponential with the time constant J/k.

>>> from graphmethods.dynamics.motion import ReducedModel
>>> r = run(ReducedModel(J_e=0.025, M_e=30.0), omega_0=0.0, t_end=1.5)
>>> round(float(r.omega[-1]), 6), round(float(r.epsilon[-1]), 6)
(1800.0, 1200.0)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import Any, cast

import numpy as np
import numpy.typing as npt

from graphmethods.dynamics.motion import FloatArray, PhiFunction, ReducedModel, _check_positive
from graphmethods.errors import InputError, MotionError
from graphmethods.units import real

__all__ = ["Brake", "ConstantDrive", "Run", "SteadyState", "run"]

TWO_PI = 2.0 * math.pi

# Dormand–Prince 5(4): nodes, stages, fifth-order weights, error weights, dense output (Shampine)
_C = np.array([0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0, 1.0])
_A = [
    np.array([]),
    np.array([1 / 5]),
    np.array([3 / 40, 9 / 40]),
    np.array([44 / 45, -56 / 15, 32 / 9]),
    np.array([19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729]),
    np.array([9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656]),
    np.array([35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84]),
]
_B = np.array([35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84, 0.0])
_E = _B - np.array([5179 / 57600, 0.0, 7571 / 16695, 393 / 640, -92097 / 339200, 187 / 2100, 1 / 40])
_P = np.array([
    [1, -8048581381 / 2820520608, 8663915743 / 2820520608, -12715105075 / 11282082432],
    [0, 0, 0, 0],
    [0, 131558114200 / 32700410799, -68118460800 / 10900136933, 87487479700 / 32700410799],
    [0, -1754552775 / 470086768, 14199869525 / 1410260304, -10690763975 / 1880347072],
    [0, 127303824393 / 49829197408, -318862633887 / 49829197408, 701980252875 / 199316789632],
    [0, -282668133 / 205662961, 2019193451 / 616988883, -1453857185 / 822651844],
    [0, 40617522 / 29380423, -110615467 / 29380423, 69997945 / 29380423],
])


#: a driving moment of the speed, ω (rad/s) ↦ M (N·m): a motor characteristic or :class:`ConstantDrive`
Drive = Callable[[float], float]
#: any further moment (φ, ω, t) ↦ M (N·m)
Extra = Callable[[float, float, float], float]
#: the right-hand side of the integrated system, (t, (φ, ω, W, Q)) ↦ its derivative
Rhs = Callable[[float, FloatArray], FloatArray]

@dataclass(frozen=True, kw_only=True)
class Brake:
    """A brake: a moment M_b + c·|ω| (N·m) against the motion, applied from time ``t_on`` (s).

    >>> b = Brake(M_b=200.0, c=2.0, t_on=1.0)
    >>> b(10.0, 0.5), b(10.0, 1.5), b(0.0, 2.0)
    (0.0, -220.0, 0.0)
    """

    M_b: float
    c: float = 0.0
    t_on: float = -math.inf

    def __post_init__(self) -> None:
        for name in ("M_b", "c"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
                raise InputError(f"Brake.{name} = {v!r}: give a finite moment ≥ 0")

    def __call__(self, omega: float, t: float) -> float:
        if t < self.t_on or omega == 0:
            return 0.0
        return -math.copysign(self.M_b + self.c * abs(omega), omega)


@dataclass(frozen=True)
class ConstantDrive:
    """A constant driving moment M_d (N·m), whatever the speed (a drive balanced by work, as in
    the textbook's steady-state problems).

    >>> ConstantDrive(143.4)(12.0)
    143.4
    """

    M_d: float

    def __call__(self, omega: float) -> float:
        return self.M_d


@dataclass(frozen=True, eq=False)
class SteadyState:
    """The steady periodic motion reached at the end of a run (its last period φ_T).

    Attributes
    ----------
    t_steady : float
        Time (s, from t0) after which ω stays within ``tol``·ω_m of the steady ω at the same φ.
    tol : float
        That tolerance (relative to ω_m).
    periods : int
        Periods integrated until the steady state was recognised.
    omega_max, omega_min, phi_omega_max, phi_omega_min : float
        Extremes of ω (rad/s) over the last period and their angles (rad, absolute).
    omega_m_textbook, omega_m_time, omega_m_integral : float
        The three mean speeds: (ω_max + ω_min)/2, φ_T/t_T and ∫ω dφ/φ_T (rad/s).
    delta : float
        (ω_max − ω_min)/ω_m with the textbook mean.
    t_T : float
        Time of one period, s.
    epsilon_max, epsilon_min : float
        Extremes of ε over the last period (at the step points and dense samples), rad/s².
    remaining : float
        Estimated |ω − ω_limit| at the last period start, rad/s (Aitken).
    phi_0, phi_T : float
        The model's position 0 and period, rad (``to_dict`` gives the angles after position 0).
    """

    t_steady: float
    tol: float
    periods: int
    omega_max: float
    omega_min: float
    phi_omega_max: float
    phi_omega_min: float
    omega_m_textbook: float
    omega_m_time: float
    omega_m_integral: float
    delta: float
    t_T: float
    epsilon_max: float
    epsilon_min: float
    remaining: float
    phi_0: float = 0.0
    phi_T: float = TWO_PI

    @property
    def omega_m(self) -> float:
        return self.omega_m_textbook

    def _from_0_deg(self, phi: float) -> float:
        """An angle after position 0, degrees in [0, φ_T) (round-off of the period's ends taken as 0)."""
        a = float(np.mod(phi - self.phi_0, self.phi_T))
        return 0.0 if min(a, self.phi_T - a) <= 1e-9 * self.phi_T else math.degrees(a)

    def to_dict(self) -> dict[str, float | int]:
        return {"t_steady": self.t_steady, "tol": self.tol, "periods": self.periods,
                "omega_m": self.omega_m, "delta": self.delta, "omega_max": self.omega_max,
                "omega_min": self.omega_min,
                "phi_omega_max_deg": self._from_0_deg(self.phi_omega_max),
                "phi_omega_min_deg": self._from_0_deg(self.phi_omega_min),
                "omega_m_textbook": self.omega_m_textbook, "omega_m_time": self.omega_m_time,
                "omega_m_integral": self.omega_m_integral, "t_T": self.t_T,
                "epsilon_max": self.epsilon_max, "epsilon_min": self.epsilon_min,
                "omega_remaining": self.remaining}


@dataclass(frozen=True, eq=False)
class Run:
    """A motion integrated from given initial conditions.

    Attributes
    ----------
    t, phi, omega, epsilon : ndarray
        At the integrator's accepted steps: time (s), angle (rad, absolute, growing), ω (rad/s),
        ε (rad/s²). The first entry is the initial state.
    work : ndarray
        Work of all the moments since the start, J.
    T : ndarray
        Kinetic energy ½ J(φ) ω², J.
    J : ndarray
        Total inertia J_F + J_e(φ) at the steps, kg·m².
    energy_residual : float
        max |T − T0 − W| over the run, relative to the largest of T and |W|: the energy balance.
    error_estimate : float
        Sum of the integrator's local error estimates of ω, rad/s (an a-posteriori global bound).
    rtol : float
        The integrator's relative tolerance.
    ended_by : str
        ``"t_end"``, ``"turns"``, ``"stopped"`` (ω fell to 0) or ``"steady"``.
    steady : SteadyState or None
        With ``until_steady``: the steady motion and the time to reach it.
    """

    t: np.ndarray
    phi: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray
    work: np.ndarray
    T: np.ndarray
    J: np.ndarray
    energy_residual: float
    error_estimate: float
    rtol: float
    ended_by: str
    steady: SteadyState | None
    phi_T: float
    _K: np.ndarray
    _Y: np.ndarray
    _rhs: Rhs

    @property
    def steps(self) -> int:
        return int(self.t.size - 1)

    def _dense(self, i: npt.ArrayLike, theta: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
        """State at θ ∈ [0, 1] of step i (arrays of equal shape): (t, y)."""
        i = np.asarray(i)
        theta = np.asarray(theta, dtype=float)
        h = self.t[i + 1] - self.t[i]
        powers = np.stack([theta, theta**2, theta**3, theta**4], axis=-1)       # (..., 4)
        Q = np.einsum("...sk,sp->...kp", self._K[i], _P)                       # (..., 4 state, 4)
        y = self._Y[i] + h[..., None] * np.einsum("...kp,...p->...k", Q, powers)
        return self.t[i] + theta * h, y

    def at_time(self, times: npt.ArrayLike) -> dict[str, FloatArray]:
        """φ, ω, ε at given times (s), from the dense output."""
        x = np.atleast_1d(np.asarray(times, dtype=float))
        if (x < self.t[0] - 1e-12).any() or (x > self.t[-1] + 1e-12).any():
            raise InputError(f"times outside the run {self.t[0]:g}…{self.t[-1]:g} s")
        i = np.clip(np.searchsorted(self.t, x, side="right") - 1, 0, self.steps - 1)
        theta = (x - self.t[i]) / (self.t[i + 1] - self.t[i])
        y, eps = self._partial_steps(i, theta)
        return {"t": x, "phi": y[:, 0], "omega": y[:, 1], "epsilon": eps}

    def _partial_steps(self, i: npt.ArrayLike, theta: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
        """The state after θ of step i, by a fresh Dormand–Prince step of θh (fifth order, not the
        fourth-order dense output), and ε there."""
        ys, eps = [], []
        for ii, th in zip(np.atleast_1d(i), np.atleast_1d(theta)):
            h = th * (self.t[ii + 1] - self.t[ii])
            K = _refit(self._rhs, self.t[ii], self._Y[ii], h)
            ys.append(self._Y[ii] + h * (_B @ K))
            eps.append(K[6][1])
        return np.array(ys), np.array(eps)

    def at_phi(self, phi: npt.ArrayLike) -> dict[str, FloatArray]:
        """t, ω, ε where the link reaches the given angles (rad; the first time, while ω > 0)."""
        x = np.atleast_1d(np.asarray(phi, dtype=float))
        if (x < self.phi[0] - 1e-12).any() or (x > self.phi.max() + 1e-12).any():
            raise InputError(f"angles outside the run {self.phi[0]:g}…{self.phi.max():g} rad")
        i = np.clip(np.searchsorted(np.maximum.accumulate(self.phi), x, side="left") - 1, 0, self.steps - 1)
        lo, hi = np.zeros_like(x), np.ones_like(x)
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            _, y = self._dense(i, mid)
            below = y[:, 0] < x
            lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
        theta = 0.5 * (lo + hi)
        for _ in range(3):      # Newton on the fifth-order step: φ(θ) − x, dφ/dθ = ω h
            y, eps = self._partial_steps(i, theta)
            h = self.t[i + 1] - self.t[i]
            theta = np.clip(theta - (y[:, 0] - x) / np.maximum(y[:, 1] * h, 1e-300), 0.0, 1.0)
        y, eps = self._partial_steps(i, theta)
        t = self.t[i] + theta * (self.t[i + 1] - self.t[i])
        return {"phi": x, "t": t, "omega": y[:, 1], "epsilon": eps}

    def extremes(self) -> dict[str, float]:
        """The extremes of ω and ε over the whole run, found on the dense solution (not at the steps).

        ω_max and ω_min lie at a root of ε (bisected on the fifth-order partial steps) or at an end of
        the run; ε_max and ε_min by a golden-section search there. ``error_extremes_omega`` bounds
        the error of the ω extremes: the integrator's global estimate plus the last bracket's spread.

        Returns
        -------
        dict
            ``omega_max_run``, ``t_omega_max_run`` (s), ``phi_omega_max_run_deg`` (°, absolute) and the
            same for ``omega_min_run``; ``epsilon_max_run``, ``epsilon_min_run`` (rad/s²) with their times;
            ``error_extremes_omega`` (rad/s).

        Examples
        --------
        >>> from graphmethods.dynamics.motion import ReducedModel
        >>> r = run(ReducedModel(J_e=1.0, M_e=lambda p: np.cos(p)), omega_0=1.0, turns=1)
        >>> bool(abs(r.extremes()["omega_max_run"] - math.sqrt(3.0)) < 1e-8)   # ½ω² = ½ + sin φ at φ = π/2
        True
        """
        return _dense_extremes(self)

    def summary(self) -> dict[str, Any]:
        """A JSON-ready summary (no arrays)."""
        out = {"ended_by": self.ended_by, "t_end": float(self.t[-1]), "phi_end_deg": math.degrees(self.phi[-1]),
               "omega_end": float(self.omega[-1]), "turns": float((self.phi[-1] - self.phi[0]) / TWO_PI),
               "steps": self.steps, "rtol": self.rtol, "error_estimate_omega": self.error_estimate,
               "energy_residual": self.energy_residual}
        out.update(self.extremes())
        if self.steady is not None:
            out["steady"] = self.steady.to_dict()
        return out


def _moment_function(model: ReducedModel, drive: Drive | None, drive_off_at: float | None, brake: Brake | None,
                     extra: Extra | None) -> Callable[[float, float, float], float]:
    M_e = cast(PhiFunction, model.M_e)       # a function since ReducedModel's construction
    if drive is None and extra is None and brake is None:
        def M_pos(phi: float, omega: float, t: float) -> float:
            return float(M_e(np.array([phi]))[0])
        return M_pos

    def M(phi: float, omega: float, t: float) -> float:
        m = float(M_e(np.array([phi]))[0])
        if drive is not None and (drive_off_at is None or t < drive_off_at):
            m += float(drive(omega))
        if brake is not None:
            m += brake(omega, t)
        if extra is not None:
            m += float(np.asarray(extra(phi, omega, t)))
        return m
    return M


def _check_run(model: ReducedModel, *, J_F: float, drive: Drive | None, brake: Brake | None, phi_0: float | None,
               omega_0: float, t_0: float, t_end: float | None, turns: float | None, until_steady: bool, tol: float,
               rtol: float) -> float:
    """The arguments of :func:`run` checked (InputError naming the bad one); returns the starting angle φ0."""
    if not isinstance(model, ReducedModel):
        raise InputError("model: give a ReducedModel (J_e(φ) and M_e(φ))")
    real(J_F, "J_F", unit="kg·m²", tiny_ok=True)          # the number policy: finite, at most 1e100
    phi_0 = model.phi_0 if phi_0 is None else real(phi_0, "phi_0", unit="rad", tiny_ok=True)
    for name, v in (("phi_0", phi_0), ("omega_0", omega_0), ("t_0", t_0)):
        if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)):
            raise InputError(f"{name} = {v!r} is not a finite number")
        real(v, name, tiny_ok=True)
    if t_end is not None:
        real(t_end, "t_end", unit="s", tiny_ok=True)
    if turns is not None:
        real(turns, "turns", tiny_ok=True)
    if omega_0 < 0:
        raise InputError(f"omega_0 = {omega_0!r} rad/s: the run starts at rest (0) or turning forwards (> 0)")
    if t_end is None and turns is None and not until_steady:
        raise InputError("say when to stop: t_end (s), turns, or until_steady")
    if t_end is not None and not (math.isfinite(t_end) and t_end > t_0):
        raise InputError(f"t_end = {t_end!r} s must come after t_0 = {t_0!r} s")
    if turns is not None:
        _check_positive(turns, "turns")
    _check_positive(tol, "tol")
    _check_positive(rtol, "rtol")
    if drive is not None and not callable(drive):
        raise InputError("drive: give a callable ω ↦ M (a motor, or ConstantDrive(M_d))")
    if brake is not None and not isinstance(brake, Brake):
        raise InputError("brake: give a Brake(M_b=..., c=..., t_on=...)")

    return phi_0


@np.errstate(over="ignore", invalid="ignore")     # an overflowing trial stage is rejected, not reported by numpy
def run(model: ReducedModel, *, J_F: float = 0.0, drive: Drive | None = None, drive_off_at: float | None = None,
        brake: Brake | None = None, extra: Extra | None = None, phi_0: float | None = None, omega_0: float = 0.0,
        t_0: float = 0.0, t_end: float | None = None, turns: float | None = None, until_steady: bool = False,
        tol: float = 1e-3, rtol: float = 1e-10, omega_ref: float | None = None, max_periods: int = 20000,
        max_steps: int = 2_000_000) -> Run:
    """Integrate the motion from φ0, ω0, t0 until a time, a number of turns, a stop or the steady state.

    Parameters
    ----------
    model : ReducedModel
        J_e(φ) (kg·m²) and the position-dependent moment M_e(φ) (N·m); its period φ_T is the period
        of the steady state.
    J_F : float
        Flywheel (and rotor) inertia added on the reduced shaft, kg·m².
    drive : callable ω ↦ M, optional
        A driving moment depending on speed (N·m): :class:`~graphmethods.dynamics.motor.DCMotor`,
        :class:`~graphmethods.dynamics.motor.InductionMotor`, :class:`ConstantDrive`, ...
    drive_off_at : float, optional
        Time (s) at which the drive is switched off (run-down).
    brake : Brake, optional
    extra : callable (φ, ω, t) ↦ M, optional
        Any further moment (N·m), e.g. a :class:`~graphmethods.dynamics.formula.Formula` in phi, omega, t.
    phi_0, omega_0, t_0 : float
        Initial angle (rad; default the model's position 0), speed (rad/s, ≥ 0) and time (s).
    t_end, turns, until_steady
        When to stop (the first reached; at least one must be given): a time (s), a number of
        turns of 2π after φ0, or the steady state. The run also ends when ω falls to 0.
    tol : float
        With ``until_steady``: the band (relative to ω_m) that defines "steady".
    rtol : float
        Relative tolerance of each step (of ω against ``omega_ref``, and of φ against 2π).
    omega_ref : float, optional
        The speed the accuracy is measured against (default: the largest of ω0 and the speeds met).

    Returns
    -------
    Run

    Raises
    ------
    InputError
        Bad parameters; no end condition.
    MotionError
        The machine cannot start (no positive moment at rest), or no steady state within
        ``max_periods`` periods, or the step count runs out.

    Notes
    -----
    One function of more than 80 lines, on purpose: the Dormand–Prince loop's step, its landing on the
    declared breaks and on switch times, the period boundaries and the steady-state test share their state
    (step size, the clamp of φ at a break, the next break and boundary, the accepted steps) at every step;
    split, each part would pass most of it both ways. The argument checks are :func:`_check_run`.

    Examples
    --------
    A DC motor M = M_0(1 − ω/ω_0) on a constant inertia from rest: ω → ω_0 with τ = J ω_0/M_0.

    >>> from graphmethods.dynamics.motor import DCMotor
    >>> r = run(ReducedModel(J_e=2.0, M_e=0.0), drive=DCMotor(M_0=100.0, omega_0=50.0), t_end=1.0)
    >>> bool(abs(r.omega[-1] - 50 * (1 - math.exp(-1.0))) < 1e-8)
    True
    """
    phi_0 = _check_run(model, J_F=J_F, drive=drive, brake=brake, phi_0=phi_0, omega_0=omega_0, t_0=t_0,
                       t_end=t_end, turns=turns, until_steady=until_steady, tol=tol, rtol=rtol)
    J_F = float(J_F)
    M = _moment_function(model, drive, drive_off_at, brake, extra)
    J_e = cast(PhiFunction, model.J_e)       # the raw functions (checked once by ReducedModel); each step's
    if model.dJ_e is not None:       # result is checked for finiteness instead
        dJ_e: PhiFunction = model.dJ_e
    else:
        hJ = 1e-6 * model.phi_T

        def dJ_e(p: FloatArray) -> FloatArray:
            return (J_e(p + hJ) - J_e(p - hJ)) / (2 * hJ)

    clamp = [-math.inf, math.inf]        # φ for the moment, kept on one side of a break while landing on it

    def rhs(t: float, y: FloatArray) -> FloatArray:
        phi, omega = y[0], y[1]
        if not (math.isfinite(phi) and math.isfinite(omega) and abs(omega) < 1e150):
            return np.full(4, math.nan)       # a trial stage that overflowed: the step is rejected and shortened
        p = np.array([phi])
        J = J_F + float(J_e(p)[0])
        if not J > 0:
            raise MotionError(f"the total inertia J_F + J_e = {J:.6g} kg·m² at φ = {math.degrees(phi):.6g}° is "
                              f"not positive; add flywheel inertia")
        m = M(min(max(phi, clamp[0]), clamp[1]), omega, t)
        eps = (m - 0.5 * omega * omega * float(dJ_e(p)[0])) / J
        return np.array([omega, eps, m * omega, omega * omega])

    y = np.array([phi_0, float(omega_0), 0.0, 0.0])
    k1 = rhs(t_0, y)
    if omega_0 == 0 and not k1[1] > 0:
        raise MotionError(f"the machine cannot start from rest at φ0 = {math.degrees(phi_0):.6g}°: the moment there "
                          f"is {M(phi_0, 0.0, t_0):.6g} N·m ≤ 0; start where the driving moment exceeds the "
                          f"resistance, or give it a starting speed")
    w_ref = float(omega_ref) if omega_ref else max(float(omega_0), 1e-300)
    L = model.phi_T
    phi_stop = phi_0 + TWO_PI * turns if turns is not None else math.inf
    t_stop = t_end if t_end is not None else math.inf
    switch_times = sorted(x for x in (drive_off_at, None if brake is None else brake.t_on)
                          if x is not None and math.isfinite(x) and x > t_0)

    ts, Ys, Ks = [t_0], [y], []
    eps_list = [k1[1]]
    err_sum = 0.0
    t = t_0
    h = None
    ended_by = ""
    # Poincaré samples at period boundaries φ0 + kφ_T
    next_boundary = phi_0 + L
    boundary: list[tuple[float, float, float]] = [(t_0, float(omega_0), 0.0)]     # (t, ω, Q)
    steady_k = None
    remaining = math.nan
    breaks = np.array(model.breaks, dtype=float)

    def break_after(phi: float) -> float:
        """The first declared break (a jump or kink of M_e, repeated every period) beyond φ."""
        if breaks.size == 0:
            return math.inf
        k = np.floor((phi + 1e-12 * max(1.0, abs(phi)) - breaks) / L) + 1
        return float(np.min(breaks + k * L))

    next_break = break_after(phi_0)
    h_land = None
    for _ in range(max_steps):
        w_ref = max(w_ref, abs(y[1]))
        if h is None:       # an initial step: a small fraction of the time to turn or to speed up
            scale_t = min(abs(1e-2 * w_ref / k1[1]) if k1[1] else math.inf,
                          1e-2 * TWO_PI / max(abs(y[1]), 1e-300))
            h = min(scale_t, (t_stop - t) if math.isfinite(t_stop) else scale_t)
            h = h if math.isfinite(h) and h > 0 else 1e-6
        # land exactly on switch times and the end time
        limit = min([s for s in switch_times if s > t + 1e-15 * max(1.0, abs(t))] + [t_stop])
        h_try = min(h, limit - t) if math.isfinite(limit) else h
        if h_land is not None:
            h_try = min(h_land, h_try)
        K = np.empty((7, 4))
        K[0] = k1
        for s in range(1, 7):
            K[s] = rhs(t + _C[s] * h_try, y + h_try * (_A[s] @ K[:s]))
        y_new = y + h_try * (_B @ K)
        if h_land is None and y_new[0] > next_break and math.isfinite(next_break) and np.all(np.isfinite(y_new)):
            # the step passes a break: take it again, ending on the break (located on this step's dense
            # output: φ is smooth through a jump of M), with the moment's left limit up to it
            lo, hi = _crossing(t, h_try, y, K, next_break)
            if hi * h_try > 1e-13 * max(1.0, abs(t)):
                h_land = hi * h_try
                clamp[1] = next_break - 1e-12 * max(1.0, abs(next_break))   # the left limit up to the break
                continue
        err = h_try * (_E @ K)
        sc_phi = rtol * TWO_PI
        sc_w = rtol * max(w_ref, abs(y_new[1]))
        e_norm = max(abs(err[0]) / sc_phi, abs(err[1]) / sc_w)
        if not np.all(np.isfinite(y_new)):
            e_norm = math.inf
        if e_norm > 1.0:
            h = h_try * max(0.2, 0.9 * e_norm ** -0.2)
            if h < 1e-14 * max(1.0, abs(t)):
                raise MotionError(f"the step size fell below 1e-14 s at t = {t:.6g} s, φ = "
                                  f"{math.degrees(y[0]):.6g}°: the moment is singular there")
            continue
        landing = h_land is not None and h_try >= h_land * (1 - 1e-12)
        gap = next_break - y_new[0] if landing else 0.0
        tol_phi = 1e-11 * max(1.0, abs(next_break))
        if landing and gap < -tol_phi:
            # past the break: this step (smooth, on the left limit) locates it well; take it again
            lo, hi = _crossing(t, h_try, y, K, next_break)
            h_land = 0.5 * (lo + hi) * h_try
            continue
        t_new = t + h_try
        k1 = K[6]
        clamp[0] = -math.inf
        if landing and gap > tol_phi:              # short of the break: go on towards it (Newton in time)
            h_land = gap / max(y_new[1], 1e-300)
        elif h_land is not None:
            clamp[1] = math.inf
            if landing:                            # on the break: the next step starts on its right side
                clamp[0] = next_break + 1e-12 * max(1.0, abs(next_break))
                next_break = break_after(max(y_new[0], next_break))
            h_land = None
            k1 = rhs(t_new, y_new)
        ts.append(t_new)
        Ys.append(y_new)
        Ks.append(K)
        eps_list.append(k1[1])
        err_sum += abs(err[1])
        grow = 5.0 if e_norm == 0 else min(5.0, 0.9 * e_norm ** -0.2)
        h = h_try * grow if h_try == h else max(h, h_try)
        if y_new[0] > next_break:          # passed a break on a step that ended just short of it
            next_break = break_after(y_new[0])
        t, y = t_new, y_new
        # events inside the step: stop (ω → 0), turns, period boundaries
        if y[1] <= 0:
            ended_by = "stopped"
            break
        if y[0] >= phi_stop:
            ended_by = "turns"
            break
        if t >= t_stop * (1 - 1e-15) and math.isfinite(t_stop):
            ended_by = "t_end"
            break
        if until_steady:
            while y[0] >= next_boundary:
                boundary.append((math.nan, math.nan, math.nan))     # filled below (dense output)
                tb, yb = _cross(ts, Ys, Ks, next_boundary)
                boundary[-1] = (tb, yb[1], yb[3])
                next_boundary += L
                steady_k, remaining = _steady_check(boundary, tol)
                if steady_k is not None:
                    break
            if steady_k is not None:
                ended_by = "steady"
                break
            if len(boundary) > max_periods:
                raise MotionError(f"no steady state after {max_periods} periods (t = {t:.6g} s): the speed at "
                                  f"the period start still changes by {abs(boundary[-1][1] - boundary[-2][1]):.3g} "
                                  f"rad/s a period; check the drive against the load")
    else:
        if until_steady and len(boundary) >= 2:
            raise MotionError(f"no steady state within {max_steps} steps ({len(boundary) - 1} periods, t = {t:.6g} s): "
                              f"the speed at the period start still changes by "
                              f"{abs(boundary[-1][1] - boundary[-2][1]):.3g} rad/s a period; the speed settles only "
                              f"when a moment depends on it (a motor, a brake M_B + C·ω with C > 0, a moment in ω), "
                              f"and the more slowly the smaller that dependence is against the inertia")
        raise MotionError(f"the run needs more than {max_steps} steps (t = {t:.6g} s); shorten it or loosen rtol")

    t_arr = np.array(ts)
    Y = np.array(Ys)
    Kall = np.array(Ks)
    if ended_by in ("stopped", "turns") and Kall.size:
        # cut the last step where ω = 0 or φ = φ_stop, by bisection on the dense output
        comp, target = (1, 0.0) if ended_by == "stopped" else (0, phi_stop)
        i = t_arr.size - 2
        lo, hi = 0.0, 1.0
        sign = 1.0 if comp == 1 else -1.0             # ω decreases through 0; φ increases through φ_stop
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            _, ym = _dense_one(t_arr[i], t_arr[i + 1], Y[i], Kall[i], mid)
            if sign * (ym[comp] - target) > 0:
                lo = mid
            else:
                hi = mid
        hm = hi * (t_arr[i + 1] - t_arr[i])
        clamp[0] = -math.inf                             # the shortened step, taken again (up to φ_stop
        clamp[1] = phi_stop - 1e-12 * max(1.0, abs(phi_stop)) if comp == 0 else math.inf   # from the left)
        Kall[-1] = _refit(rhs, t_arr[i], Y[i], hm)
        ym = Y[i] + hm * (_B @ Kall[-1])
        ym[comp] = target                                  # the event, to the integrator's accuracy
        t_arr[-1], Y[-1] = t_arr[i] + hm, ym
        eps_list[-1] = Kall[-1][6][1]
    clamp[0], clamp[1] = -math.inf, math.inf
    phi, omega, W, Q = Y.T
    J = J_F + model.J_e_at(phi)
    T = 0.5 * J * omega**2
    scale = max(float(np.max(T)), float(np.max(np.abs(W))), 1e-300)
    residual = float(np.max(np.abs(T - T[0] - W)) / scale)
    res = Run(t=_frozen(t_arr), phi=_frozen(phi), omega=_frozen(omega), epsilon=_frozen(np.array(eps_list)),
              work=_frozen(W), T=_frozen(T), J=_frozen(J), energy_residual=residual, error_estimate=float(err_sum),
              rtol=rtol,
              ended_by=ended_by, steady=None, phi_T=L, _K=Kall, _Y=Y, _rhs=rhs)
    if ended_by == "steady" and steady_k is not None:
        st = _steady_state(res, boundary, steady_k, tol, remaining)
        object.__setattr__(res, "steady", replace(st, phi_0=model.phi_0))
    return res


def _frozen(a: npt.ArrayLike) -> FloatArray:
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


def _crossing(t: float, h: float, y: FloatArray, K: FloatArray, level: float) -> tuple[float, float]:
    """The fractions (lo, hi) of the step [t, t + h] between which φ of its dense output reaches
    ``level`` (bisection to the resolution of a float)."""
    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if _dense_one(t, t + h, y, K, mid)[1][0] < level:
            lo = mid
        else:
            hi = mid
    return lo, hi


def _dense_one(t0: float, t1: float, y0: FloatArray, K: FloatArray, theta: float) -> tuple[float, FloatArray]:
    h = t1 - t0
    p = np.array([theta, theta**2, theta**3, theta**4])
    return t0 + theta * h, y0 + h * (K.T @ (_P @ p))


def _refit(rhs: Rhs, t0: float, y0: FloatArray, h: float) -> FloatArray:
    K = np.empty((7, 4))
    K[0] = rhs(t0, y0)
    for s in range(1, 7):
        K[s] = rhs(t0 + _C[s] * h, y0 + h * (_A[s] @ K[:s]))
    return K


def _cross(ts: Sequence[float], Ys: Sequence[FloatArray], Ks: Sequence[FloatArray],
           phi_b: float) -> tuple[float, FloatArray]:
    """(t, y) where φ = phi_b in the last step (bisection on the dense output)."""
    t0, t1, y0, K = ts[-2], ts[-1], Ys[-2], Ks[-1]
    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        _, ym = _dense_one(t0, t1, y0, K, mid)
        if ym[0] < phi_b:
            lo = mid
        else:
            hi = mid
    return _dense_one(t0, t1, y0, K, 0.5 * (lo + hi))


def _steady_check(boundary: Sequence[tuple[float, float, float]], tol: float) -> tuple[int | None, float]:
    """(k, remaining) once the Poincaré sequence ω_k has converged to min(1e-3·tol, 1e-9) (else (None, …))."""
    if len(boundary) < 3:
        return None, math.nan
    w = [b[1] for b in boundary]
    d1, d0 = w[-1] - w[-2], w[-2] - w[-3]
    if abs(d1) <= 1e-12 * abs(w[-1]):
        return len(boundary) - 1, 0.0
    if len(boundary) < 4 or d0 == 0:
        return None, math.nan
    q = d1 / d0
    if not 0 <= q < 1:
        return None, math.nan
    remaining = d1 * q / (1 - q)                 # signed: the limit is about w[-1] + remaining
    if abs(remaining) <= min(1e-3 * tol, 1e-9) * abs(w[-1]):
        return len(boundary) - 1, remaining
    return None, remaining


def _golden_max(f: Callable[[float], float], lo: float, hi: float, iterations: int) -> tuple[float, float]:
    """(x, f(x)) of the largest f on [lo, hi] by golden-section search (f unimodal there)."""
    g = (math.sqrt(5.0) - 1.0) / 2.0
    c, d = hi - g * (hi - lo), lo + g * (hi - lo)
    fc, fd = f(c), f(d)
    for _ in range(iterations):
        if fc >= fd:
            hi, d, fd = d, c, fc
            c = hi - g * (hi - lo)
            fc = f(c)
        else:
            lo, c, fc = c, d, fd
            d = lo + g * (hi - lo)
            fd = f(d)
    return (c, fc) if fc >= fd else (d, fd)


def _golden_extreme(res: Run, ts: FloatArray, ws: FloatArray, phis: FloatArray, j: int,
                    sense: int) -> tuple[float, float]:
    """(ω, φ) of the maximum (sense +1) or minimum (−1) of ω(t) near the sample j of the last period (times ts,
    speeds ws, angles phis): a golden-section search on the fifth-order partial steps, never worse than the
    sample."""
    # golden section on ω(t) (fifth-order partial steps) around the best sample
    step = float(ts[1] - ts[0])             # at the ends the bracket reaches into the neighbour periods
    lo = float(ts[j - 1]) if j > 0 else max(float(ts[0]) - step, float(res.t[0]))
    hi = float(ts[j + 1]) if j < ts.size - 1 else min(float(ts[-1]) + step, float(res.t[-1]))
    tt, _ = _golden_max(lambda x: sense * float(res.at_time([x])["omega"][0]), lo, hi, 40)
    at = res.at_time([tt])
    if sense * (at["omega"][0] - ws[j]) >= 0:
        return float(at["omega"][0]), float(at["phi"][0])
    return float(ws[j]), float(phis[j])


def _steady_state(res: Run, boundary: Sequence[tuple[float, float, float]], k: int, tol: float,
                  remaining: float) -> SteadyState:
    tA, wA, QA = boundary[k - 1]
    tB, wB, QB = boundary[k]
    L = res.phi_T
    # the last period, densely: 32 samples per step between tA and tB
    i0 = max(int(np.searchsorted(res.t, tA, side="right")) - 1, 0)
    i1 = min(int(np.searchsorted(res.t, tB, side="left")), res.steps)
    idx = np.repeat(np.arange(i0, i1), 32)
    theta = np.tile(np.arange(32) / 32.0, i1 - i0)
    ts, ys = res._dense(idx, theta)
    inside = (ts > tA) & (ts < tB)
    ends = res.at_time([tA, tB])
    ts = np.concatenate(([tA], ts[inside], [tB]))
    ys = np.concatenate((np.array([[ends["phi"][0], ends["omega"][0]]]), ys[inside][:, :2],
                         np.array([[ends["phi"][1], ends["omega"][1]]])))
    phis, ws = ys[:, 0], ys[:, 1]
    j_max, j_min = int(np.argmax(ws)), int(np.argmin(ws))

    w_max, p_max = _golden_extreme(res, ts, ws, phis, j_max, +1)
    w_min, p_min = _golden_extreme(res, ts, ws, phis, j_min, -1)
    t_T = tB - tA
    om_tb = 0.5 * (w_max + w_min)
    eps = res.at_time(ts[::4])["epsilon"]
    # time to reach the steady state: the last time |ω(t) − ω_p(φ(t))| exceeds tol·ω_m, refined
    order = np.argsort(phis)
    phase_p = phis[order] - phis[order][0]
    w_p = ws[order]

    shift = 0.0 if not math.isfinite(remaining) else remaining     # Aitken's estimate of what is left

    def steady_omega(phi: npt.ArrayLike) -> FloatArray:
        s = np.mod(np.asarray(phi) - phis[order][0], L)
        w: FloatArray = np.interp(s, np.append(phase_p, L), np.append(w_p, w_p[0])) + shift
        return w

    n_all = res.steps
    idx = np.repeat(np.arange(n_all), 8)
    th = np.tile(np.arange(8) / 8.0, n_all)
    ta, ya = res._dense(idx, th)
    dev = np.abs(ya[:, 1] - steady_omega(ya[:, 0]))
    band = tol * om_tb
    bad = np.flatnonzero(dev > band)
    if bad.size == 0:
        t_steady = float(res.t[0])
    else:
        j = int(bad[-1])
        i, lo, hi = int(idx[j]), float(th[j]), (float(th[j]) + 1.0 / 8.0)
        for _ in range(50):
            mid = 0.5 * (lo + hi)
            _, ym = res._dense(np.array([i]), np.array([mid]))
            if abs(ym[0, 1] - float(steady_omega(ym[0, 0]))) > band:
                lo = mid
            else:
                hi = mid
        t_steady = float(res.t[i] + hi * (res.t[i + 1] - res.t[i]))
    return SteadyState(
        t_steady=t_steady - float(res.t[0]), tol=tol, periods=k, omega_max=w_max, omega_min=w_min,
        phi_omega_max=p_max, phi_omega_min=p_min, omega_m_textbook=om_tb, omega_m_time=float(L / t_T),
        omega_m_integral=float((QB - QA) / L), delta=(w_max - w_min) / om_tb, t_T=float(t_T),
        epsilon_max=float(eps.max()), epsilon_min=float(eps.min()), remaining=float(abs(remaining)), phi_T=L)


def _dense_samples(res: Run, per_step: int = 8) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Times, ω and ε (the slope of the dense output's ω) at ``per_step`` points of every step and its end."""
    n = res.steps
    idx = np.repeat(np.arange(n), per_step)
    theta = np.tile(np.arange(per_step) / per_step, n)
    slope = np.stack([np.ones_like(theta), 2 * theta, 3 * theta**2, 4 * theta**3], axis=-1)
    Q = np.einsum("...sk,sp->...kp", res._K[idx], _P)
    ts, ys = res._dense(idx, theta)
    eps = np.einsum("...kp,...p->...k", Q, slope)[:, 1]
    ts = np.append(ts, res.t[-1])
    return ts, np.append(ys[:, 1], res.omega[-1]), np.append(eps, res.epsilon[-1])


def _omega_extreme(res: Run, ts: FloatArray, ws: FloatArray, sense: int) -> tuple[float, float, float, float]:
    """(ω, t, φ, spread) of the largest (sense +1) or smallest (−1) ω: the root of ε next to the best
    sample, bisected on the fifth-order partial steps, or an end of the run."""
    j = int(np.argmax(sense * ws))
    lo, hi = float(ts[max(j - 1, 0)]), float(ts[min(j + 1, ts.size - 1)])
    best = res.at_time([ts[j]])
    cands = [(float(best["omega"][0]), float(ts[j]), float(best["phi"][0]))]
    e_lo, e_hi = (float(res.at_time([x])["epsilon"][0]) for x in (lo, hi))
    spread = 0.0
    if sense * e_lo > 0 > sense * e_hi:              # a root of ε inside: ω has its extreme there
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if sense * float(res.at_time([mid])["epsilon"][0]) > 0:
                lo = mid
            else:
                hi = mid
        ends = res.at_time([lo, hi])
        spread = float(abs(ends["omega"][1] - ends["omega"][0]))
        cands.append((float(ends["omega"][0]), lo, float(ends["phi"][0])))
    w, t, phi = max(cands, key=lambda c: sense * c[0])
    return w, t, phi, spread


def _epsilon_extreme(res: Run, ts: FloatArray, es: FloatArray, sense: int) -> tuple[float, float]:
    """(ε, t) of the largest (sense +1) or smallest (−1) ε: golden section around the best sample."""
    j = int(np.argmax(sense * es))
    lo, hi = float(ts[max(j - 1, 0)]), float(ts[min(j + 1, ts.size - 1)])

    def f(tt: float) -> float:
        return sense * float(res.at_time([tt])["epsilon"][0])

    x, fx = _golden_max(f, lo, hi, 50)
    cands = [(fx, x), (f(float(ts[j])), float(ts[j])), (sense * float(es[j]), float(ts[j]))]
    cands += [(sense * float(e), float(t)) for e, t in zip(res.epsilon, res.t) if lo <= t <= hi]
    v, t = max(cands)
    return sense * v, t


def _dense_extremes(res: Run) -> dict[str, float]:
    """See :meth:`Run.extremes`."""
    if res.steps == 0:
        w, e = float(res.omega[0]), float(res.epsilon[0])
        t, p = float(res.t[0]), math.degrees(float(res.phi[0]))
        return {"omega_max_run": w, "t_omega_max_run": t, "phi_omega_max_run_deg": p, "omega_min_run": w,
                "t_omega_min_run": t, "phi_omega_min_run_deg": p, "epsilon_max_run": e, "t_epsilon_max_run": t,
                "epsilon_min_run": e, "t_epsilon_min_run": t, "error_extremes_omega": res.error_estimate}
    ts, ws, es = _dense_samples(res)
    w_max, t_max, p_max, s_max = _omega_extreme(res, ts, ws, +1)
    w_min, t_min, p_min, s_min = _omega_extreme(res, ts, ws, -1)
    e_max, te_max = _epsilon_extreme(res, ts, es, +1)
    e_min, te_min = _epsilon_extreme(res, ts, es, -1)
    return {"omega_max_run": w_max, "t_omega_max_run": t_max, "phi_omega_max_run_deg": math.degrees(p_max),
            "omega_min_run": w_min, "t_omega_min_run": t_min, "phi_omega_min_run_deg": math.degrees(p_min),
            "epsilon_max_run": e_max, "t_epsilon_max_run": te_max, "epsilon_min_run": e_min,
            "t_epsilon_min_run": te_min, "error_extremes_omega": res.error_estimate + max(s_max, s_min)}
