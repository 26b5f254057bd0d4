"""Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the table of velocities
per position, English notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import kinematics


def build():
    shaper = read_case(files("graphmethods.problems") / "data" / "shaper.json")
    return kinematics.velocity_table(shaper, notation="en")
