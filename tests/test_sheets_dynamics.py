"""The dynamics figures of a linkage study: J_e(φ) (also turned 90°), M_d and M_r, ΔT / T, ω, ε, the Zhukovsky lever.

Geometry is measured on the drawing: a point drawn at (x, y) mm reads back, through the
figure's own axes and scales, as the value it stands for (±0.001 mm); the lever's arm in mm
× force × μ_v/ω₁ is the reduced moment the power method gives.
"""

import math
import pathlib
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from figure_checks import assert_fits_and_labels_apart
from hypothesis import given, settings, strategies as st

from graphmethods.dynamics.study import Study
from graphmethods.errors import InputError
from graphmethods.kinematics import read_case
from graphmethods.render import svg
from graphmethods.render.recording import record
from graphmethods.scene import markup
from graphmethods.scene.primitives import Label
from graphmethods.sheets import dynamics as dyn
from graphmethods.sheets.speed_graphs import acceleration_graph, speed_graph
from graphmethods.sheets.zhukovsky_lever import zhukovsky_lever

SVG = "{http://www.w3.org/2000/svg}"
PROFILES = ("en", "ru", "zh")
DATA = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data"
FIGURES = {
    "inertia": (dyn.inertia_graph, {}),
    "inertia-turned": (dyn.inertia_graph, {"turned": True}),
    "moment": (dyn.moment_graph, {}),
    "delta-T": (dyn.delta_T_graph, {}),
    "kinetic": (dyn.delta_T_graph, {"kinetic": True}),
    "speed": (speed_graph, {}),
    "acceleration": (acceleration_graph, {}),
    "lever": (zhukovsky_lever, {}),
}


def case(name="slider_crank_press"):
    return read_case(DATA / f"{name}.json")


@pytest.fixture(scope="module")
def study():
    return Study(case(), positions=12)          # one exact solution for the whole module


@pytest.fixture(scope="module")
def scenes(study):
    return [(f"{key}-{nt}", fn(study, notation=nt, **kw)) for key, (fn, kw) in FIGURES.items() for nt in PROFILES]


def centre(rec, gid):
    (c,) = rec.in_group(gid, "circle")
    return np.array(c.data[:2])


def read_value(axis, point):
    """The value a page point stands for on an axis (its own origin and scale)."""
    if axis.direction == "x":
        return (point[0] - axis.origin[0]) * axis.scale.per_mm
    if isinstance(axis, dyn.DownAxis):
        return (point[1] - axis.origin[1]) * axis.scale.per_mm
    return (axis.origin[1] - point[1]) * axis.scale.per_mm


# ----------------------------------------------------------------------------- every figure

def test_every_axis_has_its_mu_caption_and_the_page_is_scale_true(scenes):
    for fid, scene in scenes:
        root = ET.fromstring(svg.to_bytes(scene))
        vb = [float(v) for v in root.get("viewBox").split()]
        assert root.get("width") == f"{vb[2]:g}mm" and (vb[2], vb[3]) == (scene.page.width_mm, scene.page.height_mm)
        texts = ["".join(t.itertext()) for t in root.iter(SVG + "text")]
        for axis in scene.axes():
            caption = markup.plain(axis.scale.caption(scene.notation))
            assert caption in texts, f"{fid}: no caption {caption!r} for axis {axis.name}"
        for s in scene.scales():
            assert markup.plain(s.caption(scene.notation)) in texts, fid
        assert markup.plain(scene.title) in texts


def test_nothing_leaves_the_frame_and_no_two_labels_overlap(scenes):
    for fid, scene in scenes:
        assert_fits_and_labels_apart(scene, fid)


def test_one_switch_changes_every_word(study):
    def words(nt):
        s = speed_graph(study, notation=nt)
        return " ".join(p.text for p in s.primitives() if isinstance(p, Label))
    en, ru, zh = (words(nt) for nt in PROFILES)
    assert "Angular velocity" in en and "rad/s" in en
    assert "Угловая скорость" in ru and "рад/с" in ru and "ωср" in ru and "rad/s" not in ru and "," in ru
    assert "曲柄角速度" in zh and "Angular" not in zh


def test_deterministic_svg(study):
    assert svg.to_bytes(zhukovsky_lever(study, notation="zh")) == svg.to_bytes(zhukovsky_lever(study,
                                                                                                          notation="zh"))


# ----------------------------------------------------------------------------- values read back from the drawing

def test_J_e_points_read_back_as_J_e_and_phi(study):
    scene = dyn.inertia_graph(study)
    rec = record(scene)
    ax_phi, ax_J = scene.element("axis-phi"), scene.element("axis-Y")
    for k in range(study.m + 1):
        p = centre(rec, f"dot-{k}")
        assert read_value(ax_J, p) == pytest.approx(study.J_e[k], abs=1e-3 * ax_J.scale.per_mm)
        assert read_value(ax_phi, p) == pytest.approx(study.phi[k], abs=1e-3 * ax_phi.scale.per_mm)
    parts = [e.name for e in scene.elements if e.name.startswith("curve-") and e.name != "curve-J_e"]
    assert len(parts) == 4                                      # J1, the rod (m and J), the slider


def test_turned_J_e_graph_reads_back_with_phi_down_the_page(study):
    scene = dyn.inertia_graph(study, turned=True, notation="ru")
    rec = record(scene)
    ax_J, ax_phi = scene.element("axis-J"), scene.element("axis-phi")
    assert isinstance(ax_phi, dyn.DownAxis) and ax_phi.tip[1] > ax_phi.start[1]
    for k in range(study.m):
        p = centre(rec, f"dot-{k}")
        assert read_value(ax_J, p) == pytest.approx(study.J_e[k], abs=1e-3 * ax_J.scale.per_mm)
        assert read_value(ax_phi, p) == pytest.approx(study.phi[k], abs=1e-3 * ax_phi.scale.per_mm)


def test_moment_graph_draws_M_r_at_the_positions_and_the_balancing_M_d_without_J_e():
    s = Study(case(), positions=12)
    scene = dyn.moment_graph(s)
    assert "inertia" not in s.computed and "exact" not in s.computed and "plans" in s.computed
    rec = record(scene)
    ax = scene.element("axis-Y")
    for k in range(s.m + 1):
        assert read_value(ax, centre(rec, f"dot-{k}")) == pytest.approx(s.M_r[k], abs=1e-3 * ax.scale.per_mm)
    M_d_line = scene.element("curve-M_d")
    M_d = read_value(ax, M_d_line.points[0])
    M_d_curve, M_r_curve = s.moments
    assert M_d == pytest.approx(M_d_curve.mean(), abs=1e-3 * ax.scale.per_mm)
    assert M_d * 2 * math.pi == pytest.approx(M_r_curve.work(), rel=1e-12)      # the work balance of what is drawn


def test_delta_T_graph_points_are_the_diagram_ordinates_and_extremes_are_marked(study):
    scene = dyn.delta_T_graph(study, notation="zh")
    rec = record(scene)
    ax = scene.element("axis-Y")
    for k in range(study.m + 1):
        assert read_value(ax, centre(rec, f"dot-{k}")) == pytest.approx(study.delta_T[k], abs=1e-3 * ax.scale.per_mm)
    curve = np.array(scene.element("curve-dT").points)
    top, bottom = centre(rec, "mark-dT_max"), centre(rec, "mark-dT_min")
    assert top[1] == pytest.approx(curve[:, 1].min(), abs=1e-9) and bottom[1] == pytest.approx(curve[:, 1].max(),
                                                                                             abs=1e-9)


def test_speed_graph_marks_the_exact_extremes_and_the_mean(study):
    scene = speed_graph(study)
    rec = record(scene)
    ex = study.exact
    ax_w, ax_phi = scene.element("axis-Y"), scene.element("axis-phi")
    assert ax_w.min_value > 0                                      # a suppressed zero: the axis starts high
    assert ax_w.min_value in ax_w.ticks and ax_w.min_value <= ex.omega_min
    for key, w, p in (("omega_max", ex.omega_max, ex.phi_omega_max_from_0),
                      ("omega_min", ex.omega_min, ex.phi_omega_min_from_0)):
        c = centre(rec, f"mark-{key}")
        assert read_value(ax_w, c) == pytest.approx(w, abs=1e-6)
        assert read_value(ax_phi, c) == pytest.approx(p, abs=1e-6)
    level = scene.element("level-omega_m")
    assert read_value(ax_w, level.start) == pytest.approx(ex.motion.omega_m, abs=1e-9)
    assert (ex.omega_max - ex.omega_min) / ex.motion.omega_m == pytest.approx(study.delta, rel=1e-8)


def test_acceleration_graph_marks_the_largest_eps_and_chi(study):
    scene = acceleration_graph(study, notation="ru")
    mo = study.exact.motion
    c = centre(record(scene), "mark-eps_max")
    assert read_value(scene.element("axis-Y"), c) == pytest.approx(mo.epsilon_max, abs=1e-6)
    assert get_number("ru", mo.chi) in markup.plain(scene.element("legend").text)


def get_number(nt, v):
    from graphmethods.scene import notation

    return notation(nt).number(v)


# ----------------------------------------------------------------------------- the lever

def lever_moment_on_paper(scene, omega_1):
    """F·h·μ_v/ω₁ measured on the drawing: the force from its vector's length, h from p to its line."""
    rec = record(scene)
    mu_v = next(s for s in scene.scales() if s.symbol == "μ_v").per_mm
    mu_F = next(s for s in scene.scales() if s.symbol == "μ_F").per_mm
    p = centre(rec, "pole")
    (shaft,) = rec.in_group("force-F", "path")
    (head,) = rec.in_group("force-F", "polygon")
    start, tip = np.array(shaft.data[0][0]), np.array(head.data[0])
    F = math.dist(start, tip) * mu_F
    u = (tip - start) / np.hypot(*(tip - start))
    h = abs((p - start)[0] * u[1] - (p - start)[1] * u[0])           # distance from p to the line of action
    dim = scene.element("dimension-h")
    assert dim.length_mm == pytest.approx(h, abs=1e-3)                 # the arm is dimensioned
    return F * h * mu_v / omega_1, h


@pytest.mark.parametrize("name", ["slider_crank_press", "four_bar_rocker", "slotted_lever", "shaper"])
def test_lever_moment_on_the_drawing_equals_the_power_method(name):
    s = Study(case(name), positions=12)
    scene = zhukovsky_lever(s)
    k = int(scene.title.rsplit(" ", 1)[1])
    M, h = lever_moment_on_paper(scene, s.plans.omega_1)
    assert M == pytest.approx(s.M_r[k], rel=1e-6)
    assert get_number("en", h) in markup.plain(scene.element("label-h").text)
    assert "exact" not in s.computed and "inertia" not in s.computed


@settings(deadline=None, max_examples=15)
@given(k=st.sampled_from([1, 2, 3, 4, 5]), mu_v=st.sampled_from([0.04, 0.05, 0.1]),
       nt=st.sampled_from(PROFILES))
def test_lever_at_any_loaded_position_and_scale(k, mu_v, nt):
    s = _press_study()
    scene = zhukovsky_lever(s, position=k, mu_v=mu_v, notation=nt)
    M, _ = lever_moment_on_paper(scene, s.plans.omega_1)
    assert M == pytest.approx(s.M_r[k], rel=1e-6)


_CACHE = {}


def _press_study():
    if "press" not in _CACHE:
        _CACHE["press"] = Study(case(), positions=12)
    return _CACHE["press"]


def test_lever_refuses_an_unloaded_position_and_a_scale_that_does_not_fit(study):
    with pytest.raises(InputError, match="carries no load.*choose a loaded position: 1, 2, 3, 4, 5"):
        zhukovsky_lever(study, position=8)
    with pytest.raises(InputError, match="position 13"):
        zhukovsky_lever(study, position=13)
    with pytest.raises(InputError, match="needs .* but the sheet leaves"):
        zhukovsky_lever(study, position=3, mu_v=0.001)


def test_figures_accept_a_problem_file_and_refuse_other_things():
    scene = dyn.moment_graph(case("four_bar_rocker"))
    assert scene.element("curve-M_r")
    with pytest.raises(InputError, match="expected a Study"):
        dyn.moment_graph(42)
    with pytest.raises(InputError, match="needs .* mm but the sheet leaves"):
        dyn.moment_graph(case(), mu_M=0.5)


def test_fast_occupancy_agrees_with_the_plain_one():
    from graphmethods.sheets.layout import Occupancy

    rng = np.random.default_rng(3)
    fast, slow = dyn.FastOccupancy(), Occupancy()
    for _ in range(60):
        seg = rng.uniform(0, 100, size=(2, 2))
        fast.add_line(seg)
        slow.add_line(seg)
    for _ in range(5):
        b = tuple(rng.uniform(0, 100, size=2)) + ()
        fast.add_box((b[0], b[1], b[0] + 3, b[1] + 2))
        slow.add_box((b[0], b[1], b[0] + 3, b[1] + 2))
    for _ in range(400):
        x, y = rng.uniform(-5, 105, size=2)
        box = (x, y, x + rng.uniform(0.5, 8), y + rng.uniform(0.5, 4))
        assert fast.is_free(box) == slow.is_free(box)
        assert fast.is_free(box, lines=False) == slow.is_free(box, lines=False)
