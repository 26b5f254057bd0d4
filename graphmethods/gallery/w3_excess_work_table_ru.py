"""W3 (step resisting moment, M_d by work balance): excess-work table, Russian notation."""

from graphmethods import problems, sheets


def build():
    return sheets.excess_work_table(problems.w3(), notation="ru")
