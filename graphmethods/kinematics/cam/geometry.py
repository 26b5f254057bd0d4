"""The cam's geometry by inversion of motion: pitch point, pressure angle, curvature, profile.

Conventions (the file's and the figures'). The cam centre O is the origin. At φ = 0 (the start of
the first phase) the follower stands above O: a translating follower moves along +y on the line
x = e (cam turning counterclockwise; e ≥ 0 is the side that lowers the rise's pressure angle, since
the velocity pole of cam and follower lies at x = ds/dφ); an oscillating follower's pivot A is at
(a, 0) and its roller centre B at A + l·(−cos θ, sin θ), θ = ψ₀ + ψ, so the arm swings against the
cam's rotation on the rise (the arrangement with the smaller pressure angle). A clockwise cam is the
mirror image in the y axis. Inversion keeps the cam still and turns the follower by −φ about O: the
cam's own frame is the fixed frame at φ = 0, and a point B of the follower at cam angle φ is
``R(−φ)·B`` there (``R(+φ)`` of the mirror for a clockwise cam).

In the follower's frame (the fixed frame before the turn) the pitch curve's tangent analogue is
``W = B' − J·B`` and its second derivative ``V = B'' − 2J·B' − B`` (J: a quarter turn
counterclockwise, ' = d/dφ). For a translating follower W = (s₀ + s, ds/dφ − e), so the pressure
angle (between the normal at contact and the follower's velocity) is
``tan α = (ds/dφ − e)/(s₀ + s)`` and the radius of curvature is
``ρ = |W|³ / ((s₀+s)(s₀+s−s'') + (s'−e)(2s'−e))`` (> 0 where the pitch curve is convex).
The roller's profile is the pitch curve offset inward by r_r along its normal; the flat face's is
the envelope of its lines, touching at ``(ds/dφ, r_b + s)``, with ``ρ = r_b + s + d²s/dφ²``.

>>> import numpy as np
>>> g = pitch_frame("translating", 0.04, np.array([0.0]), np.array([0.02]), np.array([0.0]), offset=0.0)
>>> [round(float(v), 12) for v in (g.alpha[0], g.kappa[0])]
[0.463647609001, 26.832815729997]
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from graphmethods.errors import InputError

Array = NDArray[np.float64]


@dataclass(frozen=True)
class PitchFrame:
    """The pitch point and its analogues in the follower's frame, at a set of cam angles.

    Attributes
    ----------
    B : (N, 2) array
        The pitch point (roller centre or knife edge), m, before the turn by −φ.
    W, V : (N, 2) arrays
        dP/dφ and d²P/dφ² of the pitch curve P = R(−φ)·B, expressed in the follower's frame, m/rad, m/rad².
    alpha : (N,) array
        Pressure angle, rad, signed: positive when the normal leans ahead of the follower's velocity
        on the rise (translating: tan α = (ds/dφ − e)/(s₀ + s)).
    kappa : (N,) array
        Curvature of the pitch curve, 1/m, positive where it is convex.
    """

    B: Array
    W: Array
    V: Array
    alpha: Array
    kappa: Array

    def profile(self, roller_radius: float) -> Array:
        """The roller's envelope (the pitch curve offset inward by r_r), follower frame, m."""
        n = np.stack((-self.W[:, 1], self.W[:, 0]), axis=1) / np.hypot(self.W[:, 0], self.W[:, 1])[:, None]
        return self.B - roller_radius * n


def psi_0(r0: float, arm: float, pivot: float) -> float:
    """ψ₀, the angle OAB (rad) of an oscillating follower on the base circle r₀ (arm l, pivot distance a).

    >>> round(math.degrees(psi_0(0.05, 0.1, 0.12)), 6)
    24.146848
    """
    c = (pivot ** 2 + arm ** 2 - r0 ** 2) / (2.0 * pivot * arm)
    if not -1.0 < c < 1.0:
        raise InputError(f"the pitch base radius {r0:g} m cannot be reached by an arm of {arm:g} m pivoted {pivot:g} m "
                         f"from the cam centre (it must lie between {abs(pivot - arm):g} and {pivot + arm:g} m)")
    return math.acos(c)


def pitch_frame(follower_type: str, r0: float, s: Array, s1: Array, s2: Array, *, offset: float = 0.0,
                arm: float = 0.0, pivot: float = 0.0) -> PitchFrame:
    """Pitch point, pressure angle and curvature from the displacement s(φ) and its analogues.

    Parameters
    ----------
    follower_type : str
        ``translating`` (s in m) or ``oscillating`` (s = ψ, the arm's swing, in rad).
    r0 : float
        The pitch curve's base radius, m (roller: base radius + roller radius).
    s, s1, s2 : arrays
        s, ds/dφ and d²s/dφ² at the cam angles, m (rad) per rad.
    offset : float
        e, m (translating).
    arm, pivot : float
        l and a, m (oscillating).

    Returns
    -------
    PitchFrame

    Examples
    --------
    >>> import numpy as np
    >>> g = pitch_frame("oscillating", 0.05, np.zeros(1), np.zeros(1), np.zeros(1), arm=0.1, pivot=0.12)
    >>> round(float(np.hypot(*g.B[0])), 12), round(1.0 / float(g.kappa[0]), 12)
    (0.05, 0.05)
    """
    s, s1, s2 = (np.asarray(v, dtype=float) for v in (s, s1, s2))
    if follower_type == "translating":
        if r0 <= abs(offset):
            raise InputError(f"the pitch base radius {r0:g} m must exceed the offset |e| = {abs(offset):g} m")
        s0 = math.sqrt(r0 * r0 - offset * offset)
        z = np.zeros_like(s)
        B, B1, B2 = np.stack((z + offset, s0 + s), 1), np.stack((z, s1), 1), np.stack((z, s2), 1)
        u = np.stack((z, z + 1.0), 1)
    else:
        th = psi_0(r0, arm, pivot) + s
        sn, cs = np.sin(th), np.cos(th)
        B = np.stack((pivot - arm * cs, arm * sn), 1)
        B1 = arm * s1[:, None] * np.stack((sn, cs), 1)
        B2 = arm * s2[:, None] * np.stack((sn, cs), 1) + arm * (s1 * s1)[:, None] * np.stack((cs, -sn), 1)
        u = np.stack((sn, cs), 1)
    W = np.stack((B1[:, 0] + B[:, 1], B1[:, 1] - B[:, 0]), 1)
    V = np.stack((B2[:, 0] + 2.0 * B1[:, 1] - B[:, 0], B2[:, 1] - 2.0 * B1[:, 0] - B[:, 1]), 1)
    cross = u[:, 1] * W[:, 1] + u[:, 0] * W[:, 0]          # u⊥ × W with u⊥ = (u_y, −u_x)
    dot = u[:, 1] * W[:, 0] - u[:, 0] * W[:, 1]
    with np.errstate(divide="ignore"):
        alpha = np.arctan(cross / dot)
    norm = np.hypot(W[:, 0], W[:, 1])
    kappa = -(W[:, 0] * V[:, 1] - W[:, 1] * V[:, 0]) / norm ** 3
    return PitchFrame(B, W, V, alpha, kappa)


def pressure_angle(r0: float, s: Array, s1: Array, *, arm: float, pivot: float) -> Array:
    """The signed pressure angle α (rad) of an oscillating follower: :func:`pitch_frame`'s ``alpha`` alone.

    The same operations in the same order as :func:`pitch_frame` (so the same bits), without the
    second derivatives and the curvature: the base radius's design asks for α some ten thousand times.

    Parameters
    ----------
    r0 : float
        The pitch curve's base radius, m.
    s, s1 : arrays
        ψ and dψ/dφ at the cam angles, rad and rad/rad.
    arm, pivot : float
        l and a, m.

    Returns
    -------
    array
        α, rad.

    Examples
    --------
    >>> import numpy as np
    >>> s, s1 = np.array([0.1, 0.3]), np.array([0.2, -0.4])
    >>> g = pitch_frame("oscillating", 0.05, s, s1, np.zeros(2), arm=0.1, pivot=0.12)
    >>> bool(np.array_equal(pressure_angle(0.05, s, s1, arm=0.1, pivot=0.12), g.alpha))
    True
    """
    return pressure_angle_at(psi_0(r0, arm, pivot), s, s1, arm=arm, pivot=pivot)


def pressure_angle_at(psi0: float | Array, s: Array, s1: Array, *, arm: float, pivot: float) -> Array:
    """:func:`pressure_angle` at the arm's starting angle ψ₀ (rad) instead of r₀: a column of ψ₀ (one per row
    of ``s`` and ``s1``) gives many base radii at once, the same bits as one at a time.

    >>> import numpy as np
    >>> s, s1 = np.array([[0.1, 0.3]]), np.array([[0.2, -0.4]])
    >>> both = pressure_angle_at(np.array([[psi_0(0.05, 0.1, 0.12)], [psi_0(0.06, 0.1, 0.12)]]), s, s1, arm=0.1,
    ...                          pivot=0.12)
    >>> bool(np.array_equal(both[1], pressure_angle(0.06, s[0], s1[0], arm=0.1, pivot=0.12)))
    True
    """
    s, s1 = np.asarray(s, dtype=float), np.asarray(s1, dtype=float)
    th = psi0 + s
    sn, cs = np.sin(th), np.cos(th)
    a1 = arm * s1
    W_x = a1 * sn + arm * sn
    W_y = a1 * cs - (pivot - arm * cs)
    with np.errstate(divide="ignore"):
        return np.arctan((cs * W_y + sn * W_x) / (cs * W_x - sn * W_y))


def to_cam_frame(points: Array, phi_rad: Array, sense: str) -> Array:
    """Points of the follower's frame at cam angles φ turned back by −φ into the cam's own frame (m).

    >>> import numpy as np
    >>> to_cam_frame(np.array([[0.0, 1.0]]), np.array([np.pi / 2]), "ccw").round(12).tolist()
    [[1.0, 0.0]]
    """
    c, s = np.cos(phi_rad), np.sin(phi_rad)
    x, y = points[:, 0], points[:, 1]
    out = np.stack((x * c + y * s, -x * s + y * c), 1)
    if sense == "cw":
        out[:, 0] = -out[:, 0]
    return out
