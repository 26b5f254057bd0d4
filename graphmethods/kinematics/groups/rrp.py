"""The RRP dyad: a link P–C pinned at a known point P and at C to a slider that moves along a guide.

Link ``links[0]`` is the rod P–C (length ``l``); link ``links[1]`` is the slider (block) at C,
which slides along a :class:`~graphmethods.kinematics.groups.base.Guide` on the frame or on a
moving link (then it turns with that link). The mirror group (PRR: the guide first, then the
rod) is the same group: the order of its pairs along the chain does not change the solution.
The branch +1 puts C ahead of the foot of P on the guide (along the guide's direction), −1
behind it. The rod's angle is the direction P→C; the slider's is the guide's.

Positions: with h the signed distance of P from the guide line and w = √(l² − h²),
C = F + σ·w·u (F the foot of P, u the guide's direction). Velocities, as the plan is drawn:
``v_C = v_P + v_CP`` with v_CP ⟂ PC, and v_C = v_C(guide) + v_rel with v_rel ∥ the guide.
Accelerations: ``a_C = a_P + a^n_CP + a^τ_CP = a_C(guide) + a^k + a^r`` with the Coriolis
term a^k = 2·ω_guide × v_rel (zero on the frame) and a^r ∥ the guide.

>>> import numpy as np
>>> from graphmethods.kinematics.groups.base import Relative, Guide, State
>>> st = State(phi=np.zeros(1))
>>> st.z["A"] = np.array([0.0 + 0.3j]); st.v["A"] = np.array([-1.0 + 0j]); st.a["A"] = np.zeros(1, complex)
>>> g = RRP(P="A", C="B", l=0.5, guide=Guide("0", 0j, 0.0), links=("2", "3"))
>>> g.positions(st); g.velocities(st)
>>> complex(st.z["B"][0]), complex(st.v["B"][0])
((0.4+0j), (-1+0j))
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.kinematics.groups.base import (
    GROUND,
    Group,
    Guide,
    Joints,
    Pair,
    Real,
    Record,
    Relative,
    State,
    Vec,
    cross,
    dot,
    fmt,
    solve2,
)
from graphmethods.kinematics.vectors import ComplexArray, FloatArray


def _product(a: Any, b: Any, c: Any) -> Any:
    """a·b·c, for a quantity computed when asked."""
    return a * b * c


@dataclass(frozen=True, eq=False)
class RRP(Group):
    """RRP dyad (see the module docstring).

    Parameters
    ----------
    P : str
        The known joint of the rod.
    C : str
        The slider's joint (found).
    l : float
        Rod P–C, m.
    guide : Guide
        The guide the slider moves along.
    links : (str, str)
        Textbook numbers of the rod and the slider.
    branch : int
        +1: C ahead of the foot of P along the guide; −1: behind it.
    """

    P: str
    C: str
    l: float
    guide: Guide
    links: tuple[str, str] = ("2", "3")
    branch: int = 1

    kind = "RRP"

    def __post_init__(self) -> None:
        self._check("l", f"{self.P}{self.C}")
        self._check_branch()

    @property
    def pairs(self) -> tuple[Pair, ...]:
        return (("R", "?", self.links[0], self.P), ("R", self.links[0], self.links[1], self.C),
                ("P", self.guide.link, self.links[1], self.C))

    def joints(self) -> Joints:
        return Joints(known=(self.P,), found=(self.C,), guides=(self.guide,))

    @functools.cached_property
    def _k(self) -> tuple[Any, ...]:
        """The group's numbers as 0-d arrays: l, l·(1 + 1e-15), the branch, 0. Numpy takes a 0-d array
        as an operand faster than a Python number (about 0.3 µs a call); the values, and so the results,
        are the same to the bit."""
        return tuple(np.array(x) for x in (float(self.l), self.l * (1.0 + 1e-15), float(self.branch), 0.0))

    @functools.cached_property
    def _frame(self) -> tuple[Any, ...] | None:
        """On a guide of the frame through given coordinates: its point G, direction u, the velocity and
        acceleration of G (0), and the factors i·ω_g, i·ε_g − ω_g², 2i·ω_g (0) as 0-d arrays (see
        :attr:`_k`); else None."""
        if self.guide.link != GROUND or isinstance(self.guide.through, str):
            return None
        w = 0.0
        return tuple(np.array(x) for x in (complex(self.guide.through), self.guide.turn, 0j, 0j, 1j * w,
                                           1j * w - w * w, 2j * w))

    def _line(self, st: State) -> tuple[Vec, Vec, Real, Real]:
        """:meth:`Guide.line`, on the frame as 0-d arrays."""
        fr = self._frame
        return self.guide.line(st) if fr is None else (fr[0], fr[1], 0.0, 0.0)

    def _geometry(self, st: State) -> tuple[Vec, Vec, ComplexArray, FloatArray]:
        G, u, _, _ = self._line(st)
        R = st.z[self.P] - G
        h = cross(u, R)
        return G, u, R, h

    def margin(self, st: State) -> FloatArray:
        h = self._geometry(st)[3]
        return (self.l - h) * (self.l + h)

    def positions(self, st: State) -> None:
        G, u, R, h = self._geometry(st)
        l, lim, branch, zero = self._k
        bad = np.abs(h) > lim
        self.fail(st, bad, lambda i: f"{self.P} is {fmt(abs(h[i]))} m from the guide of {self.C}, farther than "
                                     f"{self.P}{self.C} = {fmt(self.l)} m")
        w = np.sqrt(np.maximum((l - h) * (l + h), zero))
        s = dot(u, R) + branch * w
        C = G + s * u
        st.z[self.C] = C
        st.relative[self._name()] = Relative(s=s, u=u)   # type: ignore[assignment]  # v_rel, a_rel when asked
        st.e[self.links[0]] = (C - st.z[self.P]) / l
        st.e[self.links[1]] = self.guide.line(st)[1] if self._frame is None else self.guide.turn  # broadcasts

    def _guide_motion(self, st: State) -> tuple[Vec, Vec, Any, Any, Any]:
        """(v_G, a_G, i·ω_g, i·ε_g − ω_g², 2i·ω_g) of the guide (see :attr:`_frame`)."""
        fr = self._frame
        if fr is not None:
            return fr[2], fr[3], fr[4], fr[5], fr[6]
        _, _, wg, eg = self.guide.line(st)
        vG, aG = self.guide.kinematics(st)
        return vG, aG, 1j * wg, 1j * eg - wg * wg, 2j * wg

    def velocities(self, st: State) -> None:
        _, u, _, _ = self._line(st)
        vG, _, iwg, _, _ = self._guide_motion(st)
        name = self._name()
        s = st.relative[name]["s"]
        rP = st.z[self.C] - st.z[self.P]
        nP = -1j * rP
        frame = self._frame is not None
        # the guide's point under C turning with its link (on the frame: zeros, no array)
        turning = st.zeros_complex() if frame else iwg * s * u
        # v_G + iω_g·s·u + ṡ·u = v_P + ω·i·rP
        sd, w, det = solve2(u, nP, st.v[self.P] - vG - turning)
        self.check_det(st, det, f"the rod {self.P}{self.C} stands perpendicular to the guide")
        st.conditioning[name] = np.abs(det) / self._k[0]
        st.omega[self.links[0]] = w
        st.omega[self.links[1]] = st.zeros if self.guide.link == GROUND else st.omega[self.guide.link]
        v_guide = st.zeros_complex() if frame else vG + turning
        st.v[self.C] = v_guide + sd * u             # exactly along a guide of the frame; v_rel = ṡ·u when asked
        st.relative[name].update({"s_dot": sd, "v_guide": v_guide})
        st.keep(name, (rP, nP, det))

    def accelerations(self, st: State) -> None:
        _, u, _, _ = self._line(st)
        _, aG, _, turn_a, cor = self._guide_motion(st)
        name = self._name()
        rel = st.relative[name]
        s, sd = rel["s"], rel["s_dot"]
        kept = st.kept.pop(name, None)
        if kept is None:
            rP = st.z[self.C] - st.z[self.P]
            kept = (rP, -1j * rP, None)
        rP, nP, det = kept
        w = st.omega[self.links[0]]
        frame = self._frame is not None
        if frame:                                           # a guide of the frame: both are zeros, no array
            a_guide = a_k = st.zeros_complex()
        else:
            a_guide = aG + turn_a * s * u                   # the guide's point under C
            a_k = cor * sd * u                              # Coriolis, 2ω_g × v_rel
        sdd, e, _ = solve2(u, nP, st.a[self.P] - w * w * rP - a_guide - a_k, det)
        del kept, rP, nP, det                           # not held meanwhile (peak memory at 10⁶ positions)
        st.epsilon[self.links[0]] = e
        st.epsilon[self.links[1]] = st.zeros if self.guide.link == GROUND else st.epsilon[self.guide.link]
        st.a[self.C] = a_guide + a_k + sdd * u             # a_rel = s̈·u when asked
        rel.update({"s_ddot": sdd, "a_guide": a_guide})
        if frame:       # 2ω_g × v_rel = 0 (its zeros signed as the product signs them), computed when asked
            rel.lazy["a_coriolis"] = functools.partial(_product, cor, sd, u)   # type: ignore[attr-defined]
        else:
            rel["a_coriolis"] = a_k

    def records(self, st: State) -> tuple[Record, ...]:
        P, C = self.P, self.C
        c = st.z[C]
        G, u, wg, _ = self.guide.line(st)
        u = np.broadcast_to(u, c.shape)
        uP = 1j * (c - st.z[P]) / self.l
        s = cross(uP, u)
        rel = st.relative[self._name()]
        moving = self.guide.link != GROUND
        gname = f"v_{C}{self.guide.link}" if moving else ""
        vel_eq = f"v_{C} = v_{P} + v_{C}{P}" + (f" = {gname} + v_{C}{C}{self.guide.link}" if moving else "")
        v_guide = np.broadcast_to(rel["v_guide"], c.shape)
        vel = Record(point=C, plan="velocity", equation=vel_eq,
                     known=((f"v_{P}", st.v[P]),) + (((gname, v_guide),) if moving else ()),
                     lines=((f"⟂ {P}{C}", st.v[P], uP), ("∥ guide", v_guide, u)), meet=st.v[C],
                     sin_between=s)
        out = [vel]
        if "a_rel" in rel:
            w = st.omega[self.links[0]]
            nP = -w * w * (c - st.z[P])
            known: tuple[tuple[str, np.ndarray], ...] = ((f"a_{P}", st.a[P]), (f"a^n_{C}{P}", nP))
            base = np.broadcast_to(rel["a_guide"], c.shape)
            eq = f"a_{C} = a_{P} + a^n_{C}{P} + a^τ_{C}{P}"
            if moving:
                known += ((f"a_{C}{self.guide.link}", rel["a_guide"]), ("a^k", rel["a_coriolis"]))
                base = base + rel["a_coriolis"]
                eq += f" = a_{C}{self.guide.link} + a^k + a^r"
            out.append(Record(point=C, plan="acceleration", equation=eq, known=known,
                              lines=((f"⟂ {P}{C}", st.a[P] + nP, uP), ("∥ guide", base, u)), meet=st.a[C],
                              sin_between=s))
        return tuple(out)
