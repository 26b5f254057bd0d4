"""The single-cylinder engine: the gas moment from the indicator diagram (M_d, a curve) against the
generator's constant M_r, ΔE and ω of the exact steady cycle on one φ axis, Chinese notation.
"""

from graphmethods.dynamics.study import Study
from graphmethods.problems.builtin import case
from graphmethods.sheets.cycle_panels import linkage_panels

PNG = True  # also rendered to PNG for the README


def build():
    return linkage_panels(Study(case("engine")), notation="zh")
