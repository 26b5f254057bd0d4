"""The dynamic study of a linkage problem: lazy, each quantity computed once, when first asked for.

A :class:`Study` holds a problem (:class:`~graphmethods.kinematics.case.Case`: linkage, masses,
working-stroke load, n, [δ]) and the number of positions m. Positions, velocity plans, J_e, M_r,
the excess work, the three flywheels (ΔW_max method, Wittenbauer at m positions with straight
chords, exact) are cached properties: a figure that draws only the moment diagram never builds
J_e; asking for J_F twice computes it once. ``computed`` lists what has been computed, in order.

Conventions: φ is the crank rotation from position 0 (the start of the working stroke), in the
crank's sense, rad; M_r ≥ 0 is the reduced resisting moment; M_d is constant, from the work
balance over one turn; M_e = M_d − M_r.

>>> from graphmethods.kinematics import read_case
>>> import pathlib
>>> study = Study(read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json"))
>>> round(study.M_d, 4), study.computed
(143.4309, ['M_d'])
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import cached_property
from typing import Any, TypeVar

import numpy as np
from numpy.typing import ArrayLike

from graphmethods.dynamics import excess_work as ew
from graphmethods.dynamics.flywheel import Flywheel, flywheel
from graphmethods.dynamics.graphical import FINE_CAP, REFINE, diagram_scales, with_refined_estimate
from graphmethods.dynamics.moments import MomentCurve
from graphmethods.dynamics.motion import FlywheelResult, ReducedModel, exact_flywheel
from graphmethods.dynamics.reduction import (
    ReducedInertia,
    load_switch_angles,
    load_work,
    reduced_inertia,
    reduced_inertia_slope,
    resisting_moment,
)
from graphmethods.dynamics.translating import TranslatingLink
from graphmethods.dynamics.wittenbauer import WittenbauerResult, wittenbauer
from graphmethods.errors import InputError, NoFlywheelNeeded
from graphmethods.kinematics.case import Case, DiagramLoad
from graphmethods.kinematics.linkage_mechanism import LinkageMechanism
from graphmethods.kinematics.plans import VelocityPlans
from graphmethods.kinematics.positions import Positions
from graphmethods.kinematics.vectors import FloatArray
from graphmethods.units import MAX_POSITIONS, count

TWO_PI = 2.0 * math.pi
SMOOTH = 32             # chords per interval between positions in the drawn M_r (a smooth curve by hand)
JUMP_SIDE = 1e-9        # rad either side of a switching position: the two ordinates of the jump
#: rad beyond the load's switch angles where :meth:`Study._M_r_in_window` still solves the linkage (the load's
#: own tolerance, 1e-12 of the stroke, is some 1e-12 rad: a million times inside it)
LOAD_WINDOW_MARGIN = 1e-6


_T = TypeVar("_T")
_S = TypeVar("_S", bound="Study")


def _logged(fn: Callable[[_S], _T]) -> cached_property[_T]:
    """A cached property that records its name in ``computed`` the one time it runs."""
    name = fn.__name__

    def wrapper(self: _S) -> _T:
        value = fn(self)
        self.computed.append(name)
        return value

    wrapper.__name__ = name
    wrapper.__doc__ = fn.__doc__
    return cached_property(wrapper)


#: the unit of each key of :meth:`Study.summary` (for the Markdown table)
_SUMMARY_UNITS = {
    "n_rpm": "rev/min", "omega_m": "rad/s", "M_d": "N·m", "delta_W_max": "J", "J_F_energy": "kg·m²",
    "J_F_wittenbauer": "kg·m²", "J_F_wittenbauer_error_estimate": "kg·m²", "kl_mm": "mm", "mu_J": "kg·m²/mm",
    "mu_T": "J/mm", "J_e_min": "kg·m²", "J_e_max": "kg·m²", "J_e_mean": "kg·m²", "J_F_exact": "kg·m²",
    "phi_omega_max_deg": "°", "phi_omega_min_deg": "°", "switch_angles_deg": "°",
    "wittenbauer_positions_omega_max": "position", "wittenbauer_positions_omega_min": "position",
    "A_jk": "J", "J_e_j": "kg·m²", "J_e_k": "kg·m²", "J_F_formula_90": "kg·m²", "delta_phi_deg": "°",
    "mu_max_deg": "°",
}


class Study:
    """The dynamic analysis of a linkage problem at m positions (see the module docstring).

    Parameters
    ----------
    case : Case
        The problem (read with :func:`graphmethods.kinematics.read_case`).
    positions : int
        Number of positions m (≥ 3; 12 by default).
    """

    def __init__(self, case: Case, *, positions: int = 12, estimate: bool = True) -> None:
        if not isinstance(case, Case):
            raise InputError(f"a Study needs a problem read with read_case(path) or case_from_dict(dict), "
                             f"got {type(case).__name__}")
        self.case = case
        self.m = count(positions, "the number of positions", low=3, high=MAX_POSITIONS,
                       why="checked before any work; textbooks use 8 to 48")
        self.estimate = estimate
        self.computed: list[str] = []

    # ----------------------------------------------------------------- speed data
    @property
    def omega_m(self) -> float:
        """Mean crank speed, rad/s."""
        return self.case.omega_m

    @property
    def delta(self) -> float:
        """Permissible coefficient of fluctuation [δ]."""
        return self.case.delta

    @property
    def mechanism(self) -> LinkageMechanism:
        """The problem's linkage."""
        return self.case.mechanism

    # ----------------------------------------------------------------- kinematics at positions
    @_logged
    def positions(self) -> Positions:
        """The linkage at positions 0…m."""
        return self.mechanism.positions(m=self.m)

    @_logged
    def plans(self) -> VelocityPlans:
        """Velocity plans at positions 0…m, built for ω₁ = ω_m."""
        return self.mechanism.velocity_plans(self.positions, omega_1=self.omega_m)

    @property
    def phi(self) -> FloatArray:
        """Crank rotation of positions 0…m from position 0, rad."""
        phi: FloatArray = self.positions.phi_from_start
        return phi

    # ----------------------------------------------------------------- the reduced model
    @_logged
    def M_d(self) -> float:
        """Constant driving moment from the work balance over one turn, N·m (exact)."""
        return load_work(self.mechanism, self.case.load) / TWO_PI

    @_logged
    def M_r(self) -> FloatArray:
        """Reduced resisting moment at positions 0…m, N·m (≥ 0)."""
        return resisting_moment(self.positions, self.plans, self.case.load)

    @_logged
    def inertia(self) -> ReducedInertia:
        """J_e and its parts at positions 0…m, kg·m²."""
        return reduced_inertia(self.plans, self.case.inertias)

    @property
    def J_e(self) -> FloatArray:
        """J_e at positions 0…m, kg·m²."""
        return self.inertia.J_e

    @_logged
    def switch_angles(self) -> tuple[float, float]:
        """Crank rotations from position 0 where the load switches on and off, rad (exact)."""
        return load_switch_angles(self.mechanism, self.case.load)

    def _J_e_exact(self, phi: ArrayLike) -> FloatArray:
        """J_e at crank rotations ``phi`` (rad from position 0), kg·m², from the linkage itself."""
        x = np.asarray(phi, dtype=float)
        pos = self.mechanism.positions(phi_from_start=x.ravel())
        return reduced_inertia(self.mechanism.velocity_plans(pos), self.case.inertias).J_e.reshape(x.shape)

    def _dJ_e_exact(self, phi: ArrayLike) -> FloatArray:
        """dJ_e/dφ at crank rotations ``phi`` (rad from position 0), kg·m²/rad, from the core's accelerations."""
        x = np.asarray(phi, dtype=float)
        return reduced_inertia_slope(self.mechanism, x, self.case.inertias).reshape(x.shape)

    def _M_r_exact(self, phi: ArrayLike) -> FloatArray:
        """M_r at crank rotations ``phi`` (rad from position 0), N·m, from the linkage itself."""
        x = np.asarray(phi, dtype=float)
        pos = self.mechanism.positions(phi_from_start=x.ravel())
        return resisting_moment(pos, self.mechanism.velocity_plans(pos), self.case.load).reshape(x.shape)

    def _M_r_in_window(self, phi: ArrayLike) -> FloatArray:
        """:meth:`_M_r_exact`, the linkage solved only where the load can act: between its switch angles
        (:attr:`switch_angles`, widened by :data:`LOAD_WINDOW_MARGIN`) and at the dead centre of position 0;
        elsewhere M_r = 0 without a solve. The same numbers bit for bit (each angle's solve is its own), at a
        third to a half of the cost: the exact flywheel's quadratures sample M_e at thousands of angles.

        >>> from graphmethods.problems.builtin import case
        >>> s = Study(case("press"))
        >>> p = np.linspace(0.0, 2 * math.pi, 97)
        >>> bool(np.array_equal(s._M_r_in_window(p), s._M_r_exact(p)))
        True
        """
        x = np.asarray(phi, dtype=float)
        if isinstance(self.case.load, DiagramLoad):        # a diagram acts over both strokes
            return self._M_r_exact(x)
        on, off = self.switch_angles
        t = np.mod(x.ravel(), TWO_PI)
        d = LOAD_WINDOW_MARGIN
        inside = ((t >= on - d) & (t <= off + d)) | (t <= d) | (t >= TWO_PI - d)
        out = np.zeros(t.size)
        if inside.any():
            out[inside] = self._M_r_exact(x.ravel()[inside])
        return out.reshape(x.shape)

    @property
    def is_engine(self) -> bool:
        """True when the load's net work drives the crank (an engine's gas force from its indicator
        diagram): the driving moment is then the curve and the constant from the work balance resists."""
        return self.M_d < 0.0

    def moment_curves(self, phi: ArrayLike) -> tuple[FloatArray, FloatArray]:
        """The reduced driving and resisting moments M_d(φ), M_r(φ) at crank rotations ``phi`` (rad
        from position 0), N·m, both as a user names them: for a working machine M_d is the constant
        of the work balance and M_r the load's moment; for an engine (:attr:`is_engine`) M_d is the
        load's moment (positive where it drives, negative on the compression stroke) and M_r the
        constant. M_d − M_r is the same reduced moment either way.

        >>> from graphmethods.problems.builtin import case
        >>> e = Study(case("engine"))
        >>> M_d, M_r = e.moment_curves(np.array([0.5, 4.0]))
        >>> e.is_engine, bool(M_d[0] > 0 > M_d[1]), round(float(M_r[0]), 2) == round(-e.M_d, 2)
        (True, True, True)
        """
        x = np.asarray(phi, dtype=float)
        load = np.asarray(self._M_r_exact(x), dtype=float)
        const = np.full_like(load, self.M_d)
        if self.is_engine:
            return -load, -const
        return const, load

    def power(self, *, eta: float = 1.0, reserve: float = 1.0) -> dict[str, Any]:
        """The mean power N = M_m·ω_m (W) and, for a working machine, the motor for it.

        M_m is the mean driving moment: M_d of the work balance for a working machine, the constant
        resistance for an engine (N is then the engine's mean power). With a drive of efficiency η
        between the motor and the crank (``eta``; mechanisms in series or parallel combined with
        :mod:`graphmethods.dynamics.power`) the driving moment becomes M_d/η, and the motor is the
        next IEC rated power above N/η·reserve.

        >>> from graphmethods.problems.builtin import case
        >>> p = Study(case("press")).power(eta=0.85)
        >>> round(p["N_mean"], 1), round(p["M_d_with_losses"], 2), p["motor_P_rated_kW"]
        (4506.0, 168.74, 5.5)
        """
        from graphmethods.dynamics.power import choose_motor, mean_power, moment_with_losses

        M_m = -self.M_d if self.is_engine else self.M_d
        out: dict[str, Any] = {"N_mean": mean_power(M_m=M_m, omega_m=self.omega_m), "M_m": M_m}
        if self.is_engine:
            out["note"] = "an engine: N_mean is the mean power it gives at ω_m (no motor to choose)"
            return out
        m = choose_motor(out["N_mean"], eta=eta, reserve=reserve)
        out.update(eta=m.eta, reserve=m.reserve, M_d_with_losses=moment_with_losses(self.M_d, eta=eta),
                   N_required=m.N_required, motor_P_rated_kW=m.P_rated_kW)
        return out

    def translating(self, point: str | None = None) -> TranslatingLink:
        """The translating equivalent link at ``point`` (default: the point the load acts on, the
        slider or ram): m_e = Σ[m(v_S/v)² + J_S(ω/v)²] straight from the plans, and
        F_e = (M_d − M_r)/(v/ω₁), the power of every force and moment over the link's speed, at
        positions 0…m except the dead centres (see :mod:`graphmethods.dynamics.translating`).

        >>> from graphmethods.problems.builtin import case
        >>> t = Study(case("scotch-yoke"), positions=4).translating()
        >>> t.index.tolist(), t.dead_centres.tolist(), t.m_e.round(4).tolist()
        ([1, 3], [0, 2, 4], [30.5, 30.5])
        """
        from graphmethods.dynamics.translating import equivalent_mass

        if point is None:
            if getattr(self.case.load, "kind", None) not in ("force", "diagram"):
                raise InputError("this problem's load is a moment on a turning link; name the point of a translating "
                                 "link (a slider or ram) for the equivalent mass")
            point = str(self.case.load.at)
        tr = equivalent_mass(self.plans, self.case.inertias, point=point)
        M_e = (self.M_d - self.M_r)[tr.index]
        from dataclasses import replace

        F_e = np.array(M_e / tr.v_q)
        F_e.setflags(write=False)
        phi = np.array(self.phi[tr.index])
        phi.setflags(write=False)
        return replace(tr, F_e=F_e, phi=phi)

    @_logged
    def model(self) -> ReducedModel:
        """The exact reduced model: J_e(φ), M_e(φ) as functions, the load's jumps declared."""
        M_d = self.M_d
        # dJ_e/dφ from the core's accelerations (a mechanism without the core: a difference of J_e)
        dJ_e = self._dJ_e_exact if hasattr(self.mechanism, "motion") else None
        return ReducedModel(J_e=self._J_e_exact, M_e=lambda p: M_d - self._M_r_in_window(p), dJ_e=dJ_e,
                            breaks=self.switch_angles)

    # ----------------------------------------------------------------- the graphical methods at m positions
    @_logged
    def moments(self) -> tuple[MomentCurve, MomentCurve]:
        """M_d and M_r as the course draws them.

        M_r goes through its ordinates at the positions and at the load's switching positions, with
        the jumps there (as the course adds the switching positions), and between them is the smooth
        curve a draftsman draws through the ordinates: the reduced moment itself, by
        :data:`SMOOTH` chords per interval. M_d is the constant that balances its work: the work
        balance :attr:`M_d` to about 10⁻⁵, so a sheet prints the study's M_d and J_F.
        """
        phi, M_r = drawn_resisting_moment(self)
        curve = MomentCurve.points(phi, M_r)
        return MomentCurve.constant(curve.mean(), period=TWO_PI), curve

    @_logged
    def excess_work(self) -> ew.ExcessWork:
        """The excess-work table of the drawn moment curves (crossings exact for the chords)."""
        M_d, M_r = self.moments
        return ew.from_moments(M_d, M_r)

    @_logged
    def delta_T(self) -> FloatArray:
        """ΔT at positions 0…m from the drawn curves (the chords' areas), J."""
        M_d, M_r = self.moments
        return (M_d - M_r).integral(self.phi)

    @_logged
    def flywheel_energy(self) -> Flywheel:
        """The ΔW_max method: J_F = ΔW_max/(ω_m²[δ]) − mean J_e (J_e taken constant)."""
        return flywheel(self.excess_work.delta_W_max, delta=self.delta, omega_m=self.omega_m,
                        J_e=float(np.mean(self.J_e[:-1])))

    @_logged
    def wittenbauer(self) -> WittenbauerResult:
        """The energy–mass diagram at positions 0…m with its tangent rays, and J_F from kl.

        Its error estimate is J_F at 16m positions minus J_F at m (see
        :func:`~graphmethods.dynamics.graphical.with_refined_estimate`).
        """
        mu_J, mu_T = diagram_scales(self.J_e, self.delta_T)
        wb = wittenbauer(J_e=self.J_e, delta_T=self.delta_T, omega_m=self.omega_m, delta=self.delta,
                         mu_J=mu_J, mu_T=mu_T, phi=self.phi)
        m_fine = min(REFINE * self.m, FINE_CAP)
        if self.estimate and m_fine > self.m:
            fine = _fine_study(self.case, m_fine)
            wb = with_refined_estimate(wb, fine.wittenbauer.J_F, m_fine)
        return wb

    @_logged
    def exact(self) -> FlywheelResult:
        """The exact flywheel for [δ] and its motion (the reference for the errors)."""
        return exact_flywheel(self.model, omega_m=self.omega_m, delta=self.delta)

    def at_angles(self, phi_deg: ArrayLike) -> list[dict[str, float]]:
        """The reduced quantities and the steady motion at given crank angles, as a textbook asks for them.

        At each angle (degrees from +x, counterclockwise, as the problem file defines φ): J_e (kg·m²),
        dJ_e/dφ (kg·m²/rad), M_d, M_r and M_e = M_d − M_r (N·m), the steady motion's ω (rad/s) and ε
        (rad/s²) with the exact flywheel for [δ] (J_F = 0 when none is needed), and the powers
        N_d = M_d·ω and N_r = M_r·ω (W). ω² = 2(T0 + ΔE(φ))/(J_F + J_e), ε = (M_e − ½ω² dJ_e/dφ)/(J_F + J_e).

        Examples
        --------
        >>> from graphmethods.problems.builtin import case
        >>> row = Study(case("press")).at_angles([30.0])[0]
        >>> round(row["M_d"], 2), bool(row["omega"] > 0)
        (143.43, True)
        """
        from graphmethods.dynamics.motion import _balanced_energy, periodic_motion

        x = np.mod(np.asarray(phi_deg, dtype=float).ravel(), 360.0)
        rot = self.mechanism.positions(phi=np.radians(x)).phi_from_start
        try:
            J_F = float(self.exact.J_F)
        except NoFlywheelNeeded:
            J_F = 0.0
        model = self.model
        steady = periodic_motion(model, J_F=J_F, omega_m=self.omega_m)
        E = _balanced_energy(model, 1e-6)
        dE = np.asarray(E(model.phi_0 + np.mod(rot - model.phi_0, model.phi_T)), dtype=float)
        J_e = self._J_e_exact(rot)
        dJ = model.dJ_e_at(rot) if hasattr(model, "dJ_e_at") else self._dJ_e_exact(rot)
        M_d, M_r = self.moment_curves(rot)
        M_e = M_d - M_r
        J = J_F + J_e
        omega = np.sqrt(2.0 * (steady.T0 + dE) / J)
        eps = (M_e - 0.5 * omega**2 * dJ) / J
        return [{"phi_deg": float(a), "phi_from_start_deg": float(np.degrees(r)), "J_e": float(je),
                 "dJ_e_dphi": float(dj), "M_d": float(md), "M_r": float(mr), "M_e": float(me), "J_F": J_F,
                 "omega": float(w), "epsilon": float(e), "N_d": float(md * w), "N_r": float(mr * w)}
                for a, r, je, dj, md, mr, me, w, e in zip(x, rot, J_e, dJ, M_d, M_r, M_e, omega, eps)]

    # ----------------------------------------------------------------- report
    def to_markdown(self, *, exact: bool | None = None) -> str:
        """The study's results as a Markdown table (quantity, value, unit), as a notebook shows it.

        ``exact=None`` (default) reports the exact flywheel only when it has been computed already
        (it takes about a second for the press), ``True`` computes it, ``False`` leaves it out.

        >>> import pathlib
        >>> from graphmethods.kinematics import read_case
        >>> s = Study(read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json"))
        >>> s.to_markdown().splitlines()[2]
        '| quantity | value | unit |'
        >>> "exact" in s.computed
        False
        """
        use_exact = ("exact" in self.computed) if exact is None else exact
        data = self.summary(exact=use_exact)
        rows = [(k, data[k]) for k in data]
        lines = ["| quantity | value | unit |", "|---|--:|---|"]
        for key, value in rows:
            if isinstance(value, list):
                text = ", ".join(f"{v:.5g}" if isinstance(v, float) else str(v) for v in value)
            elif isinstance(value, float):
                text = f"{value * 100:.3g} %" if key.endswith("rel_error") else f"{value:.6g}"
            else:
                text = str(value)
            lines.append(f"| {key} | {text} | {_SUMMARY_UNITS.get(key, '')} |")
        title = getattr(self.case, "title", "")
        head = (f"**Dynamic study** of {title}, {self.m} positions" if str(title)
                else f"**Dynamic study**, {self.m} positions")
        tail = [] if use_exact else ["", "(the exact flywheel is not computed yet: `study.to_markdown(exact=True)`)"]
        return "\n".join([head, ""] + lines + tail) + "\n"

    def _repr_markdown_(self) -> str:
        return self.to_markdown()

    def summary(self, *, exact: bool = True) -> dict[str, Any]:
        """The study's results as a JSON-ready dict (the keys of shared/cases/README.md).

        With ``exact`` (default) the exact flywheel is solved too, and each method's relative
        error against it is reported; without it, nothing exact is computed.
        """
        fe = self.flywheel_energy
        try:
            wb = self.wittenbauer
        except NoFlywheelNeeded as exc:      # an answer, not an error
            return self._no_flywheel_summary(fe, str(exc))
        out: dict[str, Any] = {
            "positions": self.m,
            "n_rpm": self.case.n_rpm,
            "omega_m": self.omega_m,
            "delta": self.delta,
            "M_d": self.M_d,
            "delta_W_max": self.excess_work.delta_W_max,
            "J_F_energy": fe.J_F,
            "J_F_wittenbauer": wb.J_F,
            "J_F_wittenbauer_error_estimate": wb.error_estimate,
            "kl_mm": wb.kl_mm,
            "mu_J": wb.mu_J,
            "mu_T": wb.mu_T,
            "wittenbauer_positions_omega_max": list(wb.index_omega_max),
            "wittenbauer_positions_omega_min": list(wb.index_omega_min),
            "J_e_min": float(self.J_e.min()),
            "J_e_max": float(self.J_e.max()),
            "J_e_mean": float(np.mean(self.J_e[:-1])),
        }
        if exact:
            try:
                ex = self.exact
            except NoFlywheelNeeded as exc:
                return self._no_flywheel_summary(fe, str(exc))
            out.update({
                "J_F_exact": ex.J_F,
                "J_F_energy_rel_error": (fe.J_F - ex.J_F) / ex.J_F,
                "J_F_wittenbauer_rel_error": (wb.J_F - ex.J_F) / ex.J_F,
                "phi_omega_max_deg": math.degrees(ex.phi_omega_max_from_0),
                "phi_omega_min_deg": math.degrees(ex.phi_omega_min_from_0),
                "switch_angles_deg": [math.degrees(a) for a in self.switch_angles],
            })
            from graphmethods.dynamics.flywheel_formulas import lecture_formulas

            out.update(lecture_formulas(self.model, ex))    # formula (90), χ ≈ 2δ/Δφ, χ, tan μ
        return out


    def _no_flywheel_summary(self, fe: Flywheel, why: str) -> dict[str, Any]:
        """The summary when the machine's own inertia keeps δ within [δ]: J_F = 0 is the answer."""
        return {
            "positions": self.m, "n_rpm": self.case.n_rpm, "omega_m": self.omega_m, "delta": self.delta,
            "M_d": self.M_d, "delta_W_max": self.excess_work.delta_W_max,
            "flywheel_needed": False, "J_F_energy": fe.J_F, "J_F_wittenbauer": 0.0, "J_F_exact": 0.0,
            "J_e_min": float(self.J_e.min()), "J_e_max": float(self.J_e.max()),
            "J_e_mean": float(np.mean(self.J_e[:-1])),
            "note": "no flywheel is needed: the mechanism's own inertia keeps δ within [δ] (J_F = 0); " + why,
        }

def drawn_resisting_moment(study: Study) -> tuple[FloatArray, FloatArray]:
    """The knots (rad from position 0) and ordinates (N·m) of M_r as drawn: the positions, SMOOTH
    steps between them, and both sides of every jump at the load's switching positions.

    >>> from graphmethods.problems import builtin
    >>> st = Study(builtin.case("press"))
    >>> phi, M_r = drawn_resisting_moment(st)
    >>> phi.size == 12 * SMOOTH + 1 + 4, abs(MomentCurve.points(phi, M_r).mean() / st.M_d - 1) < 1e-4
    (True, True)
    """
    grid = np.linspace(0.0, TWO_PI, study.m * SMOOTH + 1)
    grid[::SMOOTH] = study.phi                      # the positions themselves, bit for bit
    M = study._M_r_exact(grid)
    M[::SMOOTH] = study.M_r
    phi_k, M_k = [grid], [M]
    try:
        switches = [a for a in study.switch_angles if 0.0 < a < TWO_PI]
    except InputError:                              # a load without a working stroke: no switching positions
        switches = []
    for a in switches:
        left, right = study._M_r_exact(np.array([a - JUMP_SIDE, a + JUMP_SIDE]))
        phi_k.append(np.array([a, a]))
        M_k.append(np.array([left, right]))
    x = np.concatenate(phi_k)
    y = np.concatenate(M_k)
    order = np.argsort(x, kind="stable")           # a switching position's left side before its right
    return x[order], y[order]


def _fine_study(case: Case, m: int) -> Study:
    """The finer construction behind the error estimate: REFINE·m positions, beyond the user's limit
    MAX_POSITIONS (the kinematics core checks its own, MAX_POSITIONS_COMPUTED)."""
    fine = Study.__new__(Study)
    fine.case, fine.m, fine.estimate, fine.computed = case, int(m), False, []
    return fine


class AngleStudy(Study):
    """A :class:`Study` whose positions are the linkage at given crank angles, not 0…m: the plans and
    figures of a textbook's own crank angle.

    Parameters
    ----------
    case : Case
    phi_deg : sequence of float
        Crank angles, degrees from +x, counterclockwise (as the problem file defines φ).

    Examples
    --------
    >>> from graphmethods.problems.builtin import case
    >>> s = AngleStudy(case("press"), [30.0, 120.0])
    >>> s.positions.n
    2
    """

    def __init__(self, case: Case, phi_deg: ArrayLike) -> None:
        super().__init__(case, positions=3)
        self.phi_angles: FloatArray = np.radians(np.asarray(phi_deg, dtype=float).ravel())
        self.m = int(self.phi_angles.size)

    @_logged
    def positions(self) -> Positions:
        """The linkage at the given crank angles."""
        return self.mechanism.positions(phi=self.phi_angles)
