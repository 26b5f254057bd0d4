"""Checking a hand drawing: what a student measured and wrote, against the exact construction at the
student's own scales, with a diagnosis of the usual mistakes and an overlay to print on film.

The answers file (TOML) holds the student's scales and page, the lengths and areas they measured and
the values they wrote (see :data:`SCHEMA` and the examples in ``graphmethods/problems/data/answers``)::

    student = "A. Student"
    [page]
    size = "A4"
    orientation = "landscape"
    [energy_indicator]
    mu_E = 5.0                       # J/mm
    arrows_mm = [-10, 110, -20, 25, -100, 5, -10]
    [results]
    delta_W_max = 575.0              # J
    omega_max_at = "e"
    J_F = 43.69                      # kg·m²

Each item gets the expected value at the student's scales, the deviation and a verdict:

``ok``       within the tolerance;
``carried``  wrong, but it follows (within tolerance) from the student's own earlier wrong values:
             not a new mistake;
``wrong``    a new mistake; when the value fits one of the usual mistakes (:data:`MISTAKES`, each a
             hypothesis "recompute with this mistake": it is diagnosed when the student's value
             matches it within tolerance and the correct value does not), that mistake is named.

Tolerances (documented rules):

* a length measured on the drawing: ±0.5 mm (:data:`TOL_MM`);
* an area measured between curves: ±0.5 mm × the region's perimeter at the student's scales (the
  band half a millimetre wide along its boundary); when the region's shape is not known (areas
  given as data), the perimeter of the square of that area, 4√|f|;
* a value computed without drawing (ω_m, tan ψ, works from given areas): 0.1 % (:data:`TOL_REL`,
  four significant figures);
* a derived value: first-order worst case propagation of the tolerances of the measured values it
  comes from (e.g. ΔW_max: the sum of the work tolerances of the intervals between E_max and
  E_min; J_F = μ_T·kl/(ω_m²δ): μ_T·0.5 mm/(ω_m²δ)), plus 0.1 %;
* a position (where ω_max occurs): every point whose level is within the ΔW_max tolerance of the
  extreme (Wittenbauer: every vertex within 0.5 mm of the touching ray) is accepted.

>>> rep = check("W1", {"energy_indicator": {"mu_E": 5.0, "arrows_mm": [-10, 110, -20, 25, -100, 5, -10]},
...                    "results": {"delta_W_max": 575.0, "J_F": 0.4795}})
>>> [(i.key, i.verdict) for i in rep.items if i.verdict != "ok"], [m.code for m in rep.mistakes]
([('results.J_F', 'wrong')], ['n_as_omega'])
"""

from __future__ import annotations

import json
import math
import pathlib
import re
import sys
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.problems.reference_cases import title_of
from graphmethods.scene import Page, Scale, Scene, Text, in_language, notation as get_notation
from graphmethods.scene.elements import Element, Line
from graphmethods.scene.primitives import Circle, Path, Style
from graphmethods.sheets import check_acceleration as ca, worksheets as ws
from graphmethods.titles import Title
from graphmethods.units import MAX_POSITIONS, count, json_text, omega_from_n, read_text, real

if TYPE_CHECKING:
    from graphmethods.dynamics.excess_work import ExcessWork
    from graphmethods.kinematics.case import Case

TOL_MM = 0.5
TOL_REL = 1e-3
PROBLEM_IDS = ("W1", "W2", "W3", "W4", "W4-drawing", "W4-exact", "press", "slotted-lever")

#: the usual mistakes: code -> what the student did
MISTAKES = {
    "sign_flipped": "a sign flipped in the staircase (a gain taken as a loss, or back)",
    "degrees_as_radians": "degrees used as radians",
    "n_as_omega": "n (rev/min) used as ω (rad/s)",
    "scale_forgotten": "the scale factor forgotten (μ_M·μ_φ, μ_v, μ_T …)",
    "scale_twice": "the scale factor applied twice",
    "J_e_not_subtracted": "J_e not subtracted",
    "delta_not_halved": "ω_max, ω_min = ω_m(1 ± δ) used instead of ω_m(1 ± δ/2) (in tan ψ: (1 ± δ)² for (1 ± δ/2)²)",
    **ca.MISTAKES,                        # those of an acceleration plan
}

# ----------------------------------------------------------------------------- words (en, ru, zh)
#: what the overlay writes, (en, ru, zh), as markup; ``{placeholders}`` are filled by :func:`_w`. The
#: keys of :data:`MISTAKES` name the mistakes (short, for the list of wrong items); the text, Markdown
#: and JSON reports stay English.
WORDS = {
    "overlay":        ("Overlay", "Накладка для проверки", "叠加校核图"),
    "heading":        ("{overlay}: {rest}", "{overlay}: {rest}", "{overlay}：{rest}"),
    "howto":          ("print at 100 % (no scaling) on transparent film; check: the bar below is {bar}",
                       "печатать на прозрачной плёнке в масштабе 100 % (без подгонки по размеру); "
                       "проверка: отрезок внизу равен {bar}",
                       "按 100 % 比例（不缩放）打印在透明胶片上；检查：下方线段长 {bar}"),
    # one wrong item; {unit} is empty for a position (the double space it leaves is closed up)
    "item":           ("{label}: {student} (expected {expected}) {unit} — {why}",
                       "{label}: {student} (должно быть {expected}) {unit} — {why}",
                       "{label}：{student}（应为 {expected}）{unit}——{why}"),
    "or":             ("{a} or {b}", "{a} или {b}", "{a} 或 {b}"),
    "carried":        ("carried over", "следствие предыдущей ошибки", "由前面的错误导致"),
    "wrong":          ("wrong", "неверно", "错误"),
    # the items (from Item.key): {i} an interval such as c–d, {omega} a speed such as ω_{max}
    "area":           ("area {i}", "площадь {i}", "面积 {i}"),
    "work":           ("work {i}", "избыточная работа {i}", "盈亏功 {i}"),
    "arrow":          ("arrow {i}", "вектор {i}", "矢量 {i}"),
    "n_areas":        ("number of intervals", "число участков", "区间数"),
    "n_works":        ("number of intervals (works)", "число участков (работы)", "区间数（盈亏功）"),
    "n_arrows":       ("number of arrows", "число векторов", "矢量数"),
    "point_of":       ("point of {omega}", "точка {omega}", "{omega} 所在点"),
    "angle_of":       ("angle of {omega}", "угол φ при {omega}", "{omega} 所在转角 φ"),
    "position_of":    ("position of {omega}", "положение {omega}", "{omega} 所在位置"),
    "sense_of":       ("sense of {omega}", "направление {omega}", "{omega} 的转向"),
    "direction_of":   ("direction of {v}", "направление вектора {v}", "{v} 的方向"),
    # the usual mistakes (the keys of MISTAKES), short
    "sign_flipped":   ("sign flipped in the staircase", "перепутан знак избыточной работы",
                       "盈亏功正负号颠倒"),
    "degrees_as_radians": ("degrees used as radians", "градусы приняты за радианы", "把度当作弧度"),
    "n_as_omega":     ("n (rev/min) used as ω (rad/s)", "n (об/мин) принято за ω (рад/с)",
                       "把 n (r/min) 当作 ω (rad/s)"),
    "scale_forgotten": ("scale factor forgotten", "не учтён масштабный коэффициент", "漏乘比例尺"),
    "scale_twice":    ("scale factor applied twice", "масштабный коэффициент учтён дважды", "比例尺乘了两次"),
    "J_e_not_subtracted": ("{J_e} not subtracted", "не вычтен {J_e}", "未减去 {J_e}"),
    # ω_max = ω_m(1 + δ) for ω_m(1 + δ/2), and squared in tan ψ (and in J_F through ω_max² − ω_min²)
    "delta_not_halved": ("(1 ± δ) instead of (1 ± δ/2)", "(1 ± δ) вместо (1 ± δ/2)", "用 (1 ± δ) 代替了 (1 ± δ/2)"),
    **ca.WORDS,
}


def _w(nt, key: str, **kw) -> str:
    """A text of :data:`WORDS` in the notation's language, ``{placeholders}`` filled from ``kw``."""
    return in_language(WORDS[key], nt, **kw)


#: the answers file: section -> allowed keys (top-level keys: problem, student)
SCHEMA = {
    "page": ("size", "orientation"),
    "moment_diagram": ("mu_M", "mu_phi", "mu_phi_deg", "areas_mm2", "origin_mm"),
    "energy_indicator": ("mu_E", "step_mm", "arrows_mm", "origin_mm"),
    "velocity_plan": ("position", "positions", "mu_v", "pa_mm", "pb_mm", "ab_mm", "ps2_mm", "origin_mm"),
    "energy_mass": ("positions", "mu_J", "mu_T", "tan_psi_max", "tan_psi_min", "kl_mm", "omega_max_at",
                    "omega_min_at", "origin_mm"),
    "acceleration_plan": ca.SECTION_KEYS,           # its vectors' keys depend on the linkage
    "results": ("M_d", "works_J", "delta_W_max", "omega_m", "omega_max", "omega_min", "omega_max_at",
                "omega_min_at", "J_F", "v_A", "v_B", "v_BA", "v_S2", "omega_2", "omega_2_sense"),
}
TOP_LEVEL = ("problem", "student")

#: What each key of the answers file holds (the number policy of graphmethods.units applies to all):
#: "scale" a positive number, "count" the number of positions m, "index" a position number,
#: "list" a flat list of numbers, "xy" two numbers, "at" a point label, an angle or a list of positions,
#: "text" text; any other key a number.
KEY_KINDS = {
    "size": "text", "orientation": "text", "omega_2_sense": "text",
    "mu_M": "scale", "mu_phi": "scale", "mu_phi_deg": "scale", "mu_E": "scale", "mu_v": "scale",
    "mu_J": "scale", "mu_T": "scale", "step_mm": "scale",
    "positions": "count", "position": "index",
    "areas_mm2": "list", "arrows_mm": "list", "works_J": "list", "origin_mm": "xy",
    "omega_max_at": "at", "omega_min_at": "at",
}


# ----------------------------------------------------------------------------- TOML

def load_toml(text: str, *, source: str = "<answers>") -> dict:
    """TOML text as a dict, read by the standard ``tomllib`` (Python ≥ 3.11) or its backport ``tomli``.

    >>> load_toml('problem = "W1"\\n[results]\\nJ_F = 1.5e-1  # kg·m²')
    {'problem': 'W1', 'results': {'J_F': 0.15}}
    """
    if sys.version_info >= (3, 11):
        import tomllib
    else:                                # Python 3.10: the same parser, installed as a dependency
        import tomli as tomllib
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{source}: not valid TOML ({exc})") from None


def read_answers(path) -> dict:
    """Read and validate an answers file (see :data:`SCHEMA`): numbers, text, lists as tuples.

    >>> import pathlib
    >>> a = read_answers(pathlib.Path(__file__).parents[1] / "problems" / "data" / "answers" / "w3_correct.toml")
    >>> a["moment_diagram"]["areas_mm2"], a["results"]["omega_max_at"]
    ((-1560.0, 1590.0), 0.0)
    """
    p = pathlib.Path(path)
    text = read_text(p, missing="no such answers file")
    return validate_answers(load_toml(text, source=str(p)), source=str(p))


def validate_answers(data: dict, *, source: str = "<answers>") -> dict:
    """Check the sections and keys of an answers dict; numbers become floats, lists tuples of floats."""
    if not isinstance(data, dict):
        raise InputError(f"{source}: the answers must be a table of sections")
    out: dict = {}
    for key, value in data.items():
        if key in TOP_LEVEL:
            if not isinstance(value, str):
                raise InputError(f"{source}: {key} must be text")
            out[key] = value
            continue
        if key not in SCHEMA:
            raise InputError(f"{source}: unknown section or key {key!r}; sections: {', '.join(SCHEMA)} "
                             f"(and {', '.join(TOP_LEVEL)})")
        if not isinstance(value, dict):
            raise InputError(f"{source}: {key!r} must be a [section]")
        sec = {}
        for k, v in value.items():
            if k not in SCHEMA[key]:
                raise InputError(f"{source}: [{key}] has no key {k!r}; its keys are {', '.join(SCHEMA[key])}")
            if v == "" or v == []:      # left blank in a template (graphmethods.sheets.answers): not answered
                continue
            kind = KEY_KINDS.get(k, "text" if k.endswith("_sense") else "number")
            sec[k] = _typed_answer(kind, _answer_value(v, f"{source}: [{key}] {k}"), f"{source}: [{key}] {k}")
        if sec or not value:            # a section whose every key is blank is not answered either
            out[key] = sec
    return out


def _typed_answer(kind: str, v, where: str):
    """One answer checked for what its key holds (see :data:`KEY_KINDS`), before any work."""
    if kind == "text":
        if not isinstance(v, str):
            raise InputError(f"{where} must be text, got {v!r}")
        return v
    if kind == "at":
        items = v if isinstance(v, tuple) else (v,)
        if not items:
            raise InputError(f"{where}: give a point label (\"b\"), an angle in degrees or positions [0, 6]")
        for x in items:
            if isinstance(x, tuple):
                raise InputError(f"{where} must be a label, a number or a flat list, got {v!r}")
        return v
    if kind == "list":
        if not isinstance(v, tuple):
            raise InputError(f"{where} must be a list of numbers, e.g. [-10, 110, -20], got {v!r}")
        return tuple(real(x, f"{where}[{i}]") if not isinstance(x, (str, tuple)) else
                     _not_a_number(x, f"{where}[{i}]") for i, x in enumerate(v))
    if kind == "xy":
        if not isinstance(v, tuple) or len(v) != 2:
            raise InputError(f"{where} must be two numbers [x, y] in mm, got {v!r}")
        return tuple(real(x, f"{where}[{i}]") if not isinstance(x, (str, tuple)) else
                     _not_a_number(x, f"{where}[{i}]") for i, x in enumerate(v))
    if isinstance(v, (str, tuple)):
        _not_a_number(v, where)
    if kind == "count":
        return count(v, where, low=3, high=MAX_POSITIONS, why="the number of positions m")
    if kind == "index":
        return count(v, where, low=0, high=MAX_POSITIONS, why="a position number")
    if kind == "scale":
        return real(v, where, lo=0.0, lo_open=True, hint="a scale or a step is a positive number")
    return real(v, where)


def _not_a_number(v, where: str):
    raise InputError(f"{where} must be a number, got {v!r}")


def _answer_value(v, where: str, depth: int = 0):
    if isinstance(v, bool):
        raise InputError(f"{where}: expected a number or text, got {v!r}")
    if isinstance(v, int):
        return v                          # its size is checked by the number policy (units.real)
    if isinstance(v, float):
        if not math.isfinite(v):
            raise InputError(f"{where}: {v!r} is not finite")
        return v
    if isinstance(v, str):
        return v
    if isinstance(v, (list, tuple)):
        if depth >= 2:
            raise InputError(f"{where}: lists nested too deeply; give a flat list of numbers")
        return tuple(_answer_value(x, where, depth + 1) for x in v)
    raise InputError(f"{where}: expected a number, text or list, got {v!r}")


# ----------------------------------------------------------------------------- problems

@dataclass(frozen=True, eq=False)
class CycleData:
    """What the check needs of a cycle problem (W1–W4, indicator and step-moment worksheets)."""

    id: str
    title: Title
    cycle: ExcessWork
    n_rpm: float | None
    delta: float | None
    J_e: float = 0.0
    areas_given: bool = False             # the areas are data (mm² at the problem's μ_M, μ_φ)
    M_d: float | None = None              # a constant driving moment found by work balance


@dataclass(frozen=True, eq=False)
class LinkageData:
    """A slider-crank problem: a case file (press), or worksheet variants (one plan, or a table)."""

    id: str
    title: Title
    case: Case | None = None                  # velocity plan at positions, Study
    plan_variant: ws.PlanVariant | None = None
    em_variant: ws.EnergyMassVariant | None = None
    accel_variant: object | None = None   # acceleration_worksheet.AccelerationPlanVariant


def load_problem(spec) -> CycleData | LinkageData:
    """A problem to check against: a built-in id (W1…W4, press), a worksheet id ``KIND:SEED:N``, or a
    problem file (a worksheet problem file, or a linkage case file such as the press's).

    >>> load_problem("W3").M_d, load_problem("step-moment:7:1").id
    (16.25, 'step-moment:7:1')
    """
    from graphmethods import problems

    text = str(spec).strip()
    low = text.lower()
    builtin = {"w1": problems.w1, "w2": problems.w2, "w3": problems.w3, "w4": problems.w4_drawing,
               "w4-drawing": problems.w4_drawing, "w4-exact": problems.w4_exact}
    if low in builtin:
        p = builtin[low]()
        return CycleData(p.id, p.title, p.excess_work, p.n_rpm, p.delta, p.J_e, areas_given=p.areas_mm2 is not None,
                         M_d=float(p.excess_work.M_d.mean()) if p.excess_work.M_d is not None else None)
    if low == "press":
        from graphmethods.kinematics import read_case

        path = pathlib.Path(problems.__file__).parent / "data" / "slider_crank_press.json"
        case = read_case(path)
        return LinkageData("press", title_of(case), case=case)
    if low == "slotted-lever":            # acceleration plans only (the velocity plan check knows slider-cranks)
        from graphmethods.kinematics import read_case

        case = read_case(pathlib.Path(problems.__file__).parent / "data" / "slotted_lever.json")
        return LinkageData("slotted-lever", title_of(case), case=case)
    v = ws.parse_id(text)
    if v is None:
        fp = pathlib.Path(text)
        if not fp.exists():
            raise InputError(f"problem {text!r}: not a built-in id ({', '.join(PROBLEM_IDS)}), not a worksheet id "
                             f"KIND:SEED:N, and no such file")
        try:
            data = json.loads(fp.read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
            raise InputError(f"{fp}: not a readable JSON problem file ({exc})") from None
        if isinstance(data, dict) and data.get("format") == ws.PROBLEM_FORMAT:
            v = ws.variant_from_dict(data, source=str(fp))
        else:
            from graphmethods.kinematics import case_from_dict

            case = case_from_dict(data, source=str(fp))
            if case.kind != "slider_crank":
                raise InputError(f"{fp}: the check knows slider-crank problems; this one is a {case.kind}")
            return LinkageData(str(fp), title_of(case) or Title.of(fp.stem), case=case)
    return _from_variant(v)


def _from_variant(v) -> CycleData | LinkageData:
    title = v.title
    if v.kind == "indicator":
        return CycleData(v.id, title, v.excess_work, v.n_rpm, v.delta_value, v.J_e, areas_given=True)
    if v.kind == "step-moment":
        return CycleData(v.id, title, v.excess_work, v.n_rpm, v.delta_value, v.J_e, M_d=v.M_d)
    if v.kind == "velocity-plan":
        return LinkageData(v.id, title, plan_variant=v)
    if v.kind == "acceleration-plan":
        return LinkageData(v.id, title, accel_variant=v)
    return LinkageData(v.id, title, em_variant=v)


# ----------------------------------------------------------------------------- the report

@dataclass(frozen=True)
class Item:
    """One checked item: the student's value against the expected one at the student's scales.

    Attributes
    ----------
    key : str
        Where it is in the answers file (``"energy_indicator.arrows_mm[3]"``).
    label : str
        What it is (``"arrow c–d"``).
    unit : str
        Its unit (``"mm"``, ``"J"`` …; ``""`` for a position).
    expected, student : float or str
        Expected value (for a position: the accepted positions joined by ``" or "``) and the student's.
    deviation : float or None
        student − expected.
    tolerance : float or None
        The tolerance applied (same unit).
    verdict : str
        ``"ok"``, ``"carried"`` or ``"wrong"``.
    mistakes : tuple of str
        Codes of :data:`MISTAKES` diagnosed for this item (empty when none fits).
    note : str
        How the tolerance was made, or where a carried error comes from.
    """

    key: str
    label: str
    unit: str
    expected: float | str
    student: float | str
    deviation: float | None
    tolerance: float | None
    verdict: str
    mistakes: tuple = ()
    note: str = ""

    def to_dict(self) -> dict:
        return {"key": self.key, "label": self.label, "unit": self.unit, "expected": self.expected,
                "student": self.student, "deviation": self.deviation, "tolerance": self.tolerance,
                "verdict": self.verdict, "mistakes": list(self.mistakes), "note": self.note}


@dataclass(frozen=True)
class Mistake:
    """A diagnosed mistake and the items it explains."""

    code: str
    text: str
    items: tuple


@dataclass(frozen=True, eq=False)
class CheckReport:
    """The result of a check: items with verdicts, diagnosed mistakes, and what the overlay needs."""

    problem: str
    title: Title | str                    # the problem's title; the text reports print the English
    student: str
    items: tuple
    page: Page
    notes: tuple = ()
    data: CycleData | LinkageData | None = field(default=None, repr=False)
    answers: dict = field(default_factory=dict, repr=False)

    @property
    def wrong(self) -> tuple:
        """Items that are new mistakes (verdict ``wrong``)."""
        return tuple(i for i in self.items if i.verdict == "wrong")

    @property
    def carried(self) -> tuple:
        return tuple(i for i in self.items if i.verdict == "carried")

    @property
    def ok(self) -> bool:
        """True when every item is within tolerance."""
        return all(i.verdict == "ok" for i in self.items)

    @property
    def mistakes(self) -> tuple:
        """The diagnosed mistakes, in the order they first appear, each with its items."""
        order: list[str] = []
        by: dict[str, list[str]] = {}
        for it in self.items:
            for code in it.mistakes:
                if code not in by:
                    order.append(code)
                    by[code] = []
                by[code].append(it.key)
        return tuple(Mistake(c, MISTAKES[c], tuple(by[c])) for c in order)

    def summary(self) -> str:
        n_w, n_c = len(self.wrong), len(self.carried)
        if self.ok:
            return f"all {len(self.items)} items correct"
        undiag = sum(1 for i in self.wrong if not i.mistakes)
        parts = [f"{n_w} wrong item{'s' if n_w != 1 else ''}"]
        if self.mistakes:
            parts.append(f"{len(self.mistakes)} usual mistake{'s' if len(self.mistakes) != 1 else ''} recognised")
        if undiag:
            parts.append(f"{undiag} without a recognised cause")
        if n_c:
            parts.append(f"{n_c} carried over from earlier errors")
        return f"{len(self.items)} items: " + ", ".join(parts)

    # -- output
    def to_dict(self) -> dict:
        """The report as a JSON-ready dict."""
        return {"problem": self.problem, "title": str(self.title), "student": self.student, "ok": self.ok,
                "summary": self.summary(),
                "page": {"size": self.page.size, "orientation": self.page.orientation},
                "items": [i.to_dict() for i in self.items],
                "mistakes": [{"code": m.code, "text": m.text, "items": list(m.items)} for m in self.mistakes],
                "notes": list(self.notes)}

    def to_json(self) -> str:
        return json_text(self.to_dict(), indent=1, ensure_ascii=False)

    def _rows(self):
        for it in self.items:
            yield (it.label, _fmt(it.expected), _fmt(it.student), _fmt(it.deviation), _fmt(it.tolerance),
                   it.unit, it.verdict + (" (" + ", ".join(it.mistakes) + ")" if it.mistakes else ""))

    def to_text(self) -> str:
        """Aligned plain text: one line per item, then the mistakes and the summary."""
        head = ("item", "expected", "student", "deviation", "tolerance", "unit", "verdict")
        rows = [head] + list(self._rows())
        widths = [max(len(r[k]) for r in rows) for k in range(len(head))]
        lines = [f"Check of {self.problem} ({self.title})" + (f" — {self.student}" if self.student else "")]
        lines += ["  ".join(c.ljust(w) if k in (0, 5, 6) else c.rjust(w) for k, (c, w) in enumerate(zip(r, widths)))
                  .rstrip() for r in rows]
        lines += self._tail("- ")
        return "\n".join(lines) + "\n"

    def to_markdown(self) -> str:
        """A Markdown table of the items, then the mistakes and the summary."""
        head = ("item", "expected", "student", "deviation", "tolerance", "unit", "verdict")
        lines = [f"### Check of {self.problem} ({self.title})" + (f" — {self.student}" if self.student else ""), "",
                 "| " + " | ".join(head) + " |", "|" + "|".join(("---", "--:", "--:", "--:", "--:", "---", "---")) + "|"]
        for r in self._rows():
            cells = list(r)
            if not cells[6].startswith("ok"):
                cells[6] = f"**{cells[6]}**"
            lines.append("| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |")
        lines.append("")
        lines += self._tail("- ")
        return "\n".join(lines) + "\n"

    def _repr_markdown_(self) -> str:          # a notebook shows the report
        return self.to_markdown()

    def _tail(self, bullet: str) -> list[str]:
        out = []
        if self.mistakes:
            out.append("Mistakes recognised:")
            labels = {i.key: i.label for i in self.items}
            out += [f"{bullet}{m.text}: {', '.join(labels[k] for k in m.items)}" for m in self.mistakes]
        undiag = [i for i in self.wrong if not i.mistakes]
        if undiag:
            out.append("Wrong, no usual mistake fits:")
            out += [f"{bullet}{i.label}" for i in undiag]
        carried = self.carried
        if carried:
            out.append("Carried over (follow from the student's own earlier values):")
            out += [f"{bullet}{i.label}: {i.note}" for i in carried]
        out += [f"Note: {n}" for n in self.notes]
        out.append(f"Result: {self.summary()}")
        return out

    def overlay(self, *, notation="en") -> Scene:
        """The correct construction at the student's scales on a page the size of theirs, to print 1:1 on
        film; the student's wrong items in red.

        Parameters
        ----------
        notation : str or Notation
            ``"en"``, ``"ru"`` or ``"zh"``: the symbols, units, number style and words of everything the
            overlay draws (heading, how to print it, the list of wrong items with the names of the
            mistakes, see :data:`WORDS`). The text, Markdown and JSON reports stay English.

        Returns
        -------
        Scene

        Examples
        --------
        >>> from graphmethods.render.recording import record
        >>> rep = check("W1", {"energy_indicator": {"mu_E": 5.0, "arrows_mm": [-10, 110, 20, 25, -100, 5, -10]}})
        >>> [t for t in record(rep.overlay(notation="ru")).texts() if t.startswith("вектор")]
        ['вектор c–d: 20 (должно быть −20) мм — перепутан знак избыточной работы']
        """
        return _overlay(self, notation)


def _fmt(v) -> str:
    """A value for the report: four significant digits (whole numbers in full)."""
    if v is None:
        return ""
    if isinstance(v, str):
        return v
    if v == 0:
        return "0"
    return f"{v:.0f}" if abs(v) >= 1e4 else f"{v:.4g}"


# ----------------------------------------------------------------------------- the checker

class _Checker:
    def __init__(self, answers: dict):
        self.a = answers
        self.items: list[Item] = []
        self.notes: list[str] = []

    def get(self, section: str, key: str, default: Any = None) -> Any:
        return self.a.get(section, {}).get(key, default)

    def need(self, section: str, key: str, why: str):
        v = self.get(section, key)
        if v is None:
            raise InputError(f"the answers give [{section}] values but no {key} ({why}); add it")
        if isinstance(v, (str, tuple)):
            raise InputError(f"[{section}] {key} must be a number, got {v!r}")
        if not v > 0:
            raise InputError(f"[{section}] {key} = {v!r} must be positive")
        return float(v)

    def number(self, section: str, key: str) -> float | None:
        v = self.get(section, key)
        if v is None:
            return None
        if isinstance(v, (str, tuple)):
            raise InputError(f"[{section}] {key} must be a number, got {v!r}")
        return float(v)

    def numbers(self, section: str, key: str) -> list[float] | None:
        v = self.get(section, key)
        if v is None:
            return None
        if not isinstance(v, tuple) or any(isinstance(x, str) for x in v):
            raise InputError(f"[{section}] {key} must be a list of numbers, got {v!r}")
        return [float(x) for x in v]

    def value(self, key: str, label: str, unit: str, expected: float, student: float, tol: float, *,
              own: float | None = None, own_tol: float | None = None, own_from: str = "",
              hypotheses=(), hyp_tol=None, note: str = "") -> Item:
        """Judge a numeric item (see the module docstring)."""
        dev = student - expected
        codes: tuple[str, ...]
        if abs(dev) <= tol:
            verdict, codes = "ok", ()
        else:
            ot = tol if own_tol is None else own_tol
            if own is not None and abs(student - own) <= ot and abs(own - expected) > ot:
                verdict, codes = "carried", ()
                note = f"follows from {own_from}: expected {_fmt(own)} from those"
            else:
                verdict = "wrong"
                found: list[str] = []
                for hyp in hypotheses:
                    code, h = hyp[0], hyp[1]
                    if h is None or not math.isfinite(h):
                        continue
                    t = hyp[2] if len(hyp) > 2 else (tol if hyp_tol is None else hyp_tol(h))
                    if abs(student - h) <= t and code not in found:
                        found.append(code)
                codes = tuple(found)
        it = Item(key, label, unit, float(expected), float(student), float(dev), float(tol), verdict, codes, note)
        self.items.append(it)
        return it

    def position(self, key: str, label: str, accepted, student, *, own_accepted=None, own_from: str = "") -> Item:
        acc = [str(a) for a in accepted]

        def one(x) -> str:
            if isinstance(x, float) and x.is_integer():
                return str(int(x))
            return x.strip() if isinstance(x, str) else _fmt(x)

        given = [one(x) for x in student] if isinstance(student, tuple) else [one(student)]
        s = " and ".join(given)          # a list, as study prints it ([0, 6]): every one must be accepted
        own = None if own_accepted is None else [str(a) for a in own_accepted]
        if all(g in acc for g in given):
            verdict, note = "ok", ""
        elif own is not None and all(g in own for g in given):
            verdict, note = "carried", f"follows from {own_from}"
        else:
            verdict, note = "wrong", ""
        it = Item(key, label, "", " or ".join(acc), s, None, None, verdict, (), note)
        self.items.append(it)
        return it


def _rel(tol_abs: float, value: float) -> float:
    return tol_abs + TOL_REL * abs(value)


def _levels_accepted(E, labels, tol: float, which: str) -> list[str]:
    """Labels whose level is within ``tol`` of the extreme (the first and last point are one point)."""
    E = np.asarray(E, dtype=float)
    ext = E.max() if which == "max" else E.min()
    idx = [k for k in range(E.size) if abs(E[k] - ext) <= tol + 1e-9 * max(1.0, abs(ext))]
    if 0 in idx or E.size - 1 in idx:
        idx = sorted(set(idx) | {0, E.size - 1})
    return [labels[k] for k in idx]


def _check_cycle(ck: _Checker, p: CycleData) -> None:
    c = p.cycle
    A = np.asarray(c.work, dtype=float)
    n = A.size
    L = c.labels
    names = [f"{L[i]}–{L[i + 1]}" for i in range(n)]
    has_curves = c.M_d is not None
    # ---- moment diagram: areas
    f_student = ck.numbers("moment_diagram", "areas_mm2")
    tol_A = [TOL_REL * abs(a) for a in A]                # work tolerances (computed, not drawn)
    tol_f: list[float] = []                              # the student's area tolerances, mm²
    k_student: float | None = None
    if "moment_diagram" in ck.a:
        mu_M = ck.need("moment_diagram", "mu_M", "N·m per mm of the moment diagram")
        if ck.get("moment_diagram", "mu_phi") is not None:
            mu_phi = ck.need("moment_diagram", "mu_phi", "rad per mm")
        elif ck.get("moment_diagram", "mu_phi_deg") is not None:
            mu_phi = math.radians(ck.need("moment_diagram", "mu_phi_deg", "degrees per mm"))
        else:
            raise InputError("the answers give a [moment_diagram] but no mu_phi (rad/mm) or mu_phi_deg (°/mm)")
        k_student = mu_M * mu_phi
        if f_student is not None:
            if len(f_student) != n:
                ck.position("moment_diagram.areas_mm2", "number of intervals", [n], float(len(f_student)))
                f_student = None
            else:
                if has_curves:
                    per = ws.region_perimeters_mm(c, mu_M=mu_M, mu_phi=mu_phi)
                    basis = "0.5 mm × the region's perimeter"
                else:
                    per = 4.0 * np.sqrt(np.abs(A / k_student))
                    basis = "0.5 mm × 4√|f| (region shape not known)"
                tol_f = [TOL_MM * float(x) for x in per]
                for i in range(n):
                    exp = A[i] / k_student
                    ck.value(f"moment_diagram.areas_mm2[{i}]", f"area {names[i]}", "mm²", exp, f_student[i], tol_f[i],
                             hypotheses=[("sign_flipped", -exp)], note=basis)
                    tol_A[i] = tol_f[i] * k_student
    # the base the work hypotheses start from: the student's areas, or the data's
    if f_student is not None:
        f_base, k_base = np.asarray(f_student), k_student
    elif p.areas_given and c.areas_mm2 is not None and c.mu_M is not None and c.mu_phi is not None:
        f_base, k_base = np.asarray(c.areas_mm2, dtype=float), float(c.mu_M * c.mu_phi)
    else:
        f_base, k_base = None, None
    # ---- works
    w_student = ck.numbers("results", "works_J")
    if w_student is not None and len(w_student) != n:
        ck.position("results.works_J", "number of intervals (works)", [n], float(len(w_student)))
        w_student = None
    if w_student is not None:
        for i in range(n):
            own = None if f_student is None or k_student is None else f_student[i] * k_student
            base = A[i] if own is None else own
            hyps: list[tuple[Any, ...]] = [("sign_flipped", -base), ("degrees_as_radians", base * 180.0 / math.pi),
                    ("degrees_as_radians", base * math.pi / 180.0)]
            if f_base is not None and k_base is not None:
                hyps += [("scale_forgotten", f_base[i]), ("scale_twice", f_base[i] * k_base ** 2)]
            ck.value(f"results.works_J[{i}]", f"work {names[i]}", "J", A[i], w_student[i], _rel(tol_A[i], A[i]),
                     own=own, own_tol=_rel(tol_A[i], own or 0.0), own_from="the student's area",
                     hypotheses=hyps, hyp_tol=lambda h, i=i: _rel(tol_A[i], h),
                     note="from the areas" if f_student is not None else "computed")
    # the student's own works (from what they wrote, else from their areas, else their arrows below)
    if w_student is not None:
        own_A = np.asarray(w_student)
        own_tol_A = [TOL_REL * abs(x) for x in own_A]
    elif f_student is not None and k_student is not None:
        own_A = np.asarray(f_student) * k_student
        own_tol_A = [t * k_student for t in tol_f]
    else:
        own_A, own_tol_A = None, []
    # ---- energy indicator: arrows
    arrows = ck.numbers("energy_indicator", "arrows_mm")
    if "energy_indicator" in ck.a:
        mu_E = ck.need("energy_indicator", "mu_E", "J per mm of the energy indicator")
        if arrows is not None:
            if len(arrows) != n:
                ck.position("energy_indicator.arrows_mm", "number of arrows", [n], float(len(arrows)))
                arrows = None
            else:
                for i in range(n):
                    own = None if own_A is None else own_A[i] / mu_E
                    base = A[i] / mu_E if own is None else own
                    ck.value(f"energy_indicator.arrows_mm[{i}]", f"arrow {names[i]}", "mm", A[i] / mu_E, arrows[i],
                             TOL_MM, own=own, own_from="the student's work", hypotheses=[("sign_flipped", -base)],
                             note="±0.5 mm")
                if own_A is None:                         # ΔW_max read off the student's staircase
                    own_A = np.asarray(arrows) * mu_E
                    own_tol_A = [TOL_MM * mu_E] * n
    # ---- ΔW_max
    E = np.asarray(c.E, dtype=float)
    i_hi, i_lo = int(np.argmax(E)), int(np.argmin(E))
    span = range(min(i_hi, i_lo), max(i_hi, i_lo))
    tol_dW = float(sum(tol_A[i] for i in span))
    own_E = None if own_A is None else np.concatenate(([0.0], np.cumsum(own_A)))
    own_tol_dW = None
    if own_E is not None:
        o_hi, o_lo = int(np.argmax(own_E)), int(np.argmin(own_E))
        own_tol_dW = float(sum(own_tol_A[i] for i in range(min(o_hi, o_lo), max(o_hi, o_lo))))
    dW_student = ck.number("results", "delta_W_max")
    if dW_student is not None:
        own = None if own_E is None else float(own_E.max() - own_E.min())
        base_A = A if own_A is None else own_A
        hyps = []
        for i in range(n):
            flipped = base_A.copy()
            flipped[i] = -flipped[i]
            EE = np.concatenate(([0.0], np.cumsum(flipped)))
            hyps.append(("sign_flipped", float(EE.max() - EE.min())))
        base = float(np.ptp(np.concatenate(([0.0], np.cumsum(base_A)))))
        hyps += [("degrees_as_radians", base * 180 / math.pi), ("degrees_as_radians", base * math.pi / 180)]
        if k_base is not None:
            hyps += [("scale_forgotten", base / k_base), ("scale_twice", base * k_base)]
        base_tol = tol_dW if own_tol_dW is None else own_tol_dW
        ck.value("results.delta_W_max", "ΔW_max", "J", c.delta_W_max, dW_student, _rel(tol_dW, c.delta_W_max),
                 own=own, own_tol=_rel(base_tol, own or 0.0), own_from="the student's own works",
                 hypotheses=hyps, hyp_tol=lambda h: _rel(base_tol, h),
                 note="sum of the work tolerances between E_max and E_min")
    # ---- where ω_max and ω_min occur
    for which, key in (("max", "omega_max_at"), ("min", "omega_min_at")):
        s = ck.get("results", key)
        if s is None:
            continue
        if isinstance(s, tuple) and not all(isinstance(x, str) for x in s):
            raise InputError(f"[results] {key}: give one point label (e.g. \"b\") or one angle in degrees, "
                             f"or a list of labels; got {s!r}")
        if isinstance(s, (str, tuple)):
            acc = _levels_accepted(E, L, tol_dW, which)
            own_acc = None if own_E is None or own_tol_dW is None else _levels_accepted(own_E, L, own_tol_dW, which)
            ck.position(f"results.{key}", f"point of ω_{which}", acc, s, own_accepted=own_acc,
                        own_from="the student's own levels")
        else:
            if c.phi is None:
                raise InputError(f"[results] {key}: this problem has no angles (no moment curves); give the point "
                                 f"label, e.g. \"b\"")
            idx = [L.index(lab) for lab in _levels_accepted(E, L, tol_dW, which)]
            phis = [math.degrees(c.phi[k] - c.phi[0]) for k in idx]
            tol_deg = TOL_MM * math.degrees(k_student / ck.need("moment_diagram", "mu_M", "")) \
                if k_student is not None else 1.0
            best = min(phis, key=lambda x: abs(x - float(s)))
            ck.value(f"results.{key}", f"angle of ω_{which}", "°", best, float(s), tol_deg,
                     note="±0.5 mm on the φ axis" if k_student is not None else "±1°")
    # ---- M_d, ω's and J_F
    M_d_student = ck.number("results", "M_d")
    if M_d_student is not None:
        if p.M_d is None:
            ck.notes.append("M_d is not checked: this problem gives no constant driving moment")
        else:
            ck.value("results.M_d", "M_d", "N·m", p.M_d, M_d_student, _rel(0.0, p.M_d),
                     hypotheses=[("degrees_as_radians", p.M_d * 180 / math.pi),
                                 ("degrees_as_radians", p.M_d * math.pi / 180)], hyp_tol=lambda h: _rel(0.0, h),
                     note="0.1 %")
    asks = [k for k in ("omega_m", "omega_max", "omega_min", "J_F") if ck.get("results", k) is not None]
    if asks and (p.n_rpm is None or p.delta is None):
        ck.notes.append(f"{', '.join(asks)} not checked: problem {p.id} gives no n and [δ]")
        return
    if not asks or p.n_rpm is None or p.delta is None:
        return
    n_rpm, d = float(p.n_rpm), float(p.delta)
    w = omega_from_n(n_rpm)
    om_s = ck.number("results", "omega_m")
    for key, f_exact, f_wrong in (("omega_m", 1.0, 1.0), ("omega_max", 1 + d / 2, 1 + d), ("omega_min", 1 - d / 2, 1 - d)):
        s = ck.number("results", key)
        if s is None:
            continue
        own = None if (om_s is None or key == "omega_m" or not om_s > 0) else om_s * f_exact
        hyps = [("n_as_omega", n_rpm * f_exact), ("degrees_as_radians", 6 * n_rpm * f_exact)]
        if key != "omega_m":
            hyps.append(("delta_not_halved", w * f_wrong))
        ck.value(f"results.{key}", key.replace("omega_", "ω_"), "rad/s", w * f_exact, s, _rel(0.0, w * f_exact),
                 own=own, own_from="the student's ω_m", hypotheses=hyps, hyp_tol=lambda h: _rel(0.0, h), note="0.1 %")
    J_s = ck.number("results", "J_F")
    if J_s is not None:
        J_exp = c.delta_W_max / (w * w * d) - p.J_e
        tol = _rel(tol_dW / (w * w * d), J_exp)
        dW_base = c.delta_W_max if dW_student is None else dW_student
        w_own = w if om_s is None or not om_s > 0 else om_s     # ω_m = 0 written: no result follows from it
        own = None
        if dW_student is not None or om_s is not None:
            own = dW_base / (w_own * w_own * d) - p.J_e
        t_dW = tol_dW if dW_student is None or own_tol_dW is None else max(tol_dW, own_tol_dW)
        hyps = []
        for code, X2, sub in (("n_as_omega", n_rpm ** 2, p.J_e), ("degrees_as_radians", (6 * n_rpm) ** 2, p.J_e),
                              ("delta_not_halved", 2 * w * w, p.J_e), ("J_e_not_subtracted", w * w, 0.0)):
            if code == "J_e_not_subtracted" and p.J_e <= 0:
                continue
            h = dW_base / (X2 * d) - sub
            hyps.append((code, h, t_dW / (X2 * d) + TOL_REL * abs(h)))
        ck.value("results.J_F", "J_F", "kg·m²", J_exp, J_s, tol, own=own,
                 own_tol=_rel(t_dW / (w_own * w_own * d), own or 0.0),
                 own_from="the student's own ΔW_max and ω_m", hypotheses=hyps, note="from the ΔW_max tolerance, + 0.1 %")


def _plan_data(ck: _Checker, p: LinkageData) -> tuple[dict[str, np.ndarray], float, float | None, float]:
    """(vectors by label, l_AB, n_rpm or None, ω₁) of the velocity plan the student drew."""
    if p.plan_variant is not None:
        v = p.plan_variant
        if ck.get("velocity_plan", "position") is not None:
            ck.notes.append("velocity_plan.position ignored: this problem has one position")
        return v.vectors(), v.l, None, v.omega_1
    case = p.case
    assert case is not None                  # a linkage problem is a case file or a worksheet variant
    pos_k = ck.get("velocity_plan", "position")
    m = int(ck.get("velocity_plan", "positions", 12))
    if pos_k is None or isinstance(pos_k, (str, tuple)) or not float(pos_k).is_integer() or not 0 <= pos_k <= m:
        raise InputError(f"[velocity_plan] position must be the position number 0…{m} the plan was drawn for")
    mech = case.mechanism
    positions = mech.positions(m=m)
    plan = mech.velocity_plans(positions, omega_1=case.omega_m)
    k = int(pos_k)
    vec: dict[str, np.ndarray] = {}
    for name in plan.order:
        vec.setdefault(plan.label(name), np.asarray(plan.v(name)[k], dtype=float))
    return vec, float(case.mechanism.l), float(case.n_rpm), float(case.omega_m)  # type: ignore[attr-defined]
    # (.l: a slider-crank's connecting rod; the check takes slider-crank cases only)


def _check_plan(ck: _Checker, p: LinkageData) -> None:
    vec, l_AB, n_rpm, w1 = _plan_data(ck, p)
    mu_v = ck.need("velocity_plan", "mu_v", "(m/s) per mm of the velocity plan")
    seg_exp = {s: float(np.hypot(*(vec[b] - vec[a]))) for s, (a, b) in ws.SEGMENTS.items()}
    ratio = None if n_rpm is None else n_rpm / w1
    seg_student = {}
    for s in ws.SEGMENTS:
        val = ck.number("velocity_plan", f"{s}_mm")
        if val is None:
            continue
        seg_student[s] = val
        exp = seg_exp[s] / mu_v
        hyps = [] if ratio is None else [("n_as_omega", exp * ratio)]
        ck.value(f"velocity_plan.{s}_mm", s, "mm", exp, val, TOL_MM, hypotheses=hyps, note="±0.5 mm")
    tol_v = TOL_MM * mu_v
    for key, s in (("v_A", "pa"), ("v_B", "pb"), ("v_BA", "ab"), ("v_S2", "ps2")):
        val = ck.number("results", key)
        if val is None:
            continue
        own = seg_student[s] * mu_v if s in seg_student else None
        seg = seg_student.get(s, seg_exp[s] / mu_v)
        hyps = [("scale_forgotten", seg), ("scale_twice", seg * mu_v ** 2)]
        if ratio is not None:
            hyps.append(("n_as_omega", seg * mu_v * ratio))
        ck.value(f"results.{key}", key, "m/s", seg_exp[s], val, _rel(tol_v, seg_exp[s]), own=own,
                 own_tol=_rel(tol_v, own or 0.0), own_from=f"the student's {s}", hypotheses=hyps,
                 hyp_tol=lambda h: _rel(tol_v, h), note="0.5 mm × μ_v, + 0.1 %")
    val = ck.number("results", "omega_2")
    if val is not None:
        exp = seg_exp["ab"] / l_AB
        tol = _rel(tol_v / l_AB, exp)
        v_ba = ck.number("results", "v_BA")
        own = v_ba / l_AB if v_ba is not None else (seg_student["ab"] * mu_v / l_AB if "ab" in seg_student else None)
        seg = seg_student.get("ab", seg_exp["ab"] / mu_v)
        hyps = [("scale_forgotten", seg / l_AB)] + ([] if ratio is None else [("n_as_omega", exp * ratio)])
        ck.value("results.omega_2", "ω_2", "rad/s", exp, val, tol, own=own, own_tol=_rel(tol_v / l_AB, own or 0.0),
                 own_from="the student's v_BA", hypotheses=hyps, hyp_tol=lambda h: _rel(tol_v / l_AB, h),
                 note="0.5 mm × μ_v / AB, + 0.1 %")
    sense = ck.get("results", "omega_2_sense")
    if sense is not None:
        if p.plan_variant is not None:
            exp_sense = p.plan_variant.answers()["omega_2_sense"]
        else:
            assert p.case is not None
            k = int(ck.get("velocity_plan", "position"))
            m = int(ck.get("velocity_plan", "positions", 12))
            w2 = float(p.case.mechanism.velocity_plans(p.case.mechanism.positions(m=m),
                                                        omega_1=p.case.omega_m).omega("AB")[k])
            exp_sense = "ccw" if w2 > 0 else "cw"
        ck.position("results.omega_2_sense", "sense of ω_2", [exp_sense], str(sense).strip().lower())


def _em_data(ck: _Checker, p: LinkageData) -> tuple[np.ndarray, np.ndarray, float, float]:
    """(J_e, ΔT, n_rpm, δ) of the energy–mass diagram the student drew."""
    if p.em_variant is not None:
        v = p.em_variant
        return np.asarray(v.J_e, dtype=float), np.asarray(v.delta_T, dtype=float), v.n_rpm, v.delta_value
    from graphmethods.dynamics.study import Study

    m = ck.get("energy_mass", "positions", 12)
    if isinstance(m, (str, tuple)) or not float(m).is_integer() or m < 3:
        raise InputError("[energy_mass] positions must be the number of positions m (an integer ≥ 3)")
    assert p.case is not None
    study = Study(p.case, positions=int(m), estimate=False)
    return np.asarray(study.J_e, dtype=float), np.asarray(study.delta_T, dtype=float), p.case.n_rpm, p.case.delta


def _support(J, T, a_max: float, a_min: float):
    """Intercepts (J, at J_e = 0) of the support lines of slopes a_max (above) and a_min (below)."""
    return float(np.max(T - a_max * J)), float(np.min(T - a_min * J))


def _touching(J, T, a: float, b: float, *, mu_J: float, mu_T: float, upper: bool) -> list[int]:
    """Vertices within 0.5 mm (on paper) of the line ΔT = b + a·J (positions 0…m−1)."""
    x, y = J / mu_J, T / mu_T
    slope = a * mu_J / mu_T
    dist = np.abs(y - (b / mu_T + slope * x)) / math.hypot(1.0, slope)
    return [int(i) for i in np.flatnonzero(dist[:-1] <= TOL_MM)]


def _check_em(ck: _Checker, p: LinkageData) -> None:
    J, T, n_rpm, d = _em_data(ck, p)
    mu_J = ck.need("energy_mass", "mu_J", "kg·m² per mm of the energy–mass diagram")
    mu_T = ck.need("energy_mass", "mu_T", "J per mm of the energy–mass diagram")
    w = omega_from_n(n_rpm)
    c = mu_J / (2 * mu_T)
    exact = (c * w * w * (1 + d / 2) ** 2, c * w * w * (1 - d / 2) ** 2)
    textbook = (c * w * w * (1 + d), c * w * w * (1 - d))
    wrong_d = (c * w * w * (1 + d) ** 2, c * w * w * (1 - d) ** 2)
    tans_student = []
    for k, key in enumerate(("tan_psi_max", "tan_psi_min")):
        val = ck.number("energy_mass", key)
        tans_student.append(val)
        if val is None:
            continue
        exp = exact[k] if abs(val - exact[k]) <= abs(val - textbook[k]) else textbook[k]
        f = (1 + d / 2) ** 2 if k == 0 else (1 - d / 2) ** 2
        hyps: list[tuple[Any, ...]] = [("delta_not_halved", wrong_d[k]), ("n_as_omega", c * n_rpm ** 2 * f),
                ("scale_forgotten", w * w * f / 2)]
        ck.value(f"energy_mass.{key}", key.replace("tan_psi_", "tan ψ_"), "", exp, val, _rel(0.0, exp),
                 hypotheses=hyps, hyp_tol=lambda h: _rel(0.0, h), note="0.1 % ((1 ± δ/2)² or (1 ± δ))")
    a_max, a_min = 0.5 * w * w * (1 + d / 2) ** 2, 0.5 * w * w * (1 - d / 2) ** 2     # J/(kg·m²)
    b_up, b_lo = _support(J[:-1], T[:-1], a_max, a_min)
    kl_exp = (b_up - b_lo) / mu_T
    own_slopes = None
    if all(t is not None for t in tans_student):
        own_slopes = (tans_student[0] * mu_T / mu_J, tans_student[1] * mu_T / mu_J)
    kl_s = ck.number("energy_mass", "kl_mm")
    if kl_s is not None:
        own = None
        if own_slopes is not None:
            ou, ol = _support(J[:-1], T[:-1], *own_slopes)
            own = (ou - ol) / mu_T
        base = own_slopes or (a_max, a_min)
        bu, bl = _support(J[:-1], T[:-1], *base)
        J_min = float(J.min())
        hyps = [("J_e_not_subtracted", ((bu + base[0] * J_min) - (bl + base[1] * J_min)) / mu_T)]
        wu, wl = _support(J[:-1], T[:-1], 0.5 * w * w * (1 + d) ** 2, 0.5 * w * w * (1 - d) ** 2)
        hyps.append(("delta_not_halved", (wu - wl) / mu_T))
        ck.value("energy_mass.kl_mm", "kl", "mm", kl_exp, kl_s, TOL_MM, own=own, own_from="the student's tan ψ",
                 hypotheses=hyps, note="±0.5 mm")
    for which, key in (("max", "omega_max_at"), ("min", "omega_min_at")):
        s = ck.get("energy_mass", key)
        if s is None:
            continue
        upper = which == "max"
        a = a_max if upper else a_min
        acc = _touching(J, T, a, b_up if upper else b_lo, mu_J=mu_J, mu_T=mu_T, upper=upper)
        own_acc = None
        if own_slopes is not None:
            ou, ol = _support(J[:-1], T[:-1], *own_slopes)
            own_acc = _touching(J, T, own_slopes[0 if upper else 1], ou if upper else ol, mu_J=mu_J, mu_T=mu_T,
                                upper=upper)
        ck.position(f"energy_mass.{key}", f"position of ω_{which}", acc, s, own_accepted=own_acc,
                    own_from="the student's rays")
    J_s = ck.number("results", "J_F")
    if J_s is not None:
        J_exp = mu_T * kl_exp / (w * w * d)
        tol_abs = mu_T * TOL_MM / (w * w * d)
        kl_base = kl_exp if kl_s is None else kl_s
        own = None if kl_s is None else mu_T * kl_s / (w * w * d)
        hyps = []
        for code, factor in (("n_as_omega", mu_T / (n_rpm ** 2 * d)), ("scale_forgotten", 1.0 / (w * w * d)),
                             ("delta_not_halved", mu_T / (2 * w * w * d)),
                             ("degrees_as_radians", mu_T / ((6 * n_rpm) ** 2 * d))):
            h = factor * kl_base
            hyps.append((code, h, factor * TOL_MM + TOL_REL * abs(h)))
        ck.value("results.J_F", "J_F", "kg·m²", J_exp, J_s, _rel(tol_abs, J_exp), own=own,
                 own_tol=_rel(tol_abs, own or 0.0), own_from="the student's kl", hypotheses=hyps,
                 note="μ_T·0.5 mm/(ω_m²δ), + 0.1 %")


def _page_of(answers: dict) -> Page:
    sec = answers.get("page", {})
    size = str(sec.get("size", "A4"))
    orientation = str(sec.get("orientation", "landscape"))
    try:
        return Page(size, orientation, frame=False)
    except InputError as exc:
        raise InputError(f"[page]: {exc}") from None


def check(problem, answers) -> CheckReport:
    """Check a student's answers against a problem.

    Parameters
    ----------
    problem : str or CycleData or LinkageData
        A built-in id (``W1`` … ``W4``, ``press``), a worksheet id ``KIND:SEED:N``, a problem file path,
        or the result of :func:`load_problem`.
    answers : dict or path
        The answers (a dict shaped like :data:`SCHEMA`, or a TOML file).

    Returns
    -------
    CheckReport
    """
    data = problem if isinstance(problem, (CycleData, LinkageData)) else load_problem(problem)
    if isinstance(answers, (str, pathlib.Path)):
        answers = read_answers(answers)
    else:
        answers = validate_answers(answers)
    ck = _Checker(answers)
    if isinstance(data, CycleData):
        for sec in ("velocity_plan", "energy_mass", "acceleration_plan"):
            if sec in answers:
                raise InputError(f"[{sec}] does not belong to {data.id}, a cycle problem (areas, works, moments)")
        for key in ("v_A", "v_B", "v_BA", "v_S2", "omega_2", "omega_2_sense"):
            if key in answers.get("results", {}):
                raise InputError(f"[results] {key} does not belong to {data.id}, a cycle problem")
        _check_cycle(ck, data)
    else:
        for sec in ("moment_diagram", "energy_indicator"):
            if sec in answers:
                raise InputError(f"[{sec}] is not checked for {data.id}, a linkage problem; use [velocity_plan] and "
                                 f"[energy_mass]")
        if data.accel_variant is not None or (data.case is not None and data.case.kind != "slider_crank"):
            for sec in ("velocity_plan", "energy_mass"):
                if sec in answers:
                    raise InputError(f"[{sec}] is not checked for {data.id}; its plan is checked in [acceleration_plan]")
        if "acceleration_plan" in answers:
            ca.check_acceleration(ck, data)
        if "velocity_plan" in answers:
            if data.em_variant is not None:
                raise InputError(f"[velocity_plan]: {data.id} gives a table of J_e and ΔT, no linkage to draw")
            _check_plan(ck, data)
        if "energy_mass" in answers or "J_F" in answers.get("results", {}):
            if data.plan_variant is not None:
                raise InputError(f"[energy_mass]: {data.id} is a velocity-plan problem")
            if "energy_mass" not in answers:
                raise InputError("J_F of a linkage problem is checked with the [energy_mass] diagram's scales; "
                                 "add the section with mu_J and mu_T")
            _check_em(ck, data)
    if not ck.items:
        raise InputError("the answers hold nothing to check; fill in what was measured (a blank answers file: "
                         "KIND-answers.toml, written by graphmethods worksheet)")
    for it in ck.items:               # results are checked finite before they are reported
        for what, v in (("expected", it.expected), ("student", it.student), ("tolerance", it.tolerance)):
            if isinstance(v, float) and not math.isfinite(v):
                raise InputError(f"{it.key}: the {what} value came out {v}: the answers' scales lie outside the "
                                 f"range the check can compute with; give scales of less extreme magnitude")
    named = answers.get("problem")
    if named and named.strip().lower() != str(data.id).lower():
        ck.notes.append(f"the answers file names problem {named!r}; checked against {data.id}")
    return CheckReport(str(data.id), data.title, answers.get("student", ""), tuple(ck.items), _page_of(answers),
                       tuple(ck.notes), data=data, answers=answers)


# ----------------------------------------------------------------------------- overlay

def _wrong_index(report: CheckReport, prefix: str) -> dict:
    out = {}
    for it in report.items:
        if it.verdict != "ok" and it.key.startswith(prefix) and it.key.endswith("]"):
            out[int(it.key[len(prefix) + 1:-1])] = it.student
    return out


_KEY = re.compile(r"(\w+)\.(\w+?)(?:\[(\d+)\])?")
_SYMBOL_LABELS = {"omega_max": "ω_{max}", "omega_min": "ω_{min}", "omega_2": "ω_{2}", "v_A": "v_{A}", "v_B": "v_{B}",
                  "v_BA": "v_{BA}", "v_S2": "v_{S2}", "pa_mm": "pa", "pb_mm": "pb", "ab_mm": "ab", "ps2_mm": "ps_{2}",
                  "kl_mm": "kl"}


def _overlay_label(it: Item, report: CheckReport, nt) -> str:
    """An item's label in the overlay's notation (markup), made from its key (``Item.label`` is English)."""
    m = _KEY.fullmatch(it.key)
    section, name, idx = (m.group(1), m.group(2), m.group(3)) if m else ("", "", None)
    per_interval = {"areas_mm2": ("area", "n_areas"), "works_J": ("work", "n_works"),
                    "arrows_mm": ("arrow", "n_arrows")}
    if name in per_interval:
        if idx is None:
            return _w(nt, per_interval[name][1])
        assert isinstance(report.data, CycleData)       # per-interval keys belong to cycle problems
        L = report.data.cycle.labels
        i = int(idx)
        return _w(nt, per_interval[name][0], i=ws.markup.literal(f"{L[i]}–{L[i + 1]}"))
    if name in ("omega_max_at", "omega_min_at"):
        omega = f"ω_{{{name[6:9]}}}"
        if section == "energy_mass":
            return _w(nt, "position_of", omega=omega)
        return _w(nt, "angle_of" if it.unit == "°" else "point_of", omega=omega)
    if name == "omega_2_sense":
        return _w(nt, "sense_of", omega="ω_{2}")
    if section == "acceleration_plan":
        return ca.item_label(it.key, lambda key, **kw: _w(nt, key, **kw))
    if name in ("tan_psi_max", "tan_psi_min"):
        return f"{ws.sym('tan', nt)} ψ_{{{name[-3:]}}}"
    if name in ("delta_W_max", "M_d", "omega_m", "J_F"):
        return ws.sym(name, nt)
    if name in _SYMBOL_LABELS:
        return _SYMBOL_LABELS[name]
    return ws.markup.literal(it.label)


def _overlay_value(v, nt) -> str:
    """A value of the list of wrong items: a number in the notation's style, or a position (``"b or c"``,
    a sense ``"cw"``) in its words."""
    if not isinstance(v, str):
        return ws.num(v, nt)
    parts = [ws.word(p, nt) if p in ("cw", "ccw") else ws.markup.literal(p) for p in v.split(" or ")]
    text = parts[0]
    for p in parts[1:]:
        text = _w(nt, "or", a=text, b=p)
    return text


def _wrong_line(it: Item, report: CheckReport, nt) -> str:
    """One line of the overlay's red list: label, the student's value, the expected one, the unit, and why."""
    if it.mistakes:
        sep = "、" if get_notation(nt).code == "zh" else ", "
        why = sep.join(_w(nt, code, J_e=ws.sym("J_e", nt)) for code in it.mistakes)
    else:
        why = _w(nt, "carried" if it.verdict == "carried" else "wrong")
    text = _w(nt, "item", label=_overlay_label(it, report, nt), student=_overlay_value(it.student, nt),
              expected=_overlay_value(it.expected, nt), unit=ws.unit(it.unit, nt), why=why)
    return re.sub(" {2,}", " ", text)


def _overlay(report: CheckReport, notation) -> Scene:
    from graphmethods.scene.elements import Frame
    from graphmethods.sheets.layout import Occupancy

    nt = get_notation(notation)
    page = report.page
    W, H = page.width_mm, page.height_mm
    a = report.answers
    data = report.data
    els: list[Element] = []
    red = ws.RED
    rest = f"{report.problem} — {Title.of(report.title).title_in(nt.code)}" + (
        f" — {report.student}" if report.student else "")
    title = _w(nt, "heading", overlay=_w(nt, "overlay"), rest=ws.markup.literal(rest))
    y = 12.0
    for line in ws.wrap(title, (W - 24.0) / 1.15, 3.2):          # bold runs wider than the estimate
        els.append(Text((12.0, y), line, size_mm=3.2, bold=True, name="overlay-title"))
        y += 4.5
    y += 0.5
    for line in ws.wrap(_w(nt, "howto", bar=f"100 {ws.unit('mm', nt)}"), W - 24.0, 2.6):
        els.append(Text((12.0, y), line, size_mm=2.6, name="overlay-howto"))
        y += 3.6
    els.append(Line((12.0, H - 8.0), (112.0, H - 8.0), style=Style(width_mm=0.35), name="ruler"))
    for x in (12.0, 62.0, 112.0):
        els.append(Line((x, H - 10.0), (x, H - 6.0), style=Style(width_mm=0.35), name="ruler-tick"))
    els.append(Text((114.0, H - 7.0), f"100 {ws.unit('mm', nt)}", size_mm=2.6, name="ruler-text"))
    # wrong items listed, right-aligned at the right margin (a line too long for the page is broken)
    y += 3.4
    for it in report.items:
        if it.verdict == "ok":
            continue
        for line in ws.wrap(_wrong_line(it, report, nt), W - 24.0, 2.6):
            els.append(ws.ColorText((W - 12.0, y), line, size_mm=2.6, anchor="end", color=red, name="wrong-list"))
            y += 3.8
    slots = _Slots(W, H, top=max(y, 24.0) + 4.0)

    def origin_for(section: str, size: tuple, offset: tuple) -> tuple:
        given = a.get(section, {}).get("origin_mm")
        if given is not None:
            if not (isinstance(given, tuple) and len(given) == 2 and all(not isinstance(v, str) for v in given)):
                raise InputError(f"[{section}] origin_mm must be [x, y] in mm from the page's top-left corner")
            return (float(given[0]), float(given[1]))
        x, y0 = slots.take(*size)
        return (x + offset[0], y0 + offset[1])

    def cross(at, name):
        x, y0 = at
        return ws.Shapes((Path(((x - 4, y0), (x + 4, y0)), Style(width_mm=0.25)),
                          Path(((x, y0 - 4), (x, y0 + 4)), Style(width_mm=0.25)),
                          Circle(x, y0, 2.0, Style(width_mm=0.25))), name=name)

    if isinstance(data, CycleData):
        c = data.cycle
        if "moment_diagram" in a and c.M_d is not None and c.M_r is not None and c.period is not None:
            md = a["moment_diagram"]
            mu_M = float(md["mu_M"])
            mu_phi = float(md["mu_phi"]) if "mu_phi" in md else math.radians(float(md["mu_phi_deg"]))
            M_all = np.concatenate((c.M_d.M, c.M_r.M, [0.0]))
            w_mm = c.period / mu_phi
            hi, lo = float(M_all.max()) / mu_M, float(M_all.min()) / mu_M
            o = origin_for("moment_diagram", (w_mm + 20.0, hi - lo + 16.0), (8.0, hi + 8.0))
            frame = Frame(o, Scale("μ_φ", "rad", mu_phi), Scale("μ_M", "N·m", mu_M))
            occ = Occupancy()
            els.append(Line((o[0], o[1]), (o[0] + w_mm, o[1]), style=Style(width_mm=0.25), name="md-axis-phi"))
            els.append(Line((o[0], o[1] - hi), (o[0], o[1] - lo), style=Style(width_mm=0.25), name="md-axis-M"))
            els += ws.moment_regions(frame, c, wrong=_wrong_index(report, "moment_diagram.areas_mm2"), nt=nt, occ=occ,
                                     name="md")
            els.append(cross(o, "md-origin"))
        if "energy_indicator" in a:
            ei = a["energy_indicator"]
            mu_E = float(ei["mu_E"])
            step = float(ei.get("step_mm", 16.0))
            E = np.asarray(c.E, dtype=float)
            hi, lo = max(E.max(), 0.0) / mu_E, min(E.min(), 0.0) / mu_E
            n = c.work.size
            o = origin_for("energy_indicator", (step * n + 40.0, hi - lo + 16.0), (6.0, hi + 8.0))
            occ = Occupancy()
            first = o[0]
            wrong = _wrong_index(report, "energy_indicator.arrows_mm")
            els += ws.staircase(first, o[1], c.work, mu_E=mu_E, step_mm=step, labels=c.labels, nt=nt, occ=occ,
                                wrong=wrong, name="ei")
            els += ws.extremes(first, o[1], c.work, mu_E=mu_E, step_mm=step, nt=nt, occ=occ, name="ei-ext")
            els.append(cross((first, o[1]), "ei-origin"))
    elif isinstance(data, LinkageData):
        if "velocity_plan" in a:
            vec, l_AB, _, _ = _plan_data(_Checker(a), data)
            mu_v = float(a["velocity_plan"]["mu_v"])
            xs = [float(v[0]) / mu_v for v in vec.values()]
            ys = [-float(v[1]) / mu_v for v in vec.values()]
            size = (max(xs) - min(xs) + 40.0, max(ys) - min(ys) + 30.0)
            o = origin_for("velocity_plan", size, (20.0 - min(xs), 15.0 - min(ys)))
            if data.plan_variant is not None:
                pv = data.plan_variant
                A, B = pv.positions.xy("A")[0], pv.positions.xy("B")[0]
            else:
                k = int(a["velocity_plan"]["position"])
                m = int(a["velocity_plan"].get("positions", 12))
                assert data.case is not None
                pos = data.case.mechanism.positions(m=m)
                A, B = pos.xy("A")[k], pos.xy("B")[k]
            u = (B - A) / np.hypot(*(B - A))
            wrong = {it.key.split(".")[1][:-3]: it.student for it in report.items
                     if it.verdict != "ok" and it.key.startswith("velocity_plan.") and it.key.endswith("_mm")}
            els += ws.velocity_plan(o, vec, mu_v=mu_v, link_dir=u, nt=nt, wrong=wrong, name="plan")
            els.append(cross(o, "plan-pole"))
        if "acceleration_plan" in a:
            pr = ca.problem_of(_Checker(a), data)
            plan = pr.plan()
            mu_a = float(a["acceleration_plan"]["mu_a"])
            xs = [z.real / mu_a for z in plan.images.values()]
            ys = [-z.imag / mu_a for z in plan.images.values()]
            o = origin_for("acceleration_plan", (max(xs) - min(xs) + 40.0, max(ys) - min(ys) + 30.0),
                           (20.0 - min(xs), 15.0 - min(ys)))
            mine = [it for it in report.items if it.key.startswith("acceleration_plan.") and it.key.endswith("_mm")]
            wrong = {it.key.split(".")[1][:-3]: it.student for it in mine if it.verdict == "wrong"}
            carried = [it.key.split(".")[1][:-3] for it in mine if it.verdict == "carried"]
            els += ca.plan_elements(o, plan, mu_a=mu_a, wrong=wrong, carried=carried, nt=nt, name="acc")
            els.append(cross(o, "acc-pole"))
        if "energy_mass" in a:
            from graphmethods.dynamics.wittenbauer import wittenbauer

            J, T, n_rpm, d = _em_data(_Checker(a), data)
            mu_J, mu_T = float(a["energy_mass"]["mu_J"]), float(a["energy_mass"]["mu_T"])
            res = wittenbauer(J_e=J, delta_T=T, omega_m=omega_from_n(n_rpm), delta=d, mu_J=mu_J, mu_T=mu_T)
            hi = max(float(T.max()) / mu_T, res.k_mm, 0.0)
            lo = min(float(T.min()) / mu_T, res.l_mm, 0.0)
            width = float(J.max()) / mu_J + 40.0
            o = origin_for("energy_mass", (width + 30.0, hi - lo + 24.0), (30.0, hi + 12.0))
            box = (max(o[0] - 30.0, 2.0), max(o[1] - hi - 12.0, 2.0), min(W - 2.0, o[0] + width),
                   min(H - 12.0, o[1] - lo + 12.0))
            axes = (Line((o[0], box[1] + 2.0), (o[0], box[3] - 2.0), style=Style(width_mm=0.25), name="em-axis-T"),
                    Line((o[0], o[1]), (o[0] + float(J.max()) / mu_J + 10.0, o[1]), style=Style(width_mm=0.25),
                         name="em-axis-J"))
            els += list(axes) + ws.energy_mass_construction(res, origin=o, box=box, axes=axes, nt=nt, prefix="em-")
            wrong_kl = next((it for it in report.items if it.key == "energy_mass.kl_mm" and it.verdict != "ok"), None)
            if wrong_kl is not None:
                y_student = o[1] - res.k_mm + float(wrong_kl.student)         # where the student's l would be
                els.append(Line((o[0] - 6.0, y_student), (o[0] + 6.0, y_student), style=Style(stroke=red, width_mm=0.45),
                                name="em-kl-student-mark"))
                kl = ws.value_unit(float(wrong_kl.student), "mm", nt)
                els.append(ws.ColorText((o[0] + 8.0, y_student + 1.0), f"kl = {kl}?",
                                        size_mm=2.8, color=red, name="em-kl-student"))
            els.append(cross(o, "em-origin"))
    return Scene(page, tuple(els), title=title, notation=nt.code, name="overlay")


class _Slots:
    """Places constructions on the page left to right, then in the next row (a shelf packer)."""

    def __init__(self, W: float, H: float, *, top: float):
        self.W, self.H = W, H
        self.x, self.y, self.row = 12.0, top, 0.0

    def take(self, w: float, h: float) -> tuple[float, float]:
        if self.x + w > self.W - 8.0 and self.x > 12.0:
            self.x, self.y, self.row = 12.0, self.y + self.row + 6.0, 0.0
        if self.x + w > self.W - 8.0 or self.y + h > self.H - 14.0:
            raise InputError(f"the construction ({w:.0f} × {h:.0f} mm at the student's scales) does not fit the "
                             f"{self.W:.0f} × {self.H:.0f} mm page; give its origin_mm, or a larger [page]")
        at = (self.x, self.y)
        self.x += w + 6.0
        self.row = max(self.row, h)
        return at
