"""The Zhukovsky lever of a study's position: the velocity plan turned 90° as a lever, the load at the
images of its points, the balancing force and moment (split out of :mod:`graphmethods.sheets.dynamics`,
whose common parts it uses; ``sheets.zhukovsky_lever`` is this function)."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from graphmethods.dynamics.study import Study
from graphmethods.errors import InputError
from graphmethods.scene import (
    Dimension,
    Line,
    Page,
    Point,
    Scale,
    Scene,
    Table,
    Text,
    Vector,
    markup,
    notation as get_notation,
)
from graphmethods.scene.elements import Element
from graphmethods.scene.notation import Notation
from graphmethods.scene.primitives import MAIN, THIN, Style
from graphmethods.sheets.dynamics import as_study, problem_text, require_step_load, value_text
from graphmethods.sheets.frame import FastOccupancy, SheetFrame  # SheetFrame re-exported for cycle_panels, motion
from graphmethods.sheets.layout import TEXT_MM, Box, given_scale

# ----------------------------------------------------------------------------- 5. the Zhukovsky lever

def _link_points(link: str, names) -> tuple[str, str] | None:
    """The two named points a link name joins (``"O2B"`` -> ``("O2", "B")``), or None."""
    parts = re.findall(r"[A-Z][0-9]*", link)
    if len(parts) == 2 and "".join(parts) == link and all(p in names for p in parts):
        return parts[0], parts[1]
    return None


@dataclass(frozen=True)
class LeverLoad:
    """The load at one position as a force at the image of its point (a moment on a rocker becomes M/l at its end)."""

    point: str
    force: np.ndarray        # N, (2,)
    M_r: float               # the power method's reduced moment there, N·m


def lever_load(study, k: int) -> LeverLoad:
    """The working-stroke load at position ``k`` as one force (N) at a point of the linkage."""
    load = study.case.load
    plans, pos = study.plans, study.positions
    M_r = float(study.M_r[k])
    if M_r <= 0.0:
        loaded = [int(i) for i in np.flatnonzero(np.asarray(study.M_r)[:-1] > 0)]
        raise InputError(f"position {k} carries no load (M_r = 0 there), so the lever has no force to show; "
                         f"choose a loaded position: {', '.join(map(str, loaded)) or 'none'}")
    if load.kind == "force":
        g = np.asarray(study.mechanism.guides[load.at], dtype=float)
        v = float(plans.v_along_guide(load.at)[k])
        return LeverLoad(load.at, -load.magnitude * math.copysign(1.0, v) * g / np.hypot(*g), M_r)
    ends = _link_points(study.mechanism.link_name(load.at), pos.names)
    if ends is None:
        raise InputError(f"the moment load on link {load.at} cannot be shown on the lever: its end points are "
                         f"not named points of the linkage")
    speeds = [float(plans.speed(p)[k]) for p in ends]
    i = int(np.argmax(speeds))
    end, other = ends[i], ends[1 - i]
    l = float(np.hypot(*(pos.xy(end)[k] - pos.xy(other)[k])))
    v = plans.v(end)[k]
    return LeverLoad(end, -load.magnitude / l * v / np.hypot(*v), M_r)


def _default_lever_position(study) -> int:
    """The loaded position whose plan images lie furthest apart (the clearest lever)."""
    plans = study.plans
    M_r = np.asarray(study.M_r)[:-1]
    moving = [p for p in plans.order if plans.label(p) != "p"]
    V = np.stack([plans.v(p)[:-1] for p in moving], axis=1)                      # (m, n, 2)
    d = np.hypot(*(V[:, :, None, :] - V[:, None, :, :]).transpose(3, 0, 1, 2))   # (m, n, n)
    iu = np.triu_indices(len(moving), 1)
    spread = d[:, iu[0], iu[1]].min(axis=1) if len(iu[0]) else np.ones(len(M_r))
    spread = np.where(M_r > 0, spread, -1.0)
    return int(np.argmax(spread))


def zhukovsky_lever(study, *, position: int | None = None, mu_v=None, mu_F=None, notation="en", page=None,
                    title=None, title_block: bool = True, name: str = "zhukovsky-lever") -> Scene:
    """Zhukovsky's lever at one position: the velocity plan turned 90°, the load at the image of its point.

    The plan (drawn for ω₁ = ω_m to μ_v) is turned 90° against the crank's rotation and
    treated as a rigid lever pivoted at the pole p; the working load F is applied at the
    image of its point (a moment M on a rocker as the force M/l at its end), and its arm h
    about p is dimensioned. Then M_r = F·h·μ_v/ω₁, the same value as the power method's
    (written beside it for comparison).

    Parameters
    ----------
    position : int, optional
        The position (0…m−1); by default the one with the largest M_r.
    mu_v : float or Scale, optional
        (m/s) per mm of the plan; picked when not given.
    mu_F : float or Scale, optional
        N per mm of the force vector; picked when not given.

    Raises
    ------
    InputError
        If no load acts at the position.

    Examples
    --------
    >>> import pathlib
    >>> from graphmethods.kinematics import read_case
    >>> press = read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json")
    >>> s = zhukovsky_lever(press, position=2)
    >>> s.element("label-h").text
    'h = 121.4 mm'
    """

    study = as_study(study)
    require_step_load(study, "Zhukovsky lever")
    nt = get_notation(notation)
    k = _lever_position(study, position)
    g = LeverGeometry.of(study, k)
    lay = LEVER
    sheet = SheetFrame(nt=nt, page=page,
                       title=title or f"{nt.word('dynamics.lever')}, {nt.word('dynamics.position')} {k}",
                       problem=problem_text(study, nt), title_block=title_block,
                       default_page=Page("A4", "landscape", frame=True))
    x0, y0, x1, y1 = sheet.box
    nb = nt.number
    s_F = given_scale(mu_F, nt.sym("dynamics.mu_F"), nt.unit("N"), g.F_abs, lay.force_mm if mu_F is None else 1e9,
                      what="the force vector")
    f_len = s_F.to_mm(g.F_abs)
    rows_probe = ((nt.word("dynamics.plan_turned"),
                   f"{nt.sym('dynamics.omega_1')} = {value_text(nt, g.omega_1, 'rad/s')}"),
                  (nt.word("dynamics.by_lever"), f"= {nb(g.F_abs)}·00.00·{nb(1.0e-4)}/{nb(g.omega_1)}"))
    text_mm, row_mm = result_lettering(page, lay)
    table_w = Table((0.0, 0.0), rows_probe, header_rows=0, align="ll", size_mm=text_mm).width_mm
    box = (x0 + lay.left_mm, sheet.top + lay.top_mm, x1 - table_w - lay.table_gap_mm, sheet.caption_y - lay.bottom_mm)
    s_v = _lever_scale(g, mu_v, box, f_len, nt)
    img, tip, foot, lo, hi = g.on_paper(s_v, f_len)
    p_page = _pole_on_page(box, lo, hi, s_v, s_F)
    occ = sheet.occ
    lever_lines, force, line_of_action, h_mm = _lever_lines(study, g, p_page, img, tip, foot, f_len)
    occ.register(*lever_lines, force, *line_of_action)
    arm, h_label = _lever_arm(g, p_page, img, foot, h_mm, occ, nt, sheet.box)
    pole = Point(_at(p_page, np.zeros(2)), radius_mm=0.9, name="pole")
    occ.add_box((p_page[0] - 1, p_page[1] - 1, p_page[0] + 1, p_page[1] + 1))
    F_text = f"{nt.sym('dynamics.F')} = {value_text(nt, g.F_abs, 'N')}"
    els: list[Element] = lever_lines + line_of_action + [arm, h_label, force, pole]
    els += _lever_names(study, g, p_page, img, force, F_text, occ, sheet.box)
    # the result, worked out on the drawing, beside the power method's value
    M_lever = g.F_abs * h_mm * s_v.per_mm / g.omega_1
    rows = _lever_rows(g, nt, F_text, h_mm, s_v, M_lever)
    probe = Table((0.0, 0.0), rows, header_rows=0, align="ll", size_mm=text_mm, row_height_mm=row_mm)
    table = Table((x1 - probe.width_mm, sheet.top + 4.0), rows, header_rows=0, align="ll", size_mm=text_mm,
                  row_height_mm=row_mm, name="result")
    occ.add_box((table.at[0], table.at[1], table.at[0] + table.width_mm, table.at[1] + table.height_mm))
    els += [table]
    scales = (s_v, s_F)
    elements = [sheet.header()] + els + sheet.captions(scales)
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 notes=(s_v.note, s_F.note, f"position {k}: M_r by the lever {M_lever:.6g} N·m, by power "
                        f"{g.load.M_r:.6g} N·m"))


@dataclass(frozen=True)
class ZhukovskyLayout:
    """The millimetre constants of the Zhukovsky lever sheet."""

    left_mm: float = 12.0        # the lever's box inside the frame: left
    top_mm: float = 8.0          # below the title
    table_gap_mm: float = 14.0   # left of the result table
    bottom_mm: float = 14.0      # above the captions
    force_mm: float = 30.0       # the force vector's length when μ_F is picked
    arm_offset_mm: float = 8.0   # the arm's dimension line from the arm
    row_mm: float = 7.0          # the result table's rows


LEVER = ZhukovskyLayout()


def result_lettering(page: object, lay: ZhukovskyLayout = LEVER) -> tuple[float, float]:
    """The result table's text size and row height, mm: the sheet's, or on a slide its values' (5 mm once the
    slide's design page is enlarged; at 3.2 mm the table filled a tenth of a slide and left half of it empty).

    >>> from graphmethods.sheets.projector import design_slide
    >>> result_lettering(None), result_lettering(design_slide(1.25))
    ((3.2, 7.0), (4.0, 8.75))
    """
    from graphmethods.sheets.engine.lettering import is_slide, lettering

    if page is None or not is_slide(page):
        return TEXT_MM, lay.row_mm
    size = lettering("SLIDE").value_mm / float(getattr(page, "enlarged", 1.0))
    return size, lay.row_mm * size / TEXT_MM


def _lever_position(study: Study, position: int | None) -> int:
    """The position drawn: the given one (0…m, m being 0 again), or the one with the largest M_r."""
    m = study.m
    if position is None:
        return _default_lever_position(study)
    if isinstance(position, bool) or not isinstance(position, (int, np.integer)) or not 0 <= position <= m:
        raise InputError(f"position {position!r}: give a position number 0…{m}")
    return int(position) % m


def _at(p_page: np.ndarray, off: np.ndarray) -> tuple[float, float]:
    """The page point ``off`` mm from the pole p."""
    q = p_page + off
    return (float(q[0]), float(q[1]))


@dataclass(frozen=True)
class LeverGeometry:
    """The velocity plan at one position turned 90° against ω₁ (m/s), and the load at the image of its point."""

    k: int
    names: tuple[str, ...]
    images: dict[str, np.ndarray]      # m/s, turned
    load: LeverLoad
    F_abs: float                       # N
    Fhat: np.ndarray                   # the force's direction on paper (y down)
    omega_1: float                     # rad/s

    @classmethod
    def of(cls, study: Study, k: int) -> LeverGeometry:
        plans = study.plans
        sense = int(plans.sense)

        def turned(v: object) -> np.ndarray:
            v = np.asarray(v, dtype=float)
            return np.array([v[1], -v[0]]) if sense > 0 else np.array([-v[1], v[0]])

        names = tuple(plans.order)
        ld = lever_load(study, k)
        F = np.asarray(ld.force, dtype=float)
        F_abs = float(np.hypot(*F))
        return cls(k, names, {p: turned(plans.v(p)[k]) for p in names}, ld, F_abs, np.array([F[0], -F[1]]) / F_abs,
                   float(plans.omega_1))

    def paper(self, v: np.ndarray, s_v: Scale) -> np.ndarray:
        """A turned velocity as a paper offset from p (mm, y down)."""
        return np.array([v[0], -v[1]]) / s_v.per_mm

    def on_paper(self, s_v: Scale, f_len: float) -> tuple[dict[str, np.ndarray], np.ndarray, np.ndarray,
                                                          np.ndarray, np.ndarray]:
        """Paper offsets from p (mm) of the images, the force's tip and the arm's foot, and their extent."""
        img = {p: np.array([v[0], -v[1]]) / s_v.per_mm for p, v in self.images.items()}
        b = img[self.load.point]
        tip = b + self.Fhat * f_len
        foot = b - self.Fhat * float(np.dot(b, self.Fhat))              # foot of the perpendicular from p
        cloud = np.vstack(list(img.values()) + [np.zeros(2), tip, foot])
        return img, tip, foot, cloud.min(axis=0), cloud.max(axis=0)


def _pole_on_page(box: Box, lo: np.ndarray, hi: np.ndarray, s_v: Scale, s_F: Scale) -> np.ndarray:
    """Where the pole p stands so that the lever's extent ``lo``…``hi`` (mm from p) is centred in ``box``.

    Raises
    ------
    InputError
        When the lever at the given scales does not fit the box.
    """
    bw, bh = box[2] - box[0], box[3] - box[1]
    if hi[0] - lo[0] > bw + 1e-9 or hi[1] - lo[1] > bh + 1e-9:
        raise InputError(f"the lever at {markup.plain(s_v.caption())} and {markup.plain(s_F.caption())} needs "
                         f"{(hi - lo)[0]:.0f} × {(hi - lo)[1]:.0f} mm but the sheet leaves {bw:.0f} × {bh:.0f} mm; "
                         f"give larger scales or none")
    return np.array([(box[0] + box[2]) / 2, (box[1] + box[3]) / 2]) - (lo + hi) / 2


def _lever_scale(g: LeverGeometry, mu_v: object, box: Box, f_len: float, nt: Notation) -> Scale:
    """μ_v: given, or the first round value at which the lever (images, force, arm) fits the box."""
    u_v = nt.unit("(m/s)")
    if mu_v is not None:
        return mu_v if isinstance(mu_v, Scale) else Scale(nt.sym("dynamics.mu_v"), u_v, mu_v)  # type: ignore[arg-type]
    bw, bh = box[2] - box[0], box[3] - box[1]
    span = max(float(np.ptp([v[0] for v in g.images.values()] + [0.0])) / bw,
               float(np.ptp([v[1] for v in g.images.values()] + [0.0])) / bh)
    for c in sorted({float(f"{mm!r}e{e}") for e in range(math.floor(math.log10(span)) - 1,
                                                            math.floor(math.log10(span)) + 4)
                     for mm in (1.0, 2.0, 2.5, 4.0, 5.0)}):
        if c < span:
            continue
        lo, hi = g.on_paper(Scale(nt.sym("dynamics.mu_v"), u_v, c), f_len)[3:]
        if hi[0] - lo[0] <= bw and hi[1] - lo[1] <= bh:
            return Scale(nt.sym("dynamics.mu_v"), u_v, c, note=f"picked: the lever fits {bw:.0f} × {bh:.0f} mm at "
                                                              f"{nt.number(c)} (m/s)/mm")
    raise InputError("the lever does not fit the sheet; give mu_v and mu_F")  # pragma: no cover - F alone fits


def _lever_lines(study: Study, g: LeverGeometry, p_page: np.ndarray, img: dict[str, np.ndarray], tip: np.ndarray,
                 foot: np.ndarray, f_len: float) -> tuple[list[Element], Vector, list[Element], float]:
    """The lever (p to every image, the links between images), the force, its line of action to the arm's foot."""
    plans = study.plans
    lever_lines: list[Element] = []
    for p in g.names:
        if plans.label(p) == "p" or np.hypot(*g.images[p]) == 0:
            continue
        lever_lines.append(Line(_at(p_page, np.zeros(2)), _at(p_page, img[p]), style=MAIN,
                                name=f"lever-p{plans.label(p)}"))
    for link in study.mechanism.omega_links:
        ends = _link_points(link, list(g.names))
        if ends is None or any(plans.label(e) == "p" for e in ends):
            continue
        a, b = ends
        lever_lines.append(Line(_at(p_page, img[a]), _at(p_page, img[b]), style=MAIN,
                                name=f"lever-{plans.label(a)}{plans.label(b)}"))
    b_img = img[g.load.point]
    force = Vector(_at(p_page, b_img), _at(p_page, tip), name="force-F")
    line_of_action: list[Element] = []
    t_foot = float(np.dot(foot - b_img, g.Fhat))
    if t_foot < 0.0 or t_foot > f_len:         # the foot is off the vector: carry its line of action there
        far = tip if t_foot > f_len else b_img
        line_of_action.append(Line(_at(p_page, far), _at(p_page, foot),
                                   style=Style(width_mm=0.18, dash=(5.0, 1.2, 1.0, 1.2)), name="line-of-action"))
    return lever_lines, force, line_of_action, float(np.hypot(*foot))


def _lever_arm(g: LeverGeometry, p_page: np.ndarray, img: dict[str, np.ndarray], foot: np.ndarray, h_mm: float,
               occ: FastOccupancy, nt: Notation, within: Box) -> tuple[Dimension, Text]:
    """The arm h dimensioned beside it, on the side away from the lever, and its value written along it."""
    u = foot / max(h_mm, 1e-12)
    normal = np.array([-u[1], u[0]])
    centre = np.mean(np.vstack(list(img.values())), axis=0) - foot / 2
    side = -1.0 if float(np.dot(centre, normal)) > 0 else 1.0
    arm = Dimension(_at(p_page, np.zeros(2)), _at(p_page, foot), "", offset_mm=LEVER.arm_offset_mm * side,
                    size_mm=TEXT_MM, name="dimension-h")
    occ.register(arm)
    h_text = f"{nt.sym('dynamics.h')} = {nt.number(h_mm)} {nt.unit('mm')}"
    a_, b_ = np.asarray(arm.line_start), np.asarray(arm.line_end)
    away = np.asarray(arm.line_start) - np.asarray(arm.start)          # from the arm towards its dimension line
    compass = "e" if away[0] > abs(away[1]) else "w" if -away[0] > abs(away[1]) else ("s" if away[1] > 0 else "n")
    order = {"e": ("e", "ne", "se", "w"), "w": ("w", "nw", "sw", "e"), "n": ("n", "ne", "nw", "s"),
             "s": ("s", "se", "sw", "n")}[compass]
    h_lab = None
    for t in (0.5, 0.4, 0.6, 0.3, 0.7):
        h_lab = occ.first_free(tuple((a_ + (b_ - a_) * t).tolist()), h_text, order, (1.2, 2.5), TEXT_MM, within)
        if h_lab is not None:
            break
    if h_lab is None:
        h_lab = occ.place_label_with_leader(tuple(((a_ + b_) / 2).tolist()), h_text, order, size_mm=TEXT_MM,
                                            within=within)[0]
    else:
        occ.add_label(h_lab)
    return arm, Text((h_lab.x, h_lab.y), h_text, size_mm=TEXT_MM, anchor=h_lab.anchor, name="label-h")


def _lever_names(study: Study, g: LeverGeometry, p_page: np.ndarray, img: dict[str, np.ndarray], force: Vector,
                 F_text: str, occ: FastOccupancy, within: Box) -> list[Element]:
    """The images' dots, the names p, a, b, … beside them, and the force's value."""
    plans = study.plans
    dots: list[Element] = []
    for p in g.names:
        lab_text = plans.label(p)
        if lab_text == "p":
            continue
        q = _at(p_page, img[p])
        dots.append(Point(q, radius_mm=0.6, name=f"image-{lab_text}"))
        occ.add_box((q[0] - 0.7, q[1] - 0.7, q[0] + 0.7, q[1] + 0.7))
    labels: list[Element] = []
    pole: list[str | None] = [None]
    for point in pole + list(g.names):
        text = "p" if point is None else plans.label(point)
        if point is not None and text == "p":
            continue
        q = _at(p_page, np.zeros(2)) if point is None else _at(p_page, img[point])
        lab = occ.first_free(q, text, ("ne", "nw", "se", "sw", "n", "s", "e", "w"), (1.0, 3.0, 5.5), TEXT_MM + 0.5,
                             within)
        leader = None
        if lab is None:                         # nothing free beside it (a slide's 5 mm names): off, with a leader
            lab, leader = occ.place_label_with_leader(q, text, size_mm=TEXT_MM + 0.5, gap_mm=1.0, within=within)
        else:
            occ.add_label(lab)
        labels.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM + 0.5, anchor=lab.anchor, name=f"name-{text}"))
        if leader is not None:
            labels.append(Line(leader[0], leader[1], style=THIN, name=f"name-{text}-leader"))
    lab, leader = occ.place_label_with_leader(force.mid, F_text, ("n", "s", "ne", "se", "nw", "sw", "e", "w"),
                                              size_mm=TEXT_MM, gap_mm=1.5, within=within)
    labels.append(Text((lab.x, lab.y), F_text, size_mm=TEXT_MM, anchor=lab.anchor, name="label-F"))
    if leader is not None:
        labels.append(Line(leader[0], leader[1], style=THIN, name="leader-F"))
    return dots + labels


def lever_law(nt: Notation) -> str:
    """The lever's law in the notation's symbols, as the result table and the step caption write it (the zh step
    wrote F·h where its table wrote F_r·h).

    >>> from graphmethods.scene import notation
    >>> lever_law(notation("zh"))
    'F_r·h·μ_v/ω_1'
    """
    return (f"{nt.sym('dynamics.F')}·{nt.sym('dynamics.h')}·{nt.sym('dynamics.mu_v')}/"
            f"{nt.sym('dynamics.omega_1')}")


def _lever_rows(g: LeverGeometry, nt: Notation, F_text: str, h_mm: float, s_v: Scale,
                M_lever: float) -> tuple[tuple[str, str], ...]:
    """The result: M_r = F·h·μ_v/ω₁ worked out on the drawing, beside the power method's value."""
    nb = nt.number
    return (
        (nt.word("dynamics.plan_turned"), f"{nt.sym('dynamics.omega_1')} = {value_text(nt, g.omega_1, 'rad/s')}"),
        (nt.word("dynamics.force"), F_text),
        (nt.word("dynamics.arm"), f"{nt.sym('dynamics.h')} = {nb(h_mm)} {nt.unit('mm')}"),
        (nt.word("dynamics.by_lever"), f"{nt.sym('M_r')} = {lever_law(nt)}"),
        ("", f"= {nb(g.F_abs)}·{nb(h_mm)}·{nb(s_v.per_mm)}/{nb(g.omega_1)}"),
        ("", f"= {value_text(nt, M_lever, 'N·m')}"),
        (nt.word("dynamics.by_power"), f"{nt.sym('M_r')} = {value_text(nt, g.load.M_r, 'N·m')}"),
    )
