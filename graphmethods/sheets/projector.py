"""The projector slide: a figure or a construction's steps laid out on a smaller design page and
drawn z : 1 on a 16:9 slide, so its text reads from the back of a lecture hall.

:func:`for_projector` sizes the steps of :mod:`graphmethods.sheets.steps`; :func:`projector_figure`
does the same for any one figure; :func:`layout_faults` says what leaves the slide or covers text.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager

from graphmethods.errors import InputError
from graphmethods.scene import Page, Scene
from graphmethods.scene.elements import Text
from graphmethods.scene.markup import MIN_TEXT_MM
from graphmethods.scene.steps import PROJECTOR_TEXT, BuildUp, DesignPage, enlarge, enlarge_note
from graphmethods.sheets.engine.lettering import lettering

#: the gap between the figure's page and the caption box, mm
CAPTION_GAP_MM = 1.5

#: the 16:9 slide the steps are shown on (no frame, no title block)
SLIDE_PAGE = Page("slide", "landscape", margins_mm=(8.0, 8.0, 4.0, 8.0), frame=False)
#: how much a slide's design page may be enlarged, tried from the largest down
ZOOMS = (1.9, 1.8, 1.7, 1.6, 1.5, 1.4, 1.3, 1.2, 1.1, 1.0)


def design_slide(z: float) -> Page:
    """The slide laid out at 1/z of its size (margins too), to be drawn z : 1 (:class:`DesignPage`).

    >>> p = design_slide(2.0)
    >>> p.width_mm, p.margins_mm
    (169.35, (4.0, 4.0, 2.0, 4.0))
    """
    if z == 1.0:
        return SLIDE_PAGE
    t, r, b, left = SLIDE_PAGE.margins_mm
    return DesignPage("slide", "landscape", margins_mm=(t / z, r / z, b / z, left / z), frame=False, enlarged=z)


def smallest_text_mm(bu: BuildUp) -> float:
    """The smallest text of the steps' slides, mm: the figure's labels and the step captions."""
    from graphmethods.render.recording import record

    sizes = [c.data.size_mm for c in record(bu.figure).calls if c.kind == "text"]
    return min(sizes + [bu.caption_mm])


def for_projector(make: Callable[[Page], BuildUp], *, lettered: bool = False, uncrossed: bool = False) -> BuildUp:
    """Steps on a 16:9 slide with text sized for a projector.

    The figure functions size their text for paper (2.5…3.5 mm), which on a 338.7 mm slide is
    about 1/70 of its height. So the figure is laid out on a smaller design page, 1/z of the
    slide, and the whole drawing (text, lines, captions) is drawn z : 1: nothing is laid out
    anew, so nothing can come to overlap or leave the frame. z is the smallest of :data:`ZOOMS`
    that makes the smallest text :data:`~graphmethods.scene.steps.PROJECTOR_TEXT` of the slide's
    height (1/40: 4.8 mm), or, for a figure too dense for that, the largest at which its layout
    still fits. The scales and millimetres written stay those of the drawing at 1 : 1; a note on
    the slide says so.

    A dense figure (a shaper's plans, its lever) holds its layout only at 1.0…1.2 : 1, so its paper
    lettering (2.8 mm line labels, 3.2 mm equations) came out at 2.8…3.4 mm on the slide. With
    ``lettered`` the figure is built on each design page lettered for the slide
    (:func:`slide_lettered`: at least 3.5/z mm, so 3.5 mm and up once drawn z : 1), and its label
    placement and layout work with those sizes: no slide text is below the slide's minimum, whatever z.

    Parameters
    ----------
    make : callable
        Builds the steps on a given page (``lambda page: velocity_plan_steps(case, page=page)``).
    lettered : bool
        Build every design page :func:`slide_lettered` (default: the figure's own sizes).
    uncrossed : bool
        Take no enlargement whose figure has a label crossed by its own ink (:func:`crossed_labels`; the six-bar
        press's Wittenbauer slide at 1.6 : 1 set its position number 1 on the curve). Default: not checked.

    Examples
    --------
    >>> from graphmethods.sheets.steps import energy_indicator_steps, resolve_case
    >>> bu = for_projector(lambda pg: energy_indicator_steps(resolve_case("W3"), page=pg), lettered=True)
    >>> smallest_text_mm(bu) * bu.enlarged >= 3.5
    True
    """
    bound = PROJECTOR_TEXT * SLIDE_PAGE.height_mm

    def build_on(page: Page) -> BuildUp:
        if not lettered:
            return make(page)
        with slide_lettered(page):
            return make(page)

    # the slide at 1 : 1 in the figure's own lettering (its error, if any, is the answer): its smallest text
    # says how much enlargement the projector needs, its μ how large the construction is drawn
    reference = make(SLIDE_PAGE)
    drawn = {(sc.symbol, sc.unit): sc.per_mm for sc in reference.figure.scales()}

    def holds(bu: BuildUp, z: float) -> bool:
        """No overlap, nothing out of the page, the note "drawn z : 1" clear of the figure's ink, and the
        construction drawn on the slide at least :data:`KEEP_SIZE` as large as at 1 : 1 (a figure that
        keeps fixed margins for its labels would otherwise shrink its drawing to make room)."""
        if layout_faults(bu):
            return False
        free = note_free(bu.figure)
        if not free(enlarge_note(bu.figure, z, SLIDE_NOTE_MM / z, free)):
            return False
        if uncrossed and crossed_labels(bu.figure):
            return False
        return all(z / sc.per_mm >= KEEP_SIZE / drawn[sc.symbol, sc.unit] for sc in bu.figure.scales()
                   if (sc.symbol, sc.unit) in drawn and sc.unit not in ("rad", "°"))

    def attempt(z: float) -> BuildUp | None:
        try:
            bu = build_on(design_slide(z))
        except InputError:
            return None
        return bu if holds(bu, z) else None

    need = bound / smallest_text_mm(reference)          # the text sizes do not depend on the page
    # the candidates, largest first: the smallest enlargement that is enough, and every one below it
    enough = [w for w in ZOOMS[:-1] if w >= need - 1e-9]
    candidates = [w for w in ZOOMS[:-1] if w <= (enough[-1] if enough else ZOOMS[0]) + 1e-9]
    # a smaller enlargement leaves more room, so the ones that hold are a tail of the list: bisect
    lo, hi, best = 0, len(candidates) - 1, None
    while lo <= hi:
        mid = (lo + hi) // 2
        found = attempt(candidates[mid])
        if found is not None:
            best, hi = found, mid - 1
        else:
            lo = mid + 1
    if best is None:                                    # too dense to enlarge: at 1 : 1, lettered
        best = build_on(SLIDE_PAGE) if lettered else reference
    return _on_slide(best)


@contextmanager
def slide_lettered(page: Page) -> Iterator[float]:
    """Build figures lettered for a slide laid out on ``page`` (the slide or a :class:`DesignPage` of it,
    drawn z : 1): every text made inside is at least the slide's minimum divided by z, mm (yielded).

    >>> from graphmethods.scene import Text
    >>> with slide_lettered(design_slide(1.4)) as least:
    ...     t = Text((0, 0), "B", size_mm=2.0)
    >>> round(least, 3), round(t.size_mm * 1.4, 3)
    (2.5, 3.5)
    """

    least = lettering("SLIDE").minimum_mm / float(getattr(page, "enlarged", 1.0))
    token = MIN_TEXT_MM.set(max(MIN_TEXT_MM.get(), least))
    try:
        yield least
    finally:
        MIN_TEXT_MM.reset(token)


def layout_faults(bu: BuildUp) -> list[str]:
    """What in the finished figure leaves the page's inner box (down to the caption box) or covers
    other text: estimated label boxes (as the layout estimates them) and every line's points.

    >>> from graphmethods.sheets.steps import build
    >>> layout_faults(build("W1", "energy-indicator", page="A4"))
    []
    """
    from graphmethods.render.recording import record
    from graphmethods.scene.elements import label_bbox

    fig = bu.figure
    x0, y0, x1, _ = fig.page.inner_box()
    y1 = bu.caption_box[1]                     # down to the caption box
    tol = 0.05
    faults: list[str] = []
    boxes: list[tuple[str, tuple[float, float, float, float]]] = []
    for c in record(fig).calls:
        owner = c.groups[0] if c.groups else ""
        if c.kind == "text":
            b = label_bbox(c.data)
            boxes.append((owner, b))
        elif c.kind in ("path", "polygon"):
            points = c.data[0] if c.kind == "path" else c.data
            xs, ys = [p[0] for p in points], [p[1] for p in points]
            b = (min(xs), min(ys), max(xs), max(ys))
        else:
            continue
        if b[0] < x0 - tol or b[1] < y0 - tol or b[2] > x1 + tol or b[3] > y1 + tol:
            faults.append(f"{owner} leaves the page's inner box")
    for i, (na, a) in enumerate(boxes):
        for nb, b in boxes[i + 1:]:
            if na != nb and min(a[2], b[2]) - max(a[0], b[0]) > 0.3 and min(a[3], b[3]) - max(a[1], b[1]) > 0.3:
                faults.append(f"{na} covers {nb}")
    return faults


def projector_figure(make: Callable[[Page], Scene]) -> Scene:
    """Any figure on a 16:9 slide with its text sized for a projector, as :func:`for_projector`
    sizes the steps' slides (no caption band): ``make`` draws the figure on a given page.

    Examples
    --------
    >>> from graphmethods.problems import builtin
    >>> from graphmethods.sheets.forces import force_scheme
    >>> s = projector_figure(lambda pg: force_scheme(builtin.case("press"), 3, page=pg, title_block=False))
    >>> s.page.size, any(n.startswith("drawn 1.3 : 1") for n in s.notes)
    ('SLIDE', True)
    """
    from graphmethods.scene.steps import Step

    def as_steps(page: Page) -> BuildUp:
        fig = make(page)
        x0, _, x1, y1 = page.inner_box()
        y1 += CAPTION_GAP_MM / float(getattr(page, "enlarged", 1.0))   # the last line's descenders, in the margin
        return BuildUp(fig, (Step("", tuple(range(len(fig.elements)))),), (x0, y1, x1, y1), caption_mm=1e3)

    return for_projector(as_steps).figure


def crossed_labels(fig: Scene) -> tuple[str, ...]:
    """The texts of ``fig`` a line, an arrow or a circle of it passes through (the figure-quality measure's
    test, :func:`~graphmethods.sheets.engine.quality.measure`)."""
    from graphmethods.sheets.engine.quality import measure

    return measure(fig).crossed


def note_free(fig: Scene) -> Callable[[Text], bool]:
    """A test of a text against the figure's ink and text: whether no line, arrow or circle of ``fig`` crosses its
    glyphs (as the figure-quality measure judges a label crossed; the note "drawn z : 1" is added after the
    figure's own labels were placed, and a ray may run up to the page's top) and no text of ``fig`` lies under
    them (the six-bar press's stroke "H = 270,8 мм" stood under the ru note at the top of its scheme's slide).

    >>> from graphmethods.scene import Line, Page, Scene, Text
    >>> free = note_free(Scene(Page("A4"), (Line((0, 10), (100, 10), name="l"), Text((10, 50), "H", name="h"))))
    >>> free(Text((10, 11), "crossed", size_mm=3.5)), free(Text((10, 30), "clear", size_mm=3.5))
    (False, True)
    >>> free(Text((8, 50), "over H", size_mm=3.5))
    False
    """
    import numpy as np

    from graphmethods.render.recording import record
    from graphmethods.scene.elements import label_bbox
    from graphmethods.scene.primitives import Label
    from graphmethods.sheets.engine.quality import OVERLAP_MM, boxes_crossed, glyph_box, segments_marked

    rec = record(fig)
    seg, _ = segments_marked(rec)
    labels = [c.data for c in rec.calls if c.kind == "text"]
    # as the measure judges text over text: across by the glyphs, up and down by the whole line
    gx = np.array([glyph_box(lab) for lab in labels], dtype=float).reshape(-1, 4)
    ly = np.array([label_bbox(lab) for lab in labels], dtype=float).reshape(-1, 4)

    def free(text: Text) -> bool:
        own = [p for p in text.primitives() if isinstance(p, Label)]
        boxes = np.array([glyph_box(p) for p in own], dtype=float).reshape(-1, 4)
        lines = np.array([label_bbox(p) for p in own], dtype=float).reshape(-1, 4)
        if len(seg) and bool(boxes_crossed(seg, boxes).any()):
            return False
        ox = np.minimum(boxes[:, None, 2], gx[None, :, 2]) - np.maximum(boxes[:, None, 0], gx[None, :, 0])
        oy = np.minimum(lines[:, None, 3], ly[None, :, 3]) - np.maximum(lines[:, None, 1], ly[None, :, 1])
        return not bool(((ox > OVERLAP_MM) & (oy > OVERLAP_MM)).any())

    return free


def _on_slide(bu: BuildUp) -> BuildUp:
    """The steps drawn on the whole slide: enlarged from their design page (z = 1: as they are),
    the caption band inside the slide's margins, the note "drawn z : 1" clear of the figure's ink."""
    z = float(getattr(bu.figure.page, "enlarged", 1.0))
    return enlarge(bu, SLIDE_PAGE, note_mm=SLIDE_NOTE_MM / z, free=note_free(bu.figure) if z != 1.0 else None)


#: an enlarged slide draws the construction at least this fraction of its size at 1 : 1
KEEP_SIZE = 0.75

#: the enlargement note's size on the slide, mm
SLIDE_NOTE_MM = 5.0
