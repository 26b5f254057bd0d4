"""The figures of a motion from given initial conditions: ω(t), ω(φ) and ε(φ), scale-true on A4.

Each function takes a :class:`~graphmethods.dynamics.regimes.Run` and returns a
:class:`~graphmethods.scene.Scene` on an A4 landscape sheet with a frame and a title block. The
scales are picked (convenient values that fill the sheet) unless given, and captioned under the
figure; t in s, φ in rad (with turns marked), ω in rad/s, ε in rad/s². Once the run is steady,
ω_m is drawn as a dashed level and the moment the steady state is reached is marked.

>>> from graphmethods.dynamics.motion import ReducedModel
>>> from graphmethods.dynamics.regimes import run
>>> r = run(ReducedModel(J_e=0.025, M_e=30.0), t_end=1.5)
>>> s = motion_graph(r, x="t", y="omega", problem="gear train")
>>> [c.caption("en") for c in s.scales()]
['μ_t = 0.01 s/mm', 'μ_ω = 20 (rad/s)/mm']
"""

from __future__ import annotations

import math

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import Axis, Frame, Page, Point, Polyline, Scene, Text, axis_ticks, notation as get_notation
from graphmethods.scene.primitives import MAIN, THIN
from graphmethods.sheets.dynamics import SMALL_MM, SheetFrame, suppressed_base
from graphmethods.sheets.layout import TEXT_MM, given_scale
from graphmethods.sheets.styles import LEVEL, PROJECTION

TURN = PROJECTION

#: (x, y) of a motion graph -> the key of its title in scene/vocabulary/motion.toml
_TITLES = {("t", "omega"): "motion.speed_t", ("phi", "omega"): "motion.speed_phi",
           ("phi", "epsilon"): "motion.acceleration_phi", ("t", "epsilon"): "motion.acceleration_t"}


def _samples(res, per_step: int):
    """t, φ, ω, ε at the steps and ``per_step`` − 1 points inside each, from the dense output (ε inside
    a step is the derivative of the dense ω; at the steps the integrator's own ε)."""
    n = res.steps
    if n == 0:
        raise InputError("the run has no steps to draw")
    k = max(1, int(per_step))
    idx = np.repeat(np.arange(n), k)
    th = np.tile(np.arange(k) / k, n)
    t, y = res._dense(idx, th)
    # ε = dω/dt from the dense polynomial: d/dθ of y, over h
    from graphmethods.dynamics.regimes import _P

    dp = np.stack([np.ones_like(th), 2 * th, 3 * th**2, 4 * th**3], axis=-1)
    Q = np.einsum("nsk,sp->nkp", res._K[idx], _P)
    dy = np.einsum("nkp,np->nk", Q, dp)
    eps = dy[:, 1]
    inner = th > 0                       # at the step points the integrator's own ε
    eps = np.where(inner, eps, res.epsilon[idx])
    t = np.append(t, res.t[-1])
    phi = np.append(y[:, 0], res.phi[-1])
    w = np.append(y[:, 1], res.omega[-1])
    eps = np.append(eps, res.epsilon[-1])
    return t, phi, w, eps


def motion_graph(res, *, x: str = "t", y: str = "omega", notation="en", problem: str = "", title: str | None = None,
                 mu_x=None, mu_y=None, per_step: int = 8, name: str | None = None) -> Scene:
    """One graph of a run: ``x`` in {"t", "phi"} against ``y`` in {"omega", "epsilon"}.

    Parameters
    ----------
    res : Run
        The motion (:func:`graphmethods.dynamics.regimes.run`).
    x, y : str
        The axes: time t (s) or angle φ (rad from the start); speed ω (rad/s) or acceleration ε (rad/s²).
    notation : {"en", "ru", "zh"}
    problem : str
        The problem's name, for the title block.
    mu_x, mu_y : float, optional
        Scales (units per mm); picked when not given.
    per_step : int
        Points drawn per integration step (the dense output between the steps).
    """
    if (x, y) not in _TITLES:
        raise InputError(f"motion_graph: x must be 't' or 'phi' and y 'omega' or 'epsilon', not {x!r}, {y!r}")
    nt = get_notation(notation)
    title = title or nt.word(_TITLES[(x, y)])
    t, phi, w, eps = _samples(res, per_step)
    xv = t - t[0] if x == "t" else phi - phi[0]
    yv = w if y == "omega" else eps
    sheet = SheetFrame(nt=nt, page=None, title=title, problem=problem or "", title_block=True,
                       default_page=Page("A4", "landscape", frame=True))
    x0, _, x1, _ = sheet.box
    px0, px1 = x0 + 22.0, x1 - 30.0
    py0, py1 = sheet.top + 14.0, sheet.caption_y - 16.0
    x_span = float(xv.max())
    if not x_span > 0:
        raise InputError("the run spans no time or angle to draw")
    x_sym, x_unit = ("t", "s") if x == "t" else (nt.sym("phi"), "rad")
    y_sym, y_unit = (nt.sym("dynamics.omega"), "rad/s") if y == "omega" else (nt.sym("dynamics.eps"), "rad/s²")
    ux, uy = nt.unit(x_unit), nt.unit(y_unit)
    uy_cap = f"({uy})" if "/" in uy else uy
    s_x = given_scale(mu_x, f"μ_{x_sym}" if x == "t" else nt.sym("mu_phi"), ux, x_span, px1 - px0, what="the run")
    lo, hi = min(0.0, float(yv.min())), max(0.0, float(yv.max()))
    if hi - lo <= 0:
        hi = lo + 1.0
    mu_sym = nt.sym("dynamics.mu_omega") if y == "omega" else nt.sym("dynamics.mu_eps")
    s_y = given_scale(mu_y, mu_sym, uy_cap, hi - lo, py1 - py0, what="the graph")
    origin = (px0, py0 + s_y.to_mm(hi))
    f = Frame(origin, s_x, s_y)
    xticks = tuple(v for v in axis_ticks(0.0, x_span, s_x, min_gap_mm=12.0) if 0 <= v <= x_span)
    yticks = tuple(v for v in axis_ticks(lo, hi, s_y, min_gap_mm=8.0) if lo <= v <= hi)
    dec = nt.decimal
    # values on both sides of 0 (ε): the abscissa at the graph's foot, where the curve's jumps do not strike its
    # values out, and a thin line at 0
    foot = f.pt(0.0, lo)[1] if lo < 0 else origin[1]
    ax_x = Axis((origin[0], foot), s_x, "x", min_value=0.0, max_value=x_span, ticks=xticks,
                label=nt.quantity(x_sym, x_unit), size_mm=SMALL_MM, decimal=dec, name="axis-x", labels_side="below")
    ax_y = Axis(origin, s_y, "y", min_value=lo, max_value=hi, ticks=yticks, label=nt.quantity(y_sym, y_unit),
                size_mm=SMALL_MM, decimal=dec, name="axis-y", skip_zero_label=False)
    # at most ~6000 points: a polyline of a long run is thinned evenly (ends kept)
    keep = np.unique(np.linspace(0, xv.size - 1, min(xv.size, 6000)).round().astype(int))
    els = [sheet.header(), ax_x, ax_y, Polyline(f.pts(xv[keep], yv[keep]), style=MAIN, name=f"curve-{y}")]
    if lo < 0:
        els.insert(1, Polyline((origin, f.pt(x_span, 0.0)), style=THIN, name="zero-line"))
    notes = [s_x.note, s_y.note]
    if x == "phi":               # the crank turns, thin dashed verticals
        for k in range(1, int(x_span / (2 * math.pi)) + 1):
            xx = f.pt(2 * math.pi * k, 0.0)[0]
            if xx - origin[0] > 3.0:
                els.append(Polyline(((xx, f.pt(0, lo)[1]), (xx, f.pt(0, hi)[1])), style=TURN, name=f"turn-{k}"))
    legend = ""
    st = res.steady
    if st is not None and y == "omega":
        yy = f.pt(0.0, st.omega_m)[1]
        els.append(Polyline(((origin[0], yy), (f.pt(x_span, 0)[0] + 2.0, yy)), style=LEVEL, name="level-omega_m"))
        els.append(Text((f.pt(x_span, 0)[0] + 3.0, yy - 1.0),
                        f"{nt.sym('dynamics.omega_m')} = {nt.number(st.omega_m, sig=4)}", size_mm=TEXT_MM,
                        name="label-omega_m"))
        x_st = st.t_steady if x == "t" else float(res.at_time([res.t[0] + st.t_steady])["phi"][0] - phi[0])
        w_st = float(res.at_time([res.t[0] + st.t_steady])["omega"][0])
        at = f.pt(x_st, w_st)
        els.append(Point(at, radius_mm=1.1, filled=False, name="mark-steady"))
        els.append(Polyline((at, (at[0], origin[1])), style=THIN, name="leader-steady"))
        legend = (f"δ = {nt.number(st.delta, sig=3)}; t_{{steady}} = {nt.number(st.t_steady, sig=4)} {nt.unit('s')} "
                  f"(±{nt.number(100 * st.tol, sig=2)} %)")
    els += sheet.captions((s_x, s_y), legend=legend)
    return Scene(sheet.page((s_x, s_y)), tuple(els), title=sheet.title, notation=nt.code,
                 name=name or f"motion-{y}-{x}", notes=tuple(notes))


def energy_mass_curve(res, *, notation="en", problem: str = "", title: str | None = None) -> Scene:
    """The run in the energy–mass plane: T against the total inertia J = J_F + J_e(φ) (Wittenbauer's
    diagram, open): a start-up leaves T = 0 and winds into the closed loop of the steady state; a
    run-down winds back to T = 0. The J axis starts at a round value below the least J (a suppressed
    zero); the start is marked with a circle, the end with a dot.

    >>> from graphmethods.dynamics.motion import ReducedModel
    >>> from graphmethods.dynamics.regimes import run
    >>> import numpy as np
    >>> r = run(ReducedModel(J_e=lambda p: 1 + 0.2 * np.cos(2 * p), M_e=lambda p: 5 + 3 * np.sin(p)), turns=3)
    >>> energy_mass_curve(r).element("curve-T").points[0][1] > energy_mass_curve(r).element("curve-T").points[-1][1]
    True
    """
    nt = get_notation(notation)
    title = title or nt.word("motion.energy_mass")
    J, T = np.asarray(res.J, dtype=float), np.asarray(res.T, dtype=float)
    sheet = SheetFrame(nt=nt, page=None, title=title, problem=problem or "", title_block=True,
                       default_page=Page("A4", "landscape", frame=True))
    x0, _, x1, _ = sheet.box
    px0, px1 = x0 + 22.0, x1 - 30.0
    py0, py1 = sheet.top + 14.0, sheet.caption_y - 16.0
    J_lo, J_hi = float(J.min()), float(J.max())
    span = max(J_hi - J_lo, 1e-9 * max(J_hi, 1e-300))
    s_J = given_scale(None, "μ_J", nt.unit("kg·m²"), span * 1.25, px1 - px0, what="the inertia")
    ticks = axis_ticks(J_lo - 0.2 * span, J_hi, s_J, min_gap_mm=12.0)
    base = max([t for t in ticks if t <= J_lo] or [J_lo])
    T_hi = max(float(T.max()), 1e-300)
    T_lo = float(T.min())
    # a steady run's loop sits far above T = 0: the T axis starts at a round value below it (a suppressed zero,
    # as the J axis), else the loop is a sliver at the top of a 0…T_max axis
    T_base = 0.0
    if T_lo > 0.0 and T_hi - T_lo < 0.35 * T_hi:
        probe = given_scale(None, "μ_T", nt.unit("J"), (T_hi - T_lo) * 1.25, py1 - py0, what="the energy")
        T_base = suppressed_base(T_lo, T_hi, probe)
    s_T = given_scale(None, "μ_T", nt.unit("J"), T_hi - T_base, py1 - py0, what="the energy")
    origin = (px0 - s_J.to_mm(base), py0 + s_T.to_mm(T_hi))
    f = Frame(origin, s_J, s_T)
    foot = f.pt(base, T_base)[1]
    # the J axis from its (suppressed) base at T = T_base; the T axis stands at J = base
    ax_J = Axis((origin[0], foot), s_J, "x", min_value=base, max_value=J_hi, label=nt.quantity("J", "kg·m²"),
                ticks=tuple(t for t in ticks if base <= t <= J_hi), size_mm=SMALL_MM, decimal=nt.decimal,
                name="axis-J")
    ax_T = Axis((px0, f.pt(base, 0.0)[1]), s_T, "y", min_value=T_base, max_value=T_hi, label=nt.quantity("T", "J"),
                ticks=tuple(v for v in axis_ticks(T_base, T_hi, s_T, min_gap_mm=8.0) if T_base <= v <= T_hi),
                size_mm=SMALL_MM, decimal=nt.decimal, name="axis-T", skip_zero_label=T_base == 0.0)
    keep = np.unique(np.linspace(0, J.size - 1, min(J.size, 6000)).round().astype(int))
    els = [sheet.header(), ax_J, ax_T, Polyline(f.pts(J[keep], T[keep]), style=MAIN, name="curve-T"),
           Point(f.pt(J[0], T[0]), radius_mm=1.1, filled=False, name="mark-start"),
           Point(f.pt(J[-1], T[-1]), radius_mm=0.8, name="mark-end")]
    els += sheet.captions((s_J, s_T))
    return Scene(sheet.page((s_J, s_T)), tuple(els), title=sheet.title, notation=nt.code, name="energy-mass-run",
                 notes=(s_J.note, s_T.note, f"the J axis starts at {base:g} kg·m²"))


def motion_figures(res, *, notation="en", problem: str = "") -> dict:
    """The figures of a run by file stem: ω(t), ω(φ), ε(φ), and T(J) when the inertia varies."""
    out = {"omega_t": motion_graph(res, x="t", y="omega", notation=notation, problem=problem),
           "omega_phi": motion_graph(res, x="phi", y="omega", notation=notation, problem=problem),
           "epsilon_phi": motion_graph(res, x="phi", y="epsilon", notation=notation, problem=problem)}
    J = np.asarray(res.J, dtype=float)
    if float(J.max() - J.min()) > 1e-9 * float(J.max()):
        out["energy_mass"] = energy_mass_curve(res, notation=notation, problem=problem)
    return out
