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

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphmethods.errors import AssemblyError, InputError

GROUND = "0"


def cross(a, b):
    """z-component of a × b for complex plane vectors (Im(conj(a)·b))."""
    return a.real * b.imag - a.imag * b.real


def dot(a, b):
    """Scalar product of complex plane vectors (Re(conj(a)·b))."""
    return a.real * b.real + a.imag * b.imag


def solve2(e1, e2, rhs):
    """Real x, y with ``x·e1 + y·e2 = rhs`` (complex plane vectors, vectorised).

    Returns ``(x, y, det)`` with ``det = e1 × e2``; where det is 0 the values are not finite
    (callers check ``det`` first).
    """
    det = np.asarray(cross(e1, e2))
    if np.count_nonzero(det) == det.size:         # every position solvable (as det.all(), without its wrapper)
        return cross(rhs, e2) / det, cross(e1, rhs) / det, det
    with np.errstate(divide="ignore", invalid="ignore"):
        x = cross(rhs, e2) / det
        y = cross(e1, rhs) / det
    return x, y, det


def fmt(x: float) -> str:
    """A length or number for a message (6 significant digits)."""
    return f"{x:.6g}"


class _Angles(dict):
    """Link angles computed when first asked for, from the links' unit directions."""

    def __init__(self, directions: dict):
        super().__init__()
        self._e = directions

    def __missing__(self, link):
        th = np.angle(np.broadcast_to(self._e[link], self._n)) if link in self._e else None
        if th is None:
            raise KeyError(link)
        self[link] = th
        return th

    def __contains__(self, link):
        return dict.__contains__(self, link) or link in self._e

    def keys(self):
        return list(dict.fromkeys([*self._e, *dict.keys(self)]))     # solving order, however they were asked for

    def __iter__(self):
        return iter(self.keys())

    def items(self):
        return [(k, self[k]) for k in self.keys()]

    def values(self):
        return [self[k] for k in self.keys()]

    def __len__(self):
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
    relative : dict name -> dict
        Per group, the sliding quantities (relative velocity and acceleration along a guide,
        Coriolis terms) as complex arrays.
    conditioning : dict group name -> ndarray (n,)
        |sin| of the angle between the two construction lines of the group's plan.
    """

    phi: np.ndarray
    labels: np.ndarray | None = None
    z: dict = field(default_factory=dict)
    v: dict = field(default_factory=dict)
    a: dict = field(default_factory=dict)
    e: dict = field(default_factory=dict)
    theta: dict = field(default_factory=dict)
    omega: dict = field(default_factory=dict)
    epsilon: dict = field(default_factory=dict)
    relative: dict = field(default_factory=dict)
    conditioning: dict = field(default_factory=dict)
    kinematic: bool = True

    @property
    def zeros(self) -> np.ndarray:
        """A shared read-only array of n zeros (the angular velocity of a translating link)."""
        z = self.__dict__.get("_zeros")
        if z is None:
            z = np.zeros(self.phi.shape)
            z.flags.writeable = False
            self.__dict__["_zeros"] = z
        return z

    def __post_init__(self):
        angles = _Angles(self.e)
        angles._n = self.phi.shape
        angles.update(self.theta)
        self.theta = angles

    @property
    def n(self) -> int:
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
    through: Any
    angle: float = 0.0

    def line(self, st: State):
        """(G, u, omega, epsilon): a point of the line, its unit direction, and the turning of the
        link that carries it (zeros for the frame), each over the positions."""
        G = st.z[self.through] if isinstance(self.through, str) else complex(self.through)
        turn = complex(math.cos(self.angle), math.sin(self.angle))
        if self.link == GROUND:
            return G, turn, 0.0, 0.0          # scalars: they broadcast over the positions
        return G, st.e[self.link] * turn, st.omega.get(self.link, 0.0), st.epsilon.get(self.link, 0.0)

    def kinematics(self, st: State):
        """(v_G, a_G): velocity and acceleration of the guide's point (zeros for the frame)."""
        if isinstance(self.through, str):
            return st.v[self.through], st.a.get(self.through, 0j)
        return 0j, 0j

    def describe(self) -> str:
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
    known: tuple
    lines: tuple
    meet: np.ndarray
    sin_between: np.ndarray


class Group:
    """Base of the structural groups (class II dyads): see the subclasses.

    Subclasses set ``kind`` (``"RRR"``, ...), ``links`` (the two textbook link numbers) and
    implement ``positions``, ``velocities``, ``accelerations``, ``records``, ``inputs`` (the
    points and links the group needs) and ``outputs`` (the points and links it adds).
    """

    kind = "?"
    links: tuple[str, str] = ("", "")
    #: (pair kind, link, link) for its three kinematic pairs: "R" revolute, "P" prismatic
    pairs: tuple = ()

    def inputs(self) -> tuple[set, set]:  # pragma: no cover - interface
        raise NotImplementedError

    def outputs(self) -> tuple[tuple, tuple]:  # pragma: no cover - interface
        raise NotImplementedError

    @property
    def name(self) -> str:
        return f"{self.kind} ({self.links[0]}, {self.links[1]})"

    def _name(self) -> str:
        try:
            return self.__dict__["_cached_name"]
        except KeyError:
            object.__setattr__(self, "_cached_name", self.name)
            return self.__dict__["_cached_name"]

    def fail(self, st: State, bad: np.ndarray, why) -> None:
        """Raise AssemblyError at the first position where ``bad`` holds; ``why(i)`` explains it."""
        if np.count_nonzero(bad):
            i = int(np.argmax(bad))
            raise AssemblyError(f"group {self.name}: cannot be assembled at {st.where(i)}: {why(i)}")

    def check_det(self, st: State, det: np.ndarray, what: str) -> None:
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

    def margin(self, st: State) -> np.ndarray:
        """How far each position is from failing to assemble (m², > 0 assembles); used to find
        toggles between positions."""
        return np.ones(st.n)


def check_length(name: str, value, *, positive: bool = True) -> float:
    """A finite length in m (> 0 when ``positive``); InputError naming it otherwise."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise InputError(f"{name} must be a number in m, got {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise InputError(f"{name} must be finite, got {value!r}")
    if positive and value <= 0:
        raise InputError(f"{name} must be > 0 m, got {value!r}")
    return value


def check_branch(name: str, value) -> int:
    """+1 or −1."""
    if isinstance(value, bool) or value not in (1, -1):
        raise InputError(f"{name}: branch must be +1 or -1, got {value!r}")
    return int(value)


def rigid(st: State, link: str, origin: str, z: np.ndarray):
    """Velocity and acceleration of a point at ``z`` fixed on ``link`` whose point ``origin`` is known."""
    r = z - st.z[origin]
    w, e = st.omega[link], st.epsilon[link]
    return st.v[origin] + 1j * w * r, st.a[origin] + (1j * e - w * w) * r
