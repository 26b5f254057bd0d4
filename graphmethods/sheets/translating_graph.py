"""The translating equivalent link's m_e(φ) against the crank angle (A4 landscape).

m_e = Σ[m(v_S/v)² + J_S(ω/v)²] grows without bound at the dead centres (v = 0), so each branch
between two dead centres is drawn up to ``cap`` times the smallest m_e and the cut is said in
the legend; the positions 0…m are marked on the φ axis and m_e is dotted at the study's positions
(except the dead centres, where it is not defined).

>>> from graphmethods.dynamics.study import Study
>>> from graphmethods.problems.builtin import case
>>> s = equivalent_mass_graph(Study(case("scotch-yoke")))
>>> s.name, s.element("curve-m_e-1").name
('equivalent-mass-graph', 'curve-m_e-1')
"""

from __future__ import annotations

from typing import Any

import numpy as np

from graphmethods.scene import notation as get_notation
from graphmethods.sheets.dynamics import MAIN, CurveSpec, as_study, phi_graph


def equivalent_mass_graph(study: Any, *, point: str | None = None, cap: float = 6.0, samples: int = 720,
                          notation: str = "en", mu_m: Any = None, mu_phi: Any = None) -> Any:
    """m_e(φ) of the translating link at ``point`` (default: the point the load acts on).

    Parameters
    ----------
    study : Study or Case
    point : str, optional
        A point of the translating link.
    cap : float
        Each branch is drawn while m_e ≤ cap·min m_e (default 6).
    samples : int
        Positions the curve is computed at (the dead centres fall among the study's own positions).
    """
    from graphmethods.dynamics.study import Study

    study = as_study(study)
    nt = get_notation(notation)
    fine = Study(study.case, positions=int(samples), estimate=False).translating(point)
    dots_tr = study.translating(point)
    top = cap * float(fine.m_e.min())
    phi, m_e = np.asarray(fine.phi, dtype=float), np.asarray(fine.m_e, dtype=float)
    keep = m_e <= top
    # branches: runs of kept samples, split at the dead centres (gaps in the positions) and at the cap
    idx = np.asarray(fine.index)
    breaks = np.flatnonzero((np.diff(idx) > 1) | (np.diff(keep.astype(int)) != 0)) + 1
    curves: list = []
    for seg in np.split(np.arange(phi.size), breaks):
        if seg.size >= 2 and keep[seg].all():
            curves.append(CurveSpec(f"m_e-{len(curves) + 1}", phi[seg], m_e[seg], MAIN, "m_e" if not curves else ""))
    dk = np.asarray(dots_tr.m_e, dtype=float) <= top
    legend = nt.word("translating.legend", cap=nt.number(cap, sig=3), top=nt.number(top, sig=4))
    return phi_graph(study, nt=nt, title=nt.word("translating.title"), page=None, title_block=True,
                        name="equivalent-mass-graph",
                        curves=curves, y_lo=0.0, y_hi=top, y_symbol="m_e", y_unit="kg", scale_symbol="μ_m",
                        mu_Y=mu_m, mu_phi=mu_phi, what="the equivalent mass", legend=legend, zero=True,
                        dots=(np.asarray(dots_tr.phi)[dk], np.asarray(dots_tr.m_e)[dk]))
