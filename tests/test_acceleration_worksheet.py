"""The acceleration-plan worksheet and the check of its typed answers, against accelerations found here
independently: the positions of the joints written out by hand and differentiated twice numerically."""

import json
import math
from dataclasses import replace

import numpy as np
import pytest

from graphmethods.errors import InputError
from graphmethods.render.recording import record
from graphmethods.sheets import check as ck, worksheets as ws
from graphmethods.sheets.check import acceleration as ca
from graphmethods.sheets.check.report import Checker


def joints(v, phi: float) -> dict:
    """The joints of a variant's linkage at crank angle φ (rad), m, complex, written out by hand."""
    A = v.r * complex(math.cos(phi), math.sin(phi))
    if v.mechanism == "slider-crank":
        q = v.d - A.imag
        B = complex(A.real + math.sqrt(v.l ** 2 - q * q), v.d)
        return {"A": A, "B": B, "S2": A + (B - A) * v.l_S / v.l}
    O3 = complex(0.0, -v.d)
    u = (A - O3) / abs(A - O3)
    return {"A": A, "A3": A, "B": O3 + v.l * u, "S3": O3 + v.l_S * u}


def by_hand(v, h: float = 1e-4) -> dict:
    """a of each joint (m/s², complex) and ε of the turning link (rad/s², ccw +) by central differences in
    time, the crank at ω₁ with ε₁ (φ(t) = φ0 + ω₁t + ε₁t²/2)."""
    phi0 = v.plan.phi

    def at(t):
        return joints(v, phi0 + v.omega_1 * t + 0.5 * v.epsilon_1 * t * t)

    m, z, p = at(-h), at(0.0), at(h)
    acc = {k: (p[k] - 2 * z[k] + m[k]) / h ** 2 for k in z}
    if v.mechanism == "slider-crank":
        ang = {t: np.angle(at(t)["B"] - at(t)["A"]) for t in (-h, 0.0, h)}
    else:
        ang = {t: np.angle(at(t)["A"] - complex(0.0, -v.d)) for t in (-h, 0.0, h)}
    eps = (ang[h] - 2 * ang[0.0] + ang[-h]) / h ** 2
    return {"a": acc, "epsilon": float(eps)}


VARIANTS = ws.variants("acceleration-plan", count=8, seed=1)


def test_the_variants_cover_both_linkages_and_a_speeding_crank():
    kinds = {v.mechanism for v in VARIANTS}
    assert kinds == {"slider-crank", "slotted-lever"}
    assert any(v.epsilon_1 != 0 for v in VARIANTS) and any(v.epsilon_1 == 0 for v in VARIANTS)
    assert [v.id for v in ws.variants("acceleration-plan", count=3, seed=1)] == [v.id for v in VARIANTS[:3]]
    assert ws.variants("acceleration-plan", count=3, seed=1)[2].data() == VARIANTS[2].data()


@pytest.mark.parametrize("v", VARIANTS, ids=lambda v: v.id)
def test_the_answers_are_the_accelerations_computed_by_hand(v):
    a = v.answers()
    hand = by_hand(v)
    B = "B"
    assert a["a_B_mm"] * v.mu_a == pytest.approx(abs(hand["a"][B]), rel=1e-5, abs=1e-6)
    S = "S2" if v.mechanism == "slider-crank" else "S3"
    assert a[f"a_{S}_mm"] * v.mu_a == pytest.approx(abs(hand["a"][S]), rel=1e-5, abs=1e-6)
    assert a["a_A_mm"] * v.mu_a == pytest.approx(v.r * math.hypot(v.omega_1 ** 2, v.epsilon_1), rel=1e-12)
    link = "2" if v.mechanism == "slider-crank" else "3"
    assert a[f"epsilon_{link}"] == pytest.approx(abs(hand["epsilon"]), rel=1e-5, abs=1e-6)
    assert a[f"epsilon_{link}_sense"] == ("ccw" if hand["epsilon"] > 0 else "cw")
    if v.mechanism == "slotted-lever":          # a^k = 2·ω3·v_rel, both by hand
        O3 = complex(0.0, -v.d)
        h = 1e-6
        ph = v.plan.phi
        J = [joints(v, ph + s * v.omega_1 * h)["A"] - O3 for s in (-1, 1)]
        w3 = (np.angle(J[1]) - np.angle(J[0])) / (2 * h)
        v_rel = (abs(J[1]) - abs(J[0])) / (2 * h)
        assert a["ak_A3A2_mm"] * v.mu_a == pytest.approx(2 * abs(w3 * v_rel), rel=1e-5)


@pytest.mark.parametrize("v", VARIANTS[:4], ids=lambda v: v.id)
def test_the_key_draws_the_plan_at_mu_a_and_the_student_page_does_not(v):
    key = record(ws.key_page(v))
    hand = by_hand(v)
    L = key.vector_length_mm("key-a_B")
    assert L * v.mu_a == pytest.approx(abs(hand["a"]["B"]), rel=1e-4)
    student = record(ws.student_page(v))
    with pytest.raises(InputError):
        student.vector_length_mm("key-a_B")
    # the paper's lines line up (each page clears them behind its own lettering: the holes differ)
    assert (replace(ws.key_page(v).element("grid"), holes=())
            == replace(ws.student_page(v).element("grid"), holes=()))


def test_a_problem_file_round_trips_and_is_checked(tmp_path):
    v = VARIANTS[0]
    path = tmp_path / "p.json"
    path.write_text(v.to_json(), encoding="utf-8")
    w = ws.variant_from_dict(json.loads(path.read_text(encoding="utf-8")))
    assert w.answers() == v.answers()
    good = {k: round(x, 1) for k, x in v.answers().items() if k.endswith("_mm")}
    rep = ck.check(str(path), {"acceleration_plan": {"mu_a": v.mu_a, **good}})
    assert rep.ok, rep.to_text()


def test_lengths_within_half_a_millimetre_pass_and_beyond_fail():
    v = VARIANTS[1]
    a = v.answers()
    for off, ok in ((0.45, True), (-0.45, True), (0.7, False)):
        rep = ck.check(v.id, {"acceleration_plan": {"mu_a": v.mu_a, "a_B_mm": a["a_B_mm"] + off}})
        assert rep.ok is ok


def _slotted_lever_reversed_coriolis(v):
    """a^τ_A3O3 (m/s²) when a^k is drawn the wrong way, solved here as a student does: a3 on the line ∥ the
    slot through the end of −a^k, and on the line ⊥ O3A through the end of a^n_A3O3."""
    O3 = complex(0.0, -v.d)
    ph, h = v.plan.phi, 1e-6
    P = [joints(v, ph + s * v.omega_1 * h)["A"] - O3 for s in (-1, 0, 1)]
    w3 = (np.angle(P[2]) - np.angle(P[0])) / (2 * h)
    v_rel = (abs(P[2]) - abs(P[0])) / (2 * h)
    u = P[1] / abs(P[1])
    a_A = -v.omega_1 ** 2 * joints(v, ph)["A"] + 1j * v.epsilon_1 * joints(v, ph)["A"]
    v_A3A2 = -v_rel * u                           # the lever's point A3 relative to the block A2 on the crank
    ak = 2j * w3 * v_A3A2                         # turned 90° in the sense of ω3
    n = -w3 ** 2 * P[1]
    k = a_A - ak                                  # the mistake: turned the other way
    # k + s·u = n + t·(i u): two real equations
    M = np.array([[u.real, -(1j * u).real], [u.imag, -(1j * u).imag]])
    _, t = np.linalg.solve(M, [(n - k).real, (n - k).imag])
    return abs(t)


def test_a_reversed_coriolis_term_is_named_and_the_rest_carried():
    v = next(x for x in VARIANTS if x.mechanism == "slotted-lever" and x.epsilon_1 == 0)
    a = v.answers()
    wrong_tau = float(_slotted_lever_reversed_coriolis(v) / v.mu_a)
    assert abs(wrong_tau - a["at_A3O3_mm"]) > 1.0              # the mistake shows in a^τ
    eps_own = wrong_tau * v.mu_a / abs(joints(v, v.plan.phi)["A"] - complex(0, -v.d))
    rep = ck.check(v.id, {"acceleration_plan": {"mu_a": v.mu_a, "ak_A3A2_mm": a["ak_A3A2_mm"],
                                                "at_A3O3_mm": wrong_tau, "epsilon_3": eps_own}})
    verdicts = {i.key.split(".")[1]: (i.verdict, i.mistakes) for i in rep.items}
    assert verdicts["ak_A3A2_mm"] == ("ok", ())                 # same length: the sense is the mistake
    assert verdicts["at_A3O3_mm"] == ("wrong", ("coriolis_reversed",))
    assert verdicts["epsilon_3"][0] == "carried"


def test_a_missing_factor_2_is_named_where_it_is_made():
    v = next(x for x in VARIANTS if x.mechanism == "slotted-lever")
    a = v.answers()
    rep = ck.check(v.id, {"acceleration_plan": {"mu_a": v.mu_a, "ak_A3A2_mm": a["ak_A3A2_mm"] / 2}})
    assert [(i.verdict, i.mistakes) for i in rep.items if i.key.endswith("ak_A3A2_mm")] == \
        [("wrong", ("coriolis_factor_2",))]


def test_an_unrecognised_error_is_wrong_without_a_name_and_a_stated_mu_a_is_checked():
    v = VARIANTS[0]
    a = v.answers()
    rep = ck.check(v.id, {"acceleration_plan": {"mu_a": v.mu_a * 2, "a_B_mm": a["a_B_mm"] / 2 + 7.0}})
    items = {i.key.split(".")[1]: i for i in rep.items}
    assert items["mu_a"].verdict == "wrong"
    assert items["a_B_mm"].verdict == "wrong" and items["a_B_mm"].mistakes == ()


def test_bad_answers_say_what_is_wrong():
    v = next(x for x in VARIANTS if x.mechanism == "slider-crank")
    with pytest.raises(InputError, match="no such vector"):
        ck.check(v.id, {"acceleration_plan": {"mu_a": v.mu_a, "ak_A3A2_mm": 3.0}})
    with pytest.raises(InputError, match="ε is found for link"):
        ck.check(v.id, {"acceleration_plan": {"mu_a": v.mu_a, "epsilon_7": 3.0}})
    with pytest.raises(InputError, match="mu_a"):
        ck.check(v.id, {"acceleration_plan": {"a_B_mm": 3.0}})
    with pytest.raises(InputError, match="position"):
        ck.check("slotted-lever", {"acceleration_plan": {"mu_a": 0.1, "a_B_mm": 3.0}})
    with pytest.raises(InputError, match="acceleration_plan"):
        ck.check(v.id, {"velocity_plan": {"mu_v": 0.1, "pa_mm": 3.0}})
    with pytest.raises(InputError, match="no key"):
        ck.validate_answers({"acceleration_plan": {"a_B_cm": 3.0}})


def test_the_overlay_draws_the_plan_at_the_students_scale_with_the_wrong_vector_red():
    v = next(x for x in VARIANTS if x.mechanism == "slotted-lever")
    a = v.answers()
    rep = ck.check(v.id, {"acceleration_plan": {"mu_a": v.mu_a, "ak_A3A2_mm": a["ak_A3A2_mm"] / 2,
                                                "a_B_mm": a["a_B_mm"]}})
    rec = record(rep.overlay(notation="ru"))
    assert rec.vector_length_mm("acc-a_B") * v.mu_a == pytest.approx(abs(by_hand(v)["a"]["B"]), rel=1e-4)
    assert any(t.endswith("пропущен множитель 2 в 2ω·v") for t in rec.texts())


def test_the_command_line_worksheet_and_check(tmp_path, capsys):
    from graphmethods.cli import main

    out = tmp_path / "class"
    assert main(["worksheet", "acceleration-plan", "--variants", "2", "--seed", "4", "--out", str(out), "--quiet"]) == 0
    template = (out / "acceleration-plan-answers.toml").read_text(encoding="utf-8")
    v = ws.variant("acceleration-plan", seed=4, number=2)
    a = v.answers()
    filled = template.replace('mu_a = ""', f"mu_a = {v.mu_a}").replace('a_B_mm = ""', f"a_B_mm = {a['a_B_mm']:.1f}")
    ans = tmp_path / "s.toml"
    ans.write_text(filled, encoding="utf-8")
    assert main(["check", str(out / "problems" / "acceleration-plan-02.json"), str(ans)]) == 0
    assert "all 2 items correct" in capsys.readouterr().out


# ----------------------------------------------------------------------------- acceleration plans drawn in CAD

ezdxf = pytest.importorskip("ezdxf")
DRAWINGS = __import__("pathlib").Path(ck.__file__).parents[2] / "problems" / "data" / "drawings"


class _SlottedLever:
    """The built-in slotted lever (problems/data/slotted_lever.json) as the hand formulas above need it."""

    mechanism, r, d, l, l_S, epsilon_1 = "slotted-lever", 0.10, 0.30, 0.50, 0.25, 0.0
    omega_1 = 2 * math.pi * 60 / 60

    def __init__(self, phi):
        self.plan = type("P", (), {"phi": phi})()


def test_a_drawing_is_measured_where_the_student_drew_it():
    from graphmethods.sheets.check import cad

    rep = cad.check_drawing("slotted-lever", DRAWINGS / "slotted_lever_acc_correct.dxf")
    sec = rep.answers["acceleration_plan"]
    assert rep.ok and sec["mu_a"] == 0.04 and sec["position"] == 2
    plan = ca.problem_of(Checker(rep.answers), rep.data).plan()
    hand = by_hand(_SlottedLever(plan.phi))
    for key, point in (("a_B", "B"), ("a_S3", "S3")):
        assert sec[f"{key}_mm"] * 0.04 == pytest.approx(abs(hand["a"][point]), abs=0.3 * 0.04)  # hand error ≤ 0.3 mm
        assert sec[f"{key}_deg"] == pytest.approx(math.degrees(np.angle(hand["a"][point])), abs=1.0)
    assert sec["epsilon_3"] == pytest.approx(abs(hand["epsilon"]), rel=0.02)


def test_the_overlay_over_a_drawing_puts_the_correct_plan_at_the_students_pole_in_red(tmp_path):
    from graphmethods.sheets.check import cad

    rep = cad.check_drawing("slotted-lever", DRAWINGS / "slotted_lever_acc_mistakes.dxf")
    scene = cad.overlay_on_drawing(rep, notation="en")
    rec = record(scene)
    plan = ca.problem_of(Checker(rep.answers), rep.data).plan()
    hand = by_hand(_SlottedLever(plan.phi))
    assert rec.vector_length_mm("check-acc-a_B") * 0.04 == pytest.approx(abs(hand["a"]["B"]), rel=1e-4)
    start = rec.in_group("check-acc-a_B", "path")[0].data[0][0]
    assert start == pytest.approx(rep.answers["acceleration_plan"]["origin_mm"], abs=1e-3)
    assert all(p.style.stroke == ws.RED for p in rec.in_group("check-acc-a_B", "path"))
    out = tmp_path / "o.dxf"
    out.write_bytes(cad.overlay_dxf(rep))
    doc = ezdxf.readfile(out)
    assert doc.layers.has_entry("CHECK") and len(doc.modelspace().query('*[layer=="CHECK"]')) > 20
    assert len(doc.modelspace().query('*[layer=="Plan"]')) == len(
        ezdxf.readfile(DRAWINGS / "slotted_lever_acc_mistakes.dxf").modelspace().query('*[layer=="Plan"]'))


def test_a_worksheets_key_page_in_dxf_reads_back_correct(tmp_path, capsys):
    from graphmethods.cli import main
    from graphmethods.sheets.check import cad

    assert main(["worksheet", "acceleration-plan", "--variants", "2", "--seed", "5", "--out", str(tmp_path / "c"),
                 "--dxf", "--quiet"]) == 0
    for n in (1, 2):
        rep = cad.check_drawing(f"acceleration-plan:5:{n}", tmp_path / "c" / "dxf" / f"acceleration-plan-0{n}-key.dxf")
        keys = {i.key for i in rep.items}
        assert rep.ok and {"acceleration_plan.a_A_mm", "acceleration_plan.a_B_mm", "acceleration_plan.a_B_deg"} <= keys


def test_a_drawing_without_a_pole_or_a_scale_says_what_to_write(tmp_path):
    from graphmethods.sheets.check import cad

    doc = ezdxf.readfile(DRAWINGS / "press_acc_correct.dxf")
    for t in doc.modelspace().query("TEXT"):
        if t.dxf.text.startswith("μa"):
            doc.modelspace().delete_entity(t)
    doc.saveas(tmp_path / "no_scale.dxf")
    with pytest.raises(InputError, match="μa"):
        cad.check_drawing("press", tmp_path / "no_scale.dxf")
    rep = cad.check_drawing("press", tmp_path / "no_scale.dxf", mu_a=1.0)
    assert rep.ok
