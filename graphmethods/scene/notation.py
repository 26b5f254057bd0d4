"""Notation profiles: the symbols, words and units of three textbook traditions.

``en`` (English theory of machines), ``ru`` (Russian ТММ) and ``zh`` (Chinese 机械原理)
write the same construction differently: M_d/M_r vs M_д/M_с vs M_ed/M_er, "excess
work" vs "избыточная работа" vs 盈功/亏功, ΔW_max vs A_изб, "M, N·m" vs "M, Н·м" vs
"M/(N·m)". A figure asks its profile for every string it draws, so one switch
changes the whole figure. The texts themselves are data: the TOML files of
:mod:`graphmethods.scene.vocabulary` (``notation.toml`` for the keys below).

>>> ru = get("ru")
>>> ru.sym("M_d"), ru.sym("delta_W_max"), ru.unit("N·m"), ru.quantity("M", "N·m")
('M_д', 'A_{изб}', 'Н·м', 'M, Н·м')
>>> get("zh").quantity("M", "N·m"), get("zh").word("gain")
('M/(N·m)', '盈功')
>>> get("ru").number(0.025)
'0,025'
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from graphmethods.errors import InputError
from graphmethods.scene import vocabulary
from graphmethods.scene.numbers import format_column, format_value

_PROFILES = ("en", "ru", "zh")


class VocabularyError(LookupError):
    """A figure asked for a word or symbol the vocabulary lacks: a programming error, never bad input
    (so no ``except InputError`` that retries another variant or layout can swallow it)."""


@dataclass(frozen=True)
class Notation:
    """One textbook tradition's symbols (markup), words, units and number style.

    Use :func:`get` to obtain one; ``code`` is ``"en"``, ``"ru"`` or ``"zh"``.
    """

    code: str
    symbols: Mapping[str, str] = field(repr=False)
    words: Mapping[str, str] = field(repr=False)
    units: Mapping[str, str] = field(repr=False)
    decimal: str = "."
    quantity_style: str = "comma"   # "comma": "M, N·m"; "slash": "M/(N·m)"

    def sym(self, key: str) -> str:
        """The symbol (markup) for a concept key such as ``"M_d"`` or ``"delta_W_max"``."""
        try:
            return self.symbols[key]
        except KeyError:
            raise VocabularyError(f"notation {self.code}: no symbol {key!r}; add it to scene/vocabulary/") from None

    def word(self, key: str, **fill: object) -> str:
        """The words for a concept key such as ``"energy_indicator"`` or ``"kinematics.scheme"``.

        Keys of a figure family carry its vocabulary module's name (``"kinematics.plan"``, from
        ``scene/vocabulary/kinematics.toml``); ``fill`` gives the text's
        ``{placeholders}`` (:meth:`str.format`); without any the text is returned as written.

        >>> get("ru").word("kinematics.plan", k=3)
        'План скоростей, положение 3'
        """
        try:
            text = self.words[key]
        except KeyError:
            raise VocabularyError(f"notation {self.code}: no word {key!r}; add it to scene/vocabulary/") from None
        return text.format(**fill) if fill else text

    def unit(self, unit: str) -> str:
        """A unit as this tradition writes it (``"J"`` -> ``"Дж"`` in ru); unknown units pass through."""
        return self.units.get(unit, unit)

    def quantity(self, symbol: str, unit: str) -> str:
        """An axis or column name with its unit: ``"M, N·m"`` (en, ru) or ``"M/(N·m)"`` (zh)."""
        u = self.unit(unit)
        if not u:
            return symbol
        if self.quantity_style == "slash":
            simple = all(c not in u for c in "·/ °")
            return f"{symbol}/{u}" if simple else f"{symbol}/({u})"
        return f"{symbol}, {u}"

    def number(self, value: float, *, sig: int = 4, plus: bool = False, reference: float | None = None) -> str:
        """A value written with this tradition's decimal separator and a typographic minus; 0 when it
        is within the round-off of a computation of size ``reference``
        (:func:`~graphmethods.scene.numbers.within_roundoff`)."""
        return format_value(value, sig=sig, decimal=self.decimal, plus=plus, reference=reference)

    def column(self, values: Iterable[float], *, sig: int = 4, reference: float | None = None) -> list[str]:
        """A table column written with one number of decimals, this tradition's separator
        (:func:`~graphmethods.scene.numbers.format_column`).

        >>> get("ru").column([0.0517825, 0.055])
        ['0,05178', '0,05500']
        """
        return format_column(values, sig=sig, decimal=self.decimal, reference=reference)

    @property
    def colon(self) -> str:
        """The colon after a caption: full-width "：" in Chinese text, ": " otherwise."""
        return "：" if self.code == "zh" else ": "

    @property
    def list_separator(self) -> str:
        """Between the numbers of a list: "; " where the decimal mark is a comma ("0,08; u = 6", never
        "0,08, u = 6"), full-width "，" in Chinese text, ", " otherwise.

        >>> get("ru").list_separator, get("en").list_separator, get("zh").list_separator
        ('; ', ', ', '，')
        """
        return "，" if self.code == "zh" else ("; " if self.decimal == "," else ", ")

    @property
    def semicolon(self) -> str:
        """The separator of two clauses: full-width "；" in Chinese text, ";  " otherwise."""
        return "；" if self.code == "zh" else ";  "

    def zero(self, symbol: str, because: str) -> str:
        """A quantity that is zero in this position, said with its reason, as a textbook writes it.

        >>> get("en").zero("a^n_{BA}", "ω_{2}")
        'a^n_{BA} = 0 (ω_{2} = 0 in this position)'
        """
        return f"{symbol} = 0 ({self.word('numbers.zero_here', q=because)})"


class _Texts(Mapping[str, str]):
    """One language's words (or symbols): the core's keys at once, a family's ``"family.key"`` read from its
    file the first time one of its keys is asked for (:func:`vocabulary.family` parses each file once per
    process, for the three languages). Iterating reads every family (in the order of
    :func:`vocabulary.tables`: the core's, then the families' sorted by name)."""

    def __init__(self, i: int, table: str) -> None:
        self._i, self._table = i, table
        self._found: dict[str, str] = {}
        self._read: set[str] = set()
        self._complete = False
        self._read_family(vocabulary.CORE)

    def _read_family(self, name: str) -> None:
        triples: dict[str, tuple[str, str, str]] = getattr(vocabulary.family(name), self._table)
        prefix = "" if name == vocabulary.CORE else f"{name}."
        self._found.update((prefix + key, triple[self._i]) for key, triple in triples.items())
        self._read.add(name)

    def __getitem__(self, key: str) -> str:
        try:
            return self._found[key]
        except KeyError:
            name = key.partition(".")[0]
            if name in self._read or name not in vocabulary.family_names():
                raise
        self._read_family(name)
        return self._found[key]

    def _every(self) -> dict[str, str]:
        if not self._complete:
            self._found.clear()
            self._read.clear()
            for name in (vocabulary.CORE, *vocabulary.family_names()):
                self._read_family(name)
            self._complete = True
        return self._found

    def __iter__(self) -> Iterator[str]:
        return iter(self._every())

    def __len__(self) -> int:
        return len(self._every())


def _build(code: str) -> Notation:
    i = _PROFILES.index(code)
    units = MappingProxyType(dict(vocabulary.family(vocabulary.CORE).units_ru) if code == "ru" else {})
    return Notation(code, _Texts(i, "symbols"), _Texts(i, "words"), units, decimal="," if code == "ru" else ".",
                    quantity_style="slash" if code == "zh" else "comma")


NOTATIONS = MappingProxyType({code: _build(code) for code in _PROFILES})


def get(notation: Notation | str | None = None) -> Notation:
    """The profile for ``"en"``, ``"ru"`` or ``"zh"`` (``None`` means ``"en"``; a Notation passes through).

    Parameters
    ----------
    notation : Notation, str or None
        A language code (any case), a profile, or None for English.

    Returns
    -------
    Notation
        The language's symbols, words, units and decimal sign.

    Raises
    ------
    InputError
        For an unknown code.

    Examples
    --------
    >>> get("RU").code, get(None).code, get(get("zh")).code, get("ru").decimal
    ('ru', 'en', 'zh', ',')
    """
    if notation is None:
        return NOTATIONS["en"]
    if isinstance(notation, Notation):
        return notation
    try:
        return NOTATIONS[str(notation).lower()]
    except KeyError:
        raise InputError(f"unknown notation {notation!r}; use one of {', '.join(_PROFILES)}") from None


def in_language(words: tuple[str, str, str], notation: Notation | str | None = None, **fill: object) -> str:
    """The text of an ``(en, ru, zh)`` triple in a notation's language, ``{placeholders}`` filled.

    The sheets keep their own vocabulary as tables of such triples; this picks one text for
    a figure's profile.

    Parameters
    ----------
    words : tuple of str
        The same text in en, ru and zh, in that order. (Without ``fill`` any triple is picked
        from alike, such as one tuple of paragraphs per language.)
    notation : Notation, str or None
        A profile or its code, as :func:`get` takes it (``None`` means ``"en"``).
    **fill
        Values for the text's ``{placeholders}`` (:meth:`str.format`). Without any, the text is
        returned as written, so ``{{`` stays doubled and markup such as ``ψ_{max}`` is kept.

    Returns
    -------
    str
        The text in the notation's language.

    Raises
    ------
    InputError
        For an unknown notation.

    Examples
    --------
    >>> in_language(("gain", "избыток", "盈功"), "zh")
    '盈功'
    >>> in_language(("position {k}", "положение {k}", "位置{k}"), get("ru"), k=3)
    'положение 3'
    """
    code = get(notation).code
    if code not in _PROFILES:
        raise InputError(f"unknown notation {code!r}; use one of {', '.join(_PROFILES)}")
    text = words[_PROFILES.index(code)]
    return text.format(**fill) if fill else text
