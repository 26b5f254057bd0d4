"""Force analysis of the RPR dyad (block 2 pinned at P slides in the slot of link 3 turning about Q).

As courses solve it: the block's moments about P give the couple the slot exerts on it; the
moments of link 3 about its pivot Q give the normal force of the block on the slot,
``R_23 ⟂ slot``; then the polygon of link 3 (ΣF_3 + R_23 + R_43 = 0) gives the pivot's reaction
and the block's polygon (ΣF_2 + R_32 + R_12 = 0) the reaction at P.

>>> import numpy as np
>>> from graphmethods.dynamics.forces.base import Force, Kin, xy
>>> from graphmethods.kinematics.groups import RPR
>>> g = RPR(P="A", Q="O3", coincident="A3", links=("2", "3"))
>>> kin = Kin(z={"A": np.array([0.1j]), "O3": np.array([-0.3j]), "A3": np.array([0.1j])},
...           e={"2": np.array([1j]), "3": np.array([1j])}, n=1)
>>> M3 = Force("M_3", F=np.zeros(1, complex), at=np.array([-0.3j]), M=np.array([-20.0]))   # −20 N·m on the lever
>>> res = solve(g, kin, {"3": [M3]}, {"A": "1", "O3": "0"}.__getitem__)
>>> [(r.key, xy(r.R[0])) for r in res.reactions]       # 20 N·m / 0.4 m = 50 N
[('R_12', [-50.0, 0.0]), ('R_23', [-50.0, 0.0]), ('R_03', [50.0, 0.0])]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

from graphmethods.dynamics.forces.base import Force, ForcePlan, GroupForces, Kin, Polygon, dyad_loads, reaction
from graphmethods.dynamics.forces.statics import cross, moment_about
from graphmethods.kinematics.groups import RPR


def solve(g: RPR, kin: Kin, loads: Mapping[str, Sequence[Force]], carrier: Callable[[str], str]) -> GroupForces:
    """Reactions of an RPR group (see the module docstring; parameters as :func:`..rrr.solve`)."""
    d = dyad_loads(g.links, kin, loads)
    l2, l3, f3, F3 = d.l2, d.l3, d.f3, d.F3
    P, Q = kin.z[g.P], kin.z[g.Q]
    a, b = carrier(g.P), carrier(g.Q)
    u = kin.direction(l3)
    nrm = 1j * u
    Mc_32 = d.slot_couple(P)
    # link 3 about Q: M_Q(F_3) + (P − Q) × (−N·n) − Mc_32 = 0
    N = (moment_about(f3, Q) - Mc_32) / cross(P - Q, nrm)
    R_32 = N * nrm
    R_b3 = -(F3 - R_32)
    block = d.block_in_slot(a, g.P, P, R_32, Mc_32, u)
    reactions = (*block.reactions, reaction(b, l3, "R", R_b3, Q))
    tb = f"{b}{l3}"
    plan = ForcePlan(
        group=g.name, links=(l2, l3),
        first=((f"R_{l2}{l3}", -R_32),),
        steps=(block.steps[0],
               f"link {l3}: ΣM_{g.Q} = 0 gives R_{l2}{l3} ⟂ the slot",
               f"link {l3}: ΣF_{l3} + R_{l2}{l3} + R_{tb} = 0",
               block.steps[1]),
        polygons=(Polygon((l3,), (*d.known(f3), (f"R_{l2}{l3}", -R_32)), ((f"R_{tb}", None, R_b3),)), block.polygon))
    return GroupForces(reactions, plan)
