"""The step-by-step builds of the graphical calculus, the Zhukovsky lever, the force plans and the kinematic
scheme (split out of :mod:`graphmethods.sheets.steps`, which lists them; built from the pieces of
:mod:`graphmethods.sheets.step_rules`)."""

from __future__ import annotations

import numpy as np

from graphmethods.scene.steps import BuildUp
from graphmethods.sheets import step_rules as S

# ----------------------------------------------------------------------------- graphical calculus

def differentiation_steps(subject, *, notation="en", page="slide", m: int = 12) -> BuildUp:
    """The slider's kinematic diagrams by graphical differentiation, step by step: s(φ); its chords;
    the v axes and the pole P₁; the rays; the points; v(φ); its chords; the a axes and P₂; the rays;
    the points; a(φ); the comparison.

    Parameters
    ----------
    subject : Case or linkage with one slider
        As :func:`graphmethods.sheets.calculus.kinematic_diagrams` takes it.
    """
    from graphmethods.sheets import calculus as C

    nt, (pg, box, cap_mm, tb) = S.step_start(notation, page)
    figure = C.kinematic_diagrams(subject, m=m, notation=nt, page=pg, title_block=tb)
    s_, v_, a_ = nt.sym("calculus.s"), nt.sym("calculus.v"), nt.sym("calculus.a")

    rules = [(nt.word("steps.s_curve", s=s_, m=m, mus=S._text_of(figure, "formula-s-1")),
              S._starts("title", "axis-phi-s", "axis-s", "ordinate-s-", "dot-s-", "curve-s", "formula-s-",
                      "scale-captions"))]
    for f, g, pole, H, band in ((s_, v_, "pole-v-", "H1", "v"), (v_, a_, "pole-a-", "H2", "a")):
        rules += [
            (nt.word("steps.chords", f=f), S._starts(f"chord-{'s' if band == 'v' else 'v'}-")),
            (nt.word("steps.pole_d", g=g, P=S._text_of(figure, f"{pole}label"),
                     H=S._text_of(figure, f"dimension-{H}-text")),
             S._starts(f"axis-phi-{band}", f"axis-{band}", pole, f"dimension-{H}")),
            (nt.word("steps.rays_d", P=S._text_of(figure, f"{pole}label"), f=f), S._starts(f"ray-{band}-")),
            (nt.word("steps.project_d"), S._starts(f"projection-{band}-", f"dot-{band}-")),
            (nt.word("steps.curve_d", g=g, mu=S._text_of(figure, f"formula-{band}-1")),
             S._starts(f"curve-{band}", f"formula-{band}-")),
        ]
    rules.append((nt.word("steps.compare_d"), lambda n: False))
    return S._build(figure, rules, box, cap_mm, rest=len(rules))


def integration_steps(subject, *, notation="en", page="slide", m: int = 12) -> BuildUp:
    """The work diagrams by graphical integration (method of chords), step by step: M_d and M_r; the
    mean ordinates; the pole and its rays; the chords A_d(φ), A_r(φ); ΔE = A_d − A_r; the accuracy.

    Parameters
    ----------
    subject : Study, Case, cycle problem with moment curves, or (M_d, M_r)
        As :func:`graphmethods.sheets.work_diagrams.work_diagrams` takes it.
    """
    from graphmethods.sheets.work_diagrams import work_diagrams

    nt, (pg, box, cap_mm, tb) = S.step_start(notation, page)
    figure = work_diagrams(subject, m=m, notation=nt, page=pg, title_block=tb)
    P = S._text_of(figure, "pole-label")

    rules = [
        (nt.word("steps.moments", Md=nt.sym("M_d"), Mr=nt.sym("M_r"), mu=S._text_of(figure, "formula-M-1")),
         S._starts("title", "axis-phi-M", "axis-M", "curve-M_", "name-M-", "formula-M-", "scale-captions")),
        (nt.word("steps.means", Mr=nt.sym("M_r")), S._starts("mean-")),
        (nt.word("steps.pole_i", P=P, H=S._text_of(figure, "dimension-H-text")),
         S._starts("pole-", "dimension-H", "ray-", "projection-")),
        (nt.word("steps.chords_i", Ad=nt.sym("calculus.A_d"), Ar=nt.sym("calculus.A_r"),
                 mu=S._text_of(figure, "formula-A-1")),
         S._starts("axis-phi-A", "axis-A", "chords-A_", "dot-A_", "name-A-", "formula-A-")),
        (nt.word("steps.dE", eq=S._text_of(figure, "formula-dE-1")), S._starts("axis-phi-dE", "axis-dE", "ordinate-dE-",
                                                                    "curve-dE", "dot-dE-", "formula-dE-")),
        (nt.word("steps.accuracy"), lambda n: False),
    ]
    return S._build(figure, rules, box, cap_mm, rest=len(rules))


# ----------------------------------------------------------------------------- Zhukovsky's lever

def zhukovsky_steps(study, position: int | None = None, *, notation="en", page="slide") -> BuildUp:
    """Zhukovsky's lever at one position, step by step: the plan turned 90° as a lever; the load at
    the image of its point; its arm h about p; the balance of moments, M_r.

    Parameters
    ----------
    study : Study or Case
        As :func:`graphmethods.sheets.zhukovsky_lever.zhukovsky_lever` takes it.
    position : int, optional
        The position (default: the one with the largest M_r).
    """
    from graphmethods.sheets.zhukovsky_lever import lever_law, zhukovsky_lever

    nt, (pg, box, cap_mm, tb) = S.step_start(notation, page)
    figure = zhukovsky_lever(study, position=position, notation=nt, page=pg, title_block=tb)
    mu_v = next((sc for sc in figure.scales() if "v" in sc.symbol), figure.scales()[0])
    rules = [
        (nt.word("steps.lever", mu=mu_v.caption(nt)),
         lambda n: n in ("title", "pole", "scale-captions") or n.startswith(("lever-", "image-", "name-"))),
        (nt.word("steps.load", F=S._text_of(figure, "label-F")), S._leader_of(["force-F", "label-F"])),
        (nt.word("steps.arm", h=S._text_of(figure, "label-h")), S._leader_of(["dimension-h", "label-h"])),
        (nt.word("steps.balance", Mr=nt.sym("M_r"), law=lever_law(nt)), lambda n: False),
    ]
    return S._build(figure, rules, box, cap_mm, rest=len(rules))


# ----------------------------------------------------------------------------- the force plans

def _relation(nt, d: complex, group, motion, i: int) -> str:
    """How a closing side's known direction ``d`` is drawn: ∥ or ⊥ a segment between two of the
    group's points, or ⊥ the guide of one of its links."""
    pts = [getattr(group, a) for a in ("P", "Q", "C", "R") if isinstance(getattr(group, a, None), str)]
    pts = [p for p in pts if p in motion.z]
    pairs = [(a, b) for n_a, a in enumerate(pts) for b in pts[n_a + 1:]]
    for key, test in (("par", lambda c: abs((np.conj(c) * d).imag)), ("perp", lambda c: abs((np.conj(c) * d).real))):
        for a, b in pairs:
            seg = complex(motion.z[b][i] - motion.z[a][i])
            if abs(seg) > 0 and test(seg / abs(seg)) < 1e-9:
                return nt.word(f"steps.{key}", x=f"{a}{b}")
    for ln in group.links:
        e = complex(np.broadcast_to(motion._state.e[ln], (motion.n,))[i])
        if abs(e) > 0 and abs((np.conj(e / abs(e)) * d).real) < 1e-9:
            return nt.word("steps.perp_g")
    return nt.word("steps.known_dir")


def force_plans_steps(case, position: int | None = None, *, notation="en", page="slide", m: int = 12) -> BuildUp:
    """The force plans of one position, step by step, group by group in the order they are solved:
    μ_F; for each group the known forces laid end to end, the two unknown directions, their meeting
    point (the polygon closes), the reactions; the crank's polygon closed by R_01; the table of
    reactions and M_b with its two checks.

    Parameters
    ----------
    case : Case
        A linkage problem with masses (as :func:`graphmethods.sheets.forces.force_plans` takes it).
    position : int, optional
        Position 0…m (default 2, as the figure).

    Examples
    --------
    >>> from graphmethods.problems import builtin
    >>> bu = force_plans_steps(builtin.case("press"), 3)
    >>> caption = bu.captions()[1]
    >>> caption.split(": R")[0]
    'group RRP (2, 3): lay the known forces end to end at μ_F'
    >>> bu.scene_at(len(bu)) == bu.figure
    True
    """
    from graphmethods.sheets import forces as SF

    nt, (pg, box, cap_mm, tb) = S.step_start(notation, page)
    fa, i = SF.analysed(case, position=position, phi_deg=None, m=m)
    figure = SF.force_plans(case, i, m=m, notation=nt, page=pg, title_block=tb)
    names = {e.name for e in figure.elements}
    groups = {g.name: g for g in fa.motion.linkage.groups}
    newton = nt.unit("N")

    big = max([float(abs(r.R[i])) for r in fa.reactions.values()] + [0.0])

    def size(F) -> str:                                  # the reactions table's value: round-off is 0
        return f"{nt.number(SF.round_off_zero(float(abs(F[i])), big), sig=5)} {newton}"

    rules: list = [(nt.word("steps.f_scale", mu=figure.scales()[0].caption(nt)), ["title", "scale-captions", "legend"])]
    solved: set[str] = set()
    for j, pl in enumerate(fa.plans):
        poly = pl.polygons[0]
        nk = len(poly.known)
        head = S._text_of(figure, f"caption-{j}")
        known = nt.word("steps.f_known", g=head, forces=", ".join(SF._markup(lbl, nt) for lbl, _ in poly.known))
        if pl.first:
            known += nt.word("steps.f_first", parts=", ".join(SF._markup(lbl, nt) for lbl, _ in pl.first))
        rules.append((known, lambda n, j=j, nk=nk: n == f"caption-{j}" or n.startswith(f"known-{j}-") or any(
            n == f"label-{j}-{s}" for s in range(nk))))
        closing = poly.closing
        labels = [SF._markup(lbl, nt) for lbl, _, _ in closing]
        if len(closing) == 2 and all(d is not None for _, d, _ in closing):
            g = groups.get(pl.group)
            rel = [_relation(nt, complex(d[i]), g, fa.motion, i) if g is not None else nt.word("steps.known_dir")
                   for _, d, _ in closing]
            rules.append((nt.word("steps.f_dirs", X=labels[0], relX=rel[0], Y=labels[1], relY=rel[1]),
                          lambda n, j=j: n.startswith(f"direction-{j}-")))
            rules.append((nt.word("steps.f_meet", X=labels[0], x=size(closing[0][2]), Y=labels[1],
                                  y=size(closing[1][2])),
                          lambda n, j=j: n.startswith(f"closing-{j}-")))
            mine = [r for r in fa.reactions.values() if (r.by in pl.links or r.on in pl.links)
                    and not ({r.by, r.on} & solved)]
            listed = "; ".join(f"{SF._markup(r.key, nt)} = {size(r.R)}" for r in sorted(mine, key=lambda r: r.key))
            rules.append((nt.word("steps.f_react", list=listed), lambda n, j=j, nk=nk: (
                n.startswith(f"label-{j}-") and int(n.rsplit("-", 1)[1]) >= nk)
                or n.startswith((f"inner-{j}-", f"label-inner-{j}-"))))      # each link's own polygon
        else:
            rules.append((nt.word("steps.f_close", X=labels[-1], x=size(closing[-1][2])),
                          lambda n, j=j: n.startswith((f"closing-{j}-", f"direction-{j}-", f"label-{j}-",
                                                       f"inner-{j}-", f"label-inner-{j}-"))))
        solved |= set(pl.links)
    Mb = float(fa.M_balance[i])
    rules.append((nt.word("steps.f_result", Mb=f"{nt.number(Mb, sig=6)} {nt.unit('N·m')}",
                     dl=SF.percent_text(float(fa.difference_percent(fa.M_balance_lever)[i]), nt),
                     dp=SF.percent_text(float(fa.difference_percent(fa.M_balance_power)[i]), nt)),
                  lambda n: n == "table" or n.startswith("result-")))
    rules = [r for r in rules if S._draws(r[1], names)]
    return S._build(figure, rules, box, cap_mm, rest=None)


def zhukovsky_forces_steps(case, position: int | None = None, *, notation="en", page="slide",
                           m: int = 12) -> BuildUp:
    """Zhukovsky's lever with every force of the force analysis, step by step: the velocity plan of
    analogues turned 90° as a lever; each force (a couple as two forces) at the image of its point,
    with its moment about p; the balancing force from Σ M_p = 0; M_b beside the force plans'.

    Parameters
    ----------
    case : Case
        As :func:`graphmethods.sheets.forces.zhukovsky_forces` takes it.
    position : int, optional
        Position 0…m (default 2, as the figure).

    Examples
    --------
    >>> from graphmethods.problems import builtin
    >>> bu = zhukovsky_forces_steps(builtin.case("four-bar"), 2, notation="ru")
    >>> bu.captions()[-1].split(" = ")[0]
    'M_{ур}'
    """
    from graphmethods.sheets import forces as SF

    nt, (pg, box, cap_mm, tb) = S.step_start(notation, page)
    fa, i = SF.analysed(case, position=position, phi_deg=None, m=m)
    figure = SF.zhukovsky_forces(case, i, m=m, notation=nt, page=pg, title_block=tb)
    lev = fa.lever
    nm_ = nt.unit("N·m")
    items = [f for f in lev.forces if abs(f.F[i]) > 0]
    mu = "; ".join(s.caption(nt) for s in figure.scales())
    rules: list = [(nt.word("steps.z_lever", mu=mu),
                    lambda n: n in ("title", "pole", "label-pole", "text-0", "scale-captions", "legend")
                    or n.startswith(("ray-", "image-")))]
    couple_said = False
    big = max([abs(complex(f.F[i])) * abs(complex(lev.image_pin[i])) for f in items]     # a force times the lever's
              + [abs(float(f.moment[i])) for f in items] + [0.0])                      # size: its moments' scale
    j = 0
    while j < len(items):
        lbl = items[j].label
        idx = [j]
        while j + len(idx) < len(items) and items[j + len(idx)].label == lbl:
            idx.append(j + len(idx))
        moment = sum(float(items[t].moment[i]) for t in idx)
        moment = SF.round_off_zero(moment, big)   # a force through p (or along its own image's ray): rounding only
        couple = len(idx) > 1
        text = "steps.z_couple" if couple else "steps.z_force"
        wanted = {f"force-{t}" for t in idx} | {f"label-force-{t}" for t in idx}
        if couple and not couple_said:
            wanted.add("text-1")
            couple_said = True
        rules.append((nt.word(text, F=SF._markup(lbl, nt), M=f"{nt.number(moment, sig=4)} {nm_}"),
                      lambda n, w=frozenset(wanted): n in w))
        j += len(idx)
    Fb, Mb = nt.sym("forces.F_b"), nt.sym("forces.M_b")
    F_b = f"{nt.number(float(abs(lev.F_balance[i])), sig=5)} {nt.unit('N')}"
    rules.append((nt.word("steps.z_balance", Fb=Fb, x=F_b),
                  lambda n: n in ("F_b", f"label-force-{len(items)}", "text-2")
                  or (n == "text-1" and not couple_said)))
    rules.append((nt.word("steps.z_result", Mb=Mb, Fb=Fb, x=f"{nt.number(float(lev.M_balance[i]), sig=6)} {nm_}",
                     y=f"{nt.number(float(fa.M_balance[i]), sig=6)} {nm_}",
                     d=SF.percent_text(float(fa.difference_percent(lev.M_balance)[i]), nt)),
                  lambda n: n in ("text-3", "text-4")))
    return S._build(figure, rules, box, cap_mm, rest=None)


# ----------------------------------------------------------------------------- the kinematic scheme

def scheme_steps(linkage, *, notation="en", page="slide", m: int = 12) -> BuildUp:
    """The kinematic scheme in m positions, step by step: the frame; the crank in m positions; the
    other links found by their lengths; the paths of the centres of mass; the extreme positions; one
    position drawn thick.

    Parameters
    ----------
    linkage : Case, Study or Mechanism
        As :func:`graphmethods.sheets.kinematics.kinematic_scheme` takes it.
    """
    from graphmethods.sheets import kinematics as K

    nt, (pg, box, cap_mm, tb) = S.step_start(notation, page)
    figure = K.kinematic_scheme(linkage, m=m, notation=nt, page=pg, title_block=tb)
    mech = K._Linkage.of(linkage, m=m).mech
    pin = mech.crank_pin
    crank = next(ln for ln, (a, b) in mech.link_joints.items() if b == pin)
    others = [ln for ln in mech.link_joints if ln != crank]
    moving = [j for j in dict.fromkeys(b for ln in others for b in mech.link_joints[ln])
              if j != pin and j not in mech.fixed_joints]
    mu_l = figure.scales()[0]

    def pos_of(links):
        return lambda n: n.startswith("position-") and n.rsplit("-", 1)[-1] in links

    def mark_of(points):
        return lambda n: any(n.startswith(f"mark-{p}-") for p in points) and not n.endswith("-extreme")

    rules = [
        (nt.word("steps.frame", mu=mu_l.caption(nt)),
         lambda n: n in ("title", "crank-circle", "scale-captions", "legend")
         or n.startswith(("pivot-", "guide-", "name-O"))),
        (nt.word("steps.crank_pos", m=m, c=K._sub(crank)),
         lambda n: pos_of([crank])(n) or mark_of([pin])(n) or (n.startswith(f"number-{pin}-")
                                                                  and not n.endswith("-extreme"))),
        (nt.word("steps.output_pos", pts=", ".join(moving) or pin, links=", ".join(K._sub(x) for x in others)),
         lambda n: pos_of(others)(n) or mark_of(moving)(n) or (n.startswith("number-out-")
                                                                and not n.endswith("-extreme"))),
        (nt.word("steps.paths"), lambda n: n.startswith("path-")),
        (nt.word("steps.extremes_table" if any(e.name == "positions-table" for e in figure.elements)
                 else "steps.extremes_s"), lambda n: n.startswith("extreme-") or n.endswith("-extreme")
         or n in ("dimension-H", "summary", "positions-table")),
        (nt.word("steps.thick"), lambda n: False),
    ]
    kept = S._kept(rules, figure)
    return S._build(figure, kept, box, cap_mm, rest=len(kept))
