"""W1 (diesel generator, areas only): energy indicator diagram (staircase of excess works), English
notation.
"""

from graphmethods import problems, sheets


def build():
    return sheets.energy_indicator(problems.w1(), notation="en")
