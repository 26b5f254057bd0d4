"""The main inscriptions of a course sheet, drawn to their standards.

- ``"gost"``: ГОСТ 2.104 form 1, 185 × 55 mm (Russian sheets): the changes area and the signatures
  (Разраб., Пров., Т.контр., Н.контр., Утв.), the designation, the title, Лит., Масса, Масштаб,
  Лист, Листов and the organisation.
- ``"gb"``: GB/T 10609.1, 180 × 56 mm (Chinese sheets): the change and signature areas (设计, 审核,
  工艺, 批准), 阶段标记, 重量, 比例, 共 张 第 张, the organisation, the drawing's name and code.

:class:`FormBlock` has the interface :class:`~graphmethods.scene.page.Page` asks of a title block's
table: ``width_mm``, ``height_mm`` and ``draw()``. Lines are 0.5 mm (outline and main dividers) and
0.18 mm (thin), as both standards draw them; every text is 3.5 mm or larger (a column head wider than
its column condensed at that height), the title up to 7 mm.

>>> b = FormBlock.of("gost", right=831.0, bottom=584.0, fields={"title": "Динамический анализ"})
>>> b.width_mm, b.height_mm, b.box()
(185.0, 55.0, (646.0, 529.0, 831.0, 584.0))
>>> "Разраб." in [p.text for p in b.draw().children if hasattr(p, "text")]
True
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field

from graphmethods.scene import markup
from graphmethods.scene.notation import get as get_notation
from graphmethods.scene.primitives import Group, Label, Path, Primitive, Style

THICK = Style(width_mm=0.5)
THIN = Style(width_mm=0.18)
CAPTION_MM = 3.5          # the smallest lettering of an A1/A2 sheet (ГОСТ 2.304, GB/T 14691)
TITLE_MM = 7.0
#: the narrowest condensed lettering of a column head: 60 % of the font's width (ГОСТ 2.304 type A is
#: narrow, d = h/14; a condensed sans at 0.6 still reads as letters)
CONDENSED_MIN = 0.6
#: a column head leaves this much of its column free (0.8 mm each side: the condensed text clear of the lines)
HEAD_MARGIN_MM = 1.6

#: the language whose course sheets carry each standard form
STANDARD_OF = {"gost": "ru", "gb": "zh"}


def form_for(code: str) -> str:
    """The main inscription of a course sheet in language ``code``: ``"gost"`` (ru), ``"gb"`` (zh) or
    ``"simple"``.

    >>> form_for("ru"), form_for("zh"), form_for("en")
    ('gost', 'gb', 'simple')
    """
    return next((f for f, c in STANDARD_OF.items() if c == code), "simple")


#: (width, height) of each form, mm
SIZE = {"gost": (185.0, 55.0), "gb": (180.0, 56.0)}


@dataclass(frozen=True)
class FormBlock:
    """A standard main inscription whose bottom-right corner is (right, bottom), mm.

    ``fields``: ``title``, ``designation`` (the document's code), ``student``, ``checker``,
    ``organisation`` (or the group), ``sheet_no``, ``sheets``, ``scale``, ``mass``; all optional text.
    """

    form: str
    right: float
    bottom: float
    fields: Mapping[str, str] = field(default_factory=dict)
    name: str = "title-block"

    @classmethod
    def of(cls, form: str, *, right: float, bottom: float, fields: Mapping[str, str]) -> FormBlock:
        return cls(form, float(right), float(bottom), dict(fields))

    @property
    def width_mm(self) -> float:
        return SIZE[self.form][0]

    @property
    def height_mm(self) -> float:
        return SIZE[self.form][1]

    @property
    def at(self) -> tuple[float, float]:
        """The top-left corner, mm (as a :class:`~graphmethods.scene.elements.Table` has it)."""
        return (self.right - self.width_mm, self.bottom - self.height_mm)

    def box(self) -> tuple[float, float, float, float]:
        return (self.right - self.width_mm, self.bottom - self.height_mm, self.right, self.bottom)

    def draw(self) -> Group:
        x0, y0, _, _ = self.box()
        prims = _gost(self, x0, y0) if self.form == "gost" else _gb(self, x0, y0)
        return Group(self.name, tuple(prims))


class _Words:
    """The caption words of a form in its own language: ``_Words("ru")["drawn"]`` is "Разраб."."""

    def __init__(self, code: str) -> None:
        self.nt = get_notation(code)

    def __getitem__(self, key: str) -> str:
        return self.nt.word(f"title_block.{key}")


def _line(x0: float, y0: float, x1: float, y1: float, style: Style = THIN) -> Path:
    return Path(((x0, y0), (x1, y1)), style)


def _rect(x0: float, y0: float, x1: float, y1: float, style: Style) -> Path:
    return Path(((x0, y0), (x1, y0), (x1, y1), (x0, y1)), style, closed=True)


def _text(x: float, y: float, text: str, *, size: float = CAPTION_MM, anchor: str = "start",
          width: float | None = None) -> Label:
    """A text with its middle at height ``y``, condensed to ``width`` when it is wider.

    A column head wider than its column ("Изм." in ГОСТ 2.104's 7 mm column, "更改文件号" in GB/T 10609.1's
    16 mm one) keeps its height and is condensed, as ГОСТ 2.304's narrow type A lettering sets it, to at
    most :data:`CONDENSED_MIN` of its width; a text longer still (a long name) is also set smaller.

    >>> lab = _text(3.5, 0.0, "Изм.", anchor="middle", width=6.4)
    >>> lab.size_mm, 0.6 < lab.stretch < 1.0
    (3.5, True)
    """
    stretch = 1.0
    if width is not None and text:
        need = markup.text_width_mm(markup.literal(text), size)
        if need > width:
            stretch = max(CONDENSED_MIN, width / need)
            size = size * min(1.0, width / (need * stretch))
    runs = tuple(markup.parse(markup.literal(text)))
    return Label(x, y + 0.35 * size, runs, size_mm=size, anchor=anchor, stretch=round(stretch, 3))


def _cjk(ch: str) -> bool:
    """Is ``ch`` (its first character) a CJK character or a full-width mark (no spaces around it)?"""
    return bool(ch) and ("\u3000" <= ch[0] <= "\u9fff" or "\uff00" <= ch[0] <= "\uffef")


def _wrapped(x0: float, y0: float, w: float, h: float, text: str, *, size: float = TITLE_MM) -> list[Label]:
    """``text`` centred in the cell, on as many lines as it needs, the largest size ≤ ``size`` that fits."""
    if not text:
        return []
    # words, and each CJK character (or full-width mark) on its own: Chinese text breaks between characters
    words = re.findall(r"[\u3000-\u9fff\uff00-\uffef]|[^\s\u3000-\u9fff\uff00-\uffef]+", text)
    s = size
    while True:
        lines, cur = [], ""
        for wd in words:
            sep = "" if (_cjk(wd) or (cur and _cjk(cur[-1]))) else " "
            trial = f"{cur}{sep}{wd}" if cur else wd
            if cur and markup.text_width_mm(markup.literal(trial), s) > w - 4.0:
                lines.append(cur)
                cur = wd
            else:
                cur = trial
        lines.append(cur)
        widest = max(markup.text_width_mm(markup.literal(t), s) for t in lines)
        if (len(lines) * s * 1.35 <= h - 2.0 and widest <= w - 4.0) or s <= CAPTION_MM:
            break
        s = max(CAPTION_MM, s - 0.5)
    top = y0 + h / 2 - (len(lines) - 1) * s * 1.35 / 2
    return [_text(x0 + w / 2, top + i * s * 1.35, t, size=s, anchor="middle", width=w - 2.0)
            for i, t in enumerate(lines)]


def _gost(b: FormBlock, x0: float, y0: float) -> list[Primitive]:
    """ГОСТ 2.104 form 1: 185 × 55; rows of 5 mm; left part 7 + 10 + 23 + 15 + 10 = 65 mm, the title
    column 70 mm, the right part 50 mm (Лит. 3 × 5, Масса 17, Масштаб 18)."""
    W, f = _Words("ru"), b.fields
    out: list[Primitive] = [_rect(x0, y0, x0 + 185.0, y0 + 55.0, THICK)]
    cols = (7.0, 10.0, 23.0, 15.0, 10.0)
    xs = [x0]
    for c in cols:
        xs.append(xs[-1] + c)                             # x0 … x0 + 65
    xl = xs[-1]
    for k in range(1, 11):                                # the left part's rows
        out.append(_line(x0, y0 + 5 * k, xl, y0 + 5 * k, THICK if k in (6,) else THIN))
    for i, x in enumerate(xs[1:-1], start=1):             # its columns: all five above, four below (17 = 7 + 10)
        out.append(_line(x, y0, x, y0 + (30.0 if i == 1 else 55.0), THICK))
    out.append(_line(xl, y0, xl, y0 + 55.0, THICK))
    for i, key in enumerate(("change", "sheet", "doc", "sign", "date")):
        out.append(_text((xs[i] + xs[i + 1]) / 2, y0 + 27.5, W[key], anchor="middle", width=cols[i] - HEAD_MARGIN_MM))
    people = (("drawn", f.get("student", "")), ("checked", f.get("checker", "")), ("tech", ""), ("norm", ""),
              ("approved", ""))
    for r, (key, who) in enumerate(people):
        y = y0 + 32.5 + 5 * r
        out.append(_text(x0 + 1.0, y, W[key], width=16.0))
        if who:
            out.append(_text(xs[2] + 1.0, y, who, width=21.0))
    xr = xl + 70.0                                        # the right part starts here
    out += [_line(xl, y0 + 15.0, x0 + 185.0, y0 + 15.0, THICK),       # under the designation
            _line(xr, y0 + 15.0, xr, y0 + 55.0, THICK),
            _line(xl, y0 + 40.0, xr, y0 + 40.0, THICK),               # title above, material below
            _line(xr, y0 + 20.0, x0 + 185.0, y0 + 20.0, THICK),
            _line(xr, y0 + 35.0, x0 + 185.0, y0 + 35.0, THICK),
            _line(xr, y0 + 40.0, x0 + 185.0, y0 + 40.0, THICK)]
    for dx in (5.0, 10.0):                                # Лит.: three cells of 5 mm
        out.append(_line(xr + dx, y0 + 20.0, xr + dx, y0 + 35.0, THIN))
    for dx in (15.0, 32.0):                               # Масса | Масштаб
        out.append(_line(xr + dx, y0 + 15.0, xr + dx, y0 + 35.0, THICK))
    out.append(_line(xr + 20.0, y0 + 35.0, xr + 20.0, y0 + 40.0, THICK))       # Лист | Листов
    out += [_text(xr + 7.5, y0 + 17.5, W["lit"], anchor="middle", width=14.0),
            _text(xr + 23.5, y0 + 17.5, W["mass"], anchor="middle", width=16.0),
            _text(xr + 41.0, y0 + 17.5, W["scale"], anchor="middle", width=17.0),
            _text(xr + 2.5, y0 + 27.5, W["lit_value"], anchor="middle")]
    if f.get("mass"):
        out.append(_text(xr + 23.5, y0 + 27.5, f["mass"], anchor="middle", width=16.0))
    if f.get("scale"):
        out.append(_text(xr + 41.0, y0 + 27.5, f["scale"], anchor="middle", width=17.0))
    sheet = f"{W['sheet']} {f.get('sheet_no', '')}".strip()
    sheets = f"{W['sheets']} {f.get('sheets', '')}".strip()
    out += [_text(xr + 1.0, y0 + 37.5, sheet, width=18.0), _text(xr + 21.0, y0 + 37.5, sheets, width=28.0)]
    out += _wrapped(xl, y0, 120.0, 15.0, f.get("designation", ""), size=5.0)
    out += _wrapped(xl, y0 + 15.0, 70.0, 25.0, f.get("title", ""))
    out += _wrapped(xr, y0 + 40.0, 50.0, 15.0, f.get("organisation", ""), size=5.0)
    return out


def _gb(b: FormBlock, x0: float, y0: float) -> list[Primitive]:
    """GB/T 10609.1: 180 × 56; rows of 7 mm; the change and signature areas 10 + 10 + 16 + 16 + 12 + 16
    = 80 mm, the other area 50 mm (阶段标记 4 × 6.5, 重量 12, 比例 12), the name and code area 50 mm."""
    W, f = _Words("zh"), b.fields
    out: list[Primitive] = [_rect(x0, y0, x0 + 180.0, y0 + 56.0, THICK)]
    cols = (10.0, 10.0, 16.0, 16.0, 12.0, 16.0)
    xs = [x0]
    for c in cols:
        xs.append(xs[-1] + c)
    xl = xs[-1]                                           # x0 + 80
    for k in range(1, 8):
        out.append(_line(x0, y0 + 7 * k, xl, y0 + 7 * k, THICK if k == 4 else THIN))
    for x in xs[1:-1]:
        out.append(_line(x, y0, x, y0 + 56.0, THIN))
    out.append(_line(xl, y0, xl, y0 + 56.0, THICK))
    for i, key in enumerate(("change", "count", "zone", "doc", "sign", "date")):
        out.append(_text((xs[i] + xs[i + 1]) / 2, y0 + 24.5, W[key], anchor="middle", width=cols[i] - HEAD_MARGIN_MM))
    rows = (("drawn", f.get("student", ""), "norm"), ("checked", f.get("checker", ""), ""), ("tech", "", ""),
            ("approved", "", ""))
    for r, (key, who, right) in enumerate(rows):
        y = y0 + 31.5 + 7 * r
        out.append(_text(x0 + 5.0, y, W[key], anchor="middle", width=9.4))
        if who:
            out.append(_text(xs[1] + 1.0, y, who, width=24.0))
        if right:
            out.append(_text((xs[3] + xs[4]) / 2, y, W[right], anchor="middle", width=15.4))
    xm, xn = xl + 50.0, xl + 100.0                        # the other area | the name and code area
    out += [_line(xm, y0, xm, y0 + 56.0, THICK),
            _line(xl, y0 + 7.0, xm, y0 + 7.0, THIN), _line(xl, y0 + 21.0, xm, y0 + 21.0, THICK),
            _line(xl, y0 + 28.0, xm, y0 + 28.0, THIN),
            _line(xm, y0 + 18.0, xn, y0 + 18.0, THICK), _line(xm, y0 + 38.0, xn, y0 + 38.0, THICK)]
    for dx in (6.5, 13.0, 19.5):
        out.append(_line(xl + dx, y0 + 7.0, xl + dx, y0 + 21.0, THIN))
    for dx in (26.0, 38.0):
        out.append(_line(xl + dx, y0, xl + dx, y0 + 21.0, THIN))
    out += [_text(xl + 13.0, y0 + 3.5, W["lit"], anchor="middle", width=25.0),
            _text(xl + 32.0, y0 + 3.5, W["mass"], anchor="middle", width=11.4),
            _text(xl + 44.0, y0 + 3.5, W["scale"], anchor="middle", width=11.4)]
    if f.get("scale"):
        out.append(_text(xl + 44.0, y0 + 14.0, f["scale"], anchor="middle", width=11.4))
    of = W.nt.word("title_block.of", n=f.get("sheets", "  "), k=f.get("sheet_no", "  "))
    out.append(_text(xl + 25.0, y0 + 24.5, of, anchor="middle", width=48.0))
    out += _wrapped(xl, y0 + 28.0, 50.0, 28.0, f.get("organisation", ""), size=5.0)
    out += _wrapped(xm, y0, 50.0, 18.0, f.get("title", ""))
    out += _wrapped(xm, y0 + 18.0, 50.0, 20.0, f.get("designation", ""), size=5.0)
    return out


__all__ = ["FormBlock", "SIZE", "STANDARD_OF", "form_for"]
