"""The triad-six-bar split into its driver and its Assur groups, the structural formula and W (the
structure diagram of the structural-analysis chapter); notation en."""

from graphmethods.problems import builtin
from graphmethods.sheets.structure_diagram import structure_diagram

PNG = True  # also rendered to PNG for the README


def build():
    return structure_diagram(builtin.case("triad-six-bar"), notation="en")
