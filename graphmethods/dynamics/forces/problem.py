"""The force analysis of a problem file: its masses and its working load at the positions asked for.

The working load is the file's: a force on the output slider along its guide, against the
slider's motion on the working stroke between the file's stroke fractions (a force diagram:
its force on each stroke, resisting or driving); a moment on the output rocker against its
working swing. Weights (``gravity=True``) act along −y of the file's frame, g = 9.81 m/s².

>>> from graphmethods.problems import builtin
>>> fa = case_forces(builtin.case("press"), phi_deg=[90.0])
>>> sorted(fa.reactions)
['R_01', 'R_03', 'R_12', 'R_23']
>>> abs(float(fa.M_balance[0] - fa.M_balance_lever[0])) < 1e-9 * abs(float(fa.M_balance[0]))
True
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from graphmethods.dynamics.forces.analysis import G_STANDARD, ForceAnalysis, Mass, kinetostatics
from graphmethods.dynamics.forces.base import Force
from graphmethods.dynamics.reduction import _diagrams, load_active
from graphmethods.errors import InputError


def link_number(case: Any, link: str | None, point: str) -> str:
    """The textbook number of a problem's link given by name (``"AB"``, ``"block"``) or number, or —
    for a translating mass (``link`` None) — of the slider at ``point``."""
    lk = case.linkage
    if link is not None and str(link) in lk.links:
        return str(link)
    names = {str(v): str(k) for k, v in getattr(case.mechanism, "link_numbers", {}).items()}
    if link is not None and str(link) in names:
        return names[str(link)]
    if link is None:
        for g in lk.groups:
            if g.kind == "RRP" and g.C == point:
                return str(g.links[1])
            if g.kind == "RPP" and g.R == point:
                return str(g.links[1])
            if g.kind == "PRP" and g.C == point:
                return str(g.links[0] if g.guide_1.link == "0" else g.links[1])
    raise InputError(f"{case.source}: cannot tell which link {link or point!r} is; links: {', '.join(lk.links)}")


def working_load(case: Any, motion: Any, positions: Any) -> list[tuple[str, Force]]:
    """The file's working load at the motion's positions as (link, Force)."""
    lk = motion.linkage
    load = case.load
    n = motion.n
    strokes = lk.strokes()
    if strokes is None:
        raise InputError(f"{case.source}: the output has no strokes, so the working load cannot be placed")
    ends = lk.solve(np.array([strokes.phi_start, strokes.phi_end]), level=0)
    if load.kind == "moment":
        link = link_number(case, load.at, "")
        th = ends.theta[link]
        swing = float(np.mod(th[1] - th[0] + math.pi, 2 * math.pi) - math.pi)
        M = np.where(load_active(positions, load), -math.copysign(load.magnitude, swing), 0.0)
        where = lk.pivots.get(link, lk.crank.centre)     # a couple: drawn at the rocker's pivot
        at = np.asarray(motion.z[where], dtype=complex)
        return [(link, Force(f"M_c{link}", np.zeros(n, dtype=complex), at, M))]
    point = load.at
    link = link_number(case, None, point)
    zs, ze = ends.z[point]
    w = (ze - zs) / abs(ze - zs)                     # the slider's motion on the working stroke
    if load.kind == "force":
        F = np.where(load_active(positions, load), -load.magnitude * w, 0j)
    else:
        F = np.zeros(n, dtype=complex)
        frac = positions.s / positions.H
        for d in _diagrams(load):
            if d.stroke == "working":
                on = positions.working
                motion_dir = w
            else:
                on = ~positions.working | positions.extreme
                motion_dir = -w
            mag = np.where(on, d.value(frac), 0.0)
            F = F + (-1.0 if d.opposes else 1.0) * mag * motion_dir
    at = np.asarray(motion.z[point], dtype=complex)
    return [(link, Force(f"F_c{link}", np.asarray(F, dtype=complex), at, np.zeros(n)))]


def drawn_loads(info: Any, motion: Any) -> list[tuple[str, Force]]:
    """The constant loads of a drawn file (:class:`graphmethods.kinematics.drawn.DrawnLoad`) as (link, Force):
    a force at its point of the link, or a moment (drawn at a point of the link)."""
    n = motion.n
    out = []
    for i, ld in enumerate(info.loads):
        at = np.asarray(motion.z[ld.at or motion.linkage.crank.centre], dtype=complex)
        if ld.kind == "force":
            out.append((ld.link, Force(f"F_e{i + 1}", np.full(n, ld.F, dtype=complex), at, np.zeros(n))))
        else:
            out.append((ld.link, Force(f"M_e{i + 1}", np.zeros(n, dtype=complex), at, np.full(n, ld.M))))
    return out


def case_forces(case: Any, *, phi_deg: Sequence[float] | None = None, m: int | None = None,
                omega_1: float | None = None, epsilon_1: float = 0.0, gravity: bool = False) -> ForceAnalysis:
    """The force analysis of a problem file at crank angles ``phi_deg`` (degrees from +x) or at the
    positions 0…m, at ``omega_1`` (rad/s; default the file's mean speed) and ``epsilon_1`` (rad/s²)."""
    lk = case.linkage
    w1 = case.omega_m if omega_1 is None else float(omega_1)
    if phi_deg is not None:
        phi = np.radians(np.asarray(phi_deg, dtype=float))
        motion = lk.motion(phi=phi, omega_1=w1, epsilon_1=epsilon_1)
        positions = case.mechanism.positions(phi=phi)
    else:
        motion = lk.motion(m=m, omega_1=w1, epsilon_1=epsilon_1)
        positions = case.mechanism.positions(m=12 if m is None else m)
    masses = [Mass(link_number(case, it.link, it.point), it.point, float(it.m), float(it.J))
              for it in case.inertias]
    info = getattr(case, "drawn", None)
    loads = working_load(case, motion, positions) if info is None or "load" in case.__dict__ else []
    if info is not None:
        loads += drawn_loads(info, motion)
    return kinetostatics(motion, masses=masses, loads=loads, gravity=G_STANDARD if gravity else 0.0)
