"""The single-cylinder engine: the gas moment from the indicator diagram as the driving moment M_d
(chords through 12 positions, negative on the compression stroke) against the generator's constant
resisting moment M_r from the work balance, English notation.
"""

from graphmethods.dynamics.study import Study
from graphmethods.problems.builtin import case
from graphmethods.sheets.dynamics import moment_graph

PNG = True  # also rendered to PNG for the README


def build():
    return moment_graph(Study(case("engine"), positions=12), notation="en")
