"""The acceleration plan of a linkage in one position, constructed as the book draws it.

From the pole π at the scale μ_a, group by group in the order of the structural formula:

- the crank O–A at ω₁ and ε₁: ``a_A = a^n_A + a^τ_A``, a^n_A = ω₁²·l_OA from a toward O (drawn
  from π), a^τ_A = ε₁·l_OA ⟂ OA (drawn only when ε₁ ≠ 0);
- two points of one link (RRR, the rod of an RRP): ``a_C = a_B + a^n_CB + a^τ_CB``, the normal
  component ω²·l_BC drawn from b toward the centre (from C to B), the tangential one unknown,
  ⟂ BC: a dashed line through the end of a^n_CB;
- a block sliding on a turning link (RPR, a guide on a moving link): ``a_A3 = a_A2 + a^k_A3A2 +
  a^r_A3A2``, the Coriolis component 2·ω₃·v_A3A2 with its direction v_A3A2 turned 90° in the
  sense of ω₃, the relative component unknown, ∥ the slot; with ``a_A3 = a_O3 + a^n_A3O3 + a^τ_A3O3``;
- a triad (class III): Assur's special point K first, on two dashed lines ⟂ two binary links, each
  through the end of that link's a^n and of K's a^n about the link's inner joint; then the third
  binary link's joint from k, and the other two from it;
- extra points by similarity: the images of the points of one link form a figure similar to
  the link (``a_S = a_B + (a_C − a_B)·(S − B)/(C − B)`` in complex numbers).

Only the positions and the velocity plan (ω, v) of the linkage are read from the core; every
acceleration is built here from the components above, and each unknown point is where its two
construction lines meet. The angular accelerations follow from the tangential components:
ε = a^τ/l, its sense from the sense of a^τ about the centre.

Plan vectors are complex numbers x + iy in m/s² (the vector from π to the image); a figure turns
them into millimetres with μ_a.

>>> from graphmethods.kinematics.presets import slider_crank
>>> press = slider_crank(r=0.1, l=0.4, points={"S2": ("AB", 0.2)})
>>> plan = acceleration_plan(press, 0, m=12, omega_1=10.0)      # far dead centre
>>> round(plan.a("B").real, 12)                                # −ω²r(1 + r/l)
-12.5
>>> [s.equation for s in plan.steps][1]
'a_B = a_A + a^n_BA + a^τ_BA'
>>> round(abs(plan.a("S2") - (plan.a("A") + plan.a("B")) / 2), 12)   # s2 halves ab
0.0
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.kinematics.groups import GROUND, PRP, RPP, RPR, RRP, RRR, Guide, Triad
from graphmethods.kinematics.groups.base import State
from graphmethods.kinematics.linkage import Linkage, Point

#: ratio below which two construction lines count as parallel (the plan cannot be closed)
PARALLEL = 1e-12


@dataclass(frozen=True)
class Component:
    """One vector drawn in the plan: from the image ``start`` to the image ``end``.

    Attributes
    ----------
    symbol : str
        The acceleration it stands for, plain text: ``"a_A"``, ``"a^n_BA"``, ``"a^τ_BA"``,
        ``"a^k_A3A2"``, ``"a^r_A3A2"``.
    kind : str
        ``"absolute"`` (from π), ``"normal"``, ``"tangential"``, ``"coriolis"``, ``"relative"``.
    start, end : str
        Image labels (``"π"``, ``"a"``, ``"n_BA"``, ``"b"``).
    vector : complex
        end − start, m/s².
    known : bool
        True: a known component (drawn solid); False: found by the construction (dashed).
    link : str
        For a normal, tangential or Coriolis component, the link whose ω (ε) it is made of
        (the turning guide's for Coriolis), else ``""``.
    factor : float
        What multiplies it: the length l (m) for a normal (ω²·l) or tangential (ε·l) component,
        |v_rel| (m/s) for a Coriolis one (2·ω·v_rel); 0 otherwise.
    """

    symbol: str
    kind: str
    start: str
    end: str
    vector: complex
    known: bool
    link: str = ""
    factor: float = 0.0

    @property
    def magnitude(self) -> float:
        """|vector|, m/s²."""
        return abs(self.vector)


@dataclass(frozen=True)
class Line:
    """A construction line of the plan: the unknown image lies on it.

    Attributes
    ----------
    label : str
        ``"⟂ BA"``, ``"∥ guide"``, ``"∥ O3A3"``.
    through : str
        The image label it is drawn through.
    point : complex
        That image, m/s².
    direction : complex
        Unit direction.
    """

    label: str
    through: str
    point: complex
    direction: complex


@dataclass(frozen=True)
class Step:
    """How one point's image is found.

    Attributes
    ----------
    point : str
        The point (``"B"``).
    label : str
        Its image (``"b"``).
    method : str
        ``"crank"`` (the known components of the crank pin), ``"intersection"`` (of two
        construction lines), ``"similarity"`` (on the images of its link), ``"same"`` (the
        image of another point: a slider that translates with it).
    equation : str
        The vector equation as the book writes it, plain text.
    components : tuple of Component
        The vectors this step draws, known ones first, then the ones found.
    lines : tuple of Line
        The two construction lines (intersection), else empty.
    on : tuple of str
        For similarity, the two points of the link it is similar to, else empty.
    sin_between : float
        |sin| of the angle between the two lines (1 without lines).
    """

    point: str
    label: str
    method: str
    equation: str
    components: tuple[Component, ...] = ()
    lines: tuple[Line, ...] = ()
    on: tuple[str, ...] = ()
    sin_between: float = 1.0


@dataclass(frozen=True)
class AccelerationPlan:
    """The acceleration plan of one position (see the module docstring).

    Attributes
    ----------
    phi : float
        Crank angle from +x, rad.
    phi_from_start : float
        Crank rotation from position 0 in the crank's sense, rad.
    position : int or None
        Textbook position number, or None at an arbitrary angle.
    omega_1, epsilon_1 : float
        Crank speed (rad/s, > 0 in its sense) and angular acceleration (rad/s², + speeding up).
    images : mapping label -> complex
        Every image of the plan (points and the ends of the known components), m/s² from π.
    labels : mapping point -> label
        The image of every point (``"π"`` for the fixed ones).
    steps : tuple of Step
        The construction in order.
    omega, epsilon : mapping link -> float
        Angular velocity (from the velocity plan) and angular acceleration (from this plan) of
        every moving link, rad/s and rad/s², counterclockwise +.
    lengths : mapping link -> float
        The length l of the link each ε was found from (the points its a^τ joins), m.
    """

    phi: float
    phi_from_start: float
    position: int | None
    omega_1: float
    epsilon_1: float
    images: Mapping[str, complex]
    labels: Mapping[str, str]
    steps: tuple[Step, ...]
    omega: Mapping[str, float]
    epsilon: Mapping[str, float]
    lengths: Mapping[str, float] = field(default_factory=dict)

    def a(self, point: str) -> complex:
        """Acceleration of ``point`` (its plan vector from π), m/s²."""
        try:
            return self.images[self.labels[point]]
        except KeyError:
            raise InputError(f"no point {point!r} in this acceleration plan; points: "
                             f"{', '.join(self.labels)}") from None

    @property
    def components(self) -> tuple[Component, ...]:
        """Every vector drawn, in construction order."""
        return tuple(c for s in self.steps for c in s.components)

    @property
    def largest(self) -> float:
        """The longest distance of an image from π, m/s² (what μ_a must fit)."""
        return max((abs(z) for z in self.images.values()), default=0.0)

    def mu_a(self, *, fit_mm: float) -> float:
        """The convenient scale μ_a ((m/s²)/mm, 1, 2, 2.5, 4, 5 × 10^k) at which the plan's images
        all lie within ``fit_mm`` of π.

        >>> from graphmethods.kinematics.presets import slider_crank
        >>> acceleration_plan(slider_crank(r=0.1, l=0.4), 0, omega_1=10.0).mu_a(fit_mm=50.0)
        0.25
        """
        from graphmethods.units import convenient_at_least

        if not (math.isfinite(fit_mm) and fit_mm > 0):
            raise InputError(f"fit_mm must be a positive number of mm, got {fit_mm!r}")
        if self.largest == 0.0:
            raise InputError("every acceleration of this plan is zero: no scale can be fitted")
        return float(convenient_at_least(self.largest / fit_mm))


def _along(guide: Guide, point: str, link: str) -> str:
    """The right side of ``a_X = a_X(guide) + a^k + a^r`` for a slider on ``guide`` (on the frame:
    only the relative component, along the guide)."""
    if guide.link == GROUND:
        return f"a^r_{point}{guide.link} (∥ guide)"
    g = f"{point}{guide.link}"
    return f"a_{g} + a^k_{point}{g} + a^r_{point}{g}"


class _Builder:
    """Builds one position's plan from the core's positions and velocities (not its accelerations)."""

    def __init__(self, lk: Linkage, st: State, i: int) -> None:
        self.lk = lk
        self.i = i
        self.z: dict[str, complex] = {k: complex(v[i]) for k, v in st.z.items()}
        self.v: dict[str, complex] = {k: complex(np.broadcast_to(v, st.phi.shape)[i]) for k, v in st.v.items()}
        self.w: dict[str, float] = {k: float(np.broadcast_to(v, st.phi.shape)[i]) for k, v in st.omega.items()}
        self.st = st
        self.images: dict[str, complex] = {"π": 0j}
        self.labels: dict[str, str] = {}
        self.eps: dict[str, float] = {}
        self.lengths: dict[str, float] = {}
        self.on_link: dict[str, list[str]] = {}
        self.steps: list[Step] = []

    # -------------------------------------------------------------- helpers
    def pick(self, rel: Mapping[str, Any], key: str) -> complex:
        """One position's value of a group's sliding quantity."""
        return complex(np.broadcast_to(rel[key], self.st.phi.shape)[self.i])

    def image(self, point: str) -> complex:
        return self.images[self.labels[point]]

    def put(self, point: str, value: complex) -> str:
        label = "π" if point in self.lk.ground else point.lower()
        self.labels[point] = label
        self.images[label] = value
        return label

    def aux(self, label: str, value: complex) -> str:
        self.images[label] = value
        return label

    def member(self, link: str, point: str) -> None:
        pts = self.on_link.setdefault(link, [])
        if point not in pts:
            pts.append(point)

    def on(self, link: str, at: complex) -> complex:
        """Acceleration of the point of ``link`` at ``at`` from the images of its points (similarity),
        or from ω and ε when only one point of it is known."""
        if link == GROUND:
            return 0j
        pts = self.on_link.get(link, [])
        for j, p in enumerate(pts):
            for q in pts[j + 1:]:
                d = self.z[q] - self.z[p]
                if abs(d) > 1e-12 * (abs(self.z[q]) + abs(self.z[p]) + 1.0):
                    return self.image(p) + (self.image(q) - self.image(p)) * (at - self.z[p]) / d
        p = pts[0]
        w, e = self.w.get(link, 0.0), self.eps[link]
        return self.image(p) + (1j * e - w * w) * (at - self.z[p])

    def tangential(self, link: str, centre: str, point: str, a_tau: complex) -> None:
        r = self.z[point] - self.z[centre]
        self.eps[link] = float((r.real * a_tau.imag - r.imag * a_tau.real) / abs(r) ** 2)
        self.lengths[link] = abs(r)

    def meet(self, l1: Line, l2: Line, where: str) -> tuple[complex, float]:
        """The point where two construction lines meet."""
        d1, d2 = l1.direction, l2.direction
        det = d1.real * d2.imag - d1.imag * d2.real
        if abs(det) < PARALLEL:
            raise InputError(f"acceleration plan at position {where}: the construction lines {l1.label} and "
                             f"{l2.label} are parallel (a toggle); choose another position")
        rhs = l2.point - l1.point
        t = (rhs.real * d2.imag - rhs.imag * d2.real) / det
        return l1.point + t * d1, abs(det)

    def normal(self, link: str, point: str, centre: str) -> complex:
        """a^n of ``point`` about ``centre`` on ``link``: ω²·l, directed from the point toward the centre."""
        w = self.w[link]
        return w * w * (self.z[centre] - self.z[point])

    def coriolis(self, link: str, omega: float, v_rel: complex) -> complex:
        """a^k = 2·ω × v_rel of a point sliding on ``link`` turning at ``omega``: v_rel turned 90° in
        the sense of ω (a subclass can draw a student's mistake here)."""
        return 2j * omega * v_rel

    # -------------------------------------------------------------- the construction
    def crank(self) -> None:
        cr = self.lk.crank
        self.put(cr.centre, 0j)
        for k in self.lk.ground:
            self.put(k, 0j)
        e1 = self.lk.sense * self.eps_1
        self.eps[cr.link] = e1
        self.lengths[cr.link] = cr.r
        an = self.normal(cr.link, cr.pin, cr.centre)
        r = self.z[cr.pin] - self.z[cr.centre]
        at = 1j * e1 * r
        O, A = cr.centre, cr.pin
        comps: list[Component]
        if e1 != 0.0:
            n = self.aux(f"n_{A}", an)
            lab = self.put(A, an + at)
            comps = [Component(f"a^n_{A}", "normal", "π", n, an, True, cr.link, cr.r),
                     Component(f"a^τ_{A}", "tangential", n, lab, at, True, cr.link, cr.r),
                     Component(f"a_{A}", "absolute", "π", lab, an + at, True)]
            eq = f"a_{A} = a^n_{A}{O} + a^τ_{A}{O}"
        else:
            lab = self.put(A, an)
            comps = [Component(f"a_{A}", "absolute", "π", lab, an, True)]
            eq = f"a_{A} = a^n_{A}{O}"
        self.member(cr.link, O)
        self.member(cr.link, A)
        self.steps.append(Step(A, lab, "crank", eq, tuple(comps)))

    def point(self, p: Point) -> None:
        pts = self.on_link.get(p.link, [])
        two = None
        for j, x in enumerate(pts):
            for y in pts[j + 1:]:
                if abs(self.z[y] - self.z[x]) > 1e-12 * (abs(self.z[x]) + abs(self.z[y]) + 1.0):
                    two = (x, y)
                    break
            if two:
                break
        val = self.on(p.link, self.z[p.name])
        lab = self.put(p.name, val)
        self.member(p.link, p.name)
        if two is None:
            src = pts[0]
            self.steps.append(Step(p.name, lab, "same" if self.z[p.name] == self.z[src] else "similarity",
                                   f"a_{p.name} = a_{src}", (Component(f"a_{p.name}", "absolute", "π", lab, val,
                                                                        False),), on=(src,)))
            return
        x, y = two
        lx, ly = self.labels[x], self.labels[y]
        eq = f"{lx}{lab}/{lx}{ly} = {x}{p.name}/{x}{y}"
        self.steps.append(Step(p.name, lab, "similarity", eq,
                               (Component(f"a_{p.name}", "absolute", "π", lab, val, False),), on=(x, y)))

    def two_points(self, link: str, known: str, point: str) -> tuple[str, Component, Line]:
        """``a_point = a_known + a^n + a^τ``: the normal component drawn from the known image,
        and the dashed line ⟂ the link through its end."""
        an = self.normal(link, point, known)
        kl = self.labels[known]
        n = self.aux(f"n_{point}{known}", self.image(known) + an)
        r = self.z[point] - self.z[known]
        comp = Component(f"a^n_{point}{known}", "normal", kl, n, an, True, link, abs(r))
        line = Line(f"⟂ {known}{point}", n, self.images[n], 1j * r / abs(r))
        return n, comp, line

    def guide_line(self, guide: Guide, link: str, point: str, v_rel: complex, name: str
                   ) -> tuple[str, list[Component], Line, str]:
        """``a_point = a_point(guide) + a^k + a^r``: the image of the guide's point under ``point``,
        the Coriolis component 2ω_g × v_rel from it, the dashed line ∥ the guide through its end."""
        _, u, _, _ = guide.line(self.st)
        u = complex(np.broadcast_to(u, self.st.phi.shape)[self.i])
        comps: list[Component] = []
        if guide.link == GROUND:
            return "π", comps, Line("∥ guide", "π", 0j, u), "π"
        wg = self.w[guide.link]
        base = self.on(guide.link, self.z[point])
        g = self.aux(f"{point.lower()}_{guide.link}", base)
        comps.append(Component(f"a_{point}{guide.link}", "absolute", "π", g, base, True))
        ak = self.coriolis(guide.link, wg, v_rel)
        k = self.aux(f"k_{name}", base + ak)
        comps.append(Component(f"a^k_{name}", "coriolis", g, k, ak, True, guide.link, abs(v_rel)))
        return k, comps, Line("∥ guide", k, self.images[k], u), g

    def rrr(self, g: RRR) -> None:
        P, Q, C = g.P, g.Q, g.C
        n1, c1, l1 = self.two_points(g.links[0], P, C)
        n2, c2, l2 = self.two_points(g.links[1], Q, C)
        c, s = self.meet(l1, l2, self.where)
        lab = self.put(C, c)
        t1, t2 = c - self.images[n1], c - self.images[n2]
        self.tangential(g.links[0], P, C, t1)
        self.tangential(g.links[1], Q, C, t2)
        comps = (c1, c2, Component(f"a^τ_{C}{P}", "tangential", n1, lab, t1, False, g.links[0], c1.factor),
                 Component(f"a^τ_{C}{Q}", "tangential", n2, lab, t2, False, g.links[1], c2.factor),
                 Component(f"a_{C}", "absolute", "π", lab, c, False))
        for link, pt in ((g.links[0], P), (g.links[0], C), (g.links[1], Q), (g.links[1], C)):
            self.member(link, pt)
        eq = f"a_{C} = a_{P} + a^n_{C}{P} + a^τ_{C}{P} = a_{Q} + a^n_{C}{Q} + a^τ_{C}{Q}"
        self.steps.append(Step(C, lab, "intersection", eq, comps, (l1, l2), sin_between=s))

    def rrp(self, g: RRP) -> None:
        P, C = g.P, g.C
        n1, c1, l1 = self.two_points(g.links[0], P, C)
        rel = self.st.relative[g._name()]
        v_rel = complex(np.broadcast_to(rel["v_rel"], self.st.phi.shape)[self.i])
        gl = g.guide.link
        k, gcomps, l2, _ = self.guide_line(g.guide, g.links[1], C, v_rel, f"{C}{C}{gl}")
        c, s = self.meet(l1, l2, self.where)
        lab = self.put(C, c)
        t1 = c - self.images[n1]
        self.tangential(g.links[0], P, C, t1)
        comps = [c1, *gcomps, Component(f"a^τ_{C}{P}", "tangential", n1, lab, t1, False, g.links[0], c1.factor)]
        eq = f"a_{C} = a_{P} + a^n_{C}{P} + a^τ_{C}{P}"
        if gl != GROUND:
            comps.append(Component(f"a^r_{C}{C}{gl}", "relative", k, lab, c - self.images[k], False))
            eq += f" = a_{C}{gl} + a^k_{C}{C}{gl} + a^r_{C}{C}{gl}"
            self.eps[g.links[1]] = self.eps[gl]          # the slider turns with its guide
        else:
            self.eps[g.links[1]] = 0.0
        comps.append(Component(f"a_{C}", "absolute", "π", lab, c, False))
        self.member(g.links[0], P)
        self.member(g.links[0], C)
        self.member(g.links[1], C)
        self.steps.append(Step(C, lab, "intersection", eq, tuple(comps), (l1, l2), sin_between=s))

    def rpr(self, g: RPR) -> None:
        P, Q, A3 = g.P, g.Q, g.coincident
        block = P if P[-1:].isdigit() else P + g.links[0]
        w3 = self.w[g.links[1]]
        v_rel = self.v[A3] - self.v[P]                      # v_A3A2
        ak = self.coriolis(g.links[1], w3, v_rel)                               # v_rel turned 90° in the sense of ω₃
        pl = self.labels[P]
        k = self.aux(f"k_{A3}{block}", self.image(P) + ak)
        u = complex(np.broadcast_to(self.st.e[g.links[1]], self.st.phi.shape)[self.i])
        l1 = Line(f"∥ {Q}{A3}", k, self.images[k], u)
        n2, c2, l2 = self.two_points(g.links[1], Q, A3)
        a3, s = self.meet(l2, l1, self.where)
        lab = self.put(A3, a3)
        t2 = a3 - self.images[n2]
        self.tangential(g.links[1], Q, A3, t2)
        self.eps[g.links[0]] = self.eps[g.links[1]]
        comps = (Component(f"a^k_{A3}{block}", "coriolis", pl, k, ak, True, g.links[1], abs(v_rel)), c2,
                 Component(f"a^r_{A3}{block}", "relative", k, lab, a3 - self.images[k], False),
                 Component(f"a^τ_{A3}{Q}", "tangential", n2, lab, t2, False, g.links[1], c2.factor),
                 Component(f"a_{A3}", "absolute", "π", lab, a3, False))
        self.member(g.links[1], Q)
        self.member(g.links[1], A3)
        self.member(g.links[0], P)
        eq = f"a_{A3} = a_{block} + a^k_{A3}{block} + a^r_{A3}{block} = a_{Q} + a^n_{A3}{Q} + a^τ_{A3}{Q}"
        self.steps.append(Step(A3, lab, "intersection", eq, comps, (l1, l2), sin_between=s))

    def prp(self, g: PRP) -> None:
        C = g.C
        rel = self.st.relative[g._name()]
        k1, cs1, l1, _ = self.guide_line(g.guide_1, g.links[0], C, self.pick(rel, "v_rel_1"), f"{C}{g.links[0]}")
        k2, cs2, l2, _ = self.guide_line(g.guide_2, g.links[1], C, self.pick(rel, "v_rel_2"), f"{C}{g.links[1]}")
        c, s = self.meet(l1, l2, self.where)
        lab = self.put(C, c)
        comps = [*cs1, *cs2, Component(f"a^r_{C}{g.links[0]}", "relative", k1, lab, c - self.images[k1], False),
                 Component(f"a^r_{C}{g.links[1]}", "relative", k2, lab, c - self.images[k2], False),
                 Component(f"a_{C}", "absolute", "π", lab, c, False)]
        for link, gd in zip(g.links, (g.guide_1, g.guide_2)):
            self.eps[link] = 0.0 if gd.link == GROUND else self.eps[gd.link]
            self.member(link, C)
        eq = f"a_{C} = {_along(g.guide_1, C, g.links[0])} = {_along(g.guide_2, C, g.links[1])}"
        self.steps.append(Step(C, lab, "intersection", eq, tuple(comps), (l1, l2), sin_between=s))

    def rpp(self, g: RPP) -> None:
        P, R, A3 = g.P, g.R, g.coincident
        block = P if P[-1:].isdigit() else P + g.links[0]
        rel = self.st.relative[g._name()]
        yoke = g.links[1]
        w = self.w[yoke]
        u2 = complex(np.broadcast_to(self.st.e[yoke], self.st.phi.shape)[self.i])
        u1 = complex(np.broadcast_to(self.st.e[g.links[0]], self.st.phi.shape)[self.i])
        v_rel = self.v[A3] - self.v[P]
        ak = self.coriolis(yoke, w, v_rel)
        pl = self.labels[P]
        k = self.aux(f"k_{A3}{block}", self.image(P) + ak)
        l1 = Line("∥ slot", k, self.images[k], u1)
        sd2 = self.pick(rel, "s2_dot")
        k2, cs2, l2, _ = self.guide_line(g.guide, yoke, A3, sd2 * u2, f"{A3}{g.guide.link}")
        a3, s = self.meet(l1, l2, self.where)
        lab = self.put(A3, a3)
        self.eps[yoke] = 0.0 if g.guide.link == GROUND else self.eps[g.guide.link]
        self.eps[g.links[0]] = self.eps[yoke]
        e = self.eps[yoke]
        aR = a3 + (1j * e - w * w) * (self.z[R] - self.z[A3])
        comps = [Component(f"a^k_{A3}{block}", "coriolis", pl, k, ak, True, yoke, abs(v_rel)), *cs2,
                 Component(f"a^r_{A3}{block}", "relative", k, lab, a3 - self.images[k], False),
                 Component(f"a^r_{A3}{g.guide.link}", "relative", k2, lab, a3 - self.images[k2], False),
                 Component(f"a_{A3}", "absolute", "π", lab, a3, False)]
        self.member(yoke, A3)
        self.member(g.links[0], P)
        eq = f"a_{A3} = a_{block} + a^k_{A3}{block} + a^r_{A3}{block} = {_along(g.guide, A3, yoke)}"
        self.steps.append(Step(A3, lab, "intersection", eq, tuple(comps), (l1, l2), sin_between=s))
        rl = self.put(R, aR)
        self.member(yoke, R)
        same = "same" if self.z[R] == self.z[A3] or (w == 0.0 and e == 0.0) else "similarity"
        self.steps.append(Step(R, rl, same, f"a_{R} = a_{A3}" if same == "same" else f"{R} on link {yoke}",
                               (Component(f"a_{R}", "absolute", "π", rl, aR, False),), on=(A3,)))

    def triad(self, g: Triad) -> None:
        """Assur's special point K (on the lines of two binary links, a point of the basic link) first,
        then the joint of the third binary link from K, then the other two from it (see
        :mod:`.groups.triad`)."""
        Ks, (i, j, k) = g.special_point(self.st)
        K, t = g.special, g.links[0]
        P, B, ks = g.outer, g.inner, g.links[1:]
        self.z[K] = complex(Ks[self.i])
        comps: list[Component] = []
        lines = []
        for x in (j, k):                     # a_K = a_Px + a^n_BxPx + a^n_KBx + a^τ (⟂ PxBx)
            n1, c1, _ = self.two_points(ks[x], P[x], B[x])
            a2 = self.normal(t, K, B[x])
            n2 = self.aux(f"n_{K}{B[x]}", self.images[n1] + a2)
            comps += [c1, Component(f"a^n_{K}{B[x]}", "normal", n1, n2, a2, True, t, abs(self.z[B[x]] - self.z[K]))]
            r = self.z[B[x]] - self.z[P[x]]
            lines.append(Line(f"⟂ {P[x]}{B[x]}", n2, self.images[n2], 1j * r / abs(r)))
        kk, s = self.meet(lines[0], lines[1], self.where)      # k: where the two dashed lines meet (its a^τ,
        lab = self.put(K, kk)                                  # mixed of two links, give no ε: not drawn)
        comps.append(Component(f"a_{K}", "absolute", "π", lab, kk, False))
        self.steps.append(Step(K, lab, "intersection",
                               f"a_{K} = a_{P[j]} + a^n_{B[j]}{P[j]} + a^n_{K}{B[j]} + a^τ = a_{P[k]} + "
                               f"a^n_{B[k]}{P[k]} + a^n_{K}{B[k]} + a^τ (Assur's point)", tuple(comps),
                               (lines[0], lines[1]), sin_between=s))
        self.member(t, K)
        for x, frm, link in ((i, K, t), (j, B[i], t), (k, B[i], t)):
            n1, c1, l1 = self.two_points(link, frm, B[x])
            n2, c2, l2 = self.two_points(ks[x], P[x], B[x])
            b, s = self.meet(l1, l2, self.where)
            lab = self.put(B[x], b)
            t1, t2 = b - self.images[n1], b - self.images[n2]
            if x == i:
                self.tangential(t, frm, B[x], t1)
            self.tangential(ks[x], P[x], B[x], t2)
            self.steps.append(Step(B[x], lab, "intersection",
                                   f"a_{B[x]} = a_{frm} + a^n_{B[x]}{frm} + a^τ_{B[x]}{frm} = a_{P[x]} + "
                                   f"a^n_{B[x]}{P[x]} + a^τ_{B[x]}{P[x]}",
                                   (c1, *((c2,) if x == i else ()),       # a^n of B_j, B_k: drawn for K
                                    *((Component(f"a^τ_{B[x]}{frm}", "tangential", n1, lab, t1, False, link,
                                                 c1.factor),) if x == i else ()),   # ε_t: from b_i's alone
                                    Component(f"a^τ_{B[x]}{P[x]}", "tangential", n2, lab, t2, False, ks[x], c2.factor),
                                    Component(f"a_{B[x]}", "absolute", "π", lab, b, False)), (l1, l2), sin_between=s))
            self.member(t, B[x])
            self.member(ks[x], P[x])
            self.member(ks[x], B[x])

    eps_1: float = 0.0
    where: str = ""

    def build(self) -> None:
        self.crank()
        for step in self.lk._steps:
            if isinstance(step, Point):
                self.point(step)
            elif isinstance(step, RRR):
                self.rrr(step)
            elif isinstance(step, RRP):
                self.rrp(step)
            elif isinstance(step, RPR):
                self.rpr(step)
            elif isinstance(step, PRP):
                self.prp(step)
            elif isinstance(step, RPP):
                self.rpp(step)
            elif isinstance(step, Triad):
                self.triad(step)
            else:                                       # pragma: no cover - every group kind is above
                raise InputError(f"no acceleration plan construction for group {step.name}")


def acceleration_plans(linkage: Linkage, *, m: int | None = None, phi: Any = None, omega_1: float = 1.0,
                       epsilon_1: float = 0.0) -> tuple[AccelerationPlan, ...]:
    """The acceleration plans of a linkage in its positions 0…m (or at given crank angles).

    Parameters
    ----------
    linkage : Linkage
    m : int, optional
        Equal crank steps per turn from position 0 (default 12).
    phi : array_like, optional
        Crank angles from +x, rad, instead of ``m``.
    omega_1 : float
        Crank speed, rad/s (> 0).
    epsilon_1 : float
        Crank angular acceleration, rad/s² (+ speeding up in the crank's sense).

    Raises
    ------
    InputError
        Bad arguments, or a position where two construction lines are parallel.

    Examples
    --------
    >>> from graphmethods.kinematics.presets import four_bar
    >>> plans = acceleration_plans(four_bar(l1=0.3, l2=0.1, l3=0.35, l4=0.25), m=12, omega_1=5.0)
    >>> len(plans), plans[3].position
    (13, 3)
    """
    if not isinstance(linkage, Linkage):
        raise InputError(f"an acceleration plan needs a Linkage (kinematics.presets, a problem file's "
                         f".linkage); got {type(linkage).__name__}")
    mo = linkage.motion(m=m if phi is None else None, phi=phi, omega_1=omega_1, epsilon_1=epsilon_1, level=1)
    st = mo._state
    out = []
    for i in range(mo.n):
        b = _Builder(linkage, st, i)
        b.eps_1 = float(epsilon_1)
        k = None if mo.index is None else int(mo.index[i])
        b.where = f"{k}" if k is not None else f"φ = {math.degrees(float(mo.phi[i])):.6g}°"
        b.build()
        out.append(AccelerationPlan(
            phi=float(mo.phi[i]), phi_from_start=float(mo.phi_from_start[i]), position=k,
            omega_1=float(omega_1), epsilon_1=float(epsilon_1), images=MappingProxyType(b.images),
            labels=MappingProxyType(b.labels), steps=tuple(b.steps), omega=MappingProxyType(dict(b.w)),
            epsilon=MappingProxyType(b.eps), lengths=MappingProxyType(b.lengths)))
    return tuple(out)


def acceleration_plan(linkage: Linkage, position: int | None = None, *, m: int | None = None,
                      phi: float | None = None, omega_1: float = 1.0, epsilon_1: float = 0.0) -> AccelerationPlan:
    """The acceleration plan of one position ``position`` of 0…m, or at one crank angle ``phi`` (rad).

    See :func:`acceleration_plans` for the arguments.

    >>> from graphmethods.kinematics.presets import slotted_lever
    >>> plan = acceleration_plan(slotted_lever(r=0.1, l_O1O3=0.3, l_O3B=0.6), 2, omega_1=10.0)
    >>> [c.symbol for c in plan.steps[1].components if c.known]
    ['a^k_A3A2', 'a^n_A3O3']
    """
    if (position is None) == (phi is None):
        raise InputError("give exactly one of position (0…m) or phi (a crank angle, rad)")
    if phi is not None:
        return acceleration_plans(linkage, phi=[phi], omega_1=omega_1, epsilon_1=epsilon_1)[0]
    mm = 12 if m is None else m
    if isinstance(position, bool) or not isinstance(position, (int, np.integer)) or not 0 <= position <= mm:
        raise InputError(f"position must be an integer from 0 to m = {mm}, got {position!r}")
    return acceleration_plans(linkage, m=mm, omega_1=omega_1, epsilon_1=epsilon_1)[int(position)]
