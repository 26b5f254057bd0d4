"""Lettering by page format: one table of text sizes per format, from the standard series.

ГОСТ 2.304 and GB/T 14691 letter in the series 2.5, 3.5, 5, 7, 10, 14 mm (the font size, the em
height). A course sheet (A1, A2) writes its labels at 3.5 mm at least, its values at 5 and its titles
at 7; an A4 figure may go down to 2.5 mm. Sub- and superscripts are drawn at
:data:`graphmethods.scene.markup.SCRIPT_SCALE` of their text and are exempt from the minimum.

>>> lettering("A1")
Lettering(label_mm=3.5, value_mm=5.0, title_mm=7.0, heading_mm=5.0, minimum_mm=3.5)
>>> lettering("A4").minimum_mm
2.5
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any, TypeVar, cast

from graphmethods.scene.markup import MIN_TEXT_MM

F = TypeVar("F", bound=Callable[..., Any])

#: the standard series of lettering sizes (mm): ГОСТ 2.304, GB/T 14691, ISO 3098
SERIES_MM = (2.5, 3.5, 5.0, 7.0, 10.0, 14.0)


@dataclass(frozen=True)
class Lettering:
    """Text sizes (font size, mm) of one page format.

    Parameters
    ----------
    label_mm : float, mm
        Point names, vector names, tick values: the bulk of the text.
    value_mm : float, mm
        Results written out on the sheet (a balancing moment, a table's values).
    title_mm : float, mm
        The sheet's title.
    heading_mm : float, mm
        The heading of a panel.
    minimum_mm : float, mm
        The smallest size a text may have on this format (sub- and superscripts aside).
    """

    label_mm: float
    value_mm: float
    title_mm: float
    heading_mm: float
    minimum_mm: float


#: one table per page format; a slide's text is seen from the back of a room: as large as A1's labels
LETTERING: dict[str, Lettering] = {
    "A0": Lettering(3.5, 5.0, 7.0, 5.0, 3.5),
    "A1": Lettering(3.5, 5.0, 7.0, 5.0, 3.5),
    "A2": Lettering(3.5, 5.0, 7.0, 5.0, 3.5),
    "A3": Lettering(2.5, 3.5, 5.0, 3.5, 2.5),
    "A4": Lettering(2.5, 3.5, 5.0, 3.5, 2.5),
    "SLIDE": Lettering(3.5, 5.0, 7.0, 5.0, 3.5),
}


def lettering(page: Any) -> Lettering:
    """The lettering of a page format: a :class:`~graphmethods.scene.Page` or its size name ("A1", "slide").

    A page drawn inside a larger sheet (:func:`graphmethods.sheets.composition.region_page`) keeps the
    sheet's size, so a figure drawn into a region of an A1 sheet letters as A1.

    >>> from graphmethods.scene import Page
    >>> lettering(Page("A2", "landscape")).title_mm
    7.0
    """
    size = str(getattr(page, "size", page)).upper()
    return LETTERING.get(size, LETTERING["A4"])


def is_course_sheet(page: Any) -> bool:
    """A1 or A2 (or A0): a course sheet, lettered at 3.5 mm and up, judged for empty space.

    >>> is_course_sheet("A1"), is_course_sheet("A4")
    (True, False)
    """
    return str(getattr(page, "size", page)).upper() in ("A0", "A1", "A2")


def is_slide(page: Any) -> bool:
    """A 16:9 slide (``graphmethods steps``' PDF slides, SVG frames and the HTML stepper): lettered as an A1
    sheet (read from the back of a room) and judged for empty space inside its margins.

    >>> is_slide("slide"), is_slide("A4")
    (True, False)
    """
    return str(getattr(page, "size", page)).upper() == "SLIDE"


@contextmanager
def lettered(page: Any) -> Iterator[Lettering]:
    """Build figures lettered for ``page``'s format: every text made inside is at least its minimum size.

    The parts of an A1 sheet are drawn by the figure functions of the A4 figures; built inside
    ``with lettered("A1"):`` their texts (and tables' rows) come out at 3.5 mm and up, and their label
    placement works with those sizes. Outside, sizes are as given.

    >>> from graphmethods.scene import Text
    >>> with lettered("A1"):
    ...     t = Text((0, 0), "B", size_mm=2.8)
    >>> t.size_mm, Text((0, 0), "B", size_mm=2.8).size_mm
    (3.5, 2.8)
    """
    let = lettering(page)
    token = MIN_TEXT_MM.set(let.minimum_mm if is_course_sheet(page) else MIN_TEXT_MM.get())
    try:
        yield let
    finally:
        MIN_TEXT_MM.reset(token)


def lettered_by_page(default: str = "A1") -> Callable[[F], F]:
    """Decorate a sheet function so that it builds its parts :func:`lettered` for its ``page`` argument
    (``default`` when not given)."""
    def wrap(fn: F) -> F:
        @functools.wraps(fn)
        def sheet(*args: Any, **kwargs: Any) -> Any:
            page = kwargs.get("page", default)
            with lettered(page if hasattr(page, "size") else str(page).upper()):
                return fn(*args, **kwargs)
        return cast(F, sheet)
    return wrap


__all__ = ["LETTERING", "SERIES_MM", "Lettering", "is_course_sheet", "is_slide", "lettered", "lettered_by_page",
           "lettering"]
