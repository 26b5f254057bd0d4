"""Positions of a linkage: crank angles, numbering from the working stroke, point coordinates.

A :class:`Positions` is what ``mech.positions(m=12)`` returns: the crank angles φ (rad, from
+x, counterclockwise), their textbook numbers 0…m counted from the extreme position that
starts the working stroke in the crank's sense of rotation (position m = position 0), the
extreme positions found exactly, the working-stroke angle and the time ratio K, and the
coordinates (m) of every named point at every position.

>>> from graphmethods.kinematics import SliderCrank
>>> pos = SliderCrank(r=0.1, l=0.4).positions(m=12)
>>> pos.n, pos.m, [int(i) for i in pos.index[:3]]
(13, 12, [0, 1, 2])
>>> round(float(pos.K), 6), round(float(pos.H), 6)
(1.0, 0.2)
>>> pos.xy("B")[0].tolist()          # far dead centre: B at r + l on the x axis
[0.5, 0.0]
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from graphmethods.errors import InputError


@dataclass(frozen=True)
class Strokes:
    """The two extreme positions of a linkage and the strokes between them.

    Attributes
    ----------
    phi_start, phi_end : float
        Crank angles (rad, from +x, counterclockwise) of the extreme positions that start
        the working stroke and the return stroke.
    working_angle, return_angle : float
        Crank rotation (rad, > 0) during the working and the return stroke; they add up to 2π.
    K : float
        Time ratio at constant crank speed, ``working_angle / return_angle`` (> 1 when the
        working stroke is the slow one: quick return).
    start_name, end_name : str
        What the extreme positions are (``"far dead centre"``, ``"near dead centre"``,
        ``"crank and coupler extended"``, ``"crank ⟂ rocker"``, …).
    """

    phi_start: float
    phi_end: float
    working_angle: float
    return_angle: float
    K: float
    start_name: str
    end_name: str

    @property
    def theta(self) -> float:
        """The crank angle between the extreme positions beyond π (rad): K = (π + θ)/(π − θ)."""
        return abs(self.working_angle - self.return_angle) / 2.0


def _ro(a: np.ndarray) -> np.ndarray:
    a.flags.writeable = False
    return a


@dataclass(frozen=True, eq=False)
class Positions:
    """A linkage in n positions (see the module docstring). Lengths in m, angles in rad.

    Attributes
    ----------
    mechanism
        The linkage these positions belong to.
    phi : ndarray (n,)
        Crank angle from +x, counterclockwise, rad.
    phi_from_start : ndarray (n,)
        Crank rotation from position 0 in the crank's sense, rad, in [0, 2π] (2π exactly at
        position m).
    m : int or None
        Number of equal steps when built with ``positions(m=...)``; else None.
    index : ndarray (n,) of int or None
        Textbook position numbers 0…m (None for arbitrary angles).
    strokes : Strokes or None
        Extreme positions, stroke angles and K (None for a linkage without extreme positions,
        e.g. a double-crank four-bar).
    extreme : ndarray (n,) of bool
        True where φ is (to 1e-13 rad) an extreme position: there the output stands still and
        the velocity plan puts its point exactly at the pole.
    working : ndarray (n,) of bool or None
        True on the working stroke (ends included).
    coords : mapping name -> ndarray (n, 2)
        Coordinates (m) of every joint and extra point.
    theta : mapping link -> ndarray (n,)
        Angle of every moving link (rad, direction of its name, e.g. "AB" from A to B).
    s, H : ndarray (n,), float or None
        For a slider output (slider-crank B, shaper ram C): displacement along the guide from
        the start of the working stroke, positive in the working sense, m; and the stroke H.
    stroke_direction : ndarray (2,) or None
        Unit vector along the guide in the sense of the working stroke.
    psi, psi_max : ndarray (n,), float or None
        For a rocker output (four-bar, slotted lever, shaper): rocker angle from its start
        extreme, positive in the working sense, rad; and the swing angle.
    """

    mechanism: Any
    phi: np.ndarray
    phi_from_start: np.ndarray
    m: int | None
    index: np.ndarray | None
    strokes: Strokes | None
    extreme: np.ndarray
    working: np.ndarray | None
    coords: Mapping[str, np.ndarray]
    theta: Mapping[str, np.ndarray]
    s: np.ndarray | None = None
    H: float | None = None
    stroke_direction: np.ndarray | None = None
    psi: np.ndarray | None = None
    psi_max: float | None = None
    _geom: Mapping[str, tuple] = field(default_factory=lambda: MappingProxyType({}), repr=False, compare=False)

    # -- convenience ------------------------------------------------------------------
    @property
    def n(self) -> int:
        """Number of positions (m + 1 for ``positions(m=...)``: 0…m)."""
        return int(self.phi.shape[0])

    def __len__(self) -> int:
        return self.n

    @property
    def phi_deg(self) -> np.ndarray:
        """Crank angles in degrees, normalised to [0, 360)."""
        d = np.mod(np.degrees(self.phi), 360.0)
        return np.where(d >= 360.0, 0.0, d)

    @property
    def K(self) -> float | None:
        """Time ratio (working / return crank angle), or None without extreme positions."""
        return None if self.strokes is None else self.strokes.K

    @property
    def working_angle(self) -> float | None:
        """Crank angle of the working stroke (rad), or None."""
        return None if self.strokes is None else self.strokes.working_angle

    @property
    def names(self) -> tuple[str, ...]:
        """Names of all points with coordinates."""
        return tuple(self.coords)

    def xy(self, name: str) -> np.ndarray:
        """Coordinates (n, 2) of point ``name`` in m."""
        try:
            return self.coords[name]
        except KeyError:
            raise InputError(f"no point {name!r} in this linkage; known points: {', '.join(self.coords)}") from None


def build_positions(mech, phi: np.ndarray, *, m: int | None, phi_start: float, strokes: Strokes | None,
                    geom: dict[str, tuple], theta: dict[str, np.ndarray], phi_from_start: np.ndarray | None = None,
                    output: dict | None = None) -> Positions:
    """Assemble a frozen :class:`Positions` (used by the mechanisms; not public API)."""
    n = phi.shape[0]
    sense = mech.sense
    if phi_from_start is None:
        phi_from_start = np.mod(sense * (phi - phi_start), 2.0 * math.pi)
        phi_from_start = np.where(phi_from_start > 2.0 * math.pi - 1e-13, 0.0, phi_from_start)
    tol = 1e-13
    if strokes is not None:
        d0 = np.abs(np.mod(phi - strokes.phi_start + math.pi, 2.0 * math.pi) - math.pi)
        d1 = np.abs(np.mod(phi - strokes.phi_end + math.pi, 2.0 * math.pi) - math.pi)
        extreme = (d0 <= tol) | (d1 <= tol)
        tr = np.mod(sense * (phi - strokes.phi_start), 2.0 * math.pi)
        working = (tr <= strokes.working_angle + tol) | (tr >= 2.0 * math.pi - tol)
        working = _ro(working)
    else:
        extreme = np.zeros(n, dtype=bool)
        working = None
    index = None
    if m is not None:
        index = _ro(np.arange(n))
    coords = {}
    for name, (x, y) in geom.items():
        c = np.empty((n, 2))
        c[:, 0] = x
        c[:, 1] = y
        coords[name] = _ro(c)
    out: dict[str, Any] = {k: (_ro(np.array(v, dtype=float)) if isinstance(v, np.ndarray) else v)
                           for k, v in (output or {}).items()}
    return Positions(
        mechanism=mech, phi=_ro(np.array(phi, dtype=float)), phi_from_start=_ro(np.array(phi_from_start, dtype=float)),
        m=m, index=index, strokes=strokes, extreme=_ro(extreme), working=working,
        coords=MappingProxyType(coords), theta=MappingProxyType({k: _ro(np.array(v, dtype=float)) for k, v in theta.items()}),
        _geom=MappingProxyType(geom), **out,
    )
