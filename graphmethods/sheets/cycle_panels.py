"""The three-panel figure of a cycle: M_d and M_r, ΔE and ω one above the other on one φ axis.

The Chinese chapter's figure (机械的运转及其速度波动的调节): the moments, the energy they store and
release, and the speed it gives, each to its own value scale but all to one φ scale, so a vertical
through any angle reads the three together; the energy is highest and lowest where M_d and M_r cross,
and ω with it. Drawn for a cycle problem given by moment curves (W3, W4), from
:func:`graphmethods.problems.cycle_motion.cycle_motion`, on A4 portrait, scale-true.

>>> from graphmethods.problems import w3
>>> s = cycle_panels(w3())
>>> [c.caption("en") for c in s.scales()]
['μ_φ = 0.05236 rad/mm (3°/mm)', 'μ_M = 2 N·m/mm', 'μ_E = 1 J/mm', 'μ_ω = 0.02 (rad/s)/mm']
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphmethods.scene import Axis, Frame, Page, Polyline, Scene, Text, axis_ticks, notation as get_notation
from graphmethods.scene.elements import pi_ticks
from graphmethods.scene.primitives import MAIN
from graphmethods.sheets.dynamics import SMALL_MM, SheetFrame, suppressed_base
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
    legend = (f"J = {n(cm.J, sig=4)} {nt.unit(problem.inertia_unit)}; ω_{{max}} = {n(float(w.max()), sig=4)}, "
              f"ω_{{min}} = {n(float(w.min()), sig=4)} {nt.unit('rad/s')}")
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
    legend = (f"{nt.sym('dynamics.J_F')} = {n(ex.J_F, sig=4)} {nt.unit('kg·m²')}; "
              f"{nt.sym('dynamics.omega_max')} = {n(mo.omega_max, sig=4)}{nt.list_separator}"
              f"{nt.sym('dynamics.omega_min')} = {n(mo.omega_min, sig=4)} {nt.unit('rad/s')}; δ = {n(mo.delta, sig=3)}")
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


def panels_scene(data: PanelData, *, nt, title: str | None, problem: str) -> Scene:
    """Lay out and draw :class:`PanelData` on A4 portrait (the three panels, captions, legend)."""
    P, ph2, Md2, Mr2, phi, E, w = data.period, data.phi_M, data.M_d, data.M_r, data.phi, data.delta_E, data.omega
    title = title or nt.word("motion.cycle_panels")
    mu, wu = data.moment_unit, data.work_unit
    sheet = SheetFrame(nt=nt, page=None, title=title, problem=problem, title_block=True,
                       default_page=Page("A4", "portrait", frame=True))
    x0, _, x1, _ = sheet.box
    px0, px1 = x0 + 24.0, x1 - 22.0
    top, bottom = sheet.top + 8.0, sheet.caption_y - 40.0
    gap = 14.0
    h = (bottom - top - 2 * gap) / 3.0
    s_phi = given_angle_scale(None, nt.sym("mu_phi"), P, px1 - px0)
    M_hi = float(max(Md2.max(), Mr2.max(), 0.0))
    M_lo = float(min(Md2.min(), Mr2.min(), 0.0))
    s_M = given_scale(None, nt.sym("mu_M"), nt.unit(mu), M_hi - M_lo, h, what="the moments")
    E_lo, E_hi = float(min(E.min(), 0.0)), float(max(E.max(), 0.0))
    s_E = given_scale(None, "μ_E", nt.unit(wu), max(E_hi - E_lo, 1e-12), h, what="the energy")
    w_lo, w_hi = float(w.min()), float(w.max())
    uw = f"({nt.unit('rad/s')})"
    w_base = suppressed_base(w_lo, w_hi, given_scale(None, nt.sym("dynamics.mu_omega"), uw,
                                                     max(w_hi - w_lo, 1e-12) * 1.4, h, what="ω"), zero=None)
    s_w = given_scale(None, nt.sym("dynamics.mu_omega"), uw, max(w_hi - w_base, 1e-12), h, what="ω")
    ticks, labels = pi_ticks(P, s_phi, min_gap_mm=14.0)
    els = [sheet.header()]
    panels = [("M", s_M, M_lo, M_hi, nt.quantity(nt.sym("M"), mu)),
              ("E", s_E, E_lo, E_hi, nt.quantity("ΔE", wu)),
              ("omega", s_w, w_base, w_hi, nt.quantity(nt.sym("dynamics.omega"), "rad/s"))]
    frames = {}
    y_top = top
    for key, s_y, lo, hi, label in panels:
        origin = (px0, y_top + s_y.to_mm(hi))          # the page point of φ = 0 and the value 0
        f = Frame(origin, s_phi, s_y)
        level = lo if lo > 0 else 0.0                  # the φ axis at 0, or at the suppressed base
        ax_phi = Axis((px0, f.pt(0.0, level)[1]), s_phi, "x", min_value=0.0, max_value=P, ticks=ticks,
                      tick_labels=labels, label=nt.sym("phi"), size_mm=SMALL_MM, name=f"{key}-axis-phi",
                      labels_side="above" if hi <= 0 else "")
        yt = tuple(v for v in axis_ticks(lo, hi, s_y, min_gap_mm=7.0) if lo <= v <= hi)
        ax_y = Axis(origin, s_y, "y", min_value=lo, max_value=hi, ticks=yt, label=label, size_mm=SMALL_MM,
                    decimal=nt.decimal, name=f"{key}-axis-y", skip_zero_label=lo < 0)
        els += [ax_phi, ax_y]
        frames[key] = f
        y_top += h + gap
    fM, fE, fw = frames["M"], frames["E"], frames["omega"]
    els.append(Polyline(fM.pts(ph2, Mr2), style=MAIN, name="curve-M_r"))
    els.append(Polyline(fM.pts(ph2, Md2), style=DASHED, name="curve-M_d"))
    # a curve is named at its peak, a constant at the period's end (an engine's M_r, a machine's M_d)
    for key, vals, dy in (("M_r", Mr2, -1.5), ("M_d", Md2, -2.5)):
        if float(np.ptp(vals)) > 1e-9 * max(1.0, float(np.abs(vals).max())):
            k_top = int(np.argmax(np.abs(vals)))
            at = fM.pt(float(ph2[k_top]), float(vals[k_top]))
            pos = (at[0] + 4.0, at[1] + (5.0 if vals[k_top] >= 0 else -3.0))
        else:
            at = fM.pt(P, float(vals[-1]))
            pos = (at[0] + 2.0, at[1] + dy)
        els.append(Text(pos, nt.sym(key), size_mm=TEXT_MM, name=f"name-{key}"))
    els.append(Polyline(fE.pts(phi, E), style=MAIN, name="curve-delta_E"))
    els.append(Polyline(fw.pts(phi, w), style=MAIN, name="curve-omega"))
    # verticals through the boundaries of the excess-work table (the crossings), through all panels
    for k, b in enumerate(data.guides):
        if 1e-9 < b < P - 1e-9:
            xa = fM.pt(b, 0.0)[0]
            ya, yb = fM.pt(b, M_hi)[1], fw.pt(b, w_base)[1]
            els.append(Polyline(((xa, ya), (xa, yb)), style=GUIDE, name=f"guide-{k}"))
    legend = data.legend
    scales = (s_phi, s_M, s_E, s_w)
    els += sheet.captions(scales[:2], legend="")
    els.append(Text((x0, sheet.caption_y - 6.0), "   ".join(s.caption(nt) for s in scales[2:]), size_mm=TEXT_MM,
                    name="scale-captions-2"))
    els.append(Text((x0, sheet.caption_y - 12.0), legend, size_mm=TEXT_MM, name="legend"))
    # the title block's line holds the three value scales (all four are captioned under the figure)
    short = scales[1:]
    return Scene(sheet.page(short), tuple(els), title=sheet.title, notation=nt.code, name="cycle-panels",
                 notes=tuple(s.note for s in scales))
