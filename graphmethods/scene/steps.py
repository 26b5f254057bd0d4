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

import functools
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

from graphmethods.errors import InputError
from graphmethods.scene import markup
from graphmethods.scene.elements import Element, Text, make_label
from graphmethods.scene.page import PAPER, Page
from graphmethods.scene.primitives import Circle, Group, Label, Path, Polygon, Primitive, Style
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
    enlarged : float
        The figure is drawn ``enlarged`` : 1 (a slide for a projector, :func:`enlarge`): its scales,
        and the millimetres its texts and captions quote, are those of the drawing at 1 : 1, so a
        length measured on the page is ``enlarged`` times the one they mean.
    """

    figure: Scene
    steps: tuple[Step, ...]
    caption_box: tuple[float, float, float, float]
    caption_mm: float = 5.0
    enlarged: float = 1.0

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

    def caption_element(self, k: int, *, numbered: bool = True) -> Element:
        """Step ``k``'s caption centred in the caption box: one line, or as many lines (broken at
        spaces) as it needs to stay inside the box's width."""
        k = self._check(k)
        x0, y0, x1, y1 = self.caption_box
        text = f"{k}. {self.steps[k - 1].caption}" if numbered else self.steps[k - 1].caption
        lines = wrap(text, self.caption_mm, x1 - x0 - 4.0)
        if len(lines) == 1:
            return Text(((x0 + x1) / 2, (y0 + y1) / 2), text, size_mm=self.caption_mm, anchor="middle",
                        valign="middle", name="step-caption")
        return CaptionLines(((x0 + x1) / 2, (y0 + y1) / 2), tuple(lines), self.caption_mm, name="step-caption")

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
        ``name -> bool``; an element goes to the first step whose rule it matches (a leader line
        ``leader-NAME`` that no rule names goes with its label ``NAME``).
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

    def step_of(name: str) -> int | None:
        k = next((j for j, t in enumerate(tests) if t(name)), None)
        if k is None and name.startswith("leader-"):          # a label's leader line goes with its label
            return step_of(name[len("leader-"):])
        return k

    for i, e in enumerate(figure.elements):
        k = step_of(e.name)
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


# ----------------------------------------------------------------------------- captions on lines

#: line pitch of a caption broken over several lines, in font sizes
LINE_PITCH = 1.3


def _words(text: str) -> list[str]:
    """``text`` split at the spaces outside markup braces (``v_{B A}`` stays one word)."""
    out, depth, cur = [], 0, ""
    for ch in text:
        depth += (ch == "{") - (ch == "}")
        if ch == " " and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += ch
    out.append(cur)
    return [w for w in out if w]


#: what never starts a line: closing brackets and the punctuation after a word, and a per cent sign
CLOSING = ")]}»”,.;:!?%"
#: a number as the figures write it (1.5, 0,000, −150, 4.8·10⁻³)
_NUMBER = re.compile(r"^[−+-]?\(?\d[\d.,]*(·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?$")


@functools.cache
def _units() -> frozenset[str]:
    """Every unit the notations write (en and ru), and the degree and per cent signs."""
    from graphmethods.scene import vocabulary

    ru = vocabulary.family(vocabulary.CORE).units_ru
    return frozenset(ru) | frozenset(ru.values()) | {"°", "%"}


def _glued(words: list[str]) -> list[str]:
    """The words of a line with what must not begin a line joined to the word before it: a word that starts with a
    closing bracket or punctuation ("%)"), and a unit after its number ("538,423 Н·м;"). The ru Zhukovsky slide
    wrapped "(расхождение 0,000 %)" leaving "%)" alone on a line."""
    out: list[str] = []
    for w in words:
        unit = w.rstrip(CLOSING) or w
        if out and (w[0] in CLOSING or (unit in _units() and _NUMBER.match(out[-1].rsplit(" ", 1)[-1]))):
            out[-1] = f"{out[-1]} {w}"
        else:
            out.append(w)
    return _short_brackets(out)


def _short_brackets(words: list[str]) -> list[str]:
    """A bracketed remark of at most :data:`SHORT_REMARK` words kept on one line ("(расхождение 0,000 %)")."""
    out: list[str] = []
    i = 0
    while i < len(words):
        w = words[i]
        ends = [j for j in range(i, min(i + SHORT_REMARK, len(words))) if words[j].rstrip(CLOSING[1:]).endswith(")")]
        end = ends[0] if ends and w.startswith("(") else None
        out.append(" ".join(words[i:end + 1]) if end is not None else w)
        i = i + 1 if end is None else end + 1
    return out


#: the words of a bracketed remark that wrapping keeps together
SHORT_REMARK = 3


def wrap(text: str, size_mm: float, width_mm: float) -> list[str]:
    """``text`` (markup) broken at spaces into lines no wider than ``width_mm`` at ``size_mm``
    (a word wider than the width gets a line of its own); a closing bracket or a unit never begins a line.

    >>> wrap("Through a, draw the direction of v_{BA} ⊥ AB", 5.0, 60.0)
    ['Through a, draw the', 'direction of v_{BA} ⊥ AB']
    >>> wrap("по планам сил: 538,423 Н·м (расхождение 0,000 %)", 5.0, 130.0)     # not "…0,000" and "%)"
    ['по планам сил: 538,423 Н·м', '(расхождение 0,000 %)']
    """
    lines: list[str] = []
    for word in _glued(_words(text)):
        if lines and markup.text_width_mm(f"{lines[-1]} {word}", size_mm) <= width_mm:
            lines[-1] = f"{lines[-1]} {word}"
        else:
            lines.append(word)
    return lines or [""]


@dataclass(frozen=True)
class CaptionLines(Element):
    """Lines of markup centred one under the other about ``at`` (the middle of the block), mm.

    >>> el = CaptionLines((100.0, 50.0), ("one", "two"), 5.0, name="c")
    >>> [round(p.y, 3) for p in el.primitives()]
    [47.75, 54.25]
    """

    at: tuple[float, float]
    lines: tuple[str, ...]
    size_mm: float
    name: str = ""

    def primitives(self) -> tuple[Label, ...]:
        from graphmethods.scene.elements import ASCENT, DESCENT

        x, y = self.at
        pitch = LINE_PITCH * self.size_mm
        up, down = (ASCENT + 0.1) * self.size_mm, (DESCENT + markup.SUB_SHIFT) * self.size_mm
        first = y - ((len(self.lines) - 1) * pitch + up + down) / 2 + up      # the block centred on y
        return tuple(make_label((x, first + i * pitch), line, size_mm=self.size_mm, anchor="middle")
                     for i, line in enumerate(self.lines))


# ----------------------------------------------------------------------------- slides for a projector

#: the height of the smallest text on a projected slide, as a fraction of the slide's height
PROJECTOR_TEXT = 1.0 / 40.0


@dataclass(frozen=True)
class DesignPage(Page):
    """A page laid out at ``1/enlarged`` of its paper size, to be drawn enlarged ``enlarged`` : 1
    (a 16:9 slide laid out at 1/1.8 of 338.7 × 190.5 mm: its 2.6 mm labels are projected at 4.7 mm).

    >>> p = DesignPage("slide", enlarged=2.0, frame=False)
    >>> p.width_mm, p.height_mm, p.size
    (169.35, 95.25, 'SLIDE')
    """

    enlarged: float = 1.0

    def _dims(self) -> tuple[float, float]:
        short, long = PAPER[str(self.size).upper()]
        z = float(self.enlarged)
        return (long / z, short / z) if self.orientation == "landscape" else (short / z, long / z)


def _enlarge_style(st: Style, z: float) -> Style:
    return st.with_(width_mm=st.width_mm * z, dash=tuple(d * z for d in st.dash) if st.dash else st.dash)


def _enlarge_prim(p: Primitive, z: float) -> Primitive:
    if isinstance(p, Group):
        return Group(p.name, tuple(_enlarge_prim(c, z) for c in p.children))
    if isinstance(p, Label):
        return replace(p, x=p.x * z, y=p.y * z, size_mm=p.size_mm * z)
    if isinstance(p, (Path, Polygon)):
        return replace(p, points=tuple((x * z, y * z) for x, y in p.points), style=_enlarge_style(p.style, z))
    if isinstance(p, Circle):
        return replace(p, cx=p.cx * z, cy=p.cy * z, r=p.r * z, style=_enlarge_style(p.style, z))
    return p  # pragma: no cover - the scene model produces only the five kinds


@dataclass(frozen=True)
class Enlarged(Element):
    """An element drawn ``factor`` times larger about the page's origin: coordinates, text sizes,
    line widths and dashes.

    >>> from graphmethods.scene.elements import Line
    >>> Enlarged(Line((1, 2), (3, 2), name="l"), 2.0).primitives()[0].points
    ((2.0, 4.0), (6.0, 4.0))
    """

    element: Element
    factor: float
    name: str = ""

    def __post_init__(self) -> None:
        object.__setattr__(self, "name", self.element.name)

    def primitives(self) -> tuple[Primitive, ...]:
        return tuple(_enlarge_prim(p, self.factor) for p in self.element.primitives())


def enlarge_note(fig: Scene, z: float, note_mm: float, free: Callable[[Text], bool] | None = None) -> Text:
    """The note an enlarged figure carries at the top right of its design page ("drawn 1.3 : 1 for the
    projector; …"), or the ratio alone ("1.3 : 1") beside a long title or where ``free`` (a test of the note
    against the figure's ink, given by the caller: a ray may run to the page's top) refuses the long one.

    >>> from graphmethods.scene import Page
    >>> fig = Scene(DesignPage("slide", enlarged=2.0, frame=False), (), notation="en")
    >>> enlarge_note(fig, 2.0, 2.5).text, enlarge_note(fig, 2.0, 2.5, free=lambda t: False).text
    ('drawn 2 : 1 for the projector; μ and mm as at 1 : 1', '2 : 1')
    """
    from graphmethods.scene.notation import get as get_notation

    design = fig.page
    x0, y0, x1, _ = design.inner_box()
    nt = get_notation(fig.notation)
    title = next((e for e in fig.elements if e.name == "title"), None)
    right = title.bbox() if title is not None else None
    # the title is bold: 12 % wider than the estimate of regular text
    room = x1 - (right[0] + 1.12 * (right[2] - right[0]) if right is not None else x0) - 3.0
    words = nt.word("steps.enlarged", z=nt.number(z))
    ratio = f"{nt.number(z)} : 1"
    note = Text((x1, y0 + note_mm), ratio, size_mm=note_mm, anchor="end", name="enlarged")
    if markup.text_width_mm(words, note_mm) <= room:
        long = replace(note, text=words)
        if free is None or free(long):
            return long
    return note


def enlarge(bu: BuildUp, page: Page, *, note_mm: float, free: Callable[[Text], bool] | None = None) -> BuildUp:
    """``bu``, laid out on a :class:`DesignPage`, drawn on ``page`` (its full size) ``z`` : 1
    (z = the design page's ``enlarged``): every element and the caption box enlarged; the scales
    stay those of the drawing at 1 : 1 (every μ and every millimetre the figure and its captions
    quote refer to it), and a note at the top right of the slide says so (it joins step 1).

    Parameters
    ----------
    bu : BuildUp
        Built on a :class:`DesignPage` whose paper is ``page``'s.
    page : Page
        The page drawn on; its margins hold the figure and the caption band.
    note_mm : float
        Size of the note at 1 : 1, mm.
    free : callable, optional
        Whether the long note is clear of the figure's ink (:func:`enlarge_note`).
    """
    design = bu.figure.page
    z = float(getattr(design, "enlarged", 1.0))
    fig = bu.figure
    els = tuple(Enlarged(e, z) for e in fig.elements)
    steps = bu.steps
    if z != 1.0:
        els += (Enlarged(enlarge_note(fig, z, note_mm, free), z),)
        steps = (Step(steps[0].caption, steps[0].elements + (len(fig.elements),)),) + steps[1:]
    x0, cy0, cx1, cy1 = bu.caption_box
    scene = replace(fig, page=page, elements=els, extra_scales=fig.scales(),
                    notes=fig.notes + ((f"drawn {z:g} : 1 on the {page.size.lower()}; scales per mm at 1 : 1",)
                                       if z != 1.0 else ()))
    box = (round(x0 * z, 9), round(cy0 * z, 9), round(cx1 * z, 9), round(cy1 * z, 9))
    return BuildUp(scene, steps, box, bu.caption_mm * z, enlarged=z * bu.enlarged)
