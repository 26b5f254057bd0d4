"""SVG output through svgwrite: scale-true, deterministic, escaped. The only module importing svgwrite.

The page is ``width="297mm" height="210mm" viewBox="0 0 297 210"``, so one user
unit prints as one millimetre. Every number goes through
:func:`~graphmethods.scene.numbers.format_mm`; group ids come from element names;
there are no dates, so the same scene gives byte-identical SVG in any process.
User text is escaped by the XML writer (and characters XML cannot hold are
replaced by U+FFFD).

>>> from graphmethods.scene import Scene, Page, Text
>>> svg = to_string(Scene(Page("A4", "portrait"), (Text((10, 20), "a < b & M_d", name="t"),), name="demo"))
>>> 'width="210mm"' in svg and 'viewBox="0 0 210 297"' in svg and "a &lt; b &amp; M" in svg
True
"""

from __future__ import annotations

import os
import pathlib
import re
import xml.etree.ElementTree as ET
from typing import Any

from graphmethods.render.base import draw
from graphmethods.render.files import write_atomic
from graphmethods.scene.markup import SCRIPT_SCALE, baseline_shift_mm
from graphmethods.scene.numbers import format_mm as fmt
from graphmethods.scene.primitives import XY, Label, Style
from graphmethods.scene.scene import Scene

#: font list: DejaVu Sans (Greek, Cyrillic), then common CJK fonts for Chinese text
FONT_FAMILY = ("'DejaVu Sans', 'Liberation Sans', Arial, 'Noto Sans CJK SC', 'Source Han Sans SC', "
               "'Microsoft YaHei', 'PingFang SC', 'WenQuanYi Micro Hei', sans-serif")

_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")


def clean_text(text: str) -> str:
    """Text as XML can hold it: control characters other than tab/newline become U+FFFD.

    >>> clean_text("a\\x00b")
    'a\\ufffdb'
    """
    return _NOT_XML.sub("\ufffd", text)


def indent(elem: ET.Element, level: int = 0) -> None:
    """Indent an SVG tree for readable files and diffs, never inside ``<text>`` (whitespace there would
    show); tags with or without the SVG namespace."""
    if elem.tag.rsplit("}", 1)[-1] in ("text", "title") or len(elem) == 0:
        return
    pad = "\n" + "  " * (level + 1)
    elem.text = pad
    for child in elem:
        indent(child, level + 1)
        child.tail = pad
    elem[-1].tail = "\n" + "  " * level


class SvgRenderer:
    """A :class:`~graphmethods.render.base.Renderer` that builds an SVG document with svgwrite."""

    def __init__(self) -> None:
        import svgwrite  # the only import of svgwrite in graphmethods

        # svgwrite ships no type information: its drawing and elements are Any here
        self._svgwrite: Any = svgwrite
        self.dwg: Any = None
        self._stack: list[Any] = []

    def begin(self, width_mm: float, height_mm: float, *, title: str, name: str) -> None:
        W, H = fmt(width_mm), fmt(height_mm)
        self.dwg = self._svgwrite.Drawing(size=(f"{W}mm", f"{H}mm"), viewBox=f"0 0 {W} {H}", profile="full",
                                          debug=False)
        if title:
            self.dwg.set_desc(title=clean_text(title))
        root = self.dwg.g(id=name)
        root["font-family"] = FONT_FAMILY
        root["stroke-linejoin"] = "round"
        self.dwg.add(root)
        self._stack = [root]

    def _add(self, elem: Any) -> Any:
        self._stack[-1].add(elem)
        return elem

    def begin_group(self, id: str) -> None:
        self._stack.append(self._add(self.dwg.g(id=id)))

    def end_group(self) -> None:
        self._stack.pop()

    @staticmethod
    def _stroke(elem: Any, style: Style, filled: bool) -> Any:
        elem["fill"] = style.fill if (filled and style.fill) else "none"
        if style.stroke and style.width_mm > 0:
            elem["stroke"] = style.stroke
            elem["stroke-width"] = fmt(style.width_mm)
            if style.dash:
                elem["stroke-dasharray"] = " ".join(fmt(d) for d in style.dash)
        return elem

    def path(self, points: tuple[XY, ...], style: Style, closed: bool) -> None:
        pts = [(fmt(x), fmt(y)) for x, y in points]
        elem = self.dwg.polygon(pts) if closed else self.dwg.polyline(pts)
        self._add(self._stroke(elem, style, filled=False))

    def polygon(self, points: tuple[XY, ...], style: Style) -> None:
        pts = [(fmt(x), fmt(y)) for x, y in points]
        self._add(self._stroke(self.dwg.polygon(pts), style, filled=True))

    def circle(self, cx: float, cy: float, r: float, style: Style) -> None:
        elem = self.dwg.circle()
        elem["cx"], elem["cy"], elem["r"] = fmt(cx), fmt(cy), fmt(r)
        self._add(self._stroke(elem, style, filled=True))

    def text(self, label: Label) -> None:
        size = label.size_mm
        elem = self.dwg.text("")
        elem["x"], elem["y"], elem["font-size"] = fmt(label.x), fmt(label.y), fmt(size)
        elem["xml:space"] = "preserve"   # keep the space after a subscript ("f₁ = …")
        if label.anchor != "start":
            elem["text-anchor"] = label.anchor
        if label.bold:
            elem["font-weight"] = "bold"
        if label.color != "#000000":
            elem["fill"] = label.color
        runs = label.runs
        if len(runs) == 1 and runs[0][1] == 0:
            elem.text = clean_text(runs[0][0])
        else:
            offset = 0.0  # current baseline shift, mm (down positive)
            for chunk, shift in runs:
                target = baseline_shift_mm(shift, size)
                span = self.dwg.tspan(clean_text(chunk))
                if abs(target - offset) > 1e-12:
                    span["dy"] = fmt(target - offset)
                    offset = target
                if shift:
                    span["font-size"] = fmt(size * SCRIPT_SCALE)
                elem.add(span)
        self._add(elem)

    def end(self) -> str:
        root = self.dwg.get_xml()
        indent(root)
        return '<?xml version="1.0" encoding="utf-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"


def to_string(scene: Scene) -> str:
    """The SVG document of ``scene`` (str); byte-identical for the same scene in any process."""
    text: str = draw(scene, SvgRenderer())
    return text


def to_bytes(scene: Scene) -> bytes:
    """The SVG document of ``scene`` encoded as UTF-8."""
    return to_string(scene).encode("utf-8")


def save(scene: Scene, path: str | os.PathLike[str], *, overwrite: bool = False) -> pathlib.Path:
    """Write ``scene`` as SVG to ``path`` atomically; refuses to replace a file unless ``overwrite``.

    Raises
    ------
    OutputExistsError
        If ``path`` exists and ``overwrite`` is false.

    Returns
    -------
    pathlib.Path
        The path written.
    """
    return write_atomic(path, to_bytes(scene), overwrite=overwrite)
