"""The worksheet kind ``cam``: a disc cam with a translating knife-edge or roller follower (in-line or offset)
→ the smallest base radius from the permissible pressure angles (combined ds/dφ–s diagram), the profile by
inversion of motion at a stated μ_l, the displacements s_k at the marked positions and the largest pressure
angles of the rise and of the return.

A variant's student page has the statement, the table of the marked positions k with their cam angles φ_k
(a blank row for s_k in mm), the empty axes of the combined diagram and, at μ_l, the cam centre O with the
offset circle and the follower's axis in position 0 to draw on; its key has the combined diagram with the
tangents at [α] and the admissible zone, the profile by inversion (base circles, the follower turned back
by −φ_k at every position, the pitch points, the pitch curve, the rollers and their envelope), s_k filled
in, and the answers: the designed base radius r_b (and r₀ of the pitch curve for a roller), the largest
pressure angles. ``graphmethods check`` reads the student's profile drawn in CAD (DXF, SVG) or the
answers typed into ``cam-answers.toml`` (:mod:`graphmethods.sheets.check.cam`).

>>> from graphmethods.sheets import worksheets as ws
>>> v = ws.variant("cam", seed=3, number=1)
>>> v.id, v.contact in ("knife", "roller"), len(v.answers()["s_mm"]) == len(v.positions_deg)
('cam:3:1', True, True)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any, ClassVar

import numpy as np

from graphmethods.errors import InputError
from graphmethods.kinematics.cam import CamDesign, CamProblem, cam_from_dict, design
from graphmethods.kinematics.cam.geometry import to_cam_frame
from graphmethods.scene import Axis, Point, Polyline, Scale, Scene, Text, axis_ticks
from graphmethods.scene.elements import Element, Line, make_label
from graphmethods.scene.notation import Notation
from graphmethods.scene.primitives import MAIN, THIN, Style
from graphmethods.sheets.cam_sheet import CENTRES, Circles
from graphmethods.sheets.worksheets.classset import register
from graphmethods.sheets.worksheets.elements import TEXT_MM, X0, X1, wrap
from graphmethods.sheets.worksheets.pages import CAPTION_ROOM, Sheet, answers_and_solution
from graphmethods.sheets.worksheets.variants import Variant, pick, pick_scale
from graphmethods.titles import Title

LAWS = ("parabolic", "harmonic", "cycloidal", "polynomial_345")
CONTACTS = ("knife", "roller")
#: each rise and return is divided into this many equal parts on a worksheet
N_DIV = 6
#: the dash-dot of the follower's axes
AXIS = Style(width_mm=0.18, dash=(8.0, 1.5, 1.0, 1.5))

TITLE = Title.of({"en": "Disc cam: base radius and profile", "ru": "Синтез кулачкового механизма",
                  "zh": "盘形凸轮：基圆半径与廓线"})

STATEMENT = (
    ("A disc cam turning counterclockwise drives a translating {follower} follower{offset}. The follower rises "
     "by h = {h} over {rise} ({rise_law}), dwells over {dwell}, returns over {ret} ({ret_law}){dwell2}. "
     "Permissible pressure angle [α] = {alpha}° on the rise, {alpha_ret}° on the return.",
     "1) On the axes given, draw the combined ds/dφ–s diagram with the tangents at [α]; find the smallest base "
     "radius r_{{0}} of the {pitch}{rb}.",
     "2) Draw the profile by inversion at {mu_l}: turn the follower back by −φ_{{k}} at the positions of the "
     "table, lay off s_{{k}} (write it in mm), draw the {curves}.",
     "3) Find the largest pressure angles of the rise and of the return."),
    ("Дисковый кулачок, вращающийся против часовой стрелки, приводит поступательный {follower} толкатель{offset}. "
     "Толкатель поднимается на h = {h} за {rise} ({rise_law}), выстаивает {dwell}, опускается за {ret} "
     "({ret_law}){dwell2}. Допустимый угол давления [ϑ] = {alpha}° на подъёме, {alpha_ret}° на опускании.",
     "1) На данных осях постройте совмещённую диаграмму dS/dφ–S с касательными под [ϑ]; найдите наименьший "
     "радиус r_{{0}} {pitch}{rb}.",
     "2) Постройте профиль методом обращения движения в масштабе {mu_l}: поверните толкатель на −φ_{{k}} в "
     "положениях таблицы, отложите S_{{k}} (запишите в мм), проведите {curves}.",
     "3) Найдите наибольшие углы давления на подъёме и на опускании."),
    ("逆时针转动的盘形凸轮推动直动{follower}从动件{offset}。从动件在 {rise} 内上升 h = {h}（{rise_law}），"
     "休止 {dwell}，在 {ret} 内返回（{ret_law}）{dwell2}。许用压力角：推程 [α] = {alpha}°，回程 {alpha_ret}°。",
     "1) 在所给坐标轴上作 ds/dφ–s 线图及 [α] 切线，求{pitch}的最小基圆半径 r_{{0}}{rb}。",
     "2) 按 {mu_l} 用反转法作廓线：在表中各位置将从动件反转 −φ_{{k}}，量取 s_{{k}}（以 mm 填写），画出{curves}。",
     "3) 求推程和回程的最大压力角。"),
)

def _say(key: str, nt: Notation, **fill: str) -> str:
    return nt.word("camcheck." + key, **fill)


@dataclass(frozen=True)
class CamVariant(Variant):
    """A disc cam turning counterclockwise with a translating follower: rise, dwell, return, dwell.

    ``contact`` ``"knife"`` or ``"roller"`` (``roller_radius``, m); ``offset`` e ≥ 0 (m, the side that lowers
    the rise's pressure angle); ``lift`` h (m); the phase angles in degrees (the last dwell is what is left of
    360°); the laws of the rise and the return; the permissible pressure angles (degrees); ``n_div`` parts per
    rise and return (the marked positions); ``mu_l`` the profile's scale, m/mm.

    >>> v = CamVariant(seed=0, number=1, contact="roller", offset=0.005, roller_radius=0.005, lift=0.02,
    ...                rise_deg=120.0, dwell_deg=60.0, return_deg=120.0, rise_law="cycloidal",
    ...                return_law="harmonic", alpha_max_deg=30.0, alpha_return_max_deg=70.0, n_div=6, mu_l=0.0005)
    >>> a = v.answers()
    >>> round(a["pitch_base_radius"] - a["base_radius"], 12), a["s_mm"][6]        # h / μ_l at the top
    (0.005, 40.0)
    """

    kind: ClassVar[str] = "cam"
    seed: int
    number: int
    contact: str
    offset: float
    roller_radius: float
    lift: float
    rise_deg: float
    dwell_deg: float
    return_deg: float
    rise_law: str
    return_law: str
    alpha_max_deg: float
    alpha_return_max_deg: float
    n_div: int
    mu_l: float

    def __post_init__(self) -> None:
        if self.contact not in CONTACTS:
            raise InputError(f"contact {self.contact!r}: give one of {', '.join(CONTACTS)}")
        if isinstance(self.n_div, bool) or not isinstance(self.n_div, int) or not 2 <= self.n_div <= 12:
            raise InputError(f"n_div = {self.n_div!r}: give an integer from 2 to 12 (parts of the rise and return)")
        if not (isinstance(self.mu_l, (int, float)) and self.mu_l > 0):
            raise InputError(f"mu_l = {self.mu_l!r}: give the profile's scale, m/mm, > 0")

    @property
    def dwell2_deg(self) -> float:
        """The dwell after the return, degrees (what is left of the turn)."""
        return 360.0 - self.rise_deg - self.dwell_deg - self.return_deg

    def problem_dict(self) -> dict[str, Any]:
        """The variant as a ``"kind": "cam"`` problem file (``graphmethods cam`` reads it)."""
        fol: dict[str, Any] = {"type": "translating", "contact": self.contact, "offset": self.offset}
        if self.contact == "roller":
            fol["roller_radius"] = self.roller_radius
        motion: list[dict[str, Any]] = [
            {"phase": "rise", "angle_deg": self.rise_deg, "lift": self.lift, "law": self.rise_law},
            {"phase": "dwell", "angle_deg": self.dwell_deg},
            {"phase": "return", "angle_deg": self.return_deg, "lift": self.lift, "law": self.return_law}]
        if self.dwell2_deg > 1e-9:
            motion.append({"phase": "dwell", "angle_deg": self.dwell2_deg})
        return {"kind": "cam", "name": dict(TITLE.texts), "follower": fol, "cam": {"sense": "ccw", "n_rpm": 60.0},
                "motion": [m for m in motion if m["angle_deg"] > 0],
                "pressure_angle_max_deg": self.alpha_max_deg,
                "pressure_angle_return_max_deg": self.alpha_return_max_deg}

    def to_dict(self) -> dict[str, Any]:
        """The worksheet's problem file, which is also a ``"kind": "cam"`` problem file: ``graphmethods cam`` reads
        it (the same numbers as the key), ``graphmethods check`` reads it as the variant."""
        return {**super().to_dict(), **{k: v for k, v in self.problem_dict().items() if k != "kind"}}

    @cached_property
    def problem(self) -> CamProblem:
        return cam_from_dict(self.problem_dict(), source=f"worksheet {self.id}")

    @cached_property
    def cam(self) -> CamDesign:
        """The exact design (the key's numbers)."""
        return design(self.problem)

    @cached_property
    def positions_deg(self) -> tuple[float, ...]:
        """The marked positions' cam angles φ_k, degrees: each rise and return in ``n_div`` parts, the dwells'
        ends (0 … 360°, 360° left out)."""
        return positions_of(self.problem, self.n_div)

    def answers(self) -> dict[str, Any]:
        cam = self.cam
        s = self.problem.motion(np.asarray(self.positions_deg))[0]
        out: dict[str, Any] = {"mu_l": self.mu_l, "base_radius": cam.base_radius}
        if self.contact == "roller":
            out["pitch_base_radius"] = cam.pitch_base_radius
        out["s_mm"] = [float(round(x / self.mu_l, 9)) for x in s]
        out["alpha_max_rise_deg"] = cam.alpha_max_rise_deg
        out["alpha_max_return_deg"] = cam.alpha_max_return_deg
        return out


def positions_of(p: CamProblem, n_div: int) -> tuple[float, ...]:
    """The cam angles (degrees) of the construction's positions: each rise and return in ``n_div`` equal parts,
    each dwell's end; from 0, 360° left out.

    >>> from graphmethods.problems.builtin import cam_problem
    >>> positions_of(cam_problem("shaper-cam"), 2)
    (0.0, 45.0, 90.0, 105.0, 150.0, 195.0)
    """
    out = [0.0]
    for ph in p.phases:
        k = 1 if ph.kind == "dwell" else n_div
        out += [round(ph.start_deg + ph.angle_deg * (i + 1) / k, 9) for i in range(k)]
    return tuple(x for x in out if x < 360.0 - 1e-9)


def generate(rng: np.random.Generator) -> dict[str, Any]:
    """A variant's data with nice numbers: the base radius designed with a knife (r₀ does not depend on the
    roller), then a roller of a convenient radius that leaves r_b ≥ 1.3 r_r and the pitch curve's ρ_min ≥ 1.5 r_r
    (no undercut); μ_l the convenient scale at which the inversion fills its box."""
    for _ in range(100):
        contact = str(pick(rng, ("roller", "roller", "knife")))
        data: dict[str, Any] = {
            "contact": "knife", "offset": float(pick(rng, (0.0, 0.0, 0.004, 0.005, 0.008))), "roller_radius": 0.0,
            "lift": float(pick(rng, (0.015, 0.016, 0.02, 0.025, 0.03))),
            "rise_deg": float(pick(rng, (90.0, 120.0, 150.0))), "dwell_deg": float(pick(rng, (30.0, 45.0, 60.0))),
            "return_deg": float(pick(rng, (90.0, 120.0, 150.0))),
            "rise_law": str(pick(rng, LAWS)), "return_law": str(pick(rng, LAWS)),
            "alpha_max_deg": float(pick(rng, (25.0, 30.0, 35.0))),
            "alpha_return_max_deg": float(pick(rng, (60.0, 70.0, 75.0))), "n_div": N_DIV, "mu_l": 1.0}
        if 360.0 - data["rise_deg"] - data["dwell_deg"] - data["return_deg"] < 30.0:
            continue
        try:
            cam = CamVariant(seed=0, number=0, **data).cam
        except InputError:
            continue
        r0 = cam.pitch_base_radius
        if contact == "roller":
            fits = [r for r in (0.004, 0.005, 0.006, 0.008, 0.01) if r0 - r >= 1.3 * r and cam.rho_pitch_min >= 2.5 * r]
            if not fits:
                continue
            data.update(contact="roller", roller_radius=float(pick(rng, fits)))
        if r0 - data["roller_radius"] < 0.008:              # a cam too small to draw a shaft in
            continue
        data["mu_l"] = pick_scale(2.0 * _reach(cam), 92.0)
        return data
    raise InputError("no cam variant with a drawable profile was found")  # pragma: no cover


def _reach(cam: CamDesign) -> float:
    """The largest distance from O the inversion draws (the followers reach 25 % of r₀ past the pitch curve), m."""
    return cam.pitch_base_radius + cam.problem.stroke + 0.25 * cam.pitch_base_radius + 1.2 * cam.problem.roller_radius


# ----------------------------------------------------------------------------- the profile by inversion

def follower_lines(cam: CamDesign, phi_deg: Any, *, reach: float) -> np.ndarray:
    """The follower's axis at cam angles φ (degrees) turned back by −φ into the cam's frame: for each angle the
    point 40 % of s₀ out from the foot on the offset circle (the centre is left clear for the letter O) and the
    point ``reach`` m past the pitch point, shape (N, 2, 2), m."""
    p = cam.problem
    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    s = p.motion(phi)[0]
    s0 = math.sqrt(max(cam.pitch_base_radius ** 2 - p.offset ** 2, 0.0))
    start = 0.4 * s0                     # clear of the centre, where O is lettered
    rad = np.radians(phi)
    a = to_cam_frame(np.column_stack((np.full(phi.shape, p.offset), np.full(phi.shape, start))), rad, p.sense)
    b = to_cam_frame(np.column_stack((np.full(phi.shape, p.offset), s0 + s + reach)), rad, p.sense)
    return np.stack((a, b), 1)


def inversion_elements(cam: CamDesign, centre: tuple[float, float], mu_l: float, nt: Notation, *,
                       phi_deg: tuple[float, ...], full: bool, name: str = "inv") -> list[Element]:
    """The profile by inversion with the cam centre O at ``centre`` (page mm, y down) at μ_l (m/mm).

    ``full`` false: what the student is given (O, the offset circle, the follower's axis in position 0);
    true: the whole construction (base circles, the follower at every position, the pitch points numbered,
    the pitch curve, the rollers, the profile). The overlay of a check draws it too.
    """
    from graphmethods.sheets.layout import Occupancy, label_bbox

    p = cam.problem
    cx, cy = centre

    def P(xy: np.ndarray) -> list[tuple[float, float]]:
        xy = np.atleast_2d(xy)
        return list(zip((cx + xy[:, 0] / mu_l).round(4).tolist(), (cy - xy[:, 1] / mu_l).round(4).tolist()))
    reach = 0.25 * cam.pitch_base_radius + 1.2 * p.roller_radius
    els: list[Element] = []
    if p.offset:
        els.append(Circles(((cx, cy, abs(p.offset) / mu_l),), THIN, name=f"{name}-offset-circle"))
    lines = follower_lines(cam, phi_deg if full else (0.0,), reach=reach)
    els += [Line(P(ln)[0], P(ln)[1], style=AXIS, name=f"{name}-follower-{k}") for k, ln in enumerate(lines)]
    st = cam.state(np.asarray(phi_deg if full else (0.0,)))
    if full:
        dense = cam.state(np.linspace(0.0, 360.0, 721))
        els.append(Circles(((cx, cy, cam.base_radius / mu_l),), THIN, name=f"{name}-base-circle"))
        if p.contact == "roller":
            els.append(Circles(((cx, cy, cam.pitch_base_radius / mu_l),), CENTRES, name=f"{name}-pitch-base-circle"))
            els.append(Polyline(tuple(P(dense.pitch)), CENTRES, closed=True, name=f"{name}-pitch-curve"))
            els.append(Circles(tuple((x, y, p.roller_radius / mu_l) for x, y in P(st.pitch)), THIN,
                               name=f"{name}-rollers"))
        els.append(Polyline(tuple(P(dense.profile)), MAIN, closed=True, name=f"{name}-profile"))
        els += [Point(q, radius_mm=0.6, name=f"{name}-B-{k}") for k, q in enumerate(P(st.pitch))]
    els.append(Point((cx, cy), radius_mm=0.9, name=f"{name}-O"))
    occ = Occupancy()
    from graphmethods.sheets.cam_diagrams import register_ink

    register_ink(occ, *els)
    lab, leader = occ.place_label_with_leader((cx, cy), "O", ("sw", "se", "nw", "ne", "s", "w", "n", "e"),
                                              size_mm=TEXT_MM, gap_mm=0.8)
    els.append(Text((lab.x, lab.y), "O", size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-O-name"))
    if leader is not None:
        els.append(Line(leader[0], leader[1], style=THIN, name=f"{name}-O-leader"))
    for k, ln in enumerate(lines):
        (xa, ya), (x, y) = P(ln)
        u = np.array([x - xa, y - ya]) / max(math.hypot(x - xa, y - ya), 1e-9)
        for t in (2.6, 4.0, 5.5, 7.0):             # along the follower's axis, past its end, clear of ink
            at = (round(x + t * u[0], 3), round(y + t * u[1] + 0.35 * TEXT_MM, 3))
            lab = make_label(at, str(k), size_mm=TEXT_MM, anchor="middle")
            if occ.is_free(label_bbox(lab)):
                break
        occ.add_label(lab)
        els.append(Text(at, str(k), size_mm=TEXT_MM, anchor="middle", name=f"{name}-k-{k}"))
    return els


def _name_O(comb: list[Element]) -> list[Element]:
    """The letter O beside the combined diagram's cam centre, clear of the diagram's ink."""
    from graphmethods.sheets.cam_diagrams import register_ink
    from graphmethods.sheets.layout import Occupancy

    occ = Occupancy()
    register_ink(occ, *comb)
    O = next(e for e in comb if e.name == "c-O")
    at = O.at  # type: ignore[attr-defined]
    lab = occ.place_label(at, "O", ("e", "w", "ne", "nw", "se", "sw"), size_mm=TEXT_MM, gap_mm=1.5)
    return [Text((lab.x, lab.y), "O", size_mm=TEXT_MM, anchor=lab.anchor, name="c-O-letter")]


# ----------------------------------------------------------------------------- the page

def _statement(v: CamVariant, nt: Notation, s_l: Scale) -> dict[str, str]:
    deg = "°"

    def ang(a: float) -> str:
        return f"{nt.number(a)}{deg}"
    roller = v.contact == "roller"
    follower = nt.word("cam.roller" if roller else "cam.knife")
    if roller:
        follower += f" ({nt.sym('cam.r_r')} = {nt.number(v.roller_radius * 1000)} {nt.unit('mm')})"
    rb = _say("rb_roller", nt, rb=nt.sym("cam.r_b"), r0=nt.sym("cam.r_0"), rr=nt.sym("cam.r_r")) if roller else ""
    return {"follower": follower, "offset": _say("offset", nt, e=f"{nt.number(v.offset * 1000)} {nt.unit('mm')}")
            if v.offset else "", "h": f"{nt.number(v.lift * 1000)} {nt.unit('mm')}", "rise": ang(v.rise_deg),
            "rise_law": nt.word("cam." + v.rise_law), "dwell": ang(v.dwell_deg), "ret": ang(v.return_deg),
            "ret_law": nt.word("cam." + v.return_law),
            "dwell2": _say("dwell2", nt, a=ang(v.dwell2_deg)) if v.dwell2_deg > 1e-9 else "",
            "alpha": nt.number(v.alpha_max_deg), "alpha_ret": nt.number(v.alpha_return_max_deg),
            "pitch": _say("pitch_roller" if roller else "pitch_knife", nt), "rb": rb, "mu_l": s_l.caption(nt),
            "curves": _say("curves_roller" if roller else "curves_knife", nt)}


#: the statement's fill-ins kept on one line (a number with its unit, a scale)
_WHOLE = ("h", "rise", "dwell", "ret", "dwell2_angle", "mu_l", "alpha", "alpha_ret")


def _statement_paragraphs(sh: Sheet, fmt: dict[str, str]) -> None:
    """The statement as :meth:`Sheet.statement` writes it, but only the short fill-ins kept on one line (the
    phrases that differ by contact wrap)."""
    from graphmethods.scene import in_language
    from graphmethods.sheets.worksheets.elements import NBSP
    from graphmethods.sheets.worksheets.texts import STATEMENTS

    fmt = {k: v.replace(" ", NBSP) if k in _WHOLE else v for k, v in fmt.items()}
    parts: tuple[str, ...] = in_language(STATEMENTS["cam"], sh.nt)  # type: ignore[arg-type,assignment]
    sh.paragraph(parts[0].format(**fmt), name="given")
    for k, task in enumerate(parts[1:]):
        sh.paragraph(task.format(**fmt), indent=4.0, name=f"task-{k + 1}")
    sh.y += 1.5


def _positions_table(sh: Sheet, v: CamVariant, nt: Notation) -> None:
    s = v.answers()["s_mm"]
    ks = ["k"] + [str(k) for k in range(len(v.positions_deg))]
    phis = [nt.quantity("φ_{k}", "°")] + [nt.number(a) for a in v.positions_deg]
    full = [nt.quantity(f"{nt.sym('calculus.s')}_{{k}}", "mm")] + [nt.number(x, sig=3) for x in s]
    shown = full if sh.key else [full[0]] + [""] * len(s)
    sh.table((ks, phis, shown), value_rows=(2,), name="positions", width_rows=(ks, phis, full), size=2.8,
             row_mm=5.6, value_row_mm=7.0)


def _answers(v: CamVariant, nt: Notation) -> tuple[list[str], list[str], list[str]]:
    a, cam, p = v.answers(), v.cam, v.problem
    heads = [nt.quantity(nt.sym("cam.r_b"), "mm")]
    vals = [nt.number(a["base_radius"] * 1000, sig=4)]
    if v.contact == "roller":
        heads.append(nt.quantity(nt.sym("cam.r_0"), "mm"))
        vals.append(nt.number(a["pitch_base_radius"] * 1000, sig=4))
    al = nt.sym("cam.alpha")
    heads += [f"{al}_{{max}}, {nt.word('camcheck.rise')}, °", f"{al}_{{max}}, {nt.word('camcheck.return')}, °"]
    vals += [nt.number(a["alpha_max_rise_deg"], sig=3), nt.number(a["alpha_max_return_deg"], sig=3)]
    s0 = math.sqrt(cam.pitch_base_radius ** 2 - p.offset ** 2)
    r0, s_, ds = nt.sym("cam.r_0"), nt.sym("calculus.s"), nt.sym("cam.ds")     # S and dS/dφ in Russian, as the diagram
    lines = [f"{s_}_{{0}} = max(|{ds} − e|/tan[{al}] − {s_}) = {nt.number(s0 * 1000, sig=4)} {nt.unit('mm')}; "
             f"{r0} = √({s_}_{{0}}² + e²) = {nt.number(cam.pitch_base_radius * 1000, sig=4)} {nt.unit('mm')}"]
    if v.contact == "roller":
        lines[0] += (f"; {nt.sym('cam.r_b')} = {r0} − {nt.sym('cam.r_r')} = "
                     f"{nt.number(cam.base_radius * 1000, sig=4)} {nt.unit('mm')}")
    lines.append(f"{al}_{{max}}: φ = {nt.number(round(cam.phi_alpha_max_rise_deg, 1))}° "
                 f"({nt.number(a['alpha_max_rise_deg'], sig=3)}°), φ = "
                 f"{nt.number(round(cam.phi_alpha_max_return_deg, 1))}° "
                 f"({nt.number(a['alpha_max_return_deg'], sig=3)}°)")
    return heads, vals, lines


_STUDENT_KEEPS = ("c-axis-", "c-zero", "c-follower-line")


def _finer_ticks(e: Element, nt: Notation) -> Element:
    """An axis of the combined diagram with its ticks as close as their values can be read (the A4 figure's
    22 mm apart leave the worksheet's narrower diagram with 0 alone), every tick labelled, in mm as the
    table of s_k is; other elements as they are."""
    if not (isinstance(e, Axis) and e.name in ("c-axis-ds", "c-axis-s")):
        return e
    ticks = axis_ticks(e.min_value, e.max_value, e.scale, min_gap_mm=10.0)
    return replace(e, ticks=ticks, tick_labels=tuple(nt.number(t * 1000.0, sig=3) for t in ticks),
                   label=nt.quantity(e.label, "mm"))


def page(v: CamVariant, nt: Any, key: bool) -> Scene:
    """The student's page (``key`` false) or the answer key of a variant."""
    from graphmethods.sheets.cam_diagrams import combined_diagram
    from graphmethods.sheets.layout import Occupancy

    sh, nt = Sheet.begin(v, nt, key)
    s_l = Scale(nt.sym("worksheets.mu_l"), nt.unit("m"), v.mu_l)
    _statement_paragraphs(sh, _statement(v, nt, s_l))
    _positions_table(sh, v, nt)
    top, H = sh.drawing_box()
    split = X0 + 0.40 * (X1 - X0)
    cam = v.cam
    y = top
    for k, line in enumerate(wrap(nt.word("cam.combined"), split - 3.0 - X0, TEXT_MM)):
        y += TEXT_MM * 1.4
        sh.add(Text((X0, y), line, size_mm=TEXT_MM, bold=True, name=f"c-heading-{k}"))
    comb, s_c = combined_diagram(cam, (X0, y - 4.0, split - 3.0, top + H), Occupancy(), nt)
    # the A1 heading (ours is above) and r₀ written at O (it is in the answers) left out; O named clear of ink
    comb = [_finer_ticks(e, nt) for e in comb if not e.name.startswith(("c-title-", "c-O-name", "c-O-leader"))]
    if not key:
        comb = [e for e in comb if e.name.startswith(_STUDENT_KEEPS)]
    sh.add(*comb)
    if key:
        sh.add(*_name_O(comb))
    reach = _reach(cam)
    box = (split + 2.0, top, X1, top + H)
    if 2.0 * reach / v.mu_l > min(box[2] - box[0], box[3] - box[1]) + 1e-6:
        raise InputError(f"{v.id}: the profile at μ_l = {v.mu_l} m/mm does not fit its box")
    centre = (round((box[0] + box[2]) / 2.0), round((box[1] + box[3]) / 2.0))
    sh.add(*inversion_elements(cam, centre, v.mu_l, nt, phi_deg=v.positions_deg, full=key, name="inv"))
    sh.caption([s_l.caption(nt), s_c.caption(nt)], y=top + H + 5.0)
    sh.y = top + H + CAPTION_ROOM
    heads, vals, lines = _answers(v, nt)
    answers_and_solution(sh, heads, vals, lines)
    return sh.scene((s_l, s_c))


# registered with the other kinds (graphmethods.sheets.worksheets imports this module at its end)
register("cam", CamVariant, generate, page, TITLE, STATEMENT)
