"""The kinematic scheme on a 16:9 slide (``graphmethods steps P kinematic-scheme``): what the slide adds beside
the drawing, for :func:`graphmethods.sheets.kinematic_scheme.kinematic_scheme`.

- The facts (extreme positions, θ, K, the swing) and the link lengths the scheme is drawn from, in a column at the
  right, lettered as the slide's values (:func:`slide_facts`).
- The positions table (:func:`positions_table`): position, φ and the output's displacement s (or swing ψ) in
  each position, the numbers ``graphmethods kinematics P`` prints. A tall linkage (the two-slider compressor:
  its cylinders at 90°) on a wide slide left more than half the slide empty at the largest μ_l that fits its
  height. A lecturer fills that width with what the scheme is drawn *for*: the table of the output's positions,
  read off the drawing and plotted next as s(φ) in the kinematic diagrams. Turning the scheme would draw it
  unlike the machine and the textbook; repeating the lengths would say nothing new. The table goes in only
  where it costs the drawing nothing (the same μ_l with it as without it), so a wide linkage keeps its width.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from graphmethods.scene import Table, Text

#: a slide's facts column: its share of the width, and the gap left of it, mm
SLIDE_FACTS_SHARE, SLIDE_FACTS_GAP_MM = 0.28, 8.0


def _value_mm(page: Any) -> float:
    """The slide's value lettering on the design page (5 mm once enlarged z : 1)."""
    from graphmethods.sheets.engine.lettering import lettering

    return lettering("SLIDE").value_mm / float(getattr(page, "enlarged", 1.0))


def slide_facts(facts: Sequence[str], sheet: Any, page: Any, *, caption_room_mm: float) -> list[Text]:
    """On a slide, the scheme's facts (extreme positions, θ, K, the swing, the lengths) as a column at the right,
    lettered as the slide's values (5 mm once enlarged) and wrapped to :data:`SLIDE_FACTS_SHARE` of the width,
    one paragraph each, all named ``summary``; elsewhere none (the sheet writes them in a line over its captions).
    A tall linkage (the shaper, a two-slider) filled a third of a slide's width with its facts in one 3 mm line
    under it."""
    from graphmethods.scene.markup import text_width_mm
    from graphmethods.scene.steps import wrap
    from graphmethods.sheets.engine.lettering import is_slide

    if page is None or not is_slide(page) or not facts:
        return []
    size = _value_mm(page)
    x0, _, x1, _ = sheet.box
    width = SLIDE_FACTS_SHARE * (x1 - x0)
    left = x1 - max(text_width_mm(line, size) for f in facts for line in wrap(f, size, width))
    paragraphs = [wrap(f, size, width) for f in facts]
    lines = sum(len(p) for p in paragraphs)
    # the paragraphs spread down the drawing's height (from the title to over the captions), a line to two lines
    # apart
    room = sheet.caption_y - caption_room_mm - (sheet.top + 2.0 + size)
    extra = min(4.0 * size, max(2.5 * size, (room - 1.5 * size * (lines - len(paragraphs)))
                                / max(len(paragraphs) - 1, 1)))
    out: list[Text] = []
    y = sheet.top + 2.0 + size
    for p in paragraphs:
        for line in p:
            out.append(Text((left, y), line, size_mm=size, name="summary"))
            y += 1.5 * size
        y += extra - 1.5 * size                         # the next paragraph starts ``extra`` under this one's last line
    return out


def _rows(pos: Any, nt: Any) -> tuple[tuple[str, ...], ...] | None:
    """The table's rows: a heading, then position, φ from position 0 (°) and s (m) or ψ (°) per position."""
    if pos.s is not None:
        slider = next(iter(pos.mechanism.guides))
        head, values = nt.quantity(f"s_{{{slider}}}", nt.unit("m")), np.asarray(pos.s, dtype=float)
    elif pos.psi is not None:
        head, values = nt.quantity("ψ", "°"), np.degrees(np.asarray(pos.psi, dtype=float))
    else:
        return None
    phi = np.degrees(np.asarray(pos.phi_from_start, dtype=float))
    index = pos.index if pos.index is not None else range(pos.n)
    out = nt.column(values, sig=4, reference=float(np.abs(values).max()) or 1.0)
    angles = nt.column(phi, sig=3, reference=360.0)
    return ((nt.word("kinematics.position"), nt.quantity("φ", "°"), head),
            *((str(int(i)), a, v) for i, a, v in zip(index, angles, out)))


def overlaps(table: Table, element: Any) -> bool:
    """Whether a label of ``element`` (a dimension's value, a name, a number) runs into ``table``: the slotting
    machine dimensions its stroke beside its steep guide, right of the linkage, and "H = 400 mm" ran into it."""
    from graphmethods.scene.elements import label_bbox
    from graphmethods.scene.primitives import Label

    x0, y0 = table.at
    x1, y1 = x0 + table.width_mm, y0 + table.height_mm
    boxes = [label_bbox(p) for p in element.primitives() if isinstance(p, Label)]
    return any(b[0] < x1 and x0 < b[2] and b[1] < y1 and y0 < b[3] for b in boxes)


def positions_table(pos: Any, nt: Any, sheet: Any, page: Any, right: float | None, *, caption_room_mm: float,
                    scale_at: Callable[[float | None], tuple[Any, Any]]) -> tuple[list[Table], tuple[Any, Any]]:
    """On a slide, the table of the output's positions right-aligned at ``right`` (the facts column's left), when
    the drawing keeps its μ_l beside it; with the scale and frame to draw at (``scale_at(right edge)``).

    Returns
    -------
    (list of Table, (Scale, Frame))
        The table (none off a slide, for a linkage without an output, or where it would shrink the drawing) and
        what ``scale_at`` gives for the drawing's area.
    """
    from graphmethods.sheets.engine.lettering import is_slide

    plain = scale_at(right)
    rows = _rows(pos, nt) if pos is not None and page is not None and is_slide(page) else None
    if rows is None or right is None:
        return [], plain
    size = _value_mm(page)
    row_h = min(1.6 * size, (sheet.caption_y - caption_room_mm - sheet.top - 2.0) / len(rows))
    probe = Table((0.0, 0.0), rows, align="rrr", size_mm=min(size, row_h / 1.6), row_height_mm=row_h,
                  name="positions-table")
    left = float(right) - probe.width_mm
    beside = scale_at(left - SLIDE_FACTS_GAP_MM)
    if beside[0].per_mm != plain[0].per_mm or row_h < 1.4 * size:
        return [], plain
    return [Table((left, sheet.top + 2.0), rows, align="rrr", size_mm=probe.size_mm, row_height_mm=row_h,
                  name="positions-table")], beside
