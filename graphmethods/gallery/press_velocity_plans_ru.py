"""Offset slider-crank press (problems/data/slider_crank_press.json): the velocity plans of all 12
positions on one sheet to one μ_v, Russian notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import kinematics


def build():
    press = read_case(files("graphmethods.problems") / "data" / "slider_crank_press.json")
    return kinematics.velocity_plan_grid(press, notation="ru")
