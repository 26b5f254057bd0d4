"""One notation per language on every output: the drift the issue found, scanned for in the outputs
themselves (sheets, figures, step captions), not in the vocabulary tables."""

from __future__ import annotations

import re

import pytest

from graphmethods.gallery import figure
from graphmethods.problems import builtin
from graphmethods.render.recording import record
from graphmethods.sheets import steps
from graphmethods.sheets.flywheel_hyperbola import flywheel_hyperbola
from graphmethods.sheets.forces import force_plans, force_scheme, zhukovsky_forces

CJK = r"[\u4e00-\u9fff]"


def _texts(scene) -> list[str]:
    return [c.data.text for c in record(scene).calls if c.kind == "text"]


def _raw_texts(scene) -> list[str]:
    """The texts with their markup runs kept apart: ``S_{2}`` reads ``("S", 0), ("2", -1)``."""
    return [c.data for c in record(scene).calls if c.kind == "text"]


@pytest.mark.parametrize("lang", ["ru", "zh"])
@pytest.mark.parametrize("fig", ["force-plans", "zhukovsky-lever"])
def test_step_captions_write_the_inertia_force_as_the_drawing_does(fig: str, lang: str) -> None:
    bu = steps.build("shaper", fig, notation=lang)
    sub = {"ru": "и", "zh": "I"}[lang]
    captions = " ".join(s.caption for s in bu.steps)
    assert not re.search(r"[FM]_\{i\d", captions), captions[:300]
    assert re.search(rf"[FM]_\{{{sub}\d", captions)


def test_the_russian_hyperbola_speaks_russian() -> None:
    texts = " ".join(_texts(flywheel_hyperbola(575.0, omega_m=62.83, machine="ac-generator", notation="ru")))
    assert "Jм" in texts and "ωср" in texts and "JF" not in texts and "ωm" not in texts
    assert not re.search(r"\d\.\d", texts), "a decimal point in Russian text"


def test_the_russian_drive_scheme_writes_russian_units() -> None:
    texts = " ".join(_texts(figure("drive_scheme_ru").build()))
    assert "N·m/rad" not in texts and "Н·м/рад" in texts


@pytest.mark.parametrize("draw", [force_scheme, force_plans, zhukovsky_forces])
def test_force_figures_lower_the_digits_of_point_names(draw) -> None:
    scene = draw(builtin.case("shaper"), 2, notation="en")
    flat = [lab for lab in _raw_texts(scene) if len(lab.runs) == 1 and re.fullmatch(r"[A-Za-z]\d+", lab.runs[0][0])]
    assert not flat, [lab.text for lab in flat]


@pytest.mark.parametrize("name", ["press_force_plans_zh", "press_force_scheme_zh", "press_zhukovsky_forces_zh",
                                  "flywheel_design_zh", "press_dynamic_analysis_zh", "press_kinematic_analysis_zh"])
def test_chinese_text_takes_full_width_punctuation(name: str) -> None:
    texts = _texts(figure(name).build())
    ascii_after_cjk = [t for t in texts if re.search(rf"{CJK}[,:;] ?", t)]
    assert not ascii_after_cjk, ascii_after_cjk


@pytest.mark.parametrize("lang", ["ru", "zh"])
@pytest.mark.parametrize(("problem", "answers"), [("W1", "w1_mistakes.toml"), ("W3", "w3_mistakes.toml"),
                                                  ("press", "press_wittenbauer_mistakes.toml")])
@pytest.mark.parametrize("style", ["text", "markdown"])
def test_check_reports_write_subscripts_and_the_decimal_sign_of_their_language(problem, answers, lang, style) -> None:
    """A check report in ru/zh writes ω_max as the en report does (never a flat ωmax, Jм, ωср) and its numbers with
    the language's decimal sign (a comma in ru)."""
    from graphmethods.sheets.check import check

    report = check(problem, _answers(answers))
    text = report.to_text(lang) if style == "text" else report.to_markdown(lang)
    assert not re.search(r"(ω|ψ|J|W|A)(max|min|ср|м|изб|m|F)\b", text), text
    if lang == "ru":
        assert not re.search(r"\d\.\d", text), "a decimal point in a Russian report"
        assert re.search(r"\d,\d", text)


def _answers(name: str):
    import pathlib

    import graphmethods

    return pathlib.Path(graphmethods.__file__).parent / "problems" / "data" / "answers" / name
