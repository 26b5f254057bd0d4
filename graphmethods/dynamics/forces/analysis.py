"""The force (kinetostatic) analysis of any linkage, group by group from the last to the crank.

d'Alembert: every moving link is in equilibrium under its applied forces (the inertia force
``F_i = −m·a_S`` at its centre of mass and the inertia moment ``M_i = −J_S·ε``, its weight when
asked, the working load) and the reactions of its pairs. The groups are solved in the reverse of
the structural formula, each by its own solver (:data:`SOLVERS`, one module per dyad type); a
group's reactions on the links it is attached to are added to their loads; the crank last gives
the frame's reaction R_01 and the balancing moment M_b. Zhukovsky's lever and the power balance
give M_b again (:mod:`.lever`). Vectorised over the positions of a :class:`Motion`.

>>> import numpy as np
>>> from graphmethods.kinematics.presets import slider_crank
>>> lk = slider_crank(r=0.1, l=0.4)
>>> mo = lk.motion(phi=[np.pi / 2], omega_1=10.0)
>>> load = [("3", Force("F_c", F=np.array([1000 + 0j]), at=mo.z["B"], M=np.zeros(1)))]
>>> fa = kinetostatics(mo, masses=[], loads=load)
>>> round(float(fa.M_balance[0]), 9)            # 1000 N against the slider moving −x: M_b = F·r
100.0
>>> [round(float(x[0]), 9) for x in (fa.M_balance_lever, fa.M_balance_power)]
[100.0, 100.0]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from types import MappingProxyType
from typing import Any

import numpy as np

from graphmethods.dynamics.forces import prp, rpp, rpr, rrp, rrr, triad
from graphmethods.dynamics.forces.base import (
    Force,
    ForcePlan,
    GroupForces,
    Kin,
    Polygon,
    Reaction,
    on_link,
    reaction,
    resultant,
)
from graphmethods.dynamics.forces.lever import Lever, power_balance, zhukovsky
from graphmethods.dynamics.forces.statics import Cx, Fl, moment_about
from graphmethods.errors import InputError
from graphmethods.kinematics.structure import GROUND
from graphmethods.units import ROUNDOFF, is_finite

#: standard gravity, m/s² (acts along −y of the file's frame)
G_STANDARD = 9.81

#: group kind -> its force solver (a new dyad type: one module with ``solve``, one line here)
SOLVERS: dict[str, Callable[..., GroupForces]] = {
    "RRR": rrr.solve, "RRP": rrp.solve, "RPR": rpr.solve, "PRP": prp.solve, "RPP": rpp.solve, "triad": triad.solve}


@dataclass(frozen=True)
class Mass:
    """A moving mass: ``m`` (kg) at the point ``at`` of link ``link`` (textbook number) with the
    moment of inertia ``J`` about that point (kg·m²; for the crank about its centre)."""

    link: str
    at: str
    m: float
    J: float


@dataclass(frozen=True, eq=False)
class Inertia:
    """The inertia load of one mass over the positions.

    Attributes
    ----------
    link, at : str
    F_i : complex ndarray (n,)
        −m·a_S, N, at the centre of mass.
    M_i : ndarray (n,)
        −J_S·ε, N·m, counterclockwise +.
    h : ndarray (n,)
        The Russian form: F_i moved parallel to itself by h = |M_i|/|F_i| (m) replaces both (NaN
        where F_i = 0 and M_i ≠ 0: a pure couple; 0 where M_i = 0).
    shifted : complex ndarray (n,)
        The point the moved F_i passes through: S + d with d ⟂ F_i, d × F_i = M_i.
    """

    link: str
    at: str
    F_i: Cx
    M_i: Fl
    h: Fl
    shifted: Cx


def _inertia(link: str, at: str, S: Cx, F: Cx, M: Fl) -> Inertia:
    F2 = np.abs(F) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        d = np.where(M == 0.0, 0j, -1j * F * M / F2)
        h = np.where(M == 0.0, 0.0, np.abs(M) / np.sqrt(F2))
    return Inertia(link, at, F, M, h, S + d)


@dataclass(frozen=True, eq=False)
class ForceAnalysis:
    """The force analysis of a linkage at n positions (SI, counterclockwise +).

    Attributes
    ----------
    motion : Motion
        The kinematics it is built on.
    inertia : tuple of Inertia
        Every mass's inertia force and moment.
    applied : mapping link -> tuple of Force
        Every applied force on each moving link: inertia, weight (``G_k``), working load.
    reactions : mapping key -> Reaction
        ``"R_12"`` ... in every pair (frame = 0), the lower link number first.
    plans : tuple of ForcePlan
        The groups' force plans in the order they are solved (last group first), then the crank's.
    M_balance : ndarray (n,)
        The balancing moment on the crank from the force plans, N·m.
    lever : Lever
        Zhukovsky's lever; ``M_balance_lever`` its balancing moment.
    M_balance_power : ndarray (n,)
        From the power balance.
    gravity : float
        g used, m/s² (0: no weights).
    """

    motion: Any
    inertia: tuple[Inertia, ...]
    applied: Mapping[str, tuple[Force, ...]]
    reactions: Mapping[str, Reaction]
    plans: tuple[ForcePlan, ...]
    M_balance: Fl
    lever: Lever
    M_balance_power: Fl
    gravity: float

    @property
    def M_balance_lever(self) -> Fl:
        return self.lever.M_balance

    @property
    def n(self) -> int:
        return int(self.M_balance.shape[0])

    def difference_percent(self, other: Fl) -> Fl:
        """|M_b − other| / max(|M_b|, |other|) × 100 (0 where both are 0), per cent."""
        den = np.maximum(np.abs(self.M_balance), np.abs(other))
        with np.errstate(divide="ignore", invalid="ignore"):
            out: Fl = np.where(den > 0, 100.0 * np.abs(self.M_balance - other) / den, 0.0)
        return out

    def inertia_of(self, link: str) -> tuple[Cx, Fl]:
        """(Σ F_i, Σ M_i) of the masses of ``link`` (zeros for a massless link)."""
        F: Cx = np.zeros(self.n, dtype=complex)
        M: Fl = np.zeros(self.n)
        for it in self.inertia:
            if it.link == link:
                F = F + it.F_i
                M = M + it.M_i
        return F, M


def _carriers(lk: Any) -> tuple[dict[str, str], dict[str, tuple[str, str]]]:
    """Which link carries each joint (for the revolute pairs of later groups); joints shared by the two
    links of a group (the middle joint C) are ambiguous."""
    one = dict.fromkeys(lk.ground, GROUND)
    one[lk.crank.pin] = lk.crank.link
    two: dict[str, tuple[str, str]] = {}
    for p in lk.points:
        one[p.name] = p.link
    for g in lk.groups:
        if g.kind == "triad":
            for k, b in zip(g.links[1:], g.inner):
                two[b] = (k, g.links[0])
        elif g.kind in ("RPR", "RPP"):
            one[g.coincident] = g.links[1]
            if g.kind == "RPP":
                one[g.R] = g.links[1]
        else:
            two[g.C] = tuple(g.links)
    return one, two


def _rigid_refs(lk: Any) -> dict[str, tuple[str, str | None]]:
    """Two points of each link: one whose velocity is that of the link (for the lever and the
    power) and a second one (None: along the link's own direction, 0.1 m) for a couple's forces."""
    refs: dict[str, tuple[str, str | None]] = {lk.crank.link: (lk.crank.centre, lk.crank.pin)}
    for g in lk.groups:
        if g.kind == "triad":
            refs[g.links[0]] = (g.inner[0], g.inner[1])
            refs.update({k: (p, b) for k, p, b in zip(g.links[1:], g.outer, g.inner)})
            continue
        l2, l3 = g.links
        if g.kind == "RRR":
            refs[l2], refs[l3] = (g.P, g.C), (g.Q, g.C)
        elif g.kind == "RRP":
            refs[l2], refs[l3] = (g.P, g.C), (g.C, None)
        elif g.kind == "RPR":
            refs[l2], refs[l3] = (g.P, g.Q), (g.Q, g.P)
        elif g.kind == "PRP":
            refs[l2], refs[l3] = (g.C, None), (g.C, None)
        else:
            refs[l2], refs[l3] = (g.P, g.R), (g.R, g.P)
    return refs


def _kinematic_scales(motion: Any) -> tuple[Fl, Fl]:
    """The size of the accelerations in each position: the largest |a| of a point (m/s²), and that over the
    crank's length l_OA (rad/s²); an inertia force or moment below :data:`ROUNDOFF` of m or J times them is
    the round-off of a zero acceleration (a slider at its dead centre, a link at its extreme swing)."""
    lk = motion.linkage
    a_max = np.max([np.abs(np.asarray(a, dtype=complex)) for a in motion.a_.values()], axis=0)
    l_OA = np.abs(np.asarray(motion.z[lk.crank.pin]) - np.asarray(motion.z[lk.crank.centre]))
    eps: Fl = a_max / np.where(l_OA > 0, l_OA, 1.0)
    out: Fl = np.asarray(a_max, dtype=float)
    return out, eps


def _balance_roundoff(M_b: Fl, lever: Lever, M_power: Fl, reactions: Mapping[str, Reaction],
                      l_OA: Fl) -> tuple[Fl, Lever, Fl]:
    """M_b from the plans, the lever (with its F_b) and the power balance, each 0 where it is within the
    round-off of its computation: below :data:`ROUNDOFF` times the larger of the position's largest
    reaction times the crank's length l_OA (m) and the largest |M_b| of the cycle. At a dead centre M_b is
    0, and is written 0, never 3.2·10⁻¹⁵ N·m.

    >>> from graphmethods.dynamics.forces.lever import Lever
    >>> lev = Lever((), np.zeros(2, complex), np.array([4e-15j, 300j]), np.array([-5e-16, 30.0]))
    >>> R = {"R_01": reaction("0", "1", "R", np.array([700.0, 700.0j]), np.zeros(2, complex))}
    >>> M_b, lev, M_p = _balance_roundoff(np.array([3e-15, 30.0]), lev, np.array([-5e-16, 30.0]), R, np.full(2, 0.1))
    >>> M_b.tolist(), lev.M_balance.tolist(), lev.F_balance.tolist(), M_p.tolist()
    ([0.0, 30.0], [0.0, 30.0], [0j, 300j], [0.0, 30.0])
    """
    R_max = np.max([np.abs(r.R) for r in reactions.values()], axis=0) if reactions else np.zeros_like(l_OA)
    M_max = max(float(np.max(np.abs(M), initial=0.0)) for M in (M_b, lever.M_balance, M_power))
    scale = np.maximum(R_max * l_OA, M_max)

    def zeroed(M: Fl) -> Fl:
        out: Fl = np.where(np.abs(M) <= ROUNDOFF * scale, 0.0, M)
        return out

    M_l = zeroed(lever.M_balance)
    lever = replace(lever, M_balance=M_l, F_balance=np.where(M_l == 0.0, 0j, lever.F_balance))
    return zeroed(M_b), lever, zeroed(M_power)


def kinetostatics(motion: Any, *, masses: Sequence[Mass], loads: Sequence[tuple[str, Force]] = (),
                  gravity: float = 0.0) -> ForceAnalysis:
    """The force analysis of a solved linkage (see the module docstring).

    Parameters
    ----------
    motion : Motion
        The linkage at its positions, with accelerations (``Linkage.motion``).
    masses : sequence of Mass
        The moving masses.
    loads : sequence of (link, Force)
        The working load (forces at points, couples), N and N·m, per link number.
    gravity : float
        g, m/s², along −y (0: weights left out).

    Raises
    ------
    InputError
        A mass or load on an unknown link or point, a group pinned at a joint shared by two
        links (say which link carries it with an extra point at distance 0), or a position where a
        group's force plan cannot close (its directions parallel).
    """
    lk = motion.linkage
    n = motion.n
    if not (isinstance(gravity, (int, float)) and is_finite(gravity) and gravity >= 0):
        raise InputError(f"gravity must be a finite g ≥ 0 in m/s², got {gravity!r}")
    if lk.crank.pin not in motion.a_:
        raise InputError("the force analysis needs accelerations: solve the motion with level=2")
    links = set(lk.links)
    applied: dict[str, list[Force]] = {k: [] for k in lk.links}
    inertia = []
    a_scale, eps_scale = _kinematic_scales(motion)
    for ms in masses:
        if ms.link not in links:
            raise InputError(f"a mass on link {ms.link!r}: the moving links are {', '.join(lk.links)}")
        if ms.at not in motion.z:
            raise InputError(f"a mass at {ms.at!r}: no such point; points: {', '.join(motion.points)}")
        if not (is_finite(ms.m) and is_finite(ms.J) and ms.m >= 0 and ms.J >= 0):
            raise InputError(f"the mass of link {ms.link}: m = {ms.m!r} kg and J = {ms.J!r} kg·m² must be finite "
                             f"and ≥ 0")
        S: Cx = np.asarray(motion.z[ms.at], dtype=complex)
        F: Cx = np.asarray(-ms.m * np.asarray(motion.a_[ms.at]), dtype=complex)
        M: Fl = np.asarray(-ms.J * np.asarray(motion.epsilon[ms.link]), dtype=float)
        F = np.where(np.abs(F) <= ROUNDOFF * ms.m * a_scale, 0j, F)       # a dead centre's a_S of round-off: 0
        M = np.where(np.abs(M) <= ROUNDOFF * ms.J * eps_scale, 0.0, M)
        inertia.append(_inertia(ms.link, ms.at, S, F, M))
        if ms.m or ms.J:
            applied[ms.link].append(Force(f"F_i{ms.link}", F, S, M))
        if gravity and ms.m:
            applied[ms.link].append(Force(f"G_{ms.link}", np.full(n, -1j * ms.m * gravity, dtype=complex), S,
                                                np.zeros(n)))
    for link, f in loads:
        if link not in links:
            raise InputError(f"a load {f.label} on link {link!r}: the moving links are {', '.join(lk.links)}")
        applied[link].append(f)
    frozen_applied = {k: tuple(v) for k, v in applied.items()}

    # ------------------------------------------------------------------ groups, last to first
    one, two = _carriers(lk)

    def carrier(p: str) -> str:
        if p in one:
            return one[p]
        if p in two:
            a, b = two[p]
            raise InputError(f"{lk.name}: a group is pinned at {p}, the joint of links {a} and {b}; the force "
                             f"analysis needs the link that carries it: add an extra point at distance 0 on that "
                             f"link and pin the group there")
        raise InputError(f"{lk.name}: no link carries the joint {p!r}")

    kin = Kin(z={k: np.asarray(v, dtype=complex) for k, v in motion.z.items()},
              e={k: np.asarray(v, dtype=complex) for k, v in motion._state.e.items()}, n=n)
    loads_now: dict[str, list[Force]] = {k: list(v) for k, v in frozen_applied.items()}
    reactions: dict[str, Reaction] = {}
    plans = []
    for g in reversed(lk.groups):
        res = SOLVERS[g.kind](g, kin, loads_now, carrier)
        for r in res.reactions:
            bad = ~np.isfinite(r.R)
            if bad.any():
                i = int(np.argmax(bad))
                raise InputError(f"{lk.name}: the force plan of group {g.name} does not close at "
                                 f"{motion._state.where(i)}: its two unknown directions are parallel")
            key = r.key if r.key not in reactions else f"{r.key}@{g.name}"
            reactions[key] = r
            for side in (r.by, r.on):
                if side not in g.links and side != GROUND:
                    loads_now[side].append(on_link(r, side))
        plans.append(res.plan)
    # ------------------------------------------------------------------ the crank
    cr = lk.crank
    O = kin.z[cr.centre]
    f1 = loads_now[cr.link]
    R_01 = -resultant(f1, n)
    M_b = -moment_about(f1, O)
    r01 = reaction(GROUND, cr.link, "R", R_01, O)
    reactions[r01.key] = r01
    plans.append(ForcePlan(group=f"I (0, {cr.link})", links=(cr.link,),
                           steps=(f"link {cr.link}: ΣM_{cr.centre} = 0 gives M_b",
                                  f"link {cr.link}: ΣF_{cr.link} + R_0{cr.link} = 0"),
                           first=(), polygons=(Polygon((cr.link,), tuple((f.label, f.F) for f in f1),
                                                       ((r01.key, None, R_01),)),)))
    # ------------------------------------------------------------------ the two checks
    refs = _rigid_refs(lk)
    rigid: dict[str, tuple[Cx, Fl, Cx, Cx]] = {}
    for k, (p, q) in refs.items():
        d = kin.z[q] - kin.z[p] if q is not None else 0.1 * kin.direction(k)
        d = np.where(np.abs(d) > 0, d, 0.1 * kin.direction(k))
        rigid[k] = (kin.z[p], np.broadcast_to(np.asarray(motion.omega[k], dtype=float), (n,)),
                    np.asarray(motion.v_[p], dtype=complex), np.asarray(d, dtype=complex))
    moving = {k: v for k, v in frozen_applied.items() if v}
    lever = zhukovsky(rigid, moving, centre=O, pin=kin.z[cr.pin], omega_1=motion.omega_1, sense=lk.sense)
    M_power = power_balance(rigid, moving, omega_1=motion.omega_1, sense=lk.sense)
    M_b, lever, M_power = _balance_roundoff(M_b, lever, M_power, reactions, np.abs(kin.z[cr.pin] - O))
    return ForceAnalysis(motion=motion, inertia=tuple(inertia), applied=MappingProxyType(frozen_applied),
                         reactions=MappingProxyType(reactions), plans=tuple(plans), M_balance=M_b, lever=lever,
                         M_balance_power=M_power, gravity=float(gravity))
