"""The force (kinetostatic) analysis of any linkage: inertia loads, reactions group by group, the
balancing moment, checked by Zhukovsky's lever and the power balance (domain.md §8a).

One solver per dyad type (:mod:`.rrr`, :mod:`.rrp`, :mod:`.rpr`, :mod:`.prp`, :mod:`.rpp`), the
driver :func:`kinetostatics` (:mod:`.analysis`), the checks (:mod:`.lever`), and problem files
(:func:`case_forces`, :mod:`.problem`).
"""

from graphmethods.dynamics.forces.analysis import G_STANDARD, SOLVERS, ForceAnalysis, Inertia, Mass, kinetostatics
from graphmethods.dynamics.forces.base import Force, ForcePlan, Polygon, Reaction
from graphmethods.dynamics.forces.lever import Lever, power_balance, zhukovsky
from graphmethods.dynamics.forces.problem import case_forces, working_load

__all__ = ["G_STANDARD", "SOLVERS", "Force", "ForceAnalysis", "ForcePlan", "Inertia", "Lever", "Mass", "Polygon",
           "Reaction", "case_forces", "kinetostatics", "power_balance", "working_load", "zhukovsky"]
