"""The kinematic scheme's bodies and labels (issue 26, lane kscheme): ternary links as plates, a point of a
link joined to it, a swinging driver's arc, labels clear of every line (a leader when no near place is free),
the slider diagrams' rays broken behind their tick labels."""

import math

import numpy as np
import pytest

from graphmethods.dynamics.study import Study
from graphmethods.kinematics.case import case_from_dict
from graphmethods.problems import builtin
from graphmethods.render import svg
from graphmethods.scene import Line
from graphmethods.sheets import kinematic_diagrams, kinematic_scheme
from graphmethods.sheets.engine.quality import measure
from graphmethods.sheets.plates import Plate, body_outline, is_plate, link_bodies

SWING = {"kind": "linkage",
         "joints": {"O1": [0.0, 0.0], "A": [0.0, 0.08], "B": [0.24, 0.2], "O2": [0.3, 0.0], "S2": [0.12, 0.14]},
         "links": {"0": ["O1", "O2"], "1": ["O1", "A"], "2": ["A", "B", "S2"], "3": ["O2", "B"]},
         "driver": {"link": 1, "about": "O1", "range_deg": [30, 150]}, "n_rpm": 120, "sense": "ccw"}


def test_link_bodies_hold_every_joint_of_a_link():
    assert link_bodies(builtin.case("six-bar-press").mechanism)["3"] == ("B", "O2", "C")   # the rocker to C
    assert link_bodies(builtin.case("triad-six-bar").mechanism)["3"] == ("B", "C", "D")   # the basic link
    assert link_bodies(builtin.case("drawn/triad_six_bar").mechanism)["3"] == ("B", "C", "D")
    assert all(len(b) == 2 for b in link_bodies(builtin.case("press").mechanism).values())


def test_body_outline_a_plate_goes_round_joints_in_line_are_one_line():
    assert is_plate(((0, 0), (10, 0), (4, 3))) and not is_plate(((0, 0), (10, 0), (4, 0.1)))
    assert body_outline(((0, 0), (30, 0), (10, 0))) == ((0.0, 0.0), (30.0, 0.0))
    ring = body_outline(((0, 0), (10, 10), (10, 0), (0, 10)))
    area = 0.5 * abs(sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(ring, ring[1:] + ring[:1])))
    assert area == pytest.approx(100.0)                        # a simple polygon, not a bow tie


def test_the_triad_s_basic_link_is_a_hatched_plate_in_the_thick_position():
    scene = kinematic_scheme(builtin.case("triad-six-bar"))
    thick = scene.element("thick-BCD")
    assert isinstance(thick, Plate) and thick.hatch and len(thick.corners) == 3
    assert len(thick.parts()[0].hatch_segments()) > 5
    thin = [e for e in scene.elements if isinstance(e, Plate) and e.name.startswith("position-")]
    assert len(thin) == 11 and not any(p.hatch for p in thin)          # the other positions: outlines only
    joints = {scene.element(f"joint-{j}").at for j in "BCD"}
    assert {tuple(np.round(c, 9)) for c in thick.corners} == {tuple(np.round(j, 9)) for j in joints}


def test_a_lever_point_that_drives_a_link_stands_on_its_link():
    scene = kinematic_scheme(builtin.case("six-bar-press"))
    rocker = scene.element("thick-BO2C")
    assert isinstance(rocker, Line)
    ends = {tuple(np.round(rocker.start, 9)), tuple(np.round(rocker.end, 9))}
    assert ends == {tuple(np.round(scene.element(f"{k}").at, 9)) for k in ("pivot-O2", "joint-C")}


def test_a_swinging_driver_draws_its_arc_over_the_range():
    case = case_from_dict(SWING)
    scene = kinematic_scheme(case)
    names = [e.name for e in scene.elements]
    assert "crank-arc" in names and "crank-circle" not in names
    arc = scene.element("crank-arc")
    o = np.asarray(scene.element("pivot-O1").at)
    ang = sorted(math.degrees(math.atan2(o[1] - y, x - o[0])) for x, y in (arc.points[0], arc.points[-1]))
    assert ang == pytest.approx([30.0, 150.0], abs=1e-6)
    assert measure(scene).crossed == ()


@pytest.mark.parametrize("name", ["shaper", "six-bar-press", "engine", "two-slider", "triad-six-bar",
                                  "slotting-machine", "whitworth", "scotch-yoke"])
def test_no_scheme_label_is_crossed_and_leaders_reach_their_points(name):
    scene = kinematic_scheme(Study(builtin.case(name), positions=12), notation="ru")
    q = measure(scene)
    assert q.crossed == () and q.overlaps == ()
    for lead in (e for e in scene.elements if e.name.startswith("leader-")):
        assert 0.5 < math.dist(lead.start, lead.end) < 45.0


def test_the_scheme_is_deterministic():
    case = builtin.case("triad-six-bar")
    assert svg.to_bytes(kinematic_scheme(case)) == svg.to_bytes(kinematic_scheme(case))


def test_the_pole_rays_are_broken_behind_the_tick_labels():
    from graphmethods.scene import Line as L
    from graphmethods.sheets.linkage_figures import broken_behind

    assert measure(kinematic_diagrams(builtin.case("engine"))).crossed == ()
    pieces = broken_behind([L((0, 0), (10, 0), name="ray")], [(4, -1, 6, 1)])
    assert [p.name for p in pieces] == ["ray", "ray-1"] and pieces[0].end == (3.6, 0.0)


def test_the_kinematic_sheet_holds_the_triad_s_scheme_with_its_plate():
    from graphmethods.sheets import kinematic_analysis_sheet

    scene = kinematic_analysis_sheet(Study(builtin.case("triad-six-bar"), positions=12))
    assert scene.scales()                                       # the plate is an element, not a group of them
