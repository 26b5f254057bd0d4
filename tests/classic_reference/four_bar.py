"""The four-bar linkage O1–A–B–O2: crank O1A, coupler AB, rocker O2B on the ground O1O2.

Frame: O1 is the origin; O2 = l1 (cos γ, sin γ) with γ = ``ground_angle``. ``assembly=+1``
puts B on the left of the directed line A→O2 (for a horizontal ground and the usual drawing:
B above the ground line at the extreme positions); −1 is the mirror (crossed) branch. The
branch is kept for every position, which is continuous over the cycle whenever the linkage
assembles at every position (never passes a toggle).

Links: 1 = crank ``"O1A"`` (length l2), 2 = coupler ``"AB"`` (l3), 3 = rocker ``"O2B"`` (l4);
the ground O1O2 has length l1. (Lengths follow the loop-closure numbering l1…l4; link numbers
follow the textbook numbering with the crank as link 1.)

Position equations: d = |O2A|; B is the intersection of the circles (A, l3) and (O2, l4),
B = A + a ê + σ h ê⟂ with a = (l3² − l4² + d²)/2d and h from Heron's formula (no cancellation
near the toggle). The crank turns fully iff l1 + l2 < l3 + l4 and |l1 − l2| > |l3 − l4|
(Grashof with the crank or the ground shortest). A linkage whose crank cannot turn fully
(double rocker, triple rocker) can still be studied with ``positions(phi=...)`` inside the
range where it assembles. The rocker's extreme positions (crank and coupler extended /
folded) are found in closed form; position 0 starts the slow stroke unless
``working_stroke="fast"``.

>>> import math
>>> fb = FourBar(l1=0.30, l2=0.08, l3=0.25, l4=0.20)
>>> st = fb.strokes()
>>> round(math.degrees(st.working_angle), 3), round(st.K, 4)
(182.7, 1.0305)
>>> plan = fb.velocity_plans(fb.positions(m=12))
>>> bool(plan.ill_conditioned.any()), float(plan.omega("O2B")[0])
(False, 0.0)
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
class FourBar(Mechanism):
    """Four-bar linkage (see the module docstring).

    Parameters
    ----------
    l1 : float
        Ground O1O2, m.
    l2 : float
        Crank O1A, m.
    l3 : float
        Coupler AB, m.
    l4 : float
        Rocker O2B, m.
    ground_angle : float
        Direction of O1→O2 from +x, rad (default 0: O2 on the +x axis).
    assembly : int
        +1: B on the left of A→O2; −1: the other branch.
    sense : int
        +1 crank counterclockwise (default), −1 clockwise.
    working_stroke : str
        ``"slow"`` (default) or ``"fast"``: which swing of the rocker is the working stroke.
    points : mapping
        Extra points ``{"S2": ("AB", 0.125, 0.0), "K": ("AB", 0.1, 0.5)}``.
    """

    l1: float
    l2: float
    l3: float
    l4: float
    ground_angle: float = 0.0
    assembly: int = 1
    sense: int = 1
    working_stroke: str = "slow"
    points: Any = field(default=())

    joints = ("O1", "A", "B", "O2")
    link_joints = {"O1A": ("O1", "A"), "AB": ("A", "B"), "O2B": ("O2", "B")}
    link_numbers = {1: "O1A", 2: "AB", 3: "O2B"}
    kind = "four-bar"

    def __post_init__(self):
        for name in ("l1", "l2", "l3", "l4"):
            object.__setattr__(self, name, _check_length(name, getattr(self, name)))
        object.__setattr__(self, "ground_angle", _check_length("ground_angle", self.ground_angle, positive=False))
        self._validate_common()
        lens = {"l1 (ground O1O2)": self.l1, "l2 (crank O1A)": self.l2, "l3 (coupler AB)": self.l3,
                "l4 (rocker O2B)": self.l4}
        longest = max(lens, key=lens.get)
        rest = sum(lens.values()) - lens[longest]
        if lens[longest] >= rest:
            fail(f"four-bar: the links cannot close a loop: the longest, {longest} = {_fmt(lens[longest])} m, is "
                 f"not shorter than the sum of the other three = {_fmt(rest)} m")

    # ------------------------------------------------------------------ conditions
    @property
    def turns_fully(self) -> bool:
        """True if the crank O1A can make full turns (crank-rocker or double crank)."""
        l1, l2, l3, l4 = self.l1, self.l2, self.l3, self.l4
        return l1 + l2 < l3 + l4 and abs(l1 - l2) > abs(l3 - l4)

    @property
    def grashof(self) -> str:
        """Grashof classification: ``"crank-rocker"``, ``"double-crank"``, ``"double-rocker"``
        (Grashof, coupler shortest), ``"rocker-crank"`` (Grashof, rocker shortest: the input rocks),
        ``"triple-rocker"`` (non-Grashof) or ``"change-point"`` (s + l = p + q)."""
        ls = [self.l1, self.l2, self.l3, self.l4]
        s, L = min(ls), max(ls)
        pq = sum(ls) - s - L
        if math.isclose(s + L, pq, rel_tol=1e-12):
            return "change-point"
        if s + L > pq:
            return "triple-rocker"
        i = ls.index(s)
        return ("double-crank", "crank-rocker", "double-rocker", "rocker-crank")[i]

    def _grashof_text(self) -> str:
        ls = {"ground O1O2": self.l1, "crank O1A": self.l2, "coupler AB": self.l3, "rocker O2B": self.l4}
        s_name = min(ls, key=ls.get)
        s, L = ls[s_name], max(ls.values())
        pq = sum(ls.values()) - s - L
        kind = self.grashof
        if kind == "triple-rocker":
            return f"Grashof is violated (s + l = {_fmt(s + L)} m > p + q = {_fmt(pq)} m): no link turns fully"
        if kind == "change-point":
            return f"s + l = p + q = {_fmt(pq)} m: a change-point linkage that passes through a toggle"
        if kind in ("double-rocker", "rocker-crank"):
            return (f"Grashof holds (s + l = {_fmt(s + L)} m < p + q = {_fmt(pq)} m) but the shortest link is the "
                    f"{s_name}, so O1A can only rock; a crank needs the crank O1A or the ground as the shortest link")
        return f"Grashof holds (s + l = {_fmt(s + L)} m < p + q = {_fmt(pq)} m), {kind}"

    def _failing_ranges(self) -> list[str]:
        l1, l2, l3, l4, g = self.l1, self.l2, self.l3, self.l4, self.ground_angle
        out = []
        c_hi = (l1 * l1 + l2 * l2 - (l3 + l4) ** 2) / (2 * l1 * l2)
        c_lo = (l1 * l1 + l2 * l2 - (l3 - l4) ** 2) / (2 * l1 * l2)
        eps = 1e-12
        if c_hi >= -1.0 - eps:
            a = math.acos(max(-1.0, min(1.0, c_hi)))
            if a < math.pi:
                out.append(f"φ in ({_deg(g + a)}, {_deg(g + 2 * math.pi - a)}) where |O2A| > l3 + l4 = "
                           f"{_fmt(l3 + l4)} m (coupler and rocker cannot reach)")
            else:
                out.append(f"φ = {_deg(g + math.pi)} where coupler and rocker come in line (toggle)")
        if c_lo <= 1.0 + eps:
            a = math.acos(min(1.0, max(-1.0, c_lo)))
            if a > 0:
                out.append(f"φ in ({_deg(g - a)}, {_deg(g + a)}) where |O2A| < |l3 − l4| = {_fmt(abs(l3 - l4))} m")
            else:
                out.append(f"φ = {_deg(g)} where coupler and rocker fold onto each other (toggle)")
        if not out:   # never an empty "assembly fails for ." (a change-point linkage's toggles, rounding aside)
            out.append(f"the toggle positions, where coupler and rocker come in line (l1 = {_fmt(l1)}, "
                       f"l2 = {_fmt(l2)}, l3 = {_fmt(l3)}, l4 = {_fmt(l4)} m)")
        return out

    def _check_full_turn(self) -> None:
        if not self.turns_fully:
            fail(f"four-bar l1 = {_fmt(self.l1)}, l2 = {_fmt(self.l2)}, l3 = {_fmt(self.l3)}, l4 = {_fmt(self.l4)} m: "
                 f"the crank O1A cannot make a full turn; assembly fails for " + "; and for ".join(self._failing_ranges())
                 + f". {self._grashof_text()}. Use positions(phi=...) inside the range where it assembles, or "
                   f"change the lengths (full turn needs l1 + l2 < l3 + l4 and |l1 − l2| > |l3 − l4|)")

    def _check_positions(self, phi, labels) -> None:
        d, *_ = self._ad(phi)
        l3, l4 = self.l3, self.l4
        tol = 4e-15 * (self.l1 + self.l2 + l3 + l4)
        far = d > l3 + l4 + tol
        near = d < abs(l3 - l4) - tol
        zero = d <= tol
        bad = far | near | zero
        if bad.any():
            i = int(np.argmax(bad))
            where = self._where(phi, labels, i)
            if far[i]:
                why = (f"|O2A| = {_fmt(d[i])} m exceeds l3 + l4 = {_fmt(l3 + l4)} m: the coupler AB and the rocker "
                       f"O2B cannot reach each other")
            elif zero[i]:
                why = "A coincides with O2: the position of B is undefined"
            else:
                why = f"|O2A| = {_fmt(d[i])} m is less than |l3 − l4| = {_fmt(abs(l3 - l4))} m: the coupler AB and the rocker O2B cannot meet"
            fail(f"four-bar: cannot be assembled at {where}: {why}. {self._grashof_text()}")

    # ------------------------------------------------------------------ geometry
    @property
    def O2(self) -> tuple[float, float]:
        """Coordinates of O2, m."""
        return self.l1 * math.cos(self.ground_angle), self.l1 * math.sin(self.ground_angle)

    def _link_length(self, canon: str) -> float:
        return {"O1A": self.l2, "AB": self.l3, "O2B": self.l4}[canon]

    def _ad(self, phi):
        ox, oy = self.O2
        Ax, Ay = self.l2 * np.cos(phi), self.l2 * np.sin(phi)
        Dx, Dy = ox - Ax, oy - Ay
        d = np.hypot(Dx, Dy)
        return d, Ax, Ay, Dx, Dy

    def _hd(self, phi):
        d, Ax, Ay, Dx, Dy = self._ad(phi)
        l3, l4 = self.l3, self.l4
        P = (l3 + l4 - d) * (d + l4 - l3) * (d + l3 - l4) * (d + l3 + l4)
        h = np.sqrt(np.maximum(P, 0.0)) / (2.0 * d)
        a = (l3 * l3 - l4 * l4 + d * d) / (2.0 * d)
        return d, h, a, Ax, Ay, Dx / d, Dy / d

    def _geometry(self, phi):
        n = phi.shape[0]
        d, h, a, Ax, Ay, ex, ey = self._hd(phi)
        sh = self.assembly * h
        Bx = Ax + a * ex - sh * ey
        By = Ay + a * ey + sh * ex
        ox, oy = self.O2
        geom = {"O1": (np.zeros(n), np.zeros(n)), "A": (Ax, Ay), "B": (Bx, By), "O2": (np.full(n, ox), np.full(n, oy))}
        theta = {"O1A": np.array(phi, dtype=float), "AB": np.arctan2(By - Ay, Bx - Ax), "O2B": np.arctan2(By - oy, Bx - ox)}
        return geom, theta

    def _extremes(self):
        if not self.turns_fully:
            return None
        l1, l2, l3, l4, g = self.l1, self.l2, self.l3, self.l4, self.ground_angle
        angles = []
        for L in (l3 + l2, l3 - l2):
            if L <= 0:
                return None
            xg = (L * L - l4 * l4 + l1 * l1) / (2.0 * l1)
            y2 = L * L - xg * xg
            if y2 <= 0:
                return None  # the rocker turns fully (double crank): no extreme positions
            angles.append(g + math.atan2(self.assembly * math.sqrt(y2), xg))
        return ((angles[0], "crank and coupler extended"), (angles[1] + math.pi, "crank and coupler folded"))

    def _default_start(self) -> float:
        return float(V.norm_angle(self.ground_angle))

    def _output(self, geom, theta, strokes):
        return self._rocker_output(theta, strokes, "O2B")

    # ------------------------------------------------------------------ velocity plan
    def _construct(self, pos: Positions, Om: float):
        n = pos.n
        g = pos._geom
        Ax, Ay = g["A"]
        Bx, By = g["B"]
        ox, oy = self.O2
        ax, ay = -Om * Ay, Om * Ax                                 # pa ⟂ O1A
        ux, uy = (Bx - Ax) / self.l3, (By - Ay) / self.l3          # unit A→B
        wx, wy = (Bx - ox) / self.l4, (By - oy) / self.l4          # unit O2→B
        # b: on the line through p ⟂ O2B and on the line through a ⟂ AB
        bx, by, s = V.intersect(0.0, 0.0, -wy, wx, ax, ay, -uy, ux)
        bx, by = np.array(bx, dtype=float), np.array(by, dtype=float)
        vel = {"O1": (np.zeros(n), np.zeros(n)), "A": (ax, ay), "B": (bx, by), "O2": (np.zeros(n), np.zeros(n))}
        self._snap_extremes(vel, {}, pos.extreme)
        bad = s == 0.0
        if bad.any():  # exactly parallel: leave finite placeholders; velocity_plans raises or uses the analytic values
            bx[bad] = 0.0
            by[bad] = 0.0
        w2 = (ux * (by - ay) - uy * (bx - ax)) / self.l3
        w3 = (wx * by - wy * bx) / self.l4
        omegas = {"O1A": np.full(n, Om), "AB": w2, "O2B": w3}
        self._snap_extremes(vel, omegas, pos.extreme)
        cons = [pole("O1"), pole("O2"), known("A", "O1", "O1A"), PointConstruction(
            name="B", method="intersection", equation="v_B = v_A + v_BA;  v_B ⟂ O2B, v_BA ⟂ AB",
            lines=(line("a", "perpendicular", "AB", ax, ay, -uy, ux, n),
                   line("p", "perpendicular", "O2B", 0.0, 0.0, -wy, wx, n)),
            sin_between=V.frozen(np.asarray(s, dtype=float)))]
        return vel, omegas, cons

    def _snap_extremes(self, vel, omegas, mask):
        if mask.any():
            vel["B"][0][mask] = 0.0
            vel["B"][1][mask] = 0.0
            if "O2B" in omegas:
                omegas["O2B"][mask] = 0.0

    def _toggle_text(self):
        return "the coupler AB and the rocker O2B are in line (toggle)"

    # ------------------------------------------------------------------ analytic derivative
    def _derivatives(self, phi):
        l2, l3, l4 = self.l2, self.l3, self.l4
        geom, theta = self._geometry(phi)
        d, h, *_ = self._hd(phi)
        th3, th4 = theta["AB"], theta["O2B"]
        sin_mu = self.assembly * h * d / (l3 * l4)        # sin(θ4 − θ3), from h: exact near the toggle
        with np.errstate(divide="ignore", invalid="ignore"):
            dth3 = l2 * np.sin(phi - th4) / (l3 * sin_mu)
            dth4 = l2 * np.sin(phi - th3) / (l4 * sin_mu)
        n = phi.shape[0]
        dxy = {"O1": (np.zeros(n), np.zeros(n)), "A": (-l2 * np.sin(phi), l2 * np.cos(phi)),
               "B": (-l4 * dth4 * np.sin(th4), l4 * dth4 * np.cos(th4)), "O2": (np.zeros(n), np.zeros(n))}
        return dxy, {"O1A": np.ones(n), "AB": dth3, "O2B": dth4}, theta, geom
