"""Text with subscripts: a tiny markup and an estimate of how wide a text is on paper.

The markup follows TeX: ``_x`` or ``_{...}`` is a subscript, ``^x`` or ``^{...}`` a
superscript, ``\\_`` and ``\\^`` are literal characters. Nothing else is special, so
ordinary text passes through unchanged. A run is ``(text, shift)`` with shift
``0`` (baseline), ``-1`` (subscript) or ``+1`` (superscript).

>>> parse("ΔW_{max} = 575 J")
(('ΔW', 0), ('max', -1), (' = 575 J', 0))
>>> plain("μ_M = 100 N·m/mm")
'μM = 100 N·m/mm'
>>> round(text_width_mm("M_d", 3.5), 2)
4.58
"""

from __future__ import annotations

import functools
import re
from contextvars import ContextVar

Run = tuple[str, int]

#: size of a sub/superscript relative to the text size
SCRIPT_SCALE = 0.7
#: baseline shift of a subscript (down) and a superscript (up), in em of the text size
SUB_SHIFT = 0.22
SUP_SHIFT = 0.38


def baseline_shift_mm(shift: int, size_mm: float) -> float:
    """How far a run's baseline lies below the line's (mm; a superscript's is negative), for a run's
    ``shift`` of -1 (subscript), 0 or +1 (superscript) in text of ``size_mm``: every backend's one rule.

    >>> baseline_shift_mm(-1, 5.0), baseline_shift_mm(0, 5.0), baseline_shift_mm(1, 5.0)
    (1.1, 0.0, -1.9)
    """
    return {0: 0.0, -1: SUB_SHIFT * size_mm, 1: -SUP_SHIFT * size_mm}[shift]


def _per_mille(widths: str) -> tuple[float, ...]:
    """Advance widths written as a font's metrics give them, in thousandths of an em (``"318 401"``), in em."""
    return tuple(int(w) / 1000 for w in widths.split())


# Advance widths of DejaVu Sans (the default font of matplotlib), 1/1000 em, for ASCII 32..126.
_ASCII_EM = _per_mille(
    "318 401 460 838 636 950 780 275 390 390 500 838 318 361 318 337 636 636 636 636 636 636 636 636 636 636 337 337 "
    "838 838 838 531 1000 684 686 698 770 632 575 775 752 295 295 656 557 863 748 787 603 787 695 635 611 732 684 989 "
    "685 611 685 390 337 390 838 500 500 613 635 550 635 615 352 635 634 278 278 579 278 974 634 612 635 635 411 521 "
    "392 634 592 818 592 592 525 636 337 636 838"
)
# ... and for Greek (U+0370..U+03FF) and Cyrillic (U+0400..U+045F).
_GREEK_EM = _per_mille(
    "654 568 862 647 278 278 748 650 640 640 500 549 550 549 337 295 640 640 640 640 500 500 692 318 746 871 408 640 "
    "812 640 825 826 338 684 686 557 684 632 685 752 787 295 656 684 863 748 632 787 752 603 640 632 611 611 787 685 "
    "787 764 295 611 659 541 634 338 579 659 638 592 612 541 544 634 612 338 589 592 636 559 558 612 602 635 587 634 "
    "602 579 660 578 660 837 338 579 612 579 837 656 614 619 699 842 699 660 837 664 787 612 648 587 575 458 660 660 "
    "865 627 934 837 758 659 792 615 687 607 768 625 699 612 611 536 664 635 550 278 787 615 615 605 635 698 863 651 "
    "635 703 698 703"
)
_CYRILLIC_EM = _per_mille(
    "632 632 786 610 698 635 295 295 295 1094 1045 786 710 748 609 752 684 686 686 610 781 632 1077 641 748 748 710 "
    "752 863 752 787 752 603 698 611 609 861 685 776 686 1069 1094 833 882 686 698 1080 695 613 617 589 525 691 615 "
    "901 532 650 650 604 639 754 654 612 654 635 550 583 592 855 592 681 591 915 942 707 790 589 549 842 602 615 615 "
    "625 525 549 521 278 278 278 902 898 652 604 650 592 654"
)
_SPECIAL_EM = {"·": 0.318, "−": 0.838, "±": 0.838, "≈": 0.838, "°": 0.5, "→": 0.838, "²": 0.401,
               "³": 0.401, "⁻": 0.5, "¹": 0.401, "–": 0.5, "—": 1.0, "…": 1.0, "≡": 0.838, "Σ": 0.632}


@functools.lru_cache(maxsize=8192)
def parse(text: str) -> tuple[Run, ...]:
    """Split markup into runs ``(text, shift)``; adjacent runs of one shift are merged.

    Examples
    --------
    >>> parse("M_d"), parse("10^{-3}"), parse(r"a\\_b")
    ((('M', 0), ('d', -1)), (('10', 0), ('-3', 1)), (('a_b', 0),))
    """
    runs: list[tuple[str, int]] = []

    def add(chunk: str, shift: int) -> None:
        if not chunk:
            return
        if runs and runs[-1][1] == shift:
            runs[-1] = (runs[-1][0] + chunk, shift)
        else:
            runs.append((chunk, shift))

    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch == "\\" and i + 1 < n and text[i + 1] in "_^\\{}":
            add(text[i + 1], 0)
            i += 2
        elif ch in "_^" and i + 1 < n:
            shift = -1 if ch == "_" else 1
            if text[i + 1] == "{":
                close = text.find("}", i + 2)
                if close < 0:  # unbalanced: take the rest literally
                    add(text[i:], 0)
                    break
                add(text[i + 2:close], shift)
                i = close + 1
            else:
                add(text[i + 1], shift)
                i += 2
        else:
            add(ch, 0)
            i += 1
    return tuple(runs)


def literal(text: str) -> str:
    """Escape user text so the markup draws it exactly as typed (``_`` and ``^`` stay literal).

    >>> parse(literal("W1_diesel^2"))
    (('W1_diesel^2', 0),)
    """
    return text.replace("\\", "\\\\").replace("_", "\\_").replace("^", "\\^").replace("{", "\\{").replace("}", "\\}")


def plain(text: str) -> str:
    """The characters a reader sees (markup removed), as SVG text content reads.

    >>> plain("ψ_{max}")
    'ψmax'
    """
    return "".join(t for t, _ in parse(text))


def typed(text: str) -> str:
    """The text as plain-text reports write it: a subscript after ``_``, a superscript after ``^`` (the
    spelling of the English item names, ``ω_max``), so a lowered index is not read into its symbol.

    >>> typed("ω_{ср}"), typed("tg ψ_{min}"), typed("J_{м}"), typed(r"a\\_b")
    ('ω_ср', 'tg ψ_min', 'J_м', 'a_b')
    """
    return "".join(("_" if shift < 0 else "^" if shift > 0 else "") + t for t, shift in parse(text))


_CJK = "\u3000-\u303f\u4e00-\u9fff\uff08\uff09"
_FULL_WIDTH = {",": "，", ":": "：", ";": "；"}
_ASCII_BY_CJK = re.compile(rf"(?<=[{_CJK}]) ?([,:;]) *|(?<![{_CJK}]) ?([,:;]) *(?=[{_CJK}])")


def full_width_punctuation(text: str) -> str:
    """Chinese typography: an ASCII comma, colon or semicolon next to Chinese text becomes full-width
    (its spaces go: a full-width sign carries its own), so a zh figure never mixes "位置: 3" with "位置：3".

    >>> full_width_punctuation("ω = 1.2 rad/s, 逆时针"), full_width_punctuation("O_{1}: 在图纸之外")
    ('ω = 1.2 rad/s，逆时针', 'O_{1}：在图纸之外')
    >>> full_width_punctuation("φ = 30°, ω = 2")
    'φ = 30°, ω = 2'
    """
    return _ASCII_BY_CJK.sub(lambda mt: _FULL_WIDTH[mt.group(1) or mt.group(2)], text)


def lowered_digits(name: str) -> str:
    """A point or link name as the books write it, its digits lowered: ``"S2"`` -> ``"S_{2}"``,
    ``"O3A"`` -> ``"O_{3}A"``, ``"s4"`` -> ``"s_{4}"`` (one notation on every sheet).

    >>> lowered_digits("S2"), lowered_digits("O3A"), lowered_digits("B")
    ('S_{2}', 'O_{3}A', 'B')
    """
    return re.sub(r"([A-Za-z])(\d+)", lambda mt: f"{mt.group(1)}_{{{mt.group(2)}}}", name)


def is_cjk(ch: str) -> bool:
    """True for a Chinese/Japanese/Korean ideograph, kana, or full-width punctuation.

    Parameters
    ----------
    ch : str
        One character.

    Examples
    --------
    >>> is_cjk("速"), is_cjk("，"), is_cjk("v")
    (True, True, False)
    """
    o = ord(ch)
    return (0x2E80 <= o <= 0x9FFF) or (0xAC00 <= o <= 0xD7AF) or (0xF900 <= o <= 0xFAFF) or (0xFF00 <= o <= 0xFFEF) \
        or (0x3000 <= o <= 0x303F) or (0x20000 <= o <= 0x2FFFF)


def has_cjk(text: str) -> bool:
    """True when the text needs a CJK font.

    Parameters
    ----------
    text : str
        Any text.

    Examples
    --------
    >>> has_cjk("速度 v_B"), has_cjk("v_B")
    (True, False)
    """
    return any(is_cjk(ch) for ch in text)


def char_em(ch: str) -> float:
    """Estimated advance width of one character in em (DejaVu Sans; CJK full width).

    Parameters
    ----------
    ch : str
        One character.

    Returns
    -------
    float, em
        Its advance: the font's for ASCII, Greek and Cyrillic, 1 for a CJK character.

    Examples
    --------
    >>> round(char_em("M"), 3), char_em("速")
    (0.863, 1.0)
    """
    o = ord(ch)
    if 32 <= o <= 126:
        return _ASCII_EM[o - 32]
    if ch in _SPECIAL_EM:
        return _SPECIAL_EM[ch]
    if is_cjk(ch):
        return 1.0
    if 0x370 <= o < 0x400:
        return _GREEK_EM[o - 0x370]
    if 0x400 <= o < 0x460:
        return _CYRILLIC_EM[o - 0x400]
    return 0.7


#: the smallest font size (mm) of the text made while it is set: a course sheet (A1, A2) letters at 3.5 mm
#: and up, so its parts, drawn by the same figure functions as the A4 figures, are lettered up while they
#: are built (:func:`graphmethods.sheets.engine.lettering.lettered` sets it; 0: as given). Widths measured
#: meanwhile (:func:`text_width_mm`) are those of the lettered-up text.
MIN_TEXT_MM: ContextVar[float] = ContextVar("MIN_TEXT_MM", default=0.0)


def text_width_mm(text: str, size_mm: float, *, markup: bool = True) -> float:
    """Estimated width of a text on paper, mm, for layout (tables, label placement).

    Parameters
    ----------
    text : str
        The text (markup unless ``markup=False``).
    size_mm : float, mm
        Font size (em height), raised to the sheet's smallest lettering.

    Returns
    -------
    float, mm
        The text's width: sub- and superscripts at their reduced size.

    Examples
    --------
    >>> round(text_width_mm("v_B", 5.0), 3)
    5.361
    """
    return _width_em(text, markup) * max(size_mm, MIN_TEXT_MM.get())


@functools.lru_cache(maxsize=8192)
def _width_em(text: str, markup: bool) -> float:
    runs = parse(text) if markup else ((text, 0),)
    return sum((1.0 if shift == 0 else SCRIPT_SCALE) * sum(char_em(c) for c in chunk) for chunk, shift in runs)
