"""The text output of ``graphmethods flywheel`` in ``--lang en|ru|zh``: the figures' words, symbols and digits.

One truth: a number the text prints is the number the flywheel figures print, with the same significant
digits (:data:`graphmethods.scene.numbers.FLYWHEEL_DIGITS`), the language's decimal sign and symbols
(J_м, ω_ср, A_изб in Russian), and its units.

>>> from graphmethods.dynamics import excess_work as ew
>>> cycle = ew.from_work([-50, 550, -100, 125, -500, 25, -50])
>>> out = {"n_rpm": 600.0, "delta": 1 / 300, "J_total": 43.69476, "J_F": 43.69476, "omega_max": 62.9366,
...        "omega_min": 62.7271, "flywheel_needed": True}
>>> lines = report_lines(out, cycle, lang="ru", omega_m=62.83185, J_e=0.0)
>>> lines[0], lines[-1]
('Таблица избыточных работ', 'J_м = 43,69 кг·м²')
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from graphmethods.scene import markup
from graphmethods.scene.notation import Notation, get
from graphmethods.scene.numbers import FLYWHEEL_DIGITS as DIGITS


def _t(text: str) -> str:
    """A figure's markup as a text report writes it (ω_{ср} -> ω_ср)."""
    return markup.typed(text)


def value(nt: Notation, v: float, kind: str, unit: str = "", *, reference: float | None = None) -> str:
    """``v`` with the digits of its ``kind`` (:data:`DIGITS`), the language's decimal sign and unit.

    >>> value(get("ru"), 43.69476, "J", "kg·m²"), value(get("en"), 62.83185, "omega", "rad/s")
    ('43,69 кг·м²', '62.8319 rad/s')
    """
    text = nt.number(float(v), sig=DIGITS[kind], reference=reference)       # round-off of a sum of ``reference``s: 0
    return f"{text} {nt.unit(unit)}" if unit else text


def table_lines(cycle: Any, nt: Notation, unit: str = "J") -> list[str]:
    """The excess-work table and its summary (E_max, E_min, ΔW_max, closure) in ``nt``'s words."""
    u = nt.unit(unit)
    rows = cycle.rows()
    head = [nt.word("flywheel.report_interval")]
    if cycle.phi is not None:
        head += [nt.quantity(f"φ {nt.word('flywheel.report_from')}", "°"),
                 nt.quantity(f"φ {nt.word('flywheel.report_to')}", "°")]
    if cycle.areas_mm2 is not None:
        head += [nt.quantity("f", "mm²")]
    head += [nt.quantity(_t(nt.sym("A")), unit), nt.quantity(f"{_t(nt.sym('E'))} {nt.word('flywheel.report_at_end')}",
                                                             unit)]
    body = []
    ref = max([abs(float(r["A_J"])) for r in rows] + [0.0])             # the size of the works summed
    for r in rows:
        line = [r["interval"]]
        if cycle.phi is not None:
            line += [value(nt, r["phi_from_deg"], "W"), value(nt, r["phi_to_deg"], "W")]
        if cycle.areas_mm2 is not None:
            line += [value(nt, r["f_mm2"], "W")]
        line += [value(nt, r["A_J"], "W"), value(nt, r["E_J"], "W", reference=ref)]
        body.append(line)
    widths = [max(len(r[k]) for r in [head] + body) for k in range(len(head))]

    def fmt(r: Sequence[str]) -> str:
        return "  ".join(c.ljust(w) if k == 0 else c.rjust(w) for k, (c, w) in enumerate(zip(r, widths)))

    out = [nt.word("excess_work_table"), fmt(head)] + [fmt(r) for r in body]
    for sym, i, E in (("E_max", cycle.index_E_max, cycle.E_max), ("E_min", cycle.index_E_min, cycle.E_min)):
        at = nt.word("flywheel.report_at", p=cycle.labels[i])
        phi = f" (φ = {value(nt, math.degrees(cycle.phi[i]), 'W')}°)" if cycle.phi is not None else ""
        out.append(f"{_t(nt.sym(sym))} = {value(nt, E, 'W', reference=ref)} {u} {at}{phi}")
    out.append(f"{_t(nt.sym('delta_W_max'))} = {value(nt, cycle.delta_W_max, 'W')} {u}")
    out.append(f"{nt.word('residual')} ΣA = {value(nt, cycle.residual, 'W', reference=ref)} {u}")
    return out


def moment_lines(out: dict[str, Any], nt: Notation) -> list[str]:
    """The lines the moment input (--M-d/--M-r) adds: the moments, the energy's extremes, ε's extremes."""
    def angles(a: Sequence[float]) -> str:
        return nt.list_separator.join(f"{value(nt, x, 'W')}°" for x in a)

    def given(text: str) -> str:                  # "19999.999999999993 (balances M_r)": the balancing constant
        head, _, rest = str(text).partition(" (balances ")
        try:
            other = _t(nt.sym("M_r" if rest.startswith("M_r") else "M_d"))
            if not rest:
                return text
            return f"{value(nt, float(head), 'moment')} ({nt.word('flywheel.report_balances', M=other)})"
        except ValueError:
            return text

    Nm = nt.unit("N·m")
    lines = [nt.word("flywheel.report_moments", Md=_t(nt.sym("M_d")), gd=given(out["M_d_given"]),
                     md=value(nt, out["M_d_mean"], "moment"), Mr=_t(nt.sym("M_r")), gr=given(out["M_r_given"]),
                     mr=value(nt, out["M_r_mean"], "moment"), Nm=Nm, T=value(nt, out["period_deg"], "W")),
             nt.word("flywheel.report_energy_at", hi=angles(out["phi_E_max_deg"]), lo=angles(out["phi_E_min_deg"]))]
    if "epsilon_max" in out:
        lines.append(nt.word("flywheel.report_epsilon", J=value(nt, out["J_epsilon"], "J", "kg·m²"),
                             emax=value(nt, out["epsilon_max"], "moment", "rad/s²"),
                             pmax=angles(out["phi_epsilon_max_deg"]),
                             emin=value(nt, out["epsilon_min"], "moment", "rad/s²"),
                             pmin=angles(out["phi_epsilon_min_deg"])))
    return lines


def sizing_lines(out: dict[str, Any], nt: Notation) -> list[str]:
    """The rim and the disc as the design figure's table gives them: lengths in mm, masses, mD², speeds."""
    lines = []
    sep = nt.list_separator
    for key in ("rim", "disc"):
        if key not in out:
            continue
        d = out[key]
        name = nt.word(f"flywheel.{key}_short")
        material = nt.word("flywheel." + d["material"].replace(" ", "_"))
        lengths = [(k, d[k]) for k in ("D", "D1", "D2", "H", "B") if k in d]
        parts = [f"{k} = {value(nt, v * 1000.0, 'mm', 'mm')}" for k, v in lengths]
        parts.append(f"m = {value(nt, d['m'], 'mass', 'kg')}")
        if "J_rim" in d:
            parts.append(f"J = {value(nt, d['J_rim'], 'J', 'kg·m²')}")
        parts += [f"mD² = {value(nt, d['mD2'], 'J', 'kg·m²')}", f"QD² = {value(nt, d['QD2_kgf_m2'], 'J', 'kgf·m²')}",
                  f"GD² = {value(nt, d['GD2_N_m2'], 'J', 'N·m²')}",
                  f"{nt.word('flywheel.speed')} {value(nt, d['rim_speed'], 'speed', 'm/s')}",
                  f"{nt.word('flywheel.limit')} {value(nt, d['speed_limit'], 'speed', 'm/s')}"]
        lines.append(f"{name} ({material}){nt.colon}{sep.join(parts)}"
                     + ("" if d["speed_ok"] else nt.word("flywheel.report_over")))
    return lines


def report_lines(out: dict[str, Any], cycle: Any, *, lang: str, omega_m: float, J_e: float, mc: Any = None,
                 machine: Any = None, machine_end: str = "strict") -> list[str]:
    """The whole text report of ``graphmethods flywheel`` (see the module docstring)."""
    nt = get(lang)
    wm, JF, Je = _t(nt.sym("dynamics.omega_m")), _t(nt.sym("dynamics.J_F")), _t(nt.sym("dynamics.J_e"))
    dW = _t(nt.sym("delta_W_max"))
    rad_s, kgm2 = nt.unit("rad/s"), nt.unit("kg·m²")
    lines = table_lines(cycle, nt)
    if mc is not None:
        lines += moment_lines(out, nt)
    lines.append(nt.word("flywheel.report_mean", wm=wm, w=value(nt, omega_m, "omega"), u=rad_s,
                         n=value(nt, out["n_rpm"], "omega"), rpm=nt.unit("rev/min")))
    if "omega_at_boundaries" in out:
        lines.append(nt.word("flywheel.report_boundaries", u=rad_s) + nt.colon + nt.list_separator.join(
            f"{lab} {value(nt, w, 'omega')}" for lab, w in zip(cycle.labels, out["omega_at_boundaries"])))
    if "J_total" in out:                                       # [δ] given (or the machine's): J_F found
        if machine is not None:
            lines.append(nt.word("flywheel.report_machine", name=machine.name(lang), range=machine.range_text(),
                                 end=nt.word(f"flywheel.end_{machine_end}"),
                                 d=value(nt, 1.0 / out["delta"], "inverse")))
        lines.append(f"[δ] = {value(nt, out['delta'], 'delta')}{nt.list_separator}"
                     f"{_t(nt.sym('dynamics.omega_max'))} = {value(nt, out['omega_max'], 'omega')}{nt.list_separator}"
                     f"{_t(nt.sym('dynamics.omega_min'))} = {value(nt, out['omega_min'], 'omega', 'rad/s')}")
        lines.append(nt.word("flywheel.report_required", W=dW, wm=wm, J=value(nt, out["J_total"], "J", "kg·m²")))
        after = nt.word("flywheel.report_after_Je", Je=Je, J=value(nt, J_e, "J", "kg·m²")) if J_e else ""
        lines.append(f"{JF} = {value(nt, out['J_F'], 'J')} {kgm2}{after}")
        if not out["flywheel_needed"]:
            lines.append(nt.word("flywheel.report_not_needed"))
    elif out["delta"] > 0:
        lines.append(nt.word("flywheel.report_delta", W=dW, wm=wm, d=value(nt, out["delta"], "delta"),
                             inv=value(nt, 1.0 / out["delta"], "inverse"), J=value(nt, out["J"], "J", "kg·m²")))
    else:
        lines.append(nt.word("flywheel.report_no_fluctuation"))
    lines += sizing_lines(out, nt)
    lines += [nt.word("flywheel.report_wrote", f=out[key]) for key in ("figure", "hyperbola") if key in out]
    return lines


__all__ = ["moment_lines", "report_lines", "sizing_lines", "table_lines", "value"]
