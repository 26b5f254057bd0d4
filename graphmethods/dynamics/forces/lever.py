"""Two checks of the balancing moment: Zhukovsky's lever and the power balance.

Zhukovsky's lever: the velocity plan turned 90° (here counterclockwise) is a rigid lever pivoted
at the pole p; every force is applied at the image of its point, a couple M on a link as two
equal and opposite forces at two points of that link, and the balancing moment as a force F_b
at the crank pin ⟂ O–A. The moments about p sum to zero, which gives F_b and M_b = F_b·l_OA.

The power balance: ``M_b·ω₁ + Σ F·v + Σ M·ω = 0`` over every force (inertia included).

>>> import numpy as np
>>> from graphmethods.dynamics.forces.base import Force
>>> # a crank O–A (0.1 m) at 10 rad/s ccw, 100 N at A along −y in position φ = 0
>>> pts = {"1": (np.array([0j]), np.array([10.0]), np.array([0j]), np.array([0.1 + 0j]))}
>>> f = Force("F", F=np.array([-100j]), at=np.array([0.1 + 0j]), M=np.zeros(1))
>>> lev = zhukovsky(pts, {"1": [f]}, centre=np.array([0j]), pin=np.array([0.1 + 0j]), omega_1=10.0, sense=1)
>>> round(float(lev.M_balance[0]), 9), round(float(power_balance(pts, {"1": [f]}, omega_1=10.0, sense=1)[0]), 9)
(10.0, 10.0)
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from graphmethods.dynamics.forces.base import Force
from graphmethods.dynamics.forces.statics import Cx, Fl, cross

#: link -> (a point O of it, its ω, v_O, and d: from O to a second point of the link), each (n,)
Rigid = Mapping[str, tuple[Cx, Fl, Cx, Cx]]


def _velocity(rigid: Rigid, link: str, z: Cx) -> Cx:
    O, w, vO, _ = rigid[link]
    out: Cx = vO + 1j * w * (z - O)
    return out


@dataclass(frozen=True, eq=False)
class LeverForce:
    """One force on the lever: its label, link, the image of its point (m per rad/s of the crank:
    v/ω₁ turned 90°; divide by μ_v·... for the drawing), the force (N) and its moment about p (N·m)."""

    label: str
    link: str
    image: Cx
    F: Cx
    moment: Fl


@dataclass(frozen=True, eq=False)
class Lever:
    """Zhukovsky's lever over the positions.

    Attributes
    ----------
    forces : tuple of LeverForce
        Every force (couples already replaced by pairs of forces) with its moment about p.
    image_pin : complex ndarray (n,)
        Image of the crank pin, where the balancing force acts.
    F_balance : complex ndarray (n,)
        The balancing force at the crank pin ⟂ O–A, N.
    M_balance : ndarray (n,)
        The balancing moment on the crank, N·m, counterclockwise +.
    """

    forces: tuple[LeverForce, ...]
    image_pin: Cx
    F_balance: Cx
    M_balance: Fl


def zhukovsky(rigid: Rigid, loads: Mapping[str, Sequence[Force]], *, centre: Cx, pin: Cx, omega_1: float,
              sense: int) -> Lever:
    """The balancing moment from Zhukovsky's lever (see the module docstring).

    Parameters
    ----------
    rigid : mapping link -> (O, ω, v_O, d)
        A point of each link with its velocity (m, m/s), the link's ω (rad/s), and d (m) from O to
        a second point of the link (where a couple's second force goes), (n,) each.
    loads : mapping link -> forces
        Every force and couple on the moving links (not the reactions), N, N·m.
    centre, pin : complex ndarray (n,)
        The crank's centre and pin, m.
    omega_1 : float
        Crank speed, rad/s (> 0); ``sense`` +1 counterclockwise, −1 clockwise.
    """
    items = []
    total: Fl = np.zeros(np.shape(pin), dtype=float)
    for link, forces in loads.items():
        O, _, _, d = rigid[link]
        for f in forces:
            pairs: list[tuple[str, Cx, Cx]] = []
            if np.any(f.F != 0):
                pairs.append((f.label, f.at, f.F))
            if np.any(f.M != 0):
                # the couple as F at O + d and −F at O with d × F = M (F ⟂ d, |F| = |M|/|d|)
                F = f.M * 1j * d / np.abs(d) ** 2
                name = "M" + f.label[1:] if f.label.startswith("F") else f.label
                pairs += [(name, O + d, F), (name, O + 0 * d, -F)]
            for label, at, F in pairs:
                img = 1j * _velocity(rigid, link, at) / omega_1
                mom = cross(img, F)
                items.append(LeverForce(label, link, img, F, mom))
                total = total + mom
    img_A = 1j * (1j * sense * omega_1 * (pin - centre)) / omega_1
    r = np.abs(pin - centre)
    nb = 1j * (pin - centre) / r
    t = -total / cross(img_A, nb)
    F_b: Cx = t * nb
    return Lever(tuple(items), img_A, F_b, cross(pin - centre, F_b))


def power_balance(rigid: Rigid, loads: Mapping[str, Sequence[Force]], *, omega_1: float, sense: int) -> Fl:
    """M_b from ``M_b·ω₁ + Σ F·v + Σ M·ω = 0``, N·m (counterclockwise +; ω₁ signed by ``sense``)."""
    first = next(iter(rigid.values()))[0]
    P: Fl = np.zeros(np.shape(first), dtype=float)
    for link, forces in loads.items():
        _, w, _, _ = rigid[link]
        for f in forces:
            v = _velocity(rigid, link, f.at)
            p = np.real(np.conj(v) * f.F) + f.M * w
            P = P + p
    out: Fl = -P / (sense * omega_1)
    return out
