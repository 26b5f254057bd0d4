"""The symbols of forces and moments as the books write them: the inertia and balancing subscripts of a
force's label in the notation's language (moved down out of :mod:`graphmethods.sheets.forces`, so that the
force working, tables and figures share it without importing one another).

>>> force_symbol("F_i2"), force_symbol("M_i3", "ru"), force_symbol("F_b", "zh"), force_symbol("R^τ_12@B")
('F_{i2}', 'M_{и3}', 'F_{b}', 'R^{τ}_{12}')
"""

from __future__ import annotations

import re

from graphmethods.scene import notation as get_notation
from graphmethods.scene.notation import Notation


def force_symbol(label: str, nt: Notation | str | None = None) -> str:
    """A force's or moment's label as markup with the book's subscripts.

    Parameters
    ----------
    label : str
        The solver's ASCII label: ``F_i2`` (inertia force of link 2), ``M_i3`` (inertia moment), ``F_b``
        (balancing force), ``R^τ_12`` (a reaction's component); anything after ``@`` (the point) is dropped.
    nt : Notation or str, optional
        The notation (``"en"``, ``"ru"``, ``"zh"``) whose inertia and balancing subscripts are written;
        English by default.

    Returns
    -------
    str
        The markup: ``R^τ_12`` → ``R^{τ}_{12}``, ``F_i2`` → ``F_{i2}`` (ru ``F_{и2}``, zh ``F_{I2}``), ``F_b`` →
        ``F_{b}`` (ru ``F_{ур}``), ``R_01@…`` → ``R_{01}``; a label without a subscript unchanged.

    Examples
    --------
    >>> force_symbol("F_i2"), force_symbol("M_i3", "ru"), force_symbol("F_i2", "zh"), force_symbol("F_b", "ru")
    ('F_{i2}', 'M_{и3}', 'F_{I2}', 'F_{ур}')
    """
    label = label.split("@")[0]
    m = re.fullmatch(r"([A-Za-z]+)(\^[^_]+)?_(.+)", label)
    if not m:
        return label
    sup = "^{" + m.group(2)[1:] + "}" if m.group(2) else ""
    sub = m.group(3)
    if m.group(1) in ("F", "M") and not sup:
        words = get_notation(nt)
        if sub[:1] == "i" and (len(sub) == 1 or (sub[1:].isdigit() and sub[1:].isascii())):
            sub = words.word("forces.sub_inertia") + sub[1:]
        elif sub == "b":
            sub = words.word("forces.sub_balance")
    return f"{m.group(1)}{sup}_{{{sub}}}"
