"""Graphical calculus sheets: geometry to scale (recording renderer), captions, notation, layout, refusals."""

import math
import pathlib
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from figure_checks import assert_fits_and_labels_apart

from graphmethods import problems
from graphmethods.dynamics import graphical_calculus as gc
from graphmethods.dynamics.moments import MomentCurve
from graphmethods.dynamics.study import Study
from graphmethods.errors import InputError
from graphmethods.kinematics import FourBar, read_case
from graphmethods.render import svg
from graphmethods.render.recording import record
from graphmethods.scene import markup
from graphmethods.sheets import calculus
from graphmethods.sheets.work_diagrams import work_diagrams

SVG = "{http://www.w3.org/2000/svg}"
PROFILES = ("en", "ru", "zh")
PRESS = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data" / "slider_crank_press.json"
TOL = 1e-3          # mm: the drawing is exact to the SVG's 3 decimals


@pytest.fixture(scope="module")
def press():
    return read_case(PRESS)


def all_figures():
    case = read_case(PRESS)
    out = []
    for nt in PROFILES:
        out.append((f"kinematic-{nt}", calculus.kinematic_diagrams(case, notation=nt)))
        out.append((f"work-{nt}", work_diagrams(Study(case), notation=nt)))
    out += [("kinematic-m6", calculus.kinematic_diagrams(case, m=6)),
            ("kinematic-m24-analogues", calculus.kinematic_diagrams(case, m=24, analogues=True, notation="ru")),
            ("work-m6", work_diagrams(case, m=6, notation="zh")),
            ("work-w3", work_diagrams(problems.w3())),
            ("work-w4", work_diagrams(problems.w4_exact(), m=8, notation="ru", moment_unit="kG·m",
                                               work_unit="kG·m"))]
    return out


FIGURES = all_figures()
IDS = [i for i, _ in FIGURES]


def seg(scene, name):
    """The (start, end) page points of a Line element, or of a line broken behind texts (its pieces are
    ``name``, ``name-1``, ...: from the first's start to the last's end)."""
    pieces = [e for e in scene.elements if e.name == name or (e.name.startswith(name + "-")
                                                              and e.name[len(name) + 1:].isdigit())]
    return np.asarray(pieces[0].start), np.asarray(pieces[-1].end)


def slope(p, q):
    return (q[1] - p[1]) / (q[0] - p[0])


# ----------------------------------------------------------------------------- every figure

@pytest.mark.parametrize("fid, scene", FIGURES, ids=IDS)
def test_scale_true_page_and_every_scale_captioned(fid, scene):
    root = ET.fromstring(svg.to_bytes(scene))
    vb = [float(v) for v in root.get("viewBox").split()]
    assert root.get("width") == f"{vb[2]:g}mm" and (vb[2], vb[3]) == (scene.page.width_mm, scene.page.height_mm)
    texts = ["".join(t.itertext()) for t in root.iter(SVG + "text")]

    def captioned(s):
        """The caption, or the scale's formula ending in its value (μ_v = μ_s/(μ_t·H_1) = 0.045 (m/s)/mm)."""
        symbol, value = markup.plain(s.caption(scene.notation)).split(" = ", 1)
        return any(t.startswith(symbol + " = ") and t.endswith(" = " + value) for t in texts)

    for axis in scene.axes():
        if axis.name.startswith("axis-phi"):
            continue                                            # the φ axes share μ_φ, captioned once
        assert any(captioned(s) for s in scene.scales() if s == axis.scale), f"{fid}: no caption for {axis.name}"
    for s in scene.scales():
        assert captioned(s), f"{fid}: {s.symbol} not captioned"
    assert markup.plain(scene.title) in texts


@pytest.mark.parametrize("fid, scene", FIGURES, ids=IDS)
def test_nothing_leaves_the_frame_and_no_two_labels_overlap(fid, scene):
    assert_fits_and_labels_apart(scene, fid)


@pytest.mark.parametrize("fid, scene", FIGURES, ids=IDS)
def test_construction_lines_thin_results_thick(fid, scene):
    for e in scene.elements:
        if e.name.startswith(("ray-", "projection-", "chord-", "mean-")):
            assert e.style.width_mm <= 0.18, e.name
        if e.name.startswith(("curve-", "chords-A")):
            assert e.style.width_mm >= 0.5, e.name


def test_the_same_input_gives_the_same_svg(press):
    a = svg.to_bytes(calculus.kinematic_diagrams(press, notation="zh"))
    assert a == svg.to_bytes(calculus.kinematic_diagrams(press, notation="zh"))
    b = svg.to_bytes(work_diagrams(Study(press), notation="ru"))
    assert b == svg.to_bytes(work_diagrams(Study(press), notation="ru"))


# ----------------------------------------------------------------------------- kinematic diagrams: geometry

@pytest.mark.parametrize("m", [6, 12])
def test_kinematic_diagrams_are_drawn_to_scale_rays_parallel_to_chords(press, m):
    scene = calculus.kinematic_diagrams(press, m=m)
    mu_phi, mu_s, mu_v, mu_a, mu_t = (s.per_mm for s in scene.scales())
    sd = gc.slider_diagrams(press.mechanism, m, mu_phi=mu_phi, mu_s=mu_s, omega_1=press.omega_m, H1_mm=30.0,
                            H2_mm=30.0)
    assert (mu_v, mu_a) == pytest.approx((sd.v.mu, sd.a.mu), rel=1e-12)
    assert mu_t == pytest.approx(mu_phi / press.omega_m)
    # s: the ordinate at each position is s/μ_s, at φ/μ_φ from the origin
    origin_s = np.asarray(scene.element("axis-s").origin)
    for k in range(m + 1):
        p = np.asarray(scene.element(f"dot-s-{k}").at)
        assert (origin_s[1] - p[1]) * mu_s == pytest.approx(sd.s[k], abs=TOL * mu_s)
        assert (p[0] - origin_s[0]) * mu_phi == pytest.approx(sd.phi[k], abs=TOL * mu_phi)
    # v: rays from P₁ (H₁ left of the origin) parallel to the chords of s; projected to mid-intervals
    origin_v = np.asarray(scene.element("axis-v").origin)
    pole = np.asarray(scene.element("pole-v-point").at)
    assert pole[1] == pytest.approx(origin_v[1]) and origin_v[0] - pole[0] == pytest.approx(30.0)
    for k in range(1, m + 1):
        c0, c1 = seg(scene, f"chord-s-{k}")
        r0, r1 = seg(scene, f"ray-v-{k}")
        assert np.allclose(r0, pole) and r1[0] == pytest.approx(origin_v[0])          # touches the axis
        assert slope(r0, r1) == pytest.approx(slope(c0, c1), rel=1e-9)
        q0, q1 = seg(scene, f"projection-v-{k}")
        assert np.allclose(q0, r1) and q1[1] == pytest.approx(q0[1])                    # horizontal
        dot = np.asarray(scene.element(f"dot-v-{k}").at)
        assert np.allclose(q1, dot)
        assert (origin_v[1] - dot[1]) * mu_v == pytest.approx(sd.v.values[k - 1], abs=TOL * mu_v)
        assert (dot[0] - origin_v[0]) * mu_phi == pytest.approx((k - 0.5) * 2 * math.pi / m, abs=TOL * mu_phi)
    # a: rays from P₂ parallel to the chords between the v points; a at the positions; closed
    origin_a = np.asarray(scene.element("axis-a").origin)
    pole_a = np.asarray(scene.element("pole-a-point").at)
    v_pts = [np.asarray(scene.element(f"dot-v-{k}").at) for k in range(1, m + 1)]
    for k in range(1, m):
        r0, r1 = seg(scene, f"ray-a-{k}")
        assert np.allclose(r0, pole_a)
        assert slope(r0, r1) == pytest.approx(slope(v_pts[k - 1], v_pts[k]), rel=1e-9, abs=1e-12)
        dot = np.asarray(scene.element(f"dot-a-{k}").at)
        assert dot[1] == pytest.approx(r1[1]) and (origin_a[1] - dot[1]) * mu_a == pytest.approx(sd.a.values[k],
                                                                                              abs=TOL * mu_a)
    first, last = scene.element("dot-a-0").at, scene.element(f"dot-a-{m}").at
    assert first[1] == pytest.approx(last[1], abs=1e-9)                # the diagram closes over the turn
    assert last[0] - first[0] == pytest.approx(2 * math.pi / mu_phi)


def test_kinematic_diagrams_curves_pass_through_their_points(press):
    scene = calculus.kinematic_diagrams(press)
    for curve, prefix, ks in (("curve-v", "dot-v-", range(1, 13)), ("curve-a", "dot-a-", range(13))):
        pts = np.asarray(scene.element(curve).points)
        for k in ks:
            d = np.asarray(scene.element(f"{prefix}{k}").at)
            assert np.hypot(*(pts - d).T).min() < 1e-9, (curve, k)


def test_kinematic_diagrams_caption_each_graph_with_its_formula_and_compare(press):
    scene = calculus.kinematic_diagrams(press)
    rec = record(scene)
    texts = rec.texts()
    assert "μv = μs/(μt·H1) = 0.12 (m/s)/mm" in texts and "μa = μv/(μt·H2) = 3.6 (m/s²)/mm" in texts
    assert "H1 = 30 mm (picked to fit)" in texts and "μt = μφ/ω1 = 0.001111 s/mm" in texts
    rows = scene.element("comparison-table").rows
    assert [r[1] for r in rows[1:]] == ["analytic", "velocity plans", "analytic", "acceleration plans"]
    sd = gc.slider_diagrams(press.mechanism, 12, mu_phi=math.pi / 90, mu_s=0.004, omega_1=press.omega_m,
                            H1_mm=30, H2_mm=30)
    cmp = sd.comparison()
    assert rows[2][2] == f"{cmp[1]['error']:.3g} m/s" and rows[3][3] == f"{cmp[2]['error_mm']:.2g} mm"
    assert any("H1 = 30 mm" in n for n in scene.notes)


def test_given_pole_distances_are_used_and_said_given(press):
    scene = calculus.kinematic_diagrams(press, H1_mm=20, H2_mm=15, notation="ru")
    texts = record(scene).texts()
    assert "H1 = 20 мм (задано)" in texts and "H2 = 15 мм (задано)" in texts
    o = scene.element("axis-a").origin
    assert o[0] - scene.element("pole-a-point").at[0] == pytest.approx(15.0)
    with pytest.raises(InputError, match="no room for the pole"):
        calculus.kinematic_diagrams(press, H1_mm=80)


def test_analogues_use_mu_phi_and_per_radian_units(press):
    scene = calculus.kinematic_diagrams(press, analogues=True)
    mu_phi, mu_s, mu_v, mu_a = (s.per_mm for s in scene.scales())
    H1 = scene.element("axis-v").origin[0] - scene.element("pole-v-point").at[0]
    H2 = scene.element("axis-a").origin[0] - scene.element("pole-a-point").at[0]
    assert mu_v == pytest.approx(mu_s / (mu_phi * H1)) and mu_a == pytest.approx(mu_v / (mu_phi * H2))
    assert "(m/rad)" in scene.scales()[2].unit and scene.element("axis-v").label == "v_{B}, m/rad"


def test_the_shaper_ram_is_differentiated_too():
    case = read_case(PRESS.with_name("shaper.json"))
    scene = calculus.kinematic_diagrams(case, m=12)
    assert scene.element("axis-s").label.startswith("s_{C}")


# ----------------------------------------------------------------------------- work diagrams: geometry

def test_work_diagrams_chords_parallel_to_rays_and_drawn_to_scale(press):
    st = Study(press)
    scene = work_diagrams(st)
    mu_phi, mu_M, mu_A = (s.per_mm for s in scene.scales())
    origin_M = np.asarray(scene.element("axis-M").origin)
    pole = np.asarray(scene.element("pole-point").at)
    H = origin_M[0] - pole[0]
    assert mu_A == pytest.approx(mu_M * mu_phi * H, rel=1e-12) and pole[1] == pytest.approx(origin_M[1])
    wd = gc.study_work_diagrams(st, mu_phi=mu_phi, mu_M=mu_M, H_mm=H)
    chords_r = np.asarray(scene.element("chords-A_r").points)
    chords_d = np.asarray(scene.element("chords-A_d").points)
    origin_A = np.asarray(scene.element("axis-A").origin)
    np.testing.assert_allclose((origin_A[1] - chords_r[:, 1]) * mu_A, wd.A_r.values, atol=TOL * mu_A)
    np.testing.assert_allclose((chords_r[:, 0] - origin_A[0]) * mu_phi, st.phi, atol=TOL * mu_phi)
    for i, ybar in enumerate(wd.A_r.mean_ordinate):
        if ybar == 0.0:
            continue
        rays = [e for e in scene.elements if e.name.startswith("ray-r-")
                and abs((origin_M[1] - e.end[1]) * mu_M - ybar) < 1e-6 * mu_M * 1000]
        assert rays, f"no ray to the mean ordinate of interval {i + 1}"
        # a ray is broken behind the M values it passes (ГОСТ 2.303): ray-r-k, ray-r-k-1, … on one line from P
        base = "-".join(rays[0].name.split("-")[:3])
        pieces = [e for e in scene.elements if e.name == base or e.name.startswith(base + "-")]
        r0, r1 = pole, np.asarray(rays[0].end)
        assert any(np.allclose(e.start, pole) for e in pieces) and r1[0] == pytest.approx(origin_M[0])
        u = (r1 - r0) / np.linalg.norm(r1 - r0)
        assert all(abs(u[0] * (q[1] - r0[1]) - u[1] * (q[0] - r0[0])) < 1e-6 for e in pieces for q in (e.start, e.end))
        assert slope(r0, r1) == pytest.approx(slope(chords_r[i], chords_r[i + 1]), rel=1e-9)
    # A_d is one straight line parallel to the M_d ray; both diagrams end at one point (the work balance)
    d = np.diff(chords_d, axis=0)
    assert np.allclose(d[:, 1] / d[:, 0], d[0, 1] / d[0, 0])
    assert np.allclose(chords_d[-1], chords_r[-1], atol=1e-9)
    # ΔE = A_d − A_r, ordinate by ordinate, to the same μ_A
    curve_E = np.asarray(scene.element("curve-dE").points)
    origin_E = np.asarray(scene.element("axis-dE").origin)
    np.testing.assert_allclose((origin_E[1] - curve_E[:, 1]) * mu_A, wd.delta_E, atol=TOL * mu_A)
    np.testing.assert_allclose(wd.delta_E, st.delta_T, atol=1e-9)          # the study's ΔT, the same chords


def test_work_diagrams_mean_ordinates_have_the_area_of_their_interval():
    scene = work_diagrams(problems.w4_exact(), m=8)
    mu_phi, mu_M, _ = (s.per_mm for s in scene.scales())
    M_r = problems.w4_exact().excess_work.M_r
    phi = np.linspace(0, 2 * math.pi, 9)
    for i in range(8):
        pts = np.asarray(scene.element(f"mean-r-{i + 1}").points)         # ⊓-shaped step: base, top, base
        width, height = pts[2, 0] - pts[1, 0], pts[0, 1] - pts[1, 1]
        exact = float(np.diff(M_r.integral(phi[i:i + 2]))[0])
        assert width * height * mu_phi * mu_M == pytest.approx(exact, rel=1e-9)


def test_work_diagrams_pick_or_take_H_and_say_which(press):
    picked = work_diagrams(problems.w3())
    assert picked.notes[-1].startswith("H = ") and "picked" in picked.notes[-1]
    given = work_diagrams(problems.w3(), H_mm=40, notation="ru")
    assert "H = 40 мм (задано)" in record(given).texts()
    o = given.element("axis-M").origin
    assert o[0] - given.element("pole-point").at[0] == pytest.approx(40.0)
    with pytest.raises(InputError, match="give a larger H_mm"):
        work_diagrams(problems.w3(), H_mm=2)
    with pytest.raises(InputError, match="larger μ_M"):
        work_diagrams(problems.w3(), mu_M=0.1)


def test_work_diagrams_accuracy_table_says_exact_at_ends_error_inside():
    scene = work_diagrams(problems.w3(), m=12)
    rows = scene.element("accuracy-table").rows
    body = {r[0]: r for r in rows[1:]}
    assert body["A_r"][1] == "0 J" and body["A_d"][1] == "0 J" and body["ΔE"][1] == "0 J"
    inside = 50.0 * (math.pi / 6) * 0.25            # jump 50 N·m in the middle of an interval π/6 wide
    assert body["A_r"][3] == f"{inside:.3g} J" and body["A_d"][3] == "0 J"


def test_work_diagrams_of_a_pair_of_curves_and_refusals():
    M_r = MomentCurve.points([0, math.pi, 2 * math.pi], [0.0, 40.0, 0.0])
    scene = work_diagrams((MomentCurve.constant(20.0), M_r), m=4)
    assert scene.element("chords-A_r").points[-1] == pytest.approx(scene.element("chords-A_d").points[-1])
    with pytest.raises(InputError, match="areas or works fix no curves"):
        work_diagrams(problems.w1())
    with pytest.raises(InputError, match="linkage problem"):
        calculus.kinematic_diagrams(problems.w3())
    four_bar = FourBar(l1=0.5, l2=0.1, l3=0.45, l4=0.3)
    with pytest.raises(InputError, match="one slider"):
        calculus.kinematic_diagrams(four_bar)


# ----------------------------------------------------------------------------- notation

def test_one_switch_changes_the_whole_figure(press):
    texts = {nt: " ".join(record(work_diagrams(Study(press), notation=nt)).texts()) for nt in PROFILES}
    assert "Work diagrams" in texts["en"] and "Ar" in texts["en"] and "ΔE" in texts["en"]
    assert "Диаграммы работ" in texts["ru"] and "Aс" in texts["ru"] and "ΔT" in texts["ru"] and "Дж" in texts["ru"]
    assert "功线图" in texts["zh"] and "Wr" in texts["zh"] and "Mer" in texts["zh"]
    assert not any(w in texts["ru"] for w in ("Work", "picked", " J/mm", "Scales"))
    kin = {nt: " ".join(record(calculus.kinematic_diagrams(press, notation=nt)).texts()) for nt in PROFILES}
    assert "Kinematic diagrams" in kin["en"] and "velocity plans" in kin["en"]
    assert "Кинематические" in kin["ru"] and "vB, м/с" in kin["ru"] and "планы скоростей" in kin["ru"]
    assert "滑块运动线图" in kin["zh"] and "速度图" in kin["zh"] and "vB/(m/s)" in kin["zh"]
    assert not any(w in kin["zh"] for w in ("velocity plans", "Kinematic", "picked"))


def test_small_curve_helper_passes_through_its_points_and_closes():
    x = np.linspace(0, 2 * math.pi, 13)
    X, Y = calculus.smooth_through(x, np.sin(x), period=2 * math.pi)
    np.testing.assert_allclose(Y[::12], np.sin(x), atol=1e-15)
    np.testing.assert_allclose(np.interp(np.linspace(0, 6, 50), X, Y), np.sin(np.linspace(0, 6, 50)), atol=5e-3)
    with pytest.raises(InputError):
        calculus.smooth_through([1.0], [2.0])


def test_a_strip_too_low_for_values_7_mm_apart_gets_closer_values_not_none():
    # W4-exact's ΔE swings ±5π J (ΔE = 20φ − ∫M_r, M_r a triangle 0 … 40 … 0 N·m) and μ_A = μ_M μ_φ H
    scene = work_diagrams(problems.w4_exact())
    mu_phi, mu_M, mu_A = (s.per_mm for s in scene.scales())
    H = float(scene.notes[-1].split()[2])
    assert mu_A == pytest.approx(mu_M * mu_phi * H, rel=1e-12)
    swing_mm = 5 * math.pi / mu_A
    assert swing_mm < 7.0                                   # no value but 0 at 7 mm apart on either side
    ax = scene.element("axis-dE")
    written = [(v, t) for v, t in zip(ax.ticks, ax.tick_labels) if v != 0 and t]
    assert written, "the ΔE axis has no value written"
    gaps = np.diff([v / mu_A for v in ax.ticks])
    assert 3.5 <= gaps.min() and all(abs(v) / mu_A <= swing_mm + 1e-9 for v, _ in written)
    texts = record(scene).texts()
    assert all(t in texts for _, t in written)
    # a strip tall enough keeps its values at least 7 mm apart
    ax_A = scene.element("axis-A")
    assert np.diff([v / mu_A for v in ax_A.ticks]).min() >= 7.0 - 1e-9
