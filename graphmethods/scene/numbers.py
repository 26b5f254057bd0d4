"""Numbers on paper: the one millimetre formatter and the formatter of physical values.

:func:`format_mm` is the only way a coordinate becomes text in an output file
(3 decimals of a millimetre, trailing zeros stripped, ``-0`` written ``0``).
:func:`format_value` writes a physical value for a label, with a typographic
minus sign and the decimal separator of the notation profile.

>>> format_mm(12.5), format_mm(-0.0001), format_mm(3.14159), format_mm(100.0)
('12.5', '0', '3.142', '100')
>>> format_value(-550.0), format_value(34.36116964863836), format_value(0.02618, decimal=",")
('−550', '34.36', '0,02618')
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

from graphmethods.errors import InputError
from graphmethods.units import ROUNDOFF, is_finite

MINUS = "\u2212"
#: significant digits of each kind of flywheel quantity, one rule for its figures (the design's table, the
#: J_F–[δ] hyperbola) and the text of ``graphmethods flywheel``: inertias, masses and lengths in mm 4, works
#: and angular speeds 6 (ω_max and ω_min differ in the fourth digit at δ = 1/300), speeds 3
FLYWHEEL_DIGITS = {"J": 4, "mass": 4, "mm": 4, "density": 4, "W": 6, "omega": 6, "speed": 3, "delta": 6,
                   "inverse": 4, "angle": 4, "moment": 6}


def within_roundoff(value: float, reference: float) -> bool:
    """True when ``value`` is the round-off of a computation whose values are of size ``reference``
    (|value| ≤ 10⁻⁹·|reference|): it is zero, and is written 0, never 4.8·10⁻³⁰.

    >>> within_roundoff(4.796e-30, 0.24 * 31.4**2), within_roundoff(0.3, 1.0), within_roundoff(0.0, 0.0)
    (True, False, True)
    """
    return abs(float(value)) <= ROUNDOFF * abs(float(reference))


def round_off_zero(value: float, size: float) -> float:
    """``value``, or 0 when it is round-off beside ``size`` (the largest of its kind in this position):
    a reaction of 2.7·10⁻²⁹ N beside forces of 10³ N is a zero the solver did not hit exactly.

    Parameters
    ----------
    value : float
        A computed value, in any unit (N, N·m, m/s², ...).
    size : float
        The largest value of its kind in the same computation, in the same unit.

    Returns
    -------
    float
        ``value``, or 0.0 when :func:`within_roundoff` of ``size``.

    Examples
    --------
    >>> round_off_zero(2.67e-29, 3452.4), round_off_zero(-12.5, 3452.4)
    (0.0, -12.5)
    """
    return 0.0 if within_roundoff(value, size) else value


def format_mm(x: float) -> str:
    """Format a paper coordinate in mm: 3 decimals, trailing zeros stripped, -0 as 0.

    Parameters
    ----------
    x : float, mm
        A finite coordinate or length on the page.

    Raises
    ------
    InputError
        If ``x`` is NaN or infinite (a figure computed a coordinate from bad data).

    Examples
    --------
    >>> format_mm(0.0005), format_mm(-2.0), format_mm(1e-9)
    ('0.001', '-2', '0')
    """
    try:
        return _MM_TEXT[x]
    except (KeyError, TypeError):           # not written yet, or not hashable (a 0-d array)
        pass
    x = float(x)
    s = f"{x:.3f}"
    if s[-1] in "nf":                       # 'nan', 'inf', '-inf': the only texts not ending in a digit
        raise InputError(f"cannot write the coordinate {x!r} mm: a figure element computed it from non-finite data")
    s = s.rstrip("0").rstrip(".")
    if s in ("-0", ""):
        s = "0"
    if len(_MM_TEXT) < _MM_TEXT_MAX:
        _MM_TEXT[x] = s
    return s


def format_points(points: Sequence[tuple[float, float]]) -> str:
    """Points as text, ``x,y`` pairs spaced, each number by :func:`format_mm` (an SVG ``points`` attribute;
    the numbers written before are taken from its memo directly).

    >>> format_points(((0.0, 1.5), (2.0004, -0.0001)))
    '0,1.5 2,0'
    """
    get = _MM_TEXT.get
    try:
        return " ".join([f"{get(x) or format_mm(x)},{get(y) or format_mm(y)}" for x, y in points])
    except TypeError:                       # a number that cannot be hashed (a 0-d array): format_mm alone
        return " ".join(f"{format_mm(x)},{format_mm(y)}" for x, y in points)


#: the coordinates written so far in this process and their text (a figure writes the same ones again and
#: again: grid lines, axes, the frame). Keyed by the float; a number equal to a key (an int, a numpy float)
#: converts to that same float, so it gets the same text.
_MM_TEXT: dict[float, str] = {}
_MM_TEXT_MAX = 1 << 17


def _round_sig(value: float, sig: int) -> tuple[float, int]:
    """``value`` rounded to ``sig`` significant digits and the number of decimals that takes."""
    if value == 0:
        return 0.0, 0
    exponent = math.floor(math.log10(abs(value)))
    decimals = max(0, sig - 1 - exponent)
    rounded = round(value, decimals)
    if rounded != 0 and math.floor(math.log10(abs(rounded))) > exponent:  # 9.9996 -> 10.00
        decimals = max(0, decimals - 1)
    return rounded, decimals


def format_column(values: Iterable[float], *, sig: int = 4, decimal: str = ".",
                  reference: float | None = None) -> list[str]:
    """A table column's values, all with the same decimals, as a table prints them: the decimals that
    ``sig`` significant digits of the column's largest value take, fewer when every value ends in zeros.

    Parameters
    ----------
    values : iterable of float
        The column, in the unit its heading states.
    sig : int
        Significant digits of the largest value.
    decimal : str
        Decimal separator (``","`` in the Russian profile).
    reference : float, optional
        As in :func:`format_value`: a value within the round-off of a computation of that size is 0.

    Examples
    --------
    >>> format_column([0.0517825, 0.055, 0.0523])
    ['0.05178', '0.05500', '0.05230']
    >>> format_column([0.0, 30.0, 360.0]), format_column([360.06, 65.58, -10.46], decimal=",")
    (['0', '30', '360'], ['360,1', '65,6', '−10,5'])
    """
    vals = [float(v) for v in values]
    if not all(is_finite(v) for v in vals):
        raise InputError("cannot write a table column with a value that is not finite")
    vals = [0.0 if reference is not None and within_roundoff(v, reference) else v for v in vals]
    top = max((abs(v) for v in vals), default=0.0)
    if top == 0.0 or top < 1e-4 or top >= 1e12:
        return [format_value(v, sig=sig, decimal=decimal) for v in vals]
    decimals = _round_sig(top, sig)[1]
    while decimals > 0 and all(f"{abs(v):.{decimals}f}".endswith("0") for v in vals):
        decimals -= 1
    out = []
    for v in vals:
        text = f"{abs(v):.{decimals}f}"
        zero = float(text) == 0.0
        out.append("0" if zero else (MINUS if v < 0 else "") + text.replace(".", decimal))
    return out


def format_value(value: float, *, sig: int = 4, decimal: str = ".", plus: bool = False,
                 reference: float | None = None) -> str:
    """Format a physical value for a label: ``sig`` significant digits, no trailing zeros.

    Parameters
    ----------
    value : float
        The value, in whatever unit the label states.
    sig : int
        Significant digits kept (integers with more digits are written in full).
    decimal : str
        Decimal separator (``","`` in the Russian profile).
    plus : bool
        Write an explicit ``+`` in front of positive values (signed excess work).
    reference : float, optional
        The size of the values the computation of ``value`` handles (ω₁ for an angular speed,
        ω₁²·r for an acceleration): a value within its round-off (:func:`within_roundoff`) is 0.

    Examples
    --------
    >>> format_value(43.69476), format_value(1234567.0), format_value(15.0, plus=True)
    ('43.69', '1234567', '+15')
    >>> format_value(2.5e-6), format_value(6.119e-14, reference=12.6)
    ('2.5·10⁻⁶', '0')
    """
    value = float(value)
    if not is_finite(value):
        raise InputError(f"cannot write the value {value!r} on a figure: it is not finite")
    if value == 0 or (reference is not None and within_roundoff(value, reference)):
        return "0"
    mag = abs(value)
    if mag < 1e-4 or mag >= 1e12:
        exponent = math.floor(math.log10(mag))
        mantissa = format_value(mag / 10.0**exponent, sig=sig, decimal=decimal)
        if mantissa == "10":
            mantissa, exponent = "1", exponent + 1
        sup = str(exponent).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
        text = f"{mantissa}·10{sup}"
    else:
        rounded, decimals = _round_sig(mag, sig)
        text = f"{rounded:.{decimals}f}"
        if "." in text:
            text = text.rstrip("0").rstrip(".")
        text = text.replace(".", decimal)
    if value < 0:
        return MINUS + text
    return ("+" + text) if plus else text


#: the smallest scale written as a plain decimal (six decimals: 0.000002); a smaller one keeps its power of ten
SCALE_PLAIN_MIN = 1e-6


def format_scale(per_mm: float, *, sig: int = 4, decimal: str = ".") -> str:
    """A drawing scale (units per mm) as a draftsman writes it: a plain decimal, ``0.00002`` and never
    ``2·10⁻⁵`` (ru, zh and en course books write μ_J = 0,00002 кг·м²/мм); the one rule of every μ on a figure,
    a sheet and in the text of the command line. Below :data:`SCALE_PLAIN_MIN` (no convenient scale of a
    course drawing) and otherwise as :func:`format_value`.

    >>> format_scale(2e-5), format_scale(2.5e-5, decimal=","), format_scale(0.02618), format_scale(2e-7)
    ('0.00002', '0,000025', '0.02618', '2·10⁻⁷')
    """
    mag = abs(float(per_mm))
    if not SCALE_PLAIN_MIN <= mag < 1e-4 or not is_finite(mag):
        return format_value(per_mm, sig=sig, decimal=decimal)
    exponent = math.floor(math.log10(mag))
    decimals = max(0, sig - 1 - exponent)
    text = f"{round(mag, decimals):.{decimals}f}".rstrip("0").rstrip(".").replace(".", decimal)
    return (MINUS + text) if per_mm < 0 else text
