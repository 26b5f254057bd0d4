"""SVG output written as text from the scene's primitives: scale-true, deterministic, escaped.

The page is ``width="297mm" height="210mm" viewBox="0 0 297 210"``, so one user
unit prints as one millimetre. Every number goes through
:func:`~graphmethods.scene.numbers.format_mm`; group ids come from element names;
there are no dates, so the same scene gives byte-identical SVG in any process.
User text is escaped as XML requires (and characters XML cannot hold are
replaced by U+FFFD). The document is written line by line as text, not built as a tree
first: svgwrite (used before) added only a second copy of every element, 21-23 % of the
gallery's time, and no check our own escaping lacks.

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

from graphmethods.render.base import draw
from graphmethods.render.files import write_atomic
from graphmethods.scene.elements import label_bbox
from graphmethods.scene.markup import SCRIPT_SCALE, baseline_shift_mm
from graphmethods.scene.numbers import format_mm as fmt, format_points
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


_SVG_OPEN = ('<svg baseProfile="full" height="{H}mm" version="1.1" viewBox="0 0 {W} {H}" width="{W}mm" '
             'xmlns="http://www.w3.org/2000/svg" xmlns:ev="http://www.w3.org/2001/xml-events" '
             'xmlns:xlink="http://www.w3.org/1999/xlink">')
_CDATA = str.maketrans({"&": "&amp;", "<": "&lt;", ">": "&gt;"})
_ATTRIB = str.maketrans({"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "\r": "&#13;", "\n": "&#10;",
                         "\t": "&#09;"})


def _tag(name: str, attrs: dict[str, str], text: str | None = None) -> str:
    """One element as XML: attributes sorted by name, values and text escaped, empty ones self-closed."""
    head = "<" + name + "".join(f' {k}="{attrs[k].translate(_ATTRIB)}"' for k in sorted(attrs))
    return head + " />" if not text else f"{head}>{text}</{name}>"


def _style_attrs(style: Style, filled: bool) -> tuple[str, str]:
    """A style as the text of its attributes ``(' fill="…"', ' stroke="…" stroke-dasharray="…" stroke-width="…"')``:
    the parts before and after a primitive's own attributes in name order (``points``, ``r`` fall between),
    made once per style (a figure draws thousands of primitives in a few styles).

    >>> _style_attrs(Style(width_mm=0.18, dash=(2.0, 1.0)), False)
    (' fill="none"', ' stroke="#000000" stroke-dasharray="2 1" stroke-width="0.18"')
    """
    try:
        return _STYLE_TEXT[(style, filled)]
    except KeyError:
        pass
    except TypeError:                       # a style that cannot be hashed (a list of dashes): not kept
        return _style_text(style, filled)
    found = _style_text(style, filled)
    if len(_STYLE_TEXT) < 4096:             # a process's styles are few; a bound all the same
        _STYLE_TEXT[(style, filled)] = found
    return found


def _style_text(style: Style, filled: bool) -> tuple[str, str]:
    attrs = SvgRenderer._stroke({}, style, filled)
    fill = f' fill="{attrs.pop("fill").translate(_ATTRIB)}"'
    return fill, "".join(f' {k}="{attrs[k].translate(_ATTRIB)}"' for k in sorted(attrs))


_STYLE_TEXT: dict[tuple[Style, bool], tuple[str, str]] = {}


class SvgRenderer:
    """A :class:`~graphmethods.render.base.Renderer` that writes the SVG document's text directly.

    Each primitive becomes one line of the file, indented by its depth; attributes are sorted by name,
    values and text escaped as XML requires, a group without children is written self-closed. The bytes are
    those the svgwrite-and-ElementTree writer before it gave (every golden file of the gallery is the same).
    """

    def __init__(self) -> None:
        self._out: list[str] = []
        self._open: list[tuple[int, int]] = []    # per open group: its opening tag's index in _out, its depth

    def begin(self, width_mm: float, height_mm: float, *, title: str, name: str) -> None:
        W, H = fmt(width_mm), fmt(height_mm)
        self._out = ['<?xml version="1.0" encoding="utf-8"?>\n' + _SVG_OPEN.format(W=W, H=H)]
        if title:
            self._out.append("\n  <title>" + clean_text(title).translate(_CDATA) + "</title>")
        self._out.append("\n  <defs />")
        self._open = []
        self._begin(_tag("g", {"id": name, "font-family": FONT_FAMILY, "stroke-linejoin": "round"})[:-3] + ">")

    def _begin(self, open_tag: str) -> None:
        depth = len(self._open) + 1
        self._open.append((len(self._out), depth))
        self._out.append("\n" + "  " * depth + open_tag)

    def _add(self, element: str) -> None:
        self._out.append("\n" + "  " * (len(self._open) + 1) + element)

    def begin_group(self, id: str) -> None:
        self._begin(f'<g id="{id.translate(_ATTRIB)}">')

    def end_group(self) -> None:
        at, depth = self._open.pop()
        if at == len(self._out) - 1:                  # no children: <g id="..." />
            self._out[at] = self._out[at][:-1] + " />"
        else:
            self._out.append("\n" + "  " * depth + "</g>")

    @staticmethod
    def _stroke(attrs: dict[str, str], style: Style, filled: bool) -> dict[str, str]:
        """The style's attributes added to ``attrs`` (the plain form of :func:`_style_attrs`, for the tests)."""
        attrs["fill"] = style.fill if (filled and style.fill) else "none"
        if style.stroke and style.width_mm > 0:
            attrs["stroke"] = style.stroke
            attrs["stroke-width"] = fmt(style.width_mm)
            if style.dash:
                attrs["stroke-dasharray"] = " ".join(fmt(d) for d in style.dash)
        return attrs

    def path(self, points: tuple[XY, ...], style: Style, closed: bool) -> None:
        fill, stroke = _style_attrs(style, False)
        self._add(f'<{"polygon" if closed else "polyline"}{fill} points="{format_points(points)}"{stroke} />')

    def polygon(self, points: tuple[XY, ...], style: Style) -> None:
        fill, stroke = _style_attrs(style, True)
        self._add(f'<polygon{fill} points="{format_points(points)}"{stroke} />')

    def circle(self, cx: float, cy: float, r: float, style: Style) -> None:
        fill, stroke = _style_attrs(style, True)
        self._add(f'<circle cx="{fmt(cx)}" cy="{fmt(cy)}"{fill} r="{fmt(r)}"{stroke} />')

    def text(self, label: Label) -> None:
        size = label.size_mm
        x, anchor = label.x, label.anchor
        transform = ""
        if label.stretch != 1.0:
            # condensed lettering, scaled across about its start: the start is placed here, as the PDF and
            # DXF writers place it (librsvg anchors a scaled text's middle/end by its unscaled width)
            x, anchor = label_bbox(label)[0], "start"
            transform = f' transform="matrix({fmt(label.stretch)} 0 0 1 {fmt(x * (1.0 - label.stretch))} 0)"'
        # the attributes in name order, as _tag writes them: fill, font-size, font-weight, text-anchor,
        # transform, x, xml:space, y (numbers from format_mm need no escaping)
        head = ("<text" + (f' fill="{label.color.translate(_ATTRIB)}"' if label.color != "#000000" else "")
                + f' font-size="{fmt(size)}"' + (' font-weight="bold"' if label.bold else "")
                + (f' text-anchor="{anchor.translate(_ATTRIB)}"' if anchor != "start" else "") + transform
                + f' x="{fmt(x)}" xml:space="preserve" y="{fmt(label.y)}"')   # keep the space after a subscript
        runs = label.runs
        if len(runs) == 1 and runs[0][1] == 0:
            text = clean_text(runs[0][0]).translate(_CDATA)
            self._add(f"{head}>{text}</text>" if text else head + " />")
            return
        spans = []
        offset = 0.0  # current baseline shift, mm (down positive)
        for chunk, shift in runs:
            target = baseline_shift_mm(shift, size)
            span = "<tspan"
            if abs(target - offset) > 1e-12:
                span += f' dy="{fmt(target - offset)}"'
                offset = target
            if shift:
                span += f' font-size="{fmt(size * SCRIPT_SCALE)}"'
            text = clean_text(chunk).translate(_CDATA)
            spans.append(f"{span}>{text}</tspan>" if text else span + " />")
        joined = "".join(spans)
        self._add(f"{head}>{joined}</text>" if joined else head + " />")

    def end(self) -> str:
        while self._open:
            self.end_group()
        self._out.append("\n</svg>\n")
        return "".join(self._out)


def to_string(scene: Scene) -> str:
    """The SVG document of ``scene`` (str); byte-identical for the same scene in any process."""
    text: str = draw(scene, SvgRenderer())
    return text


def to_bytes(scene: Scene) -> bytes:
    """The SVG document of ``scene`` encoded as UTF-8."""
    return to_string(scene).encode("utf-8")


def save(scene: Scene, path: str | os.PathLike[str], *, overwrite: bool = False) -> pathlib.Path:
    """Write ``scene`` as SVG to ``path`` atomically and return the path, as
    :func:`graphmethods.render.formats.save` does for every format (an existing file is replaced only with
    ``overwrite``, else :class:`~graphmethods.errors.OutputExistsError`)."""
    return write_atomic(path, to_bytes(scene), overwrite=overwrite)
