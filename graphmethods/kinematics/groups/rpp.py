"""The RPP dyad: a block pinned at a known point P slides in a slot of a link that slides on a guide.

The Scotch yoke and the sine mechanism (кулисный механизм с поступательной кулисой, 正弦机构):
link ``links[0]`` is the block pinned at P, link ``links[1]`` the slotted slider (the yoke) that
moves along ``guide`` (on the frame or on a moving link, whose turning it shares). The yoke's
reference point R (named ``R``: the ram's joint) lies on the guide; its slot passes through R
(or at the signed offset ``e`` from it, to the left of the slot's direction) at the angle
``slot_angle`` from the guide. ``coincident`` names the yoke's point under P (A3).
No assembly branch: P fixes the yoke's place along the guide (unless slot ∥ guide).

Velocities: ``v_A3 = v_A2 + v_A3A2`` (∥ slot) with ``v_A3 = v_R`` + rotation, v_R ∥ the guide.
Accelerations: ``a_A3 = a_A2 + a^k_A3A2 + a^r_A3A2`` and a_R along the guide (+ Coriolis on a
moving guide).

>>> import numpy as np
>>> from graphmethods.kinematics.groups.base import Guide, State
>>> st = State(phi=np.zeros(1))
>>> st.z["A"] = np.array([0.06 + 0.08j]); st.v["A"] = np.array([-8.0 + 6j])
>>> g = RPP(P="A", R="C", coincident="A3", guide=Guide("0", 0j, 0.0), slot_angle=np.pi / 2)
>>> g.positions(st); g.velocities(st); complex(st.v["C"][0])
(-8+0j)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphmethods.kinematics.groups.base import (
    Group,
    Guide,
    Joints,
    Pair,
    Real,
    Record,
    State,
    Vec,
    broadcast,
    cross,
    solve2,
)
from graphmethods.kinematics.vectors import FloatArray


@dataclass(frozen=True, eq=False)
class RPP(Group):
    """RPP dyad (see the module docstring).

    Parameters
    ----------
    P : str
        The known joint of the block.
    R : str
        The yoke's reference point on the guide (found).
    coincident : str
        Name of the yoke's point under P.
    guide : Guide
        The guide the yoke slides along.
    slot_angle : float
        Angle of the slot from the guide, rad (π/2 for a Scotch yoke).
    e : float
        Signed offset of the slot from R, m.
    links : (str, str)
        Textbook numbers of the block and the yoke.
    """

    P: str
    R: str
    coincident: str
    guide: Guide
    slot_angle: float = np.pi / 2
    e: float = 0.0
    links: tuple[str, str] = ("2", "3")

    kind = "RPP"

    def __post_init__(self) -> None:
        self._check("e", "offset e of the slot", positive=False)

    @property
    def pairs(self) -> tuple[Pair, ...]:
        return (("R", "?", self.links[0], self.P), ("P", self.links[0], self.links[1], self.P),
                ("P", self.guide.link, self.links[1], self.R))

    def joints(self) -> Joints:
        return Joints(known=(self.P,), found=(self.R, self.coincident), guides=(self.guide,))

    def _lines(self, st: State) -> tuple[Vec, Vec, Vec, Real, Real]:
        G, u2, w, e = self.guide.line(st)
        u1 = u2 * complex(np.cos(self.slot_angle), np.sin(self.slot_angle))
        return G, u2, u1, w, e

    def margin(self, st: State) -> FloatArray:
        return np.full(st.n, np.sin(self.slot_angle) ** 2)

    def positions(self, st: State) -> None:
        G, u2, u1, _, _ = self._lines(st)
        # P = G + s2·u2 + (s1 + i·e)·u1
        s1, s2, det = solve2(u1, u2, st.z[self.P] - G - 1j * self.e * u1)
        self.fail(st, np.abs(det) <= 1e-15, lambda i: f"the slot of link {self.links[1]} is parallel to its guide")
        st.z[self.R] = G + s2 * u2
        st.z[self.coincident] = st.z[self.P]
        st.relative[self._name()] = {"s1": s1, "s2": s2}
        n = (st.n,)
        st.e[self.links[1]] = np.broadcast_to(u2, n)
        st.e[self.links[0]] = np.broadcast_to(u1, n)

    def velocities(self, st: State) -> None:
        G, u2, u1, w, _ = self._lines(st)
        vG, _ = self.guide.kinematics(st)
        rel = st.relative[self._name()]
        P = st.z[self.P]
        sd1, sd2, det = solve2(u1, u2, st.v[self.P] - vG - 1j * w * (P - G))
        self.check_det(st, det, f"the slot of link {self.links[1]} is parallel to its guide")
        n = (st.n,)
        st.conditioning[self._name()] = np.broadcast_to(np.abs(det), n)
        st.v[self.R] = vG + 1j * w * (st.z[self.R] - G) + sd2 * u2
        st.v[self.coincident] = st.v[self.P] - sd1 * u1
        st.omega[self.links[0]] = np.broadcast_to(w, n)
        st.omega[self.links[1]] = np.broadcast_to(w, n)
        rel.update({"s1_dot": sd1, "s2_dot": sd2, "v_rel": -sd1 * u1, "v_guide": vG + 1j * w * (st.z[self.R] - G)})

    def accelerations(self, st: State) -> None:
        G, u2, u1, w, e = self._lines(st)
        _, aG = self.guide.kinematics(st)
        rel = st.relative[self._name()]
        P = st.z[self.P]
        sd1, sd2 = rel["s1_dot"], rel["s2_dot"]
        rhs = st.a[self.P] - aG - (1j * e - w * w) * (P - G) - 2j * w * (sd1 * u1 + sd2 * u2)
        sdd1, sdd2, _ = solve2(u1, u2, rhs)
        rR = st.z[self.R] - G
        a_guide = aG + (1j * e - w * w) * rR
        st.a[self.R] = a_guide + 2j * w * sd2 * u2 + sdd2 * u2
        k = 2j * w * sd1 * u1
        st.a[self.coincident] = st.a[self.P] - k - sdd1 * u1
        st.epsilon[self.links[0]] = np.broadcast_to(e, (st.n,))
        st.epsilon[self.links[1]] = np.broadcast_to(e, (st.n,))
        rel.update({"s1_ddot": sdd1, "s2_ddot": sdd2, "a_rel": -sdd1 * u1, "a_coriolis": -k, "a_guide": a_guide,
                    "a_coriolis_guide": 2j * w * sd2 * u2})

    def records(self, st: State) -> tuple[Record, ...]:
        P, R, A3 = self.P, self.R, self.coincident
        _, u2, u1, _, _ = self._lines(st)
        n = (st.n,)
        u2, u1 = np.broadcast_to(u2, n), np.broadcast_to(u1, n)
        rel = broadcast(st, st.relative[self._name()])
        s = cross(u1, u2)
        out = [Record(point=A3, plan="velocity", equation=f"v_{A3} = v_{P} + v_{A3}{P} = v_{R}",
                      known=((f"v_{P}", st.v[P]), (f"v_{R}(guide)", rel["v_guide"])),
                      lines=(("∥ slot", st.v[P], u1), ("∥ guide", rel["v_guide"], u2)), meet=st.v[A3],
                      sin_between=s)]
        if "a_rel" in rel:
            b2 = rel["a_guide"] + rel["a_coriolis_guide"]
            out.append(Record(point=A3, plan="acceleration",
                              equation=f"a_{A3} = a_{P} + a^k_{A3}{P} + a^r_{A3}{P}",
                              known=((f"a_{P}", st.a[P]), (f"a^k_{A3}{P}", rel["a_coriolis"]),
                                     (f"a_{R}(guide)", rel["a_guide"])),
                              lines=(("∥ slot", st.a[P] + rel["a_coriolis"], u1), ("∥ guide", b2, u2)),
                              meet=st.a[A3], sin_between=s))
        return tuple(out)
