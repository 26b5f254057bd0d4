"""The cam designed and analysed: base radius, pressure angles, curvature, impacts, profile.

:func:`design` takes a :class:`~graphmethods.kinematics.cam.problem.CamProblem` and returns a
frozen :class:`CamDesign`. Every extremum is exact to rounding: it is the maximum over the cam
angle of a closed-form function, found per smooth piece of each phase by a grid and golden
sections (:func:`~graphmethods.kinematics.cam.extrema.maximize`).

* Base radius given: ``base_radius`` of the profile; the pitch curve's is r₀ = r_b + r_r.
* Translating knife or roller, designed: |α| ≤ [α] on the rise and ≤ [α]_return on the return
  means ``s₀ ≥ |ds/dφ − e|/tan[α] − s`` at every φ of the phase, so
  ``s₀ = max over the rises and returns of (|ds/dφ − e|/tan[α] − s)`` and ``r₀ = √(s₀² + e²)``
  (the combined ds/dφ–s diagram's construction, in closed form).
* Oscillating knife or roller, designed: the smallest r₀ with the largest |α| of the rise and of the
  return within their limits, by bisection on r₀ (|α| falls as r₀ grows).
* Flat face, designed: ``r_b = max over φ of (ρ_min − s − d²s/dφ²)``, the smallest with the profile's
  radius of curvature ρ = r_b + s + s'' ≥ ρ_min everywhere.

>>> from graphmethods.kinematics.cam.problem import EXAMPLE, cam_from_dict
>>> d = design(cam_from_dict(EXAMPLE))
>>> round(d.pitch_base_radius, 9), round(d.alpha_max_rise_deg, 9)
(0.016410132, 30.0)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import TypeVar

import numpy as np
from numpy.typing import NDArray

from graphmethods.errors import InputError
from graphmethods.kinematics.cam.extrema import maximize, maximize_rows
from graphmethods.kinematics.cam.geometry import (
    PitchFrame,
    pitch_frame,
    pressure_angle,
    pressure_angle_at,
    psi_0,
    to_cam_frame,
)
from graphmethods.kinematics.cam.problem import CamProblem, Phase

Array = NDArray[np.float64]
K = TypeVar("K")
V = TypeVar("V")
#: a function of (s, ds/dφ, d²s/dφ²) over a phase, to be maximised
Objective = Callable[[Array, Array, Array], Array]


@dataclass(frozen=True)
class Impact:
    """A jump of the follower's velocity (``hard``: infinite acceleration) or acceleration (``soft``).

    Attributes
    ----------
    phi_deg : float
        Where, degrees of cam turn.
    kind : str
        ``hard`` or ``soft``.
    jump : float
        The jump of v (m/s, or rad/s) for a hard impact, of a (m/s², or rad/s²) for a soft one.
    """

    phi_deg: float
    kind: str
    jump: float


@dataclass(frozen=True)
class CamState:
    """The cam at a set of angles: motion, pressure angle, pitch and profile points (SI, cam frame)."""

    phi_deg: Array
    s: Array
    ds: Array
    d2s: Array
    d3s: Array
    v: Array
    a: Array
    jerk: Array
    alpha_deg: Array
    pitch: Array
    profile: Array


@dataclass(frozen=True)
class CamDesign:
    """A cam mechanism solved: the base radii and the extremes that judge it.

    Attributes
    ----------
    problem : CamProblem
    base_radius : float
        r_b, the profile's base radius, m (designed, or the file's).
    pitch_base_radius : float
        r₀ = r_b + r_r, m (= r_b for a knife or a flat face).
    designed : bool
        True when r_b was designed, False when the file gave it.
    alpha_max_rise_deg, alpha_max_return_deg : float
        The largest |α| over the rises and over the returns, degrees (0 for a flat face).
    phi_alpha_max_rise_deg, phi_alpha_max_return_deg : float
        Where they occur, degrees.
    rho_pitch_min : float
        The smallest radius of curvature of the pitch curve where convex, m (flat face: of the profile).
    phi_rho_min_deg : float
        Where it occurs, degrees.
    undercut : bool
        rho_pitch_min below the roller radius (flat face: the profile's ρ not positive).
    face_width_min : float or None
        Flat face: 2·max|ds/dφ|, m.
    impacts : tuple of Impact
    """

    problem: CamProblem
    base_radius: float
    pitch_base_radius: float
    designed: bool
    alpha_max_rise_deg: float
    alpha_max_return_deg: float
    phi_alpha_max_rise_deg: float
    phi_alpha_max_return_deg: float
    rho_pitch_min: float
    phi_rho_min_deg: float
    undercut: bool
    face_width_min: float | None
    impacts: tuple[Impact, ...]

    def frame(self, s: Array, s1: Array, s2: Array) -> PitchFrame:
        """The pitch frame (:func:`~graphmethods.kinematics.cam.geometry.pitch_frame`) at this r₀."""
        p = self.problem
        return pitch_frame(p.follower_type, self.pitch_base_radius, s, s1, s2, offset=p.offset, arm=p.arm,
                           pivot=p.pivot)

    def state(self, phi_deg: Array | list[float]) -> CamState:
        """Motion, pressure angle, pitch point and profile point at cam angles φ (degrees).

        >>> from graphmethods.kinematics.cam.problem import EXAMPLE, cam_from_dict
        >>> st = design(cam_from_dict(EXAMPLE)).state([0.0, 60.0])
        >>> [round(float(x), 9) for x in st.s], st.pitch.shape
        ([0.0, 0.01], (2, 2))
        """
        p = self.problem
        phi = np.asarray(phi_deg, dtype=float)
        s, s1, s2, s3 = p.motion(phi)
        w = p.omega
        rad = np.radians(np.mod(phi, 360.0))
        if p.contact == "flat":
            alpha = np.zeros_like(s)
            pitch = np.stack((np.zeros_like(s) + p.offset, self.base_radius + s), 1)
            prof = np.stack((s1, self.base_radius + s), 1)
        else:
            g = self.frame(s, s1, s2)
            alpha, pitch = g.alpha, g.B
            prof = g.profile(p.roller_radius) if p.contact == "roller" else g.B
        return CamState(phi, s, s1, s2, s3, w * s1, w * w * s2, w ** 3 * s3, np.degrees(alpha),
                        to_cam_frame(pitch, rad, p.sense), to_cam_frame(prof, rad, p.sense))


def _smooth_pieces(phases: tuple[Phase, ...], kinds: tuple[str, ...]) -> Iterator[tuple[Phase, float, float, bool]]:
    """(phase, x_lo, x_hi, left) for every smooth piece of the phases of these kinds."""
    for ph in phases:
        if ph.kind in kinds:
            for lo, hi in ph.pieces():
                yield ph, lo, hi, hi < 1.0


def _phase_max(ph: Phase, lo: float, hi: float, left: bool, g: Objective, stop_above: float | None = None
               ) -> tuple[float, float]:
    """max over x in [lo, hi] of g(s, s1, s2) on one piece of a phase: (φ in degrees, value)."""
    x, v = maximize(lambda t: g(*ph.values(t, left=left)[:3]), lo, hi, stop_above=stop_above)
    return ph.start_deg + x * ph.angle_deg, v


def _max_over(phases: tuple[Phase, ...], kinds: tuple[str, ...], g: Objective, stop_above: float | None = None
              ) -> tuple[float, float]:
    """(φ in degrees, value) of the largest g over the phases of these kinds (with ``stop_above``: any
    value above it as soon as one is found, see :func:`~graphmethods.kinematics.cam.extrema.maximize`)."""
    best = (0.0, -math.inf)
    for ph, lo, hi, left in _smooth_pieces(phases, kinds):
        cand = _phase_max(ph, lo, hi, left, g, stop_above)
        if cand[1] > best[1]:
            best = cand
        if stop_above is not None and best[1] > stop_above:
            break
    return best


def _tan(deg: float) -> float:
    return math.tan(math.radians(deg))


def _design_translating(p: CamProblem) -> float:
    """r₀ of a translating knife or roller follower: s₀ = max(|s' − e|/tan[α] − s), r₀ = √(s₀² + e²)."""
    e = p.offset
    assert p.alpha_max_deg is not None
    s0 = -math.inf
    for kind, limit in (("rise", p.alpha_max_deg), ("return", p.alpha_return_max_deg)):
        t = _tan(limit)

        def need(s: Array, s1: Array, s2: Array, t: float = t) -> Array:
            return np.abs(s1 - e) / t - s
        s0 = max(s0, _max_over(p.phases, (kind,), need)[1])
    if not s0 > 0.0:
        raise InputError(f"the pressure angle limits hold at any base radius (s₀ = {s0:g} m); give base_radius")
    return math.hypot(s0, e)


def _alpha_max(p: CamProblem, r0: float, kind: str, stop_above: float | None = None) -> tuple[float, float]:
    """(φ, largest |α| in rad) over the phases of this kind at the pitch base radius r₀ (with ``stop_above``:
    any |α| above it, as soon as the grid shows one)."""
    def g(s: Array, s1: Array, s2: Array) -> Array:
        if p.oscillating:                   # α alone, the bits of the k-section's admissible()
            return np.abs(pressure_angle(r0, s, s1, arm=p.arm, pivot=p.pivot))
        return np.abs(pitch_frame(p.follower_type, r0, s, s1, s2, offset=p.offset, arm=p.arm, pivot=p.pivot).alpha)
    return _max_over(p.phases, (kind,), g, stop_above)


def psi_0_rows(r0: Array, arm: float, pivot: float) -> tuple[Array, NDArray[np.bool_]]:
    """ψ₀ of each base radius r₀ (rad, :func:`~graphmethods.kinematics.cam.geometry.psi_0` one by one, so the
    same bits) and whether the arm reaches it (where not, ψ₀ is 0).

    >>> psi, ok = psi_0_rows(np.array([0.05, 0.5]), 0.1, 0.12)
    >>> psi.round(6).tolist(), ok.tolist()
    ([0.421442, 0.0], [True, False])
    """
    psi = np.zeros(len(r0))
    ok = np.zeros(len(r0), dtype=bool)
    for i, r in enumerate(np.asarray(r0, dtype=float).tolist()):
        try:
            psi[i], ok[i] = psi_0(r, arm, pivot), True
        except InputError:
            pass
    return psi, ok


def _design_oscillating(p: CamProblem) -> float:
    """r₀ of an oscillating knife or roller follower: the smallest with |α| within the limits (k-section on r₀,
    every candidate at once)."""
    assert p.alpha_max_deg is not None
    lim = {"rise": math.radians(p.alpha_max_deg), "return": math.radians(p.alpha_return_max_deg)}
    lo_r, hi_r = abs(p.pivot - p.arm), p.pivot + p.arm

    def admissible(r0: Array) -> NDArray[np.bool_]:
        psi0, ok = psi_0_rows(r0, p.arm, p.pivot)
        ok &= psi0 + p.stroke < math.pi
        col = psi0[:, None]
        worst = np.full(len(r0), -math.inf)     # only its sign counts: a grid value over a limit settles it
        for ph, lo, hi, left in _smooth_pieces(p.phases, tuple(lim)):
            def g(x: Array, ph: Phase = ph, left: bool = left) -> Array:
                s, s1 = ph.values(x, left=left)[:2]
                return np.abs(pressure_angle_at(col, s, s1, arm=p.arm, pivot=p.pivot))
            worst = np.maximum(worst, maximize_rows(g, lo, hi, len(r0), stop_above=lim[ph.kind])[1] - lim[ph.kind])
        return ok & (worst <= 0.0)
    r0 = smallest_admissible(lo_r, hi_r, admissible)
    if r0 is None:
        raise InputError(f"no base radius keeps the pressure angles within [α] = {p.alpha_max_deg:g}° / "
                         f"{p.alpha_return_max_deg:g}° with this arm and pivot; give base_radius or change them")
    return r0


def smallest_admissible(lo_r: float, hi_r: float, admissible: Callable[[Array], NDArray[np.bool_]], *,
                        per_round: int = 64) -> float | None:
    """The smallest r in (lo_r, hi_r) with ``admissible(r)`` (true from there up): the first admissible of 64
    grid points, then k-section to rounding (``per_round`` points of the bracket asked at once, the bracket
    shrinking to the gap between the last inadmissible and the first admissible of them); None when no grid
    point is admissible.

    Parameters
    ----------
    lo_r, hi_r : float
        The open interval searched.
    admissible : callable
        Vectorised: an array of r to an array of booleans.
    per_round : int
        Points asked at once in each round (≥ 1; 1 is a bisection).

    Returns
    -------
    float or None
        The smallest admissible float (two neighbouring floats bracket the change), or None.

    Examples
    --------
    >>> round(smallest_admissible(0.0, 1.0, lambda r: r >= 0.3), 12)
    0.3
    >>> smallest_admissible(0.0, 1.0, lambda r: r >= 0.3) == smallest_admissible(0.0, 1.0, lambda r: r >= 0.3,
    ...                                                                             per_round=1)
    True
    """
    grid = np.linspace(lo_r, hi_r, 66)[1:-1]
    ok = np.asarray(admissible(grid), dtype=bool)
    if not ok.any():
        return None
    i = int(np.argmax(ok))
    lo, hi = (float(grid[i - 1]) if i > 0 else lo_r), float(grid[i])
    for _ in range(200):
        mids = np.unique(np.linspace(lo, hi, per_round + 2)[1:-1])
        mids = mids[(mids > lo) & (mids < hi)]
        if not mids.size:                   # lo and hi neighbouring floats
            break
        ok = np.asarray(admissible(mids), dtype=bool)
        j = int(np.argmax(ok)) if ok.any() else len(mids)
        lo, hi = (float(mids[j - 1]) if j > 0 else lo), (float(mids[j]) if j < len(mids) else hi)
    return hi


def _impacts(p: CamProblem) -> tuple[Impact, ...]:
    """Jumps of velocity (hard) and acceleration (soft) at phase boundaries and inside parabolic phases."""
    out = []
    n = len(p.phases)
    scale_v = max(abs(float(v)) for ph in p.phases for v in ph.values(np.linspace(0, 1, 9))[1]) or 1.0
    scale_a = max(abs(float(v)) for ph in p.phases for v in ph.values(np.linspace(0, 1, 9))[2]) or 1.0
    joins = []
    for i, ph in enumerate(p.phases):
        nxt = p.phases[(i + 1) % n]
        end = [float(v[0]) for v in ph.values(np.array([1.0]), left=True)]
        start = [float(v[0]) for v in nxt.values(np.array([0.0]))]
        joins.append((nxt.start_deg, end, start))
        for lo, _hi in ph.pieces()[1:]:
            a = [float(v[0]) for v in ph.values(np.array([lo]), left=True)]
            b = [float(v[0]) for v in ph.values(np.array([lo]))]
            joins.append((ph.start_deg + lo * ph.angle_deg, a, b))
    for phi, before, after in sorted(joins, key=lambda j: j[0]):
        dv, da = after[1] - before[1], after[2] - before[2]
        if abs(dv) > 1e-9 * scale_v:
            out.append(Impact(phi % 360.0, "hard", p.omega * dv))
        elif abs(da) > 1e-9 * scale_a:
            out.append(Impact(phi % 360.0, "soft", p.omega ** 2 * da))
    return tuple(out)


#: the designs made in this process, by problem (frozen, hashable): the gallery, a sheet's figures and a class
#: set draw one cam several times, and an oscillating follower's bisection on r₀ is the costly part
_DESIGNS: dict[CamProblem, CamDesign] = {}


def design(p: CamProblem) -> CamDesign:
    """Design (or take) the base radius and find the cam's extremes (see the module's docstring).

    Made once per problem in a process (a :class:`CamDesign` is frozen: the same problem gives the same
    design, shared).

    Parameters
    ----------
    p : CamProblem

    Returns
    -------
    CamDesign

    Raises
    ------
    InputError
        A base radius that cannot be designed or used (the message says why and what to give).

    Examples
    --------
    >>> from graphmethods.kinematics.cam.problem import EXAMPLE, cam_from_dict
    >>> design(cam_from_dict(EXAMPLE)) is design(cam_from_dict(EXAMPLE))
    True
    """
    return made_once(_DESIGNS, p, design_afresh)


def made_once(cache: dict[K, V], key: K, make: Callable[[K], V]) -> V:
    """``make(key)``, kept in ``cache`` for the process (at most 64 entries; a key that cannot be hashed is
    made afresh): the cam's design and the rocker zone's boundary are made once per frozen value.

    >>> made: dict[float, float] = {}
    >>> made_once(made, 2.0, lambda x: x * x), made
    (4.0, {2.0: 4.0})
    """
    try:
        found = cache.get(key)
    except TypeError:                       # something unhashable inside: made afresh
        return make(key)
    if found is None:
        if len(cache) >= 64:
            cache.clear()
        found = cache[key] = make(key)
    return found


def design_afresh(p: CamProblem) -> CamDesign:
    """:func:`design` without the process's cache (what the bench times); the same parameters, result and
    errors."""
    rr = p.roller_radius
    designed = p.base_radius is None
    if p.contact == "flat":
        rb = p.base_radius if p.base_radius is not None else _max_over(
            p.phases, ("rise", "dwell", "return"), lambda s, s1, s2: p.rho_min_allowed - s - s2)[1]
        if not rb > 0.0:
            raise InputError(f"the designed base radius came out {rb:g} m (not positive): give rho_min_allowed > 0 or "
                             "base_radius")
        r0 = rb
    else:
        if p.base_radius is not None:
            r0 = p.base_radius + rr
        else:
            r0 = _design_oscillating(p) if p.oscillating else _design_translating(p)
        rb = r0 - rr
        if not rb > 0.0:
            raise InputError(f"the designed pitch base radius {r0:g} m is not larger than the roller radius {rr:g} m; "
                             "give base_radius or a smaller roller")
    kinds = ("rise", "dwell", "return")
    if p.contact == "flat":
        phi_rho, neg = _max_over(p.phases, kinds, lambda s, s1, s2: -(rb + s + s2))
        rho = -neg
        undercut = not rho > 0.0
        alpha_r = alpha_t = (0.0, 0.0)
        width: float | None = 2.0 * _max_over(p.phases, kinds, lambda s, s1, s2: np.abs(s1))[1]
    else:
        def kappa(s: Array, s1: Array, s2: Array) -> Array:
            return pitch_frame(p.follower_type, r0, s, s1, s2, offset=p.offset, arm=p.arm, pivot=p.pivot).kappa
        phi_rho, k_max = _max_over(p.phases, kinds, kappa)
        rho = 1.0 / k_max if k_max > 0.0 else math.inf
        if any(i.kind == "hard" and i.jump < 0.0 for i in _impacts(p)):
            rho = 0.0                            # a drop of ds/dφ is a convex corner of the pitch curve
        undercut = p.contact == "roller" and rho < rr
        alpha_r, alpha_t = _alpha_max(p, r0, "rise"), _alpha_max(p, r0, "return")
        width = None
    return CamDesign(p, rb, r0, designed, math.degrees(max(alpha_r[1], 0.0)), math.degrees(max(alpha_t[1], 0.0)),
                     alpha_r[0], alpha_t[0], rho, phi_rho, undercut, width, _impacts(p))
