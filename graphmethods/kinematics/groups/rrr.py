"""The RRR dyad: two links pinned together at C, their outer ends pinned at known points P and Q.

Link ``links[0]`` is P–C (length ``l_PC``), link ``links[1]`` is Q–C (length ``l_QC``). The
branch +1 puts C on the left of the directed line P→Q. Each link's angle is the direction
P→C (Q→C).

Positions: with d = |PQ|, C = P + a·ê + σ·h·ê⟂, a = (l_PC² − l_QC² + d²)/(2d) and h from
Heron's formula (no cancellation near the toggle). Velocities, as the plan is drawn:
``v_C = v_P + v_CP = v_Q + v_CQ`` with v_CP ⟂ PC and v_CQ ⟂ QC (two lines meet at c).
Accelerations: ``a_C = a_P + a^n_CP + a^τ_CP = a_Q + a^n_CQ + a^τ_CQ``, a^n = ω²·l toward
the centre, a^τ ⟂ the link.

>>> import numpy as np
>>> from graphmethods.kinematics.groups.base import State
>>> st = State(phi=np.zeros(1))
>>> st.z.update(A=np.array([0j]), D=np.array([2 + 0j]))
>>> g = RRR(P="A", Q="D", C="C", l_PC=2.0 ** 0.5, l_QC=2.0 ** 0.5, links=("2", "3"))
>>> g.positions(st); complex(np.round(st.z["C"][0], 12))
(1+1j)
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.kinematics.groups.base import Group, Joints, Pair, Record, State, cross, fmt, solve2
from graphmethods.kinematics.vectors import ComplexArray, FloatArray


@dataclass(frozen=True, eq=False)
class RRR(Group):
    """RRR dyad (see the module docstring).

    Parameters
    ----------
    P, Q : str
        The known outer joints.
    C : str
        The middle joint (found).
    l_PC, l_QC : float
        Link lengths, m.
    links : (str, str)
        Textbook numbers of the links P–C and Q–C.
    branch : int
        +1: C left of P→Q; −1: right.
    """

    P: str
    Q: str
    C: str
    l_PC: float
    l_QC: float
    links: tuple[str, str] = ("2", "3")
    branch: int = 1

    kind = "RRR"

    def __post_init__(self) -> None:
        self._check("l_PC", f"{self.P}{self.C}")
        self._check("l_QC", f"{self.Q}{self.C}")
        self._check_branch()

    @property
    def pairs(self) -> tuple[Pair, ...]:
        return (("R", "?", self.links[0], self.P), ("R", self.links[0], self.links[1], self.C),
                ("R", "?", self.links[1], self.Q))

    def joints(self) -> Joints:
        return Joints(known=(self.P, self.Q), found=(self.C,))

    @functools.cached_property
    def _k(self) -> tuple[Any, ...]:
        """The group's numbers as 0-d arrays: l_PC, l_QC, l_PC + l_QC, l_PC² − l_QC², 2, i·branch. Numpy
        takes a 0-d array as an operand faster than a Python number (about 0.3 µs a call); the values,
        and so the results, are the same to the bit."""
        l1, l2 = self.l_PC, self.l_QC
        return tuple(np.array(x) for x in (l1, l2, l1 + l2, l1 * l1 - l2 * l2, 2.0, 1j * self.branch))

    def _heron(self, st: State) -> tuple[ComplexArray, ComplexArray, FloatArray, FloatArray]:
        P, Q = st.z[self.P], st.z[self.Q]
        D = Q - P
        d = np.abs(D)
        l1, l2, l12 = self._k[:3]
        d_l1 = d + l1
        prod = (l12 - d) * (d + l2 - l1) * (d_l1 - l2) * (d_l1 + l2)
        return P, D, d, prod

    def margin(self, st: State) -> FloatArray:
        return self._heron(st)[3]

    def positions(self, st: State) -> None:
        P, D, d, prod = self._heron(st)
        l1, l2 = self.l_PC, self.l_QC
        if prod.min() > 0.0:                      # every position assembles (the usual case)
            self._place(st, P, D, d, prod)
            return
        tol = 4e-15 * (l1 + l2 + d)
        far = d > l1 + l2 + tol
        near = d < abs(l1 - l2) - tol
        zero = d <= tol

        def why(i: int) -> str:
            if zero[i]:
                return f"{self.P} and {self.Q} coincide, so the position of {self.C} is undefined"
            if far[i]:
                return (f"|{self.P}{self.Q}| = {fmt(d[i])} m exceeds {self.P}{self.C} + {self.Q}{self.C} = "
                        f"{fmt(l1 + l2)} m (the links cannot reach each other)")
            return (f"|{self.P}{self.Q}| = {fmt(d[i])} m is less than |{self.P}{self.C} − {self.Q}{self.C}| = "
                    f"{fmt(abs(l1 - l2))} m (the links cannot meet)")

        self.fail(st, far | near | zero, why)
        self._place(st, P, D, d, np.maximum(prod, 0.0))

    def _place(self, st: State, P: ComplexArray, D: ComplexArray, d: FloatArray, prod: FloatArray) -> None:
        """C from Heron's ``prod`` (≥ 0 at every position: the caller clips it)."""
        l1, l2, _, sq, two, ib = self._k
        d2 = two * d
        h = np.sqrt(prod) / d2
        a = (sq + d * d) / d2
        e = D / d
        C = P + (a + ib * h) * e
        st.z[self.C] = C
        st.e[self.links[0]] = (C - P) / l1
        st.e[self.links[1]] = (C - st.z[self.Q]) / l2

    def _arms(self, st: State) -> tuple[ComplexArray, ComplexArray, ComplexArray, ComplexArray]:
        """(P→C, Q→C, and the plan's two lines: P→C turned +90°, Q→C turned −90°) over the positions."""
        C = st.z[self.C]
        rP, rQ = C - st.z[self.P], C - st.z[self.Q]
        return rP, rQ, 1j * rP, -1j * rQ

    def velocities(self, st: State) -> None:
        rP, rQ, nP, nQ = self._arms(st)
        # v_P + ω_i·i·rP = v_Q + ω_j·i·rQ
        w1, w2, det = solve2(nP, nQ, st.v[self.Q] - st.v[self.P])
        self.check_det(st, det, f"the links {self.P}{self.C} and {self.Q}{self.C} are in line")
        st.conditioning[self._name()] = np.abs(det) / (np.abs(rP) * np.abs(rQ))
        st.omega[self.links[0]], st.omega[self.links[1]] = w1, w2
        st.v[self.C] = st.v[self.P] + 1j * w1 * rP
        st.keep(self._name(), (rP, rQ, nP, nQ, det))

    def accelerations(self, st: State) -> None:
        kept = st.kept.pop(self._name(), None)
        rP, rQ, nP, nQ, det = kept if kept is not None else (*self._arms(st), None)
        w1, w2 = st.omega[self.links[0]], st.omega[self.links[1]]
        aP_n = st.a[self.P] - w1 * w1 * rP                 # a_P + a^n_CP
        e1, e2, _ = solve2(nP, nQ, st.a[self.Q] - w2 * w2 * rQ - aP_n, det)
        st.epsilon[self.links[0]], st.epsilon[self.links[1]] = e1, e2
        st.a[self.C] = aP_n + 1j * e1 * rP

    def records(self, st: State) -> tuple[Record, ...]:
        P, Q, C = self.P, self.Q, self.C
        c = st.z[C]
        uP, uQ = 1j * (c - st.z[P]) / self.l_PC, 1j * (c - st.z[Q]) / self.l_QC
        s = cross(uP, uQ)
        vel = Record(point=C, plan="velocity", equation=f"v_{C} = v_{P} + v_{C}{P} = v_{Q} + v_{C}{Q}",
                     known=((f"v_{P}", st.v[P]), (f"v_{Q}", st.v[Q])),
                     lines=((f"⟂ {P}{C}", st.v[P], uP), (f"⟂ {Q}{C}", st.v[Q], uQ)), meet=st.v[C], sin_between=s)
        out = [vel]
        if C in st.a:
            w1, w2 = st.omega[self.links[0]], st.omega[self.links[1]]
            nP = -w1 * w1 * (c - st.z[P])
            nQ = -w2 * w2 * (c - st.z[Q])
            out.append(Record(
                point=C, plan="acceleration",
                equation=f"a_{C} = a_{P} + a^n_{C}{P} + a^τ_{C}{P} = a_{Q} + a^n_{C}{Q} + a^τ_{C}{Q}",
                known=((f"a_{P}", st.a[P]), (f"a^n_{C}{P}", nP), (f"a_{Q}", st.a[Q]), (f"a^n_{C}{Q}", nQ)),
                lines=((f"⟂ {P}{C}", st.a[P] + nP, uP), (f"⟂ {Q}{C}", st.a[Q] + nQ, uQ)),
                meet=st.a[C], sin_between=s))
        return tuple(out)
