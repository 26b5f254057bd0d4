"""The sine mechanism (Scotch yoke) of the oil pump: an RPP group on the frame's guide, the yoke's
slot drawn through C in position 2, 12 positions, English notation.
"""

from graphmethods.problems.builtin import case
from graphmethods.sheets import kinematics


def build():
    return kinematics.kinematic_scheme(case("scotch-yoke"), notation="en", thick=2)
