"""The three-panel figure of a cycle: M_d and M_r, ΔE and ω one above the other on one φ axis.

The Chinese chapter's figure (机械的运转及其速度波动的调节): the moments, the energy they store and
release, and the speed it gives, each to its own value scale but all to one φ scale, so a vertical
through any angle reads the three together; the energy is highest and lowest where M_d and M_r cross,
and ω with it. Drawn for a cycle problem given by moment curves (W3, W4), from
:func:`graphmethods.problems.cycle_motion.cycle_motion`, on A4 portrait, scale-true.

>>> from graphmethods.problems import w3
>>> s = cycle_panels(w3())
>>> [c.caption("en") for c in s.scales()]
['μ_φ = 0.05236 rad/mm (3°/mm)', 'μ_M = 1 N·m/mm', 'μ_E = 0.5 J/mm', 'μ_ω = 0.02 (rad/s)/mm']
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphmethods.scene import Axis, Frame, Page, Polyline, Scale, Scene, Text, axis_ticks, notation as get_notation
from graphmethods.scene.elements import pi_ticks
from graphmethods.scene.primitives import MAIN
from graphmethods.sheets.dynamics import SMALL_MM, SheetFrame, suppressed_base
from graphmethods.sheets.engine.labels import Ink
from graphmethods.sheets.layout import TEXT_MM, given_angle_scale, given_scale
from graphmethods.sheets.styles import PART, PROJECTION

DASHED, GUIDE = PART, PROJECTION


def cycle_panels(problem, *, notation="en", title: str | None = None, samples: int = 1441) -> Scene:
    """M_d and M_r (top), ΔE (middle) and ω (bottom) against φ on one angle scale (A4 portrait).

    Parameters
    ----------
    problem : CycleProblem
        A cycle problem given by moment curves, with ω0 or n and [δ].
    notation : {"en", "ru", "zh"}
    samples : int
        Angles drawn over the period (the curves' knots and crossings are added).
    """
    from graphmethods.problems.cycle_motion import cycle_motion

    nt = get_notation(notation)
    cm = cycle_motion(problem)
    ew = problem.excess_work
    P = cm.period
    D = ew.M_d - ew.M_r
    phi = np.unique(np.concatenate([np.linspace(0.0, P, samples), D.phi - D.start, ew.phi - D.start]))
    phi = phi[(phi >= 0) & (phi <= P)]
    # jumps: draw both sides (left limit just before the knot)
    left_d, Md = ew.M_d.limits(phi + D.start)
    left_r, Mr = ew.M_r.limits(phi + D.start)
    Md[-1], Mr[-1] = left_d[-1], left_r[-1]          # the period ends on its left limit (no wrap)
    ph2 = np.repeat(phi, 2)
    Md2 = np.column_stack([left_d, Md]).ravel()
    Mr2 = np.column_stack([left_r, Mr]).ravel()
    wu = problem.work_unit
    n = nt.number
    w = cm.omega_at(phi)
    w_max, w_min = nt.column((float(w.max()), float(w.min())))          # one digits rule: 11,80 by 7,793
    legend = (f"J = {n(cm.J, sig=4)} {nt.unit(problem.inertia_unit)}; ω_{{max}} = {w_max}{nt.list_separator}"
              f"ω_{{min}} = {w_min} {nt.unit('rad/s')}")
    if cm.delta is not None:
        legend += f"; δ = {n(cm.delta, sig=3)}"
    data = PanelData(period=P, phi_M=ph2, M_d=Md2, M_r=Mr2, phi=phi, delta_E=cm.delta_E(phi), omega=w,
                     guides=tuple(float(b) for b in np.asarray(ew.phi, dtype=float) - D.start),
                     moment_unit=wu if wu != "J" else "N·m", work_unit=wu, legend=legend)
    return panels_scene(data, nt=nt, title=title, problem=problem.title)


def linkage_panels(study, *, notation="en", title: str | None = None, samples: int = 720) -> Scene:
    """The three-panel figure of a linkage problem's steady cycle with its exact flywheel.

    The moments are the reduced ones, exact at every drawn angle (the load's jumps drawn on both
    sides); for an engine (the load drives the crank) the driving moment is the curve and the
    resisting moment the constant (:meth:`graphmethods.dynamics.study.Study.moment_curves`). ΔE and
    ω are those of the steady motion with J_e(φ) + J_F, J_F exact for [δ]
    (:func:`~graphmethods.dynamics.motion.periodic_motion`); the guides pass through the crossings of
    M_d and M_r.

    >>> from graphmethods.dynamics.study import Study
    >>> from graphmethods.problems.builtin import case
    >>> s = linkage_panels(Study(case("press")))
    >>> s.name, len(s.scales())
    ('linkage-panels', 4)
    """
    from graphmethods.dynamics.motion import periodic_motion
    from graphmethods.sheets.dynamics import problem_text

    nt = get_notation(notation)
    P = 2.0 * np.pi
    ex = study.exact
    mo = periodic_motion(study.model, J_F=ex.J_F, omega_m=study.omega_m, positions=int(samples))
    phi = np.asarray(mo.phi, dtype=float) - mo.phi_0
    sw = [float(a) for a in study.switch_angles if 1e-12 < a < P - 1e-12]
    phi_M = np.unique(np.concatenate([phi, sw]))
    M_d, M_r = study.moment_curves(phi_M)
    left_d, left_r = study.moment_curves(np.maximum(phi_M - 1e-9, 0.0))
    ph2 = np.repeat(phi_M, 2)
    Md2 = np.column_stack([left_d, M_d]).ravel()
    Mr2 = np.column_stack([left_r, M_r]).ravel()
    D = Md2 - Mr2
    guides = [float(ph2[k] + (ph2[k + 1] - ph2[k]) * D[k] / (D[k] - D[k + 1]))
              for k in range(D.size - 1) if D[k] * D[k + 1] < 0 or (D[k] == 0 and k > 0)]
    n = nt.number
    # the symbols of the dynamic sheet (J_м in Russian); "158,1; ω_min" where a comma is the decimal mark
    w_max, w_min = nt.column((float(mo.omega_max), float(mo.omega_min)))   # one digits rule for the pair
    legend = (f"{nt.sym('dynamics.J_F')} = {n(ex.J_F, sig=4)} {nt.unit('kg·m²')}; "
              f"{nt.sym('dynamics.omega_max')} = {w_max}{nt.list_separator}"
              f"{nt.sym('dynamics.omega_min')} = {w_min} {nt.unit('rad/s')}; δ = {n(mo.delta, sig=3)}")
    data = PanelData(period=P, phi_M=ph2, M_d=Md2, M_r=Mr2, phi=phi, delta_E=np.asarray(mo.delta_E, dtype=float),
                     omega=np.asarray(mo.omega, dtype=float), guides=tuple(guides), moment_unit="N·m",
                     work_unit="J", legend=legend)
    scene = panels_scene(data, nt=nt, title=title, problem=problem_text(study, nt))
    return Scene(scene.page, scene.elements, title=scene.title, notation=scene.notation, name="linkage-panels",
                 notes=scene.notes)


@dataclass(frozen=True, eq=False)
class PanelData:
    """What the three panels draw, in physical units over one period from its start (φ in rad).

    ``phi_M``, ``M_d``, ``M_r``: the moment curves (a jump is two points at one angle); ``phi``,
    ``delta_E``, ``omega``: the energy (J) and speed (rad/s); ``guides``: angles of the verticals
    (the crossings of M_d and M_r); ``legend``: the line of results under the figure.
    """

    period: float
    phi_M: np.ndarray
    M_d: np.ndarray
    M_r: np.ndarray
    phi: np.ndarray
    delta_E: np.ndarray
    omega: np.ndarray
    guides: tuple
    moment_unit: str
    work_unit: str
    legend: str


def _panel_scales(data: PanelData, nt, room_mm: float, gap: float) -> list[tuple[Scale, float, float]]:
    """Each panel's convenient scale, lowest and highest value (M, ΔE, ω; ω from its suppressed base).

    A convenient scale leaves a panel up to 2.5 times lower than its third of ``room_mm``: the room the others
    leave is offered to each in turn, so the panels fill the page from the title to the legend."""
    Md2, Mr2, E, w = data.M_d, data.M_r, data.delta_E, data.omega
    mu, wu, uw = data.moment_unit, data.work_unit, f"({nt.unit('rad/s')})"
    M_lo, M_hi = float(min(Md2.min(), Mr2.min(), 0.0)), float(max(Md2.max(), Mr2.max(), 0.0))
    E_lo, E_hi = float(min(E.min(), 0.0)), float(max(E.max(), 0.0))
    w_lo, w_hi = float(w.min()), float(w.max())

    def scales_for(hs: list[float]) -> list[tuple[Scale, float, float]]:
        s_M = given_scale(None, nt.sym("mu_M"), nt.unit(mu), M_hi - M_lo, hs[0], what="the moments")
        s_E = given_scale(None, "μ_E", nt.unit(wu), max(E_hi - E_lo, 1e-12), hs[1], what="the energy")
        w_base = suppressed_base(w_lo, w_hi, given_scale(None, nt.sym("dynamics.mu_omega"), uw,
                                                         max(w_hi - w_lo, 1e-12) * 1.4, hs[2], what="ω"), zero=None)
        s_w = given_scale(None, nt.sym("dynamics.mu_omega"), uw, max(w_hi - w_base, 1e-12), hs[2], what="ω")
        return [(s_M, M_lo, M_hi), (s_E, E_lo, E_hi), (s_w, w_base, w_hi)]

    h = (room_mm - 2 * gap) / 3.0
    picked = scales_for([h, h, h])
    for i in range(3):
        used = [sc.to_mm(hi - lo) for sc, lo, hi in picked]
        trial = list(used)
        trial[i] += room_mm - sum(used) - 2 * gap
        again = scales_for(trial)
        if again[i][0].to_mm(again[i][2] - again[i][1]) > used[i] + 1e-9:
            picked[i] = again[i]
    return picked


def _curve_names(els: list, fM: Frame, data: PanelData, nt) -> list:
    """M_d and M_r named at a curve's peak, a constant's at the period's end, each where no line is."""
    ink = Ink()
    ink.add_primitives([p for e in els[1:] for p in e.primitives()])
    out: list = []
    for key, vals in (("M_r", data.M_r), ("M_d", data.M_d)):
        if float(np.ptp(vals)) > 1e-9 * max(1.0, float(np.abs(vals).max())):
            k_top = int(np.argmax(np.abs(vals)))
            at = fM.pt(float(data.phi_M[k_top]), float(vals[k_top]))
            dirs: tuple[str, ...] = ("ne", "nw", "e", "w", "se", "sw") if vals[k_top] >= 0 else ("se", "sw", "e", "w")
        else:
            at = fM.pt(data.period, float(vals[-1]))
            dirs = ("e", "ne", "se", "n", "s")
        lab, leader = ink.place(at, nt.sym(key), size_mm=TEXT_MM, directions=dirs, gap_mm=1.5)
        out.append(Text((lab.x, lab.y), nt.sym(key), size_mm=TEXT_MM, anchor=lab.anchor, name=f"name-{key}"))
        if leader is not None:
            out.append(Polyline(leader, style=GUIDE, name=f"leader-{key}"))
    return out


def _guides(data: PanelData, fM: Frame, axis_y: dict) -> list:
    """Verticals through the boundaries of the excess-work table (the crossings), through every panel, broken
    where a panel's φ axis writes its values (a guide through "π/2" struck it out) and between the panels."""
    band = SMALL_MM * 1.6
    pieces: list[tuple[float, float]] = []          # each panel's height, less the band of its φ values
    for y_hi, y_lo, y_axis, above, inside in axis_y.values():
        if inside:
            pieces.append((y_hi, y_lo))
        elif above:
            pieces += [(y_hi, y_axis - band), (y_axis, y_lo)]
        else:
            pieces += [(y_hi, y_axis), (y_axis + band, y_lo)]
    out: list = []
    for k, b in enumerate(data.guides):
        if 1e-9 < b < data.period - 1e-9:
            xa = fM.pt(b, 0.0)[0]
            out += [Polyline(((xa, u), (xa, v)), style=GUIDE, name=f"guide-{k}" + (f"-{j}" if j else ""))
                    for j, (u, v) in enumerate(pieces) if v - u > 0.5]
    return out


def panels_scene(data: PanelData, *, nt, title: str | None, problem: str) -> Scene:
    """Lay out and draw :class:`PanelData` on A4 portrait (the three panels, captions, legend)."""
    P, ph2, phi = data.period, data.phi_M, data.phi
    title = title or nt.word("motion.cycle_panels")
    mu, wu = data.moment_unit, data.work_unit
    sheet = SheetFrame(nt=nt, page=None, title=title, problem=problem, title_block=True,
                       default_page=Page("A4", "portrait", frame=True))
    x0, _, x1, _ = sheet.box
    px0, px1 = x0 + 24.0, x1 - 22.0
    top, bottom = sheet.top + 8.0, sheet.caption_y - 22.0     # the legend and the captions under the ω panel
    gap = 14.0
    s_phi = given_angle_scale(None, nt.sym("mu_phi"), P, px1 - px0)
    picked = _panel_scales(data, nt, bottom - top, gap)
    ticks, labels = pi_ticks(P, s_phi, min_gap_mm=14.0)
    els = [sheet.header()]
    names = (("M", nt.quantity(nt.sym("M"), mu)), ("E", nt.quantity("ΔE", wu)),
             ("omega", nt.quantity(nt.sym("dynamics.omega"), "rad/s")))
    # the room the convenient scales leave goes into the gaps: the three fill the page to the legend
    gap += max((bottom - top) - sum(s_y.to_mm(hi - lo) for s_y, lo, hi in picked) - 2 * gap, 0.0) / 2.0
    frames, axis_y = {}, {}
    y_top = top
    for (key, label), (s_y, lo, hi) in zip(names, picked):
        origin = (px0, y_top + s_y.to_mm(hi))          # the page point of φ = 0 and the value 0
        f = Frame(origin, s_phi, s_y)
        level = lo if lo > 0 else 0.0                  # the φ axis at 0, or at the suppressed base
        # an axis inside its panel (values on both sides of 0) is crossed by its curve: its φ values are read
        # on the panels below, on the one φ scale, and the guides carry them up
        inside = lo < -1e-9 * max(abs(hi), abs(lo))    # the axis not at the panel's foot (round-off aside)
        ax_phi = Axis((px0, f.pt(0.0, level)[1]), s_phi, "x", min_value=0.0, max_value=P,
                      ticks=() if inside else ticks, tick_labels=() if inside else labels, label=nt.sym("phi"),
                      size_mm=SMALL_MM, name=f"{key}-axis-phi", labels_side="above" if hi <= 0 else "")
        yt = tuple(v for v in axis_ticks(lo, hi, s_y, min_gap_mm=7.0) if lo <= v <= hi)
        ax_y = Axis(origin, s_y, "y", min_value=lo, max_value=hi, ticks=yt, label=label, size_mm=SMALL_MM,
                    decimal=nt.decimal, name=f"{key}-axis-y", skip_zero_label=lo < 0)
        els += [ax_phi, ax_y]
        frames[key] = f
        axis_y[key] = (f.pt(0.0, hi)[1], f.pt(0.0, lo)[1], f.pt(0.0, level)[1], hi <= 0, inside)
        y_top += s_y.to_mm(hi - lo) + gap
    fM, fE, fw = frames["M"], frames["E"], frames["omega"]
    els.append(Polyline(fM.pts(ph2, data.M_r), style=MAIN, name="curve-M_r"))
    els.append(Polyline(fM.pts(ph2, data.M_d), style=DASHED, name="curve-M_d"))
    els += _curve_names(els, fM, data, nt)
    els.append(Polyline(fE.pts(phi, data.delta_E), style=MAIN, name="curve-delta_E"))
    els.append(Polyline(fw.pts(phi, data.omega), style=MAIN, name="curve-omega"))
    els += _guides(data, fM, axis_y)
    scales = (s_phi,) + tuple(sc for sc, _, _ in picked)
    els += sheet.captions(scales[:2], legend="")
    els.append(Text((x0, sheet.caption_y - 6.0), "   ".join(s.caption(nt) for s in scales[2:]), size_mm=TEXT_MM,
                    name="scale-captions-2"))
    els.append(Text((x0, sheet.caption_y - 12.0), data.legend, size_mm=TEXT_MM, name="legend"))
    # the title block's line holds the three value scales (all four are captioned under the figure)
    return Scene(sheet.page(scales[1:]), tuple(els), title=sheet.title, notation=nt.code, name="cycle-panels",
                 notes=tuple(s.note for s in scales))
