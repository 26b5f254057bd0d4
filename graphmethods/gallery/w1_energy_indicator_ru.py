"""W1 (diesel generator, areas only): energy indicator diagram (staircase of excess works), Russian
notation.
"""

from graphmethods import problems, sheets


def build():
    return sheets.energy_indicator(problems.w1(), notation="ru")
