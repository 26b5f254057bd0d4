"""The reduced (equivalent) model of a linkage: J_e(φ), M_e(φ), the Zhukovsky lever, gear trains.

Kinetic energy and power are kept (domain.md §2), using the velocity analogues of the plans
(plans built for ω₁ = 1 rad/s, or divided by ω₁):

``J_e = Σ [ m_i (v_Si/ω₁)² + J_Si (ω_i/ω₁)² ]``,  ``M_e = Σ [ F_i · v_i/ω₁ + M_i ω_i/ω₁ ]``.

The working-stroke load of a problem file (:class:`~graphmethods.kinematics.case.Load`) switches
on and off at fractions of the stroke; :func:`load_switch_angles` finds those crank angles
exactly, so the exact solver sees the jumps where they are, not between positions.

>>> from graphmethods.kinematics import read_case
>>> import numpy as np
>>> from graphmethods.kinematics import SliderCrank, Inertia
>>> mech = SliderCrank(r=0.1, l=0.4, points={"S2": ("AB", 0.13, 0.0)})
>>> plans = mech.velocity_plans(mech.positions(m=4))
>>> J = reduced_inertia(plans, [Inertia("OA", "O", 0.0, 0.5), Inertia(None, "B", 12.0, 0.0)])
>>> J.J_e.round(6).tolist()          # at the dead centres only the crank counts
[0.5, 0.62, 0.5, 0.62, 0.5]
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType
from typing import cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from graphmethods.dynamics.moments import MomentCurve
from graphmethods.errors import InputError
from graphmethods.kinematics.case import DiagramLoad, Inertia, Load
from graphmethods.kinematics.linkage_mechanism import LinkageMechanism
from graphmethods.kinematics.plans import VelocityPlans
from graphmethods.kinematics.positions import Positions
from graphmethods.kinematics.vectors import FloatArray
from graphmethods.units import is_finite

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True, eq=False)
class ReducedInertia:
    """J_e at each position and its parts (kg·m²).

    ``parts`` maps a label such as ``"m3 (B)"`` or ``"J_S2 (AB)"`` to its share, (n,).
    """

    J_e: FloatArray
    parts: Mapping[str, FloatArray]

    @property
    def J_e_min(self) -> float:
        """The smallest J_e, kg·m²."""
        return float(self.J_e.min())

    @property
    def J_e_max(self) -> float:
        """The largest J_e, kg·m²."""
        return float(self.J_e.max())


def reduced_inertia(plans: VelocityPlans, inertias: Iterable[Inertia]) -> ReducedInertia:
    """J_e(φ) = Σ m (v_S/ω₁)² + J (ω_link/ω₁)² from velocity plans and the moving masses.

    Parameters
    ----------
    plans : VelocityPlans
        The plans at the positions wanted (any ω₁: analogues are used).
    inertias : iterable of Inertia
        ``(link, point, m, J)``: mass m (kg) at ``point``, moment of inertia J (kg·m²) about it
        turning with ``link`` (None for a translating body).
    """
    parts: dict[str, FloatArray] = {}
    total: FloatArray = np.zeros(plans.n)
    for it in inertias:
        if it.m < 0 or it.J < 0:
            raise InputError(f"negative mass or inertia for {it.point}: m = {it.m}, J = {it.J}")
        if it.m:
            v = plans.analogue(it.point)
            part = it.m * (v[:, 0] ** 2 + v[:, 1] ** 2)
            parts[f"m ({it.point})"] = part
            total = total + part
        if it.J:
            if it.link is None:
                raise InputError(f"an inertia J = {it.J} at {it.point} needs the link it turns with")
            part = it.J * plans.omega_ratio(it.link) ** 2
            parts[f"J ({plans.positions.mechanism.link_name(it.link)})"] = part
            total = total + part
    for a in (*parts.values(), total):
        a.setflags(write=False)
    return ReducedInertia(J_e=total, parts=MappingProxyType(parts))


def reduced_inertia_slope(mechanism: LinkageMechanism, phi_from_start: ArrayLike,
                          inertias: Iterable[Inertia]) -> FloatArray:
    """dJ_e/dφ = Σ 2 [ m v_S·a_S + J ω ε ] (kg·m²/rad) at crank rotations ``phi_from_start`` (rad), exactly,
    from the core's accelerations rather than a difference of J_e.

    The core is solved at unit crank speed and no crank acceleration, so that v_S and ω are the velocity
    analogues dX/dφ, dθ/dφ and a_S, ε their derivatives d²X/dφ², d²θ/dφ² with respect to the crank's
    rotation; J_e = Σ m |v_S|² + J ω² (:func:`reduced_inertia`) has the derivative above.

    >>> from graphmethods.kinematics import SliderCrank, Inertia
    >>> mech = SliderCrank(r=0.1, l=0.4)
    >>> slope = reduced_inertia_slope(mech, np.array([0.0, 1.0]), [Inertia(None, "B", 12.0, 0.0)])
    >>> bool(abs(slope[0]) < 1e-15), bool(slope[1] != 0)           # none at the dead centre
    (True, True)
    """
    motion = mechanism.motion(phi_from_start=np.asarray(phi_from_start, dtype=float).ravel(), omega_1=1.0,
                              epsilon_1=0.0, level=2)
    total: FloatArray = np.zeros(len(motion.phi))
    for it in inertias:
        if it.m:
            v, a = motion.v(it.point), motion.a(it.point)
            total = total + 2.0 * it.m * (v[:, 0] * a[:, 0] + v[:, 1] * a[:, 1])
        if it.J:
            if it.link is None:
                raise InputError(f"an inertia J = {it.J} at {it.point} needs the link it turns with")
            _, omega, epsilon = motion.link(mechanism.number(it.link))
            total = total + 2.0 * it.J * omega * epsilon
    return total


def _stroke_fraction(positions: Positions, load: Load) -> FloatArray:
    """s/H (a force) or ψ/ψ_max (a moment) at each position."""
    out: FloatArray
    if load.kind == "force":
        if positions.s is None or positions.H is None:
            raise InputError(f"a force load on {load.at} needs a slider output; this linkage has none")
        out = positions.s / positions.H
        return out
    if positions.psi is None or positions.psi_max is None:
        raise InputError(f"a moment load on {load.at} needs a rocker output; this linkage has none")
    out = positions.psi / positions.psi_max
    return out


def _diagrams(load: DiagramLoad) -> list[ForceDiagram]:
    """The parts of a diagram load as force diagrams against the stroke."""
    return [ForceDiagram(load.at, x=tuple(x), F=tuple(F), against="stroke", stroke=stroke, opposes=not drives)
            for x, F, stroke, drives in load.parts]


def load_active(positions: Positions, load: Load) -> NDArray[np.bool_]:
    """Where the working-stroke load acts: on the working stroke, between its stroke fractions."""
    frac = _stroke_fraction(positions, load)
    if positions.working is None:
        raise InputError(f"the load on {load.at} acts on the working stroke; this linkage's output has none")
    tol = 1e-12
    out: NDArray[np.bool_] = positions.working & (frac >= load.start - tol) & (frac <= load.end + tol)
    return out


def resisting_moment(positions: Positions, plans: VelocityPlans, load: Load | DiagramLoad) -> FloatArray:
    """The reduced resisting moment M_r ≥ 0 (N·m) of the load at each position.

    A force F opposing the slider gives F |v_B|/ω₁; a moment M opposing a rocker gives
    M |ω_i|/ω₁; zero where the load does not act.
    """
    if isinstance(load, DiagramLoad):        # signed: negative where a diagram drives
        return np.asarray(sum(diagram_moment(positions, plans, d) for d in _diagrams(load)), dtype=float)
    if load.kind == "force":
        analogue = np.abs(plans.v_along_guide(load.at)) / plans.omega_1
    else:
        analogue = np.abs(plans.omega_ratio(load.at))
    out: FloatArray = np.where(load_active(positions, load), load.magnitude * analogue, 0.0)
    return out


#: parts each bracket of :func:`load_switch_angles` is split into a round (one solve of 2·(_SPLIT − 1) angles)
_SPLIT = 32


def _fraction_at(mechanism: LinkageMechanism, phi_from_start: FloatArray, load: Load) -> FloatArray:
    """:func:`_stroke_fraction` at crank rotations ``phi_from_start`` (rad from position 0), from the core's
    motion alone where the load's output is the linkage's (no :class:`Positions` assembled: the same numbers,
    at a fraction of the cost of the small solves :func:`load_switch_angles` makes)."""
    lk = getattr(mechanism, "linkage", None)
    out = None if lk is None or lk.output is None else lk.output[0]
    if lk is not None and out == ("point" if load.kind == "force" else "link"):
        mo = lk.motion(phi_from_start=phi_from_start, level=0)
        value: FloatArray = mo.s / lk.stroke_H() if load.kind == "force" else mo.psi / lk.psi_max()
        return value
    return _stroke_fraction(mechanism.positions(phi_from_start=phi_from_start), load)


def load_switch_angles(mechanism: LinkageMechanism, load: Load | DiagramLoad) -> tuple[float, float]:
    """Crank rotations from position 0 (rad) where the load switches on and off.

    The stroke fraction grows monotonically over the working stroke, so each switch angle is the
    root of ``fraction(φ) = start`` (``= end``), found to machine precision by splitting both brackets
    into :data:`_SPLIT` parts a round, all in one solve of the linkage.
    """
    strokes = mechanism.strokes()
    if strokes is None:
        raise InputError("this linkage has no working stroke; a working-stroke load needs one")
    if isinstance(load, DiagramLoad):   # diagrams change over the strokes; they start and end at the dead centres
        return 0.0, float(strokes.working_angle)
    lo = np.zeros(2)
    hi = np.full(2, strokes.working_angle)
    target = np.array([load.start, load.end])[:, None]
    steps = np.arange(1, _SPLIT) / _SPLIT
    rows = np.arange(2)
    tiny = strokes.working_angle * 2.0 ** -64
    done = np.zeros(2, dtype=bool)
    settled = done.copy()
    for _ in range(64):          # each round splits both brackets in _SPLIT in one solve: 11 rounds, not 64
        t = lo[:, None] + (hi - lo)[:, None] * steps
        below = _fraction_at(mechanism, t.ravel(), load).reshape(t.shape) < target
        j = np.where(below.all(axis=1), _SPLIT - 1, np.argmin(below, axis=1))   # the first point not below
        new_lo = np.where(j > 0, t[rows, np.maximum(j - 1, 0)], lo)
        new_hi = np.where(j < _SPLIT - 1, t[rows, np.minimum(j, _SPLIT - 2)], hi)
        # a bracket is done when it no longer narrows (adjacent numbers) or is as narrow as 64 halvings make it
        done |= ((new_lo == lo) & (new_hi == hi)) | (new_hi - new_lo <= tiny)
        lo, hi = np.where(settled, lo, new_lo), np.where(settled, hi, new_hi)
        settled = done.copy()
        if settled.all():
            break
    a, b = 0.5 * (lo + hi)
    # a switch at a dead centre (fraction 0 or 1) is the stroke's own end, exact: the fraction touches its
    # target there with zero slope, so bisection would only find it to √ε (1e-8 rad)
    return (0.0 if load.start <= 0.0 else float(a),
            float(strokes.working_angle) if load.end >= 1.0 else float(b))


def load_work(mechanism: LinkageMechanism, load: Load | DiagramLoad) -> float:
    """Work of the load over one cycle, J (exact: the stroke fraction is monotone while it acts).

    A force does F·H·(end − start); a moment M·ψ_max·(end − start).
    """
    pos = mechanism.positions(m=4)
    if isinstance(load, DiagramLoad):        # resisting work minus driving work
        if pos.H is None:
            raise InputError("a force diagram acts on a slider output; this linkage has none")
        H = pos.H
        return sum((1.0 if d.opposes else -1.0) * d.work(H=H) for d in _diagrams(load))
    span = pos.H if load.kind == "force" else pos.psi_max
    if span is None:
        raise InputError(f"a {load.kind} load needs a {'slider' if load.kind == 'force' else 'rocker'} output; "
                         f"this linkage has none")
    return load.magnitude * span * (load.end - load.start)


# --------------------------------------------------------------------- force diagrams
@dataclass(frozen=True)
class ForceDiagram:
    """A force on a slider given as a diagram, as course problems give it.

    Parameters
    ----------
    point : str
        The slider point it acts on (``"B"``).
    x, F : sequences of float
        The diagram's points: F (N, magnitude ≥ 0) against ``x``, piecewise linear between them; a
        repeated x is a jump (vertical side). Zero outside the first and last x.
    against : {"stroke", "angle"}
        ``"stroke"``: x is the stroke fraction s/H, measured from the start of the working stroke
        on both strokes (a press's cutting force with overrun, a compressor's or engine's indicator
        diagram); ``"angle"``: x is the crank rotation from position 0, rad.
    stroke : {"working", "return"}
        With ``against="stroke"``, the stroke the diagram belongs to.
    opposes : bool
        True for a resisting force (it opposes the slider's motion); False for a driving one (gas
        pressure on an expansion stroke).

    Examples
    --------
    The press's cutting force, 5000 N from 5 % to 95 % of the working stroke:

    >>> cut = ForceDiagram("B", x=(0.05, 0.05, 0.95, 0.95), F=(0.0, 5000.0, 5000.0, 0.0))
    >>> round(cut.work(H=0.2), 6)        # F·H·0.9
    900.0
    """

    point: str
    x: tuple[float, ...]
    F: tuple[float, ...]
    against: str = "stroke"
    stroke: str = "working"
    opposes: bool = True

    def __post_init__(self) -> None:
        if self.against not in ("stroke", "angle"):
            raise InputError(f"against = {self.against!r}: give 'stroke' (s/H) or 'angle' (crank rotation, rad)")
        if self.stroke not in ("working", "return"):
            raise InputError(f"stroke = {self.stroke!r}: give 'working' or 'return'")
        # validates: finite, non-decreasing, two points or more (cast: MomentCurve converts any sequence of
        # numbers, and reports what is not one, so the tuples are passed as given)
        curve = MomentCurve(cast(FloatArray, self.x), cast(FloatArray, self.F))
        if (curve.M < 0).any():
            raise InputError("a force diagram gives magnitudes (F ≥ 0); say whether it resists with opposes=")
        if self.against == "stroke" and (curve.phi[0] < -1e-12 or curve.phi[-1] > 1 + 1e-12):
            raise InputError(f"stroke fractions run from 0 to 1; the diagram spans {curve.phi[0]:g}…{curve.phi[-1]:g}")

    def value(self, x: ArrayLike) -> FloatArray:
        """F at ``x`` (right-continuous at a jump), 0 outside the diagram, N."""
        curve = MomentCurve(np.asarray(self.x, dtype=float), np.asarray(self.F, dtype=float))
        xs = np.asarray(x, dtype=float)
        inside = (xs >= curve.phi[0]) & (xs <= curve.phi[-1])
        out: FloatArray = np.where(inside, curve.limits(np.clip(xs, curve.phi[0], curve.phi[-1]))[1], 0.0)
        return out

    def work(self, *, H: float) -> float:
        """|Work| of a stroke diagram over its stroke, J: H × the area under F(s/H) (exact)."""
        if self.against != "stroke":
            raise InputError("the work of a diagram against the crank angle depends on the velocities; "
                             "integrate diagram_moment over the positions instead")
        return H * MomentCurve(np.asarray(self.x, dtype=float), np.asarray(self.F, dtype=float)).work()


def diagram_moment(positions: Positions, plans: VelocityPlans, diagram: ForceDiagram) -> FloatArray:
    """The reduced moment of a force diagram at each position, N·m: F |v|/ω₁, positive where it
    resists (``opposes``), negative where it drives.

    >>> from graphmethods.kinematics import SliderCrank
    >>> mech = SliderCrank(r=0.1, l=0.4)
    >>> pos = mech.positions(m=4)
    >>> d = ForceDiagram("B", x=(0.0, 1.0), F=(1000.0, 1000.0))
    >>> diagram_moment(pos, mech.velocity_plans(pos), d).round(6).tolist()   # |v_B| = r at 90°
    [0.0, 100.0, 0.0, 0.0, 0.0]
    """
    speed = np.abs(plans.v_along_guide(diagram.point)) / plans.omega_1
    if diagram.against == "angle":
        F = diagram.value(positions.phi_from_start)
    else:
        if positions.s is None or positions.H is None or positions.working is None:
            raise InputError("a force diagram against the stroke needs a slider output; this linkage has none")
        on_stroke = positions.working if diagram.stroke == "working" else ~positions.working | positions.extreme
        F = np.where(on_stroke, diagram.value(positions.s / positions.H), 0.0)
    M: FloatArray = F * speed
    return M if diagram.opposes else -M


# --------------------------------------------------------------------- Zhukovsky lever
@dataclass(frozen=True, eq=False)
class ZhukovskyLever:
    """The velocity plan turned 90° as a rigid lever about the pole p.

    ``images`` maps each loaded point to its turned plan image (n, 2) in m/rad (analogue units;
    divide by μ_v for mm on a plan drawn to μ_v); ``moment`` is Σ (image × F) + Σ M_i ω_i/ω₁,
    the reduced moment M_e (N·m), equal to the power method's.
    """

    images: Mapping[str, FloatArray]
    forces: Mapping[str, FloatArray]
    moment: FloatArray


def _turn(v: FloatArray, sense: int) -> FloatArray:
    """Turn vectors (n, 2) by 90° against ``sense`` (−90° for a counterclockwise crank)."""
    out: FloatArray = np.column_stack((v[:, 1], -v[:, 0])) if sense > 0 else np.column_stack((-v[:, 1], v[:, 0]))
    return out


def zhukovsky_lever(plans: VelocityPlans, *, forces: Mapping[str, ArrayLike] | None = None,
                    moments: Mapping[str, ArrayLike] | None = None) -> ZhukovskyLever:
    """The reduced moment by Zhukovsky's lever.

    The plan of analogues v/ω₁ is turned 90° opposite to the crank's rotation; each force F
    (N, (n, 2) or (2,)) is applied at the image of its point; the moment of all forces about
    the pole, plus the link moments times ω_i/ω₁, is M_e (positive: driving, in the crank's
    sense). For a counterclockwise crank the image of v is (v_y, −v_x), and its moment about p,
    v_y F_y + v_x F_x = F·v, is exactly the power method's term.

    >>> import numpy as np
    >>> from graphmethods.kinematics import SliderCrank
    >>> mech = SliderCrank(r=0.1, l=0.4)
    >>> plans = mech.velocity_plans(mech.positions(m=12))
    >>> lever = zhukovsky_lever(plans, forces={"B": np.array([-1000.0, 0.0])})
    >>> bool(np.allclose(lever.moment, -1000.0 * plans.analogue("B")[:, 0]))
    True
    """
    images: dict[str, FloatArray] = {}
    fs: dict[str, FloatArray] = {}
    total: FloatArray = np.zeros(plans.n)
    for name, given in (forces or {}).items():
        F = np.broadcast_to(np.asarray(given, dtype=float), (plans.n, 2))
        img = _turn(plans.analogue(name), plans.sense)
        images[name] = img
        fs[name] = F
        total = total + plans.sense * (img[:, 0] * F[:, 1] - img[:, 1] * F[:, 0])
    for link, M in (moments or {}).items():
        total = total + np.asarray(M, dtype=float) * plans.omega_ratio(link)
    return ZhukovskyLever(images=MappingProxyType(images), forces=MappingProxyType(fs), moment=total)


def power_moment(plans: VelocityPlans, *, forces: Mapping[str, ArrayLike] | None = None,
                 moments: Mapping[str, ArrayLike] | None = None) -> FloatArray:
    """The reduced moment by power: M_e = Σ F·(v/ω₁) + Σ M_i (ω_i/ω₁), N·m (+ in the crank's sense)."""
    total: FloatArray = np.zeros(plans.n)
    for name, given in (forces or {}).items():
        F = np.broadcast_to(np.asarray(given, dtype=float), (plans.n, 2))
        v = plans.analogue(name)
        total = total + (F[:, 0] * v[:, 0] + F[:, 1] * v[:, 1])
    for link, M in (moments or {}).items():
        total = total + np.asarray(M, dtype=float) * plans.omega_ratio(link)
    return total


# --------------------------------------------------------------------- gear trains
@dataclass(frozen=True)
class Shaft:
    """A shaft of a drive: its inertia J (kg·m²), the moment on it M (N·m, + driving), and its speed
    ratio ``omega_ratio`` = ω_i/ω to the shaft everything is reduced to."""

    name: str
    J: float
    omega_ratio: float
    M: float = 0.0


@dataclass(frozen=True)
class ReducedDrive:
    """A multi-shaft drive reduced to one shaft: J_e = Σ J_i (ω_i/ω)², M_e = Σ M_i (ω_i/ω)."""

    J_e: float
    M_e: float
    parts: Mapping[str, float]


def reduce_drive(shafts: Sequence[Shaft]) -> ReducedDrive:
    """Reduce the shafts of a gear train (two-, three-, four-mass models …) to one shaft.

    >>> motor = Shaft("motor", J=0.05, omega_ratio=4.0, M=30.0)       # turns 4× faster
    >>> crank = Shaft("crank", J=2.0, omega_ratio=1.0, M=-100.0)
    >>> d = reduce_drive([motor, crank])
    >>> round(d.J_e, 6), round(d.M_e, 6)
    (2.8, 20.0)
    """
    parts: dict[str, float] = {}
    J = M = 0.0
    for s in shafts:
        if not (is_finite(s.J) and s.J >= 0):
            raise InputError(f"shaft {s.name}: J = {s.J!r} must be a non-negative inertia in kg·m²")
        if not (is_finite(s.omega_ratio) and s.omega_ratio != 0):
            raise InputError(f"shaft {s.name}: the speed ratio ω_i/ω = {s.omega_ratio!r} must be a non-zero number")
        part = s.J * s.omega_ratio**2
        parts[s.name] = part
        J += part
        M += s.M * s.omega_ratio
    return ReducedDrive(J_e=J, M_e=M, parts=MappingProxyType(parts))
