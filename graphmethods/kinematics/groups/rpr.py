"""The RPR dyad: a block pinned at a known point P slides along a slotted link that turns about Q.

The crank and slotted lever (кулисный механизм, 导杆机构), oscillating or rotating: link
``links[0]`` is the block (it turns with the slotted link), link ``links[1]`` the slotted link
pivoted at the known point Q. The slot's line is at the signed distance ``e`` from Q (0: the
slot passes through the pivot), to the left of its direction. The slotted link's angle is the
slot's direction; branch +1 makes it point from Q's foot toward P (the slot's coordinate s of
P is positive), −1 the opposite. ``coincident`` names the point of the slotted link under P
(the textbook's A3, when P is A = A1 = A2).

Positions: P − Q = (s + i·e)·u, so s = σ√(|PQ|² − e²) and u = (P − Q)/(s + i·e).
Velocities, as the plan is drawn: ``v_A3 = v_A2 + v_A3A2`` with v_A3 ⟂ QA3 (about the pivot)
and v_A3A2 ∥ the slot. Accelerations: ``a_A3 = a_A2 + a^k_A3A2 + a^r_A3A2`` with the Coriolis
term a^k_A3A2 = 2·ω₃ × v_A3A2 and a^r ∥ the slot; ``a_A3 = a_Q + a^n_A3Q + a^τ_A3Q``.

>>> import numpy as np
>>> from graphmethods.kinematics.groups.base import State
>>> st = State(phi=np.zeros(1))
>>> st.z.update(A=np.array([0.1j]), O3=np.array([-0.3j]))
>>> st.v.update(A=np.array([-1.0 + 0j]), O3=np.zeros(1, complex))
>>> g = RPR(P="A", Q="O3", coincident="A3", links=("2", "3"))
>>> g.positions(st); g.velocities(st)
>>> round(float(st.omega["3"][0]), 12), round(float(st.relative[g.name]["s_dot"][0]), 12)
(2.5, 0.0)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphmethods.kinematics.groups.base import Group, Joints, Pair, Record, State, cross, fmt, solve2
from graphmethods.kinematics.vectors import FloatArray


@dataclass(frozen=True, eq=False)
class RPR(Group):
    """RPR dyad (see the module docstring).

    Parameters
    ----------
    P : str
        The known joint of the block (the crank pin A).
    Q : str
        The slotted link's known pivot.
    coincident : str
        Name of the slotted link's point under P (``"A3"``).
    e : float
        Signed offset of the slot from Q, m (0 by default).
    links : (str, str)
        Textbook numbers of the block and the slotted link.
    branch : int
        +1: the slot's direction points toward P; −1 away from it.
    """

    P: str
    Q: str
    coincident: str
    e: float = 0.0
    links: tuple[str, str] = ("2", "3")
    branch: int = 1

    kind = "RPR"

    def __post_init__(self) -> None:
        self._check("e", f"offset e of the slot of link {self.links[1]}", positive=False)
        self._check_branch()

    @property
    def pairs(self) -> tuple[Pair, ...]:
        return (("R", "?", self.links[0], self.P), ("P", self.links[0], self.links[1], self.P),
                ("R", "?", self.links[1], self.Q))

    def joints(self) -> Joints:
        return Joints(known=(self.P, self.Q), found=(self.coincident,))

    def margin(self, st: State) -> FloatArray:
        rho = np.abs(st.z[self.P] - st.z[self.Q])
        return (rho - abs(self.e)) * (rho + abs(self.e))

    def positions(self, st: State) -> None:
        R = st.z[self.P] - st.z[self.Q]
        rho = np.abs(R)
        e = self.e
        tol = 1e-15 * max(abs(e), 1.0)
        if e == 0.0:
            bad = rho == 0.0
            why = lambda i: f"{self.P} passes through the pivot {self.Q}: the slot's direction is undefined"  # noqa: E731
        else:
            bad = rho < abs(e) - tol
            why = lambda i: (f"|{self.P}{self.Q}| = {fmt(rho[i])} m is less than the slot's offset |e| = "  # noqa: E731
                             f"{fmt(abs(e))} m")
        self.fail(st, bad, why)
        s = self.branch * np.sqrt(np.maximum((rho - abs(e)) * (rho + abs(e)), 0.0))
        u = R / (s + 1j * e)
        u = u / np.abs(u)
        st.z[self.coincident] = st.z[self.P]
        st.relative[self._name()] = {"s": s, "u": u}
        st.e[self.links[0]] = u
        st.e[self.links[1]] = u

    def velocities(self, st: State) -> None:
        rel = st.relative[self._name()]
        u = rel["u"]
        R = st.z[self.P] - st.z[self.Q]
        # v_P − v_Q = ṡ·u + ω·i·(P − Q)
        sd, w, det = solve2(u, 1j * R, st.v[self.P] - st.v[self.Q])
        self.check_det(st, det, f"the slot of link {self.links[1]} is perpendicular to {self.Q}{self.P}")
        st.conditioning[self._name()] = np.abs(det) / np.maximum(np.abs(R), 1e-300)
        st.omega[self.links[0]] = w
        st.omega[self.links[1]] = w.copy()
        st.v[self.coincident] = st.v[self.Q] + 1j * w * R
        rel.update({"s_dot": sd, "v_rel": -sd * u})           # v_A3A2 = v_A3 − v_A2 = −ṡ·u

    def accelerations(self, st: State) -> None:
        rel = st.relative[self._name()]
        u, sd = rel["u"], rel["s_dot"]
        R = st.z[self.P] - st.z[self.Q]
        w = st.omega[self.links[1]]
        a_k = 2j * w * sd * u                          # a_A2 − a_A3 contains +2ω×(ṡu)
        sdd, e, _ = solve2(u, 1j * R, st.a[self.P] - st.a[self.Q] + w * w * R - a_k)
        st.epsilon[self.links[0]] = e
        st.epsilon[self.links[1]] = e.copy()
        st.a[self.coincident] = st.a[self.Q] + (1j * e - w * w) * R
        rel.update({"s_ddot": sdd, "a_rel": -sdd * u, "a_coriolis": -a_k})   # a^k_A3A2 = 2ω₃ × v_A3A2

    def records(self, st: State) -> tuple[Record, ...]:
        P, Q, A3 = self.P, self.Q, self.coincident
        rel = st.relative[self._name()]
        u = rel["u"]
        R = st.z[P] - st.z[Q]
        n = 1j * R / np.maximum(np.abs(R), 1e-300)
        s = cross(n, u)
        vel = Record(point=A3, plan="velocity", equation=f"v_{A3} = v_{P} + v_{A3}{P}",
                     known=((f"v_{P}", st.v[P]),),
                     lines=((f"⟂ {Q}{A3}", st.v[Q], n), (f"∥ {Q}{A3}", st.v[P], u)), meet=st.v[A3], sin_between=s)
        out = [vel]
        if "a_rel" in rel:
            w = st.omega[self.links[1]]
            nQ = -w * w * R
            out.append(Record(
                point=A3, plan="acceleration",
                equation=f"a_{A3} = a_{P} + a^k_{A3}{P} + a^r_{A3}{P} = a_{Q} + a^n_{A3}{Q} + a^τ_{A3}{Q}",
                known=((f"a_{P}", st.a[P]), (f"a^k_{A3}{P}", rel["a_coriolis"]), (f"a_{Q}", st.a[Q]),
                       (f"a^n_{A3}{Q}", nQ)),
                lines=((f"⟂ {Q}{A3}", st.a[Q] + nQ, n), (f"∥ {Q}{A3}", st.a[P] + rel["a_coriolis"], u)),
                meet=st.a[A3], sin_between=s))
        return tuple(out)
