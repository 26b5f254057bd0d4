"""Linkages in m positions and their velocity plans (numpy only; SI floats in, frozen results out).

The core: any linkage of class II as a :class:`Linkage` (fixed joints, a :class:`Crank`, Assur
groups from :mod:`graphmethods.kinematics.groups` in solving order, extra :class:`Point` s) with
positions, velocities and accelerations (:meth:`Linkage.motion`), its structure and its
strokes; :mod:`graphmethods.kinematics.presets` builds the textbook ones, and
:class:`LinkageMechanism` gives any of them the interface below.

The four classic kinds of the problem files are presets on the core
(:mod:`graphmethods.kinematics.classic`, dimensions in m, keyword-only): :class:`SliderCrank`,
:class:`FourBar`, :class:`SlottedLever`, :class:`Shaper`. Each, like any
:class:`LinkageMechanism`, gives ``positions(m=12)`` (or ``positions(phi=...)``) ->
:class:`Positions` and ``velocity_plans(positions, omega_1=1.0)`` -> :class:`VelocityPlans`,
vectorised over all positions at once; ``derivatives(phi)`` is the derivative of the position
equations, ``motion(...)`` adds accelerations. Problem files are read by :func:`read_case`.

>>> from graphmethods.kinematics import SliderCrank
>>> mech = SliderCrank(r=0.1, l=0.4, e=0.02, points={"S2": ("AB", 0.13, 0.0)})
>>> plan = mech.velocity_plans(mech.positions(m=12), omega_1=1.0)
>>> plan.v("B").shape, plan.omega("AB").shape
((13, 2), (13,))
"""

from graphmethods.kinematics.case import (
                                          Case,
                                          FourBarCase,
                                          Inertia,
                                          Load,
                                          ShaperCase,
                                          SliderCrankCase,
                                          SlottedLeverCase,
                                          case_from_dict,
                                          read_case,
)
from graphmethods.kinematics.classic import FourBar, Shaper, SliderCrank, SlottedLever
from graphmethods.kinematics.linkage import Crank, Linkage, Motion, Point, Structure
from graphmethods.kinematics.linkage_mechanism import LinkageMechanism
from graphmethods.kinematics.mechanism import Mechanism, PointOnLink
from graphmethods.kinematics.plans import ConstructionLine, PointConstruction, VelocityPlans, convenient_scale
from graphmethods.kinematics.positions import Positions, Strokes

__all__ = [
    "Crank", "Linkage", "LinkageMechanism", "Motion", "Point", "Structure",
    "Case", "ConstructionLine", "FourBar", "FourBarCase", "Inertia", "Load", "Mechanism", "PointConstruction",
    "PointOnLink", "Positions", "Shaper", "ShaperCase", "SliderCrank", "SliderCrankCase", "SlottedLever",
    "SlottedLeverCase", "Strokes", "VelocityPlans", "case_from_dict", "convenient_scale", "read_case",
]
