"""W3 (step resisting moment, M_d by work balance): energy graph ΔE(φ), Chinese notation."""

from graphmethods import problems, sheets


def build():
    return sheets.energy_graph(problems.w3(), notation="zh")
