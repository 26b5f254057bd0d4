"""The acceleration figures: one large plan with its construction, the plans of all positions, the table.

Each function takes a linkage problem (as :mod:`graphmethods.sheets.kinematics` does: a problem
file read by :func:`~graphmethods.kinematics.read_case`, a Study, a mechanism, or a core
:class:`~graphmethods.kinematics.linkage.Linkage`) and returns a Scene:

- :func:`acceleration_plan`: the plan of one position drawn large from the pole π: the known
  components solid (the normal ones ω²·l from their point toward the centre, the Coriolis ones
  2ω·v_rel), the unknown directions as dashed construction lines (⟂ the link, ∥ the slot or
  guide), the components found where they meet (dashed vectors), the images of the centres of
  mass by similarity; under the plan the vector equations as the book writes them with the
  known values; beside it a table of every vector's drawn length and value, and the angular
  acceleration ε of every link with its sense.
- :func:`acceleration_plan_grid`: the plans of all positions on one sheet, to one μ_a.
- :func:`acceleration_table`: the accelerations per position (a table like the velocity table).

The construction itself is :mod:`graphmethods.kinematics.acceleration_plan`; a figure only turns
its plan vectors into millimetres with μ_a. The sense of ε is written beside the plan (as the
velocity plan writes the sense of ω): the textbook rule is to carry a^τ to the link's point on
the scheme and read the turn it gives about the other point, which is what the sign of ε says.

>>> from graphmethods.kinematics.presets import slider_crank
>>> from graphmethods.render.recording import record
>>> s = acceleration_plan(slider_crank(r=0.1, l=0.4, points={"S2": ("AB", 0.2)}), 2, omega_1=10.0, mu_a=0.2)
>>> round(record(s).vector_length_mm("vector-pi-a") * 0.2, 9)     # |a_A| = ω₁²·r = 10 m/s²
10.0
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from graphmethods.errors import InputError
from graphmethods.kinematics.acceleration_plan import AccelerationPlan, Component, acceleration_plans
from graphmethods.scene import Line, Page, Point, Scale, Scene, Table, Text, Vector, markup, notation as get_notation
from graphmethods.scene.elements import Element, Group as ElementGroup
from graphmethods.scene.numbers import within_roundoff
from graphmethods.scene.primitives import DASHED
from graphmethods.sheets import acceleration_layout as AL, kinematics as K
from graphmethods.sheets.layout import TEXT_MM, Occupancy, Sheet
from graphmethods.sheets.styles import CELL
from graphmethods.sheets.velocity_table import table_rows

SMALL_MM = K.SMALL_MM
TABLE_MM = K.TABLE_MM
LINE_STYLE = DASHED

_SYM = re.compile(r"^(a(?:\^[nτkr])?)_(\w+)$")


def symbol(plain: str) -> str:
    """Markup of a plain symbol of the construction: ``"a^n_BA"`` -> ``"a^n_{BA}"``.

    >>> symbol("a^k_A3A2"), symbol("a_S2")
    ('a^k_{A3A2}', 'a_{S2}')
    """
    mt = _SYM.match(plain)
    return f"{mt.group(1)}_{{{mt.group(2)}}}" if mt else plain


def image(label: str) -> str:
    """Markup of an image label: ``"n_BA"`` -> ``"n_{BA}"``, ``"a3"`` -> ``"a_{3}"``, ``"π"`` -> ``"π"``.

    >>> image("n_BA"), image("s2"), image("k_A3A2")
    ('n_{BA}', 's_{2}', 'k_{A3A2}')
    """
    if "_" in label:
        head, tail = label.split("_", 1)
        return f"{head}_{{{tail}}}"
    return K._sub(label)


def _id(label: str) -> str:
    """An image label as it may appear in an element name (ASCII: π is ``pi``)."""
    return label.replace("π", "pi")


def _elname(c: Component) -> str:
    return f"vector-{_id(c.start)}-{_id(c.end)}"


class _Problem:
    """The linkage to draw, its speed and the words of its problem, from whatever the user gave."""

    def __init__(self, obj, *, m, omega_1, epsilon_1) -> None:
        from graphmethods.kinematics.linkage import Linkage

        if isinstance(epsilon_1, bool) or not isinstance(epsilon_1, (int, float)) or not math.isfinite(epsilon_1):
            raise InputError(f"epsilon_1 is the crank's angular acceleration in rad/s² (a finite number), "
                             f"got {epsilon_1!r}")
        self.epsilon_1 = float(epsilon_1)
        if isinstance(obj, Linkage):
            if omega_1 is not None and (isinstance(omega_1, bool) or not isinstance(omega_1, (int, float))
                                        or not math.isfinite(omega_1) or omega_1 <= 0):
                raise InputError(f"omega_1 is the crank speed in rad/s and must be > 0, got {omega_1!r}")
            self.linkage, self.m = obj, 12 if m is None else m
            self.omega_1, self.problem, self.n_rpm = (1.0 if omega_1 is None else float(omega_1)), "", None
            return
        lk = K._Linkage.of(obj, m=m, omega_1=omega_1)
        self.phi = getattr(obj, "phi_angles", None)      # a study at given crank angles (AngleStudy)
        mech = lk.mech
        self.linkage = mech.linkage          # every mechanism is a linkage of the core
        self.m = 12 if lk.m is None else lk.m
        self.omega_1, self.problem, self.n_rpm = lk.omega_1, lk.problem, lk.n_rpm

    def plans(self) -> tuple[AccelerationPlan, ...]:
        if getattr(self, "phi", None) is not None:
            return acceleration_plans(self.linkage, phi=self.phi, omega_1=self.omega_1, epsilon_1=self.epsilon_1)
        if isinstance(self.m, bool) or not isinstance(self.m, (int, np.integer)) or self.m < 3:
            raise InputError(f"the number of positions m must be an integer ≥ 3, got {self.m!r}")
        return acceleration_plans(self.linkage, m=int(self.m), omega_1=self.omega_1, epsilon_1=self.epsilon_1)

    def speed_text(self, nt) -> str:
        return nt.word("acceleration.speed", w=nt.number(self.omega_1, sig=4), e=nt.number(self.epsilon_1, sig=4))


def _pick_mu_a(mu_a, need: float, *, what: str, nt) -> Scale:
    """μ_a of an acceleration plan (:func:`~graphmethods.sheets.kinematics._pick_plan_scale`)."""
    return K._pick_plan_scale(mu_a, need, symbol="μ_a", unit="m/s²", what=what, nt=nt)


def _default_position(plans: tuple[AccelerationPlan, ...], linkage) -> int:
    """The working-stroke position whose plan is the fullest figure (as for the velocity plan)."""
    mo = linkage.motion(m=len(plans) - 1, level=0)
    working = mo.strokes.working_angle if mo.strokes is not None else 2 * math.pi
    best, score = 1, -1.0
    for k, p in enumerate(plans[:-1]):
        if bool(mo.extreme[k]) or mo.phi_from_start[k] > working:
            continue
        pts = np.array([[z.real, z.imag] for z in p.images.values()])
        big = float(np.max(np.hypot(pts[:, 0], pts[:, 1])))
        if big <= 0:
            continue
        sc = K._hull_area(pts) / big ** 2
        if sc > score + 1e-12:
            best, score = k, sc
    return best


_JOINT = re.compile(r"[A-Z][0-9]*")


def _length_name(rel: str) -> str:
    """The length of a relative normal or tangential acceleration ``a_XY`` as the books write it, l_YX.

    >>> _length_name("BA"), _length_name("K3B"), _length_name("A3O3")
    ('AB', 'BK3', 'O3A3')
    """
    joints = _JOINT.findall(rel)
    return "".join(reversed(joints)) if "".join(joints) == rel and len(joints) == 2 else rel


def _check_position(position, m: int) -> int:
    if isinstance(position, bool) or not isinstance(position, (int, np.integer)) or not 0 <= int(position) < m:
        raise InputError(f"position {position!r}: give one of the positions 0…{m - 1}")
    return int(position)


def _equations(plan: AccelerationPlan, linkage, nt) -> list[tuple[str, str]]:
    """(the vector equation, its known values) of every step, in markup."""
    unit = nt.unit("m/s²")
    cr = linkage.crank
    out = []

    def num(x: float) -> str:
        return nt.number(x, sig=4)

    for s in plan.steps:
        eq = " = ".join(" + ".join(symbol(t.strip()) for t in side.split(" + ")) for side in s.equation.split(" = "))
        eq = eq.replace("Assur's point", nt.word("acceleration.assur_point"))     # the record's words, translated
        if s.method == "similarity" and len(s.on) == 2:
            x, y = s.on
            lx, ly = image(plan.labels[x]), image(plan.labels[y])
            eq = f"{lx}{image(s.label)}/{lx}{ly} = {K._sub(x + s.point)}/{K._sub(x + y)}"
        vals = []
        if s.method == "crank" and plan.epsilon_1 == 0.0:
            c = s.components[0]
            vals.append(f"{symbol(c.symbol)} = ω_{{1}}²·l_{{{cr.centre + cr.pin}}} = "
                        f"{num(plan.omega_1)}²·{num(cr.r)} = {num(c.magnitude)} {unit}")
        for c in s.components:
            if not c.known:
                continue
            rel = c.symbol.split("_", 1)[1]
            if c.kind == "normal":
                ends = (cr.centre + cr.pin) if s.method == "crank" else _length_name(rel)
                w = abs(plan.omega[c.link])
                if within_roundoff(w, plan.omega_1):        # the link stands still here: no normal component
                    vals.append(nt.zero(symbol(c.symbol), f"ω_{{{c.link}}}"))
                    continue
                vals.append(f"{symbol(c.symbol)} = ω_{{{c.link}}}²·l_{{{ends}}} = {num(w)}²·{num(c.factor)} = "
                            f"{num(c.magnitude)} {unit}")
            elif c.kind == "tangential":                 # the crank's own a^τ (ε₁ given)
                vals.append(f"{symbol(c.symbol)} = ε_{{{c.link}}}·l_{{{cr.centre + cr.pin}}} = "
                            f"{num(abs(plan.epsilon_1))}·{num(c.factor)} = {num(c.magnitude)} {unit}")
            elif c.kind == "coriolis" and within_roundoff(plan.omega[c.link], plan.omega_1):
                vals.append(nt.zero(symbol(c.symbol), f"ω_{{{c.link}}}"))
            elif c.kind == "coriolis" and within_roundoff(c.factor, plan.omega_1 * cr.r):
                vals.append(nt.zero(symbol(c.symbol), f"v_{{{rel}}}"))
            elif c.kind == "coriolis":
                vals.append(f"{symbol(c.symbol)} = 2·ω_{{{c.link}}}·v_{{{rel}}} = 2·{num(abs(plan.omega[c.link]))}·"
                            f"{num(c.factor)} = {num(c.magnitude)} {unit}")
        out.append((eq, ";  ".join(vals)))
    return out


def _eps_texts(plan: AccelerationPlan, linkage, nt) -> list[tuple[str, str]]:
    """(link, text) of ε of every link found from a tangential component: formula, value and sense."""
    out: list[tuple[str, str]] = []
    unit = nt.unit("rad/s²")
    r = linkage.crank.r
    a_ref = plan.omega_1**2 * r + abs(plan.epsilon_1) * r     # the size of the plan's accelerations
    for s in plan.steps:
        for c in s.components:
            if c.kind != "tangential" or s.method == "crank" or any(c.link == o for o, _ in out):
                continue
            e = plan.epsilon[c.link]
            rel = c.symbol.split("_", 1)[1]
            if within_roundoff(c.magnitude, a_ref):       # no tangential component: the link's ε is 0
                out.append((c.link, nt.zero(f"ε_{{{c.link}}}", symbol(c.symbol))))
                continue
            out.append((c.link, (f"ε_{{{c.link}}} = {symbol(c.symbol)}/l_{{{_length_name(rel)}}} = "
                                f"{nt.number(c.magnitude, sig=4)}/{nt.number(c.factor, sig=4)} = "
                                f"{nt.number(abs(e), sig=4)} {unit}, {K._sense_word(nt, e)}")))
    return out


def _place_labels(occ: Occupancy, pts: dict, plan: AccelerationPlan, *, size_mm: float, within, hard=None,
                  leaders=None, prefix: str = "") -> list:
    """Labels of the images: coincident images share one label, each placed away from π
    (:func:`~graphmethods.sheets.kinematics._plan_labels`)."""
    return K._plan_labels(occ, pts, "π", [lb for lb in pts if lb != "π"], markup_of=image, id_of=_id,
                          size_mm=size_mm, within=within, prefix=prefix, hard=hard, leaders=leaders)


@dataclass(frozen=True)
class AccelerationPlanLayout(K.PlanLayout):
    """The millimetre constants of one acceleration plan drawn large: those of the velocity plan, the
    equations under the plan."""

    row_mm: float = 6.0                 # the table's rows
    equation_mm: float = 5.4            # between the lines of equations under the plan
    equations_below_mm: float = 7.0     # the first equation below the plan's area
    values_indent_mm: float = 6.0       # the known values under their equation
    equation_columns_gap_mm: float = 8.0  # between two columns of equations (a slide)
    min_plan_mm: float = 40.0           # the least height the plan may have


ACCELERATION_PLAN_LAYOUT = AccelerationPlanLayout()

Block = AL.Block


def _equation_texts(columns: list[list[Block]], origins, lay: AccelerationPlanLayout) -> list[Element]:
    """The equations' Text elements, each column from its origin (mm); the lines of one text broken
    (:func:`~graphmethods.sheets.acceleration_layout.wrap`) are one group of its name."""
    out: list[Element] = []
    for col, (cx, ey) in zip(columns, origins):
        row = 0
        for b_ in col:
            names = [nm for nm, _, _ in b_]
            for i, (nm, line, dx) in enumerate(b_):
                t = Text((cx + dx, ey + row * lay.equation_mm), line, size_mm=TEXT_MM,
                         name=nm if names.count(nm) == 1 else f"{nm}-line-{i - names.index(nm)}")
                row += 1
                if names.count(nm) == 1:
                    out.append(t)
                elif names.index(nm) == i:
                    out.append(ElementGroup((t,), name=nm))
                else:
                    out[-1] = ElementGroup(out[-1].elements + (t,), name=nm)     # type: ignore[attr-defined]
    return out


def _acceleration_lines(plan: AccelerationPlan, pts: dict, nt) -> tuple[list[Line], list[str]]:
    """The construction lines (dashed, through their image, past the point found) and their labels."""
    lines, texts = [], []
    guide = nt.word("kinematics.guide")
    for s in plan.steps:
        X = np.asarray(pts[s.label])
        for ln in s.lines:
            d = np.array([ln.direction.real, -ln.direction.imag])
            d /= float(np.hypot(*d))
            lines.append(K._through(np.asarray(pts[ln.through]), d, X, f"line-{s.point}-{_id(ln.through)}",
                                    LINE_STYLE))
            text = ln.label.replace("⟂", "⊥").replace("guide", guide).replace("slot", guide)
            texts.append(" ".join(K._sub(w) for w in text.split(" ")))
    return lines, texts


def _broken_for_labels(elements: list, boxes: list) -> list:
    """The construction lines and leaders among ``elements`` broken where they would cross a label's box
    (mm; a crowded plan: a line is interrupted for an inscription, ГОСТ 2.303), the rest as they are, in
    order."""
    from graphmethods.sheets.linkage_figures import broken_behind

    return [q for e in elements for q in (broken_behind([e], boxes) if isinstance(e, Line) else [e])]


def _component_vectors(pts: dict, comps, *, prefix: str, head_mm: float, width_mm: float) -> list[Element]:
    """The components of a plan as vectors (each once; those of zero length left out)."""
    vecs: list[Element] = []
    seen = set()
    for c in comps:
        if math.dist(pts[c.start], pts[c.end]) < 1e-9 or _elname(c) in seen:
            continue
        seen.add(_elname(c))
        vecs.append(Vector(pts[c.start], pts[c.end], known=c.known, head_length_mm=head_mm, head_width_mm=width_mm,
                           name=f"{prefix}{_elname(c)}"))
    return vecs


def _table_heads(head: tuple[str, ...]) -> list[tuple[tuple[str, ...], ...]]:
    """The table's headings on one row, and (when a heading has a unit after a comma) on two, each unit under
    its word, as a narrow table sets them ("Acceleration," over "m/s²"): the plan takes the one that draws it
    larger, so that one plan has one μ_a in every language whose text fits.

    >>> _table_heads(("Vector", "Length, mm"))
    [(('Vector', 'Length, mm'),), (('Vector', 'Length,'), ('', 'mm'))]
    >>> len(_table_heads(("矢量", "长度/mm")))
    1
    """
    split = [h.split(", ", 1) for h in head]
    if all(len(p) == 1 for p in split):
        return [(head,)]
    return [(head,), (tuple(p[0] + ("," if len(p) == 2 else "") for p in split),
                      tuple(p[1] if len(p) == 2 else "" for p in split))]


def _acceleration_column(comps, pts: dict, head: tuple[tuple[str, ...], ...], s_a: Scale,
                         eps: list[tuple[str, str]], at, limit, nt, lay: AccelerationPlanLayout) -> list[Element]:
    """Beside the plan at ``at`` (mm): every component's drawn length and value, then ε of the links; the
    table (under the heading rows ``head``) must end left of and above ``limit`` (mm)."""
    rows = list(head)
    lengths = [math.dist(pts[c.start], pts[c.end]) for c in comps]
    # the values with one number of decimals, four digits of the largest (1234 m/s², not 1233.701); 0 for a
    # length within the round-off of the plan's construction
    values = nt.column([L * s_a.per_mm for L in lengths], sig=4, reference=max(lengths, default=0.0) * s_a.per_mm)
    for c, L, v in zip(comps, lengths, values):
        rows.append((image(c.start) + image(c.end), K._num(nt, L, 2), f"{symbol(c.symbol)} = {v}"))
    tables = [Table(at, tuple(rows), align="crl", size_mm=TABLE_MM, row_height_mm=lay.row_mm, name="table",
                    header_rows=len(head))]
    below = lay.after_table_mm + len(eps) * lay.line_mm                             # ε of the links under it
    if tables[0].bottom_left[1] + below > limit[1] + 2 * lay.line_mm:   # a long table (a triad's): rows closer
        room = limit[1] - at[1] - below
        row = max(TABLE_MM * 1.7, room / (len(rows) + 0.5))
        tables = [Table(at, tuple(rows), align="crl", size_mm=TABLE_MM, row_height_mm=row, name="table",
                        header_rows=len(head))]
    if max(t.top_right[0] for t in tables) > limit[0] + 1e-6 or max(t.bottom_left[1] for t in tables) > limit[1]:
        raise InputError("the table of vectors does not fit beside the plan; give a larger page")
    wy = max(t.bottom_left[1] for t in tables) + lay.after_table_mm
    return [*tables] + [Text((at[0], wy + i * lay.line_mm), t, size_mm=TEXT_MM, name=f"epsilon-{link}")
                        for i, (link, t) in enumerate(eps)]


def acceleration_plan(linkage, position: int | None = None, *, m: int | None = None, omega_1: float | None = None,
                      epsilon_1: float = 0.0, mu_a=None, notation="en", page=None, title=None, problem=None,
                      title_block: bool = True, name: str = "acceleration-plan") -> Scene:
    """One acceleration plan drawn large, with its construction, equations, table and ε.

    Parameters
    ----------
    linkage : Case, Study, Mechanism, Positions, VelocityPlans or Linkage
    position : int, optional
        The position drawn (default: the fullest plan of the working stroke).
    m : int, optional
        Positions per crank turn (12).
    omega_1 : float, optional
        Crank speed, rad/s (the problem's mean speed, or 1).
    epsilon_1 : float
        Crank angular acceleration, rad/s² (+ speeding up): its own a^τ is drawn.
    mu_a : float or Scale, optional
        Acceleration scale, (m/s²)/mm; picked (a convenient value) so the plan fills its area.

    Raises
    ------
    InputError
        A position not among 0…m−1, a given μ_a the plan does not fit, bad speeds.

    Examples
    --------
    >>> from graphmethods.kinematics.presets import slotted_lever
    >>> s = acceleration_plan(slotted_lever(r=0.1, l_O1O3=0.3, l_O3B=0.6), 2, omega_1=10.0, notation="ru")
    >>> s.title, sorted(e.name for e in s.elements if e.name.startswith("line-"))
    ('План ускорений, положение 2', ['line-A3-k_A3A2', 'line-A3-n_A3O3'])
    """
    pr = _Problem(linkage, m=m, omega_1=omega_1, epsilon_1=epsilon_1)
    nt = get_notation(notation)
    lay = ACCELERATION_PLAN_LAYOUT
    plans = pr.plans()
    last = len(plans) - (1 if getattr(pr, "phi", None) is None else 0)     # at given angles: no repeated last one
    k = _default_position(plans, pr.linkage) if position is None else _check_position(position, last)
    plan = plans[k]
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("acceleration.plan", k=str(k)),
                  problem=pr.problem if problem is None else problem, title_block=title_block)
    x0, _y0, x1, _y1 = sheet.box
    eqs = _equations(plan, pr.linkage, nt)
    eps = _eps_texts(plan, pr.linkage, nt)
    comps = plan.components
    one_line = (nt.word("kinematics.vector"), nt.word("kinematics.length"),
                nt.quantity(nt.word("acceleration.value"), "m/s²"))
    phi = (f"φ = {nt.number(math.degrees(plan.phi_from_start), sig=5)}° ({nt.word('kinematics.phi_from')}),  "
           f"{pr.speed_text(nt)}")
    arr = np.array([[zz.real, zz.imag] for zz in plan.images.values()])
    best: AL.Arrangement | None = None
    head: tuple[tuple[str, ...], ...] = (one_line,)
    for heads in _table_heads(one_line):     # the headings on one line, or each unit under its word when narrower
        probe = Table((0.0, 0.0), heads + tuple((image(c.start) + image(c.end), "000,00",     # the values as printed
                                                 f"{symbol(c.symbol)} = {K._num(nt, c.magnitude, 3)}") for c in comps),
                      size_mm=TABLE_MM, row_height_mm=lay.row_mm, header_rows=len(heads))
        parts = AL.Parts(sheet.box, sheet.top, sheet.caption_y - lay.caption_room_mm, probe.width_mm,
                         probe.height_mm, phi, eqs, eps, arr, slide=getattr(sheet.probe, "size", "") == "SLIDE")
        a = AL.arrange(parts, lay, lambda w: K._plan_split(sheet.box, w, lay))
        if a is not None and (best is None or a.need < best.need * (1 - 1e-9)):
            best, head = a, heads
    if best is None and page is None:                   # a triad's many equations: the A4 page upright
        return acceleration_plan(linkage, position, m=m, omega_1=omega_1, epsilon_1=epsilon_1, mu_a=mu_a,
                                 notation=notation, page=Page("A4", "portrait", frame=True), title=title,
                                 problem=problem, title_block=title_block, name=name)
    if best is None:
        raise InputError("the plan and its equations do not fit on this page; give a larger page")
    area, split = best.area, best.split
    s_a, f = K._fit_plan(area, arr.min(axis=0), arr.max(axis=0), mu_a, symbol="μ_a", unit="m/s²", k=k, nt=nt, lay=lay)
    pts = {lb: f.pt(zz.real, zz.imag) for lb, zz in plan.images.items()}
    occ = sheet.occ
    cons, cons_texts = _acceleration_lines(plan, pts, nt)
    occ.register(*cons)
    vecs = _component_vectors(pts, comps, prefix="", head_mm=lay.head_mm, width_mm=1.1)
    pole = Point(pts["π"], radius_mm=lay.pole_mm, name="pole")
    occ.register(*vecs, pole)
    hard = Occupancy(pad_mm=0.3)
    hard.register(*vecs)
    cons_labels = K._label_lines(occ, cons, cons_texts, hard=hard, area=area)
    leaders: list = []
    names = _place_labels(occ, pts, plan, size_mm=TEXT_MM + 0.3, within=(area[0], area[1] - 4, area[2], area[3] + 4),
                          hard=hard, leaders=leaders)
    # beside the plan: the table and ε; under the plan (or under ε): φ and the equations
    column = _acceleration_column(comps, pts, head, s_a, eps if best.eps_in_column else [],
                                  (split + lay.column_x_mm, sheet.top + lay.column_x_mm), (x1, best.column_bottom),
                                  nt, lay)
    text_els = _equation_texts(best.columns, best.origins, lay)
    scales = (s_a,)
    boxes = [b for b in (t.bbox() for t in cons_labels + names if isinstance(t, Text)) if b is not None]
    cons, leaders, cons_labels = (_broken_for_labels(x, boxes) for x in (cons, leaders, cons_labels))
    elements = [sheet.header()] + cons + vecs + [pole] + leaders + cons_labels + names + text_els + column
    elements += sheet.captions(scales, legend=nt.word("acceleration.legend"), reserve=True)
    return sheet.scene(elements, scales, name=name, notes=(s_a.note,) if s_a.note else ())


def acceleration_plan_grid(linkage, *, m: int | None = None, omega_1: float | None = None, epsilon_1: float = 0.0,
                           mu_a=None, columns: int | None = None, notation="en", page=None, title=None, problem=None,
                           title_block: bool = True, name: str = "acceleration-plans") -> Scene:
    """The acceleration plans of all positions 0…m−1 on one sheet, each in its cell, to one μ_a.

    Each cell: the pole π, the known components (solid), the components found and the absolute
    accelerations (dashed), the images labelled; a plan too large for its cell at the common scale
    is written as values.

    >>> from graphmethods.kinematics.presets import four_bar
    >>> s = acceleration_plan_grid(four_bar(l1=0.3, l2=0.1, l3=0.35, l4=0.25), omega_1=10.0, m=6)
    >>> s.scales()[0].symbol, s.element("plan-3-vector-pi-a").known
    ('μ_a', True)
    """
    pr = _Problem(linkage, m=m, omega_1=omega_1, epsilon_1=epsilon_1)
    nt = get_notation(notation)
    lay = K.PLAN_GRID_LAYOUT
    plans = pr.plans()[:-1]
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("acceleration.plans"),
                  problem=pr.problem if problem is None else problem, title_block=title_block)
    spans = []
    for p in plans:
        arr = np.array([[z.real, z.imag] for z in p.images.values()])
        spans.append((np.ptp(arr[:, 0]), np.ptp(arr[:, 1])))
    grid = K._plan_grid(sheet, np.array(spans), np.ones(len(spans), dtype=bool), columns, lay)
    s_a = _pick_mu_a(mu_a, grid.need, what="the largest plan in its cell", nt=nt)
    occ = sheet.occ
    cells: list = []
    drawn: list = []
    labels: list = []
    for k, p in enumerate(plans):
        box, inner = grid.cell(k, lay)
        prefix = f"plan-{k}-"
        cells += K._grid_cell(box, nt.word("kinematics.position") + f" {k}", prefix, CELL, occ, lay)
        arr = np.array([[z.real, z.imag] for z in p.images.values()])
        f = K._centred_frame(inner, arr.min(axis=0), arr.max(axis=0), s_a)
        pts = {lb: f.pt(z.real, z.imag) for lb, z in p.images.items()}
        vecs = _component_vectors(pts, p.components, prefix=prefix, head_mm=2.2, width_mm=0.8)
        pole = Point(pts["π"], radius_mm=lay.pole_mm, name=f"{prefix}pole")
        occ.register(*vecs, pole)
        drawn += vecs + [pole]
        main = {lb: at for lb, at in pts.items() if lb in p.labels.values()}
        labels += _place_labels(occ, main, p, size_mm=SMALL_MM + 0.2, within=box, prefix=prefix, leaders=labels)
    legend = f"{pr.speed_text(nt)};  {nt.word('acceleration.legend')}"
    elements = [sheet.header()] + cells + drawn + labels + sheet.captions((s_a,), legend=legend, reserve=True)
    return sheet.scene(elements, (s_a,), name=name, notes=(s_a.note,) if s_a.note else ())


def acceleration_rows(linkage, *, m: int | None = None, omega_1: float | None = None,
                      epsilon_1: float = 0.0) -> tuple[tuple[str, ...], tuple[tuple[float, ...], ...]]:
    """The accelerations per position: column symbols (markup) and rows of values.

    Columns: the position, φ from position 0 (°), |a| of every moving point (m/s²; a slider on a
    guide of the frame signed along +x of its guide) and ε of every moving link (rad/s²,
    counterclockwise +).

    >>> from graphmethods.kinematics.presets import slider_crank
    >>> cols, rows = acceleration_rows(slider_crank(r=0.1, l=0.4), omega_1=10.0)
    >>> cols[:4], rows[0][3]
    (('k', 'φ', 'a_{A}', 'a_{B}'), -12.5)
    """
    pr = _Problem(linkage, m=m, omega_1=omega_1, epsilon_1=epsilon_1)
    plans = pr.plans()[:-1]
    lk = pr.linkage
    guides = lk.guides
    pts = [p for p in plans[0].labels if p not in lk.ground]
    links = [link for link in lk.links if link != lk.crank.link and any(abs(pl.epsilon.get(link, 0.0)) > 0
                                                                        for pl in plans)]
    cols = ("k", "φ") + tuple(symbol(f"a_{p}") for p in pts) + tuple(f"ε_{{{link}}}" for link in links)
    rows = []
    for k, p in enumerate(plans):
        vals: list[float] = [float(k), math.degrees(p.phi_from_start)]
        for q in pts:
            a = p.a(q)
            if q in guides:
                gx, gy = guides[q]
                vals.append(a.real * gx + a.imag * gy)
            else:
                vals.append(abs(a))
        vals += [p.epsilon[link] for link in links]
        rows.append(tuple(vals))
    return cols, tuple(rows)


def acceleration_table(linkage, *, m: int | None = None, omega_1: float | None = None, epsilon_1: float = 0.0,
                       notation="en", page=None, title=None, problem=None, title_block: bool = True,
                       name: str = "acceleration-table") -> Scene:
    """The accelerations per position as a drawn table (see :func:`acceleration_rows`).

    >>> from graphmethods.kinematics.presets import slider_crank
    >>> s = acceleration_table(slider_crank(r=0.1, l=0.4), omega_1=10.0, notation="zh")
    >>> s.title
    '各位置的加速度'
    """
    pr = _Problem(linkage, m=m, omega_1=omega_1, epsilon_1=epsilon_1)
    nt = get_notation(notation)
    cols, rows = acceleration_rows(linkage, m=m, omega_1=omega_1, epsilon_1=epsilon_1)
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("acceleration.table"), problem=pr.problem if problem is None
                  else problem, title_block=title_block, has_scales=False)
    x0, _y0, x1, _y1 = sheet.box
    head = [nt.word("kinematics.position"), nt.quantity("φ", "°")]
    for c in cols[2:]:
        head.append(nt.quantity(c, "rad/s²" if c.startswith("ε") else "m/s²"))
    data = np.asarray(rows, dtype=float).reshape(len(rows), -1)
    # each column with one number of decimals, four digits of its largest value (as the table of velocities)
    written = [nt.column(data[:, j], sig=4, reference=float(np.abs(data[:, j]).max())) for j in range(1, data.shape[1])]
    body = [(str(int(r[0])), *(col[i] for col in written)) for i, r in enumerate(rows)]
    rows_all = (tuple(head),) + tuple(body)
    note = f"{pr.speed_text(nt)};  {nt.word('acceleration.signed')}"
    lines = [note] if markup.text_width_mm(note, TEXT_MM) <= x1 - x0 else note.split(";  ")    # narrow: two lines
    avail = (sheet.caption_y - 4.0 - 6.0 * len(lines)) - (sheet.top + 2.0)
    row_h, size, fits = table_rows(avail, len(rows_all), most=6.0)
    if not fits:
        raise InputError(f"{len(body)} positions do not fit on this sheet (rows would be {row_h:.1f} mm); "
                         f"give fewer positions or a larger page")
    table = Table((x0, sheet.top + 2.0), rows_all, size_mm=size, row_height_mm=row_h, align="c" * len(head),
                  name="table")
    while table.top_right[0] > x1 and size > 2.0:
        size -= 0.2
        table = Table((x0, sheet.top + 2.0), rows_all, size_mm=size, row_height_mm=row_h, align="c" * len(head),
                      name="table")
    if table.top_right[0] > x1:
        raise InputError(f"the table is {table.width_mm:.0f} mm wide but the sheet leaves {x1 - x0:.0f} mm; "
                         f"give a larger page")
    notes = [Text((x0, table.bottom_left[1] + 6.0 * (i + 1)), t, size_mm=TEXT_MM, name="note" + (f"-{i}" if i else ""))
             for i, t in enumerate(lines)]
    return sheet.scene([sheet.header(), table, *notes], (), name=name)
