"""The force plans of one position: each group's polygon at one μ_F, and the results beside them.

For each Assur group, in the order they are solved (the last group first), the group's force
plan as the course draws it: the known forces laid head to tail (solid; the tangential parts
found first from the moments about the middle joint, the inertia forces, weights, the load, the
reactions of the groups solved before), closed by the unknowns (dashed) along their directions
(thin lines through the ends), and on it each link's own polygon closed by the inner reaction
(``R_12 + F_i2 + R_32 = 0``: R_12 and R_32 dashed between the group polygon's vertices); then the
crank's polygon closed by R_01. One scale μ_F for every
polygon, a convenient value picked to fit (reported). Beside them: every reaction's magnitude
and the balancing moment from the force plans, Zhukovsky's lever and the power balance, with
their differences in per cent.

>>> from graphmethods.problems import builtin
>>> s = force_plans(builtin.case("press"), position=3, notation="ru")
>>> s.title
'Планы сил, положение 3'
>>> sorted(e.name for e in s.elements if e.name.startswith("closing-"))[:2]
['closing-0-0', 'closing-0-1']
"""

from __future__ import annotations

import math
import re

import numpy as np

from graphmethods.errors import InputError
from graphmethods.problems.reference_cases import title_of
from graphmethods.scene import Line, Page, Table, Text, Vector, notation as get_notation
from graphmethods.scene.notation import Notation
from graphmethods.scene.primitives import THIN
from graphmethods.sheets.layout import TEXT_MM, Sheet, given_scale

SMALL_MM = 2.8
TABLE_MM = 3.2

def analysed(case, *, position: int | None, phi_deg: float | None, m: int, gravity: bool = False):
    """The force analysis a force figure draws and the index of its position in it: position
    ``position`` of 0…m (default 2), or the one crank angle ``phi_deg`` (degrees) when given."""
    from graphmethods.dynamics.forces import case_forces

    if phi_deg is not None:
        return case_forces(case, phi_deg=[float(phi_deg)], gravity=gravity), 0
    k = 2 if position is None else position
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or not 0 <= int(k) <= m:
        raise InputError(f"position {position!r}: give a position number 0…{m}")
    return case_forces(case, m=m, gravity=gravity), int(k)


def percent_text(d: float, nt: Notation) -> str:
    """A difference of two balancing moments in per cent, as a course project prints it: three
    decimals (round-off, some 1e-14 %, prints 0.000 on every machine), the notation's decimal mark."""
    text = f"{abs(d):.3f}"
    return text.replace(".", nt.decimal)


def _markup(label: str, nt: Notation | str | None = None) -> str:
    """``R^τ_12`` → ``R^{τ}_{12}``, ``F_i2`` → ``F_{i2}`` (ru ``F_{и2}``, zh ``F_{I2}``), ``F_b`` → ``F_{b}``
    (ru ``F_{ур}``), ``R_01@…`` → ``R_{01}``: the inertia and balancing subscripts as the books write them.

    >>> _markup("F_i2"), _markup("M_i3", "ru"), _markup("F_i2", "zh"), _markup("F_b", "ru")
    ('F_{i2}', 'M_{и3}', 'F_{I2}', 'F_{ур}')
    """
    label = label.split("@")[0]
    m = re.fullmatch(r"([A-Za-z]+)(\^[^_]+)?_(.+)", label)
    if not m:
        return label
    sup = "^{" + m.group(2)[1:] + "}" if m.group(2) else ""
    sub = m.group(3)
    if m.group(1) in ("F", "M") and not sup:
        words = get_notation(nt)
        if sub[:1] == "i" and (len(sub) == 1 or sub[1:].isdigit()):
            sub = words.word("forces.sub_inertia") + sub[1:]
        elif sub == "b":
            sub = words.word("forces.sub_balance")
    return f"{m.group(1)}{sup}_{{{sub}}}"


def _inner_sides(poly, inner, pts: np.ndarray, i: int) -> list:
    """The sides of a link's own polygon (the inner reaction's: ``R_12 + F_i2 + R_32 = 0``) not already drawn
    in its group's polygon, laid on that polygon: the first force they share is made to coincide, so the
    inner reaction closes between two of the group polygon's vertices, as the books draw it. Each side is
    ``((label, F), z_start, z_end)`` in N (complex). None when the two share no force after the first side.

    >>> from graphmethods.problems import builtin
    >>> from graphmethods.dynamics.forces import case_forces
    >>> pl = case_forces(builtin.case("press"), m=12).plans[0]
    >>> pts = np.cumsum([0j] + [complex(F[3]) for _, F in pl.polygons[0].known]
    ...                 + [complex(F[3]) for _, _, F in pl.polygons[0].closing])
    >>> [lbl for (lbl, _), _, _ in _inner_sides(pl.polygons[0], pl.polygons[1], pts, 3)]
    ['R_12', 'R_32']
    """
    main = [lbl for lbl, _ in poly.known]
    drawn = set(main) | {lbl for lbl, _, _ in poly.closing}
    sides = [(lbl, F) for lbl, F in inner.known] + [(lbl, F) for lbl, _, F in inner.closing]
    for q, (lbl, _) in enumerate(sides):
        if q > 0 and lbl in main:
            z = complex(pts[main.index(lbl)]) - sum(complex(F[i]) for _, F in sides[:q])
            out = []
            for lb, F in sides:
                z1 = z + complex(F[i])
                if lb not in drawn:
                    out.append(((lb, F), z, z1))
                z = z1
            return out
    return []


def _label(occ, where, text: str, name: str, *, within) -> list:
    """A label beside its point, or further off with a leader line when nothing beside it is free."""
    lab, leader = occ.place_label_with_leader(where, text, size_mm=SMALL_MM, within=within)
    out: list = [Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, name=name)]
    if leader is not None:
        out.append(Line(leader[0], leader[1], style=THIN, name=f"leader-{name}"))
    return out


def force_plans(case, position: int | None = None, *, phi_deg: float | None = None, m: int = 12,
                gravity: bool = False, mu_F=None, notation="en", page=None, title=None,
                title_block: bool = True, name: str = "force-plans"):
    """The force plans of every group and of the crank in one position (see the module docstring).

    Parameters
    ----------
    case : Case
        A problem file (``builtin.case("shaper")``).
    position : int, optional
        Position 0…m (default 2); or ``phi_deg``, the crank angle in degrees.
    gravity : bool
        Add the weights.
    mu_F : float or Scale, optional
        N per mm of every polygon; a convenient value is picked to fit when not given.
    notation : {"en", "ru", "zh"}

    Raises
    ------
    InputError
        A position outside 0…m, or a given μ_F at which a polygon does not fit.
    """
    nt = get_notation(notation)
    fa, i = analysed(case, position=position, phi_deg=phi_deg, m=m, gravity=gravity)
    head = nt.word("forces.plans_title", k=i) if phi_deg is None else \
        nt.word("forces.plans_title_phi", phi=nt.number(float(phi_deg), sig=5))
    sheet = Sheet(nt=nt, page=page, title=title or head, problem=title_of(case), title_block=title_block,
                  default_page=Page("A3", "landscape", frame=True))
    x0, _, x1, _ = sheet.box
    # ------------------------------------------------------------------ the table beside the plans
    rows = [(nt.word("forces.pair"), nt.quantity("|R|", "N"))]
    for key, r in sorted(fa.reactions.items(), key=lambda kv: (len(kv[0]), kv[0])):
        rows.append((_markup(key), nt.number(float(abs(r.R[i])), sig=5)))
    Mb = float(fa.M_balance[i])
    M_b = nt.sym("forces.M_b")
    res_lines = [f"{nt.word('forces.Mb_plans', Mb=M_b)} = {nt.number(Mb, sig=6)} {nt.unit('N·m')}"]
    for key, other in (("lever", fa.M_balance_lever), ("power", fa.M_balance_power)):
        d = float(fa.difference_percent(other)[i])
        res_lines.append(f"{nt.word('forces.Mb_' + key, Mb=M_b)} = {nt.number(float(other[i]), sig=6)} {nt.unit('N·m')}")
        res_lines.append(f"    {nt.word('forces.diff')} {percent_text(d, nt)} %")
    if gravity:
        res_lines.append(nt.word("forces.weights"))
    probe = Table((0.0, 0.0), tuple(rows), align="cr", size_mm=TABLE_MM, row_height_mm=6.0)
    from graphmethods.scene import markup

    right_w = max([probe.width_mm] + [markup.text_width_mm(t, TEXT_MM) for t in res_lines])
    split = x1 - right_w - 6.0
    area = (x0 + 2.0, sheet.top + 8.0, split - 6.0, sheet.caption_y - 10.0)
    # ------------------------------------------------------------------ the polygons and μ_F
    polys = [pl.polygons[0] for pl in fa.plans]
    n_p = len(polys)
    gap = 8.0
    pw = (area[2] - area[0] - gap * (n_p - 1)) / n_p
    ph = area[3] - area[1]

    def path(poly):
        pts = [0j]
        for _, F in poly.known:
            pts.append(pts[-1] + complex(F[i]))
        for _, _, F in poly.closing:
            pts.append(pts[-1] + complex(F[i]))
        return np.array(pts)

    paths = [path(p) for p in polys]
    need = max(max(float(np.ptp(p.real)) / pw, float(np.ptp(p.imag)) / ph) for p in paths)
    if need <= 0:
        raise InputError("every force is zero in this position; there is no force plan to draw")
    biggest = max(max(float(np.ptp(p.real)), float(np.ptp(p.imag) * pw / ph)) for p in paths)
    s_F = given_scale(mu_F, "μ_F", nt.unit("N"), biggest, pw - 2.0, what="the force plans")
    els: list = [sheet.header()]
    occ = sheet.occ
    labels = []
    for j, (pl, poly, pts) in enumerate(zip(fa.plans, polys, paths)):
        left = area[0] + j * (pw + gap)
        lo = np.array([pts.real.min(), pts.imag.min()]) / s_F.per_mm
        hi = np.array([pts.real.max(), pts.imag.max()]) / s_F.per_mm
        cx = left + pw / 2 - (lo[0] + hi[0]) / 2
        cy = area[1] + ph / 2 + (lo[1] + hi[1]) / 2

        def at(z: complex) -> tuple[float, float]:
            return (cx + z.real / s_F.per_mm, cy - z.imag / s_F.per_mm)   # noqa: B023

        cap = (nt.word("forces.crank", g=pl.links[0]) if pl.group.startswith("I ")
               else nt.word("forces.group", g=pl.group))
        els.append(Text((left, area[1] - 4.0), cap, size_mm=TEXT_MM, name=f"caption-{j}"))
        sides = [(lbl, F, True, None) for lbl, F in poly.known] + \
                [(lbl, F, False, dirs) for lbl, dirs, F in poly.closing]
        for s, (lbl, _F, known, direction) in enumerate(sides):
            a, b = at(complex(pts[s])), at(complex(pts[s + 1]))
            kind = "known" if known else "closing"
            if math.dist(a, b) >= 0.3:
                v = Vector(a, b, known=known, head_length_mm=2.5, name=f"{kind}-{j}-{s - (0 if known else len(poly.known))}")
                els.append(v)
                occ.add_primitives(v.primitives())
                labels.append((v.mid, _markup(lbl, nt), f"label-{j}-{s}"))
            if direction is not None:
                u = complex(direction[i])
                e = np.array([u.real, -u.imag])
                A, B = np.array(a), np.array(b)
                ln = Line(tuple((A - 6.0 * e).tolist()), tuple((B + 6.0 * e).tolist()) if math.dist(a, b) >= 0.3
                          else tuple((A + 6.0 * e).tolist()), style=THIN, name=f"direction-{j}-{s}")
                els.append(ln)
        for t, inner in enumerate(pl.polygons[1:]):
            for (lbl, _F), z0, z1 in _inner_sides(poly, inner, pts, i):
                a, b = at(z0), at(z1)
                if math.dist(a, b) >= 0.3:
                    v = Vector(a, b, known=False, head_length_mm=2.5, name=f"inner-{j}-{t}-{lbl}")
                    els.append(v)
                    occ.add_primitives(v.primitives())
                    labels.append((v.mid, _markup(lbl, nt), f"label-inner-{j}-{t}-{lbl}"))
    for mid, text, nm in labels:
        els += _label(occ, mid, text, nm, within=(area[0] - 4, area[1] - 2, area[2] + 4, area[3] + 4))
    tx = split + 2.0
    table = Table((tx, sheet.top + 2.0), tuple(rows), align="cr", size_mm=TABLE_MM, row_height_mm=6.0, name="table")
    els.append(table)
    ty = table.bottom_left[1] + 7.0
    for t_i, line in enumerate(res_lines):
        els.append(Text((tx, ty + t_i * 5.6), line, size_mm=TEXT_MM, name=f"result-{t_i}"))
    scales = (s_F,)
    els += sheet.captions(scales, legend=nt.word("forces.plans_legend"), reserve=True)
    return sheet.scene(els, scales, name=name, notes=(s_F.note,) if s_F.note else ())


def zhukovsky_forces(case, position: int | None = None, *, phi_deg: float | None = None, m: int = 12,
                     gravity: bool = False, mu_l=None, mu_F=None, notation="en", page=None, title=None,
                     title_block: bool = True, name: str = "zhukovsky-forces"):
    """Zhukovsky's lever with every force of the force analysis (inertia forces, couples as pairs of
    forces, weights, the load) at the images of their points, and the balancing force F_b at the
    image of the crank pin; M_b = F_b·l_{{OA}} beside the force plans' value.

    The plan of analogues v/ω₁ (m) turned 90° counterclockwise is drawn to μ_l (m per mm), the
    forces to μ_F (N per mm); both picked as convenient values when not given.

    Examples
    --------
    >>> from graphmethods.problems import builtin
    >>> s = zhukovsky_forces(builtin.case("four-bar"), position=2)
    >>> [e.name for e in s.elements if e.name == "F_b"]
    ['F_b']
    """
    from graphmethods.scene import Point, markup
    from graphmethods.scene.scale import pick_scale

    nt = get_notation(notation)
    fa, i = analysed(case, position=position, phi_deg=phi_deg, m=m, gravity=gravity)
    head = nt.word("forces.lever_title", k=i) if phi_deg is None else \
        nt.word("forces.lever_title_phi", phi=nt.number(float(phi_deg), sig=5))
    mo, lev = fa.motion, fa.lever
    lk = mo.linkage
    sheet = Sheet(nt=nt, page=page, title=title or head, problem=title_of(case), title_block=title_block,
                  default_page=Page("A3", "landscape", frame=True))
    x0, _, x1, _ = sheet.box
    Fb = complex(lev.F_balance[i])
    Mb_l, Mb = float(lev.M_balance[i]), float(fa.M_balance[i])
    d = float(fa.difference_percent(lev.M_balance)[i])
    texts = [nt.word("forces.turned"), nt.word("forces.couple"),
             nt.word("forces.lever_equation", Fb=nt.number(abs(Fb), sig=5)),
             nt.word("forces.lever_result", Mb=nt.number(Mb_l, sig=6)),
             nt.word("forces.lever_plans", Mb=nt.number(Mb, sig=6), d=percent_text(d, nt))]
    right_w = max(markup.text_width_mm(t, TEXT_MM) for t in texts)
    split = x1 - right_w - 6.0
    area = (x0 + 4.0, sheet.top + 4.0, split - 6.0, sheet.caption_y - 8.0)
    fixed = set(lk.ground)
    images = {p: 1j * complex(mo.v_[p][i]) / mo.omega_1 for p in mo.points if p not in fixed}
    items = [(f.label, complex(f.image[i]), complex(f.F[i])) for f in lev.forces if abs(f.F[i]) > 0]
    items.append(("F_b", complex(lev.image_pin[i]), Fb))
    F_max = max(abs(F) for _, _, F in items)
    s_F = given_scale(mu_F, "μ_F", nt.unit("N"), F_max, 28.0, what="the largest force on the lever")
    cloud = np.array([0j] + list(images.values()) + [z for _, z, _ in items])
    span_x, span_y = float(np.ptp(cloud.real)), float(np.ptp(cloud.imag))
    room_x, room_y = area[2] - area[0] - 2 * 32.0, area[3] - area[1] - 2 * 32.0
    if mu_l is None:
        s_l = pick_scale(max(span_x * room_y / room_x, span_y, 1e-12), room_y, symbol="μ_l", unit=nt.unit("m"))
    else:
        s_l = given_scale(mu_l, "μ_l", nt.unit("m"), max(span_x * room_y / room_x, span_y), room_y,
                          what="the lever")
    cx = (area[0] + area[2]) / 2 - (float(cloud.real.min()) + float(cloud.real.max())) / 2 / s_l.per_mm
    cy = (area[1] + area[3]) / 2 + (float(cloud.imag.min()) + float(cloud.imag.max())) / 2 / s_l.per_mm

    def at(z: complex) -> tuple[float, float]:
        return (cx + z.real / s_l.per_mm, cy - z.imag / s_l.per_mm)

    els: list = [sheet.header()]
    occ = sheet.occ
    pole = at(0j)
    els.append(Point(pole, radius_mm=0.7, name="pole"))
    for p, z in images.items():
        if abs(z) / s_l.per_mm >= 0.3:
            ln = Line(pole, at(z), style=THIN, name=f"ray-{p}")
            els.append(ln)
            occ.add_primitives(ln.primitives())
    vec_labels = []
    for j, (label, z, F) in enumerate(items):
        a = at(z)
        b = (a[0] + F.real / s_F.per_mm, a[1] - F.imag / s_F.per_mm)
        v = Vector(a, b, known=True, head_length_mm=2.5, name="F_b" if label == "F_b" else f"force-{j}")
        els.append(v)
        occ.add_primitives(v.primitives())
        vec_labels.append((b, _markup(label, nt), f"label-force-{j}"))
    names = [(at(z), p.lower() if len(p) == 1 else p[0].lower() + p[1:], f"image-{p}") for p, z in images.items()]
    for where, text, nm in [(pole, "p", "label-pole")] + names + vec_labels:
        els += _label(occ, where, text, nm, within=(area[0] - 4, area[1] - 4, area[2] + 4, area[3] + 4))
    tx = split + 2.0
    for t_i, t in enumerate(texts):
        els.append(Text((tx, sheet.top + 2.0 + t_i * 6.0), t, size_mm=TEXT_MM, name=f"text-{t_i}"))
    scales = (s_l, s_F)
    els += sheet.captions(scales, legend=nt.word("forces.lever_legend"), reserve=True)
    return sheet.scene(els, scales, name=name, notes=tuple(s.note for s in scales if s.note))


def force_scheme(case, position: int | None = None, *, phi_deg: float | None = None, m: int = 12,
                 gravity: bool = False, mu_l=None, mu_F=None, notation="en", page=None, title=None,
                 title_block: bool = True, name: str = "force-scheme"):
    """The linkage in one position with every applied force: the inertia forces at the centres of
    mass, the weights (``gravity``), the working load, each drawn to μ_F from its point; the
    inertia and load moments as arcs in their sense; the balancing moment on the crank. The
    scheme is drawn to μ_l (m per mm); both scales convenient values picked to fit.

    Examples
    --------
    >>> from graphmethods.problems import builtin
    >>> s = force_scheme(builtin.case("press"), position=3)
    >>> sorted(e.name for e in s.elements if e.name.startswith("force-"))
    ['force-0', 'force-1', 'force-2']
    """
    from graphmethods.scene import markup
    from graphmethods.scene.scale import pick_scale
    from graphmethods.sheets.kinematic_symbols import FixedPivot, PinJoint, RotationArrow, SliderBlock

    nt = get_notation(notation)
    fa, i = analysed(case, position=position, phi_deg=phi_deg, m=m, gravity=gravity)
    head = nt.word("forces.scheme_title", k=i) if phi_deg is None else \
        nt.word("forces.scheme_title_phi", phi=nt.number(float(phi_deg), sig=5))
    mo = fa.motion
    lk = mo.linkage
    sheet = Sheet(nt=nt, page=page, title=title or head, problem=title_of(case), title_block=title_block,
                  default_page=Page("A3", "landscape", frame=True))
    x0, _, x1, _ = sheet.box
    texts = [nt.word("forces.inertia"),
             nt.word("forces.scheme_balance", Mb=nt.number(float(fa.M_balance[i]), sig=6))]
    right_w = max(markup.text_width_mm(t, TEXT_MM) for t in texts)
    split = x1 - right_w - 6.0
    area = (x0 + 4.0, sheet.top + 4.0, split - 6.0, sheet.caption_y - 8.0)
    z = {p: complex(mo.z[p][i]) for p in mo.points}
    # the links as segments between their points
    segs: list[tuple[str, str]] = [(lk.crank.centre, lk.crank.pin)]
    blocks: list[tuple[str, complex]] = []
    for g in lk.groups:
        if g.kind == "RRR":
            segs += [(g.P, g.C), (g.Q, g.C)]
        elif g.kind == "RRP":
            segs.append((g.P, g.C))
            blocks.append((g.C, complex(np.broadcast_to(mo._state.e[g.links[1]], (mo.n,))[i])))
        elif g.kind == "RPR":
            segs.append((g.Q, g.P))
            blocks.append((g.P, complex(np.broadcast_to(mo._state.e[g.links[1]], (mo.n,))[i])))
        elif g.kind == "PRP":
            blocks += [(g.C, complex(np.broadcast_to(mo._state.e[ln], (mo.n,))[i])) for ln in g.links]
        else:
            segs.append((g.P, g.R))
            blocks.append((g.P, complex(np.broadcast_to(mo._state.e[g.links[0]], (mo.n,))[i])))
    segs += [(p.origin, p.name) for p in lk.points]
    forces = [(f.label, complex(f.F[i]), complex(f.at[i]), float(f.M[i]))
              for fs in fa.applied.values() for f in fs]
    F_max = max([abs(F) for _, F, _, _ in forces] + [0.0])
    if F_max == 0.0:
        raise InputError("no force acts in this position; there is nothing to draw")
    s_F = given_scale(mu_F, "μ_F", nt.unit("N"), F_max, 30.0, what="the largest force")
    cloud = np.array(list(z.values()))
    room_x, room_y = area[2] - area[0] - 2 * 34.0, area[3] - area[1] - 2 * 34.0
    span = max(float(np.ptp(cloud.real)) * room_y / room_x, float(np.ptp(cloud.imag)), 1e-12)
    s_l = (pick_scale(span, room_y, symbol="μ_l", unit=nt.unit("m")) if mu_l is None
           else given_scale(mu_l, "μ_l", nt.unit("m"), span, room_y, what="the scheme"))
    cx = (area[0] + area[2]) / 2 - (float(cloud.real.min()) + float(cloud.real.max())) / 2 / s_l.per_mm
    cy = (area[1] + area[3]) / 2 + (float(cloud.imag.min()) + float(cloud.imag.max())) / 2 / s_l.per_mm

    def at(w: complex) -> tuple[float, float]:
        return (cx + w.real / s_l.per_mm, cy - w.imag / s_l.per_mm)

    els: list = [sheet.header()]
    occ = sheet.occ
    for a, b in segs:
        if abs(z[a] - z[b]) > 0:
            ln = Line(at(z[a]), at(z[b]), name=f"link-{a}-{b}")
            els.append(ln)
            occ.add_primitives(ln.primitives())
    for p in lk.ground:
        els.append(FixedPivot(at(z[p]), name=f"pivot-{p}"))
    for j, (p, u) in enumerate(blocks):
        els.append(SliderBlock(at(z[p]), angle_deg=math.degrees(math.atan2(u.imag, u.real)), name=f"block-{j}"))
    joints = {q for s in segs for q in s} - set(lk.ground)
    els += [PinJoint(at(z[p]), name=f"joint-{p}") for p in sorted(joints)]
    for el in els[1:]:
        occ.add_primitives(el.primitives())
    labels = [(at(z[p]), p, f"point-{p}") for p in sorted(z)]
    n_f = 0
    for label, F, where, M in forces:
        start = at(where)
        if abs(F) / s_F.per_mm >= 0.3:
            tip = (start[0] + F.real / s_F.per_mm, start[1] - F.imag / s_F.per_mm)
            v = Vector(start, tip, head_length_mm=2.5, name=f"force-{n_f}")
            n_f += 1
            els.append(v)
            occ.add_primitives(v.primitives())
            labels.append((tip, _markup(label, nt), f"label-{label}"))
        if M != 0.0:
            mlabel = "M" + label[1:] if label.startswith("F") else label
            arc = RotationArrow(start, radius_mm=6.0, start_deg=200.0, sweep_deg=100.0 if M > 0 else -100.0,
                                name=f"moment-{mlabel}")
            els.append(arc)
            occ.add_primitives(arc.primitives())
            labels.append(((start[0] - 6.0, start[1]), f"{_markup(mlabel, nt)} = {nt.number(M, sig=4)} {nt.unit('N·m')}",
                           f"label-{mlabel}"))
    cr = lk.crank
    Mb = float(fa.M_balance[i])
    arc_b = RotationArrow(at(z[cr.centre]), radius_mm=9.0, start_deg=20.0, sweep_deg=110.0 if Mb > 0 else -110.0,
                          label=nt.sym("forces.M_b"), size_mm=SMALL_MM, name="M_b")
    els.append(arc_b)
    occ.add_primitives(arc_b.primitives())        # the labels below keep off M_b's arc and its name
    for at_mm, text, nm in labels:
        els += _label(occ, at_mm, text, nm, within=(area[0] - 4, area[1] - 4, area[2] + 4, area[3] + 4))
    tx = split + 2.0
    for t_i, t in enumerate(texts):
        els.append(Text((tx, sheet.top + 2.0 + t_i * 6.0), t, size_mm=TEXT_MM, name=f"text-{t_i}"))
    scales = (s_l, s_F)
    els += sheet.captions(scales, legend=nt.word("forces.scheme_legend"), reserve=True)
    return sheet.scene(els, scales, name=name, notes=tuple(s.note for s in scales if s.note))
