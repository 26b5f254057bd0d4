"""Problem titles in the figure's language: every ru and zh figure of a built-in problem draws its
title in that language (never the English one); a plain-string title is used for every language;
a missing language falls back to the English title."""

import json
import pathlib

import pytest

from graphmethods import problems, sheets
from graphmethods.dynamics.study import Study
from graphmethods.errors import InputError
from graphmethods.kinematics import case_from_dict, read_case
from graphmethods.problems import CycleProblem
from graphmethods.problems.reduced import four_stroke_engine, smooth_machine
from graphmethods.problems.reference_cases import CASE_TITLES, title_of
from graphmethods.render.recording import record
from graphmethods.sheets import check as chk, worksheets as ws
from graphmethods.titles import LANGUAGES, Title, text_in

DATA = pathlib.Path(problems.__file__).parent / "data"
LINKAGES = ("slider_crank_press", "four_bar_rocker", "slotted_lever", "shaper")
CYCLES = {"W1": problems.w1, "W2": problems.w2, "W3": problems.w3, "W4-drawing": problems.w4_drawing,
          "W4-exact": problems.w4_exact}


def drawn(scene) -> str:
    """Every text the scene draws (the recording renderer's labels), one per line."""
    return "\n".join(record(scene).texts())


def cycle_figures(problem, nt):
    """Every excess-work figure the problem's data allow (moment curves: the moment figures too)."""
    kw = {"work_unit": "kG·m"} if problem.id.startswith("W4") else {}
    out = [sheets.energy_indicator(problem, notation=nt, **kw), sheets.excess_work_table(problem, notation=nt, **kw)]
    if problem.M_r is not None:
        mkw = dict(kw, moment_unit="kG·m") if kw else {}
        out += [sheets.moment_diagram(problem, notation=nt, **mkw), sheets.work_diagrams(problem, notation=nt, **mkw)]
        ekw = dict(kw, J_e=problem.J_e, omega_0=problem.omega_0) if problem.omega_0 is not None else kw
        out.append(sheets.energy_graph(problem, notation=nt, **ekw))
    return out


def linkage_figures(case, nt):
    """The kinematic, dynamic and flywheel figures of a linkage problem (one shared study)."""
    st = Study(case, positions=12)
    out = [sheets.kinematic_scheme(st, notation=nt), sheets.velocity_plan_grid(st, notation=nt),
           sheets.velocity_plan(st, 2, notation=nt), sheets.velocity_table(st, notation=nt),
           sheets.inertia_graph(st, notation=nt), sheets.inertia_graph(st, turned=True, notation=nt),
           sheets.moment_graph(st, notation=nt), sheets.delta_T_graph(st, notation=nt),
           sheets.zhukovsky_lever(st, position=2, notation=nt), sheets.wittenbauer_diagram(st, notation=nt),
           sheets.dynamic_analysis_sheet(st, page="A2", notation=nt), sheets.work_diagrams(st, notation=nt)]
    if case.kind in ("slider_crank", "shaper"):
        out.append(sheets.kinematic_diagrams(case, notation=nt))
    return out


# ----------------------------------------------------------------------------- the Title itself

def test_a_title_by_language_picks_the_language_and_falls_back_to_english():
    t = Title.of({"zh": "压力机", "en": "press", "ru": "пресс"})
    assert [t.title_in(lang) for lang in LANGUAGES] == ["press", "пресс", "压力机"]
    assert str(t) == "press" and t.texts == (("en", "press"), ("ru", "пресс"), ("zh", "压力机"))
    partial = Title.of({"en": "press", "ru": "пресс"})
    assert partial.title_in("zh") == "press" and not partial.translated("zh") and partial.translated("ru")
    assert Title.of({"ru": "пресс"}).title_in("zh") == "пресс"          # no English: the language given
    assert Title.of(t) is t and Title.of(None).title_in("ru") == "" and not Title.of(None)


def test_a_plain_string_title_is_used_for_every_language():
    t = Title.of("hand pump")
    assert {t.title_in(lang) for lang in LANGUAGES} == {"hand pump"}
    assert t.to_json() == "hand pump" and not any(t.translated(lang) for lang in LANGUAGES)
    assert text_in("hand pump", "zh") == "hand pump" and text_in({"en": "a", "zh": "乙"}, "zh") == "乙"


@pytest.mark.parametrize("value, match", [
    ({"de": "Presse"}, "unknown language 'de'"),
    ({}, "at least one of en, ru, zh"),
    ({"en": "press", "ru": ""}, "the ru title must be non-empty text"),
    ({"en": 3}, "the en title must be non-empty text"),
    (3, "must be text, or a mapping of language"),
])
def test_bad_titles_are_refused_with_what_to_do(value, match):
    with pytest.raises(InputError, match=match):
        Title.of(value)


def test_to_json_round_trips():
    for value in ("press", {"en": "press", "zh": "压力机"}):
        assert Title.of(Title.of(value).to_json()) == Title.of(value)


# ----------------------------------------------------------------------------- the built-in problems

def test_every_built_in_problem_has_its_title_in_three_languages():
    titles = [p.title for p in problems.all_examples()]
    titles += [read_case(DATA / f"{name}.json").title for name in LINKAGES if name != "slider_crank_press"]
    titles += [title_of(read_case(DATA / "slider_crank_press.json"))]
    titles += [smooth_machine().title, four_stroke_engine().title]
    titles += [ws.TITLES[kind] for kind in ws.KINDS]
    for t in titles:
        assert all(t.translated(lang) for lang in LANGUAGES), t
        assert len({t.title_in(lang) for lang in LANGUAGES}) == 3, t


@pytest.mark.parametrize("nt", ["ru", "zh"])
@pytest.mark.parametrize("pid", sorted(CYCLES))
def test_cycle_figures_draw_the_title_in_their_language(pid, nt):
    problem = CYCLES[pid]()
    english = problem.title.title_in("en")
    for scene in cycle_figures(problem, nt):
        texts = drawn(scene)
        assert english not in texts, f"{scene.name} ({nt}) draws the English title {english!r}"
        assert problem.title.title_in(nt) in texts, f"{scene.name} ({nt}) does not draw the {nt} title"


@pytest.mark.parametrize("nt", ["ru", "zh"])
@pytest.mark.parametrize("name", LINKAGES)
def test_linkage_figures_draw_the_title_in_their_language(name, nt):
    case = read_case(DATA / f"{name}.json")
    title = title_of(case)
    for scene in linkage_figures(case, nt):
        texts = " ".join(drawn(scene).split())            # the ГОСТ title block wraps a long title in its cell
        assert title.title_in("en") not in texts, f"{name} {scene.name} ({nt}) draws the English title"
        if nt == "zh":                                   # a Chinese title wraps between any two characters
            texts = "".join(texts.split())
        assert title.title_in(nt) in texts, f"{name} {scene.name} ({nt}) does not draw the {nt} title"


def test_english_figures_keep_the_english_title():
    assert "W1: Diesel generator: energy indicator diagram" in drawn(sheets.energy_indicator(problems.w1()))
    press = read_case(DATA / "slider_crank_press.json")
    assert "offset slider-crank press, m = 12" in drawn(sheets.wittenbauer_diagram(Study(press, positions=12)))


def test_chinese_figures_take_full_width_punctuation():
    assert "W3：阶梯形阻抗力矩下的飞轮转动惯量" in drawn(sheets.energy_indicator(problems.w3(), notation="zh"))
    press = read_case(DATA / "slider_crank_press.json")
    assert "偏置曲柄滑块压力机，m = 12" in drawn(sheets.wittenbauer_diagram(Study(press, positions=12), notation="zh"))


def test_the_reference_press_read_as_it_is_gets_our_translations(press_case_path):
    raw = json.loads(press_case_path.read_text(encoding="utf-8"))
    assert isinstance(raw["name"], str)                          # the reference file: English only
    case = read_case(press_case_path)
    assert case.name == raw["name"] and not case.title.translated("ru")
    assert title_of(case) is CASE_TITLES[("slider_crank", raw["name"])]
    for nt in ("ru", "zh"):
        texts = drawn(sheets.kinematic_scheme(case, notation=nt))
        assert raw["name"] not in texts and title_of(case).title_in(nt) in texts


def test_worksheets_draw_their_title_in_their_language():
    for nt in ("ru", "zh"):
        sheet = ws.worksheet("indicator", variants=1, seed=5, notation=nt)
        v = sheet.variants[0]
        assert v.title is ws.TITLES["indicator"]
        for scene in sheet.scenes:
            texts = drawn(scene)
            assert v.title.title_in(nt) in texts and v.title.title_in("en") not in texts


def test_the_check_overlay_names_the_problem_in_its_language():
    text = drawn(chk.check("W1", DATA / "answers" / "w1_mistakes.toml").overlay(notation="ru"))
    assert "Дизель-генератор" in text and "Diesel generator" not in text
    assert chk.load_problem("press").title.title_in("zh") == "偏置曲柄滑块压力机"
    assert chk.check("W1", DATA / "answers" / "w1_mistakes.toml").to_dict()["title"] == \
        "Diesel generator: energy indicator diagram"                          # the report stays English


# ----------------------------------------------------------------------------- user problems

PRESS = {"r": 0.1, "l": 0.4, "e": 0.02, "l_AS2": 0.13, "m2": 8, "J_S2": 0.12, "m3": 12, "J1": 0.5, "F0": 5000,
         "force_from": 0.05, "force_to": 0.95, "n_rpm": 300, "delta": 0.04}


@pytest.mark.parametrize("nt", ["en", "ru", "zh"])
def test_a_plain_string_title_still_works_in_every_notation(nt):
    own = CycleProblem(id="P7", title="Hand pump", work_J=(40, -40))
    assert "P7: Hand pump" in drawn(sheets.energy_indicator(own, notation=nt)).replace("P7：", "P7: ")
    case = case_from_dict({**PRESS, "name": "my own press"})
    assert case.name == "my own press" and "my own press" in drawn(sheets.kinematic_scheme(case, notation=nt))


def test_a_problem_file_may_give_its_title_by_language():
    case = case_from_dict({**PRESS, "name": {"en": "small press", "ru": "малый пресс", "zh": "小型压力机"}})
    assert case.name == "small press"
    assert "малый пресс" in drawn(sheets.velocity_table(case, notation="ru"))
    assert "小型压力机" in drawn(sheets.velocity_table(case, notation="zh"))
    # a file that translates its title itself keeps its own words, even under a reference case's name
    own = case_from_dict({**PRESS, "name": {"en": "offset slider-crank press", "ru": "наш пресс"}})
    assert title_of(own).title_in("ru") == "наш пресс"


def test_a_missing_language_falls_back_to_the_english_title():
    case = case_from_dict({**PRESS, "name": {"en": "small press", "ru": "малый пресс"}})
    texts = drawn(sheets.velocity_table(case, notation="zh"))
    assert "small press" in texts and "малый пресс" not in texts
    own = CycleProblem(id="P8", title={"en": "Punch", "ru": "Пробивной пресс"}, work_J=(25, -25))
    assert "P8：Punch" in drawn(sheets.excess_work_table(own, notation="zh"))
    assert "P8: Пробивной пресс" in drawn(sheets.excess_work_table(own, notation="ru"))


def test_a_title_given_to_a_sheet_is_shown_in_its_language():
    scene = sheets.energy_indicator(problems.w1(), notation="zh", problem={"en": "Exercise 3", "zh": "习题 3"})
    assert "习题 3" in drawn(scene) and "Exercise 3" not in drawn(scene)


@pytest.mark.parametrize("name, match", [
    ({"de": "Presse"}, "key 'name'.*unknown language 'de'"),
    ({"en": "press", "zh": 5}, "key 'name'.*the zh title must be non-empty text"),
    (["press"], "key 'name' must be text, or a mapping"),
])
def test_bad_titles_in_a_problem_file_name_the_key(name, match):
    with pytest.raises(InputError, match=match):
        case_from_dict({**PRESS, "name": name})
