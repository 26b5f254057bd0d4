"""The pieces every step-by-step build-up is made of: its page and caption box (:func:`step_page`,
:func:`step_start`), the rules that pick a step's elements by name (:func:`_starts`, :func:`_leader_of`), the
steps that draw something (:func:`_kept`) and the partition of a figure into its steps (:func:`_build`).

Moved down out of :mod:`graphmethods.sheets.steps` (which imports them back) so that the build-ups split
out of it (:mod:`~graphmethods.sheets.construction_steps`, :mod:`~graphmethods.sheets.cam_steps`) use them
without importing the module that lists them.

>>> nt, (page, box, size, tb) = step_start("en", "slide")
>>> (page.width_mm, page.height_mm), size, tb
((338.7, 190.5), 6.5, False)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from graphmethods.errors import InputError
from graphmethods.scene import Axis, Page, Scale, Scene, markup, notation as get_notation
from graphmethods.scene.markup import text_width_mm
from graphmethods.scene.notation import Notation
from graphmethods.scene.steps import LINE_PITCH, BuildUp, Rule, partition, wrap
from graphmethods.sheets.projector import CAPTION_GAP_MM, SLIDE_PAGE

#: the caption band under the figure, mm, and the caption size, by page kind
SLIDE_BAND_MM, SLIDE_CAPTION_MM = 20.0, 6.5
SHEET_BAND_MM, SHEET_CAPTION_MM = 14.0, 5.0


# ----------------------------------------------------------------------------- pages

def step_page(page="slide") -> tuple[Page, tuple[float, float, float, float], float, bool]:
    """The page a step figure is built on, the caption box under it, the caption size and whether the
    figure gets a title block.

    ``"slide"`` is a 16:9 slide (338.7 × 190.5 mm, no frame, no title block, 6.5 mm captions for a
    projector); ``"A4"`` … ``"A1"`` are landscape sheets with a frame and a title block. A
    :class:`~graphmethods.scene.Page` is used with its bottom margin grown by the caption band.

    Parameters
    ----------
    page : Page or str
        ``"slide"``, ``"A4"``, ``"A3"``, ``"A2"``, ``"A1"`` or a page.

    Returns
    -------
    (Page, (float, float, float, float), float, bool)
        The figure's page, the caption box (left, top, right, bottom, mm), the caption size (mm) and whether
        the figure gets a title block.

    Raises
    ------
    InputError
        For another page name.

    Examples
    --------
    >>> page, box, size, tb = step_page("slide")
    >>> (page.width_mm, page.height_mm), box, size, tb
    ((338.7, 190.5), (8.0, 168.0, 330.7, 186.5), 6.5, False)
    """
    if isinstance(page, Page):
        base = page
    else:
        name = str(page).strip()
        if name.lower() == "slide":
            base = SLIDE_PAGE
        elif name.upper() in ("A4", "A3", "A2", "A1"):
            base = Page(name.upper(), "landscape", frame=True)
        else:
            raise InputError(f"page {page!r}: use slide, A4, A3, A2 or A1")
    slide = base.size == "SLIDE"
    z = float(getattr(base, "enlarged", 1.0))          # a design page: everything 1/z of the slide's
    band = (SLIDE_BAND_MM if slide else SHEET_BAND_MM) / z
    t, r, b, left = base.margins_mm
    page_ = base.with_(margins_mm=(t, r, b + band, left))
    # the caption box starts a little below the figure's page: the descenders of the figure's last
    # line (its scale captions, 1 mm above the page's inner box) stay out of it
    box = (left, base.height_mm - b - band + CAPTION_GAP_MM / z, base.width_mm - r, base.height_mm - b)
    return page_, box, (SLIDE_CAPTION_MM if slide else SHEET_CAPTION_MM) / z, not slide


def step_start(notation: str | Notation = "en", page: str | Page = "slide") -> tuple[
        Notation, tuple[Page, tuple[float, float, float, float], float, bool]]:
    """What every step figure starts from: its notation and :func:`step_page`'s page, caption box (mm),
    caption size (mm) and title-block flag.

    Parameters
    ----------
    notation : Notation or str
        ``"en"``, ``"ru"``, ``"zh"`` or a profile.
    page : Page or str
        ``"slide"``, ``"A4"`` … ``"A1"``, or a page (see :func:`step_page`).

    Examples
    --------
    >>> nt, (page, box, size, tb) = step_start("ru", "A3")
    >>> nt.code, page.size, size, tb
    ('ru', 'A3', 5.0, True)
    """
    return get_notation(notation), step_page(page)




def _fit(caption_mm: float, box, captions) -> float:
    """The caption size: the given one, or smaller until every caption, broken into lines at
    spaces, fits the box (as many lines as its height holds)."""
    from graphmethods.scene.elements import ASCENT, DESCENT

    width, height = box[2] - box[0] - 4.0, box[3] - box[1]
    size = caption_mm
    while size > 0.4 * caption_mm:
        # n lines take (n − 1) pitches plus one line's height with a superscript and a subscript
        tall = (ASCENT + 0.1 + DESCENT + markup.SUB_SHIFT) * size
        rows = max(1, int((height - tall) // (LINE_PITCH * size)) + 1)
        if all(len(wrap(f"{len(captions)}. {c}", size, width)) <= rows
               and all(text_width_mm(line, size) <= width for line in wrap(f"{len(captions)}. {c}", size, width))
               for c in captions):
            return size
        size *= 0.95
    return size


def _build(figure, rules, box, caption_mm, rest) -> BuildUp:
    caps = [c for c, _ in rules]
    return partition(figure, rules, caption_box=box, caption_mm=_fit(caption_mm, box, caps), rest=rest)


def _axis_scale(figure, name: str) -> Scale:
    """The scale of the figure's axis called ``name``."""
    axis = figure.element(name)
    if not isinstance(axis, Axis):
        raise InputError(f"{figure.name}: {name} is not an axis")
    return axis.scale


def _text_of(figure, name: str) -> str:
    """The text of the figure's element called ``name`` (empty when there is none)."""
    return next((str(getattr(e, "text", "")) for e in figure.elements if e.name == name), "")


def _starts(*prefixes: str) -> Callable[[str], bool]:
    """Rule: the elements whose names begin with one of ``prefixes``."""
    return lambda n: n.startswith(prefixes)


def _leader_of(names):
    """Rule: the element named one of ``names``, or a leader line drawn to it (``leader-NAME``)."""
    wanted = set(names)
    return lambda n: n in wanted or (n.startswith("leader-") and n[len("leader-"):] in wanted)


def _draws(rule: Rule, names: set[str]) -> bool:
    """Whether ``rule`` (a name, names or a predicate) takes any of ``names``."""
    if callable(rule):
        return any(rule(n) for n in names)
    return bool(({rule} if isinstance(rule, str) else set(rule)) & names)


def _kept(rules: Sequence[tuple[str, Rule]], figure: Scene) -> list[tuple[str, Rule]]:
    """``rules`` without the steps that draw nothing of their own (an image that coincides with one drawn
    before); the last step, which takes what no rule names, stays."""
    drawn = {e.name for e in figure.elements}
    return [r for r in rules[:-1] if _draws(r[1], drawn)] + [rules[-1]]
