"""The report of a check (items with verdicts, the usual mistakes diagnosed, the text, Markdown and
JSON forms) and the checker that judges each item against the tolerances.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import Page, Scene
from graphmethods.sheets.check import acceleration as ca
from graphmethods.sheets.check.tolerances import TOL_REL
from graphmethods.titles import Title
from graphmethods.units import json_text

if TYPE_CHECKING:
    from graphmethods.sheets.check.problems import CycleData, LinkageData

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
        names = self.mistake_names()
        return tuple(Mistake(c, names[c], tuple(by[c])) for c in order)

    def mistake_names(self) -> dict[str, str]:
        """The names of the mistakes this kind of check diagnoses, by code (:data:`MISTAKES`)."""
        return MISTAKES

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
        return json_text(self.to_dict(), indent=1)

    def to_text(self, lang: str = "en") -> str:
        """Aligned plain text in ``lang`` (en, ru, zh): one line per item with its verdict in words, then the
        mistakes, the carried items and the summary (:func:`graphmethods.sheets.check.wording.report_text`)."""
        from graphmethods.sheets.check.wording import report_text

        return report_text(self, lang)

    def to_markdown(self, lang: str = "en") -> str:
        """A CommonMark table of the items, then the mistakes and the summary, in ``lang``."""
        from graphmethods.sheets.check.wording import report_markdown

        return report_markdown(self, lang)

    def _repr_markdown_(self) -> str:          # a notebook shows the report
        return self.to_markdown()

    def overlay(self, *, notation="en") -> Scene:
        """The correct construction at the student's scales on a page the size of theirs, to print 1:1 on
        film; the student's wrong items in red.

        Parameters
        ----------
        notation : str or Notation
            ``"en"``, ``"ru"`` or ``"zh"``: the symbols, units, number style and words of everything the
            overlay draws (heading, how to print it, the list of wrong items with the names of the
            mistakes, see :data:`WORDS`). The text and Markdown reports take the language as ``lang``.

        Returns
        -------
        Scene

        Examples
        --------
        >>> from graphmethods.render.recording import record
        >>> from graphmethods.sheets.check import check
        >>> rep = check("W1", {"energy_indicator": {"mu_E": 5.0, "arrows_mm": [-10, 110, 20, 25, -100, 5, -10]}})
        >>> [t for t in record(rep.overlay(notation="ru")).texts() if t.startswith("вектор")]
        ['вектор c–d: 20 (должно быть −20) мм — перепутан знак избыточной работы']
        """
        from graphmethods.sheets.check.overlay import overlay

        return overlay(self, notation)


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

class Checker:
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


def rel(tol_abs: float, value: float) -> float:
    """The tolerance of a value read off a drawing: the drafting one plus :data:`TOL_REL` of the value.

    Parameters
    ----------
    tol_abs : float
        The absolute tolerance, in the value's unit (mm on paper, or that times a scale).
    value : float
        The expected value, same unit.

    Examples
    --------
    >>> rel(0.5, 120.0)
    0.62
    """
    return tol_abs + TOL_REL * abs(value)


def levels_accepted(E, labels, tol: float, which: str) -> list[str]:
    """Labels whose level is within ``tol`` of the extreme (the first and last point are one point)."""
    E = np.asarray(E, dtype=float)
    ext = E.max() if which == "max" else E.min()
    idx = [k for k in range(E.size) if abs(E[k] - ext) <= tol + 1e-9 * max(1.0, abs(ext))]
    if 0 in idx or E.size - 1 in idx:
        idx = sorted(set(idx) | {0, E.size - 1})
    return [labels[k] for k in idx]


