"""The press problem: Zhukovsky's lever with every force of the force analysis in position 3 (inertia
forces, moments as pairs of forces, the load) and the balancing force at the image of the crank pin."""

from graphmethods.problems import builtin
from graphmethods.sheets.forces import zhukovsky_forces


def build():
    return zhukovsky_forces(builtin.case("press"), position=3, notation="en")
