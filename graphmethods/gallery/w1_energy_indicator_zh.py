"""W1 (diesel generator, areas only): energy indicator diagram (staircase of excess works), Chinese
notation.
"""

from graphmethods import problems, sheets

PNG = True  # also rendered to PNG for the README


def build():
    return sheets.energy_indicator(problems.w1(), notation="zh")
