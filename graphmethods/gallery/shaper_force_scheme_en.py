"""The shaper problem in position 2 with every force on it: inertia forces and moments, weights, the
working load, and the balancing moment on the crank."""

from graphmethods.problems import builtin
from graphmethods.sheets.forces import force_scheme


def build():
    return force_scheme(builtin.case("shaper"), position=2, gravity=True, notation="en")
