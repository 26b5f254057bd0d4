"""W3 (step resisting moment, M_d by work balance): moment diagram M_d, M_r with hatched excess-
work areas, Russian notation.
"""

from graphmethods import problems, sheets


def build():
    return sheets.moment_diagram(problems.w3(), notation="ru")
