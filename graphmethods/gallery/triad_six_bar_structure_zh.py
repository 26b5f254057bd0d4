"""The triad-six-bar split into its driver and its Assur groups, the structural formula and W (the
structure diagram of the structural-analysis chapter); notation zh."""

from graphmethods.problems import builtin
from graphmethods.sheets.structure_diagram import structure_diagram


def build():
    return structure_diagram(builtin.case("triad-six-bar"), notation="zh")
