"""The press: the A1 force-analysis sheet of position 3 (the course project's second sheet:
the scheme with every force, Zhukovsky's lever, the force plan of each group with each link's own polygon,
the result table of the balancing moment three ways); notation zh."""

from graphmethods.problems import builtin
from graphmethods.sheets.force_analysis_sheet import force_analysis_sheet


def build():
    return force_analysis_sheet(builtin.case("press"), position=3, page="A1", notation="zh")
