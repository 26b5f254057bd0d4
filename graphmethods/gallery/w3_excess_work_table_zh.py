"""W3 (step resisting moment, M_d by work balance): excess-work table, Chinese notation."""

from graphmethods import problems, sheets


def build():
    return sheets.excess_work_table(problems.w3(), notation="zh")
