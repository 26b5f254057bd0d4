"""Titles in en, ru and zh for the reference cases, which are read as they are.

The reference case files (``shared/cases/``; ``problems/data/slider_crank_press.json`` is the
press's, byte for byte) give their title in English only and must not be edited. The
translations of the problems we ship live here, keyed by the case's identity: a problem file
has no id, so its kind and its English name. :func:`title_of` gives any problem's title,
with these translations when the problem is one of these cases and its file gives no
translation of its own; any other title is returned as it is (a language it lacks falls back
to the English, see :class:`graphmethods.titles.Title`). The worked examples W1–W4 carry
their translations themselves (:data:`graphmethods.problems.worked_examples.TITLES`, keyed by
their ids).

>>> import pathlib
>>> from graphmethods.kinematics import read_case
>>> press = read_case(pathlib.Path(__file__).parent / "data" / "slider_crank_press.json")
>>> press.title.title_in("ru")                     # the file as it is: English only
'offset slider-crank press'
>>> title_of(press).title_in("ru"), title_of(press).title_in("zh")
('дезаксиальный кривошипно-ползунный пресс', '偏置曲柄滑块压力机')
"""

from __future__ import annotations

from graphmethods.titles import LANGUAGES, Title

# (kind, English name as the file gives it) -> the title in every language
CASE_TITLES = {
    ("slider_crank", "offset slider-crank press"): Title.of({
        "en": "offset slider-crank press",
        "ru": "дезаксиальный кривошипно-ползунный пресс",
        "zh": "偏置曲柄滑块压力机",
    }),
}


def title_of(problem) -> Title:
    """The title of a problem, with our translations when it is a reference case that lacks them.

    Parameters
    ----------
    problem : object
        A problem with a ``title`` (a Title, a mapping by language or text), such as a
        :class:`~graphmethods.kinematics.case.Case` or a
        :class:`~graphmethods.problems.cycle.CycleProblem`; its ``kind`` (if any) and English
        title identify a reference case. Anything without a title gives an empty Title.

    Returns
    -------
    Title
        The translated title of a reference case whose own title is in English only (or is a
        plain string), else the problem's own title.

    Examples
    --------
    >>> from graphmethods.problems import w1
    >>> title_of(w1()).title_in("zh")               # W1 carries its own translations
    '柴油发电机组的能量指示图'
    >>> title_of(type("P", (), {"title": "my press"})()).title_in("zh")
    'my press'
    """
    own = Title.of(getattr(problem, "title", None))
    if any(own.translated(lang) for lang in LANGUAGES if lang != "en"):
        return own                          # the file translates its title itself
    return CASE_TITLES.get((str(getattr(problem, "kind", "")), own.title_in("en")), own)
