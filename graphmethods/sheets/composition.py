"""Figures set side by side on one large sheet: each drawn into its own box of the sheet.

A course project's A1 sheet is several figures (a scheme, plans, a table) on one page. Each
figure function draws on a page it is given; :func:`region_page` makes a page of the sheet's
size whose inner box is one region (no frame, no title block), so the figure draws itself at
the sheet's own coordinates inside that region, with its own heading and scale captions. The
figure's elements are then gathered under one named group by :func:`inset`.

>>> from graphmethods.scene import Page, Scene
>>> p = region_page(Page("A1", "landscape"), (20.0, 30.0, 300.0, 200.0))
>>> p.inner_box(), p.content_box(), p.frame, p.title_block is None
((20.0, 30.0, 300.0, 200.0), (20.0, 30.0, 300.0, 200.0), False, True)
"""

from __future__ import annotations

from graphmethods.errors import InputError
from graphmethods.scene import Page, Scene
from graphmethods.scene.elements import Group
from graphmethods.scene.scale import Scale

Box = tuple[float, float, float, float]


def region_page(sheet_page: Page, box: Box) -> Page:
    """A page of ``sheet_page``'s size and orientation whose inner box is ``box`` (mm, page coordinates).

    Parameters
    ----------
    sheet_page : Page
        The large sheet.
    box : (x0, y0, x1, y1), mm
        The region, x to the right and y down from the page's top-left corner.

    Raises
    ------
    InputError
        A region that is empty or leaves the page.
    """
    x0, y0, x1, y1 = (float(v) for v in box)
    W, H = sheet_page.width_mm, sheet_page.height_mm
    if not (0.0 <= x0 < x1 <= W and 0.0 <= y0 < y1 <= H):
        raise InputError(f"region {box!r} mm does not lie on the {sheet_page.size} page ({W:g} × {H:g} mm); "
                         f"give a larger page")
    return Page(sheet_page.size, sheet_page.orientation, margins_mm=(y0, W - x1, H - y1, x0), frame=False)


def inset(scene: Scene, name: str) -> tuple[Group, tuple[Scale, ...]]:
    """A figure drawn on a :func:`region_page`, as one group ``name`` of the sheet, and its scales.

    >>> from graphmethods.scene import Scene, Text
    >>> g, scales = inset(Scene(Page("A4"), (Text((20, 20), "a", name="t"),)), "part")
    >>> g.name, [e.name for e in g.elements], scales
    ('part', ['t'], ())
    """
    return Group(elements=tuple(scene.elements), name=name), tuple(scene.scales())


__all__ = ["inset", "region_page"]
