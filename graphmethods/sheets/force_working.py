"""The working of the force sheet, as a teacher checks it: the inertia loads and each group's moment equation
with numbers, in the sheet's language.

- :func:`inertia_working`: for every moving mass with a load in the position,
  ``F_и3 = m_3·a_S3 = 20·0.6006 = 12.012 N``, ``M_и3 = J_S3·ε_3 = 1.1·1.1297 = 1.2427 N·m`` and
  ``h_3 = M_и3/F_и3 = …`` (the numbers ``forces P --position K`` prints: same values, same digits rule);
- :func:`moment_working`: the moment equation of a link of a group about the point where the group's other
  unknowns meet, which gives a component of a reaction before the plan is drawn (``ΣM_C(4) = 0:
  R^τ_34·l_BC + M_C(F_и4) + M_и4 = 0``), then the same with the numbers and the component found (signed:
  negative, it acts the other way round the point than assumed).

Only the lines whose numbers close are written: a moment equation is checked against the solver's own
component before it is printed (one truth), and left out when its terms do not sum to zero (a couple in a
prismatic pair the sheet does not draw).

>>> from graphmethods.problems import builtin
>>> from graphmethods.sheets.forces import analysed
>>> case = builtin.case("shaper")
>>> fa, i = analysed(case, position=3, phi_deg=None, m=12)
>>> inertia_working(case, fa, i, "en")[0]
'F_{i3} = m_{3}·a_{S3} = 20·0.6006 = 12.012 N'
>>> moment_working(fa, i, 0, "en")[1]
'R^{τ}_{34}·0.135 − 0.11034 − 0.036824 = 0, R^{τ}_{34} = 1.0901 N'
"""

from __future__ import annotations

import re
from typing import Any

from graphmethods.scene import notation as get_notation
from graphmethods.scene.notation import Notation
from graphmethods.scene.numbers import round_off_zero
from graphmethods.sheets.force_symbols import force_symbol

#: a moment equation is printed only when its terms sum to zero within this share of the largest
CLOSES = 1e-6


def _sub(text: str) -> str:
    """``S3`` → ``{S3}``: a point's or link's name as a subscript group."""
    return "{" + text + "}"


def inertia_working(case: Any, fa: Any, i: int, nt: Notation | str = "en") -> list[str]:
    """The inertia loads of position ``i`` worked out: ``F = m·a_S``, ``M = J_S·ε`` and the arm
    ``h = M/F`` of every mass with a load, in the notation's language and decimal mark (N, N·m, m)."""
    from graphmethods.dynamics.forces.problem import link_number

    nt = get_notation(nt)
    mo = fa.motion
    si = nt.word("forces.sub_inertia")
    n = nt.number
    loads = [float(abs(it.F_i[i])) for it in fa.inertia]
    big_F = max(loads + [0.0])
    big_M = max([float(abs(it.M_i[i])) for it in fa.inertia] + [0.0])
    out: list[str] = []
    for it, mass in zip(fa.inertia, getattr(case, "inertias", ())):
        if (link_number(case, mass.link, mass.point), mass.point) != (it.link, it.at):
            continue                                         # not the same mass: nothing printed for it
        k = it.link
        F = round_off_zero(float(abs(it.F_i[i])), big_F)
        M = round_off_zero(float(it.M_i[i]), big_M)
        if F > 0.0 and mass.m > 0.0:
            a = float(abs(mo.a_[it.at][i]))
            out.append(f"F_{{{si}{k}}} = m_{_sub(k)}·a_{_sub(it.at)} = {n(mass.m, sig=5)}·{n(a, sig=4)}"
                       f" = {n(F, sig=5)} {nt.unit('N')}")
        if M != 0.0 and mass.J > 0.0:
            eps = float(abs(mo.epsilon[k][i]))
            out.append(f"M_{{{si}{k}}} = J_{_sub(it.at)}·ε_{_sub(k)} = {n(mass.J, sig=5)}·{n(eps, sig=4)}"
                       f" = {n(abs(M), sig=5)} {nt.unit('N·m')}")
        if F > 0.0 and M != 0.0:
            h = float(it.h[i])
            out.append(f"h_{_sub(k)} = M_{{{si}{k}}}/F_{{{si}{k}}} = {n(abs(M), sig=5)}/{n(F, sig=5)}"
                       f" = {n(h, sig=5)} {nt.unit('m')}")
    return out


def _on_link(fa: Any, k: str, i: int, group: tuple[str, ...],
             unknown: str) -> list[tuple[str, complex, complex, float]]:
    """Every known force on link ``k`` in position ``i``: (label, force N, point m, couple N·m): its applied
    loads and the reactions of the links outside ``group`` solved before (not ``unknown``, the one sought)."""
    out = [(f.label, complex(f.F[i]), complex(f.at[i]), float(f.M[i])) for f in fa.applied.get(k, ())]
    for key, r in fa.reactions.items():
        a, b = key[2], key[3:]
        if key == unknown or k not in (a, b) or (a in group and b in group):
            continue
        other = b if a == k else a
        if other in group or other == "0":
            continue
        F = complex(r.R[i]) if b == k else -complex(r.R[i])
        out.append((f"R_{other}{k}", F, complex(r.at[i]), 0.0))
    return out


def _term(value: float, nt: Notation) -> str:
    """A signed term of a sum, as written after the first: `` + 0.42`` or `` − 0.42``."""
    return f" {'−' if value < 0 else '+'} {nt.number(abs(value), sig=5)}"


def moment_working(fa: Any, i: int, j: int, nt: Notation | str = "en") -> list[str]:
    """The moment equations of plan ``j``'s group in position ``i`` (two lines each: the equation in symbols,
    then in numbers with the component found), for the components the solver finds from a moment about a
    point (``R^τ`` of an outer reaction, a slider's reaction square to its slot); none for the crank."""
    nt = get_notation(nt)
    pl = fa.plans[j]
    mo = fa.motion
    first = dict(pl.first)
    out: list[str] = []
    for step in pl.steps:
        m = re.match(r"link (\w+): ΣM_(\w+) = 0 gives (\S+)", step)
        if not m or m.group(3) not in first or m.group(2) not in mo.z:
            continue
        k, P_name, label = m.groups()
        P = complex(mo.z[P_name][i])
        digits = label.split("_")[-1]
        key = "R_" + digits if "R_" + digits in fa.reactions else "R_" + digits[::-1]
        if key not in fa.reactions:
            continue
        A = complex(fa.reactions[key].at[i])
        R = complex(first[label][i])
        l_AP = abs(A - P)
        if l_AP == 0.0:
            continue
        tau = ((A - P).conjugate() * R).imag / l_AP        # its moment about P over the arm: signed R
        terms = []
        for lbl, F, at, M in _on_link(fa, k, i, tuple(pl.links), key):
            mF = ((at - P).conjugate() * F).imag
            if F != 0 and abs(mF) > 0.0:
                terms.append((f"M_{_sub(P_name)}({force_symbol(lbl, nt)})", mF))
            if M != 0.0:
                terms.append((force_symbol(lbl.replace("F_", "M_", 1), nt), M))
        big = max([abs(tau * l_AP)] + [abs(v) for _, v in terms])
        size = l_AP * max(abs(complex(r.R[i])) for r in fa.reactions.values())   # the position's moments
        if round_off_zero(big, size) == 0.0:
            continue                                        # every term round-off: R^τ is 0, nothing to write
        if abs(tau * l_AP + sum(v for _, v in terms)) > CLOSES * big:
            continue                                        # a couple the sheet does not draw: no line
        terms = [(s, v) for s, v in terms if round_off_zero(abs(v), big) != 0.0]
        a_name = next((p for p in mo.points if abs(complex(mo.z[p][i]) - A) < 1e-12 * (1 + abs(A))), "A")
        arm = f"l_{{{a_name}{P_name}}}"
        R_sym = force_symbol(label, nt)
        symbols = f"ΣM_{_sub(P_name)}({k}) = 0:  {R_sym}·{arm}" + "".join(f" + {s}" for s, _ in terms) + " = 0"
        numbers = (f"{R_sym}·{nt.number(l_AP, sig=5)}" + "".join(_term(v, nt) for _, v in terms)
                   + f" = 0, {R_sym} = {nt.number(round_off_zero(tau, big / l_AP), sig=5)} {nt.unit('N')}")
        out += [symbols, numbers]
    return out


def lever_working(fa: Any, i: int, nt: Notation | str = "en", *, per_line: int = 3) -> list[str]:
    """Zhukovsky's lever's moment equation about the pole p with numbers: each force's magnitude times its
    arm on the plan of analogues (m), signed by its sense against F_b's, ``per_line`` terms to a line (F_b's
    value is the lever's next line, :func:`~graphmethods.sheets.force_panels.lever_texts`).

    >>> from graphmethods.problems import builtin
    >>> from graphmethods.sheets.forces import analysed
    >>> fa, i = analysed(builtin.case("press"), position=3, phi_deg=None, m=12)
    >>> lever_working(fa, i, "en")[-1]
    '     + 288.18·0.0991 − 5000·0.0991 = 0'
    """
    nt = get_notation(nt)
    lev = fa.lever
    F_b = complex(lev.F_balance[i])
    pin = complex(lev.image_pin[i])
    F_big = max([abs(complex(f.F[i])) for f in lev.forces] + [abs(F_b)])
    big = max([abs(float(f.moment[i])) for f in lev.forces] + [F_big * abs(pin)])   # a force times the lever's size
    s_b = 1.0 if (pin.conjugate() * F_b).imag >= 0 else -1.0     # F_b's moment taken positive
    terms = []
    for f in lev.forces:
        F, M = abs(complex(f.F[i])), float(f.moment[i])
        if round_off_zero(F, F_big) != 0.0 and round_off_zero(abs(M), big) != 0.0:
            terms.append((s_b * M < 0, f"{nt.number(F, sig=5)}·{nt.number(abs(M) / F, sig=4)}"))
    h_b = abs((pin.conjugate() * F_b).imag) / abs(F_b) if abs(F_b) > 0 else abs(pin)
    fb = force_symbol("F_b", nt)
    head = f"Σ M_p = 0:  {fb}·{nt.number(h_b, sig=4)}"
    parts = [f" {'−' if neg else '+'} {t}" for neg, t in terms]
    lines = [head + "".join(parts[:per_line])]
    lines += ["    " + "".join(parts[k:k + per_line]) for k in range(per_line, len(parts), per_line)]
    lines[-1] += " = 0"
    return lines


def power_working(fa: Any, i: int, nt: Notation | str = "en") -> list[str]:
    """The balancing moment from the power balance worked out, ``M_b·ω_1 + ΣF·v·cos α + ΣM·ω = 0``: each
    force's power (its magnitude, its point's speed, the angle α between them: the pressure angle, ϑ in ru),
    each couple's (M·ω, signed),
    then M_b = −ΣP/ω_1 (the result table's third value; the terms of round-off size left out).

    >>> from graphmethods.problems import builtin
    >>> from graphmethods.sheets.forces import analysed
    >>> fa, i = analysed(builtin.case("press"), position=3, phi_deg=None, m=12)
    >>> power_working(fa, i, "en")[-1]
    'M_b = −ΣP/ω_{1} = −(−14463)/31.416 = 460.361 N·m'
    """
    import numpy as np

    nt = get_notation(nt)
    mo = fa.motion
    w1 = mo.linkage.sense * mo.omega_1
    n = nt.number
    W = nt.unit("W")
    terms: list[tuple[str, float]] = []
    scale = 0.0                                            # the powers' own size: |F|·|v|, |M|·|ω_1|
    for f in fa.lever.forces:                              # a force's point moves at v = −i·image·ω₁
        F = complex(f.F[i])
        if f.label.startswith("M") or F == 0:
            continue
        v = -1j * complex(f.image[i]) * mo.omega_1
        P = (v.conjugate() * F).real
        scale = max(scale, abs(F) * abs(v))
        alpha = round_off_zero(float(np.degrees(np.angle(F / v))), 180.0) if v != 0 else 90.0
        terms.append((f"P({force_symbol(f.label, nt)}) = {n(abs(F), sig=5)}·{n(abs(v), sig=4)}·cos "
                      f"{n(abs(alpha), sig=4)}° = ", P))
    for k, fs in fa.applied.items():
        w = float(mo.omega[k][i])
        for f in fs:
            M = float(f.M[i])
            if M != 0.0 and w != 0.0:
                name = force_symbol(f.label.replace("F_", "M_", 1) if f.label.startswith("F_") else f.label, nt)
                w_text = n(w, sig=4) if w > 0 else f"({n(w, sig=4)})"
                terms.append((f"P({name}) = {n(M, sig=5)}·{w_text} = ", M * w))
                scale = max(scale, abs(M) * max(abs(w), abs(w1)))
    terms = [(t, P) for t, P in terms if round_off_zero(abs(P), scale) != 0.0]
    M_b = nt.sym("forces.M_b")
    total = sum(P for _, P in terms)
    return ([f"{M_b}·ω_{{1}} + ΣF·v·cos {nt.sym('cam.alpha')} + ΣM·ω = 0"] + [f"{t}{n(P, sig=5)} {W}" for t, P in terms]
            + [f"{M_b} = −ΣP/ω_{{1}} = −({n(total, sig=5)})/{n(w1, sig=5)}"
               f" = {n(float(fa.M_balance_power[i]), sig=6)} {nt.unit('N·m')}"])


def drawn_lengths(sides: list[tuple[str, complex, bool]], s_F: Any, nt: Notation | str = "en", *,
                  least_mm: float = 1.0) -> list[str]:
    """The lengths (mm) the known forces of a plan are drawn at, as the course writes them before drawing:
    ``F_{c3}/μ_F = 5000/20 = 250 mm`` (none for a force of round-off size or shorter than ``least_mm``, too
    short to lay off; the sides as :func:`~graphmethods.sheets.force_sheet_plans.plan_sides` gives them).

    >>> from graphmethods.scene import Scale
    >>> drawn_lengths([("F_c3", 5000 + 0j, True), ("R_03", 1e3j, False)], Scale("μ_F", "N", 20.0))
    ['F_{c3}/μ_F = 5000/20 = 250 mm']
    """
    nt = get_notation(nt)
    big = max([abs(F) for _, F, _ in sides] + [0.0])
    out = []
    for lbl, F, known in sides:
        if not known or round_off_zero(abs(F), big) == 0.0 or "'" in lbl or abs(F) / s_F.per_mm < least_mm:
            continue
        name = force_symbol(lbl, nt)
        out.append(f"{name}/μ_F = {nt.number(abs(F), sig=5)}/{nt.number(s_F.per_mm, sig=4)}"
                   f" = {nt.number(abs(F) / s_F.per_mm, sig=4)} {nt.unit('mm')}")
    return out


def working_lines(case: Any, fa: Any, i: int, nt: Notation | str = "en") -> list[tuple[str, bool]]:
    """The sheet's working, in order: (text, heading?): the inertia loads, M_b from the power balance, then
    each group's moment equations under the group's name (the groups with none left out).

    >>> from graphmethods.problems import builtin
    >>> from graphmethods.sheets.forces import analysed
    >>> case = builtin.case("press")
    >>> fa, i = analysed(case, position=3, phi_deg=None, m=12)
    >>> [t for t, heading in working_lines(case, fa, i, "en") if heading]
    ['Inertia loads', 'M_b from the power balance', 'group RRP (2, 3)']
    """
    nt = get_notation(nt)
    out: list[tuple[str, bool]] = []
    loads = inertia_working(case, fa, i, nt)
    if loads:
        out += [(nt.word("forces.inertia_loads"), True)] + [(t, False) for t in loads]
    power = power_working(fa, i, nt)
    out += [(nt.word("forces.Mb_power", Mb=nt.sym("forces.M_b")), True)] + [(t, False) for t in power]
    for j, pl in enumerate(fa.plans):
        lines = moment_working(fa, i, j, nt)
        if lines:
            out += [(nt.word("forces.group", g=pl.group), True)] + [(t, False) for t in lines]
    return out


__all__ = ["drawn_lengths", "inertia_working", "lever_working", "moment_working", "power_working", "working_lines"]
