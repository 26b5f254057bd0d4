"""The press (offset slider-crank, 12 positions): reduced moment of inertia J_e(φ) and the share
of each moving mass, English notation.
"""

import pathlib

from graphmethods import problems
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import read_case
from graphmethods.sheets.dynamics import inertia_graph

PRESS = pathlib.Path(problems.__file__).parent / "data" / "slider_crank_press.json"


def build():
    return inertia_graph(Study(read_case(PRESS), positions=12), notation="en")
