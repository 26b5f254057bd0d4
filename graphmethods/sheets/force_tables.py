"""The force sheet's tables, each the rows of one table as ``forces P --position K`` prints them (one truth):

- :func:`reaction_rows`: every reaction of the position, its components and magnitude (N), the force of
  link i on link j as the command line names it;
- :func:`inertia_rows`: every link's inertia force (components and magnitude, N), its inertia moment (N·m)
  and the arm h = |M_и|/|F_и| (m) at which the force alone stands for both;
- :func:`load_rows`: the external loads (the working load, weights) with their points, as given;
- :func:`cycle_rows`: the balancing moment at every position of the cycle from the force plans and from
  Zhukovsky's lever (the ordinates of M_b(φ), :mod:`~graphmethods.sheets.balancing_graph`).

Round-off beside the table's largest value prints as 0.

>>> from graphmethods.problems import builtin
>>> from graphmethods.sheets.forces import analysed
>>> fa, i = analysed(builtin.case("press"), position=3, phi_deg=None, m=12)
>>> reaction_rows(fa, i, "en")[1]
('R_{01}', '−4628.1', '518.75', '4657')
>>> inertia_rows(fa, i, "en")[2]
('2', '−83.757', '532.53', '539.08', '−30.191', '0.056006')
>>> cycle_rows(fa, "en")[5]
('3', '90', '460.36', '460.36')
"""

from __future__ import annotations

from typing import Any

import numpy as np

from graphmethods.scene import notation as get_notation
from graphmethods.scene.numbers import round_off_zero
from graphmethods.sheets.force_symbols import force_symbol as _markup


def reaction_rows(fa: Any, i: int, nt: Any = "en") -> list[tuple[str, ...]]:
    """The reactions of position ``i``: pair, R_x, R_y, |R| (N), the pairs in the command line's order."""
    nt = get_notation(nt)
    N = "N"
    rows: list[tuple[str, ...]] = [(nt.word("forces.pair"), nt.quantity("R_x", N), nt.quantity("R_y", N),
                                    nt.quantity("|R|", N))]
    big = max([float(abs(r.R[i])) for r in fa.reactions.values()] + [0.0])
    for key, r in sorted(fa.reactions.items(), key=lambda kv: (len(kv[0]), kv[0])):
        R = complex(r.R[i])
        rows.append((_markup(key), *(nt.number(round_off_zero(v, big), sig=5) for v in (R.real, R.imag, abs(R)))))
    return rows


def inertia_rows(fa: Any, i: int, nt: Any = "en") -> list[tuple[str, ...]]:
    """The inertia loads of position ``i``: link, F_иx, F_иy, |F_и| (N), M_и (N·m), h (m; "—" for a link with
    a couple and no force)."""
    nt = get_notation(nt)
    si = nt.word("forces.sub_inertia")
    rows: list[tuple[str, ...]] = [(nt.word("forces.link"), nt.quantity(f"F_{{{si}x}}", "N"),
                                    nt.quantity(f"F_{{{si}y}}", "N"), nt.quantity(f"|F_{{{si}}}|", "N"),
                                    nt.quantity(f"M_{{{si}}}", "N·m"), nt.quantity("h", "m"))]
    loads = {k: fa.inertia_of(k) for k in fa.motion.linkage.links}
    big_F = max([float(abs(F[i])) for F, _ in loads.values()] + [0.0])
    big_M = max([float(abs(M[i])) for _, M in loads.values()] + [0.0])
    for k, (F_, M_) in loads.items():
        F, M = complex(F_[i]), round_off_zero(float(M_[i]), big_M)
        Fx, Fy, Fa = (round_off_zero(v, big_F) for v in (F.real, F.imag, abs(F)))
        h = "0" if M == 0.0 else ("—" if Fa == 0.0 else nt.number(abs(M) / abs(F), sig=5))
        rows.append((k, nt.number(Fx, sig=5), nt.number(Fy, sig=5), nt.number(Fa, sig=5), nt.number(M, sig=5), h))
    return rows


def load_rows(fa: Any, i: int, nt: Any = "en") -> list[tuple[str, ...]]:
    """The external loads of position ``i`` (the working load, weights; no inertia load): load, link, its
    point x, y (m), F_x, F_y, |F| (N), a couple M (N·m), "—" where a load has none (a column no load has
    left out); [] when there is none.

    >>> from graphmethods.problems import builtin
    >>> from graphmethods.sheets.forces import analysed
    >>> fa, i = analysed(builtin.case("four-bar"), position=3, phi_deg=None, m=12)
    >>> load_rows(fa, i, "en")[1]
    ('M_{c3}', '3', '−40')
    """
    nt = get_notation(nt)
    rows: list[tuple[str, ...]] = []
    n = nt.number
    for k, forces in fa.applied.items():
        for f in forces:
            if f.label.startswith("F_i"):
                continue
            F, M = complex(f.F[i]), float(f.M[i])
            if F != 0:
                at = complex(f.at[i])
                xy = [round_off_zero(v, abs(at)) for v in (at.real, at.imag)]       # a point on an axis: 0
                Fx, Fy = (round_off_zero(v, abs(F)) for v in (F.real, F.imag))
                rows.append((_markup(f.label), k, n(xy[0], sig=5), n(xy[1], sig=5), n(Fx, sig=5), n(Fy, sig=5),
                             n(abs(F), sig=5), "—"))
            if M != 0:
                rows.append((_markup(f.label), k, "—", "—", "—", "—", "—", n(M, sig=5)))
    if not rows:
        return []
    table = [(nt.word("forces.load"), nt.word("forces.link"), nt.quantity("x", "m"), nt.quantity("y", "m"),
              nt.quantity("F_x", "N"), nt.quantity("F_y", "N"), nt.quantity("|F|", "N"),
              nt.quantity("M", "N·m"))] + rows
    keep = [c for c in range(8) if c < 2 or any(r[c] != "—" for r in rows)]     # no column of dashes only
    return [tuple(r[c] for c in keep) for r in table]


def cycle_rows(fa: Any, nt: Any = "en") -> list[tuple[str, ...]]:
    """The balancing moment at positions 0…m: position, φ (°, from position 0), M_b from the force plans
    and from the lever (N·m); two heading rows (the quantity, then the method)."""
    nt = get_notation(nt)
    M_b = nt.sym("forces.M_b")
    unit = nt.quantity(M_b, "N·m")
    rows: list[tuple[str, ...]] = [(nt.word("dynamics.position"), nt.quantity("φ", "°"), unit, unit),
                                   ("", "", nt.word("forces.by_plans"), nt.word("forces.by_lever"))]
    M, L = np.asarray(fa.M_balance, dtype=float), np.asarray(fa.M_balance_lever, dtype=float)
    big = float(np.abs(M).max()) if len(M) else 0.0
    phi = np.degrees(np.asarray(fa.motion.phi_from_start, dtype=float))
    for k in range(len(M)):
        rows.append((str(k), nt.number(round_off_zero(float(phi[k]), 360.0), sig=4),
                     nt.number(round_off_zero(float(M[k]), big), sig=5),
                     nt.number(round_off_zero(float(L[k]), big), sig=5)))
    return rows


__all__ = ["cycle_rows", "inertia_rows", "load_rows", "reaction_rows"]
