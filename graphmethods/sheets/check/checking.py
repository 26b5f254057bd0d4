"""One check: a student's answers against a problem, section by section.
"""

from __future__ import annotations

import math
import pathlib
from typing import TYPE_CHECKING

from graphmethods.errors import InputError
from graphmethods.scene import Page
from graphmethods.sheets.check import acceleration as ca
from graphmethods.sheets.check.hypotheses import check_cycle, check_em, check_plan
from graphmethods.sheets.check.problems import CycleData, LinkageData, load_problem
from graphmethods.sheets.check.report import Checker, CheckReport
from graphmethods.sheets.check.typed_answers import read_answers, validate_answers

if TYPE_CHECKING:
    pass

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
    ck = Checker(answers)
    if isinstance(data, CycleData):
        for sec in ("velocity_plan", "energy_mass", "acceleration_plan"):
            if sec in answers:
                raise InputError(f"[{sec}] does not belong to {data.id}, a cycle problem (areas, works, moments)")
        for key in ("v_A", "v_B", "v_BA", "v_S2", "omega_2", "omega_2_sense"):
            if key in answers.get("results", {}):
                raise InputError(f"[results] {key} does not belong to {data.id}, a cycle problem")
        check_cycle(ck, data)
    else:
        for sec in ("moment_diagram", "energy_indicator"):
            if sec in answers:
                raise InputError(f"[{sec}] is not checked for {data.id}, a linkage problem; use [velocity_plan] and "
                                 f"[energy_mass]")
        if data.accel_variant is not None or (data.case is not None and data.case.kind != "slider_crank"):
            for sec in ("velocity_plan", "energy_mass"):
                if sec in answers:
                    raise InputError(f"[{sec}] is not checked for {data.id}; its plan is checked in "
                                     f"[acceleration_plan]")
        if "acceleration_plan" in answers:
            ca.check_acceleration(ck, data)
        if "velocity_plan" in answers:
            if data.em_variant is not None:
                raise InputError(f"[velocity_plan]: {data.id} gives a table of J_e and ΔT, no linkage to draw")
            check_plan(ck, data)
        if "energy_mass" in answers or "J_F" in answers.get("results", {}):
            if data.plan_variant is not None:
                raise InputError(f"[energy_mass]: {data.id} is a velocity-plan problem")
            if "energy_mass" not in answers:
                raise InputError("J_F of a linkage problem is checked with the [energy_mass] diagram's scales; "
                                 "add the section with mu_J and mu_T")
            check_em(ck, data)
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


