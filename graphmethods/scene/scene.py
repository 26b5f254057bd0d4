"""A scene: a page, the elements drawn on it, and what a reader needs to know about it.

A scene is frozen; :meth:`Scene.add` returns a new one. Its :meth:`Scene.groups`
are the primitives a backend draws, one named group per element, with unique
ids made from the element names (never from a global counter).

>>> from graphmethods.scene.elements import Axis, Text
>>> from graphmethods.scene.scale import Scale
>>> s = Scene(Page("A4", "landscape"), name="demo")
>>> s = s.add(Axis((20, 100), Scale("μ_M", "N·m", 2.0), "y", max_value=40, name="M"), Text((20, 20), "M_d"))
>>> [g.name for g in s.groups()], [sc.caption() for sc in s.scales()]
(['M', 'text'], ['μ_M = 2 N·m/mm'])
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from typing import Any

from graphmethods.errors import InputError
from graphmethods.scene.elements import Axis, Element, ScaleCaptions, bbox
from graphmethods.scene.markup import MIN_TEXT_MM, full_width_punctuation
from graphmethods.scene.page import Page
from graphmethods.scene.primitives import Group, Label, Primitive, walk
from graphmethods.scene.scale import Scale

_ID_BAD = re.compile(r"[^A-Za-z0-9_.-]+")


def make_id(name: str) -> str:
    """A valid XML id from an element name (ASCII letters, digits, ``_ . -``).

    >>> make_id("vector a→b"), make_id("1st"), make_id("")
    ('vector-a-b', 'g-1st', 'g')
    """
    try:
        return _IDS[name]
    except (KeyError, TypeError):
        pass
    made = _make_id(name)
    if type(name) is str and len(_IDS) < 1 << 15:      # the same few hundred names again and again
        _IDS[name] = made
    return made


_IDS: dict[str, str] = {}


def _make_id(name: str) -> str:
    s = _ID_BAD.sub("-", str(name)).strip("-")
    if not s or not (s[0].isalpha() or s[0] == "_"):
        s = "g-" + s if s else "g"
    return s


def _chinese_punctuation(prim: Any) -> Any:
    """A primitive with its labels' ASCII ``,:;`` next to Chinese text made full-width (one typography on
    every zh figure, whatever recipe joined the words)."""
    if isinstance(prim, Group):
        return Group(prim.name, tuple(_chinese_punctuation(c) for c in prim.children))
    if isinstance(prim, Label) and any(c in t for t, _ in prim.runs for c in ",:;"):
        return replace(prim, runs=tuple((full_width_punctuation(t), sh) for t, sh in prim.runs))
    return prim


def _unique(prims: Iterable[Primitive], used: set[str]) -> tuple[Primitive, ...]:
    out: list[Primitive] = []
    for p in prims:
        if isinstance(p, Group):
            base = make_id(p.name)
            name, n = base, 1
            while name in used:
                n += 1
                name = f"{base}-{n}"
            used.add(name)
            out.append(Group(name, _unique(p.children, used)))
        else:
            out.append(p)
    return tuple(out)


@dataclass(frozen=True)
class Scene:
    """A figure: a :class:`Page` and the elements on it, plus metadata.

    Parameters
    ----------
    page : Page
    elements : tuple of Element
        Drawn in order (later on top).
    title : str
        The figure's title (markup), also the SVG ``<title>``.
    notation : str
        The notation profile the figure was drawn in (``en``, ``ru``, ``zh``).
    name : str
        Short name (id of the root group, file names in the gallery).
    extra_scales : tuple of Scale
        Scales used without an axis (μ_E of an energy indicator drawn without one).
    notes : tuple of str
        Plain-text facts about the figure (which scales were picked and why).
    """

    page: Page = field(default_factory=Page)
    elements: tuple[Element, ...] = ()
    title: str = ""
    notation: str = "en"
    name: str = "figure"
    extra_scales: tuple[Scale, ...] = ()
    notes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        els = tuple(self.elements)
        for e in els:
            if not isinstance(e, Element):
                raise InputError(f"scene {self.name}: {e!r} is not a figure element")
        object.__setattr__(self, "elements", els)
        if self.notation == "zh":          # the title as drawn: one typography (see _chinese_punctuation)
            object.__setattr__(self, "title", full_width_punctuation(self.title))

    def add(self, *elements: Element) -> Scene:
        """A new scene with ``elements`` appended."""
        return replace(self, elements=self.elements + tuple(elements))

    def with_(self, **changes: Any) -> Scene:
        """A copy with some fields changed."""
        return replace(self, **changes)

    def element(self, name: str) -> Element:
        """The first element called ``name``."""
        for e in self.elements:
            if e.name == name:
                return e
        have = ", ".join(e.name for e in self.elements)
        raise InputError(f"scene {self.name}: no element named {name!r}; have {have}")

    def axes(self) -> tuple[Axis, ...]:
        """The axes drawn (top-level elements and inside groups)."""
        out: list[Axis] = []

        def visit(els: Iterable[Element]) -> None:
            for e in els:
                if isinstance(e, Axis):
                    out.append(e)
                visit(getattr(e, "elements", ()))

        visit(self.elements)
        return tuple(out)

    def scales(self) -> tuple[Scale, ...]:
        """Every scale the figure uses: its axes', the captions', then ``extra_scales`` (no repeats)."""
        found = [a.scale for a in self.axes()]
        for e in self.elements:
            if isinstance(e, ScaleCaptions):
                found.extend(e.scales)
        found.extend(self.extra_scales)
        out, keys = [], set()
        for s in found:
            key = (s.symbol, s.unit, s.per_mm)
            if key not in keys:
                keys.add(key)
                out.append(s)
        return tuple(out)

    def groups(self) -> tuple[Group, ...]:
        """The primitives to draw: the page's group (frame, title block; when drawn), then one group per
        element; ids unique."""
        lettering = MIN_TEXT_MM.get()            # what text sizes come out depends on it (lettered_size)
        memo = self.__dict__.get("_groups_memo")  # once per lettering: a class set writes each page twice
        if memo is not None and memo[0] == lettering:
            drawn: tuple[Group, ...] = memo[1]
            return drawn
        page = self.page.primitives()
        prims = ([Group("page", page)] if page else []) + [e.draw() for e in self.elements]
        drawn = tuple(g for g in _unique(prims, set()) if isinstance(g, Group))     # all groups, as given
        if self.notation == "zh":
            drawn = tuple(_chinese_punctuation(g) for g in drawn)
        object.__setattr__(self, "_groups_memo", (lettering, drawn))
        return drawn

    def primitives(self) -> tuple[Primitive, ...]:
        """Every primitive, depth first (groups included)."""
        return tuple(walk(self.groups()))

    def bbox(self) -> tuple[float, float, float, float] | None:
        """Estimated box (x0, y0, x1, y1) in mm of everything drawn."""
        return bbox(self.groups())

    def save(self, path: Any, *, overwrite: bool = False) -> Any:
        """Write the scene as the file ``path`` names it (.svg, .pdf, .png or .dxf), atomically, as
        :func:`graphmethods.render.formats.save` does; ``overwrite=True`` replaces an existing file
        (as matplotlib's ``savefig`` does), else an existing file is kept and
        :class:`~graphmethods.errors.OutputExistsError` raised.

        Returns
        -------
        pathlib.Path
            The path written.

        Examples
        --------
        >>> import tempfile, pathlib
        >>> from graphmethods.scene import Page, Text
        >>> s = Scene(Page("A4"), (Text((10, 12), "M_d", name="t"),))
        >>> with tempfile.TemporaryDirectory() as d:
        ...     p = s.save(pathlib.Path(d) / "a.svg")
        ...     p = s.save(pathlib.Path(d) / "a.svg", overwrite=True)      # again: replaced
        ...     p.name
        'a.svg'
        """
        # the writers sit one layer up (graphmethods.render), looked up by name at call time
        import importlib

        return importlib.import_module("graphmethods.render.formats").save(self, path, overwrite=overwrite)

    def _repr_svg_(self) -> str:
        """Inline display in notebooks (Jupyter calls this): the SVG of the scene."""
        # The SVG writer sits one layer up (graphmethods.render); it is looked up by
        # name at call time so that the scene model never imports a backend.
        import importlib

        return str(importlib.import_module("graphmethods.render.svg").to_string(self))
