"""The crank and slotted lever (guide-bar, кулисный механизм, 导杆机构).

Crank O1–A turns about O1; a block (link 2) pinned to the crank at A slides along the slotted
lever (rocker, link 3) that swings about O3. Frame: O1 is the origin, O3 lies at distance
``l_O1O3`` from O1 in the direction ``theta_O3`` (default −π/2: O3 straight below O1, as in
the shaper). The rocker's end B is ``l_O3B`` from O3 along O3→A. The crank must be shorter
than O1O3 (oscillating slotted lever).

Points: O1, A (crank pin = A1 = A2, the block's centre), A3 (the point of the rocker under A),
O3, B. Links: 1 = crank ``"O1A"``, 2 = the block (``"block"``, turns with the rocker),
3 = rocker ``"O3B"``.

Extreme positions (exact): the rocker is tangent to the crank circle, O1A ⟂ O3A, at
φ = theta_O3 ± arccos(r / l_O1O3); the working (slow) stroke takes the crank round the far
side: working angle π + θ, return π − θ with θ = 2 arcsin(r / l_O1O3) (also the rocker's swing
ψ_max), K = (π + θ)/(π − θ).

Velocity plan: v_A2 = ω₁ × O1A (known); v_A3 = v_A2 + v_A3A2 with v_A3 ⟂ O3A (line through p)
and v_A3A2 ∥ O3A (line through a); rocker points by proportion, pb = pa3 · O3B/O3A.

>>> import math
>>> sl = SlottedLever(r=0.1, l_O1O3=0.3, l_O3B=0.5)
>>> st = sl.strokes()
>>> round(math.degrees(st.working_angle), 4), round(st.K, 4)
(218.9424, 1.5521)
>>> plan = sl.velocity_plans(sl.positions(m=12))
>>> float(plan.omega(3)[0]), round(float(plan.sin_min.min()), 12)
(0.0, 1.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from classic_reference import vectors as V
from classic_reference.mechanism import Mechanism, PointConstruction, _check_length, _deg, _fmt, fail, known, line, pole
from graphmethods.kinematics.positions import Positions


@dataclass(frozen=True, kw_only=True)
class SlottedLever(Mechanism):
    """Crank and oscillating slotted lever (see the module docstring).

    Parameters
    ----------
    r : float
        Crank O1A, m (< l_O1O3).
    l_O1O3 : float
        Centre distance O1O3, m.
    l_O3B : float
        Rocker O3B, m (≥ l_O1O3 + r, so the pin stays in the slot).
    theta_O3 : float
        Direction of O1→O3 from +x, rad (default −π/2: O3 below O1).
    sense : int
        +1 crank counterclockwise (default), −1 clockwise.
    working_stroke : str
        ``"slow"`` (default) or ``"fast"``.
    points : mapping
        Extra points, e.g. ``{"S3": ("O3B", 0.25, 0.0)}``.
    """

    r: float
    l_O1O3: float
    l_O3B: float
    theta_O3: float = -math.pi / 2
    sense: int = 1
    working_stroke: str = "slow"
    points: Any = field(default=())

    joints = ("O1", "A", "A3", "O3", "B")
    link_joints = {"O1A": ("O1", "A"), "O3B": ("O3", "B")}
    link_numbers = {1: "O1A", 2: "block", 3: "O3B"}
    kind = "slotted lever"

    def __post_init__(self):
        self._validate_lever()
        self._validate_common()

    def _validate_lever(self):
        for name in ("r", "l_O1O3", "l_O3B"):
            object.__setattr__(self, name, _check_length(name, getattr(self, name)))
        object.__setattr__(self, "theta_O3", _check_length("theta_O3", self.theta_O3, positive=False))
        r, d, L = self.r, self.l_O1O3, self.l_O3B
        if r >= d:
            fail(f"{self.kind}: crank r = {_fmt(r)} m is not shorter than the centre distance O1O3 = {_fmt(d)} m: the "
                 f"crank pin would pass {'through' if r == d else 'round'} the rocker's pivot O3 (a rotating guide-bar, "
                 f"not an oscillating slotted lever); make r < l_O1O3")
        if L < d + r:
            fail(f"{self.kind}: rocker O3B = {_fmt(L)} m is shorter than the farthest distance of the crank pin from "
                 f"O3, l_O1O3 + r = {_fmt(d + r)} m (at φ = {_deg(self.theta_O3 + math.pi)}): the pin would leave the "
                 f"slot; make l_O3B ≥ l_O1O3 + r")

    # ------------------------------------------------------------------ geometry
    @property
    def O3(self) -> tuple[float, float]:
        """Coordinates of the rocker pivot O3, m."""
        return self.l_O1O3 * math.cos(self.theta_O3), self.l_O1O3 * math.sin(self.theta_O3)

    @property
    def omega_links(self):
        return ("O1A", "block", "O3B")

    def _link_length(self, canon: str) -> float:
        return {"O1A": self.r, "O3B": self.l_O3B}[canon]

    def _geometry(self, phi):
        n = phi.shape[0]
        ox, oy = self.O3
        Ax, Ay = self.r * np.cos(phi), self.r * np.sin(phi)
        Dx, Dy = Ax - ox, Ay - oy
        rho = np.hypot(Dx, Dy)
        ux, uy = Dx / rho, Dy / rho
        th3 = np.arctan2(Dy, Dx)
        geom = {"O1": (np.zeros(n), np.zeros(n)), "A": (Ax, Ay), "A3": (Ax, Ay),
                "O3": (np.full(n, ox), np.full(n, oy)), "B": (ox + self.l_O3B * ux, oy + self.l_O3B * uy)}
        theta = {"O1A": np.array(phi, dtype=float), "block": th3, "O3B": th3}
        return geom, theta

    def _extremes(self):
        a = math.acos(self.r / self.l_O1O3)
        name = "rocker extreme (crank ⟂ rocker)"
        return (self.theta_O3 + a, name), (self.theta_O3 - a, name)

    def _output(self, geom, theta, strokes):
        return self._rocker_output(theta, strokes, "O3B")

    # ------------------------------------------------------------------ velocity plan
    def _construct(self, pos: Positions, Om: float):
        n = pos.n
        g = pos._geom
        ox, oy = self.O3
        Ax, Ay = g["A"]
        Dx, Dy = Ax - ox, Ay - oy
        rho = np.hypot(Dx, Dy)
        ux, uy = Dx / rho, Dy / rho
        ax, ay = -Om * Ay, Om * Ax                                    # pa2 ⟂ O1A
        # a3: on the line through p ⟂ O3A and on the line through a2 ∥ O3A
        a3x, a3y, s = V.intersect(0.0, 0.0, -uy, ux, ax, ay, ux, uy)
        a3x, a3y = np.array(a3x, dtype=float), np.array(a3y, dtype=float)
        k = self.l_O3B / rho                                          # pb = pa3 · O3B/O3A
        bx, by = a3x * k, a3y * k
        w3 = (ux * a3y - uy * a3x) / rho
        vel = {"O1": (np.zeros(n), np.zeros(n)), "A": (ax, ay), "A3": (a3x, a3y),
               "O3": (np.zeros(n), np.zeros(n)), "B": (bx, by)}
        omegas = {"O1A": np.full(n, Om), "block": w3, "O3B": w3.copy()}
        self._snap_extremes(vel, omegas, pos.extreme)
        cons = [pole("O1"), pole("O3"), known("A", "O1", "O1A"), PointConstruction(
            name="A3", method="intersection", equation="v_A3 = v_A2 + v_A3A2;  v_A3 ⟂ O3A, v_A3A2 ∥ O3A",
            lines=(line("p", "perpendicular", "O3A", 0.0, 0.0, -uy, ux, n),
                   line("a", "parallel", "O3A", ax, ay, ux, uy, n)),
            sin_between=V.frozen(np.asarray(s, dtype=float))),
            PointConstruction(name="B", method="proportion", on="O3B",
                              equation="pb = pa3 · O3B/O3A (points of the rocker by proportion)")]
        return vel, omegas, cons

    def _snap_extremes(self, vel, omegas, mask):
        if mask.any():
            for name in ("A3", "B"):
                vel[name][0][mask] = 0.0
                vel[name][1][mask] = 0.0
            for link in ("block", "O3B"):
                if link in omegas:
                    omegas[link][mask] = 0.0

    # ------------------------------------------------------------------ analytic derivative
    def _derivatives(self, phi):
        r, L = self.r, self.l_O3B
        geom, theta = self._geometry(phi)
        ox, oy = self.O3
        Ax, Ay = geom["A"]
        rho = np.hypot(Ax - ox, Ay - oy)
        th3 = theta["O3B"]
        dth3 = r * np.cos(phi - th3) / rho            # from r e^{iφ} = O3 + ρ e^{iθ3}
        c3, s3 = np.cos(th3), np.sin(th3)
        n = phi.shape[0]
        dxy = {"O1": (np.zeros(n), np.zeros(n)), "A": (-r * np.sin(phi), r * np.cos(phi)),
               "A3": (-rho * dth3 * s3, rho * dth3 * c3), "O3": (np.zeros(n), np.zeros(n)),
               "B": (-L * dth3 * s3, L * dth3 * c3)}
        return dxy, {"O1A": np.ones(n), "block": dth3, "O3B": dth3}, theta, geom
