"""The press: crank speed ω(φ) of the exact steady motion with the exact flywheel for [δ] = 0.04;
ω_m, ω_max and ω_min marked, English notation.
"""

import pathlib

from graphmethods import problems
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import read_case
from graphmethods.sheets.dynamics import speed_graph

PNG = True  # also rendered to PNG for the README

PRESS = pathlib.Path(problems.__file__).parent / "data" / "slider_crank_press.json"


def build():
    return speed_graph(Study(read_case(PRESS), positions=12), notation="en")
