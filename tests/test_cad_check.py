"""Checking a drawing made in CAD (graphmethods.sheets.check.cad): the example drawings of
graphmethods/problems/data/drawings (made by tests/drawings/make_student_drawings.py as a student draws,
with planted mistakes) are read, measured and checked; exactly the planted mistakes are found."""

import math
import pathlib
import shutil

import numpy as np
import pytest

ezdxf = pytest.importorskip("ezdxf")

from graphmethods import cli  # noqa: E402
from graphmethods.errors import InputError  # noqa: E402
from graphmethods.render import svg  # noqa: E402
from graphmethods.render.recording import record  # noqa: E402
from graphmethods.sheets.check import cad  # noqa: E402
from graphmethods.sheets.check.classcheck import check_class, class_files  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
DRAWINGS = ROOT / "graphmethods" / "problems" / "data" / "drawings"
ANSWERS = ROOT / "graphmethods" / "problems" / "data" / "answers"

#: what tests/drawings/make_student_drawings.py planted: (new mistakes, their diagnosis, carried over)
#: what a reversed Coriolis component carries into the slotted lever's plan
_SLOTTED_CARRIED = {f"acceleration_plan.{k}" for k in ("at_A3O3_mm", "a_A3_mm", "a_A3_deg", "a_B_mm", "a_B_deg",
                                                        "a_S3_mm", "a_S3_deg", "epsilon_3")}
#: the items the W1 drawings with mistakes get wrong
_W1_WRONG = {"energy_indicator.arrows_mm[2]", "results.omega_max", "results.omega_min", "results.J_F"}

PLANTED = {
    "press_plan_correct.dxf": ("press", set(), set(), set()),
    "press_plan_mistakes.dxf": ("press", {"velocity_plan.ps2_mm", "drawing.ps2_deg", "results.v_B"}, {"scale_twice"},
                                {"results.v_S2"}),
    "press_wittenbauer_correct.dxf": ("press", set(), set(), set()),
    "press_wittenbauer_mistakes.dxf": ("press", {"energy_mass.kl_mm", "results.J_F"},
                                       {"J_e_not_subtracted", "n_as_omega"}, set()),
    "press_acc_correct.dxf": ("press", set(), set(), set()),
    "press_acc_mistakes.dxf": ("press", {"acceleration_plan.an_BA_deg"}, {"normal_reversed"},
                               {"acceleration_plan.at_BA_mm", "acceleration_plan.a_B_mm", "acceleration_plan.a_S2_mm",
                                "acceleration_plan.a_S2_deg", "acceleration_plan.epsilon_2"}),
    "slotted_lever_acc_correct.dxf": ("slotted-lever", set(), set(), set()),
    "slotted_lever_acc_mistakes.dxf": ("slotted-lever", {"acceleration_plan.ak_A3A2_deg"}, {"coriolis_reversed"},
                                       _SLOTTED_CARRIED),
    "slotted_lever_acc_mistakes.svg": ("slotted-lever", {"acceleration_plan.ak_A3A2_deg"}, {"coriolis_reversed"},
                                       _SLOTTED_CARRIED),
    "w1_correct.dxf": ("W1", set(), set(), set()),
    "w1_correct.svg": ("W1", set(), set(), set()),
    "w1_mistakes.dxf": ("W1", _W1_WRONG, {"sign_flipped", "delta_not_halved", "n_as_omega"}, {"results.delta_W_max"}),
    "w1_mistakes.svg": ("W1", _W1_WRONG, {"sign_flipped", "delta_not_halved", "n_as_omega"}, {"results.delta_W_max"}),
}


def press_velocities(phi, r=0.1, l=0.4, e=0.02, l_AS2=0.13, omega=2 * math.pi * 300 / 60):
    """The press's velocities written out by hand (independent of the package): |v_A|, |v_B|, |v_BA|, |v_S2|."""
    s, c = math.sin(phi), math.cos(phi)
    q = e - r * s
    w = math.sqrt(l * l - q * q)
    v_B = omega * (-r * s + q * r * c / w)
    omega_2 = omega * (-r * c / w)
    v_S2 = math.hypot(omega * (-r * s) + l_AS2 * omega_2 * (-q / l), omega * (r * c) + l_AS2 * omega_2 * (w / l))
    return {"pa": omega * r, "pb": abs(v_B), "ab": abs(omega_2) * l, "ps2": v_S2}


@pytest.mark.parametrize("name", sorted(PLANTED))
def test_exactly_the_planted_mistakes_are_found(name):
    problem, wrong, codes, carried = PLANTED[name]
    rep = cad.check_drawing(problem, DRAWINGS / name)
    assert {i.key for i in rep.wrong} == wrong
    assert {m.code for m in rep.mistakes} == codes
    assert {i.key for i in rep.carried} == carried
    assert len(rep.items) >= (6 if "wittenbauer" in name else 11 if "_acc_" in name else 12)   # every item read


def test_the_correct_plan_is_measured_within_half_a_millimetre():
    from graphmethods.kinematics import read_case

    case = read_case(ROOT / "graphmethods" / "problems" / "data" / "slider_crank_press.json")
    phi = float(case.mechanism.positions(m=12).phi[2])
    rep = cad.check_drawing("press", DRAWINGS / "press_plan_correct.dxf")
    sec = rep.answers["velocity_plan"]
    assert sec["mu_v"] == 0.05 and sec["position"] == 2                 # read from the texts on the sheet
    for seg, v in press_velocities(phi).items():
        assert sec[f"{seg}_mm"] == pytest.approx(v / 0.05, abs=0.5), seg
    assert set(rep.answers["results"]) == {"v_A", "v_B", "v_BA", "v_S2", "omega_2"}


def test_dxf_and_svg_of_one_staircase_read_alike():
    a = cad.check_drawing("W1", DRAWINGS / "w1_mistakes.dxf").answers
    b = cad.check_drawing("W1", DRAWINGS / "w1_mistakes.svg").answers
    assert a["energy_indicator"]["arrows_mm"] == pytest.approx(b["energy_indicator"]["arrows_mm"], abs=1e-3)
    assert a["results"] == b["results"] and a["energy_indicator"]["step_mm"] == pytest.approx(16.0, abs=0.05)
    works = np.array([-50, 550, 100, 125, -500, 25, -50]) / 5.0       # the drawn staircase, c–d flipped
    assert np.allclose(a["energy_indicator"]["arrows_mm"], works, atol=0.5)


def _without_labels(tmp_path) -> tuple[pathlib.Path, dict]:
    doc = ezdxf.readfile(DRAWINGS / "press_plan_correct.dxf")
    msp = doc.modelspace()
    letters = {}
    for e in list(msp.query("TEXT")):
        if e.dxf.text in ("p", "a", "b", "s2"):
            letters[e.dxf.text] = e
            msp.delete_entity(e)
    path = tmp_path / "unlabelled.dxf"
    doc.saveas(path)
    return path, letters


def test_missing_labels_ask_for_a_mapping(tmp_path):
    path, _ = _without_labels(tmp_path)
    with pytest.raises(InputError, match=r"no label p, a, b near an arrow end.*--point p=X,Y"):
        cad.check_drawing("press", path)
    labelled = cad.check_drawing("press", DRAWINGS / "press_plan_correct.dxf")
    ends = {k: tuple(v) for k, v in cad.name_points(cad.arrows(cad.read(DRAWINGS / "press_plan_correct.dxf")),
                                                     cad.notes(cad.read(DRAWINGS / "press_plan_correct.dxf")).labels,
                                                     ("p", "a", "b", "s2")).items()}
    rep = cad.check_drawing("press", path, points={k: (x + 0.2, y - 0.2) for k, (x, y) in ends.items()})
    assert [(i.key, i.verdict) for i in rep.items] == [(i.key, i.verdict) for i in labelled.items]
    rc = cli.main(["check", "press", str(path)] + [f"--point={k}={x:.2f},{y:.2f}" for k, (x, y) in ends.items()])
    assert rc == 0


def test_overlay_in_red_over_the_students_own_drawing(tmp_path):
    rep = cad.check_drawing("press", DRAWINGS / "press_plan_mistakes.dxf")
    student = ezdxf.readfile(DRAWINGS / "press_plan_mistakes.dxf")
    out = tmp_path / "o.dxf"
    out.write_bytes(cad.overlay_dxf(rep))
    doc = ezdxf.readfile(out)
    before = sorted((e.dxftype(), e.dxf.layer) for e in student.modelspace())
    kept = sorted((e.dxftype(), e.dxf.layer) for e in doc.modelspace() if e.dxf.layer != "CHECK")
    assert kept == before                                                   # the student's drawing is untouched
    check = [e for e in doc.modelspace() if e.dxf.layer == "CHECK"]
    assert check and all(e.dxf.true_color == int(cad.RED.lstrip("#"), 16) for e in check)
    pole = cad.name_points(cad.arrows(cad.read(DRAWINGS / "press_plan_mistakes.dxf")),
                           cad.notes(cad.read(DRAWINGS / "press_plan_mistakes.dxf")).labels, ("p",))["p"]
    (circle,) = [e for e in doc.groups.get("CHECK-check-plan-pole") if e.dxftype() == "CIRCLE"]
    assert math.dist((circle.dxf.center.x, circle.dxf.center.y), tuple(pole)) < 1e-3   # drawn where the student drew
    shaft = next(e for e in doc.groups.get("CHECK-check-plan-pa") if e.dxftype() == "LWPOLYLINE")
    head = next(e for e in doc.groups.get("CHECK-check-plan-pa") if e.dxftype() == "SOLID")
    start = shaft.get_points("xy")[0]
    assert math.dist(start, tuple(pole)) < 1e-3
    from graphmethods.kinematics import read_case

    case = read_case(ROOT / "graphmethods" / "problems" / "data" / "slider_crank_press.json")
    v_A = press_velocities(float(case.mechanism.positions(m=12).phi[2]))["pa"]
    assert math.dist(start, (head.dxf.vtx0.x, head.dxf.vtx0.y)) == pytest.approx(v_A / 0.05, abs=1e-3)
    scene = cad.overlay_on_drawing(rep)
    rec = record(scene)
    assert rec.group_ids()[0] == "student-drawing" and any(g.startswith("check-") for g in rec.group_ids())
    red = [c for c in rec.calls if c.kind == "text" and "check-" in "".join(c.groups)]
    assert red and all(c.data.color == cad.RED for c in red)
    assert "ps2 = 59.82 mm?" in "".join(rec.texts()) or "59.82" in "".join(rec.texts())
    assert svg.to_bytes(scene) == svg.to_bytes(cad.overlay_on_drawing(rep))


def test_bad_drawings_are_input_errors(tmp_path, capsys):
    bad = tmp_path / "bad.dxf"
    bad.write_text("this is not a drawing", encoding="utf-8")
    with pytest.raises(InputError, match="not a readable DXF"):
        cad.check_drawing("press", bad)
    rc = cli.main(["check", "press", str(bad)])
    err = capsys.readouterr().err
    assert rc == 2 and len(err.strip().splitlines()) == 1
    with pytest.raises(InputError, match="no scale"):
        cad.check_drawing("W1", DRAWINGS / "press_plan_correct.dxf")
    with pytest.raises(InputError, match="not a readable SVG"):
        (tmp_path / "x.svg").write_text("<svg", encoding="utf-8")
        cad.check_drawing("W1", tmp_path / "x.svg")
    rc = cli.main(["check", "press", str(DRAWINGS / "press_plan_correct.dxf"), "--point", "p=1"])
    assert rc == 2 and "LABEL=X,Y" in capsys.readouterr().err


def test_cli_check_of_a_drawing_writes_overlays(tmp_path, capsys):
    rc = cli.main(["check", "W1", str(DRAWINGS / "w1_mistakes.dxf"), "--overlay", str(tmp_path / "o.dxf")])
    out = capsys.readouterr().out
    assert rc == 1 and "sign flipped" in out and "n (rev/min) used as ω" in out
    assert "CHECK" in [ly.dxf.name for ly in ezdxf.readfile(tmp_path / "o.dxf").layers]
    rc = cli.main(["check", "W1", str(DRAWINGS / "w1_correct.svg"), "--overlay", str(tmp_path / "o.svg")])
    capsys.readouterr()
    assert rc == 0 and b"student-drawing" in (tmp_path / "o.svg").read_bytes()


def test_a_class_of_drawings_and_answers_files(tmp_path, capsys):
    d = tmp_path / "class"
    d.mkdir()
    for name in PLANTED:
        problem = PLANTED[name][0]
        stem, suffix = name.rsplit(".", 1)
        shutil.copy(DRAWINGS / name, d / f"{stem}-{suffix}__{problem}.{suffix}")
    shutil.copy(ANSWERS / "w1_correct.toml", d)
    (d / "broken__W1.dxf").write_text("0\nSECTION\n", encoding="utf-8")
    rep = check_class(class_files(d))
    by = {s.path.name: s for s in rep.submissions}
    assert by["broken__W1.dxf"].report is None and "DXF" in by["broken__W1.dxf"].error
    for name, (problem, wrong, _codes, _carried) in PLANTED.items():
        stem, suffix = name.rsplit(".", 1)
        s = by[f"{stem}-{suffix}__{problem}.{suffix}"]
        assert {i.key for i in s.report.wrong} == wrong and s.student == f"{stem}-{suffix}"
    assert rep.exit_status() == 3
    rc = cli.main(["check-class", str(d), "--out", str(tmp_path / "out")])
    capsys.readouterr()
    assert rc == 3
    students = tmp_path / "out" / "students"
    assert (students / "press_plan_mistakes-dxf__press.dxf-overlay.dxf").exists()
    assert (students / "w1_mistakes-svg__W1.svg-overlay.svg").exists()
    assert not (students / "w1_mistakes-svg__W1.svg-overlay.dxf").exists()
    table = (tmp_path / "out" / "class.csv").read_text(encoding="utf-8")
    assert "direction of ps2" in table and "broken__W1.dxf" in table


def test_a_worksheets_own_key_page_in_dxf_checks_correct(tmp_path, capsys):
    """Round trip: the answer key page written as DXF by graphmethods is read back as a correct drawing."""
    rc = cli.main(["worksheet", "velocity-plan", "--variants", "1", "--seed", "7", "--out", str(tmp_path / "c"),
                   "--dxf", "--quiet"])
    capsys.readouterr()
    assert rc == 0
    rep = cad.check_drawing("velocity-plan:7:1", tmp_path / "c" / "dxf" / "velocity-plan-01-key.dxf")
    assert rep.ok and len(rep.items) == 13
    assert rep.answers["velocity_plan"]["mu_v"] == 0.04                 # the caption μ_{v} = … read as one text


def _student_draws_on(page: pathlib.Path, out: pathlib.Path, variant, *, typed: dict, jitter: float):
    """A student opens the worksheet page in CAD, draws the plan from the printed pole and types the answers
    into the table under the headings."""
    drawing = cad.read(page)
    (p_label,) = [t for t in drawing.texts if t.text == "p"]
    pole = np.array(min(drawing.circles, key=lambda c: math.hypot(c[0] - p_label.x, c[1] - p_label.y))[:2])
    mu_v = cad.notes(drawing).values["mu_v"]                           # the scale printed on the page
    vec = variant.vectors()
    pts = {k: pole + np.asarray(v, float) / mu_v + (np.array([jitter, -jitter]) if k != "p" else 0.0)
           for k, v in vec.items()}
    doc = ezdxf.readfile(page)
    msp = doc.modelspace()
    for f, t in (("p", "a"), ("p", "b"), ("a", "b"), ("p", "s2")):
        s, e = pts[f], pts[t]
        u = (e - s) / np.hypot(*(e - s))
        base, n = e - 2.5 * u, np.array([-u[1], u[0]]) * 0.45
        msp.add_line(tuple(s), tuple(base))
        msp.add_solid([tuple(e), tuple(base + n), tuple(base - n)])
    for k, (dx, dy) in zip(("a", "b", "s2"), ((1.5, 1.0), (-3.5, 1.0), (1.5, -3.5))):
        msp.add_text(k, height=3.0).set_placement((pts[k][0] + dx, pts[k][1] + dy))
    heads = {t.text.split(",")[0]: t for t in drawing.texts if t.text.endswith(("m/s", "rad/s"))}
    for head, value in typed.items():
        h = heads[head]
        if value is None:              # the length of pb as drawn, in mm, typed for v_B
            value = float(np.hypot(*(pts["b"] - pts["p"])))
        msp.add_text(f"{value:.3f}".replace(".", ","), height=2.5).set_placement((h.x - 5, h.y - 8))
    doc.saveas(out)


def test_teacher_exports_variants_receives_dxf_and_checks_the_class(tmp_path, capsys):
    cli.main(["worksheet", "velocity-plan", "--variants", "2", "--seed", "7", "--out", str(tmp_path / "c"), "--dxf",
              "--quiet"])
    capsys.readouterr()
    from graphmethods.sheets import worksheets as ws

    inbox = tmp_path / "inbox"
    inbox.mkdir()
    for i, (student, slip) in enumerate((("ivanova", False), ("chen", True)), start=1):
        v = ws.parse_id(f"velocity-plan:7:{i}")
        ans = v.answers()
        typed = {"vA": ans["v_A"], "vB": ans["v_B"], "vBA": ans["v_BA"], "vS2": ans["v_S2"], "ω2": ans["omega_2"]}
        if slip:                       # v_B typed as pb in mm: the scale forgotten
            typed["vB"] = None
        _student_draws_on(tmp_path / "c" / "dxf" / f"velocity-plan-{i:02d}-student.dxf",
                          inbox / f"{student}__velocity-plan_7_{i}.dxf", v, typed=typed, jitter=0.15)
    rc = cli.main(["check-class", str(inbox), "--out", str(tmp_path / "report")])
    capsys.readouterr()
    assert rc == 1
    rep = check_class(class_files(inbox))
    by = {s.student: s.report for s in rep.submissions}
    assert by["ivanova"].ok and len(by["ivanova"].items) == 13
    assert [(i.key, i.mistakes) for i in by["chen"].wrong] == [("results.v_B", ("scale_forgotten",))]
    assert (tmp_path / "report" / "students" / "chen__velocity-plan_7_2.dxf-overlay.dxf").exists()


def test_the_energy_mass_diagram_is_measured_where_it_was_drawn():
    from graphmethods.dynamics.study import Study
    from graphmethods.dynamics.wittenbauer import wittenbauer
    from graphmethods.kinematics import read_case

    case = read_case(ROOT / "graphmethods" / "problems" / "data" / "slider_crank_press.json")
    study = Study(case, positions=12, estimate=False)
    res = wittenbauer(J_e=study.J_e, delta_T=study.delta_T, omega_m=case.omega_m, delta=case.delta, mu_J=0.005,
                      mu_T=4.0)
    rep = cad.check_drawing("press", DRAWINGS / "press_wittenbauer_correct.dxf")
    sec = rep.answers["energy_mass"]
    assert (sec["mu_J"], sec["mu_T"]) == (0.005, 4.0)
    assert sec["kl_mm"] == pytest.approx(res.kl_mm, abs=0.5)                # k and l found at the rays' crossings
    assert {i.key for i in rep.items} >= {"drawing.ray_max_deg", "drawing.ray_min_deg", "energy_mass.kl_mm"}
    assert sec["origin_mm"] == pytest.approx((60.0, 297.0 - 255.0), abs=1e-6)   # where the student's axes cross


def test_a_drawing_in_centimetres_is_read_in_millimetres(tmp_path):
    doc = ezdxf.readfile(DRAWINGS / "press_plan_correct.dxf")
    for e in doc.modelspace():
        e.scale_uniform(0.1)
    doc.units = ezdxf.units.CM
    doc.saveas(tmp_path / "cm.dxf")
    mm = cad.check_drawing("press", DRAWINGS / "press_plan_correct.dxf")
    cm = cad.check_drawing("press", tmp_path / "cm.dxf")
    assert cm.ok and cm.answers["velocity_plan"]["pa_mm"] == pytest.approx(mm.answers["velocity_plan"]["pa_mm"],
                                                                            abs=1e-6)
