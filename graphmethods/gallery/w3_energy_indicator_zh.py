"""W3 (step resisting moment, M_d by work balance): energy indicator diagram (staircase of excess
works), Chinese notation.
"""

from graphmethods import problems, sheets


def build():
    return sheets.energy_indicator(problems.w3(), notation="zh")
