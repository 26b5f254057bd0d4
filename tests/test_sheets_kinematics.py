"""The kinematics figures: scheme to μ_l, velocity plans to μ_v, the table; geometry, words, refusals, CLI."""

import itertools
import json
import math
import pathlib
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from figure_checks import assert_fits_and_labels_apart
from hypothesis import given, settings, strategies as st

from graphmethods import cli
from graphmethods.dynamics.study import Study
from graphmethods.errors import InputError
from graphmethods.kinematics import FourBar, SliderCrank, read_case
from graphmethods.render import svg
from graphmethods.render.recording import record
from graphmethods.scene import Group, Line, Vector, markup
from graphmethods.scene.primitives import Label
from graphmethods.sheets import kinematics as ks

DATA = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data"
SVG = "{http://www.w3.org/2000/svg}"
PROFILES = ("en", "ru", "zh")
PRESS = read_case(DATA / "slider_crank_press.json")
SHAPER = read_case(DATA / "shaper.json")
FIGS = ("kinematic_scheme", "velocity_plan_grid", "velocity_plan", "velocity_table")


def all_figures():
    out = []
    for (cid, case), fig, nt in itertools.product((("press", PRESS), ("shaper", SHAPER)), FIGS, PROFILES):
        out.append((f"{cid}-{fig}-{nt}", getattr(ks, fig)(case, notation=nt)))
    return out


FIGURES = all_figures()
IDS = [i for i, _ in FIGURES]


def toggle_four_bar():
    """A double rocker and crank angles up to 1e-9 rad from its toggle (coupler and rocker in line)."""
    fb = FourBar(l1=0.3, l2=0.2, l3=0.25, l4=0.2, points={"S2": ("AB", 0.125)})
    t = math.acos((0.3 ** 2 + 0.2 ** 2 - 0.45 ** 2) / (2 * 0.3 * 0.2))
    return fb, fb.positions(phi=[-1.2, -0.6, 0.0, 0.6, 1.2, t - 1e-9, t - 1e-3])


# ----------------------------------------------------------------------------- every figure

@pytest.mark.parametrize("fid, scene", FIGURES, ids=IDS)
def test_scale_true_page_with_every_scale_captioned(fid, scene):
    root = ET.fromstring(svg.to_bytes(scene))
    vb = [float(v) for v in root.get("viewBox").split()]
    assert (vb[2], vb[3]) == (scene.page.width_mm, scene.page.height_mm)
    assert root.get("width") == f"{vb[2]:g}mm"
    texts = ["".join(t.itertext()) for t in root.iter(SVG + "text")]
    for s in scene.scales():
        assert markup.plain(s.caption(scene.notation)) in texts, f"{fid}: no caption for {s.symbol}"
    want = {"kinematic_scheme": ["μ_l"], "velocity_plan_grid": ["μ_v"], "velocity_plan": ["μ_v"],
            "velocity_table": []}[fid.split("-")[1]]
    assert [s.symbol for s in scene.scales()] == want
    assert markup.plain(scene.title) in texts


@pytest.mark.parametrize("fid, scene", FIGURES, ids=IDS)
def test_nothing_leaves_the_frame_and_no_two_labels_overlap(fid, scene):
    assert_fits_and_labels_apart(scene, fid)


def test_same_input_gives_byte_identical_svg():
    for fig in FIGS:
        a = svg.to_bytes(getattr(ks, fig)(SHAPER, notation="ru"))
        b = svg.to_bytes(getattr(ks, fig)(read_case(DATA / "shaper.json"), notation="ru"))
        assert a == b, fig


def test_one_switch_changes_every_word():
    words = {nt: " ".join(p.text for f in FIGS for p in getattr(ks, f)(PRESS, notation=nt).primitives()
                          if isinstance(p, Label)) for nt in PROFILES}
    assert "Kinematic scheme" in words["en"] and "guide" in words["en"] and "Position" in words["en"]
    assert "План механизма" in words["ru"] and "направляющей" in words["ru"] and "м/с" in words["ru"]
    assert "机构运动简图" in words["zh"] and "导路" in words["zh"] and "速度多边形" in words["zh"]
    for nt in ("ru", "zh"):
        assert not any(w in words[nt] for w in ("Velocity", "guide", "Position", "Scales", "positions"))


# ----------------------------------------------------------------------------- the kinematic scheme

@pytest.mark.parametrize("case", [PRESS, SHAPER], ids=["press", "shaper"])
def test_scheme_links_are_their_lengths_to_scale(case):
    mech = case.mechanism
    scene = ks.kinematic_scheme(case)
    (mu_l,) = scene.scales()
    lengths = {"OA": mech.r, "AB": getattr(mech, "l", None), "O1A": mech.r, "BC": getattr(mech, "l_BC", None),
               "O3B": getattr(mech, "l_O3B", None)}
    seen = 0
    for e in scene.elements:
        # a thin line broken behind a name (ГОСТ 2.303) is a group of collinear pieces: its span is the link
        pieces = [q for q in e.elements if isinstance(q, Line)] if isinstance(e, Group) else [e]
        if pieces and all(isinstance(q, Line) for q in pieces) and (
                e.name.startswith("position-") or e.name.startswith("thick-") or e.name.startswith("extreme-")):
            link = e.name.split("-")[-1]
            ends = [p for q in pieces for p in (q.start, q.end)]
            span = max(math.dist(p, q) for p in ends for q in ends)
            assert span * mu_l.per_mm == pytest.approx(lengths[link], abs=1e-3 * mu_l.per_mm)
            seen += 1
    pos = mech.positions(12)
    assert seen == 12 * len(mech.link_joints) + len(mech.link_joints)      # 12 positions and the extreme
    assert any(e.name.startswith("thick-") and e.style.width_mm > 0.5 for e in scene.elements if isinstance(e, Line))
    # the stroke is dimensioned to scale between the slider's extreme positions
    dim = scene.element("dimension-H")
    assert dim.length_mm * mu_l.per_mm == pytest.approx(pos.H, abs=1e-3 * mu_l.per_mm)
    assert f"{pos.H * 1000:.4g} mm" in markup.plain(dim.text)        # a dimension is in mm, as drawings give it


def test_scheme_numbers_every_position_at_the_crank_pin_and_the_output():
    scene = ks.kinematic_scheme(PRESS)
    at_pin = [scene.element(f"number-A-{k}").text for k in range(12)] + [scene.element("number-A-extreme").text]
    assert at_pin == ["0 (12)"] + [str(k) for k in range(1, 12)] + ["6′"]
    out = [t for e in scene.elements if e.name.startswith("number-out-") for t in e.text.split(", ")]
    assert sorted(out) == sorted(at_pin)                       # each number once at the output point too
    mech = PRESS.mechanism
    pos = mech.positions(12)
    mu = scene.scales()[0].per_mm
    a0 = scene.element("joint-A").at
    o = scene.element("pivot-O").at
    # the crank pin of the thick position is where position 0 puts it, seen from the pivot O
    np.testing.assert_allclose(((a0[0] - o[0]) * mu, (o[1] - a0[1]) * mu), pos.coords["A"][0], atol=1e-9)
    assert "extreme positions 0 and 6′" in scene.element("summary").text
    assert "K = 1.017" in scene.element("summary").text


def test_scheme_symbols_slider_on_its_guide_ground_under_pivots():
    scene = ks.kinematic_scheme(SHAPER)
    block = scene.element("block-C")
    guide = scene.element("guide-C")
    (s1, s2) = guide.surface
    yc = block.at[1]
    assert s1[1] == pytest.approx(s2[1]) and abs(abs(s1[1] - yc) - block.height_mm / 2) < 1e-9  # block on the guide
    for j in ("O1", "O3"):
        piv = scene.element(f"pivot-{j}")
        (g1, g2) = piv.ground_line
        assert min(g1[1], g2[1]) > piv.at[1]                                                   # ground below
        assert piv.hatch_region().hatch_segments()
    assert scene.element("block-A").at == scene.element("block-A").at   # the block on the rocker is drawn


def test_scheme_of_a_study_computes_only_positions():
    study = Study(PRESS, positions=12)
    ks.kinematic_scheme(study)
    assert study.computed == ["positions"]
    ks.velocity_plan_grid(study)
    assert study.computed == ["positions", "plans"]
    ks.velocity_table(study)
    ks.velocity_plan(study)
    assert study.computed == ["positions", "plans"]                     # cached: nothing built twice


def test_scheme_refusals():
    with pytest.raises(InputError, match="thick = 12"):
        ks.kinematic_scheme(PRESS, thick=12)
    with pytest.raises(InputError, match="needs .* but the sheet leaves"):
        ks.kinematic_scheme(PRESS, mu_l=0.001)
    with pytest.raises(InputError, match="expected a linkage problem"):
        ks.kinematic_scheme([0.1, 0.4])
    scene = ks.kinematic_scheme(PRESS, thick=None, trajectories=False, mu_l=0.004)
    assert not any(e.name.startswith("thick-") or e.name.startswith("path-") for e in scene.elements)


# ----------------------------------------------------------------------------- velocity plans: geometry

def _check_plan(rec, plans, k: int, mu: float, prefix: str) -> int:
    """Every vector of plan k: drawn length × μ_v = |v| (±0.001 mm); the polygons close. Returns the count."""
    images, vectors = ks._plan_layout(plans)
    xy = ks._image_xy(plans, images, k)
    ends = {}
    for v in vectors:
        gid = f"{prefix}vector-{v.start}{v.end}"
        value = float(np.hypot(*(xy[v.end] - xy[v.start])))
        paths, heads = rec.in_group(gid, "path"), rec.in_group(gid, "polygon")
        if value / mu < 1e-9:                                   # a zero vector is a dot
            (dot,) = rec.in_group(gid, "circle")
            assert not paths
            start = tip = dot.data[:2]
        else:
            start, tip = paths[0].data[0][0], heads[0].data[0]
        assert abs(math.dist(start, tip) - value / mu) <= 1e-3, (gid, math.dist(start, tip), value / mu)
        assert not paths or (paths[0].style.dash is None) == v.known     # known solid, found dashed
        ends.setdefault(v.end, []).append(tip)
        ends.setdefault(("start", v.start), []).append(start)
    pole = ends[("start", "p")][0]
    for label, tips in ends.items():
        if isinstance(label, tuple):
            continue
        for t in tips:                                          # p→x and y→x end at the same image x
            assert math.dist(t, tips[0]) <= 1e-9
    for v in vectors:                                           # y→x starts where p→y ends: the polygon closes
        if v.start != "p" and v.start in ends:
            assert math.dist(ends[("start", v.start)][0], ends[v.start][0]) <= 1e-9
    assert all(math.dist(s, pole) <= 1e-9 for s in ends[("start", "p")])
    return len(vectors)


@pytest.mark.parametrize("case", [PRESS, SHAPER], ids=["press", "shaper"])
def test_grid_vectors_to_scale_and_polygons_close(case):
    scene = ks.velocity_plan_grid(case)
    (mu_v,) = scene.scales()
    plans = case.mechanism.velocity_plans(12, omega_1=case.omega_m)
    rec = record(scene)
    n = sum(_check_plan(rec, plans, k, mu_v.per_mm, f"plan-{k}-") for k in range(12))
    assert n == 12 * (4 if case is PRESS else 8)
    # one cell per position, headed by its number; every image labelled
    assert [scene.element(f"plan-{k}-heading").text for k in (0, 1, 11)] == ["0 (12)", "1", "11"]
    labels = " ".join(p.text for p in scene.primitives() if isinstance(p, Label))
    assert ("p, b" if case is PRESS else "p, a3, b, c, s3, s4") in labels     # at the pole in position 0


@pytest.mark.parametrize("case, k", [(PRESS, 1), (PRESS, 4), (SHAPER, 2), (SHAPER, 9)])
def test_large_plan_construction_lines_pass_through_the_points_they_find(case, k):
    scene = ks.velocity_plan(case, position=k)
    (mu_v,) = scene.scales()
    plans = case.mechanism.velocity_plans(12, omega_1=case.omega_m)
    rec = record(scene)
    assert _check_plan(rec, plans, k, mu_v.per_mm, "") >= 4
    tips = {}
    for e in scene.elements:
        if isinstance(e, Vector):
            tips[e.name.split("-")[1][1:] if e.name.startswith("vector-p") else None] = e.end
    found = 0
    for name, c in plans.constructions.items():
        if c.method != "intersection":
            continue
        X = np.asarray(tips[c.label])
        for ln in c.lines:
            seg = scene.element(f"line-{name}-{ln.through}")
            (p0, p1), = [call.data[0] for call in rec.in_group(f"line-{name}-{ln.through}", "path")]
            a, b = np.asarray(p0), np.asarray(p1)
            d = (b - a) / np.hypot(*(b - a))
            dist = abs((X - a)[0] * d[1] - (X - a)[1] * d[0])
            assert dist <= 1e-3, (name, ln.through, dist)           # through the point it finds ...
            through = np.asarray(tips[ln.through]) if ln.through != "p" else np.asarray(scene.element("pole").at)
            assert abs((through - a)[0] * d[1] - (through - a)[1] * d[0]) <= 1e-3   # ... and its own point
            assert seg.style.width_mm < 0.25                         # drawn thin
            found += 1
    assert found == 2 * sum(c.method == "intersection" for c in plans.constructions.values())
    # the table tabulates the drawn lengths and the values length × μ_v
    rows = scene.element("table").rows[1:]
    for row in rows:
        length = float(row[1])
        value = float(row[2].split("=")[1])
        assert value == pytest.approx(length * mu_v.per_mm, abs=0.01 * mu_v.per_mm + 1e-3)


def test_large_plan_equations_and_angular_velocities():
    scene = ks.velocity_plan(PRESS, position=1, notation="en")
    texts = [markup.plain(e.text) for e in scene.elements if e.name.startswith(("equation-", "omega-"))]
    assert "vB = vA + vBA;  vBA ⊥ AB,  vB ∥ guide" in texts
    assert "as2/ab = AS2/AB" in texts
    plans = PRESS.mechanism.velocity_plans(12, omega_1=PRESS.omega_m)
    w2 = abs(float(plans.omega(2)[1]))
    (omega,) = [t for t in texts if t.startswith("ω2")]
    assert f"{w2:.4g}" in omega and "clockwise" in omega
    assert ks.fullest_position(plans) == 1 and ks.velocity_plan(PRESS).title.endswith("position 1")


@pytest.mark.hard
def test_dead_centre_plan_is_degenerate_not_nan():
    scene = ks.velocity_plan(PRESS, position=0, mu_v=0.05)
    rec = record(scene)
    assert rec.in_group("vector-pb", "circle") and not rec.in_group("vector-pb", "path")    # b at p
    names = [e.text for e in scene.elements if e.name.startswith("name-")]
    assert "p, b" in names
    assert "v_{B} = 0" in scene.element("table").rows[2][2].replace("0.000", "0")


@pytest.mark.hard
def test_ill_conditioned_positions_are_marked_everywhere():
    fb, pos = toggle_four_bar()
    plans = fb.velocity_plans(pos)
    assert plans.ill_conditioned.tolist() == [False] * 5 + [True, False]
    grid = ks.velocity_plan_grid(plans, notation="en")
    cell = grid.element("plan-5-cell")
    assert cell.style.dash is not None and cell.style.width_mm >= 0.5
    assert "ill-conditioned" in grid.element("plan-5-heading").text
    assert "off the scale" in grid.element("plan-5-value-0").text          # 10⁴ times too long for its cell
    assert "ill-conditioned" in grid.element("legend").text
    assert grid.element("plan-6-cell").style.dash is None
    t = ks.velocity_rows(plans)
    assert t.ill_conditioned.tolist() == plans.ill_conditioned.tolist() and np.isfinite(t.values).all()
    md = ks.velocity_table_markdown(plans)
    assert "| 5 * |" in md and "ill-conditioned" in md
    drawn = ks.velocity_table(plans).element("table").rows
    assert drawn[6][0] == "5 *"
    big = ks.velocity_plan(plans, position=5)
    assert "analytic derivative" in big.element("ill-conditioned").text
    ks.kinematic_scheme(pos)                                             # arbitrary angles draw too


@given(r=st.floats(0.02, 0.2), ratio=st.floats(2.2, 6.0), e=st.floats(-0.5, 0.5), k=st.integers(1, 11),
       sense=st.sampled_from([1, -1]))
@settings(max_examples=12, deadline=None)
def test_any_slider_crank_plan_is_to_scale_and_closes(r, ratio, e, k, sense):
    mech = SliderCrank(r=r, l=ratio * r, e=e * r, sense=sense, points={"S2": ("AB", 0.4 * ratio * r)})
    plans = mech.velocity_plans(12, omega_1=7.0)
    scene = ks.velocity_plan(plans, position=k)
    _check_plan(record(scene), plans, k, scene.scales()[0].per_mm, "")
    grid = ks.velocity_plan_grid(plans)
    rec = record(grid)
    for kk in (0, k):
        _check_plan(rec, plans, kk, grid.scales()[0].per_mm, f"plan-{kk}-")


def test_plan_refusals():
    with pytest.raises(InputError, match="position 12: give one of the positions 0…11"):
        ks.velocity_plan(PRESS, position=12)
    with pytest.raises(InputError, match="does not fit"):
        ks.velocity_plan(PRESS, position=1, mu_v=0.001)
    with pytest.raises(InputError, match="does not fit"):
        ks.velocity_plan_grid(PRESS, mu_v=0.01)
    with pytest.raises(InputError, match="omega_1"):
        ks.velocity_plan_grid(PRESS.mechanism, omega_1=-1.0)
    plans = PRESS.mechanism.velocity_plans(12, omega_1=2.0)
    with pytest.raises(InputError, match="for ω₁ = 2 rad/s, not 3"):
        ks.velocity_plan_grid(plans, omega_1=3.0)


# ----------------------------------------------------------------------------- the table

@pytest.mark.parametrize("case", [PRESS, SHAPER], ids=["press", "shaper"])
def test_table_is_the_velocity_plans_and_markdown_has_the_same_rows(case):
    t = ks.velocity_rows(case)
    plans = case.mechanism.velocity_plans(12, omega_1=case.omega_m)
    rows = [i for i, lab in enumerate(t.labels) if "′" not in lab]
    out = next(iter(case.mechanism.guides))
    np.testing.assert_allclose(t.values[rows, t.columns.index(f"v_{out}") - 1], plans.v_along_guide(out)[:12],
                               atol=1e-12)
    last = max(case.mechanism.link_numbers)
    np.testing.assert_allclose(t.values[rows, t.columns.index(f"omega_{last}") - 1], plans.omega(last)[:12],
                               atol=1e-12)
    ext = t.labels.index("6′" if case is PRESS else "7′")
    assert t.values[ext, t.columns.index(f"v_{out}") - 1] == 0.0                 # the slider stops there
    assert list(t.values[:, 0]) == sorted(t.values[:, 0])                         # in order of φ
    drawn = ks.velocity_table(case).element("table").rows
    md = ks.velocity_table_markdown(case).splitlines()
    assert len(drawn) == len(t.labels) + 1 and md[0].count("|") == len(drawn[0]) + 1
    for row, line in zip(drawn[1:], md[2:]):
        assert line == "| " + " | ".join(row) + " |"
    assert "v_{BA}" in drawn[0][5] if case is PRESS else "v_{CB}" in " ".join(drawn[0])


def test_table_in_russian_uses_decimal_commas_and_russian_units():
    rows = ks.velocity_table(PRESS, notation="ru").element("table").rows
    assert rows[0][0] == "Положение" and rows[0][2] == "v_{A}, м/с" and rows[0][-1] == "ω_{2}, рад/с"
    assert rows[2][3] == "−1,901"


# ----------------------------------------------------------------------------- the command line

@pytest.fixture
def run(capsys):
    def _run(*argv):
        rc = cli.main(["kinematics", *map(str, argv)])
        out, err = capsys.readouterr()
        return rc, out, err
    return _run


def test_cli_writes_the_figures_and_refuses_to_overwrite(run, tmp_path):
    case = DATA / "slider_crank_press.json"
    out = tmp_path / "figs"
    rc, stdout, err = run(case, "--figures", out, "--json")
    assert rc == 0 and err == ""
    res = json.loads(stdout)
    names = sorted(p.name for p in out.iterdir())
    assert names == ["slider_crank_press_acceleration_plan_1.svg", "slider_crank_press_acceleration_plans.svg",
                     "slider_crank_press_acceleration_table.svg",
                     "slider_crank_press_kinematic_scheme.svg", "slider_crank_press_velocity_plan_1.svg",
                     "slider_crank_press_velocity_plans.svg", "slider_crank_press_velocity_table.md",
                     "slider_crank_press_velocity_table.svg"]
    assert sorted(pathlib.Path(p).name for p in res["figures"]) == names and len(res["positions"]) == 13
    scheme = (out / names[3]).read_bytes()
    assert scheme == svg.to_bytes(ks.kinematic_scheme(Study(PRESS)))
    before = {p.name: p.stat().st_mtime_ns for p in out.iterdir()}
    (out / names[1]).unlink()
    rc, stdout, err = run(case, "--figures", out, "--lang", "ru")
    assert rc == 2 and stdout == "" and "exist; use --force" in err and len(err.strip().splitlines()) == 1
    assert sorted(p.name for p in out.iterdir()) == sorted(set(names) - {names[1]})          # nothing written
    assert all(p.stat().st_mtime_ns == before[p.name] for p in out.iterdir())
    rc, stdout, _ = run(case, "--figures", out, "--lang", "ru", "--force")
    assert rc == 0 and stdout.splitlines()[-1].startswith("wrote ")
    assert "План механизма" in (out / names[3]).read_text(encoding="utf-8")
    assert "План ускорений" in (out / names[0]).read_text(encoding="utf-8")


def test_cli_an_error_writes_nothing(run, tmp_path):
    out = tmp_path / "figs"
    rc, stdout, err = run(DATA / "shaper.json", "--figures", out, "--plan-position", 12)
    assert rc == 2 and stdout == "" and "position 12" in err
    assert not out.exists()
    rc, _, err = run(DATA / "shaper.json", "--lang", "ru")
    assert rc == 2 and "add --figures DIR" in err
    (tmp_path / "file").write_text("x", encoding="utf-8")
    rc, _, err = run(DATA / "shaper.json", "--figures", tmp_path / "file")
    assert rc == 2 and "not a directory" in err


@pytest.mark.parametrize("fmt, magic", [("png", b"\x89PNG"), ("pdf", b"%PDF")])
def test_cli_png_and_pdf(run, tmp_path, fmt, magic):
    rc, _, _ = run(DATA / "shaper.json", "--figures", tmp_path, "--format", fmt, "-m", 6, "--plan-position", 2)
    assert rc == 0
    files = sorted(tmp_path.glob(f"*.{fmt}"))
    assert [p.name for p in files] == [f"shaper_{n}.{fmt}" for n in (
        "acceleration_plan_2", "acceleration_plans", "acceleration_table", "kinematic_scheme", "velocity_plan_2",
        "velocity_plans", "velocity_table")]
    assert all(p.read_bytes()[:4] == magic for p in files)
    assert "| 0 (6) |" in (tmp_path / "shaper_velocity_table.md").read_text(encoding="utf-8")
