"""Problem files: a linkage with its masses, its load and its speed, read from JSON and validated.

One JSON object per file, SI units (m, kg, kg·m², N, N·m, rev/min), angles in keys ending in
``_deg``. ``kind`` selects the format (default ``"slider_crank"``, the press format of
``shared/cases/slider_crank_press.json``); ``about`` and ``units`` are free text; ``name``, the
problem's title, is text (used for every language) or a mapping by language such as
``{"en": "offset slider-crank press", "ru": "…", "zh": "…"}`` (a figure in a language the mapping
lacks shows the English; see :class:`graphmethods.titles.Title`).
Every other key is checked: a missing, misspelt, non-numeric or out-of-range key, or
dimensions that cannot be assembled, raise an :class:`~graphmethods.errors.InputError` (or
its subclass AssemblyError) whose one-line message names the file and the key.

Formats (required keys; optional ones with their default):

``slider_crank``  r, l, e, l_AS2, m2, J_S2, m3, J1, F0, force_from, force_to, n_rpm, delta;
                  assembly (1), sense ("ccw"), working_stroke ("toward_crank")
``four_bar``      l1 (ground O1O2), l2 (crank O1A), l3 (coupler AB), l4 (rocker O2B), l_AS2, l_O2S3,
                  m2, J_S2, m3, J_S3, J1, M3, moment_from, moment_to, n_rpm, delta;
                  ground_angle_deg (0), assembly (1), sense ("ccw"), working_stroke ("slow")
``slotted_lever`` r, l_O1O3, l_O3B, l_O3S3, m3, J_S3, J1, M3, moment_from, moment_to, n_rpm, delta;
                  theta_O3_deg (−90), m2 (0: block at A), sense ("ccw"), working_stroke ("slow")
``shaper``        r, l_O1O3, l_O3B, l_BC, y_guide, l_O3S3, l_BS4, m3, J_S3, m4, J_S4, m5, J1, F0,
                  force_from, force_to, n_rpm, delta; theta_O3_deg (−90), m2 (0), assembly (1),
                  sense ("ccw"), working_stroke ("slow")

The load acts on the working stroke only, against the motion: a force F0 on the slider (press
B, shaper ram C) while its displacement s is between force_from·H and force_to·H, or a moment
M3 on the rocker while its swing ψ is between moment_from·ψ_max and moment_to·ψ_max.

>>> case = case_from_dict({"r": 0.1, "l": 0.4, "e": 0.02, "l_AS2": 0.13, "m2": 8, "J_S2": 0.12,
...                        "m3": 12, "J1": 0.5, "F0": 5000, "force_from": 0.05, "force_to": 0.95,
...                        "n_rpm": 300, "delta": 0.04})
>>> case.kind, case.mechanism.l, round(case.omega_m, 4)
('slider_crank', 0.4, 31.4159)
>>> [i.point for i in case.inertias]
['O', 'S2', 'B']
"""

from __future__ import annotations

import math
import os
import pathlib
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from graphmethods.errors import AssemblyError, InputError
from graphmethods.kinematics.classic import FourBar, Shaper, SliderCrank, SlottedLever
from graphmethods.kinematics.linkage import Linkage
from graphmethods.kinematics.linkage_mechanism import LinkageMechanism
from graphmethods.titles import Title
from graphmethods.units import DELTA_MAX, angle_deg, finite_result, json_value, omega_from_n, read_text, real


@dataclass(frozen=True)
class Inertia:
    """A moving mass for the reduced model: J_e gets ``m·(v_point/ω₁)² + J·(ω_link/ω₁)²``.

    Attributes
    ----------
    link : str or None
        Link whose angular velocity multiplies J (None for a translating slider).
    point : str
        Point whose velocity multiplies m (the centre of mass).
    m : float
        Mass, kg.
    J : float
        Moment of inertia about ``point``, kg·m² (for the crank: about its pivot).
    """

    link: str | None
    point: str
    m: float
    J: float


@dataclass(frozen=True)
class Load:
    """The resisting load of the working stroke (zero on the return stroke).

    Attributes
    ----------
    kind : str
        ``"force"`` on a slider point along its guide, or ``"moment"`` on a link; it always
        opposes the motion.
    at : str
        The point (force) or link (moment).
    magnitude : float
        N or N·m (≥ 0).
    start, end : float
        Fractions of the stroke (s/H for a force, ψ/ψ_max for a moment) between which it acts.
    """

    kind: str
    at: str
    magnitude: float
    start: float
    end: float


#: one stroke of a force diagram: (stroke fractions x, forces F in N, "working" or "return", drives)
DiagramPart = tuple[tuple[float, ...], tuple[float, ...], str, bool]


@dataclass(frozen=True)
class DiagramLoad:
    """Forces on a slider given as diagrams against the stroke (an indicator diagram), as course
    problems give them: each part is one stroke's force F (N, ≥ 0) against the stroke fraction s/H
    (from the start of the working stroke on both strokes), piecewise linear, and whether it drives
    the slider (gas expanding) or resists its motion (gas compressed, a cutting force).

    Attributes
    ----------
    at : str
        The slider point.
    parts : tuple of (x, F, stroke, drives)
        ``x`` and ``F`` tuples of floats, ``stroke`` ``"working"`` or ``"return"``, ``drives`` bool.
    """

    at: str
    parts: tuple[DiagramPart, ...]
    kind: str = "diagram"


@dataclass(frozen=True)
class Case:
    """A problem file, validated (see the module docstring).

    Attributes
    ----------
    kind : str
        ``"slider_crank"``, ``"four_bar"``, ``"slotted_lever"`` or ``"shaper"``.
    title : Title
        The problem's title (the file's ``name``): plain text, or text by language.
    about : str
        Free text from the file.
    source : str
        Where it was read from (file path or ``"<dict>"``).
    mechanism : LinkageMechanism
        The linkage with its centres of mass as extra points.
    n_rpm : float
        Mean crank speed, rev/min.
    delta : float
        Permissible coefficient of speed fluctuation.
    inertias : tuple of Inertia
        Every moving mass.
    load : Load or DiagramLoad
        The working-stroke load (a linkage file may give force diagrams).
    values : mapping
        Every key of the file after validation (numbers as floats).
    """

    kind: str
    title: Title
    about: str
    source: str
    mechanism: LinkageMechanism
    n_rpm: float
    delta: float
    inertias: tuple[Inertia, ...]
    load: Load | DiagramLoad
    values: Mapping[str, Any]

    @property
    def name(self) -> str:
        """The title as one string: the English text, or the plain string the file gives."""
        return str(self.title)

    @property
    def omega_m(self) -> float:
        """Mean crank speed, rad/s."""
        return omega_from_n(self.n_rpm)

    @property
    def linkage(self) -> Linkage:
        """The problem's linkage on the kinematics core (:class:`~graphmethods.kinematics.linkage.Linkage`:
        accelerations, structure), the same linkage as ``mechanism``."""
        return self.mechanism.linkage

    def __getattr__(self, key: str) -> Any:
        # every validated key is also an attribute: case.m2, case.F0, ...
        values = self.__dict__.get("values")
        if values is not None and key in values:
            return values[key]
        raise AttributeError(key)


class SliderCrankCase(Case):
    """A slider-crank (press) problem file."""


class FourBarCase(Case):
    """A four-bar problem file."""


class SlottedLeverCase(Case):
    """A crank and slotted lever problem file."""


class ShaperCase(Case):
    """A shaper problem file."""


REQUIRED = object()
_TEXT = {"name", "about", "units", "kind"}

# key: (check, default, meaning)
_COMMON_TAIL = {
    "n_rpm": ("positive", REQUIRED, "mean crank speed, rev/min"),
    "delta": ("delta", REQUIRED, "permissible coefficient of speed fluctuation, 0 < δ < 1"),
    "sense": ("sense", "ccw", 'crank sense of rotation, "ccw" or "cw"'),
}

#: a key's check ("positive", "nonneg", "real", "fraction", "delta", "sign", "sense", or the allowed texts),
#: its default (REQUIRED: none) and its meaning
Spec = tuple[str | tuple[str, ...], object, str]


def _link_mass(i: str, link: str) -> dict[str, Spec]:
    """The keys m<i> (kg) and J_S<i> (kg·m², about the centre of mass S<i>) of link i, ``link`` naming it."""
    return {f"m{i}": ("nonneg", REQUIRED, f"{link} mass, kg"),
            f"J_S{i}": ("nonneg", REQUIRED, f"{link} moment of inertia about S{i}, kg·m²")}


def _centre(point: str, i: str, link: str) -> dict[str, Spec]:
    """The key l_<point>S<i>: where link i's centre of mass S<i> lies, measured from ``point`` along it, m."""
    return {f"l_{point}S{i}": ("nonneg", REQUIRED, f"distance from {point} to the {link}'s centre of mass S{i}, m")}


#: the key groups the kinds share (the slotted lever and the shaper: the same crank, slot and rocker)
_J1_O1: dict[str, Spec] = {
    "J1": ("nonneg", REQUIRED, "crank and everything turning with it, about O1, kg·m²"),
}
_FORCE_SPAN: dict[str, Spec] = {
    "force_from": ("fraction", REQUIRED, "fraction of the stroke where the force starts"),
    "force_to": ("fraction", REQUIRED, "fraction of the stroke where the force ends"),
}
_ROCKER_MOMENT: dict[str, Spec] = {
    "M3": ("nonneg", REQUIRED, "resisting moment on the rocker during its working swing, N·m"),
    "moment_from": ("fraction", REQUIRED, "fraction of the swing where the moment starts"),
    "moment_to": ("fraction", REQUIRED, "fraction of the swing where the moment ends"),
}
_SLOTTED: dict[str, Spec] = {
    "r": ("positive", REQUIRED, "crank O1A, m"),
    "l_O1O3": ("positive", REQUIRED, "centre distance O1O3, m"),
    "l_O3B": ("positive", REQUIRED, "rocker O3B, m"),
}
_ROCKER_PLACE: dict[str, Spec] = {
    "theta_O3_deg": ("real", -90.0, "direction of O1->O3 from +x, degrees"),
    **_centre("O3", "3", "rocker"),
}
_BLOCK_ROCKER_MASS: dict[str, Spec] = {
    "m2": ("nonneg", 0.0, "block mass (at A), kg"),
    **_link_mass("3", "rocker"),
}
_SLOW_OR_FAST_SWING: dict[str, Spec] = {"working_stroke": (("slow", "fast"), "slow", "which swing works")}

SPECS: dict[str, dict[str, Spec]] = {
    "slider_crank": {
        "r": ("positive", REQUIRED, "crank O-A, m"),
        "l": ("positive", REQUIRED, "connecting rod A-B, m"),
        "e": ("real", REQUIRED, "offset: the slider's guide is the line y = e, m"),
        **_centre("A", "2", "rod"),
        **_link_mass("2", "rod"),
        "m3": ("nonneg", REQUIRED, "slider mass, kg"),
        "J1": ("nonneg", REQUIRED, "crank and everything turning with it, about O, kg·m²"),
        "F0": ("nonneg", REQUIRED, "resisting force on the slider during the working stroke, N"),
        **_FORCE_SPAN,
        "assembly": ("sign", 1, "+1: slider on the +x side of A, -1: on the -x side"),
        "working_stroke": (("toward_crank", "away_from_crank", "slow", "fast"), "toward_crank", "which stroke works"),
        **_COMMON_TAIL,
    },
    "four_bar": {
        "l1": ("positive", REQUIRED, "ground O1O2, m"),
        "l2": ("positive", REQUIRED, "crank O1A, m"),
        "l3": ("positive", REQUIRED, "coupler AB, m"),
        "l4": ("positive", REQUIRED, "rocker O2B, m"),
        "ground_angle_deg": ("real", 0.0, "direction of O1->O2 from +x, degrees"),
        **_centre("A", "2", "coupler"),
        **_centre("O2", "3", "rocker"),
        **_link_mass("2", "coupler"),
        **_link_mass("3", "rocker"),
        **_J1_O1,
        **_ROCKER_MOMENT,
        "assembly": ("sign", 1, "+1 or -1: the branch of the linkage"),
        **_SLOW_OR_FAST_SWING,
        **_COMMON_TAIL,
    },
    "slotted_lever": {
        **_SLOTTED,
        **_ROCKER_PLACE,
        **_BLOCK_ROCKER_MASS,
        **_J1_O1,
        **_ROCKER_MOMENT,
        **_SLOW_OR_FAST_SWING,
        **_COMMON_TAIL,
    },
    "shaper": {
        **_SLOTTED,
        "l_BC": ("positive", REQUIRED, "connecting link BC, m"),
        "y_guide": ("real", REQUIRED, "height of the ram's guide line above O1, m"),
        **_ROCKER_PLACE,
        **_centre("B", "4", "link"),
        **_BLOCK_ROCKER_MASS,
        **_link_mass("4", "link BC"),
        "m5": ("nonneg", REQUIRED, "ram mass, kg"),
        **_J1_O1,
        "F0": ("nonneg", REQUIRED, "cutting force on the ram during the working stroke, N"),
        **_FORCE_SPAN,
        "assembly": ("sign", 1, "+1: ram C on the +x side of B, -1: on the -x side"),
        "working_stroke": (("slow", "fast"), "slow", "which stroke works"),
        **_COMMON_TAIL,
    },
}


def _value(source: str, key: str, raw: Any, check: str | tuple[str, ...], meaning: str) -> Any:
    """The checked value of one key (text, ±1 or a float); ``raw`` is as JSON gives it."""
    where = f"{source}: key {key!r} ({meaning})"
    if isinstance(check, tuple):
        if raw not in check:
            raise InputError(f"{where} must be one of {', '.join(check)}; got {raw!r}")
        return raw
    if check == "sense":
        if raw not in ("ccw", "cw"):
            raise InputError(f'{where} must be "ccw" or "cw"; got {raw!r}')
        return raw
    if check == "sign":
        if raw not in (1, -1) or isinstance(raw, bool):
            raise InputError(f"{where} must be 1 or -1; got {raw!r}")
        return int(raw)
    if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
        raise InputError(f"{where} must be a number; got {raw!r}")
    if key.endswith("_deg"):       # any finite angle, reduced exactly modulo 360
        return angle_deg(raw, where)
    # the toolkit's one policy for numbers (graphmethods.units.real), then the key's physical range
    value = real(raw, where)
    if check == "positive" and not value > 0:
        raise InputError(f"{where} must be > 0; got {raw!r}")
    if check == "nonneg" and not value >= 0:
        raise InputError(f"{where} must be ≥ 0; got {raw!r}")
    if check == "fraction" and not 0.0 <= value <= 1.0:
        raise InputError(f"{where} must be a fraction between 0 and 1; got {raw!r}")
    if check == "delta" and not 0.0 < value < DELTA_MAX:
        raise InputError(f"{where} must be between 0 and {DELTA_MAX:g} (e.g. 0.04 or 1/25); got {raw!r}")
    return value


def _validated(data: Mapping[str, Any], kind: str, source: str) -> dict[str, Any]:
    """Every key of ``kind`` checked (defaults filled in): texts, ±1 and floats by key."""
    spec = SPECS[kind]
    unknown = [k for k in data if k not in spec and k not in _TEXT]
    if unknown:
        raise InputError(f"{source}: unknown key {unknown[0]!r} for kind {kind!r}; the keys are: "
                         f"{', '.join(spec)} (and name, about, units, kind)")
    for k in _TEXT - {"name"}:
        if k in data and not isinstance(data[k], str):
            raise InputError(f"{source}: key {k!r} must be text; got {data[k]!r}")
    out: dict[str, Any] = {}
    for key, (check, default, meaning) in spec.items():
        if key not in data:
            if default is REQUIRED:
                raise InputError(f"{source}: key {key!r} is missing ({meaning})")
            out[key] = default
            continue
        out[key] = _value(source, key, data[key], check, meaning)
    return out


def _order(v: Mapping[str, float], lo: str, hi: str, what: str) -> None:
    if not v[lo] < v[hi]:
        raise InputError(f"{lo} = {v[lo]:g} must be less than {hi} = {v[hi]:g} ({what})")


def _within(v: Mapping[str, float], key: str, length_key: str) -> None:
    if v[key] > v[length_key]:
        raise InputError(f"{key} = {v[key]:g} m lies beyond the link ({length_key} = {v[length_key]:g} m); "
                         f"a centre of mass must lie on its link")


def case_from_dict(data: Mapping[str, Any], *, source: str = "<dict>") -> Case:
    """Validate a problem given as a dict (a parsed JSON object) and build its :class:`Case`.

    Raises
    ------
    InputError, AssemblyError
        One line naming ``source`` and the offending key or length condition.
    """
    if not isinstance(data, Mapping):
        raise InputError(f"{source}: a problem file must hold one JSON object {{...}}, got {type(data).__name__}")
    kind = data.get("kind", "slider_crank")
    if kind == "linkage":
        from graphmethods.kinematics.linkage_file import linkage_case

        return linkage_case(data, source=source)
    if not isinstance(kind, str) or kind not in SPECS:
        raise InputError(f"{source}: unknown kind {kind!r}; known kinds: {', '.join(SPECS)}, linkage")
    v = _validated(data, kind, source)
    title = Title.of(data.get("name"), where=f"{source}: key 'name'")
    sense = 1 if v["sense"] == "ccw" else -1
    common = dict(kind=kind, title=title, about=data.get("about", ""), source=source,
                  n_rpm=v["n_rpm"], delta=v["delta"])
    omega = finite_result(omega_from_n(v["n_rpm"]), f"{source}: ω = πn/30 from key 'n_rpm'", unit="rad/s")
    if not 0.0 < omega * omega < math.inf:
        raise InputError(f"{source}: key 'n_rpm' = {v['n_rpm']:g} rev/min: ω² = (πn/30)² leaves the float range; "
                         f"give the mean speed in rev/min between about 1e-90 and 1e90")
    mech: LinkageMechanism
    inertias: tuple[Inertia, ...]
    cls: type[Case]
    try:
        if kind == "slider_crank":
            mech = SliderCrank(r=v["r"], l=v["l"], e=v["e"], assembly=v["assembly"], sense=sense,
                               working_stroke=v["working_stroke"], points={"S2": ("AB", v["l_AS2"], 0.0)})
            inertias = (Inertia("OA", "O", 0.0, v["J1"]), Inertia("AB", "S2", v["m2"], v["J_S2"]),
                        Inertia(None, "B", v["m3"], 0.0))
            load = Load("force", "B", v["F0"], v["force_from"], v["force_to"])
            _order(v, "force_from", "force_to", "fractions of the stroke")
            _within(v, "l_AS2", "l")
            cls = SliderCrankCase
        elif kind == "four_bar":
            mech = FourBar(l1=v["l1"], l2=v["l2"], l3=v["l3"], l4=v["l4"],
                           ground_angle=math.radians(v["ground_angle_deg"]), assembly=v["assembly"], sense=sense,
                           working_stroke=v["working_stroke"],
                           points={"S2": ("AB", v["l_AS2"], 0.0), "S3": ("O2B", v["l_O2S3"], 0.0)})
            mech._check_full_turn()
            inertias = (Inertia("O1A", "O1", 0.0, v["J1"]), Inertia("AB", "S2", v["m2"], v["J_S2"]),
                        Inertia("O2B", "S3", v["m3"], v["J_S3"]))
            load = Load("moment", "O2B", v["M3"], v["moment_from"], v["moment_to"])
            _order(v, "moment_from", "moment_to", "fractions of the swing")
            _within(v, "l_AS2", "l3")
            _within(v, "l_O2S3", "l4")
            cls = FourBarCase
        elif kind == "slotted_lever":
            mech = SlottedLever(r=v["r"], l_O1O3=v["l_O1O3"], l_O3B=v["l_O3B"],
                                theta_O3=math.radians(v["theta_O3_deg"]), sense=sense,
                                working_stroke=v["working_stroke"], points={"S3": ("O3B", v["l_O3S3"], 0.0)})
            inertias = (Inertia("O1A", "O1", 0.0, v["J1"]), Inertia("block", "A", v["m2"], 0.0),
                        Inertia("O3B", "S3", v["m3"], v["J_S3"]))
            load = Load("moment", "O3B", v["M3"], v["moment_from"], v["moment_to"])
            _order(v, "moment_from", "moment_to", "fractions of the swing")
            _within(v, "l_O3S3", "l_O3B")
            cls = SlottedLeverCase
        else:
            mech = Shaper(r=v["r"], l_O1O3=v["l_O1O3"], l_O3B=v["l_O3B"], l_BC=v["l_BC"], y_guide=v["y_guide"],
                          theta_O3=math.radians(v["theta_O3_deg"]), assembly=v["assembly"], sense=sense,
                          working_stroke=v["working_stroke"],
                          points={"S3": ("O3B", v["l_O3S3"], 0.0), "S4": ("BC", v["l_BS4"], 0.0)})
            inertias = (Inertia("O1A", "O1", 0.0, v["J1"]), Inertia("block", "A", v["m2"], 0.0),
                        Inertia("O3B", "S3", v["m3"], v["J_S3"]), Inertia("BC", "S4", v["m4"], v["J_S4"]),
                        Inertia(None, "C", v["m5"], 0.0))
            load = Load("force", "C", v["F0"], v["force_from"], v["force_to"])
            _order(v, "force_from", "force_to", "fractions of the stroke")
            _within(v, "l_O3S3", "l_O3B")
            _within(v, "l_BS4", "l_BC")
            cls = ShaperCase
    except AssemblyError as exc:
        raise AssemblyError(f"{source}: {exc}") from None
    except InputError as exc:
        raise InputError(f"{source}: {exc}") from None
    return cls(mechanism=mech, inertias=inertias, load=load, values=MappingProxyType(v), **common)


def read_case(path: str | os.PathLike[str]) -> Case:
    """Read and validate a problem file (JSON, see the module docstring).

    Parameters
    ----------
    path : str or path-like
        The file.

    Returns
    -------
    Case
        A :class:`SliderCrankCase`, :class:`FourBarCase`, :class:`SlottedLeverCase` or
        :class:`ShaperCase`.

    Raises
    ------
    InputError, AssemblyError
        Unreadable file, invalid JSON, a bad key or impossible dimensions (one line).
    """
    p = pathlib.Path(path)
    return case_from_dict(json_value(read_text(p), str(p)), source=str(p))
