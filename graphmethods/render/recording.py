"""A renderer that records the primitives drawn, for tests of geometry (not pixels).

>>> from graphmethods.scene import Scene, Page, Scale, Vector
>>> mu = Scale("μ_E", "J", 10.0)
>>> rec = record(Scene(Page("A4"), (Vector.of((50, 100), value=250.0, scale=mu, angle_deg=90, name="ab"),)))
>>> round(rec.vector_length_mm("ab"), 6)
25.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from graphmethods.errors import InputError
from graphmethods.scene.primitives import XY, Label, Style
from graphmethods.scene.scene import Scene


@dataclass(frozen=True, init=False)
class Call:
    """One call a backend received: its kind, the ids of the groups around it, and its data (``__init__``
    written out as the primitives' are: a sheet's fill records thousands)."""

    kind: str
    groups: tuple[str, ...]
    data: Any = None
    style: Style | None = None

    def __init__(self, kind: str, groups: tuple[str, ...], data: Any = None, style: Style | None = None) -> None:
        self.__dict__.update(kind=kind, groups=groups, data=data, style=style)


class RecordingRenderer:
    """Records every call; :meth:`in_group` and friends query what was drawn."""

    def __init__(self) -> None:
        self.calls: list[Call] = []
        self._stack: list[str] = []
        self.width_mm = self.height_mm = 0.0
        self.title = self.name = ""

    # -- Renderer protocol
    def begin(self, width_mm: float, height_mm: float, *, title: str, name: str) -> None:
        self.width_mm, self.height_mm, self.title, self.name = width_mm, height_mm, title, name
        self.calls.append(Call("begin", (), (width_mm, height_mm, title, name)))

    def begin_group(self, id: str) -> None:
        self.calls.append(Call("begin_group", tuple(self._stack), id))
        self._stack.append(id)

    def end_group(self) -> None:
        self._stack.pop()
        self.calls.append(Call("end_group", tuple(self._stack)))

    def path(self, points: tuple[XY, ...], style: Style, closed: bool) -> None:
        self.calls.append(Call("path", tuple(self._stack), (tuple(points), closed), style))

    def polygon(self, points: tuple[XY, ...], style: Style) -> None:
        self.calls.append(Call("polygon", tuple(self._stack), tuple(points), style))

    def circle(self, cx: float, cy: float, r: float, style: Style) -> None:
        self.calls.append(Call("circle", tuple(self._stack), (cx, cy, r), style))

    def text(self, label: Label) -> None:
        self.calls.append(Call("text", tuple(self._stack), label))

    def end(self) -> RecordingRenderer:
        self.calls.append(Call("end", ()))
        return self

    # -- queries
    def group_ids(self) -> list[str]:
        """Every group id, in drawing order."""
        return [c.data for c in self.calls if c.kind == "begin_group"]

    def in_group(self, id: str, kind: str | None = None) -> list[Call]:
        """The drawing calls inside group ``id`` (at any depth), optionally of one kind."""
        if id not in self.group_ids():
            raise InputError(f"no group {id!r} was drawn; groups: {', '.join(self.group_ids())}")
        return [c for c in self.calls if id in c.groups and c.kind not in ("begin_group", "end_group")
                and (kind is None or c.kind == kind)]

    def texts(self, id: str | None = None) -> list[str]:
        """The plain text of every label (inside group ``id`` when given)."""
        calls = self.calls if id is None else self.in_group(id)
        return [c.data.text for c in calls if c.kind == "text"]

    def vector_length_mm(self, id: str) -> float:
        """Drawn length of the vector in group ``id``: from its shaft's start to its head's tip."""
        paths = self.in_group(id, "path")
        heads = self.in_group(id, "polygon")
        if not paths or not heads:
            raise InputError(f"group {id!r} is not a vector (needs a shaft and a head)")
        start = paths[0].data[0][0]
        tip = heads[0].data[0]
        return math.dist(start, tip)


def record(scene: Scene) -> RecordingRenderer:
    """Draw ``scene`` into a :class:`RecordingRenderer` and return it."""
    from graphmethods.render.base import draw

    rec = RecordingRenderer()
    draw(scene, rec)
    return rec
