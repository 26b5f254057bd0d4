"""The J_F–[δ] hyperbola: the flywheel inertia J_F = ΔW_max/(ω_m²[δ]) − J_e against the permissible
coefficient of fluctuation [δ], over the range of the table of recommended [δ] by machine
(:mod:`graphmethods.dynamics.permissible_delta`), the chosen [δ] marked (domain.md §4, §6). A designer
reads from it how fast a stricter [δ] makes the flywheel grow. A4 landscape.

The abscissa is 1/[δ], so the hyperbola is drawn as the straight line it is in 1/[δ] and a machine's
band of [δ] (1/200 … 1/300 for an AC generator) is a third of the axis, not 1.7 mm at its origin.

>>> s = flywheel_hyperbola(575.0, omega_m=62.83185307179586, J_e=0.0, delta=1 / 300)
>>> s.name, s.element("chosen").name
('flywheel-hyperbola', 'chosen')
"""

from __future__ import annotations

from typing import Any

import numpy as np

from graphmethods.dynamics.flywheel_formulas import hyperbola
from graphmethods.dynamics.permissible_delta import delta_range, machine_row
from graphmethods.errors import InputError
from graphmethods.scene import Axis, Line, Page, Point, Polyline, Scene, Text, axis_ticks, notation as get_notation
from graphmethods.scene.primitives import DASHED, MAIN, Style
from graphmethods.sheets.engine.labels import Ink
from graphmethods.sheets.flywheel_design import DIGITS
from graphmethods.sheets.frame import SheetFrame
from graphmethods.sheets.layout import TEXT_MM, given_scale

BAND = Style(width_mm=1.2)
SMALL_MM = 2.8          # notes under the graph



def flywheel_hyperbola(delta_W_max: float, *, omega_m: float, J_e: float = 0.0, delta: float | None = None,
                       machine: str | None = None, notation: str = "en", page: Page | None = None,
                       mu_delta: float | None = None, mu_J: float | None = None, samples: int = 240,
                       title: str | None = None, problem: str = "") -> Scene:
    """J_F against 1/[δ], drawn to scales μ_{1/[δ]} (mm⁻¹) and μ_J (kg·m²/mm), the chosen [δ] marked.

    Parameters
    ----------
    delta_W_max : float
        The maximum fluctuation of energy ΔW_max, J.
    omega_m : float
        Mean angular speed, rad/s.
    J_e : float
        The mechanism's own reduced inertia, kg·m² (subtracted).
    delta : float, optional
        The chosen [δ], marked with its J_F; default the machine's strict end, if a machine is given.
    machine : str, optional
        A row of the [δ] table: its range is drawn as a band on the δ axis.
    mu_delta, mu_J : float, optional
        Scales of 1/[δ] (per mm) and of J_F (picked to fit when not given).
    samples : int
        Points of the curve (geometrically spaced in δ).
    """
    nt = get_notation(notation)
    row = machine_row(machine) if machine is not None else None
    if delta is None and row is not None:
        delta = row.strict
    lo, hi = delta_range()
    if delta is not None:
        lo, hi = min(lo, float(delta)), max(hi, float(delta))
    deltas = np.geomspace(lo, hi, int(samples))
    J = hyperbola(delta_W_max, omega_m=omega_m, J_e=J_e, deltas=deltas)
    J_c = None if delta is None else float(hyperbola(delta_W_max, omega_m=omega_m, J_e=J_e, deltas=[float(delta)])[0])
    # where J_e alone keeps δ within [δ] no flywheel is needed: the line starts on the axis at J_F = 0 (it ran
    # below the axis, through its values)
    deltas, J = _needed(deltas, J, delta_W_max / (omega_m ** 2 * J_e) if J_e > 0 else None)
    J_lo, J_hi = min(J_c or 0.0, 0.0), float(J.max()) if len(J) else 0.0
    if not J_hi > 0:
        raise InputError(f"J_F ≤ 0 over the whole range of [δ]: J_e = {J_e:g} kg·m² already keeps δ within "
                         f"1/{1 / lo:.4g}; no flywheel and no hyperbola to draw")
    JF, wm, Je = nt.sym("dynamics.J_F"), nt.sym("dynamics.omega_m"), nt.sym("dynamics.J_e")
    sheet = SheetFrame(nt=nt, page=page, title=title or nt.word("flywheel.hyperbola_title", JF=JF),
                       problem=problem, title_block=True, default_page=Page("A4", "landscape", frame=True))
    x0, _, x1, _ = sheet.box
    px0, px1 = x0 + 30.0, x1 - 28.0
    py0, py1 = sheet.top + 14.0, sheet.caption_y - 24.0
    x_hi = 1.0 / lo                                    # the abscissa is 1/[δ]: the hyperbola drawn straight
    s_d = given_scale(mu_delta, "μ_{1/[δ]}", "", x_hi, px1 - px0, what="the 1/[δ] axis")
    kgm2 = nt.unit("kg·m²")
    s_J = given_scale(mu_J, "μ_{J}", "kg·m²", J_hi - J_lo, py1 - py0, what="the J_F axis")  # captions translate
    origin = (px0, py0 + s_J.to_mm(J_hi))

    def at(d: float, j: float) -> tuple[float, float]:
        return (origin[0] + s_d.to_mm(1.0 / d), origin[1] - s_J.to_mm(j))

    num = nt.number
    els: list[Any] = [sheet.header()]
    els.append(Axis(origin, s_d, "x", min_value=0.0, max_value=x_hi, ticks=axis_ticks(0.0, x_hi, s_d),
                    label="1/[δ]", skip_zero_label=True, decimal=nt.decimal, name="axis-delta"))
    els.append(Axis(origin, s_J, "y", min_value=J_lo, max_value=J_hi, ticks=axis_ticks(J_lo, J_hi, s_J),
                    label=nt.quantity(JF, "kg·m²"), decimal=nt.decimal, name="axis-J"))
    els.append(Polyline(tuple(at(float(d), float(j)) for d, j in zip(deltas, J)), style=MAIN, name="hyperbola"))
    if row is not None:
        els.append(Line(at(row.lenient, 0.0), at(row.strict, 0.0), style=BAND, name="machine-band"))
        els.append(Text((at(row.lenient, 0.0)[0], origin[1] + 9.0), f"{row.name(nt.code)}{nt.colon}{row.range_text()}",
                        size_mm=SMALL_MM, name="machine-label"))
    if delta is not None and J_c is not None:
        p = at(float(delta), J_c)
        els.append(Line(at(float(delta), 0.0), p, style=DASHED, name="chosen-delta-line"))
        els.append(Line((origin[0], p[1]), p, style=DASHED, name="chosen-J-line"))
        chosen = (f"{nt.word('flywheel.chosen')}{nt.colon}[δ] = 1/{num(1 / float(delta), sig=DIGITS['inverse'])}"
                  f"{nt.list_separator}{JF} = {num(J_c, sig=DIGITS['J'])} {kgm2}")
        # the value where no line is, inside the frame: above the rising line to its left, or below it to its
        # right (near the origin, where the axes' values are, "nw" ran off the frame)
        ink = Ink()
        ink.add_primitives([q for e in els[1:] for q in e.primitives()])
        lab, leader = ink.place(p, chosen, size_mm=TEXT_MM, directions=("nw", "se", "e", "ne", "n"), gap_mm=1.5,
                                within=(x0 + 2.0, sheet.top, x1 - 2.0, origin[1] - 1.0))
        els.append(Point(p, radius_mm=0.9, name="chosen"))
        els.append(Text((lab.x, lab.y), chosen, size_mm=TEXT_MM, anchor=lab.anchor, name="chosen-label"))
        if leader is not None:
            els.append(Line(leader[0], leader[1], style=Style(width_mm=0.18), name="chosen-leader"))
    notes_y = sheet.caption_y - 16.0
    dW = nt.sym("delta_W_max")
    els.append(Text((x0 + 4.0, notes_y), nt.word("flywheel.hyperbola_formula", JF=JF, wm=wm, Je=Je, dW=dW) + ";  " +
                    nt.word("flywheel.hyperbola_data", W=num(float(delta_W_max), sig=DIGITS["W"]),
                            w=num(float(omega_m), sig=DIGITS["omega"]), J=num(float(J_e), sig=DIGITS["J"]), wm=wm,
                            Je=Je, dW=dW),
                    size_mm=TEXT_MM, name="formula"))
    rng = nt.word("flywheel.hyperbola_range", a=num(1 / hi, sig=DIGITS["inverse"]),
                  b=num(1 / lo, sig=DIGITS["inverse"]))
    els.append(Text((x0 + 4.0, notes_y + 5.0), rng,
                    size_mm=SMALL_MM, name="range-note"))
    els += sheet.captions((s_d, s_J))
    return Scene(sheet.page((s_d, s_J)), tuple(els), title=sheet.title, notation=nt.code, name="flywheel-hyperbola",
                 notes=(s_d.note, s_J.note))


def _needed(deltas: np.ndarray, J: np.ndarray, delta_0: float | None) -> tuple[np.ndarray, np.ndarray]:
    """The part of the hyperbola where a flywheel is needed (J_F ≥ 0), from ``delta_0`` (the [δ] that J_e alone
    keeps, where J_F = 0) when it falls inside the range.

    >>> d, j = _needed(np.array([0.1, 0.05, 0.01]), np.array([-1.0, 0.0, 4.0]), 0.05)
    >>> d.tolist(), j.tolist()
    ([0.05, 0.05, 0.01], [0.0, 0.0, 4.0])
    """
    keep = J >= 0.0
    if delta_0 is None or keep.all() or not keep.any():
        return deltas[keep], J[keep]
    return np.concatenate(([delta_0], deltas[keep])), np.concatenate(([0.0], J[keep]))
