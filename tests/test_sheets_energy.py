"""The excess-work figures: geometry to scale, captions, notation, layout, and refusals."""

import itertools
import math
import xml.etree.ElementTree as ET

import pytest
from figure_checks import assert_fits_and_labels_apart
from hypothesis import given, settings, strategies as st

from graphmethods import problems, sheets
from graphmethods.dynamics import excess_work as ew
from graphmethods.errors import InputError
from graphmethods.render import svg
from graphmethods.render.recording import record
from graphmethods.scene import Page, Region, markup
from graphmethods.scene.primitives import Label, Path, walk

SVG = "{http://www.w3.org/2000/svg}"
PROFILES = ("en", "ru", "zh")


def w4_kw(fig):
    return {"moment_diagram": dict(moment_unit="kG·m", work_unit="kG·m"),
            "energy_graph": dict(work_unit="kG·m", J_e=0.8, omega_0=10.0)}.get(fig, dict(work_unit="kG·m"))


def all_figures():
    """(id, scene) for W1–W4, every figure their data allows, every profile."""
    cases = {"W1": (problems.w1(), ("energy_indicator", "excess_work_table")),
             "W2": (problems.w2(), ("energy_indicator", "excess_work_table")),
             "W3": (problems.w3(), ("moment_diagram", "excess_work_table", "energy_indicator", "energy_graph")),
             "W4": (problems.w4_exact(), ("moment_diagram", "excess_work_table", "energy_indicator", "energy_graph"))}
    out = []
    for cid, (problem, figs) in cases.items():
        for fig, nt in itertools.product(figs, PROFILES):
            kw = w4_kw(fig) if cid == "W4" else {}
            out.append((f"{cid}-{fig}-{nt}", getattr(sheets, fig)(problem, notation=nt, **kw)))
    return out


FIGURES = all_figures()
IDS = [i for i, _ in FIGURES]


def svg_texts(root):
    return ["".join(t.itertext()) for t in root.iter(SVG + "text")]


@pytest.mark.parametrize("fid, scene", FIGURES, ids=IDS)
def test_svg_page_is_scale_true_and_every_axis_caption_is_drawn(fid, scene):
    root = ET.fromstring(svg.to_bytes(scene))
    vb = [float(v) for v in root.get("viewBox").split()]
    assert root.get("width") == f"{vb[2]:g}mm" and root.get("height") == f"{vb[3]:g}mm"
    assert (vb[2], vb[3]) == (scene.page.width_mm, scene.page.height_mm)
    texts = svg_texts(root)
    for axis in scene.axes():
        caption = markup.plain(axis.scale.caption(scene.notation))
        assert caption in texts, f"{fid}: no caption {caption!r} for axis {axis.name}"
    assert scene.title and markup.plain(scene.title) in texts


@pytest.mark.parametrize("fid, scene", FIGURES, ids=IDS)
def test_nothing_leaves_the_frame_and_no_two_labels_overlap(fid, scene):
    assert_fits_and_labels_apart(scene, fid)


def test_one_switch_changes_the_whole_figure():
    texts = {nt: " ".join(lab.text for lab in sheets.energy_indicator(problems.w1(), notation=nt).primitives()
                          if isinstance(lab, Label)) for nt in PROFILES}
    assert "Energy indicator" in texts["en"] and "gain" in texts["en"]
    assert "能量指示图" in texts["zh"] and "盈功" in texts["zh"] and "亏功" in texts["zh"]
    assert "Дж" in texts["ru"] and "Масштабы" in texts["ru"] and "Aизб" in texts["ru"]
    assert not any(w in texts["ru"] for w in ("gain", "Energy", " J/mm", "Scales"))
    assert not any(w in texts["zh"] for w in ("gain", "Energy", "Scales"))
    md = {nt: [lab.text for lab in sheets.moment_diagram(problems.w3(), notation=nt).primitives()
               if isinstance(lab, Label)] for nt in PROFILES}
    assert "Md" in md["en"] and "Mд" in md["ru"] and "Med" in md["zh"] and "Mer" in md["zh"]


# ----------------------------------------------------------------------------- energy indicator

@pytest.mark.parametrize("problem", [problems.w1(), problems.w2()], ids=["W1", "W2"])
def test_indicator_vectors_are_work_over_mu_long_up_for_gains(problem):
    cyc = problem.excess_work
    scene = sheets.energy_indicator(problem)
    (mu_E,) = scene.scales()
    rec = record(scene)
    root = ET.fromstring(svg.to_bytes(scene))
    for k, A in enumerate(cyc.work):
        gid = f"vector-{cyc.labels[k]}{cyc.labels[k + 1]}"
        assert rec.vector_length_mm(gid) == pytest.approx(abs(A) / mu_E.per_mm, abs=1e-9)
        (g,) = [e for e in root.iter(SVG + "g") if e.get("id") == gid]
        start = [float(v) for v in g.find(SVG + "polyline").get("points").split()[0].split(",")]
        tip = [float(v) for v in g.find(SVG + "polygon").get("points").split()[0].split(",")]
        assert math.dist(start, tip) == pytest.approx(abs(A) / mu_E.per_mm, abs=0.001)
        assert (tip[1] < start[1]) == (A > 0)                      # up on paper for a gain


def test_indicator_closes_on_the_start_level_and_dimensions_delta_W_max():
    cyc = problems.w1().excess_work
    scene = sheets.energy_indicator(cyc, mu_E=5.0)
    start = scene.element("vector-ab").start
    last = scene.element(f"vector-{cyc.labels[-2]}{cyc.labels[-1]}")
    assert last.end[1] == pytest.approx(start[1], abs=1e-9)
    dim = scene.element("dimension-delta-W-max")
    assert dim.length_mm == pytest.approx(575.0 / 5.0)
    assert "575" in dim.text and "ΣA = 0 J (closure)" == markup.plain(scene.element("closure").text)
    top = scene.element("mark-E_max").at[1]
    bottom = scene.element("mark-E_min").at[1]
    assert bottom - top == pytest.approx(575.0 / 5.0)


def test_indicator_of_measured_areas_writes_the_residual():
    cyc = ew.from_areas([50, -550, 100, -125, 500, -25, 47], mu_M=1.0, mu_phi=1.0)   # residual −3
    scene = sheets.energy_indicator(cyc, notation="ru")
    assert markup.plain(scene.element("closure").text) == "ΣA = −3 Дж (невязка)"


@given(st.lists(st.floats(min_value=-500, max_value=500).filter(lambda v: abs(v) > 1.0), min_size=1, max_size=11))
@settings(max_examples=25, deadline=None)
def test_indicator_staircase_of_any_closed_cycle(works):
    works = works + [-sum(works)]
    if abs(works[-1]) < 1e-6:
        works = works[:-1]
    cyc = ew.from_work(works, closure_tol=1e-9)
    scene = sheets.energy_indicator(cyc)
    (mu,) = scene.scales()
    y0 = scene.element("vector-ab").start[1]
    for k in range(len(works)):
        v = scene.element(f"vector-{cyc.labels[k]}{cyc.labels[k + 1]}")
        assert (y0 - v.end[1]) * mu.per_mm == pytest.approx(cyc.E[k + 1], abs=1e-6 * (1 + abs(cyc.E[k + 1])))
    assert mu.to_mm(cyc.E.max() - cyc.E.min()) <= 200


# ----------------------------------------------------------------------------- moment diagram

@pytest.mark.parametrize("problem", [problems.w3(), problems.w4_exact()], ids=["W3", "W4"])
def test_moment_diagram_regions_are_the_excess_work_to_scale(problem):
    from shapely.geometry import LineString, Polygon

    cyc = problem.excess_work
    scene = sheets.moment_diagram(problem)
    mu_phi, mu_M = scene.scales()
    regions = [e for e in scene.elements if isinstance(e, Region)]
    assert len(regions) == len(cyc.work)
    for region, A in zip(regions, cyc.work):
        poly = Polygon(region.outline)
        assert poly.area * mu_M.per_mm * mu_phi.per_mm == pytest.approx(abs(A), rel=1e-9)
        segs = region.hatch_segments()
        assert segs and all(poly.buffer(1e-6).covers(LineString(s)) for s in segs)
        dx, dy = segs[0][1][0] - segs[0][0][0], segs[0][1][1] - segs[0][0][1]
        assert (dx * dy < 0) == (A > 0)                            # / for a gain, \ for a loss
    notes = annotations(scene)
    assert len(notes) == len(cyc.work)
    for i, A in enumerate(cyc.work):
        area = abs(A) / (mu_M.per_mm * mu_phi.per_mm)
        assert notes[i].startswith(f"f{i + 1} = ") and f"{area:.4g}" in notes[i].replace("−", "").replace("+", "")
    labels = [lab.text for lab in scene.primitives() if isinstance(lab, Label)]
    for name in cyc.labels:
        assert name in labels


def annotations(scene) -> list[str]:
    """The text written in (or for) each region, lines joined by spaces."""
    out = []
    for e in scene.elements:
        if e.name.startswith("annotation-"):
            out.append(" ".join(p.text for p in walk(e.primitives()) if isinstance(p, Label)))
    return out


def test_moment_diagram_writes_area_and_work_of_each_interval():
    cyc = problems.w3().excess_work
    scene = sheets.moment_diagram(cyc, mu_M=0.5, mu_phi=math.radians(2.0))
    area = 34.36116964863836 / (0.5 * math.radians(2.0))
    notes = annotations(scene)
    assert notes[0].split() == ["f1", "=", f"−{area:.0f}", "mm²", "A1", "=", "−34.36", "J"]
    assert notes[1] == f"f2 = +{area:.0f} mm² A2 = +34.36 J"
    signs = [p for p in walk(scene.element("annotation-1").primitives()) if isinstance(p, Path)]
    assert len(signs) == 1                                          # − is one stroke, + would be two
    assert [s.per_mm for s in scene.scales()] == [math.radians(2.0), 0.5]


def test_moment_diagram_curves_pass_through_their_values():
    scene = sheets.moment_diagram(problems.w4_exact(), moment_unit="kG·m", work_unit="kG·m")
    mu_phi, mu_M = scene.scales()
    ax = scene.element("axis-M")
    peak = min(scene.element("curve-M_r").points, key=lambda p: p[1])
    assert (ax.origin[1] - peak[1]) * mu_M.per_mm == pytest.approx(40.0)
    assert (peak[0] - ax.origin[0]) * mu_phi.per_mm == pytest.approx(math.pi)


def test_figures_need_the_data_they_draw():
    areas_only = problems.w1()
    with pytest.raises(InputError, match="energy_indicator"):
        sheets.moment_diagram(areas_only)
    with pytest.raises(InputError, match="energy_indicator"):
        sheets.energy_graph(areas_only)
    with pytest.raises(InputError, match="needs .* mm but the sheet leaves"):
        sheets.moment_diagram(problems.w3(), mu_M=0.01)
    with pytest.raises(InputError, match="too small"):
        sheets.energy_graph(problems.w4_exact(), T0=10.0)
    with pytest.raises(InputError, match="expected an excess-work cycle"):
        sheets.energy_indicator([50, -50])


# ----------------------------------------------------------------------------- energy graph

def test_energy_graph_follows_the_running_energy_and_marks_its_extremes():
    cyc = problems.w4_exact().excess_work
    scene = sheets.energy_graph(cyc, notation="zh")
    mu_phi, mu_E = scene.scales()
    f_origin = scene.element("axis-E").origin
    for k, name in enumerate(cyc.labels):
        dot = scene.element(f"point-{name}").elements[0].at
        assert (f_origin[1] - dot[1]) * mu_E.per_mm == pytest.approx(cyc.E[k], abs=1e-9)
        assert (dot[0] - f_origin[0]) * mu_phi.per_mm == pytest.approx(cyc.phi[k] - cyc.phi[0], abs=1e-9)
    top, bottom = scene.element("mark-E_max").at, scene.element("mark-E_min").at
    assert (bottom[1] - top[1]) * mu_E.per_mm == pytest.approx(cyc.delta_W_max)
    assert scene.element("dimension-delta-W-max").length_mm * mu_E.per_mm == pytest.approx(cyc.delta_W_max)


def test_kinetic_energy_graph_from_omega_0_is_drawn_from_T_equals_zero():
    scene = sheets.energy_graph(problems.w4_exact(), J_e=0.8, omega_0=10.0, notation="ru", work_unit="kG·m")
    mu_phi, mu_T = scene.scales()
    assert mu_T.symbol == "μ_T" and scene.element("axis-E").min_value == 0.0
    a = scene.element("point-a").elements[0].at
    assert (scene.element("axis-E").origin[1] - a[1]) * mu_T.per_mm == pytest.approx(40.0)
    assert markup.plain(scene.element("label-T0").text) == "T0 = 40 кГ·м"
    assert "55,71" in scene.element("label-T_max").text and "24,29" in scene.element("label-T_min").text


# ----------------------------------------------------------------------------- table

def test_table_rows_are_the_excess_work_table():
    cyc = problems.w2().excess_work
    scene = sheets.excess_work_table(cyc)
    rows = scene.element("table").rows
    assert rows[0][0] == "Interval" and rows[1][-3:] == ("a", "0", "E_{min}" if cyc.index_E_min == 0 else "")
    body = rows[2:-1]
    assert [r[0] for r in body] == [f"{a}–{b}" for a, b in zip(cyc.labels, cyc.labels[1:])]
    assert [r[-3] for r in body] == list(cyc.labels[1:])
    assert [r[-4] for r in body] == ["−50", "+550", "−100", "+125", "−500", "+25", "−50"]
    assert [r[-2] for r in body] == ["−50", "500", "400", "525", "25", "50", "0"]
    marks = {r[-3]: r[-1] for r in body}
    assert marks["b"] == "E_{min}" and marks["e"] == "E_{max}"
    assert "ΔWmax = Emax − Emin = 575 J" == markup.plain(scene.element("delta-W-max").text)


def test_table_of_measured_areas_shows_areas_and_the_drawing_scales():
    scene = sheets.excess_work_table(problems.w4_drawing(), notation="zh", work_unit="kG·m", moment_unit="kG·m")
    rows = scene.element("table").rows
    assert rows[0][1] == "f/mm²" and [r[1] for r in rows[2:-1]] == ["+200", "−200", "−200", "+200"]
    assert [s.caption("zh") for s in scene.scales()] == ["μ_M = 1 kG·m/mm", "μ_φ = 0.075 rad/mm"]


def test_the_same_table_as_markdown_comes_from_the_core():
    cyc = problems.w1().excess_work
    md = cyc.to_markdown()
    drawn = sheets.excess_work_table(cyc).element("table").rows
    for row in drawn[2:-1]:
        assert f"| {row[0]} |" in md


@pytest.mark.parametrize("page", [Page("A3", "portrait"), Page("A2", "landscape", frame=True), Page("A4", "portrait")],
                         ids=["A3-portrait", "A2-landscape-frame", "A4-portrait-no-frame"])
def test_figures_fit_other_pages_and_use_them(page):
    small = sheets.moment_diagram(problems.w3())
    big = sheets.moment_diagram(problems.w3(), page=page)
    assert big.page.size == page.size and big.page.title_block is not None
    x0, y0, x1, y1 = big.page.inner_box()
    bx = big.bbox()
    assert bx[0] >= x0 and bx[1] >= y0 and bx[2] <= x1 and bx[3] <= y1
    if page.size != "A4":
        assert big.scales()[1].per_mm <= small.scales()[1].per_mm      # more paper, larger drawing


@pytest.mark.parametrize("nt", ["en", "ru", "zh"])
def test_w1_staircase_goes_down_first_as_the_source_prints_it(nt, worked_examples):
    """W1 as printed: deficit work first, b the lowest point and e the highest (page y grows downward)."""
    rec = record(sheets.energy_indicator(problems.w1(), notation=nt))
    signs = []
    for a, b in zip("abcdefg", "bcdefgh"):
        start, *_ = rec.in_group(f"vector-{a}{b}", "path")[0].data[0]
        tip = rec.in_group(f"vector-{a}{b}", "polygon")[0].data[0]
        signs.append(1 if tip[1] < start[1] else -1)                  # up on the page is a gain
    assert signs == [1 if A > 0 else -1 for A in worked_examples["W1"]["areas_J"]]
    assert signs[0] == -1
    cyc = problems.w1().excess_work
    assert (cyc.labels[cyc.index_E_min], cyc.labels[cyc.index_E_max]) == ("b", "e")
