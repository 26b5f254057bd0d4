"""W2 (engine crankshaft, points a…h): excess-work table, Russian notation."""

from graphmethods import problems, sheets


def build():
    return sheets.excess_work_table(problems.w2(), notation="ru")
