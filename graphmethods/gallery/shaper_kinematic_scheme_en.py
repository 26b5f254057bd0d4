"""Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the kinematic scheme in
12 positions to μ_l (position 0 thick, the extreme positions and the stroke H marked), English
notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import kinematics


def build():
    shaper = read_case(files("graphmethods.problems") / "data" / "shaper.json")
    return kinematics.kinematic_scheme(shaper, notation="en")
