"""What each panel of the force sheet holds, stated without drawing it: for a composer that sizes the
panels' boxes to their drawings (:class:`~graphmethods.sheets.force_fit.PanelContent`).

Four kinds, each drawn by its recipe in the box it is given:

- ``"scheme"``: the linkage in the position with every force (:func:`~graphmethods.sheets.forces.force_scheme`),
  its points in m (the joints, the guides' ends and the forces' tips at the μ_F that draws the largest
  force half the linkage's size);
- ``"lever"``: Zhukovsky's lever (:func:`~graphmethods.sheets.forces.zhukovsky_forces`), the plan of analogues
  v/ω₁ turned 90° (m) with its forces' tips the same way;
- ``"group"``: group ``j`` cut from the linkage (:func:`~graphmethods.sheets.force_sheet_plans.group_panel`);
- ``"plan"``: force plan ``j`` (:func:`~graphmethods.sheets.force_sheet_plans.plan_panel`), its vertices in N.

The fixed text (heading, the lines above the drawing, the scale line under it) is given in mm at the
page's lettering.

>>> from graphmethods.problems import builtin
>>> from graphmethods.sheets.forces import analysed
>>> fa, i = analysed(builtin.case("press"), position=3, phi_deg=None, m=12)
>>> c = panel_content(fa, i, "plan", 0, page="A1")
>>> c.unit, len(c.points), c.text_mm[1] > 40.0
('N', 7, True)
>>> round(c.size_mm(50.0)[0])
116
"""

from __future__ import annotations

from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import notation as get_notation
from graphmethods.scene.markup import text_width_mm
from graphmethods.scene.notation import Notation
from graphmethods.scene.scale import pick_scale
from graphmethods.sheets import force_working as FW
from graphmethods.sheets.engine.lettering import lettering
from graphmethods.sheets.force_fit import PanelContent

KINDS = ("scheme", "lever", "group", "plan")


def _with_tips(points: list[complex], arrows: list[tuple[complex, complex]], ratio: float = 0.5) -> tuple[complex, ...]:
    """``points`` and the tips of ``arrows`` (point m, force N) drawn so the largest is ``ratio`` of the
    points' size (m)."""
    z = np.asarray(points, dtype=complex)
    size = max(float(np.ptp(z.real)), float(np.ptp(z.imag)), 1e-12)
    F_max = max([abs(F) for _, F in arrows] + [0.0])
    k = ratio * size / F_max if F_max > 0 else 0.0
    return tuple(points) + tuple(w + k * F for w, F in arrows)


def scheme_texts(fa: Any, i: int, nt: Notation) -> list[str]:
    """The scheme's lines: what its arrows are, M_b from the force plans."""
    return [nt.word("forces.inertia"), nt.word("forces.scheme_balance", Mb=nt.number(float(fa.M_balance[i]), sig=6))]


def lever_texts(fa: Any, i: int, nt: Notation) -> list[str]:
    """The lever's column: the plan turned, the couples, Σ M_p = 0 and F_b, M_b, the force plans' M_b."""
    from graphmethods.sheets import forces as SF

    lev = fa.lever
    Mb_l, Mb = float(lev.M_balance[i]), float(fa.M_balance[i])
    d = float(fa.difference_percent(lev.M_balance)[i])
    return [nt.word("forces.turned"), nt.word("forces.couple"),
            nt.word("forces.lever_equation", Fb=nt.number(abs(complex(lev.F_balance[i])), sig=5)),
            nt.word("forces.lever_result", Mb=nt.number(Mb_l, sig=6)),
            nt.word("forces.lever_plans", Mb=nt.number(Mb, sig=6), d=SF.percent_text(d, nt))]


def panel_content(fa: Any, i: int, kind: str, j: int = 0, *, nt: Any = "en", page: Any = "A1") -> PanelContent:
    """What panel ``kind`` (``"scheme"``, ``"lever"``, ``"group"``, ``"plan"``; ``j`` the plan's number, the
    crank's last) of the force analysis ``fa`` in position ``i`` holds: its points in model units and its
    fixed text in mm at ``page``'s lettering.

    Raises
    ------
    InputError
        An unknown kind or a plan number out of range.
    """
    from graphmethods.sheets import forces as SF
    from graphmethods.sheets.force_sheet_plans import (
        _found,
        _side_point,
        found_line,
        group_cloud,
        plan_equation,
        plan_sides,
    )

    nt = get_notation(nt)
    if kind not in KINDS:
        raise InputError(f"panel kind {kind!r}: give one of {', '.join(KINDS)}")
    if kind in ("group", "plan") and not 0 <= j < len(fa.plans):
        raise InputError(f"plan {j}: this force analysis has plans 0…{len(fa.plans) - 1}")
    let = lettering(page)
    head = let.title_mm + 5.0                                    # the heading and the gap under it
    below = SF.PLANS_LAYOUT.bottom_mm + 1.0                      # the scale line
    pad = SF.lettering_pad(page)
    mo = fa.motion
    if kind == "plan":
        sides = plan_sides(fa, j, i)
        pts = np.cumsum([0j] + [F for _, F, _ in sides])
        found = _found(fa, j, i, sides)
        mu = pick_scale(float(np.ptp(np.abs(pts))) or 1.0, 100.0, symbol="μ_F", unit=nt.unit("N"))
        lines = [found_line(lbl, R, mu, nt) for lbl, R in found]
        moments = FW.moment_working(fa, i, j, nt)
        width = max([text_width_mm(plan_equation(fa, j, i, nt), let.value_mm)]
                    + [text_width_mm(t, let.value_mm) for t in lines]
                    + [text_width_mm(t, let.label_mm) for t in moments])
        height = (head + 2.0 * let.value_mm + (len(found) + 0.5) * 1.8 * let.value_mm + SF.PLANS_LAYOUT.overhang_mm
                  + len(moments) * 1.8 * let.label_mm)
        margin = SF.PLANS_LAYOUT.left_mm + SF.PLANS_LAYOUT.overhang_mm
        return PanelContent(tuple(complex(p) for p in pts), nt.unit("N"), (width, height), below, margin)
    if kind == "group":
        lk = mo.linkage
        sides = plan_sides(fa, j, i)
        where = [_side_point(fa, lbl, i, lk.crank.pin, lk.crank.centre) for lbl, _, _ in sides]
        arrows = [(w, F) for w, (_, F, _) in zip(where, sides)]
        arrows += [(complex(f.at[i]), complex(f.F[i])) for ln in fa.plans[j].links for f in fa.applied.get(ln, ())]
        points = _with_tips(group_cloud(fa, j, i) + where, arrows)
        return PanelContent(points, nt.unit("m"), (0.0, head + 4.0), below, pad)
    if kind == "scheme":
        z = [complex(mo.z[p][i]) for p in mo.points] + SF._guide_ends(mo, SF._links_of(mo, i)[1])
        arrows = [(complex(f.at[i]), complex(f.F[i])) for fs in fa.applied.values() for f in fs]
        texts = scheme_texts(fa, i, nt)
    else:
        fixed = set(mo.linkage.ground)
        z = [0j] + [1j * complex(mo.v_[p][i]) / mo.omega_1 for p in mo.points if p not in fixed]
        lev = fa.lever
        arrows = [(complex(f.image[i]), complex(f.F[i])) for f in lev.forces]
        arrows.append((complex(lev.image_pin[i]), complex(lev.F_balance[i])))
        texts = lever_texts(fa, i, nt) + FW.lever_working(fa, i, nt)
    width = max(text_width_mm(t, let.label_mm) for t in texts)
    height = head + 2.0 + len(texts) * SF.SCHEME_LAYOUT.text_pitch_mm + SF.SCHEME_LAYOUT.reach_top_mm
    return PanelContent(_with_tips(z, arrows), nt.unit("m"), (width, height), below, pad)


__all__ = ["KINDS", "lever_texts", "panel_content", "scheme_texts"]
