"""Checking a class at once: a folder of answers files and drawings, one per student, checked one by one
as ``graphmethods check`` does, gathered in one table of students × items.

Each file names its student and problem inside (``student = …``, ``problem = …`` in an answers file), or
in its name ``STUDENT__PROBLEM.toml`` (a worksheet id's colons written as underscores:
``ivanov__indicator_7_3.toml`` is problem ``indicator:7:3``), or the problem is given for the whole
class. Drawings (``.dxf``, ``.svg``) are read by :mod:`graphmethods.sheets.check.cad`.

A file that cannot be read or checked is reported (its row says why) and the others are still checked.

Scores: an item ``ok`` counts 1, ``carried`` (follows from the student's own earlier error) ½, ``wrong``
0; the score is their sum over the items the student answered.

>>> import pathlib
>>> answers = pathlib.Path(__file__).parents[2] / "problems" / "data" / "answers"
>>> cls = check_class([answers / "w1_correct.toml", answers / "w1_mistakes.toml"])
>>> [(s.student, s.score_text) for s in cls.submissions]
[('Example student (correct)', '21/21'), ('Example student (mistakes)', '9.5/14')]
"""

from __future__ import annotations

import csv
import html
import io
import pathlib
import re
from collections.abc import Callable
from dataclasses import dataclass, field

from graphmethods.errors import GraphmethodsError, InputError
from graphmethods.sheets.check.checking import check
from graphmethods.sheets.check.report import CheckReport
from graphmethods.sheets.check.typed_answers import read_answers

#: file kinds checked: answers files, and drawings made in CAD
ANSWER_SUFFIXES = (".toml",)
DRAWING_SUFFIXES = (".dxf", ".svg")
#: points per verdict
POINTS = {"ok": 1.0, "carried": 0.5, "wrong": 0.0}


def _num(x: float) -> str:
    return f"{x:g}"


@dataclass(frozen=True, eq=False)
class Submission:
    """One student's file and what its check gave (``report``), or why it could not be checked (``error``)."""

    path: pathlib.Path
    student: str
    problem: str
    report: CheckReport | None = None
    error: str | None = None

    @property
    def points(self) -> float:
        return 0.0 if self.report is None else sum(POINTS[i.verdict] for i in self.report.items)

    @property
    def n_items(self) -> int:
        return 0 if self.report is None else len(self.report.items)

    @property
    def score_text(self) -> str:
        """``points/items`` (``"—"`` when the file could not be checked)."""
        return "—" if self.report is None else f"{_num(self.points)}/{self.n_items}"

    @property
    def percent(self) -> float | None:
        return None if not self.n_items else 100.0 * self.points / self.n_items


@dataclass(frozen=True, eq=False)
class ClassReport:
    """The checks of a class: one :class:`Submission` per file, in file-name order."""

    submissions: tuple[Submission, ...]
    columns: tuple[tuple[str, str], ...] = field(default=())     # (item key, label) in order of first appearance

    def __post_init__(self):
        if not self.columns:
            seen: dict[str, str] = {}
            for s in self.submissions:
                for it in (s.report.items if s.report else ()):
                    seen.setdefault(it.key, it.label)
            object.__setattr__(self, "columns", tuple(seen.items()))

    @property
    def failed(self) -> tuple[Submission, ...]:
        """The files that could not be checked."""
        return tuple(s for s in self.submissions if s.report is None)

    @property
    def all_ok(self) -> bool:
        return not self.failed and all(s.report is not None and s.report.ok for s in self.submissions)

    def exit_status(self) -> int:
        """0 every item of every student right; 1 some item wrong or carried; 3 some file could not be checked."""
        if self.failed:
            return 3
        return 0 if self.all_ok else 1

    @staticmethod
    def cell(s: Submission, key: str, lang: str = "en") -> str:
        """A table cell: the verdict of item ``key`` in words, the mistakes named (``""`` when not answered)."""
        from graphmethods.sheets.check.wording import notation_of, verdict_text

        if s.report is None:
            return ""
        for it in s.report.items:
            if it.key == key:
                return verdict_text(it, notation_of(lang))
        return ""

    def rows(self, lang: str = "en") -> list[list[str]]:
        """Header row, then one row per student: file, student, problem, score, per cent, the items, error."""
        from graphmethods.sheets.check.wording import item_label, notation_of, word

        nt = notation_of(lang)
        labels = []
        for key, label in self.columns:
            first = next((it for s in self.submissions if s.report for it in s.report.items if it.key == key), None)
            sub = next((s for s in self.submissions if s.report and first in s.report.items), None)
            labels.append(item_label(first, sub.report, nt) if first is not None and sub and sub.report else label)
        head = ([word(nt, "col_file"), word(nt, "col_name"), word(nt, "col_problem"), word(nt, "col_score"), "%"]
                + labels + [word(nt, "col_error")])
        out = [head]
        for s in self.submissions:
            pct = s.percent
            out.append([s.path.name, s.student, s.problem, s.score_text, "" if pct is None else f"{pct:.0f}"]
                       + [self.cell(s, k, lang) for k, _ in self.columns] + [s.error or ""])
        return out

    def summary(self, lang: str = "en") -> str:
        from graphmethods.sheets.check.wording import notation_of, word

        n = len(self.submissions)
        n_ok = sum(1 for s in self.submissions if s.report is not None and s.report.ok)
        if lang == "en":
            text = f"{n} file{'s' if n != 1 else ''}: {n_ok} all correct, {n - n_ok - len(self.failed)} with mistakes"
            return text + (f", {len(self.failed)} could not be checked" if self.failed else "")
        nt = notation_of(lang)
        text = word(nt, "class_summary", n=n, ok=n_ok, bad=n - n_ok - len(self.failed))
        sep = "，" if lang == "zh" else ", "
        return text + (sep + word(nt, "class_failed", n=len(self.failed)) if self.failed else "")

    # -- output
    def to_csv(self, lang: str = "en", *, sep: str = ",") -> str:
        """The table as CSV (``sep``-separated, quoted where needed), every text cell that a spreadsheet would
        take for a formula (``=``, ``+``, ``-``, ``@`` first) prefixed with ``'``.

        >>> safe_cell("=HYPERLINK(1)"), safe_cell("-3"), safe_cell("ok")
        ("'=HYPERLINK(1)", '-3', 'ok')
        """
        buf = io.StringIO()
        csv.writer(buf, delimiter=sep, lineterminator="\r\n").writerows(
            [[safe_cell(c) for c in r] for r in self.rows(lang)])
        return buf.getvalue()

    def csv_bytes(self, lang: str = "en", *, sep: str = ",") -> bytes:
        """:meth:`to_csv` as UTF-8 with a byte-order mark, the way Excel recognises UTF-8 (without it, Cyrillic
        and Chinese names show as mojibake); ``sep=";"`` for the locales whose Excel splits on ``;``."""
        return self.to_csv(lang, sep=sep).encode("utf-8-sig")

    def to_markdown(self, lang: str = "en") -> str:
        """The table as CommonMark (a blank line around the table and each paragraph), then the summary."""
        from graphmethods.sheets.check.wording import notation_of, word

        nt = notation_of(lang)
        ok = word(nt, "ok")
        rows = self.rows(lang)
        n_items = len(self.columns)

        def esc(c: str) -> str:
            return c.replace("|", "\\|").replace("\n", " ")
        lines = [f"# {word(nt, 'class_check')}", "", "| " + " | ".join(esc(c) for c in rows[0]) + " |",
                 "|" + "|".join("---" for _ in rows[0]) + "|"]
        for r in rows[1:]:
            lines.append("| " + " | ".join(f"**{esc(c)}**" if 5 <= k < 5 + n_items and c and c != ok else esc(c)
                                           for k, c in enumerate(r)) + " |")
        lines += ["", word(nt, "result", summary=self.summary(lang)), "", word(nt, "scores")]
        return "\n".join(lines) + "\n"

    def to_html(self, *, title: str | None = None, lang: str = "en") -> str:
        """A self-contained HTML page in ``lang`` (no scripts, no external files): the table, then each
        student's report."""
        from graphmethods.sheets.check.wording import notation_of, word

        nt = notation_of(lang)
        title = title or word(nt, "class_check")
        rows = self.rows(lang)
        e = html.escape
        css = ("body{font-family:'DejaVu Sans',Arial,sans-serif;margin:2em;color:#111}"
               "table{border-collapse:collapse;font-size:0.9em}td,th{border:1px solid #999;padding:0.25em 0.5em;"
               "vertical-align:top}th{background:#eee}td.ok{background:#e3f4e3}td.carried{background:#fdf3d0}"
               "td.wrong{background:#f8d7d7;font-weight:bold}td.error{color:#a00}td.num{text-align:right}"
               "pre{background:#f6f6f6;padding:0.8em;overflow-x:auto}")
        out = ["<!DOCTYPE html>", f'<html lang="{e(lang)}">', "<head>", '<meta charset="utf-8">',
               f"<title>{e(title)}</title>", f"<style>{css}</style>", "</head>", "<body>", f"<h1>{e(title)}</h1>",
               f"<p>{e(self.summary(lang))}. {e(word(nt, 'scores'))}</p>", "<table>",
               "<tr>" + "".join(f"<th>{e(c)}</th>" for c in rows[0]) + "</tr>"]
        n_items = len(self.columns)
        for s, r in zip(self.submissions, rows[1:]):
            verdicts = {it.key: it.verdict for it in (s.report.items if s.report else ())}
            cells = []
            for k, c in enumerate(r):
                cls = ""
                if 5 <= k < 5 + n_items and c:
                    cls = verdicts.get(self.columns[k - 5][0], "")
                elif k in (3, 4):
                    cls = "num"
                elif k == len(r) - 1 and c:
                    cls = "error"
                cells.append(f'<td class="{cls}">{e(c)}</td>' if cls else f"<td>{e(c)}</td>")
            out.append("<tr>" + "".join(cells) + "</tr>")
        out.append("</table>")
        for s in self.submissions:
            out.append(f"<h2>{e(s.student)} — {e(s.path.name)}</h2>")
            body = (s.report.to_text(lang) if s.report is not None else word(nt, "not_checked", why=s.error or ""))
            out.append(f"<pre>{e(body)}</pre>")
        out += ["</body>", "</html>"]
        return "\n".join(out) + "\n"


_NUMBER_CELL = re.compile(r"^[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?$")


def safe_cell(text: str) -> str:
    """A CSV cell a spreadsheet shows as text: one that starts with ``=``, ``+``, ``-``, ``@``, a tab or a
    carriage return (and is not a plain number) gets a leading ``'``, so ``=HYPERLINK(…)`` is no formula."""
    if text and text[0] in "=+-@\t\r" and not _NUMBER_CELL.match(text):
        return "'" + text
    return text


def class_files(directory) -> list[pathlib.Path]:
    """The answers files and drawings in ``directory`` (not in subfolders), sorted by name.

    Raises
    ------
    InputError
        If ``directory`` is not a folder, or holds no such file.
    """
    d = pathlib.Path(directory)
    if not d.is_dir():
        raise InputError(f"{d}: not a folder; give the folder of the students' answers files and drawings")
    found = sorted(p for p in d.iterdir() if p.is_file() and p.suffix.lower() in ANSWER_SUFFIXES + DRAWING_SUFFIXES
                   and not p.name.startswith("."))
    if not found:
        raise InputError(f"{d}: no answers files (*.toml) or drawings (*.dxf, *.svg) in it")
    return found


_WORKSHEET_ID = re.compile(r"^([a-z][a-z-]*)_(\d+)_(\d+)$")


def names_from_file_name(path) -> tuple[str, str | None]:
    """(student, problem or None) from a file name ``STUDENT__PROBLEM.ext`` (underscores of a worksheet id
    stand for its colons); without ``__`` the whole stem is the student.

    >>> names_from_file_name("ivanov_a__indicator_7_3.toml"), names_from_file_name("petrova.dxf")
    (('ivanov_a', 'indicator:7:3'), ('petrova', None))
    >>> names_from_file_name("li__press.svg")
    ('li', 'press')
    """
    stem = pathlib.Path(path).stem
    if "__" not in stem:
        return stem, None
    student, problem = stem.rsplit("__", 1)
    m = _WORKSHEET_ID.match(problem)
    if m:
        problem = f"{m.group(1)}:{m.group(2)}:{m.group(3)}"
    return student, problem


def check_file(path, *, problem: str | None = None) -> Submission:
    """Check one student's file (an answers file or a drawing); errors become the submission's ``error``."""
    path = pathlib.Path(path)
    student, from_name = names_from_file_name(path)
    # a file name that is not valid UTF-8 (its bytes kept as surrogates): shown with replacement characters
    student = student.encode("utf-8", "surrogateescape").decode("utf-8", "replace")
    named = problem or from_name
    report: CheckReport
    try:
        from graphmethods.sheets.check import cam

        if named is not None and cam.is_cam_problem(named):      # a cam profile: a drawing or a [cam] answers file
            report = (cam.check_drawing(named, path) if path.suffix.lower() in DRAWING_SUFFIXES
                      else cam.check_cam_answers(named, path))
            return Submission(path, report.student or student, str(named), report=report)
        if path.suffix.lower() in DRAWING_SUFFIXES:
            from graphmethods.sheets.check import cad

            if named is None:
                raise InputError("no problem: name the file STUDENT__PROBLEM" + path.suffix + " or give --problem")
            report = cad.check_drawing(named, path)
        else:
            answers = read_answers(path)
            named = problem or answers.get("problem") or from_name
            if not named:
                raise InputError("no problem: write problem = \"…\" in the file, name it STUDENT__PROBLEM.toml, "
                                 "or give --problem")
            if not problem and answers.get("problem"):
                named = answers["problem"]
            report = check(named, answers)
            if answers.get("student"):
                student = answers["student"]
        return Submission(path, student, str(named), report=report)
    except GraphmethodsError as exc:
        return Submission(path, student, str(named or ""), error=str(exc))
    except (OSError, UnicodeDecodeError, ValueError, ArithmeticError, LookupError, TypeError, AttributeError,
            RecursionError) as exc:      # a file no reader could make sense of: its row says so, the class goes on
        why = " ".join(f"{type(exc).__name__}: {exc}".split())[:300]
        return Submission(path, student, str(named or ""), error=why)


def check_class(files, *, problem: str | None = None,
                progress: Callable[[int, int, Submission], None] | None = None) -> ClassReport:
    """Check every file (see :func:`class_files`); ``progress(i, n, submission)`` is called after each."""
    files = list(files)
    subs = []
    for i, f in enumerate(files, 1):
        s = check_file(f, problem=problem)
        subs.append(s)
        if progress is not None:
            progress(i, len(files), s)
    return ClassReport(tuple(subs))
