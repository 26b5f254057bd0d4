"""Checking a hand drawing: verdicts at the student's scales, diagnosis of the usual mistakes, overlay, outputs."""

import argparse
import json
import math
import pathlib
import re
import sys

import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.cli import check as cli_check
from graphmethods.errors import InputError, OutputExistsError
from graphmethods.render import svg
from graphmethods.render.recording import record
from graphmethods.scene import vocabulary
from graphmethods.sheets import check as ck, worksheets as ws
from graphmethods.sheets.check.overlay import overlay_label, overlay_value

ANSWERS = pathlib.Path(ck.__file__).parents[2] / "problems" / "data" / "answers"
FILES = sorted(ANSWERS.glob("*.toml"))

#: what each shipped mistakes file plants: (mistake code or None for "no usual mistake fits", item key),
#: and the items that are carried over from those
PLANTED = {
    "w1_mistakes.toml": ({("sign_flipped", "energy_indicator.arrows_mm[2]"), ("delta_not_halved", "results.omega_max"),
                          ("delta_not_halved", "results.omega_min"), ("n_as_omega", "results.J_F")},
                         {"results.delta_W_max"}),
    "w3_mistakes.toml": ({("degrees_as_radians", "results.M_d"), ("scale_forgotten", "results.works_J[0]"),
                          ("scale_forgotten", "results.works_J[1]"), (None, "results.omega_min_at")},
                         {"results.delta_W_max", "results.J_F"}),
    "press_plan_mistakes.toml": ({(None, "velocity_plan.ab_mm"), ("scale_twice", "results.v_B"),
                                  ("scale_forgotten", "results.v_S2")}, {"results.v_BA", "results.omega_2"}),
    "press_wittenbauer_mistakes.toml": ({("n_as_omega", "energy_mass.tan_psi_min"),
                                         ("J_e_not_subtracted", "energy_mass.kl_mm"),
                                         (None, "energy_mass.omega_min_at")}, {"results.J_F"}),
    # acceleration plans (made by tests/drawings/make_acceleration_examples.py): one usual mistake each, the
    # rest of the plan carried over from it
    "press_acc_mistakes.toml": ({("normal_reversed", "acceleration_plan.at_BA_mm")},
                                {"acceleration_plan.a_B_mm", "acceleration_plan.a_S2_mm",
                                 "acceleration_plan.epsilon_2"}),
    "slotted_lever_acc_mistakes.toml": ({("coriolis_reversed", "acceleration_plan.at_A3O3_mm")},
                                        {"acceleration_plan.a_A3_mm", "acceleration_plan.a_B_mm",
                                         "acceleration_plan.a_S3_mm", "acceleration_plan.epsilon_3"}),
    "slotted_lever_acc_factor.toml": ({("coriolis_factor_2", "acceleration_plan.ak_A3A2_mm")},
                                      {"acceleration_plan.at_A3O3_mm", "acceleration_plan.a_A3_mm",
                                       "acceleration_plan.a_B_mm", "acceleration_plan.a_S3_mm",
                                       "acceleration_plan.epsilon_3"}),
    "slotted_lever_acc_no_coriolis.toml": ({("coriolis_forgotten", "acceleration_plan.at_A3O3_mm")},
                                         {"acceleration_plan.a_A3_mm", "acceleration_plan.a_B_mm",
                                          "acceleration_plan.a_S3_mm", "acceleration_plan.epsilon_3"}),
    "slotted_lever_acc_length.toml": ({("normal_wrong_length", "acceleration_plan.an_A3O3_mm")},
                                      {"acceleration_plan.ar_A3A2_mm", "acceleration_plan.a_A3_mm",
                                       "acceleration_plan.a_B_mm", "acceleration_plan.a_S3_mm"}),
    "worksheet_acc_crank.toml": ({("crank_tangential_forgotten", "acceleration_plan.a_A_mm")},
                                 {"acceleration_plan.at_BA_mm", "acceleration_plan.a_B_mm", "acceleration_plan.a_S2_mm",
                                  "acceleration_plan.epsilon_2"}),
}


def problem_of(path):
    return ck.read_answers(path)["problem"]


def found(report):
    out = set()
    for it in report.wrong:
        out |= {(code, it.key) for code in it.mistakes} if it.mistakes else {(None, it.key)}
    return out


# ----------------------------------------------------------------------------- the shipped examples

def test_every_kind_ships_a_correct_and_a_mistakes_file():
    names = {p.name for p in FILES}
    for stem in ("w1", "w3", "press_plan", "press_wittenbauer"):          # indicator, step-moment, plan, wittenbauer
        assert {f"{stem}_correct.toml", f"{stem}_mistakes.toml"} <= names
    codes = {code for planted, _ in PLANTED.values() for code, _ in planted if code}
    assert codes == set(ck.MISTAKES)                                      # every usual mistake is exercised


@pytest.mark.parametrize("path", [p for p in FILES if p.name.endswith("_correct.toml")], ids=lambda p: p.name)
def test_a_correct_solution_passes(path):
    report = ck.check(problem_of(path), path)
    assert report.ok, report.to_text()
    assert not report.mistakes and len(report.items) >= 5


@pytest.mark.parametrize("name", sorted(PLANTED))
def test_the_check_finds_exactly_the_planted_mistakes(name):
    report = ck.check(problem_of(ANSWERS / name), ANSWERS / name)
    planted, carried = PLANTED[name]
    assert found(report) == planted, report.to_text()
    assert {i.key for i in report.carried} == carried
    assert not report.ok
    for it in report.items:                            # everything else is right
        if (it.key not in {k for _, k in planted}) and it.key not in carried:
            assert it.verdict == "ok", it


def test_numbers_in_the_report_are_at_the_students_scales():
    r = ck.check("W3", ANSWERS / "w3_correct.toml")
    area = next(i for i in r.items if i.key == "moment_diagram.areas_mm2[0]")
    k = 0.5 * math.radians(2.5)                        # μ_M·μ_φ of the student's drawing
    assert area.expected == pytest.approx(-43.75 * math.pi / 4 / k) == pytest.approx(-1575.0)
    # the tolerance is 0.5 mm along the region's boundary: a 45°/2.5 = 18 mm by 43.75/0.5 = 87.5 mm rectangle
    assert area.tolerance == pytest.approx(0.5 * 2 * (18.0 + 87.5))
    r2 = ck.check("W3", {"moment_diagram": {"mu_M": 1.0, "mu_phi_deg": 5.0, "areas_mm2": [-394, 394]}})
    assert r2.items[0].expected == pytest.approx(-1575.0 / 4) and r2.ok


def test_tolerances_propagate_to_J_F():
    r = ck.check("press", ANSWERS / "press_wittenbauer_correct.toml")
    J_F = next(i for i in r.items if i.key == "results.J_F")
    w = math.pi * 300 / 30
    assert J_F.tolerance == pytest.approx(4.0 * 0.5 / (w * w * 0.04) + 1e-3 * J_F.expected)
    # 0.9 mm off on kl is outside 0.5 mm; J_F from that kl is "carried", not a new mistake
    a = ck.read_answers(ANSWERS / "press_wittenbauer_correct.toml")
    a["energy_mass"]["kl_mm"] = J_F.expected * w * w * 0.04 / 4.0 + 0.9
    a["results"]["J_F"] = 4.0 * a["energy_mass"]["kl_mm"] / (w * w * 0.04)
    r = ck.check("press", a)
    assert [(i.key, i.verdict) for i in r.items if i.verdict != "ok"] == [("energy_mass.kl_mm", "wrong"),
                                                                         ("results.J_F", "carried")]


def test_measured_areas_set_the_tolerance_of_the_works_and_of_delta_W_max():
    r = ck.check("W3", ANSWERS / "w3_mistakes.toml")          # mu_M = 0.5 N·m/mm, mu_phi = 2.5 °/mm
    by = {i.key: i for i in r.items}
    k = 0.5 * math.radians(2.5)                                 # J per mm² of the student's diagram
    for i in range(2):
        area, work = by[f"moment_diagram.areas_mm2[{i}]"], by[f"results.works_J[{i}]"]
        assert work.tolerance == pytest.approx(area.tolerance * k + 1e-3 * abs(work.expected))
    band = sum(by[f"moment_diagram.areas_mm2[{i}]"].tolerance * k for i in range(1))    # E_max to E_min: a–b
    dW = by["results.delta_W_max"]
    assert dW.tolerance == pytest.approx(band + 1e-3 * dW.expected)


def test_a_position_within_drafting_precision_of_the_extreme_is_accepted():
    r = ck.check("W1", {"results": {"omega_max_at": "e", "omega_min_at": "b"}})
    assert r.ok
    r = ck.check("W1", {"results": {"omega_max_at": "b", "omega_min_at": "f"}})
    assert [i.verdict for i in r.items] == ["wrong", "wrong"]
    r = ck.check("W3", {"results": {"omega_max_at": "c"}})   # a and c are the same point of the cycle
    assert r.ok and r.items[0].expected == "a or c"


# ----------------------------------------------------------------------------- the diagnosis as a property

@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 10**5), number=st.integers(1, 20), which=st.integers(0, 7),
       mistake=st.sampled_from(["sign", "n_as_omega", "J_e", "delta", "scale"]))
def test_one_planted_mistake_in_a_perfect_indicator_answer_is_found_alone(seed, number, which, mistake):
    v = ws.variant("indicator", seed=seed, number=number)
    a = v.answers()
    n = len(a["works_J"])
    i = which % n
    arrows = list(a["arrows_mm"])
    works = list(a["works_J"])
    res = {"works_J": works, "delta_W_max": a["delta_W_max"], "omega_m": a["omega_m"], "J_F": a["J_F"]}
    w, d, dW = v.omega_m, v.delta_value, a["delta_W_max"]
    expect = set()
    if mistake == "sign":
        arrows[i] = -arrows[i]
        expect = {("sign_flipped", f"energy_indicator.arrows_mm[{i}]")}
    elif mistake == "n_as_omega":
        res["J_F"] = dW / (v.n_rpm ** 2 * d) - v.J_e
        expect = {("n_as_omega", "results.J_F")}
    elif mistake == "J_e":
        res["J_F"] = dW / (w * w * d)
        expect = {("J_e_not_subtracted", "results.J_F")}
    elif mistake == "delta":
        res["omega_max"] = w * (1 + d)
        expect = {("delta_not_halved", "results.omega_max")}
    else:
        works[i] = v.areas_mm2[i]
        expect = {("scale_forgotten", f"results.works_J[{i}]")}
    report = ck.check(v.id, {"energy_indicator": {"mu_E": v.mu_E, "arrows_mm": arrows}, "results": res})
    assert found(report) == expect, report.to_text()
    assert not report.carried


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 10**5), noise=st.floats(-0.45, 0.45))
def test_drafting_noise_within_half_a_millimetre_is_never_a_mistake(seed, noise):
    v = ws.variant("velocity-plan", seed=seed, number=1)
    a = v.answers()
    sec = {"mu_v": v.mu_v, **{f"{s}_mm": a[f"{s}_mm"] + noise for s in ("pa", "pb", "ab", "ps2")}}
    res = {k: a[k] + noise * v.mu_v for k in ("v_A", "v_B", "v_BA", "v_S2")}
    report = ck.check(v.id, {"velocity_plan": sec, "results": res})
    assert report.ok, report.to_text()


# ----------------------------------------------------------------------------- problems and answers files

def test_problems_by_id_and_by_file(tmp_path):
    assert ck.load_problem("w2").id == "W2" and ck.load_problem("W4").id == "W4-drawing"
    assert ck.load_problem("press").case.n_rpm == 300.0
    v = ws.variant("wittenbauer", seed=3, number=2)
    assert ck.load_problem("wittenbauer:3:2").em_variant.data() == v.data()
    f = tmp_path / "p.json"
    f.write_text(v.to_json(), encoding="utf-8")
    assert ck.load_problem(str(f)).em_variant.data() == v.data()
    case = tmp_path / "press.json"
    case.write_text((pathlib.Path(ck.__file__).parents[2] / "problems" / "data" / "slider_crank_press.json")
                    .read_text(encoding="utf-8"), encoding="utf-8")
    r = ck.check(str(case), ANSWERS / "press_plan_correct.toml")
    assert r.ok
    with pytest.raises(InputError, match="not a built-in id"):
        ck.load_problem("W9")


def test_a_problem_without_n_and_delta_says_what_it_did_not_check():
    r = ck.check("W4", {"results": {"J_F": 1.0}, "energy_indicator": {"mu_E": 1.0, "arrows_mm": [15, -15, -15, 15]}})
    assert r.ok and any("no n and [δ]" in n for n in r.notes)


def test_answers_are_read_as_toml_the_small_reader_refused():
    # dotted keys, an inline table and a literal multi-line string: valid TOML, refused by the
    # hand-written subset reader this package had before it read TOML with tomllib / tomli
    text = ('student = \'\'\'A. Student\'\'\'\npage = {size = "A4", orientation = "landscape"}\n'
            'energy_indicator.mu_E = 5.0\nenergy_indicator.arrows_mm = [10, -110, 20, -25, 100, -5, 10]\n'
            '[results]\ndelta_W_max = 575.0\n')
    a = ck.validate_answers(ck.load_toml(text))
    assert a["page"] == {"size": "A4", "orientation": "landscape"} and a["energy_indicator"]["mu_E"] == 5.0
    assert a == ck.validate_answers(tomllib_or_tomli().loads(text))
    with pytest.raises(InputError, match="f.toml: not valid TOML"):
        ck.load_toml("a = [1,,2]", source="f.toml")


def tomllib_or_tomli():
    try:
        import tomllib as lib
    except ModuleNotFoundError:      # Python 3.10
        import tomli as lib
    return lib


def test_without_tomllib_the_answers_are_read_by_tomli(monkeypatch):
    pytest.importorskip("tomli")     # installed on Python 3.10 (a dependency there); CI tests it on 3.10
    reference = {p.name: ck.read_answers(p) for p in FILES}
    monkeypatch.setitem(sys.modules, "tomllib", None)         # as on Python 3.10
    with pytest.raises(ModuleNotFoundError):
        import tomllib as _  # noqa: F401
    assert {p.name: ck.read_answers(p) for p in FILES} == reference
    assert ck.check("W1", ANSWERS / "w1_correct.toml").ok


def test_answers_files_are_validated():
    with pytest.raises(InputError, match="unknown section or key 'result'"):
        ck.check("W1", {"result": {}})
    with pytest.raises(InputError, match=r"\[results\] has no key 'JF'"):
        ck.check("W1", {"results": {"JF": 1.0}})
    with pytest.raises(InputError, match="no mu_E"):
        ck.check("W1", {"energy_indicator": {"arrows_mm": [1]}})
    with pytest.raises(InputError, match="does not belong"):
        ck.check("W1", {"velocity_plan": {"mu_v": 1.0}})
    with pytest.raises(InputError, match="position must be"):
        ck.check("press", {"velocity_plan": {"mu_v": 0.05, "pa_mm": 62.8}})
    with pytest.raises(InputError, match="nothing to check"):
        ck.check("W1", {"page": {"size": "A4"}})
    r = ck.check("W1", {"energy_indicator": {"mu_E": 5.0, "arrows_mm": [10, -110, 20]}})
    assert [(i.label, i.verdict) for i in r.items] == [("number of arrows", "wrong")]


# ----------------------------------------------------------------------------- outputs and overlay

def test_text_markdown_and_json_say_the_same():
    r = ck.check("W1", ANSWERS / "w1_mistakes.toml")
    text, md, js = r.to_text(), r.to_markdown(), json.loads(r.to_json())
    assert "n (rev/min) used as ω (rad/s): J_F" in text and "Result:" in text
    assert md.startswith("### Check of W1") and "| arrow c–d | -20 | 20 |" in md
    assert "**wrong: sign flipped in the staircase**" in md and "carried over" in text      # verdicts in words
    assert js["ok"] is False and [m["code"] for m in js["mistakes"]] == ["sign_flipped", "delta_not_halved",
                                                                         "n_as_omega"]
    assert {i["key"]: i["verdict"] for i in js["items"]}["results.delta_W_max"] == "carried"
    assert js["page"] == {"size": "A4", "orientation": "landscape"}


def test_overlay_is_the_correct_construction_at_the_students_scales_with_wrong_items_red():
    r = ck.check("W1", ANSWERS / "w1_mistakes.toml")
    scene = r.overlay()
    assert (scene.page.width_mm, scene.page.height_mm) == (297.0, 210.0) and not scene.page.frame
    rec = record(scene)
    work = [-50, 550, -100, 125, -500, 25, -50]
    labels = "abcdefgh"
    for i, A in enumerate(work):
        gid = f"vector-{labels[i]}{labels[i + 1]}"
        assert rec.vector_length_mm(gid) == pytest.approx(abs(A) / 5.0, abs=1e-3)     # at the student's μ_E
        strokes = {c.style.stroke for c in rec.in_group(gid, "path")}
        assert strokes == ({ws.RED} if i == 2 else {"#000000"})
    red_texts = [c.data.text for c in rec.calls if c.kind == "text" and c.data.color == ws.RED]
    assert "20 mm?" in red_texts and "arrow c–d: 20 (expected −20) mm — sign flipped in the staircase" in red_texts
    x0, y0, x1, y1 = scene.bbox()
    assert x0 >= 0 and y0 >= 0 and x1 <= 297 and y1 <= 210
    # the origin can be put where the student's is
    a = ck.read_answers(ANSWERS / "w1_mistakes.toml")
    a["energy_indicator"]["origin_mm"] = (40.0, 60.0)
    moved = record(ck.check("W1", a).overlay())
    assert moved.in_group("vector-ab", "path")[0].data[0][0] == (40.0, 60.0)


@pytest.mark.parametrize("name", ["w3_mistakes.toml", "press_plan_mistakes.toml", "press_wittenbauer_mistakes.toml"])
def test_every_overlay_fits_the_students_page(name):
    r = ck.check(problem_of(ANSWERS / name), ANSWERS / name)
    scene = r.overlay(notation="ru")
    x0, y0, x1, y1 = scene.bbox()
    assert x0 >= 0 and y0 >= 0 and x1 <= scene.page.width_mm and y1 <= scene.page.height_mm
    assert svg.to_bytes(scene) == svg.to_bytes(r.overlay(notation="ru"))           # deterministic


def test_overlay_regions_and_plan_segments_are_to_scale():
    r = ck.check("W3", ANSWERS / "w3_correct.toml")
    scene = r.overlay()
    k = 0.5 * math.radians(2.5)
    for i, A in enumerate(r.data.cycle.work):
        assert scene.element(f"md-region-{i + 1}").shape().area == pytest.approx(abs(A) / k, rel=1e-9)
    r = ck.check("press", ANSWERS / "press_plan_mistakes.toml")
    rec = record(r.overlay())
    assert rec.vector_length_mm("plan-pb") == pytest.approx(60.7076, abs=1e-3)
    assert {c.style.stroke for c in rec.in_group("plan-ab", "path")} == {ws.RED}



# ----------------------------------------------------------------------------- the overlay's language

#: English words the overlay may draw (its own wording, the item labels and the mistake names)
ENGLISH = ("Overlay", "print at", "scaling", "transparent", "film", "the bar below", "expected", "carried over",
           "wrong", " or ", "area", "work", "arrow", "number of", "point of", "angle of", "position of",
           "sense of", "sign flipped", "staircase", "degrees", "radians", "used as", "rev/min", "scale factor",
           "forgotten", "twice", "subtracted", "instead of", "clockwise")
#: the names of the usual mistakes on a Russian and a Chinese overlay (ТММ and 机械原理 wording)
NAMES = {
    "ru": {"sign_flipped": "перепутан знак избыточной работы", "degrees_as_radians": "градусы приняты за радианы",
           "n_as_omega": "n (об/мин) принято за ω (рад/с)", "scale_forgotten": "не учтён масштабный коэффициент",
           "scale_twice": "масштабный коэффициент учтён дважды", "J_e_not_subtracted": "не вычтен Jп",
           "delta_not_halved": "(1 ± δ) вместо (1 ± δ/2)",
           "normal_reversed": "нормальное ускорение направлено от центра",
           "coriolis_reversed": "кориолисово ускорение в обратную сторону",
           "coriolis_forgotten": "забыто кориолисово ускорение", "coriolis_factor_2": "пропущен множитель 2 в 2ω·v",
           "normal_wrong_length": "ω²·l с неверной длиной",
           "crank_tangential_forgotten": "забыто касательное ускорение кривошипа"},
    "zh": {"sign_flipped": "盈亏功正负号颠倒", "degrees_as_radians": "把度当作弧度",
           "n_as_omega": "把 n (r/min) 当作 ω (rad/s)", "scale_forgotten": "漏乘比例尺",
           "scale_twice": "比例尺乘了两次",
           "J_e_not_subtracted": "未减去 Je", "delta_not_halved": "用 (1 ± δ) 代替了 (1 ± δ/2)",
           "normal_reversed": "法向分量方向画反", "coriolis_reversed": "哥氏加速度方向画反",
           "coriolis_forgotten": "漏了哥氏加速度", "coriolis_factor_2": "2ω·v 中漏了系数 2",
           "normal_wrong_length": "ω²·l 用错了杆长", "crank_tangential_forgotten": "漏了曲柄的切向加速度"},
}
OWN = {"ru": ("Накладка для проверки: ", "печатать на прозрачной плёнке в масштабе 100 %", "100 мм", "должно быть",
              "следствие предыдущей ошибки", "неверно"),
       "zh": ("叠加校核图：", "按 100 % 比例（不缩放）打印在透明胶片上", "100 mm", "应为", "由前面的错误导致", "错误")}


def red_list(scene):
    """The overlay's red list of wrong items, one text per line."""
    return [c.data.text for c in record(scene).calls if c.kind == "text" and c.groups[0].startswith("wrong-list")]


def test_every_usual_mistake_has_a_name_in_every_notation():
    for code in ck.MISTAKES:
        names = vocabulary.family("check").words[code]
        assert len(names) == 3 and all(names) and len(set(names)) == 3, code
    assert set(NAMES["ru"]) == set(NAMES["zh"]) == set(ck.MISTAKES)


@pytest.mark.parametrize("nt", ["ru", "zh"])
@pytest.mark.parametrize("name", sorted(PLANTED))
def test_the_overlay_speaks_its_notation(name, nt):
    r = ck.check(problem_of(ANSWERS / name), ANSWERS / name)
    planted, carried = PLANTED[name]
    assert found(r) == planted and {i.key for i in r.carried} == carried          # still exactly the planted ones
    scene = r.overlay(notation=nt)
    texts = record(scene).texts()
    everything = "\n".join(texts)
    for word in ENGLISH:
        assert word not in everything, (word, [t for t in texts if word in t])
    for code in ck.MISTAKES:
        assert code not in everything
    if nt == "ru":
        assert not re.search(r"\bmm\b", everything) and not re.search(r"\d\.\d", everything)   # мм, decimal comma
    for word in OWN[nt][:3]:
        assert word in everything
    lines = red_list(scene)
    assert len(lines) == len(r.wrong) + len(r.carried)
    assert all(OWN[nt][3] in line for line in lines)
    for code in {c for c, _ in planted if c}:
        assert any(line.endswith(NAMES[nt][code]) for line in lines), code
    assert sum(line.endswith(OWN[nt][4]) for line in lines) == len(carried)
    assert sum(line.endswith(OWN[nt][5]) for line in lines) == sum(1 for c, _ in planted if c is None)


def test_the_overlay_lines_in_three_notations():
    r = ck.check("W1", ANSWERS / "w1_mistakes.toml")
    assert red_list(r.overlay(notation="ru")) == [
        "вектор c–d: 20 (должно быть −20) мм — перепутан знак избыточной работы",
        "Aизб: 775 (должно быть 575) Дж — следствие предыдущей ошибки",
        "ωmax: 63,04 (должно быть 62,94) рад/с — (1 ± δ) вместо (1 ± δ/2)",
        "ωmin: 62,62 (должно быть 62,73) рад/с — (1 ± δ) вместо (1 ± δ/2)",
        "Jм: 0,6458 (должно быть 43,69) кг·м² — n (об/мин) принято за ω (рад/с)"]
    assert red_list(r.overlay(notation="zh")) == [
        "矢量 c–d：20（应为 −20）mm——盈亏功正负号颠倒",
        "ΔWmax：775（应为 575）J——由前面的错误导致",
        "ωmax：63.04（应为 62.94）rad/s——用 (1 ± δ) 代替了 (1 ± δ/2)",
        "ωmin：62.62（应为 62.73）rad/s——用 (1 ± δ) 代替了 (1 ± δ/2)",
        "JF：0.6458（应为 43.69）kg·m²——把 n (r/min) 当作 ω (rad/s)"]
    en = r.overlay(notation="en")
    texts = record(en).texts()
    assert texts[:3] == ["Overlay: W1 — Diesel generator: energy indicator diagram — Example student (mistakes)",
                         "print at 100 % (no scaling) on transparent film; check: the bar below is 100 mm", "100 mm"]
    assert red_list(en) == [
        "arrow c–d: 20 (expected −20) mm — sign flipped in the staircase",
        "ΔWmax: 775 (expected 575) J — carried over",
        "ωmax: 63.04 (expected 62.94) rad/s — (1 ± δ) instead of (1 ± δ/2)",
        "ωmin: 62.62 (expected 62.73) rad/s — (1 ± δ) instead of (1 ± δ/2)",
        "JF: 0.6458 (expected 43.69) kg·m² — n (rev/min) used as ω (rad/s)"]
    r = ck.check("press", ANSWERS / "press_wittenbauer_mistakes.toml")
    assert red_list(r.overlay(notation="ru"))[1:3] == ["kl: 136,5 (должно быть 131,1) мм — не вычтен Jп",
                                                       "положение ωmin: 7 (должно быть 5) — неверно"]
    assert "kl = 136,5 мм?" in record(r.overlay(notation="ru")).texts()
    assert "ωmin 所在位置：7（应为 5）——错误" in red_list(r.overlay(notation="zh"))


def _every_kind_of_item():
    """Reports whose items cover every key the check makes (counts, angles, senses included)."""
    reports = [ck.check(problem_of(p), p) for p in FILES]
    reports.append(ck.check("W1", {"energy_indicator": {"mu_E": 5.0, "arrows_mm": [10, -110, 20]},
                                   "results": {"works_J": [1.0, 2.0]}}))
    reports.append(ck.check("W3", {"moment_diagram": {"mu_M": 0.5, "mu_phi_deg": 2.5, "areas_mm2": [1, 2, 3]},
                                   "results": {"omega_max_at": 40.0}}))
    return reports


def test_every_item_label_is_in_the_overlays_notation():
    from graphmethods.scene import markup

    keys = set()
    for r in _every_kind_of_item():
        for it in r.items:
            keys.add(re.sub(r"\[\d+\]", "[]", it.key))
            en = markup.plain(overlay_label(it, r, "en"))
            assert en == re.sub("[_^]", "", it.label), it.key            # the report's label, sub/superscripts drawn
            for nt in ("ru", "zh"):
                label = overlay_label(it, r, nt)
                base = "".join(t for t, shift in markup.parse(label) if shift == 0)     # subscripts aside
                assert not any(w.strip() in label for w in ENGLISH), (it.key, label)
                assert not re.search(r"[A-Za-z]{4,}", base), (it.key, label)
    assert {"moment_diagram.areas_mm2", "results.works_J", "energy_indicator.arrows_mm", "results.omega_2_sense",
            "energy_mass.omega_min_at", "results.omega_max_at", "energy_mass.tan_psi_min"} <= keys
    sense = next(it for r in _every_kind_of_item() for it in r.items if it.key == "results.omega_2_sense")
    assert overlay_value(sense.student, "ru") == "по часовой стрелке"
    assert overlay_value("b or c", "zh") == "b 或 c" and overlay_value(-34.36, "ru") == "−34,36"


def test_a_long_heading_or_line_is_broken_to_stay_on_the_page():
    a = ck.read_answers(ANSWERS / "w3_mistakes.toml")                  # A4 portrait
    a["student"] = "Иванова Анна Сергеевна, группа МТ-21, вариант 7 (работа переделана после консультации)"
    scene = ck.check("W3", a).overlay(notation="ru")
    rec = record(scene)
    heading = [c for c in rec.calls if c.kind == "text" and c.data.bold]
    assert len(heading) >= 2
    x0, y0, x1, y1 = scene.bbox()
    assert x0 >= 0 and x1 <= scene.page.width_mm
    lines = red_list(scene)
    assert all(ws.markup.text_width_mm(t, 2.6, markup=False) <= scene.page.width_mm - 24.0 for t in lines)


def _args(*argv):
    p = argparse.ArgumentParser()
    sub = p.add_subparsers()
    cli_check.add_parser(sub)
    return p.parse_args(["check", *argv])


def test_cli_formats_exit_status_and_overlay_files(tmp_path, capsys):
    assert cli_check.run(_args("W1", str(ANSWERS / "w1_correct.toml"))) == 0
    assert "Result: all 21 items correct" in capsys.readouterr().out
    assert cli_check.run(_args("W1", str(ANSWERS / "w1_mistakes.toml"), "--format", "json")) == 1
    assert json.loads(capsys.readouterr().out)["ok"] is False
    out = tmp_path / "film.svg"
    assert cli_check.run(_args("press", str(ANSWERS / "press_plan_mistakes.toml"), "--format", "markdown",
                               "--overlay", str(out))) == 1
    assert out.read_bytes().startswith(b"<?xml") and b'width="420mm"' in out.read_bytes()
    with pytest.raises(OutputExistsError, match="--force"):
        cli_check.run(_args("press", str(ANSWERS / "press_plan_mistakes.toml"), "--overlay", str(out)))
    assert cli_check.run(_args("press", str(ANSWERS / "press_plan_mistakes.toml"), "--overlay", str(out),
                               "--force")) == 1
    pdf = tmp_path / "film.pdf"
    cli_check.run(_args("W3", str(ANSWERS / "w3_mistakes.toml"), "--overlay", str(pdf)))
    assert pdf.read_bytes().startswith(b"%PDF")
    with pytest.raises(InputError, match=".svg, .pdf, .png or .dxf"):
        cli_check.run(_args("W3", str(ANSWERS / "w3_mistakes.toml"), "--overlay", str(tmp_path / "x.jpg")))
    with pytest.raises(InputError, match="no such answers file"):
        cli_check.run(_args("W3", str(tmp_path / "none.toml")))
