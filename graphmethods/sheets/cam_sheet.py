"""The course project's cam sheet, on A1: the motion diagrams, the base radius, the profile by inversion.

Left: the acceleration analogue and its graphical integration by chords to the velocity analogue and
the displacement (:func:`~graphmethods.sheets.cam_diagrams.motion_column`). Middle: the combined
ds/dφ–s diagram with the tangents at [α] and the admissible zone of the cam centre (a translating
follower; an oscillating one shows its pressure angle over the cycle), the pressure angle α(φ) and the
results table. Right: the profile by inversion of motion: the cam centre O, the base circles, the
follower's positions turned back by −φ at the division points (numbered), the pitch curve through the
roller centres, the roller circles and their envelope (or the flat face's lines), the follower in
position 0 and the largest pressure angle marked where it occurs.

Every number printed is the one ``graphmethods cam FILE --json`` prints (the same :class:`CamDesign`).

>>> from graphmethods.kinematics.cam import design
>>> from graphmethods.problems.builtin import cam_problem
>>> s = cam_sheet(design(cam_problem("shaper-cam")))
>>> s.page.size, [e.name for e in s.elements][:2]
('A1', ['title', 'motion'])
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from graphmethods.kinematics.cam import CamDesign, CamProblem, design
from graphmethods.scene import notation as get_notation
from graphmethods.scene.elements import Element, Group, Line, Point, Polyline, Text
from graphmethods.scene.notation import Notation
from graphmethods.scene.page import Page, TitleBlock
from graphmethods.scene.primitives import DASHED, MAIN, THIN, Circle, Primitive, Style
from graphmethods.scene.scale import Scale, pick_scale
from graphmethods.scene.scene import Scene
from graphmethods.sheets.cam_diagrams import (
    HEAD_MM,
    TEXT_MM,
    alpha_graph,
    combined_diagram,
    fitted_table,
    heading,
    motion_column,
    nodes,
    positions_table,
    register_ink,
    rho_graph,
    segment,
)
from graphmethods.sheets.cam_rocker import rocker_diagram
from graphmethods.sheets.engine import course_page, lettering
from graphmethods.sheets.frame import FastOccupancy
from graphmethods.sheets.layout import Box, Occupancy
from graphmethods.sheets.styles import CENTRE_LINE as CENTRES, PROJECTION

TITLE_MM = lettering("A1").title_mm


@dataclass(frozen=True)
class Circles(Element):
    """Circles of one style: ``(x, y, r)`` in mm."""

    circles: tuple[tuple[float, float, float], ...]
    style: Style = THIN
    name: str = "circles"

    def primitives(self) -> tuple[Primitive, ...]:
        return tuple(Circle(x, y, r, self.style) for x, y, r in self.circles)


@dataclass(frozen=True)
class SheetBoxes:
    """The A1 cam sheet's parts (mm, page coordinates)."""

    motion: Box
    combined: Box
    alpha: Box
    table: Box
    profile: Box


def _profile_width(cam: CamDesign, n_div: int, box: Box) -> float:
    """How wide the profile panel needs to be at the scale that fits its height (mm)."""
    pts = inversion(cam, n_div).points()
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    x0, y0, x1, y1 = box
    mu = pick_scale(max((hi[0] - lo[0]) / (x1 - x0 - 10.0), (hi[1] - lo[1]) / (y1 - y0 - HEAD_MM - 20.0)), 1.0)
    return mu.to_mm(float(hi[0] - lo[0])) + 16.0


def _boxes(page: Page, profile_mm: float) -> SheetBoxes:
    """Left: the motion diagrams (1.5°/mm needs 330 mm); right: the profile as wide as its scale needs
    (``profile_mm``) with the combined diagram beside it on the top row, the pressure angle and the table
    below."""
    x0, y0, x1, y1 = page.content_box()
    top = y0 + TITLE_MM + 6.0
    a = x0 + 335.0
    b = max(x1 - profile_mm, a + 140.0)
    low = top + 0.62 * (y1 - top)
    split = a + 0.42 * (x1 - a)
    return SheetBoxes(motion=(x0, top, a - 6.0, y1), combined=(a + 6.0, top, b - 6.0, low),
                      alpha=(a + 6.0, low + 8.0, split - 6.0, y1), table=(split + 4.0, low + 8.0, x1, y1),
                      profile=(b + 4.0, top, x1, low))


def _page(nt: Notation, title: str, problem: str, scales: list[Scale]) -> Page:
    tb = TitleBlock(title, problem, tuple(s.caption(nt) for s in scales[:3]),
                    headings=(nt.word("figure"), nt.word("problem"), nt.word("scales")), size_mm=TEXT_MM)
    return course_page("A1").with_(title_block=tb)


def _rot(points: np.ndarray, phi: np.ndarray, sense: str) -> np.ndarray:
    from graphmethods.kinematics.cam.geometry import to_cam_frame

    return to_cam_frame(points, phi, sense)


@dataclass(frozen=True)
class Inversion:
    """What the inversion draws, in the cam's own frame (m): the curves, the division points' followers."""

    phi_k: np.ndarray                  # division points, rad
    pitch: np.ndarray                  # dense pitch curve
    profile: np.ndarray                # dense profile
    pitch_k: np.ndarray                # pitch points at the division points
    followers: list[np.ndarray]        # each division point's follower axis (translating) or arm (oscillating)
    pivot_arc: np.ndarray | None       # the arc of the pivot's positions (oscillating)
    stem: np.ndarray                   # the follower in position 0: its stem or arm
    faces: tuple[np.ndarray, ...] = ()  # a flat follower's face at each division point, turned back

    def points(self) -> np.ndarray:
        parts = [self.pitch, self.profile, self.stem, np.zeros((1, 2)), *self.followers, *self.faces]
        if self.pivot_arc is not None:
            parts.append(self.pivot_arc)
        return np.vstack(parts)


def inversion(cam: CamDesign, n_div: int) -> Inversion:
    """The inversion's geometry (see :class:`Inversion`); the followers reach 35 % of r₀ (or of h) past the
    pitch point."""
    p = cam.problem
    dense = cam.state(np.linspace(0.0, 360.0, 721))
    phi_k = nodes(cam, n_div)[:-1]
    st = cam.state(np.degrees(phi_k))
    reach = 0.35 * max(cam.pitch_base_radius, p.stroke if not p.oscillating else 0.0)
    followers, arc = [], None
    if p.oscillating:
        pivots = _rot(np.column_stack((np.full(phi_k.shape, p.pivot), np.zeros(phi_k.shape))), phi_k, p.sense)
        followers = [np.array([a, b]) for a, b in zip(pivots, st.pitch)]
        span = float(phi_k.max()) + math.radians(10.0)    # the arc the pivot runs on through the division points
        ang = np.linspace(-math.radians(10.0), span, 1 + int(math.degrees(span + math.radians(10.0)) // 2))
        arc = _rot(np.column_stack((np.full(ang.shape, p.pivot), np.zeros(ang.shape))), ang, p.sense)
        stem = np.array([pivots[0], st.pitch[0]])
    else:
        r = cam.pitch_base_radius
        s0 = math.sqrt(max(r * r - p.offset ** 2, 0.0))
        start = 0.0 if p.offset else 0.35 * s0
        for f, sv in zip(phi_k, st.s):
            pts = np.array([[p.offset, start], [p.offset, s0 + sv + reach]])
            followers.append(_rot(pts, np.array([f, f]), p.sense))
        stem = _rot(np.array([[p.offset, s0], [p.offset, s0 + reach + p.stroke]]), np.zeros(2), p.sense)
    return Inversion(phi_k, dense.pitch, dense.profile, st.pitch, followers, arc, stem, _faces(cam, phi_k))


def _faces(cam: CamDesign, phi_k: np.ndarray) -> tuple[np.ndarray, ...]:
    """A flat follower's face at each division point, turned back: a segment through the contact, ⟂ the axis
    (m; none for a roller or a knife edge). Part of the drawing's extent: the faces ran into the title block."""
    p = cam.problem
    if p.contact != "flat":
        return ()
    s = p.motion(np.degrees(phi_k))[0]
    half = 0.5 * (cam.face_width_min or 0.0) + 0.1 * cam.base_radius
    return tuple(_rot(np.array([[-half, cam.base_radius + sv], [half, cam.base_radius + sv]]), np.array([f, f]),
                      p.sense) for f, sv in zip(phi_k, s))


def profile_panel(cam: CamDesign, box: Box, occ: Occupancy, nt: Notation, *, n_div: int,
                  heading_share: float = 0.9) -> tuple[list[Element], Scale]:
    """The profile by inversion (see the module docstring), as large as the box allows."""
    p = cam.problem
    geo = inversion(cam, n_div)
    pts = geo.points()
    x0, y0, x1, y1 = box
    head, top = heading(box, nt.word("cam.profile"), occ, "profile", share=heading_share)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    mu = pick_scale(max((hi[0] - lo[0]) / (x1 - x0 - 10.0), (hi[1] - lo[1]) / (y1 - top - 12.0)), 1.0,
                    symbol="μ_l", unit="m")
    cx = (x0 + x1) / 2.0 - mu.to_mm((lo[0] + hi[0]) / 2.0)
    cy = (top + 6.0 + y1 - 6.0) / 2.0 + mu.to_mm((lo[1] + hi[1]) / 2.0)

    def P(xy: np.ndarray) -> tuple[tuple[float, float], ...]:
        xy = np.atleast_2d(xy)
        return tuple(zip((cx + xy[:, 0] / mu.per_mm).tolist(), (cy - xy[:, 1] / mu.per_mm).tolist()))
    els: list[Element] = [Circles(((cx, cy, mu.to_mm(cam.base_radius)),), THIN, name="base-circle")]
    if p.contact == "roller":
        els.append(Circles(((cx, cy, mu.to_mm(cam.pitch_base_radius)),), CENTRES, name="pitch-base-circle"))
    if not p.oscillating and p.offset and p.contact != "flat":
        els.append(Circles(((cx, cy, mu.to_mm(abs(p.offset))),), THIN, name="offset-circle"))
    if geo.pivot_arc is not None:
        els.append(Polyline(P(geo.pivot_arc), CENTRES, closed=bool(np.allclose(geo.pivot_arc[0], geo.pivot_arc[-1])),
                            name="pivot-circle"))
    els += [segment(P(line), PROJECTION, name=f"follower-{i}") for i, line in enumerate(geo.followers)]
    if p.contact == "roller":
        els.append(Polyline(P(geo.pitch), CENTRES, closed=True, name="pitch-curve"))
        els.append(Circles(tuple((x, y, mu.to_mm(p.roller_radius)) for x, y in P(geo.pitch_k)), THIN,
                           name="rollers"))
    if p.contact == "flat":
        els += _flat_lines(geo, P)
    els.append(Polyline(P(geo.profile), MAIN, closed=True, name="profile"))
    els += [Point(q, radius_mm=0.7, name=f"B-{i}") for i, q in enumerate(P(geo.pitch_k))]
    els += _follower_at_zero(cam, geo, P, mu)
    els.append(Point((cx, cy), radius_mm=1.0, name="O"))
    register_ink(occ, *els)
    lab = occ.place_label((cx, cy), "O", ("sw", "se", "nw", "ne", "s", "w"), size_mm=TEXT_MM, within=box)
    els.append(Text((lab.x, lab.y), "O", size_mm=TEXT_MM, anchor=lab.anchor, name="O-name"))
    els += _alpha_mark(cam, P, occ, nt, box)
    els += _numbers(P(geo.pitch_k), (cx, cy), occ, box)
    return head + els, mu


def _flat_lines(geo: Inversion, P: Any) -> list[Element]:
    """The flat face at each division point (:func:`_faces`)."""
    return [segment(P(face), THIN, name=f"face-{i}") for i, face in enumerate(geo.faces)]


def _follower_at_zero(cam: CamDesign, geo: Inversion, P: Any, mu: Scale) -> list[Element]:
    """The follower drawn in position 0: roller (or edge, or face) and its stem or arm, heavy."""
    p = cam.problem
    out: list[Element] = [segment(P(geo.stem), MAIN, name="stem-0")]
    if p.oscillating:
        out.append(Point(P(geo.stem[0])[0], radius_mm=1.0, name="pivot-0"))
    if p.contact == "roller":
        (bx, by), = P(geo.pitch_k[0])
        out.append(Circles(((bx, by, mu.to_mm(p.roller_radius)),), MAIN, name="roller-0"))
    return out


def _alpha_mark(cam: CamDesign, P: Any, occ: Occupancy, nt: Notation, box: Box) -> list[Element]:
    """The largest pressure angle: the normal at the contact and the follower's velocity direction through
    the pitch point, where it occurs, and its value written beside them."""
    p = cam.problem
    if p.contact == "flat":
        return []
    rise = cam.alpha_max_rise_deg >= cam.alpha_max_return_deg
    f = cam.phi_alpha_max_rise_deg if rise else cam.phi_alpha_max_return_deg
    a = cam.alpha_max_rise_deg if rise else cam.alpha_max_return_deg
    s, s1, s2, _ = p.motion([f])
    g = cam.frame(s, s1, s2)
    B, W = g.B[0], g.W[0]
    n = np.array([-W[1], W[0]]) / math.hypot(*W)
    u = np.array([0.0, 1.0]) if not p.oscillating else np.array([math.sin(math.atan2(B[1], p.pivot - B[0])),
                                                                  math.cos(math.atan2(B[1], p.pivot - B[0]))])
    L = 0.45 * cam.pitch_base_radius
    rad = np.array([math.radians(f)] * 2)
    out: list[Element] = [segment(P(_rot(np.array([B, B + L * n]), rad, p.sense)), THIN, name="alpha-normal"),
                          segment(P(_rot(np.array([B, B + L * u]), rad, p.sense)), DASHED, name="alpha-velocity")]
    register_ink(occ, *out)
    text = nt.word("cam.alpha_max", sym=nt.sym("cam.alpha"), value=nt.number(a, sig=4))
    at = P(_rot(np.array([B + 0.6 * L * (n + u) / 2]), rad[:1], p.sense))[0]
    lab, leader = occ.place_label_with_leader(at, text, ("ne", "nw", "se", "sw", "e", "w"), size_mm=TEXT_MM,
                                              within=box)
    out.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name="alpha-max"))
    if leader is not None:
        out.append(Line(leader[0], leader[1], THIN, name="alpha-leader"))
    return out


def _numbers(points: tuple[tuple[float, float], ...], centre: tuple[float, float], occ: Occupancy,
             box: Box) -> list[Element]:
    """The division points' numbers beside their pitch points, outward from the cam centre first."""
    out: list[Element] = []
    for i, (x, y) in enumerate(points):
        dx, dy = x - centre[0], y - centre[1]
        ew = "e" if dx > 0 else "w"
        ns = "s" if dy > 0 else "n"
        dirs = (ns + ew, ew, ns, "n", "s", "e", "w", "ne", "nw", "se", "sw")
        lab, leader = occ.place_label_with_leader((x, y), str(i), dirs, size_mm=TEXT_MM, gap_mm=1.5, within=box)
        out.append(Text((lab.x, lab.y), str(i), size_mm=TEXT_MM, anchor=lab.anchor, name=f"number-{i}"))
        if leader is not None:
            out.append(Line(leader[0], leader[1], THIN, name=f"number-{i}-leader"))
    return out


def _m(nt: Notation, v: float) -> str:
    return f"{nt.number(v, sig=4)} {nt.unit('m')}"


def results_rows(cam: CamDesign, nt: Notation, con: Any) -> list[tuple[str, str]]:
    """The results table's rows: (what, value), every value as ``graphmethods cam --json`` prints it."""
    p = cam.problem
    w = nt.word
    sym_a = nt.sym("cam.alpha")
    laws = [w(f"cam.{ph.law}") for ph in p.phases if ph.kind != "dwell"]
    angles = " / ".join(f"{nt.number(ph.angle_deg)}°" for ph in p.phases)
    unit = "°" if p.oscillating else ""
    h = nt.number(math.degrees(p.stroke), sig=4) + "°" if p.oscillating else _m(nt, p.stroke)
    rows = [(w("cam.row_follower"), f"{w('cam.' + p.follower_type)}, {w('cam.' + p.contact)}"),
            (w("cam.row_phases"), angles), (w("cam.row_laws"), " / ".join(laws)),
            (f"{w('cam.row_stroke')} {nt.sym('dynamics.h')}", h),
            (w("cam.row_omega"), f"{nt.number(p.omega, sig=4)} {nt.unit('rad/s')}")]
    if p.contact != "flat":
        rows.append((f"{w('cam.row_limits')} [{sym_a}]",
                     f"{nt.number(p.alpha_max_deg or 0.0)}° / {nt.number(p.alpha_return_max_deg)}°"))
    if p.oscillating:
        rows.append((w("cam.row_arm"), f"{_m(nt, p.arm)}, {_m(nt, p.pivot)}"))
    elif p.contact != "flat":
        rows.append((f"{w('cam.row_offset')} {nt.sym('cam.e')}", _m(nt, p.offset)))
    if p.contact == "roller":
        rows.append((f"{w('cam.row_roller')} {nt.sym('cam.r_r')}", _m(nt, p.roller_radius)))
    how = w("cam.row_given") if not cam.designed else w("cam.row_designed_flat" if p.contact == "flat"
                                                         else "cam.row_designed")
    rows += [(f"{w('cam.row_base')} {nt.sym('cam.r_b')}", f"{_m(nt, cam.base_radius)} ({how})"),
             (f"{w('cam.row_pitch')} {nt.sym('cam.r_0')}", _m(nt, cam.pitch_base_radius))]
    if p.contact != "flat":
        rows.append((f"{w('cam.row_alpha')} {sym_a}_{{max}}", f"{nt.number(cam.alpha_max_rise_deg)}° / "
                     f"{nt.number(cam.alpha_max_return_deg)}°"))
    rho = w("cam.row_rho_flat" if p.contact == "flat" else "cam.row_rho")
    rows += [(f"{rho} {nt.sym('cam.rho')}_{{min}}", _m(nt, cam.rho_pitch_min) if math.isfinite(cam.rho_pitch_min)
              else "∞"), (w("cam.row_undercut"), w("cam.yes" if cam.undercut else "cam.no"))]
    if cam.face_width_min is not None:
        rows.append((w("cam.row_width"), _m(nt, cam.face_width_min)))
    imp = ", ".join(f"{w('cam.' + i.kind)} {nt.number(i.phi_deg)}°" for i in cam.impacts) or w("cam.none")
    exact = con.error_s <= 1e-12 * p.stroke          # steps of a uniform law: the chords are exact
    err = f"{nt.number(0.0 if exact else con.error_s, sig=2)} {nt.unit('rad' if unit else 'm')}"
    rows += [(w("cam.row_impacts"), imp), (w("cam.row_error", n=len(con.nodes)), err)]
    return rows


def cam_sheet(cam: CamDesign | CamProblem, *, notation: Any = "en", n_div: int = 8, name: str = "cam-sheet") -> Scene:
    """The A1 cam sheet of a designed cam (see the module docstring).

    Parameters
    ----------
    cam : CamDesign or CamProblem
        From :func:`graphmethods.kinematics.cam.design` (a problem is designed first).
    notation : {"en", "ru", "zh"}
    n_div : int
        Strips per rise and per return (the division points of the construction and of the inversion).

    Returns
    -------
    Scene
    """
    if isinstance(cam, CamProblem):
        cam = design(cam)
    nt = get_notation(notation)
    title = nt.word("cam.sheet")
    problem = cam.problem.title.title_in(nt.code)
    probe = _page(nt, title, problem, [Scale("μ", "m", 1.0)] * 3)
    x0, y0, x1, y1 = probe.content_box()
    bx = _boxes(probe, _profile_width(cam, n_div, (x1 - 330.0, y0 + TITLE_MM + 6.0, x1, y0 + 0.64 * (y1 - y0))))
    occ = FastOccupancy()
    occ.add_box((x0, y0, x0 + 200.0, y0 + TITLE_MM + 1.5))
    motion, m_scales, con = motion_column(cam, bx.motion, occ, nt, n_div=n_div)
    if cam.problem.contact == "flat":
        mid, mid_scales = rho_graph(cam, bx.combined, occ, nt)
        extra: list[Element] = positions_table(cam, bx.alpha, nt, n_div)
        more: list[Scale] = []
    else:
        if cam.problem.oscillating:
            mid, mid_scale = rocker_diagram(cam, bx.combined, occ, nt, phi_k_deg=np.degrees(nodes(cam, n_div)[:-1]))
        else:
            mid, mid_scale = combined_diagram(cam, bx.combined, occ, nt)
        mid_scales = [mid_scale]
        extra, more = alpha_graph(cam, bx.alpha, occ, nt)
    prof, mu_l = profile_panel(cam, bx.profile, occ, nt, n_div=n_div)
    rows = results_rows(cam, nt, con)
    scales = [mu_l, *m_scales, *mid_scales, *more]
    cap = [(nt.word("scales") if k == 0 else "", s.caption(nt)) for k, s in enumerate(scales)]
    table = fitted_table(bx.table[:2], ((nt.word("cam.results"), ""), *rows, *cap), bx.table, align="ll",
                         name="results")
    page = _page(nt, title, problem, scales)
    elements = (Text((x0, y0 + TITLE_MM), title, size_mm=TITLE_MM, bold=True, name="title"),
                Group(tuple(motion), name="motion"), Group(tuple(mid), name="combined"),
                Group(tuple(extra), name="alpha"), Group(tuple(prof), name="profile"), table)
    return Scene(page, elements, title=title, notation=nt.code, name=name, extra_scales=tuple(scales))


def cam_inversion(cam: CamDesign | CamProblem, *, notation: Any = "en", page: Page | None = None,
                  title_block: bool = True, n_div: int = 8, name: str = "cam-inversion") -> Scene:
    """The profile by inversion alone, on its own page (A4 landscape by default): the lecture's figure.

    Its elements are the profile panel's, by name (``base-circle``, ``follower-k``, ``B-k``, ``number-k``,
    ``pitch-curve``, ``rollers``, ``profile``, ``stem-0``, ``alpha-…``), so the steps can split it.

    >>> from graphmethods.problems.builtin import cam_problem
    >>> s = cam_inversion(cam_problem("oscillating-cam"))
    >>> s.page.size, "pivot-circle" in [e.name for e in s.elements]
    ('A4', True)
    """
    if isinstance(cam, CamProblem):
        cam = design(cam)
    nt = get_notation(notation)
    title = nt.word("cam.inversion")
    pg = page if page is not None else Page("A4", "landscape", frame=True)
    probe = pg if pg.title_block is not None or not title_block else pg.with_(title_block=TitleBlock(
        title, cam.problem.title.title_in(nt.code), ("μ_l",),
        headings=(nt.word("figure"), nt.word("problem"), nt.word("scales")), size_mm=TEXT_MM))
    occ = FastOccupancy()
    els, mu = profile_panel(cam, probe.content_box(), occ, nt, n_div=n_div, heading_share=0.55)
    if title_block and probe.title_block is not None:
        probe = probe.with_(title_block=replace(probe.title_block, scales=(mu.caption(nt),)))
    return Scene(probe, tuple(els), title=title, notation=nt.code, name=name, extra_scales=(mu,))


__all__ = ["cam_inversion", "cam_sheet", "profile_panel", "results_rows"]
