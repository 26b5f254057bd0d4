"""The cam problem: a follower, a cam's rotation and a table of phases (``"kind": "cam"`` files).

The file format is the contract of ``shared/cases/README.md``, "Cam mechanisms"; :data:`EXAMPLE` is its
example (a translating roller follower, rise–dwell–return–dwell).

An oscillating follower gives ``arm`` (m, pivot to roller centre), ``pivot`` (m, the pivot's
distance from the cam centre) and each rise's or return's swing ``lift_deg`` (degrees) instead
of ``lift``. The base radius is ``base_radius`` (m, of the profile) when given; otherwise it is
designed (:mod:`graphmethods.kinematics.cam.design`). A file may carry ``name`` (a title, text or
``{"en": ..., "ru": ..., "zh": ...}``).

>>> p = cam_from_dict({"kind": "cam", "follower": {"type": "translating", "contact": "knife"},
...     "cam": {"n_rpm": 60}, "base_radius": 0.04,
...     "motion": [{"phase": "rise", "angle_deg": 180, "lift": 0.01, "law": "harmonic"},
...                {"phase": "return", "angle_deg": 180, "lift": 0.01, "law": "harmonic"}]})
>>> [ph.kind for ph in p.phases], round(p.omega, 6)
(['rise', 'return'], 6.283185)
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from graphmethods.errors import InputError
from graphmethods.kinematics.cam.laws import BREAKS, LAWS, unit_law
from graphmethods.titles import Title
from graphmethods.units import json_value, omega_from_n, read_text, real

Array = NDArray[np.float64]
PHASES = ("rise", "dwell", "return")
CONTACTS = ("knife", "roller", "flat")
TYPES = ("translating", "oscillating")


@dataclass(frozen=True)
class Phase:
    """One phase of the follower's motion.

    Attributes
    ----------
    kind : str
        ``rise``, ``dwell`` or ``return``.
    start_deg, angle_deg : float
        Where it starts (cam angle φ from the start of the first phase) and how long it lasts, degrees.
    lift : float
        The rise or fall: m (translating) or rad (oscillating); 0 for a dwell.
    law : str
        One of :data:`~graphmethods.kinematics.cam.laws.LAWS`; ``""`` for a dwell.
    level : float
        The displacement at the phase's start (m or rad, from the lowest position).
    """

    kind: str
    start_deg: float
    angle_deg: float
    lift: float = 0.0
    law: str = ""
    level: float = 0.0

    @property
    def end_deg(self) -> float:
        return self.start_deg + self.angle_deg

    @property
    def Phi(self) -> float:
        """The phase angle Φ, rad."""
        return math.radians(self.angle_deg)

    def pieces(self) -> list[tuple[float, float]]:
        """The x-intervals on which the phase's law is smooth (the parabolic law splits at ½)."""
        cuts = [0.0, *BREAKS.get(self.law, ()), 1.0]
        return list(zip(cuts[:-1], cuts[1:]))

    def values(self, x: Array, *, left: bool = False) -> tuple[Array, Array, Array, Array]:
        """s, ds/dφ, d²s/dφ², d³s/dφ³ at phase fractions x (m or rad, per rad of cam turn)."""
        x = np.asarray(x, dtype=float)
        if self.kind == "dwell":
            z = np.zeros_like(x)
            return z + self.level, z, z.copy(), z.copy()
        f, d1, d2, d3 = unit_law(self.law, x, left=left)
        h, Phi = self.lift, self.Phi
        sign = 1.0 if self.kind == "rise" else -1.0
        base = self.level if self.kind == "rise" else self.level - h
        s = base + h * f if self.kind == "rise" else base + h * (1.0 - f)
        return s, sign * h * d1 / Phi, sign * h * d2 / Phi ** 2, sign * h * d3 / Phi ** 3


@dataclass(frozen=True)
class CamProblem:
    """A cam mechanism to analyse or design (SI; angles of the file in degrees).

    Attributes
    ----------
    follower_type : str
        ``translating`` or ``oscillating``.
    contact : str
        ``knife``, ``roller`` or ``flat``.
    roller_radius : float
        r_r, m (0 unless a roller).
    offset : float
        e, m (translating): e ≥ 0 on the side that lowers the rise's pressure angle.
    arm, pivot : float
        Oscillating follower: arm length l (pivot to roller centre) and the pivot's distance a from
        the cam centre, m (0 for a translating follower).
    sense : str
        The cam's rotation, ``ccw`` or ``cw``.
    omega : float
        The cam's angular speed, rad/s (> 0).
    phases : tuple of Phase
        In order, their angles summing to 360°.
    base_radius : float or None
        The profile's base radius r_b, m, or None to design it.
    alpha_max_deg, alpha_return_max_deg : float or None
        Permissible pressure angles [α] of the rise and of the return, degrees.
    rho_min_allowed : float
        Flat face: the least radius of curvature of the profile, m.
    title : Title
        The problem's name.
    """

    follower_type: str
    contact: str
    roller_radius: float
    offset: float
    arm: float
    pivot: float
    sense: str
    omega: float
    phases: tuple[Phase, ...]
    base_radius: float | None
    alpha_max_deg: float | None
    alpha_return_max_deg: float
    rho_min_allowed: float = 0.0
    title: Title = field(default_factory=Title)
    kind: str = "cam"

    @property
    def oscillating(self) -> bool:
        return self.follower_type == "oscillating"

    @property
    def stroke(self) -> float:
        """The largest displacement h (m, or rad for an oscillating follower)."""
        return max(max(p.level for p in self.phases), max(p.level + (p.lift if p.kind == "rise" else 0.0)
                                                          for p in self.phases))

    def motion(self, phi_deg: Array | list[float]) -> tuple[Array, Array, Array, Array]:
        """s, ds/dφ, d²s/dφ², d³s/dφ³ at cam angles φ (degrees, any; reduced mod 360).

        At a phase boundary the phase that starts there is used (right-continuous).

        >>> p = cam_from_dict(EXAMPLE)
        >>> [round(float(v[0]), 12) for v in p.motion([60.0])]
        [0.01, 0.019098593171, 0.0, -0.08594366927]
        """
        phi = np.mod(np.asarray(phi_deg, dtype=float), 360.0)
        starts = np.array([p.start_deg for p in self.phases])
        idx = np.clip(np.searchsorted(starts, phi, side="right") - 1, 0, len(self.phases) - 1)
        out = [np.zeros_like(phi) for _ in range(4)]
        for k, p in enumerate(self.phases):
            m = idx == k
            if m.any():
                vals = p.values(np.clip((phi[m] - p.start_deg) / p.angle_deg, 0.0, 1.0))
                for o, v in zip(out, vals):
                    o[m] = v
        return out[0], out[1], out[2], out[3]


EXAMPLE = {"kind": "cam", "follower": {"type": "translating", "contact": "roller", "roller_radius": 0.01,
                                       "offset": 0.005},
           "cam": {"sense": "ccw", "n_rpm": 120},
           "motion": [{"phase": "rise", "angle_deg": 120, "lift": 0.02, "law": "cycloidal"},
                      {"phase": "dwell", "angle_deg": 60},
                      {"phase": "return", "angle_deg": 120, "lift": 0.02, "law": "harmonic"},
                      {"phase": "dwell", "angle_deg": 60}],
           "pressure_angle_max_deg": 30, "pressure_angle_return_max_deg": 70}


def _choice(d: Mapping[str, Any], key: str, options: tuple[str, ...], where: str, default: str | None = None) -> str:
    value = d.get(key, default)
    if value is None:
        raise InputError(f"{where}: missing key {key!r}; give one of {', '.join(options)}")
    if not isinstance(value, str) or value.strip().lower() not in options:
        raise InputError(f"{where}: {key} = {value!r}; give one of {', '.join(options)}")
    return value.strip().lower()


def _mapping(d: Mapping[str, Any], key: str, where: str) -> Mapping[str, Any]:
    value = d.get(key)
    if not isinstance(value, Mapping):
        raise InputError(f"{where}: key {key!r} must be an object, e.g. "
                         + ('{"type": "translating", "contact": "roller", "roller_radius": 0.01}' if key == "follower"
                            else '{"sense": "ccw", "n_rpm": 120}'))
    return value


def _phases(motion: object, oscillating: bool, where: str) -> tuple[Phase, ...]:
    """The phase table, checked: angles sum to 360°, rises and returns balance, laws known."""
    if not isinstance(motion, list) or not motion:
        raise InputError(f"{where}: key 'motion' must be a list of phases, e.g. "
                         '[{"phase": "rise", "angle_deg": 120, "lift": 0.02, "law": "cycloidal"}, ...]')
    lift_key, unit = ("lift_deg", "°") if oscillating else ("lift", "m")
    raw, start, level = [], 0.0, 0.0
    for i, ph in enumerate(motion):
        w = f"{where}: motion[{i}]"
        if not isinstance(ph, Mapping):
            raise InputError(f"{w} must be an object with phase, angle_deg, {lift_key} and law")
        kind = _choice(ph, "phase", PHASES, w)
        angle = real(ph.get("angle_deg"), f"{w}.angle_deg", unit="°", lo=0.0, lo_open=True, hi=360.0)
        lift, law = 0.0, ""
        if kind != "dwell":
            lift = real(ph.get(lift_key), f"{w}.{lift_key}", unit=unit, lo=0.0, lo_open=True,
                        hint=f"give the {kind}'s {'swing in degrees' if oscillating else 'lift in m'}")
            lift = math.radians(lift) if oscillating else lift
            law = _choice(ph, "law", LAWS, w)
        raw.append((kind, start, angle, lift, law, level))
        start += angle
        level += lift if kind == "rise" else -lift if kind == "return" else 0.0
    if abs(start - 360.0) > 1e-9:
        raise InputError(f"{where}: the phases' angles sum to {start:g}°; they must sum to 360°")
    total = sum(r[3] for r in raw if r[0] == "rise")
    if abs(level) > 1e-9 * max(total, 1e-300):
        raise InputError(f"{where}: the rises lift {total:g} and the returns lower "
                         f"{total - level:g}; they must balance over one turn")
    low = min(r[5] for r in raw)              # the lowest position: s is measured from it
    return tuple(Phase(k, s, a, h, law, lv - low) for k, s, a, h, law, lv in raw)


def cam_from_dict(data: Mapping[str, Any], *, source: str = "cam problem") -> CamProblem:
    """A :class:`CamProblem` from the decoded JSON of a ``"kind": "cam"`` file, every key checked.

    Raises
    ------
    InputError
        A missing or unusable key (the message names it, the file and what to give).
    """
    if not isinstance(data, Mapping) or data.get("kind") != "cam":
        raise InputError(f'{source}: not a cam problem (give "kind": "cam")')
    fol, cam = _mapping(data, "follower", source), _mapping(data, "cam", source)
    ftype = _choice(fol, "type", TYPES, f"{source}: follower")
    contact = _choice(fol, "contact", CONTACTS, f"{source}: follower")
    osc = ftype == "oscillating"
    rr = (real(fol.get("roller_radius"), f"{source}: follower.roller_radius", unit="m", lo=0.0, lo_open=True)
          if contact == "roller" else 0.0)
    e = real(fol.get("offset", 0.0), f"{source}: follower.offset", unit="m") if not osc else 0.0
    arm = pivot = 0.0
    if osc:
        if contact == "flat":
            raise InputError(f"{source}: an oscillating flat-faced follower is not supported; use a knife or a roller")
        arm = real(fol.get("arm"), f"{source}: follower.arm", unit="m", lo=0.0, lo_open=True)
        pivot = real(fol.get("pivot"), f"{source}: follower.pivot", unit="m", lo=0.0, lo_open=True)
    sense = _choice(cam, "sense", ("ccw", "cw"), f"{source}: cam", default="ccw")
    if ("omega" in cam) == ("n_rpm" in cam):
        raise InputError(f"{source}: cam: give the speed as n_rpm (rev/min) or omega (rad/s), one of them")
    omega = (real(cam["omega"], f"{source}: cam.omega", unit="rad/s", lo=0.0, lo_open=True) if "omega" in cam
             else omega_from_n(real(cam["n_rpm"], f"{source}: cam.n_rpm", unit="rev/min", lo=0.0, lo_open=True)))
    phases = _phases(data.get("motion"), osc, source)
    rb = data.get("base_radius")
    base = None if rb is None else real(rb, f"{source}: base_radius", unit="m", lo=0.0, lo_open=True)
    a_max = data.get("pressure_angle_max_deg")
    alpha = None if a_max is None else real(a_max, f"{source}: pressure_angle_max_deg", unit="°", lo=0.0,
                                            lo_open=True, hi=90.0, hi_open=True)
    alpha_ret = real(data.get("pressure_angle_return_max_deg", 70.0), f"{source}: pressure_angle_return_max_deg",
                     unit="°", lo=0.0, lo_open=True, hi=90.0, hi_open=True)
    if base is None and contact != "flat" and alpha is None:
        raise InputError(f"{source}: no base_radius and no pressure_angle_max_deg; give the base radius (m) or the "
                         "permissible pressure angle of the rise to design it")
    rho_min = real(data.get("rho_min_allowed", 0.0), f"{source}: rho_min_allowed", unit="m", lo=0.0)
    title = Title.of(data.get("name"), where=f"{source}: key 'name'")
    return CamProblem(ftype, contact, rr, e, arm, pivot, sense, omega, phases, base, alpha, alpha_ret, rho_min, title)


def read_cam(path: str | os.PathLike[str]) -> CamProblem:
    """Read and check a ``"kind": "cam"`` problem file (:func:`cam_from_dict`)."""
    text = read_text(path, missing="no such problem file")
    return cam_from_dict(json_value(text, str(path)), source=str(path))
