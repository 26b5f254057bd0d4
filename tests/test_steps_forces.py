"""Lecture steps of the force analysis (issue 20): the force plans group by group and Zhukovsky's
lever with every force, checked against the force-analysis records and independent computations."""

import math
import re

import numpy as np
import pytest

from graphmethods.cli import main
from graphmethods.dynamics.forces import case_forces
from graphmethods.errors import InputError
from graphmethods.render.recording import record
from graphmethods.scene import markup
from graphmethods.sheets import steps as S

NUMBER = r"(−?[\d.]+)"


@pytest.fixture(scope="module")
def built():
    cache = {}

    def get(case, figure, position=3, lang="en"):
        key = (case, figure, position, lang)
        if key not in cache:
            cache[key] = S.build(case, figure, position=position, notation=lang)
        return cache[key]
    return get


def _names(bu):
    return [[bu.figure.elements[i].name for i in s.elements] for s in bu.steps]


def _step_of(bu, name):
    return next(k for k, ns in enumerate(_names(bu)) if name in ns)


@pytest.mark.parametrize("case", ["press", "four-bar", "shaper", "six-bar-press"])
def test_force_plan_steps_follow_the_construction_group_by_group(built, case):
    """Known forces, then the two directions, then the meeting point, then the reactions; one group
    after the other in the order they are solved; the table last."""
    bu = built(case, "force-plans")
    fa = case_forces(S.resolve_case(case), m=12)
    names = {e.name for e in bu.figure.elements}
    last = 0
    for j, pl in enumerate(fa.plans):
        poly = pl.polygons[0]
        steps_known = {_step_of(bu, n) for n in names if n.startswith(f"known-{j}-")}
        assert len(steps_known) == 1          # every known side drawn (> 0.3 mm) in one step
        known = steps_known.pop()
        assert known > last or j == 0
        directed = [c for c in poly.closing if c[1] is not None]
        closing = {_step_of(bu, n) for n in names if n.startswith(f"closing-{j}-")}
        assert len(closing) == 1
        if len(directed) == 2:
            dirs = {_step_of(bu, n) for n in names if n.startswith(f"direction-{j}-")}
            assert dirs == {known + 1} and closing == {known + 2}
            labels = {_step_of(bu, f"label-{j}-{s}") for s in range(len(poly.known), len(poly.known) + 2)}
            assert labels == {known + 3}
            assert "meet" in bu.captions()[known + 2]
        else:
            assert closing == {known + 1}
        last = max(closing)
    assert _step_of(bu, "table") == len(bu) - 1 and "M_b" in bu.captions()[-1]


@pytest.mark.parametrize("case", ["press", "four-bar", "shaper"])
def test_force_plan_captions_give_what_the_drawing_measures(built, case):
    """Each closing side's value in the caption is its drawn length × μ_F (0.3 % = the caption's
    5 digits and the drawing's 3 decimals of a mm)."""
    bu = built(case, "force-plans")
    assert bu.enlarged > 1.0
    mu_F = bu.figure.scales()[0].per_mm
    rec = record(bu.figure)
    meets = [c for c in bu.captions() if c.startswith("The two lines meet")]
    assert meets
    for cap in meets:
        k = bu.captions().index(cap)
        drawn = sorted(n for n in _names(bu)[k] if n.startswith("closing-"))
        values = [float(v) for v in re.findall(rf"= {NUMBER} N", cap)]
        assert len(values) == len(drawn) == 2
        for name, value in zip(drawn, values):
            # a slide for a projector is drawn bu.enlarged : 1; μ_F is per mm of the drawing at 1 : 1
            assert rec.vector_length_mm(name) / bu.enlarged * mu_F == pytest.approx(value, rel=3e-3, abs=mu_F * 2e-3)


@pytest.mark.parametrize("case", ["press", "four-bar", "six-bar-press"])
def test_the_directions_said_are_the_directions_drawn(built, case):
    """'∥ AB' in a caption: the dashed line drawn in that step is parallel to A–B of the linkage in
    that position (positions from the kinematics core); '⊥ the guide': perpendicular to the slider's
    line."""
    bu = built(case, "force-plans")
    mo = case_forces(S.resolve_case(case), m=12).motion
    rec = record(bu.figure)
    checked = 0
    for k, cap in enumerate(bu.captions()):
        if not cap.startswith("Through the end of the chain"):
            continue
        lines = sorted(n for n in _names(bu)[k] if n.startswith("direction-"))
        rels = re.findall(r"the line of \S+ (∥ \w+|⊥ the guide)", cap)
        assert len(rels) == len(lines) == 2
        for name, rel in zip(lines, rels):
            (x0, y0), (x1, y1) = rec.in_group(name, "path")[0].data[0][:2]
            drawn = complex(x1 - x0, -(y1 - y0))
            if rel.startswith("∥"):
                a, b = re.fullmatch(r"∥ ([A-Z]\d?)([A-Z]\d?)", rel).groups()
                seg = complex(mo.z[b][3] - mo.z[a][3])
                assert abs((np.conj(seg) * drawn).imag) / abs(seg) / abs(drawn) < 1e-3
            else:
                assert abs(drawn.real) / abs(drawn) < 1e-3      # the press's guide is horizontal
            checked += 1
    assert checked >= 2


@pytest.mark.parametrize("case", ["press", "four-bar", "shaper", "slotted-lever"])
def test_lever_captions_moments_balance_by_the_power_method(built, case):
    """The moments about p said step by step sum to sense·M_b, and M_b from the power balance (an
    independent method: Σ F·v + Σ M·ω) is the value the last caption gives."""
    bu = built(case, "zhukovsky-lever")
    fa = case_forces(S.resolve_case(case), m=12)
    sense = fa.motion.linkage.sense
    total = 0.0
    for cap in bu.captions():
        m = re.search(rf"is {NUMBER}(·10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+))? N·m$", cap)
        if m:
            total += float(m.group(1).replace("−", "-"))
    Mb_power = float(fa.M_balance_power[3])
    assert total == pytest.approx(sense * Mb_power, rel=2e-3, abs=1e-3 * abs(Mb_power))
    said = float(re.search(rf"M_b = F_b·l_{{OA}} = {NUMBER} N·m", bu.captions()[-1]).group(1).replace("−", "-"))
    assert said == pytest.approx(Mb_power, rel=1e-5)
    # every force of the lever is in a step of its own (a couple's two forces together), before F_b
    forces = [n for ns in _names(bu) for n in ns if n.startswith("force-")]
    assert _step_of(bu, "F_b") == len(bu) - 2 and all(_step_of(bu, n) < len(bu) - 2 for n in forces)


@pytest.mark.parametrize("lang,script", [("ru", "[А-Яа-я]"), ("zh", "[\u4e00-\u9fff]")])
def test_force_captions_are_in_the_figures_language(built, lang, script):
    for figure in ("force-plans", "zhukovsky-lever"):
        bu, en = built("shaper", figure, lang=lang), built("shaper", figure)
        assert len(bu) == len(en) and bu.figure.notation == lang
        assert all(re.search(script, markup.plain(c)) for c in bu.captions()), bu.captions()


def test_a_bad_position_is_refused_with_a_message():
    for figure in ("force-plans", "zhukovsky-lever"):
        with pytest.raises(InputError, match="give a position number 0…12"):
            S.build("press", figure, position=13)
    with pytest.raises(InputError, match="needs a linkage"):
        S.build("W1", "force-plans")


def test_cli_writes_the_force_plan_steps(tmp_path, capsys):
    out = tmp_path / "fp.html"
    assert main(["steps", "press", "force-plans", "--position", "3", "--format", "html", "--lang", "zh",
                 "--out", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert "力多边形" in text and "<script" in text
    shown = capsys.readouterr().out
    assert re.search(r"wrote .*fp\.html: 8 steps", shown)
    assert main(["steps", "press", "zhukovsky-lever", "--position", "13", "--out", str(tmp_path / "z.pdf")]) == 2
    err = capsys.readouterr().err
    assert "position 13" in err and len(err.strip().splitlines()) == 1 and not (tmp_path / "z.pdf").exists()
    assert math.isfinite(len(shown))
