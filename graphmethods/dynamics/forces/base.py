"""What the force analysis of every group shares: applied forces, reactions, force-plan records.

Plane vectors are complex numbers x + iy over the positions (arrays of shape (n,)), as in the
kinematics core; moments are counterclockwise positive. A force ``F`` applied at ``at`` with a
couple ``M`` has the moment ``(at − X) × F + M`` about a point X.

A reaction ``R_ij`` is the force link i exerts on link j (frame = 0) at their pair; a revolute
pair transmits a force through its joint, a prismatic pair a force perpendicular to the guide
and a couple (the normal force's line of action is moved off the slider's joint by
h = M/N along the guide).

>>> import numpy as np
>>> from graphmethods.dynamics.forces.statics import moment_about
>>> f = Force("G_2", F=np.array([-10j]), at=np.array([0.2 + 0j]), M=np.zeros(1))
>>> float(moment_about([f], np.array([0j]))[0])         # 0.2 m × (−10 N) about the origin
-2.0
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from graphmethods.dynamics.forces.statics import Cx, Fl, cross, moment_about
from graphmethods.errors import InputError


@dataclass(frozen=True, eq=False)
class Force:
    """A force on a link (an inertia force, a weight, the working load, a reaction from a group
    solved before), over the positions.

    Attributes
    ----------
    label : str
        As the figure writes it: ``"F_i2"``, ``"G_2"``, ``"F_load"``, ``"R_43"``, ``"M_i2"``.
    F : complex ndarray (n,)
        The force, N (0 for a pure couple).
    at : complex ndarray (n,)
        Its point of application, m.
    M : ndarray (n,)
        A couple applied with it, N·m, counterclockwise + (the inertia moment, a load moment, the
        couple of a prismatic pair).
    """

    label: str
    F: Cx
    at: Cx
    M: Fl


def resultant(forces: Sequence[Force], n: int) -> Cx:
    """Σ F over the forces, N (n,)."""
    total: Cx = np.zeros(n, dtype=complex)
    for f in forces:
        total = total + f.F
    return total


def pair_key(i: str, j: str) -> str:
    """``"R_12"`` for links 1 and 2 (``"R_10_11"`` when a number has two digits)."""
    return f"R_{i}{j}" if len(i) == 1 and len(j) == 1 else f"R_{i}_{j}"


def _order(i: str) -> tuple[int, str]:
    return (len(i), i)


@dataclass(frozen=True, eq=False)
class Reaction:
    """The reaction in one kinematic pair, over the positions.

    Attributes
    ----------
    key : str
        ``"R_ij"`` with i before j (the lower link number first).
    by, on : str
        The link numbers i and j: ``R`` is the force link i exerts on link j.
    kind : str
        ``"R"`` (revolute: the force acts through the joint) or ``"P"`` (prismatic).
    R : complex ndarray (n,)
        Force of link i on link j, N.
    at : complex ndarray (n,)
        The joint (revolute) or the slider's joint on the guide (prismatic), m.
    M : ndarray (n,)
        The couple link i exerts on link j about ``at`` (prismatic pairs; 0 for revolute), N·m.
    guide : complex ndarray (n,) or None
        The guide's unit direction (prismatic pairs).
    """

    key: str
    by: str
    on: str
    kind: str
    R: Cx
    at: Cx
    M: Fl
    guide: Cx | None = None

    @property
    def h(self) -> Fl:
        """Where the normal force of a prismatic pair acts: its signed distance from ``at`` along
        the guide, m (M/(u × R)); 0 for a revolute pair, NaN where the normal force is zero."""
        if self.guide is None:
            return np.zeros(self.R.shape)
        with np.errstate(divide="ignore", invalid="ignore"):
            out: Fl = self.M / cross(self.guide, self.R)
        return out


def reaction(by: str, on: str, kind: str, R: Cx, at: Cx, M: Fl | None = None, guide: Cx | None = None) -> Reaction:
    """The reaction ``R`` of link ``by`` on link ``on``, stored as ``R_ij`` with i the lower number
    (the force and couple turned round when ``by`` is the higher one)."""
    M = np.zeros(R.shape) if M is None else np.broadcast_to(M, R.shape).astype(float)
    if _order(by) > _order(on):
        return Reaction(pair_key(on, by), on, by, kind, -R, at, -M, guide)
    return Reaction(pair_key(by, on), by, on, kind, R, at, M, guide)


def on_link(r: Reaction, link: str) -> Force:
    """The reaction as a force on ``link`` (one of its two links)."""
    if link == r.on:
        return Force(r.key, r.R, r.at, r.M)
    if link == r.by:
        name = pair_key(r.on, r.by)
        return Force(name, -r.R, r.at, -r.M)
    raise InputError(f"{r.key} does not act on link {link}")


@dataclass(frozen=True, eq=False)
class Polygon:
    """One force polygon of a plan: the known forces laid head to tail in order, closed by the
    unknowns.

    Attributes
    ----------
    links : tuple of str
        The links whose equilibrium it draws.
    known : tuple of (str, complex ndarray)
        The known forces in drawing order (label, N).
    closing : tuple of (str, complex ndarray or None, complex ndarray)
        The unknowns that close it: label, the direction of its line (unit; None when the
        unknown's direction is not known in advance and it is simply the closing side) and the
        force found, N.
    """

    links: tuple[str, ...]
    known: tuple[tuple[str, Cx], ...]
    closing: tuple[tuple[str, Cx | None, Cx], ...]

    @property
    def residual(self) -> Fl:
        """|Σ of every side| over the positions, N (0 to rounding: the polygon closes)."""
        total: Cx = np.zeros(np.shape(self.closing[0][2]), dtype=complex)
        for _, F in self.known:
            total = total + F
        for _, _, F in self.closing:
            total = total + F
        out: Fl = np.abs(total)
        return out


@dataclass(frozen=True, eq=False)
class ForcePlan:
    """How one group's reactions are found (the course's construction), over the positions.

    Attributes
    ----------
    group : str
        ``"RRR (2, 3)"``.
    links : tuple of str
    steps : tuple of str
        The construction in words, in order (the moment equations first).
    first : tuple of (str, complex ndarray)
        The components found before the plan from moment equations (the tangential parts
        R^τ of the outer reactions, a normal force from the moments about a pivot).
    polygons : tuple of Polygon
        The group's plan, then the polygon of one link that gives the inner reaction.
    """

    group: str
    links: tuple[str, ...]
    steps: tuple[str, ...]
    first: tuple[tuple[str, Cx], ...]
    polygons: tuple[Polygon, ...]


@dataclass(frozen=True, eq=False)
class GroupForces:
    """What a group solver returns: the reactions in its three pairs and its force plan."""

    reactions: tuple[Reaction, ...]
    plan: ForcePlan


@dataclass(frozen=True, eq=False)
class Kin:
    """The kinematic state a group solver reads: positions of every point and every link's unit
    direction, over the positions (from the kinematics core's :class:`Motion`)."""

    z: dict[str, Cx]
    e: dict[str, Cx]
    n: int

    def direction(self, link: str) -> Cx:
        out: Cx = np.broadcast_to(np.asarray(self.e[link], dtype=complex), (self.n,))
        return out


@dataclass(frozen=True, eq=False)
class DyadLoads:
    """The loads on a dyad's two links as every group solver starts from them, over the positions.

    Attributes
    ----------
    l2, l3 : str
        The group's links (the one at its first outer joint first).
    f2, f3 : list of Force
        Every force on each link (inertia, weight, load, reactions of later groups), N.
    F2, F3 : complex ndarray (n,)
        Their resultants, N.

    >>> import numpy as np
    >>> kin = Kin(z={}, e={}, n=1)
    >>> w = Force("G_3", F=np.array([-5j]), at=np.array([0j]), M=np.zeros(1))
    >>> d = dyad_loads(("2", "3"), kin, {"3": [w]})
    >>> d.known(d.f3), xy(d.F2[0]), xy(d.F3[0])
    ((('G_3', array([-0.-5.j])),), [0.0, 0.0], [0.0, -5.0])
    """

    l2: str
    l3: str
    f2: list[Force]
    f3: list[Force]
    F2: Cx
    F3: Cx

    @staticmethod
    def known(forces: Sequence[Force]) -> tuple[tuple[str, Cx], ...]:
        """The forces as the known sides of a polygon (label, N), in order."""
        return tuple((f.label, f.F) for f in forces)

    def link2_step(self, outer: str) -> str:
        """The step :meth:`link2_polygon` draws, in words: ``"link 2: R_12 + ΣF_2 + R_32 = 0"``."""
        return f"link {self.l2}: R_{outer} + ΣF_{self.l2} + R_{self.l3}{self.l2} = 0"

    def link2_polygon(self, outer: str, R_outer: Cx, R_32: Cx) -> Polygon:
        """The polygon of link 2 alone that gives the inner reaction: ``R_outer + ΣF_2 + R_32 = 0``
        (``outer`` the outer reaction's pair digits, e.g. ``"12"``; forces in N)."""
        return Polygon((self.l2,), ((f"R_{outer}", R_outer), *self.known(self.f2)),
                       ((f"R_{self.l3}{self.l2}", None, R_32),))

    def slot_couple(self, at: Cx) -> Fl:
        """The couple of the slot of link 3 on block 2 pinned at ``at`` (m), N·m: the block's own moments about
        its pin, reversed (the slot's force R_32 passes through the pin)."""
        return -moment_about(self.f2, at)

    def block_in_slot(self, a: str, P: str, at: Cx, R_32: Cx, Mc_32: Fl, u: Cx) -> BlockInSlot:
        """Block 2, pinned at ``P`` (position ``at``, m) to link ``a``, sliding in the slot of link 3 (unit
        direction ``u``) that pushes it with ``R_32`` (N) and the couple ``Mc_32`` (:meth:`slot_couple`): the
        reaction at P from the block's polygon, and the steps and the polygon that say so (RPP, RPR).

        >>> import numpy as np
        >>> f = Force("F", F=np.array([-10j]), at=np.array([0.1 + 0j]), M=np.zeros(1))
        >>> d = dyad_loads(("2", "3"), Kin(z={}, e={}, n=1), {"2": [f]})
        >>> at = np.array([0j])
        >>> b = d.block_in_slot("1", "A", at, np.array([4j]), d.slot_couple(at), np.array([1 + 0j]))
        >>> float(d.slot_couple(at)[0]), xy(b.reactions[0].R[0]), b.steps[0]     # 10 N at 0.1 m; 10 − 4 N at A
        (1.0, [0.0, 6.0], 'link 2: ΣM_A = 0 gives the couple of the slot on the block')
        """
        R_a2 = -(self.F2 + R_32)
        ta = f"{a}{self.l2}"
        return BlockInSlot(
            reactions=(reaction(a, self.l2, "R", R_a2, at), reaction(self.l3, self.l2, "P", R_32, at, Mc_32, u)),
            steps=(f"link {self.l2}: ΣM_{P} = 0 gives the couple of the slot on the block",
                   f"link {self.l2}: ΣF_{self.l2} + R_{self.l3}{self.l2} + R_{ta} = 0"),
            polygon=Polygon((self.l2,), (*self.known(self.f2), (f"R_{self.l3}{self.l2}", R_32)),
                            ((f"R_{ta}", None, R_a2),)))


@dataclass(frozen=True, eq=False)
class BlockInSlot:
    """What :meth:`DyadLoads.block_in_slot` finds: the reactions on the block (R_a2 at P, then R_32 with the
    slot's couple), the first and the last step of the group's plan, and the block's polygon."""

    reactions: tuple[Reaction, Reaction]
    steps: tuple[str, str]
    polygon: Polygon


def dyad_loads(links: tuple[str, str], kin: Kin, loads: Mapping[str, Sequence[Force]]) -> DyadLoads:
    """The loads of a dyad's links ``links`` read from ``loads`` (link -> forces, N), summed."""
    l2, l3 = links
    f2, f3 = list(loads.get(l2, ())), list(loads.get(l3, ()))
    return DyadLoads(l2, l3, f2, f3, resultant(f2, kin.n), resultant(f3, kin.n))


def xy(z: complex) -> list[float]:
    """[x, y] of a plane vector rounded to 1e-9 (no −0): for messages, JSON and doctests.

    >>> xy(complex(-1e-17, 2.5))
    [0.0, 2.5]
    """
    return [round(float(np.real(z)), 9) + 0.0, round(float(np.imag(z)), 9) + 0.0]
