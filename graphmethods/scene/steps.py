"""A construction told step by step: the finished figure split into ordered steps, each with a caption.

A :class:`BuildUp` holds a finished :class:`~graphmethods.scene.Scene` and a partition of its
elements into :class:`Step` s, in the order a teacher draws them. Nothing is drawn twice: step
k shows exactly the elements of steps 1…k, taken from the finished figure in its own drawing
order, so the last step *is* the finished figure. :meth:`BuildUp.slide` shows one step for a
lecture: the earlier steps in grey, the new one in colour, its caption under the figure.

Steps are made by :func:`partition` from rules on the element names (the names the figure
function gives, such as ``vector-pa`` or ``line-B-a``); a step source (the velocity plan, the
energy indicator, the Wittenbauer diagram, and later the acceleration and force plans) is a
function that builds the figure and lists its rules.

>>> from graphmethods.scene import Page, Scene, Text, Line
>>> fig = Scene(Page("A4"), (Text((20, 20), "Title", name="title"), Line((20, 40), (80, 40), name="axis"),
...                          Line((20, 40), (50, 10), name="ray")), name="demo")
>>> bu = partition(fig, [("Axes", ("title", "axis")), ("The ray", ("ray",))], caption_box=(10, 180, 287, 200))
>>> len(bu), [e.name for e in bu.scene_at(1).elements], bu.scene_at(2) == fig
(2, ['title', 'axis'], True)
>>> [e.name for e in bu.slide(2).elements]
['title', 'axis', 'ray', 'step-caption']
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

from graphmethods.errors import InputError
from graphmethods.scene.elements import Element, Text
from graphmethods.scene.primitives import Circle, Group, Label, Path, Polygon, Primitive
from graphmethods.scene.scene import Scene

#: colour of the step being drawn, and of the steps drawn before it
NEW_COLOUR = "#c62828"
OLD_COLOUR = "#9a9a9a"
#: the new step's lines are drawn at least this wide, mm
NEW_WIDTH_MM = 0.35
#: elements never tinted: the figure's title stays black on every slide
UNTINTED = ("title",)

Rule = str | Sequence[str] | Callable[[str], bool]


@dataclass(frozen=True)
class Step:
    """One step of a construction.

    Attributes
    ----------
    caption : str
        What the step does, in the figure's language (markup: ``v_{BA}``, ``ψ_{max}``).
    elements : tuple of int
        Indices of the finished figure's elements this step adds.
    """

    caption: str
    elements: tuple[int, ...]


def _tint_prim(p: Primitive, colour: str, min_width_mm: float = 0.0) -> Primitive:
    if isinstance(p, Group):
        return Group(p.name, tuple(_tint_prim(c, colour, min_width_mm) for c in p.children))
    if isinstance(p, Label):
        return replace(p, color=colour)
    if isinstance(p, (Path, Polygon, Circle)):
        st = p.style
        stroke = colour if st.stroke and st.stroke.lower() not in ("none", "#ffffff", "#fff", "white") else st.stroke
        fill = colour if st.fill and st.fill.lower() not in ("none", "#ffffff", "#fff", "white") else st.fill
        width = max(st.width_mm, min_width_mm) if st.stroke and st.width_mm > 0 else st.width_mm
        return replace(p, style=st.with_(stroke=stroke, fill=fill, width_mm=width))
    return p  # pragma: no cover - the scene model produces only the five kinds


@dataclass(frozen=True)
class Tinted(Element):
    """An element drawn in one colour (strokes, fills and text; white fills stay white), its lines
    at least ``min_width_mm`` wide.

    >>> from graphmethods.scene.elements import Line
    >>> Tinted(Line((0, 0), (10, 0), name="l"), "#ff0000").draw().children[0].style.stroke
    '#ff0000'
    """

    element: Element
    colour: str
    min_width_mm: float = 0.0
    name: str = ""

    def __post_init__(self) -> None:
        object.__setattr__(self, "name", self.element.name)

    def primitives(self) -> tuple[Primitive, ...]:
        return tuple(_tint_prim(p, self.colour, self.min_width_mm) for p in self.element.primitives())


def tinted(element: Element, colour: str) -> Element:
    """``element`` in ``colour`` (the new step's lines at least :data:`NEW_WIDTH_MM` wide, to be seen
    from the back of a lecture hall); the figure's title is never tinted."""
    if element.name in UNTINTED:
        return element
    return Tinted(element, colour, NEW_WIDTH_MM if colour == NEW_COLOUR else 0.0)


@dataclass(frozen=True)
class BuildUp:
    """A finished figure and its construction steps (see the module docstring).

    Attributes
    ----------
    figure : Scene
        The finished figure, exactly as its figure function draws it.
    steps : tuple of Step
        Every element of ``figure`` belongs to exactly one step; no step is empty.
    caption_box : (float, float, float, float), mm
        Where the caption goes under the figure (x0, y0, x1, y1); the figure leaves it free.
    caption_mm : float, mm
        Caption text size.
    """

    figure: Scene
    steps: tuple[Step, ...]
    caption_box: tuple[float, float, float, float]
    caption_mm: float = 5.0

    def __post_init__(self) -> None:
        n = len(self.figure.elements)
        seen = sorted(i for s in self.steps for i in s.elements)
        if seen != list(range(n)):
            raise InputError(f"{self.figure.name}: the steps must hold every element of the figure exactly once")
        if any(not s.elements for s in self.steps):
            raise InputError(f"{self.figure.name}: a step adds no element")
        object.__setattr__(self, "steps", tuple(self.steps))

    def __len__(self) -> int:
        return len(self.steps)

    @property
    def notation(self) -> str:
        return self.figure.notation

    def captions(self) -> tuple[str, ...]:
        """The captions (markup), step 1 first."""
        return tuple(s.caption for s in self.steps)

    def _check(self, k: int) -> int:
        if isinstance(k, bool) or not isinstance(k, int) or not 1 <= k <= len(self.steps):
            raise InputError(f"step {k!r}: give a step from 1 to {len(self.steps)}")
        return k

    def step_of(self) -> tuple[int, ...]:
        """For every element of the figure, the number (1…) of the step that adds it."""
        out = [0] * len(self.figure.elements)
        for k, s in enumerate(self.steps, start=1):
            for i in s.elements:
                out[i] = k
        return tuple(out)

    def scene_at(self, k: int) -> Scene:
        """The figure as it stands after step ``k`` (1-based): steps 1…k, untinted, in drawing order."""
        k = self._check(k)
        of = self.step_of()
        return replace(self.figure, elements=tuple(e for e, s in zip(self.figure.elements, of) if s <= k))

    def layer(self, k: int, colour: str) -> tuple[Element, ...]:
        """The elements step ``k`` adds, tinted ``colour``, in drawing order."""
        k = self._check(k)
        return tuple(tinted(self.figure.elements[i], colour) for i in sorted(self.steps[k - 1].elements))

    def caption_element(self, k: int, *, numbered: bool = True) -> Text:
        """Step ``k``'s caption as a text element centred in the caption box."""
        k = self._check(k)
        x0, y0, x1, y1 = self.caption_box
        text = f"{k}. {self.steps[k - 1].caption}" if numbered else self.steps[k - 1].caption
        return Text(((x0 + x1) / 2, (y0 + y1) / 2), text, size_mm=self.caption_mm, anchor="middle", valign="middle",
                    name="step-caption")

    def slide(self, k: int, *, new: str = NEW_COLOUR, old: str = OLD_COLOUR) -> Scene:
        """Step ``k`` for a lecture: steps before it in ``old`` colour, its own elements in ``new``,
        its caption under the figure."""
        k = self._check(k)
        of = self.step_of()
        els = [tinted(e, new if s == k else old) for e, s in zip(self.figure.elements, of) if s <= k]
        return replace(self.figure, elements=tuple(els) + (self.caption_element(k),),
                       name=f"{self.figure.name}-step-{k}")


def partition(figure: Scene, rules: Sequence[tuple[str, Rule]], *, caption_box: tuple[float, float, float, float],
              caption_mm: float = 5.0, rest: int | None = None) -> BuildUp:
    """Split ``figure`` into steps by rules on its element names.

    Parameters
    ----------
    figure : Scene
        The finished figure.
    rules : sequence of (caption, rule)
        One per step, in order. A rule is an element name, a sequence of names, or a predicate
        ``name -> bool``; an element goes to the first step whose rule it matches.
    caption_box : (x0, y0, x1, y1), mm
        Where the captions go.
    rest : int, optional
        The step (1-based) that takes the elements no rule matches; without it such an element
        is an error.

    Raises
    ------
    InputError
        An element no rule matches (without ``rest``), or a step left empty.
    """
    tests: list[Callable[[str], bool]] = []
    for _caption, rule in rules:
        if callable(rule):
            tests.append(rule)
        else:
            names = {rule} if isinstance(rule, str) else set(rule)
            tests.append(names.__contains__)
    chosen: list[list[int]] = [[] for _ in tests]
    for i, e in enumerate(figure.elements):
        k = next((j for j, t in enumerate(tests) if t(e.name)), None)
        if k is None:
            if rest is None:
                raise InputError(f"{figure.name}: no step draws the element {e.name!r}")
            k = rest - 1
        chosen[k].append(i)
    steps = [Step(caption, tuple(idx)) for (caption, _), idx in zip(rules, chosen)]
    empty = [s.caption for s in steps if not s.elements]
    if empty:
        raise InputError(f"{figure.name}: no element for the step {empty[0]!r}")
    x0, y0, x1, y1 = (float(v) for v in caption_box)
    return BuildUp(figure, tuple(steps), (x0, y0, x1, y1), caption_mm)
