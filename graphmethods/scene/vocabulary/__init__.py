"""The vocabulary of every figure family: words, symbols and Russian units in en / ru / zh, as data.

The texts live in the TOML files of this folder, one per figure family (``kinematics.toml`` the
kinematic figures', ``forces.toml`` the force analysis', ...), each entry one row keyed by its
concept with the three languages as its columns, so a word cannot be changed in one language and
forgotten in another::

    [words]
    plan = ["Velocity plan, position {k}", "План скоростей, положение {k}", "速度多边形（位置{k}）"]
    [symbols]
    omega = "ω"          # one text: the three languages write it alike

- ``[words]``: texts with ``{placeholders}`` for
  :meth:`~graphmethods.scene.notation.Notation.word`;
- ``[symbols]``: symbol markup for :meth:`~graphmethods.scene.notation.Notation.sym`;
- ``[units_ru]`` (``notation.toml`` only): every unit as Russian writes it, one table for all
  figures (:meth:`~graphmethods.scene.notation.Notation.unit`).

``notation.toml`` holds the notation's own tables, reached without a prefix (``sym("M_d")``); a
family's keys are reached through its file's name: ``[words] plan`` of ``kinematics.toml`` is
``notation.word("kinematics.plan", k=3)``. The figure modules keep no tables of their own
(``tests/test_vocabulary.py`` holds them to it, and checks that every key has three non-empty
texts with the same placeholders).

>>> table = parse('[words]\\ngain = ["gain", "избыток", "盈功"]\\n[symbols]\\nomega = "ω"', "example")
>>> table.words["gain"][1], table.symbols["omega"]
('избыток', ('ω', 'ω', 'ω'))
"""

from __future__ import annotations

import sys
from functools import cache
from importlib import resources
from typing import NamedTuple

Triple = tuple[str, str, str]

#: the file of the notation's own (unprefixed) tables and of the one table of Russian units
CORE = "notation"


class Family(NamedTuple):
    """One vocabulary file's tables: ``{key: (en, ru, zh)}`` words and symbols, ``{unit: ru}`` units."""

    symbols: dict[str, Triple]
    words: dict[str, Triple]
    units_ru: dict[str, str]


def _triple(value: object, where: str) -> Triple:
    """An entry as ``(en, ru, zh)``: a list of three non-empty texts, or one text for all three."""
    if isinstance(value, str) and value:
        return (value, value, value)
    if isinstance(value, list) and len(value) == 3 and all(isinstance(t, str) and t for t in value):
        return (value[0], value[1], value[2])
    raise ValueError(f"vocabulary {where}: give [\"en\", \"ru\", \"zh\"] (or one text for all three), not {value!r}")


def parse(text: str, name: str) -> Family:
    """The tables of one vocabulary file's TOML text.

    Parameters
    ----------
    text : str
        The file's TOML: tables ``[words]``, ``[symbols]`` and (the core only) ``[units_ru]``.
    name : str
        The family's name (the file's stem), for messages.

    Returns
    -------
    Family
        Its words and symbols as ``(en, ru, zh)`` triples and its Russian units.

    Raises
    ------
    ValueError
        For an unknown table, an entry that is not three texts (or one), or Russian units outside
        the core file (a programming error, found at import).
    """
    if sys.version_info >= (3, 11):
        import tomllib
    else:                                # Python 3.10: the same parser, installed as a dependency
        import tomli as tomllib
    data = tomllib.loads(text)
    unknown = set(data) - {"words", "symbols", "units_ru"}
    if unknown or ("units_ru" in data and name != CORE):
        raise ValueError(f"vocabulary {name}: tables are [words] and [symbols] (and [units_ru] in {CORE}.toml "
                         f"only), not {sorted(unknown) or ['units_ru']}")
    words = {key: _triple(value, f"{name}.{key}") for key, value in data.get("words", {}).items()}
    symbols = {key: _triple(value, f"{name}.{key}") for key, value in data.get("symbols", {}).items()}
    units = {str(unit): str(ru) for unit, ru in data.get("units_ru", {}).items()}
    return Family(symbols, words, units)


def families() -> list[str]:
    """The names of the figure families' files, sorted (``["acceleration", "calculus", ...]``; not the core)."""
    return list(family_names())


@cache
def family_names() -> tuple[str, ...]:
    """:func:`families`, listed once per process."""
    names = (entry.name for entry in resources.files(__name__).iterdir())
    return tuple(sorted(n.removesuffix(".toml") for n in names if n.endswith(".toml") and n != f"{CORE}.toml"))


@cache
def family(name: str) -> Family:
    """The tables of one vocabulary file (``family("check").words["carried"]``), read once.

    >>> family("numbers").words["zero_here"][0]
    '{q} = 0 in this position'
    """
    text = resources.files(__name__).joinpath(f"{name}.toml").read_text(encoding="utf-8")
    return parse(text, name)


def tables() -> tuple[dict[str, Triple], dict[str, Triple], dict[str, str]]:
    """The core tables merged with every family's, a family's keys prefixed by its name.

    Returns
    -------
    tuple of dict
        ``(symbols, words, units_ru)``: the core's unprefixed entries and ``"family.key"`` ones.

    >>> symbols, words, units_ru = tables()
    >>> symbols["M_d"][1], words["kinematics.plan"][0][:13], units_ru["J"]
    ('M_д', 'Velocity plan', 'Дж')
    """
    core = family(CORE)
    all_symbols, all_words = dict(core.symbols), dict(core.words)
    for name in families():
        tables_of = family(name)
        all_words.update((f"{name}.{key}", triple) for key, triple in tables_of.words.items())
        all_symbols.update((f"{name}.{key}", triple) for key, triple in tables_of.symbols.items())
    return all_symbols, all_words, dict(core.units_ru)
