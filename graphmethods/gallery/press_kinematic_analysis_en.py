"""The press: the A1 kinematic-analysis sheet (the course project's first sheet: the scheme
in 12 positions, the velocity plans, the acceleration plans of a working-stroke and a return-stroke
position, the slider's kinematic diagrams when there is a slider); notation en."""

from graphmethods.problems import builtin
from graphmethods.sheets.kinematic_analysis_sheet import kinematic_analysis_sheet


def build():
    return kinematic_analysis_sheet(builtin.case("press"), page="A1", notation="en")
