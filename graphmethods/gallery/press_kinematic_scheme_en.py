"""Offset slider-crank press (problems/data/slider_crank_press.json): the kinematic scheme in 12
positions to μ_l (position 0 thick, the extreme positions and the stroke H marked), English
notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import kinematics

PNG = True  # also rendered to PNG for the README


def build():
    press = read_case(files("graphmethods.problems") / "data" / "slider_crank_press.json")
    return kinematics.kinematic_scheme(press, notation="en")
