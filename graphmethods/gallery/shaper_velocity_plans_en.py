"""Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the velocity plans of
all 12 positions on one sheet to one μ_v, English notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import kinematics


def build():
    shaper = read_case(files("graphmethods.problems") / "data" / "shaper.json")
    return kinematics.velocity_plan_grid(shaper, notation="en")
