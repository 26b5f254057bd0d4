"""The Wittenbauer figures: the compact A4 diagram and the A1/A2 dynamic-analysis sheet.

Geometry is measured on what is drawn (the recording renderer), never on pixels: the rays
bound the curve and touch it at the reported tangencies, kl on paper gives J_F, projection
lines join matching points, every axis has its μ caption.
"""

import json
import pathlib
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from figure_checks import assert_fits_and_labels_apart
from hypothesis import given, settings, strategies as st

from graphmethods.cli import main
from graphmethods.dynamics.study import Study
from graphmethods.dynamics.wittenbauer import wittenbauer
from graphmethods.errors import InputError, MotionError
from graphmethods.kinematics import read_case
from graphmethods.render import svg
from graphmethods.render.recording import record
from graphmethods.scene import Page, markup
from graphmethods.sheets.dynamic_analysis_sheet import dynamic_analysis_sheet
from graphmethods.sheets.wittenbauer import ray_span, wittenbauer_diagram

SVG = "{http://www.w3.org/2000/svg}"
PROFILES = ("en", "ru", "zh")
DATA = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data"
CASES = ("slider_crank_press", "four_bar_rocker", "slotted_lever", "shaper")


def case(name="slider_crank_press"):
    return read_case(DATA / f"{name}.json")


@pytest.fixture(scope="module")
def press():
    return case()


@pytest.fixture(scope="module")
def scenes(press):
    """(id, scene, prefix) for the A4 diagram and the A1 sheet in every profile, and the A2 sheet."""
    study = Study(press, positions=12)
    out = [(f"A4-{nt}", wittenbauer_diagram(study, notation=nt), "") for nt in PROFILES]
    out += [(f"A1-{nt}", dynamic_analysis_sheet(study, notation=nt), "D-") for nt in PROFILES]
    out.append(("A2-en", dynamic_analysis_sheet(study, page="A2"), "D-"))
    return out


# ----------------------------------------------------------------------------- measuring the drawing

def group_paths(rec, gid):
    return [c.data[0] for c in rec.in_group(gid, "path")]


def circle_centre(rec, gid):
    (c,) = rec.in_group(gid, "circle")
    return np.array(c.data[:2])


def ray_line(rec, gid):
    """The drawn ray as (point, unit direction) on paper."""
    (pts,) = group_paths(rec, gid)
    a, b = np.array(pts[0]), np.array(pts[-1])
    return a, (b - a) / np.hypot(*(b - a))


def above(point, line):
    """Signed distance (mm) of a point above a line on paper (y grows down the page)."""
    a, d = line
    y_line = a[1] + d[1] / d[0] * (point[0] - a[0])
    return (y_line - point[1]) * abs(d[0])            # perpendicular distance, + above


def curve_points(rec, gid):
    (pts,) = group_paths(rec, gid)
    return np.array(pts)


def check_rays(scene, res_J_F, prefix, tol=1e-3):
    """The drawn rays bound every point of the drawn curve and touch it at the marked tangencies;
    return kl measured on the drawn ordinate axis (mm)."""
    rec = record(scene)
    up, lo = ray_line(rec, f"{prefix}ray-max"), ray_line(rec, f"{prefix}ray-min")
    pts = curve_points(rec, f"{prefix}curve")
    assert max(above(p, up) for p in pts) <= tol                       # none over the upper ray
    assert min(above(p, lo) for p in pts) >= -tol                      # none under the lower ray
    marks = [g for g in rec.group_ids() if g.startswith(f"{prefix}tangency-")]
    assert any("-max-" in g for g in marks) and any("-min-" in g for g in marks)
    for g in marks:
        line = up if "-max-" in g else lo
        assert abs(above(circle_centre(rec, g), line)) <= tol, g
    # k and l: where the drawn rays cut the drawn ordinate axis
    (axis,) = group_paths(rec, f"{prefix}axis-T")[:1]
    x_axis = axis[0][0]
    y_k = up[0][1] + up[1][1] / up[1][0] * (x_axis - up[0][0])
    y_l = lo[0][1] + lo[1][1] / lo[1][0] * (x_axis - lo[0][0])
    assert np.allclose(circle_centre(rec, f"{prefix}point-k"), (x_axis, y_k), atol=tol)
    assert np.allclose(circle_centre(rec, f"{prefix}point-l"), (x_axis, y_l), atol=tol)
    return y_l - y_k


def J_axis_from(scene, prefix=""):
    """Where a diagram's J axis starts (its suppressed zero, kg·m²; 0 without one)."""
    return float(scene.element(f"{prefix}axis-J").min_value)


def mu(scene, symbol_start):
    return next(s for s in scene.scales() if s.symbol.startswith(symbol_start))


# ----------------------------------------------------------------------------- the tests

def test_rays_bound_the_curve_touch_it_and_kl_on_paper_gives_J_F(scenes, press):
    exact_kl = Study(press, positions=12).wittenbauer   # J_F does not depend on the drawing's scales
    for fid, scene, prefix in scenes:
        kl = check_rays(scene, exact_kl.J_F, prefix)
        mu_T = next(s for s in scene.scales() if s.unit in ("J", "Дж")).per_mm
        J_0 = scene.element(f"{prefix}axis-J").min_value     # where the drawn ordinate axis stands (J_0, or 0)
        J_F = kl * mu_T / (press.omega_m**2 * press.delta) - J_0
        assert J_F == pytest.approx(exact_kl.J_F, rel=1e-9), fid
        rec = record(scene)
        dim = scene.element(f"{prefix}dimension-kl")
        assert dim.length_mm == pytest.approx(kl, abs=1e-3)
        assert f"{get_number(scene.notation, kl)}" in markup.plain(scene.element(f"{prefix}label-kl").text)
        table = " ".join(rec.texts("result"))
        assert get_number(scene.notation, exact_kl.J_F) in table, fid


@pytest.mark.parametrize("name", ["four_bar_rocker", "slider_crank_press"])
def test_a_J_e_varying_little_gets_a_suppressed_zero_the_curve_fills_the_diagram_and_the_rays_keep_true_slopes(name):
    c = case(name)
    study = Study(c, positions=12)
    scene = dynamic_analysis_sheet(study, notation="ru")
    rec = record(scene)
    J = np.asarray(study.J_e, dtype=float)
    ax = scene.element("D-axis-J")
    J_0 = ax.min_value
    assert 0.0 < J_0 <= J.min() and J.min() - J_0 < 0.5 * (J.max() - J.min())     # a round value just below
    assert scene.element("J-axis-J").min_value == J_0                              # the turned graph starts there too
    for gid in ("D-axis-J-break", "J-axis-J-break"):
        assert gid in rec.group_ids(), gid
    mu_J = next(s for s in scene.scales() if s.unit == "кг·м²").per_mm
    mu_T = next(s for s in scene.scales() if s.unit == "Дж").per_mm
    # each vertex stands at its true J_e measured from J_0
    x_axis = ax.pos(J_0)[0]
    for k in range(study.m):
        assert circle_centre(rec, f"D-vertex-{k}")[0] == pytest.approx(x_axis + (J[k] - J_0) / mu_J, abs=1e-6)
    # the curve fills the diagram (before: a strip of 20-25 % of an axis from 0)
    pts = curve_points(rec, "D-curve")
    assert np.ptp(pts[:, 0]) > 0.6 * (ax.pos(ax.max_value)[0] - x_axis)
    # tan ψ of the true J values: (μ_J/μ_T)·ω_m²(1 ± δ/2)²/2 (domain.md §7), whatever the origin
    for key, sign in (("max", 1.0), ("min", -1.0)):
        _, d = ray_line(rec, f"D-ray-{key}")
        tan = mu_J / mu_T * 0.5 * c.omega_m**2 * (1.0 + sign * c.delta / 2) ** 2
        assert -d[1] / d[0] == pytest.approx(tan, rel=1e-9), key
    # k, l on the drawn axis; J_F = μ_T·kl/(ω_m²[δ]) − J_0 is the construction's J_F
    kl = check_rays(scene, study.wittenbauer.J_F, "D-")
    assert kl * mu_T / (c.omega_m**2 * c.delta) - J_0 == pytest.approx(study.wittenbauer.J_F, rel=1e-9)
    table = " ".join(rec.texts("result"))
    assert f"Jп0 = {get_number('ru', J_0)} кг·м²" in table and get_number("ru", study.wittenbauer.J_F) in table
    assert "O1 за пределами листа" in table                                        # O1, far off, said so


@pytest.mark.parametrize("name", ["four_bar_rocker", "single_cylinder_engine", "scotch_yoke_pump",
                                  "two_slider_compressor", "shaper", "whitworth_quick_return"])
def test_the_A1_sheet_of_every_kind_fits_and_keeps_its_labels_apart(name):
    assert_fits_and_labels_apart(dynamic_analysis_sheet(Study(case(name), positions=12)), name)


def test_a_J_e_varying_much_keeps_its_axis_from_zero():
    scene = dynamic_analysis_sheet(Study(case("shaper"), positions=12))
    assert scene.element("D-axis-J").min_value == 0.0
    assert "D-axis-J-break" not in record(scene).group_ids()


def get_number(nt, v):
    from graphmethods.scene import notation

    return notation(nt).number(v)


def test_every_axis_has_its_mu_caption_and_the_svg_is_scale_true(scenes):
    for fid, scene, _ in scenes:
        root = ET.fromstring(svg.to_bytes(scene))
        vb = [float(v) for v in root.get("viewBox").split()]
        assert root.get("width") == f"{vb[2]:g}mm" and (vb[2], vb[3]) == (scene.page.width_mm, scene.page.height_mm)
        texts = ["".join(t.itertext()) for t in root.iter(SVG + "text")]
        assert scene.axes(), fid
        for axis in scene.axes():
            caption = markup.plain(axis.scale.caption(scene.notation))
            assert caption in texts, f"{fid}: no caption {caption!r} for axis {axis.name}"


def test_nothing_leaves_the_frame_and_no_two_labels_overlap(scenes):
    for fid, scene, _ in scenes:
        assert_fits_and_labels_apart(scene, fid)


def test_projection_lines_connect_matching_points(press):
    study = Study(press, positions=12)
    scene = dynamic_analysis_sheet(study)
    rec = record(scene)
    mu_J, mu_T, mu_phi = mu(scene, "μ_J").per_mm, mu(scene, "μ_T").per_mm, mu(scene, "μ_φ").per_mm
    J_axis = scene.element("J-axis-J")
    T_axis = scene.element("T-axis-Y")
    for k in range(study.m):
        # a projection line is broken where it would run through a text: its pieces run on one line
        h_pieces, v_pieces = group_paths(rec, f"projection-T-{k}"), group_paths(rec, f"projection-J-{k}")
        h, v = (h_pieces[0][0], h_pieces[-1][-1]), (v_pieces[0][0], v_pieces[-1][-1])
        for pieces, (a, b) in ((h_pieces, h), (v_pieces, v)):
            for piece in pieces:
                for pt in piece:
                    (dx, dy), (ex, ey) = np.subtract(b, a), np.subtract(pt, a)
                    assert abs(dx * ey - dy * ex) < 1e-6 * np.hypot(dx, dy)
        vertex = circle_centre(rec, f"D-vertex-{k}")
        dT_dot, J_dot = circle_centre(rec, f"T-dot-{k}"), circle_centre(rec, f"J-dot-{k}")
        assert np.allclose(h[0], dT_dot, atol=1e-9) and np.allclose(h[-1], vertex, atol=1e-9)
        assert np.allclose(v[0], J_dot, atol=1e-9) and np.allclose(v[-1], vertex, atol=1e-9)
        assert h[0][1] == pytest.approx(h[-1][1], abs=1e-9) and v[0][0] == pytest.approx(v[-1][0], abs=1e-9)
        # the levels are the data: ΔT read on the ΔT graph, J_e on the turned graph, φ on both
        assert (T_axis.origin[1] - dT_dot[1]) * mu_T == pytest.approx(study.delta_T[k], abs=1e-3 * mu_T)
        assert (J_dot[0] - J_axis.origin[0]) * mu_J == pytest.approx(study.J_e[k], abs=1e-3 * mu_J)
        assert (J_dot[1] - J_axis.origin[1]) * mu_phi == pytest.approx(study.phi[k], abs=1e-3 * mu_phi)
        assert (dT_dot[0] - T_axis.origin[0]) * mu_phi == pytest.approx(study.phi[k], abs=1e-3 * mu_phi)


def test_the_sheet_models_only_what_it_draws(press):
    study = Study(press, positions=12)
    dynamic_analysis_sheet(study)
    assert "exact" not in study.computed and "model" not in study.computed
    assert {"inertia", "M_r", "delta_T"} <= set(study.computed)
    study2 = Study(press, positions=12)
    wittenbauer_diagram(study2, notation="ru")
    assert "exact" not in study2.computed and "M_d" not in study2.computed


def test_same_input_gives_byte_identical_svg(press):
    a = svg.to_bytes(dynamic_analysis_sheet(Study(press, positions=12), notation="zh"))
    b = svg.to_bytes(dynamic_analysis_sheet(Study(press, positions=12), notation="zh"))
    assert a == b


@pytest.mark.parametrize("name", CASES)
def test_every_problem_file_draws_a_correct_sheet(name):
    c = case(name)
    study = Study(c, positions=12)
    sheet = dynamic_analysis_sheet(study, page="A2")
    check_rays(sheet, study.wittenbauer.J_F, "D-")
    diagram = wittenbauer_diagram(study, notation="zh")
    kl = check_rays(diagram, study.wittenbauer.J_F, "")
    assert kl * mu(diagram, "μ_E").per_mm / (c.omega_m**2 * c.delta) - J_axis_from(diagram) == pytest.approx(
        study.wittenbauer.J_F, rel=1e-9)


def ellipse(m=12, *, J0=2.0, dJ=0.4, T=300.0, lag=0.7):
    phi = np.linspace(0, 2 * np.pi, m + 1)
    return J0 + dJ * np.cos(phi + lag), T * np.sin(phi), phi


@settings(deadline=None, max_examples=20)
@given(J0=st.floats(0.05, 50.0), ratio=st.floats(0.02, 0.8), T=st.floats(1.0, 5e4), lag=st.floats(-3.0, 3.0),
       m=st.integers(6, 40), omega=st.floats(5.0, 200.0), delta=st.sampled_from([0.5, 0.2, 0.05, 1 / 300, 1e-3]))
def test_any_closed_curve_draws_correctly_and_J_F_does_not_depend_on_the_scales(J0, ratio, T, lag, m, omega, delta):
    J, dT, phi = ellipse(m, J0=J0, dJ=ratio * J0, T=T, lag=lag)
    try:
        res = wittenbauer(J_e=J, delta_T=dT, omega_m=omega, delta=delta, mu_J=1.0, mu_T=1.0, phi=phi)
    except MotionError as exc:                     # no flywheel needed: nothing to draw
        assert "no flywheel is needed" in str(exc)
        return
    scene = wittenbauer_diagram(res)
    kl = check_rays(scene, res.J_F, "")
    mu_T = mu(scene, "μ_T").per_mm
    assert kl * mu_T / (omega**2 * delta) - J_axis_from(scene) == pytest.approx(res.J_F, rel=1e-7, abs=1e-9 * J0)


@pytest.mark.hard
def test_small_delta_puts_O1_hundreds_of_sheets_away_and_the_rays_still_bound(press):
    J, dT, phi = ellipse(24)
    res = wittenbauer(J_e=J, delta_T=dT, omega_m=30.0, delta=1e-3, mu_J=1.0, mu_T=1.0, phi=phi)
    scene = wittenbauer_diagram(res)
    drawn = [r for r in scene.notes if r.startswith("J_F")]
    assert drawn
    kl = check_rays(scene, res.J_F, "")
    assert kl * mu(scene, "μ_T").per_mm / (30.0**2 * 1e-3) - J_axis_from(scene) == pytest.approx(res.J_F, rel=1e-9)
    x0, _, x1, _ = scene.page.inner_box()
    on_paper = wittenbauer(J_e=J, delta_T=dT, omega_m=30.0, delta=1e-3, mu_J=mu(scene, "μ_J").per_mm,
                           mu_T=mu(scene, "μ_T").per_mm, phi=phi)
    assert abs(on_paper.O1_mm[0]) > 100 * (x1 - x0)                    # O1 far away; never drawn
    assert "point-O1" not in [e.name for e in scene.elements]
    # the rays end on the frame (O1 side)
    rec = record(scene)
    for g in ("ray-max", "ray-min"):
        (pts,) = group_paths(rec, g)
        assert pts[0][0] == pytest.approx(scene.page.inner_box()[0], abs=1e-6) or \
            pts[0][1] == pytest.approx(scene.page.inner_box()[3], abs=1e-6)


@pytest.mark.hard
def test_huge_delta_draws_O1_when_it_falls_on_the_sheet():
    J, dT, phi = ellipse(24, J0=1.0, dJ=0.3, T=300.0)
    res = wittenbauer(J_e=J, delta_T=dT, omega_m=20.0, delta=0.5, mu_J=1.0, mu_T=1.0, phi=phi)
    scene = wittenbauer_diagram(res)
    check_rays(scene, res.J_F, "")
    names = [e.name for e in scene.elements]
    page = scene.page.inner_box()
    O1 = np.array(res.O1_mm)  # at μ = 1: convert with the drawn scales
    drawn = wittenbauer(J_e=J, delta_T=dT, omega_m=20.0, delta=0.5, mu_J=mu(scene, "μ_J").per_mm,
                        mu_T=mu(scene, "μ_T").per_mm, phi=phi)
    origin = scene.element("axis-T").origin
    O1_page = (origin[0] + drawn.O1_mm[0], origin[1] - drawn.O1_mm[1])
    inside = page[0] <= O1_page[0] <= page[2] and page[1] <= O1_page[1] <= page[3]
    assert ("point-O1" in names) == inside
    assert O1.shape == (2,)


@pytest.mark.hard
def test_constant_J_e_gives_a_vertical_curve_and_the_delta_W_max_flywheel():
    phi = np.linspace(0, 2 * np.pi, 13)
    dT = 200.0 * np.sin(phi) + 50 * np.sin(2 * phi)
    dT[-1] = 0.0
    res = wittenbauer(J_e=np.full(13, 2.0), delta_T=dT, omega_m=10.0, delta=0.05, mu_J=1.0, mu_T=1.0, phi=phi)
    scene = wittenbauer_diagram(res)
    kl = check_rays(scene, res.J_F, "")
    dW = float(dT.max() - dT.min())
    J_F = kl * mu(scene, "μ_T").per_mm / (10.0**2 * 0.05) - J_axis_from(scene)
    assert J_F == pytest.approx(dW / (10.0**2 * 0.05) - 2.0, rel=1e-9)
    xs = curve_points(record(scene), "curve")[:, 0]
    assert np.ptp(xs) < 1e-9                                             # a vertical line


@pytest.mark.hard
def test_a_straight_stretch_parallel_to_a_ray_touches_along_it():
    # three collinear points whose line has exactly the upper ray's slope
    omega, delta = 10.0, 0.1
    a_max = 0.5 * omega**2 * (1 + delta / 2) ** 2
    J = np.array([1.0, 1.2, 1.4, 1.3, 1.1, 1.0])
    dT = np.array([0.0, 0.2 * a_max, 0.4 * a_max, -30.0, -40.0, 0.0])
    res = wittenbauer(J_e=J, delta_T=dT, omega_m=omega, delta=delta, mu_J=1.0, mu_T=1.0)
    assert res.upper[0].kind == "segment" and set(res.upper[0].indices) >= {0, 1, 2}
    scene = wittenbauer_diagram(res)
    check_rays(scene, res.J_F, "")
    marks = [e.name for e in scene.elements if e.name.startswith("tangency-max-")]
    assert {"tangency-max-0", "tangency-max-1", "tangency-max-2"} <= set(marks)


def test_textbook_tangents_draw_their_own_rays_and_the_other_J_F(press):
    study = Study(press, positions=12)
    book = wittenbauer_diagram(study, mu_J=0.005, mu_T=10.0, tangents="textbook")
    kl = check_rays(book, 0, "")
    J_F = kl * 10.0 / (press.omega_m**2 * press.delta) - J_axis_from(book)
    assert J_F == pytest.approx(study.wittenbauer.J_F_other_tangents, rel=1e-9)
    assert "(1 ± δ)" in " ".join(record(book).texts("result"))


def test_given_scales_are_used_and_refused_when_they_do_not_fit(press):
    study = Study(press, positions=12)
    s = wittenbauer_diagram(study, mu_J=0.01, mu_T=10.0)
    assert [sc.per_mm for sc in s.scales()] == [10.0, 0.01]
    with pytest.raises(InputError, match="needs .* mm but the sheet leaves"):
        wittenbauer_diagram(study, mu_T=1.0)
    with pytest.raises(InputError, match="A1 or A2"):
        dynamic_analysis_sheet(study, page="A4")
    big = dynamic_analysis_sheet(study, page=Page("A1", "landscape", frame=True), mu_T=5.0, mu_J=0.005)
    assert mu(big, "μ_T").per_mm == 5.0 and mu(big, "μ_J").per_mm == 0.005


def test_ray_span_clips_to_the_frame_and_keeps_off_the_title_block():
    clip, origin = (10.0, 10.0, 287.0, 200.0), (100.0, 50.0)
    lo, hi = ray_span(intercept_mm=-20.0, tan=0.5, origin=origin, clip=clip, O1_x=-1e6, x_from=60.0, x_to=80.0)
    assert lo == pytest.approx(-90.0) and hi == pytest.approx(80.0)          # enters at the left edge
    lo, hi = ray_span(intercept_mm=-20.0, tan=0.5, origin=origin, clip=clip, O1_x=-50.0, x_from=60.0, x_to=80.0)
    assert lo == pytest.approx(-50.0)                                           # starts at O1 on the sheet
    lo, _ = ray_span(intercept_mm=-20.0, tan=0.5, origin=origin, clip=clip, O1_x=-1e6, x_from=60.0, x_to=80.0,
                     avoid=((0.0, 100.0, 300.0, 200.0),))
    assert lo == pytest.approx(-60.0)               # stops at the title block's row (y = 100)


# ----------------------------------------------------------------------------- the command line

def test_study_command_writes_the_sheet_keeps_the_json_and_refuses_to_overwrite(tmp_path, capsys, press_case_path):
    target = tmp_path / "sheet.svg"
    assert main(["study", str(press_case_path), "--no-exact", "--json"]) == 0
    plain = json.loads(capsys.readouterr().out)
    assert main(["study", str(press_case_path), "--no-exact", "--json", "--sheet", str(target), "--lang", "ru"]) == 0
    out = capsys.readouterr()
    assert json.loads(out.out) == plain and "wrote" in out.err                   # the JSON as it was
    root = ET.fromstring(target.read_bytes())
    assert root.get("width") == "841mm" and "Диаграмма энергомасс" in target.read_text(encoding="utf-8")
    before = target.read_bytes()
    assert main(["study", str(press_case_path), "--no-exact", "--sheet", str(target), "--page", "a2"]) == 2
    assert "--force" in capsys.readouterr().err and target.read_bytes() == before
    assert main(["study", str(press_case_path), "--no-exact", "--sheet", str(target), "--page", "A2", "--force"]) == 0
    assert ET.fromstring(target.read_bytes()).get("width") == "594mm"


def test_study_command_writes_pdf_and_nothing_on_error(tmp_path, capsys, press_case_path):
    pdf = tmp_path / "sheet.pdf"
    assert main(["study", str(press_case_path), "--no-exact", "--sheet", str(pdf)]) == 0
    assert pdf.read_bytes()[:5] == b"%PDF-"
    capsys.readouterr()
    bad = tmp_path / "bad.json"
    bad.write_text('{"r": 0.1}', encoding="utf-8")
    assert main(["study", str(bad), "--sheet", str(tmp_path / "x.svg")]) == 2
    assert main(["study", str(press_case_path), "--sheet", str(tmp_path / "x.jpg")]) == 2   # .png is a format now
    assert main(["study", str(press_case_path), "--sheet", str(tmp_path / "no" / "x.svg")]) == 2
    err = capsys.readouterr().err
    assert ".svg, .pdf, .png or .dxf" in err and "does not exist" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.json", "sheet.pdf"]
