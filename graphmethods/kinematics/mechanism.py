"""What every linkage seen by the dynamics and the sheets shares: extra points on links, link names
and numbers, checks of lengths and crank angles.

:class:`Mechanism` is the interface the reduced model and the drawings read (``positions``,
``velocity_plans``, ``strokes``, ``guides``, link names and numbers);
:class:`~graphmethods.kinematics.linkage_mechanism.LinkageMechanism` gives it to any linkage of
the Assur-group core, and :mod:`graphmethods.kinematics.classic` builds the four classic kinds
of the problem files as presets on it.

Extra points (centres of mass, coupler points) are given per link by the distance from a
joint and the angle to the link line: ``points={"S2": ("AB", 0.13, 0.0)}`` puts S2 on AB,
0.13 m from A, on the line A→B; ``("AB", 0.1, math.pi/2)`` would be 0.1 m from A at 90°
counterclockwise from A→B; ``("BA", ...)`` measures from B toward A.

>>> p = PointOnLink.of("S2", ("AB", 0.13))
>>> p.link, p.distance, p.angle
('AB', 0.13, 0.0)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from graphmethods.errors import InputError
from graphmethods.kinematics.vectors import FloatArray
from graphmethods.units import MAX_POSITIONS_COMPUTED, real


@dataclass(frozen=True)
class PointOnLink:
    """An extra point of a link: ``distance`` (m) from the link's first joint, at ``angle`` (rad,
    counterclockwise) from the line first joint → second joint.

    Attributes
    ----------
    name : str
        The point's name (``"S2"``, ``"K"``); must not be a joint name.
    link : str
        The link by its joints, first joint first (``"AB"``, ``"BA"``, ``"O2B"``).
    distance : float
        Distance from the first joint, m (≥ 0).
    angle : float
        Angle from the link line, rad.
    """

    name: str
    link: str
    distance: float
    angle: float = 0.0

    @classmethod
    def of(cls, name: str, spec: object) -> PointOnLink:
        """Normalise ``(link, distance)``, ``(link, distance, angle)`` or a PointOnLink."""
        if isinstance(spec, PointOnLink):
            return spec if spec.name == name else cls(name, spec.link, spec.distance, spec.angle)
        if not isinstance(spec, (tuple, list)) or len(spec) not in (2, 3) or not isinstance(spec[0], str):
            raise InputError(f"point {name!r}: give (link, distance_m) or (link, distance_m, angle_rad), "
                             f"e.g. ('AB', 0.13, 0.0); got {spec!r}")
        vals: list[float] = []
        for what, x in zip(("distance", "angle"), spec[1:]):
            if isinstance(x, bool) or not isinstance(x, (int, float, np.floating, np.integer)):
                raise InputError(f"point {name!r}: {what} must be a finite number, got {x!r}")
            vals.append(real(x, f"point {name!r}: {what}", tiny_ok=True))
        if vals[0] < 0:
            raise InputError(f"point {name!r}: distance must be ≥ 0 m (turn the angle by π instead), got {vals[0]}")
        return cls(name, spec[0], *vals)


#: Largest angle in rad the API takes (files give degrees, reduced exactly modulo 360 when read).
MAX_ANGLE_RAD = 1e6


def _check_length(name: str, value: object, *, positive: bool = True, allow_zero: bool = False) -> float:
    """A length (m) or an offset or angle (``positive=False``) checked by the toolkit's number policy."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise InputError(f"{name} must be a number in m, got {value!r}")
    # the toolkit's number policy: finite, magnitudes up to 1e100, and a length (a divisor) at least 1e-100;
    # an offset or an angle is only a term: tiny is fine
    length = real(value, name, tiny_ok=not positive)
    if positive and (length < 0 or (length == 0 and not allow_zero)):
        raise InputError(f"{name} must be {'≥' if allow_zero else '>'} 0 m, got {length!r}")
    if name.startswith(("theta", "ground_angle")) and abs(length) > MAX_ANGLE_RAD:
        raise InputError(f"{name} = {length:g} rad is beyond ±{MAX_ANGLE_RAD:g} rad; reduce it modulo 2π first "
                         f"(or give degrees in a problem file, which are reduced exactly)")
    return length


def _fmt(x: float) -> str:
    return f"{x:.6g}"


def _deg(phi: float) -> str:
    return f"{math.degrees(phi) % 360.0:.4g}°"


class Mechanism:
    """Base of the linkages (not instantiated itself; see
    :class:`~graphmethods.kinematics.linkage_mechanism.LinkageMechanism`)."""

    #: joint names, in drawing order
    joints: tuple[str, ...] = ()
    #: the crank pin (its velocity is the known vector pa)
    crank_pin: str = "A"
    #: canonical moving links that can carry extra points -> (first joint, second joint)
    link_joints: Mapping[str, tuple[str, str]] = {}
    #: textbook link numbers (crank = 1) -> canonical link name
    link_numbers: Mapping[int, str] = {}
    #: allowed values of ``working_stroke``
    working_strokes: tuple[str, ...] = ("slow", "fast")
    #: mechanism name for messages
    kind: str = "linkage"
    #: the fixed joints (drawn on hatched ground; their plan image is the pole)
    fixed_joints: tuple[str, ...] = ()
    #: +1: the crank turns counterclockwise, −1 clockwise (set by the subclass)
    sense: int
    #: which stroke works, one of ``working_strokes`` (set by the subclass)
    working_stroke: str
    #: the extra points on links (a subclass sets what the user gave; :meth:`_validate_common` normalises it)
    points: tuple[PointOnLink, ...]

    @property
    def slotted_links(self) -> tuple[tuple[str, str, str, str, str], ...]:
        """Blocks on slotted links: (pin on the block, its point on the slotted link, pivot, block
        number, link number); none unless the mechanism has some."""
        return ()

    # ---------------------------------------------------------------- validation
    def _validate_common(self) -> None:
        if self.sense not in (1, -1) or isinstance(self.sense, bool):
            raise InputError(f"{self.kind}: sense must be +1 (counterclockwise) or -1 (clockwise), got {self.sense!r}")
        if hasattr(self, "assembly") and (self.assembly not in (1, -1) or isinstance(self.assembly, bool)):
            raise InputError(f"{self.kind}: assembly must be +1 or -1, got {self.assembly!r}")
        if self.working_stroke not in self.working_strokes:
            raise InputError(f"{self.kind}: working_stroke must be one of {', '.join(self.working_strokes)}; "
                             f"got {self.working_stroke!r}")
        raw: object = self.points
        items: list[tuple[object, object]]
        if isinstance(raw, Mapping):
            items = list(raw.items())
        elif isinstance(raw, (tuple, list)):
            items = [(p.name, p) if isinstance(p, PointOnLink) else (None, p) for p in raw]
            if any(k is None for k, _ in items):
                raise InputError(f"{self.kind}: points must be a mapping name -> (link, distance, angle), "
                                 f"e.g. {{'S2': ('AB', 0.13, 0.0)}}")
        else:
            raise InputError(f"{self.kind}: points must be a mapping name -> (link, distance, angle), got {raw!r}")
        specs = []
        for name, spec in items:
            if not isinstance(name, str) or not name or not name.isidentifier():
                raise InputError(f"{self.kind}: point names must be identifiers like 'S2', got {name!r}")
            if name in self.joints:
                raise InputError(f"{self.kind}: point {name!r} clashes with a joint name ({', '.join(self.joints)})")
            p = PointOnLink.of(name, spec)
            self._resolve_link(p.link, what=f"point {name!r}")
            specs.append(p)
        object.__setattr__(self, "points", tuple(specs))

    def _resolve_link(self, link: str, *, what: str = "link") -> tuple[str, str, str, bool]:
        """(first joint, second joint, canonical name, reversed?) of a link written as joints."""
        for canon, (x, y) in self.link_joints.items():
            if link == x + y:
                return x, y, canon, False
            if link == y + x:
                return y, x, canon, True
        raise InputError(f"{self.kind}: {what}: unknown link {link!r}; the moving links are "
                         f"{', '.join(self.link_joints)} (either order, first joint = where the distance starts)")

    def link_name(self, link: int | str) -> str:
        """Canonical name of a link given by joints (``"BA"`` -> ``"AB"``) or textbook number."""
        if isinstance(link, (int, np.integer)) and not isinstance(link, bool):
            try:
                return self.link_numbers[int(link)]
            except KeyError:
                raise InputError(f"{self.kind}: no link number {link}; links: "
                                 + ", ".join(f"{k} = {v}" for k, v in self.link_numbers.items())) from None
        if isinstance(link, str):
            if link in self.omega_links:
                return link
            for canon in self.omega_links:
                x, y = self._omega_joints(canon)
                if link in (x + y, y + x):
                    return canon
        raise InputError(f"{self.kind}: unknown link {link!r}; links: "
                         + ", ".join(f"{k} = {v}" for k, v in self.link_numbers.items()))

    @property
    def omega_links(self) -> tuple[str, ...]:
        """Canonical names of the links whose angular velocities the plans report."""
        return tuple(self.link_numbers.values())

    def _omega_joints(self, canon: str) -> tuple[str, str]:
        return self.link_joints.get(canon, (canon, ""))

    @property
    def guides(self) -> dict[str, tuple[float, float]]:
        """Slider points -> unit direction (+) of their guide."""
        return {}

    @staticmethod
    def _angles(values: object, name: str) -> FloatArray:
        """Crank angles (rad) as a flat float array, checked: numbers, finite, at most ±MAX_ANGLE_RAD."""
        if isinstance(values, (bool, str, bytes)) or (isinstance(values, np.ndarray) and values.dtype == bool):
            raise InputError(f"{name}: crank angles must be numbers in rad, got {values!r}")
        try:
            a: FloatArray = np.array(values, dtype=float).reshape(-1)
        except (TypeError, ValueError, OverflowError):
            raise InputError(f"{name}: crank angles must be numbers in rad, got {values!r}") from None
        if a.size == 0:
            raise InputError(f"{name}: give at least one crank angle")
        if a.size > MAX_POSITIONS_COMPUTED:
            raise InputError(f"{name}: {a.size} angles is above the limit {MAX_POSITIONS_COMPUTED}")
        bad = ~np.isfinite(a)
        if bad.any():
            raise InputError(f"{name}: angle #{int(np.argmax(bad))} is {a[bad][0]!r}; angles must be finite (rad)")
        big = np.abs(a) > MAX_ANGLE_RAD
        if big.any():
            raise InputError(f"{name}: angle #{int(np.argmax(big))} = {a[big][0]:g} rad is beyond "
                             f"±{MAX_ANGLE_RAD:g} rad; reduce it modulo 2π first")
        return a

    @staticmethod
    def _where(phi: FloatArray, labels: NDArray[np.integer[Any]] | None, i: int) -> str:
        """'position 3 (φ = 210°)' or 'angle #3 (φ = 210°)' for messages."""
        pos = f"position {int(labels[i])}" if labels is not None else f"angle #{i}"
        return f"{pos} (φ = {_deg(float(phi[i]))})"

