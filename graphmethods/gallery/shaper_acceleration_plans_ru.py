"""Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the acceleration plans
of all positions to one μ_a, Russian notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import acceleration


def build():
    case = read_case(files("graphmethods.problems") / "data" / "shaper.json")
    return acceleration.acceleration_plan_grid(case, notation="ru")
