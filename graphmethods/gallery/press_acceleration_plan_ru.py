"""Offset slider-crank press (problems/data/slider_crank_press.json): one large acceleration plan with
its construction lines, the equations under it, the table of vector lengths and ε of the links,
Russian notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import acceleration


def build():
    case = read_case(files("graphmethods.problems") / "data" / "slider_crank_press.json")
    return acceleration.acceleration_plan(case, notation="ru")
