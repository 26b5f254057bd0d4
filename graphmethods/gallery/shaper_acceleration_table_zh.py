"""Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the accelerations of the
points and links per position, Chinese notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import acceleration


def build():
    case = read_case(files("graphmethods.problems") / "data" / "shaper.json")
    return acceleration.acceleration_table(case, notation="zh")
