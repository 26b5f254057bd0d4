"""The worksheet kind ``acceleration-plan``: a linkage (a slider-crank, or a crank with an oscillating slotted
lever) in one position, its velocities given → the acceleration plan at a stated μ_a, the length of each
vector in mm and the ε of each link.

A variant's student page has the statement, the data and the given velocities (ω of each link, and the
sliding speed v_rel where a block slides on a turning lever), the scheme drawn at μ_l in that position,
graph paper with the pole π, and answer boxes; its key has the exact plan drawn at μ_a
(:func:`graphmethods.sheets.check.acceleration.plan_elements`) and every answer filled in.
``graphmethods check`` reads the answers (the keys of :func:`answer_keys`, see
:mod:`graphmethods.sheets.check.acceleration`).

>>> from graphmethods.sheets import worksheets as ws
>>> v = ws.variant("acceleration-plan", seed=3, number=1)
>>> v.id, v.mechanism, sorted(k for k in v.answers() if k.startswith("epsilon"))[:1]
('acceleration-plan:3:1', 'slotted-lever', ['epsilon_3'])
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any, ClassVar

import numpy as np

from graphmethods.errors import InputError
from graphmethods.kinematics.acceleration_plan import AccelerationPlan
from graphmethods.kinematics.linkage import Linkage
from graphmethods.scene import Scale, Scene, Text
from graphmethods.scene.elements import Element, Line, Point, label_bbox
from graphmethods.scene.primitives import THIN, Label, Polygon
from graphmethods.sheets.check import acceleration as ca
from graphmethods.sheets.worksheets.classset import register
from graphmethods.sheets.worksheets.elements import TEXT_MM, THICK, X0, X1, Grid, Shapes, arc, ground, pin, slider
from graphmethods.sheets.worksheets.pages import CAPTION_ROOM, Sheet, answers_and_solution
from graphmethods.sheets.worksheets.texts import value_unit
from graphmethods.sheets.worksheets.variants import Variant, pick, pick_scale
from graphmethods.titles import Title

MECHANISMS = ("slider-crank", "slotted-lever")

TITLE = Title.of({"en": "Acceleration plan of a linkage", "ru": "План ускорений механизма", "zh": "机构的加速度多边形"})

STATEMENT = (
    ("The {mech} is drawn at {mu_l} in position {k} (crank angle φ = {phi} from the x axis): {sizes}. The crank "
     "turns counterclockwise at ω_{{1}} = {omega_1}, ε_{{1}} = {epsilon_1}. Its velocities in this position are "
     "given in the second table.",
     "1) Draw the acceleration plan from the pole π at {mu_a}, group by group: the normal components ω²l toward "
     "the centres, the tangential ones ⊥ the links{coriolis}; the centres of mass by similarity.",
     "2) Measure every vector in mm and find ε of each link with its sense."),
    ("{mech} вычерчен в масштабе {mu_l} в положении {k} (угол кривошипа φ = {phi} от оси x): {sizes}. Кривошип "
     "вращается против часовой стрелки с ω_{{1}} = {omega_1}, ε_{{1}} = {epsilon_1}. Скорости в этом положении "
     "даны во второй таблице.",
     "1) Постройте план ускорений от полюса π в масштабе {mu_a} по группам: нормальные ускорения ω²l к центрам, "
     "касательные ⊥ звеньям{coriolis}; центры масс по подобию.",
     "2) Измерьте все векторы в мм и найдите ε каждого звена с направлением."),
    ("{mech}按 {mu_l} 画在位置 {k}（曲柄与 x 轴夹角 φ = {phi}）：{sizes}。曲柄逆时针转动，ω_{{1}} = {omega_1}，"
     "ε_{{1}} = {epsilon_1}。此位置的速度见第二个表。",
     "1) 以 {mu_a} 从极点 π 按杆组作加速度多边形：法向分量 ω²l 指向中心，切向分量 ⊥ 杆{coriolis}；质心按相似原理。",
     "2) 量出各矢量的长度（mm），求各杆的 ε 及其转向。"),
)


@dataclass(frozen=True)
class AccelerationPlanVariant(Variant):
    """A linkage in position ``position`` of 12 (numbered from the extreme position of the working stroke).

    ``mechanism`` ``"slider-crank"``: crank ``r``, rod ``l``, offset ``d``, S2 at ``l_S`` from A;
    ``"slotted-lever"``: crank ``r``, lever O3B = ``l``, O1O3 = ``d`` (O3 below O1), S3 at ``l_S`` from O3.
    Lengths in m, ω_1 rad/s, ε_1 rad/s², ``mu_l`` m/mm, ``mu_a`` (m/s²)/mm.

    >>> v = AccelerationPlanVariant(seed=0, number=1, mechanism="slider-crank", r=0.1, l=0.4, d=0.0, l_S=0.2,
    ...                             position=0, omega_1=10.0, epsilon_1=0.0, mu_l=0.004, mu_a=0.25)
    >>> round(v.answers()["a_B_mm"] * 0.25, 9)        # ω²r(1 + r/l) at the dead centre
    12.5
    """

    kind: ClassVar[str] = "acceleration-plan"
    seed: int
    number: int
    mechanism: str
    r: float
    l: float
    d: float
    l_S: float
    position: int
    omega_1: float
    epsilon_1: float
    mu_l: float
    mu_a: float

    def __post_init__(self) -> None:
        if self.mechanism not in MECHANISMS:
            raise InputError(f"mechanism {self.mechanism!r}: give one of {', '.join(MECHANISMS)}")

    @cached_property
    def linkage(self) -> Linkage:
        from graphmethods.kinematics.presets import slider_crank, slotted_lever

        if self.mechanism == "slider-crank":
            return slider_crank(r=self.r, l=self.l, e=self.d, points={"S2": ("AB", self.l_S)})
        return slotted_lever(r=self.r, l_O1O3=self.d, l_O3B=self.l, points={"S3": ("O3B", self.l_S)})

    @cached_property
    def plan(self) -> AccelerationPlan:
        return ca.build_plan(self.linkage, self.position, m=12, omega_1=self.omega_1, epsilon_1=self.epsilon_1)[0]

    def given(self) -> dict[str, float]:
        """The velocities the student is given: ω of each moving link but the crank (rad/s, ccw +), and the
        sliding speed |v_A3A2| (m/s) of a slotted lever."""
        out = {f"omega_{k}": float(w) for k, w in self.plan.omega.items() if k in self.plan.lengths
               and k != self.linkage.crank.link}
        k = next((c for c in self.plan.components if c.kind == "coriolis"), None)
        if k is not None:
            out["v_rel"] = k.factor
        return out

    def answers(self) -> dict[str, Any]:
        p = self.plan
        out: dict[str, Any] = {"mu_a": self.mu_a}
        for c in ca.vectors(p):
            out[f"{ca.key_of(c.symbol)}_mm"] = c.magnitude / self.mu_a
        for link in ca.turning_links(p, self.linkage.crank.link):
            out[f"epsilon_{link}"] = abs(p.epsilon[link])
            out[f"epsilon_{link}_sense"] = "ccw" if p.epsilon[link] > 0 else "cw"
        return out


def generate(rng: np.random.Generator) -> dict[str, Any]:
    """A variant's data with nice numbers, a plan whose every vector is at least 4 mm and whose construction
    lines cross at more than 20°."""
    for _ in range(200):
        mech = MECHANISMS[int(rng.integers(2))]
        r = pick(rng, (0.05, 0.06, 0.08, 0.1, 0.12))
        if mech == "slider-crank":
            l = round(r * pick(rng, (3, 3.5, 4, 5)), 3)
            d = pick(rng, (0.0, 0.0, round(r / 5, 3), round(r / 4, 3)))
            l_S = round(l * pick(rng, (0.3, 0.35, 0.4)), 3)
        else:
            d = round(r * pick(rng, (2, 2.5, 3)), 3)
            l = round((d + r) * pick(rng, (1.2, 1.3, 1.5)), 2)
            l_S = round(l / 2, 3)
        k = int(pick(rng, (1, 2, 3, 4, 5, 7, 8, 9, 10, 11)))
        omega_1 = float(pick(rng, (8, 10, 12, 15, 16, 20)))
        eps_1 = float(pick(rng, (0.0, 0.0, 0.0, 20.0, 40.0, -30.0)))
        data: dict[str, Any] = {"mechanism": mech, "r": r, "l": l, "d": d, "l_S": l_S, "position": k,
                                "omega_1": omega_1, "epsilon_1": eps_1, "mu_l": 0.001, "mu_a": 1.0}
        try:
            v = AccelerationPlanVariant(seed=0, number=0, **data)
            plan = v.plan
        except InputError:
            continue
        if min(s.sin_between for s in plan.steps) < math.sin(math.radians(20.0)):
            continue
        mu_a = plan.mu_a(fit_mm=55.0)
        if min(c.magnitude for c in plan.components) / mu_a < 4.0:     # every component drawn, none vanishing
            continue
        z = [complex(p) for p in _scheme_xy(v).values()]
        span = max(max(p.real for p in z) - min(p.real for p in z),
                   2.7 * (max(p.imag for p in z) - min(p.imag for p in z)))
        data.update(mu_l=pick_scale(span, 150.0), mu_a=mu_a)
        try:                                   # the page must hold the scheme and the plan
            page(AccelerationPlanVariant(seed=0, number=0, **data), "en", False)
        except InputError:
            continue
        return data
    raise InputError("no acceleration-plan variant with a well-conditioned construction was found")  # pragma: no cover


# ----------------------------------------------------------------------------- the pages

def _scheme_xy(v: AccelerationPlanVariant) -> dict[str, complex]:
    """The joints of the variant's position, m (y up)."""
    mo = v.linkage.motion(m=12, omega_1=v.omega_1, level=1)
    return {k: complex(z[v.position]) for k, z in mo._state.z.items()}


def _scheme(v: AccelerationPlanVariant, origin: tuple[float, float], nt: Any) -> list[Element]:
    """The linkage in its position at μ_l, the fixed point O (O1) at ``origin``."""
    from graphmethods.sheets.layout import Occupancy

    z = _scheme_xy(v)
    ox, oy = origin
    c = z["O"] if "O" in z else z["O1"]

    def P(p: complex) -> tuple[float, float]:
        return (ox + (p - c).real / v.mu_l, oy - (p - c).imag / v.mu_l)

    els: list[Element] = []
    if v.mechanism == "slider-crank":
        O, A, B, S = "O", "A", "B", "S2"
        links = [(O, A), (A, B)]
        els += [slider(P(z[B]), guide_mm=34.0, name="scheme-slider")]
        fixed = [O]
    else:
        O, A, B, S = "O1", "A", "B", "S3"
        links = [(O, A), ("O3", B)]
        fixed = [O, "O3"]
    for a, b in links:
        els.append(Line(P(z[a]), P(z[b]), style=THICK, name=f"scheme-{a}{b}"))
    if v.mechanism == "slotted-lever":           # the block on the crank pin, along the lever
        u = (z["B"] - z["O3"]) / abs(z["B"] - z["O3"])
        n = 1j * u
        pa = z["A"]
        corners = [pa + (su * 5.0 * u + sn * 2.8 * n) * v.mu_l for su, sn in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        els.append(Shapes((Polygon(tuple(P(q) for q in corners), THIN.with_(width_mm=0.5, fill="#ffffff")),),
                             name="scheme-block"))
    for f in fixed:
        els.append(ground(P(z[f]), name=f"scheme-ground-{f}"))
    els.append(pin(P(z[A]), name="scheme-pin-A"))
    els.append(Point(P(z[S]), radius_mm=0.9, name=f"scheme-{S}"))
    els.append(arc(P(z[O]), 8.0, math.degrees(v.plan.phi) + 20.0, math.degrees(v.plan.phi) + 70.0, arrow=True,
                      name="scheme-omega"))
    occ = Occupancy()
    for e in els:
        occ.add_primitives(e.primitives())
    for name in [*fixed, A, B, S]:
        text = name[0] + (f"_{{{name[1:]}}}" if len(name) > 1 else "")
        lab = occ.place_label(P(z[name]), text, ("ne", "nw", "se", "sw", "n", "s", "e", "w"), size_mm=TEXT_MM,
                              gap_mm=2.2)
        occ.add_label(lab)
        els.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name=f"scheme-name-{name}"))
    # the crank's sense named at the head of its arc
    w = v.plan.phi + math.radians(70.0)
    tip = (P(z[O])[0] + 8.0 * math.cos(w), P(z[O])[1] - 8.0 * math.sin(w))
    lab = occ.place_label(tip, "ω_{1}", ("n", "nw", "ne", "w", "e", "sw", "se", "s"), size_mm=TEXT_MM, gap_mm=1.5)
    els.append(Text((lab.x, lab.y), "ω_{1}", size_mm=TEXT_MM, anchor=lab.anchor, name="scheme-omega-name"))
    return els


def _mu_l_caption(scheme: list[Element], text: str, top: float, bottom: float) -> Text:
    """The scheme's μ_l, at its top right, or its bottom right or left when the mechanism is there."""
    from graphmethods.sheets.layout import Occupancy

    occ = Occupancy(pad_mm=0.8)
    for e in scheme:
        occ.add_primitives(e.primitives())
    tries = ((X1, top + 2.0, "end"), (X1, bottom, "end"), (X0, bottom, "start"), (X1, bottom + 5.0, "end"))
    for x, y, anchor in tries:
        cand = Text((x, y), text, size_mm=TEXT_MM, anchor=anchor, name="caption-mu-l")
        if all(occ.is_free(label_bbox(p), within=None) for p in cand.primitives() if isinstance(p, Label)):
            return cand
    return cand


def _box(points: list[tuple[float, float]]) -> tuple[float, float, float, float]:
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return min(xs), min(ys), max(xs), max(ys)


def _answer_heads(v: AccelerationPlanVariant, nt: Any) -> tuple[list[str], list[str]]:
    a = v.answers()
    heads, vals = [], []
    for c in ca.vectors(v.plan):
        heads.append(nt.quantity(_symbol_markup(c.symbol), "mm"))
        vals.append(nt.number(a[f"{ca.key_of(c.symbol)}_mm"]))
    for link in ca.turning_links(v.plan, v.linkage.crank.link):
        heads.append(nt.quantity(f"ε_{{{link}}}", "rad/s²"))
        vals.append(f"{nt.number(a[f'epsilon_{link}'])} {nt.word('kinematics.' + a[f'epsilon_{link}_sense'])}")
    return heads, vals


def _symbol_markup(symbol: str) -> str:
    """``a^τ_BA`` → a^{τ}_{BA} (markup)."""
    head, _, sub = symbol.partition("_")
    if "^" in head:
        base, sup = head.split("^")
        return f"{base}^{{{sup}}}_{{{sub}}}"
    return f"{head}_{{{sub}}}"


def page(v: AccelerationPlanVariant, nt: Any, key: bool) -> Scene:
    """The student's page (``key`` false) or the answer key of a variant."""
    sh, nt = Sheet.begin(v, nt, key)
    s_l = Scale(nt.sym("worksheets.mu_l"), nt.unit("m"), v.mu_l)
    s_a = Scale("μ_a", nt.unit("(m/s²)"), v.mu_a)
    m = value_unit
    if v.mechanism == "slider-crank":
        sizes = (f"OA = {m(v.r, 'm', nt)}, AB = {m(v.l, 'm', nt)}, e = {m(v.d, 'm', nt)}, "
                 f"AS_{{2}} = {m(v.l_S, 'm', nt)}")
    else:
        sizes = (f"O_{{1}}A = {m(v.r, 'm', nt)}, O_{{1}}O_{{3}} = {m(v.d, 'm', nt)}, O_{{3}}B = {m(v.l, 'm', nt)}, "
                 f"O_{{3}}S_{{3}} = {m(v.l_S, 'm', nt)}")
    sh.statement({"mech": nt.word("worksheets.mech_" + v.mechanism.replace("-", "_")), "mu_l": s_l.caption(nt),
                  "k": str(v.position),
                  "phi": f"{nt.number(round(math.degrees(v.plan.phi) % 360.0, 2))}°", "sizes": sizes,
                  "omega_1": m(v.omega_1, "rad/s", nt), "epsilon_1": f"{nt.number(v.epsilon_1)} {nt.unit('rad/s²')}",
                  "mu_a": s_a.caption(nt),
                  "coriolis": nt.word("worksheets.coriolis") if v.mechanism == "slotted-lever" else ""})
    g = v.given()
    heads = [nt.quantity(f"ω_{{{k[6:]}}}", "rad/s") for k in g if k.startswith("omega_")]
    vals = [f"{nt.number(abs(w))} {nt.word('kinematics.ccw' if w > 0 else 'kinematics.cw')}"
            for k, w in g.items() if k.startswith("omega_")]
    if "v_rel" in g:
        heads.append(nt.quantity("v_{A3A2}", "m/s"))
        vals.append(nt.number(g["v_rel"]))
    sh.table((heads, vals), name="given", full=False)
    # the scheme
    z = _scheme_xy(v)
    c = z["O"] if "O" in z else z["O1"]
    pts = [((p - c).real / v.mu_l, -(p - c).imag / v.mu_l) for p in z.values()]
    x0, y0, _, y1 = _box(pts)
    top = sh.y + 4.0
    origin = (X0 + 12.0 - x0, top + 6.0 - y0)
    scheme = _scheme(v, origin, nt)
    caption = _mu_l_caption(scheme, s_l.caption(nt), top, origin[1] + y1 + 5.0)
    sh.add(*scheme, caption)
    sh.y = max(origin[1] + y1 + 10.0, caption.at[1] + 5.0)
    # the plan's box
    top, H = sh.drawing_box()
    imgs = [(z_.real / v.mu_a, -z_.imag / v.mu_a) for z_ in v.plan.images.values()]
    bx0, by0, bx1, by1 = _box(imgs)
    if bx1 - bx0 > X1 - X0 - 10.0 or by1 - by0 > H - 8.0:
        raise InputError(f"{v.id}: the acceleration plan at {v.mu_a} (m/s²)/mm does not fit its box "
                         f"({bx1 - bx0:.0f} × {by1 - by0:.0f} mm in {X1 - X0:.0f} × {H:.0f} mm)")
    pole = ((X0 + X1) / 2 - (bx0 + bx1) / 2, top + H / 2 - (by0 + by1) / 2)
    pole = (5.0 * round(pole[0] / 5.0), 5.0 * round(pole[1] / 5.0))
    sh.add(Grid((X0, top, X1, top + H), anchor=pole, name="grid"))
    if key:
        sh.add(*ca.plan_elements(pole, v.plan, mu_a=v.mu_a, nt=nt, name="key"))
    else:
        sh.add(Point(pole, label="π", label_dir="nw", size_mm=TEXT_MM, name="pole"))
    sh.caption([s_a.caption(nt)], y=top + H + 5.0)
    sh.y = top + H + CAPTION_ROOM
    heads, vals = _answer_heads(v, nt)
    eqs = [s.equation for s in v.plan.steps if s.method != "similarity"]
    from graphmethods.sheets.acceleration import symbol

    lines = [" ".join(symbol(t) if t.startswith(("a_", "a^")) else t for t in e.split()) for e in eqs]
    answers_and_solution(sh, heads, vals, lines)
    return sh.scene((s_l, s_a))


# registered with the other kinds (graphmethods.sheets.worksheets imports this module at its end)
register("acceleration-plan", AccelerationPlanVariant, generate, page, TITLE, STATEMENT)
