"""graphmethods.sheets: whole textbook figures, one function per figure, problem -> Scene.

- excess work (:mod:`~graphmethods.sheets.energy`): :func:`moment_diagram`, :func:`excess_work_table`,
  :func:`energy_indicator`, :func:`energy_graph`;
- linkages (:mod:`~graphmethods.sheets.kinematics`): :func:`kinematic_scheme`, :func:`velocity_plan_grid`,
  :func:`velocity_plan`, :func:`velocity_table`;
- accelerations (:mod:`~graphmethods.sheets.acceleration`): :func:`acceleration_plan`,
  :func:`acceleration_plan_grid`, :func:`acceleration_table`;
- the reduced model (:mod:`~graphmethods.sheets.dynamics`): :func:`inertia_graph`, :func:`moment_graph`,
  :func:`delta_T_graph`, :func:`speed_graph`, :func:`acceleration_graph`, :func:`zhukovsky_lever`;
- the flywheel (:mod:`~graphmethods.sheets.wittenbauer`): :func:`wittenbauer_diagram`,
  :func:`dynamic_analysis_sheet`;
- graphical calculus (:mod:`~graphmethods.sheets.calculus`): :func:`kinematic_diagrams`, :func:`work_diagrams`;
- the course project's A1 sheets: :func:`kinematic_analysis_sheet` (the first,
  :mod:`~graphmethods.sheets.kinematic_analysis_sheet`) and :func:`force_analysis_sheet` (the second,
  :mod:`~graphmethods.sheets.force_analysis_sheet`); the cam sheet :func:`cam_sheet`
  (:mod:`~graphmethods.sheets.cam_sheet`).

Every function takes keyword scales (picked and captioned when not given) and ``notation="en"|"ru"|"zh"``.

>>> from graphmethods import problems, sheets
>>> from graphmethods.render import svg
>>> scene = sheets.energy_indicator(problems.w1(), notation="ru")
>>> svg.to_string(scene).count('width="297mm"')
1
"""

from graphmethods.sheets.acceleration import acceleration_plan, acceleration_plan_grid, acceleration_table
from graphmethods.sheets.calculus import kinematic_diagrams, work_diagrams
from graphmethods.sheets.cam_sheet import cam_sheet
from graphmethods.sheets.dynamics import (
                                          acceleration_graph,
                                          delta_T_graph,
                                          inertia_graph,
                                          moment_graph,
                                          speed_graph,
                                          zhukovsky_lever,
)
from graphmethods.sheets.energy import energy_graph, energy_indicator, excess_work_table, moment_diagram
from graphmethods.sheets.force_analysis_sheet import force_analysis_sheet
from graphmethods.sheets.kinematic_analysis_sheet import kinematic_analysis_sheet
from graphmethods.sheets.kinematic_scheme import kinematic_scheme
from graphmethods.sheets.velocity_plans import velocity_plan, velocity_plan_grid
from graphmethods.sheets.velocity_table import velocity_table
from graphmethods.sheets.wittenbauer import dynamic_analysis_sheet, wittenbauer_diagram

__all__ = [
    "acceleration_graph", "acceleration_plan", "acceleration_plan_grid", "acceleration_table", "cam_sheet",
    "delta_T_graph",
    "dynamic_analysis_sheet", "energy_graph", "energy_indicator",
    "excess_work_table", "force_analysis_sheet", "inertia_graph", "kinematic_analysis_sheet",
    "kinematic_diagrams", "kinematic_scheme", "moment_diagram",
    "moment_graph", "speed_graph", "velocity_plan", "velocity_plan_grid", "velocity_table", "wittenbauer_diagram",
    "work_diagrams", "zhukovsky_lever",
]
