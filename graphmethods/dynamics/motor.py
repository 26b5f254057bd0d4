"""Speed-dependent driving moments (motor characteristics) and the steady motion they drive.

Two characteristics, each as seen on the reduced shaft through an ideal gear of ratio
u = ω_motor / ω (so M_d(ω) = u · M_motor(u ω); the rotor's inertia, J_rotor u², belongs in J_F):

* :class:`DCMotor`: the straight line M = M_0 (1 − ω_motor/ω_0) (stall torque M_0, no-load speed ω_0);
* :class:`InductionMotor`: Kloss's formula M = 2 M_k / (s/s_k + s_k/s) with the slip
  s = 1 − ω_motor/ω_s, built from rated power, rated speed, synchronous speed (or rated slip) and
  the overload ratio λ = M_k/M_nom: M_nom = P_nom/ω_nom, M_k = λ M_nom,
  s_k = s_nom (λ + sqrt(λ² − 1)) (the root of Kloss's formula through the rated point on the
  stable branch).

Equation of motion in the φ-domain
----------------------------------
With J(φ) = J_F + J_e(φ) and the kinetic energy T = ½ J ω², the energy theorem
dT/dt = (M_d + M_e) ω gives, dividing by ω = dφ/dt,

    dT/dφ = M_d(ω) + M_e(φ),   ω = sqrt(2 T / J(φ)).

(Expanding d(½Jω²)/dφ = J ω dω/dφ + ½ ω² J' recovers the moment form J ε = M_d + M_e − ½ ω² J'
with ε = ω dω/dφ.) Integrating T, not ω, needs no J'(φ) and keeps the energy balance exact in
form. :func:`motor_motion` integrates it with a fixed-step classical RK4 on φ (steps at uniform
angles plus the model's ``breaks``, so a jump of the load falls on a step boundary; the moment is
evaluated one-sided at the step ends), and finds the periodic steady state by shooting on T(0)
(secant iteration on T(φ_T) − T(0)).

>>> from graphmethods.dynamics.motion import ReducedModel
>>> motor = DCMotor(M_0=400.0, omega_0=40.0)               # N·m, rad/s
>>> model = ReducedModel(J_e=1.0, M_e=lambda phi: -200.0 - 100.0 * np.sin(phi))
>>> res = motor_motion(model, motor, J_F=5.0)
>>> round(float(np.mean(res.omega[:-1])), 6)   # ∫M_d dφ = ∫M_r dφ: ω averaged over φ is 20 rad/s
20.0
>>> res.multiplier < 1                                       # a stable steady state
True
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Protocol, TypeVar

import numpy as np

from graphmethods.dynamics.motion import MotionResult, ReducedModel, _check_count, _check_mean, _check_positive, _frozen
from graphmethods.errors import InputError, MotionError
from graphmethods.kinematics.vectors import FloatArray
from graphmethods.units import omega_from_n, real

__all__ = ["DCMotor", "InductionMotor", "Motor", "motor_motion"]

#: a speed or speeds, rad/s: a float, or an array of them (the moment comes back the same)
_Speed = TypeVar("_Speed", float, FloatArray)


class Motor(Protocol):
    """What :func:`motor_motion` asks of a motor (:class:`DCMotor`, :class:`InductionMotor` or one of
    the user's own): its characteristic on the reduced shaft, called with ω (rad/s, a float or an
    array) for M_d (N·m); its largest moment for ω ≥ 0; and the speed at which it gives a moment.

    >>> def stall_moment(motor: Motor) -> float:
    ...     return motor.M_max
    >>> stall_moment(DCMotor(M_0=100.0, omega_0=50.0, ratio=2.0))       # N·m on the reduced shaft
    200.0
    """

    def __call__(self, omega: _Speed) -> _Speed:
        """Driving moment on the reduced shaft (N·m) at its speed ω (rad/s)."""
        ...

    @property
    def M_max(self) -> float:
        """Largest driving moment on the reduced shaft for ω ≥ 0, N·m."""
        ...

    def omega_at(self, M: float) -> float:
        """Reduced-shaft speed (rad/s) at which the motor gives the moment M (N·m)."""
        ...


@dataclass(frozen=True, kw_only=True)
class DCMotor:
    """A DC motor's straight characteristic M = M_0 (1 − ω_motor/ω_0), reduced through ratio u.

    Parameters
    ----------
    M_0 : float
        Stall (starting) torque on the motor shaft, N·m.
    omega_0 : float
        No-load speed of the motor shaft, rad/s.
    ratio : float
        u = ω_motor / ω of the reduced shaft (1: the motor drives the reduced shaft directly).

    Examples
    --------
    >>> m = DCMotor(M_0=100.0, omega_0=50.0, ratio=2.0)
    >>> float(m(10.0))          # motor at 20 rad/s: 100·(1 − 20/50) = 60 N·m, ×2 on the crank
    120.0
    >>> m.omega_at(120.0)
    10.0
    """

    M_0: float
    omega_0: float
    ratio: float = 1.0

    def __post_init__(self) -> None:
        for name in ("M_0", "omega_0", "ratio"):
            _check_positive(getattr(self, name), f"DCMotor.{name}")

    def __call__(self, omega: _Speed) -> _Speed:
        """Driving moment on the reduced shaft (N·m) at its speed ω (rad/s); floats or arrays."""
        u = self.ratio
        M: _Speed = u * self.M_0 * (1.0 - u * omega / self.omega_0)
        return M

    @property
    def M_max(self) -> float:
        """Largest driving moment on the reduced shaft for ω ≥ 0 (at stall), N·m."""
        return self.ratio * self.M_0

    def omega_at(self, M: float) -> float:
        """Reduced-shaft speed (rad/s) at which the motor gives the moment M (N·m) there."""
        u = self.ratio
        return self.omega_0 * (1.0 - M / (u * self.M_0)) / u


@dataclass(frozen=True, kw_only=True)
class InductionMotor:
    """An induction motor by Kloss's formula, from its rating, reduced through ratio u.

    Parameters
    ----------
    P_nom : float
        Rated power, W.
    n_nom : float
        Rated speed, rev/min.
    lam : float
        Overload ratio λ = M_k / M_nom (> 1; typically 1.7–3).
    n_sync : float, optional
        Synchronous speed, rev/min (e.g. 1500 for a 4-pole motor on 50 Hz) ...
    s_nom : float, optional
        ... or the rated slip (then n_sync = n_nom / (1 − s_nom)). Give exactly one.
    ratio : float
        u = ω_motor / ω of the reduced shaft.

    Attributes
    ----------
    M_nom, M_k, s_k, omega_sync, s_nom_value
        Rated and breakdown torque (motor shaft, N·m), critical slip, synchronous speed (rad/s),
        rated slip.

    Examples
    --------
    >>> m = InductionMotor(P_nom=7500.0, n_nom=1440.0, n_sync=1500.0, lam=2.2)
    >>> round(m.M_nom, 3), round(m.s_k, 5)
    (49.736, 0.16638)
    >>> round(float(m(omega_from_n(1440.0))), 3)      # the rated point
    49.736
    """

    P_nom: float
    n_nom: float
    lam: float
    n_sync: float | None = None
    s_nom: float | None = None
    ratio: float = 1.0
    M_nom: float = field(init=False)
    M_k: float = field(init=False)
    s_k: float = field(init=False)
    omega_sync: float = field(init=False)
    s_nom_value: float = field(init=False)

    def __post_init__(self) -> None:
        for name in ("P_nom", "n_nom", "lam", "ratio"):
            _check_positive(getattr(self, name), f"InductionMotor.{name}")
        if (self.n_sync is None) == (self.s_nom is None):
            raise InputError("InductionMotor: give exactly one of n_sync (rev/min) and s_nom (rated slip)")
        if self.n_sync is not None:
            n_s = _check_positive(self.n_sync, "InductionMotor.n_sync")
            s = (n_s - self.n_nom) / n_s
        else:
            assert self.s_nom is not None                # exactly one of n_sync and s_nom (checked above)
            s = float(self.s_nom)
            if not 0 < s < 1:
                raise InputError(f"InductionMotor.s_nom = {self.s_nom!r}: the rated slip lies in (0, 1)")
            n_s = self.n_nom / (1.0 - s)
        if not 0 < s < 1:
            raise InputError(f"InductionMotor: rated speed {self.n_nom} rev/min must be below the "
                             f"synchronous speed {n_s} rev/min (rated slip {s:.4g})")
        if not self.lam > 1:
            raise InputError(f"InductionMotor.lam = {self.lam!r}: the overload ratio M_k/M_nom must exceed 1")
        M_nom = self.P_nom / omega_from_n(self.n_nom)
        object.__setattr__(self, "s_nom_value", s)
        object.__setattr__(self, "omega_sync", omega_from_n(n_s))
        object.__setattr__(self, "M_nom", M_nom)
        object.__setattr__(self, "M_k", self.lam * M_nom)
        object.__setattr__(self, "s_k", s * (self.lam + math.sqrt(self.lam**2 - 1.0)))

    def __call__(self, omega: _Speed) -> _Speed:
        """Driving moment on the reduced shaft (N·m) at its speed ω (rad/s); floats or arrays."""
        u = self.ratio
        s = 1.0 - u * omega / self.omega_sync
        M: _Speed = u * 2.0 * self.M_k * s * self.s_k / (s * s + self.s_k * self.s_k)
        return M

    @property
    def M_max(self) -> float:
        """Largest driving moment on the reduced shaft for ω ≥ 0, N·m (M_k, or the starting torque)."""
        if self.s_k <= 1:
            return self.ratio * self.M_k
        return float(self(0.0))

    def omega_at(self, M: float) -> float:
        """Reduced-shaft speed (rad/s) on the stable branch (|s| < s_k) giving the moment M (N·m)."""
        m = M / self.ratio
        if abs(m) > self.M_k:
            raise MotionError(f"the induction motor cannot give {M:.6g} N·m on the reduced shaft: "
                              f"its breakdown torque there is {self.ratio * self.M_k:.6g} N·m")
        if m == 0:
            s = 0.0
        else:
            q = self.M_k / m
            s = self.s_k * (q - math.copysign(math.sqrt(q * q - 1.0), q))
        return (1.0 - s) * self.omega_sync / self.ratio


class _Stall(Exception):
    def __init__(self, k: int, T: float) -> None:
        super().__init__(k, T)
        self.k, self.T = k, T
        self.T_start = math.nan                  # the starting energy, set by the caller that knows it


def _one_period(T0: float, h: list[float], J0: list[float], Jm: list[float], J1: list[float], M0: list[float],
                Mm: list[float], M1: list[float], M_d: Callable[[float], float]) -> list[float]:
    """RK4 for dT/dφ = M_d(sqrt(2T/J)) + M_e over the steps; T at the nodes (list)."""
    out = [T0]
    T = T0
    sqrt = math.sqrt
    for k in range(len(h)):
        hk = h[k]
        if T <= 0:
            raise _Stall(k, T)
        k1 = M_d(sqrt(2.0 * T / J0[k])) + M0[k]
        T2 = T + 0.5 * hk * k1
        if T2 <= 0:
            raise _Stall(k, T2)
        k2 = M_d(sqrt(2.0 * T2 / Jm[k])) + Mm[k]
        T3 = T + 0.5 * hk * k2
        if T3 <= 0:
            raise _Stall(k, T3)
        k3 = M_d(sqrt(2.0 * T3 / Jm[k])) + Mm[k]
        T4 = T + hk * k3
        if T4 <= 0:
            raise _Stall(k, T4)
        k4 = M_d(sqrt(2.0 * T4 / J1[k])) + M1[k]
        T = T + hk / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
        out.append(T)
    if T <= 0:
        raise _Stall(len(h) - 1, T)
    return out


class _Steps:
    """The RK4 step grid over one period and the model sampled on it (one-sided at step ends)."""

    def __init__(self, model: ReducedModel, J_F: float, steps: int) -> None:
        a, L = model.phi_0, model.phi_T
        uniform = a + L * (np.arange(steps + 1) / steps)
        x = np.unique(np.concatenate([uniform, model.breaks]))
        x = x[(x >= a) & (x <= a + L)]
        self.x, self.uniform = x, uniform
        h = np.diff(x)
        mid = x[:-1] + 0.5 * h
        right = np.nextafter(x[:-1], np.inf)       # just after the step's start
        left = np.nextafter(x[1:], -np.inf)        # just before its end
        Jx = J_F + model.J_e_at(x)
        self.Jx = Jx
        Jmid = J_F + model.J_e_at(mid)
        self.M_right = model.M_e_at(right)
        self.M_mid = model.M_e_at(mid)
        self.M_left = model.M_e_at(left)
        self.Jmid = Jmid
        self.h = h
        self.args = (h.tolist(), Jx[:-1].tolist(), Jmid.tolist(), Jx[1:].tolist(),
                     self.M_right.tolist(), self.M_mid.tolist(), self.M_left.tolist())
        # ∫ M_e dφ by Simpson's rule on each step
        self.work = float(np.sum(h / 6.0 * (self.M_right + 4.0 * self.M_mid + self.M_left)))


def _shoot(st: _Steps, M_d: Motor, T_guess: float, model: ReducedModel, max_iter: int) -> tuple[FloatArray, float]:
    """The periodic T at the nodes (T(φ_T) = T(0)) by secant iteration on T(0), and the period map's multiplier."""
    def P(T0: float) -> list[float]:
        try:
            return _one_period(T0, *st.args, M_d)
        except _Stall as s:
            s.T_start = T0
            raise

    def describe(stall: _Stall | None) -> str:
        assert stall is not None                 # no trajectory: a stall was met
        phi = st.x[stall.k]
        return (f"the machine stops: starting position 0 with the kinetic energy {stall.T_start:.6g} J, "
                f"the energy runs out near φ = "
                f"{math.degrees(phi):.6g}° ({math.degrees(phi - model.phi_0):.4g}° after position 0), "
                f"where it would fall to {stall.T:.4g} J: the driving moment and the inertia cannot "
                f"carry the load peak there. Increase J_F or the motor's torque, or reduce the load")

    Ta = T_guess
    traj: list[float] | None = None
    stall: _Stall | None = None
    for factor in (1.0, 2.0, 4.0, 8.0, 16.0):       # a little more energy may carry it past a peak
        try:
            traj = P(factor * T_guess)
            Ta = factor * T_guess
            break
        except _Stall as s:
            stall = stall or s
    if traj is None:
        raise MotionError(describe(stall))
    Ga = traj[-1] - Ta
    best = (abs(Ga), Ta, traj)
    Tb = traj[-1]
    for _ in range(max_iter):
        try:
            traj = P(Tb)
        except _Stall as s:
            stall = s
            Tb = 0.5 * (Ta + Tb)                     # back towards the last state that ran
            continue
        Gb = traj[-1] - Tb
        if abs(Gb) < best[0]:
            best = (abs(Gb), Tb, traj)
        if abs(Gb) <= 1e-14 * Tb or Gb == Ga:
            break
        Tn = Tb - Gb * (Tb - Ta) / (Gb - Ga)
        if not Tn > 0:
            Tn = 0.5 * Tb
        Ta, Ga, Tb = Tb, Gb, Tn
        if abs(Tb - Ta) <= 1e-15 * Ta:
            break
    G_best, T0, traj = best
    if G_best > 1e-8 * T0:
        if stall is not None:
            raise MotionError(describe(stall))
        raise MotionError(f"no periodic steady state found: after {max_iter} shooting iterations "
                          f"T(φ_T) − T(0) = {G_best:.3g} J at T(0) = {T0:.6g} J; the motion may be "
                          f"unstable (motor beyond its breakdown torque)")
    # the period map's multiplier dT(φ_T)/dT(0), by a central difference
    eta = 1e-6 * T0
    try:
        mult = (P(T0 + eta)[-1] - P(T0 - eta)[-1]) / (2 * eta)
    except _Stall:  # pragma: no cover - T0 ± 1e-6 T0 stalls only at the edge of stalling
        mult = math.nan
    if not mult < 1:
        raise MotionError(f"the periodic motion found is unstable (period-map multiplier {mult:.6g} ≥ 1): "
                          f"the motor works on the falling side of its characteristic; a larger "
                          f"motor or a smaller load is needed")
    return np.array(traj), mult


def _steady_state(model: ReducedModel, motor: Motor, J_F: float, steps: int,
                  max_iter: int) -> tuple[_Steps, FloatArray, float, float]:
    """The periodic kinetic energy T at the step nodes (J), with the step grid, the period map's
    multiplier and the accuracy of ω (from re-solving with half the steps)."""
    st = _Steps(model, J_F, steps)
    J_min = float(min(st.Jx.min(), st.Jmid.min()))
    if not J_min > 0:
        raise MotionError(f"the total inertia J_F + J_e must be positive: J_F = {J_F:.6g} kg·m², "
                          f"min(J_F + J_e) = {J_min:.6g} kg·m²")
    L = model.phi_T
    resisting = -st.work
    available = motor.M_max * L
    if resisting > available:
        raise MotionError(f"the speed cannot be sustained: the motor's driving work is at most "
                          f"{available:.6g} J per period (M_max = {motor.M_max:.6g} N·m over "
                          f"{L:.6g} rad) but the resisting work is {resisting:.6g} J: short by "
                          f"{resisting - available:.6g} J")
    omega_eq = motor.omega_at(resisting / L)
    if not omega_eq > 0:
        raise MotionError(f"the speed cannot be sustained: the motor gives the mean resisting moment "
                          f"{resisting / L:.6g} N·m only at ω = {omega_eq:.6g} rad/s ≤ 0")
    T_guess = 0.5 * float(st.Jx[0]) * omega_eq**2
    T, mult = _shoot(st, motor, T_guess, model, max_iter)

    # accuracy: re-solve with half the steps, compare ω on the common nodes
    half = _Steps(model, J_F, steps // 2)
    T_half, _ = _shoot(half, motor, float(T[0]), model, max_iter)
    common = np.searchsorted(st.x, half.x)
    w_full = np.sqrt(2.0 * T[common] / st.Jx[common])
    w_half = np.sqrt(2.0 * T_half / half.Jx)
    accuracy = float(np.max(np.abs(w_full - w_half)) / np.max(w_full) / 15.0)
    return st, T, mult, accuracy


def _omega_extremes(st: _Steps, T: FloatArray, w: FloatArray, Md: FloatArray) -> tuple[float, float, float, float]:
    """(φ, ω) of ω_max and of ω_min: the extreme nodes, refined on the two neighbouring steps by cubic
    Hermite T and quadratic J."""
    x, J, h = st.x, st.Jx, st.h
    dT_right = Md[:-1] + st.M_right
    dT_left = Md[1:] + st.M_left

    def local_extreme(k: int, sense: int) -> tuple[float, float]:
        best = (sense * w[k], float(x[k]), float(w[k]))
        s = np.linspace(0.0, 1.0, 257)
        for j in (k - 1, k):
            if j < 0 or j >= h.size:
                continue
            hh = h[j]
            h00, h10 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s
            h01, h11 = -2 * s**3 + 3 * s**2, s**3 - s**2
            Ts = h00 * T[j] + h10 * hh * dT_right[j] + h01 * T[j + 1] + h11 * hh * dT_left[j]
            Js = J[j] * (1 - s) * (1 - 2 * s) + 4 * st.Jmid[j] * s * (1 - s) + J[j + 1] * s * (2 * s - 1)
            ws = np.sqrt(2.0 * np.maximum(Ts, 0.0) / Js)
            i = int(np.argmax(sense * ws))
            if sense * ws[i] > best[0]:
                best = (sense * ws[i], float(x[j] + s[i] * hh), float(ws[i]))
        return best[1], best[2]

    p_max, w_max = local_extreme(int(np.argmax(w)), +1)
    p_min, w_min = local_extreme(int(np.argmin(w)), -1)
    return p_max, w_max, p_min, w_min


def motor_motion(model: ReducedModel, motor: Motor, *, J_F: float, steps: int = 3600, positions: int = 360,
                 mean: str = "textbook", max_iter: int = 60) -> MotionResult:
    """The periodic steady motion under a speed-dependent driving moment M_d(ω).

    (Over 80 lines only through this docstring, which documents every parameter; the code is 49 lines.)

    Integrates dT/dφ = M_d(ω) + M_e(φ), ω = sqrt(2T/(J_F + J_e(φ))), by fixed-step RK4 on φ and
    finds the periodic steady state by shooting on T(0). ε = (M_d + M_e − ½ω² dJ_e/dφ)/J;
    t = ∫dφ/ω by the trapezoidal rule with its end correction (fourth order, one-sided at jumps).

    Parameters
    ----------
    model : ReducedModel
        J_e(φ) and the position-dependent moment M_e(φ) (−M_r, and any other moment of φ alone).
    motor : DCMotor, InductionMotor or similar
        Callable ω ↦ M_d on the reduced shaft (N·m, for floats), with ``M_max`` (largest moment
        for ω ≥ 0) and ``omega_at(M)`` (speed on the stable branch giving M).
    J_F : float
        Flywheel (and rotor) inertia on the reduced shaft, kg·m².
    steps : int
        RK4 steps per period (even, a multiple of ``positions``); the model's breaks are added.
        Declare every jump of M_e in ``model.breaks``: a jump inside a step lowers RK4 to first
        order there (``accuracy`` then shows it).
    positions : int
        Output intervals: results at positions 0…m.
    mean : {"textbook", "time"}
        The mean δ refers to (both means are reported).

    Returns
    -------
    MotionResult
        ``method="rk4"``; ``multiplier`` is the period map's dT(φ_T)/dT(0) (< 1: stable);
        ``accuracy`` the largest relative change of ω when the steps are halved, divided by 15.

    Raises
    ------
    MotionError
        The motor cannot sustain the speed (its largest moment times φ_T is less than the
        resisting work, or the machine stops during the period), or no stable steady state exists.

    Examples
    --------
    >>> m = InductionMotor(P_nom=4000.0, n_nom=1430.0, n_sync=1500.0, lam=2.0, ratio=5.0)
    >>> from graphmethods.dynamics.motion import ReducedModel
    >>> model = ReducedModel(J_e=2.0, M_e=lambda phi: -80.0 * (1 + np.sin(phi) ** 2))
    >>> res = motor_motion(model, m, J_F=10.0)
    >>> 0 < res.delta < 0.05, round(res.omega_m_time, 3)
    (True, 30.117)
    """
    J_F = real(J_F, "J_F", unit="kg·m²", tiny_ok=True)      # the number policy: finite, at most 1e100
    steps = _check_count(steps, "steps", 4)
    positions = _check_count(positions, "positions", 1)
    mean = _check_mean(mean)
    if steps % 2 or steps % positions:
        raise InputError(f"steps = {steps}: make it even and a multiple of positions = {positions}")
    for name in ("M_max", "omega_at"):
        if not hasattr(motor, name) or not callable(motor):
            raise InputError(f"motor: give a DCMotor, an InductionMotor or a callable ω ↦ M_d with "
                             f"M_max and omega_at(M) (missing {name})")

    st, T, mult, accuracy = _steady_state(model, motor, J_F, steps, max_iter)
    L = model.phi_T

    x, J, h = st.x, st.Jx, st.h
    w = np.sqrt(2.0 * T / J)
    Md = np.asarray(motor(w), dtype=float)
    dJ = model.dJ_e_at(x)
    eps_right = (Md[:-1] + st.M_right - 0.5 * w[:-1] ** 2 * dJ[:-1]) / J[:-1]
    eps_left = (Md[1:] + st.M_left - 0.5 * w[1:] ** 2 * dJ[1:]) / J[1:]
    # t: trapezoid + end correction with f = 1/ω, f' = −ε/ω³ (one-sided at the step ends)
    f = 1.0 / w
    dt = 0.5 * h * (f[:-1] + f[1:]) + h**2 / 12.0 * (-eps_right / w[:-1] ** 3 + eps_left / w[1:] ** 3)
    t = np.concatenate([[0.0], np.cumsum(dt)])
    t_T = float(t[-1])

    p_max, w_max, p_min, w_min = _omega_extremes(st, T, w, Md)
    omega_m_tb = 0.5 * (w_max + w_min)
    omega_m_time = L / t_T
    omega_m = omega_m_tb if mean == "textbook" else omega_m_time
    eps_all = np.concatenate([eps_right, eps_left])
    i_eps = int(np.argmax(np.abs(eps_all)))
    x_eps = np.concatenate([x[:-1], x[1:]])[i_eps]

    out = np.searchsorted(x, st.uniform[:: steps // positions])
    eps_out = np.append(eps_right, eps_left[-1])[out]
    return MotionResult(
        phi=_frozen(x[out]), omega=_frozen(w[out]), t=_frozen(t[out]), epsilon=_frozen(eps_out),
        T=_frozen(T[out]), delta_E=_frozen(T[out] - T[0]), J=_frozen(J[out]), J_F=J_F, T0=float(T[0]),
        mean=mean, omega_m=float(omega_m), omega_m_textbook=float(omega_m_tb),
        omega_m_time=float(omega_m_time), delta=float((w_max - w_min) / omega_m),
        omega_max=w_max, omega_min=w_min, phi_omega_max=p_max, phi_omega_min=p_min,
        epsilon_max=float(eps_all[i_eps]), phi_epsilon_max=float(x_eps),
        chi=float(abs(eps_all[i_eps]) / omega_m**2), t_T=t_T, phi_0=model.phi_0, phi_T=L,
        closure_residual=float(T[-1] - T[0]), accuracy=accuracy, method="rk4", multiplier=float(mult))
