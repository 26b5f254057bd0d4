"""One notation per language on every output (issue 26, item 7).

Every output the toolkit writes for one problem is collected per language — the A1 sheets, the A4
figures (scheme, plans, tables, structure diagram, motion and dynamics figures), the cam sheet and its
figures, the lecture build-ups (slides and the captions the HTML stepper shows), every worksheet kind
with its answer key, the check reports (text, Markdown) and overlays, the drive scheme and the
command line's force table — and each quantity is looked for in every spelling the issue found. A
second spelling of one quantity in one language fails, naming where each spelling was written.

Texts of scenes are read from the recording renderer with their markup restored (``S_{2}``, never a
flat ``S2``), so a lowered digit and a flat one are two spellings.
"""

from __future__ import annotations

import re
from collections import defaultdict
from pathlib import Path

import pytest

import graphmethods
from graphmethods.problems import builtin
from graphmethods.render.recording import record

LANGS = ("en", "ru", "zh")
PROBLEM = "shaper"                       # the richest linkage: a slotted lever, a link and a ram
CJK = "\u4e00-\u9fff"


def _markup(label) -> str:
    return "".join(t if s == 0 else ("_{" if s < 0 else "^{") + t + "}" for t, s in label.runs)


def _scene(scene) -> list[str]:
    return [_markup(c.data) for c in record(scene).calls if c.kind == "text"]


def _figures(lang: str) -> dict[str, list[str]]:
    from graphmethods import sheets
    from graphmethods.cli.kinematics import figures
    from graphmethods.dynamics.study import Study
    from graphmethods.sheets.structure_diagram import structure_diagram

    case = builtin.case(PROBLEM)
    study = Study(case, positions=12)
    out = {f"A4 {k}": _scene(s) for k, s in figures(case, 12, notation=lang).items() if not isinstance(s, str)}
    out["A4 structure diagram"] = _scene(structure_diagram(case, notation=lang))
    for f in ("inertia_graph", "moment_graph", "delta_T_graph", "speed_graph", "acceleration_graph",
              "zhukovsky_lever", "wittenbauer_diagram", "kinematic_diagrams", "work_diagrams"):
        out[f"A4 {f}"] = _scene(getattr(sheets, f)(study, notation=lang))
    out["A1 kinematic sheet"] = _scene(sheets.kinematic_analysis_sheet(study, notation=lang))
    out["A1 force sheet"] = _scene(sheets.force_analysis_sheet(study, position=3, notation=lang))
    out["A1 dynamic sheet"] = _scene(sheets.dynamic_analysis_sheet(study, notation=lang))
    return out


def _cams(lang: str) -> dict[str, list[str]]:
    import importlib

    cam = builtin.cam_problem("shaper-cam")
    sheet = importlib.import_module("graphmethods.sheets.cam_sheet")
    figs = importlib.import_module("graphmethods.sheets.cam_figures")
    out = {"cam sheet": _scene(sheet.cam_sheet(cam, notation=lang))}
    for f in ("cam_motion_diagrams", "cam_combined_diagram", "cam_pressure_angle"):
        out[f"cam {f}"] = _scene(getattr(figs, f)(cam, notation=lang))
    return out


def _steps(lang: str) -> dict[str, list[str]]:
    from graphmethods.sheets import steps

    out = {}
    for fig in steps.FIGURES:
        source = {"inversion": "shaper-cam", "energy-indicator": "W1"}.get(fig, PROBLEM)
        bu = steps.build(source, fig, notation=lang, position=2 if fig in steps.POSITIONED else None)
        out[f"steps {fig} captions"] = [s.caption for s in bu.steps]
        out[f"steps {fig} slide"] = _scene(bu.slide(len(bu.steps)))
    return out


def _worksheets(lang: str) -> dict[str, list[str]]:
    from graphmethods.sheets.worksheets import worksheet
    from graphmethods.sheets.worksheets.variants import KINDS

    out = {}
    for kind in KINDS:
        ws = worksheet(kind, variants=1, seed=3, notation=lang)
        out[f"worksheet {kind}"] = [t for s in ws.students for t in _scene(s)]
        out[f"worksheet {kind} key"] = [t for s in ws.keys for t in _scene(s)]
    return out


ANSWERS = (("W1", "w1_mistakes.toml"), ("W3", "w3_mistakes.toml"), ("press", "press_wittenbauer_mistakes.toml"),
           ("press", "press_plan_mistakes.toml"), ("press", "press_acc_mistakes.toml"),
           ("slotted-lever", "slotted_lever_acc_mistakes.toml"))


def _checks(lang: str) -> dict[str, list[str]]:
    from graphmethods.sheets.check import check
    from graphmethods.sheets.check.overlay import overlay

    folder = Path(graphmethods.__file__).parent / "problems" / "data" / "answers"
    out = {}
    for problem, answers in ANSWERS:
        report = check(problem, folder / answers)
        out[f"check {answers} text"] = report.to_text(lang).splitlines()
        out[f"check {answers} markdown"] = report.to_markdown(lang).splitlines()
        out[f"check {answers} overlay"] = _scene(overlay(report, lang))
    return out


def _others(lang: str) -> dict[str, list[str]]:
    from graphmethods.cli.forces import _text, result
    from graphmethods.gallery.catalogue import _three_mass_drive
    from graphmethods.sheets.drive_scheme import drive_scheme

    return {"drive scheme": _scene(drive_scheme(_three_mass_drive(), notation=lang)),
            "forces (command line)": _text(result(builtin.case(PROBLEM), position=3), lang).splitlines()}


_cache: dict[str, dict[str, list[str]]] = {}


def outputs(lang: str) -> dict[str, list[str]]:
    """Every output's texts in ``lang``: output name -> texts (markup kept)."""
    if lang not in _cache:
        _cache[lang] = {**_figures(lang), **_cams(lang), **_steps(lang), **_worksheets(lang), **_checks(lang),
                        **_others(lang)}
    return _cache[lang]


#: one quantity, its spellings: name -> pattern. The first is the language's own; any other found is a drift.
#: A quantity absent from a language's table is not checked there.
SPELLINGS: dict[str, dict[str, dict[str, str]]] = {
    "inertia force or moment": {
        "en": {"F_{i…}": r"[FM]_\{?i(\d|\}|\b)", "F_{и…}": r"[FM]_\{?и", "F_{I…}": r"[FM]_\{?I(\d|\}|\b)"},
        "ru": {"F_{и…}": r"[FM]_\{?и", "F_{i…}": r"[FM]_\{?i(\d|\}|\b)", "F_{I…}": r"[FM]_\{?I(\d|\}|\b)"},
        "zh": {"F_{I…}": r"[FM]_\{?I(\d|\}|\b)", "F_{i…}": r"[FM]_\{?i(\d|\}|\b)", "F_{и…}": r"[FM]_\{?и"},
    },
    "flywheel's moment of inertia": {
        "en": {"J_F": r"J_\{?F\b", "J_м": r"J_\{?м"},
        "ru": {"J_м": r"J_\{?м", "J_F": r"J_\{?F(?![_a-z])"},
        "zh": {"J_F": r"J_\{?F\b", "J_м": r"J_\{?м"},
    },
    "reduced moment of inertia": {
        "ru": {"J_п": r"J_\{?п", "J_e": r"J_\{?e\b"},
        "en": {"J_e": r"J_\{?e\b", "J_п": r"J_\{?п"},
    },
    "mean angular speed": {
        "en": {"ω_m": r"ω_\{?m\b", "ω_ср": r"ω_\{?ср"},
        "ru": {"ω_ср": r"ω_\{?ср", "ω_m": r"ω_\{?m\b"},
        "zh": {"ω_m": r"ω_\{?m\b", "ω_ср": r"ω_\{?ср"},
    },
    "pressure angle": {
        "en": {"α": "α", "ϑ": "ϑ"},
        "ru": {"ϑ": "ϑ", "α": "α"},
        "zh": {"α": "α", "ϑ": "ϑ"},
    },
    "Zhukovsky": {
        "zh": {"茹可夫斯基": "茹可夫斯基", "茹科夫斯基": "茹科夫斯基"},
    },
    "decimal sign": {
        "en": {"point": r"\d\.\d", "comma": r"(?<![\d,])\d+,\d{1,3}(?!\d)\s*(m|N|J|kg|rad|Н|м|Дж|кг|рад)"},
        "ru": {"comma": r"\d,\d", "point": r"(?<![\w.])\d+\.\d+(?![\w.])"},
    },
    "newton-metre": {
        "en": {"N·m": "N·m", "Н·м": "Н·м"},
        "ru": {"Н·м": "Н·м", "N·m": r"\bN·m\b"},
        "zh": {"N·m": "N·m", "Н·м": "Н·м"},
    },
    "radian per second": {
        "ru": {"рад/с": "рад/с", "rad/s": r"\brad/s"},
        "en": {"rad/s": "rad/s", "рад/с": "рад/с"},
    },
    "punctuation after Chinese text": {
        "zh": {"full-width": "[，：；]", "ASCII": rf"[{CJK}）] ?[,:;]|[,:;] ?[{CJK}（]"},
    },
    "markup": {
        lang: {"x_{01}": r"[_^]\{[^{]", "x_{{01}}": r"[_^]?\{\{|\}\}"} for lang in LANGS
    },
    "superscript mark": {
        lang: {"a^{τ}": r"\^\{", "a^τ printed with its caret": r"\^(?!\{)"} for lang in LANGS
    },
    "point names": {
        lang: {"O_{1}": r"[OSABC]_\{\d", "O1": r"(?<![\w{/·])[OS]\d(?![\d}])"} for lang in LANGS
    },
}

#: outputs a quantity is not held to, with the reason (machine-read text whose spelling is a contract)
EXEMPT: dict[str, str] = {
    "decimal sign": r"forces \(command line\)",       # a table of columns for a spreadsheet: '.' in every language
    "superscript mark": r".*(captions|text|markdown)$",  # plain text writes a^τ_BA (a caption is markup: drawn raised)
}


def drifts(lang: str, texts: dict[str, list[str]]) -> list[str]:
    """Every quantity written in more than one spelling in ``lang``: one line per spelling after the
    first found, with up to three outputs and their text."""
    found = []
    for quantity, per_lang in SPELLINGS.items():
        spellings = per_lang.get(lang)
        if not spellings:
            continue
        where: dict[str, list[str]] = defaultdict(list)
        for output, lines in texts.items():
            if quantity in EXEMPT and re.fullmatch(EXEMPT[quantity], output):
                continue
            for line in lines:
                for name, pattern in spellings.items():
                    if re.search(pattern, line):
                        where[name].append(f"{output}: {line[:90]!r}")
        own = next(iter(spellings))
        for name, places in where.items():
            if name != own:
                found.append(f"{quantity} in {lang} written {name} (the language writes {own}): {places[:3]}")
    return found


@pytest.mark.parametrize("lang", LANGS)
def test_every_output_writes_one_spelling_per_quantity(lang: str) -> None:
    assert drifts(lang, outputs(lang)) == []


def test_the_collector_sees_every_kind_of_output() -> None:
    names = " ".join(outputs("ru"))
    for kind in ("A1 kinematic sheet", "A4 velocity_plan", "A4 structure diagram", "cam sheet", "steps wittenbauer",
                 "captions", "worksheet cam key", "check w1_mistakes.toml text", "overlay", "drive scheme",
                 "forces (command line)"):
        assert kind in names, kind


def test_a_second_spelling_is_caught() -> None:
    texts = {"sheet": ["F_{и3} = 120 Н", "S_{2}"], "caption": ["F_{i3} = 120 Н", "S2 on the rod"]}
    found = drifts("ru", texts)
    assert any("inertia" in f and "F_{i…}" in f for f in found)
    assert any("point names" in f and "O1" in f for f in found)
    assert drifts("zh", {"a": ["ε = 3 rad/s², 逆时针"], "b": ["位置：3"]})
    assert drifts("ru", {"a": ["ε = 3,5 рад/с²"], "b": ["ε = 3.5 рад/с²"]})
    assert drifts("en", {"a": ["R′_{01}"], "b": ["R′_{{01}}: the frame's reaction"]})
    assert drifts("en", {"plan": ["a^{n}_{BA}"], "overlay": ["a^τ_{BA} = 3 mm?"]})
    assert not drifts("en", {"plan": ["a^{n}_{BA}"], "steps captions": ["Draw a^τ_{BA} ⊥ AB"]})
