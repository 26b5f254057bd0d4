"""Offset slider-crank press (problems/data/slider_crank_press.json): the acceleration plans of all
positions to one μ_a, Russian notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import acceleration


def build():
    case = read_case(files("graphmethods.problems") / "data" / "slider_crank_press.json")
    return acceleration.acceleration_plan_grid(case, notation="ru")
