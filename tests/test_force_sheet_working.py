"""The force sheet's working (the inertia loads and each group's moment equation with numbers) and its
composition: the numbers are ``forces --json``'s, the parts' boxes lie apart inside the frame, every part's
drawing stays in its box, and the sheet is deterministic."""

import json
import math
import re

import pytest

from graphmethods import cli
from graphmethods.problems import builtin
from graphmethods.sheets.force_analysis_sheet import force_analysis_sheet, force_sheet_boxes, sheet_page
from graphmethods.sheets.force_working import inertia_working, moment_working, power_working, working_lines
from graphmethods.sheets.forces import analysed

try:
    from test_force_analysis_sheet import _number, _walk
except ImportError:                                     # run from the repository root as a package
    from tests.test_force_analysis_sheet import _number, _walk


def _json(name, capsys):
    assert cli.main(["forces", name, "--position", "3", "--json"]) == 0
    return json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("name, lang", [("shaper", "en"), ("press", "ru"), ("six-bar-press", "zh")])
def test_the_inertia_working_prints_the_json_s_loads_and_arms(name, lang, capsys):
    data = _json(name, capsys)
    case = builtin.case(name)
    fa, i = analysed(case, position=3, phi_deg=None, m=12)
    lines = inertia_working(case, fa, i, lang)
    assert lines
    for line in lines:
        head, value = line.split(" = ")[0], line.split(" = ")[-1]
        k = re.search(r"_\{\D*(\d+)\}", head).group(1)
        link = data["links"][k]
        v = _number(value.split()[0])
        if head.startswith("F"):
            assert v == pytest.approx(abs(complex(*link["F_i"])), rel=1e-4)
            m, a = (_number(t) for t in line.split(" = ")[2].split("·"))
            assert m * a == pytest.approx(v, rel=1e-3)
        elif head.startswith("M"):
            assert v == pytest.approx(abs(link["M_i"]), rel=1e-4)
        else:
            assert v == pytest.approx(link["h"], rel=1e-4)


@pytest.mark.parametrize("name", ["press", "shaper", "four-bar", "six-bar-press"])
def test_each_moment_equation_closes_and_finds_the_json_s_reaction(name, capsys):
    """ΣM = 0 with the printed terms sums to zero (to their digits), and a whole reaction found by a moment
    (R_23 square to a slot) is the json's |R|; an R^τ is a part of the json's reaction, no larger."""
    data = _json(name, capsys)
    R = {k: abs(complex(*v)) for k, v in data["reactions"].items()}
    case = builtin.case(name)
    fa, i = analysed(case, position=3, phi_deg=None, m=12)
    found = 0
    for j in range(len(fa.plans)):
        lines = moment_working(fa, i, j, "en")
        for symbols, numbers in zip(lines[::2], lines[1::2]):
            assert symbols.startswith("ΣM_") and symbols.endswith(" = 0")
            equation, result = numbers.split(" = 0, ")
            label, value = result.split(" = ")
            value_N = _number(value.split()[0])
            terms = re.findall(r"[−+] [\d.]+", equation)
            arm = _number(equation.split("·")[1].split()[0])
            total = value_N * arm + sum(_number(t.replace(" ", "")) for t in terms)
            assert abs(total) <= 1e-3 * max([abs(value_N * arm)] + [abs(_number(t.replace(" ", ""))) for t in terms])
            key = "R_" + label.split("_")[-1].strip("{}")
            key = key if key in R else "R_" + key[2:][::-1]
            if "^" in label:
                assert abs(value_N) <= R[key] * (1 + 1e-4)
            else:
                assert abs(value_N) == pytest.approx(R[key], rel=1e-4)
            found += 1
    assert found >= 1


def test_the_sheet_writes_its_working_and_each_plan_its_moment_equations():
    case = builtin.case("shaper")
    s = force_analysis_sheet(case, position=3, notation="ru")
    texts = [e.text for e in _walk(s.elements) if e.name.startswith("working-") and not e.bold]
    fa, i = analysed(case, position=3, phi_deg=None, m=12)
    loads = inertia_working(case, fa, i, "ru")
    assert texts == loads + power_working(fa, i, "ru")
    moments = [e.text for e in _walk(s.element("plans").elements)
               if e.name.startswith("moment-") and hasattr(e, "text")]
    assert moments == [t for j in range(len(fa.plans)) for t in moment_working(fa, i, j, "ru")]
    assert [t for t, head in working_lines(case, fa, i, "ru") if not head][:len(texts)] == texts


def _overlap(a, b):
    return min(a[2], b[2]) - max(a[0], b[0]) > 1e-6 and min(a[3], b[3]) - max(a[1], b[1]) > 1e-6


@pytest.mark.parametrize("name", ["press", "shaper", "triad-six-bar", "scotch-yoke"])
def test_the_boxes_lie_apart_inside_the_frame_and_every_part_inside_its_box(name):
    case = builtin.case(name)
    fa, i = analysed(case, position=3, phi_deg=None, m=12)
    inner = sheet_page("A1", "force").inner_box()
    boxes = force_sheet_boxes(fa, i, (inner[0] + 5, inner[1] + 17, inner[2] - 5, inner[3] - 5), 160.0,
                              column_bottom=inner[3] - 60)
    for k, b in boxes.items():
        assert inner[0] <= b[0] < b[2] <= inner[2] and inner[1] <= b[1] < b[3] <= inner[3], k
    keys = sorted(boxes)
    assert not [(a, b) for n, a in enumerate(keys) for b in keys[n + 1:] if _overlap(boxes[a], boxes[b])]
    s = force_analysis_sheet(case, position=3)
    parts = {e.name: e.bbox() for e in s.element("plans").elements}
    parts.update({n: s.element(n).bbox() for n in ("scheme", "lever", "balancing")})
    for n, b in parts.items():                      # every part's ink inside the frame, apart from the others
        assert b is not None and inner[0] <= b[0] and b[2] <= inner[2] and inner[1] <= b[1] and b[3] <= inner[3], n
    names = sorted(parts)
    assert not [(a, b) for n, a in enumerate(names) for b in names[n + 1:] if _overlap(parts[a], parts[b])]


def test_the_force_sheet_is_deterministic():
    from graphmethods.render.svg import to_string

    case = builtin.case("shaper")
    a = to_string(force_analysis_sheet(case, position=3, notation="zh"))
    b = to_string(force_analysis_sheet(case, position=3, notation="zh"))
    assert a == b


@pytest.mark.parametrize("name, lang", [("shaper", "en"), ("press", "ru"), ("triad-six-bar", "zh")])
def test_the_sheet_s_tables_print_the_json_s_reactions_and_inertia_loads(name, lang, capsys):
    """One truth: the reactions' table (R_x, R_y, |R|) and the inertia loads' (F_иx, F_иy, |F_и|, M_и, h) hold
    ``forces --json``'s numbers, round-off printed as 0."""
    data = _json(name, capsys)
    s = force_analysis_sheet(builtin.case(name), position=3, notation=lang)
    reactions = s.element("reactions").rows
    assert len(reactions) - 1 == len(data["reactions"])
    big = max(abs(complex(*v)) for v in data["reactions"].values())
    for row in reactions[1:]:
        key = "R_" + row[0].split("{")[1].rstrip("}")
        Rx, Ry = data["reactions"][key]
        for printed, exact in zip(row[1:], (Rx, Ry, abs(complex(Rx, Ry)))):
            assert _number(printed) == pytest.approx(exact, rel=1e-4, abs=1e-9 * big)
    loads = s.element("inertia").rows
    assert [r[0] for r in loads[1:]] == list(data["links"])
    for row in loads[1:]:
        link = data["links"][row[0]]
        Fx, Fy = link["F_i"]
        for printed, exact in zip(row[1:5], (Fx, Fy, abs(complex(Fx, Fy)), link["M_i"])):
            assert _number(printed) == pytest.approx(exact, rel=1e-4, abs=1e-6)
        assert _number(row[5]) == pytest.approx(link["h"] or 0.0, rel=1e-4, abs=1e-9)


def test_the_cycle_table_prints_each_position_s_balancing_moment(capsys):
    """The M_b table's row k is ``forces --position k --json``'s M_balance (from the plans) and the lever's."""
    s = force_analysis_sheet(builtin.case("shaper"), position=3, notation="en")
    rows = s.element("cycle").rows
    assert [r[0] for r in rows[2:]] == [str(k) for k in range(13)]
    for k in (0, 3, 8):
        assert cli.main(["forces", "shaper", "--position", str(k), "--json"]) == 0
        data = json.loads(capsys.readouterr().out)
        assert _number(rows[2 + k][2]) == pytest.approx(data["M_balance"], rel=1e-4, abs=1e-6)
        assert _number(rows[2 + k][3]) == pytest.approx(data["M_balance_lever"], rel=1e-4, abs=1e-6)


@pytest.mark.parametrize("name", ["press", "shaper", "four-bar", "scotch-yoke"])
def test_the_power_working_sums_to_the_json_s_balancing_moment(name, capsys):
    """M_b by the power balance: the printed powers sum to −M_b·ω₁ (to their digits) and M_b is the json's."""
    data = _json(name, capsys)
    fa, i = analysed(builtin.case(name), position=3, phi_deg=None, m=12)
    lines = power_working(fa, i, "en")
    powers = [_number(t.split(" = ")[-1].split()[0]) for t in lines[1:-1]]
    total = _number(lines[-1].split("−(")[1].split(")")[0])
    w1 = _number(lines[-1].split(")/")[1].split()[0])
    assert sum(powers) == pytest.approx(total, rel=1e-3)
    assert _number(lines[-1].split(" = ")[-1].split()[0]) == pytest.approx(data["M_balance_power"], rel=1e-5)
    assert -total / w1 == pytest.approx(data["M_balance_power"], rel=1e-3)


@pytest.mark.parametrize("name", ["shaper", "four-bar", "whitworth"])
def test_the_loads_table_prints_the_json_s_external_loads(name, capsys):
    """One truth: each external load's row holds ``forces --json``'s point, force and couple."""
    from graphmethods.sheets.force_tables import load_rows

    data = _json(name, capsys)
    fa, i = analysed(builtin.case(name), position=3, phi_deg=None, m=12)
    rows = load_rows(fa, i, "en")
    assert len(rows) - 1 == len(data["loads"])
    head = rows[0]
    for row, load in zip(rows[1:], data["loads"]):
        cells = dict(zip(head, row))
        assert row[0].replace("{", "").replace("}", "") == load["label"] and row[1] == str(load["link"])
        if "force" in load:
            (x, y), (Fx, Fy) = load["at"], load["force"]
            exact_values = (("x, m", x), ("y, m", y), ("F_x, N", Fx), ("F_y, N", Fy), ("|F|, N", math.hypot(Fx, Fy)))
            for key, exact in exact_values:
                assert _number(cells[key]) == pytest.approx(exact, rel=1e-4, abs=1e-9)
        else:
            assert _number(cells["M, N·m"]) == pytest.approx(load["moment"], rel=1e-4)
