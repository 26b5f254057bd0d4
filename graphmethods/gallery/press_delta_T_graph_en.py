"""The press: increment of kinetic energy ΔT(φ) of the drawn moments, its extremes marked, English
notation.
"""

import pathlib

from graphmethods import problems
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import read_case
from graphmethods.sheets.dynamics import delta_T_graph

PRESS = pathlib.Path(problems.__file__).parent / "data" / "slider_crank_press.json"


def build():
    return delta_T_graph(Study(read_case(PRESS), positions=12), notation="en")
