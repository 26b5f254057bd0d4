"""Offset slider-crank press (problems/data/slider_crank_press.json): the table of velocities per
position, Chinese notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import kinematics


def build():
    press = read_case(files("graphmethods.problems") / "data" / "slider_crank_press.json")
    return kinematics.velocity_table(press, notation="zh")
