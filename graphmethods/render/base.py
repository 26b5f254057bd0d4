"""The Renderer protocol: a backend draws primitives only, and :func:`draw` feeds it a scene.

A backend implements ``begin``, ``begin_group``/``end_group``, ``path``, ``polygon``,
``circle``, ``text`` and ``end``; it never sees an element, a scale or a notation.
All coordinates are page millimetres (x right, y down, origin top-left).

>>> from graphmethods.scene import Scene, Page, Text
>>> from graphmethods.render.recording import RecordingRenderer
>>> rec = draw(Scene(Page("A4"), (Text((10, 10), "M_d", name="label"),)), RecordingRenderer())
>>> [c.kind for c in rec.calls]
['begin', 'begin_group', 'text', 'end_group', 'end']
"""

from __future__ import annotations

from typing import Any, Protocol, runtime_checkable

from graphmethods.scene import markup
from graphmethods.scene.primitives import XY, Circle, Group, Label, Path, Polygon, Primitive, Style
from graphmethods.scene.scene import Scene, make_id


@runtime_checkable
class Renderer(Protocol):
    """What a backend implements: primitives only (paths, polygons, circles, text, groups)."""

    def begin(self, width_mm: float, height_mm: float, *, title: str, name: str) -> None:
        """Start a page of the given size; ``title`` is plain text, ``name`` a valid id."""

    def begin_group(self, id: str) -> None:
        """Open a named group (ids are unique within a scene)."""

    def end_group(self) -> None:
        """Close the innermost group."""

    def path(self, points: tuple[XY, ...], style: Style, closed: bool) -> None:
        """A polyline (closed: a polygon outline, not filled)."""

    def polygon(self, points: tuple[XY, ...], style: Style) -> None:
        """A filled polygon."""

    def circle(self, cx: float, cy: float, r: float, style: Style) -> None:
        """A circle."""

    def text(self, label: Label) -> None:
        """A line of text with sub/superscript runs, baseline at ``label.y``."""

    def end(self) -> Any:
        """Finish the page and return the backend's result."""


def _emit(prim: Primitive, renderer: Renderer) -> None:
    if isinstance(prim, Group):
        renderer.begin_group(prim.name)
        for child in prim.children:
            _emit(child, renderer)
        renderer.end_group()
    elif isinstance(prim, Path):
        renderer.path(prim.points, prim.style, prim.closed)
    elif isinstance(prim, Polygon):
        renderer.polygon(prim.points, prim.style)
    elif isinstance(prim, Circle):
        renderer.circle(prim.cx, prim.cy, prim.r, prim.style)
    elif isinstance(prim, Label):
        renderer.text(prim)
    else:  # pragma: no cover - the scene model produces only the five kinds
        raise TypeError(f"not a drawing primitive: {prim!r}")


def draw(scene: Scene, renderer: Renderer) -> Any:
    """Draw ``scene`` with ``renderer`` and return what ``renderer.end()`` returns."""
    renderer.begin(scene.page.width_mm, scene.page.height_mm, title=markup.plain(scene.title),
                   name=make_id(scene.name))
    for group in scene.groups():
        _emit(group, renderer)
    return renderer.end()
