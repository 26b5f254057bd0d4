"""What a student's answers are checked against: a built-in problem, a worksheet variant (by its id or
its problem file), or a problem file, as the data the checks need.
"""

from __future__ import annotations

import json
import pathlib
from dataclasses import dataclass
from typing import TYPE_CHECKING

from graphmethods.errors import InputError
from graphmethods.problems.reference_cases import title_of
from graphmethods.sheets.worksheets.variants import (
    PROBLEM_FORMAT,
    EnergyMassVariant,
    PlanVariant,
    parse_id,
    variant_from_dict,
)
from graphmethods.titles import Title

if TYPE_CHECKING:
    from graphmethods.dynamics.excess_work import ExcessWork
    from graphmethods.kinematics.case import Case

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


PROBLEM_IDS = ("W1", "W2", "W3", "W4", "W4-drawing", "W4-exact", "press", "slotted-lever")


@dataclass(frozen=True, eq=False)
class LinkageData:
    """A slider-crank problem: a case file (press), or worksheet variants (one plan, or a table)."""

    id: str
    title: Title
    case: Case | None = None                  # velocity plan at positions, Study
    plan_variant: PlanVariant | None = None
    em_variant: EnergyMassVariant | None = None
    accel_variant: object | None = None   # worksheets.acceleration_plan.AccelerationPlanVariant


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
    v = parse_id(text)
    if v is None:
        fp = pathlib.Path(text)
        if not fp.exists():
            raise InputError(f"problem {text!r}: not a built-in id ({', '.join(PROBLEM_IDS)}), not a worksheet id "
                             f"KIND:SEED:N, and no such file")
        try:
            data = json.loads(fp.read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
            raise InputError(f"{fp}: not a readable JSON problem file ({exc})") from None
        if isinstance(data, dict) and data.get("format") == PROBLEM_FORMAT:
            v = variant_from_dict(data, source=str(fp))
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


