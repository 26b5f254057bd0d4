"""The PRP dyad: two sliders pinned together at C, each moving along its own guide.

Link ``links[0]`` slides along ``guide_1`` and link ``links[1]`` along ``guide_2`` (each guide
on the frame or on a moving link, whose turning the slider shares); they are pinned at C, which
therefore lies on both guide lines. There is no assembly branch: C is where the lines cross.

Velocities, as the plan is drawn: ``v_C = v_C1 + v_rel1 = v_C2 + v_rel2``, each relative
velocity along its guide (v_C1, v_C2: the guides' points under C). Accelerations:
``a_C = a_C1 + a^k_1 + a^r_1 = a_C2 + a^k_2 + a^r_2`` with the Coriolis terms 2·ω_guide × v_rel.

>>> import numpy as np
>>> from graphmethods.kinematics.groups.base import Guide, State
>>> st = State(phi=np.zeros(1))
>>> g = PRP(C="C", guide_1=Guide("0", 0j, 0.0), guide_2=Guide("0", 1j, np.pi / 4), links=("2", "3"))
>>> g.positions(st); complex(np.round(st.z["C"][0], 12))
(-1+0j)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphmethods.kinematics.groups.base import Group, Guide, Joints, Pair, Record, State, broadcast, cross, solve2
from graphmethods.kinematics.vectors import FloatArray


@dataclass(frozen=True, eq=False)
class PRP(Group):
    """PRP dyad (see the module docstring).

    Parameters
    ----------
    C : str
        The joint of the two sliders (found).
    guide_1, guide_2 : Guide
        The guides of the first and the second slider.
    links : (str, str)
        Textbook numbers of the two sliders.
    """

    C: str
    guide_1: Guide
    guide_2: Guide
    links: tuple[str, str] = ("2", "3")

    kind = "PRP"

    @property
    def pairs(self) -> tuple[Pair, ...]:
        return (("P", self.guide_1.link, self.links[0], self.C), ("R", self.links[0], self.links[1], self.C),
                ("P", self.guide_2.link, self.links[1], self.C))

    def joints(self) -> Joints:
        return Joints(found=(self.C,), guides=(self.guide_1, self.guide_2))

    def margin(self, st: State) -> FloatArray:
        _, u1, _, _ = self.guide_1.line(st)
        _, u2, _, _ = self.guide_2.line(st)
        return cross(u1, u2) ** 2

    def positions(self, st: State) -> None:
        G1, u1, _, _ = self.guide_1.line(st)
        G2, u2, _, _ = self.guide_2.line(st)
        s1, s2, det = solve2(u1, -u2, G2 - G1)
        n = (st.n,)
        bad = np.broadcast_to(np.abs(det) <= 1e-15, n)
        self.fail(st, bad, lambda i: f"the two guides of {self.C} are parallel")
        st.z[self.C] = np.broadcast_to(G1 + s1 * u1, n).copy()
        st.relative[self._name()] = {"s1": np.broadcast_to(s1, n), "s2": np.broadcast_to(s2, n)}
        st.e[self.links[0]] = np.broadcast_to(u1, n)
        st.e[self.links[1]] = np.broadcast_to(u2, n)

    def velocities(self, st: State) -> None:
        rel = st.relative[self._name()]
        _, u1, w1, _ = self.guide_1.line(st)
        _, u2, w2, _ = self.guide_2.line(st)
        vG1, _ = self.guide_1.kinematics(st)
        vG2, _ = self.guide_2.kinematics(st)
        v1 = vG1 + 1j * w1 * rel["s1"] * u1
        v2 = vG2 + 1j * w2 * rel["s2"] * u2
        sd1, sd2, det = solve2(u1, -u2, v2 - v1)
        self.check_det(st, det, f"the guides of {self.C} are parallel")
        n = (st.n,)
        st.conditioning[self._name()] = np.broadcast_to(np.abs(det), n)
        st.v[self.C] = np.broadcast_to(v1 + sd1 * u1, n)
        for link, w in zip(self.links, (w1, w2)):
            st.omega[link] = np.broadcast_to(w, n)
        rel.update({"s1_dot": sd1, "s2_dot": sd2, "v_guide_1": v1, "v_guide_2": v2, "v_rel_1": sd1 * u1,
                    "v_rel_2": sd2 * u2})

    def accelerations(self, st: State) -> None:
        rel = st.relative[self._name()]
        _, u1, w1, e1 = self.guide_1.line(st)
        _, u2, w2, e2 = self.guide_2.line(st)
        _, aG1 = self.guide_1.kinematics(st)
        _, aG2 = self.guide_2.kinematics(st)
        a1 = aG1 + (1j * e1 - w1 * w1) * rel["s1"] * u1
        a2 = aG2 + (1j * e2 - w2 * w2) * rel["s2"] * u2
        k1 = 2j * w1 * rel["s1_dot"] * u1
        k2 = 2j * w2 * rel["s2_dot"] * u2
        sdd1, sdd2, _ = solve2(u1, -u2, a2 + k2 - a1 - k1)
        n = (st.n,)
        st.a[self.C] = np.broadcast_to(a1 + k1 + sdd1 * u1, n)
        for link, e in zip(self.links, (e1, e2)):
            st.epsilon[link] = np.broadcast_to(e, n)
        rel.update({"s1_ddot": sdd1, "s2_ddot": sdd2, "a_guide_1": a1, "a_guide_2": a2, "a_coriolis_1": k1,
                    "a_coriolis_2": k2, "a_rel_1": sdd1 * u1, "a_rel_2": sdd2 * u2})

    def records(self, st: State) -> tuple[Record, ...]:
        C = self.C
        rel = broadcast(st, st.relative[self._name()])
        _, u1, _, _ = self.guide_1.line(st)
        _, u2, _, _ = self.guide_2.line(st)
        u1, u2 = np.broadcast_to(u1, (st.n,)), np.broadcast_to(u2, (st.n,))
        s = cross(u1, u2)
        g1, g2 = self.guide_1.link, self.guide_2.link
        out = [Record(point=C, plan="velocity", equation=f"v_{C} = v_{C}{g1} + v_{C}{C}{g1} = v_{C}{g2} + v_{C}{C}{g2}",
                      known=((f"v_{C}{g1}", rel["v_guide_1"]), (f"v_{C}{g2}", rel["v_guide_2"])),
                      lines=(("∥ guide 1", rel["v_guide_1"], u1), ("∥ guide 2", rel["v_guide_2"], u2)),
                      meet=st.v[C], sin_between=s)]
        if "a_rel_1" in rel:
            b1 = rel["a_guide_1"] + rel["a_coriolis_1"]
            b2 = rel["a_guide_2"] + rel["a_coriolis_2"]
            out.append(Record(point=C, plan="acceleration",
                              equation=f"a_{C} = a_{C}{g1} + a^k_1 + a^r_1 = a_{C}{g2} + a^k_2 + a^r_2",
                              known=((f"a_{C}{g1}", rel["a_guide_1"]), ("a^k_1", rel["a_coriolis_1"]),
                                     (f"a_{C}{g2}", rel["a_guide_2"]), ("a^k_2", rel["a_coriolis_2"])),
                              lines=(("∥ guide 1", b1, u1), ("∥ guide 2", b2, u2)), meet=st.a[C], sin_between=s))
        return tuple(out)
