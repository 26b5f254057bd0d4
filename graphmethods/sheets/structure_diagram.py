"""The structure diagram: the mechanism split into its driver and its Assur groups, as the structural-
analysis chapter draws it (структурный анализ, разложение на группы Ассура; 结构分析, 拆分杆组).

Each part is drawn apart, at the drawn position and to one scale μ_l: the driving link with the frame
(class I), then every Assur group in the order of the structural formula, its links as bars (a basic
ternary link of a triad as a triangle), its inner pairs as pins and blocks, its outer pairs marked: a
pair on the frame as a fixed pivot (a guide of the frame hatched), a pair on a link of an earlier part
as a double circle ◎. Under each part its formula and its class and order; under all of them the
structural formula, Chebyshev's W and the class of the mechanism. Built on the layout engine
(:mod:`graphmethods.sheets.engine`): one panel per part, their widths shared by what they need.

>>> from graphmethods.problems import builtin
>>> scene = structure_diagram(builtin.case("triad-six-bar"), notation="en")
>>> [e.name for e in scene.elements if e.name.startswith("part-")]
['part-I(0,1)', 'part-III(2,3,4,5)']
>>> scene.element("formula").text
'structural formula: I(0,1) → III(2,3,4,5)'
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphmethods.problems.reference_cases import title_of
from graphmethods.scene import Element, Page, Scene, notation as get_notation
from graphmethods.scene.elements import Group as ElementGroup, Line, Polyline, Text
from graphmethods.scene.markup import lowered_digits
from graphmethods.scene.primitives import MAIN, Circle, Style
from graphmethods.sheets.engine import Ink, Panel, Split, extent_of, lettering, shares_for
from graphmethods.sheets.frame import SheetFrame
from graphmethods.sheets.kinematic_symbols import JOINT, FixedPivot, Guide, PinJoint, SliderBlock
from graphmethods.sheets.yoke import yoke
from graphmethods.units import convenient_at_least

ROMAN = {1: "I", 2: "II", 3: "III"}
#: room around a part's drawing for its joints' names and symbols, mm
PAD_MM = 9.0


@dataclass(frozen=True)
class OuterPair(Element):
    """An outer pair on a link of an earlier part: a double circle ◎ (mm)."""

    at: tuple[float, float]
    radius_mm: float = 1.1
    name: str = "outer-pair"

    def primitives(self) -> tuple[Any, ...]:
        x, y = self.at
        return (Circle(x, y, self.radius_mm * 1.9, Style(width_mm=0.25)), Circle(x, y, self.radius_mm, JOINT))


@dataclass
class Part:
    """One part of the split mechanism: the driver with the frame, or one Assur group.

    Attributes
    ----------
    formula : str
        ``"I(0,1)"``, ``"II(2,3)"``, ``"III(2,3,4,5)"``.
    cls, order : int
        Assur's class and order (the driver: 1, 0).
    kind : str
        ``"crank"``, ``"RRR"``, ..., ``"triad"``.
    links : dict link -> list of joints
        The joints on each of its links (a bar between two, a plate over three).
    fixed, outer, inner : list of str
        Its pairs on the frame, on links of earlier parts, and between its own links.
    blocks : list of (joint, link)
        Its sliders: a block at the joint, along the direction of that link.
    guides : list of (joint, link)
        Its prismatic pairs with the frame: a hatched guide through the joint.
    yokes : list of (joint, link, angle)
        A slotted link translating on the frame's guide (a Scotch yoke, link ``link``): the block at ``joint``
        slides in its slot, at ``angle`` (rad, from +x) on the drawing.
    """

    formula: str
    cls: int
    order: int
    kind: str
    links: dict[str, list[str]] = field(default_factory=dict)
    fixed: list[str] = field(default_factory=list)
    outer: list[str] = field(default_factory=list)
    inner: list[str] = field(default_factory=list)
    blocks: list[tuple[str, str]] = field(default_factory=list)
    guides: list[tuple[str, str]] = field(default_factory=list)
    yokes: list[tuple[str, str, float]] = field(default_factory=list)


def _add(seq: list[str], x: str) -> None:
    if x not in seq:
        seq.append(x)


def structure_parts(lk: Any) -> list[Part]:
    """The driver and the Assur groups of a linkage as :class:`Part` s, in the order of the formula."""
    cr = lk.crank
    driver = Part(f"I(0,{cr.link})", 1, 0, "crank", {cr.link: [cr.centre, cr.pin]}, fixed=[cr.centre],
                  inner=[cr.pin])
    parts = [driver]
    driving = {p for g in lk.groups for p in g.inputs()[0]}
    for g in lk.groups:
        shown = g.links if g.cls == 2 else sorted(g.links, key=lambda k: (len(k), k))
        part = Part(f"{ROMAN.get(g.cls, str(g.cls))}({','.join(shown)})", g.cls, g.order, g.kind,
                    {k: [] for k in g.links})
        for kind, a, b, j in g.pairs:
            inside = [x for x in (a, b) if x in g.links]
            outside = [x for x in (a, b) if x not in g.links]
            for x in inside:
                _add(part.links[x], j)
            if kind == "P":
                part.blocks.append((j, b))
                if outside and outside[0] == "0":
                    part.guides.append((j, b))
            elif not outside:
                _add(part.inner, j)
            else:
                _add(part.fixed if j in lk.ground else part.outer, j)
        if g.kind == "RPP" and getattr(getattr(g, "guide", None), "link", None) == "0":  # a yoke on the frame
            part.yokes.append((g.P, g.links[1], float(g.guide.angle + g.slot_angle)))
        parts.append(part)
    for p in lk.points:                                # a lever's end that drives a later group is a joint
        if p.name in driving:
            for part in parts:
                if p.link in part.links:
                    _add(part.links[p.link], p.name)
                    _add(part.inner, p.name)
    return parts


def _drawn_angle(lk: Any) -> float:
    """The crank angle to draw at: the drawing's (a triad's), else the start of the working stroke, else 0."""
    tracks = lk._tracks() if getattr(lk, "_triads", ()) else {}
    if tracks:
        return float(next(iter(tracks.values())).phi_0)
    st = lk.strokes()
    return float(st.phi_start) if st is not None else 0.0


def _link_ink(pts: list[complex], name: str, to: Any) -> Element:
    """A link drawn through its joints: a bar (two joints, or all in line) or a closed plate."""
    xy = [to(z) for z in pts]
    if len(pts) >= 3:
        a, b, c = pts[:3]
        if abs(((b - a).conjugate() * (c - a)).imag) > 1e-9 * abs(b - a) * abs(c - a):
            return Polyline(tuple(xy), MAIN, closed=True, name=name)
    far = max(((i, j) for i in range(len(pts)) for j in range(i + 1, len(pts))),
              key=lambda ij: abs(pts[ij[0]] - pts[ij[1]]))
    return Line(xy[far[0]], xy[far[1]], MAIN, name=name)


def _yoke(pin: complex, u: complex, slot_angle: float, z: dict[str, complex], to: Any, k: str,
          box: tuple[float, float, float, float]) -> tuple[list[Element], tuple[float, float]]:
    """A yoke (a slotted crosshead, link ``k``) as the textbooks draw it (:func:`graphmethods.sheets.yoke.yoke`):
    its slot through the block's ``pin`` at ``slot_angle`` (rad), a rod from the slot along the guide (direction
    ``u``, away from the other joints) and the yoke's block on the frame's hatched guide. Returns the elements and
    the middle of the rod (mm)."""
    c = np.asarray(to(pin))
    others = [np.asarray(to(q)) - c for q in z.values() if abs(q - pin) > 1e-12]
    return yoke(c, slot_angle, np.array([u.real, -u.imag]) / max(abs(u), 1e-12), others, box, name=k)


def _part_elements(part: Part, z: dict[str, complex], e: dict[str, complex], panel: Panel, ink: Ink,
                   size_mm: float) -> list[Element]:
    """One part drawn in its panel: links, guides, blocks, pins, outer pairs, names and link numbers."""
    def to(c: complex) -> tuple[float, float]:
        return panel.to_page(c.real, c.imag)

    els: list[Element] = []
    for k, js in part.links.items():
        if len(js) >= 2 and max(abs(z[a] - z[b]) for a in js for b in js) > 0:
            els.append(_link_ink([z[j] for j in js], f"link-{k}", to))
    yoke_links = {k for _, k, _ in part.yokes}
    for j, k in part.guides:
        if k in yoke_links:                                             # drawn with the yoke's rod
            continue
        u = e[k]
        ang = math.degrees(math.atan2(u.imag, u.real))
        d = 9.0 * np.array([math.cos(math.radians(ang)), -math.sin(math.radians(ang))])
        c = np.asarray(to(z[j]))
        els.append(Guide(tuple(c - d), tuple(c + d), name=f"guide-{j}"))
    slotted = {j: ang for j, _, ang in part.yokes}
    rods = {k: _yoke(z[j], e[k], ang, z, to, k, panel.box) for j, k, ang in part.yokes}
    for j, k in part.blocks:
        if (j, k) in part.guides and k in rods:                        # the yoke's own block on the frame's guide
            continue
        ang = slotted.get(j, math.atan2(e[k].imag, e[k].real))
        els.append(SliderBlock(to(z[j]), angle_deg=math.degrees(ang), length_mm=7.0, height_mm=4.0,
                               name=f"block-{j}"))
    for els_k, _ in rods.values():
        els[:0] = els_k
    centre = sum(z[j] for js in part.links.values() for j in js) / max(1, sum(len(js) for js in part.links.values()))
    for j in part.fixed:
        down = z[j] - centre
        ang = math.degrees(math.atan2(down.imag, down.real)) if abs(down) > 0 else 270.0
        els.append(FixedPivot(to(z[j]), direction_deg=round(ang / 90.0) * 90.0 % 360.0, name=f"pivot-{j}"))
    els += [OuterPair(to(z[j]), name=f"outer-{j}") for j in part.outer]
    els += [PinJoint(to(z[j]), radius_mm=1.0, name=f"pin-{j}") for j in part.inner if j not in part.outer]
    for el in els:
        ink.add_primitives(el.primitives())
    texts: list[Element] = []
    for j in dict.fromkeys([*part.fixed, *part.outer, *part.inner]):
        lab, leader = ink.place(to(z[j]), lowered_digits(j), size_mm=size_mm, within=panel.box)
        texts.append(Text((lab.x, lab.y), lowered_digits(j), size_mm=size_mm, anchor=lab.anchor, name=f"name-{j}"))
        if leader is not None:
            texts.append(Line(leader[0], leader[1], name=f"leader-{j}"))
    for k, js in part.links.items():
        if k in rods:                                                   # a yoke's number by its rod
            lab, _ = ink.place(rods[k][1], k, size_mm=size_mm, directions=("n", "s", "ne", "se"), gap_mm=1.5,
                               within=panel.box, leader=False)
        elif len(js) >= 2:
            m = sum(z[j] for j in js) / len(js)
            lab, _ = ink.place(to(m), k, size_mm=size_mm, within=panel.box, leader=False)
        else:
            lab, _ = ink.place(to(z[js[0]]), k, size_mm=size_mm, directions=("n", "ne", "nw", "s"), gap_mm=3.0,
                               within=panel.box, leader=False)
        texts.append(Text((lab.x, lab.y), k, size_mm=size_mm, bold=True, anchor=lab.anchor, name=f"number-{k}"))
    return els + texts


def _shares(exts: list, area: tuple[float, float, float, float], margins: tuple[float, float, float, float], *,
            gap_mm: float, least: float = 0.18) -> tuple[float, ...]:
    """The parts' shares of the row that give them the largest common convenient scale: the smallest μ_l at
    which every part fits the height and all of them, each as wide as its drawing plus its margins (at least
    ``least`` of the row), fit the width; the room left shared in proportion to those widths.

    >>> _shares([(0, 0, 1, 0.5), (0, 0, 3, 0.5)], (0, 0, 212, 100), (10, 5, 10, 5), gap_mm=2.0)
    (0.277778, 0.722222)
    """
    width = area[2] - area[0] - gap_mm * (len(exts) - 1)
    height = area[3] - area[1] - margins[0] - margins[2]
    side, floor = margins[1] + margins[3], least * width
    w = [max(x[2] - x[0], 0.0) for x in exts]
    h = [max(x[3] - x[1], 0.0) for x in exts]
    if height <= 0 or width <= 0 or max(w + h) <= 0:
        return shares_for([1.0] * len(exts), least=least)
    mu = convenient_at_least(max(max(h) / height, 1e-12))
    for _ in range(60):                                  # up the convenient series until the row holds them
        if sum(max(wi / mu + side, floor) for wi in w) <= width:
            break
        mu = convenient_at_least(mu * 1.000001)
    needs = [max(wi / mu + side, floor) for wi in w]
    total = sum(needs)
    return tuple(round(n / total, 6) for n in needs)


def structure_diagram(case: Any, *, notation: str = "en", page: Page | None = None, title: str | None = None,
                      phi: float | None = None) -> Scene:
    """The structure diagram of a linkage (see the module docstring).

    Parameters
    ----------
    case : problem case or Linkage
        A linkage problem (``builtin.case("triad-six-bar")``) or a core linkage.
    notation : {"en", "ru", "zh"}
    page : Page, optional
        Default A4 landscape.
    phi : float, optional
        Crank angle to draw at, rad (default: the drawing's, else position 0).
    """
    lk = getattr(case, "linkage", case)
    nt = get_notation(notation)
    sheet = SheetFrame(nt=nt, page=page, title=title or nt.word("structure.title"),
                       problem=title_of(case) if hasattr(case, "linkage") else "", title_block=True,
                       default_page=Page("A4", "landscape", frame=True))
    let = lettering(sheet.page(()))
    st = lk.solve([_drawn_angle(lk) if phi is None else float(phi)], level=0)
    z = {k: complex(v[0]) for k, v in st.z.items()}
    e = {k: complex(np.broadcast_to(v, (1,))[0]) for k, v in st.e.items()}
    parts = structure_parts(lk)
    x0, _, x1, _ = sheet.box
    foot = 3 * let.value_mm * 1.6
    area = (x0, sheet.top + 2.0, x1, sheet.caption_y - let.label_mm * 2.0 - foot)
    exts = [extent_of([(z[j].real, z[j].imag) for js in p.links.values() for j in js]) for p in parts]
    names = [f"part-{p.formula}" for p in parts]
    margins = (2.6 * let.label_mm + PAD_MM, PAD_MM, PAD_MM, PAD_MM)
    boxes = Split("h", tuple(zip(names, _shares(exts, area, margins, gap_mm=6.0))), gap_mm=6.0).boxes(area)
    panels = [Panel(boxes[n], x, symbol="μ_l", unit="m", margins_mm=margins) for n, x in zip(names, exts)]
    sized = [p.scale for p, x in zip(panels, exts) if max(x[2] - x[0], x[3] - x[1]) > 0]   # a lone block: no size
    common = max(sized or [p.scale for p in panels], key=lambda s: s.per_mm)  # one scale for every part
    panels = [Panel(p.box, p.extent, symbol="μ_l", unit="m", margins_mm=margins, scale_given=common)
              for p in panels]
    els: list[Element] = [sheet.header()]
    ink = Ink()
    for part, panel, name in zip(parts, panels, names):
        bx0, by0, bx1, _ = panel.box
        cx = (bx0 + bx1) / 2
        head = [Text((cx, by0 + let.label_mm * 1.2), part.formula, size_mm=let.heading_mm, anchor="middle",
                     bold=True, name=f"{name}-formula"),
                Text((cx, by0 + let.label_mm * 2.5), nt.word("structure.driver") if part.cls == 1 else
                     nt.word("structure.group", cls=ROMAN.get(part.cls, part.cls), order=part.order) +
                     (f" ({part.kind})" if part.cls == 2 else ""), size_mm=let.label_mm, anchor="middle",
                     name=f"{name}-class")]
        for h in head:
            ink.add_primitives(h.primitives())
        els.append(ElementGroup(tuple(head + _part_elements(part, z, e, panel, ink, let.label_mm)), name=name))
    s = lk.structure()
    y = sheet.caption_y - let.label_mm * 2.0 - foot + let.value_mm * 1.4
    for key, text in (("formula", nt.word("structure.formula", formula=s.formula)),
                      ("dof", nt.word("structure.dof", n=s.n_moving, p5=s.p_lower, p4=s.p_higher, W=s.dof)),
                      ("class", nt.word("structure.class", cls=ROMAN.get(s.mechanism_class, s.mechanism_class)))):
        els.append(Text((x0, y), text, size_mm=let.value_mm, name=key))
        y += let.value_mm * 1.6
    els += sheet.captions([common], nt.word("structure.outer"))
    return sheet.scene(els, [common], name="structure-diagram")


__all__ = ["OuterPair", "Part", "structure_diagram", "structure_parts"]
