"""W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): moment diagram M_d, M_r with hatched excess-
work areas, English notation.
"""

from graphmethods import problems, sheets


def build():
    return sheets.moment_diagram(problems.w4_exact(), notation="en", moment_unit="kG·m", work_unit="kG·m")
