"""The single-cylinder engine's dynamic-analysis sheet (A2): M_d (gas) and M_r, ΔT, J_e turned 90°,
the energy–mass diagram and the flywheel from kl, Russian notation.
"""

from graphmethods.dynamics.study import Study
from graphmethods.problems.builtin import case
from graphmethods.sheets.wittenbauer import dynamic_analysis_sheet


def build():
    return dynamic_analysis_sheet(Study(case("engine"), positions=12), page="A2", notation="ru")
