"""graphmethods.sheets: whole textbook figures, one function per figure, problem -> Scene.

- excess work (:mod:`~graphmethods.sheets.energy`): :func:`moment_diagram`, :func:`excess_work_table`,
  :func:`energy_indicator`; the kinetic-energy graph :func:`energy_graph` (:mod:`~graphmethods.sheets.energy_graph`);
- linkages (:mod:`~graphmethods.sheets.kinematics`): :func:`kinematic_scheme`, :func:`velocity_plan_grid`,
  :func:`velocity_plan`, :func:`velocity_table`;
- accelerations (:mod:`~graphmethods.sheets.acceleration`): :func:`acceleration_plan`,
  :func:`acceleration_plan_grid`, :func:`acceleration_table`;
- the reduced model (:mod:`~graphmethods.sheets.dynamics`): :func:`inertia_graph`, :func:`moment_graph`,
  :func:`delta_T_graph`; :func:`speed_graph`, :func:`acceleration_graph`
  (:mod:`~graphmethods.sheets.speed_graphs`); :func:`zhukovsky_lever` (:mod:`~graphmethods.sheets.zhukovsky_lever`);
- the flywheel (:mod:`~graphmethods.sheets.wittenbauer`): :func:`wittenbauer_diagram`,
  :func:`dynamic_analysis_sheet`;
- graphical calculus (:mod:`~graphmethods.sheets.calculus`): :func:`kinematic_diagrams`; :func:`work_diagrams`
  (:mod:`~graphmethods.sheets.work_diagrams`);
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

The functions are imported when first asked for (a module ``__getattr__``): ``import graphmethods.sheets``
loads none of the sheet modules, so a command that draws one figure pays for that figure's modules only.
A function named as its module (``cam_sheet``, ``kinematic_analysis_sheet``, ...) stays the function when
the module is imported later (as it was when the package imported every module up front).
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
import types
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:                      # the names for mypy and the reader; at run time they load when asked
    from graphmethods.sheets.acceleration import acceleration_plan, acceleration_plan_grid, acceleration_table
    from graphmethods.sheets.calculus import kinematic_diagrams
    from graphmethods.sheets.cam_sheet import cam_sheet
    from graphmethods.sheets.dynamic_analysis_sheet import dynamic_analysis_sheet
    from graphmethods.sheets.dynamics import delta_T_graph, inertia_graph, moment_graph
    from graphmethods.sheets.energy import energy_indicator, excess_work_table, moment_diagram
    from graphmethods.sheets.energy_graph import energy_graph
    from graphmethods.sheets.force_analysis_sheet import force_analysis_sheet
    from graphmethods.sheets.kinematic_analysis_sheet import kinematic_analysis_sheet
    from graphmethods.sheets.kinematic_scheme import kinematic_scheme
    from graphmethods.sheets.speed_graphs import acceleration_graph, speed_graph
    from graphmethods.sheets.velocity_plans import velocity_plan, velocity_plan_grid
    from graphmethods.sheets.velocity_table import velocity_table
    from graphmethods.sheets.wittenbauer import wittenbauer_diagram
    from graphmethods.sheets.work_diagrams import work_diagrams
    from graphmethods.sheets.zhukovsky_lever import zhukovsky_lever

#: each public function's module (under this package)
_HOME = {
    "acceleration_plan": "acceleration", "acceleration_plan_grid": "acceleration",
    "acceleration_table": "acceleration", "kinematic_diagrams": "calculus", "work_diagrams": "work_diagrams",
    "cam_sheet": "cam_sheet", "acceleration_graph": "speed_graphs", "delta_T_graph": "dynamics",
    "inertia_graph": "dynamics", "moment_graph": "dynamics", "speed_graph": "speed_graphs",
    "zhukovsky_lever": "zhukovsky_lever", "energy_graph": "energy_graph", "energy_indicator": "energy",
    "excess_work_table": "energy", "moment_diagram": "energy", "force_analysis_sheet": "force_analysis_sheet",
    "kinematic_analysis_sheet": "kinematic_analysis_sheet", "kinematic_scheme": "kinematic_scheme",
    "velocity_plan": "velocity_plans", "velocity_plan_grid": "velocity_plans", "velocity_table": "velocity_table",
    "dynamic_analysis_sheet": "dynamic_analysis_sheet", "wittenbauer_diagram": "wittenbauer",
}


def __getattr__(name: str) -> Any:
    """A public function, imported from its module the first time it is asked for (a submodule's name: the
    submodule, as when the package imported them all)."""
    home = _HOME.get(name)
    if home is None:
        if name.startswith("_") or importlib.util.find_spec(f"{__name__}.{name}") is None:
            raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
        return importlib.import_module(f"{__name__}.{name}")
    value = getattr(importlib.import_module(f"{__name__}.{home}"), name)
    types.ModuleType.__setattr__(_package, name, value)
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_HOME))


class _Sheets(types.ModuleType):
    """The package's module type: importing a submodule named as a public function (``cam_sheet``) leaves
    the package's attribute the function (the import system would bind the submodule there)."""

    def __setattr__(self, name: str, value: Any) -> None:
        if name in _HOME and isinstance(value, types.ModuleType):
            home = self.__dict__.get(name)
            if home is None or isinstance(home, types.ModuleType):     # not asked for yet: forgotten, asked anew
                self.__dict__.pop(name, None)
            return
        super().__setattr__(name, value)


_package = sys.modules[__name__]
_package.__class__ = _Sheets

__all__ = [
    "acceleration_graph", "acceleration_plan", "acceleration_plan_grid", "acceleration_table", "cam_sheet",
    "delta_T_graph",
    "dynamic_analysis_sheet", "energy_graph", "energy_indicator",
    "excess_work_table", "force_analysis_sheet", "inertia_graph", "kinematic_analysis_sheet",
    "kinematic_diagrams", "kinematic_scheme", "moment_diagram",
    "moment_graph", "speed_graph", "velocity_plan", "velocity_plan_grid", "velocity_table", "wittenbauer_diagram",
    "work_diagrams", "zhukovsky_lever",
]
