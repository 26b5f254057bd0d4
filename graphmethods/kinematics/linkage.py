"""Any planar linkage of class II: fixed joints + a driving crank + Assur groups in solving order.

A :class:`Linkage` is solved group by group, vectorised over all positions at once: positions,
velocities and accelerations of every point, angle, ω and ε of every link, and the
construction records of the velocity and acceleration plans. The crank turns at ω₁ in its
``sense`` with the angular acceleration ε₁ (positive when it speeds up in its own sense).

The structure is an output too (:meth:`Linkage.structure`): the groups in order with class and
order, the formula as courses write it, ``I(0,1) → II(2,3) → II(4,5)``, and the degree of
freedom by Chebyshev's formula W = 3n − 2p₅ − p₄.

The output (the last slider on the frame, or the last link pivoted on the frame) has its
extreme positions found numerically to machine precision (:meth:`Linkage.strokes`); positions
0…m are numbered from the start of the working stroke, in the crank's sense.

>>> import math
>>> from graphmethods.kinematics.groups import RRP, Guide
>>> press = Linkage(ground={"O": (0.0, 0.0)}, crank=Crank("O", "A", r=0.1),
...                 groups=[RRP(P="A", C="B", l=0.4, guide=Guide("0", 0j, 0.0), links=("2", "3"))],
...                 points=[Point("S2", link="2", origin="A", distance=0.13)])
>>> press.structure().formula
'I(0,1) → II(2,3)'
>>> mo = press.motion(m=12, omega_1=10.0)
>>> mo.xy("B")[0].tolist(), mo.v("B")[0].tolist()      # far dead centre
([0.5, 0.0], [0.0, 0.0])
>>> round(float(mo.a("B")[0, 0]), 12)                 # −ω²r(1 + r/l)
-12.5
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections import OrderedDict
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, cast

import numpy as np
import numpy.typing as npt

from graphmethods.errors import AssemblyError, InputError
from graphmethods.kinematics.groups.base import GROUND, Group, Guide, Record, State, check_length, fmt
from graphmethods.kinematics.positions import Strokes, at_extremes
from graphmethods.units import MAX_POSITIONS_COMPUTED, count, is_finite, real

TWO_PI = 2.0 * math.pi

#: what a geometry's full-turn check and dead centres found, shared by every Linkage of the same numbers
#: (a figure, a class set or a problem read afresh builds the same linkage again and again); the key is
#: :meth:`Linkage.geometry_key`, the value a dict of "full_turn" (None, or the AssemblyError's message),
#: "extremes" and "strokes". Bounded: the least recently used geometry goes first.
_GEOMETRY: OrderedDict[tuple[Any, ...], dict[str, Any]] = OrderedDict()
_GEOMETRY_SIZE = 512


def _numbers(obj: Any) -> Any:
    """A hashable value holding every number of a frozen dataclass (its type and fields, nested), or
    None when some field is not hashable or not a dataclass field (such a linkage is not shared)."""
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        out: list[Any] = [type(obj).__qualname__]
        for f in dataclasses.fields(obj):
            v = _numbers(getattr(obj, f.name))
            if v is None:
                return None
            out.append((f.name, v))
        return tuple(out)
    if isinstance(obj, (tuple, list)):
        items = [_numbers(v) for v in obj]
        return None if any(v is None for v in items) else (type(obj).__name__, tuple(items))
    if isinstance(obj, (str, int, float, complex, bool)) or obj is None:
        return ("value", obj)
    return None


@dataclass(frozen=True)
class Crank:
    """The driving link (class I mechanism): pin = centre + r·(cos φ, sin φ).

    Attributes
    ----------
    centre : str
        The fixed joint it turns about.
    pin : str
        Its moving joint (the crank pin, A).
    r : float
        Length, m.
    link : str
        Textbook number (``"1"``).
    """

    centre: str
    pin: str
    r: float
    link: str = "1"

    def __post_init__(self) -> None:
        object.__setattr__(self, "r", check_length(f"crank {self.centre}{self.pin}", self.r))


@dataclass(frozen=True)
class Point:
    """An extra point fixed on a link (a centre of mass, a coupler point, the end of a lever).

    It lies ``distance`` (m) from the link's point ``origin`` at ``angle`` (rad) from the link's
    own direction (for a link P–C found by a group, the direction P→C; for a slotted link the
    slot's direction; for the crank the direction centre→pin). Its velocity and acceleration
    follow by similarity: ``v = v_origin + ω × r``, ``a = a_origin + ε × r − ω²·r``.
    """

    name: str
    link: str
    origin: str
    distance: float
    angle: float = 0.0

    @functools.cached_property
    def offset(self) -> complex:
        """distance·e^(i·angle): the point from its origin in the link's own frame (x along the link)."""
        return self.distance * complex(math.cos(self.angle), math.sin(self.angle))

    def __post_init__(self) -> None:
        object.__setattr__(self, "distance", check_length(f"point {self.name}: distance", self.distance,
                                                          positive=False))
        object.__setattr__(self, "angle", check_length(f"point {self.name}: angle", self.angle, positive=False))
        if self.distance < 0:
            raise InputError(f"point {self.name}: distance must be ≥ 0 m (turn the angle by π instead), "
                             f"got {self.distance}")


@dataclass(frozen=True)
class GroupInfo:
    """One structural group: its class, order, kind and links."""

    kind: str
    cls: int
    order: int
    links: tuple[str, ...]


@dataclass(frozen=True)
class Structure:
    """The structural analysis of a linkage.

    Attributes
    ----------
    groups : tuple of GroupInfo
        The driving mechanism (class I: frame and crank) and the Assur groups, in solving order.
    formula : str
        As courses write it: ``"I(0,1) → II(2,3) → II(4,5)"``.
    n_moving : int
        Number of moving links n.
    p_lower, p_higher : int
        Lower (revolute, prismatic) pairs p₅ and higher pairs p₄.
    dof : int
        Chebyshev's degree of freedom W = 3n − 2p₅ − p₄.
    mechanism_class : int
        The highest class of its groups.
    """

    groups: tuple[GroupInfo, ...]
    formula: str
    n_moving: int
    p_lower: int
    p_higher: int
    dof: int
    mechanism_class: int


@dataclass(frozen=True, eq=False)
class Motion:
    """A linkage solved at n positions (see :meth:`Linkage.motion`). SI units, counterclockwise +.

    Attributes
    ----------
    linkage : Linkage
    phi : ndarray (n,)
        Crank angles from +x, rad.
    phi_from_start : ndarray (n,)
        Crank rotation from position 0 in the crank's sense, rad.
    index : ndarray (n,) of int or None
        Textbook position numbers 0…m (None at arbitrary angles).
    omega_1, epsilon_1 : float
        Crank speed (rad/s, > 0, in its sense) and angular acceleration (rad/s², + speeding up).
    points : tuple of str
        Every point, in solving order (fixed joints first).
    z, v_, a_ : mapping name -> complex ndarray (n,)
        Positions (m), velocities (m/s), accelerations (m/s²) as x + iy; :meth:`xy`, :meth:`v`,
        :meth:`a` give them as (n, 2) arrays.
    theta, omega, epsilon : mapping link -> ndarray (n,)
        Link angles (rad), angular velocities (rad/s), angular accelerations (rad/s²).
    relative : mapping group -> mapping
        Sliding quantities of each group (relative velocity and acceleration, Coriolis terms).
    conditioning : ndarray (n,)
        Smallest |sin| between two construction lines over the groups (1 with no group).
    extreme : ndarray (n,) of bool
        Positions at an extreme position of the output (to 1e-13 rad).
    strokes : Strokes or None
    """

    linkage: Linkage
    phi: np.ndarray
    phi_from_start: np.ndarray
    index: np.ndarray | None
    omega_1: float
    epsilon_1: float
    points: tuple[str, ...]
    z: Mapping[str, np.ndarray]
    v_: Mapping[str, np.ndarray]
    a_: Mapping[str, np.ndarray]
    theta: Mapping[str, np.ndarray]
    omega: Mapping[str, np.ndarray]
    epsilon: Mapping[str, np.ndarray]
    relative: Mapping[str, Mapping[str, Any]]
    conditioning: np.ndarray
    extreme: np.ndarray
    strokes: Strokes | None
    _state: Any = None

    @property
    def n(self) -> int:
        return int(self.phi.shape[0])

    def _get(self, table: Mapping[str, np.ndarray], name: str, what: str) -> np.ndarray:
        try:
            c = table[name]
        except KeyError:
            raise InputError(f"no point {name!r} in this linkage; points: {', '.join(self.points)}") from None
        return np.column_stack((c.real, c.imag))

    def xy(self, name: str) -> np.ndarray:
        """Coordinates of ``name``, (n, 2), m."""
        return self._get(self.z, name, "position")

    def v(self, name: str) -> np.ndarray:
        """Velocity of ``name``, (n, 2), m/s."""
        return self._get(self.v_, name, "velocity")

    def a(self, name: str) -> np.ndarray:
        """Acceleration of ``name``, (n, 2), m/s²."""
        return self._get(self.a_, name, "acceleration")

    def link(self, number: int | str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(θ, ω, ε) of link ``number`` (textbook number, ``"2"`` or 2)."""
        key = str(number)
        if key not in self.omega:
            raise InputError(f"no link {number!r}; links: {', '.join(self.omega)}")
        return self.theta[key], self.omega[key], self.epsilon[key]

    def records(self) -> tuple[Record, ...]:
        """The construction records of every group's velocity and acceleration plans, in order."""
        out = []
        for g in self.linkage.groups:
            out.extend(cast(Any, g).records(self._state))    # every dyad has records()
        return tuple(out)

    @property
    def s(self) -> np.ndarray | None:
        """Output slider's displacement from the start of the working stroke (m, + in the working
        sense), or None."""
        return self.linkage._output_s(self)

    @property
    def psi(self) -> np.ndarray | None:
        """Output rocker's angle from its start extreme (rad, + in the working sense), or None."""
        return self.linkage._output_psi(self)


#: Most Assur groups a linkage may have (textbook mechanisms: one to five; each group's checks cost a solve)
MAX_GROUPS = 64


class Linkage:
    """A planar linkage: fixed joints, a crank, class-II groups in solving order, extra points.

    Parameters
    ----------
    ground : mapping name -> (x, y)
        The fixed joints, m.
    crank : Crank
        The driving link.
    groups : sequence of Group
        The Assur groups in the order they are solved (each needs only what is known before it).
    points : sequence of Point, optional
        Extra points on the links.
    sense : int
        +1: the crank turns counterclockwise; −1 clockwise.
    output : str, optional
        The output: a point on a guide of the frame (``"B"``) or a link number (``"3"``); by
        default the last group's slider on the frame, else its link pivoted on the frame.
    working_stroke : str
        ``"slow"`` (default), ``"fast"``, ``"toward_crank"`` or ``"away_from_crank"`` (a slider
        output: the stroke toward the crank's centre starts at the farther extreme).
    name : str
        For messages.
    start : float
        Crank angle of position 0 (rad) when the output has no extreme positions (it turns fully).
    swing : (float, float), optional
        A driver that swings (a lever, a rocker) between these absolute angles (rad, first < second):
        m positions spread over the range, angles outside it refused, no strokes; None: a full turn.
    """

    def __init__(self, *, ground: Mapping[str, tuple[float, float]], crank: Crank, groups: Sequence[Group] = (),
                 points: Iterable[Point] = (), sense: int = 1, output: str | None = None,
                 working_stroke: str = "slow", name: str = "linkage", start: float = 0.0,
                 swing: tuple[float, float] | None = None) -> None:
        if isinstance(sense, bool) or sense not in (1, -1):
            raise InputError(f"{name}: sense must be +1 (counterclockwise) or -1 (clockwise), got {sense!r}")
        if working_stroke not in ("slow", "fast", "toward_crank", "away_from_crank"):
            raise InputError(f"{name}: working_stroke must be slow, fast, toward_crank or away_from_crank; "
                             f"got {working_stroke!r}")
        if len(groups) > MAX_GROUPS:
            raise InputError(f"{name}: {len(groups)} Assur groups; at most {MAX_GROUPS} are accepted (MAX_GROUPS: a "
                             f"machine of the course has two to five)")
        self.name = name
        self.swing = None if swing is None else (float(swing[0]), float(swing[1]))
        if self.swing is not None and not (math.isfinite(self.swing[0]) and math.isfinite(self.swing[1])
                                           and 0.0 < self.swing[1] - self.swing[0]
                                           <= TWO_PI + 1e-12 * (1.0 + abs(self.swing[0]))):
            raise InputError(f"{name}: the driver's range must be two finite angles a < b ≤ a + 360°, got {swing!r}")
        self._start = float(_norm(start))
        self.sense = int(sense)
        self.working_stroke = working_stroke
        self.ground: dict[str, complex] = {}
        for k, xy in ground.items():
            try:
                x, y = (float(c) for c in xy)
            except (TypeError, ValueError):
                raise InputError(f"{name}: fixed joint {k!r} must be (x, y) in m, got {xy!r}") from None
            if not (is_finite(x) and is_finite(y)):
                raise InputError(f"{name}: fixed joint {k!r} must have finite coordinates, got {xy!r}")
            self.ground[str(k)] = complex(x, y)
        self.crank = crank
        self.groups = tuple(groups)
        self.points = tuple(points)
        self._check_order()
        self.output = self._choose_output(output)
        self._cache: dict[Any, Any] = {}
        key = self.geometry_key()
        self._geometry: dict[str, Any] = {}
        if key is not None:
            got = _GEOMETRY.get(key)
            if got is None:
                got = _GEOMETRY[key] = {}
                if len(_GEOMETRY) > _GEOMETRY_SIZE:
                    _GEOMETRY.popitem(last=False)
            else:
                _GEOMETRY.move_to_end(key)
            self._geometry = got

    def geometry_key(self) -> tuple[Any, ...] | None:
        """Every number and choice that fixes the linkage's motion (fixed joints, crank, groups, extra points,
        sense, start, working stroke, output) as one hashable key, or None when a group is not a frozen
        dataclass of numbers. Two linkages with the same key share their full-turn check and dead centres.

        Examples
        --------
        >>> from graphmethods.kinematics.presets import six_bar_press
        >>> six_bar_press().geometry_key() == six_bar_press().geometry_key() is not None
        True
        """
        parts = [_numbers(self.crank), _numbers(list(self.groups)), _numbers(list(self.points))]
        if any(p is None for p in parts):
            return None
        return (tuple(sorted((k, v.real, v.imag) for k, v in self.ground.items())), *parts, self.sense,
                self._start, self.working_stroke, self.output, self.swing)

    # ------------------------------------------------------------------ structure
    def _check_order(self) -> None:
        """Check that every group needs only what is known before it; place each extra point right
        after its link is known (so a later group can be driven from it: the end of a lever)."""
        known_pts = set(self.ground)
        if self.crank.centre not in self.ground:
            raise InputError(f"{self.name}: the crank turns about {self.crank.centre!r}, which is not a fixed joint "
                             f"({', '.join(self.ground)})")
        if self.crank.pin in known_pts:
            raise InputError(f"{self.name}: the crank pin {self.crank.pin!r} is already a fixed joint")
        known_pts.add(self.crank.pin)
        known_links = {GROUND, self.crank.link}
        pending = list(self.points)
        names = [p.name for p in pending]
        dup = sorted({x for x in names if names.count(x) > 1})
        if dup:
            raise InputError(f"{self.name}: extra point {dup[0]!r} is given twice")
        steps: list[Any] = []                       # the dyads (their solving methods) and the points

        def place() -> None:
            moved = True
            while moved:
                moved = False
                for p in list(pending):
                    if p.link in known_links and p.link != GROUND and p.origin in known_pts:
                        if p.name in known_pts:
                            raise InputError(f"{self.name}: extra point {p.name!r} clashes with a joint or point name")
                        steps.append(p)
                        known_pts.add(p.name)
                        pending.remove(p)
                        moved = True

        place()
        for g in self.groups:
            if not isinstance(g, Group):
                raise InputError(f"{self.name}: {g!r} is not an Assur group")
            pts, links = g.inputs()
            missing = sorted(p for p in pts if p not in known_pts)
            if missing:
                raise InputError(f"{self.name}: group {g.name} needs {', '.join(missing)}, which no earlier group "
                                 f"or point finds; list the groups in solving order")
            lmiss = sorted(k for k in links if k not in known_links)
            if lmiss:
                raise InputError(f"{self.name}: group {g.name} needs link {', '.join(lmiss)} solved before it")
            outs, new_links = g.outputs()
            for p in outs:
                if p in known_pts or p in names:
                    raise InputError(f"{self.name}: point {p!r} of group {g.name} is already defined")
                known_pts.add(p)
            for k in new_links:
                if k in known_links:
                    raise InputError(f"{self.name}: link {k!r} of group {g.name} is already numbered")
                known_links.add(k)
            steps.append(g)
            place()
        for p in pending:
            if p.link not in known_links or p.link == GROUND:
                raise InputError(f"{self.name}: point {p.name!r} is on link {p.link!r}, which is not a moving link "
                                 f"({', '.join(sorted(known_links - {GROUND}))})")
            raise InputError(f"{self.name}: point {p.name!r} is measured from {p.origin!r}, which is not a "
                             f"point of the linkage")
        self._steps = tuple(steps)
        self._r = np.array(self.crank.r)            # an operand numpy takes faster than a float (see _I)
        self._links = tuple(sorted(known_links - {GROUND}, key=lambda k: (len(k), k)))

    @property
    def links(self) -> tuple[str, ...]:
        """Textbook numbers of the moving links."""
        return self._links

    def structure(self) -> Structure:
        """Groups in order with class and order, the structural formula, Chebyshev's W.

        >>> from graphmethods.kinematics.presets import six_bar_press
        >>> s = six_bar_press().structure()
        >>> s.formula, s.dof, s.n_moving, s.p_lower
        ('I(0,1) → II(2,3) → II(4,5)', 1, 5, 7)
        """
        infos = [GroupInfo("crank", 1, 0, ("0", self.crank.link))]
        parts = [f"I(0,{self.crank.link})"]
        p5 = 1
        roman = {1: "I", 2: "II", 3: "III"}
        for g in self.groups:
            infos.append(GroupInfo(g.kind, g.cls, g.order, tuple(g.links)))
            shown = g.links if g.cls == 2 else sorted(g.links, key=lambda k: (len(k), k))   # III(2,3,4,5)
            parts.append(f"{roman.get(g.cls, str(g.cls))}({','.join(shown)})")
            p5 += len(g.pairs)
        n = len(self.links)
        return Structure(groups=tuple(infos), formula=" → ".join(parts), n_moving=n, p_lower=p5, p_higher=0,
                         dof=3 * n - 2 * p5, mechanism_class=max((g.cls for g in self.groups), default=1))

    def _choose_output(self, output: str | None) -> tuple[str, str] | None:
        guides = self.guides
        if output is not None:
            output = str(output)
            if output in guides:
                return ("point", output)
            if output in self.links:
                return ("link", output)
            raise InputError(f"{self.name}: output {output!r} is neither a slider on a guide of the frame "
                             f"({', '.join(guides) or 'none'}) nor a link ({', '.join(self.links)})")
        for g in reversed(self.groups):
            for p, _ in self._group_sliders(g):
                return ("point", p)
            for link, _pivot in self._group_rockers(g):
                return ("link", link)
        return None

    @staticmethod
    def _group_sliders(g: Group) -> Iterator[tuple[str, Guide]]:
        from graphmethods.kinematics.groups import PRP, RPP, RRP
        if isinstance(g, RRP) and g.guide.link == GROUND:
            yield g.C, g.guide
        elif isinstance(g, RPP) and g.guide.link == GROUND:
            yield g.R, g.guide
        elif isinstance(g, PRP):
            for gd in (g.guide_1, g.guide_2):
                if gd.link == GROUND:
                    yield g.C, gd
                    break

    def _group_rockers(self, g: Group) -> Iterator[tuple[str, str]]:
        from graphmethods.kinematics.groups import RPR, RRR, Triad
        if isinstance(g, Triad):
            for k, P in zip(g.links[1:], g.outer):
                if P in self.ground:
                    yield k, P
        elif isinstance(g, RRR):
            if g.Q in self.ground:
                yield g.links[1], g.Q
            elif g.P in self.ground:
                yield g.links[0], g.P
        elif isinstance(g, RPR) and g.Q in self.ground:
            yield g.links[1], g.Q

    @property
    def guides(self) -> dict[str, tuple[float, float]]:
        """Sliders on guides of the frame -> unit direction of the guide."""
        out = {}
        for g in self.groups:
            for p, gd in self._group_sliders(g):
                out[p] = (math.cos(gd.angle), math.sin(gd.angle))
        return out

    @property
    def pivots(self) -> dict[str, str]:
        """Links pivoted on the frame (other than the crank) -> their fixed joint."""
        out = {}
        for g in self.groups:
            for link, pivot in self._group_rockers(g):
                out[link] = pivot
        return out

    # ------------------------------------------------------------------ solving
    def solve(self, phi: npt.ArrayLike, *, omega_1: float = 1.0, epsilon_1: float = 0.0, level: int = 2,
              labels: np.ndarray | None = None, upto: Group | None = None) -> State:
        """Solve the linkage at crank angles ``phi`` (rad); level 0 positions, 1 + velocities,
        2 + accelerations. Returns the raw :class:`~graphmethods.kinematics.groups.State`.

        What is the same at every position is a read-only array (n,) that from
        :data:`SHARED_FROM` positions up takes no memory per position (stride 0): the fixed joints'
        positions, their zero velocities and accelerations, the crank's ω and ε. A read-only
        ``phi`` is the crank's angle as it is (else a copy).

        >>> from graphmethods.kinematics.presets import six_bar_press
        >>> st = six_bar_press().solve([0.0, 1.0], omega_1=10.0)
        >>> st.z["O2"].tolist(), st.omega["1"].tolist(), st.omega["1"].flags.writeable
        ([(0.25+0.1j), (0.25+0.1j)], [10.0, 10.0], False)
        """
        phi = np.asarray(phi, dtype=float)
        if phi.ndim != 1:
            phi = phi.reshape(-1)
        n = phi.shape[0]
        st = State(phi=phi, labels=labels)
        if self._triads:
            st.track.update(self._tracks() if upto is None else self._cache.get("tracks", {}))
        fixed, zero_c = self._fixed(n)
        for k, z in fixed.items():
            st.z[k] = z                              # a point of the result, the same at every position
            st.v[k] = zero_c
            st.a[k] = zero_c
        cr = self.crank
        Om = self.sense * float(omega_1)
        Ep = self.sense * float(epsilon_1)
        e = np.exp(_I * phi)
        st.z[cr.pin] = st.z[cr.centre] + self._r * e
        st.theta[cr.link] = phi if not phi.flags.writeable else phi.copy()
        st.e[cr.link] = e
        for step in self._steps:
            if step is upto:
                return st                            # the outer joints of a triad, for its track
            if isinstance(step, Point):
                st.z[step.name] = st.z[step.origin] + step.offset * st.e[step.link]
            else:
                step.positions(st)
        if level >= 1:
            st.omega[cr.link] = self._kept_constant(Om, n)
            st.v[cr.pin] = 1j * Om * cr.r * e
            self._velocities(st)
        if level >= 2:
            st.epsilon[cr.link] = self._kept_constant(Ep, n)
            st.a[cr.pin] = (1j * Ep - Om * Om) * cr.r * e
            self._accelerations(st)
        return st

    @functools.cached_property
    def _triads(self) -> tuple[Group, ...]:
        """The class III groups, which solve their positions from a track (:mod:`.groups.triad`)."""
        return tuple(g for g in self.groups if g.cls == 3)

    def _tracks(self) -> dict[str, Any]:
        """Each triad's drawn assembly continued over the crank's motion, made once, in solving order
        (a triad's outer joints may hang on an earlier triad)."""
        tracks: dict[str, Any] | None = self._cache.get("tracks")
        if tracks is None or len(tracks) < len(self._triads):
            tracks = self._cache["tracks"] = {}
            try:
                for g in self._triads:
                    tracks[g._name()] = cast(Any, g).track(
                        lambda phi, g=g: self.solve(phi, level=0, upto=g))
            except AssemblyError as exc:
                del self._cache["tracks"]
                raise AssemblyError(f"{self.name}: {exc}") from None
        return tracks

    def _kept_constant(self, value: float, n: int) -> np.ndarray:
        """The crank's ω or ε at every position (see :func:`_constant`), kept for up to 16 (value, n)
        below :data:`SHARED_FROM`, as a course asks for the same crank speed again and again."""
        if n >= SHARED_FROM:
            return _constant(value, n)
        kept: dict[tuple[int, str], np.ndarray] = self._cache.setdefault("constants", {})
        key = (n, value.hex())                      # the exact value: −0.0 is not 0.0
        a = kept.get(key)
        if a is None:
            if len(kept) >= 16:
                kept.clear()
            a = kept[key] = _constant(value, n)
        return a

    def _fixed(self, n: int) -> tuple[dict[str, np.ndarray], np.ndarray]:
        """The fixed joints' positions and their zero velocity as read-only arrays (n,) (see
        :func:`_constant`), kept for up to 8 sizes below :data:`SHARED_FROM`."""
        kept: dict[int, tuple[dict[str, np.ndarray], np.ndarray]] = self._cache.setdefault("fixed", {})
        if n in kept:
            return kept[n]
        made = {k: _constant(c, n) for k, c in self.ground.items()}, _constant(0j, n)
        if n < SHARED_FROM:
            if len(kept) >= 8:
                kept.clear()
            kept[n] = made
        return made

    def _velocities(self, st: State) -> None:
        """The velocities of every point and link after the crank's (v = v_O + ω × r on a link)."""
        for step in self._steps:
            if isinstance(step, Point):
                r = st.z[step.name] - st.z[step.origin]
                st.v[step.name] = st.v[step.origin] + _I * st.omega[step.link] * r
            else:
                step.velocities(st)

    def _accelerations(self, st: State) -> None:
        """The accelerations of every point and link after the crank's (a = a_O + ε × r − ω²·r)."""
        for step in self._steps:
            if isinstance(step, Point):
                r = st.z[step.name] - st.z[step.origin]
                w = st.omega[step.link]
                st.a[step.name] = st.a[step.origin] + (_I * st.epsilon[step.link] - w * w) * r
            else:
                step.accelerations(st)

    def _check_phi(self, values: npt.ArrayLike, name: str) -> np.ndarray:
        """Crank angles (rad) as a new 1-D float array; InputError if empty or not finite."""
        try:
            a = np.array(values, dtype=float)
        except (TypeError, ValueError):
            raise InputError(f"{name}: crank angles must be numbers in rad, got {values!r}") from None
        if a.ndim != 1:
            a = a.reshape(-1)
        if a.size == 0:
            raise InputError(f"{name}: give at least one crank angle")
        if np.count_nonzero(np.isfinite(a)) != a.size:
            bad = ~np.isfinite(a)
            raise InputError(f"{name}: angle #{int(np.argmax(bad))} is {a[bad][0]!r}; angles must be finite (rad)")
        return a

    def _crank_angles(self, m: int | None, phi: npt.ArrayLike | None, phi_from_start: npt.ArrayLike | None,
                      start: float) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
        """(φ from +x, rotation from position 0, position numbers or None) for :meth:`motion`: new
        arrays, read-only."""
        labels = None
        if self.swing is not None:
            return self._swing_angles(m, phi, phi_from_start)
        if phi is None and phi_from_start is None:
            m = _count_positions(m, 3)
            self.check_full_turn()
            labels = np.arange(m + 1)
            tr = (TWO_PI / m) * labels
            tr[m] = TWO_PI
            ang = _norm_in_place(np.multiply(tr, self.sense) + start)
            ang[m] = ang[0]
        elif phi_from_start is not None:
            tr = self._check_phi(phi_from_start, "phi_from_start")
            ang = _norm_in_place(np.multiply(tr, self.sense) + start)
        else:
            assert phi is not None
            ang = self._check_phi(phi, "phi")
            tr = ang - start
            if self.sense < 0:
                np.negative(tr, out=tr)
            np.mod(tr, TWO_PI, out=tr)
            np.putmask(tr, tr > TWO_PI - 1e-13, 0.0)
        return _freeze(ang), _freeze(tr), None if labels is None else _freeze(labels)

    def _swing_angles(self, m: int | None, phi: npt.ArrayLike | None, phi_from_start: npt.ArrayLike | None
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
        """:meth:`_crank_angles` of a swinging driver: m equal steps from the range's start to its end, or the
        angles given, each taken into the range (modulo 360°) or refused."""
        assert self.swing is not None
        a, b = self.swing
        labels = None
        if phi is None and phi_from_start is None:
            m = _count_positions(m, 1)
            self.check_full_turn()
            labels = np.arange(m + 1)
            ang = a + (b - a) * (labels / m)
            ang[m] = b
        else:
            given = phi_from_start if phi_from_start is not None else phi
            assert given is not None
            ang = self._check_phi(given, "phi_from_start" if phi is None else "phi") + (a if phi is None else 0.0)
            ang = a + np.mod(ang - a, TWO_PI)
            tol = 1e-12 * max(1.0, abs(a), abs(b))
            ang = np.where(ang > TWO_PI + a - tol, a, ang)
            bad = ang > b + tol
            if bad.any():
                x = float(np.degrees(ang[bad][0]))
                raise InputError(f"{self.name}: the driver's angle {x % 360:.6g}° lies outside its range "
                                 f"[{math.degrees(a):.6g}°, {math.degrees(b):.6g}°] (range_deg)")
            ang = np.minimum(ang, b)
            self.check_full_turn()
        return _freeze(ang), _freeze(ang - a), None if labels is None else _freeze(labels)

    def _grid(self, m: int | None, phi: npt.ArrayLike | None, phi_from_start: npt.ArrayLike | None,
              strokes: Strokes | None) -> tuple[np.ndarray, np.ndarray, np.ndarray | None, np.ndarray]:
        """(φ, rotation from position 0, position numbers or None, at an extreme) for :meth:`motion`,
        read-only; the grid of m equal steps is kept per m (up to :data:`SHARED_FROM` positions), as
        a course asks for the same 12 positions again and again."""
        key = ("grid", m) if phi is None and phi_from_start is None else None
        if key in self._cache:
            return self._cache[key]                 # type: ignore[no-any-return]
        start = strokes.phi_start if strokes is not None else self._default_start()
        ang, tr, labels = self._crank_angles(m, phi, phi_from_start, start)
        grid = ang, tr, labels, _freeze(at_extremes(ang, strokes))   # before solving: adds to no peak
        if key is not None and ang.shape[0] < SHARED_FROM:
            self._cache[key] = grid
        return grid

    def motion(self, m: int | None = None, *, phi: npt.ArrayLike | None = None,
               phi_from_start: npt.ArrayLike | None = None, omega_1: float = 1.0, epsilon_1: float = 0.0,
               level: int = 2) -> Motion:
        """The linkage at m + 1 positions 0…m (or at given crank angles), with velocities and
        accelerations.

        Parameters
        ----------
        m : int, optional
            Equal crank steps per turn (≥ 3) from the start of the working stroke (default 12).
        phi : array_like, optional
            Crank angles from +x, rad, instead.
        phi_from_start : array_like, optional
            Crank rotation from position 0 in the crank's sense, rad, instead.
        omega_1 : float
            Crank speed, rad/s (> 0; 1 gives the velocity analogues).
        epsilon_1 : float
            Crank angular acceleration, rad/s², positive when speeding up.
        level : int
            2 (default): positions, velocities and accelerations; 1: no accelerations; 0: positions only.

        Raises
        ------
        AssemblyError
            A position where a group cannot be assembled or is at a toggle (named).

        Examples
        --------
        >>> from graphmethods.kinematics.presets import six_bar_press
        >>> mo = six_bar_press().motion(m=12, omega_1=10.0)
        >>> mo.n, int(mo.index[-1]), bool(mo.extreme[0]), float(mo.v("D")[0, 0])
        (13, 12, True, 0.0)
        """
        for nm, val, pos in (("omega_1", omega_1, True), ("epsilon_1", epsilon_1, False)):
            if isinstance(val, bool) or not isinstance(val, (int, float, np.floating, np.integer)):
                raise InputError(f"{nm} must be a finite number{' > 0 (rad/s)' if pos else ' (rad/s²)'}, got {val!r}")
            real(val, nm, unit="rad/s" if pos else "rad/s²", lo=0.0 if pos else None, lo_open=pos)   # 1e100 policy
        omega_1, epsilon_1 = float(omega_1), float(epsilon_1)
        if (m is not None) + (phi is not None) + (phi_from_start is not None) > 1:
            raise InputError("give only one of m, phi or phi_from_start")
        if m is not None and (isinstance(m, bool) or not isinstance(m, (int, np.integer)) or m < 3):
            raise InputError(f"the number of positions m must be an integer ≥ 3, got {m!r}")   # before it is a key
        strokes = self.strokes()
        ang, tr, labels, extreme = self._grid(m, phi, phi_from_start, strokes)
        st = self.solve(ang, omega_1=omega_1, epsilon_1=epsilon_1, labels=labels, level=level)
        if strokes is not None:
            self._snap(st, extreme)
        ro = MappingProxyType
        return Motion(linkage=self, phi=ang, phi_from_start=tr, index=labels, omega_1=float(omega_1),
                      epsilon_1=float(epsilon_1), points=tuple(st.z), z=ro(st.z), v_=ro(st.v), a_=ro(st.a),
                      theta=ro(st.theta), omega=ro(st.omega), epsilon=ro(st.epsilon), relative=ro(st.relative),
                      conditioning=_freeze(_smallest(st.conditioning, ang.shape[0])), extreme=extreme,
                      strokes=strokes, _state=st)

    def _snap(self, st: State, mask: np.ndarray) -> None:
        """At the extreme positions the output stands still exactly (as the plan draws it)."""
        if not np.count_nonzero(mask) or self.output is None:
            return
        kind, name = self.output
        if kind == "point":
            if name in st.v:
                st.v[name] = np.where(mask, 0j, st.v[name])
        elif name in st.omega:
            st.omega[name] = np.where(mask, 0.0, st.omega[name])

    # ------------------------------------------------------------------ full turn, extremes
    def _output(self) -> tuple[str, str]:
        """The output, (``"point"``, name) or (``"link"``, number), where one is known to exist."""
        assert self.output is not None, f"{self.name}: no output (neither a slider on the frame nor a rocker)"
        return self.output

    def _default_start(self) -> float:
        return self._start

    def check_full_turn(self, samples: int = 2048) -> None:
        """Raise AssemblyError if some group cannot be assembled, or passes a toggle, somewhere in a
        full crank turn (its assembly margin reaches zero, where the branch could jump).

        Checked once per geometry (see :meth:`geometry_key`): ``samples`` positions in one solve, then the
        smallest margin of every group refined at once, each round solving 33 angles per group across its
        bracket (:func:`_refine_minima`), to 1e-15 rad."""
        if "full_turn" in self._cache:
            return
        if "full_turn" not in self._geometry:
            self._geometry["full_turn"] = self._find_toggle(samples)
        message = self._geometry["full_turn"]
        if message is not None:
            raise AssemblyError(message)
        self._cache["full_turn"] = True

    def _find_toggle(self, samples: int) -> str | None:
        """The AssemblyError's message for the first group that reaches a toggle in a full turn (or in a
        swinging driver's range), or None."""
        a0, span = (0.0, TWO_PI) if self.swing is None else (self.swing[0], self.swing[1] - self.swing[0])
        phi = a0 + np.linspace(0.0, span, samples, endpoint=self.swing is not None)
        try:
            if self.swing is not None:
                self._check_swing_assembles(phi)
            st = self.solve(phi, level=0)               # raises at a sample that cannot assemble
            if not self.groups:
                return None
            margins = [g.margin(st) for g in self.groups]
            scales = [float(np.max(np.abs(mg))) or 1.0 for mg in margins]
            centres = np.array([phi[int(np.argmin(mg))] for mg in margins])
            x, smallest = _refine_minima(self._own_margins, centres, span / samples)
        except AssemblyError as exc:
            return str(exc)
        for k, g in enumerate(self.groups):
            if smallest[k] > 1e-12 * scales[k]:
                continue
            if self.swing is not None:
                return (f"{self.name}: the driver's range reaches a toggle of group {g.name} at "
                        f"φ = {math.degrees(x[k]):.6g}° (its links come in line): the assembly would jump; "
                        f"narrow range_deg to stay clear of it")
            return (f"{self.name}: group {g.name} reaches a toggle at φ = {math.degrees(x[k]) % 360:.6g}° "
                    f"(its links come in line): the crank cannot turn through it on one branch, "
                    f"the assembly would jump; change the lengths or study the range with phi=")
        return None

    def _own_margins(self, phi: np.ndarray) -> np.ndarray:
        """Row k: group k's assembly margin at the angles of row k of ``phi`` (all rows in one solve; a
        swinging driver's angles held inside its range)."""
        if self.swing is not None:
            phi = np.clip(phi, self.swing[0], self.swing[1])
        st = self.solve(phi.reshape(-1), level=0)
        return np.stack([g.margin(st).reshape(phi.shape)[k] for k, g in enumerate(self.groups)])

    def _check_swing_assembles(self, phi: np.ndarray) -> None:
        """A swinging driver's range that leaves the assembly: refused at the angle where it does (bisected
        between the last sample that assembles and the first that does not, from the range's start)."""
        def ok(x: float) -> bool:
            try:
                self.solve(np.array([x]), level=0)
            except AssemblyError:
                return False
            return True

        good = np.array([ok(float(x)) for x in phi[:: max(1, phi.size // 256)]] + [ok(float(phi[-1]))])
        if good.all():
            return
        xs = np.append(phi[:: max(1, phi.size // 256)], phi[-1])
        j = int(np.argmin(good))
        lo, hi = (float(xs[j - 1]), float(xs[j])) if j > 0 else (float(xs[0]), float(xs[0]))
        if j > 0 and good[j - 1]:
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if ok(mid) else (lo, mid)
        raise AssemblyError(f"{self.name}: the driver's range reaches a toggle at φ = {math.degrees(lo):.6g}°: beyond "
                            f"it the linkage cannot be assembled; narrow range_deg to stay clear of it")

    def _out_value(self, st: State) -> tuple[Any, Any, Any]:
        """(coordinate, its derivative, its second derivative) of the output over the positions."""
        kind, name = self._output()
        if kind == "point":
            gx, gy = self.guides[name]
            u = complex(gx, gy)

            def c(z: Any) -> Any:
                return z.real * u.real + z.imag * u.imag

            return c(st.z[name]), c(st.v.get(name, st.z[name])), c(st.a.get(name, st.z[name]))
        return st.theta[name], st.omega.get(name), st.epsilon.get(name)

    def extremes(self) -> tuple[float, float] | None:
        """Crank angles (rad) where the output is at its largest and smallest coordinate (its
        dead centres), found to machine precision; None if the output turns fully or there is no
        output."""
        if "extremes" in self._cache:
            return self._cache["extremes"]            # type: ignore[no-any-return]
        if "extremes" in self._geometry:
            res: tuple[float, float] | None = self._geometry["extremes"]
        else:
            res = None
            if self.output is not None and self.swing is None:
                res = self._find_extremes()
            self._geometry["extremes"] = res
        self._cache["extremes"] = res
        return res

    def _find_extremes(self) -> tuple[float, float] | None:
        N = 720
        phi = np.linspace(0.0, TWO_PI, N, endpoint=False)
        try:
            self.check_full_turn()
            st = self.solve(phi, omega_1=1.0, epsilon_1=0.0)
        except AssemblyError:
            return None                 # the crank cannot turn fully: no strokes (study a range with phi=)
        _, f, _ = self._out_value(st)
        f1 = np.roll(f, -1)
        idx = np.flatnonzero((f == 0.0) | (np.sign(f) * np.sign(f1) < 0))
        if idx.size == 0:
            return None
        lo = phi[idx].copy()
        hi = lo + TWO_PI / N
        flo = f[idx].copy()
        x = np.where(flo == 0.0, lo, 0.5 * (lo + hi))
        for _ in range(100):
            s2 = self.solve(x, omega_1=1.0, epsilon_1=0.0)
            _, fx, dfx = self._out_value(s2)
            same = np.sign(fx) == np.sign(flo)
            lo = np.where(same & (fx != 0), x, lo)
            flo = np.where(same & (fx != 0), fx, flo)
            hi = np.where(~same & (fx != 0), x, hi)
            with np.errstate(divide="ignore", invalid="ignore"):
                xn = x - fx / dfx
            ok = np.isfinite(xn) & (xn >= lo) & (xn <= hi)
            xn = np.where(ok, xn, 0.5 * (lo + hi))
            xn = np.where(fx == 0.0, x, xn)
            if np.all(np.abs(xn - x) <= 1e-15 * (1 + np.abs(x))):
                x = xn
                break
            x = xn
        s3 = self.solve(x, level=0)
        c, _, _ = self._out_value(s3)
        if self._output()[0] == "link":
            c = np.unwrap(c) if c.size > 1 else c
        i_max, i_min = int(np.argmax(c)), int(np.argmin(c))
        if i_max == i_min:
            return None
        return float(_norm(x[i_max])), float(_norm(x[i_min]))

    def strokes(self) -> Strokes | None:
        """The extreme positions of the output, the working and return crank angles and K."""
        if "strokes" in self._cache:
            return self._cache["strokes"]             # type: ignore[no-any-return]
        if "strokes" in self._geometry:               # found for a linkage of the same numbers
            shared: Strokes | None = self._geometry["strokes"]
            self._cache["strokes"] = shared
            return shared
        ext = self.extremes()
        res = None
        if ext is not None:
            pa, pb = ext                           # coordinate max, min
            na, nb = "output at its largest coordinate", "output at its smallest coordinate"
            if self._output()[0] == "point":
                na, nb = "dead centre (slider at +guide end)", "dead centre (slider at −guide end)"
            t_ab = float(np.mod(self.sense * (pb - pa), TWO_PI))
            ws = self.working_stroke
            far_a = self._farther_at(pa, pb)
            if ws in ("toward_crank", "away_from_crank") and self._output()[0] == "point":
                start_a = far_a if ws == "toward_crank" else not far_a
            elif abs(t_ab - math.pi) < 1e-12:
                start_a = far_a                    # equal strokes: start where the output is farther out
            elif ws == "fast":
                start_a = t_ab < math.pi
            else:
                start_a = t_ab > math.pi
            if abs(t_ab - math.pi) < 1e-12:
                t_ab = math.pi                     # equal strokes (to the precision of the extremes)
            if start_a:
                start, end, w, ns, ne = pa, pb, t_ab, na, nb
            else:
                start, end, w, ns, ne = pb, pa, TWO_PI - t_ab, nb, na
            res = Strokes(phi_start=float(_norm(start)), phi_end=float(_norm(end)), working_angle=w,
                          return_angle=TWO_PI - w, K=w / (TWO_PI - w), start_name=ns, end_name=ne)
        self._cache["strokes"] = self._geometry["strokes"] = res
        return res

    def _farther_at(self, pa: float, pb: float) -> bool:
        """Is the output's joint (the slider, or the rocker's moving joint) farther from the crank's
        centre at crank angle ``pa`` than at ``pb``? (the far dead centre, crank and coupler extended)
        Kept per (pa, pb): the classic kinds ask it for the names of their extremes at every call."""
        key = ("farther", pa, pb)
        if key not in self._cache:
            self._cache[key] = self._find_farther(pa, pb)
        return bool(self._cache[key])

    def _find_farther(self, pa: float, pb: float) -> bool:
        kind, name = self._output()
        joint: str | None = name
        if kind == "link":
            joint = next((g.outputs()[0][list(g.links).index(name) - 1 if g.cls == 3 else 0]
                          for g in self.groups if name in g.links), None)
        if joint is None:
            return True
        st = self.solve(np.array([pa, pb]), level=0)
        da, db = np.abs(st.z[joint] - self.ground[self.crank.centre])
        return bool(da >= db)

    # ------------------------------------------------------------------ outputs
    def _ends(self) -> State:
        """The linkage at the start and the end of the working stroke (cached)."""
        if "ends" not in self._cache:
            st_ = self.strokes()
            assert st_ is not None, "only an output with a working stroke has ends"
            self._cache["ends"] = self.solve(np.array([st_.phi_start, st_.phi_end]), level=0)
        return self._cache["ends"]                    # type: ignore[no-any-return]

    def _output_s(self, mo: Motion) -> np.ndarray | None:
        if self.output is None or self.output[0] != "point" or mo.strokes is None:
            return None
        name = self.output[1]
        st = self._ends()
        gx, gy = self.guides[name]
        u = complex(gx, gy)
        zs, ze = st.z[name]
        d = 1.0 if ((ze - zs) * u.conjugate()).real >= 0 else -1.0
        s: np.ndarray = d * (((mo.z[name] - zs) * u.conjugate()).real)
        return s

    def _output_ends(self, kind: str) -> tuple[Any, Any] | None:
        """The output's position at the start and at the end of the working stroke, when the output
        is of ``kind``: the slider's point z ("point") or the rocker's angle θ ("link"); else None."""
        if self.strokes() is None or self._output()[0] != kind:
            return None
        ends = self._ends()
        start, end = (ends.z if kind == "point" else ends.theta)[self._output()[1]]
        return start, end

    def stroke_H(self) -> float | None:
        """The output slider's stroke H, m (None for a rocker output)."""
        ends = self._output_ends("point")
        return None if ends is None else float(abs(ends[1] - ends[0]))

    def _output_psi(self, mo: Motion) -> np.ndarray | None:
        if self.output is None or self.output[0] != "link" or mo.strokes is None:
            return None
        link = self.output[1]
        st = self._ends()
        th_s, th_e = st.theta[link]
        swing = float(_wrap(th_e - th_s))
        sign = 1.0 if swing >= 0 else -1.0
        psi = sign * _wrap(mo.theta[link] - th_s)
        return np.where(np.abs(psi) < 1e-15, 0.0, psi)

    def psi_max(self) -> float | None:
        """The output rocker's swing, rad (None for a slider output)."""
        ends = self._output_ends("link")
        return None if ends is None else float(abs(_wrap(ends[1] - ends[0])))


def _count_positions(m: int | None, low: int) -> int:
    """The number of positions m (12 when None): an integer ≥ ``low``, else InputError."""
    m = 12 if m is None else m
    if isinstance(m, bool) or not isinstance(m, (int, np.integer)) or m < low:
        raise InputError(f"the number of positions m must be an integer ≥ {low}, got {m!r}")
    return count(m, "the number of positions m", low=low, high=MAX_POSITIONS_COMPUTED)


def _norm(a: npt.ArrayLike) -> Any:
    """Angle(s) in [0, 2π) (rad), −0 written 0: a float for a scalar, else a new array."""
    b = np.mod(np.asarray(a, dtype=float), TWO_PI)
    return np.where(b >= TWO_PI, 0.0, b) + 0.0


def _norm_in_place(a: np.ndarray) -> np.ndarray:
    """:func:`_norm` of a new float array, in place (no temporaries)."""
    np.mod(a, TWO_PI, out=a)
    np.putmask(a, a >= TWO_PI, 0.0)
    a += 0.0
    return a


def _wrap(a: npt.ArrayLike) -> Any:
    """Angle(s) in [−π, π) (rad)."""
    return np.mod(np.asarray(a, dtype=float) + np.pi, TWO_PI) - np.pi


#: i as a 0-d array: numpy takes it as an operand about 0.3 µs faster than the Python number 1j,
#: with the same value, so the same results to the bit.
_I = np.array(1j)
_I.flags.writeable = False

#: From this many positions up, a value the same at every position is one number seen n times
#: (stride 0); below, a filled array is quicker to make.
SHARED_FROM = 4096


def _constant(value: complex | float, n: int) -> np.ndarray:
    """A read-only array (n,) of ``value`` (complex or float): see :data:`SHARED_FROM`."""
    if n >= SHARED_FROM:
        return np.broadcast_to(value, (n,))
    a = np.empty(n, dtype=complex if isinstance(value, complex) else float)
    a.fill(value)
    a.flags.writeable = False
    return a


def _refine_minima(f: Any, centres: np.ndarray, half_width: float, *, points: int = 33,
                   tol: float = 1e-15) -> tuple[np.ndarray, np.ndarray]:
    """Local minima of k functions at once, each near its own centre: ``f`` maps angles of shape (k, n) to
    values of the same shape (row k: function k). Each round evaluates ``points`` angles across every
    bracket in one call and narrows each bracket to the two steps around its smallest value, until the
    brackets are ``tol`` wide (relative). Returns the angles and the values there.

    >>> x, v = _refine_minima(lambda a: (a - np.array([[0.3], [1.0]])) ** 2, np.array([0.31, 0.99]), 0.05)
    >>> bool(np.abs(x - [0.3, 1.0]).max() < 1e-14), bool(v.max() < 1e-28)
    (True, True)
    """
    c = np.array(centres, dtype=float)
    h = np.full(c.shape, float(half_width))
    steps = np.linspace(-1.0, 1.0, points)
    best = np.asarray(f(c[:, None]))[:, 0]
    for _ in range(60):
        ang = c[:, None] + h[:, None] * steps
        vals = np.asarray(f(ang))
        i = np.argmin(vals, axis=1)
        rows = np.arange(c.size)
        better = vals[rows, i] <= best
        c = np.where(better, ang[rows, i], c)
        best = np.where(better, vals[rows, i], best)
        h = 2.0 * h / (points - 1)
        if np.all(h <= tol * (1.0 + np.abs(c))):
            break
    return c, best


def _freeze(a: np.ndarray) -> np.ndarray:
    """Make a new array of ours read-only in place (no copy) and return it."""
    a.flags.writeable = False
    return a


def _smallest(values: Mapping[str, np.ndarray], n: int) -> np.ndarray:
    """The groups' conditioning, position by position the smallest (a new array, or a view of the one group's;
    ones with no group)."""
    arrays = list(values.values())
    if not arrays:
        return np.ones(n)
    if len(arrays) == 1:
        view: np.ndarray = np.asarray(arrays[0]).view()      # the group's own array, not a copy (frozen as a view)
        return view
    out: np.ndarray = np.minimum(arrays[0], arrays[1])
    for a in arrays[2:]:
        np.minimum(out, a, out=out)
    return out


__all__ = ["Crank", "GroupInfo", "Linkage", "Motion", "Point", "Structure", "fmt"]
