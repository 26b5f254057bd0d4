"""A mechanism as it is drawn: joints at one position, links, slides, the driver; compiled into Assur groups.

The drawn form of a ``"kind": "linkage"`` problem file (``shared/cases/README.md``, "A mechanism as
it is drawn") says what a textbook's figure shows and nothing the reader must work out:

====================  ====================================================================
key                   meaning
====================  ====================================================================
``joints``            every joint and named point in the drawn position: ``{"A": [x, y]}``, m
``links``             by textbook number, ``"0"`` the frame: the joints on each link; a joint on two
                      links is a revolute pair between them; a link's angle is the direction from its
                      first listed joint to its second
``slides``            prismatic pairs ``{"block": 2, "on": 3, "at": "A", "angle_deg": 90}``: link
                      ``block`` slides on link ``on`` along the line through ``at`` (a joint of the
                      block) at ``angle_deg`` from +x in the drawn position, fixed in ``on``
``driver``            ``{"link": 1, "about": "O"}``; ``"range_deg": [a, b]`` for a driver that swings
``omega_1``           driver speed, rad/s, counterclockwise + (or ``n_rpm`` with ``sense``)
``loads``             ``{"force": [Fx, Fy], "link": 3, "at": "B" or [x, y]}`` (N) or
                      ``{"moment": M, "link": 3}`` (N·m, counterclockwise +), constant
``masses``            ``{"2": {"m": kg, "J": kg·m² about at, "at": "S2" or [x, y]}}``
``load``, ``output``, ``working_stroke``, ``delta``, ``name``, ``about``, ``units``: as in the group form
====================  ====================================================================

The program finds the structure (:mod:`graphmethods.kinematics.structure`), takes each group's
lengths and assembly branch from the drawing, and writes the group form the core solves
(:func:`compile_drawn`); the drawn position is then solved again and must give back every drawn
joint (never a silent mirror). A file holds what its command needs: the geometry and the driver
for ``kinematics``; a command that needs the speed, [δ] or the working load names every one missing.

>>> case = drawn_case({"kind": "linkage", "joints": {"O": [0, 0], "A": [0.1, 0], "B": [0.5, 0]},
...     "links": {"0": ["O"], "1": ["O", "A"], "2": ["A", "B"], "3": ["B"]},
...     "slides": [{"block": 3, "on": 0, "at": "B", "angle_deg": 0}],
...     "driver": {"link": 1, "about": "O"}, "omega_1": 10})
>>> case.drawn.structure.formula, case.linkage.groups[0].kind
('I(0,1) → II(2,3)', 'RRP')
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from graphmethods.errors import AssemblyError, InputError
from graphmethods.kinematics.groups import KINDS
from graphmethods.kinematics.groups.base import State
from graphmethods.kinematics.linkage_file import TOP_KEYS, LinkageCase, _group, _Reader, linkage_case
from graphmethods.kinematics.structure import Decomposition, FoundGroup, Slide, StructureError, decompose

DRAWN_KEYS = ("kind", "name", "about", "units", "joints", "links", "slides", "driver", "omega_1", "n_rpm", "sense",
              "loads", "masses", "load", "output", "working_stroke", "delta")

#: hidden points (a guide's point on a moving link, a load or mass given by coordinates) start with this
HIDDEN = "_"


@dataclass(frozen=True)
class DrawnLoad:
    """A constant external load of the drawn form: a force ``F`` (N, x + iy) at the point ``at`` of
    ``link``, or a moment ``M`` (N·m, counterclockwise +) on it (``at`` then names a point of the link)."""

    link: str
    at: str
    F: complex
    M: float
    kind: str


@dataclass(frozen=True)
class DrawnSlide:
    """A prismatic pair for the output: ``block`` on ``on`` at ``at``; ``turn`` the direction of the
    slide relative to the core's direction of ``on`` (``None`` for the frame: ``angle`` absolute, rad);
    ``ref`` a point of ``on`` (None for the frame)."""

    block: str
    on: str
    at: str
    angle: float
    turn: complex | None
    ref: str | None


@dataclass(frozen=True)
class DrawnInfo:
    """What the drawn form adds to the group form (see the module docstring).

    Attributes
    ----------
    structure : Decomposition
    phi_0 : float
        The driver's angle in the drawing, rad.
    swing : (float, float) or None
        The driver's range, rad (None: a full turn); ``swing_deg`` as the file gives it, degrees.
    angle_offset : mapping link -> float
        The file's angle of a link minus the core's direction of it, rad (constant).
    slides : tuple of DrawnSlide
    loads : tuple of DrawnLoad
    missing : tuple of str
        Keys a command may need that the file does not give (``omega_1 or n_rpm``, ``delta``, ``load``).
    group_form : mapping
        The compiled group form (what :func:`~graphmethods.kinematics.linkage_file.linkage_case` reads).
    """

    structure: Decomposition
    phi_0: float
    swing: tuple[float, float] | None
    swing_deg: tuple[float, float] | None
    angle_offset: Mapping[str, float]
    slides: tuple[DrawnSlide, ...]
    loads: tuple[DrawnLoad, ...]
    missing: tuple[str, ...]
    group_form: Mapping[str, Any] = field(repr=False)


@dataclass(frozen=True)
class DrawnCase(LinkageCase):
    """A problem file in the drawn form: a :class:`LinkageCase` with :attr:`drawn`. A key the file
    leaves out (the speed, [δ], the working load) is refused, naming every one missing, by the
    command that asks for it."""

    drawn: DrawnInfo | None = None

    def __getattr__(self, key: str) -> Any:
        info = self.__dict__.get("drawn")
        if info is not None and key in ("n_rpm", "delta", "load") and key not in self.__dict__:
            need = [m for m in info.missing if key != "n_rpm" or m.startswith("omega_1")]
            raise InputError(f"{self.__dict__.get('source')}: this command needs {', '.join(need)}, missing from "
                             f"the file")
        return super().__getattr__(key)


def require_cycle(case: Any, command: str, *, speed_given: bool = False) -> None:
    """Refuse a drawn file for a command that studies the steady cycle (the study, the motion): every key it
    needs and the file leaves out, in one line (the speed not, when the command line gives it); or a driver
    that swings instead of turning fully."""
    info = getattr(case, "drawn", None)
    if info is None:
        return
    missing = [k for k in info.missing if not (speed_given and k.startswith("omega_1"))]
    if missing:
        raise InputError(f"{case.source}: {command} needs {', '.join(missing)}, missing from the file")
    if info.swing is not None:
        a, b = (math.degrees(x) for x in info.swing)
        raise InputError(f"{case.source}: {command} follows the crank over whole turns; this driver swings over "
                         f"range_deg [{a:g}, {b:g}] (kinematics and forces take it)")


def is_drawn(data: Mapping[str, Any]) -> bool:
    """Is this ``"kind": "linkage"`` file in the drawn form (it has ``joints``)?"""
    return "joints" in data


class _Compiler:
    """The drawn form into the group form, group by group at the drawn position."""

    def __init__(self, data: Mapping[str, Any], source: str) -> None:
        self.rd = _Reader(source)
        self.source = source
        self.data = data
        self.z: dict[str, complex] = {}
        self.links: dict[str, tuple[str, ...]] = {}
        self.slides: list[Slide] = []
        self.points: dict[str, dict[str, Any]] = {}
        self.carrier: dict[str, str | None] = {}
        self.wanted: dict[str, list[tuple[str, complex]]] = {}     # hidden points to place, per link
        self.st = State(phi=np.zeros(1))

    # ------------------------------------------------------------------ reading
    def read(self) -> None:
        rd, d = self.rd, self.data
        raw = rd.obj("joints", d["joints"], tuple(d["joints"]) if isinstance(d["joints"], Mapping) else ())
        for name, xy in raw.items():
            if not name or name.startswith(HIDDEN):
                rd.err(f"joints.{name}", f"a joint's name must not be empty or start with {HIDDEN!r}")
            x, y = rd.xy(f"joints.{name}", xy)
            self.z[name] = complex(x, y)
        if not self.z:
            rd.err("joints", "give the joints in the drawn position, e.g. {\"O\": [0, 0], \"A\": [0.1, 0]}")
        lk = d.get("links")
        if not isinstance(lk, Mapping) or not lk:
            rd.err("links", "is missing: the links by number, \"0\" the frame, each a list of its joints")
        for k, js in lk.items():
            num = rd.link(f"links.{k}", k)
            if not isinstance(js, list) or not all(isinstance(j, str) for j in js):
                rd.err(f"links.{k}", f"must be a list of joint names; got {js!r}")
            bad = [j for j in js if j not in self.z]
            if bad:
                rd.err(f"links.{k}", f"joint {bad[0]!r} is not in joints")
            if len(set(js)) != len(js):
                rd.err(f"links.{k}", "a joint is listed twice")
            self.links[num] = tuple(js)
        if "0" not in self.links:
            rd.err("links", "the frame \"0\" is missing: list its fixed joints, e.g. \"0\": [\"O\"]")
        on_any = {j for js in self.links.values() for j in js}
        loose = [j for j in self.z if j not in on_any]
        if loose:
            rd.err(f"joints.{loose[0]}", "is on no link; list it on the link that carries it")
        for i, s in enumerate(d.get("slides", []) if isinstance(d.get("slides", []), list) else rd.err(
                "slides", "must be a list of {block, on, at, angle_deg}")):
            key = f"slides[{i}]"
            s = rd.obj(key, s, ("block", "on", "at", "angle_deg"))
            for k in ("block", "on", "at", "angle_deg"):
                if k not in s:
                    rd.err(f"{key}.{k}", "is missing (a slide is {block, on, at, angle_deg})")
            block, on = rd.link(f"{key}.block", s["block"]), rd.link(f"{key}.on", s["on"])
            for k, v in (("block", block), ("on", on)):
                if v not in self.links:
                    rd.err(f"{key}.{k}", f"no link {v} in links")
            if block == on:
                rd.err(key, "a link cannot slide on itself")
            at = rd.text(f"{key}.at", s["at"])
            if at not in self.links[block]:
                rd.err(f"{key}.at", f"{at!r} is not a joint of the block, link {block}")
            if at in self.links[on]:
                rd.err(f"{key}.at", f"{at!r} is listed on both link {block} and link {on}, which slide on each other: "
                                    f"a joint on both pins them; list it on the block only")
            ang = math.radians(rd.number(f"{key}.angle_deg", s["angle_deg"]))
            self.slides.append(Slide(block, on, at, ang))

    def driver(self) -> tuple[str, str, tuple[float, float] | None]:
        """(driver link, its pivot, its range in degrees or None)."""
        rd = self.rd
        if "driver" not in self.data:
            rd.err("driver", "is missing: {\"link\": 1, \"about\": \"O\"} (and \"range_deg\": [a, b] if it swings)")
        dv = rd.obj("driver", self.data["driver"], ("link", "about", "range_deg"))
        for k in ("link", "about"):
            if k not in dv:
                rd.err(f"driver.{k}", "is missing")
        link = rd.link("driver.link", dv["link"])
        about = rd.text("driver.about", dv["about"])
        if link == "0" or link not in self.links:
            rd.err("driver.link", f"no moving link {link} in links")
        if about not in self.links[link] or about not in self.links["0"]:
            rd.err("driver.about", f"{about!r} must be a joint of the frame and of link {link}")
        swing = None
        if "range_deg" in dv:
            r = dv["range_deg"]
            if not isinstance(r, list) or len(r) != 2:
                rd.err("driver.range_deg", f"must be [a, b] in degrees; got {r!r}")
            a, b = (rd.number(f"driver.range_deg[{i}]", r[i]) for i in (0, 1))
            if not a < b <= a + 360.0:
                rd.err("driver.range_deg", f"must be [a, b] with a < b ≤ a + 360; got {r!r}")
            swing = (a, b)
        return link, about, swing

    def speed(self, out: dict[str, Any], missing: list[str]) -> None:
        rd, d = self.rd, self.data
        if "omega_1" in d and "n_rpm" in d:
            rd.err("omega_1", "give the driver's speed once: omega_1 (rad/s, counterclockwise +) or n_rpm with sense")
        if "omega_1" in d:
            w = rd.number("omega_1", d["omega_1"])
            if w == 0:
                rd.err("omega_1", "must not be 0 (rad/s, counterclockwise +)")
            if "sense" in d and d["sense"] != ("ccw" if w > 0 else "cw"):
                rd.err("sense", f"omega_1 = {w:g} rad/s carries its sense by its sign (counterclockwise +); "
                                f"sense {d['sense']!r} contradicts it: leave sense out")
            out["n_rpm"] = abs(w) * 30.0 / math.pi
            out["sense"] = "ccw" if w > 0 else "cw"
        elif "n_rpm" in d:
            out["n_rpm"] = d["n_rpm"]
            out["sense"] = d.get("sense", "ccw")
        else:
            out["sense"] = d.get("sense", "ccw")
            missing.append("omega_1 or n_rpm")

    # ------------------------------------------------------------------ the drawn position
    def angle_of(self, link: str) -> float | None:
        """The file's angle of a link in the drawing: first listed joint to second; else its slide's."""
        js = self.links[link]
        if len(js) >= 2 and self.z[js[1]] != self.z[js[0]]:
            return cmath.phase(self.z[js[1]] - self.z[js[0]])
        for s in self.slides:
            if link in (s.block, s.on):
                return s.angle
        return None

    def known_point(self, link: str) -> str:
        """A point of ``link`` already placed (the origin for its extra points)."""
        for j in self.links[link]:
            if j in self.st.z:
                return j
        for name, p in self.points.items():
            if p["link"] == int(link):
                return name
        raise AssertionError(f"link {link} has no placed point")          # pragma: no cover - by construction

    def extra_point(self, name: str, link: str, z: complex) -> None:
        """An extra point of the group form: on ``link`` at ``z`` in the drawing (from a placed point)."""
        origin = self.known_point(link)
        e = self.e_of(link)
        off = (z - complex(self.st.z[origin][0])) / e
        self.points[name] = {"link": int(link), "from": origin, "distance": abs(off),
                             "angle_deg": math.degrees(cmath.phase(off)) if off != 0 else 0.0}
        self.st.z[name] = np.array([z])
        self.carrier[name] = link

    def e_of(self, link: str) -> complex:
        """The core's direction of a placed link in the drawing (1 for the frame)."""
        return 1 + 0j if link == "0" else complex(np.asarray(self.st.e[link]).reshape(-1)[0])

    def place(self, link: str) -> None:
        """The joints of a link just found that no group found: its extra points (and the hidden ones)."""
        for j in self.links[link]:
            if j not in self.st.z:
                self.extra_point(j, link, self.z[j])
        for name, z in self.wanted.pop(link, []):
            self.extra_point(name, link, z)

    def attach(self, joint: str, link: str) -> str:
        """The point a group is pinned at on the known ``link``: the joint, or one at distance 0 on that link
        when another link carries the joint (a compound hinge)."""
        if self.carrier.get(joint) == link or link == "0":
            return joint
        name = f"{HIDDEN}{joint}{link}"
        if name not in self.st.z:
            self.extra_point(name, link, self.z[joint])
        return name

    def guide(self, link: str, at: complex, angle: float) -> dict[str, Any]:
        """A guide of the group form along ``angle`` (absolute, drawn) through ``at``, fixed in ``link``."""
        if link == "0":
            return {"link": 0, "through": [at.real, at.imag], "angle_deg": math.degrees(angle)}
        name = f"{HIDDEN}g{len(self.points)}"
        self.extra_point(name, link, at)
        th = cmath.phase(self.e_of(link))
        return {"link": int(link), "through": name, "angle_deg": math.degrees(angle - th)}

    def fresh(self, name: str) -> str:
        while name in self.z or name in self.st.z:
            name = HIDDEN + name
        return name

    # ------------------------------------------------------------------ groups
    def group(self, fg: FoundGroup) -> dict[str, Any]:
        z = self.z
        a, b = fg.links[0], fg.links[-1]
        links = [int(k) for k in fg.links]

        def joint(c: tuple[str, Any, str]) -> str:
            return self.attach(str(c[1]), c[2])

        def toggle(what: str) -> None:
            raise StructureError(f"{self.source}: group {fg.label} is drawn at a toggle ({what}): its assembly "
                                 f"branch cannot be told; draw the mechanism in another position")

        if fg.kind == "RRR":
            P, Q, C = joint(fg.outer[0]), joint(fg.outer[1]), str(fg.inner[0][1])
            zp, zq, zc = z[str(fg.outer[0][1])], z[str(fg.outer[1][1])], z[C]
            cr = ((zq - zp).conjugate() * (zc - zp)).imag
            if cr == 0:
                toggle(f"{P}, {Q} and {C} in line")
            return {"type": "RRR", "links": links, "P": P, "Q": Q, "C": C, "l_PC": abs(zc - zp),
                    "l_QC": abs(zc - zq), "branch": 1 if cr > 0 else -1}
        if fg.kind == "RRP":
            P, C = joint(fg.outer[0]), str(fg.inner[0][1])
            s = self.slides[int(fg.outer[1][1])]
            zp, zc = z[str(fg.outer[0][1])], z[C]
            u = cmath.exp(1j * s.angle)
            dt = ((zc - zp) * u.conjugate()).real
            if dt == 0:
                toggle(f"{P}{C} perpendicular to the slide")
            return {"type": "RRP", "links": links, "P": P, "C": C, "l": abs(zc - zp),
                    "guide": self.guide(fg.outer[1][2], zc, s.angle), "branch": 1 if dt > 0 else -1}
        if fg.kind == "RPR":
            s = self.slides[int(fg.inner[0][1])]
            blk, slot = (a, b) if s.block in (a, b) and s.block == a else (b, a)
            oc = {a: fg.outer[0], b: fg.outer[1]}
            P, Q = joint(oc[blk]), joint(oc[slot])
            zp, zq = z[str(oc[blk][1])], z[str(oc[slot][1])]
            w = (zp - zq) * cmath.exp(-1j * s.angle)
            if w.real == 0:
                toggle(f"the slide perpendicular to {Q}{P}")
            return {"type": "RPR", "links": [int(blk), int(slot)], "P": P, "Q": Q,
                    "point": self.fresh(f"{oc[blk][1]}{slot}"), "e": w.imag, "branch": 1 if w.real > 0 else -1}
        if fg.kind == "PRP":
            C = str(fg.inner[0][1])
            s1, s2 = self.slides[int(fg.outer[0][1])], self.slides[int(fg.outer[1][1])]
            return {"type": "PRP", "links": links, "C": C, "guide_1": self.guide(fg.outer[0][2], z[C], s1.angle),
                    "guide_2": self.guide(fg.outer[1][2], z[C], s2.angle)}
        if fg.kind == "RPP":
            P = joint(fg.outer[0])
            zp = z[str(fg.outer[0][1])]
            s_in, s_out = self.slides[int(fg.inner[0][1])], self.slides[int(fg.outer[1][1])]
            own = [j for j in self.links[b] if j not in self.st.z]
            R = own[0] if own else self.fresh(f"{HIDDEN}R{b}")
            zr = z[R] if own else zp
            return {"type": "RPP", "links": links, "P": P, "R": R, "point": self.fresh(f"{fg.outer[0][1]}{b}"),
                    "guide": self.guide(fg.outer[1][2], zr, s_out.angle),
                    "slot_angle_deg": math.degrees(s_in.angle - s_out.angle),
                    "e": ((zp - zr) * cmath.exp(-1j * s_in.angle)).imag}
        # a triad (class III): revolute pairs only
        if any(c[0] != "R" for c in (*fg.outer, *fg.inner)):
            raise StructureError(f"{self.source}: the class III group {fg.label} has a prismatic pair; the program "
                                 f"solves triads of revolute pairs only")
        outer = [joint(c) for c in fg.outer]
        inner = [str(c[1]) for c in fg.inner]
        drawn = {p: [z[str(c[1])].real, z[str(c[1])].imag] for p, c in zip(outer, fg.outer)}
        drawn.update({p: [z[p].real, z[p].imag] for p in inner})
        return {"type": "triad", "links": links, "outer": outer, "inner": inner, "drawn": drawn}

    def solve_group(self, i: int, fg: FoundGroup, spec: dict[str, Any]) -> None:
        """Assemble the group at the drawn position and check it gives back the drawn joints."""
        if spec["type"] not in KINDS:
            raise StructureError(f"{self.source}: the class III group {fg.label} (base link {fg.links[0]}, links "
                                 f"{', '.join(fg.links[1:])}) is found, but this build has no class III solver yet")
        g = _group(self.rd, i, spec)
        if spec["type"] == "triad":        # solved from its track by the linkage; here it stands as drawn
            z = {k: complex(*xy) for k, xy in spec["drawn"].items()}
            B = [z[b] for b in spec["inner"]]
            self.st.e[str(spec["links"][0])] = np.array([(B[1] - B[0]) / abs(B[1] - B[0])])
            for k, p, b in zip(spec["links"][1:], spec["outer"], spec["inner"]):
                self.st.e[str(k)] = np.array([(z[b] - z[p]) / abs(z[b] - z[p])])
                self.st.z[b] = np.array([z[b]])
        else:
            g.positions(self.st)
        found, _ = g.outputs()
        scale = max(1.0, *(abs(v) for v in self.z.values()))
        for p in found:
            if p in self.z:
                got = complex(self.st.z[p][0])
                if not abs(got - self.z[p]) <= 1e-9 * scale:
                    raise StructureError(f"{self.source}: the drawing does not close at group {fg.label}: {p} is drawn "
                                         f"at ({self.z[p].real:.6g}, {self.z[p].imag:.6g}) but its links put it at "
                                         f"({got.real:.6g}, {got.imag:.6g})")
                self.st.z[p] = np.array([self.z[p]])
            self.carrier[p] = None if spec["type"] in ("RRR", "RRP", "PRP", "triad") else str(spec["links"][1])
        for k in fg.links:
            self.place(k)


def _hidden_requests(cp: _Compiler) -> tuple[list[DrawnLoad], dict[str, Any]]:
    """Loads and masses given by coordinates become hidden points on their links; read both."""
    rd, d = cp.rd, cp.data
    loads: list[DrawnLoad] = []
    raw = d.get("loads", [])
    if not isinstance(raw, list):
        rd.err("loads", "must be a list of {force, link, at} or {moment, link}")

    def point(key: str, link: str, at: Any, name: str) -> str:
        """A named point of the link, or one made at [x, y] (the textbook's name: S3 for a mass, L1 a load)."""
        if isinstance(at, str):
            if at not in cp.links[link]:
                rd.err(key, f"{at!r} is not a point of link {link} ({', '.join(cp.links[link])})")
            return at
        x, y = rd.xy(key, at)
        z = complex(x, y)
        same = [j for j in cp.links[link] if cp.z[j] == z]
        if same:
            return same[0]
        taken = {n for ws in cp.wanted.values() for n, _ in ws}
        while name in cp.z or name in taken:
            name += "'"                       # S3 taken by a joint: S3' (as a drawing would)
        cp.wanted.setdefault(link, []).append((name, z))
        return name

    for i, ld in enumerate(raw):
        key = f"loads[{i}]"
        ld = rd.obj(key, ld, ("force", "moment", "link", "at"))
        if "link" not in ld:
            rd.err(f"{key}.link", "is missing: the link the load acts on")
        link = rd.link(f"{key}.link", ld["link"])
        if link == "0" or link not in cp.links:
            rd.err(f"{key}.link", f"no moving link {link} in links")
        if ("force" in ld) == ("moment" in ld):
            rd.err(key, "give a force [Fx, Fy] (N) at a point, or a moment (N·m), one of them")
        if "force" in ld:
            if "at" not in ld:
                rd.err(f"{key}.at", "is missing: the point the force acts at (a point name or [x, y])")
            fx, fy = rd.xy(f"{key}.force", ld["force"])
            loads.append(DrawnLoad(link, point(f"{key}.at", link, ld["at"], f"L{i + 1}"), complex(fx, fy), 0.0,
                                   "force"))
        else:
            if "at" in ld:
                rd.err(f"{key}.at", "a moment acts on the whole link; leave out at")
            at0 = cp.links[link][0] if cp.links[link] else ""
            loads.append(DrawnLoad(link, at0, 0j, rd.number(f"{key}.moment", ld["moment"]), "moment"))
    masses: dict[str, Any] = {}
    raw_m = d.get("masses", {})
    if not isinstance(raw_m, Mapping):
        rd.err("masses", "must be an object: link number -> {m, J, at}")
    for k, spec in raw_m.items():
        link = rd.link(f"masses.{k}", k)
        if link == "0" or link not in cp.links:
            rd.err(f"masses.{k}", f"no moving link {link} in links")
        spec = dict(rd.obj(f"masses.{k}", spec, ("m", "J", "at")))
        if "at" in spec:
            spec["at"] = point(f"masses.{k}.at", link, spec["at"], f"S{link}")
        masses[k] = spec
    return loads, masses


def compile_drawn(data: Mapping[str, Any], *, source: str = "<dict>") -> tuple[dict[str, Any], DrawnInfo]:
    """The group form of a drawn problem file and what the drawn form adds (:class:`DrawnInfo`).

    Raises
    ------
    InputError
        A bad key (named), or a structure refused with its reason (:class:`StructureError`).
    """
    cp = _Compiler(data, source)
    rd = cp.rd
    unknown = [k for k in data if k not in DRAWN_KEYS]
    if unknown:
        rd.err(unknown[0], f"unknown key for a drawn linkage; the keys are: {', '.join(DRAWN_KEYS)}")
    cp.read()
    dlink, about, swing = cp.driver()
    try:
        struct = decompose(cp.links, cp.slides, driver=dlink, about=about)
    except StructureError as exc:
        raise StructureError(f"{source}: {exc}") from None
    loads, masses = _hidden_requests(cp)
    out: dict[str, Any] = {k: data[k] for k in ("kind", "name", "about", "units", "output", "working_stroke", "load",
                                                "delta") if k in data}
    missing: list[str] = []
    cp.speed(out, missing)
    missing += [k for k in ("delta", "load") if k not in data]
    # the frame and the driver
    cp.st.z.update({j: np.array([cp.z[j]]) for j in cp.links["0"]})
    cp.carrier.update(dict.fromkeys(cp.links["0"], "0"))
    out["fixed"] = {j: [cp.z[j].real, cp.z[j].imag] for j in cp.links["0"]}
    phi_0 = cp.angle_of(dlink)
    if phi_0 is None:
        rd.err(f"links.{dlink}", "the driver's angle is undefined: list its pivot and a second joint on it")
    js = cp.links[dlink]
    zO = cp.z[about]
    if js[0] == about and len(js) >= 2:
        pin = js[1]
        r = abs(cp.z[pin] - zO)
    else:                     # the driver's own direction does not start at its pivot: a hidden pin along it
        pin = f"{HIDDEN}{dlink}"
        r = max([abs(cp.z[j] - zO) for j in js] + [0.0]) or 0.1
    out["crank"] = {"centre": about, "pin": pin, "r": r}
    e1 = cmath.exp(1j * phi_0)
    cp.st.z[pin] = np.array([zO + r * e1])
    cp.st.e[dlink] = np.array([e1])
    cp.carrier[pin] = dlink
    if pin in cp.z and abs(cp.st.z[pin][0] - cp.z[pin]) > 1e-12 * max(1.0, r):
        raise StructureError(f"{source}: the driver's pin {pin} is not where its angle puts it")    # pragma: no cover
    cp.place(dlink)
    groups = []
    for i, fg in enumerate(struct.groups):
        spec = cp.group(fg)
        groups.append(spec)
        cp.solve_group(i, fg, spec)
    out["groups"] = groups
    out["points"] = cp.points
    if masses:
        out["masses"] = masses
    offsets = {}
    for k in cp.links:
        if k == "0":
            continue
        core = cmath.phase(cp.e_of(k))
        want = cp.angle_of(k)
        offsets[k] = 0.0 if want is None else want - core
    slides = []
    for s in cp.slides:
        turn = None if s.on == "0" else cmath.exp(1j * (s.angle - cmath.phase(cp.e_of(s.on))))
        ref = None if s.on == "0" else next(
            (p for p in (*cp.links[s.on], *(n for n, q in cp.points.items() if str(q["link"]) == s.on),
                         *(n for n, c in cp.carrier.items() if c == s.on)) if p in cp.st.z), None)
        slides.append(DrawnSlide(s.block, s.on, s.at, s.angle, turn, ref))
    info = DrawnInfo(structure=struct, phi_0=phi_0, swing_deg=swing,
                     swing=None if swing is None else (math.radians(swing[0]), math.radians(swing[1])),
                     angle_offset=MappingProxyType(offsets),
                     slides=tuple(slides), loads=tuple(loads), missing=tuple(missing),
                     group_form=MappingProxyType(out))
    return out, info


def driver_angles_deg(info: DrawnInfo, motion: Any, phi_deg: Any = None) -> np.ndarray:
    """The driver's angles as the file gives them, degrees: a swinging driver's inside its range (the
    angles asked for taken into it, or the range's m equal steps, without a round trip through rad);
    a full turn's in [0, 360)."""
    if info.swing_deg is None:
        src = np.degrees(np.asarray(motion.phi, dtype=float)) if phi_deg is None else np.asarray(phi_deg, float)
        out: np.ndarray = np.mod(src, 360.0)
        return out
    a, b = info.swing_deg
    if phi_deg is not None:                  # the motion has refused an angle outside the range
        x: np.ndarray = a + np.mod(np.asarray(phi_deg, dtype=float) - a, 360.0)
    elif motion.index is not None:
        x = a + (b - a) * (np.asarray(motion.index, dtype=float) / (len(motion.index) - 1))
    else:
        x = np.degrees(np.asarray(motion.phi, dtype=float))
    return x


def link_angles(info: DrawnInfo, motion: Any) -> dict[str, np.ndarray]:
    """Every moving link's angle as the file defines it (first listed joint to second), degrees in
    [0, 360), over the motion's positions."""
    out = {}
    for k, off in info.angle_offset.items():
        a = np.mod(np.degrees(np.asarray(motion.theta[k], dtype=float) + off), 360.0)
        out[k] = np.where(a >= 360.0, 0.0, a) + 0.0
    return out


def slide_kinematics(info: DrawnInfo, motion: Any) -> list[dict[str, Any]]:
    """Per prismatic pair in file order: the block's velocity ``v_rel`` and acceleration ``a_rel`` relative
    to link ``on`` along the slide (m/s, m/s², signed along its direction as ``on`` carries it) and the
    Coriolis acceleration ``a_cor`` = 2·ω_on × v_rel (complex, m/s²), over the motion's positions.

    From the points' own velocities and accelerations: ``v_block = v_on(P) + v_rel``,
    ``a_block = a_on(P) + a_cor + a_rel`` at the slide's point P.
    """
    out = []
    for s in info.slides:
        P, vb, ab = (np.asarray(t[s.at], dtype=complex) for t in (motion.z, motion.v_, motion.a_))
        w: Any
        e: Any
        if s.ref is None:
            u: Any = cmath.exp(1j * s.angle)
            w = e = 0.0
            vk = ak = 0j
        else:
            th = np.asarray(motion.theta[s.on], dtype=float)
            assert s.turn is not None
            u = np.exp(1j * th) * s.turn
            w, e = np.asarray(motion.omega[s.on], dtype=float), np.asarray(motion.epsilon[s.on], dtype=float)
            r = P - np.asarray(motion.z[s.ref], dtype=complex)
            vk = np.asarray(motion.v_[s.ref], dtype=complex) + 1j * w * r
            ak = np.asarray(motion.a_[s.ref], dtype=complex) + (1j * e - w * w) * r
        v_rel = ((vb - vk) * np.conj(u)).real
        a_cor = 2j * w * v_rel * u
        a_rel = ((ab - ak - a_cor) * np.conj(u)).real
        out.append({"block": s.block, "on": s.on, "at": s.at, "v_rel": v_rel, "a_rel": a_rel,
                    "a_cor": np.broadcast_to(a_cor, v_rel.shape)})
    return out


def drawn_case(data: Mapping[str, Any], *, source: str = "<dict>") -> DrawnCase:
    """Read a drawn problem file (see the module docstring) into a :class:`DrawnCase`.

    The drawn position is solved again by the compiled linkage and must give back every drawn
    joint; a driver that swings has its range checked for toggles.
    """
    group_form, info = compile_drawn(data, source=source)
    case = linkage_case(group_form, source=source, drawn=info)
    lk = case.linkage
    st = lk.solve(np.array([info.phi_0]), level=0)
    scale = max(1.0, *(abs(complex(*xy)) for xy in data["joints"].values()))
    for name, xy in data["joints"].items():
        got = complex(st.z[name][0])
        if not abs(got - complex(*xy)) <= 1e-9 * scale:
            raise AssemblyError(f"{source}: the drawing does not close: {name} is drawn at ({xy[0]:.6g}, {xy[1]:.6g}) "
                                f"but the linkage puts it at ({got.real:.6g}, {got.imag:.6g})")
    assert isinstance(case, DrawnCase)
    return case


__all__ = ["DrawnCase", "DrawnInfo", "DrawnLoad", "DrawnSlide", "TOP_KEYS", "compile_drawn", "drawn_case", "is_drawn",
           "driver_angles_deg", "link_angles", "require_cycle", "slide_kinematics"]
