"""The (offset) slider-crank: crank O–A, connecting rod A–B, slider B on the line y = e.

Frame: the crank centre O is the origin; the slider's guide is the line y = e, parallel to x
(e is the offset, signed). ``assembly=+1`` puts B on the +x side of A (x_B > x_A), −1 on the
−x side. Links: 1 = crank ``"OA"``, 2 = rod ``"AB"``, 3 = slider B (translates).

Position equations: A = r(cos φ, sin φ); B = (r cos φ + σ√(l² − (e − r sin φ)²), e).
Dead centres (exact): far, |OB| = l + r with A on OB; near, |OB| = l − r with A opposite.
``working_stroke`` = ``"toward_crank"`` (default: position 0 is the far dead centre, as in the
press problem), ``"away_from_crank"``, ``"slow"`` or ``"fast"``.

>>> import math
>>> mech = SliderCrank(r=0.1, l=0.4, e=0.02, points={"S2": ("AB", 0.13)})
>>> st = mech.strokes()
>>> round(math.degrees(st.phi_start), 4), st.start_name
(2.2924, 'far dead centre')
>>> plan = mech.velocity_plans(mech.positions(m=12))
>>> float(plan.v_along_guide("B")[0]), round(float(plan.omega("AB")[0]), 6)
(0.0, -0.25)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from classic_reference import vectors as V
from classic_reference.mechanism import Mechanism, PointConstruction, _check_length, _fmt, fail, known, line, pole
from graphmethods.kinematics.positions import Positions


@dataclass(frozen=True, kw_only=True)
class SliderCrank(Mechanism):
    """Offset slider-crank (see the module docstring).

    Parameters
    ----------
    r : float
        Crank O–A, m.
    l : float
        Connecting rod A–B, m (must exceed r + |e| for a full crank turn).
    e : float
        Offset: the slider's guide is the line y = e, m.
    assembly : int
        +1: B on the +x side of A; −1: on the −x side.
    sense : int
        +1 crank counterclockwise (default), −1 clockwise.
    working_stroke : str
        Which dead centre starts the working stroke: ``"toward_crank"`` (far dead centre),
        ``"away_from_crank"`` (near), ``"slow"`` or ``"fast"`` (by crank angle).
    points : mapping
        Extra points ``{"S2": ("AB", 0.13, 0.0)}`` (link, distance m from its first joint,
        angle rad from the link line).
    """

    r: float
    l: float
    e: float = 0.0
    assembly: int = 1
    sense: int = 1
    working_stroke: str = "toward_crank"
    points: Any = field(default=())

    joints = ("O", "A", "B")
    link_joints = {"OA": ("O", "A"), "AB": ("A", "B")}
    link_numbers = {1: "OA", 2: "AB"}
    working_strokes = ("toward_crank", "away_from_crank", "slow", "fast")
    kind = "slider-crank"

    def __post_init__(self):
        for name in ("r", "l"):
            object.__setattr__(self, name, _check_length(name, getattr(self, name)))
        object.__setattr__(self, "e", _check_length("e", self.e, positive=False))
        self._validate_common()
        r, l, e = self.r, self.l, self.e
        if l <= r + abs(e):
            worse = "shorter than" if l < (r + abs(e)) * (1 - 1e-12) else "not longer than"
            # where |e − r sin φ| > l (or = l): around φ = 270° for e ≥ 0, 90° for e < 0
            k = min(1.0, (l - abs(e)) / r) if r > 0 else 1.0
            a = math.asin(max(-1.0, k))
            lo, hi = (math.pi + a, 2 * math.pi - a) if e >= 0 else (a, math.pi - a)
            where = (f"assembly fails for φ in ({math.degrees(lo):.4g}°, {math.degrees(hi):.4g}°)" if hi > lo + 1e-9
                     else f"the rod stands perpendicular to the guide at φ = {math.degrees(lo):.4g}°")
            fail(f"slider-crank: rod l = {_fmt(l)} m is {worse} crank r + |e| = {_fmt(r + abs(e))} m: the slider "
                 f"cannot follow a full crank turn ({where}); make l > r + |e|")

    # ------------------------------------------------------------------ geometry
    @property
    def guides(self):
        return {"B": (1.0, 0.0)}

    def _link_length(self, canon: str) -> float:
        return self.r if canon == "OA" else self.l

    def _geometry(self, phi):
        n = phi.shape[0]
        c, s = np.cos(phi), np.sin(phi)
        Ax, Ay = self.r * c, self.r * s
        q = self.e - Ay
        w = np.sqrt((self.l - q) * (self.l + q))
        sw = self.assembly * w
        geom = {"O": (np.zeros(n), np.zeros(n)), "A": (Ax, Ay), "B": (Ax + sw, np.full(n, self.e))}
        theta = {"OA": np.array(phi, dtype=float), "AB": np.arctan2(q, sw)}
        return geom, theta

    def _extremes(self):
        r, l, e, sg = self.r, self.l, self.e, self.assembly
        x_far = sg * math.sqrt((l + r) ** 2 - e * e)
        x_near = sg * math.sqrt((l - r) ** 2 - e * e)
        return (math.atan2(e, x_far), "far dead centre"), (math.atan2(-e, -x_near), "near dead centre")

    def _start_is_a(self, t_ab: float) -> bool:
        if self.working_stroke == "toward_crank":
            return True
        if self.working_stroke == "away_from_crank":
            return False
        return super()._start_is_a(t_ab)

    def _output(self, geom, theta, strokes):
        return self._slider_output(geom, strokes, "B")

    # ------------------------------------------------------------------ velocity plan
    def _construct(self, pos: Positions, Om: float):
        n = pos.n
        g = pos._geom
        Ax, Ay = g["A"]
        Bx, By = g["B"]
        ax, ay = -Om * Ay, Om * Ax                       # pa ⟂ OA, |pa| = ω₁ r
        ux, uy = (Bx - Ax) / self.l, (By - Ay) / self.l  # unit A→B
        # b: on the line through p ∥ guide, and on the line through a ⟂ AB
        bx, by, s = V.intersect(0.0, 0.0, 1.0, 0.0, ax, ay, -uy, ux)
        bx = np.array(bx, dtype=float)
        by = np.zeros(n)
        vel = {"O": (np.zeros(n), np.zeros(n)), "A": (ax, ay), "B": (bx, by)}
        self._snap_extremes(vel, {}, pos.extreme)
        w2 = (ux * (by - ay) - uy * (bx - ax)) / self.l    # ω₂ = (AB × ab)/l²
        omegas = {"OA": np.full(n, Om), "AB": w2}
        cons = [pole("O"), known("A", "O", "OA"), PointConstruction(
            name="B", method="intersection", equation="v_B = v_A + v_BA;  v_B ∥ guide, v_BA ⟂ AB",
            lines=(line("a", "perpendicular", "AB", ax, ay, -uy, ux, n), line("p", "parallel", "guide", 0.0, 0.0, 1.0, 0.0, n)),
            sin_between=V.frozen(np.asarray(s, dtype=float)))]
        return vel, omegas, cons

    def _snap_extremes(self, vel, omegas, mask):
        if mask.any():
            vel["B"][0][mask] = 0.0
            vel["B"][1][mask] = 0.0

    def _toggle_text(self):
        return "the rod stands perpendicular to the guide"

    # ------------------------------------------------------------------ analytic derivative
    def _derivatives(self, phi):
        r, l, e, sg = self.r, self.l, self.e, self.assembly
        c, s = np.cos(phi), np.sin(phi)
        q = e - r * s
        w = np.sqrt(l * l - q * q)
        dA = (-r * s, r * c)
        dxB = -r * s + sg * q * r * c / w
        dB = (dxB, np.zeros_like(phi))
        dth2 = -r * c / (sg * w)
        geom, theta = self._geometry(phi)
        n = phi.shape[0]
        dxy = {"O": (np.zeros(n), np.zeros(n)), "A": dA, "B": dB}
        return dxy, {"OA": np.ones(n), "AB": dth2}, theta, geom
