"""The sheet of paper: A4…A1 (or a 16:9 slide), portrait or landscape, margins, frame and title block.

>>> p = Page("A3", "landscape")
>>> p.width_mm, p.height_mm
(420.0, 297.0)
>>> Page("A4", "portrait", frame=False).content_box()
(10.0, 10.0, 200.0, 287.0)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from graphmethods.errors import InputError
from graphmethods.scene import markup
from graphmethods.scene.elements import Table, lettered_size
from graphmethods.scene.primitives import Path, Primitive, Style
from graphmethods.scene.title_blocks import FormBlock

#: ISO 216 sizes in mm, (short side, long side); SLIDE is a 16:9 presentation slide (13.333 × 7.5 in)
PAPER = {"A4": (210.0, 297.0), "A3": (297.0, 420.0), "A2": (420.0, 594.0), "A1": (594.0, 841.0),
         "SLIDE": (190.5, 338.7)}

FRAME = Style(width_mm=0.5)


@dataclass(frozen=True)
class TitleBlock:
    """The block in the bottom-right corner of the frame: figure title, problem, scales used.

    ``title`` is markup; ``problem`` is drawn literally (user text). ``scales`` are
    scale captions (markup). ``headings`` are the three row names in the figure's
    notation. ``form`` is ``"simple"`` (this table), ``"gost"`` (ГОСТ 2.104 form 1, 185 × 55 mm)
    or ``"gb"`` (GB/T 10609.1, 180 × 56 mm), see :mod:`graphmethods.scene.title_blocks`;
    ``person`` are the student's rows ((heading, text), the simple form) and ``fields`` the
    standard forms' cells (student, organisation, sheet_no, sheets, designation, ...);
    ``scale_rows`` more scale captions (markup), one row each below the scales (a narrow page's).
    """

    title: str
    problem: str = ""
    scales: tuple[str, ...] = ()
    headings: tuple[str, str, str] = ("Figure", "Problem", "Scales")
    size_mm: float = 3.2
    form: str = "simple"
    person: tuple[tuple[str, str], ...] = ()
    fields: tuple[tuple[str, str], ...] = ()
    scale_rows: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "size_mm", lettered_size(self.size_mm))     # 3.5 mm and up on A1/A2

    def rows(self) -> tuple[tuple[str, str], ...]:
        rows = [(self.headings[0], self.title)]
        if self.problem:
            rows.append((self.headings[1], markup.literal(self.problem)))
        if self.scales:
            rows.append((self.headings[2], ";  ".join(self.scales)))
        rows += [("", s) for s in self.scale_rows]
        rows += [(h, markup.literal(t)) for h, t in self.person]
        return tuple(rows)

    def table(self, right: float, bottom: float, max_width_mm: float | None = None) -> Table | FormBlock:
        """The block whose bottom-right corner is at (right, bottom): a table, or a standard form.

        ``max_width_mm``: the frame's width; a text too long for it (a problem's long name on an A4
        portrait page) goes on as many rows as it needs, its heading on the first.
        """
        if self.form != "simple":
            return FormBlock.of(self.form, right=right, bottom=bottom,
                                fields={"title": markup.plain(self.title), **dict(self.fields)})
        rows = self.rows()
        bold: tuple[int, ...] = (0,)
        probe = Table((0.0, 0.0), rows, header_rows=0, align="ll", size_mm=self.size_mm, row_height_mm=7.0,
                      bold_rows=bold, name="title-block")
        if max_width_mm is not None and probe.width_mm > max_width_mm:
            rows, bold = self._wrapped(rows, max_width_mm - probe.column_widths()[0] - 2.0 * self.size_mm)
            probe = Table((0.0, 0.0), rows, header_rows=0, align="ll", size_mm=self.size_mm, row_height_mm=7.0,
                          bold_rows=bold, name="title-block")
        w, h = probe.width_mm, probe.height_mm
        w0 = max(w, min(120.0, max_width_mm if max_width_mm is not None else 120.0))
        widths = probe.column_widths()
        widths = (widths[0], widths[1] + (w0 - w))
        return Table((right - w0, bottom - h), rows, col_widths_mm=widths, header_rows=0, align="ll",
                     size_mm=self.size_mm, row_height_mm=7.0, bold_rows=bold, name="title-block")

    def _wrapped(self, rows: tuple[tuple[str, str], ...], width_mm: float
                 ) -> tuple[tuple[tuple[str, str], ...], tuple[int, ...]]:
        """The rows with each text broken into lines of ``width_mm`` (the title's lines all bold)."""
        # scene.steps draws on this module: imported here
        from graphmethods.scene.steps import wrap

        out: list[tuple[str, str]] = []
        bold: list[int] = []
        for i, (head, text) in enumerate(rows):
            for k, line in enumerate(wrap(text, self.size_mm, width_mm)):
                if i == 0:
                    bold.append(len(out))
                out.append((head if k == 0 else "", line))
        return tuple(out), tuple(bold)


@dataclass(frozen=True)
class Page:
    """A sheet: paper size, orientation, margins (top, right, bottom, left) in mm, frame, title block.

    Parameters
    ----------
    size : {'A4', 'A3', 'A2', 'A1', 'slide'}
    orientation : {'portrait', 'landscape'}
    margins_mm : (float, float, float, float), mm
        Top, right, bottom, left; the frame is drawn on them.
    frame : bool
        Draw a frame on the margins.
    title_block : TitleBlock or None
        Drawn in the bottom-right corner inside the frame.
    """

    size: str = "A4"
    orientation: str = "landscape"
    margins_mm: tuple[float, float, float, float] = (10.0, 10.0, 10.0, 10.0)
    frame: bool = False
    title_block: TitleBlock | None = None

    def __post_init__(self) -> None:
        size = str(self.size).upper()
        if size not in PAPER:
            raise InputError(f"page size {self.size!r}: use one of {', '.join(PAPER)}")
        object.__setattr__(self, "size", size)
        if self.orientation not in ("portrait", "landscape"):
            raise InputError(f"page orientation {self.orientation!r}: use 'portrait' or 'landscape'")
        m = tuple(float(v) for v in self.margins_mm)
        if len(m) != 4 or any(v < 0 for v in m) or m[0] + m[2] >= self._dims()[1] or m[1] + m[3] >= self._dims()[0]:
            raise InputError(f"margins {self.margins_mm!r} mm: give four non-negative margins (top, right, bottom, "
                             f"left) that leave room on a {size} {self.orientation} page")
        object.__setattr__(self, "margins_mm", m)

    def _dims(self) -> tuple[float, float]:
        short, long = PAPER[str(self.size).upper()]
        return (long, short) if self.orientation == "landscape" else (short, long)

    @property
    def width_mm(self) -> float:
        return self._dims()[0]

    @property
    def height_mm(self) -> float:
        return self._dims()[1]

    def with_(self, **changes: Any) -> Page:
        """A copy with some fields changed."""
        from dataclasses import replace

        return replace(self, **changes)

    def inner_box(self) -> tuple[float, float, float, float]:
        """The box inside the margins (the frame), (x0, y0, x1, y1) mm."""
        t, r, b, left = self.margins_mm
        return (left, t, self.width_mm - r, self.height_mm - b)

    def content_box(self, *, padding_mm: float = 0.0) -> tuple[float, float, float, float]:
        """Where a figure may draw: inside the frame (padded), above the title block."""
        x0, y0, x1, y1 = self.inner_box()
        pad = padding_mm + (5.0 if self.frame else 0.0)
        if self.title_block is not None:
            y1 -= self.title_block.table(x1, y1, max_width_mm=x1 - x0).height_mm + 2.0
        return (x0 + pad, y0 + pad, x1 - pad, y1 - pad)

    def primitives(self) -> tuple[Primitive, ...]:
        prims: list[Primitive] = []
        x0, y0, x1, y1 = self.inner_box()
        if self.frame:
            prims.append(Path(((x0, y0), (x1, y0), (x1, y1), (x0, y1)), FRAME, closed=True))
        if self.title_block is not None:
            prims.append(self.title_block.table(x1, y1, max_width_mm=x1 - x0).draw())
        return tuple(prims)
