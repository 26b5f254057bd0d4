"""The shaper mechanism: a slotted lever driving a ram through a connecting link.

The classic course-project mechanism (поперечно-строгальный станок, 牛头刨床): crank O1A (1),
block A (2) sliding on the slotted lever O3B (3), connecting link BC (4), ram C (5) on a
horizontal guide, the line y = ``y_guide`` (frame: O1 at the origin, as in
:class:`~graphmethods.kinematics.SlottedLever`). ``assembly=+1`` puts C on the +x side of B,
−1 on the −x side.

Position equations: the slotted lever's, then C = (x_B + σ√(l_BC² − (y_guide − y_B)²), y_guide).
The ram's extreme positions are the rocker's (checked: the link BC never comes in line with
the rocker, which would make the ram reverse in mid-stroke); the working stroke is the slow
one. Velocity plan: the slotted lever's, then c on the line through p ∥ guide and the line
through b ⟂ BC (v_C = v_B + v_CB).

>>> import math
>>> sh = Shaper(r=0.11, l_O1O3=0.38, l_O3B=0.54, l_BC=0.135, y_guide=0.1484)
>>> pos = sh.positions(m=12)
>>> round(pos.H, 4), round(math.degrees(pos.psi_max), 3)
(0.3126, 33.653)
>>> plan = sh.velocity_plans(pos)
>>> float(plan.v_along_guide("C")[0])
0.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from classic_reference import vectors as V
from classic_reference.mechanism import PointConstruction, _check_length, _fmt, fail, line
from classic_reference.slotted_lever import SlottedLever
from graphmethods.kinematics.positions import Positions


@dataclass(frozen=True, kw_only=True)
class Shaper(SlottedLever):
    """Shaper: slotted lever + connecting link BC + ram C on the guide y = y_guide.

    Parameters
    ----------
    r, l_O1O3, l_O3B, theta_O3, sense, working_stroke
        As for :class:`SlottedLever` (m, rad).
    l_BC : float
        Connecting link B–C, m.
    y_guide : float
        Height of the ram's guide line above O1 (y coordinate), m.
    assembly : int
        +1: C on the +x side of B; −1: on the −x side.
    points : mapping
        Extra points, e.g. ``{"S3": ("O3B", 0.27), "S4": ("BC", 0.0675)}``.
    """

    l_BC: float
    y_guide: float
    assembly: int = 1

    joints = ("O1", "A", "A3", "O3", "B", "C")
    link_joints = {"O1A": ("O1", "A"), "O3B": ("O3", "B"), "BC": ("B", "C")}
    link_numbers = {1: "O1A", 2: "block", 3: "O3B", 4: "BC"}
    kind = "shaper"

    def __post_init__(self):
        self._validate_lever()
        object.__setattr__(self, "l_BC", _check_length("l_BC", self.l_BC))
        object.__setattr__(self, "y_guide", _check_length("y_guide", self.y_guide, positive=False))
        self._validate_common()
        ox, oy = self.O3
        beta = math.asin(self.r / self.l_O1O3)
        centre = self.theta_O3 + math.pi               # rocker direction O3 -> O1
        # the rocker angle range [centre − β, centre + β]: where is |y_guide − y_B| largest?
        cands = [centre - beta, centre + beta]
        for t in (math.pi / 2, -math.pi / 2):
            if abs(float(V.wrap(t - centre))) <= beta:
                cands.append(t)
        q = [self.y_guide - (oy + self.l_O3B * math.sin(t)) for t in cands]
        i = max(range(len(q)), key=lambda j: abs(q[j]))
        if abs(q[i]) >= self.l_BC:
            fail(f"shaper: the link BC = {_fmt(self.l_BC)} m cannot reach the ram's guide y = {_fmt(self.y_guide)} m "
                 f"when the rocker is at {math.degrees(cands[i]) % 360:.4g}° (B is {_fmt(abs(q[i]))} m from the guide); "
                 f"make l_BC > {_fmt(abs(q[i]))} m or move the guide")
        t = np.linspace(centre - beta, centre + beta, 4097)
        yB = oy + self.l_O3B * np.sin(t)
        qq = self.y_guide - yB
        w = self.assembly * np.sqrt(self.l_BC ** 2 - qq * qq)
        f = (qq * np.cos(t) - w * np.sin(t)) / self.l_BC    # sin(angle BC − angle O3B)
        if not (np.all(f > 1e-9) or np.all(f < -1e-9)):
            j = int(np.argmin(np.abs(f)))
            fail(f"shaper: the link BC comes in line with the rocker O3B when the rocker is at "
                 f"{math.degrees(t[j]) % 360:.4g}°: the ram would stop and reverse before the rocker's extreme "
                 f"position; change l_BC, y_guide or assembly")

    # ------------------------------------------------------------------ geometry
    @property
    def guides(self):
        return {"C": (1.0, 0.0)}

    @property
    def omega_links(self):
        return ("O1A", "block", "O3B", "BC")

    def _link_length(self, canon: str) -> float:
        return {"O1A": self.r, "O3B": self.l_O3B, "BC": self.l_BC}[canon]

    def _geometry(self, phi):
        geom, theta = super()._geometry(phi)
        Bx, By = geom["B"]
        q = self.y_guide - By
        w = self.assembly * np.sqrt((self.l_BC - q) * (self.l_BC + q))
        geom["C"] = (Bx + w, np.full(phi.shape[0], self.y_guide))
        theta["BC"] = np.arctan2(q, w)
        return geom, theta

    def _output(self, geom, theta, strokes):
        out = self._rocker_output(theta, strokes, "O3B")
        out.update(self._slider_output(geom, strokes, "C"))
        return out

    # ------------------------------------------------------------------ velocity plan
    def _construct(self, pos: Positions, Om: float):
        vel, omegas, cons = super()._construct(pos, Om)
        n = pos.n
        g = pos._geom
        Bx, By = g["B"]
        Cx, Cy = g["C"]
        ux, uy = (Cx - Bx) / self.l_BC, (Cy - By) / self.l_BC     # unit B→C
        bx, by = vel["B"]
        # c: on the line through p ∥ guide and on the line through b ⟂ BC
        cx, _, s = V.intersect(0.0, 0.0, 1.0, 0.0, bx, by, -uy, ux)
        cx, cy = np.array(cx, dtype=float), np.zeros(n)
        vel["C"] = (cx, cy)
        self._snap_extremes(vel, {}, pos.extreme)
        omegas["BC"] = (ux * (cy - by) - uy * (cx - bx)) / self.l_BC
        cons.append(PointConstruction(
            name="C", method="intersection", equation="v_C = v_B + v_CB;  v_C ∥ guide, v_CB ⟂ BC",
            lines=(line("b", "perpendicular", "BC", bx, by, -uy, ux, n),
                   line("p", "parallel", "guide", 0.0, 0.0, 1.0, 0.0, n)),
            sin_between=V.frozen(np.asarray(s, dtype=float))))
        return vel, omegas, cons

    def _snap_extremes(self, vel, omegas, mask):
        super()._snap_extremes(vel, omegas, mask)
        if mask.any() and "C" in vel:
            vel["C"][0][mask] = 0.0
            vel["C"][1][mask] = 0.0

    def _toggle_text(self):
        return "the link BC stands perpendicular to the ram's guide"

    # ------------------------------------------------------------------ analytic derivative
    def _derivatives(self, phi):
        dxy, dth, theta, geom = super()._derivatives(phi)
        Bx, By = geom["B"]
        dxB, dyB = dxy["B"]
        q = self.y_guide - By
        w = self.assembly * np.sqrt(self.l_BC ** 2 - q * q)      # signed x-extent of BC
        dxy["C"] = (dxB + q * dyB / w, np.zeros_like(phi))
        dth["BC"] = -dyB / w
        return dxy, dth, theta, geom
