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

Run = tuple[str, int]

#: size of a sub/superscript relative to the text size
SCRIPT_SCALE = 0.7
#: baseline shift of a subscript (down) and a superscript (up), in em of the text size
SUB_SHIFT = 0.22
SUP_SHIFT = 0.38

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
_SPECIAL_EM = {"·": 0.318, "−": 0.838, "±": 0.838, "≈": 0.838, "°": 0.5, "→": 0.838, "²": 0.401,
               "³": 0.401, "⁻": 0.5, "¹": 0.401, "–": 0.5, "—": 1.0, "…": 1.0, "≡": 0.838, "Σ": 0.632}


def parse(text: str) -> tuple[Run, ...]:
    """Split markup into runs ``(text, shift)``; adjacent runs of one shift are merged.

    Examples
    --------
    >>> parse("M_d"), parse("10^{-3}"), parse(r"a\\_b")
    ((('M', 0), ('d', -1)), (('10', 0), ('-3', 1)), (('a_b', 0),))
    """
    runs: list[list] = []

    def add(chunk: str, shift: int) -> None:
        if not chunk:
            return
        if runs and runs[-1][1] == shift:
            runs[-1][0] += chunk
        else:
            runs.append([chunk, shift])

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
    return tuple((t, s) for t, s in runs)


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
    if 0x410 <= o <= 0x42F:  # Cyrillic capitals
        return 0.74
    if 0x400 <= o <= 0x4FF:
        return 0.63
    if 0x370 <= o <= 0x3FF:  # Greek
        return 0.64
    return 0.7


def text_width_mm(text: str, size_mm: float, *, markup: bool = True) -> float:
    """Estimated width of a text on paper, mm, for layout (tables, label placement).

    Parameters
    ----------
    text : str
        The text (markup unless ``markup=False``).
    size_mm : float, mm
        Font size (em height).
    """
    runs = parse(text) if markup else ((text, 0),)
    total = 0.0
    for chunk, shift in runs:
        scale = 1.0 if shift == 0 else SCRIPT_SCALE
        total += scale * sum(char_em(c) for c in chunk)
    return total * size_mm
