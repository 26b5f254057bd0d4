"""Any core :class:`~graphmethods.kinematics.linkage.Linkage` seen as a :class:`Mechanism`.

The dynamics (reduced model, study, flywheel) read a linkage through the ``Mechanism`` interface:
``positions(m=...)`` -> :class:`Positions`, ``velocity_plans(...)`` -> :class:`VelocityPlans`,
``strokes()``, ``guides``, link numbers. :class:`LinkageMechanism` gives that interface to any
linkage built from Assur groups; links are named by their textbook numbers (``"2"``), the
plans' construction records come from the groups, and accelerations are at hand through
:meth:`LinkageMechanism.motion`.

>>> from graphmethods.kinematics.presets import six_bar_press
>>> mech = LinkageMechanism(six_bar_press(points={"S4": ("CD", 0.175)}))
>>> plans = mech.velocity_plans(mech.positions(m=12), omega_1=10.0)
>>> plans.constructions["D"].equation
'v_D = v_C + v_DC;  v_D ∥ guide, v_DC ⟂ CD'
>>> float(plans.v_along_guide("D")[0]), mech.link_name(3), mech.link_name("DC")
(0.0, 'O2B', 'CD')
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Mapping
from types import MappingProxyType
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from graphmethods.errors import InputError
from graphmethods.kinematics import vectors as V
from graphmethods.kinematics.groups import GROUND, RPP, RPR, Group, State, Triad
from graphmethods.kinematics.linkage import Linkage, Motion, Point
from graphmethods.kinematics.mechanism import Mechanism, PointOnLink
from graphmethods.kinematics.plans import ConstructionLine, PointConstruction, VelocityPlans
from graphmethods.kinematics.positions import Positions, Strokes, build_positions
from graphmethods.kinematics.vectors import ComplexArray, FloatArray
from graphmethods.units import real

#: |sin| between two construction lines at or below which they are parallel (a toggle: refused)
TOGGLE_SIN = 1e-14


class _LazyConstructions(Mapping[str, PointConstruction]):
    """The plan's construction records, built on first use (the reduced model never needs them)."""

    def __init__(self, build: Callable[[], dict[str, PointConstruction]]) -> None:
        self._build = build
        self._data: dict[str, PointConstruction] | None = None

    def _get(self) -> dict[str, PointConstruction]:
        if self._data is None:
            self._data = self._build()
        return self._data

    def __getitem__(self, key: str) -> PointConstruction:
        return self._get()[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._get())

    def __len__(self) -> int:
        return len(self._get())


def _xy(c: ComplexArray) -> FloatArray:
    """Plane vectors x + iy as rows (x, y)."""
    out: FloatArray = np.column_stack((c.real, c.imag))
    return out


class LinkageMechanism(Mechanism):
    """A core linkage behind the ``Mechanism`` interface (see the module docstring).

    Parameters
    ----------
    linkage : Linkage
        The linkage.
    kind : str
        Its name in messages.
    """

    def __init__(self, linkage: Linkage, *, kind: str | None = None) -> None:
        if not isinstance(linkage, Linkage):
            raise InputError(f"expected a Linkage, got {type(linkage).__name__}")
        self.linkage = linkage
        self.kind = kind or linkage.name
        self.sense = linkage.sense
        self.working_stroke = linkage.working_stroke
        self.crank_pin = linkage.crank.pin
        self.fixed_joints = tuple(linkage.ground)
        driving = self._driving_points()
        names, joints, ends = self._link_names(driving)
        driving = driving | ends                             # a slotted link's end is a joint too (O3B)
        self._canon = names                                  # link number -> canonical name
        self._number = {v: k for k, v in names.items()}
        self.joints = self._joint_order(driving)
        self.link_joints = MappingProxyType(joints)
        self._translating = frozenset(k for k in names if self._slides_on_frame(k))
        self.link_numbers = MappingProxyType({int(k): v for k, v in names.items()
                                              if k.isdigit() and k.isascii() and k not in self._translating})
        self.points = tuple(PointOnLink(p.name, self._on(p), p.distance, p.angle) for p in linkage.points
                            if p.name not in driving)

    def _joint_order(self, driving: set[str]) -> tuple[str, ...]:
        """Joints in drawing order: the crank's centre and pin, then each group's new points followed
        by the fixed joints it hangs on and the link ends it adds (O1, A, B, O2; O1, A, A3, O3, B)."""
        lk = self.linkage
        order = [lk.crank.centre, lk.crank.pin]
        ground = set(lk.ground)
        for g in lk.groups:
            ins = g.inputs()[0]
            outs = g.outputs()[0]
            order += [k for k in outs if k not in order]
            order += sorted(k for k in ins if k in ground and k not in order)
            links = set(g.links)
            order += [p.name for p in lk.points if p.name in driving and p.link in links and p.name not in order]
        order += [k for k in lk.ground if k not in order]
        order += [p.name for p in lk.points if p.name in driving and p.name not in order]
        return tuple(order)

    @property
    def slotted_links(self) -> tuple[tuple[str, str, str, str, str], ...]:
        """Every block sliding on a slotted link that turns about a joint (the RPR groups) as
        (pin on the block, its coincident point on the slotted link, the link's pivot, block number,
        slotted link number): ``("A", "A3", "O3", "2", "3")`` for the slotted lever."""
        return tuple((g.P, g.coincident, g.Q, g.links[0], g.links[1])
                     for g in self.linkage.groups if isinstance(g, RPR))

    def _slides_on_frame(self, link: str) -> bool:
        """A slider on a guide of the frame (it translates: no angular velocity to report)."""
        from graphmethods.kinematics.groups import PRP, RRP
        for g in self.linkage.groups:
            if isinstance(g, RRP) and g.links[1] == link and g.guide.link == GROUND:
                return True
            if isinstance(g, RPP) and g.links[1] == link and g.guide.link == GROUND:
                return True
            if isinstance(g, PRP) and ((g.links[0] == link and g.guide_1.link == GROUND)
                                       or (g.links[1] == link and g.guide_2.link == GROUND)):
                return True
        return False

    def _link_names(self, driving: set[str]) -> tuple[dict[str, str], dict[str, tuple[str, str]], set[str]]:
        """Canonical names of the links as the classic classes name them: by their two joints ("AB",
        "O2B"), "block" for a block on a slotted link; and those joints."""
        from graphmethods.kinematics.groups import PRP, RRP, RRR, Triad
        lk = self.linkage
        cr = lk.crank
        names = {cr.link: cr.centre + cr.pin}
        joints = {cr.centre + cr.pin: (cr.centre, cr.pin)}
        ends_set: set[str] = set()
        blocks = [g for g in lk.groups if isinstance(g, (RPR, RPP))]
        for g in lk.groups:
            pairs: list[tuple[str, str, str]] = []
            if isinstance(g, RRR):
                pairs = [(g.links[0], g.P, g.C), (g.links[1], g.Q, g.C)]
            elif isinstance(g, Triad):           # the basic link by its first two joints, each binary link by its two
                pairs = sorted([(g.links[0], g.inner[0], g.inner[1]),
                                *((k, P, B) for k, P, B in zip(g.links[1:], g.outer, g.inner))],
                               key=lambda p: (len(p[0]), p[0]))
            elif isinstance(g, RRP):
                pairs = [(g.links[0], g.P, g.C)]
                names[g.links[1]] = f"slider{g.links[1]}"
            elif isinstance(g, RPR):
                ends = [p for p in lk.points if p.link == g.links[1] and p.origin == g.Q and p.name in driving] \
                    or [p for p in lk.points if p.link == g.links[1] and p.origin == g.Q]
                end = max(ends, key=lambda p: p.distance).name if ends else g.coincident
                pairs = [(g.links[1], g.Q, end)]
                if ends:
                    ends_set.add(end)
                names[g.links[0]] = "block" if len(blocks) == 1 else f"block{g.links[0]}"
            elif isinstance(g, RPP):
                names[g.links[0]] = "block" if len(blocks) == 1 else f"block{g.links[0]}"
                names[g.links[1]] = f"slider{g.links[1]}"
            elif isinstance(g, PRP):
                names[g.links[0]] = f"slider{g.links[0]}"
                names[g.links[1]] = f"slider{g.links[1]}"
            for num, x, y in pairs:
                names[num] = x + y
                joints[x + y] = (x, y)
        return names, joints, ends_set

    def _on(self, p: Point) -> str:
        """A point's link written by its joints, first joint = where its distance starts ("AB", "BA")."""
        canon = self._canon[p.link]
        if canon not in self.link_joints:
            return canon
        x, y = self.link_joints[canon]
        return x + y if p.origin == x else y + x if p.origin == y else canon

    def _driving_points(self) -> set[str]:
        """Extra points that later groups are driven from (they are joints: a lever's end B)."""
        used: set[str] = set()
        for g in self.linkage.groups:
            used |= g.inputs()[0]
        return {p.name for p in self.linkage.points} & used

    def __eq__(self, other: object) -> bool:
        return self is other

    def __hash__(self) -> int:
        return id(self)

    def __repr__(self) -> str:
        return f"LinkageMechanism({self.linkage.structure().formula}, {self.kind!r})"

    # ------------------------------------------------------------------ interface
    @property
    def omega_links(self) -> tuple[str, ...]:
        return tuple(self._canon[k] for k in self.linkage.links if k not in self._translating)

    def link_name(self, link: int | str) -> str:
        """Canonical name of a link given by its textbook number (3 or "3") or its joints ("AB", "BA")."""
        if isinstance(link, (int, np.integer)) and not isinstance(link, bool):
            if str(int(link)) not in self._canon:
                raise InputError(f"{self.kind}: no link number {int(link)}; links: "
                                 + ", ".join(f"{k} = {v}" for k, v in sorted(self.link_numbers.items())))
            link = str(int(link))
        if isinstance(link, str):
            if link in self._canon:
                return self._canon[link]
            if link in self._number:
                return link
            for canon, (x, y) in self.link_joints.items():
                if link in (x + y, y + x):
                    return canon
        raise InputError(f"{self.kind}: unknown link {link!r}; links: "
                         + ", ".join(f"{k} = {v}" for k, v in self._canon.items()))

    def number(self, link: int | str) -> str:
        """Textbook number (as text) of a link given by number or name."""
        return self._number[self.link_name(link)]

    @property
    def guides(self) -> dict[str, tuple[float, float]]:
        return self.linkage.guides

    def strokes(self) -> Strokes | None:
        """The output's strokes (None when it turns fully)."""
        return self.linkage.strokes()

    def motion(self, *args: Any, **kw: Any) -> Motion:
        """The core's :meth:`Linkage.motion` (accelerations included)."""
        return self.linkage.motion(*args, **kw)

    def positions(self, m: int | None = None, *, phi: ArrayLike | None = None,
                  phi_from_start: ArrayLike | None = None) -> Positions:
        """The linkage in ``m`` positions (or at the crank angles ``phi``), with the strokes' names."""
        lk = self.linkage
        mo = lk.motion(m=m, phi=phi, phi_from_start=phi_from_start, level=0)
        strokes = self.strokes() if mo.strokes is not None else None     # with this kind's names of its extremes
        start = strokes.phi_start if strokes is not None else lk._default_start()
        order = self.joints + tuple(p.name for p in self.points)
        order += tuple(k for k in mo.z if k not in order)
        geom = {k: (mo.z[k].real.copy(), mo.z[k].imag.copy()) for k in order}
        out: dict[str, Any] = {}          # the output's stroke s and H (a slider) or swing ψ and ψ_max (a rocker)
        if lk.output is not None and strokes is not None:
            if lk.output[0] == "point":
                gx, gy = lk.guides[lk.output[1]]
                zs, ze = lk._ends().z[lk.output[1]]
                d = 1.0 if ((ze - zs) * complex(gx, -gy)).real >= 0 else -1.0
                out = {"s": mo.s, "H": lk.stroke_H(), "stroke_direction": np.array([d * gx, d * gy])}
            else:
                out = {"psi": mo.psi, "psi_max": lk.psi_max()}
        pos = build_positions(self, np.array(mo.phi), m=None if mo.index is None else len(mo.phi) - 1,
                              phi_start=start, strokes=strokes, geom=geom,
                              theta={self._canon[k]: np.array(v) for k, v in mo.theta.items()
                                     if k not in self._translating},
                              phi_from_start=np.array(mo.phi_from_start), output=out)
        return pos

    def velocity_plans(self, positions: Positions | int | None = None, *, omega_1: float = 1.0,
                       sin_threshold: float = 1e-3) -> VelocityPlans:
        """The velocity plans at ``positions`` (a count, or Positions of this linkage) for the crank speed
        ``omega_1`` (rad/s)."""
        if positions is None or isinstance(positions, (int, np.integer)):
            positions = self.positions(positions)
        if not isinstance(positions, Positions) or positions.mechanism is not self:
            raise InputError("velocity_plans needs Positions of this same linkage (from self.positions(...))")
        if isinstance(omega_1, bool) or not isinstance(omega_1, (int, float, np.floating, np.integer)) \
                or omega_1 <= 0:
            raise InputError(f"omega_1 is the crank speed in rad/s and must be > 0, got {omega_1!r}")
        omega_1 = real(omega_1, "omega_1", unit="rad/s", lo=0.0, lo_open=True,
                       hint="the crank speed in rad/s")          # the number policy: finite, 1e-100 … 1e100
        lk = self.linkage
        st = lk.solve(positions.phi, omega_1=float(omega_1), level=1,
                      labels=positions.index)
        lk._snap(st, np.asarray(positions.extreme))
        n = positions.n
        extreme = np.asarray(positions.extreme)
        sins = [np.broadcast_to(np.abs(c), (n,)) for c in st.conditioning.values()]
        sin_min = np.minimum.reduce(sins) if sins else np.ones(n)
        toggle = (sin_min <= TOGGLE_SIN) & ~extreme
        if toggle.any():
            self._raise_toggle(positions, int(np.argmax(toggle)), st)
        self._snap_at_rest(st, extreme)
        constructions = _LazyConstructions(lambda: self._constructions(st))
        order = self.joints + tuple(p.name for p in self.points)
        vectors = {k: V.frozen(_xy(st.v[k])) for k in order + tuple(k for k in st.v if k not in order)}
        for g in self._triads():                          # Assur's special point, a point of the basic link
            K, _ = g.special_point(st)
            B1, t = g.inner[0], g.links[0]
            vectors[g.special] = V.frozen(_xy(st.v[B1] + 1j * st.omega[t] * (K - st.z[B1])))
        return VelocityPlans(positions=positions, omega_1=float(omega_1), sense=self.sense,
                             vectors=MappingProxyType(vectors),
                             omegas=MappingProxyType({self._canon[k]: V.frozen(np.asarray(w, float))
                                                      for k, w in st.omega.items() if k not in self._translating}),
                             constructions=constructions,
                             sin_min=V.frozen(sin_min), ill_conditioned=V.frozen(sin_min < sin_threshold),
                             sin_threshold=float(sin_threshold))

    def _triads(self) -> tuple[Triad, ...]:
        """The linkage's class III groups."""
        return tuple(g for g in self.linkage.groups if isinstance(g, Triad))

    def _raise_toggle(self, positions: Positions, i: int, st: State) -> None:
        """Refuse a position where two construction lines are parallel (a toggle), naming it."""
        from graphmethods.errors import AssemblyError
        from graphmethods.kinematics.groups import RRP, RRR
        name = min(st.conditioning, key=lambda k: float(np.broadcast_to(st.conditioning[k], (positions.n,))[i]))
        g = next((g for g in self.linkage.groups if g._name() == name), None)
        if isinstance(g, RRR):
            what = f"the links {self.link_name(g.links[0])} and {self.link_name(g.links[1])} are in line (toggle)"
        elif isinstance(g, RRP):
            what = f"the link {self.link_name(g.links[0])} stands perpendicular to the guide of {g.C} (toggle)"
        else:
            what = f"the group {name} is at a toggle"
        raise AssemblyError(f"{self.kind}: {self._where(positions.phi, positions.index, i)}: {what}; the two "
                            f"construction lines are parallel and the velocity is infinite for a turning crank; "
                            f"move the position off the toggle")

    def _at_rest(self, st: State, i: int) -> tuple[set[str], set[str]]:
        """The points and links that stand still when the output is at an extreme position: the output
        itself; a rocker's joints and points and the block sliding on it; and, when a slider on a frame
        guide stops while the link driving it turns about a fixed joint, that link as well unless the
        two are in line at position ``i`` (its velocity is ⟂ to both): the shaper's lever, not the
        Whitworth's; and a link whose
        two joints rest (the shaper's BC)."""
        from graphmethods.kinematics.groups import RRP, RRR, Triad
        lk = self.linkage
        if lk.output is None:
            return set(), set()
        kind, name = lk.output
        links: set[str] = {name} if kind == "link" else set()
        points: set[str] = set() if kind == "link" else {name}
        ground = set(lk.ground)
        for _ in range(len(lk.groups) + len(lk.points) + 1):
            before = (len(links), len(points))
            for g in lk.groups:
                if isinstance(g, RRP) and g.C in points and g.guide.link == GROUND:
                    for p in lk.points:
                        if p.name == g.P and p.origin in ground and p.link != lk.crank.link:
                            u = st.z[g.P][i] - st.z[p.origin][i]
                            w = st.z[g.C][i] - st.z[g.P][i]
                            if abs((u.conjugate() * w).imag) > 1e-9 * abs(u) * abs(w):   # not in line
                                links.add(p.link)
                if isinstance(g, RPR) and g.links[1] in links and g.Q in ground:
                    links.add(g.links[0])
                    points.add(g.coincident)
                if isinstance(g, RRR) and g.links[1] in links and g.Q in ground:
                    points.add(g.C)
                if isinstance(g, (RRP, RRR)) and g.P in points and g.C in points:
                    links.add(g.links[0])                 # a link with two points at rest rests
                if isinstance(g, Triad) and set(g.links[1:]) & links and sum(P in ground for P in g.outer) >= 2:
                    # a rocker of a triad on two fixed joints stops: the rest of it is a structure (a truss)
                    links |= {g.links[0]} | {k for k, P in zip(g.links[1:], g.outer) if P in ground}
                    points |= set(g.inner)
            points |= {p.name for p in lk.points if p.link in links and (p.origin in ground or p.origin in points)}
            if (len(links), len(points)) == before:
                break
        return links, points

    def _snap_at_rest(self, st: State, extreme: NDArray[np.bool_]) -> None:
        """At an extreme position what stands still (:meth:`_at_rest`) is put exactly at the pole."""
        if not extreme.any():
            return
        for i in np.flatnonzero(extreme):
            links, points = self._at_rest(st, int(i))
            for k in points:
                if k in st.v:
                    st.v[k] = np.array(np.broadcast_to(st.v[k], extreme.shape))
                    st.v[k][i] = 0.0
            for k in links:
                if k in st.omega:
                    st.omega[k] = np.array(np.broadcast_to(st.omega[k], extreme.shape), dtype=float)
                    st.omega[k][i] = 0.0

    def _constructions(self, st: State) -> dict[str, PointConstruction]:
        """How every point of the plan is found (built when a figure first asks for it)."""
        lk = self.linkage
        cons = [PointConstruction(name=k, method="pole", equation=f"v_{k} = 0") for k in lk.ground]
        cr = lk.crank
        cons.append(PointConstruction(name=cr.pin, method="known",
                                      equation=f"v_{cr.pin} = ω₁·l_{cr.centre}{cr.pin}, ⟂ {cr.centre}{cr.pin}, "
                                               f"in the sense of ω₁"))
        found: dict[int, str] = {}
        for step in lk._steps:
            if hasattr(step, "records"):
                for rec in step.records(st):
                    if rec.plan != "velocity":
                        continue
                    equation, rename = self._textbook(step, rec.equation)
                    lines = tuple(ConstructionLine(
                        through=found.get(id(pt)) or self._plan_label(st, pt),
                        relation="perpendicular" if lab.startswith("⟂") else "parallel",
                        to=rename.get(lab[2:], lab[2:]), point=V.frozen(_xy(pt)), direction=V.frozen(_xy(d)))
                        for lab, pt, d in rec.lines)
                    cons.append(PointConstruction(name=rec.point, method="intersection", equation=equation,
                                                  lines=lines, sin_between=V.frozen(np.asarray(rec.sin_between))))
                    found[id(rec.meet)] = rec.point.lower()   # a triad's lines pass through Assur's point
                    if isinstance(step, RPP):
                        cons.append(PointConstruction(
                            name=step.R, method="same", on=step.coincident,
                            equation=f"v_{step.R} = v_{step.coincident} (the slide translates)"))
            else:
                on = self._on(step)
                lever = next((g for g in lk.groups if isinstance(g, RPR) and g.links[1] == step.link), None)
                if lever is not None and step.origin == lever.Q and step.name in self.joints:
                    cons.append(PointConstruction(
                        name=step.name, method="proportion", on=on,
                        equation=f"p{step.name.lower()} = p{lever.coincident.lower()} · {lever.Q}{step.name}/"
                                 f"{lever.Q}{lever.P} (points of the rocker by proportion)"))
                elif lever is not None and step.origin == lever.Q and on not in self.link_joints:
                    cons.append(PointConstruction(
                        name=step.name, method="proportion", on=on,
                        equation=f"p{step.name.lower()} = p{lever.coincident.lower()} · {lever.Q}{step.name}/"
                                 f"{lever.Q}{lever.coincident} (points of the slotted link by proportion)"))
                else:
                    x = on[:len(step.origin)] if on.startswith(step.origin) else step.origin
                    y = on[len(x):]
                    ang = "" if step.angle == 0.0 else f", turned {math.degrees(step.angle):.6g}°"
                    cons.append(PointConstruction(
                        name=step.name, method="similarity", on=on,
                        equation=f"{step.name.lower()} on {x.lower()}{y.lower()}: {x.lower()}{step.name.lower()}/"
                                 f"{x.lower()}{y.lower()} = {x}{step.name}/{x}{y}{ang} (similarity theorem)"))
        extra = [p.name for p in self.points]           # points on links last, as the book adds them
        cons = [c for c in cons if c.name not in extra] + sorted(
            (c for c in cons if c.name in extra), key=lambda c: extra.index(c.name))
        return {c.name: c for c in cons}

    def _textbook(self, g: Group, equation: str) -> tuple[str, dict[str, str]]:
        """The velocity equation as the book writes it, with the directions of both vectors, for a
        group on the frame (``v_B = v_A + v_BA;  v_B ⟂ O2B, v_BA ⟂ AB``), and the renamed link of its
        construction lines (a slotted link by its pivot and the pin: O3A); else the group's own."""
        from graphmethods.kinematics.groups import RRP, RRR
        ground = self.linkage.ground
        if isinstance(g, RRR) and g.Q in ground:
            P, Q, C = g.P, g.Q, g.C
            return f"v_{C} = v_{P} + v_{C}{P};  v_{C} ⟂ {Q}{C}, v_{C}{P} ⟂ {P}{C}", {}
        if isinstance(g, RRP) and g.guide.link == GROUND:
            P, C = g.P, g.C
            return f"v_{C} = v_{P} + v_{C}{P};  v_{C} ∥ guide, v_{C}{P} ⟂ {P}{C}", {}
        if isinstance(g, RPR) and g.Q in ground:
            P, Q, co, blk = g.P, g.Q, g.coincident, g.links[0]
            return (f"v_{co} = v_{P}{blk} + v_{co}{P}{blk};  v_{co} ⟂ {Q}{P}, v_{co}{P}{blk} ∥ {Q}{P}",
                    {f"{Q}{co}": f"{Q}{P}"})
        return equation, {}

    def _plan_label(self, st: State, point_vec: ComplexArray) -> str:
        """The plan image a construction line is drawn through: p for the fixed points, else the point's."""
        for k, v in st.v.items():
            if v is point_vec:
                return "p" if k in self.linkage.ground else k.lower()
        return "p" if not np.any(point_vec) else "?"

    def derivatives(self, phi: ArrayLike) -> tuple[dict[str, FloatArray], dict[str, FloatArray]]:
        """dX/dφ and dθ/dφ of every point and link (the velocities at ω₁ = 1, counterclockwise)."""
        phi = self._angles(phi, "phi")
        st = self.linkage.solve(phi, omega_1=1.0, level=1)
        s = self.sense
        return ({k: _xy(c) * s for k, c in st.v.items()},
                {self._canon[k]: w * s for k, w in st.omega.items() if k not in self._translating})

    def _link_length(self, canon: str) -> float:  # pragma: no cover - not used by the core
        raise InputError("links of a core linkage have no single length")


__all__ = ["LinkageMechanism", "GROUND", "RPR"]
