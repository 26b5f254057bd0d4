"""Worksheet variants and their random generators: each variant's data, its expected answers, and the
"nice" numbers drawn from a seed (areas that close exactly, scales from the convenient series).
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Callable
from dataclasses import dataclass, fields
from fractions import Fraction
from functools import cached_property
from typing import Any, ClassVar

import numpy as np

from graphmethods.dynamics import excess_work as ew
from graphmethods.dynamics.flywheel import flywheel
from graphmethods.dynamics.moments import MomentCurve
from graphmethods.errors import InputError
from graphmethods.sheets.worksheets.texts import TITLES
from graphmethods.titles import Title
from graphmethods.units import MAX_VARIANTS, json_text, omega_from_n

KINDS = ("indicator", "step-moment", "velocity-plan", "wittenbauer", "acceleration-plan", "cam")
_KIND_CODE = {"indicator": 1, "step-moment": 2, "velocity-plan": 3, "wittenbauer": 4, "acceleration-plan": 5,
              "cam": 6}
PROBLEM_FORMAT = "graphmethods-worksheet-problem"

# ----------------------------------------------------------------------------- variants

def _fraction(text) -> Fraction:
    try:
        f = Fraction(str(text))
    except (ValueError, ZeroDivisionError):
        raise InputError(f"delta = {text!r}: give the coefficient of fluctuation as a fraction like 1/30") from None
    if not 0 < f < 1:
        raise InputError(f"delta = {text!r} must lie between 0 and 1")
    return f


class Variant:
    """Base of the worksheet variants: an id, its data as a dict, its expected answers."""

    kind: ClassVar[str] = ""
    __dataclass_fields__: ClassVar[dict[str, Any]]     # every variant is a dataclass (fields() reads them)
    seed: int
    number: int

    @property
    def id(self) -> str:
        """``"KIND:SEED:NUMBER"``; ``graphmethods check`` accepts it in place of a problem file."""
        return f"{self.kind}:{self.seed}:{self.number}"

    @property
    def title(self) -> Title:
        """The worksheet's title in en, ru and zh (``title.title_in(lang)``), the same for every variant of a kind."""
        return TITLES[self.kind]

    def data(self) -> dict:
        """The variant's inputs, JSON-ready (what a problem file holds)."""
        out = {}
        for f in fields(self):
            v = getattr(self, f.name)
            out[f.name] = list(v) if isinstance(v, tuple) else v
        return out

    def answers(self) -> dict:  # pragma: no cover - every kind overrides it
        raise NotImplementedError

    def to_dict(self) -> dict:
        """The problem file: format, kind, id, data and (for reading only) the expected answers."""
        return {"format": PROBLEM_FORMAT, "kind": self.kind, "id": self.id, "data": self.data(),
                "answers": self.answers()}

    def to_json(self) -> str:
        """:meth:`to_dict` as indented JSON text (deterministic)."""
        return json_text(self.to_dict(), indent=1, ensure_ascii=False) + "\n"


class _FlywheelVariant(Variant):
    """A variant that asks for a flywheel: the machine runs at ``n_rpm`` (rev/min) with [δ] given as text."""

    n_rpm: float
    delta: str

    @property
    def delta_value(self) -> float:
        """[δ] as a number."""
        return float(_fraction(self.delta))

    @property
    def omega_m(self) -> float:
        """Mean angular velocity, rad/s."""
        return omega_from_n(self.n_rpm)


@dataclass(frozen=True)
class IndicatorVariant(_FlywheelVariant):
    """W1 style: areas f_i (mm²) measured at μ_M (N·m/mm), μ_φ (rad/mm); n (rev/min), [δ], J_e (kg·m²).

    ``mu_E`` (J/mm) and ``step_mm`` are the stated scale and spacing of the student's energy indicator.

    >>> v = IndicatorVariant(seed=0, number=1, areas_mm2=(500, -5500, 1000, -1250, 5000, -250, 500),
    ...                      mu_M=4.0, mu_phi=0.025, n_rpm=600.0, delta="1/300", J_e=0.0, mu_E=5.0)
    >>> v.excess_work.delta_W_max, round(v.answers()["J_F"], 2)        # W1 at a drawing's scales
    (575.0, 43.69)
    """

    kind: ClassVar[str] = "indicator"
    seed: int
    number: int
    areas_mm2: tuple
    mu_M: float
    mu_phi: float
    n_rpm: float
    delta: str
    J_e: float
    mu_E: float
    step_mm: float = 16.0

    @cached_property
    def excess_work(self):
        return ew.from_areas(self.areas_mm2, mu_M=self.mu_M, mu_phi=self.mu_phi, closure_tol=1e-9)

    @cached_property
    def flywheel(self):
        return flywheel(self.excess_work.delta_W_max, delta=self.delta_value, n_rpm=self.n_rpm, J_e=self.J_e)

    def answers(self) -> dict:
        c, f = self.excess_work, self.flywheel
        return {"works_J": c.work.tolist(), "E_J": c.E.tolist(), "labels": list(c.labels),
                "arrows_mm": (c.work / self.mu_E).tolist(), "delta_W_max": c.delta_W_max,
                "omega_max_at": c.labels[c.index_E_max], "omega_min_at": c.labels[c.index_E_min],
                "omega_m": f.omega_m, "omega_max": f.omega_max, "omega_min": f.omega_min, "J_F": f.J_F}


@dataclass(frozen=True)
class StepMomentVariant(_FlywheelVariant):
    """W3 style: M_r through knots (φ in degrees, a repeated angle is a jump), M_d by work balance.

    ``mu_M`` (N·m/mm) and ``mu_phi_deg`` (°/mm) are the stated scales of the moment diagram.

    >>> v = StepMomentVariant(seed=0, number=1, shape="steps", phi_deg=(0, 45, 45, 360), M_r=(60, 60, 10, 10),
    ...                       n_rpm=100.0, delta="1/20", J_e=0.0, mu_M=0.5, mu_phi_deg=2.5)
    >>> a = v.answers()
    >>> a["M_d"], round(a["delta_W_max"], 2), round(a["J_F"], 3)                      # W3
    (16.25, 34.36, 6.267)
    """

    kind: ClassVar[str] = "step-moment"
    seed: int
    number: int
    shape: str
    phi_deg: tuple
    M_r: tuple
    n_rpm: float
    delta: str
    J_e: float
    mu_M: float
    mu_phi_deg: float

    @property
    def mu_phi(self) -> float:
        """The angle scale in rad/mm."""
        return math.radians(self.mu_phi_deg)

    @cached_property
    def M_r_curve(self) -> MomentCurve:
        return MomentCurve(np.radians(np.asarray(self.phi_deg, dtype=float)), np.asarray(self.M_r, dtype=float))

    @cached_property
    def excess_work(self):
        return ew.from_moments(M_r=self.M_r_curve)

    @property
    def M_d(self) -> float:
        return self.M_r_curve.mean()

    @cached_property
    def flywheel(self):
        return flywheel(self.excess_work.delta_W_max, delta=self.delta_value, n_rpm=self.n_rpm, J_e=self.J_e)

    def steps(self) -> list[tuple[float, float, float]]:
        """(φ from, φ to, M_r) in degrees and N·m for a step curve."""
        p, M = self.phi_deg, self.M_r
        return [(p[i], p[i + 1], M[i]) for i in range(len(p) - 1) if p[i + 1] > p[i]]

    def answers(self) -> dict:
        c, f = self.excess_work, self.flywheel
        area = 1.0 / (self.mu_M * self.mu_phi)
        return {"M_d": self.M_d, "phi_deg": np.degrees(c.phi).tolist(), "labels": list(c.labels),
                "works_J": c.work.tolist(), "E_J": c.E.tolist(), "areas_mm2": (c.work * area).tolist(),
                "delta_W_max": c.delta_W_max, "omega_max_at": c.labels[c.index_E_max],
                "omega_min_at": c.labels[c.index_E_min], "phi_omega_max_deg": math.degrees(c.phi_E_max),
                "phi_omega_min_deg": math.degrees(c.phi_E_min), "omega_m": f.omega_m, "omega_max": f.omega_max,
                "omega_min": f.omega_min, "J_F": f.J_F}


@dataclass(frozen=True)
class PlanVariant(Variant):
    """A slider-crank (crank counterclockwise, slider on the +x side) in one position φ (degrees).

    Lengths in m, ω_1 in rad/s, ``mu_l`` (m/mm) for the scheme, ``mu_v`` ((m/s)/mm) for the plan.

    >>> v = PlanVariant(seed=0, number=1, r=0.1, l=0.4, e=0.0, l_AS2=0.13, phi_deg=60.0, omega_1=10.0,
    ...                 mu_l=0.004, mu_v=0.02)
    >>> a = v.answers()
    >>> a["v_A"], round(a["pa_mm"], 3), round(a["v_B"], 4), round(a["omega_2"], 4), a["omega_2_sense"]
    (1.0, 50.0, 0.9769, 1.2804, 'cw')
    """

    kind: ClassVar[str] = "velocity-plan"
    seed: int
    number: int
    r: float
    l: float
    e: float
    l_AS2: float
    phi_deg: float
    omega_1: float
    mu_l: float
    mu_v: float

    @cached_property
    def mechanism(self):
        from graphmethods.kinematics import SliderCrank

        return SliderCrank(r=self.r, l=self.l, e=self.e, points={"S2": ("AB", self.l_AS2, 0.0)})

    @cached_property
    def positions(self):
        return self.mechanism.positions(phi=[math.radians(self.phi_deg)])

    @cached_property
    def plan(self):
        return self.mechanism.velocity_plans(self.positions, omega_1=self.omega_1)

    def vectors(self) -> dict[str, np.ndarray]:
        """Plan vectors (m/s) by plan label: ``{"p": (0, 0), "a": …, "b": …, "s2": …}``."""
        out: dict[str, np.ndarray] = {}
        for name in self.plan.order:
            out.setdefault(self.plan.label(name), np.asarray(self.plan.v(name)[0], dtype=float))
        return out

    def answers(self) -> dict:
        v = self.vectors()
        seg = {k: float(np.hypot(*(v[b] - v[a]))) for k, (a, b) in SEGMENTS.items()}
        w2 = float(self.plan.omega("AB")[0])
        return {**{f"{k}_mm": s / self.mu_v for k, s in seg.items()},
                "v_A": seg["pa"], "v_B": seg["pb"], "v_BA": seg["ab"], "v_S2": seg["ps2"],
                "omega_2": abs(w2), "omega_2_sense": "ccw" if w2 > 0 else "cw"}


#: the segments of a slider-crank's velocity plan: name -> (from, to) plan points
SEGMENTS = {"pa": ("p", "a"), "pb": ("p", "b"), "ab": ("a", "b"), "ps2": ("p", "s2")}


@dataclass(frozen=True)
class EnergyMassVariant(_FlywheelVariant):
    """A press given by its table J_e (kg·m²) and ΔT (J) at positions 0…m, with n, [δ] and μ_J, μ_T.

    ``press`` holds the linkage data the table was computed from (shown in the statement).

    >>> v = EnergyMassVariant(seed=0, number=1, press={}, phi_deg=(0, 90, 180, 270, 360),
    ...                       J_e=(1.0, 0.8, 1.0, 1.2, 1.0), delta_T=(0.0, 40.0, 0.0, -40.0, 0.0),
    ...                       n_rpm=190.98593171027443, delta="1/25", mu_J=0.005, mu_T=1.0)
    >>> round(v.result.kl_mm, 3), round(v.answers()["J_F"], 4)
    (144.032, 9.002)
    """

    kind: ClassVar[str] = "wittenbauer"
    seed: int
    number: int
    press: dict
    phi_deg: tuple
    J_e: tuple
    delta_T: tuple
    n_rpm: float
    delta: str
    mu_J: float
    mu_T: float

    def __hash__(self):          # the press dict is not hashable
        return hash((self.kind, self.seed, self.number))

    @property
    def m(self) -> int:
        return len(self.J_e) - 1

    @cached_property
    def result(self):
        from graphmethods.dynamics.wittenbauer import wittenbauer

        return wittenbauer(J_e=self.J_e, delta_T=self.delta_T, omega_m=self.omega_m, delta=self.delta_value,
                           mu_J=self.mu_J, mu_T=self.mu_T, phi=np.radians(np.asarray(self.phi_deg, dtype=float)))

    def answers(self) -> dict:
        r = self.result
        return {"tan_psi_max": r.tan_psi_max, "tan_psi_min": r.tan_psi_min, "k_mm": r.k_mm, "l_mm": r.l_mm,
                "kl_mm": r.kl_mm, "J_F": r.J_F, "omega_max_at": list(r.index_omega_max),
                "omega_min_at": list(r.index_omega_min)}


#: the kinds kept in a module of their own (under :mod:`graphmethods.sheets.worksheets`), which registers the
#: kind when imported: imported when the kind is first asked for, so a class set of one kind loads no other
OWN_MODULES = {"acceleration-plan": "acceleration_plan", "cam": "cam"}


class Kinds(dict):
    """A table by worksheet kind whose own-module kinds (:data:`OWN_MODULES`) are registered on first use."""

    def __missing__(self, kind: Any) -> Any:
        if kind in OWN_MODULES:
            load_kind(kind)
            if dict.__contains__(self, kind):
                return dict.__getitem__(self, kind)
        raise KeyError(kind)

    def __contains__(self, kind: object) -> bool:
        if dict.__contains__(self, kind):
            return True
        if kind in OWN_MODULES:
            load_kind(str(kind))
            return dict.__contains__(self, kind)
        return False


def load_kind(kind: str) -> bool:
    """Import the module of a kind kept in a module of its own (it registers itself); True when one was.

    >>> load_kind("cam") and "cam" in CLASSES
    True
    """
    home = OWN_MODULES.get(kind)
    if home is None:
        return False
    import importlib
    importlib.import_module(f"graphmethods.sheets.worksheets.{home}")
    return dict.__contains__(CLASSES, kind)


CLASSES: dict[str, Any] = Kinds({"indicator": IndicatorVariant, "step-moment": StepMomentVariant,
                                  "velocity-plan": PlanVariant, "wittenbauer": EnergyMassVariant})


def variant_from_dict(d: dict, *, source: str = "<dict>") -> Variant:
    """A variant from a problem file's dict (see :meth:`Variant.to_dict`); ``answers`` are ignored.

    Raises
    ------
    InputError
        If the format, kind or data do not fit (the message names the key).
    """
    if not isinstance(d, dict) or d.get("format") != PROBLEM_FORMAT:
        raise InputError(f"{source}: not a worksheet problem file (expected \"format\": \"{PROBLEM_FORMAT}\")")
    kind = d.get("kind")
    if kind not in CLASSES:
        raise InputError(f"{source}: unknown worksheet kind {kind!r}; kinds: {', '.join(KINDS)}")
    cls = CLASSES[kind]
    data = d.get("data")
    if not isinstance(data, dict):
        raise InputError(f"{source}: key 'data' must hold the variant's inputs")
    names = [f.name for f in fields(cls)]
    missing = [n for n in names if n not in data and n != "step_mm"]
    unknown = [k for k in data if k not in names]
    if missing or unknown:
        raise InputError(f"{source}: {'missing ' + repr(missing[0]) if missing else 'unknown ' + repr(unknown[0])} "
                         f"in 'data' for kind {kind}; the keys are {', '.join(names)}")
    kw = {k: tuple(v) if isinstance(v, list) else v for k, v in data.items()}
    try:
        var = cls(**kw)
        var.answers()                 # validate: the data must make a solvable problem
    except InputError as exc:
        raise InputError(f"{source}: {exc}") from None
    except (TypeError, ValueError) as exc:
        raise InputError(f"{source}: bad data ({exc})") from None
    return var


# ----------------------------------------------------------------------------- generators (nice numbers)

_N_RPM = (120.0, 150.0, 180.0, 200.0, 240.0, 300.0, 360.0, 400.0, 450.0, 500.0, 600.0, 720.0, 750.0, 900.0,
          1000.0, 1200.0, 1500.0)
_DELTA = ("1/10", "1/12", "1/15", "1/20", "1/25", "1/30", "1/40", "1/50", "1/60", "1/80", "1/100")
# (μ_M N·m/mm, μ_φ rad/mm) with a round product μ_M·μ_φ ≠ 1 J/mm² (so forgetting it shows)
_AREA_SCALES = ((4.0, 0.025), (10.0, 0.025), (20.0, 0.025), (200.0, 0.025), (5.0, 0.04), (50.0, 0.04),
                (100.0, 0.04), (10.0, 0.05), (50.0, 0.05), (100.0, 0.05), (4.0, 0.05), (2.0, 0.05))


def pick(rng, seq):
    """One element of ``seq`` drawn by the variant's generator (the same seed, the same choice).

    Parameters
    ----------
    rng : numpy.random.Generator
        The variant's generator.
    seq : sequence
        The choices.

    Examples
    --------
    >>> import numpy as np
    >>> pick(np.random.default_rng(7), ["a", "b", "c"])
    'c'
    """
    return seq[int(rng.integers(len(seq)))]


def _nice_below(x: float) -> float:
    """The largest of 1, 2, 2.5, 4, 5 × 10^k not above x (x > 0)."""
    from graphmethods.units import convenient_at_most

    return convenient_at_most(x)


def pick_scale(span: float, room_mm: float) -> float:
    """The convenient scale (units per mm) that draws ``span`` within ``room_mm``.

    Parameters
    ----------
    span : float
        The extent to draw, in the quantity's unit (m, m/s, J ...).
    room_mm : float, mm
        The room on the page.

    Returns
    -------
    float
        μ, units per mm, from the series 1, 2, 2.5, 4, 5 × 10^k (:func:`graphmethods.scene.pick_scale`).

    Examples
    --------
    >>> pick_scale(0.2, 80.0)
    0.0025
    """
    from graphmethods.scene import pick_scale

    return pick_scale(span, room_mm).per_mm


def _levels_ok(E: np.ndarray, margin: float) -> bool:
    """The highest and lowest running energies are single points, ``margin`` clear of every other level
    (the start/end level included), so a student cannot mistake them."""
    inner = np.sort(np.asarray(E, dtype=float)[1:-1])
    if inner.size < 2:
        return inner.size == 1 and abs(inner[0]) >= margin
    return inner[-1] - max(inner[-2], 0.0) >= margin and min(inner[1], 0.0) - inner[0] >= margin


def _gen_indicator(rng) -> dict:
    k = int(pick(rng, (5, 6, 7, 7, 8)))
    while True:
        sign = 1 if rng.random() < 0.5 else -1
        units = []
        for i in range(k - 1):
            units.append(sign * int(rng.integers(3, 46)) * (-1) ** i)
        last = -sum(units)
        want = sign * (-1) ** (k - 1)
        if last * want <= 0 or not 3 <= abs(last) <= 60:
            continue
        units.append(last)
        E = np.concatenate(([0], np.cumsum(units)))
        if _levels_ok(E, 3):
            break
    areas = tuple(int(u * 10) for u in units)
    mu_M, mu_phi = pick(rng, _AREA_SCALES)
    n = pick(rng, _N_RPM)
    delta = pick(rng, _DELTA)
    work = np.asarray(areas, dtype=float) * mu_M * mu_phi
    levels = np.concatenate(([0.0], np.cumsum(work)))
    dW = float(levels.max() - levels.min())
    J_total = dW / (omega_from_n(n) ** 2 * float(Fraction(delta)))
    J_e = _nice_below(0.25 * J_total)
    span = float(max(levels.max(), 0.0) - min(levels.min(), 0.0))
    return dict(areas_mm2=areas, mu_M=mu_M, mu_phi=mu_phi, n_rpm=n, delta=delta, J_e=J_e,
                mu_E=pick_scale(span, 90.0))


def _gen_step_moment(rng) -> dict:
    shape = "steps" if rng.random() < 0.6 else "linear"
    while True:
        if shape == "steps":
            grid = int(pick(rng, (30, 45)))
            cuts = int(pick(rng, (2, 3, 3, 4)))
            inner = sorted(int(c) for c in rng.choice(np.arange(1, 360 // grid), size=cuts - 1, replace=False))
            bounds = [0] + [c * grid for c in inner] + [360]
            values = [int(rng.integers(1, 13)) * 5 for _ in range(cuts)]
            if any(a == b for a, b in zip(values, values[1:])):
                continue
            phi: list[float] = []
            M: list[float] = []
            for a, b, m in zip(bounds, bounds[1:], values):
                phi += [a, b]
                M += [m, m]
        else:
            grid = int(pick(rng, (30, 45)))
            nk = 360 // grid
            peak = int(rng.integers(1, nk // 2 + 1))
            top = int(rng.integers(4, 17)) * 5
            base = int(rng.integers(0, 3)) * 5
            end = int(rng.integers(peak + 1, nk))
            phi = [i * grid for i in range(nk + 1)]
            M = []
            for i in range(nk + 1):
                if i <= peak:
                    M.append(base + (top - base) * i / peak)
                elif i <= end:
                    M.append(top + (base - top) * (i - peak) / (end - peak))
                else:
                    M.append(base)
            if any(float(x) != int(x) for x in M):
                continue
            M = [int(x) for x in M]
        curve = MomentCurve(np.radians(phi), np.asarray(M, dtype=float))
        M_d = curve.mean()
        if abs(M_d * 4 - round(M_d * 4)) > 1e-9:          # M_d a multiple of 0.25 N·m
            continue
        if min(abs(np.asarray(M, dtype=float) - M_d)) < 2.0:     # no stretch on or grazing the M_d line
            continue
        cyc = ew.from_moments(M_r=curve)
        if cyc.work.size < 2 or not _levels_ok(np.asarray(cyc.E), 0.05 * cyc.delta_W_max):
            continue
        break
    n = pick(rng, _N_RPM[:10])
    delta = pick(rng, _DELTA[:8])
    dW = cyc.delta_W_max
    J_total = dW / (omega_from_n(n) ** 2 * float(Fraction(delta)))
    J_e = _nice_below(0.25 * J_total)
    M_hi = max(max(M), M_d)
    return dict(shape=shape, phi_deg=tuple(int(p) for p in phi), M_r=tuple(M), n_rpm=n, delta=delta, J_e=J_e,
                mu_M=pick_scale(M_hi, 60.0), mu_phi_deg=2.5)


def _gen_plan(rng) -> dict:
    r = pick(rng, (0.05, 0.06, 0.08, 0.1, 0.12, 0.15))
    lam = pick(rng, (3, 4, 5))
    l = round(r * lam, 3)
    e = pick(rng, (0.0, 0.0, round(r / 5, 3), round(r / 4, 3)))
    l_AS2 = round(l * pick(rng, (0.3, 0.35, 0.4)), 3)
    phi = float(pick(rng, (30, 45, 60, 120, 135, 150, 210, 225, 240, 300, 315, 330)))
    omega_1 = float(pick(rng, (10, 12, 15, 16, 20, 24, 25, 30)))
    mu_l = pick_scale(r + l + r, 150.0)
    mu_v = pick_scale(omega_1 * r, 85.0)
    return dict(r=r, l=l, e=e, l_AS2=l_AS2, phi_deg=phi, omega_1=omega_1, mu_l=mu_l, mu_v=mu_v)


def _gen_press(rng) -> dict:
    r = pick(rng, (0.08, 0.1, 0.12))
    l = round(r * pick(rng, (4, 5)), 3)
    return dict(r=r, l=l, e=pick(rng, (0.0, 0.01, 0.02)), l_AS2=round(l / 3, 3),
                m2=pick(rng, (6.0, 8.0, 10.0, 12.0)), J_S2=0.0, m3=pick(rng, (10.0, 12.0, 15.0, 20.0)),
                J1=pick(rng, (0.3, 0.4, 0.5, 0.6)), F0=pick(rng, (3000.0, 4000.0, 5000.0, 6000.0, 8000.0)),
                force_from=pick(rng, (0.05, 0.1, 0.2)), force_to=pick(rng, (0.8, 0.9, 0.95)),
                n_rpm=pick(rng, (200.0, 240.0, 300.0, 360.0, 400.0)), delta=pick(rng, ("1/20", "1/25", "1/30")))


def energy_mass_from_press(press: dict, *, seed: int = 0, number: int = 1, positions: int = 12,
                           room_mm: tuple[float, float] = (150.0, 112.0)) -> EnergyMassVariant:
    """A ``wittenbauer`` variant from a press's data (the keys of ``slider_crank_press.json``).

    The table J_e, ΔT at positions 0…m is computed with :class:`~graphmethods.dynamics.study.Study` and
    rounded as a worksheet prints it (J_e to 0.001 kg·m², ΔT to 1 J); the expected answers are those of
    the rounded table. Scales μ_J, μ_T are picked so that the diagram, with its ordinate axis at J_e = 0
    and the points k and l on it, fits ``room_mm`` (width, height).
    """
    from graphmethods.dynamics.study import Study
    from graphmethods.kinematics import case_from_dict

    data = dict(press)
    J_S2 = data.get("J_S2") or round(data["m2"] * data["l"] ** 2 / 12.0, 3)
    data["J_S2"] = J_S2
    case = case_from_dict({**data, "delta": str(data["delta"])}, source="worksheet press")
    study = Study(case, positions=positions, estimate=False)
    J_e = np.round(np.asarray(study.J_e, dtype=float), 3)
    dT = np.round(np.asarray(study.delta_T, dtype=float), 0)
    J_e[-1], dT[0], dT[-1] = J_e[0], 0.0, 0.0
    phi_deg = np.round(np.degrees(study.phi), 6)
    omega = omega_from_n(data["n_rpm"])
    d = float(_fraction(data["delta"]))
    # the span to fit: from max(ΔT, 0) down to the lower ray's intercept l (x = 0); the intercepts scale
    # with 1/μ_T whatever μ_J is, so fit x first, then y
    mu_J = pick_scale(float(J_e.max()), room_mm[0] - 25.0)
    b_lo = float(np.min(dT - 0.5 * omega**2 * (1 - d / 2) ** 2 * J_e))
    b_up = float(np.max(dT - 0.5 * omega**2 * (1 + d / 2) ** 2 * J_e))
    top = max(float(dT.max()), 0.0, b_up)
    mu_T = pick_scale(top - min(b_lo, float(dT.min())), room_mm[1] - 18.0)
    return EnergyMassVariant(seed=seed, number=number, press={k: data[k] for k in sorted(data)},
                             phi_deg=tuple(float(p) for p in phi_deg), J_e=tuple(float(x) for x in J_e),
                             delta_T=tuple(float(x) for x in dT), n_rpm=float(data["n_rpm"]),
                             delta=str(data["delta"]), mu_J=mu_J, mu_T=mu_T)


GENERATORS: dict[str, Callable] = Kinds({"indicator": _gen_indicator, "step-moment": _gen_step_moment,
                                           "velocity-plan": _gen_plan, "wittenbauer": _gen_press})


def _key(params: dict) -> str:
    return json.dumps(params, sort_keys=True, allow_nan=False)


def check_kind(kind: str) -> str:
    """``kind`` when it names a worksheet kind (:data:`KINDS`).

    Raises
    ------
    InputError
        Naming the kinds, for any other.

    Examples
    --------
    >>> check_kind("velocity-plan")
    'velocity-plan'
    """
    if kind not in KINDS:
        raise InputError(f"unknown worksheet kind {kind!r}; kinds: {', '.join(KINDS)}")
    return kind


def _check_count(value, name: str, low: int, high: int = MAX_VARIANTS) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
        raise InputError(f"{name} must be an integer ≥ {low}, got {value!r}")
    if value > high:
        raise InputError(f"{name} = {value} is above the limit {high} (checked before any variant is built)")
    return int(value)


def variants(kind: str, *, count: int, seed: int) -> tuple[Variant, ...]:
    """Variants 1…count of a worksheet kind, reproducible from ``seed`` (an integer ≥ 0).

    Variant k is drawn from ``numpy.random.default_rng([seed, kind, k, attempt])``; a draw equal to an
    earlier variant's is drawn again (``attempt`` + 1), so the variants of a batch differ and variant k
    is the same whatever ``count`` is.

    >>> [v.n_rpm for v in variants("indicator", count=3, seed=1)] == \\
    ...     [v.n_rpm for v in variants("indicator", count=5, seed=1)][:3]
    True
    """
    check_kind(kind)
    count = _check_count(count, "the number of variants", 1)
    seed = _check_count(seed, "the seed", 0, high=2**63 - 1)
    gen, seen, out = GENERATORS[kind], set(), []
    for number in range(1, count + 1):
        for attempt in range(100):
            rng = np.random.default_rng([seed, _KIND_CODE[kind], number, attempt])
            params = gen(rng)
            if _key(params) not in seen:
                break
        seen.add(_key(params))
        if kind == "wittenbauer":
            out.append(energy_mass_from_press(params, seed=seed, number=number))
        else:
            out.append(CLASSES[kind](seed=seed, number=number, **params))
    return tuple(out)


def variant(kind: str, *, seed: int, number: int) -> Variant:
    """Variant ``number`` of ``kind`` for ``seed`` (the same as in any batch of that seed)."""
    return variants(kind, count=_check_count(number, "the variant number", 1), seed=seed)[-1]


def parse_id(text: str) -> Variant | None:
    """The variant an id ``"KIND:SEED:NUMBER"`` names, or None when ``text`` is not such an id.

    >>> parse_id("indicator:7:2").id, parse_id("W1")
    ('indicator:7:2', None)
    """
    m = re.fullmatch(r"([a-z-]+):(\d+):(\d+)", str(text).strip())
    if not m or m.group(1) not in KINDS:
        return None
    if len(m.group(3)) > 6 or int(m.group(3)) > MAX_VARIANTS:
        raise InputError(f"{text}: variant number {m.group(3)[:20]} is above the limit {MAX_VARIANTS} "
                         f"of a worksheet set")
    if len(m.group(2)) > 19 or int(m.group(2)) > 2**63 - 1:
        raise InputError(f"{text}: seed {m.group(2)[:20]}… is above the limit 2**63 − 1")
    return variant(m.group(1), seed=int(m.group(2)), number=int(m.group(3)))


