"""The ``cam`` worksheet kind (issue 29): variants from a seed, the student's page and the key, their numbers
against the exact design, the drafting standard of the A4 pages, the class set's files."""

import math

import numpy as np
import pytest

from graphmethods.cli import main
from graphmethods.kinematics.cam import design
from graphmethods.render.recording import record
from graphmethods.sheets import worksheets as ws
from graphmethods.sheets.engine.quality import faults, measure
from graphmethods.sheets.worksheets.cam import CamVariant, positions_of


@pytest.fixture(scope="module")
def batch():
    return ws.variants("cam", count=4, seed=3)


def test_variants_are_reproducible_and_do_not_depend_on_the_count(batch):
    again = ws.variants("cam", count=2, seed=3)
    assert [v.data() for v in again] == [v.data() for v in batch[:2]]
    assert len({str(v.data()) for v in batch}) == len(batch)
    assert ws.parse_id("cam:3:2").data() == batch[1].data()


def test_variants_have_nice_numbers_and_drawable_cams(batch):
    for v in batch:
        assert v.mu_l in (0.0002, 0.0004, 0.0005, 0.001, 0.002, 0.0025, 0.004, 0.005)
        assert v.rise_law in ("parabolic", "harmonic", "cycloidal", "polynomial_345")
        cam = v.cam
        if v.contact == "roller":
            assert cam.base_radius >= 1.3 * v.roller_radius and not cam.undercut
        assert cam.alpha_max_rise_deg <= v.alpha_max_deg + 1e-9
        assert cam.alpha_max_return_deg <= v.alpha_return_max_deg + 1e-9


def test_the_key_is_the_exact_design_at_the_marked_positions(batch):
    for v in batch:
        a, cam = v.answers(), design(v.problem)
        assert a["base_radius"] == pytest.approx(cam.base_radius, abs=1e-12)
        phi = np.asarray(v.positions_deg)
        s = v.problem.motion(phi)[0]
        assert a["s_mm"] == pytest.approx((s / v.mu_l).tolist(), abs=1e-8)
        top = list(phi).index(v.rise_deg)                   # the end of the rise: s = h
        assert a["s_mm"][top] == pytest.approx(v.lift / v.mu_l, abs=1e-9)
        if v.contact == "roller":
            assert a["pitch_base_radius"] - a["base_radius"] == pytest.approx(v.roller_radius, abs=1e-12)
        else:
            assert "pitch_base_radius" not in a


def test_marked_positions_divide_the_rise_and_return():
    v = CamVariant(seed=0, number=1, contact="knife", offset=0.0, roller_radius=0.0, lift=0.02, rise_deg=120.0,
                   dwell_deg=60.0, return_deg=90.0, rise_law="cycloidal", return_law="harmonic", alpha_max_deg=30.0,
                   alpha_return_max_deg=70.0, n_div=4, mu_l=0.001)
    assert positions_of(v.problem, 4) == (0.0, 30.0, 60.0, 90.0, 120.0, 180.0, 202.5, 225.0, 247.5, 270.0)


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_pages_meet_the_a4_drafting_standard(batch, lang):
    for v in batch[:2]:
        for page in (ws.student_page(v, notation=lang), ws.key_page(v, notation=lang)):
            assert faults(measure(page)) == [], (v.id, lang, page.name)


def test_the_key_prints_the_answers_and_the_student_page_does_not(batch):
    v = next(x for x in batch if x.contact == "roller")
    from graphmethods.scene import notation

    nt = notation("en")
    rb = nt.number(v.cam.base_radius * 1000, sig=4)
    key = record(ws.key_page(v, notation="en")).texts()
    student = record(ws.student_page(v, notation="en")).texts()
    assert rb in key and rb not in student
    assert any("μ" in t and str(v.mu_l) in t for t in student)          # the student's scale is stated
    names = [e.name for e in ws.student_page(v, notation="en").elements]
    assert "inv-O" in names and "inv-profile" not in names and "c-curve" not in names
    assert "inv-profile" in [e.name for e in ws.key_page(v, notation="en").elements]


def test_the_key_page_draws_the_inversion_to_scale(batch):
    v = next(x for x in batch if x.contact == "roller")
    page = ws.key_page(v, notation="en")
    el = {e.name: e for e in page.elements}
    circ = el["inv-base-circle"].circles[0]
    assert circ[2] * v.mu_l == pytest.approx(v.cam.base_radius, rel=1e-9)
    rollers = el["inv-rollers"].circles
    O = np.array(circ[:2])
    s0 = math.sqrt(v.cam.pitch_base_radius ** 2 - v.offset ** 2)
    for (x, y, r), s in zip(rollers, v.answers()["s_mm"]):          # roller centres at s₀ + s along each axis
        assert r * v.mu_l == pytest.approx(v.roller_radius, rel=1e-9)
        d = float(np.hypot(x - O[0], y - O[1])) * v.mu_l
        assert d == pytest.approx(math.hypot(v.offset, s0 + s * v.mu_l), abs=1e-6)


def test_worksheet_command_writes_the_class_set(tmp_path, capsys):
    out = tmp_path / "class"
    assert main(["worksheet", "cam", "--variants", "2", "--seed", "3", "-o", str(out), "--quiet"]) == 0
    assert (out / "cam-en.pdf").stat().st_size > 1000
    assert (out / "svg" / "cam-02-key.svg").exists() and (out / "problems" / "cam-01.json").exists()
    tpl = (out / "cam-answers.toml").read_text(encoding="utf-8")
    assert "[cam]" in tpl and "s_mm = []" in tpl and "base_radius = \"\"" in tpl
    first = (out / "svg" / "cam-01-student.svg").read_bytes()
    assert main(["worksheet", "cam", "--variants", "2", "--seed", "3", "-o", str(out), "--quiet", "--force"]) == 0
    assert (out / "svg" / "cam-01-student.svg").read_bytes() == first          # the same seed, the same bytes


def test_the_problem_file_is_a_cam_file_with_the_keys_numbers(tmp_path, capsys):
    import json

    v = ws.variant("cam", seed=3, number=2)
    f = tmp_path / "cam-02.json"
    f.write_text(v.to_json(), encoding="utf-8")
    assert main(["cam", str(f), "--json", "--phi-deg", ",".join(str(a) for a in v.positions_deg)]) == 0
    out = json.loads(capsys.readouterr().out)
    a = v.answers()
    assert out["base_radius"] == a["base_radius"] and out["pressure_angle_max_rise_deg"] == a["alpha_max_rise_deg"]
    assert [p["s"] / v.mu_l for p in out["positions"]] == pytest.approx(a["s_mm"], abs=1e-9)
    assert ws.variant_from_dict(json.loads(f.read_text(encoding="utf-8"))).data() == v.data()
