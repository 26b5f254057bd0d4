"""Offset slider-crank press (problems/data/slider_crank_press.json): one large velocity plan with its
construction lines, the table of vector lengths and the angular velocities, English notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import kinematics


def build():
    press = read_case(files("graphmethods.problems") / "data" / "slider_crank_press.json")
    return kinematics.velocity_plan(press, notation="en")
