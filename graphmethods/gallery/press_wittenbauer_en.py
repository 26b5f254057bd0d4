"""The press at 12 positions: the Wittenbauer energy–mass diagram alone (A4): rays at ψ_max and ψ_min
from the frame to the curve, k, l and kl, and J_F = μ_T·kl/(ω_m²[δ]); notation en.
"""

import pathlib

from graphmethods import problems
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import read_case
from graphmethods.sheets.wittenbauer import wittenbauer_diagram

PNG = True  # also rendered to PNG for the README

PRESS = pathlib.Path(problems.__file__).parent / "data" / "slider_crank_press.json"


def build():
    return wittenbauer_diagram(Study(read_case(PRESS), positions=12), notation="en")
