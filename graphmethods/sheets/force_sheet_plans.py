"""One force plan in its own panel, at its own μ_F: the force sheet's plans as the textbook draws them.

On the A1 force sheet each Assur group's force plan, and the crank's, gets a panel of its own and the
largest convenient μ_F (1, 2, 2.5, 4, 5 × 10ᵏ N/mm) at which its polygon fills that panel, printed under
it; above it the group's vector equation (the sides in the order drawn, ``… = 0``). The group plan is
:func:`graphmethods.sheets.forces._group_plan`'s (known sides solid, unknown dashed with their lines of
action, each link's own polygon closed by the inner reaction). The crank's plan is the closed triangle
the course draws: the balancing moment M_b replaced by the balancing force F_b at the crank pin,
perpendicular to OA (F_b·l_OA = M_b, Zhukovsky's F_b), so that R_21 (+ F_i1) + F_b + R′_01 = 0; R′_01,
the frame's reaction with F_b in place of M_b, closes it (dashed).

>>> from graphmethods.problems import builtin
>>> from graphmethods.sheets.forces import analysed
>>> fa, i = analysed(builtin.case("press"), position=3, phi_deg=None, m=12)
>>> [label for label, _, _ in plan_sides(fa, len(fa.plans) - 1, i)]
['F_i1', 'R_21', 'F_b', "R'_01"]
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import Element, Page, Scale, Scene, Text, Vector, markup, notation as get_notation
from graphmethods.scene.notation import Notation
from graphmethods.scene.numbers import within_roundoff
from graphmethods.sheets import force_working as FW, forces as SF
from graphmethods.sheets.engine.lettering import lettering
from graphmethods.sheets.force_fit import drawn_tip, fit_forces
from graphmethods.sheets.force_linkage import _slots, _yokes
from graphmethods.sheets.layout import Sheet, given_scale


def plan_sides(fa: Any, j: int, i: int) -> list[tuple[str, complex, bool]]:
    """The sides of plan ``j`` in position ``i`` as drawn: (label, force in N, known). A group's: its
    polygon's known forces, then the unknowns. The crank's: the known forces (F_i1, R_21), the balancing
    force F_b at the pin (Zhukovsky's, ⊥ OA), and R′_01 closing the triangle."""
    pl = fa.plans[j]
    poly = pl.polygons[0]
    sides = [(lbl, complex(F[i]), True) for lbl, F in poly.known]
    if not pl.group.startswith("I "):
        return sides + [(lbl, complex(F[i]), False) for lbl, _, F in poly.closing]
    F_b = complex(fa.lever.F_balance[i])
    sides.append(("F_b", F_b, True))
    total = sum(F for _, F, _ in sides)
    return sides + [("R'_01", -total, False)]


def _label(lbl: str, nt: Notation) -> str:
    """A side's label in the books' markup (R′_01 primed)."""
    if lbl.startswith("R'_"):
        return "R′" + SF._markup("R" + lbl[2:], nt)[1:]
    return SF._markup(lbl, nt)


def _keep_clear(sheet: Sheet, text: Text) -> None:
    """Labels placed later keep off ``text``."""
    box = text.bbox()
    if box is not None:
        sheet.occ.add_box(box)


def plan_equation(fa: Any, j: int, i: int, nt: Notation) -> str:
    """The vector equation of plan ``j``: its sides (none of round-off size) summed to zero.

    >>> from graphmethods.problems import builtin
    >>> from graphmethods.sheets.forces import analysed
    >>> fa, i = analysed(builtin.case("press"), position=3, phi_deg=None, m=12)
    >>> plan_equation(fa, 0, i, get_notation("en"))
    'R^{τ}_{12} + F_{i2} + F_{i3} + F_{c3} + R_{03} + R^{n}_{12} = 0'
    """
    sides = plan_sides(fa, j, i)
    big = max(abs(F) for _, F, _ in sides)
    kept = [lbl for lbl, F, _ in sides if big == 0.0 or not within_roundoff(abs(F), big)]   # all 0: all written
    return " + ".join(_label(lbl, nt) for lbl in kept) + " = 0"


def _found(fa: Any, j: int, i: int, sides: list[tuple[str, complex, bool]]) -> list[tuple[str, float]]:
    """The reactions plan ``j`` finds, each with its magnitude (N) as the reactions table prints it: the
    unknown sides and the inner reactions (none for the crank's R′_01, which no table lists)."""
    pl = fa.plans[j]
    big = max([float(abs(r.R[i])) for r in fa.reactions.values()] + [0.0])
    labels = [lbl for lbl, _, known in sides if not known and not lbl.startswith("R'") and "^" not in lbl]
    labels += [lbl for inner in pl.polygons[1:] for lbl, _, _ in inner.closing]
    out = []
    for lbl in labels:
        d = lbl.split("_")[-1]
        key = "R_" + d if "R_" + d in fa.reactions else "R_" + d[::-1]
        out.append((lbl, SF.round_off_zero(float(abs(fa.reactions[key].R[i])), big)))
    return out


def found_line(lbl: str, R: float, s_F: Scale, nt: Notation) -> str:
    """A reaction found on a plan as the book writes it: its side's length times μ_F.

    >>> found_line("R_05", 546.93, Scale("μ_F", "N", 50.0), get_notation("en"))
    'R_{05} = 10.94 mm · 50 N/mm = 546.93 N'
    """
    mu = s_F.caption(nt).split(" = ", 1)[1]
    return (f"{_label(lbl, nt)} = {nt.number(R / s_F.per_mm, sig=4)} {nt.unit('mm')} · {mu}"
            f" = {nt.number(R, sig=5)} {nt.unit('N')}")


def plan_panel(case: Any, fa: Any, i: int, j: int, *, nt: Any = "en", page: Page,
               phi_deg: float | None = None, working: bool = True, with_moments: bool = True) -> Scene:
    """Plan ``j`` (0: the last group solved first; the last: the crank's) of position ``i`` on ``page`` (a
    region of the sheet): its caption, its vector equation, the polygon at the largest convenient μ_F
    that fills the panel, the scale under it; with ``working`` (when the panel has room), the moment
    equations and the lengths laid off above them. ``with_moments`` false: no moment equations here, where
    the group's cut drawing writes them beside it (:func:`group_panel`).

    Raises
    ------
    InputError
        Every force of the plan zero in this position.
    """
    L = SF.PLANS_LAYOUT
    nt = get_notation(nt)
    pl = fa.plans[j]
    cap = (nt.word("forces.crank", g=pl.links[0]) if pl.group.startswith("I ") else nt.word("forces.group", g=pl.group))
    sheet = Sheet(nt=nt, page=page, title=cap, problem="", title_block=False)
    sides = plan_sides(fa, j, i)
    pts = np.cumsum([0j] + [F for _, F, _ in sides])
    inner = ([] if pl.group.startswith("I ") else      # each link's own polygon's sides: inside the panel too
             [z for poly in pl.polygons[1:] for _, z0, z1 in (SF._inner_sides(pl.polygons[0], poly, pts, i) or [])
              for z in (z0, z1)])
    fit = np.concatenate([pts, np.asarray(inner, dtype=complex)])
    let = lettering(page)
    found = _found(fa, j, i, sides)
    equation = plan_equation(fa, j, i, nt)
    if not np.any(np.abs(fit)):                                 # every force 0 (a group at rest): no polygon
        return _zero_plan(sheet, j, equation, found, nt, let.value_mm)
    wide = markup.text_width_mm(equation, let.value_mm) <= sheet.box[2] - sheet.box[0]
    eq_mm = let.value_mm if wide else let.label_mm              # the equation as large as the values when it fits
    pitch = 1.8 * let.value_mm

    def lines(s_F: Scale) -> list[str]:
        return [found_line(lbl, R, s_F, nt) for lbl, R in found]

    def lengths(s_F: Scale) -> list[str]:                       # the known forces' lengths at μ_F
        return FW.drawn_lengths(sides, s_F, nt) if working else []

    m_pitch = 1.8 * let.label_mm
    tries = (True, False) if working else (False,)
    for working in tries:                                       # the working when the panel has room for it
        moments = [part for line in (FW.moment_working(fa, i, j, nt) if working and with_moments else [])  # R^τ
                   for part in _broken(line, let.label_mm, sheet.box[2] - sheet.box[0])]
        n_known = len(FW.drawn_lengths(sides, Scale("μ_F", "N", 1.0), nt, least_mm=0.0)) if working else 0
        m_h = (len(moments) + n_known) * m_pitch

        def texts(mu: Scale, moments: list[str] = moments) -> list[tuple[str, float]]:
            return ([(t, let.label_mm) for t in moments + lengths(mu)] + [(equation, eq_mm)]
                    + [(t, let.value_mm) for t in lines(mu)])
        try:
            area, x_text, s_F = _plan_area(sheet, fit, L, texts, m_h + 2.0 * eq_mm + (len(found) + 0.5) * pitch)
            break
        except InputError:
            if not working:
                raise
    at = SF._cell(fit, (area[0], area[1], area[2] - area[0], area[3] - area[1]), s_F)
    els: list[Element] = [sheet.header()]
    for k, line in enumerate(moments + lengths(s_F)):
        kind = "moment" if k < len(moments) else "length"
        t = Text((x_text, sheet.top + let.label_mm + k * m_pitch), line, size_mm=let.label_mm, name=f"{kind}-{j}-{k}")
        _keep_clear(sheet, t)
        els.append(t)
    top = sheet.top + m_h
    eq = Text((x_text, top + eq_mm), equation, size_mm=eq_mm, name=f"equation-{j}")
    _keep_clear(sheet, eq)
    els.append(eq)
    for k, line in enumerate(lines(s_F)):
        t = Text((x_text, top + eq_mm + (k + 1) * pitch), line, size_mm=let.value_mm, name=f"found-{j}-{k}")
        _keep_clear(sheet, t)
        els.append(t)
    if pl.group.startswith("I "):
        drawn, wanted = _crank_plan(j, sides, pts, at, nt, sheet, L)
    else:
        drawn, wanted = SF._group_plan(j, pl, pts, i, at, nt, sheet.occ, L)
    els += drawn
    els += SF._labels(sheet.occ, _merged(wanted), L.within(area))
    return SF._finish(sheet, els, (s_F,), "", f"plan-{j}")


def _broken(line: str, size_mm: float, width_mm: float) -> list[str]:
    """A moment equation as one line, or broken after its last ", " into two when it is wider than ``width_mm``
    at ``size_mm`` (the equation, then the reaction it gives).

    >>> _broken("R·0.4 + 0.7 − 1469.2 = 0, R = 3682.1 N", 3.5, 200.0)
    ['R·0.4 + 0.7 − 1469.2 = 0, R = 3682.1 N']
    >>> _broken("R·0.4 + 0.7 − 1469.2 = 0, R = 3682.1 N", 3.5, 50.0)
    ['R·0.4 + 0.7 − 1469.2 = 0,', '    R = 3682.1 N']
    """
    head, sep, tail = line.rpartition(", ")
    if not sep or markup.text_width_mm(line, size_mm) <= width_mm:
        return [line]
    return [head + ",", "    " + tail]


def _zero_plan(sheet: Sheet, j: int, equation: str, found: list[tuple[str, float]], nt: Notation,
               size_mm: float) -> Scene:
    """Plan ``j`` whose polygon's forces are all zero in this position: its equation and each reaction it finds
    with its value (N, ``size_mm`` high), no polygon and no μ_F (a plan of round-off would draw 10⁻¹³ N at
    10⁻¹⁵ N/mm)."""
    pitch = 1.8 * size_mm
    x, top = sheet.box[0] + SF.PLANS_LAYOUT.left_mm, sheet.top
    els: list[Element] = [sheet.header(), Text((x, top + size_mm), equation, size_mm=size_mm, name=f"equation-{j}")]
    for k, (lbl, R) in enumerate(found):
        line = f"{_label(lbl, nt)} = {nt.number(R, sig=5)} {nt.unit('N')}"
        els.append(Text((x, top + size_mm + (k + 1) * pitch), line, size_mm=size_mm, name=f"found-{j}-{k}"))
    return SF._finish(sheet, els, (), "", f"plan-{j}")


def _merged(wanted: list[SF.LabelSpec]) -> list[SF.LabelSpec]:
    """The labels of sides drawn on one segment (a link's own polygon's R_34 and R_54 when its inertia force
    is too small to part them) written once, "R_34, R_54", at their common anchor (mm).

    >>> _merged([((0.0, 0.0), "R_{34}", "a"), ((0.5, 0.0), "R_{54}", "b"), ((9.0, 0.0), "F", "c")])
    [((0.0, 0.0), 'R_{34}, R_{54}', 'a'), ((9.0, 0.0), 'F', 'c')]
    """
    out: list[SF.LabelSpec] = []
    for anchor, text, name in wanted:
        k = next((k for k, (a, _, _) in enumerate(out) if math.dist(a, anchor) < 2.0), None)
        if k is None:
            out.append((anchor, text, name))
        else:
            out[k] = (out[k][0], f"{out[k][1]}, {text}", out[k][2])
    return out


def _plan_area(sheet: Sheet, pts: np.ndarray, L: SF.ForceFigureLayout,
               texts: Callable[[Scale], list[tuple[str, float]]], height_mm: float) -> tuple[SF.Box, float, Scale]:
    """Where a force plan (vertices ``pts``, N) is drawn in its panel, where its lines of text begin (x, mm) and
    its μ_F: the lines (``texts(μ_F)``: each text and its size, ``height_mm`` together) above the polygon (where
    the panel is as wide as they are) or in a column beside it, whichever draws the polygon larger (above on a
    tie).

    Raises
    ------
    InputError
        No room for the polygon, or every force zero.
    """
    x0, _, x1, _ = sheet.box
    m = L.left_mm + L.overhang_mm
    bottom = sheet.caption_y - L.bottom_mm
    options: list[tuple[float, int, SF.Box, float, Scale]] = []
    for n_o in (0, 1):
        col = 0.0
        for _ in range(3):                      # the column's width at the μ_F it gives (its lines print μ_F)
            top = sheet.top + (height_mm if n_o == 0 else 0.0) + L.overhang_mm
            area = (x0 + m, top, x1 - m - col, bottom)
            pw, ph = area[2] - area[0], area[3] - area[1]
            span = max(float(np.ptp(pts.real)) / max(pw, 1e-9), float(np.ptp(pts.imag)) / max(ph, 1e-9))
            if pw <= 10.0 or ph <= 10.0 or span <= 0:
                break
            s_F = given_scale(None, "μ_F", get_notation(sheet.nt).unit("N"), span * pw, pw, what="the force plan")
            if n_o == 0:                        # the lines above the polygon: as wide as the panel at most
                if max(markup.text_width_mm(t, mm) for t, mm in texts(s_F)) <= x1 - x0:
                    options.append((s_F.per_mm, n_o, area, x0, s_F))
                break
            col_new = max(markup.text_width_mm(t, mm) for t, mm in texts(s_F)) + 4.0
            if col_new <= col + 1e-9:
                options.append((s_F.per_mm, n_o, area, x1 - col + 2.0, s_F))
                break
            col = col_new
    if not options:
        if np.ptp(np.abs(pts)) == 0:
            raise InputError("every force is zero in this position; there is no force plan to draw")
        raise InputError("the force plan's panel is too small; give a larger page")
    _, _, area, x_text, s_F = min(options, key=lambda o: (o[0], o[1]))
    return area, x_text, s_F


def _crank_plan(j: int, sides: list[tuple[str, complex, bool]], pts: np.ndarray, at: SF.ToMm, nt: Notation,
                sheet: Sheet, L: SF.ForceFigureLayout) -> tuple[list[Element], list[SF.LabelSpec]]:
    """The crank's closed polygon: its sides head to tail, R′_01 dashed."""
    els: list[Element] = []
    labels: list[SF.LabelSpec] = []
    for s, (lbl, _F, known) in enumerate(sides):
        a, b = at(complex(pts[s])), at(complex(pts[s + 1]))
        if math.dist(a, b) < L.min_mm:
            continue
        v = SF._drawn(sheet.occ, Vector(a, b, known=known, head_length_mm=L.head_mm,
                                        name=f"{'known' if known else 'closing'}-{j}-{s}"))
        els.append(v)
        labels.append((v.mid, _label(lbl, nt), f"label-{j}-{s}"))
    return els, labels


def _side_point(fa: Any, lbl: str, i: int, pin: str, centre: str) -> complex:
    """Where the force of a plan's side acts (m): a reaction at its joint, an applied force at its point, the
    balancing force at the crank pin, R′_01 at the crank's centre."""
    mo = fa.motion
    if lbl == "F_b":
        return complex(mo.z[pin][i])
    if lbl.startswith("R'_"):
        return complex(mo.z[centre][i])
    if lbl.startswith("R"):
        d = lbl.split("_")[-1]
        r = fa.reactions.get("R_" + d) or fa.reactions["R_" + d[::-1]]
        return complex(r.at[i])
    for fs in fa.applied.values():
        for f in fs:
            if f.label == lbl:
                return complex(f.at[i])
    raise InputError(f"force {lbl!r} has no point of application")         # not reached: every side has one


def _group_points(mo: Any, j_links: tuple[str, ...], g: Any) -> set[str]:
    """The points of the group (or the crank) whose links are ``j_links``: its joints and its links' points."""
    names = {v for v in vars(g).values() if isinstance(v, str) and v in mo.z}
    names |= {v for f in ("inner", "outer") for v in getattr(g, f, ()) if v in mo.z}
    names |= {p.name for p in mo.linkage.points if p.link in j_links}
    return names


def _group_of(fa: Any, j: int) -> Any:
    """The linkage's group (or crank) of plan ``j`` (the plans run from the last group to the crank)."""
    lk = fa.motion.linkage
    return lk.crank if fa.plans[j].group.startswith("I ") else lk.groups[len(fa.plans) - 2 - j]


def group_cloud(fa: Any, j: int, i: int) -> list[complex]:
    """The points (m) of plan ``j``'s group cut from the linkage in position ``i``: its shape."""
    mo = fa.motion
    return [complex(mo.z[p][i]) for p in sorted(_group_points(mo, tuple(fa.plans[j].links), _group_of(fa, j)))]


def moments_fit(fa: Any, i: int, j: int, nt: Any, page: Page) -> bool:
    """Whether group ``j``'s moment equations (:func:`~graphmethods.sheets.force_working.moment_working`) fit
    across ``page`` (the group's panel) at its lettering, leaving the drawing at least 60 % of the height."""
    lines = FW.moment_working(fa, i, j, nt)
    if not lines:
        return False
    box = page.inner_box()
    let = lettering(page)
    return (max(markup.text_width_mm(t, let.label_mm) for t in lines) <= box[2] - box[0] - 2.0
            and len(lines) * 1.8 * let.label_mm <= 0.4 * (box[3] - box[1]))


def group_panel(case: Any, fa: Any, i: int, j: int, *, nt: Any = "en", page: Page, moments: bool = False) -> Scene:
    """The group of plan ``j`` (or the crank) cut from the linkage, to μ_l, with every force of its plan at
    its point to μ_F: the applied forces and moments with their values, the reactions of the links it was
    cut from (dashed: found on the plan). ``moments``: the group's moment equations with their numbers
    written under the heading, beside the drawing they are taken from (:func:`moments_fit`)."""
    nt = get_notation(nt)
    mo = fa.motion
    pl = fa.plans[j]
    lk = mo.linkage
    pts_names = _group_points(mo, tuple(pl.links), _group_of(fa, j))
    sheet = Sheet(nt=nt, page=page, title=nt.word("forces.cut_group"), problem="", title_block=False)
    let = lettering(page)
    texts: list[Text] = [Text((sheet.box[0], sheet.top + let.label_mm + k * 1.8 * let.label_mm), line,
                              size_mm=let.label_mm, name=f"moment-{j}-{k}")
                         for k, line in enumerate(FW.moment_working(fa, i, j, nt) if moments else [])]
    for t in texts:
        _keep_clear(sheet, t)
    sheet.top += len(texts) * 1.8 * let.label_mm
    z = {p: complex(mo.z[p][i]) for p in pts_names}
    sides = plan_sides(fa, j, i)
    big = max(abs(F) for _, F, _ in sides)
    where = {lbl: _side_point(fa, lbl, i, lk.crank.pin, lk.crank.centre) for lbl, _, _ in sides}
    L = SF.SCHEME_LAYOUT
    area = (sheet.box[0], sheet.top + 4.0, sheet.box[2], sheet.caption_y - L.bottom_mm)
    arrows = [(where[lbl], F) for lbl, F, _ in sides]
    arrows += [(complex(f.at[i]), complex(f.F[i])) for ln in pl.links for f in fa.applied.get(ln, ())]
    slots = [z_ for g, c, d in _slots(mo, i) if g.P in z and g.R in z for z_ in (c - d, c + d)]   # a yoke's slot
    s_l, s_F, at = fit_forces(list(z.values()) + list(where.values()) + slots, arrows, area, nt,
                              pad_mm=SF.lettering_pad(page))
    segs, blocks = SF._links_of(mo, i)
    yokes, slotted = _yokes(mo, i, z, at, area)
    segs = [(a, b) for a, b in segs if a in z and b in z and abs(z[a] - z[b]) > 0 and (a, b) not in slotted]
    occ = sheet.occ
    from graphmethods.scene import Line
    from graphmethods.sheets.kinematic_symbols import PinJoint, SliderBlock

    els: list[Element] = [sheet.header(), *texts, *(SF._drawn(occ, e) for e in SF.plates(segs, z, at))]
    els += [SF._drawn(occ, Line(at(z[a]), at(z[b]), style=SF.LINK, name=f"link-{a}-{b}")) for a, b in segs]
    els += [SF._drawn(occ, SliderBlock(at(z[p]), angle_deg=math.degrees(math.atan2(u.imag, u.real)),
                                       name=f"block-{k}")) for k, (p, u) in enumerate(blocks) if p in z]
    els += [SF._drawn(occ, e) for e in yokes]
    els += [SF._drawn(occ, PinJoint(at(z[p]), name=f"joint-{p}")) for p in sorted({q for sg in segs for q in sg})]
    labels: list[SF.LabelSpec] = [(at(z[p]), markup.lowered_digits(p), f"point-{p}") for p in sorted(z)]
    applied = [(f.label, complex(f.F[i]), complex(f.at[i]), SF.round_off_zero(float(f.M[i]), big))
               for ln in pl.links for f in fa.applied.get(ln, ())]
    drawn, wanted = SF._applied(applied, at, s_F, nt, occ, L, lambda w_: SF._directions(w_, z, segs),
                                  least=True)
    els += drawn
    labels += wanted
    own = {f[0] for f in applied}
    for k, (lbl, F, _known) in enumerate(sides):
        if lbl in own or within_roundoff(abs(F), big):
            continue
        a = at(where[lbl])
        b, _ = drawn_tip(a, F, s_F)
        els.append(SF._drawn(occ, Vector(a, b, known=lbl == "F_b", head_length_mm=L.head_mm, name=f"reaction-{k}")))
        labels.append((b, _label(lbl, nt), f"label-reaction-{k}"))
    els += SF._labels(occ, labels, L.within(area))
    return SF._finish(sheet, els, (s_l, s_F), "", f"group-{j}")


__all__ = ["group_panel", "moments_fit", "plan_equation", "plan_panel", "plan_sides"]
