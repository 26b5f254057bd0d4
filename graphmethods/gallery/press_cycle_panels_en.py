"""The press: M_d and M_r, ΔE and ω of the exact steady cycle (exact flywheel for [δ] = 0.04) one
above the other on one φ axis, the Chinese chapter's three-panel figure, English notation.
"""

from graphmethods.dynamics.study import Study
from graphmethods.problems.builtin import case
from graphmethods.sheets.cycle_panels import linkage_panels


def build():
    return linkage_panels(Study(case("press")), notation="en")
