"""Velocity plans: the pole p, the known vector pa, and every other point as the textbook finds it.

A :class:`VelocityPlans` holds, for every position at once, the plan vector of every named
point (m/s: the vector from the pole p to the point's image), the angular velocities of the
links (rad/s, counterclockwise +), how each point was found (intersection of two
construction lines, similarity, proportion) with the lines themselves so that a figure can
draw them, and a mask of ill-conditioned positions (the two lines meet at a small angle).

With ``omega_1 = 1`` (the default) the vectors are the velocity analogues v/ω₁ in m/rad and
the angular velocities the ratios ω_i/ω₁.

>>> from graphmethods.kinematics import SliderCrank
>>> mech = SliderCrank(r=0.1, l=0.4, points={"S2": ("AB", 0.13, 0.0)})
>>> plan = mech.velocity_plans(mech.positions(m=12), omega_1=10.0)
>>> plan.v("B")[0].tolist()                  # dead centre: b coincides with p
[0.0, 0.0]
>>> round(float(plan.speed("A")[3]), 12)     # v_A = ω₁ r at every position
1.0
>>> plan.constructions["B"].equation
'v_B = v_A + v_BA;  v_B ∥ guide, v_BA ⟂ AB'
>>> plan.mu_v(fit_mm=45.0)                    # a convenient scale, (m/s)/mm
0.025
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from graphmethods.errors import InputError
from graphmethods.kinematics.positions import Positions
from graphmethods.kinematics.vectors import FloatArray
from graphmethods.units import CONVENIENT, convenient_at_least


def convenient_scale(raw: float, *, series: tuple[float, ...] = CONVENIENT) -> float:
    """The smallest convenient scale (1, 2, 2.5, 4, 5 × 10^k) that is at least ``raw``.

    A scale is physical units per millimetre, so rounding it up keeps the drawing inside the
    space the raw value was computed for.

    >>> convenient_scale(0.0213), convenient_scale(3.0), convenient_scale(5.0)
    (0.025, 4.0, 5.0)
    """
    if not (isinstance(raw, (int, float, np.floating)) and abs(raw) <= 1e308 and math.isfinite(raw) and raw > 0):
        raise InputError(f"a scale must be a positive finite number, got {raw!r}")
    return convenient_at_least(float(raw), series)


@dataclass(frozen=True, eq=False)
class ConstructionLine:
    """A line of the velocity plan along which an unknown point must lie.

    Attributes
    ----------
    through : str
        Plan point the line is drawn through (``"p"`` is the pole, ``"a"``, ``"b"``, …).
    relation : str
        ``"perpendicular"`` or ``"parallel"``.
    to : str
        What it is perpendicular / parallel to: a link (``"AB"``, ``"O2B"``) or ``"guide"``.
    point : ndarray (n, 2)
        The plan point it passes through, m/s.
    direction : ndarray (n, 2)
        Unit direction of the line.
    """

    through: str
    relation: str
    to: str
    point: FloatArray
    direction: FloatArray

    @property
    def label(self) -> str:
        """Textbook annotation, e.g. ``"⟂ AB"`` or ``"∥ guide"``."""
        return ("⟂ " if self.relation == "perpendicular" else "∥ ") + self.to


@dataclass(frozen=True, eq=False)
class PointConstruction:
    """How one point of the plan is found.

    Attributes
    ----------
    name : str
        The point (``"B"``); its plan image is ``label`` (``"b"``).
    method : str
        ``"pole"`` (fixed point: its image is p), ``"known"`` (v = ω × r of the crank),
        ``"intersection"`` (of the two ``lines``), ``"similarity"`` (on the link ``on``),
        ``"proportion"`` (on the rocker ``on``), ``"same"`` (coincides with another image).
    equation : str
        The vector equation drawn (Unicode).
    lines : tuple of ConstructionLine
        The two lines for an intersection, else empty.
    on : str
        The link or points used by similarity / proportion (``"AB"``), else ``""``.
    sin_between : ndarray (n,) or None
        For an intersection, the sine of the angle between its lines (signed).
    """

    name: str
    method: str
    equation: str
    lines: tuple[ConstructionLine, ...] = ()
    on: str = ""
    sin_between: FloatArray | None = None

    @property
    def label(self) -> str:
        """The point's name in the plan (lower case: ``"b"``, ``"s2"``; ``"p"`` for fixed points)."""
        return "p" if self.method == "pole" else self.name.lower()


@dataclass(frozen=True, eq=False)
class VelocityPlans:
    """Velocity plans of a linkage in all its positions (see the module docstring).

    Attributes
    ----------
    positions : Positions
        The positions the plans were built for.
    omega_1 : float
        Crank speed, rad/s (> 0; the crank turns in ``sense``).
    sense : int
        +1 crank counterclockwise, −1 clockwise.
    vectors : mapping name -> ndarray (n, 2)
        Plan vector (velocity) of every named point, m/s.
    omegas : mapping link -> ndarray (n,)
        Angular velocity of every moving link, rad/s, counterclockwise +.
    constructions : mapping name -> PointConstruction
        How every point was found, in construction order.
    sin_min : ndarray (n,)
        Smallest |sine| between two construction lines at each position (1 when no
        intersection is needed).
    ill_conditioned : ndarray (n,) of bool
        ``sin_min < sin_threshold``: the lines meet at a small angle; at these positions the
        values come from the analytic derivative instead of the intersection.
    sin_threshold : float
        The threshold used.
    """

    positions: Positions
    omega_1: float
    sense: int
    vectors: Mapping[str, FloatArray]
    omegas: Mapping[str, FloatArray]
    constructions: Mapping[str, PointConstruction]
    sin_min: FloatArray
    ill_conditioned: NDArray[np.bool_]
    sin_threshold: float

    @property
    def n(self) -> int:
        """Number of positions."""
        return int(self.sin_min.shape[0])

    @property
    def order(self) -> tuple[str, ...]:
        """Point names in construction order."""
        return tuple(self.constructions)

    def v(self, name: str) -> FloatArray:
        """Velocity of point ``name`` (its plan vector), (n, 2), m/s."""
        try:
            return self.vectors[name]
        except KeyError:
            raise InputError(f"no point {name!r} in this velocity plan; known points: "
                             f"{', '.join(self.vectors)}") from None

    def speed(self, name: str) -> FloatArray:
        """Magnitude of the velocity of ``name``, (n,), m/s."""
        v = self.v(name)
        out: FloatArray = np.hypot(v[:, 0], v[:, 1])
        return out

    def analogue(self, name: str) -> FloatArray:
        """Velocity analogue v/ω₁ of ``name`` (derivative with respect to the crank's rotation
        in its own sense), (n, 2), m/rad."""
        return self.v(name) / self.omega_1

    def omega(self, link: int | str) -> FloatArray:
        """Angular velocity of ``link`` (name like ``"AB"`` / ``"BA"`` or textbook number), (n,),
        rad/s, counterclockwise +."""
        key: str = self.positions.mechanism.link_name(link)
        return self.omegas[key]

    def omega_ratio(self, link: int | str) -> FloatArray:
        """Angular velocity analogue ω_i/ω₁ of ``link`` (signed, counterclockwise +), (n,)."""
        return self.omega(link) / self.omega_1

    def v_rel(self, name: str, relative_to: str) -> FloatArray:
        """Relative velocity v_XY = v_X − v_Y (plan vector from y to x), (n, 2), m/s."""
        return self.v(name) - self.v(relative_to)

    def v_along_guide(self, name: str) -> FloatArray:
        """Signed velocity of a slider point along its guide (+ along +x of the guide), (n,), m/s."""
        guide: tuple[float, float] | None = self.positions.mechanism.guides.get(name)
        if guide is None:
            raise InputError(f"point {name!r} does not move along a guide; sliders of this linkage: "
                             f"{', '.join(self.positions.mechanism.guides) or 'none'}")
        v = self.v(name)
        return v[:, 0] * guide[0] + v[:, 1] * guide[1]

    def label(self, name: str) -> str:
        """Name of the point's image in the plan (``"b"``; ``"p"`` for fixed points)."""
        return self.constructions[name].label

    def lines(self, name: str) -> tuple[ConstructionLine, ...]:
        """The construction lines that locate ``name`` (empty unless found by intersection)."""
        return self.constructions[name].lines

    def mu_v(self, *, fit_mm: float | None = None, pa_mm: float | None = None, convenient: bool = True) -> float:
        """A velocity scale μ_v in (m/s)/mm.

        Give exactly one of ``fit_mm`` (the longest vector of any plan must fit in this many
        mm) or ``pa_mm`` (the textbook's choice of the length of pa, the crank pin's vector).
        With ``convenient`` the scale is rounded up to 1, 2, 2.5, 4, 5 × 10^k.
        """
        if (fit_mm is None) == (pa_mm is None):
            raise InputError("give exactly one of fit_mm (longest vector) or pa_mm (length of pa) in mm")
        length = fit_mm if fit_mm is not None else pa_mm
        assert length is not None                                  # exactly one of them is given (checked above)
        if not (math.isfinite(length) and length > 0):
            raise InputError(f"the drawn length must be a positive number of mm, got {length!r}")
        if fit_mm is not None:
            raw = max(float(np.max(self.speed(k))) for k in self.vectors)
        else:
            raw = float(np.max(self.speed(self.positions.mechanism.crank_pin)))
        raw = raw / length
        if raw == 0.0:
            raise InputError("all velocities are zero: no scale can be fitted")
        return convenient_scale(raw) if convenient else raw
