"""Checking an acceleration plan: the lengths (and, from a drawing, the directions) of its vectors, μ_a and
the ε of each link, against the exact plan at the student's μ_a, with the usual mistakes named.

The answers file's section ``[acceleration_plan]`` names each vector by its symbol with the marks
``^n``, ``^τ``, ``^k``, ``^r`` flattened to ``n``, ``t``, ``k``, ``r`` (:func:`key_of`)::

    [acceleration_plan]
    position = 2                  # a built-in problem: the position drawn (0…12)
    mu_a = 0.1                    # (m/s²)/mm
    a_A_mm = 98.7                 # πa
    an_BA_mm = 4.1                # a^n_BA, from a toward the centre A
    at_BA_mm = 60.2               # a^τ_BA
    a_B_mm = 47.0
    epsilon_2 = 51.0              # rad/s², magnitude
    epsilon_2_sense = "ccw"

(``ak_A3A2_mm`` is the Coriolis component, ``ar_A3A2_mm`` the relative one; ``…_deg`` a direction
measured from +x counterclockwise, as :mod:`graphmethods.sheets.check.cad` reads it off a drawing.)

Each usual mistake is a hypothesis: the plan is built again with that mistake made (the normal
component of a link drawn away from its centre; the Coriolis term reversed, forgotten or without its
factor 2; ω²·l with another length of the link; the crank's a^τ forgotten when ε₁ ≠ 0). An item
that is off the exact plan but on a mistaken one is ``wrong`` with the mistake named the first time
the mistake shows, and ``carried`` after that (the rest of the construction built on it). Tolerances:
±0.5 mm a length, ±0.5° + atan(0.5 mm / length) a direction, ε: 0.5 mm·μ_a/l + 0.1 %.

>>> from graphmethods.sheets.check import check
>>> from graphmethods.sheets import worksheets as ws
>>> v = ws.variant("acceleration-plan", seed=1, number=2)
>>> good = {k: round(x, 2) for k, x in v.answers().items() if k.endswith("_mm")}
>>> rep = check(v.id, {"acceleration_plan": {"mu_a": v.mu_a, **good}})
>>> rep.ok, len(rep.items) == len(good) + 1
(True, True)
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.kinematics.acceleration_plan import AccelerationPlan, Component, _Builder
from graphmethods.kinematics.linkage import Linkage
from graphmethods.scene import markup, notation as get_notation
from graphmethods.scene.elements import Element, Line, Text, Vector
from graphmethods.scene.primitives import Style
from graphmethods.sheets.check.tolerances import TOL_DEG, TOL_MM, TOL_REL
from graphmethods.sheets.worksheets.elements import RED, SMALL_MM, ColorText

_KEY = re.compile(r"^(a|an|at|ak|ar)_([A-Za-z0-9]+)_(mm|deg)$")
_EPS = re.compile(r"^epsilon_([A-Za-z0-9]+)(_sense)?$")
_MARKS = {"^n": "n", "^τ": "t", "^k": "k", "^r": "r"}

#: the usual mistakes of an acceleration plan: code -> what the student did
MISTAKES = {
    "normal_reversed": "a normal component a^n = ω²·l drawn away from the centre (it points from the point to the "
                       "centre of its link)",
    "coriolis_reversed": "the Coriolis component's sense reversed (v_rel turned the wrong way)",
    "coriolis_forgotten": "the Coriolis component 2ω·v_rel forgotten",
    "coriolis_factor_2": "the factor 2 missing in a^k = 2ω·v_rel",
    "normal_wrong_length": "ω²·l with the wrong link length",
    "crank_tangential_forgotten": "the crank's a^τ = ε₁·l_OA forgotten (ε₁ ≠ 0)",
}
#: the same, short, for the overlay (en, ru, zh)


class SectionKeys(tuple):
    """The keys of ``[acceleration_plan]``: the fixed ones, and any ``a…_X_mm``, ``a…_X_deg``, ``epsilon_L``,
    ``epsilon_L_sense`` (they depend on the linkage)."""

    def __contains__(self, key: object) -> bool:
        return isinstance(key, str) and (tuple.__contains__(self, key) or bool(_KEY.match(key))
                                         or bool(_EPS.match(key)))


SECTION_KEYS = SectionKeys(("mu_a", "position", "positions", "origin_mm", "a_X_mm", "an_XY_mm", "at_XY_mm",
                            "ak_XY_mm", "ar_XY_mm", "…_deg", "epsilon_L", "epsilon_L_sense"))


def key_of(symbol: str) -> str:
    """The answers key of a plan vector's symbol (without the ``_mm``).

    >>> key_of("a^τ_BA"), key_of("a^k_A3A2"), key_of("a_B")
    ('at_BA', 'ak_A3A2', 'a_B')
    """
    for mark, flat in _MARKS.items():
        symbol = symbol.replace(mark, flat)
    return symbol


def vectors(plan: AccelerationPlan) -> list[Component]:
    """The plan's vectors a student measures, in construction order, one per key (zero-length ones left out)."""
    out: dict[str, Component] = {}
    for c in plan.components:
        if c.magnitude > 1e-12:
            out.setdefault(key_of(c.symbol), c)
    return list(out.values())


def turning_links(plan: AccelerationPlan, crank_link: str) -> list[str]:
    """The links whose ε a student finds from a tangential component (not the crank's: ε₁ is given)."""
    return [k for k in plan.lengths if k != crank_link]


# ----------------------------------------------------------------------------- plans with a mistake made

class _Mistaken(_Builder):
    """The construction with one usual mistake made (see :data:`MISTAKES`)."""

    reversed_link: str = ""
    length_link: str = ""
    length: float = 0.0
    coriolis_factor: complex = 2j

    def normal(self, link: str, point: str, centre: str) -> complex:
        a = super().normal(link, point, centre)
        if link == self.reversed_link:
            return -a
        if link == self.length_link and abs(a) > 0:
            w = self.w[link]
            return w * w * self.length * a / abs(a)
        return a

    def coriolis(self, link: str, omega: float, v_rel: complex) -> complex:
        return self.coriolis_factor * omega * v_rel


def build_plan(linkage: Linkage, position: int, *, m: int, omega_1: float, epsilon_1: float,
               **mistake: Any) -> tuple[AccelerationPlan, _Builder]:
    """The plan of ``position`` of 0…m, with a mistake (attributes of the mistaken construction) made.

    >>> from graphmethods.kinematics.presets import slider_crank
    >>> from graphmethods.kinematics.acceleration_plan import acceleration_plan
    >>> lk = slider_crank(r=0.1, l=0.4)
    >>> p, _ = build_plan(lk, 2, m=12, omega_1=10.0, epsilon_1=0.0)
    >>> abs(p.a("B") - acceleration_plan(lk, 2, omega_1=10.0).a("B")) < 1e-12
    True
    """
    mo = linkage.motion(m=m, omega_1=omega_1, epsilon_1=epsilon_1, level=1)
    b = _Mistaken(linkage, mo._state, position)
    for k, v in mistake.items():
        setattr(b, k, v)
    b.eps_1 = float(epsilon_1)
    b.where = str(position)
    b.build()
    plan = AccelerationPlan(phi=float(mo.phi[position]), phi_from_start=float(mo.phi_from_start[position]),
                            position=position, omega_1=float(omega_1), epsilon_1=float(epsilon_1),
                            images=dict(b.images), labels=dict(b.labels), steps=tuple(b.steps),
                            omega=dict(b.w), epsilon=dict(b.eps), lengths=dict(b.lengths))
    return plan, b


@dataclass(frozen=True)
class Problem:
    """An acceleration plan to check: the linkage, the position, the speeds, the stated μ_a (if any)."""

    linkage: Linkage
    position: int
    m: int
    omega_1: float
    epsilon_1: float
    mu_a: float | None = None

    def plan(self, **mistake: Any) -> AccelerationPlan:
        return build_plan(self.linkage, self.position, m=self.m, omega_1=self.omega_1, epsilon_1=self.epsilon_1,
                          **mistake)[0]

    def hypotheses(self) -> list[tuple[str, AccelerationPlan]]:
        """(code, plan with that mistake) for every usual mistake that changes something here."""
        plan, b = build_plan(self.linkage, self.position, m=self.m, omega_1=self.omega_1, epsilon_1=self.epsilon_1)
        out: list[tuple[str, AccelerationPlan]] = []
        tries: list[tuple[str, dict[str, Any]]] = []
        normals = [c for c in plan.components if c.kind == "normal"]
        for c in normals:
            tries.append(("normal_reversed", {"reversed_link": c.link}))
            lengths = sorted({round(abs(b.z[p] - b.z[q]), 9) for pts in b.on_link.values() for p in pts for q in pts
                              if p < q} | {round(x, 9) for x in plan.lengths.values()})
            for L in lengths:
                if L > 0 and abs(L - c.factor) > 0.01 * c.factor:
                    tries.append(("normal_wrong_length", {"length_link": c.link, "length": L}))
        if any(c.kind == "coriolis" and c.magnitude > 0 for c in plan.components):
            tries += [("coriolis_reversed", {"coriolis_factor": -2j}), ("coriolis_forgotten", {"coriolis_factor": 0j}),
                      ("coriolis_factor_2", {"coriolis_factor": 1j})]
        for code, kw in tries:
            try:
                out.append((code, self.plan(**kw)))
            except InputError:           # the mistaken construction lines are parallel: no such plan
                continue
        if self.epsilon_1 != 0.0:
            out.append(("crank_tangential_forgotten", build_plan(self.linkage, self.position, m=self.m,
                                                                 omega_1=self.omega_1, epsilon_1=0.0)[0]))
        return out


def problem_of(ck: Any, data: Any) -> Problem:
    """The acceleration plan a problem asks for (a worksheet variant, or a built-in linkage at a position)."""
    v = getattr(data, "accel_variant", None)
    if v is not None:
        if ck.get("acceleration_plan", "position") not in (None, v.position):
            ck.notes.append("acceleration_plan.position ignored: this problem has one position")
        return Problem(v.linkage, v.position, 12, v.omega_1, v.epsilon_1, v.mu_a)
    case = getattr(data, "case", None)
    if case is None:
        raise InputError(f"[acceleration_plan]: {data.id} has no linkage to draw an acceleration plan of")
    from graphmethods.sheets.acceleration import _Problem

    m = int(ck.get("acceleration_plan", "positions", 12))
    k = ck.get("acceleration_plan", "position")
    if k is None or isinstance(k, (str, tuple)) or not float(k).is_integer() or not 0 <= k <= m:
        raise InputError(f"[acceleration_plan] position must be the position number 0…{m} the plan was drawn for")
    pr = _Problem(case, m=m, omega_1=None, epsilon_1=0.0)
    return Problem(pr.linkage, int(k), m, pr.omega_1, 0.0)


# ----------------------------------------------------------------------------- the check

def _angle(z: complex) -> float:
    return math.degrees(math.atan2(z.imag, z.real))


def _dev_deg(a: float, b: float) -> float:
    return (a - b + 180.0) % 360.0 - 180.0


def check_acceleration(ck: Any, data: Any) -> None:
    """Judge every answered item of ``[acceleration_plan]`` (see the module docstring); items go to ``ck``."""
    pr = problem_of(ck, data)
    sec = ck.a.get("acceleration_plan", {})
    mu_a = ck.need("acceleration_plan", "mu_a", "(m/s²) per mm of the acceleration plan")
    plan = pr.plan()
    hyps = pr.hypotheses()
    comps = vectors(plan)
    eps_links = turning_links(plan, pr.linkage.crank.link)
    _refuse_unknown_keys(sec, {key_of(c.symbol) for c in comps}, eps_links)
    judge = _Judge(ck)
    if pr.mu_a is not None:
        judge("mu_a", "μ_a", "(m/s²)/mm", pr.mu_a, mu_a, TOL_REL * pr.mu_a, (), note="the scale stated, 0.1 %")
    student_mm = _judge_vectors(judge, sec, comps, hyps, mu_a)
    _judge_epsilon(ck, judge, sec, plan, comps, hyps, eps_links, mu_a=mu_a, student_mm=student_mm)


def _refuse_unknown_keys(sec: Mapping[str, Any], keys: set[str], eps_links: list[str]) -> None:
    """An answered vector the plan does not have, or an ε of a link that does not turn, is refused."""
    for k in sec:
        m = _KEY.match(k)
        if m and f"{m.group(1)}_{m.group(2)}" not in keys:
            raise InputError(f"[acceleration_plan] {k}: this plan has no such vector; its vectors are "
                             f"{', '.join(sorted(x + '_mm' for x in keys))}")
        e = _EPS.match(k)
        if e and e.group(1) not in eps_links:
            raise InputError(f"[acceleration_plan] {k}: ε is found for link{'s' if len(eps_links) > 1 else ''} "
                             f"{', '.join(eps_links)} (epsilon_{eps_links[0] if eps_links else 'L'})")


class _Judge:
    """Judges one item against the exact plan and the mistaken ones: a mistake is named the first time it
    shows (``wrong``), and the items after it that follow from it are ``carried``."""

    def __init__(self, ck: Any) -> None:
        self.ck = ck
        self.charged: dict[str, str] = {}          # mistake code -> the item where it was named

    def __call__(self, key: str, label: str, unit: str, expected: float, student: float, tol: float,
                 hyp_values: Iterable[tuple[str, float | None]], *, own: float | None = None, own_from: str = "",
                 note: str = "", angle: bool = False) -> None:
        from graphmethods.sheets.check.report import Item

        dev = _dev_deg(student, expected) if angle else student - expected
        codes: list[str] = []
        verdict, why = "ok", note
        if abs(dev) > tol:
            for code, h in hyp_values:
                if h is None or not math.isfinite(h):
                    continue
                d = _dev_deg(student, h) if angle else student - h
                if abs(d) <= tol and code not in codes:
                    codes.append(code)
            before = [c for c in codes if c in self.charged]
            if before:
                verdict, codes = "carried", []
                why = f"follows from the earlier mistake at {self.charged[before[0]]} ({before[0]})"
            elif own is not None and abs(student - own) <= tol and abs(own - expected) > tol:
                verdict, codes = "carried", []
                why = f"follows from {own_from}: expected {own:.4g} from those"
            else:
                verdict = "wrong"
                for c in codes:
                    self.charged.setdefault(c, label)
        self.ck.items.append(Item(f"acceleration_plan.{key}", label, unit, float(expected), float(student),
                                  float(dev), float(tol), verdict, tuple(codes), why))


def _judge_vectors(judge: _Judge, sec: Mapping[str, Any], comps: list[Component],
                   hyps: list[tuple[str, AccelerationPlan]], mu_a: float) -> dict[str, float]:
    """Each vector's length (±0.5 mm) and direction (±0.5° + the angle 0.5 mm subtends); the student's
    lengths in mm by key."""
    student_mm: dict[str, float] = {}
    for c in comps:
        k = key_of(c.symbol)
        hv = [(code, _find(h, c)) for code, h in hyps]
        L = sec.get(f"{k}_mm")
        if L is not None:
            L = float(L)
            student_mm[k] = L
            judge(f"{k}_mm", c.symbol, "mm", c.magnitude / mu_a, L, TOL_MM,
                  [(code, None if z is None else abs(z) / mu_a) for code, z in hv], note="±0.5 mm")
        A = sec.get(f"{k}_deg")
        if A is not None:
            Lmm = student_mm.get(k, c.magnitude / mu_a)
            tol = TOL_DEG + math.degrees(math.atan2(TOL_MM, max(Lmm, 1e-9)))
            judge(f"{k}_deg", f"direction of {c.symbol}", "°", round(_angle(c.vector), 3), float(A), tol,
                  [(code, None if z is None or abs(z) < 1e-12 else _angle(z)) for code, z in hv], angle=True,
                  note="±0.5° + atan(0.5 mm / length)")
    return student_mm


def _judge_epsilon(ck: Any, judge: _Judge, sec: Mapping[str, Any], plan: AccelerationPlan, comps: list[Component],
                   hyps: list[tuple[str, AccelerationPlan]], eps_links: list[str], *, mu_a: float,
                   student_mm: dict[str, float]) -> None:
    """ε of each turning link (0.5 mm × μ_a / l, + 0.1 %; carried from the student's own a^τ) and its sense."""
    for link in eps_links:
        val = sec.get(f"epsilon_{link}")
        l = plan.lengths[link]
        tau = next((c for c in comps if c.kind == "tangential" and c.link == link), None)
        if val is not None:
            exp = abs(plan.epsilon[link])
            tol = TOL_MM * mu_a / l + TOL_REL * exp
            own = None
            if tau is not None and key_of(tau.symbol) in student_mm:
                own = student_mm[key_of(tau.symbol)] * mu_a / l
            judge(f"epsilon_{link}", f"ε_{link}", "rad/s²", exp, float(val), tol,
                  [(code, abs(h.epsilon.get(link, math.nan))) for code, h in hyps], own=own,
                  own_from=f"the student's {tau.symbol if tau else 'a^τ'}", note="0.5 mm × μ_a / l, + 0.1 %")
        sense = sec.get(f"epsilon_{link}_sense")
        if sense is not None:
            exp_s = "ccw" if plan.epsilon[link] > 0 else "cw"
            ck.position(f"acceleration_plan.epsilon_{link}_sense", f"sense of ε_{link}", [exp_s],
                        str(sense).strip().lower())


def _find(plan: AccelerationPlan, c: Component) -> complex | None:
    for x in plan.components:
        if x.symbol == c.symbol:
            return x.vector
    return 0j if c.kind == "coriolis" else None


def _symbol_markup(symbol: str) -> str:
    """A vector's symbol as overlay markup, drawn as the plans draw it: ``a^τ_BA`` → ``a^{τ}_{BA}`` (τ raised,
    BA lowered; plain text aτBA)."""
    head, _, sub = symbol.partition("_")
    base, _, mark = head.partition("^")
    text = markup.literal(base) + (f"^{{{mark}}}" if mark else "")
    return f"{text}_{{{sub}}}" if sub else text


def item_label(key: str, words: Any) -> str:
    """The overlay's label (markup) of an ``acceleration_plan.…`` item; ``words(name, **fill)`` gives the
    check's words in the overlay's language."""
    name = key.split(".", 1)[1]
    if name == "mu_a":
        return "μ_{a}"
    e = _EPS.match(name)
    if e:
        eps = f"ε_{{{e.group(1)}}}"
        return words("sense_of", omega=eps) if e.group(2) else eps
    m = _KEY.match(name)
    if m is None:                                   # pragma: no cover - every key of the section is above
        return markup.literal(name)
    marks = {v: k for k, v in _MARKS.items()}
    sym = _symbol_markup(f"a{marks.get(m.group(1)[1:], '')}_{m.group(2)}")
    return words("direction_of", v=sym) if m.group(3) == "deg" else sym


# ----------------------------------------------------------------------------- drawing the plan

#: how far off (mm) a point's letter goes on a leader when no place beside the point is free: within the reach
#: in which the reader of a drawing made in CAD looks for it (:data:`graphmethods.sheets.check.cad.LABEL_REACH_MM`)
NAME_LEADER_MM = (4.0, 5.0, 6.5, 8.0)
#: the directions a leader tries (degrees, counterclockwise from +x): the diagonals first, then every 22.5°
LEADER_ANGLES = (135.0, 45.0, 225.0, 315.0, 90.0, 270.0, 180.0, 0.0, *(22.5 + 45.0 * k for k in range(8)))


def _image_name(occ: Any, P: Any, text: str, leader_mm: tuple[float, ...]) -> tuple[Any, Any]:
    """The letter of a point of the plan: beside it where free; else on a short leader (it was set across the
    construction's lines: n_BA on the crank worksheet's plan); else beside it as the first choice."""
    from graphmethods.sheets.layout import place_label

    size, gap = SMALL_MM + 0.3, 0.8
    directions = ("nw", "ne", "sw", "se", "n", "s", "w", "e")
    lab = occ.first_free(P, text, directions, (gap, gap + 2.0, gap + 4.5), size, None)
    if lab is not None:
        occ.add_label(lab)
        return lab, None
    for r in leader_mm:
        found = occ.try_leaders(P, text, r, LEADER_ANGLES, size_mm=size)
        if found is not None:
            return found
    lab = place_label(P, text, directions[0], gap_mm=gap, size_mm=size)
    occ.add_label(lab)
    return lab, None


def plan_elements(origin: tuple[float, float], plan: AccelerationPlan, *, mu_a: float,
                  wrong: Mapping[str, float] | None = None, carried: Iterable[str] = (), nt: Any = "en",
                  name: str = "acc", leader_mm: tuple[float, ...] = NAME_LEADER_MM) -> list[Element]:
    """The plan drawn from the pole ``origin`` (page mm, y down) at ``mu_a``: construction lines thin,
    known vectors solid, found ones dashed, every image labelled; ``wrong`` (key -> the student's mm)
    in red with the student's value beside it; ``carried`` (keys) in red without it. ``leader_mm``: how far
    off (mm) a point's letter may go on a leader where nothing beside the point is free (a page read back
    from CAD keeps it within the reader's reach; a film laid over the student's drawing may go further).

    >>> from graphmethods.kinematics.presets import slider_crank
    >>> from graphmethods.kinematics.acceleration_plan import acceleration_plan
    >>> p = acceleration_plan(slider_crank(r=0.1, l=0.4), 2, omega_1=10.0)
    >>> v = [e for e in plan_elements((100.0, 100.0), p, mu_a=0.5) if e.name == "acc-a_A"][0]
    >>> round(math.dist(v.start, v.end) * 0.5, 9)
    10.0
    """
    nt = get_notation(nt)
    from graphmethods.sheets.layout import Occupancy

    wrong = dict(wrong or {})
    red = set(wrong) | set(carried)
    ox, oy = origin
    pts = {lb: (ox + z.real / mu_a, oy - z.imag / mu_a) for lb, z in plan.images.items()}
    els: list[Element] = []
    thin = Style(stroke="#000000", width_mm=0.18)
    for s in plan.steps:
        X = np.asarray(pts[s.label])
        for ln in s.lines:
            P0 = np.asarray(pts[ln.through])
            d = np.array([ln.direction.real, -ln.direction.imag])
            d /= float(np.hypot(*d))
            t = float((X - P0) @ d)
            a, b = P0 + d * (min(0.0, t) - 10.0), P0 + d * (max(0.0, t) + 10.0)
            els.append(Line(tuple(a.tolist()), tuple(b.tolist()), style=thin,
                            name=f"{name}-line-{s.point}-{ln.through}"))
    seen: set[str] = set()
    for c in vectors(plan):
        k = key_of(c.symbol)
        if k in seen:
            continue
        seen.add(k)
        style = Style(stroke=RED, width_mm=0.45) if k in red else Style(width_mm=0.35)
        els.append(Vector(pts[c.start], pts[c.end], known=c.known, style=style, head_length_mm=2.6,
                          head_width_mm=1.0, name=f"{name}-{k}"))
    occ = Occupancy()
    for e in els:
        occ.add_primitives(e.primitives())
    occ.add_box((ox - 1.0, oy - 1.0, ox + 1.0, oy + 1.0))
    done: set[tuple[float, float]] = set()
    for lb, P in sorted(pts.items(), key=lambda kv: (kv[0] != "π", kv[0])):
        key = (round(P[0], 2), round(P[1], 2))
        if key in done:
            continue
        done.add(key)
        text = _image_markup(lb)
        lab, leader = _image_name(occ, P, text, leader_mm)
        if leader is not None:
            els.append(Line(leader[0], leader[1], style=thin, name=f"{name}-name-{lb}-leader"))
        els.append(Text((lab.x, lab.y), text, size_mm=SMALL_MM + 0.3, anchor=lab.anchor, name=f"{name}-name-{lb}"))
    for c in vectors(plan):
        k = key_of(c.symbol)
        if k in wrong:
            mid = ((pts[c.start][0] + pts[c.end][0]) / 2, (pts[c.start][1] + pts[c.end][1]) / 2)
            txt = f"{_symbol_markup(c.symbol)} = {nt.number(wrong[k])} {nt.unit('mm')}?"
            # the student's value beside the vector, or further off with a leader where the plan is dense
            lab, leader = occ.place_label_with_leader(mid, txt, ("e", "w", "ne", "nw", "se", "sw"), size_mm=SMALL_MM,
                                                      gap_mm=2.0)
            if leader is not None:
                els.append(Line(leader[0], leader[1], style=Style(stroke=RED, width_mm=0.18),
                                name=f"{name}-student-{k}-leader"))
            els.append(ColorText((lab.x, lab.y), txt, size_mm=SMALL_MM, anchor=lab.anchor,
                                    color=RED, name=f"{name}-student-{k}"))
    return els


def _image_markup(label: str) -> str:
    """An image label as markup: ``n_BA`` → n_{BA}, ``a3`` → a_{3}, ``s2`` → s_{2}."""
    if "_" in label:
        head, tail = label.split("_", 1)
        return f"{head}_{{{tail}}}"
    m = re.fullmatch(r"([a-zπ]+)(\d+)", label)
    return f"{m.group(1)}_{{{m.group(2)}}}" if m else label
