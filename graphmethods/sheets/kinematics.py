"""The kinematics figures: the scheme in m positions, velocity plans, the table of velocities.

Each function takes a linkage problem and returns a :class:`~graphmethods.scene.Scene` on an
A4 landscape sheet with a frame and a title block (any :class:`~graphmethods.scene.Page` may
be given instead):

- :func:`kinematic_scheme`: the linkage in its m positions on one drawing to μ_l, with the
  textbook symbols (hatched ground under fixed pivots, pin joints, slider blocks on hatched
  guides), one position drawn thick and the others thin, the position numbers 0…m at the
  crank pin and at the output point, the extreme positions marked, the stroke dimensioned.
- :func:`velocity_plan_grid`: the velocity plans of all positions on one sheet, one small
  plan per position to one common μ_v, ill-conditioned positions marked.
- :func:`velocity_plan`: one large plan with its construction lines (⟂ AB through a,
  ∥ guide through p, …), the vectors with arrowheads, a table of their drawn lengths and
  values, and the vector equations.
- :func:`velocity_table` (drawn) and :func:`velocity_table_markdown`: the velocities per
  position.

The linkage may be a problem file read by :func:`graphmethods.kinematics.read_case` (its
velocities are then at the file's mean crank speed), a lazy
:class:`~graphmethods.dynamics.study.Study` (its cached positions and plans are used), a
mechanism (velocities at ``omega_1``, default 1 rad/s: the velocity analogues), its
:class:`~graphmethods.kinematics.Positions` or its
:class:`~graphmethods.kinematics.VelocityPlans`. A figure computes only what it draws: the
scheme never builds a velocity plan. Scales not given are picked (convenient values that
fill the sheet) and every scale drawn is captioned. ``notation="en" | "ru" | "zh"``
switches every word.

>>> from graphmethods.kinematics import SliderCrank
>>> from graphmethods.render.recording import record
>>> mech = SliderCrank(r=0.1, l=0.4, e=0.02, points={"S2": ("AB", 0.13)})
>>> s = velocity_plan(mech, position=2, omega_1=10.0, mu_v=0.02)
>>> round(record(s).vector_length_mm("vector-pa") * 0.02, 9)     # |v_A| = ω₁ r = 1 m/s
1.0
>>> [sc.caption("ru") for sc in kinematic_scheme(mech, notation="ru").scales()]
['μ_l = 0,0025 м/мм']
"""


from graphmethods.sheets.kinematic_scheme import (
    SCHEME_LAYOUT,
    SchemeLayout,
    _crank_numbers,
    _free_side,
    _ground_direction,
    _numbered,
    _output_numbers,
    _Parts,
    _parts,
    _rotation_arrow,
    _scheme_facts,
    _scheme_geometry,
    _scheme_grounds,
    _scheme_joints,
    _scheme_keep_clear,
    _scheme_links,
    _scheme_names,
    _scheme_numbers,
    _scheme_scale,
    _SchemeGeometry,
    _stroke_dimension,
    _tag,
    _thick_dir,
    _translating_yokes,
    kinematic_scheme,
)
from graphmethods.sheets.linkage_figures import (
    _COMPASS,
    _SUB,
    CELL_ILL,
    EXTREME,
    PRIME,
    SMALL_MM,
    TABLE_MM,
    THICK,
    TRAJECTORY,
    _centred_frame,
    _clean_further,
    _crossings,
    _dirs,
    _drawn,
    _end_extreme,
    _Extreme,
    _free_of,
    _image_xy,
    _label_lines,
    _Linkage,
    _num,
    _paper_deg,
    _pick_mu_v,
    _pick_plan_scale,
    _place,
    _plan_labels,
    _plan_layout,
    _plan_markup,
    _plan_vectors,
    _plans_of,
    _PlanVector,
    _pos_label,
    _rel_name,
    _sub,
    _through,
)
from graphmethods.sheets.velocity_plans import (
    PLAN_GRID_LAYOUT,
    VELOCITY_PLAN_LAYOUT,
    PlanGridLayout,
    PlanLayout,
    _equations,
    _fit_plan,
    _Grid,
    _grid_cell,
    _hull_area,
    _line_label,
    _off_scale_values,
    _omega_numbers,
    _omega_texts,
    _plan_grid,
    _plan_split,
    _sense_word,
    _velocity_column,
    _velocity_lines,
    _velocity_texts,
    fullest_position,
    velocity_plan,
    velocity_plan_grid,
)
from graphmethods.sheets.velocity_table import (
    VelocityTable,
    _table_cells,
    velocity_rows,
    velocity_table,
    velocity_table_markdown,
)

__all__ = [
    "CELL_ILL",
    "EXTREME",
    "PLAN_GRID_LAYOUT",
    "PRIME",
    "PlanGridLayout",
    "PlanLayout",
    "SCHEME_LAYOUT",
    "SMALL_MM",
    "SchemeLayout",
    "TABLE_MM",
    "THICK",
    "TRAJECTORY",
    "VELOCITY_PLAN_LAYOUT",
    "VelocityTable",
    "_COMPASS",
    "_Extreme",
    "_Grid",
    "_Linkage",
    "_Parts",
    "_PlanVector",
    "_SUB",
    "_SchemeGeometry",
    "_centred_frame",
    "_clean_further",
    "_crank_numbers",
    "_crossings",
    "_dirs",
    "_drawn",
    "_end_extreme",
    "_equations",
    "_fit_plan",
    "_free_of",
    "_free_side",
    "_grid_cell",
    "_ground_direction",
    "_hull_area",
    "_image_xy",
    "_label_lines",
    "_line_label",
    "_num",
    "_numbered",
    "_off_scale_values",
    "_omega_numbers",
    "_omega_texts",
    "_output_numbers",
    "_paper_deg",
    "_parts",
    "_pick_mu_v",
    "_pick_plan_scale",
    "_place",
    "_plan_grid",
    "_plan_labels",
    "_plan_layout",
    "_plan_markup",
    "_plan_split",
    "_plan_vectors",
    "_plans_of",
    "_pos_label",
    "_rel_name",
    "_rotation_arrow",
    "_scheme_facts",
    "_scheme_geometry",
    "_scheme_grounds",
    "_scheme_joints",
    "_scheme_keep_clear",
    "_scheme_links",
    "_scheme_names",
    "_scheme_numbers",
    "_scheme_scale",
    "_sense_word",
    "_stroke_dimension",
    "_sub",
    "_table_cells",
    "_tag",
    "_thick_dir",
    "_through",
    "_translating_yokes",
    "_velocity_column",
    "_velocity_lines",
    "_velocity_texts",
    "fullest_position",
    "kinematic_scheme",
    "velocity_plan",
    "velocity_plan_grid",
    "velocity_rows",
    "velocity_table",
    "velocity_table_markdown",
]
