"""Titles in the three languages of the figures: a problem's name as each notation writes it.

A problem's title is one :class:`Title`: either a plain string, used for every language, or a
mapping by language (``"en"``, ``"ru"``, ``"zh"``). :meth:`Title.title_in` gives the text for a
figure's notation; when that language is missing it falls back to the English text (or, when
there is no English, to the first language given, in the order en, ru, zh), so an untranslated
title is still printed, in the language it was written in, rather than left out.

>>> t = Title.of({"en": "offset slider-crank press", "ru": "дезаксиальный кривошипно-ползунный пресс",
...               "zh": "偏置曲柄滑块压力机"})
>>> t.title_in("ru"), t.title_in("zh"), str(t)
('дезаксиальный кривошипно-ползунный пресс', '偏置曲柄滑块压力机', 'offset slider-crank press')
>>> Title.of("my press").title_in("zh")                          # a plain string: every language
'my press'
>>> Title.of({"en": "Flywheel", "ru": "Маховик"}).title_in("zh")  # zh missing: the English
'Flywheel'
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TypeVar

from graphmethods.errors import InputError
from graphmethods.units import check_text

LANGUAGES = ("en", "ru", "zh")

K = TypeVar("K")


@dataclass(frozen=True)
class Title:
    """A title as a plain string or as texts by language, with an English fallback.

    Build one with :meth:`Title.of`. Identifiers stay ASCII elsewhere; a title is text only.

    Attributes
    ----------
    default : str
        The text used for a language that is not given: the English text, or the plain string,
        or (a mapping without English) the first language given in the order en, ru, zh.
    texts : tuple of (str, str)
        ``(language, text)`` pairs in the order en, ru, zh; empty for a plain string.
    """

    default: str = ""
    texts: tuple[tuple[str, str], ...] = ()

    @classmethod
    def of(cls, value: object, *, where: str = "title") -> Title:
        """A Title from a plain string, a mapping by language, a Title (returned as it is) or None.

        Parameters
        ----------
        value : str, mapping, Title or None
            ``"text"`` (used for every language), or ``{"en": ..., "ru": ..., "zh": ...}`` with
            any non-empty subset of those keys. None gives an empty title.
        where : str
            What the value is, for the error message (e.g. ``"press.json: key 'name'"``).

        Returns
        -------
        Title

        Raises
        ------
        InputError
            For a value that is neither text nor a mapping, an unknown language, an empty
            mapping, or a language whose text is not a non-empty string.

        Examples
        --------
        >>> Title.of({"ru": "пресс"}).title_in("en")     # no English: the first language given
        'пресс'
        >>> Title.of({"de": "Presse"})
        Traceback (most recent call last):
        ...
        graphmethods.errors.InputError: title: unknown language 'de'; give the title in en, ru and/or zh
        """
        if isinstance(value, Title):
            return value
        if value is None:
            return cls()
        if isinstance(value, str):
            return cls(check_text(value, where))
        if isinstance(value, Mapping):
            for lang in value:
                if not isinstance(lang, str) or lang not in LANGUAGES:
                    raise InputError(f"{where}: unknown language {lang!r}; give the title in "
                                     f"{', '.join(LANGUAGES[:-1])} and/or {LANGUAGES[-1]}")
            for lang, text in value.items():
                if isinstance(text, str):
                    check_text(text, f"{where} ({lang})")
                if not isinstance(text, str) or not text.strip():
                    raise InputError(f"{where}: the {lang} title must be non-empty text; got {text!r} "
                                     f"(leave a language out to fall back to English)")
            texts: tuple[tuple[str, str], ...] = tuple((lang, value[lang]) for lang in LANGUAGES if lang in value)
            if not texts:
                raise InputError(f"{where}: a title by language needs at least one of "
                                 f"{', '.join(LANGUAGES)}; got an empty mapping")
            return cls(dict(texts).get("en", texts[0][1]), texts)
        raise InputError(f"{where} must be text, or a mapping of language (en, ru, zh) to text; got {value!r}")

    def title_in(self, lang: str | None) -> str:
        """The text for language ``lang`` (``"en"``, ``"ru"``, ``"zh"``), or the fallback when it is missing.

        Parameters
        ----------
        lang : str or None
            A language code; None or an unknown code gives the fallback (:attr:`default`).

        Returns
        -------
        str

        Examples
        --------
        >>> Title.of({"en": "press", "zh": "压力机"}).title_in("ru")
        'press'
        """
        for code, text in self.texts:
            if code == lang:
                return text
        return self.default

    def translated(self, lang: str) -> bool:
        """Whether the title is written in ``lang`` itself (a plain string counts for no language).

        Examples
        --------
        >>> t = Title.of({"en": "press", "zh": "压力机"})
        >>> t.translated("zh"), t.translated("ru"), Title.of("press").translated("en")
        (True, False, False)
        """
        return any(code == lang for code, _ in self.texts)

    def to_json(self) -> str | dict[str, str]:
        """The title as a problem file writes it: the plain string, or the mapping by language.

        Examples
        --------
        >>> Title.of("press").to_json(), Title.of({"en": "press", "ru": "пресс"}).to_json()
        ('press', {'en': 'press', 'ru': 'пресс'})
        """
        return dict(self.texts) if self.texts else self.default

    def __str__(self) -> str:
        return self.default

    def __bool__(self) -> bool:
        return bool(self.default)


def titles(table: Mapping[K, tuple[str, str, str]]) -> dict[K, Title]:
    """A table of titles written one row per key, ``key: (en, ru, zh)``, as Titles by key.

    >>> titles({"W3": ("Step resisting moment: flywheel", "Ступенчатый момент сопротивления: маховик",
    ...                "阶梯形阻抗力矩下的飞轮转动惯量")})["W3"].title_in("ru")
    'Ступенчатый момент сопротивления: маховик'
    """
    return {key: Title.of(dict(zip(LANGUAGES, texts))) for key, texts in table.items()}


def text_in(value: object, lang: str | None) -> str:
    """The text of a title-like value in language ``lang``: a Title, a mapping by language, a string or None.

    Parameters
    ----------
    value : Title, mapping, str or None
        Anything :meth:`Title.of` accepts.
    lang : str or None
        ``"en"``, ``"ru"`` or ``"zh"``.

    Returns
    -------
    str
        The text in that language, or the fallback (see :class:`Title`); ``""`` for None.

    Examples
    --------
    >>> text_in({"en": "press", "ru": "пресс"}, "ru"), text_in("press", "zh"), text_in(None, "en")
    ('пресс', 'press', '')
    """
    return Title.of(value).title_in(lang)
