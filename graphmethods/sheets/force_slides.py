"""The force figures on a 16:9 slide (``graphmethods steps P zhukovsky-lever``, ``force-plans``): what a slide
does differently from a sheet, for :mod:`graphmethods.sheets.forces`.

- the lever's μ_l and μ_F fitted together to fill the slide (:func:`fills_slide`), its statements lettered as
  the slide's values and wrapped beside it as paragraphs (:func:`slide_column`, :func:`column_texts`);
- a plan's caption placed where no line of its plan crosses it (:func:`plan_caption`; on every page).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from typing import Any, TypeVar

from graphmethods.scene import Element, Text
from graphmethods.scene.steps import wrap
from graphmethods.sheets.layout import TEXT_MM, Occupancy

#: the share of a slide's width the lever's statements are wrapped to (the lever keeps the rest)
SLIDE_COLUMN_SHARE = 0.4

Layout = TypeVar("Layout")


def fills_slide(page: Any, mu_l: Any, mu_F: Any) -> bool:
    """A force figure drawn on a slide with its scales left to it: the lever takes :func:`slide_column`, its μ_l
    and μ_F fitted together to fill the slide, as on a course sheet (drawn at a fixed 28 mm largest force it
    filled a third of a slide); nothing else of the course sheet's (its working, arms, least arrows) is drawn.

    >>> from graphmethods.sheets.projector import SLIDE_PAGE
    >>> fills_slide(SLIDE_PAGE, None, None), fills_slide(SLIDE_PAGE, 0.001, None), fills_slide("A4", None, None)
    (True, False, False)
    """
    from graphmethods.sheets.engine.lettering import is_slide

    return mu_l is None and mu_F is None and page is not None and is_slide(page)


def slide_column(L: Layout, page: Any) -> Layout:
    """``L`` (a :class:`~graphmethods.sheets.forces.ForceFigureLayout`) with its text column lettered as a
    slide's values (5 mm once the slide's design page is enlarged), wrapped to :data:`SLIDE_COLUMN_SHARE` of
    the width with a paragraph's gap between two statements, its scales fitted: the lever's statements at
    3.2 mm filled two of a slide's eight rows and left its lower right empty.

    >>> from graphmethods.sheets.forces import LEVER_LAYOUT
    >>> from graphmethods.sheets.projector import design_slide
    >>> L = slide_column(LEVER_LAYOUT, design_slide(1.25))
    >>> round(L.text_mm, 3), L.column_share, L.fitted
    (4.0, 0.4, True)
    """
    from graphmethods.sheets.engine.lettering import lettering

    size = lettering("SLIDE").value_mm / float(getattr(page, "enlarged", 1.0))
    return replace(L, text_mm=size, text_pitch_mm=1.5 * size, paragraph_mm=1.0 * size,  # type: ignore[type-var]
                   column_share=SLIDE_COLUMN_SHARE, fitted=True)


def wrapped(texts: Sequence[str], L: Any, width_mm: float) -> tuple[list[str], list[str]]:
    """The column's lines and their names (``text-K`` for statement K): each statement wrapped to
    ``L.column_share`` of ``width_mm`` when the layout asks for it, as it is otherwise.

    >>> from graphmethods.sheets.forces import LEVER_LAYOUT
    >>> wrapped(["a b", "c"], LEVER_LAYOUT, 100.0)
    (['text-0', 'text-1'], ['a b', 'c'])
    """
    names = [f"text-{k}" for k in range(len(texts))]
    if L.column_share is None:
        return names, list(texts)
    pairs = [(nm, line) for nm, t in zip(names, texts) for line in wrap(t, L.text_mm, L.column_share * width_mm)]
    return [nm for nm, _ in pairs], [line for _, line in pairs]


def column_texts(texts: Sequence[str], x: float, y: float, L: Any, prefix: str = "text",
                 names: Sequence[str] | None = None) -> list[Text]:
    """Lines of text one under the other from (x, y) at ``L.text_pitch_mm``, named ``prefix-0``, ``prefix-1``, …,
    or ``names`` (the lines of one wrapped statement share its name, ``L.paragraph_mm`` more between two).

    >>> from graphmethods.sheets.forces import LEVER_LAYOUT
    >>> [t.at[1] for t in column_texts(["a", "b"], 0.0, 10.0, LEVER_LAYOUT)]
    [10.0, 16.0]
    """
    names = names if names is not None else [f"{prefix}-{k}" for k in range(len(texts))]
    out: list[Text] = []
    for k, t in enumerate(texts):
        y += 0.0 if k == 0 else L.text_pitch_mm + (L.paragraph_mm if names[k] != names[k - 1] else 0.0)
        out.append(Text((x, y), t, size_mm=L.text_mm, name=names[k]))
    return out


def plan_caption(cap: str, cell: tuple[float, float, float], drawn: Sequence[Element], L: Any, name: str) -> Text:
    """A plan's caption above its cell (left, top, width): at the left, else at the right, else higher, the first
    that no line of the plan crosses (a reaction's line of action runs ``L.overhang_mm`` beyond the cell: the
    engine's group RRP (2, 3) was struck through by R₀₃'s)."""
    left, top, width = cell
    ink = Occupancy(pad_mm=0.3)
    ink.register(*drawn)
    spots = ((left, top - L.caption_rise_mm, "start"), (left + width, top - L.caption_rise_mm, "end"),
             (left, top - L.caption_rise_mm - L.overhang_mm, "start"))
    texts = [Text((x, y), cap, size_mm=TEXT_MM, anchor=a, name=name) for x, y, a in spots]
    return next((t for t in texts if (box := t.bbox()) is not None and ink.is_free(box, lines=True)), texts[0])
