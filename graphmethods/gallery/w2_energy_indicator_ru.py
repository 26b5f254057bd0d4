"""W2 (engine crankshaft, points a…h): energy indicator diagram (staircase of excess works),
Russian notation.
"""

from graphmethods import problems, sheets


def build():
    return sheets.energy_indicator(problems.w2(), notation="ru")
