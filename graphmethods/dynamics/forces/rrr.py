"""Force analysis of the RRR dyad (links P–C and Q–C pinned at C; P, Q on links solved before).

As courses solve it: the moments of link 2 (P–C) about C give the tangential part of R_12 at P,
``R^τ_12 = −M_C(link 2)/|PC|`` ⟂ PC (the normal part passes through C), and likewise link 3
gives R^τ_43 at Q; then the group's force plan
``R^τ_12 + ΣF_2 + ΣF_3 + R^τ_43 + R^n_43 + R^n_12 = 0`` closes with the two normal parts along
PC and QC; the polygon of link 2 alone gives the inner reaction R_32.

>>> import numpy as np
>>> from graphmethods.dynamics.forces.base import Force, Kin, xy
>>> from graphmethods.kinematics.groups import RRR
>>> g = RRR(P="A", Q="D", C="C", l_PC=2 ** 0.5, l_QC=2 ** 0.5, links=("2", "3"))
>>> kin = Kin(z={"A": np.array([0j]), "D": np.array([2 + 0j]), "C": np.array([1 + 1j])}, e={}, n=1)
>>> load = Force("F", F=np.array([-10j]), at=np.array([1 + 1j]), M=np.zeros(1))   # 10 N down at C
>>> res = solve(g, kin, {"2": [], "3": [load]}, {"A": "1", "D": "0"}.__getitem__)
>>> [(r.key, xy(r.R[0])) for r in res.reactions]     # two struts in compression
[('R_12', [5.0, 5.0]), ('R_03', [-5.0, 5.0]), ('R_23', [5.0, 5.0])]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

from graphmethods.dynamics.forces.base import Force, ForcePlan, GroupForces, Kin, Polygon, dyad_loads, on_link, reaction
from graphmethods.dynamics.forces.statics import solve2, tangential, tangential_step
from graphmethods.kinematics.groups import RRR


def solve(g: RRR, kin: Kin, loads: Mapping[str, Sequence[Force]], carrier: Callable[[str], str]) -> GroupForces:
    """Reactions of an RRR group (see the module docstring).

    Parameters
    ----------
    g : RRR
        The group.
    kin : Kin
        Positions of its points, m.
    loads : mapping link -> forces
        Every force on its two links (inertia, weight, load, reactions of later groups), N.
    carrier : callable
        The link that carries a known joint (``carrier("A") == "1"``).
    """
    d = dyad_loads(g.links, kin, loads)
    l2, l3, F2 = d.l2, d.l3, d.F2
    P, Q, C = kin.z[g.P], kin.z[g.Q], kin.z[g.C]
    a, b = carrier(g.P), carrier(g.Q)
    u2, Rt2 = tangential(d.f2, P, C)           # moments about C
    u3, Rt3 = tangential(d.f3, Q, C)
    x, y = solve2(u2, u3, -(Rt2 + F2 + d.F3 + Rt3))
    Rn2, Rn3 = x * u2, y * u3
    R_a2 = Rt2 + Rn2
    R_b3 = Rt3 + Rn3
    R_32 = -(R_a2 + F2)
    reactions = (reaction(a, l2, "R", R_a2, P), reaction(b, l3, "R", R_b3, Q), reaction(l3, l2, "R", R_32, C))
    ta, tb = f"{a}{l2}", f"{b}{l3}"
    plan = ForcePlan(
        group=g.name, links=(l2, l3),
        steps=(tangential_step(l2, g.C, ta, g.P),
               tangential_step(l3, g.C, tb, g.Q),
               f"plan: R^τ_{ta} + ΣF_{l2} + ΣF_{l3} + R^τ_{tb} + R^n_{tb} + R^n_{ta} = 0, R^n ∥ the links",
               d.link2_step(ta)),
        first=((f"R^τ_{ta}", Rt2), (f"R^τ_{tb}", Rt3)),
        polygons=(
            Polygon((l2, l3), ((f"R^τ_{ta}", Rt2), *d.known(d.f2), *d.known(d.f3), (f"R^τ_{tb}", Rt3)),
                    ((f"R^n_{tb}", u3, Rn3), (f"R^n_{ta}", u2, Rn2))),
            d.link2_polygon(ta, R_a2, R_32)))
    return GroupForces(reactions, plan)


__all__ = ["on_link", "solve"]
