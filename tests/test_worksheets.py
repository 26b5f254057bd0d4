"""Worksheets: variants from a seed with nice numbers, student and key pages drawn to scale, class files."""

import argparse
import json
import math
import xml.etree.ElementTree as ET
from fractions import Fraction

import numpy as np
import pytest
from figure_checks import assert_fits_and_labels_apart
from hypothesis import given, settings, strategies as st

from graphmethods.cli import worksheet as cli_worksheet
from graphmethods.errors import InputError, OutputExistsError
from graphmethods.render import svg
from graphmethods.render.recording import record
from graphmethods.scene import markup, notation as get_notation
from graphmethods.scene.primitives import Label
from graphmethods.sheets import worksheets as ws

PROFILES = ("en", "ru", "zh")
CONVENIENT = {1.0, 2.0, 2.5, 4.0, 5.0}
SVG_NS = "{http://www.w3.org/2000/svg}"


def convenient(x: float) -> bool:
    k = math.floor(math.log10(x))
    return round(x / 10.0**k, 9) in CONVENIENT


def pages(kind, seed=1, count=2):
    return [(v, nt, ws.student_page(v, notation=nt), ws.key_page(v, notation=nt))
            for v in ws.variants(kind, count=count, seed=seed) for nt in PROFILES]


ALL = {kind: pages(kind) for kind in ws.KINDS}


# ----------------------------------------------------------------------------- variants

@pytest.mark.parametrize("kind", ws.KINDS)
def test_variants_are_reproducible_independent_of_the_batch_size_and_differ(kind):
    a = ws.variants(kind, count=6, seed=11)
    b = ws.variants(kind, count=3, seed=11)
    assert [v.data() for v in a[:3]] == [v.data() for v in b]
    assert ws.variant(kind, seed=11, number=5).data() == a[4].data()
    assert ws.parse_id(f"{kind}:11:2").data() == a[1].data()
    datas = [json.dumps({k: x for k, x in v.data().items() if k != "number"}, sort_keys=True) for v in a]
    assert len(set(datas)) == len(datas)                           # the variants of a batch differ
    assert ws.variants(kind, count=2, seed=12)[0].data() != a[0].data()


def test_no_global_random_state_is_used():
    # the legacy global state is used here on purpose: the test is that the generators leave it alone
    np.random.seed(0)  # noqa: NPY002
    state = np.random.get_state()[1].copy()  # noqa: NPY002
    ws.variants("indicator", count=3, seed=5)
    assert (np.random.get_state()[1] == state).all()  # noqa: NPY002


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 10**6), number=st.integers(1, 40))
def test_indicator_numbers_are_nice(seed, number):
    v = ws.variant("indicator", seed=seed, number=number)
    assert all(isinstance(f, int) and f % 10 == 0 and f != 0 for f in v.areas_mm2)
    assert sum(v.areas_mm2) == 0                                    # closes exactly
    signs = np.sign(v.areas_mm2)
    assert (signs[1:] != signs[:-1]).all()                         # gains and losses alternate
    k = v.mu_M * v.mu_phi
    assert k != 1.0                                                  # forgetting μ_M·μ_φ shows
    work = v.excess_work.work
    assert np.allclose(work * 2, np.round(work * 2), atol=1e-9)     # works in whole halves of a joule
    assert all(convenient(x) for x in (v.mu_M, v.mu_phi, v.mu_E, v.J_e))
    assert Fraction(v.delta).numerator == 1
    E = v.excess_work.E
    assert abs(float(E[-1])) < 1e-9
    inner = np.sort(E[1:-1])
    assert inner[-1] - max(inner[-2], 0) >= 30 * k - 1e-9         # unique extremes, 3 units apart
    assert v.answers()["J_F"] > 0


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 10**6), number=st.integers(1, 40))
def test_step_moment_numbers_are_nice(seed, number):
    v = ws.variant("step-moment", seed=seed, number=number)
    assert abs(v.M_d * 4 - round(v.M_d * 4)) < 1e-9                 # M_d a multiple of 0.25 N·m
    assert all(float(m).is_integer() for m in v.M_r)                # whole N·m at every knot
    assert all(p % 15 == 0 for p in v.phi_deg) and v.phi_deg[0] == 0 and v.phi_deg[-1] == 360
    assert convenient(v.mu_M) and v.mu_phi_deg == 2.5
    c = v.excess_work
    assert c.work.size >= 2 and abs(c.residual) <= 1e-9 * np.abs(c.work).sum()
    assert v.answers()["J_F"] > 0


def test_plan_and_energy_mass_numbers_are_nice():
    for v in ws.variants("velocity-plan", count=10, seed=3):
        assert convenient(v.mu_l) and convenient(v.mu_v)
        assert v.phi_deg % 15 == 0 and float(v.omega_1).is_integer()
        a = v.answers()
        assert a["v_A"] == pytest.approx(v.omega_1 * v.r, rel=1e-12)
        assert 40.0 <= a["pa_mm"] <= 85.0                            # a plan of a readable size
    for v in ws.variants("wittenbauer", count=4, seed=3):
        assert convenient(v.mu_J) and convenient(v.mu_T)
        assert v.J_e[0] == v.J_e[-1] and v.delta_T[0] == v.delta_T[-1] == 0.0
        assert all(round(x, 3) == x for x in v.J_e) and all(float(x).is_integer() for x in v.delta_T)
        assert v.answers()["kl_mm"] > 20.0


def test_problem_files_round_trip_and_bad_ones_are_refused():
    for kind in ws.KINDS:
        v = ws.variants(kind, count=1, seed=4)[0]
        back = ws.variant_from_dict(json.loads(v.to_json()))
        assert back.data() == v.data()
        got, want = back.answers(), v.answers()
        assert got.keys() == want.keys()
        for key, value in want.items():       # key by key: pytest.approx refuses dicts holding lists
            numeric = isinstance(value, (int, float, list, tuple)) and not isinstance(value, bool) and \
                all(isinstance(x, (int, float)) for x in (value if isinstance(value, (list, tuple)) else [value]))
            assert got[key] == (pytest.approx(value, rel=1e-12) if numeric else value), (kind, key)
    d = json.loads(ws.variants("indicator", count=1, seed=4)[0].to_json())
    with pytest.raises(InputError, match="format"):
        ws.variant_from_dict({**d, "format": "other"})
    with pytest.raises(InputError, match="unknown 'bogus'"):
        ws.variant_from_dict({**d, "data": {**d["data"], "bogus": 1}})
    with pytest.raises(InputError, match="does not close"):
        ws.variant_from_dict({**d, "data": {**d["data"], "areas_mm2": [10, -30, 10]}})
    with pytest.raises(InputError, match="unknown worksheet kind"):
        ws.variants("flywheel", count=1, seed=0)
    with pytest.raises(InputError, match="≥ 0"):
        ws.variants("indicator", count=1, seed=-1)


# ----------------------------------------------------------------------------- pages

@pytest.mark.parametrize("kind", ws.KINDS)
def test_pages_stay_in_the_frame_without_overlapping_labels_and_caption_every_axis(kind):
    for v, nt, student, key in ALL[kind]:
        for scene in (student, key):
            assert_fits_and_labels_apart(scene, f"{v.id} {nt}")
            labels = [p for p in scene.primitives() if isinstance(p, Label)]
            texts = " ".join(lab.text for lab in labels)
            for sc in scene.scales():
                assert markup.plain(sc.caption(nt)) in texts, (v.id, nt, sc.caption(nt))
            for axis in scene.axes():
                assert markup.plain(axis.scale.caption(nt)) in texts


@pytest.mark.parametrize("kind", ws.KINDS)
def test_the_key_is_the_student_page_filled_in(kind):
    """Grid, axes and every element of the student's page sit at the same place on the key (the paper's
    lines too; each page clears its paper behind its own lettering, so the grids' holes differ)."""
    from dataclasses import replace

    def lines(e):
        return replace(e, holes=()) if isinstance(e, ws.Grid) else e

    for v, nt, student, key in ALL[kind]:
        s_els = {e.name: lines(e) for e in student.elements}
        k_els = {e.name: lines(e) for e in key.elements}
        for name in ("grid", "axis-E", "axis-phi", "axis-M", "axis-J", "axis-T", "data-row-0", "answers-row-0"):
            if name in s_els:
                assert s_els[name] == k_els[name], (v.id, nt, name)
        assert len(key.elements) > len(student.elements)
        student_text = " ".join(p.text for p in student.primitives() if isinstance(p, Label))
        words = get_notation(nt)
        assert words.word("worksheets.key") not in student_text and words.word("worksheets.name") in student_text


def test_indicator_key_draws_each_work_to_mu_E():
    v = ws.variants("indicator", count=1, seed=2)[0]
    rec = record(ws.key_page(v))
    L = v.excess_work.labels
    for i, A in enumerate(v.excess_work.work):
        assert rec.vector_length_mm(f"vector-{L[i]}{L[i + 1]}") == pytest.approx(abs(A) / v.mu_E, abs=1e-3)
    ids = rec.group_ids()
    assert "extremes-dimension" in ids and "axis-E" in ids


def test_step_moment_key_hatches_each_interval_with_the_right_area():
    v = ws.variants("step-moment", count=3, seed=2)[2]
    key = ws.key_page(v)
    c = v.excess_work
    for i, A in enumerate(c.work):
        region = key.element(f"moments-region-{i + 1}")
        assert region.shape().area == pytest.approx(abs(A) / (v.mu_M * v.mu_phi), rel=1e-9)
    per = ws.region_perimeters_mm(c, mu_M=v.mu_M, mu_phi=v.mu_phi)
    for i in range(c.work.size):
        assert per[i] == pytest.approx(key.element(f"moments-region-{i + 1}").shape().length, rel=1e-9)


def test_plan_key_vectors_are_velocities_over_mu_v_and_the_polygon_closes():
    for v in ws.variants("velocity-plan", count=4, seed=8):
        rec = record(ws.key_page(v))
        a = v.answers()
        for seg in ("pa", "pb", "ab", "ps2"):
            assert rec.vector_length_mm(f"plan-{seg}") == pytest.approx(a[f"{seg}_mm"], abs=1e-3)
        key = ws.key_page(v)
        pa, pb, ab = (key.element(f"plan-{s}") for s in ("pa", "pb", "ab"))
        assert pa.start == pb.start and pa.end == ab.start and ab.end == pytest.approx(pb.end, abs=1e-9)
        guide = key.element("plan-line-guide")
        assert guide.start[1] == guide.end[1] == pytest.approx(pb.end[1], abs=1e-9)       # b on the line ∥ guide


def test_energy_mass_key_rays_touch_and_bound_the_curve_and_kl_gives_J_F():
    for v in ws.variants("wittenbauer", count=3, seed=6):
        key = ws.key_page(v)
        r = v.result
        curve = np.asarray(key.element("key-curve").points)
        assert len(curve) == v.m
        for name, upper in (("key-ray-max", True), ("key-ray-min", False)):
            ray = key.element(name)
            (x0, y0), (x1, y1) = ray.start, ray.end
            s = (y1 - y0) / (x1 - x0)
            d = curve[:, 1] - (y0 + s * (curve[:, 0] - x0))            # page y grows downwards
            assert (d >= -1e-3).all() if upper else (d <= 1e-3).all()
            assert np.abs(d).min() <= 1e-3
            assert -s == pytest.approx(r.tan_psi_max if upper else r.tan_psi_min, rel=1e-9)
        k, l = key.element("key-point-k").at, key.element("key-point-l").at
        origin = key.element("axis-J").origin
        assert k[0] == l[0] == origin[0]
        assert origin == key.element("axis-T").origin == ws.student_page(v).element("axis-J").origin
        kl = abs(l[1] - k[1])
        assert kl == pytest.approx(r.kl_mm, abs=1e-3)
        w = v.omega_m
        assert v.mu_T * kl / (w * w * v.delta_value) == pytest.approx(r.J_F, rel=1e-6)
        box = key.element("grid").box
        for name in ("key-ray-max", "key-ray-min"):
            for x, y in (key.element(name).start, key.element(name).end):
                assert box[0] - 1e-6 <= x <= box[2] + 1e-6 and box[1] - 1e-6 <= y <= box[3] + 1e-6


def test_one_switch_changes_the_language_of_the_whole_page():
    v = ws.variants("wittenbauer", count=1, seed=1)[0]
    text = {nt: " ".join(p.text for p in ws.student_page(v, notation=nt).primitives() if isinstance(p, Label))
            for nt in PROFILES}
    assert "Position" in text["en"] and "Положение" in text["ru"] and "位置" in text["zh"]
    assert "кг·м²" in text["ru"] and "0,5" in text["ru"] and "Дж" in text["ru"]
    assert "Position" not in text["ru"] + text["zh"]


def test_wrap_keeps_lines_within_the_width():
    text = "The areas between the equivalent driving and resisting moment curves ΔW_{max} = 575 J " * 3
    for width in (40.0, 90.0, 180.0):
        for line in ws.wrap(text, width, 3.2):
            assert markup.text_width_mm(line, 3.2) <= width or " " not in line
    assert ws.wrap("", 50.0, 3.2) == []
    zh = ws.wrap("在一个运动循环中，等效驱动力矩与等效阻抗力矩曲线之间的各块面积是在图上量得的。", 30.0, 3.2)
    assert all(not line.startswith(("，", "。")) for line in zh) and "".join(zh).endswith("。")


@settings(max_examples=15, deadline=None)
@given(kind=st.sampled_from(ws.KINDS), seed=st.integers(0, 10**6), nt=st.sampled_from(PROFILES))
def test_any_variant_builds_in_every_language(kind, seed, nt):
    v = ws.variant(kind, seed=seed, number=1 + seed % 7)
    for page in (ws.student_page(v, notation=nt), ws.key_page(v, notation=nt)):
        x0, y0, x1, y1 = page.page.inner_box()
        bx = page.bbox()
        assert bx[0] >= x0 and bx[1] >= y0 and bx[2] <= x1 and bx[3] <= y1


# ----------------------------------------------------------------------------- the class files

def _args(*argv):
    p = argparse.ArgumentParser()
    sub = p.add_subparsers()
    cli_worksheet.add_parser(sub)
    return p.parse_args(["worksheet", *argv])


def test_two_runs_give_identical_bytes_of_the_pdf_and_every_svg(tmp_path):
    for out in ("a", "b"):
        assert cli_worksheet.run(_args("velocity-plan", "--variants", "2", "--seed", "9", "--lang", "zh", "--out",
                                       str(tmp_path / out), "--quiet")) == 0
    a = sorted(p.relative_to(tmp_path / "a") for p in (tmp_path / "a").rglob("*") if p.is_file())
    b = sorted(p.relative_to(tmp_path / "b") for p in (tmp_path / "b").rglob("*") if p.is_file())
    assert a == b and len(a) == 1 + 4 + 2 + 1
    assert [str(x) for x in a[-2:]] == ["velocity-plan-answers.toml", "velocity-plan-zh.pdf"]
    for rel in a:
        assert (tmp_path / "a" / rel).read_bytes() == (tmp_path / "b" / rel).read_bytes(), rel
    pdf = (tmp_path / "a" / "velocity-plan-zh.pdf").read_bytes()
    assert pdf.startswith(b"%PDF") and pdf.count(b"/Type /Page ") == 4
    root = ET.fromstring((tmp_path / "a" / "svg" / "velocity-plan-01-key.svg").read_bytes())
    assert root.get("width") == "210mm" and root.get("viewBox") == "0 0 210 297"
    problem = json.loads((tmp_path / "a" / "problems" / "velocity-plan-02.json").read_text(encoding="utf-8"))
    assert problem["id"] == "velocity-plan:9:2" and problem["format"] == ws.PROBLEM_FORMAT


def test_the_cli_writes_exactly_the_contents_the_figure_layer_gives(tmp_path):
    sheet = ws.worksheet("wittenbauer", variants=1, seed=4, notation="ru")
    files = ws.contents(sheet, dxf=True)
    paths = cli_worksheet.write_worksheet(sheet, tmp_path / "set", dxf=True)
    written = {p.relative_to(tmp_path / "set").as_posix(): p.read_bytes()
               for p in (tmp_path / "set").rglob("*") if p.is_file()}
    assert written == files
    assert [p.relative_to(tmp_path / "set").as_posix() for p in paths] == ws.output_names("wittenbauer", "ru", 1)
    assert sorted(n for n in files if n.startswith("dxf/")) == sorted(ws.dxf_names("wittenbauer", 1))


def test_order_in_the_pdf_is_students_then_keys():
    sheet = ws.worksheet("indicator", variants=3, seed=1)
    assert [s.name for s in sheet.scenes] == ["indicator-student-01", "indicator-student-02", "indicator-student-03",
                                              "indicator-key-01", "indicator-key-02", "indicator-key-03"]


def test_refuses_to_overwrite_and_leaves_nothing_partial(tmp_path, monkeypatch, capsys):
    out = tmp_path / "class"
    assert cli_worksheet.run(_args("indicator", "--variants", "1", "--out", str(out))) == 0
    err = capsys.readouterr().err
    assert "worksheet: pages 1/1" in err and "PDF pages 2/2" in err                     # progress on stderr
    before = {p: p.read_bytes() for p in out.rglob("*") if p.is_file()}
    with pytest.raises(OutputExistsError, match="--force"):
        cli_worksheet.run(_args("indicator", "--variants", "1", "--out", str(out), "--quiet"))
    assert {p: p.read_bytes() for p in out.rglob("*") if p.is_file()} == before
    # an error half-way leaves no file and no temporary folder behind
    calls = {"n": 0}
    real = svg.to_bytes

    def failing(scene):
        calls["n"] += 1
        if calls["n"] == 3:
            raise InputError("disk full (simulated)")
        return real(scene)

    monkeypatch.setattr(svg, "to_bytes", failing)
    fresh = tmp_path / "fresh"
    with pytest.raises(InputError, match="simulated"):
        cli_worksheet.run(_args("step-moment", "--variants", "2", "--out", str(fresh), "--quiet"))
    assert not fresh.exists() and sorted(p.name for p in tmp_path.iterdir()) == ["class"]
    calls["n"] = 0
    with pytest.raises(InputError, match="simulated"):
        cli_worksheet.run(_args("indicator", "--variants", "2", "--out", str(out), "--force", "--quiet"))
    assert {p: p.read_bytes() for p in out.rglob("*") if p.is_file()} == before
    monkeypatch.setattr(svg, "to_bytes", real)
    assert cli_worksheet.run(_args("indicator", "--variants", "2", "--out", str(out), "--force", "--quiet")) == 0
    assert (out / "svg" / "indicator-02-key.svg").exists()


def test_progress_is_reported_for_each_stage():
    seen = []
    sheet = ws.worksheet("indicator", variants=4, seed=2, progress=lambda d, t, w: seen.append((d, t, w)))
    assert seen == [(k, 4, "pages") for k in range(1, 5)]
    assert len(sheet.students) == len(sheet.keys) == 4
