"""A problem turned into the machine that :func:`graphmethods.dynamics.regimes.run` moves.

A cycle problem given by moment curves (W3, W4) or a linkage problem file (the press, the four-bar,
the slotted lever, the shaper) becomes its reduced model: J_e(φ), the resisting moment −M_r(φ) as
the position-dependent part, and the problem's own drive, a constant M_d from the work balance
(replaced by a motor on request). A problem given only as areas or works (W1, W2, the W4 drawing)
has no M(φ) between its boundaries and cannot be moved in time.

Linkages are tabulated once, vectorised, at 3600 positions: J_e as a periodic cubic spline (its
derivative from the spline), M_r piecewise linear with its jumps (the load switching on and off)
placed exactly at the switch angles; so each step of the integrator costs a table look-up.

>>> m = machine("W4")
>>> m.name, m.M_d, m.J_F, m.omega_0, float(m.model.J_e_at(1.0))
('W4-exact', 20.0, 0.0, 10.0, 0.8)
"""

from __future__ import annotations

import math
import pathlib
from dataclasses import dataclass

import numpy as np

from graphmethods.dynamics.moments import MomentCurve
from graphmethods.dynamics.motion import ReducedModel
from graphmethods.errors import InputError
from graphmethods.problems.builtin import DATA, LINKAGES

TWO_PI = 2.0 * math.pi
#: Positions a linkage is tabulated at.
TABLE_POSITIONS = 3600


@dataclass(frozen=True, eq=False)
class Machine:
    """A problem as a machine to move.

    Attributes
    ----------
    name : str
    model : ReducedModel
        J_e(φ) and the position-dependent moment (−M_r, or M_d − M_r when M_d is a curve).
    M_d : float or None
        The constant driving moment of the problem (N·m), None when it is part of ``model``.
    J_F : float
        The problem's flywheel, kg·m² (its J_F for [δ] when it states n and [δ], else 0).
    omega_0 : float or None
        The problem's own starting speed, rad/s (W4), if any.
    omega_m : float or None
        Its mean speed, rad/s, if stated.
    problem : CycleProblem or None
        The cycle problem it was made from (None for a linkage).
    """

    name: str
    model: ReducedModel
    M_d: float | None
    J_F: float
    omega_0: float | None
    omega_m: float | None
    problem: object = None


def _cycle_machine(p, J_F_given: float | None = None) -> Machine:
    if p.M_d is None and p.M_r is None:
        raise InputError(f"problem {p.id} is given as areas or works, not as moments of φ, so its motion in time "
                         f"is not defined between the boundaries; use W3, W4 or a problem with moment curves")
    ew = p.excess_work
    M_d, M_r = ew.M_d, ew.M_r
    const = bool(np.all(M_d.M == M_d.M[0]))
    if const:
        part, Md = -M_r, float(M_d.M[0])
    else:
        part, Md = M_d - M_r, None
    breaks = tuple(float(x) for x in np.unique(part.phi[:-1]))      # knots, with the period's start
    model = ReducedModel(J_e=float(p.J_e), M_e=lambda x: part(x), phi_T=part.period, phi_0=part.start,
                         breaks=breaks)
    J_F = 0.0 if J_F_given is None else J_F_given
    omega_m = None
    if p.n_rpm is not None:
        omega_m = math.pi * p.n_rpm / 30.0
        if p.delta is not None and J_F_given is None:
            J_F = max(p.flywheel().J_F, 0.0)
    return Machine(p.id, model, Md, J_F, p.omega_0, omega_m, p)


def _linkage_machine(case, name: str, J_F_given: float | None = None) -> Machine:
    from graphmethods.dynamics.study import Study
    from graphmethods.errors import NoFlywheelNeeded
    from graphmethods.kinematics.drawn import require_cycle

    require_cycle(case, "the motion")
    study = Study(case, positions=12, estimate=False)
    m = TABLE_POSITIONS
    phi = TWO_PI * np.arange(m + 1) / m
    J = np.array(study._J_e_exact(phi), dtype=float)
    J[-1] = J[0]
    spline = ReducedModel.from_samples(J_e=J, M_e=0.0, interpolation="cubic")
    switches = [float(s) for s in study.switch_angles if 0 < s < TWO_PI]
    keep = np.ones(phi.size, dtype=bool)
    for s in switches:
        keep &= np.abs(phi - s) > 1e-9
    knots: list[tuple[float, float, float]] = [(float(a), float(b), 0.0) for a, b in
                                               zip(phi[keep], study._M_r_exact(phi[keep]))]
    for s in switches:
        left, right = study._M_r_exact(np.array([s - 1e-11, s + 1e-11]))
        knots += [(s, float(left), 0.0), (s, float(right), 1.0)]
    knots.sort(key=lambda k: (k[0], k[2]))
    M_r = MomentCurve(np.array([k[0] for k in knots]), np.array([k[1] for k in knots]))
    model = ReducedModel(J_e=spline.J_e, dJ_e=spline.dJ_e, M_e=lambda x: -M_r(x), breaks=tuple(switches))
    if J_F_given is not None:              # honoured as given: the problem's own J_F is not computed
        J_F = J_F_given
    else:
        try:
            J_F = study.exact.J_F
        except NoFlywheelNeeded:           # its own inertia keeps δ within [δ]: no flywheel
            J_F = 0.0
    return Machine(name, model, float(study.M_d), float(J_F), None, float(case.omega_m))


def machine(spec, *, J_F: float | None = None) -> Machine:
    """The machine of a built-in problem name (W1–W4, W4-exact and the linkages of
    :data:`graphmethods.problems.builtin.LINKAGES`) or of a linkage problem file (JSON).

    ``J_F`` (kg·m²), when given, is the flywheel as is: the problem's own J_F for [δ] is then not
    computed (nor refused when no flywheel is needed)."""
    from graphmethods import problems

    text = str(spec).strip()
    low = text.lower()
    cycles = {"w1": problems.w1, "w2": problems.w2, "w3": problems.w3, "w4": problems.w4_exact,
              "w4-exact": problems.w4_exact, "w4-drawing": problems.w4_drawing}
    if low in cycles:
        return _cycle_machine(cycles[low](), J_F)
    from graphmethods.kinematics import read_case

    if text == "-":                        # the problem file on standard input
        from graphmethods.problems.builtin import read_stdin_case

        return _linkage_machine(read_stdin_case(), "stdin", J_F)
    if low in LINKAGES:
        return _linkage_machine(read_case(DATA / LINKAGES[low]), low, J_F)
    p = pathlib.Path(text)
    if not p.exists() and low.startswith("drawn"):
        from graphmethods.problems.builtin import case_path

        p = case_path(low)                       # the drawn form's worked files and drawn/NAME
    if not p.exists():
        names = ", ".join(["W1", "W2", "W3", "W4", "W4-exact"] + list(LINKAGES))
        raise InputError(f"{text!r}: not a built-in problem ({names}) and no such file")
    return _linkage_machine(read_case(p), p.stem, J_F)
