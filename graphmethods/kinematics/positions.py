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
    _geom: Mapping[str, tuple[np.ndarray, np.ndarray]] = field(default_factory=lambda: MappingProxyType({}),
                                                                repr=False, compare=False)

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


def at_extremes(phi: np.ndarray, strokes: Strokes | None, *, tol: float = 1e-13) -> np.ndarray:
    """True where the crank angle φ (rad) is within ``tol`` rad of an extreme position of ``strokes``.

    Returns a new bool array (n,) (all False without strokes); its one temporary is (2, n).

    >>> s = Strokes(phi_start=0.0, phi_end=math.pi, working_angle=math.pi, return_angle=math.pi, K=1.0,
    ...             start_name="far", end_name="near")
    >>> at_extremes(np.array([0.0, 1.0, math.pi, 2 * math.pi - 1e-14]), s).tolist()
    [True, False, True, True]
    """
    n = phi.shape[0]
    if strokes is None:
        return np.zeros(n, dtype=bool)
    d = np.empty((2, n))
    np.subtract(phi, np.array([[strokes.phi_start], [strokes.phi_end]]), out=d)
    d += math.pi
    np.mod(d, 2.0 * math.pi, out=d)
    d -= math.pi
    np.abs(d, out=d)
    out: np.ndarray = np.minimum(d[0], d[1], out=d[0]) <= tol
    return out


def _working(phi: np.ndarray, sense: int, strokes: Strokes, tol: float) -> np.ndarray:
    """True where φ (rad) is on the working stroke, its ends included (a new bool array)."""
    tr = phi - strokes.phi_start
    if sense < 0:
        np.negative(tr, out=tr)
    np.mod(tr, 2.0 * math.pi, out=tr)
    out: np.ndarray = (tr <= strokes.working_angle + tol) | (tr >= 2.0 * math.pi - tol)
    return out


def _own(a: Any) -> np.ndarray:
    """``a`` as a read-only float array: frozen in place when it is a float array of its own (not a
    view), else a frozen copy. :func:`build_positions` is handed new arrays, so it copies none."""
    if isinstance(a, np.ndarray) and a.dtype == np.float64 and a.base is None and a.flags.owndata:
        a.flags.writeable = False
        return a
    return _ro(np.array(a, dtype=float))


def build_positions(mech: Any, phi: np.ndarray, *, m: int | None, phi_start: float, strokes: Strokes | None,
                    geom: Mapping[str, tuple[np.ndarray, np.ndarray]], theta: Mapping[str, np.ndarray],
                    phi_from_start: np.ndarray | None = None, output: Mapping[str, Any] | None = None) -> Positions:
    """Assemble a frozen :class:`Positions` (used by the mechanisms; not public API).

    The arrays given (``phi``, ``phi_from_start``, ``theta``, ``output``) become the result's own
    and are made read-only in place: pass new arrays (views and other dtypes are copied).
    """
    n = phi.shape[0]
    sense = mech.sense
    tol = 1e-13
    if phi_from_start is None:
        phi_from_start = np.mod(sense * (phi - phi_start), 2.0 * math.pi)
        phi_from_start = np.where(phi_from_start > 2.0 * math.pi - tol, 0.0, phi_from_start)
    working = None if strokes is None else _ro(_working(phi, sense, strokes, tol))
    extreme = _ro(at_extremes(phi, strokes, tol=tol))
    index = None if m is None else _ro(np.arange(n))
    coords = {}
    for name, (x, y) in geom.items():
        c = np.empty((n, 2))
        c[:, 0] = x
        c[:, 1] = y
        coords[name] = _ro(c)
    out: dict[str, Any] = {k: (_own(v) if isinstance(v, np.ndarray) else v) for k, v in (output or {}).items()}
    return Positions(
        mechanism=mech, phi=_own(phi), phi_from_start=_own(phi_from_start), m=m, index=index, strokes=strokes,
        extreme=extreme, working=working, coords=MappingProxyType(coords),
        theta=MappingProxyType({k: _own(v) for k, v in theta.items()}), _geom=MappingProxyType(dict(geom)), **out,
    )
