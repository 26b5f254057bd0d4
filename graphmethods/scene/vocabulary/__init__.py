"""The vocabulary of every figure family: words, symbols and Russian units in en / ru / zh.

Each module of this package holds one family's tables (the kinematic figures in
``kinematics.py``, the force analysis in ``forces.py``, ...):

- ``WORDS``: ``{key: (en, ru, zh)}``, texts with ``{placeholders}`` for
  :meth:`~graphmethods.scene.notation.Notation.word`;
- ``SYMBOLS`` (optional): ``{key: (en, ru, zh)}`` symbol markup for
  :meth:`~graphmethods.scene.notation.Notation.sym`;
- ``UNITS_RU`` (optional): ``{unit: Russian unit}`` for
  :meth:`~graphmethods.scene.notation.Notation.unit`.

A module's keys are reached through its name: ``WORDS["plan"]`` of ``kinematics.py`` is
``notation.word("kinematics.plan", k=3)``. The Russian units of all modules form one table,
and two modules may not translate a unit differently. The figure modules keep no tables of
their own (``tests/test_vocabulary.py`` holds them to it, and checks that every key has
three non-empty texts with the same placeholders).

>>> symbols, words, units_ru = tables({}, {"gain": ("gain", "избыток", "盈功")}, {})
>>> words["gain"][1]
'избыток'
"""

from __future__ import annotations

import importlib
import pkgutil
from collections.abc import Mapping

Triple = tuple[str, str, str]


def modules() -> list[str]:
    """The names of the vocabulary modules, sorted (``["acceleration", "forces", ...]``)."""
    return sorted(info.name for info in pkgutil.iter_modules(__path__) if not info.name.startswith("_"))


def tables(symbols: Mapping[str, Triple], words: Mapping[str, Triple],
           units_ru: Mapping[str, str]) -> tuple[dict[str, Triple], dict[str, Triple], dict[str, str]]:
    """The notation's own tables merged with every vocabulary module's, keys prefixed by module.

    Parameters
    ----------
    symbols, words : mapping of str to (en, ru, zh)
        The unprefixed core tables (kept in :mod:`graphmethods.scene.notation`).
    units_ru : mapping of str to str
        The core Russian units.

    Returns
    -------
    tuple of dict
        ``(symbols, words, units_ru)`` with ``"module.key"`` entries added.

    Raises
    ------
    ValueError
        When two modules translate the same unit differently (a programming error, found at
        import).
    """
    all_symbols, all_words, all_units = dict(symbols), dict(words), dict(units_ru)
    for name in modules():
        module = importlib.import_module(f"{__name__}.{name}")
        for key, triple in getattr(module, "WORDS", {}).items():
            all_words[f"{name}.{key}"] = triple
        for key, triple in getattr(module, "SYMBOLS", {}).items():
            all_symbols[f"{name}.{key}"] = triple
        for unit, ru in getattr(module, "UNITS_RU", {}).items():
            if all_units.setdefault(unit, ru) != ru:
                raise ValueError(f"vocabulary.{name}: unit {unit!r} is {ru!r} here but {all_units[unit]!r} elsewhere")
    return all_symbols, all_words, all_units
