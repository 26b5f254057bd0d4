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

# Advance widths of DejaVu Sans (the default font of matplotlib) in em, for ASCII 32..126.
_ASCII_EM = (
    0.318, 0.401, 0.46, 0.838, 0.636, 0.95, 0.78, 0.275, 0.39, 0.39, 0.5, 0.838, 0.318, 0.361, 0.318, 0.337,
    0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.337, 0.337, 0.838, 0.838, 0.838,
    0.531, 1.0, 0.684, 0.686, 0.698, 0.77, 0.632, 0.575, 0.775, 0.752, 0.295, 0.295, 0.656, 0.557, 0.863,
    0.748, 0.787, 0.603, 0.787, 0.695, 0.635, 0.611, 0.732, 0.684, 0.989, 0.685, 0.611, 0.685, 0.39, 0.337,
    0.39, 0.838, 0.5, 0.5, 0.613, 0.635, 0.55, 0.635, 0.615, 0.352, 0.635, 0.634, 0.278, 0.278, 0.579, 0.278,
    0.974, 0.634, 0.612, 0.635, 0.635, 0.411, 0.521, 0.392, 0.634, 0.592, 0.818, 0.592, 0.592, 0.525, 0.636,
    0.337, 0.636, 0.838,
)
# ... and for Greek (U+0370..U+03FF) and Cyrillic (U+0400..U+045F).
_GREEK_EM = (
    0.654, 0.568, 0.862, 0.647, 0.278, 0.278, 0.748, 0.65, 0.64, 0.64, 0.5, 0.549, 0.55, 0.549, 0.337, 0.295, 0.64,
    0.64, 0.64, 0.64, 0.5, 0.5, 0.692, 0.318, 0.746, 0.871, 0.408, 0.64, 0.812, 0.64, 0.825, 0.826, 0.338, 0.684,
    0.686, 0.557, 0.684, 0.632, 0.685, 0.752, 0.787, 0.295, 0.656, 0.684, 0.863, 0.748, 0.632, 0.787, 0.752, 0.603,
    0.64, 0.632, 0.611, 0.611, 0.787, 0.685, 0.787, 0.764, 0.295, 0.611, 0.659, 0.541, 0.634, 0.338, 0.579, 0.659,
    0.638, 0.592, 0.612, 0.541, 0.544, 0.634, 0.612, 0.338, 0.589, 0.592, 0.636, 0.559, 0.558, 0.612, 0.602, 0.635,
    0.587, 0.634, 0.602, 0.579, 0.66, 0.578, 0.66, 0.837, 0.338, 0.579, 0.612, 0.579, 0.837, 0.656, 0.614, 0.619,
    0.699, 0.842, 0.699, 0.66, 0.837, 0.664, 0.787, 0.612, 0.648, 0.587, 0.575, 0.458, 0.66, 0.66, 0.865, 0.627,
    0.934, 0.837, 0.758, 0.659, 0.792, 0.615, 0.687, 0.607, 0.768, 0.625, 0.699, 0.612, 0.611, 0.536, 0.664, 0.635,
    0.55, 0.278, 0.787, 0.615, 0.615, 0.605, 0.635, 0.698, 0.863, 0.651, 0.635, 0.703, 0.698, 0.703,
)
_CYRILLIC_EM = (
    0.632, 0.632, 0.786, 0.61, 0.698, 0.635, 0.295, 0.295, 0.295, 1.094, 1.045, 0.786, 0.71, 0.748, 0.609, 0.752,
    0.684, 0.686, 0.686, 0.61, 0.781, 0.632, 1.077, 0.641, 0.748, 0.748, 0.71, 0.752, 0.863, 0.752, 0.787, 0.752,
    0.603, 0.698, 0.611, 0.609, 0.861, 0.685, 0.776, 0.686, 1.069, 1.094, 0.833, 0.882, 0.686, 0.698, 1.08, 0.695,
    0.613, 0.617, 0.589, 0.525, 0.691, 0.615, 0.901, 0.532, 0.65, 0.65, 0.604, 0.639, 0.754, 0.654, 0.612, 0.654,
    0.635, 0.55, 0.583, 0.592, 0.855, 0.592, 0.681, 0.591, 0.915, 0.942, 0.707, 0.79, 0.589, 0.549, 0.842, 0.602,
    0.615, 0.615, 0.625, 0.525, 0.549, 0.521, 0.278, 0.278, 0.278, 0.902, 0.898, 0.652, 0.604, 0.65, 0.592, 0.654,
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


def lowered_digits(name: str) -> str:
    """A point or link name as the books write it, its digits lowered: ``"S2"`` -> ``"S_{2}"``,
    ``"O3A"`` -> ``"O_{3}A"``, ``"s4"`` -> ``"s_{4}"`` (one notation on every sheet).

    >>> lowered_digits("S2"), lowered_digits("O3A"), lowered_digits("B")
    ('S_{2}', 'O_{3}A', 'B')
    """
    return re.sub(r"([A-Za-z])(\d+)", lambda mt: f"{mt.group(1)}_{{{mt.group(2)}}}", name)


def is_cjk(ch: str) -> bool:
    """True for a Chinese/Japanese/Korean ideograph, kana, or full-width punctuation."""
    o = ord(ch)
    return (0x2E80 <= o <= 0x9FFF) or (0xAC00 <= o <= 0xD7AF) or (0xF900 <= o <= 0xFAFF) or (0xFF00 <= o <= 0xFFEF) \
        or (0x3000 <= o <= 0x303F) or (0x20000 <= o <= 0x2FFFF)


def has_cjk(text: str) -> bool:
    """True when the text needs a CJK font."""
    return any(is_cjk(ch) for ch in text)


def char_em(ch: str) -> float:
    """Estimated advance width of one character in em (DejaVu Sans; CJK full width)."""
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
        Font size (em height).
    """
    return _width_em(text, markup) * max(size_mm, MIN_TEXT_MM.get())


@functools.lru_cache(maxsize=8192)
def _width_em(text: str, markup: bool) -> float:
    runs = parse(text) if markup else ((text, 0),)
    return sum((1.0 if shift == 0 else SCRIPT_SCALE) * sum(char_em(c) for c in chunk) for chunk, shift in runs)
