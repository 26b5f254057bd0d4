"""The dynamics of the equivalent link: excess work, energy, flywheel (numpy only).

Modules: ``moments`` (moment curves), ``excess_work`` (intervals, areas, ΔW_max),
``flywheel`` (approximate method, transfer, sizing), ``kinetic_energy`` (T and ω for a
constant J_e).
"""

from graphmethods.dynamics import excess_work, flywheel, kinetic_energy, moments
from graphmethods.dynamics.moments import MomentCurve

__all__ = ["MomentCurve", "excess_work", "flywheel", "kinetic_energy", "moments"]
