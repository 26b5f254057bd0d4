"""Where an overlay's words go on a student's own drawing (:func:`graphmethods.sheets.check.cad.
overlay_on_drawing`): the check is placed against its own construction; redrawn over the student's drawing,
its heading, its red list and its letters may land on the student's frame, title and lines. These move them,
as little as they can, to paper that is free.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from graphmethods.scene import Text
from graphmethods.scene.elements import Element
from graphmethods.sheets.worksheets.elements import ColorText


def heading_clear_of(student: Element, elements, page) -> list[Element]:
    """The overlay's elements with its heading (title and how to print) and its list of wrong items each
    moved, as a block, to the nearest place free of the student's drawing (their frame, title and lines) and
    of the check's construction, searched down the page and sideways; a block with no free place stays.

    >>> from graphmethods.scene import Page
    >>> from graphmethods.scene.elements import Line
    >>> frame_top = Line((0, 12), (297, 12), name="their-line")           # the student's line under our title
    >>> title = Text((12.0, 12.0), "Overlay: W1", size_mm=3.2, name="overlay-title")
    >>> moved = heading_clear_of(frame_top, [title], Page("A4", "landscape"))
    >>> moved[0].at[1] > 12.0
    True
    """
    from graphmethods.scene.elements import bbox
    from graphmethods.sheets.layout import Occupancy

    occ = Occupancy(pad_mm=0.8)
    occ.add_primitives(student.primitives())
    blocks = ("overlay-title", "overlay-howto", "wrong-list")
    for e in elements:                              # and of the check's own construction
        if e.name not in blocks:
            occ.add_primitives(e.primitives())
    W, H = page.width_mm, page.height_mm
    moves: dict[str, tuple[float, float]] = {}
    for names in (("overlay-title", "overlay-howto"), ("wrong-list",)):
        block = [e for e in elements if e.name in names]
        box = bbox([p for e in block for p in e.primitives()]) if block else None
        if box is None:
            continue
        x0, y0, x1, y1 = box
        right = names == ("wrong-list",)
        shifts = sorted(((dx, dy) for dy in np.arange(0.0, H - 20.0 - y1, 2.0)
                         for dx in np.arange(0.0, W - (x1 - x0), 4.0) * (-1.0 if right else 1.0)
                         if 8.0 <= x0 + dx and x1 + dx <= W - 8.0), key=lambda d: (abs(d[0]) + d[1], d[1]))
        if not shifts:
            continue
        free = occ.free([(x0 + dx, y0 + dy, x1 + dx, y1 + dy) for dx, dy in shifts])
        hit = np.flatnonzero(free)
        if len(hit) == 0:
            continue
        dx, dy = shifts[int(hit[0])]
        occ.add_box((x0 + dx, y0 + dy, x1 + dx, y1 + dy))
        moves.update({n: (float(dx), float(dy)) for n in names})
    out = [replace(e, at=(e.at[0] + moves[e.name][0], e.at[1] + moves[e.name][1])) if e.name in moves else e
           for e in elements]
    return _letters_clear_of(student, out, blocks)


def _register(occ, prims) -> None:
    """Register primitives in an occupancy, circles (point marks, rollers) by their boxes too."""
    from graphmethods.scene.primitives import Circle, walk

    occ.add_primitives(prims)
    for p in walk(prims):
        if isinstance(p, Circle):
            occ.add_box((p.cx - p.r, p.cy - p.r, p.cx + p.r, p.cy + p.r))


def _letters_clear_of(student: Element, elements: list[Element], blocks: tuple[str, ...]) -> list[Element]:
    """The check's letters and values that the student's lines cross, each moved to the nearest free place
    within 12 mm, its leader with it (the check placed them against its own construction only); the others
    stay."""
    from graphmethods.scene.elements import bbox
    from graphmethods.sheets.layout import Occupancy

    texts = [k for k, e in enumerate(elements) if isinstance(e, (Text, ColorText)) and e.name not in blocks]
    occ = Occupancy(pad_mm=0.3)
    _register(occ, student.primitives())
    for k, e in enumerate(elements):
        if k not in texts:
            _register(occ, e.primitives())
    boxes = {k: bbox(elements[k].primitives()) for k in texts}
    stuck = [k for k in texts if boxes[k] is not None and not occ.free([boxes[k]])[0]]
    for k in texts:
        box = boxes[k]
        if k not in stuck and box is not None:
            occ.add_box(box)
    out = list(elements)
    shifts = sorted(((float(dx), float(dy)) for dx in np.arange(-12.0, 12.5, 1.0) for dy in np.arange(-12.0, 12.5, 1.0)
                     if 0 < dx * dx + dy * dy <= 144.0), key=lambda d: (d[0] ** 2 + d[1] ** 2, d))
    leaders = {e.name[:-len("-leader")]: k for k, e in enumerate(elements) if e.name.endswith("-leader")}
    for k in stuck:
        box = boxes[k]
        if box is None:
            continue
        x0, y0, x1, y1 = box
        hit = np.flatnonzero(occ.free([(x0 + dx, y0 + dy, x1 + dx, y1 + dy) for dx, dy in shifts]))
        if len(hit) == 0:
            continue
        dx, dy = shifts[int(hit[0])]
        e = out[k]
        out[k] = replace(e, at=(e.at[0] + dx, e.at[1] + dy))  # type: ignore[attr-defined,type-var]
        occ.add_box((x0 + dx, y0 + dy, x1 + dx, y1 + dy))
        if e.name in leaders:                       # its leader follows it (from the label to what it names)
            ln = out[leaders[e.name]]
            out[leaders[e.name]] = replace(ln, start=(ln.start[0] + dx, ln.start[1] + dy))  # type: ignore[attr-defined,type-var]
    return out


__all__ = ["heading_clear_of"]
