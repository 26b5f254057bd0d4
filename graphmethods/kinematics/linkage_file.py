"""The problem file of any linkage (``"kind": "linkage"``): fixed joints, crank, Assur groups,
extra points, masses, the working load, speed and [δ]; read and validated key by key.

One JSON object, SI units (m, kg, kg·m², N, N·m, rev/min), angles in keys ending in ``_deg``.
Every error is one line naming the file and the key (``groups[1].l_PC``), and a linkage that
cannot be assembled names the position and the violated length condition.

====================  ====================================================================
key                   meaning
====================  ====================================================================
``fixed``             fixed joints: ``{"O1": [0, 0], "O2": [0.25, 0.1]}``, m
``crank``             ``{"centre": "O1", "pin": "A", "r": 0.08}`` (link 1)
``sense``             ``"ccw"`` (default) or ``"cw"``
``groups``            the Assur groups in solving order, each ``{"type": ..., "links": [i, j], ...}``:
                      RRR ``P, Q, C, l_PC, l_QC, branch``; RRP (or PRR) ``P, C, l, guide, branch``;
                      RPR ``P, Q, point, e, branch``; PRP ``C, guide_1, guide_2``;
                      RPP ``P, R, point, guide, slot_angle_deg, e``; a class III ``triad``
                      ``links [t, k1, k2, k3], outer [P1, P2, P3], inner [B1, B2, B3], drawn`` (the
                      six joints at the drawn position, {name: [x, y]}). A guide is
                      ``{"link": 0, "through": [x, y] or "joint", "angle_deg": 0}``.
``points``            extra points: ``{"S2": {"link": 2, "from": "A", "distance": 0.15, "angle_deg": 0}}``
                      (angle from the link's own direction); a group may be driven from one
``output``            the slider point or rocker link whose strokes count (default: the last group's)
``working_stroke``    ``"slow"`` (default), ``"fast"``, ``"toward_crank"``, ``"away_from_crank"``
``masses``            per link number: ``{"m": kg, "J": kg·m², "at": "S2"}`` (J about ``at``; for the
                      crank about its centre)
``load``              ``{"force": N, "on": "D", "from": 0.05, "to": 0.95}`` on the output slider, or
                      ``{"moment": N·m, "on": 3, "from": 0, "to": 1}`` on the output rocker: it acts on
                      the working stroke between those fractions of it, against the motion
``n_rpm``, ``delta``  mean crank speed, rev/min; permissible coefficient of fluctuation [δ]
``name``, ``about``   title (text, or ``{"en": ..., "ru": ..., "zh": ...}``) and free text
====================  ====================================================================

>>> case = linkage_case({"kind": "linkage", "fixed": {"O": [0, 0]},
...     "crank": {"centre": "O", "pin": "A", "r": 0.1},
...     "groups": [{"type": "RRP", "links": [2, 3], "P": "A", "C": "B", "l": 0.4,
...                 "guide": {"link": 0, "through": [0, 0], "angle_deg": 0}}],
...     "masses": {"3": {"m": 12, "at": "B"}}, "load": {"force": 5000, "on": "B", "from": 0.05, "to": 0.95},
...     "n_rpm": 300, "delta": 0.04})
>>> case.kind, case.mechanism.linkage.structure().formula
('linkage', 'I(0,1) → II(2,3)')
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from types import MappingProxyType
from typing import Any, NoReturn

from graphmethods.errors import AssemblyError, InputError
from graphmethods.kinematics.case import Case, DiagramLoad, Inertia, Load
from graphmethods.kinematics.groups import GROUND, KINDS, PRP, RPP, RPR, RRP, RRR, Group, Guide, Triad
from graphmethods.kinematics.linkage import MAX_GROUPS, Crank, Linkage, Point
from graphmethods.kinematics.linkage_mechanism import LinkageMechanism
from graphmethods.titles import Title
from graphmethods.units import parse_number

TOP_KEYS = ("kind", "name", "about", "units", "fixed", "crank", "sense", "groups", "points", "output",
            "working_stroke", "masses", "load", "n_rpm", "delta")

GROUP_KEYS = {
    "RRR": {"P": "str", "Q": "str", "C": "str", "l_PC": "positive", "l_QC": "positive", "branch": "sign"},
    "RRP": {"P": "str", "C": "str", "l": "positive", "guide": "guide", "branch": "sign"},
    "RPR": {"P": "str", "Q": "str", "point": "str", "e": "real", "branch": "sign"},
    "PRP": {"C": "str", "guide_1": "guide", "guide_2": "guide"},
    "RPP": {"P": "str", "R": "str", "point": "str", "guide": "guide", "slot_angle_deg": "real", "e": "real"},
}
GROUP_KEYS["PRR"] = GROUP_KEYS["RRP"]
OPTIONAL = {"branch": 1, "e": 0.0, "slot_angle_deg": 90.0}

#: a value as JSON gives it (a number, text, list, object, ...): what the readers below check and convert
Json = Any


class _Reader:
    def __init__(self, source: str) -> None:
        self.source = source

    def err(self, key: str, msg: str) -> NoReturn:
        raise InputError(f"{self.source}: key {key!r}: {msg}")

    def number(self, key: str, raw: Json, check: str = "real") -> float:
        if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
            self.err(key, f"must be a number; got {raw!r}")
        value = parse_number(raw, name=f"{self.source}: key {key!r}")
        if not math.isfinite(value):
            self.err(key, f"must be finite; got {raw!r}")
        if check == "positive" and not value > 0:
            self.err(key, f"must be > 0; got {raw!r}")
        if check == "nonneg" and not value >= 0:
            self.err(key, f"must be ≥ 0; got {raw!r}")
        if check == "fraction" and not 0.0 <= value <= 1.0:
            self.err(key, f"must be a fraction between 0 and 1; got {raw!r}")
        if check == "delta" and not 0.0 < value < 1.0:
            self.err(key, f"must be between 0 and 1 (e.g. 0.04 or 1/25); got {raw!r}")
        return value

    def text(self, key: str, raw: Json) -> str:
        if not isinstance(raw, str) or not raw:
            self.err(key, f"must be a name (text) such as \"B\"; got {raw!r}")
        return raw

    def link(self, key: str, raw: Json) -> str:
        if isinstance(raw, bool) or not isinstance(raw, (int, str)) or not (str(raw).isdigit() and str(raw).isascii()):
            self.err(key, f"must be a link number (0 = frame, 1 = crank, 2, ...); got {raw!r}")
        return str(int(raw))

    def obj(self, key: str, raw: Json, allowed: Sequence[str]) -> Mapping[str, Json]:
        if not isinstance(raw, Mapping):
            self.err(key, f"must be an object {{...}}; got {raw!r}")
        bad = [k for k in raw if k not in allowed]
        if bad:
            self.err(f"{key}.{bad[0]}", f"unknown key; the keys are: {', '.join(allowed)}")
        return raw

    def xy(self, key: str, raw: Json) -> tuple[float, float]:
        if not isinstance(raw, (list, tuple)) or len(raw) != 2:
            self.err(key, f"must be [x, y] in m; got {raw!r}")
        return self.number(f"{key}[0]", raw[0]), self.number(f"{key}[1]", raw[1])

    def guide(self, key: str, raw: Json) -> Guide:
        g = self.obj(key, raw, ("link", "through", "angle_deg"))
        for k in ("link", "through"):
            if k not in g:
                self.err(f"{key}.{k}", "is missing (a guide needs its link and a point it passes through)")
        link = self.link(f"{key}.link", g["link"])
        th = g["through"]
        through: str | complex = th if isinstance(th, str) else complex(*self.xy(f"{key}.through", th))
        if link != GROUND and not isinstance(th, str):
            self.err(f"{key}.through", "on a moving link give a joint of that link by name")
        ang = math.radians(self.number(f"{key}.angle_deg", g.get("angle_deg", 0.0)))
        return Guide(link, through, ang)


def _group(rd: _Reader, i: int, raw: Json) -> Group:
    key = f"groups[{i}]"
    if not isinstance(raw, Mapping):
        rd.err(key, f"must be an object with a type; got {raw!r}")
    t = raw.get("type")
    if t not in KINDS:
        rd.err(f"{key}.type", f"must be one of {', '.join(KINDS)}; got {t!r}")
    if t == "triad":
        return _triad(rd, key, raw)
    spec = GROUP_KEYS[t]
    rd.obj(key, raw, ("type", "links", *spec))
    links = raw.get("links")
    if not isinstance(links, (list, tuple)) or len(links) != 2:
        rd.err(f"{key}.links", f"must be the two link numbers of the group, e.g. [2, 3]; got {links!r}")
    lk = (rd.link(f"{key}.links[0]", links[0]), rd.link(f"{key}.links[1]", links[1]))
    if GROUND in lk:
        rd.err(f"{key}.links", "the frame (0) is not a link of a group")
    kw: dict[str, Any] = {}     # the group's keyword arguments: names, floats, guides, the branch
    for k, check in spec.items():
        if k not in raw:
            if k in OPTIONAL:
                kw[k] = OPTIONAL[k]
                continue
            rd.err(f"{key}.{k}", f"is missing (a {t} group needs {', '.join(x for x in spec if x not in OPTIONAL)})")
        v = raw[k]
        if check == "str":
            kw[k] = rd.text(f"{key}.{k}", v)
        elif check == "guide":
            kw[k] = rd.guide(f"{key}.{k}", v)
        elif check == "sign":
            if isinstance(v, bool) or v not in (1, -1):
                rd.err(f"{key}.{k}", f"must be 1 or -1 (the assembly branch); got {v!r}")
            kw[k] = int(v)
        else:
            kw[k] = rd.number(f"{key}.{k}", v, check)
    try:
        if t == "RRR":
            return RRR(P=kw["P"], Q=kw["Q"], C=kw["C"], l_PC=kw["l_PC"], l_QC=kw["l_QC"], links=lk, branch=kw["branch"])
        if t in ("RRP", "PRR"):
            return RRP(P=kw["P"], C=kw["C"], l=kw["l"], guide=kw["guide"], links=lk, branch=kw["branch"])
        if t == "RPR":
            return RPR(P=kw["P"], Q=kw["Q"], coincident=kw["point"], e=kw["e"], links=lk, branch=kw["branch"])
        if t == "PRP":
            return PRP(C=kw["C"], guide_1=kw["guide_1"], guide_2=kw["guide_2"], links=lk)
        return RPP(P=kw["P"], R=kw["R"], coincident=kw["point"], guide=kw["guide"],
                   slot_angle=math.radians(kw["slot_angle_deg"]), e=kw["e"], links=lk)
    except InputError as exc:
        rd.err(key, str(exc))


def _triad(rd: _Reader, key: str, raw: Mapping[str, Json]) -> Triad:
    """``{"type": "triad", "links": [t, k1, k2, k3], "outer": [P1, P2, P3], "inner": [B1, B2, B3],
    "drawn": {name: [x, y], ...}}``: a class III group given at its drawn position."""
    rd.obj(key, raw, ("type", "links", "outer", "inner", "drawn"))
    for k in ("links", "outer", "inner", "drawn"):
        if k not in raw:
            rd.err(f"{key}.{k}", "is missing (a triad needs links [t, k1, k2, k3], outer [P1, P2, P3], "
                                 "inner [B1, B2, B3] and the drawn position of those six joints)")
    links = raw["links"]
    if not isinstance(links, (list, tuple)) or len(links) != 4:
        rd.err(f"{key}.links", f"must be the four link numbers [t, k1, k2, k3] (t the basic link); got {links!r}")
    lk = tuple(rd.link(f"{key}.links[{i}]", x) for i, x in enumerate(links))
    if GROUND in lk:
        rd.err(f"{key}.links", "the frame (0) is not a link of a group")
    names: dict[str, tuple[str, ...]] = {}
    for k in ("outer", "inner"):
        v = raw[k]
        if not isinstance(v, (list, tuple)) or len(v) != 3:
            rd.err(f"{key}.{k}", f"must be three joint names; got {v!r}")
        names[k] = tuple(rd.text(f"{key}.{k}[{i}]", x) for i, x in enumerate(v))
    drawn_raw = rd.obj(f"{key}.drawn", raw["drawn"], (*names["outer"], *names["inner"]))
    drawn = []
    for k in (*names["outer"], *names["inner"]):
        if k not in drawn_raw:
            rd.err(f"{key}.drawn.{k}", "is missing: [x, y] of the joint at the drawn position, m")
        x, y = rd.xy(f"{key}.drawn.{k}", drawn_raw[k])
        drawn.append((k, complex(x, y)))
    try:
        return Triad(outer=names["outer"], inner=names["inner"], drawn=tuple(drawn), links=lk)  # type: ignore[arg-type]
    except InputError as exc:
        rd.err(key, str(exc))


def build_linkage(data: Mapping[str, Json], *, source: str = "<dict>",
                  swing: tuple[float, float] | None = None) -> Linkage:
    """The :class:`Linkage` of a ``"kind": "linkage"`` problem (only its kinematic keys are read)."""
    rd = _Reader(source)
    raw_fixed = data.get("fixed")
    fixed = rd.obj("fixed", raw_fixed, tuple(raw_fixed) if isinstance(raw_fixed, Mapping) else ()) if "fixed" in data \
        else rd.err("fixed", "is missing (the fixed joints, e.g. {\"O1\": [0, 0]})")
    ground = {rd.text("fixed", k): rd.xy(f"fixed.{k}", v) for k, v in fixed.items()}
    if not ground:
        rd.err("fixed", "give at least the crank's centre")
    if "crank" not in data:
        rd.err("crank", "is missing ({\"centre\": \"O1\", \"pin\": \"A\", \"r\": 0.1})")
    c = rd.obj("crank", data["crank"], ("centre", "pin", "r"))
    for k in ("centre", "pin", "r"):
        if k not in c:
            rd.err(f"crank.{k}", "is missing")
    crank = Crank(rd.text("crank.centre", c["centre"]), rd.text("crank.pin", c["pin"]),
                  rd.number("crank.r", c["r"], "positive"))
    sense = data.get("sense", "ccw")
    if sense not in ("ccw", "cw"):
        rd.err("sense", f'must be "ccw" or "cw"; got {sense!r}')
    groups_raw = data.get("groups", [])
    if not isinstance(groups_raw, list) or not groups_raw:
        rd.err("groups", "must be a list of Assur groups in solving order, e.g. [{\"type\": \"RRR\", ...}]")
    if len(groups_raw) > MAX_GROUPS:              # refused before any group is read
        rd.err("groups", f"{len(groups_raw)} groups; at most {MAX_GROUPS} are accepted (MAX_GROUPS)")
    groups = [_group(rd, i, g) for i, g in enumerate(groups_raw)]
    points: list[Point] = []
    pts = data.get("points", {})
    if not isinstance(pts, Mapping):
        rd.err("points", f"must be an object name -> {{link, from, distance, angle_deg}}; got {pts!r}")
    for name, p in pts.items():
        key = f"points.{name}"
        p = rd.obj(key, p, ("link", "from", "distance", "angle_deg"))
        for k in ("link", "from", "distance"):
            if k not in p:
                rd.err(f"{key}.{k}", "is missing")
        points.append(Point(name, rd.link(f"{key}.link", p["link"]), rd.text(f"{key}.from", p["from"]),
                            rd.number(f"{key}.distance", p["distance"], "nonneg"),
                            math.radians(rd.number(f"{key}.angle_deg", p.get("angle_deg", 0.0)))))
    output = data.get("output")
    if output is not None and (isinstance(output, bool) or not isinstance(output, (str, int))):
        rd.err("output", f"must be a slider point (\"D\") or a link number (3); got {output!r}")
    ws = data.get("working_stroke", "slow")
    title = data.get("name")
    name = str(Title.of(title, where=f"{source}: key 'name'")) if title is not None else "linkage"
    try:
        return Linkage(ground=ground, crank=crank, groups=groups, points=points, sense=1 if sense == "ccw" else -1,
                       output=None if output is None else str(output), working_stroke=ws, name=name or "linkage",
                       swing=swing)
    except AssemblyError as exc:
        raise AssemblyError(f"{source}: {exc}") from None
    except InputError as exc:
        raise InputError(f"{source}: {exc}") from None


def linkage_case(data: Mapping[str, Json], *, source: str = "<dict>", drawn: Any = None) -> LinkageCase:
    """Validate a ``"kind": "linkage"`` problem and build its :class:`~graphmethods.kinematics.case.Case`.

    A file in the drawn form (it has ``joints``) is compiled first
    (:func:`graphmethods.kinematics.drawn.drawn_case`); ``drawn`` is what that compiler adds to the group
    form (then the speed, [δ] and the working load may be missing: a command that needs them says so).
    """
    if drawn is None and "joints" in data:
        from graphmethods.kinematics.drawn import drawn_case

        return drawn_case(data, source=source)
    rd = _Reader(source)
    unknown = [k for k in data if k not in TOP_KEYS]
    if unknown:
        rd.err(unknown[0], f"unknown key for kind 'linkage'; the keys are: {', '.join(TOP_KEYS)}")
    lk = build_linkage(data, source=source, swing=None if drawn is None else drawn.swing)
    mech = LinkageMechanism(lk, kind=lk.name)
    try:
        lk.check_full_turn()
    except AssemblyError as exc:
        raise AssemblyError(f"{source}: {exc}") from None
    known = set(lk.solve([0.0 if drawn is None else drawn.phi_0], level=0).z)
    inertias: list[Inertia] = []
    masses = data.get("masses", {})
    if not isinstance(masses, Mapping):
        rd.err("masses", "must be an object: link number -> {m, J, at}")
    for k, spec in masses.items():
        key = f"masses.{k}"
        link = rd.link(key, k)
        if link not in lk.links:
            rd.err(key, f"no moving link {link}; links: {', '.join(lk.links)}")
        spec = rd.obj(key, spec, ("m", "J", "at"))
        m = rd.number(f"{key}.m", spec.get("m", 0.0), "nonneg")
        J = rd.number(f"{key}.J", spec.get("J", 0.0), "nonneg")
        at = spec.get("at", lk.crank.centre if link == lk.crank.link else None)
        if at is None:
            rd.err(f"{key}.at", "is missing: the point the mass sits at (its centre of mass, e.g. \"S2\")")
        if rd.text(f"{key}.at", at) not in known:
            rd.err(f"{key}.at", f"no point {at!r}; points: {', '.join(sorted(known))}")
        inertias.append(Inertia(link, at, m, J))
    if drawn is not None:
        return _drawn_tail(rd, data, lk, mech, tuple(inertias), drawn)
    if "load" not in data:
        rd.err("load", "is missing: {\"force\": N, \"on\": \"D\", \"from\": 0, \"to\": 1} or "
                       "{\"moment\": ..., \"on\": 3, ...}")
    ld = rd.obj("load", data["load"], ("force", "moment", "diagram", "on", "from", "to"))
    load: Load | DiagramLoad
    if "diagram" in ld:
        load = _diagram_load(rd, ld, lk)
    else:
        load = _step_load(rd, ld, lk)
    n_rpm = rd.number("n_rpm", data["n_rpm"] if "n_rpm" in data else rd.err("n_rpm", "is missing (rev/min)"),
                      "positive")
    delta = rd.number("delta", data["delta"] if "delta" in data else rd.err("delta", "is missing ([δ])"), "delta")
    title = Title.of(data.get("name"), where=f"{source}: key 'name'")
    values = {k: data[k] for k in data}
    return LinkageCase(kind="linkage", title=title, about=data.get("about", ""), source=source, mechanism=mech,
                       n_rpm=n_rpm, delta=delta, inertias=tuple(inertias), load=load,
                       values=MappingProxyType(values))


def _drawn_tail(rd: _Reader, data: Mapping[str, Json], lk: Linkage, mech: LinkageMechanism,
                inertias: tuple[Inertia, ...], drawn: Any) -> LinkageCase:
    """The case of a drawn file: the speed, [δ] and the working load only if the file gives them."""
    from graphmethods.kinematics.drawn import DrawnCase

    load: Load | DiagramLoad | None = None
    if "load" in data:
        ld = rd.obj("load", data["load"], ("force", "moment", "diagram", "on", "from", "to"))
        load = _diagram_load(rd, ld, lk) if "diagram" in ld else _step_load(rd, ld, lk)
    n_rpm = rd.number("n_rpm", data["n_rpm"], "positive") if "n_rpm" in data else 0.0
    delta = rd.number("delta", data["delta"], "delta") if "delta" in data else 0.0
    title = Title.of(data.get("name"), where=f"{rd.source}: key 'name'")
    case = DrawnCase(kind="linkage", title=title, about=data.get("about", ""), source=rd.source, mechanism=mech,
                     n_rpm=n_rpm, delta=delta, inertias=inertias, load=load,   # type: ignore[arg-type]
                     values=MappingProxyType(dict(data)), drawn=drawn)
    for key, given in (("n_rpm", "n_rpm" in data), ("delta", "delta" in data), ("load", load is not None)):
        if not given:
            object.__delattr__(case, key)     # asked for, it names every key missing (DrawnCase.__getattr__)
    return case


def _diagram_load(rd: _Reader, ld: Mapping[str, Json], lk: Linkage) -> DiagramLoad:
    """``{"diagram": [{"stroke": "working", "s": [...], "F": [...], "drives": true}, ...], "on": "B"}``; a part
    may give the indicator diagram's gauge pressure ``"p"`` (Pa) and the bore ``"bore"`` (m) instead of F."""
    if any(k in ld for k in ("force", "moment", "from", "to")):
        rd.err("load", "a diagram load gives its forces in \"diagram\" only (no force, moment, from, to)")
    if lk.output is None or lk.output[0] != "point" or lk.strokes() is None:
        rd.err("load.diagram", "a force diagram acts on the output slider; this linkage's output is not a slider")
    on = str(ld.get("on", lk.output[1]))
    if on != lk.output[1]:
        rd.err("load.on", f"the diagram acts on the output slider {lk.output[1]!r}; got {on!r} (set \"output\")")
    parts = ld["diagram"]
    if not isinstance(parts, list) or not parts:
        rd.err("load.diagram", "must be a list of strokes: [{\"stroke\": \"working\", \"s\": [...], \"F\": [...], "
                               "\"drives\": true}, ...]")
    out: list[tuple[tuple[float, ...], tuple[float, ...], str, bool]] = []
    for i, p in enumerate(parts):
        key = f"load.diagram[{i}]"
        p = rd.obj(key, p, ("stroke", "s", "F", "p", "bore", "drives"))
        stroke = p.get("stroke", "working")
        if stroke not in ("working", "return"):
            rd.err(f"{key}.stroke", f'must be "working" or "return"; got {stroke!r}')
        drives = p.get("drives", False)
        if not isinstance(drives, bool):
            rd.err(f"{key}.drives", f"must be true (the force drives the slider) or false (it resists); got {drives!r}")
        if ("F" in p) == ("p" in p):
            rd.err(key, "give the force F (N) or the indicator diagram's gauge pressure p (Pa, with the bore in m), "
                        "one of them")
        area = 1.0
        if "p" in p:             # an indicator diagram: pressure against the stroke, F = p·πD²/4
            if "bore" not in p:
                rd.err(f"{key}.bore", "is missing: the cylinder's bore D (m) turns the pressure p into F = p·πD²/4")
            area = math.pi * rd.number(f"{key}.bore", p["bore"], "positive") ** 2 / 4.0
        elif "bore" in p:
            rd.err(f"{key}.bore", "goes with a pressure p (Pa); with a force F leave it out")
        fk = "p" if "p" in p else "F"
        xs, Fs = p.get("s"), p.get(fk)
        if not isinstance(xs, list) or not isinstance(Fs, list) or len(xs) != len(Fs) or len(xs) < 2:
            rd.err(f"{key}.s", f"s and {fk} must be lists of the same length, two points or more")
        x = tuple(rd.number(f"{key}.s[{j}]", v, "fraction") for j, v in enumerate(xs))
        F = tuple(area * rd.number(f"{key}.{fk}[{j}]", v, "nonneg") for j, v in enumerate(Fs))
        if any(b < a for a, b in zip(x, x[1:])):
            rd.err(f"{key}.s", "the stroke fractions must not decrease (repeat one for a jump)")
        out.append((x, F, stroke, drives))
    return DiagramLoad(on, tuple(out))


def _step_load(rd: _Reader, ld: Mapping[str, Json], lk: Linkage) -> Load:
    """``{"force": N, "on": "D", "from": 0.05, "to": 0.95}`` or ``{"moment": N·m, "on": 3, ...}``."""
    kind = "force" if "force" in ld else "moment" if "moment" in ld else None
    if kind is None or ("force" in ld and "moment" in ld):
        rd.err("load", "give exactly one of force (N, on the output slider) or moment (N·m, on the output rocker)")
    mag = rd.number(f"load.{kind}", ld[kind], "nonneg")
    start = rd.number("load.from", ld.get("from", 0.0), "fraction")
    end = rd.number("load.to", ld.get("to", 1.0), "fraction")
    if not start < end:
        rd.err("load.from", f"must be less than load.to ({start:g} ≥ {end:g})")
    if lk.output is None or lk.strokes() is None:
        rd.err("load", "this linkage's output has no working stroke (it turns fully); name a slider or rocker "
                       "as \"output\"")
    on = ld.get("on", lk.output[1])
    on = str(on)
    if kind == "force" and (lk.output[0] != "point" or on != lk.output[1]):
        rd.err("load.on", f"a force acts on the output slider {lk.output[1]!r}; got {on!r} (set \"output\")")
    if kind == "moment" and (lk.output[0] != "link" or on != lk.output[1]):
        rd.err("load.on", f"a moment acts on the output rocker (link {lk.output[1]}); got {on!r} (set \"output\")")
    return Load(kind, on, mag, start, end)


class LinkageCase(Case):
    """A problem file of any linkage (``"kind": "linkage"``)."""

    @property
    def linkage(self) -> Linkage:
        """The problem's linkage."""
        return self.mechanism.linkage
