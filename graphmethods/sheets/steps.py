"""Step sources: the textbook constructions told step by step, for a lecture.

Each function builds the finished figure with its own figure function (on a page that keeps a
band free under the figure for the caption) and splits its elements into steps by the element
names that figure function gives, in the order the construction records say:

- :func:`velocity_plan_steps`: the pole and μ_v; pa ⟂ OA (known); for every point found by
  intersection its vector equation, the line through the known image, the line through p, and
  their meeting point; the images by similarity or proportion; then the values read off.
- :func:`energy_indicator_steps`: the axis and start level; one vector per interval; the
  closure; the highest and lowest points and ΔW_max.
- :func:`wittenbauer_steps`: the axes; the points of positions 0…m; the curve; the ray at ψ_max;
  the ray at ψ_min; k and l; kl; J_F.
- :func:`differentiation_steps` (the slider's s, v, a by graphical differentiation),
  :func:`integration_steps` (work diagrams by the method of chords), :func:`zhukovsky_steps`
  (Zhukovsky's lever with the working load alone) and :func:`scheme_steps` (the kinematic scheme
  in m positions).
- :func:`force_plans_steps`: μ_F; for each group, in the order they are solved, the known forces
  end to end, the two unknown directions, their meeting point, the reactions; the crank closed by
  R_01; the table and M_b. :func:`zhukovsky_forces_steps`: the plan turned 90° as a lever, each
  force at the image of its point with its moment about p, F_b from Σ M_p = 0, M_b.

A new construction plugs in as one more function of
the same shape that returns a :class:`~graphmethods.scene.steps.BuildUp`; :data:`FIGURES` lists
them by name for :func:`build` and the command line.

>>> from graphmethods import problems
>>> bu = energy_indicator_steps(problems.w1(), notation="en")
>>> len(bu), bu.captions()[1]
(10, 'Interval ab: A = −50 J, a vector 10 mm down from a to b')
>>> bu.scene_at(len(bu)) == bu.figure
True
"""

from __future__ import annotations

import pathlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import Page, Scene
from graphmethods.scene.notation import Notation
from graphmethods.scene.steps import BuildUp, Rule
from graphmethods.sheets.projector import (  # noqa: F401  (re-exported: the steps' slides live here too)
    CAPTION_GAP_MM,
    KEEP_SIZE,
    SLIDE_NOTE_MM,
    SLIDE_PAGE,
    ZOOMS,
    _on_slide,
    design_slide,
    for_projector,
    layout_faults,
    projector_figure,
    smallest_text_mm,
)
from graphmethods.sheets.step_rules import (  # moved down: the build-ups split out of this module use them too
    _axis_scale,
    _build,
    _kept,
    _leader_of,
    _starts,
    _text_of,
    step_page,  # noqa: F401  (re-exported: a build-up's page, as before)
    step_start,
)

# ----------------------------------------------------------------------------- velocity plan

def velocity_plan_steps(linkage: Any, position: int | None = None, *, notation: Any = "en", page: Any = "slide",
                        m: int | None = None, omega_1: float | None = None, mu_v: Any = None) -> BuildUp:
    """The velocity plan of one position, step by step, from its construction records.

    Parameters
    ----------
    linkage : Case, Study, Mechanism, Positions or VelocityPlans
        As :func:`graphmethods.sheets.kinematics.velocity_plan` takes it.
    position : int, optional
        The position drawn (default: the fullest plan of the working stroke).
    notation : {'en', 'ru', 'zh'}
    page : 'slide', 'A4' … 'A1' or Page

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> bu = velocity_plan_steps(SliderCrank(r=0.1, l=0.4, points={"S2": ("AB", 0.13)}), 1, omega_1=10.0)
    >>> [c.split(":")[0] for c in bu.captions()][2:5]
    ['Through a, draw the direction of v_{BA} ⊥ AB', 'Through p, draw the direction of v_{B} ∥ the guide', 'b is where the two lines meet']
    """  # noqa: E501 - a doctest's expected output is one line
    from graphmethods.sheets import kinematics as K

    nt, (pg, box, cap_mm, tb) = step_start(notation, page)
    plans = K._Linkage.of(linkage, m=m, omega_1=omega_1).plans
    k = K.fullest_position(plans) if position is None else position
    figure = K.velocity_plan(linkage, k, m=m, omega_1=omega_1, mu_v=mu_v, notation=nt, page=pg, title_block=tb)
    first: tuple[str, Rule] = (nt.word("steps.pole", mu=figure.scales()[0].caption(nt)),
                               _leader_of(["title", "pole", "name-p", "scale-captions", "legend", "equation-0"]))
    rules = _kept([first, *_velocity_rules(figure, plans, int(k), nt), (nt.word("steps.read"), lambda n: False)],
                  figure)
    return _build(figure, rules, box, cap_mm, rest=len(rules))


def _velocity_rules(figure: Scene, plans: Any, k: int, nt: Notation) -> list[tuple[str, Rule]]:
    """One step per construction record after the pole: pa ⊥ OA; for a point found by intersection its
    two lines and their meeting point; an image by similarity or proportion; one that coincides."""
    from graphmethods.sheets import kinematics as K

    mech = plans.positions.mechanism
    unit = nt.unit("m/s")
    _images, vectors = K._plan_layout(plans)
    eq_text = {e.name: _text_of(figure, e.name) for e in figure.elements if e.name.startswith("equation-")}
    label_of = {c.label: n for n, c in plans.constructions.items()}

    def value(symbol: str, start: str, end: str) -> str:
        v = float(np.hypot(*(np.asarray(plans.v(label_of[end])[k]) - (0 if start == "p" else
                                                                      np.asarray(plans.v(label_of[start])[k])))))
        return f"{symbol} = {nt.number(v, sig=4)} {unit}"

    rules: list[tuple[str, Rule]] = []
    eq_i = 1
    for name, c in plans.constructions.items():
        x = c.label
        if c.method == "pole":
            continue
        eq = eq_text.get(f"equation-{eq_i}", "")
        if c.method in ("known", "intersection", "similarity", "proportion"):
            eq_i += 1
        own = _leader_of([f"vector-p{x}", f"name-{x}", f"equation-{eq_i - 1}"])
        if c.method == "known":
            crank = next(ln for ln, (a, b) in mech.link_joints.items() if b == name)
            rules.append((nt.word("steps.known", link=K._sub(crank), eq=eq), own))
        elif c.method == "intersection":
            rules += _velocity_line_rules(nt, mech, name, c.lines, label_of, f"equation-{eq_i - 1}")
            found = [pv for pv in vectors if pv.end == x]
            vals = ",  ".join(value(pv.symbol, pv.start, pv.end) for pv in found)
            rules.append((nt.word("steps.meet", x=K._plan_markup(x), values=vals),
                          _leader_of([f"vector-{pv.start}{pv.end}" for pv in found] + [f"name-{x}"])))
        elif c.method in ("similarity", "proportion"):
            rules.append((nt.word(f"steps.{c.method}", x=K._plan_markup(x), eq=eq), own))
        else:  # "same": its image coincides with another one found before
            other = next((cc.label for nn, cc in plans.constructions.items() if cc.label == x and nn != name), x)
            rules.append((nt.word("steps.same", x=K._sub(name), y=K._plan_markup(other)),
                          _leader_of([f"vector-p{x}"])))
    return rules


def _velocity_line_rules(nt: Notation, mech: Any, name: str, lines: Any, label_of: dict[str, str],
                         equation: str) -> list[tuple[str, Rule]]:
    """The two lines whose meeting point is ``name``'s image: through a known image (relative velocity) or
    through p, each ∥ or ⊥ a link or the guide; the vector equation goes with the first."""
    from graphmethods.sheets import kinematics as K

    rules: list[tuple[str, Rule]] = []
    for n_ln, ln in enumerate(lines):
        rel = "⊥" if ln.relation == "perpendicular" else "∥"
        to = nt.word("steps.guide") if ln.to == "guide" else K._sub(ln.to)
        v = f"v_{{{name}}}" if ln.through == "p" else f"v_{{{K._rel_name(mech, name, label_of[ln.through])}}}"
        names = [f"line-{name}-{ln.through}", f"label-line-{name}-{ln.through}"] + ([equation] if n_ln == 0 else [])
        rules.append((nt.word("steps.line", at=K._plan_markup(ln.through), v=v, rel=f"{rel} {to}"),
                      _leader_of(names)))
    return rules


# ----------------------------------------------------------------------------- acceleration plan

def acceleration_plan_steps(linkage: Any, position: int | None = None, *, notation: Any = "en",
                            page: Any = "slide", m: int | None = None, omega_1: float | None = None,
                            epsilon_1: float = 0.0, mu_a: Any = None) -> BuildUp:
    """The acceleration plan of one position, step by step, from its construction.

    The pole and μ_a; the crank pin's components; for every group each known component (the
    normal ones ω²·l toward the centre, the Coriolis ones with their direction) and each dashed
    direction of an unknown component, then the point where the two lines meet; the images by
    similarity; finally the table and ε of every link.

    Parameters
    ----------
    linkage : Case, Study, Mechanism or Linkage
        As :func:`graphmethods.sheets.acceleration.acceleration_plan` takes it.
    position, notation, page
        As :func:`velocity_plan_steps` takes them.

    Examples
    --------
    >>> from graphmethods.kinematics.presets import slider_crank
    >>> bu = acceleration_plan_steps(slider_crank(r=0.1, l=0.4, points={"S2": ("AB", 0.2)}), 1, omega_1=10.0)
    >>> for caption in bu.captions()[2:5]:
    ...     print(caption.split(":")[0])
    From a draw a^n_{BA} ∥ AB toward A
    Through n_{BA}, draw the direction of a^τ_{BA} ⊥ AB
    Through π, draw the direction of a_{B} ∥ the guide
    """
    from graphmethods.sheets import acceleration as SA

    nt, (pg, box, cap_mm, tb) = step_start(notation, page)
    pr = SA._Problem(linkage, m=m, omega_1=omega_1, epsilon_1=epsilon_1)
    plans = pr.plans()
    k = SA._default_position(plans, pr.linkage) if position is None else SA._check_position(position,
                                                                                              len(plans) - 1)
    figure = SA.acceleration_plan(linkage, k, m=m, omega_1=omega_1, epsilon_1=epsilon_1, mu_a=mu_a, notation=nt,
                                  page=pg, title_block=tb)
    plan = plans[k]
    tx = _AccelerationText(nt, SA._equations(plan, pr.linkage, nt), nt.unit("m/s²"))
    rules: list[tuple[str, Rule]] = [(nt.word("steps.a_pole", mu=figure.scales()[0].caption(nt)), _leader_of(
        ["title", "pole", "name-pi", "scale-captions", "legend", "equation-phi"]))]
    for j, st_ in enumerate(plan.steps):
        if st_.method == "crank":
            rules += _acceleration_crank_rules(tx, j, st_, pr.linkage.crank)
        elif st_.method != "intersection":
            c = st_.components[0]
            x = SA.image(st_.label)
            cap = (nt.word("steps.similarity", x=x, eq=tx.eqs[j][0]) if st_.method == "similarity"
                   else nt.word("steps.same", x=x, y=SA.image(plan.labels[st_.on[0]]) if st_.on else ""))
            rules.append((cap, _leader_of([SA._elname(c), _a_name(st_.label), f"equation-{j}"])))
        else:
            rules += _acceleration_intersection_rules(tx, j, st_)
    rules = _kept(rules + [(nt.word("steps.a_read"), lambda n: False)], figure)
    return _build(figure, rules, box, cap_mm, rest=len(rules))


def _a_name(label: str) -> str:
    """The element name of an acceleration image's letter."""
    from graphmethods.sheets import acceleration as SA

    return f"name-{SA._id(label)}"


@dataclass(frozen=True)
class _AccelerationText:
    """How the acceleration steps write a component: the notation, each step's (equation, values) line as
    the figure writes them, and the unit."""

    nt: Notation
    eqs: Any
    unit: str

    def value(self, c: Any) -> str:
        """``a^n_{BA} = 12.5 m/s²``."""
        from graphmethods.sheets import acceleration as SA

        return f"{SA.symbol(c.symbol)} = {self.nt.number(c.magnitude, sig=4)} {self.unit}"

    def first_value(self, j: int, c: Any) -> str:
        """The part of the values line of step j that gives component c."""
        from graphmethods.sheets import acceleration as SA

        for part in self.eqs[j][1].split(";  "):
            if part.startswith(SA.symbol(c.symbol) + " ="):
                return part
        return self.value(c)


def _acceleration_crank_rules(tx: _AccelerationText, j: int, st_: Any, cr: Any) -> list[tuple[str, Rule]]:
    """The crank pin's acceleration: πa ∥ OA alone (ε_1 = 0), or its normal and tangential parts."""
    from graphmethods.sheets import acceleration as SA, kinematics as K

    nt = tx.nt
    eq_names = [f"equation-{j}", f"values-{j}"]
    link = f"{cr.pin}{cr.centre}"
    if len(st_.components) == 1:
        c = st_.components[0]
        return [(nt.word("steps.a_crank", link=K._sub(link), O=K._sub(cr.centre), eq=tx.first_value(j, c)),
                 _leader_of([SA._elname(c), _a_name(st_.label)] + eq_names))]
    cn, ct, ca = st_.components
    return [(nt.word("steps.a_crank_n", a=SA.symbol(cn.symbol), link=K._sub(link), O=K._sub(cr.centre),
                     eq=tx.first_value(j, cn)), _leader_of([SA._elname(cn), _a_name(cn.end)] + eq_names)),
            (nt.word("steps.a_crank_t", n=SA.image(cn.end), a=SA.symbol(ct.symbol), link=K._sub(cr.centre + cr.pin),
                     eq=tx.first_value(j, ct), A=cr.pin),
             _leader_of([SA._elname(ct), SA._elname(ca), _a_name(st_.label), f"values-{j}-1"]))]


def _acceleration_intersection_rules(tx: _AccelerationText, j: int, st_: Any) -> list[tuple[str, Rule]]:
    """A point found by intersection: each known component (normal, Coriolis, the guide's point), each
    dashed direction of an unknown one, then the meeting point; the equation goes with the first."""
    from graphmethods.sheets import acceleration as SA, kinematics as K

    nt = tx.nt
    eq_names = [f"equation-{j}", f"values-{j}"]
    rules: list[tuple[str, Rule]] = []
    for i, c in enumerate(c for c in st_.components if c.known):
        names = [SA._elname(c), _a_name(c.end)] + (eq_names if not rules else [f"values-{j}-{i}"])  # its own values
        if c.kind == "normal":
            centre = c.symbol.split("_", 1)[1][len(st_.point):]
            rules.append((nt.word("steps.a_normal_pi" if c.start == "π" else "steps.a_normal", at=SA.image(c.start),
                                  a=SA.symbol(c.symbol), link=K._sub(centre + st_.point), C=K._sub(centre),
                                  eq=tx.first_value(j, c)), _leader_of(names)))
        elif c.kind == "coriolis":
            rel = c.symbol.split("_", 1)[1]
            rules.append((nt.word("steps.a_coriolis", at=SA.image(c.start), a=SA.symbol(c.symbol),
                                  dir=nt.word("steps.a_dir", rel=rel, n=c.link), eq=tx.first_value(j, c)),
                          _leader_of(names)))
        else:                                           # the guide's point under the slider
            rules.append((nt.word("steps.a_guide", x=SA.image(c.end), g=c.link or "?", C=K._sub(st_.point)),
                          _leader_of(names)))
    for ln in st_.lines:
        along = next((c for c in st_.components if not c.known and c.start == ln.through and c.kind != "absolute"),
                     None)
        if along is None:
            along = next(c for c in st_.components if c.kind == "absolute")
        relation = ln.label.replace("⟂", "⊥").split(" ", 1)
        to = nt.word("steps.guide") if relation[1] in ("guide", "slot") else K._sub(relation[1])
        lname = f"line-{st_.point}-{SA._id(ln.through)}"
        names = [lname, f"label-{lname}"] + (eq_names if not rules else [])
        rules.append((nt.word("steps.a_line", at=SA.image(ln.through), a=SA.symbol(along.symbol),
                              rel=f"{relation[0]} {to}"), _leader_of(names)))
    found = [c for c in st_.components if not c.known]
    vals = ",  ".join(tx.value(c) for c in found)
    rules.append((nt.word("steps.meet", x=SA.image(st_.label), values=vals),
                  _leader_of([SA._elname(c) for c in found] + [_a_name(st_.label)])))
    return rules


# ----------------------------------------------------------------------------- energy indicator

def slide_step_mm(n: int, page: Page) -> float | None:
    """The step between the energy indicator's ``n`` vectors on a slide (None on paper: the figure's own).

    A slide is wide: the vectors spread over its whole width (22 mm apart, the A4 figure's most, filled a third
    of it for a cycle of three intervals; three times that still left half its cells empty).

    >>> from graphmethods.sheets.projector import SLIDE_PAGE
    >>> slide_step_mm(3, SLIDE_PAGE) > 22.0, slide_step_mm(3, Page("A4", "landscape"))
    (True, None)
    """
    from graphmethods.sheets import energy as E_

    if str(page.size).upper() != "SLIDE":
        return None
    L = E_.INDICATOR_LAYOUT
    x0, _, x1, _ = page.inner_box()
    room = x1 - L.right_room_mm - (x0 + L.axis_mm + L.first_mm)
    return max(L.step_min_mm, room / max(n - 1, 1))


def energy_indicator_steps(cycle, *, notation="en", page="slide", mu_E=None, work_unit: str = "J") -> BuildUp:
    """The energy indicator diagram, step by step: the axis, one vector per interval, the closure,
    the extremes and ΔW_max.

    Parameters
    ----------
    cycle : ExcessWork or problem
        As :func:`graphmethods.sheets.energy.energy_indicator` takes it.
    """
    from graphmethods.sheets import energy as E_

    nt, (pg, box, cap_mm, tb) = step_start(notation, page)
    ew, _ = E_._cycle(cycle, nt)
    step_mm = slide_step_mm(len(ew.work), pg)
    try:
        figure = E_.energy_indicator(cycle, mu_E=mu_E, notation=nt, page=pg, title_block=tb, work_unit=work_unit,
                                     step_mm=step_mm)
    except InputError:                          # the sheet's own frame is narrower than estimated: its own step
        figure = E_.energy_indicator(cycle, mu_E=mu_E, notation=nt, page=pg, title_block=tb, work_unit=work_unit)
    s_E = _axis_scale(figure, "axis-E")
    u = nt.unit(work_unit)
    lab = ew.labels
    rules: list[tuple[str, Rule]] = [(nt.word("steps.axis_E", E=nt.sym("E"), mu=s_E.caption(nt)),
              ["title", "axis-E", "start-level", f"name-{lab[0]}", "scale-captions", "legend"])]
    for i, A in enumerate(ew.work):
        a, b = lab[i], lab[i + 1]
        cap = nt.word("steps.interval", ab=f"{a}{b}", A=nt.sym("A"), val=f"{nt.number(float(A))} {u}",
                      mm=nt.number(abs(s_E.to_mm(float(A))), sig=4),
                      dir=nt.word("steps.up" if A > 0 else "steps.down"), a=a, b=b)
        rules.append((cap, [f"vector-{a}{b}", f"value-{i + 1}", f"name-{b}", f"level-{b}"]))
    res = float(ew.residual)
    closed = abs(res) <= 1e-9 * (float(np.abs(ew.work).sum()) or 1.0)
    total = f"Σ{nt.sym('A')} = {nt.number(0.0 if closed else res)} {u}"
    rules.append((nt.word("steps.closure" if closed else "steps.residual", sum=total), ["closure", "leader-closure"]))
    rules.append((nt.word("steps.extremes", hi=lab[ew.index_E_max], lo=lab[ew.index_E_min], dW=nt.sym("delta_W_max"),
                     val=f"{nt.number(float(ew.delta_W_max))} {u}"),
                  lambda n: n in ("level-max", "level-min", "dimension-delta-W-max") or n.endswith(("E_max", "E_min"))))
    return _build(figure, rules, box, cap_mm, rest=None)


# ----------------------------------------------------------------------------- Wittenbauer diagram

def wittenbauer_steps(source, *, notation="en", page="slide", mu_J=None, mu_T=None,
                      tangents: str = "exact") -> BuildUp:
    """The Wittenbauer energy–mass diagram, step by step: axes, the points, the curve, the ray at
    ψ_max, the ray at ψ_min, k and l, kl, and J_F.

    Parameters
    ----------
    source : Study, Case or WittenbauerResult
        As :func:`graphmethods.sheets.wittenbauer.wittenbauer_diagram` takes it.
    """
    from graphmethods.sheets import wittenbauer as W

    nt, (pg, box, cap_mm, tb) = step_start(notation, page)
    figure, c = _sheet_scaled_diagram(source, nt=nt, page=pg, title_block=tb, tangents=tangents) \
        if mu_J is None and mu_T is None else (None, 1.0)
    if figure is None:
        figure = W.wittenbauer_diagram(source, mu_J=mu_J, mu_T=mu_T, tangents=tangents, notation=nt, page=pg,
                                       title_block=tb)
    data = W.diagram_data(source, tangents=tangents, notation=nt)
    s_T, s_J = _axis_scale(figure, "axis-T"), _axis_scale(figure, "axis-J")
    res = data.result(s_J.per_mm, s_T.per_mm)
    J_0 = float(getattr(figure.element("axis-J"), "min_value", 0.0))   # its suppressed zero, as the A1 sheet's
    res = W.offset_origin(res, J_0) if J_0 > 0.0 else res
    J, T = nt.sym("dynamics.J_e"), nt.sym("dynamics.dT")

    ray = {}
    tans = dict(zip(("max", "min"), nt.column((float(res.tan_psi_max), float(res.tan_psi_min)))))  # the table's digits
    for key in ("max", "min"):
        idx = res.index_omega_max if key == "max" else res.index_omega_min
        psi = nt.sym(f"dynamics.psi_{key}")
        ray[key] = (nt.word(f"steps.ray_{key}", psi=psi, tan=tans[key],
                            w=nt.sym(f"dynamics.omega_{key}"), i=", ".join(str(int(i)) for i in idx)),
                    _starts(f"ray-{key}", f"psi-{key}-", f"label-psi-{key}", f"leader-psi-{key}", f"tangency-{key}-",
                           f"label-omega-{key}", f"leader-omega-{key}"))
    rules = [
        (nt.word("steps.axes_JT", J=J, T=T, muJ=s_J.caption(nt), muT=s_T.caption(nt)),
         ["title", "axis-T", "axis-J", "axis-J-break", "scale-captions"]),      # the break: J from J_0
        (nt.word("steps.points", m=res.m - 1, J=J, T=T), _starts("vertex-", "pos-", "leader-pos-")),
        (nt.word("steps.curve", J=J, T=T), ["curve"]),
        ray["max"],
        ray["min"],
        (nt.word("steps.kl_points"), ["point-k", "point-l", "name-k", "name-l"]),
        (nt.word("steps.kl", kl=nt.number(float(res.kl_mm))) if c == 1.0 else
         nt.word("steps.kl_sheet", kl=nt.number(float(res.kl_mm)), c=nt.number(c),
                 kl1=nt.number(float(res.kl_mm) * c)), ["dimension-kl", "label-kl", "leader-kl"]),
        (nt.word("steps.J_F", JF=nt.sym("dynamics.J_F"), muT=nt.sym("mu_T"), wm=nt.sym("dynamics.omega_m"),
                 d=nt.sym("dynamics.delta"), J=f"{nt.number(float(res.J_F), sig=4)} {nt.unit('kg·m²')}"),
         lambda n: False),
    ]
    return _build(figure, rules, box, cap_mm, rest=len(rules))


def _sheet_scaled_diagram(source, *, nt, page, title_block: bool, tangents: str) -> tuple[Any, float]:
    """The energy–mass diagram of a study at the A1 dynamic sheet's scales, or at both of them c times larger
    (c from 1, 2, 2.5, 4, 5 × 10ᵏ, the smallest whose diagram fits the page, both scales still convenient):
    the rays keep the sheet's slopes, so the slides and the HTML stepper print its tan ψ_max, tan ψ_min and
    J_F, and kl is the sheet's divided by c. (None, 1) for data without a linkage study."""
    from graphmethods.dynamics.study import Study
    from graphmethods.sheets import wittenbauer as W
    from graphmethods.sheets.dynamic_analysis_sheet import sheet_scales
    from graphmethods.units import CONVENIENT, convenient_at_least

    if not isinstance(source, Study):
        return None, 1.0
    s_J, s_T, J_0 = sheet_scales(source, tangents=tangents)

    def convenient(v: float) -> bool:
        return abs(convenient_at_least(v * (1 - 1e-12)) / v - 1.0) < 1e-9

    for k in range(7):
        for m_ in CONVENIENT:
            c = float(f"{m_!r}e{k}")
            if not (convenient(c * s_J.per_mm) and convenient(c * s_T.per_mm)):
                continue
            try:
                return W.wittenbauer_diagram(source, mu_J=c * s_J.per_mm, mu_T=c * s_T.per_mm, tangents=tangents,
                                             notation=nt, page=page, title_block=title_block, J_0=J_0), c
            except InputError:
                continue
    return None, 1.0


# split out of this module, imported here so that every name reads as before: construction_steps.py
from graphmethods.sheets.construction_steps import (  # noqa: E402
    differentiation_steps,
    force_plans_steps,
    integration_steps,
    scheme_steps,
    zhukovsky_forces_steps,
    zhukovsky_steps,
)

# ----------------------------------------------------------------------------- by name

#: figure name -> (step source, what it needs: "linkage" or "cycle")
def _inversion_steps(cam: Any, *, notation: Any = "en", page: Any = "slide") -> BuildUp:
    """The cam profile by inversion (:func:`graphmethods.sheets.cam_steps.inversion_steps`)."""
    from graphmethods.sheets.cam_steps import inversion_steps

    return inversion_steps(cam, notation=notation, page=page)


FIGURES: dict[str, tuple[Callable, str]] = {
    "velocity-plan": (velocity_plan_steps, "linkage"),
    "acceleration-plan": (acceleration_plan_steps, "linkage"),
    "energy-indicator": (energy_indicator_steps, "cycle"),
    "wittenbauer": (wittenbauer_steps, "study"),
    "kinematic-diagrams": (differentiation_steps, "linkage"),
    "work-diagrams": (integration_steps, "cycle"),
    "force-plans": (force_plans_steps, "linkage"),
    "zhukovsky-lever": (zhukovsky_forces_steps, "linkage"),
    "zhukovsky-load": (zhukovsky_steps, "study"),
    "kinematic-scheme": (scheme_steps, "linkage"),
    "inversion": (_inversion_steps, "cam"),
}

#: the build-ups whose slides are built lettered for the slide (3.5 mm and up once enlarged:
#: :func:`~graphmethods.sheets.projector.slide_lettered`): every one (the dynamics build-ups' paper lettering of
#: 2.6…2.8 mm was drawn 1.0…1.2 : 1, 2.6…3.4 mm on the slide)
SLIDE_LETTERED = ("velocity-plan", "acceleration-plan", "force-plans", "zhukovsky-lever", "zhukovsky-load",
                  "kinematic-scheme", "kinematic-diagrams", "energy-indicator", "work-diagrams", "wittenbauer")

#: the dynamics build-ups: their slides take no enlargement that sets a label on a line
DYNAMICS = ("energy-indicator", "work-diagrams", "wittenbauer")

#: the figures drawn in one position (``--position K``)
POSITIONED = ("velocity-plan", "acceleration-plan", "force-plans", "zhukovsky-lever", "zhukovsky-load")

#: built-in problems: name -> problem file in graphmethods/problems/data (linkages) or a W problem
LINKAGES = {"press": "slider_crank_press.json", "four-bar": "four_bar_rocker.json",
            "slotted-lever": "slotted_lever.json", "shaper": "shaper.json"}
CYCLES = ("W1", "W2", "W3", "W4")


def _is_cam_file(text: str) -> bool:
    """Whether ``text`` names a ``"kind": "cam"`` problem file."""
    from graphmethods.units import json_value

    p = pathlib.Path(text)
    if not p.is_file():
        return False
    try:
        data = json_value(p.read_text(encoding="utf-8"), text)
    except (InputError, OSError, UnicodeDecodeError):
        return False
    return isinstance(data, dict) and data.get("kind") == "cam"


def resolve_case(case):
    """A built-in name (press, four-bar, slotted-lever, shaper, W1…W4) or a problem file, as an object the
    step sources take: a linkage :class:`~graphmethods.kinematics.Case` or a cycle problem.

    >>> from graphmethods.kinematics import Case
    >>> isinstance(resolve_case("press"), Case), resolve_case("w1").id
    (True, 'W1')
    """
    from graphmethods import problems

    if not isinstance(case, (str, pathlib.Path)):
        return case
    text = str(case).strip()
    low = text.lower().replace("_", "-")
    from graphmethods.problems import builtin as every

    if low in every.CAMS or _is_cam_file(text):
        return every.cam_problem(text)
    if low in LINKAGES or low in every.LINKAGES:
        from graphmethods.kinematics import read_case

        return read_case(every.DATA / (LINKAGES.get(low) or every.LINKAGES[low]))
    builtin = {"w1": problems.w1, "w2": problems.w2, "w3": problems.w3, "w4": problems.w4_drawing}
    if low in builtin:
        return builtin[low]()
    if text == every.STDIN:                   # the problem file on standard input
        return every.case(text)
    p = pathlib.Path(text)
    if not p.is_file() and (low.startswith("drawn") and (low in every.DRAWN or low[6:] in every.LINKAGES)):
        p = every.case_path(low)                 # the drawn form's worked files and drawn/NAME
    if not p.is_file():
        known = list(dict.fromkeys([*LINKAGES, *every.LINKAGES])) + list(CYCLES)
        raise InputError(f"case {text!r}: not a built-in problem ({', '.join(known)}) and no such file")
    from graphmethods.kinematics import read_case

    return read_case(p)


def build(case, figure: str, *, position: int | None = None, notation="en", page="slide", m: int = 12) -> BuildUp:
    """The construction ``figure`` of ``case`` as steps.

    Parameters
    ----------
    case : str, path or problem
        A built-in name (``press``, ``four-bar``, ``slotted-lever``, ``shaper``, ``W1`` … ``W4``), a
        linkage problem file, or a problem object.
    figure : str
        One of :data:`FIGURES`: ``velocity-plan``, ``energy-indicator``, ``wittenbauer``,
        ``kinematic-diagrams``, ``work-diagrams``, ``force-plans``, ``zhukovsky-lever`` (every force,
        M_b), ``zhukovsky-load`` (the working load alone, M_r), ``kinematic-scheme``.
    position : int, optional
        The position of a velocity, acceleration or force plan or of Zhukovsky's lever.
    m : int
        Positions per crank turn of a linkage study.

    Examples
    --------
    >>> bu = build("press", "wittenbauer", notation="ru")
    >>> len(bu), bu.figure.notation
    (8, 'ru')
    """
    from graphmethods.kinematics import Case

    key = str(figure).strip().lower().replace("_", "-")
    if key not in FIGURES:
        raise InputError(f"figure {figure!r}: use one of {', '.join(FIGURES)}")
    fn, needs = FIGURES[key]
    obj = resolve_case(case)
    is_linkage = isinstance(obj, Case)
    if (needs == "cam") != (getattr(obj, "kind", "") == "cam"):
        raise InputError(f"{key} is not drawn for {case}: a cam problem's construction is the inversion "
                         f"(graphmethods steps CAM inversion); the others need a linkage or a cycle")
    if needs == "cam":
        def make_cam(pg):
            return fn(obj, notation=notation, page=pg)
        if isinstance(page, str) and page.strip().lower() == "slide":
            return for_projector(make_cam)
        return make_cam(page)
    if position is not None and key not in POSITIONED:
        raise InputError(f"--position is for the velocity, acceleration and force plans and Zhukovsky's lever only, "
                         f"not for {key}")
    if needs == "linkage":
        if not is_linkage:
            raise InputError(f"{key} needs a linkage problem ({', '.join(LINKAGES)} or a problem file); {case} is "
                             f"a cycle given by its works")
        if key in POSITIONED:
            def make(pg):
                return fn(obj, position, notation=notation, page=pg, m=m)
        else:
            def make(pg):
                return fn(obj, notation=notation, page=pg, m=m)
    else:
        if is_linkage:
            from graphmethods.dynamics.study import Study

            obj = Study(obj, positions=m)
        elif needs == "study":
            raise InputError(f"{key} needs a linkage problem with masses and loads ({', '.join(LINKAGES)} or a "
                             f"problem file); {case} gives works only")
        if key == "work-diagrams":
            def make(pg):
                return fn(obj, notation=notation, page=pg, m=m)
        elif key == "zhukovsky-load":
            def make(pg):
                return fn(obj, position, notation=notation, page=pg)
        else:
            def make(pg):
                return fn(obj, notation=notation, page=pg)
    if isinstance(page, str) and page.strip().lower() == "slide":
        return for_projector(make, lettered=key in SLIDE_LETTERED, uncrossed=key in DYNAMICS)
    return make(page)
