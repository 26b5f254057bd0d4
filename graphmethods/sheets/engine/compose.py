"""The sheet composer: panels arranged on a page so that the drawings fill it (GridSpec in spirit).

An arrangement is a small tree of splits: :class:`Split` divides a box across (``"h"``, side by side)
or down (``"v"``, one over another) in shares, with a gap between the parts; a leaf is a panel's name.
:meth:`Split.boxes` gives every panel its box. Shares may come from what the panels need
(:func:`shares_for`): parts whose drawings are wide at a common scale get the wider boxes, so every
drawing fills its box at about the same scale, as on a course sheet.

>>> tree = Split("h", (("scheme", 0.4), (Split("v", (("lever", 1), ("plans", 1))), 0.6)), gap_mm=10.0)
>>> b = tree.boxes((0.0, 0.0, 510.0, 300.0))
>>> b["scheme"], b["lever"], b["plans"]
((0.0, 0.0, 200.0, 300.0), (210.0, 0.0, 510.0, 146.0), (210.0, 154.0, 510.0, 300.0))
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Union

from graphmethods.errors import InputError
from graphmethods.scene import Page

Box = tuple[float, float, float, float]
Node = Union[str, "Split"]

#: the gap between panels (mm) by page format: room for a panel's labels to breathe
GAP_MM = {"A0": 10.0, "A1": 10.0, "A2": 8.0, "A3": 6.0, "A4": 5.0, "SLIDE": 6.0}


@dataclass(frozen=True)
class Split:
    """A box divided across (``"h"``) or down (``"v"``) into parts, each a panel's name or another split.

    Parameters
    ----------
    direction : {"h", "v"}
        ``"h"``: parts side by side, left to right; ``"v"``: one over another, top to bottom.
    parts : sequence of (node, share)
        The parts and their shares of the length (any positive numbers; they are normalised).
    gap_mm : float, mm
        Between neighbouring parts.
    """

    direction: str
    parts: tuple[tuple[Node, float], ...]
    gap_mm: float = 8.0

    def __post_init__(self) -> None:
        if self.direction not in ("h", "v"):
            raise InputError(f"Split direction {self.direction!r}: use 'h' (side by side) or 'v' (one over another)")
        if not self.parts or any(not (s > 0) for _, s in self.parts):
            raise InputError(f"Split parts {self.parts!r}: give at least one part, each with a positive share")

    def boxes(self, box: Box) -> dict[str, Box]:
        """Every panel's box (mm) inside ``box``."""
        x0, y0, x1, y1 = (float(v) for v in box)
        total = sum(s for _, s in self.parts)
        length = (x1 - x0 if self.direction == "h" else y1 - y0) - self.gap_mm * (len(self.parts) - 1)
        if length <= 0:
            raise InputError(f"box {box!r} mm is too small for {len(self.parts)} parts {self.gap_mm} mm apart")
        out: dict[str, Box] = {}
        at = x0 if self.direction == "h" else y0
        for node, share in self.parts:
            d = length * share / total
            sub = (at, y0, at + d, y1) if self.direction == "h" else (x0, at, x1, at + d)
            at += d + self.gap_mm
            if isinstance(node, Split):
                out.update(node.boxes(sub))
            else:
                out[node] = sub
        return out


def shares_for(needs: Sequence[float], *, least: float = 0.15) -> tuple[float, ...]:
    """Shares of a split from what each part needs at a common scale (its extent along the split).

    Each part gets at least ``least`` of the length, so a small drawing is still large enough to read.

    >>> shares_for((2.0, 1.0, 1.0))
    (0.5, 0.25, 0.25)
    >>> [round(s, 3) for s in shares_for((10.0, 0.1))]
    [0.85, 0.15]
    """
    if not needs or any(not (n >= 0) for n in needs):
        raise InputError(f"shares_for: needs {tuple(needs)!r} must be non-negative numbers")
    total = sum(needs) or 1.0
    raw = [max(n / total, 0.0) for n in needs]
    low = [r < least for r in raw]
    fixed = least * sum(low)
    rest = sum(r for r, lo in zip(raw, low) if not lo) or 1.0
    return tuple(least if lo else r / rest * (1.0 - fixed) for r, lo in zip(raw, low))


def course_page(size: str = "A1") -> Page:
    """A course sheet (A1/A2 landscape) or an A4 figure page or a 16:9 slide, framed as the standard asks.

    A1/A2: a 20 mm binding margin on the left, 5 mm elsewhere (ГОСТ 2.301 / GB/T 14689); A4: 10 mm.

    >>> course_page("A1").inner_box()
    (20.0, 5.0, 836.0, 589.0)
    """
    s = str(size).upper()
    if s in ("A0", "A1", "A2", "A3"):
        return Page(s, "landscape", margins_mm=(5.0, 5.0, 5.0, 20.0), frame=True)
    if s == "SLIDE":
        return Page("SLIDE", "landscape", margins_mm=(6.0, 6.0, 6.0, 6.0), frame=False)
    if s == "A4":
        return Page("A4", "landscape", frame=True)
    raise InputError(f"page {size!r}: use A1, A2, A3, A4 or slide")


__all__ = ["GAP_MM", "Split", "course_page", "shares_for"]
