"""What every structural group shares: the state it reads and writes, its records, small solvers.

A linkage is solved group by group in the order of its structural formula. Every group reads
the points and links already known from a :class:`State` and adds its own: for each point its
position ``z``, velocity ``v`` and acceleration ``a`` as complex arrays (x + iy, m, m/s, m/s²),
for each link its angle ``theta``, angular velocity ``omega`` and angular acceleration
``epsilon`` (rad, rad/s, rad/s², counterclockwise +), all of shape (n,) over the positions.

Plane vectors as complex numbers make the textbook's rules one-liners: a vector turned 90°
counterclockwise is ``1j * r``; the velocity of a point X of a link that turns at ω about a
point O of it is ``v_O + 1j*omega*(X - O)`` and its acceleration
``a_O + (1j*epsilon - omega**2)*(X - O)`` (a^τ + a^n).

>>> import numpy as np
>>> x, y, det = solve2(np.array([1 + 0j]), np.array([1j]), np.array([2 - 3j]))
>>> float(x[0]), float(y[0]), float(det[0])
(2.0, -3.0, 1.0)
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any, ClassVar, TypedDict, cast

import numpy as np
from numpy.typing import NDArray

from graphmethods.errors import AssemblyError, InputError
from graphmethods.kinematics.structure import GROUND as GROUND  # the frame's number, for the groups' users
from graphmethods.kinematics.vectors import ComplexArray, FloatArray
from graphmethods.units import is_finite

#: Below this many positions a group keeps what its velocity solution found (its arms and the two
#: construction lines with their cross product) in :attr:`State.kept` for its acceleration
#: solution, which uses the same lines; from here up it computes them again, so that they take no
#: memory meanwhile (the same value as ``kinematics.linkage.SHARED_FROM``).
KEEP_BELOW = 4096

#: a plane vector over the positions, or one for all of them (a guide on the frame: it broadcasts)
Vec = ComplexArray | complex
#: a real value over the positions, or one for all of them (the turning of the frame: 0)
Real = FloatArray | float
#: a kinematic pair: (kind "R" or "P", link, link, joint), "?" where the link is whatever carries the joint
Pair = tuple[str, str, str, str]
#: the known vectors of a plan's equation by name
Known = tuple[tuple[str, ComplexArray], ...]
#: the two construction lines of a plan: (label, a point of the line, its unit direction)
Lines = tuple[tuple[str, ComplexArray, ComplexArray], ...]


class Sliding(TypedDict, total=False):
    """A group's sliding quantities over the positions (:attr:`State.relative`), as its plans use them.

    Real arrays: the slider's coordinate along its guide ``s`` (m) and its derivatives ``s_dot``
    (m/s), ``s_ddot`` (m/s²), numbered ``_1``/``_2`` where a group has two guides. Complex arrays
    (plane vectors): the slot's direction ``u``; the relative velocity and acceleration along the
    guide ``v_rel``, ``a_rel``; the guide's point under the slider ``v_guide``, ``a_guide``; the
    Coriolis terms ``a_coriolis`` (of the guide's own point: ``a_coriolis_guide``).
    """

    s: FloatArray
    s_dot: FloatArray
    s_ddot: FloatArray
    s1: FloatArray
    s2: FloatArray
    s1_dot: FloatArray
    s2_dot: FloatArray
    s1_ddot: FloatArray
    s2_ddot: FloatArray
    u: ComplexArray
    v_rel: ComplexArray
    v_guide: ComplexArray
    a_rel: ComplexArray
    a_guide: ComplexArray
    a_coriolis: ComplexArray
    a_coriolis_guide: ComplexArray
    v_rel_1: ComplexArray
    v_rel_2: ComplexArray
    v_guide_1: ComplexArray
    v_guide_2: ComplexArray
    a_rel_1: ComplexArray
    a_rel_2: ComplexArray
    a_guide_1: ComplexArray
    a_guide_2: ComplexArray
    a_coriolis_1: ComplexArray
    a_coriolis_2: ComplexArray


class Relative(dict[str, Any]):
    """A group's sliding quantities (:class:`Sliding`), some not stored but computed when first asked for:
    the relative velocity and acceleration along the guide from what is stored (``v_rel = s_dot·u``,
    ``a_rel = s_ddot·u``), and whatever the group names in :attr:`lazy` (a key → a function of no
    arguments). Each is the product the group would have stored, so the same bits; once asked for, it is
    kept.

    >>> import numpy as np
    >>> rel = Relative(s_dot=np.array([2.0]), u=np.array(1j))
    >>> "v_rel" in rel, "a_rel" in rel, rel["v_rel"].tolist()
    (True, False, [2j])
    """

    DERIVED: ClassVar[dict[str, str]] = {"v_rel": "s_dot", "a_rel": "s_ddot"}

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.lazy: dict[str, Any] = {}

    def _derivable(self, key: object) -> bool:
        if key in self.lazy:
            return True
        base = self.DERIVED.get(key) if isinstance(key, str) else None
        return base is not None and dict.__contains__(self, base) and dict.__contains__(self, "u")

    def __contains__(self, key: object) -> bool:
        return dict.__contains__(self, key) or self._derivable(key)

    def __missing__(self, key: str) -> Any:
        if not self._derivable(key):
            raise KeyError(key)
        value = self.lazy.pop(key)() if key in self.lazy else self[self.DERIVED[key]] * self["u"]
        self[key] = value
        return value


def cross(a: Vec, b: Vec) -> FloatArray:
    """z-component of a × b for complex plane vectors (Im(conj(a)·b))."""
    out: FloatArray = np.asarray(a.real * b.imag - a.imag * b.real, dtype=float)
    return out


def dot(a: Vec, b: Vec) -> FloatArray:
    """Scalar product of complex plane vectors (Re(conj(a)·b))."""
    out: FloatArray = np.asarray(a.real * b.real + a.imag * b.imag, dtype=float)
    return out


def solve2(e1: Vec, e2: Vec, rhs: Vec, det: FloatArray | None = None) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Real x, y with ``x·e1 + y·e2 = rhs`` (complex plane vectors, vectorised).

    Returns ``(x, y, det)`` with ``det = e1 × e2``; where det is 0 the values are not finite
    (callers check ``det`` first). A ``det`` given is that of the same ``e1``, ``e2``, already
    checked to be nonzero at every position (the acceleration plan's lines are the velocity
    plan's): it is used as it is.
    """
    if det is not None:
        return cross(rhs, e2) / det, cross(e1, rhs) / det, det
    det = np.asarray(cross(e1, e2))
    if np.count_nonzero(det) == det.size:         # every position solvable (as det.all(), without its wrapper)
        return cross(rhs, e2) / det, cross(e1, rhs) / det, det
    with np.errstate(divide="ignore", invalid="ignore"):
        x = cross(rhs, e2) / det
        y = cross(e1, rhs) / det
    return x, y, det


def broadcast(st: State, rel: Sliding) -> Sliding:
    """A group's sliding quantities, each broadcast to the n positions (read-only views)."""
    # cast: broadcasting keeps each item's dtype, so the items keep their types
    return cast(Sliding, {k: np.broadcast_to(np.asarray(v), (st.n,)) for k, v in rel.items()})


def fmt(x: float) -> str:
    """A length or number for a message (6 significant digits)."""
    return f"{x:.6g}"


class _Angles(dict[str, FloatArray]):
    """Link angles computed when first asked for, from the links' unit directions."""

    def __init__(self, directions: dict[str, Vec], n: tuple[int, ...]) -> None:
        super().__init__()
        self._e = directions
        self._n = n

    def __missing__(self, link: str) -> FloatArray:
        if link not in self._e:
            raise KeyError(link)
        th: FloatArray = np.angle(np.broadcast_to(self._e[link], self._n))
        self[link] = th
        return th

    def __contains__(self, link: object) -> bool:
        return dict.__contains__(self, link) or link in self._e

    def keys(self) -> list[str]:  # type: ignore[override]  # a list in solving order, not a live view
        return list(dict.fromkeys([*self._e, *dict.keys(self)]))     # solving order, however they were asked for

    def __iter__(self) -> Iterator[str]:
        return iter(self.keys())

    def items(self) -> list[tuple[str, FloatArray]]:  # type: ignore[override]  # a list, as keys()
        return [(k, self[k]) for k in self.keys()]

    def values(self) -> list[FloatArray]:  # type: ignore[override]  # a list, as keys()
        return [self[k] for k in self.keys()]

    def __len__(self) -> int:
        return len(self.keys())


@dataclass
class State:
    """Points and links of a linkage over n positions (mutable while the groups solve it).

    Attributes
    ----------
    phi : ndarray (n,)
        Crank angles, rad.
    labels : ndarray (n,) of int or None
        Textbook position numbers (for messages), else None.
    z, v, a : dict name -> complex ndarray (n,)
        Position (m), velocity (m/s), acceleration (m/s²) of every point.
    e : dict link -> complex ndarray (n,)
        Unit direction of every link (its own direction: P→C, the slot, the guide).
    theta, omega, epsilon : dict link -> ndarray (n,)
        Angle (rad, computed from ``e`` when asked for), angular velocity (rad/s), angular
        acceleration (rad/s²) of every link.
    relative : dict name -> Sliding
        Per group, the sliding quantities (relative velocity and acceleration along a guide,
        Coriolis terms) as complex arrays.
    conditioning : dict group name -> ndarray (n,)
        |sin| of the angle between the two construction lines of the group's plan.
    kept : dict group name -> tuple
        What a group's velocity solution leaves for its acceleration solution (below
        :data:`KEEP_BELOW` positions); the acceleration solution takes it out.
    track : dict group name -> Track
        A triad's drawn assembly continued over the crank's motion (:mod:`.triad`), which its
        positions start Newton's method from.
    """

    phi: FloatArray
    labels: NDArray[np.integer[Any]] | None = None
    z: dict[str, ComplexArray] = field(default_factory=dict)
    v: dict[str, ComplexArray] = field(default_factory=dict)
    a: dict[str, ComplexArray] = field(default_factory=dict)
    e: dict[str, Vec] = field(default_factory=dict)
    theta: dict[str, FloatArray] = field(default_factory=dict)
    omega: dict[str, FloatArray] = field(default_factory=dict)
    epsilon: dict[str, FloatArray] = field(default_factory=dict)
    relative: dict[str, Sliding] = field(default_factory=dict)
    conditioning: dict[str, FloatArray] = field(default_factory=dict)
    kinematic: bool = True
    kept: dict[str, tuple[Any, ...]] = field(default_factory=dict, repr=False)
    track: dict[str, Any] = field(default_factory=dict, repr=False)

    def keep(self, group: str, values: tuple[Any, ...]) -> None:
        """Keep a group's intermediate ``values`` for its next step (below :data:`KEEP_BELOW` positions)."""
        if self.phi.shape[0] < KEEP_BELOW:
            self.kept[group] = values

    @property
    def zeros(self) -> FloatArray:
        """A read-only array of n zeros (the angular velocity of a translating link) that holds no memory:
        one 0.0 seen n times (a broadcast view)."""
        z: FloatArray | None = self.__dict__.get("_zeros")
        if z is None:
            z = np.broadcast_to(np.zeros(()), self.phi.shape)
            self.__dict__["_zeros"] = z
        return z

    def zeros_complex(self) -> ComplexArray:
        """A read-only complex array of n zeros holding no memory (a guide of the frame: its point's velocity,
        acceleration and Coriolis term)."""
        z: ComplexArray | None = self.__dict__.get("_zeros_complex")
        if z is None:
            z = np.broadcast_to(np.zeros((), dtype=complex), self.phi.shape)
            self.__dict__["_zeros_complex"] = z
        return z

    def __post_init__(self) -> None:
        angles = _Angles(self.e, self.phi.shape)
        angles.update(self.theta)
        self.theta = angles

    @property
    def n(self) -> int:
        """Number of positions."""
        return int(self.phi.shape[0])

    def where(self, i: int) -> str:
        """'position 3 (φ = 210°)' or 'angle #3 (φ = 210°)' for messages."""
        deg = math.degrees(float(self.phi[i])) % 360.0
        pos = f"position {int(self.labels[i])}" if self.labels is not None else f"angle #{i}"
        return f"{pos} (φ = {deg:.6g}°)"


@dataclass(frozen=True)
class Guide:
    """A straight guide (slot, slideway) fixed on a link.

    Attributes
    ----------
    link : str
        The link that carries the guide (``"0"``: the frame).
    through : str or complex
        A point of that link the guide line passes through: a joint name, or for the frame
        its coordinates (complex, m).
    angle : float
        Direction of the guide, rad: from +x for the frame, from the link's own angle for a
        moving link.
    """

    link: str
    through: str | complex
    angle: float = 0.0

    @functools.cached_property
    def turn(self) -> complex:
        """The guide's direction in the frame of its link, e^(i·angle)."""
        return complex(math.cos(self.angle), math.sin(self.angle))

    def line(self, st: State) -> tuple[Vec, Vec, Real, Real]:
        """(G, u, omega, epsilon): a point of the line, its unit direction, and the turning of the
        link that carries it (zeros for the frame), each over the positions."""
        G = st.z[self.through] if isinstance(self.through, str) else complex(self.through)
        turn = self.turn
        if self.link == GROUND:
            return G, turn, 0.0, 0.0          # scalars: they broadcast over the positions
        return G, st.e[self.link] * turn, st.omega.get(self.link, 0.0), st.epsilon.get(self.link, 0.0)

    def kinematics(self, st: State) -> tuple[Vec, Vec]:
        """(v_G, a_G): velocity and acceleration of the guide's point (zeros for the frame)."""
        if isinstance(self.through, str):
            return st.v[self.through], st.a.get(self.through, 0j)
        return 0j, 0j

    def describe(self) -> str:
        """'guide on link 3 through B at 90°' for messages."""
        where = self.through if isinstance(self.through, str) else f"({fmt(complex(self.through).real)}, " \
                                                                   f"{fmt(complex(self.through).imag)})"
        on = "the frame" if self.link == GROUND else f"link {self.link}"
        return f"guide on {on} through {where} at {fmt(math.degrees(self.angle))}°"


@dataclass(frozen=True, eq=False)
class Record:
    """How one unknown of a plan is found (the textbook's construction), over all positions.

    Attributes
    ----------
    point : str
        The point found (its plan image is the lower-case name).
    plan : str
        ``"velocity"`` or ``"acceleration"``.
    equation : str
        The vector equation as courses write it, e.g. ``"v_C = v_B + v_CB"``.
    known : tuple of (str, ndarray)
        The known vectors of the equation by name (complex (n,), SI), e.g.
        ``(("v_B", vB),)`` or ``(("a_B", aB), ("a^n_CB", aCBn))``.
    lines : tuple of (str, ndarray, ndarray)
        The two construction lines: a label (``"⟂ BC"``, ``"∥ guide"``), a point the line passes
        through in the plan (complex (n,)) and its unit direction (complex (n,)).
    meet : ndarray
        Where the lines meet (the unknown vector), complex (n,).
    sin_between : ndarray
        Sine of the angle between the lines (0 at a toggle).
    """

    point: str
    plan: str
    equation: str
    known: Known
    lines: Lines
    meet: ComplexArray
    sin_between: FloatArray


@dataclass(frozen=True)
class Joints:
    """How a group hangs in the linkage: the ``known`` joints it is attached at (P, Q), the points it
    ``found`` (C; or R and the coincident point) and the ``guides`` its sliders move along."""

    known: tuple[str, ...] = ()
    found: tuple[str, ...] = ()
    guides: tuple[Guide, ...] = ()


class Group:
    """Base of the structural groups (class II dyads): see the subclasses.

    Subclasses are frozen dataclasses with a field ``links`` (the two textbook link numbers) and
    set ``kind`` (``"RRR"``, ...) and ``pairs``; and implement :meth:`joints` (the joints it is attached
    at and finds, the guides it slides on), ``positions``, ``velocities``, ``accelerations`` and
    ``records``. :meth:`inputs` and :meth:`outputs` follow from :meth:`joints`.
    """

    kind = "?"
    links: tuple[str, str] = ("", "")
    branch: int = 1
    #: Assur's class and order of the group (a dyad: II, 2; a triad: III, 3)
    cls = 2
    order = 2

    @property
    def pairs(self) -> tuple[Pair, ...]:
        """(pair kind, link, link, joint) for its three kinematic pairs: "R" revolute, "P" prismatic."""
        return ()

    def joints(self) -> Joints:  # pragma: no cover - interface
        """The known joints the group is attached at, the points it finds and the guides it slides on."""
        raise NotImplementedError

    def inputs(self) -> tuple[set[str], set[str]]:
        """(points, links) the group needs known: its joints, the guides' points and the links carrying them."""
        j = self.joints()
        points = set(j.known) | {g.through for g in j.guides if isinstance(g.through, str)}
        return points, {g.link for g in j.guides} - {GROUND}

    # The points are typed Any for now: kinematics.linkage (another branch's module) reuses one loop variable for
    # these names and then for its Point records (Linkage.__post_init__), which a str here would flag; tighten to
    # tuple[tuple[str, ...], tuple[str, str]] once that loop variable is renamed.
    def outputs(self) -> tuple[tuple[Any, ...], tuple[str, str]]:
        """(points, links) the group adds."""
        return self.joints().found, self.links

    def positions(self, st: State) -> None:  # pragma: no cover - interface
        """Add the group's points and link directions to ``st``."""
        raise NotImplementedError

    def velocities(self, st: State) -> None:  # pragma: no cover - interface
        """Add the velocities of its points and the angular velocities of its links to ``st``."""
        raise NotImplementedError

    def accelerations(self, st: State) -> None:  # pragma: no cover - interface
        """Add the accelerations of its points and the angular accelerations of its links to ``st``."""
        raise NotImplementedError

    def records(self, st: State) -> tuple[Record, ...]:  # pragma: no cover - interface
        """How the plans find its points (velocity, and acceleration once solved)."""
        raise NotImplementedError

    @property
    def name(self) -> str:
        """'RRR (2, 3)'."""
        return f"{self.kind} ({self.links[0]}, {self.links[1]})"

    def _name(self) -> str:
        cached: str | None = self.__dict__.get("_cached_name")
        if cached is None:
            cached = self.name
            object.__setattr__(self, "_cached_name", cached)
        return cached

    def _check(self, field_name: str, label: str, *, positive: bool = True) -> None:
        """Replace the length field ``field_name`` by its checked float (frozen dataclass: on construction)."""
        object.__setattr__(self, field_name, check_length(label, getattr(self, field_name), positive=positive))

    def _check_branch(self) -> None:
        """Replace the field ``branch`` by its checked value (+1 or −1)."""
        object.__setattr__(self, "branch", check_branch(self.name, self.branch))

    def fail(self, st: State, bad: NDArray[np.bool_], why: Callable[[int], str]) -> None:
        """Raise AssemblyError at the first position where ``bad`` holds; ``why(i)`` explains it."""
        if np.count_nonzero(bad):
            i = int(np.argmax(bad))
            raise AssemblyError(f"group {self.name}: cannot be assembled at {st.where(i)}: {why(i)}")

    def check_det(self, st: State, det: FloatArray, what: str) -> None:
        """Refuse a position where the two construction lines are exactly parallel (a toggle)."""
        det = np.asarray(det)
        if np.count_nonzero(det) == det.size:
            return
        bad = (det == 0.0) | ~np.isfinite(det)
        if bad.any():
            i = int(np.argmax(bad))
            raise AssemblyError(f"group {self.name}: at {st.where(i)} {what}: the two construction lines are "
                                f"parallel and the velocities are infinite for a turning crank (a toggle); move the "
                                f"position off it")

    def margin(self, st: State) -> FloatArray:
        """How far each position is from failing to assemble (m², > 0 assembles); used to find
        toggles between positions."""
        return np.ones(st.n)


def check_length(name: str, value: object, *, positive: bool = True) -> float:
    """A finite length in m (> 0 when ``positive``); InputError naming it otherwise."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise InputError(f"{name} must be a number in m, got {value!r}")
    length = float(value)
    if not is_finite(length):
        raise InputError(f"{name} must be finite, got {length!r}")
    if positive and length <= 0:
        raise InputError(f"{name} must be > 0 m, got {length!r}")
    return length


def check_branch(name: str, value: object) -> int:
    """+1 or −1."""
    if isinstance(value, bool) or value not in (1, -1):
        raise InputError(f"{name}: branch must be +1 or -1, got {value!r}")
    return int(value)


def rigid(st: State, link: str, origin: str, z: ComplexArray) -> tuple[ComplexArray, ComplexArray]:
    """Velocity and acceleration of a point at ``z`` fixed on ``link`` whose point ``origin`` is known."""
    r = z - st.z[origin]
    w, e = st.omega[link], st.epsilon[link]
    return st.v[origin] + 1j * w * r, st.a[origin] + (1j * e - w * w) * r
