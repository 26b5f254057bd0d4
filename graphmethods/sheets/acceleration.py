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

import numpy as np

from graphmethods.errors import InputError
from graphmethods.kinematics.acceleration_plan import AccelerationPlan, Component, acceleration_plans
from graphmethods.scene import Frame, Line, Point, Scale, Scene, Table, Text, Vector, markup, notation as get_notation
from graphmethods.scene.primitives import DASHED, Style
from graphmethods.sheets import kinematics as K
from graphmethods.sheets.layout import TEXT_MM, Occupancy, Sheet
from graphmethods.units import convenient_at_least

SMALL_MM = K.SMALL_MM
TABLE_MM = K.TABLE_MM
LINE_STYLE = DASHED
CELL = Style(width_mm=0.18)

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
        mech = lk.mech
        self.linkage = mech.linkage          # every mechanism is a linkage of the core
        self.m = 12 if lk.m is None else lk.m
        self.omega_1, self.problem, self.n_rpm = lk.omega_1, lk.problem, lk.n_rpm

    def plans(self) -> tuple[AccelerationPlan, ...]:
        if isinstance(self.m, bool) or not isinstance(self.m, (int, np.integer)) or self.m < 3:
            raise InputError(f"the number of positions m must be an integer ≥ 3, got {self.m!r}")
        return acceleration_plans(self.linkage, m=int(self.m), omega_1=self.omega_1, epsilon_1=self.epsilon_1)

    def speed_text(self, nt) -> str:
        return nt.word("acceleration.speed", w=nt.number(self.omega_1, sig=4), e=nt.number(self.epsilon_1, sig=4))


def _pick_mu_a(mu_a, need: float, *, what: str, nt) -> Scale:
    unit = nt.unit("(m/s²)")
    if mu_a is None:
        per = convenient_at_least(need)
        return Scale("μ_a", unit, per, note=f"picked: {what} needs ≥ {need:.4g} (m/s²)/mm; chose {per:g}")
    per = mu_a.per_mm if isinstance(mu_a, Scale) else mu_a
    if isinstance(per, bool) or not isinstance(per, (int, float)) or not math.isfinite(per) or per <= 0:
        raise InputError(f"mu_a is the acceleration scale in (m/s²)/mm and must be > 0, got {mu_a!r}")
    s = Scale("μ_a", unit, float(per))
    if need > s.per_mm * (1 + 1e-9):
        raise InputError(f"{what} at μ_a = {s.per_mm:g} (m/s²)/mm does not fit: it needs at least {need:.4g} "
                         f"(m/s²)/mm; give a larger μ_a, a larger page, or none to have one picked")
    return s


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
        if s.method == "similarity" and len(s.on) == 2:
            x, y = s.on
            lx, ly = image(plan.labels[x]), image(plan.labels[y])
            eq = f"{lx}{image(s.label)}/{lx}{ly} = {K._sub(x + s.point)}/{K._sub(x + y)}"
        vals = []
        if s.method == "crank" and plan.epsilon_1 == 0.0:
            c = s.components[0]
            vals.append(f"{symbol(c.symbol)} = ω_{{1}}²·l_{{{cr.centre + cr.pin}}} = {num(plan.omega_1)}²·{num(cr.r)} = "
                        f"{num(c.magnitude)} {unit}")
        for c in s.components:
            if not c.known:
                continue
            rel = c.symbol.split("_", 1)[1]
            if c.kind == "normal":
                ends = (cr.centre + cr.pin) if s.method == "crank" else rel[len(s.point):] + s.point
                w = abs(plan.omega[c.link])
                vals.append(f"{symbol(c.symbol)} = ω_{{{c.link}}}²·l_{{{ends}}} = {num(w)}²·{num(c.factor)} = "
                            f"{num(c.magnitude)} {unit}")
            elif c.kind == "tangential":                 # the crank's own a^τ (ε₁ given)
                vals.append(f"{symbol(c.symbol)} = ε_{{{c.link}}}·l_{{{cr.centre + cr.pin}}} = "
                            f"{num(abs(plan.epsilon_1))}·{num(c.factor)} = {num(c.magnitude)} {unit}")
            elif c.kind == "coriolis":
                vals.append(f"{symbol(c.symbol)} = 2·ω_{{{c.link}}}·v_{{{rel}}} = 2·{num(abs(plan.omega[c.link]))}·"
                            f"{num(c.factor)} = {num(c.magnitude)} {unit}")
        out.append((eq, ";  ".join(vals)))
    return out


def _eps_texts(plan: AccelerationPlan, linkage, nt) -> list[tuple[str, str]]:
    """(link, text) of ε of every link found from a tangential component: formula, value and sense."""
    out: list[tuple[str, str]] = []
    unit = nt.unit("rad/s²")
    for s in plan.steps:
        for c in s.components:
            if c.kind != "tangential" or s.method == "crank" or any(c.link == o for o, _ in out):
                continue
            e = plan.epsilon[c.link]
            rel = c.symbol.split("_", 1)[1]
            out.append((c.link, (f"ε_{{{c.link}}} = {symbol(c.symbol)}/l_{{{rel[len(s.point):] + s.point}}} = "
                                f"{nt.number(c.magnitude, sig=4)}/{nt.number(c.factor, sig=4)} = "
                                f"{nt.number(abs(e), sig=4)} {unit}, {K._sense_word(nt, e)}")))
    return out


def _place_labels(occ: Occupancy, pts: dict, plan: AccelerationPlan, *, size_mm: float, within, hard=None,
                  leaders=None, prefix: str = "") -> list:
    """Labels of the images: coincident images share one label, each placed away from π."""
    groups: list[list] = []
    for label, at in pts.items():
        for g in groups:
            if math.dist(g[0][1], at) < 0.8:
                g.append((label, at))
                break
        else:
            groups.append([(label, at)])
    p = np.asarray(pts["π"])
    out = []
    for g in groups:
        at = np.asarray(g[0][1])
        text = ", ".join(image(lb) for lb, _ in g)
        if any(lb == "π" for lb, _ in g):
            ds = [np.asarray(q) - p for lb, q in pts.items() if lb != "π" and math.dist(q, p) > 0.8]
            ds = [d / np.hypot(*d) for d in ds]
            mm = -np.sum(ds, axis=0) if ds else np.array([-1.0, 1.0])
            prefer = math.degrees(math.atan2(-mm[1], mm[0])) if np.hypot(*mm) > 1e-9 else 225.0
        else:
            d = at - p
            prefer = math.degrees(math.atan2(-d[1], d[0]))
        out.append(K._place(occ, tuple(at), text, prefer, size_mm=size_mm, within=within, hard=hard,
                            name=f"{prefix}name-{_id(g[0][0])}", gaps=(0.8, 1.8, 3.0, 4.5), leaders=leaders))
    return out


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
    plans = pr.plans()
    k = _default_position(plans, pr.linkage) if position is None else _check_position(position, len(plans) - 1)
    plan = plans[k]
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("acceleration.plan", k=str(k)),
                  problem=pr.problem if problem is None else problem, title_block=title_block)
    x0, _y0, x1, _y1 = sheet.box
    eqs = _equations(plan, pr.linkage, nt)
    eps = _eps_texts(plan, pr.linkage, nt)
    comps = plan.components
    head = (nt.word("kinematics.vector"), nt.word("kinematics.length"),
            nt.quantity(nt.word("acceleration.value"), "m/s²"))
    probe = Table((0.0, 0.0), (head,) + tuple((image(c.start) + image(c.end), "000,00", f"{symbol(c.symbol)} = 000,000")
                                              for c in comps), size_mm=TABLE_MM, row_height_mm=6.0)
    phi = (f"φ = {nt.number(math.degrees(plan.phi_from_start), sig=5)}° ({nt.word('acceleration.phi_from')}),  "
           f"{pr.speed_text(nt)}")
    right_w = max([probe.width_mm] + [markup.text_width_mm(t, TEXT_MM) for _, t in eps] + [60.0])
    split = min(max(x1 - right_w - 6.0, x0 + 0.45 * (x1 - x0)), x0 + 0.66 * (x1 - x0))
    # the equations under the plan: one column, or two on a slide (a short page) when every line fits
    blocks = [[("equation-phi", phi, 0.0)]] + [[(f"equation-{j}", a, 0.0)] + ([(f"values-{j}", b, 6.0)] if b else [])
                                               for j, (a, b) in enumerate(eqs)]
    half = (x1 - x0) / 2 - 4.0
    two = getattr(sheet.probe, "size", "") == "SLIDE" and len(blocks) > 2
    if two:                                    # each known value on a line of its own
        blocks = [[("equation-phi", phi, 0.0)]] + [
            [(f"equation-{j}", a, 0.0)] + [(f"values-{j}" + (f"-{i}" if i else ""), t, 6.0)
                                           for i, t in enumerate(b.split(";  ") if b else [])]
            for j, (a, b) in enumerate(eqs)]
        two = all(markup.text_width_mm(t, TEXT_MM) + dx <= half for b_ in blocks for _, t, dx in b_)
        if not two:
            blocks = [[("equation-phi", phi, 0.0)]] + [
                [(f"equation-{j}", a, 0.0)] + ([(f"values-{j}", b, 6.0)] if b else []) for j, (a, b) in enumerate(eqs)]
    n_lines = sum(len(b_) for b_ in blocks)
    cut, count = len(blocks), 0
    if two:
        for i, b_ in enumerate(blocks):
            count += len(b_)
            if count >= n_lines / 2:
                cut = i + 1
                break
    columns = [blocks[:cut], blocks[cut:]] if two else [blocks]
    eq_h = max(sum(len(b_) for b_ in col) for col in columns) * 5.4 + 2.0
    right_bottom = sheet.top + 2.0 + probe.height_mm + 6.0 + 5.6 * len(eps)
    if two and sheet.caption_y - 7.0 - eq_h < right_bottom:          # the table would reach the equations
        blocks = [[("equation-phi", phi, 0.0)]] + [
            [(f"equation-{j}", a, 0.0)] + ([(f"values-{j}", b, 6.0)] if b else []) for j, (a, b) in enumerate(eqs)]
        columns = [blocks]
        eq_h = sum(len(b_) for b_ in blocks) * 5.4 + 2.0
    area = (x0, sheet.top - 2.0, split - 4.0, sheet.caption_y - 7.0 - eq_h)
    if area[3] - area[1] < 40.0:
        raise InputError("the plan and its equations do not fit on this page; give a larger page")
    arr = np.array([[zz.real, zz.imag] for zz in plan.images.values()])
    lo, hi = arr.min(axis=0), arr.max(axis=0)
    margin = 9.0
    aw, ah = area[2] - area[0] - 2 * margin, area[3] - area[1] - 2 * margin
    need = max(float(hi[0] - lo[0]) / aw, float(hi[1] - lo[1]) / ah)
    if need <= 0:
        raise InputError(f"position {k}: every acceleration is zero; there is no plan to draw")
    s_a = _pick_mu_a(mu_a, need, what=f"the plan of position {k}", nt=nt)
    mid = ((area[0] + area[2]) / 2, (area[1] + area[3]) / 2)
    f = Frame((mid[0] - s_a.to_mm(float(lo[0] + hi[0]) / 2), mid[1] + s_a.to_mm(float(lo[1] + hi[1]) / 2)), s_a, s_a)
    pts = {lb: f.pt(zz.real, zz.imag) for lb, zz in plan.images.items()}
    occ = sheet.occ
    cons, cons_meta = [], []
    for s in plan.steps:
        X = np.asarray(pts[s.label])
        for ln in s.lines:
            P0 = np.asarray(pts[ln.through])
            d = np.array([ln.direction.real, -ln.direction.imag])
            d /= float(np.hypot(*d))
            t = float((X - P0) @ d)
            a, b = P0 + d * (min(0.0, t) - 10.0), P0 + d * (max(0.0, t) + 10.0)
            cons.append(Line(tuple(a.tolist()), tuple(b.tolist()), style=LINE_STYLE,
                             name=f"line-{s.point}-{_id(ln.through)}"))
            cons_meta.append(ln)
    K._register(occ, *cons)
    vecs = []
    seen = set()
    for c in comps:
        if math.dist(pts[c.start], pts[c.end]) < 1e-9 or _elname(c) in seen:
            continue
        seen.add(_elname(c))
        vecs.append(Vector(pts[c.start], pts[c.end], known=c.known, head_length_mm=3.0, head_width_mm=1.1,
                           name=_elname(c)))
    pole = Point(pts["π"], radius_mm=0.7, name="pole")
    K._register(occ, *vecs, pole)
    hard = Occupancy(pad_mm=0.3)
    K._register(hard, *vecs)
    cons_labels = []
    for el, ln in zip(cons, cons_meta):
        d = np.asarray(el.end) - np.asarray(el.start)
        prefer = math.degrees(math.atan2(-d[1], d[0])) + 90.0
        guide = nt.word("kinematics.guide")
        text = ln.label.replace("⟂", "⊥").replace("guide", guide).replace("slot", guide)
        text = " ".join(K._sub(w) for w in text.split(" "))
        cons_labels.append(K._place(occ, el.end, text, prefer, size_mm=SMALL_MM, hard=hard,
                                    within=(area[0], area[1] - 4, area[2] + 4, area[3] + 4),
                                    name=f"label-{el.name}", gaps=(0.6, 1.6, 3.0)))
    leaders: list = []
    names = _place_labels(occ, pts, plan, size_mm=TEXT_MM + 0.3, within=(area[0], area[1] - 4, area[2], area[3] + 4),
                          hard=hard, leaders=leaders)
    # under the plan: φ and the equations; beside it: the table and ε
    ey = area[3] + 7.0
    text_els = []
    for c_, col in enumerate(columns):
        cx = x0 + c_ * (half + 8.0)
        row = 0
        for b_ in col:
            for nm, line, dx in b_:
                text_els.append(Text((cx + dx, ey + row * 5.4), line, size_mm=TEXT_MM, name=nm))
                row += 1
    tx, ty = split + 2.0, sheet.top + 2.0
    rows = [head]
    for c in comps:
        L = math.dist(pts[c.start], pts[c.end])
        rows.append((image(c.start) + image(c.end), K._num(nt, L, 2), f"{symbol(c.symbol)} = {K._num(nt, L * s_a.per_mm, 3)}"))
    table = Table((tx, ty), tuple(rows), align="crl", size_mm=TABLE_MM, row_height_mm=6.0, name="table")
    if table.top_right[0] > x1 + 1e-6 or table.bottom_left[1] > area[3] + eq_h:
        raise InputError("the table of vectors does not fit beside the plan; give a larger page")
    wy = table.bottom_left[1] + 6.0
    eps_els = [Text((tx, wy + i * 5.6), t, size_mm=TEXT_MM, name=f"epsilon-{link}") for i, (link, t) in enumerate(eps)]
    legend = nt.word("acceleration.legend")
    scales = (s_a,)
    elements = ([sheet.header()] + cons + vecs + [pole] + leaders + cons_labels + names + text_els + [table]
                + eps_els)
    elements += sheet.captions(scales, legend=legend, reserve=True)
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
    plans = pr.plans()[:-1]
    n = len(plans)
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("acceleration.plans"),
                  problem=pr.problem if problem is None else problem, title_block=title_block)
    x0, _y0, x1, _y1 = sheet.box
    area = (x0, sheet.top, x1, sheet.caption_y - 9.0)
    W, H = area[2] - area[0], area[3] - area[1]
    ext = []
    for p in plans:
        arr = np.array([[z.real, z.imag] for z in p.images.values()])
        ext.append((np.ptp(arr[:, 0]), np.ptp(arr[:, 1])))
    ext_a = np.array(ext)
    pad_x, head_mm, pad_y = 6.0, 6.0, 4.5

    def need_for(cols: int) -> tuple[float, float, float]:
        rows = math.ceil(n / cols)
        cw, ch = W / cols, H / rows
        iw, ih = cw - 2 * pad_x, ch - head_mm - 2 * pad_y
        if iw <= 5 or ih <= 5:
            return math.inf, cw, ch
        return float(max((ext_a[:, 0] / iw).max(), (ext_a[:, 1] / ih).max())), cw, ch

    if columns is None:
        columns = min((need_for(c)[0], c) for c in range(1, n + 1))[1]
    elif isinstance(columns, bool) or not isinstance(columns, int) or not 1 <= columns <= n:
        raise InputError(f"columns must be an integer from 1 to {n} (the number of plans), got {columns!r}")
    need, cw, ch = need_for(columns)
    if not math.isfinite(need) or need <= 0:
        raise InputError(f"{n} plans in {columns} columns do not fit on this sheet; give other columns or a larger page")
    s_a = _pick_mu_a(mu_a, need, what="the largest plan in its cell", nt=nt)
    occ = sheet.occ
    elements: list = [sheet.header()]
    cells: list = []
    drawn: list = []
    labels: list = []
    for k, p in enumerate(plans):
        r, c = divmod(k, columns)
        bx0, by0 = area[0] + c * cw, area[1] + r * ch
        box = (bx0 + 0.8, by0 + 0.8, bx0 + cw - 0.8, by0 + ch - 0.8)
        prefix = f"plan-{k}-"
        cells.append(K.Polyline(((box[0], box[1]), (box[2], box[1]), (box[2], box[3]), (box[0], box[3])),
                                style=CELL, closed=True, name=f"{prefix}cell"))
        ht = Text((box[0] + 1.8, box[1] + 1.5 + TEXT_MM * 0.76), nt.word("kinematics.position") + f" {k}", size_mm=TEXT_MM,
                  bold=True, name=f"{prefix}heading")
        cells.append(ht)
        occ.add_primitives(ht.primitives())
        inner = (box[0] + pad_x - 0.8, box[1] + head_mm + pad_y - 0.8, box[2] - pad_x + 0.8, box[3] - pad_y + 0.8)
        arr = np.array([[z.real, z.imag] for z in p.images.values()])
        lo, hi = arr.min(axis=0), arr.max(axis=0)
        mid = ((inner[0] + inner[2]) / 2, (inner[1] + inner[3]) / 2)
        f = Frame((mid[0] - s_a.to_mm(float(lo[0] + hi[0]) / 2), mid[1] + s_a.to_mm(float(lo[1] + hi[1]) / 2)), s_a, s_a)
        pts = {lb: f.pt(z.real, z.imag) for lb, z in p.images.items()}
        seen = set()
        vecs = []
        for comp in p.components:
            if math.dist(pts[comp.start], pts[comp.end]) < 1e-9 or _elname(comp) in seen:
                continue
            seen.add(_elname(comp))
            vecs.append(Vector(pts[comp.start], pts[comp.end], known=comp.known, head_length_mm=2.2,
                               head_width_mm=0.8, name=f"{prefix}{_elname(comp)}"))
        pole = Point(pts["π"], radius_mm=0.55, name=f"{prefix}pole")
        K._register(occ, *vecs, pole)
        drawn += vecs + [pole]
        main = {lb: at for lb, at in pts.items() if lb in p.labels.values()}
        labels += _place_labels(occ, main, p, size_mm=SMALL_MM + 0.2, within=box, prefix=prefix, leaders=labels)
    legend = f"{pr.speed_text(nt)};  {nt.word('acceleration.legend')}"
    elements += cells + drawn + labels + sheet.captions((s_a,), legend=legend, reserve=True)
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
    body = []
    for r in rows:
        body.append((str(int(r[0])), K._num(nt, r[1], 1)) + tuple(K._num(nt, v, 3) for v in r[2:]))
    rows_all = (tuple(head),) + tuple(body)
    avail = (sheet.caption_y - 10.0) - (sheet.top + 2.0)
    row_h = min(6.0, avail / len(rows_all))
    if row_h < 4.0:
        raise InputError(f"{len(body)} positions do not fit on this sheet (rows would be {row_h:.1f} mm); "
                         f"give fewer positions or a larger page")
    size = min(TABLE_MM, row_h * 0.55)
    table = Table((x0, sheet.top + 2.0), rows_all, size_mm=size, row_height_mm=row_h, align="c" * len(head),
                  name="table")
    while table.top_right[0] > x1 and size > 2.0:
        size -= 0.2
        table = Table((x0, sheet.top + 2.0), rows_all, size_mm=size, row_height_mm=row_h, align="c" * len(head),
                      name="table")
    if table.top_right[0] > x1:
        raise InputError(f"the table is {table.width_mm:.0f} mm wide but the sheet leaves {x1 - x0:.0f} mm; "
                         f"give a larger page")
    note = Text((x0, table.bottom_left[1] + 6.0), f"{pr.speed_text(nt)};  {nt.word('acceleration.signed')}",
                size_mm=TEXT_MM, name="note")
    return sheet.scene([sheet.header(), table, note], (), name=name)
