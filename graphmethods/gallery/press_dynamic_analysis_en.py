"""The press at 12 positions: the A1 dynamic-analysis sheet (M_d, M_r; ΔT; J_e turned 90°; the
energy–mass diagram with projection lines, rays, k, l, kl; the result table); notation en.
"""

import pathlib

from graphmethods import problems
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import read_case
from graphmethods.sheets.wittenbauer import dynamic_analysis_sheet

PRESS = pathlib.Path(problems.__file__).parent / "data" / "slider_crank_press.json"


def build():
    return dynamic_analysis_sheet(Study(read_case(PRESS), positions=12), page="A1", notation="en")
