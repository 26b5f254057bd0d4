"""Force analysis of the PRP dyad (two sliders pinned at C, each on its own guide).

As courses solve it: the group's force plan ``ΣF_2 + ΣF_3 + R_12 + R_43 = 0`` closes with the
two normal forces, each ⟂ its guide; the polygon of slider 2 gives R_32; each slider's moments
about C give the couple of its guide (the normal force's line moved by h = M/N).

>>> import numpy as np
>>> from graphmethods.dynamics.forces.base import Force, Kin, xy
>>> from graphmethods.kinematics.groups import PRP, Guide
>>> g = PRP(C="C", guide_1=Guide("0", 0j, 0.0), guide_2=Guide("0", 0j, np.pi / 2), links=("2", "3"))
>>> kin = Kin(z={"C": np.array([0j])}, e={"2": np.array([1 + 0j]), "3": np.array([1j])}, n=1)
>>> w = Force("F", F=np.array([3 + 4j]), at=np.array([0j]), M=np.zeros(1))
>>> res = solve(g, kin, {"2": [w]}, {}.__getitem__)
>>> [(r.key, xy(r.R[0])) for r in res.reactions]
[('R_02', [0.0, -4.0]), ('R_03', [-3.0, 0.0]), ('R_23', [3.0, 0.0])]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

from graphmethods.dynamics.forces.base import Force, ForcePlan, GroupForces, Kin, Polygon, dyad_loads, reaction
from graphmethods.dynamics.forces.statics import moment_about, solve2
from graphmethods.kinematics.groups import PRP


def solve(g: PRP, kin: Kin, loads: Mapping[str, Sequence[Force]], carrier: Callable[[str], str]) -> GroupForces:
    """Reactions of a PRP group (see the module docstring; parameters as :func:`..rrr.solve`)."""
    d = dyad_loads(g.links, kin, loads)
    l2, l3, F2 = d.l2, d.l3, d.F2
    C = kin.z[g.C]
    g1, g2 = g.guide_1.link, g.guide_2.link
    u1, u2 = kin.direction(l2), kin.direction(l3)
    n1, n2 = 1j * u1, 1j * u2
    N1, N2 = solve2(n1, n2, -(F2 + d.F3))
    R_12, R_43 = N1 * n1, N2 * n2
    R_32 = -(R_12 + F2)
    reactions = (reaction(g1, l2, "P", R_12, C, -moment_about(d.f2, C), u1),
                 reaction(g2, l3, "P", R_43, C, -moment_about(d.f3, C), u2),
                 reaction(l3, l2, "R", R_32, C))
    t1, t2 = f"{g1}{l2}", f"{g2}{l3}"
    plan = ForcePlan(
        group=g.name, links=(l2, l3),
        steps=(f"plan: ΣF_{l2} + ΣF_{l3} + R_{t2} + R_{t1} = 0, each ⟂ its guide",
               d.link2_step(t1),
               f"links {l2}, {l3}: ΣM_{g.C} = 0 gives the lines of R_{t1} and R_{t2}"),
        first=(),
        polygons=(
            Polygon((l2, l3), (*d.known(d.f2), *d.known(d.f3)), ((f"R_{t2}", n2, R_43), (f"R_{t1}", n1, R_12))),
            d.link2_polygon(t1, R_12, R_32)))
    return GroupForces(reactions, plan)
