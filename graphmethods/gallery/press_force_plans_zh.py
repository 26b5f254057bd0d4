"""The press problem: the force plans of every group and of the crank in position 3, at one μ_F,
with every reaction and the balancing moment three ways (force plans, Zhukovsky's lever, power)."""

from graphmethods.problems import builtin
from graphmethods.sheets.forces import force_plans


def build():
    return force_plans(builtin.case("press"), position=3, notation="zh")
