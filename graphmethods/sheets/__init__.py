"""graphmethods.sheets: whole textbook figures, one function per figure, problem -> Scene.

The excess-work figures (:mod:`graphmethods.sheets.energy`): :func:`moment_diagram`,
:func:`excess_work_table`, :func:`energy_indicator`, :func:`energy_graph`.

>>> from graphmethods import problems, sheets
>>> from graphmethods.render import svg
>>> scene = sheets.energy_indicator(problems.w1(), notation="ru")
>>> svg.to_string(scene).count('width="297mm"')
1
"""

from graphmethods.sheets.energy import energy_graph, energy_indicator, excess_work_table, moment_diagram

__all__ = ["energy_graph", "energy_indicator", "excess_work_table", "moment_diagram"]
