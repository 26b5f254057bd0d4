"""Structural analysis of a drawn mechanism: Chebyshev–Grübler's W and the decomposition into Assur groups.

A mechanism is given as a textbook draws it: links by number ("0" the frame), each listing its
joints; a joint on two links is a revolute pair between them (on k links: k − 1 pairs, a compound
hinge); ``slides`` are prismatic pairs between two links. With the driver (class I: the frame
and the input link pinned to it) known, groups of zero mobility are added one by one, each
attached only to links already known (Assur's principle):

* class II (dyads): two links, three pairs, of the five kinds RRR, RRP (PRR), RPR, PRP, RPP,
  named by the pairs along the chain outer–inner–outer;
* class III (triads): a base link with three inner pairs and three binary links, each with one
  outer pair to a known link (4 links, 6 pairs).

The result is the degree of freedom W = 3n − 2p₅ − p₄, the groups in solving order and the
structural formula as courses write it, ``I(0,1) → II(2,3) → III(4,5,6,7)``. What cannot be
decomposed is refused with a named reason (:class:`StructureError`): W ≠ 1, a link with no pair,
a driver not pinned to the frame, a group of class IV or higher, passive (redundant) constraints,
a group of three prismatic pairs.

>>> s = decompose({"0": ("O", "C"), "1": ("O", "A"), "2": ("A", "B"), "3": ("B", "C")}, (), driver="1",
...               about="O")
>>> s.formula, s.dof, [g.kind for g in s.groups]
('I(0,1) → II(2,3)', 1, ['RRR'])
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from graphmethods.errors import InputError

#: the frame's link number (the fixed link of every mechanism)
GROUND = "0"


class StructureError(InputError):
    """A drawn mechanism whose structure the program cannot take: the message names the reason."""


@dataclass(frozen=True)
class Slide:
    """A prismatic pair: link ``block`` slides on link ``on`` along the line through the block's
    point ``at`` at ``angle`` (rad from +x in the drawn position, fixed in ``on``)."""

    block: str
    on: str
    at: str
    angle: float


#: one pair of a link of a group: ("R", joint, other link) or ("P", slide index, other link)
Conn = tuple[str, str | int, str]


@dataclass(frozen=True)
class FoundGroup:
    """An Assur group found by :func:`decompose`.

    Attributes
    ----------
    kind : str
        ``"RRR"``, ``"RRP"``, ``"RPR"``, ``"PRP"``, ``"RPP"`` or ``"triad"``.
    cls : int
        Its class (2 for a dyad, 3 for a triad).
    links : tuple of str
        A dyad's two links in chain order (the outer pair of ``links[0]`` first, as ``kind`` reads);
        a triad's base link first, then its three binary links.
    outer : tuple of Conn
        The outer pair of each link (a dyad's two; a triad's three, of the binary links).
    inner : tuple of Conn
        The inner pairs (a dyad's one; a triad's three, base to binary link i).
    """

    kind: str
    cls: int
    links: tuple[str, ...]
    outer: tuple[Conn, ...]
    inner: tuple[Conn, ...]

    @property
    def label(self) -> str:
        """``II(2,3)`` or ``III(4,5,6,7)``, the links in increasing order."""
        roman = {2: "II", 3: "III"}[self.cls]
        return f"{roman}({','.join(sorted(self.links, key=_num))})"


@dataclass(frozen=True)
class Decomposition:
    """The structure of a drawn mechanism.

    Attributes
    ----------
    n_moving, p_lower, p_higher, dof : int
        n, p₅, p₄ and W = 3n − 2p₅ − p₄.
    driver : str
        The input link.
    groups : tuple of FoundGroup
        The Assur groups in solving order.
    formula : str
        ``"I(0,1) → II(2,3) → III(4,5,6,7)"``.
    mechanism_class : int
        The highest class of its groups (1 with none).
    """

    n_moving: int
    p_lower: int
    p_higher: int
    dof: int
    driver: str
    groups: tuple[FoundGroup, ...]
    formula: str
    mechanism_class: int

    def as_json(self) -> dict[str, object]:
        """``{"formula": ..., "groups": [{"class": 2, "links": [2, 3], "type": "RRR"}, ...], "dof": 1}``."""
        return {"formula": self.formula, "dof": self.dof, "n": self.n_moving, "p5": self.p_lower,
                "p4": self.p_higher, "class": self.mechanism_class,
                "groups": [{"class": g.cls, "links": [int(k) for k in sorted(g.links, key=_num)], "type": g.kind}
                           for g in self.groups]}


def _num(k: str) -> tuple[int, str]:
    return (int(k), k) if k.isdigit() else (10 ** 9, k)


class _Graph:
    """Links, their joints and slides; which joints are pairs."""

    def __init__(self, links: Mapping[str, Sequence[str]], slides: Sequence[Slide]) -> None:
        self.links = {k: tuple(v) for k, v in links.items()}
        self.slides = tuple(slides)
        self.on: dict[str, list[str]] = {}
        for k, js in self.links.items():
            for j in js:
                self.on.setdefault(j, []).append(k)

    def p_lower(self) -> int:
        return sum(len(ls) - 1 for ls in self.on.values() if len(ls) > 1) + len(self.slides)

    def pairs_of(self, link: str) -> list[Conn]:
        """Every pair of ``link``: revolute at a joint shared with another link, prismatic by slide."""
        out: list[Conn] = []
        for j in self.links[link]:
            for other in self.on[j]:
                if other != link:
                    out.append(("R", j, other))
        for i, s in enumerate(self.slides):
            if s.block == link:
                out.append(("P", i, s.on))
            elif s.on == link:
                out.append(("P", i, s.block))
        return out

    def external(self, link: str, known: set[str]) -> list[Conn]:
        """The pairs of ``link`` with known links: one per joint pinned to a known link, one per slide."""
        seen: set[str] = set()
        out: list[Conn] = []
        for kind, x, other in self.pairs_of(link):
            if other not in known:
                continue
            if kind == "R":
                if x in seen:
                    continue
                seen.add(str(x))
            out.append((kind, x, other))
        return out

    def between(self, a: str, b: str, known: set[str]) -> list[Conn]:
        """The pairs between the unknown links a and b (a revolute at a joint no known link carries)."""
        out: list[Conn] = []
        for kind, x, other in self.pairs_of(a):
            if other != b:
                continue
            if kind == "R" and any(k in known for k in self.on[str(x)]):
                continue                      # a joint on a known link: each is pinned there (external)
            out.append((kind, x, other))
        return out


_DYAD_KIND = {"RRR": "RRR", "RRP": "RRP", "PRR": "RRP", "RPR": "RPR", "PRP": "PRP", "RPP": "RPP", "PPR": "RPP"}


def _dyad(g: _Graph, a: str, b: str, known: set[str]) -> FoundGroup | None:
    ea, eb = g.external(a, known), g.external(b, known)
    inner = g.between(a, b, known)
    if len(ea) != 1 or len(eb) != 1 or len(inner) != 1:
        return None
    seq = ea[0][0] + inner[0][0] + eb[0][0]
    if seq == "PPP":
        raise StructureError(f"links {a} and {b} with three prismatic pairs (PPP) are no Assur group: three slides "
                             f"cannot fix where the links stand; pin one of them")
    if seq in ("PRR", "PPR"):                 # read the chain from the other end: RRP, RPP
        a, b, ea, eb = b, a, eb, ea
        inner = g.between(a, b, known)
    return FoundGroup(_DYAD_KIND[seq], 2, (a, b), (ea[0], eb[0]), (inner[0],))


def _triad(g: _Graph, t: str, unknown: list[str], known: set[str]) -> FoundGroup | None:
    if g.external(t, known):
        return None
    nbrs = [k for k in unknown if k != t and len(g.between(t, k, known)) == 1 and len(g.external(k, known)) == 1]
    for trio in itertools.combinations(nbrs, 3):
        if any(g.between(x, y, known) for x, y in itertools.combinations(trio, 2)):
            continue
        return FoundGroup("triad", 3, (t, *trio), tuple(g.external(k, known)[0] for k in trio),
                          tuple(g.between(t, k, known)[0] for k in trio))
    return None


def decompose(links: Mapping[str, Sequence[str]], slides: Sequence[Slide], *, driver: str,
              about: str) -> Decomposition:
    """The structure of a drawn mechanism (see the module docstring).

    Parameters
    ----------
    links : mapping link number -> joint names
        ``"0"`` the frame; a joint on two links is a revolute pair between them.
    slides : sequence of Slide
        The prismatic pairs.
    driver : str
        The input link; ``about`` its fixed pivot (a joint of the frame).

    Raises
    ------
    StructureError
        With the reason: a link with no pair, W ≠ 1, a driver not pinned to the frame at ``about``
        alone, a group of class IV or higher or passive constraints, a PPP chain.
    """
    g = _Graph(links, slides)
    moving = sorted((k for k in g.links if k != GROUND), key=_num)
    for k in moving:
        if not g.pairs_of(k):
            raise StructureError(f"link {k} has no pair: it is joined to no other link (list a joint it shares "
                                 f"with another link, or a slide)")
    n, p5 = len(moving), g.p_lower()
    W = 3 * n - 2 * p5
    if W != 1:
        why = ("it cannot move: a rigid structure, or a passive (redundant) constraint such as a third parallel "
               "link; remove it" if W == 0 else
               "over-constrained (statically indeterminate); remove a redundant link or pair" if W < 0 else
               f"it needs {W} inputs and the drawn form takes one driver (a link with one pair turns freely)")
        raise StructureError(f"W = 3n − 2p₅ − p₄ = 3·{n} − 2·{p5} − 0 = {W}: {why}")
    ext = g.external(driver, {GROUND})
    if driver not in g.links or ext != [("R", about, GROUND)]:
        raise StructureError(f"the driver, link {driver}, must be pinned to the frame at {about} and nowhere else "
                             f"(its pairs with the frame: {', '.join(str(x) for _, x, _ in ext) or 'none'})")
    known = {GROUND, driver}
    groups: list[FoundGroup] = []
    while True:
        unknown = [k for k in moving if k not in known]
        if not unknown:
            break
        found = None
        for a, b in itertools.combinations(unknown, 2):
            found = _dyad(g, a, b, known)
            if found:
                break
        if found is None:
            for t in unknown:
                found = _triad(g, t, unknown, known)
                if found:
                    break
        if found is None:
            rest = ", ".join(unknown)
            raise StructureError(f"links {rest} form no Assur group of class II or III attached to the links known "
                                 f"before them ({', '.join(sorted(known, key=_num))}): a group of class IV or higher, "
                                 f"or a passive constraint beside a free link; the drawn form solves class II and "
                                 f"III groups")
        groups.append(found)
        known |= set(found.links)
    formula = " → ".join([f"I(0,{driver})", *(x.label for x in groups)])
    return Decomposition(n_moving=n, p_lower=p5, p_higher=0, dof=W, driver=driver, groups=tuple(groups),
                         formula=formula, mechanism_class=max([1, *(x.cls for x in groups)]))


__all__ = ["Decomposition", "FoundGroup", "Slide", "StructureError", "decompose"]
