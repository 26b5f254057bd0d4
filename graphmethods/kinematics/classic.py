"""The four classic kinds of the problem files as presets on the Assur-group core.

:class:`SliderCrank`, :class:`FourBar`, :class:`SlottedLever` and :class:`Shaper` take the
dimensions of the problem files (m, rad), check them with the messages users know, build the
linkage from :mod:`graphmethods.kinematics.presets` and are a
:class:`~graphmethods.kinematics.linkage_mechanism.LinkageMechanism`: positions, velocity
plans, accelerations and construction records all come from the core's groups; nothing here
computes kinematics. Point names, link names and numbers, the extreme positions' names and the
working strokes are the textbook's (and the former hand-written classes').

Links by joints: slider-crank 1 = ``"OA"``, 2 = ``"AB"`` (3 = the slider B); four-bar
1 = ``"O1A"``, 2 = ``"AB"``, 3 = ``"O2B"``; slotted lever 1 = ``"O1A"``, 2 = ``"block"``,
3 = ``"O3B"``; shaper as the slotted lever and 4 = ``"BC"`` (5 = the ram C).

>>> import math
>>> mech = SliderCrank(r=0.1, l=0.4, e=0.02, points={"S2": ("AB", 0.13)})
>>> st = mech.strokes()
>>> round(math.degrees(st.phi_start), 4), st.start_name
(2.2924, 'far dead centre')
>>> plan = mech.velocity_plans(mech.positions(m=12))
>>> float(plan.v_along_guide("B")[0]), round(float(plan.omega("AB")[0]), 6)
(0.0, -0.25)
>>> plan.constructions["B"].equation
'v_B = v_A + v_BA;  v_B ∥ guide, v_BA ⟂ AB'
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace
from types import MappingProxyType
from typing import Any

import numpy as np

from graphmethods.errors import AssemblyError, InputError
from graphmethods.kinematics import presets, vectors as V
from graphmethods.kinematics.linkage import Linkage
from graphmethods.kinematics.linkage_mechanism import LinkageMechanism
from graphmethods.kinematics.mechanism import _check_length, _deg, _fmt
from graphmethods.kinematics.positions import Positions, Strokes


def _fail(msg: str) -> None:
    raise AssemblyError(msg)


class _Classic(LinkageMechanism):
    """What the four classic kinds share: checked dimensions, the preset linkage, textbook names."""

    _dims: tuple[str, ...] = ()
    _extreme_names: tuple[str, str] = ("", "")
    kind = "linkage"

    def _finish(self, *, sense: int, working_stroke: str, points: Any) -> None:
        """Check the dimensions (set by the kind's ``__init__``) and the common arguments, then build
        the preset linkage and become its :class:`LinkageMechanism`."""
        self.sense = sense
        self.working_stroke = working_stroke
        self.points = points
        self._check()
        self._validate_common()
        pts = {p.name: (p.link, p.distance, p.angle) for p in self.points}
        LinkageMechanism.__init__(self, self._build(pts), kind=self.kind)

    def _check(self) -> None:  # pragma: no cover - each kind checks its dimensions
        raise NotImplementedError

    def _build(self, points: Mapping[str, tuple[str, float, float]]) -> Linkage:  # pragma: no cover
        raise NotImplementedError

    def __repr__(self) -> str:
        dims = ", ".join(f"{k}={getattr(self, k)!r}" for k in self._dims)
        return f"{type(self).__name__}({dims}, sense={self.sense}, working_stroke={self.working_stroke!r})"

    def _is_far(self, phi: float, other: float) -> bool:
        return self.linkage._farther_at(phi, other)

    def strokes(self) -> Strokes | None:
        """The extreme positions (found by the core to machine precision) with their textbook names."""
        st = self.linkage.strokes()
        if st is None:
            return None
        far, near = self._extreme_names
        start_far = self._is_far(st.phi_start, st.phi_end)
        return replace(st, start_name=far if start_far else near, end_name=near if start_far else far)


class SliderCrank(_Classic):
    """Offset slider-crank O–A–B, slider B on the line y = e.

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
        ``"toward_crank"`` (default: position 0 is the far dead centre), ``"away_from_crank"``,
        ``"slow"`` or ``"fast"``.
    points : mapping
        Extra points ``{"S2": ("AB", 0.13, 0.0)}`` (link, distance m from its first joint, angle rad).

    Examples
    --------
    >>> SliderCrank(r=0.1, l=0.4).positions(m=12).xy("B")[0].tolist()
    [0.5, 0.0]
    """

    joints = ("O", "A", "B")
    link_joints = MappingProxyType({"OA": ("O", "A"), "AB": ("A", "B")})
    working_strokes = ("toward_crank", "away_from_crank", "slow", "fast")
    kind = "slider-crank"
    _dims = ("r", "l", "e", "assembly")
    _extreme_names = ("far dead centre", "near dead centre")

    def __init__(self, *, r: float, l: float, e: float = 0.0, assembly: int = 1, sense: int = 1,
                 working_stroke: str = "toward_crank", points: Any = ()) -> None:
        self.r, self.l, self.e, self.assembly = r, l, e, assembly
        self._finish(sense=sense, working_stroke=working_stroke, points=points)

    def _check(self) -> None:
        self.r = _check_length("r", self.r)
        self.l = _check_length("l", self.l)
        self.e = _check_length("e", self.e, positive=False)
        r, l, e = self.r, self.l, self.e
        if l <= r + abs(e):
            worse = "shorter than" if l < (r + abs(e)) * (1 - 1e-12) else "not longer than"
            k = min(1.0, (l - abs(e)) / r) if r > 0 else 1.0
            a = math.asin(max(-1.0, k))
            lo, hi = (math.pi + a, 2 * math.pi - a) if e >= 0 else (a, math.pi - a)
            where = (f"assembly fails for φ in ({math.degrees(lo):.4g}°, {math.degrees(hi):.4g}°)" if hi > lo + 1e-9
                     else f"the rod stands perpendicular to the guide at φ = {math.degrees(lo):.4g}°")
            _fail(f"slider-crank: rod l = {_fmt(l)} m is {worse} crank r + |e| = {_fmt(r + abs(e))} m: the slider "
                  f"cannot follow a full crank turn ({where}); make l > r + |e|")

    def _build(self, points: Mapping[str, tuple[str, float, float]]) -> Linkage:
        return presets.slider_crank(r=self.r, l=self.l, e=self.e, assembly=self.assembly, sense=self.sense,
                                    working_stroke=self.working_stroke, points=points)


class FourBar(_Classic):
    """Four-bar O1–A–B–O2: crank 1 = O1A (l2), coupler 2 = AB (l3), rocker 3 = O2B (l4), ground l1.

    Parameters
    ----------
    l1, l2, l3, l4 : float
        Ground O1O2, crank O1A, coupler AB, rocker O2B, m.
    ground_angle : float
        Direction of O1→O2 from +x, rad.
    assembly : int
        +1: B on the left of A→O2; −1: the other branch.
    sense : int
        +1 crank counterclockwise (default), −1 clockwise.
    working_stroke : str
        ``"slow"`` (default) or ``"fast"``: which swing of the rocker is the working stroke.
    points : mapping
        Extra points ``{"S2": ("AB", 0.125, 0.0)}``.

    Examples
    --------
    >>> fb = FourBar(l1=0.30, l2=0.08, l3=0.25, l4=0.20)
    >>> round(math.degrees(fb.strokes().working_angle), 3), round(fb.strokes().K, 4), fb.grashof
    (182.7, 1.0305, 'crank-rocker')
    """

    joints = ("O1", "A", "B", "O2")
    link_joints = MappingProxyType({"O1A": ("O1", "A"), "AB": ("A", "B"), "O2B": ("O2", "B")})
    working_strokes = ("slow", "fast")
    kind = "four-bar"
    _dims = ("l1", "l2", "l3", "l4", "ground_angle", "assembly")
    _extreme_names = ("crank and coupler extended", "crank and coupler folded")

    def __init__(self, *, l1: float, l2: float, l3: float, l4: float, ground_angle: float = 0.0,
                 assembly: int = 1, sense: int = 1, working_stroke: str = "slow", points: Any = ()) -> None:
        self.l1, self.l2, self.l3, self.l4 = l1, l2, l3, l4
        self.ground_angle, self.assembly = ground_angle, assembly
        self._finish(sense=sense, working_stroke=working_stroke, points=points)

    def _check(self) -> None:
        for name in ("l1", "l2", "l3", "l4"):
            setattr(self, name, _check_length(name, getattr(self, name)))
        self.ground_angle = _check_length("ground_angle", self.ground_angle, positive=False)
        lens = {"l1 (ground O1O2)": self.l1, "l2 (crank O1A)": self.l2, "l3 (coupler AB)": self.l3,
                "l4 (rocker O2B)": self.l4}
        longest = max(lens, key=lambda k: lens[k])
        rest = sum(lens.values()) - lens[longest]
        if lens[longest] >= rest:
            _fail(f"four-bar: the links cannot close a loop: the longest, {longest} = {_fmt(lens[longest])} m, is "
                  f"not shorter than the sum of the other three = {_fmt(rest)} m")

    def _build(self, points: Mapping[str, tuple[str, float, float]]) -> Linkage:
        return presets.four_bar(l1=self.l1, l2=self.l2, l3=self.l3, l4=self.l4, ground_angle=self.ground_angle,
                                assembly=self.assembly, sense=self.sense, working_stroke=self.working_stroke,
                                points=points)

    @property
    def O2(self) -> tuple[float, float]:
        """Coordinates of O2, m."""
        return self.l1 * math.cos(self.ground_angle), self.l1 * math.sin(self.ground_angle)

    @property
    def turns_fully(self) -> bool:
        """True if the crank O1A can make full turns (crank-rocker or double crank)."""
        l1, l2, l3, l4 = self.l1, self.l2, self.l3, self.l4
        return bool(l1 + l2 < l3 + l4 and abs(l1 - l2) > abs(l3 - l4))

    @property
    def grashof(self) -> str:
        """Grashof classification: ``"crank-rocker"``, ``"double-crank"``, ``"double-rocker"``,
        ``"rocker-crank"``, ``"triple-rocker"`` (non-Grashof) or ``"change-point"``."""
        ls = [self.l1, self.l2, self.l3, self.l4]
        s, L = min(ls), max(ls)
        pq = sum(ls) - s - L
        if math.isclose(s + L, pq, rel_tol=1e-12):
            return "change-point"
        if s + L > pq:
            return "triple-rocker"
        return ("double-crank", "crank-rocker", "double-rocker", "rocker-crank")[ls.index(s)]

    def _grashof_text(self) -> str:
        ls = {"ground O1O2": self.l1, "crank O1A": self.l2, "coupler AB": self.l3, "rocker O2B": self.l4}
        s_name = min(ls, key=lambda k: ls[k])
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
        if not out:
            out.append(f"the toggle positions, where coupler and rocker come in line (l1 = {_fmt(l1)}, "
                       f"l2 = {_fmt(l2)}, l3 = {_fmt(l3)}, l4 = {_fmt(l4)} m)")
        return out

    def _check_full_turn(self) -> None:
        if not self.turns_fully:
            _fail(f"four-bar l1 = {_fmt(self.l1)}, l2 = {_fmt(self.l2)}, l3 = {_fmt(self.l3)}, l4 = {_fmt(self.l4)} m: "
                  "the crank O1A cannot make a full turn; assembly fails for "
                  + "; and for ".join(self._failing_ranges())
                  + f". {self._grashof_text()}. Use positions(phi=...) inside the range where it assembles, or "
                    f"change the lengths (full turn needs l1 + l2 < l3 + l4 and |l1 − l2| > |l3 − l4|)")

    def _check_angles(self, phi: np.ndarray, labels: np.ndarray | None) -> None:
        ox, oy = self.O2
        d = np.hypot(ox - self.l2 * np.cos(phi), oy - self.l2 * np.sin(phi))
        l3, l4 = self.l3, self.l4
        tol = 4e-15 * (self.l1 + self.l2 + l3 + l4)
        far, near, zero = d > l3 + l4 + tol, d < abs(l3 - l4) - tol, d <= tol
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
                why = (f"|O2A| = {_fmt(d[i])} m is less than |l3 − l4| = {_fmt(abs(l3 - l4))} m: the coupler AB and "
                       f"the rocker O2B cannot meet")
            _fail(f"four-bar: cannot be assembled at {where}: {why}. {self._grashof_text()}")

    def strokes(self) -> Strokes | None:
        """None when the crank cannot turn fully (no extreme positions to number from)."""
        return super().strokes() if self.turns_fully else None

    def positions(self, m: int | None = None, *, phi: Any = None, phi_from_start: Any = None) -> Positions:
        """As :meth:`LinkageMechanism.positions`, with the four-bar's own messages when it cannot turn or
        cannot be assembled at a given angle."""
        if phi is None and phi_from_start is None:
            self._check_full_turn()
        elif phi is not None:
            self._check_angles(self._angles(phi, "phi"), None)
        return super().positions(m, phi=phi, phi_from_start=phi_from_start)


class SlottedLever(_Classic):
    """Crank and slotted lever: crank O1A, block 2 at A sliding on the lever 3 = O3B.

    Parameters
    ----------
    r : float
        Crank O1A, m (shorter than O1O3: an oscillating lever).
    l_O1O3 : float
        Centre distance O1O3, m.
    l_O3B : float
        Lever O3B, m (≥ l_O1O3 + r: the pin stays in the slot).
    theta_O3 : float
        Direction of O1→O3 from +x, rad (default −π/2: O3 below O1).
    sense : int
        +1 crank counterclockwise (default), −1 clockwise.
    working_stroke : str
        ``"slow"`` (default) or ``"fast"``.
    points : mapping
        Extra points, e.g. ``{"S3": ("O3B", 0.25, 0.0)}``.

    Examples
    --------
    >>> sl = SlottedLever(r=0.1, l_O1O3=0.3, l_O3B=0.5)
    >>> round(math.degrees(sl.strokes().working_angle), 4), round(sl.strokes().K, 4)
    (218.9424, 1.5521)
    >>> sl.velocity_plans(12).constructions["A3"].equation
    'v_A3 = v_A2 + v_A3A2;  v_A3 ⟂ O3A, v_A3A2 ∥ O3A'
    """

    joints: tuple[str, ...] = ("O1", "A", "A3", "O3", "B")
    link_joints = MappingProxyType({"O1A": ("O1", "A"), "O3B": ("O3", "B")})
    working_strokes = ("slow", "fast")
    kind = "slotted lever"
    _dims: tuple[str, ...] = ("r", "l_O1O3", "l_O3B", "theta_O3")
    _extreme_names = ("rocker extreme (crank ⟂ rocker)", "rocker extreme (crank ⟂ rocker)")

    def __init__(self, *, r: float, l_O1O3: float, l_O3B: float, theta_O3: float = -math.pi / 2, sense: int = 1,
                 working_stroke: str = "slow", points: Any = ()) -> None:
        self.r, self.l_O1O3, self.l_O3B, self.theta_O3 = r, l_O1O3, l_O3B, theta_O3
        self._finish(sense=sense, working_stroke=working_stroke, points=points)

    def _check(self) -> None:
        for name in ("r", "l_O1O3", "l_O3B"):
            setattr(self, name, _check_length(name, getattr(self, name)))
        self.theta_O3 = _check_length("theta_O3", self.theta_O3, positive=False)
        r, d, L = self.r, self.l_O1O3, self.l_O3B
        if r >= d:
            _fail(f"{self.kind}: crank r = {_fmt(r)} m is not shorter than the centre distance O1O3 = {_fmt(d)} m: the "
                  f"crank pin would pass {'through' if r == d else 'round'} the rocker's pivot O3 (a rotating "
                  f"guide-bar, not an oscillating slotted lever); make r < l_O1O3")
        if L < d + r:
            _fail(f"{self.kind}: rocker O3B = {_fmt(L)} m is shorter than the farthest distance of the crank pin from "
                  f"O3, l_O1O3 + r = {_fmt(d + r)} m (at φ = {_deg(self.theta_O3 + math.pi)}): the pin would leave "
                  f"the slot; make l_O3B ≥ l_O1O3 + r")

    def _build(self, points: Mapping[str, tuple[str, float, float]]) -> Linkage:
        return presets.slotted_lever(r=self.r, l_O1O3=self.l_O1O3, l_O3B=self.l_O3B, theta_O3=self.theta_O3,
                                     sense=self.sense, working_stroke=self.working_stroke, points=points)

    @property
    def O3(self) -> tuple[float, float]:
        """Coordinates of the rocker pivot O3, m."""
        return self.l_O1O3 * math.cos(self.theta_O3), self.l_O1O3 * math.sin(self.theta_O3)

    def _is_far(self, phi: float, other: float) -> bool:
        return True


class Shaper(SlottedLever):
    """Shaper: slotted lever, connecting link 4 = BC and ram 5 = C on the line y = y_guide.

    Parameters
    ----------
    r, l_O1O3, l_O3B, theta_O3, sense, working_stroke
        As :class:`SlottedLever`.
    l_BC : float
        Connecting link BC, m.
    y_guide : float
        Height of the ram's guide line above O1, m.
    assembly : int
        +1: ram C on the +x side of B; −1: on the −x side.
    points : mapping
        Extra points, e.g. ``{"S3": ("O3B", 0.27), "S4": ("BC", 0.0675)}``.

    Examples
    --------
    >>> sh = Shaper(r=0.1, l_O1O3=0.3, l_O3B=0.55, l_BC=0.15, y_guide=0.24)
    >>> pos = sh.positions(m=12)
    >>> round(pos.H, 4), round(math.degrees(pos.psi_max), 4)
    (0.3667, 38.9424)
    """

    joints = ("O1", "A", "A3", "O3", "B", "C")
    link_joints = MappingProxyType({"O1A": ("O1", "A"), "O3B": ("O3", "B"), "BC": ("B", "C")})
    kind = "shaper"
    _dims = ("r", "l_O1O3", "l_O3B", "l_BC", "y_guide", "theta_O3", "assembly")

    def __init__(self, *, r: float, l_O1O3: float, l_O3B: float, l_BC: float, y_guide: float,
                 theta_O3: float = -math.pi / 2, assembly: int = 1, sense: int = 1, working_stroke: str = "slow",
                 points: Any = ()) -> None:
        self.r, self.l_O1O3, self.l_O3B, self.theta_O3 = r, l_O1O3, l_O3B, theta_O3
        self.l_BC, self.y_guide, self.assembly = l_BC, y_guide, assembly
        self._finish(sense=sense, working_stroke=working_stroke, points=points)

    def _check(self) -> None:
        super()._check()
        self.l_BC = _check_length("l_BC", self.l_BC)
        self.y_guide = _check_length("y_guide", self.y_guide, positive=False)
        if self.assembly not in (1, -1) or isinstance(self.assembly, bool):
            raise InputError(f"{self.kind}: assembly must be +1 or -1, got {self.assembly!r}")
        _, oy = self.O3
        beta = math.asin(self.r / self.l_O1O3)
        centre = self.theta_O3 + math.pi               # rocker direction O3 -> O1
        cands = [centre - beta, centre + beta]
        for t in (math.pi / 2, -math.pi / 2):
            if abs(float(V.wrap(t - centre))) <= beta:
                cands.append(t)
        q = [self.y_guide - (oy + self.l_O3B * math.sin(t)) for t in cands]
        i = max(range(len(q)), key=lambda j: abs(q[j]))
        if abs(q[i]) >= self.l_BC:
            _fail(f"shaper: the link BC = {_fmt(self.l_BC)} m cannot reach the ram's guide y = {_fmt(self.y_guide)} m "
                  f"when the rocker is at {math.degrees(cands[i]) % 360:.4g}° (B is {_fmt(abs(q[i]))} m from the "
                  f"guide); make l_BC > {_fmt(abs(q[i]))} m or move the guide")
        ts = np.linspace(centre - beta, centre + beta, 4097)
        qq = self.y_guide - (oy + self.l_O3B * np.sin(ts))
        w = self.assembly * np.sqrt(self.l_BC ** 2 - qq * qq)
        f = (qq * np.cos(ts) - w * np.sin(ts)) / self.l_BC    # sin(angle BC − angle O3B)
        if not (np.all(f > 1e-9) or np.all(f < -1e-9)):
            j = int(np.argmin(np.abs(f)))
            _fail(f"shaper: the link BC comes in line with the rocker O3B when the rocker is at "
                  f"{math.degrees(ts[j]) % 360:.4g}°: the ram would stop and reverse before the rocker's extreme "
                  f"position; change l_BC, y_guide or assembly")

    def _build(self, points: Mapping[str, tuple[str, float, float]]) -> Linkage:
        return presets.shaper(r=self.r, l_O1O3=self.l_O1O3, l_O3B=self.l_O3B, l_BC=self.l_BC, y_guide=self.y_guide,
                              theta_O3=self.theta_O3, assembly=self.assembly, sense=self.sense,
                              working_stroke=self.working_stroke, points=points)

    def positions(self, m: int | None = None, *, phi: Any = None, phi_from_start: Any = None) -> Positions:
        """As :meth:`LinkageMechanism.positions`, with the lever's swing ψ (rad) beside the ram's s."""
        pos = super().positions(m, phi=phi, phi_from_start=phi_from_start)
        st = pos.strokes
        if st is None:
            return pos
        th_s, th_e = self.linkage.solve(np.array([st.phi_start, st.phi_end]), level=0).theta["3"]
        swing = float(V.wrap(th_e - th_s))
        sign = 1.0 if swing >= 0 else -1.0
        psi = sign * V.wrap(pos.theta["O3B"] - th_s)
        psi = np.where(np.abs(psi) < 1e-15, 0.0, psi)
        psi.flags.writeable = False
        object.__setattr__(pos, "psi", psi)
        object.__setattr__(pos, "psi_max", abs(swing))
        return pos


__all__ = ["FourBar", "Shaper", "SliderCrank", "SlottedLever"]
