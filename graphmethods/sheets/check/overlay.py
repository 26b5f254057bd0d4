"""The overlay of a check: the correct construction at the student's scales on a page the size of
theirs, the wrong items in red with the mistakes named, in en / ru / zh.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import Scale, Scene, Text, markup, notation as get_notation
from graphmethods.scene.elements import Element, Line, lettered_size
from graphmethods.scene.notation import Notation
from graphmethods.scene.primitives import Circle, Path, Style
from graphmethods.sheets.check import acceleration as ca
from graphmethods.sheets.check.hypotheses import em_data, plan_data
from graphmethods.sheets.check.problems import CycleData, LinkageData
from graphmethods.sheets.check.report import Checker, CheckReport, Item
from graphmethods.sheets.worksheets.constructions import (
    energy_mass_construction,
    extremes,
    moment_regions,
    staircase,
    velocity_plan,
)
from graphmethods.sheets.worksheets.elements import RED, ColorText, Shapes, wrap
from graphmethods.sheets.worksheets.texts import value_unit
from graphmethods.titles import Title
from graphmethods.units import omega_from_n

if TYPE_CHECKING:
    pass

# ----------------------------------------------------------------------------- words (en, ru, zh)
#: what the overlay writes, (en, ru, zh), as markup; ``{placeholders}`` are filled by :func:`_w`. The
#: keys of :data:`MISTAKES` name the mistakes (short, for the list of wrong items); the text, Markdown
#: and JSON reports stay English.


# ----------------------------------------------------------------------------- overlay

def _wrong_index(report: CheckReport, prefix: str) -> dict:
    out = {}
    for it in report.items:
        if it.verdict != "ok" and it.key.startswith(prefix) and it.key.endswith("]"):
            out[int(it.key[len(prefix) + 1:-1])] = it.student
    return out


_KEY = re.compile(r"(\w+)\.(\w+?)(?:\[(\d+)\])?")
_SYMBOL_LABELS = {"omega_max": "ω_{max}", "omega_min": "ω_{min}", "omega_2": "ω_{2}", "v_A": "v_{A}", "v_B": "v_{B}",
                  "v_BA": "v_{BA}", "v_S2": "v_{S2}", "pa_mm": "pa", "pb_mm": "pb", "ab_mm": "ab", "ps2_mm": "ps_{2}",
                  "kl_mm": "kl"}


def overlay_label(it: Item, report: CheckReport, nt) -> str:
    """An item's label in the overlay's notation (markup), made from its key (``Item.label`` is English)."""
    nt = get_notation(nt)
    m = _KEY.fullmatch(it.key)
    section, name, idx = (m.group(1), m.group(2), m.group(3)) if m else ("", "", None)
    per_interval = {"areas_mm2": ("area", "n_areas"), "works_J": ("work", "n_works"),
                    "arrows_mm": ("arrow", "n_arrows")}
    if name in per_interval:
        if idx is None:
            return nt.word("check." + per_interval[name][1])
        assert isinstance(report.data, CycleData)       # per-interval keys belong to cycle problems
        L = report.data.cycle.labels
        i = int(idx)
        return nt.word("check." + per_interval[name][0], i=markup.literal(f"{L[i]}–{L[i + 1]}"))
    if name in ("omega_max_at", "omega_min_at"):
        omega = f"ω_{{{name[6:9]}}}"
        if section == "energy_mass":
            return nt.word("check.position_of", omega=omega)
        return nt.word("check.angle_of" if it.unit == "°" else "check.point_of", omega=omega)
    if name == "omega_2_sense":
        return nt.word("check.sense_of", omega="ω_{2}")
    if section == "acceleration_plan":
        return ca.item_label(it.key, lambda key, **kw: nt.word("check." + key, **kw))
    if section == "cam":                     # a cam profile (graphmethods.sheets.check.cam)
        from graphmethods.sheets.check.cam import item_label

        return item_label(it, nt)
    if name in ("tan_psi_max", "tan_psi_min"):
        return f"{nt.sym('worksheets.tan')} ψ_{{{name[-3:]}}}"
    if name in ("delta_W_max", "M_d"):
        return nt.sym(name)
    if name in ("omega_m", "J_F"):
        return nt.sym("dynamics." + name)
    if name in _SYMBOL_LABELS:
        return _SYMBOL_LABELS[name]
    return markup.literal(it.label)


def overlay_value(v, nt) -> str:
    """A value of the list of wrong items: a number in the notation's style, or a position (``"b or c"``,
    a sense ``"cw"``) in its words."""
    nt = get_notation(nt)
    if not isinstance(v, str):
        return nt.number(v)
    parts = [nt.word("kinematics." + p) if p in ("cw", "ccw") else markup.literal(p) for p in v.split(" or ")]
    text = parts[0]
    for p in parts[1:]:
        text = nt.word("check.or", a=text, b=p)
    return text


def _wrong_line(it: Item, report: CheckReport, nt) -> str:
    """One line of the overlay's red list: label, the student's value, the expected one, the unit, and why."""
    text = nt.word("check.item", label=overlay_label(it, report, nt), student=overlay_value(it.student, nt),
                   expected=overlay_value(it.expected, nt), unit=nt.unit(it.unit), why=_why(it, nt))
    return re.sub(" {2,}", " ", text)


def _why(it: Item, nt) -> str:
    """Why an item is wrong, in words: its mistakes, or wrong, or carried over."""
    if it.mistakes:
        sep = "、" if get_notation(nt).code == "zh" else ", "
        return sep.join(nt.word("check." + code, J_e=nt.sym("dynamics.J_e")) for code in it.mistakes)
    return nt.word("check.carried" if it.verdict == "carried" else "check.wrong")


def _wrong_lines(report: CheckReport, nt, *, run: int = 3) -> list[str]:
    """The red list's lines: one per wrong item, except that ``run`` or more items in a row of one list (keys
    ``x[1]``, ``x[2]`` …) wrong for the same reason share one line, first … last and how many (a profile's
    positions all off by one mistake would fill the page)."""
    wrong = [it for it in report.items if it.verdict != "ok"]
    out, k = [], 0
    while k < len(wrong):
        it, base = wrong[k], wrong[k].key.split("[")[0]
        j = k
        while (j + 1 < len(wrong) and "[" in it.key and wrong[j + 1].key.split("[")[0] == base
               and wrong[j + 1].verdict == it.verdict and wrong[j + 1].mistakes == it.mistakes):
            j += 1
        if j - k + 1 >= run:
            first, last, n = overlay_label(it, report, nt), overlay_label(wrong[j], report, nt), j - k + 1
            out.append(f"{first} … {last}（{n}）——{_why(it, nt)}" if get_notation(nt).code == "zh"
                       else f"{first} … {last} ({n}) — {_why(it, nt)}")
        else:
            out += [_wrong_line(w, report, nt) for w in wrong[k:j + 1]]
        k = j + 1
    return out


def overlay(report: CheckReport, notation) -> Scene:
    """The overlay of a check (see :meth:`CheckReport.overlay`): the heading, how to print it and the list
    of wrong items at the top, then each checked construction at the student's scales, placed where the
    answers' ``origin_mm`` says or else left to right in rows (:class:`_Slots`)."""
    from graphmethods.sheets.engine.lettering import lettered

    nt = get_notation(notation)
    W, H = report.page.width_mm, report.page.height_mm
    with lettered(report.page):                     # A1/A2 films letter at 3.5 mm and up, as the sheet they cover
        title, els, y = _overlay_head(report, nt)
        place = _Placer(report.answers, _Slots(W, H, top=max(y, 24.0) + 4.0))
        data = report.data
        if isinstance(data, CycleData):
            els += _moment_section(report, data, nt, place) + _indicator_section(report, data, nt, place)
        elif isinstance(data, LinkageData):
            els += (_velocity_section(report, data, nt, place) + _acceleration_section(report, data, nt, place)
                    + _energy_mass_section(report, data, nt, place))
        return Scene(report.page, tuple(els), title=title, notation=nt.code, name="overlay")


def _overlay_head(report: CheckReport, nt: Notation) -> tuple[str, list[Element], float]:
    """The heading, how to print the overlay, a 100 mm ruler and the wrong items (right-aligned, in red):
    (the title, the elements, the y below them in mm)."""
    W, H = report.page.width_mm, report.page.height_mm
    els: list[Element] = []
    rest = f"{report.problem} — {Title.of(report.title).title_in(nt.code)}" + (
        f" — {report.student}" if report.student else "")
    title = nt.word("check.heading", overlay=nt.word("check.overlay"), rest=markup.literal(rest))
    big, small = lettered_size(3.2), lettered_size(2.6)     # the page's lettering (3.5 mm and up on A1/A2)
    y = 12.0 + big - 3.2
    for line in wrap(title, (W - 24.0) / 1.15, big):          # bold runs wider than the estimate
        els.append(Text((12.0, y), line, size_mm=big, bold=True, name="overlay-title"))
        y += 4.5 * big / 3.2
    y += 0.5
    for line in wrap(nt.word("check.howto", bar=f"100 {nt.unit('mm')}"), W - 24.0, small):
        els.append(Text((12.0, y), line, size_mm=small, name="overlay-howto"))
        y += 3.6 * small / 2.6
    els.append(Line((12.0, H - 8.0), (112.0, H - 8.0), style=Style(width_mm=0.35), name="ruler"))
    for x in (12.0, 62.0, 112.0):
        els.append(Line((x, H - 10.0), (x, H - 6.0), style=Style(width_mm=0.35), name="ruler-tick"))
    els.append(Text((114.0, H - 7.0), f"100 {nt.unit('mm')}", size_mm=small, name="ruler-text"))
    # wrong items listed, right-aligned at the right margin (a line too long for the page is broken)
    y += 3.4 + small - 2.6
    for text in _wrong_lines(report, nt):
        for line in wrap(text, W - 24.0, small):
            els.append(ColorText((W - 12.0, y), line, size_mm=small, anchor="end", color=RED, name="wrong-list"))
            y += 3.8 * small / 2.6
    return title, els, y


@dataclass(frozen=True)
class _Placer:
    """Where each construction goes: the answers' ``origin_mm`` of its section, else the next free slot."""

    answers: dict
    slots: _Slots

    def origin(self, section: str, size: tuple[float, float], offset: tuple[float, float]) -> tuple[float, float]:
        given = self.answers.get(section, {}).get("origin_mm")
        if given is not None:
            if not (isinstance(given, tuple) and len(given) == 2 and all(not isinstance(v, str) for v in given)):
                raise InputError(f"[{section}] origin_mm must be [x, y] in mm from the page's top-left corner")
            return (float(given[0]), float(given[1]))
        x, y0 = self.slots.take(*size)
        return (x + offset[0], y0 + offset[1])


def _keep_off_cross(occ, at: tuple[float, float]) -> None:
    """Register a registration cross (its arms and the box of its circle) so that letters keep off it."""
    occ.add_primitives(_cross(at, "cross").primitives())
    occ.add_box((at[0] - 2.2, at[1] - 2.2, at[0] + 2.2, at[1] + 2.2))


def _cross(at: tuple[float, float], name: str) -> Shapes:
    """A registration cross at a construction's origin (to lay the film over the student's sheet)."""
    x, y0 = at
    return Shapes((Path(((x - 4, y0), (x + 4, y0)), Style(width_mm=0.25)),
                   Path(((x, y0 - 4), (x, y0 + 4)), Style(width_mm=0.25)),
                   Circle(x, y0, 2.0, Style(width_mm=0.25))), name=name)


def _moment_section(report: CheckReport, data: CycleData, nt: Notation, place: _Placer) -> list[Element]:
    """M_d and M_r at the student's μ_M, μ_φ, the wrong areas outlined red."""
    from graphmethods.scene.elements import Frame
    from graphmethods.sheets.layout import Occupancy

    c, a = data.cycle, report.answers
    if "moment_diagram" not in a or c.M_d is None or c.M_r is None or c.period is None:
        return []
    md = a["moment_diagram"]
    mu_M = float(md["mu_M"])
    mu_phi = float(md["mu_phi"]) if "mu_phi" in md else math.radians(float(md["mu_phi_deg"]))
    M_all = np.concatenate((c.M_d.M, c.M_r.M, [0.0]))
    w_mm = c.period / mu_phi
    hi, lo = float(M_all.max()) / mu_M, float(M_all.min()) / mu_M
    o = place.origin("moment_diagram", (w_mm + 20.0, hi - lo + 16.0), (8.0, hi + 8.0))
    frame = Frame(o, Scale("μ_φ", "rad", mu_phi), Scale("μ_M", "N·m", mu_M))
    occ = Occupancy()
    _keep_off_cross(occ, o)
    return [Line((o[0], o[1]), (o[0] + w_mm, o[1]), style=Style(width_mm=0.25), name="md-axis-phi"),
            Line((o[0], o[1] - hi), (o[0], o[1] - lo), style=Style(width_mm=0.25), name="md-axis-M"),
            *moment_regions(frame, c, wrong=_wrong_index(report, "moment_diagram.areas_mm2"), nt=nt,
                            occ=occ, name="md"),
            _cross(o, "md-origin")]


def _indicator_section(report: CheckReport, data: CycleData, nt: Notation, place: _Placer) -> list[Element]:
    """The energy indicator's staircase at the student's μ_E, the wrong arrows red."""
    from graphmethods.sheets.layout import Occupancy

    c, a = data.cycle, report.answers
    if "energy_indicator" not in a:
        return []
    ei = a["energy_indicator"]
    mu_E = float(ei["mu_E"])
    step = float(ei.get("step_mm", 16.0))
    E = np.asarray(c.E, dtype=float)
    hi, lo = max(E.max(), 0.0) / mu_E, min(E.min(), 0.0) / mu_E
    o = place.origin("energy_indicator", (step * c.work.size + 40.0, hi - lo + 16.0), (6.0, hi + 8.0))
    cross = _cross(o, "ei-origin")
    occ = Occupancy()
    _keep_off_cross(occ, o)                         # the letters keep off the registration cross
    wrong = _wrong_index(report, "energy_indicator.arrows_mm")
    return [*staircase(o[0], o[1], c.work, mu_E=mu_E, step_mm=step, labels=c.labels, nt=nt, occ=occ, wrong=wrong,
                       name="ei"),
            *extremes(o[0], o[1], c.work, mu_E=mu_E, step_mm=step, nt=nt, occ=occ, name="ei-ext"),
            cross]


def _velocity_section(report: CheckReport, data: LinkageData, nt: Notation, place: _Placer) -> list[Element]:
    """The velocity plan at the student's μ_v from its pole, the wrong segments red."""
    a = report.answers
    if "velocity_plan" not in a:
        return []
    vec, l_AB, _, _ = plan_data(Checker(a), data)
    mu_v = float(a["velocity_plan"]["mu_v"])
    xs = [float(v[0]) / mu_v for v in vec.values()]
    ys = [-float(v[1]) / mu_v for v in vec.values()]
    size = (max(xs) - min(xs) + 40.0, max(ys) - min(ys) + 30.0)
    o = place.origin("velocity_plan", size, (20.0 - min(xs), 15.0 - min(ys)))
    if data.plan_variant is not None:
        pv = data.plan_variant
        A, B = pv.positions.xy("A")[0], pv.positions.xy("B")[0]
    else:
        k = int(a["velocity_plan"]["position"])
        m = int(a["velocity_plan"].get("positions", 12))
        assert data.case is not None
        pos = data.case.mechanism.positions(m=m)
        A, B = pos.xy("A")[k], pos.xy("B")[k]
    u = (B - A) / np.hypot(*(B - A))
    wrong = {it.key.split(".")[1][:-3]: it.student for it in report.items
             if it.verdict != "ok" and it.key.startswith("velocity_plan.") and it.key.endswith("_mm")}
    return [*velocity_plan(o, vec, mu_v=mu_v, link_dir=u, nt=nt, wrong=wrong, name="plan"), _cross(o, "plan-pole")]


def _acceleration_section(report: CheckReport, data: LinkageData, nt: Notation, place: _Placer) -> list[Element]:
    """The acceleration plan at the student's μ_a, wrong vectors red (with the student's value), carried ones
    red without it."""
    a = report.answers
    if "acceleration_plan" not in a:
        return []
    plan = ca.problem_of(Checker(a), data).plan()
    mu_a = float(a["acceleration_plan"]["mu_a"])
    xs = [z.real / mu_a for z in plan.images.values()]
    ys = [-z.imag / mu_a for z in plan.images.values()]
    o = place.origin("acceleration_plan", (max(xs) - min(xs) + 40.0, max(ys) - min(ys) + 30.0),
                     (20.0 - min(xs), 15.0 - min(ys)))
    mine = [it for it in report.items if it.key.startswith("acceleration_plan.") and it.key.endswith("_mm")]
    wrong = {it.key.split(".")[1][:-3]: it.student for it in mine if it.verdict == "wrong"}
    carried = [it.key.split(".")[1][:-3] for it in mine if it.verdict == "carried"]
    return [*ca.plan_elements(o, plan, mu_a=mu_a, wrong=wrong, carried=carried, nt=nt, name="acc",
                              leader_mm=(*ca.NAME_LEADER_MM, 12.0, 16.0)),
            _cross(o, "acc-pole")]


def _energy_mass_section(report: CheckReport, data: LinkageData, nt: Notation, place: _Placer) -> list[Element]:
    """The energy-mass diagram at the student's μ_J, μ_T with its tangent rays; a wrong kl marked where the
    student's l would be."""
    from graphmethods.dynamics.wittenbauer import wittenbauer

    a, W, H = report.answers, report.page.width_mm, report.page.height_mm
    if "energy_mass" not in a:
        return []
    J, T, n_rpm, d = em_data(Checker(a), data)
    mu_J, mu_T = float(a["energy_mass"]["mu_J"]), float(a["energy_mass"]["mu_T"])
    res = wittenbauer(J_e=J, delta_T=T, omega_m=omega_from_n(n_rpm), delta=d, mu_J=mu_J, mu_T=mu_T)
    hi = max(float(T.max()) / mu_T, res.k_mm, 0.0)
    lo = min(float(T.min()) / mu_T, res.l_mm, 0.0)
    width = float(J.max()) / mu_J + 40.0
    o = place.origin("energy_mass", (width + 30.0, hi - lo + 24.0), (30.0, hi + 12.0))
    box = (max(o[0] - 30.0, 2.0), max(o[1] - hi - 12.0, 2.0), min(W - 2.0, o[0] + width),
           min(H - 12.0, o[1] - lo + 12.0))
    axes = (Line((o[0], box[1] + 2.0), (o[0], box[3] - 2.0), style=Style(width_mm=0.25), name="em-axis-T"),
            Line((o[0], o[1]), (o[0] + float(J.max()) / mu_J + 10.0, o[1]), style=Style(width_mm=0.25),
                 name="em-axis-J"))
    els: list[Element] = list(axes) + energy_mass_construction(res, origin=o, box=box, axes=axes, nt=nt, prefix="em-")
    wrong_kl = next((it for it in report.items if it.key == "energy_mass.kl_mm" and it.verdict != "ok"), None)
    if wrong_kl is not None:
        y_student = o[1] - res.k_mm + float(wrong_kl.student)         # where the student's l would be
        els.append(Line((o[0] - 6.0, y_student), (o[0] + 6.0, y_student),
                        style=Style(stroke=RED, width_mm=0.45), name="em-kl-student-mark"))
        kl = value_unit(float(wrong_kl.student), "mm", nt)
        els.append(ColorText((o[0] + 8.0, y_student + 1.0), f"kl = {kl}?", size_mm=2.8, color=RED,
                             name="em-kl-student"))
    els.append(_cross(o, "em-origin"))
    return els


class _Slots:
    """Places constructions on the page left to right, then in the next row (a shelf packer)."""

    def __init__(self, W: float, H: float, *, top: float):
        self.W, self.H = W, H
        self.x, self.y, self.row = 12.0, top, 0.0

    def take(self, w: float, h: float) -> tuple[float, float]:
        if self.x + w > self.W - 8.0 and self.x > 12.0:
            self.x, self.y, self.row = 12.0, self.y + self.row + 6.0, 0.0
        if self.x + w > self.W - 8.0 or self.y + h > self.H - 14.0:
            raise InputError(f"the construction ({w:.0f} × {h:.0f} mm at the student's scales) does not fit the "
                             f"{self.W:.0f} × {self.H:.0f} mm page; give its origin_mm, or a larger [page]")
        at = (self.x, self.y)
        self.x += w + 6.0
        self.row = max(self.row, h)
        return at
