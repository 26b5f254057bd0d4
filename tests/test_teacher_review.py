"""A teacher's review of the kinematic and dynamic A1 sheets (issue 26): one test per defect found.

Each test draws what the sheet draws (the scene, its elements by name) and checks the defect is gone: what is
drawn, where, and with what text.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from shapely import Polygon, box, linestrings

from graphmethods.dynamics.study import Study
from graphmethods.problems import builtin
from graphmethods.scene import Group, Line, Page
from graphmethods.scene.elements import label_bbox
from graphmethods.scene.primitives import Label, walk
from graphmethods.sheets.dynamic_analysis_sheet import dynamic_analysis_sheet, turned_heading
from graphmethods.sheets.dynamics import inertia_ticks
from graphmethods.sheets.kinematic_symbols import FixedPivot
from graphmethods.sheets.kinematics import kinematic_scheme, velocity_table
from graphmethods.sheets.wittenbauer import tick_label_band


def _boxes(element) -> list[tuple[float, float, float, float]]:
    return [label_bbox(p) for p in walk(element.primitives()) if isinstance(p, Label)]


def _meets(a, b) -> bool:
    return not (a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1])


@pytest.fixture(scope="module")
def dynamic_sheets():
    return {(p, lang): dynamic_analysis_sheet(Study(builtin.case(p), positions=12), notation=lang)
            for p, lang in (("shaper", "en"), ("shaper", "ru"), ("engine", "en"))}


# ----------------------------------------------------------------------------- the dynamic sheet

@pytest.mark.parametrize("key", [("shaper", "en"), ("shaper", "ru"), ("engine", "en")])
def test_wittenbauer_position_numbers_stay_out_of_the_J_axis_value_row(dynamic_sheets, key):
    """The shaper's points 0 and 2 were numbered in the J_e axis's row of values ("0 1 2 1.5 2"), the engine's
    point 0 beside "52" at a suppressed zero: they read as values of the axis."""
    scene = dynamic_sheets[key]
    band = tick_label_band(scene.element("D-axis-J"))
    numbers = [e for e in scene.elements if e.name.startswith("D-pos-")]
    assert band is not None and len(numbers) == 12
    for e in numbers:
        assert not any(_meets(b, band) for b in _boxes(e)), f"{e.name} ({e.text}) in the row of the J_e values"


@pytest.mark.parametrize("key", [("shaper", "en"), ("shaper", "ru"), ("engine", "en")])
def test_both_J_axes_have_the_same_ticks_written_alike(dynamic_sheets, key):
    """The turned J_e graph ticked every 0.25 kg·m² over the diagram ticked every 0.5 at the same μ_J, and wrote
    0.17 among 0.169 and 0.171."""
    scene = dynamic_sheets[key]
    turned, diagram = scene.element("J-axis-J"), scene.element("D-axis-J")
    assert turned.ticks == diagram.ticks
    written = [t for t in turned.tick_labels if t != "0"]
    decimals = {len(t.split(scene_decimal(key))[1]) if scene_decimal(key) in t else 0 for t in written}
    assert len(decimals) == 1, written


def scene_decimal(key) -> str:
    return "," if key[1] == "ru" else "."


def test_J_tick_values_have_one_number_of_decimals():
    from graphmethods.scene import Scale, notation

    _, labels, _ = inertia_ticks(0.1643, 0.1715, Scale("μ_J", "kg·m²", 4e-5), notation("en"))
    assert "0.170" in labels and "0.17" not in labels


def test_moment_graph_fills_its_room_in_russian(dynamic_sheets):
    """The ru shaper's M graph took μ_M = 10 N·m/mm (half its room empty) for want of 2 mm: its φ axis now
    stands lower, clear of the ΔT graph's heading, and μ_M = 5 fits (4 since the sheet draws one set of
    scales in en, ru and zh)."""
    scene = dynamic_sheets[("shaper", "ru")]
    mu_M = next(s for s in scene.scales() if s.symbol.startswith("μ_M"))
    assert mu_M.per_mm <= 5.0
    axis = _boxes(scene.element("M-axis-phi"))
    head = _boxes(scene.element("heading-T"))
    assert max(b[3] for b in axis) < min(b[1] for b in head)           # the numbers above the ΔT heading


def test_headings_put_the_symbol_after_the_quantity():
    """"Reduced moment of inertia, turned 90° J_e(φ)" read as if the symbol belonged to "turned 90°"."""
    from graphmethods.scene import notation

    for lang in ("en", "ru", "zh"):
        text = turned_heading(notation(lang))
        assert text.index("(φ)") < text.index("90°")


# ----------------------------------------------------------------------------- the kinematic scheme

@pytest.fixture(scope="module")
def schemes():
    return {p: kinematic_scheme(builtin.case(p), notation="ru", page=Page("A1", "landscape", frame=True))
            for p in ("six-bar-press", "shaper", "whitworth")}


@pytest.mark.parametrize("problem", ["six-bar-press", "shaper", "whitworth"])
def test_joint_names_stand_beside_their_joints(schemes, problem):
    """The six-bar press named O₁ 40 mm from its pivot, with a leader across the crank circle's numbers."""
    scene = schemes[problem]
    points = {e.name.split("-", 1)[1]: e.at for e in scene.elements
              if e.name.split("-", 1)[0] in ("pivot", "joint", "point") and hasattr(e, "at")}
    named = 0
    for e in scene.elements:
        j = e.name[len("name-"):]
        if not e.name.startswith("name-") or j not in points:
            continue
        b, at = _boxes(e)[0], points[j]
        near = (min(max(at[0], b[0]), b[2]), min(max(at[1], b[1]), b[3]))
        assert math.dist(near, at) <= 17.0, f"{j} named {math.dist(near, at):.1f} mm from its point"
        named += 1
    assert named >= 4


@pytest.mark.parametrize("problem", ["six-bar-press", "shaper", "whitworth"])
def test_no_name_on_a_support_and_no_arrow_through_one(schemes, problem):
    """Whitworth's O₃ stood on its own support's hatching; the shaper's ω₁ arrow ran through O₁'s."""
    scene = schemes[problem]
    supports = [Polygon(e.outline()) for e in scene.elements if isinstance(e, FixedPivot)]
    assert supports
    for e in scene.elements:
        if e.name.startswith("name-"):
            for b in _boxes(e):
                assert not any(box(*b).intersects(s) for s in supports), e.name
    arrow = scene.element("omega-1")
    arc = linestrings(np.array(arrow.arc_points()))
    assert not any(arc.intersects(s) for s in supports)


def test_thin_lines_are_broken_behind_a_crowded_name(schemes):
    """A name with no free place near its joint stands beside it and the thin lines under it are broken
    (ГОСТ 2.303): a broken line is one element, a group of its collinear pieces."""
    scene = schemes["six-bar-press"]
    names = [b for e in scene.elements if e.name.startswith("name-") for b in _boxes(e)]
    groups = [e for e in scene.elements if isinstance(e, Group) and e.name.startswith("position-")]
    assert groups                                           # O₁ of the six-bar press is crowded
    for g in groups:
        for q in g.elements:
            if isinstance(q, Line):
                seg = linestrings([q.start, q.end])
                assert not any(seg.intersects(box(*b)) for b in names)


# ----------------------------------------------------------------------------- the tables

def test_velocity_table_writes_each_column_with_four_digits():
    """The two-slider's table printed φ as 30.00 and ω as −23.562; the acceleration table ε as −2293.489."""
    rows = velocity_table(builtin.case("two-slider"), notation="en").element("table").rows
    head = rows[0]
    phi = [r[head.index("φ, °")] for r in rows[1:]]
    assert phi[:3] == ["0", "30", "60"]
    for col in range(2, len(head)):
        digits = [sum(ch.isdigit() for ch in r[col]) for r in rows[1:] if r[col] != "0"]
        assert max(digits) <= 4, (head[col], [r[col] for r in rows[1:]])


def test_acceleration_table_and_plan_values_have_four_digits():
    from graphmethods.sheets.acceleration import acceleration_plan, acceleration_table

    rows = acceleration_table(builtin.case("two-slider"), notation="en").element("table").rows
    for r in rows[1:]:
        for cell in r[2:]:
            assert sum(ch.isdigit() for ch in cell) <= 4 or cell == "0", r
    plan = acceleration_plan(builtin.case("engine"), 9, notation="en")
    table = next(e for e in plan.elements if e.name.endswith("table"))
    values = [r[2].split(" = ")[1] for r in table.rows[1:]]
    assert "1234" in values and "0" in values                # a_A = 1234 m/s², a^n_BA = 0 (ω₂ = 0)
