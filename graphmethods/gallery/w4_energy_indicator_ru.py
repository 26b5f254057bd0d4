"""W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): energy indicator diagram (staircase of
excess works), Russian notation.
"""

from graphmethods import problems, sheets


def build():
    return sheets.energy_indicator(problems.w4_exact(), notation="ru", work_unit="kG·m")
