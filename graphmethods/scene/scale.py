"""Drawing scales (масштабный коэффициент, 比例尺): the only path from a value to paper.

A scale says how many physical units one millimetre of drawing stands for:
μ_M = 100 N·m/mm means a 1 mm ordinate is 100 N·m. :func:`pick_scale` chooses a
convenient scale (1, 2, 2.5, 4, 5 × 10^k, optionally 1.5 and 3) that makes a span
fit the paper, and says what it chose.

>>> mu_M = Scale("μ_M", "N·m", 100.0)
>>> mu_M.to_mm(2500.0), mu_M.to_value(12.0), mu_M.caption()
(25.0, 1200.0, 'μ_M = 100 N·m/mm')
>>> s = pick_scale(575.0, 120.0, symbol="μ_E", unit="J")
>>> s.per_mm, s.note
(5.0, 'picked: 575 J over 120 mm needs ≥ 4.792 J/mm; chose 5 J/mm')
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, overload

import numpy as np
from numpy.typing import NDArray

from graphmethods.errors import InputError
from graphmethods.scene.numbers import format_scale, format_value
from graphmethods.units import CONVENIENT, convenient_at_least, is_finite

if TYPE_CHECKING:
    from graphmethods.scene.notation import Notation

#: the convenient mantissas textbooks use; 1.5 and 3 are allowed on request
SERIES = CONVENIENT
SERIES_EXTRA = (1.5, 3.0)


@dataclass(frozen=True)
class Scale:
    """A drawing scale: ``per_mm`` physical units (``unit``) per millimetre of paper.

    Parameters
    ----------
    symbol : str
        Its name in markup, e.g. ``"μ_M"``, ``"μ_{φ}"``.
    unit : str
        The physical unit of the drawn quantity (``"N·m"``, ``"J"``, ``"rad"``).
    per_mm : float
        Units per millimetre; positive and finite.
    note : str
        How it was chosen (set by :func:`pick_scale`), for reports.
    alt_per_mm, alt_unit : float, str
        An equivalent form shown in brackets in the caption, e.g. ``1.5`` and ``"°"``
        for ``(1.5°/mm)``; ``alt_unit=""`` shows none.

    Examples
    --------
    >>> round(Scale("μ_φ", "rad", 0.025).to_mm(3.14159), 4)
    125.6636
    """

    symbol: str
    unit: str
    per_mm: float
    note: str = ""
    alt_per_mm: float = 0.0
    alt_unit: str = ""

    def __post_init__(self) -> None:
        try:
            value = float(self.per_mm)
        except (TypeError, ValueError):
            raise InputError(f"scale {self.symbol}: {self.per_mm!r} is not a number; "
                             "give units per mm, e.g. 100") from None
        if not is_finite(value) or value <= 0:
            raise InputError(f"scale {self.symbol} = {self.per_mm!r} {self.unit}/mm: a scale must be a positive "
                             f"finite number of units per mm")
        object.__setattr__(self, "per_mm", value)

    @overload
    def to_mm(self, value: float) -> float: ...
    @overload
    def to_mm(self, value: NDArray[np.float64] | Sequence[float]) -> NDArray[np.float64]: ...

    def to_mm(self, value: float | NDArray[np.float64] | Sequence[float]) -> float | NDArray[np.float64]:
        """Paper length in mm of a physical ``value`` (float or array): value / μ."""
        if isinstance(value, (int, float)):
            return float(value) / self.per_mm
        return np.asarray(value, dtype=float) / self.per_mm

    @overload
    def to_value(self, mm: float) -> float: ...
    @overload
    def to_value(self, mm: NDArray[np.float64] | Sequence[float]) -> NDArray[np.float64]: ...

    def to_value(self, mm: float | NDArray[np.float64] | Sequence[float]) -> float | NDArray[np.float64]:
        """Physical value of a paper length in mm (float or array): mm · μ."""
        if isinstance(mm, (int, float)):
            return float(mm) * self.per_mm
        return np.asarray(mm, dtype=float) * self.per_mm

    def caption(self, notation: Notation | str | None = None) -> str:
        """The caption under a figure, in markup: ``"μ_M = 100 N·m/mm"``.

        ``notation`` (a :class:`~graphmethods.scene.notation.Notation` or its code)
        translates the unit and the decimal separator (``"μ_M = 100 Н·м/мм"`` in ru).
        """
        from graphmethods.scene.notation import get as _get_notation

        nt = _get_notation(notation)
        number = format_scale(self.per_mm, sig=4, decimal=nt.decimal)
        # a pure number (1/[δ]) per mm: "μ = 2 mm⁻¹", not "2 /mm" with its unit missing
        per = f"{nt.unit(self.unit)}/{nt.unit('mm')}" if self.unit else f"{nt.unit('mm')}⁻¹"
        text = f"{self.symbol} = {number} {per}"
        if self.alt_unit:
            sep = "" if self.alt_unit == "°" else " "
            alt = format_scale(self.alt_per_mm, sig=4, decimal=nt.decimal)
            text += f" ({alt}{sep}{nt.unit(self.alt_unit)}/{nt.unit('mm')})"
        return text


def pick_scale(span_value: float, span_mm: float, *, series: Iterable[float] = SERIES, allow_15_3: bool = False,
               symbol: str = "μ", unit: str = "") -> Scale:
    """The smallest convenient scale whose drawing of ``span_value`` fits in ``span_mm``.

    Parameters
    ----------
    span_value : float
        The physical span to draw (its absolute value is used), in ``unit``.
    span_mm : float, mm
        The paper available for it.
    series : tuple of float
        Convenient mantissas (times a power of ten).
    allow_15_3 : bool
        Also allow 1.5 and 3 (some textbooks do).
    symbol, unit : str
        Name and unit of the scale returned.

    Returns
    -------
    Scale
        With ``note`` saying what was needed and what was chosen.

    Examples
    --------
    >>> pick_scale(34.36, 150.0, symbol="μ_E", unit="J").per_mm
    0.25
    >>> pick_scale(34.36, 150.0, symbol="μ_E", unit="J", allow_15_3=True).per_mm
    0.25
    >>> pick_scale(290.0, 100.0, allow_15_3=True).per_mm
    3.0
    """
    try:
        span_value, span_mm = abs(float(span_value)), float(span_mm)
    except (TypeError, ValueError):
        raise InputError(f"pick_scale: span {span_value!r} over {span_mm!r} mm is not a pair of numbers") from None
    if not (is_finite(span_value) and is_finite(span_mm)) or span_mm <= 0:
        raise InputError(f"pick_scale for {symbol}: cannot fit {span_value!r} {unit} into {span_mm!r} mm; "
                         f"the span must be finite and the paper length positive")
    mantissas = tuple(sorted({float(m) for m in series} | (set(SERIES_EXTRA) if allow_15_3 else set())))
    if not mantissas or any(not (1.0 <= m < 10.0) for m in mantissas):
        raise InputError(f"pick_scale: series {series!r} must hold mantissas in [1, 10)")
    if span_value == 0:
        return Scale(symbol, unit, mantissas[0],
                     note=f"picked: nothing to fit; chose {format_value(mantissas[0])} {unit}/mm")
    need = span_value / span_mm
    c = convenient_at_least(need, mantissas)
    note = (f"picked: {format_value(span_value)} {unit} over {format_value(span_mm)} mm needs "
            f"≥ {format_value(need)} {unit}/mm; chose {format_value(c, sig=6)} {unit}/mm")
    return Scale(symbol, unit, c, note=note)


def pick_angle_scale(span_rad: float, span_mm: float, *, symbol: str = "μ_φ", allow_15_3: bool = True) -> Scale:
    """A φ scale in rad/mm from a convenient number of degrees per mm (1, 1.5, 2, 2.5, 3, 4, 5 × 10^k).

    The caption shows both forms: ``μ_φ = 0.02618 rad/mm (1.5°/mm)``.

    Examples
    --------
    >>> s = pick_angle_scale(2 * math.pi, 250.0)
    >>> round(s.to_mm(2 * math.pi), 3), s.caption()
    (240.0, 'μ_φ = 0.02618 rad/mm (1.5°/mm)')
    """
    deg = pick_scale(math.degrees(abs(float(span_rad))), span_mm, allow_15_3=allow_15_3, symbol=symbol, unit="°")
    per_mm = math.radians(deg.per_mm)
    note = deg.note + f" = {format_value(per_mm)} rad/mm"
    return Scale(symbol, "rad", per_mm, note=note, alt_per_mm=deg.per_mm, alt_unit="°")
