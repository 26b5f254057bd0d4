"""A check's report in the user's language (en, ru, zh): the text and Markdown forms, the verdicts as words.

The words are those of the overlay (the vocabulary's ``check`` family): an item is labelled as the
overlay labels it (``вектор c–d``), its verdict is ``correct``, ``carried over`` or ``wrong`` followed by
the usual mistakes it shows, named (``wrong: n (rev/min) used as ω (rad/s)``), never their codes. The JSON
form keeps the codes (``"verdict": "wrong"``, ``"mistakes": ["n_as_omega"]``) for programs.

Markdown is CommonMark: a blank line before and after every list and table, so that each renderer
(GitHub, Jupyter, pandoc) shows the lists as lists.

>>> from graphmethods.sheets.check import check
>>> rep = check("W1", {"energy_indicator": {"mu_E": 5.0, "arrows_mm": [-10, 110, 20, 25, -100, 5, -10]}})
>>> [line for line in report_text(rep, "ru").splitlines() if line.startswith("вектор c–d")][0].split("  ")[-1].strip()
'неверно: перепутан знак избыточной работы'
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from graphmethods.scene import markup, notation as get_notation
from graphmethods.scene.notation import Notation

if TYPE_CHECKING:
    from graphmethods.sheets.check.report import CheckReport, Item

#: languages a report is written in
LANGS = ("en", "ru", "zh")
_COLUMNS = ("col_item", "col_expected", "col_student", "col_deviation", "col_tolerance", "col_unit", "col_verdict")


def notation_of(lang: str | Notation | None) -> Notation:
    """The notation of a report's language (``"en"``, ``"ru"``, ``"zh"``)."""
    return get_notation(lang or "en")


def decimal(text: str, nt: Notation) -> str:
    """``text`` with the notation's decimal separator between digits (``62.83`` -> ``62,83`` in ru)."""
    return text if nt.decimal == "." else re.sub(r"(?<=\d)\.(?=\d)", nt.decimal, text)


def word(nt: Notation, key: str, **fill: object) -> str:
    """A word of the check family as plain text (subscripts after ``_``; fills are taken literally)."""
    return markup.typed(nt.word("check." + key, **{k: markup.literal(str(v)) for k, v in fill.items()}))


def verdict_text(it: Item, nt: Notation) -> str:
    """An item's verdict in words: ``correct``, ``carried over``, ``wrong`` or ``wrong: <the mistakes named>``.

    >>> from graphmethods.sheets.check.report import Item
    >>> it = Item("results.J_F", "J_F", "kg·m²", 1.0, 2.0, 1.0, 0.1, "wrong", ("n_as_omega",))
    >>> verdict_text(it, notation_of("en"))
    'wrong: n (rev/min) used as ω (rad/s)'
    """
    base = word(nt, {"ok": "ok", "carried": "carried"}.get(it.verdict, "wrong"))
    if not it.mistakes:
        return base
    sep = "、" if nt.code == "zh" else "; "
    named = sep.join(markup.typed(nt.word("check." + code, J_e=nt.sym("dynamics.J_e"))) for code in it.mistakes)
    return f"{base}：{named}" if nt.code == "zh" else f"{base}: {named}"


def item_label(it: Item, report: CheckReport, nt: Notation) -> str:
    """An item's label as plain text in the report's language (the overlay's label)."""
    from graphmethods.sheets.check.overlay import overlay_label

    if nt.code == "en":
        return it.label
    try:
        return markup.typed(overlay_label(it, report, nt))
    except (KeyError, IndexError, AssertionError):      # a key the overlay has no word for: the English label
        return it.label


def value_text(v: object, nt: Notation) -> str:
    """A value of the table: four significant digits (whole numbers in full), a position or sense in words."""
    from graphmethods.sheets.check.report import _fmt

    if isinstance(v, str) and nt.code != "en":
        from graphmethods.sheets.check.overlay import overlay_value

        return markup.typed(overlay_value(v, nt))
    return decimal(_fmt(v), nt)


def summary(report: CheckReport, nt: Notation) -> str:
    """The one-line summary in the report's language."""
    if nt.code == "en":
        return report.summary()
    if report.ok:
        return word(nt, "all_correct", n=len(report.items))
    undiag = sum(1 for i in report.wrong if not i.mistakes)
    parts = [word(nt, "n_wrong", n=len(report.wrong))]
    if report.mistakes:
        parts.append(word(nt, "n_mistakes", n=len(report.mistakes)))
    if undiag:
        parts.append(word(nt, "n_unexplained", n=undiag))
    if report.carried:
        parts.append(word(nt, "n_carried", n=len(report.carried)))
    return word(nt, "n_items", n=len(report.items), parts=("，" if nt.code == "zh" else ", ").join(parts))


def _rows(report: CheckReport, nt: Notation) -> list[tuple[str, ...]]:
    return [(item_label(it, report, nt), value_text(it.expected, nt), value_text(it.student, nt),
             value_text(it.deviation, nt), value_text(it.tolerance, nt), markup.typed(nt.unit(it.unit)) if it.unit
             else "", verdict_text(it, nt)) for it in report.items]


def _heading(report: CheckReport, nt: Notation) -> str:
    from graphmethods.titles import text_in

    head = word(nt, "check_of", problem=report.problem, title=text_in(report.title, nt.code))
    return head + (f" — {report.student}" if report.student else "")


def _tail(report: CheckReport, nt: Notation) -> list[list[str]]:
    """The paragraphs after the table: each a list of lines (a heading line, then list items ``- …``)."""
    out: list[list[str]] = []
    labels = {i.key: item_label(i, report, nt) for i in report.items}
    colon, comma = ("：", "、") if nt.code == "zh" else (": ", ", ")
    if report.mistakes:
        out.append([word(nt, "mistakes_found")] + [
            f"- {markup.typed(nt.word('check.' + m.code, J_e=nt.sym('dynamics.J_e')))}{colon}"
            f"{comma.join(labels[k] for k in m.items)}" for m in report.mistakes])
    undiag = [i for i in report.wrong if not i.mistakes]
    if undiag:
        out.append([word(nt, "unexplained")] + [f"- {labels[i.key]}" for i in undiag])
    if report.carried:
        out.append([word(nt, "carried_list")] + [f"- {labels[i.key]}{colon}{note_text(i.note, nt)}"
                                                 for i in report.carried])
    out += [[word(nt, "note", text=note_text(n, nt))] for n in report.notes]
    out.append([word(nt, "result", summary=summary(report, nt))])
    return out


def note_text(note: str, nt: Notation) -> str:
    """A note of the checker (English, made where the item is judged) in the report's language: where a
    carried item's value comes from, and what was read from a drawing."""
    if nt.code == "en" or not note:
        return note
    m = re.search(r"expected (\S+) from those$", note)
    if note.startswith("follows from"):
        return word(nt, "follows_own", value=decimal(m.group(1), nt)) if m else word(nt, "follows_plain")
    m = re.match(r"read from (.+?): (.*)$", note)
    if m:
        return word(nt, "read_from", file=m.group(1), values=decimal(m.group(2), nt))
    return note


def _width(text: str) -> int:
    """Columns a text takes on a terminal (a CJK character takes two)."""
    return sum(2 if markup.is_cjk(ch) else 1 for ch in text)


def report_text(report: CheckReport, lang: str | Notation | None = "en") -> str:
    """Aligned plain text: one line per item, then the mistakes, the carried items, the notes, the result."""
    nt = notation_of(lang)
    head = tuple(word(nt, c) for c in _COLUMNS)
    rows = [head] + _rows(report, nt)
    widths = [max(_width(r[k]) for r in rows) for k in range(len(head))]

    def cell(c: str, w: int, left: bool) -> str:
        pad = " " * (w - _width(c))
        return c + pad if left else pad + c
    lines = [_heading(report, nt)]
    lines += ["  ".join(cell(c, w, k in (0, 5, 6)) for k, (c, w) in enumerate(zip(r, widths))).rstrip()
              for r in rows]
    for para in _tail(report, nt):
        lines += para
    return "\n".join(lines) + "\n"


def _md_cell(c: str) -> str:
    return c.replace("|", "\\|").replace("\n", " ")


def report_markdown(report: CheckReport, lang: str | Notation | None = "en") -> str:
    """A CommonMark table of the items (verdicts other than correct in bold), then the paragraphs and lists,
    each separated by a blank line."""
    nt = notation_of(lang)
    head = tuple(word(nt, c) for c in _COLUMNS)
    ok = word(nt, "ok")
    lines = [f"### {_md_cell(_heading(report, nt))}", "", "| " + " | ".join(head) + " |",
             "|" + "|".join(("---", "--:", "--:", "--:", "--:", "---", "---")) + "|"]
    for r in _rows(report, nt):
        cells = [_md_cell(c) for c in r]
        if r[6] != ok:
            cells[6] = f"**{cells[6]}**"
        lines.append("| " + " | ".join(cells) + " |")
    for para in _tail(report, nt):
        lines.append("")
        if len(para) > 1:                       # a heading, a blank line, the list (CommonMark)
            lines += [para[0], ""] + para[1:]
        else:
            lines += para
    return "\n".join(lines) + "\n"
