"""The press: J_e(φ) turned 90° (φ down the page, J_e to the right from 0), ready to project J_e
values onto the energy–mass diagram, English notation.
"""

import pathlib

from graphmethods import problems
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import read_case
from graphmethods.sheets.dynamics import inertia_graph

PRESS = pathlib.Path(problems.__file__).parent / "data" / "slider_crank_press.json"


def build():
    return inertia_graph(Study(read_case(PRESS), positions=12), turned=True, notation="en")
