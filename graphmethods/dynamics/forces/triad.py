"""Force analysis of the class III group (triad): its reactions found together.

The triad (:mod:`graphmethods.kinematics.groups.triad`) has a basic link t with the joints B1, B2, B3
and three binary links k_i from the outer joints P_i (on links solved before) to B_i. Unknown are the
outer reactions R_i (the force the carrier of P_i exerts on k_i at P_i): six components. The six
equations of the group's equilibrium:

- each binary link about its inner joint, ``(P_i − B_i) × R_i + M_Bi(ΣF_ki) = 0`` (three), and
- the whole group: ``R_1 + R_2 + R_3 + ΣF = 0`` (two) and its moments about B1 (one),

solved together as one 6×6 system at every position (unlike a dyad's, they do not split: this is what
Assur's special points do graphically). Each binary link's polygon then gives the inner reaction
``R_ti = −(R_i + ΣF_ki)`` that the basic link exerts on k_i at B_i.

>>> import numpy as np
>>> from graphmethods.dynamics.forces.base import Force, Kin, xy
>>> from graphmethods.kinematics.groups import Triad
>>> z = {"P1": 0j, "P2": 3 + 0j, "P3": 1.2 + 3j, "B1": 1 + 1j, "B2": 2 + 1j, "B3": 1.5 + 2j}
>>> g = Triad(outer=("P1", "P2", "P3"), inner=("B1", "B2", "B3"), drawn=tuple(z.items()), links=("3", "2", "4", "5"))
>>> kin = Kin(z={k: np.array([v]) for k, v in z.items()}, e={}, n=1)
>>> w = Force("G_3", F=np.array([-10j]), at=np.array([1.5 + 4 / 3 * 1j]), M=np.zeros(1))
>>> res = solve(g, kin, {"3": [w]}, lambda p: "0")
>>> total = sum(r.R[0] for r in res.reactions if r.by == "0")     # the frame holds the weight
>>> xy(total)
[0.0, 10.0]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

import numpy as np

from graphmethods.dynamics.forces.base import Force, ForcePlan, GroupForces, Kin, Polygon, on_link, reaction, resultant
from graphmethods.dynamics.forces.statics import Cx, moment_about
from graphmethods.errors import InputError
from graphmethods.kinematics.groups import Triad


def solve(g: Triad, kin: Kin, loads: Mapping[str, Sequence[Force]], carrier: Callable[[str], str]) -> GroupForces:
    """Reactions of a triad (see the module docstring; parameters as :func:`..rrr.solve`, loads on its four links)."""
    n = kin.n
    t, ks = g.links[0], g.links[1:]
    P = [np.broadcast_to(kin.z[p], (n,)) for p in g.outer]
    B = [np.broadcast_to(kin.z[b], (n,)) for b in g.inner]
    f = {k: list(loads.get(k, ())) for k in g.links}
    F = {k: resultant(f[k], n) for k in g.links}
    every = [x for k in g.links for x in f[k]]
    A = np.zeros((n, 6, 6))
    rhs = np.zeros((n, 6))
    for i in range(3):
        d = P[i] - B[i]                          # ΣM_Bi of link k_i: d × R_i = d.x R_y − d.y R_x
        A[:, i, 2 * i], A[:, i, 2 * i + 1] = -d.imag, d.real
        rhs[:, i] = -moment_about(f[ks[i]], B[i])
        A[:, 3, 2 * i] = 1.0                     # ΣF_x of the group
        A[:, 4, 2 * i + 1] = 1.0                 # ΣF_y
        r = P[i] - B[0]                          # ΣM_B1 of the group
        A[:, 5, 2 * i], A[:, 5, 2 * i + 1] = -r.imag, r.real
    total = resultant(every, n)
    rhs[:, 3], rhs[:, 4] = -total.real, -total.imag
    rhs[:, 5] = -moment_about(every, B[0])
    det = np.linalg.det(A)
    scale = np.max(np.abs(A), axis=(1, 2)) ** 6
    bad = ~(np.abs(det) > 1e-12 * scale)
    if bad.any():
        raise InputError(f"group {g.name}: its force analysis has no solution at position #{int(np.argmax(bad))}: "
                         f"the lines of its binary links meet in one point (a dead position)")
    x = np.linalg.solve(A, rhs[..., None])[..., 0]
    R = [x[:, 2 * i] + 1j * x[:, 2 * i + 1] for i in range(3)]
    R_in: list[Cx] = [-(R[i] + F[ks[i]]) for i in range(3)]        # of t on k_i at B_i
    reactions = tuple(reaction(carrier(p), k, "R", Ri, Pi) for p, k, Ri, Pi in zip(g.outer, ks, R, P)) + \
        tuple(reaction(t, k, "R", Ri, Bi) for k, Ri, Bi in zip(ks, R_in, B))
    outer = [f"R_{carrier(p)}{k}" for p, k in zip(g.outer, ks)]
    known = tuple((x_.label, x_.F) for x_ in every)
    plan = ForcePlan(
        group=g.name, links=tuple(g.links),
        steps=(*(f"link {k}: ΣM_{b} = 0" for k, b in zip(ks, g.inner)),
               f"group: ΣF = 0, ΣM_{g.inner[0]} = 0; with the three above six equations for "
               f"{', '.join(outer)} solved together",
               *(f"link {k}: {o} + ΣF_{k} + R_{t}{k} = 0" for k, o in zip(ks, outer))),
        first=(),
        polygons=(Polygon(tuple(g.links), known, tuple((o, None, Ri) for o, Ri in zip(outer, R))),
                  *(Polygon((k,), ((o, Ri), *((x_.label, x_.F) for x_ in f[k])), ((f"R_{t}{k}", None, Rk),))
                    for k, o, Ri, Rk in zip(ks, outer, R, R_in))))
    return GroupForces(reactions, plan)


__all__ = ["on_link", "solve"]
