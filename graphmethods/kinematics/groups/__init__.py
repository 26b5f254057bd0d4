"""Assur groups of class II (dyads) and III (triads), one module each; a new dyad type is one more module.

=====  ==========================================================  ===========================
group  what it is                                                  module
=====  ==========================================================  ===========================
RRR    two links pinned together, outer ends on known points       :mod:`.rrr`
RRP    a rod and a slider on a guide (and its mirror PRR)          :mod:`.rrp`
RPR    a block on a turning slotted link (slotted lever)           :mod:`.rpr`
PRP    two sliders pinned together, each on its own guide          :mod:`.prp`
RPP    a block in the slot of a sliding yoke (Scotch yoke)         :mod:`.rpp`
triad  class III: a ternary link held by three binary links        :mod:`.triad`
=====  ==========================================================  ===========================

Each group solves, vectorised over all positions, its positions, velocities and
accelerations, and gives the construction records of its velocity and acceleration plans.
"""

from graphmethods.kinematics.groups.base import GROUND, Group, Guide, Record, State
from graphmethods.kinematics.groups.prp import PRP
from graphmethods.kinematics.groups.rpp import RPP
from graphmethods.kinematics.groups.rpr import RPR
from graphmethods.kinematics.groups.rrp import RRP
from graphmethods.kinematics.groups.rrr import RRR
from graphmethods.kinematics.groups.triad import Triad

#: group kind -> class (what a problem file's "type" selects)
KINDS = {"RRR": RRR, "RRP": RRP, "PRR": RRP, "RPR": RPR, "PRP": PRP, "RPP": RPP, "triad": Triad}

__all__ = ["GROUND", "Group", "Guide", "KINDS", "PRP", "RPP", "RPR", "RRP", "RRR", "Record", "State", "Triad"]
