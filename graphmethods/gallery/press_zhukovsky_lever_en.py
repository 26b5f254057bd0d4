"""The press: Zhukovsky's lever at the clearest loaded position: the velocity plan turned 90°, the
cutting force at the image b, its arm h; M_r = F·h·μ_v/ω₁ equals the power method's, English notation.
"""

import pathlib

from graphmethods import problems
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import read_case
from graphmethods.sheets.dynamics import zhukovsky_lever

PRESS = pathlib.Path(problems.__file__).parent / "data" / "slider_crank_press.json"


def build():
    return zhukovsky_lever(Study(read_case(PRESS), positions=12), notation="en")
