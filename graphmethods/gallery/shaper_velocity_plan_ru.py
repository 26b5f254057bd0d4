"""Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): one large velocity plan
with its construction lines, the table of vector lengths and the angular velocities, Russian
notation.
"""

from importlib.resources import files

from graphmethods.kinematics import read_case
from graphmethods.sheets import kinematics

PNG = True  # also rendered to PNG for the README


def build():
    shaper = read_case(files("graphmethods.problems") / "data" / "shaper.json")
    return kinematics.velocity_plan(shaper, notation="ru")
