"""The work diagrams by graphical integration: M_d, M_r(φ) over the works A_d, A_r(φ) over ΔE(φ), with the
pole and its rays (split out of :mod:`graphmethods.sheets.calculus`, whose common parts it uses)."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from graphmethods.dynamics import graphical_calculus as gc
from graphmethods.errors import InputError
from graphmethods.scene import markup, notation as get_notation
from graphmethods.scene.elements import Element, Line, Point, Polyline
from graphmethods.scene.notation import Notation
from graphmethods.scene.page import Page
from graphmethods.scene.primitives import THIN
from graphmethods.scene.scale import Scale, pick_angle_scale, pick_scale
from graphmethods.scene.scene import Scene
from graphmethods.sheets.calculus import (
    LAYOUT,
    RAY,
    RESULT,
    _Band,
    _broken_behind,
    _column_table,
    _column_width,
    _curve_names,
    _fan_side,
    _fmt,
    _h_dimension,
    _pole,
    _side_block,
    _strip_axes,
)
from graphmethods.sheets.engine.lettering import is_slide
from graphmethods.sheets.layout import TEXT_MM, Occupancy, Sheet, problem_title
from graphmethods.sheets.styles import PROJECTION

# ----------------------------------------------------------------------------- 2. work diagrams

def _moment_subject(subject: Any, m: int, nt: Notation) -> tuple[Any, Any, np.ndarray, Any, str]:
    """(M_d, M_r, phi, study-or-None, problem text in the notation's language) from a Study, a Case, a
    cycle problem or a pair."""
    if hasattr(subject, "moments") and hasattr(subject, "model"):            # a Study
        M_d, M_r = subject.moments
        return M_d, M_r, np.asarray(subject.phi, dtype=float), subject, problem_title(subject.case, nt)
    if hasattr(subject, "mechanism") and hasattr(subject, "load"):           # a linkage problem
        from graphmethods.dynamics.study import Study

        return _moment_subject(Study(subject, positions=m), m, nt)
    cyc, prob = subject, ""
    if not hasattr(subject, "M_r") or getattr(subject, "M_r", None) is None or not hasattr(subject, "E"):
        ew_ = getattr(subject, "excess_work", None)
        if ew_ is not None and getattr(ew_, "M_r", None) is not None:
            cyc, prob = ew_, problem_title(subject, nt)
    if isinstance(subject, (tuple, list)) and len(subject) == 2:
        M_d, M_r = subject
    elif getattr(cyc, "M_d", None) is not None and getattr(cyc, "M_r", None) is not None:
        M_d, M_r = cyc.M_d, cyc.M_r
    else:
        raise InputError("work_diagrams needs moment curves: a linkage study or problem, a cycle problem given "
                         "by M_d and M_r, or a pair (M_d, M_r) of MomentCurves; areas or works fix no curves")
    for c in (M_d, M_r):
        if not (hasattr(c, "integral") and hasattr(c, "phi")):
            raise InputError(f"work_diagrams: expected MomentCurves, got {type(c).__name__}")
    if isinstance(m, bool) or not isinstance(m, (int, np.integer)) or m < 2:
        raise InputError(f"the number of intervals m must be an integer ≥ 2, got {m!r}")
    phi = M_r.start + np.linspace(0.0, M_r.period, int(m) + 1)
    return M_d, M_r, phi, None, prob


def _accuracy_rows(nt: Notation, wd: gc.WorkDiagrams, work_unit: str, *,
                   across: bool = False) -> list[tuple[str, ...]]:
    """The accuracy table: a row per construction (A_d, A_r, ΔE) and its differences from the exact integral
    in columns; ``across``: a column per construction (a slide's right column is narrow: the long headings go
    down its first column, 110 mm wide where the rows make 165 mm and leave the diagrams half the slide)."""
    rows = _accuracy_by_construction(nt, wd, work_unit)
    return [tuple(col) for col in zip(*rows)] if across else rows


def _accuracy_by_construction(nt: Notation, wd: gc.WorkDiagrams, work_unit: str) -> list[tuple[str, ...]]:
    wu, mm = nt.unit(work_unit), nt.unit("mm")
    noise = 1e-9 * (float(np.abs(np.concatenate((wd.A_d.values, wd.A_r.values))).max()) or 1.0)

    def cells(value: float | None, value_mm: float) -> tuple[str, str]:   # rounding noise of an exact
        # construction is written 0
        if value is None:
            return "", ""
        exact = abs(value) <= noise
        return (f"{_fmt(nt, 0.0 if exact else value)} {wu}", f"{_fmt(nt, 0.0 if exact else value_mm, 2)} {mm}")

    on_sheet = nt.word("calculus.on_sheet")
    rows: list[tuple[str, ...]] = [(nt.word("calculus.construction"), nt.word("calculus.at_ends"), on_sheet,
                                    nt.word("calculus.inside"), on_sheet)]
    symbol = {"A_d": nt.sym("calculus.A_d"), "A_r": nt.sym("calculus.A_r"), "ΔE": nt.sym("dE")}
    for r in wd.comparison():
        rows.append((symbol[r["quantity"]],) + cells(r["error"], r["error_mm"]) + cells(r["inside"], r["inside_mm"]))
    return rows


def _accuracy_title(nt: Notation, study: Any) -> str:
    title = nt.word("calculus.accuracy_work")
    if study is not None:
        drawn = nt.word("calculus.drawn", M=nt.sym("M_r"))
        title += f"（{drawn}）" if nt.code == "zh" else f" ({drawn})"
    return title


@dataclass(frozen=True)
class _WorkScales:
    """The scales and pole distance of the work diagrams, the construction drawn at them, and where."""

    s_phi: Scale
    s_M: Scale
    s_A: Scale
    H: float
    wd: gc.WorkDiagrams
    gx0: float
    top: float
    strip_mm: float
    right_col: float
    M_lo: float
    M_hi: float
    period: float
    across: bool = False            # the accuracy table a column per construction (a slide)


def _work_angle_scale(mu_phi: Any, nt: Notation, period: float, width: float) -> Scale:
    """μ_φ given (checked to fit ``width`` mm) or picked to fill it."""
    if mu_phi is None:
        return pick_angle_scale(period, width, symbol=nt.sym("mu_phi"))
    s = mu_phi if isinstance(mu_phi, Scale) else Scale(nt.sym("mu_phi"), "rad", mu_phi)
    if s.to_mm(period) > width + 1e-9:
        raise InputError(f"the period at {markup.plain(s.caption())} needs {s.to_mm(period):.1f} mm but the "
                         f"sheet leaves {width:.1f} mm; give a larger μ_φ or none")
    return s


def _pick_pole(box: tuple[float, float], right_col: float, period: float, strip_mm: float, s_M: Scale, *,
               nt: Notation, A_span: float, mu_M_given: bool, mu_phi: Any, H_mm: float | None
               ) -> tuple[Scale, Scale, float, float]:
    """(μ_φ, μ_M, H, pole room): H given, or the smallest convenient H whose diagrams fit the strip; the
    pole must fit left of the moment diagram (its room grows up to ``max_pole_room_mm``, then μ_M grows)."""
    from graphmethods.units import CONVENIENT, convenient_at_least

    L, (x0, x1) = LAYOUT, box

    def width(room: float) -> float:
        return x1 - right_col - L.column_gap_mm - (x0 + room + L.graph_gap_mm)

    room = L.pole_room_mm
    for _ in range(8):
        s_phi = _work_angle_scale(mu_phi, nt, period, width(room))
        if H_mm is not None:
            H = float(H_mm)
            if not (math.isfinite(H) and H > 0):
                raise InputError(f"H_mm = {H_mm!r}: the pole distance must be a positive number of mm")
            break
        H = convenient_at_least(A_span / (s_M.per_mm * s_phi.per_mm * (strip_mm - L.dim_room_mm)), gc.POLE_SERIES)
        if H + L.graph_gap_mm <= room:
            break
        if room < L.max_pole_room_mm:       # first give the pole more room (μ_φ may grow with it) …
            room = min(H + L.graph_gap_mm, L.max_pole_room_mm)
        elif not mu_M_given:                # … then draw the moments smaller
            s_M = Scale(s_M.symbol, s_M.unit, convenient_at_least(s_M.per_mm * 1.01, CONVENIENT),
                        note=s_M.note + "; enlarged so that the pole fits")
        else:
            break
    if H + L.graph_gap_mm > room:
        if mu_phi is None and _work_angle_scale(mu_phi, nt, period, width(H + L.graph_gap_mm)).per_mm != s_phi.per_mm:
            raise InputError(f"the pole at H = {H:g} mm does not fit left of the moment diagram at "
                             f"{markup.plain(s_phi.caption())}; give a smaller H_mm, a larger μ_M or a larger μ_φ")
        room = H + L.graph_gap_mm
    room = min(room, H + L.graph_gap_mm) if H + L.graph_gap_mm >= L.pole_room_mm else L.pole_room_mm
    if s_phi.to_mm(period) > width(room) + 1e-9:
        raise InputError(f"the pole at H = {H:g} mm and the period at {markup.plain(s_phi.caption())} do not fit "
                         f"across the sheet; give a smaller H_mm or a larger μ_φ")
    return s_phi, s_M, H, room


def _construction(M_d: Any, M_r: Any, phi: np.ndarray, study: Any, *, mu_phi: float, mu_M: float,
                  H_mm: float) -> gc.WorkDiagrams:
    """The method of chords at these scales: over a study's positions, or over ``phi`` of exact curves."""
    if study is not None:
        return gc.study_work_diagrams(study, mu_phi=mu_phi, mu_M=mu_M, H_mm=H_mm)
    return gc.work_diagrams(M_d, M_r, phi, mu_phi=mu_phi, mu_M=mu_M, H_mm=H_mm, exact_d=M_d, exact_r=M_r)


def _work_scales(M_d: Any, M_r: Any, phi: np.ndarray, study: Any, sheet: Sheet, nt: Notation, *, mu_M: Any,
                 mu_phi: Any, H_mm: float | None, moment_unit: str, work_unit: str) -> _WorkScales:
    """μ_M fitted to its strip (or checked), then μ_φ and the pole distance H together, then μ_A = μ_M μ_φ H."""
    L = LAYOUT
    x0, _, x1, _ = sheet.box
    period = float(phi[-1] - phi[0])
    top, band_h = L.strip_mm(sheet)
    M_all = np.concatenate((np.asarray(M_d.M), np.asarray(M_r.M), [0.0]))
    M_lo, M_hi = float(M_all.min()), float(M_all.max())
    if mu_M is None:
        s_M = pick_scale(M_hi - M_lo, band_h - L.dim_room_mm, symbol=nt.sym("mu_M"), unit=nt.unit(moment_unit))
    else:
        s_M = mu_M if isinstance(mu_M, Scale) else Scale(nt.sym("mu_M"), nt.unit(moment_unit), mu_M)
        if s_M.to_mm(M_hi - M_lo) > band_h + 1e-9:
            raise InputError(f"the moment diagram at {markup.plain(s_M.caption())} needs "
                             f"{s_M.to_mm(M_hi - M_lo):.1f} mm but the strip leaves {band_h:.1f} mm; give a larger "
                             f"μ_M or none")
    probe_wd = _construction(M_d, M_r, phi, study, mu_phi=1.0, mu_M=1.0, H_mm=1.0)
    across = is_slide(sheet.probe)
    closure = f"{nt.sym('calculus.A_d')}(φ_T) − {nt.sym('calculus.A_r')}(φ_T) = −1234 J ({nt.word('closure')})"
    right_col = _column_width(_accuracy_rows(nt, probe_wd, work_unit, across=across), closure)
    A_span = max(float(np.ptp(np.concatenate((probe_wd.A_d.values, probe_wd.A_r.values, [0.0])))), 1e-300)
    for _ in range(3):          # the table's millimetres are written at the scales picked: wider, the graphs narrower
        s_phi, s_M_, H, room = _pick_pole((x0, x1), right_col, period, band_h, s_M, nt=nt, A_span=A_span,
                                          mu_M_given=mu_M is not None, mu_phi=mu_phi, H_mm=H_mm)
        wd = _construction(M_d, M_r, phi, study, mu_phi=s_phi.per_mm, mu_M=s_M_.per_mm, H_mm=H)
        drawn = _column_width(_accuracy_rows(nt, wd, work_unit, across=across), closure)
        if drawn <= right_col + 1e-9:
            break
        right_col = drawn
    s_M = s_M_
    s_A = Scale(nt.sym("calculus.mu_A"), nt.unit(work_unit), wd.mu_A)
    A_vals = np.concatenate((wd.A_d.values, wd.A_r.values, [0.0]))
    if s_A.to_mm(float(np.ptp(A_vals))) > band_h + 1e-9:
        raise InputError(f"at H = {H:g} mm the work diagrams need {s_A.to_mm(float(np.ptp(A_vals))):.1f} mm but the "
                         f"strip leaves {band_h:.1f} mm; give a larger H_mm or none to have one picked")
    return _WorkScales(s_phi, s_M, s_A, H, wd, x0 + room + L.graph_gap_mm, top, band_h, right_col, M_lo, M_hi,
                       period, across)


def _mean_ordinates(ws: _WorkScales, b_M: _Band, x: np.ndarray, M_d: Any, M_r: Any
                    ) -> tuple[list[Polyline], list[Line], list[Line]]:
    """Each interval's mean ordinate as a step, its projection onto the M axis and the ray to the pole
    (one projection and ray per level)."""
    steps, projections, rays = [], [], []
    pole = b_M.mm(-ws.H, 0.0)
    for key, I, curve in (("d", ws.wd.A_d, M_d), ("r", ws.wd.A_r, M_r)):
        means = np.asarray(I.mean_ordinate)
        flat = bool(np.ptp(np.asarray(curve.M)) <= 1e-12 * max(1.0, float(np.abs(curve.M).max())))
        seen: set[float] = set()
        for i, ybar in enumerate(means):
            a_, b_ = b_M.pt(x[i], ybar), b_M.pt(x[i + 1], ybar)
            if not flat:
                steps.append(Polyline((b_M.pt(x[i], 0.0), a_, b_, b_M.pt(x[i + 1], 0.0)), style=THIN,
                                      name=f"mean-{key}-{i + 1}"))
            level = round(float(ybar / ws.s_M.per_mm), 3)
            if level in seen:
                continue
            seen.add(level)
            target = b_M.pt(0.0, ybar)
            if i > 0 and abs(a_[1] - target[1]) > 1e-9:
                projections.append(Line(a_, target, style=PROJECTION, name=f"projection-{key}-{i + 1}"))
            rays.append(Line(pole, target, style=RAY if key == "r" else PROJECTION, name=f"ray-{key}-{i + 1}"))
    return steps, projections, rays


def _moment_strip(ws: _WorkScales, occ: Occupancy, nt: Notation, M_d: Any, M_r: Any, x: np.ndarray,
                  phi0: float, moment_unit: str) -> tuple[_Band, list[Element]]:
    """Strip 1: the moment diagram with the mean ordinates, their projections, the rays to the pole P."""
    ords_M = np.concatenate((np.asarray(ws.wd.A_r.mean_ordinate), np.asarray(ws.wd.A_d.mean_ordinate))) / ws.s_M.per_mm
    # the strip's room left for the dimension of H (:data:`LAYOUT` ``dim_room_mm``) on the side it goes: above the
    # diagram when the fan of rays is narrower above (the engine's moments, mostly negative)
    b_M = _Band(x0=ws.gx0, top=ws.top, height=ws.strip_mm, s_phi=ws.s_phi, s_y=ws.s_M, lo=ws.M_lo, hi=ws.M_hi,
                period=ws.period, align="top" if _fan_side(ords_M) else "bottom")
    curve_d = Polyline(b_M.pts(np.asarray(M_d.phi) - phi0, M_d.M), style=RESULT, name="curve-M_d")
    curve_r = Polyline(b_M.pts(np.asarray(M_r.phi) - phi0, M_r.M), style=RESULT, name="curve-M_r")
    steps, projections, rays = _mean_ordinates(ws, b_M, x, M_d, M_r)
    pole_els = _pole(b_M, ws.H, nt.sym("calculus.P"), "pole", occ)
    occ.register(curve_d, curve_r, *steps, *projections)
    # the dimension of H first: its extension line at the origin passes where the φ axis letters its 0,
    # and the axis moves a tick label it would cross beside its tick
    dim = _h_dimension(b_M, ws.H, ords_M, f"H = {nt.number(ws.H)} {nt.unit('mm')}", "H", occ)
    # the M values are written before the fan of rays, which is broken behind them (ГОСТ 2.303): the fan covers the
    # left of the axis, and values cleared for it left ticks unlabelled; a value that covers other ink goes, with
    # its tick
    axes, pos_M, _, _ = _strip_axes(b_M, occ, nt=nt, y_label=nt.quantity(nt.sym("M"), nt.unit(moment_unit)),
                                    m=len(x) - 1, name="M", pos="pos-M")
    axes[1] = _labelled_ticks_only(axes[1])
    occ.register(*rays)
    _keep_values_row(axes[0], occ)
    names_M = _curve_names(occ, ((curve_d, nt.sym("M_d"), b_M.origin[1]), (curve_r, nt.sym("M_r"), b_M.origin[1])),
                           "M")
    rays = _broken_behind(rays, axes[1])
    return b_M, [*axes, *steps, *projections, *rays, curve_d, curve_r, *pole_els, *dim, *names_M, *pos_M]


def _keep_values_row(axis: Any, occ: Occupancy) -> None:
    """Keep the row of the φ axis's position numbers free: a curve's name set between two of them ("6 M_r 7")
    reads as one of them (:func:`~graphmethods.sheets.tick_values.tick_label_band`)."""
    from graphmethods.sheets.tick_values import tick_label_band

    band = tick_label_band(axis)
    if band is not None:
        occ.add_box(band)


def _labelled_ticks_only(axis: Any) -> Any:
    """A value axis without the ticks whose values were left out (0 stays, unwritten as the axes write it)."""
    labels = axis.tick_labels
    if labels is None or all(lab or t == 0 for t, lab in zip(axis.ticks, labels)):
        return axis
    keep = [k for k, (t, lab) in enumerate(zip(axis.ticks, labels)) if lab or t == 0]
    return replace(axis, ticks=tuple(axis.ticks[k] for k in keep), tick_labels=tuple(labels[k] for k in keep))


def _work_strip(ws: _WorkScales, occ: Occupancy, nt: Notation, x: np.ndarray,
                work_unit: str) -> tuple[_Band, list[Element]]:
    """Strip 2: the work diagrams A_d, A_r, chords parallel to the rays."""
    wd = ws.wd
    A_vals = np.concatenate((wd.A_d.values, wd.A_r.values, [0.0]))
    b_A = _Band(x0=ws.gx0, top=LAYOUT.strip_tops(top=ws.top, strip_mm=ws.strip_mm)[1], height=ws.strip_mm,
                s_phi=ws.s_phi, s_y=ws.s_A, lo=float(A_vals.min()), hi=float(A_vals.max()), period=ws.period)
    chords_d = Polyline(b_A.pts(x, wd.A_d.values), style=RESULT, name="chords-A_d")
    chords_r = Polyline(b_A.pts(x, wd.A_r.values), style=RESULT, name="chords-A_r")
    dots_A = [Point(p, radius_mm=0.5, name=f"dot-A_r-{k}") for k, p in enumerate(chords_r.points)]
    dots_A += [Point(chords_d.points[-1], radius_mm=0.5, name="dot-A_d-end")]
    occ.register(chords_d, chords_r)
    axes, pos_A, _, _ = _strip_axes(b_A, occ, nt=nt, y_label=nt.quantity(nt.sym("A"), nt.unit(work_unit)),
                                    m=len(x) - 1, name="A", pos="pos-A")
    _keep_values_row(axes[0], occ)
    names_A = _curve_names(occ, ((chords_d, nt.sym("calculus.A_d"), b_A.origin[1]),
                                 (chords_r, nt.sym("calculus.A_r"), b_A.origin[1])), "A")
    return b_A, [*axes, chords_d, chords_r, *dots_A, *names_A, *pos_A]


def _dE_strip(ws: _WorkScales, occ: Occupancy, nt: Notation, x: np.ndarray,
              work_unit: str) -> tuple[_Band, list[Element]]:
    """Strip 3: ΔE = A_d − A_r at the same scale μ_A."""
    dE, s_A = ws.wd.delta_E, ws.s_A
    b_E = _Band(x0=ws.gx0, top=LAYOUT.strip_tops(top=ws.top, strip_mm=ws.strip_mm)[2], height=ws.strip_mm,
                s_phi=ws.s_phi, s_y=s_A, lo=float(dE.min()), hi=float(dE.max()), period=ws.period)
    curve_E = Polyline(b_E.pts(x, dE), style=RESULT, name="curve-dE")
    ordinates_E = [Line(b_E.pt(xk, 0.0), b_E.pt(xk, ek), style=THIN, name=f"ordinate-dE-{k}")
                   for k, (xk, ek) in enumerate(zip(x, dE)) if abs(s_A.to_mm(float(ek))) > 0.05]
    dots_E = [Point(p, radius_mm=0.5, name=f"dot-dE-{k}") for k, p in enumerate(curve_E.points)]
    occ.register(curve_E, *ordinates_E)
    axes, pos_E, _, _ = _strip_axes(b_E, occ, nt=nt, y_label=nt.quantity(nt.sym("dE"), nt.unit(work_unit)),
                                    m=len(x) - 1, name="dE", pos="pos-E")
    return b_E, [*axes, *ordinates_E, curve_E, *dots_E, *pos_E]


def _work_column(ws: _WorkScales, bands: tuple[_Band, _Band, _Band], x1: float, occ: Occupancy, nt: Notation, *,
                 given: bool, study: Any, work_unit: str, floor: float) -> list[Element]:
    """The right column: the formulas of the scales, the closure, and the accuracy of each construction."""
    rx, drop, wd = x1 - ws.right_col, LAYOUT.block_drop_mm, ws.wd
    wu, mm, phi = nt.unit(work_unit), nt.unit("mm"), nt.sym("phi")
    A_d, A_r = nt.sym("calculus.A_d"), nt.sym("calculus.A_r")
    picked = nt.word("calculus.given") if given else nt.word("calculus.picked")
    A_hi = float(np.concatenate((wd.A_d.values, wd.A_r.values, [0.0])).max())
    elements: list[Element] = []
    elements += _side_block(rx, bands[0].top + drop, [ws.s_M.caption(nt), ws.s_phi.caption(nt)], "formula-M", occ)
    block_A = _side_block(rx, bands[1].top + drop, [f"{ws.s_A.symbol} = {ws.s_M.symbol}·{nt.sym('mu_phi')}·H = "
                                                    f"{nt.number(wd.mu_A)} {wu}/{mm}",
                                                    f"H = {nt.number(ws.H)} {mm} ({picked})"], "formula-A", occ)
    elements += block_A
    closure = f"{A_d}({phi}_{{T}}) − {A_r}({phi}_{{T}}) = " \
              f"{nt.number(wd.closure if abs(wd.closure) > 1e-9 * max(1.0, A_hi) else 0.0)} {wu} " \
              f"({nt.word('closure')})"
    # on a slide the table (a column per construction) is taller than a strip: the ΔE block follows the A block and
    # the table has the rest of the column under them
    y_dE = bands[2].top + drop if not ws.across else block_A[-1].at[1] + LAYOUT.block_drop_mm + 2 * TEXT_MM
    elements += _side_block(rx, y_dE, [f"{nt.sym('dE')} = {A_d} − {A_r};  {ws.s_A.symbol} = "
                                                      f"{nt.number(wd.mu_A)} {wu}/{mm}", closure], "formula-dE", occ)
    rows = _accuracy_rows(nt, wd, work_unit, across=ws.across)
    return elements + _column_table(rows, _accuracy_title(nt, study), align="l" + "r" * (len(rows[0]) - 1),
                                    name="accuracy-table", title_name="accuracy-title", right=x1,
                                    bottom=bands[2].top + ws.strip_mm, under=elements, floor=floor, lettered=ws.across)


def work_diagrams(subject: Any, *, m: int = 12, H_mm: float | None = None, mu_M: Any = None, mu_phi: Any = None,
                  notation: Any = "en", page: Page | None = None, title: str | None = None, problem: Any = None,
                  moment_unit: str = "N·m", work_unit: str = "J", title_block: bool = True,
                  name: str = "work-diagrams") -> Scene:
    """The moment diagram M_d, M_r integrated by the method of chords into A_d(φ), A_r(φ), and ΔE(φ).

    Each interval's mean ordinate is drawn as a step, projected onto the M axis and joined to
    the pole P, H mm left of the origin; the work diagrams are the chords parallel to those
    rays (one scale μ_A = μ_M μ_φ H for both), and ΔE = A_d − A_r is drawn from their
    difference. A table gives each construction's largest difference from the exact integral,
    at the interval ends and inside the chords, in units of work and in mm. Three steps: the
    scales and H (:func:`_work_scales`), the strips laid out by :data:`LAYOUT`, their elements.

    Parameters
    ----------
    subject : Study, Case, cycle problem or (M_d, M_r)
        A linkage study (its positions are the intervals; M_r drawn through its values there,
        compared with the exact M_r that jumps where the load switches); a linkage problem
        (studied at ``m`` positions); a cycle problem with moment curves, or a pair of
        MomentCurves (``m`` equal intervals; the curves are exact).
    H_mm : float, optional
        Pole distance, mm. When not given, the toolkit picks the smallest H of 1, 1.5, 2, 2.5, 3,
        4, 5 × 10^k mm whose work diagrams fit their strip (the largest drawing), and says so.
    mu_M, mu_phi : float or Scale, optional
        Scales of the moment diagram; picked when not given.

    Examples
    --------
    >>> from graphmethods import problems
    >>> s = work_diagrams(problems.w3(), notation="zh")
    >>> [sc.symbol for sc in s.scales()], s.notes[-1]
    (['μ_φ', 'μ_M', 'μ_W'], 'H = 30 mm (picked: smallest convenient H whose work diagrams fit)')
    """
    nt = get_notation(notation)
    M_d, M_r, phi, study, prob = _moment_subject(subject, m, nt)
    sheet = Sheet(nt=nt, page=page, default_page=Page("A3", "landscape", frame=True), top_gap_mm=6.0,
                  title=title or nt.word("calculus.work_title"),
                  problem=prob if problem is None else problem, title_block=title_block)
    ws = _work_scales(M_d, M_r, phi, study, sheet, nt, mu_M=mu_M, mu_phi=mu_phi, H_mm=H_mm, moment_unit=moment_unit,
                      work_unit=work_unit)
    phi0 = float(phi[0])
    x = np.asarray(phi) - phi0
    occ = sheet.occ
    b_M, els_M = _moment_strip(ws, occ, nt, M_d, M_r, x, phi0, moment_unit)
    b_A, els_A = _work_strip(ws, occ, nt, x, work_unit)
    b_E, els_E = _dE_strip(ws, occ, nt, x, work_unit)
    column = _work_column(ws, (b_M, b_A, b_E), sheet.box[2], occ, nt, given=H_mm is not None, study=study,
                          work_unit=work_unit, floor=sheet.box[3])
    scales = (ws.s_phi, ws.s_M, ws.s_A)
    # a slide's column states every scale beside its diagram: the captions under them wrote μ_φ, μ_M, μ_A twice
    captions = [] if is_slide(sheet.probe) else sheet.captions(scales)
    elements = [sheet.header(), *els_M, *els_A, *els_E, *column, *captions]
    how = "given" if H_mm is not None else "picked: smallest convenient H whose work diagrams fit"
    notes = tuple(n for n in (ws.s_phi.note, ws.s_M.note) if n) + (f"H = {ws.H:g} mm ({how})",)
    return Scene(sheet.page(scales), tuple(elements), title=sheet.title, notation=nt.code, name=name,
                 extra_scales=scales, notes=notes)
