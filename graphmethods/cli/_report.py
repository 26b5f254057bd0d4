"""Text reports in ``--lang``: a result's keys named by their symbols and units in the language, its values
with the language's decimal sign (``study`` and ``motion``; the JSON keys stay the English identifiers).

>>> from graphmethods.scene.notation import get
>>> label("J_F_wittenbauer", get("ru")), label("phi_omega_max_deg", get("zh")), label("kl_mm", get("ru"))
('J_м_wittenbauer, кг·м²', 'φ_ω_max/(°)', 'kl, мм')
>>> value_text([0.5, 1.25], get("ru"))
'0,5; 1,25'
"""

from __future__ import annotations

from typing import Any

from graphmethods.scene import markup
from graphmethods.scene.notation import Notation
from graphmethods.scene.numbers import format_scale

#: the first word of a key -> its symbol (markup, or a notation key in braces) and unit
SYMBOLS = {"omega": ("ω", "rad/s"), "epsilon": ("ε", "rad/s²"), "phi": ("φ", "°"), "t": ("t", "s"),
           "J": ("J", "kg·m²"), "delta": ("δ", ""), "tol": ("tol", ""), "rtol": ("rtol", ""), "turns": ("N", ""),
           "M": ("M", "N·m"), "A": ("A", "J"), "kl": ("kl", "mm"), "mu": ("μ", ""), "n": ("n", "rev/min"),
           "chi": ("χ", ""), "tan": ("tan", ""), "positions": ("m", "")}
#: whole keys with a symbol of the notation (J_м, A_изб in Russian) and their unit
WHOLE = {"J_F": ("{dynamics.J_F}", "kg·m²"), "J_e": ("{dynamics.J_e}", "kg·m²"),
         "delta_W_max": ("{delta_W_max}", "J"), "M_d": ("{M_d}", "N·m"), "M_r": ("{M_r}", "N·m"),
         "omega_m": ("{dynamics.omega_m}", "rad/s"), "mu_J": ("μ_J", "kg·m²/mm"), "mu_T": ("{mu_T}", "J/mm")}
#: inner words written as symbols
INNER = {"omega": "ω", "epsilon": "ε", "psi": "ψ", "mu": "μ"}


def _sym(text: str, nt: Notation) -> str:
    return markup.typed(nt.sym(text[1:-1])) if text.startswith("{") else text


def label(key: str, nt: Notation) -> str:
    """``key`` as "symbol, unit" in ``nt``'s language: the longest known head (``J_F``, ``delta_W_max``), then
    the first word (``omega``, ``phi`` … ``_deg``) with the rest as its subscript."""
    deg = key.endswith("_deg")
    base = key.removesuffix("_deg").removesuffix("_mm")
    unit = "°" if deg else ("mm" if key.endswith("_mm") else None)
    parts = base.split("_")
    for n in range(len(parts), 0, -1):
        head = "_".join(parts[:n])
        if head in WHOLE:
            sym, u = WHOLE[head]
            sym = _sym(sym, nt)
            break
    else:
        n = 1
        sym, u = SYMBOLS.get(parts[0], (parts[0], ""))
    rest = "_".join(INNER.get(r, r) for r in parts[n:])
    u = unit if unit is not None else ("" if base.endswith(("_rel_error", "_percent")) else u)
    if "/" in u and nt.unit(u) == u:                    # kg·m²/mm: each part as the language writes it
        u = "/".join(nt.unit(x) for x in u.split("/"))
    return nt.quantity(f"{sym}_{rest}" if rest else sym, u)


def value_text(value: Any, nt: Notation, sig: int = 6, *, key: str = "") -> str:
    """A value in the language: numbers with its decimal sign, lists joined by its list separator; a drawing
    scale (``key`` ``mu_J``, ``mu_T``: its unit is per mm) as the sheet writes it
    (:func:`~graphmethods.scene.numbers.format_scale`: 0.00002, never 2·10⁻⁵).

    >>> from graphmethods.scene.notation import get
    >>> value_text({"mu_J": 2e-5, "J_0": 2e-5}, get("en"))
    'μ_J, kg·m²/mm 0.00002;  J_0, kg·m² 2·10⁻⁵'
    """
    if isinstance(value, bool) or value is None:
        return str(value)
    if key in WHOLE and WHOLE[key][1].endswith("/mm") and isinstance(value, (int, float)):
        return format_scale(float(value), sig=sig, decimal=nt.decimal)
    if isinstance(value, (int, float)):
        return nt.number(float(value), sig=sig)
    if isinstance(value, (list, tuple)):
        return nt.list_separator.join(value_text(v, nt, sig) for v in value)
    if isinstance(value, dict):
        return nt.semicolon.join(f"{label(k, nt)} {value_text(v, nt, sig, key=k)}" for k, v in value.items())
    return str(value)


__all__ = ["label", "value_text"]
