"""The press: reduced moments M_d (constant, by work balance) and M_r through the 12 positions, as
the graphical method draws them, English notation.
"""

import pathlib

from graphmethods import problems
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import read_case
from graphmethods.sheets.dynamics import moment_graph

PRESS = pathlib.Path(problems.__file__).parent / "data" / "slider_crank_press.json"


def build():
    return moment_graph(Study(read_case(PRESS), positions=12), notation="en")
