"""The six-bar triad's plans on a slide: the velocity plan's table fitted as drawn at the slide's lettering (it ran
into the legend), the force plans fitted to each link's own polygon (R_32 ran across the results column)."""

from graphmethods.problems import builtin
from graphmethods.sheets.projector import SLIDE_PAGE


def test_a_slide_lettered_velocity_table_ends_above_the_legend():
    from graphmethods.sheets import steps
    from graphmethods.sheets.projector import crossed_labels

    fig = steps.build("triad-six-bar", "velocity-plan", notation="en").figure
    assert crossed_labels(fig) == ()          # was: the legend crossed and under p s5, 39.85, v_S5 = 0.159


def test_force_plans_hold_each_links_own_polygon_inside_the_plans_column():
    from graphmethods.scene import Vector
    from graphmethods.sheets.forces import force_plans

    s = force_plans(builtin.case("triad-six-bar"), 2, notation="en", page=SLIDE_PAGE, title_block=False)
    column = next(e for e in s.elements if e.name == "table").at[0]
    xs = [x for e in s.elements if isinstance(e, Vector) for x in (e.start[0], e.end[0])]
    assert xs and max(xs) < column
