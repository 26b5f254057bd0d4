"""Force analysis of the RRP dyad (rod P–C, slider at C on a guide of the frame or of a link).

As courses solve it: the moments of the rod about C give ``R^τ_12 = −M_C(rod)/|PC|`` ⟂ PC;
the group's force plan ``R^τ_12 + ΣF_2 + ΣF_3 + R_03 + R^n_12 = 0`` closes with R_03 ⟂ the
guide and R^n_12 ∥ PC; the rod's polygon gives R_32; the slider's moments about C place R_03
(its couple, or its line moved by h = M/N along the guide).

>>> import numpy as np
>>> from graphmethods.dynamics.forces.base import Force, Kin, xy
>>> from graphmethods.kinematics.groups import RRP, Guide
>>> g = RRP(P="A", C="B", l=0.5, guide=Guide("0", 0j, 0.0), links=("2", "3"))
>>> kin = Kin(z={"A": np.array([0.3j]), "B": np.array([0.4 + 0j])}, e={"3": np.array([1 + 0j])}, n=1)
>>> push = Force("F", F=np.array([-400 + 0j]), at=np.array([0.4 + 0j]), M=np.zeros(1))   # on the slider
>>> res = solve(g, kin, {"3": [push]}, {"A": "1"}.__getitem__)
>>> [(r.key, xy(r.R[0])) for r in res.reactions]      # N = F·tan β = 400·0.75
[('R_12', [400.0, -300.0]), ('R_03', [0.0, 300.0]), ('R_23', [400.0, -300.0])]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

from graphmethods.dynamics.forces.base import Force, ForcePlan, GroupForces, Kin, Polygon, dyad_loads, reaction
from graphmethods.dynamics.forces.statics import moment_about, solve2, tangential, tangential_step
from graphmethods.kinematics.groups import RRP


def solve(g: RRP, kin: Kin, loads: Mapping[str, Sequence[Force]], carrier: Callable[[str], str]) -> GroupForces:
    """Reactions of an RRP group (see the module docstring; parameters as :func:`..rrr.solve`)."""
    d = dyad_loads(g.links, kin, loads)
    l2, l3, F2 = d.l2, d.l3, d.F2
    P, C = kin.z[g.P], kin.z[g.C]
    a, gl = carrier(g.P), g.guide.link
    u = kin.direction(l3)
    nrm = 1j * u
    u2, Rt2 = tangential(d.f2, P, C)           # the rod's moments about C
    x, N = solve2(u2, nrm, -(Rt2 + F2 + d.F3))
    Rn2, R_g3 = x * u2, N * nrm
    R_a2 = Rt2 + Rn2
    R_32 = -(R_a2 + F2)
    M_g3 = -moment_about(d.f3, C)          # the slider about C: R_23 passes through C
    reactions = (reaction(a, l2, "R", R_a2, P), reaction(gl, l3, "P", R_g3, C, M_g3, u),
                 reaction(l3, l2, "R", R_32, C))
    ta, tg = f"{a}{l2}", f"{gl}{l3}"
    plan = ForcePlan(
        group=g.name, links=(l2, l3),
        steps=(tangential_step(l2, g.C, ta, g.P),
               f"plan: R^τ_{ta} + ΣF_{l2} + ΣF_{l3} + R_{tg} + R^n_{ta} = 0, R_{tg} ⟂ guide, R^n_{ta} ∥ {g.P}{g.C}",
               d.link2_step(ta),
               f"link {l3}: ΣM_{g.C} = 0 gives the line of R_{tg} (h = M/N along the guide)"),
        first=((f"R^τ_{ta}", Rt2),),
        polygons=(
            Polygon((l2, l3), ((f"R^τ_{ta}", Rt2), *d.known(d.f2), *d.known(d.f3)),
                    ((f"R_{tg}", nrm, R_g3), (f"R^n_{ta}", u2, Rn2))),
            d.link2_polygon(ta, R_a2, R_32)))
    return GroupForces(reactions, plan)
