"""W1 (diesel generator, areas only): excess-work table, English notation."""

from graphmethods import problems, sheets


def build():
    return sheets.excess_work_table(problems.w1(), notation="en")
