"""Force analysis of the RPP dyad (block 2 pinned at P in the slot of yoke 3, which slides on a guide).

As courses solve it: the block's moments about P give the couple of the slot on it; the yoke's
force plan ``ΣF_3 + R_23 + R_43 = 0`` closes with R_23 ⟂ the slot and R_43 ⟂ the guide; the
yoke's moments give the couple of the guide; the block's polygon gives R_12.

>>> import numpy as np
>>> from graphmethods.dynamics.forces.base import Force, Kin, xy
>>> from graphmethods.kinematics.groups import RPP, Guide
>>> g = RPP(P="A", R="C", coincident="A3", guide=Guide("0", 0j, 0.0), slot_angle=np.pi / 2)
>>> kin = Kin(z={"A": np.array([0.06 + 0.08j]), "C": np.array([0.06 + 0j])},
...           e={"2": np.array([1j]), "3": np.array([1 + 0j])}, n=1)
>>> load = Force("F", F=np.array([-100 + 0j]), at=np.array([0.06 + 0j]), M=np.zeros(1))   # on the yoke
>>> res = solve(g, kin, {"3": [load]}, {"A": "1"}.__getitem__)
>>> [(r.key, xy(r.R[0])) for r in res.reactions]
[('R_12', [100.0, 0.0]), ('R_23', [100.0, 0.0]), ('R_03', [0.0, 0.0])]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

from graphmethods.dynamics.forces.base import Force, ForcePlan, GroupForces, Kin, Polygon, dyad_loads, reaction
from graphmethods.dynamics.forces.statics import cross, moment_about, solve2
from graphmethods.kinematics.groups import RPP


def solve(g: RPP, kin: Kin, loads: Mapping[str, Sequence[Force]], carrier: Callable[[str], str]) -> GroupForces:
    """Reactions of an RPP group (see the module docstring; parameters as :func:`..rrr.solve`)."""
    d = dyad_loads(g.links, kin, loads)
    l2, l3, f3 = d.l2, d.l3, d.f3
    P, Rz = kin.z[g.P], kin.z[g.R]
    a, gl = carrier(g.P), g.guide.link
    u1, u2 = kin.direction(l2), kin.direction(l3)
    n1, n2 = 1j * u1, 1j * u2
    Mc_32 = d.slot_couple(P)
    F3 = d.F3
    # yoke: ΣF_3 − N1·n1 + N2·n2 = 0  (R_23 = −R_32 = −N1·n1)
    N1, N2 = solve2(-n1, n2, -F3)
    R_32, R_g3 = N1 * n1, N2 * n2
    # yoke about R: M_R(F_3) + (P − R) × (−R_32) − Mc_32 + M_g3 = 0
    M_g3 = -(moment_about(f3, Rz) + cross(P - Rz, -R_32) - Mc_32)
    block = d.block_in_slot(a, g.P, P, R_32, Mc_32, u1)
    reactions = (*block.reactions, reaction(gl, l3, "P", R_g3, Rz, M_g3, u2))
    tg = f"{gl}{l3}"
    plan = ForcePlan(
        group=g.name, links=(l2, l3),
        first=(),
        steps=(block.steps[0],
               f"link {l3}: ΣF_{l3} + R_{l2}{l3} + R_{tg} = 0, R_{l2}{l3} ⟂ slot, R_{tg} ⟂ guide",
               f"link {l3}: ΣM_{g.R} = 0 gives the line of R_{tg}",
               block.steps[1]),
        polygons=(Polygon((l3,), d.known(f3), ((f"R_{l2}{l3}", n1, -R_32), (f"R_{tg}", n2, R_g3))), block.polygon))
    return GroupForces(reactions, plan)
