"""The sheet frame of the dynamics figures: page, title, content box, captions and a fine occupancy.

:class:`SheetFrame` is the one frame of the dynamics, Wittenbauer, flywheel and drive figures
(and of the cycle panels and motion graphs, which take it from :mod:`graphmethods.sheets.dynamics`).
It is the shared :class:`~graphmethods.sheets.layout.Sheet` with three differences these figures
need: a :class:`FastOccupancy` whose leader search is finer (they place many labels), a title
box as wide as the title only (the space beside it is free for drawing), and scale captions and a
legend moved off drawn lines.

>>> from graphmethods.scene import Page
>>> sheet = SheetFrame(nt="en", page=None, title="Reduced moments", problem="", title_block=True,
...                    default_page=Page("A4", "landscape", frame=True))
>>> [round(v) for v in sheet.box], sheet.occ.is_free((200.0, 30.0, 210.0, 34.0))
([15, 15, 282, 179], True)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from graphmethods.scene import Page, Scale, ScaleCaptions, Text, markup, notation as get_notation
from graphmethods.scene.elements import Element, label_bbox, make_label, place_label
from graphmethods.scene.notation import Notation
from graphmethods.scene.primitives import Label
from graphmethods.sheets.layout import TEXT_MM, Box, Occupancy, Sheet

Point2 = tuple[float, float]

#: the directions of a label's first trial, as angles (degrees, counterclockwise from east)
_ANGLE = {"e": 0, "ne": 45, "n": 90, "nw": 135, "w": 180, "sw": 225, "s": 270, "se": 315}
#: the radii of the leader search (mm)
_LEADER_RADII = (8.0, 12.0, 16.0, 21.0, 28.0, 36.0, 48.0, 60.0, 70.0)


class FastOccupancy(Occupancy):
    """:class:`~graphmethods.sheets.layout.Occupancy` whose leaders search a finer ring (every 15°, out to 70 mm).

    (The free-space test itself is :meth:`Occupancy.is_free`, vectorised over numpy arrays.)

    >>> occ = FastOccupancy()
    >>> occ.add_line(((0, 10), (100, 10)))
    >>> occ.is_free((40, 8, 60, 12)), occ.is_free((40, 12, 60, 14))
    (False, True)
    """

    def place_label_with_leader(self, at: Point2, text: str,
                                directions: Sequence[str] = ("ne", "nw", "se", "sw", "n", "s", "e", "w"), *,
                                size_mm: float = 3.5, gap_mm: float = 1.2, within: Box | None = None
                                ) -> tuple[Label, tuple[Point2, Point2] | None]:
        """As :meth:`Occupancy.place_label_with_leader`, searching a finer ring (every 15°, out to 70 mm),
        first with leaders that cross no label, then with any leader, before giving up."""
        lab = self.first_free(at, text, directions, (gap_mm, gap_mm + 2.0), size_mm, within)
        if lab is not None:
            self.add_label(lab)
            return lab, None
        first = _ANGLE[directions[0]]
        angles = sorted(range(0, 360, 15), key=lambda a: (min(abs(a - first), 360 - abs(a - first)), a))
        for strict in (True, False):
            for r in _LEADER_RADII:
                found = self.try_leaders(at, text, r, angles, size_mm=size_mm, within=within, strict=strict)
                if found is not None:
                    return found
        lab = place_label(at, text, directions[0], gap_mm=gap_mm, size_mm=size_mm)
        self.add_label(lab)
        return lab, None


class SheetFrame(Sheet):
    """The shared :class:`~graphmethods.sheets.layout.Sheet`, with a faster occupancy (these sheets place many
    labels), a title box as wide as the title, and captions moved clear of lines."""

    occ: FastOccupancy

    def __init__(self, *, nt: Notation | str, page: Page | None, title: str, problem: object, title_block: bool,
                 default_page: Page | None) -> None:
        super().__init__(nt=get_notation(nt), page=page, title=title, problem=problem, title_block=title_block,
                         default_page=default_page)
        x0, y0, _, _ = self.box
        self.occ = FastOccupancy()
        self.occ.add_box((x0, y0, x0 + markup.text_width_mm(title, self.title_mm) * 1.08, y0 + self.title_mm + 1.5))

    def captions(self, scales: Sequence[Scale], legend: str = "", *, reserve: bool = False) -> list[Element]:
        """The scale captions on the bottom line (left), a legend at its right end; both kept off lines
        (always registered: ``reserve`` is accepted as the base class takes it)."""
        x0, _, x1, _ = self.box
        y = self.caption_y
        els: list[Element] = []
        cap = ScaleCaptions((x0, y), tuple(scales), notation=self.nt, size_mm=TEXT_MM, name="scale-captions")
        for at, anchor in (((x0, y), "start"), ((x1, y), "end"), (((x0 + x1) / 2, y), "middle")):
            trial = replace(cap, at=at, anchor=anchor)
            if all(self.occ.is_free(label_bbox(p)) for p in trial.primitives() if isinstance(p, Label)):
                cap = trial
                break
        self.occ.register(cap)
        els.append(cap)
        if legend:
            lab = make_label((x1, y), legend, size_mm=TEXT_MM, anchor="end")
            if not self.occ.is_free(label_bbox(lab)):
                lab = make_label((x1, y - TEXT_MM * 1.5), legend, size_mm=TEXT_MM, anchor="end")
            self.occ.add_label(lab)
            els.append(Text((lab.x, lab.y), legend, size_mm=TEXT_MM, anchor="end", name="legend"))
        return els


__all__ = ["FastOccupancy", "SheetFrame"]
