"""The press: crank angular acceleration ε(φ) of the exact motion (it jumps where the force
switches), the largest |ε| and Artobolevsky's χ, English notation.
"""

import pathlib

from graphmethods import problems
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import read_case
from graphmethods.sheets.dynamics import acceleration_graph

PRESS = pathlib.Path(problems.__file__).parent / "data" / "slider_crank_press.json"


def build():
    return acceleration_graph(Study(read_case(PRESS), positions=12), notation="en")
