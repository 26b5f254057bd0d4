"""The A1 force-analysis sheet (the course project's second sheet), the inner reaction's own polygon on
each group's force plan, the Russian and Chinese force symbols, and ``graphmethods forces --sheet``."""

import math

import pytest

from graphmethods import cli
from graphmethods.dynamics.forces import case_forces
from graphmethods.errors import InputError
from graphmethods.problems import builtin
from graphmethods.render.recording import record
from graphmethods.sheets.force_analysis_sheet import force_analysis_sheet
from graphmethods.sheets.forces import force_plans, force_scheme


def _walk(elements):
    for e in elements:
        yield e
        yield from _walk(getattr(e, "elements", ()) or ())


def _number(text: str) -> float:
    return float(text.replace("−", "-").replace(",", ".").replace(" ", ""))


@pytest.mark.parametrize("name, k", [("press", 3), ("shaper", 4), ("four-bar", 7)])
def test_the_sheet_holds_scheme_lever_plans_and_the_result_table_of_that_position(name, k):
    case = builtin.case(name)
    fa = case_forces(case, m=12)
    s = force_analysis_sheet(case, position=k, notation="en")
    assert (s.page.size, s.page.orientation, s.page.frame) == ("A1", "landscape", True)
    names = [e.name for e in s.elements]
    assert {"scheme", "lever", "plans", "result"} <= set(names)
    boxes = {n: s.element(n).bbox() for n in ("scheme", "lever", "plans")}
    x0, y0, x1, y1 = s.page.inner_box()
    for a, A in boxes.items():                      # the parts lie apart inside the frame
        assert x0 <= A[0] and A[2] <= x1 and y0 <= A[1] and A[3] <= y1
        for b, B in boxes.items():
            if a < b:
                assert A[2] <= B[0] or B[2] <= A[0] or A[3] <= B[1] or B[3] <= A[1]
    rows = s.element("result").rows
    values = [_number(r[1]) for r in rows[1:]]
    for v, exact in zip(values, (fa.M_balance[k], fa.M_balance_lever[k], fa.M_balance_power[k])):
        assert v == pytest.approx(float(exact), rel=1e-5)
    for r, other in zip(rows[2:], (fa.M_balance_lever, fa.M_balance_power)):
        d = _number(r[2])               # printed to three decimals of a per cent, as a course project does
        assert r[2].count(".") + r[2].count(",") == 1 and len(r[2].replace(",", ".").split(".")[1]) == 3
        assert d == pytest.approx(float(fa.difference_percent(other)[k]), abs=5e-4) and d < 1e-3
    # every scale of the parts is in the scene, and the title block holds the scheme's (lever and scheme may share μ_l)
    assert len(s.scales()) >= 3 and any("μ_l" in c for c in s.page.title_block.scales)


def test_a2_a_crank_angle_and_bad_input():
    case = builtin.case("press")
    s = force_analysis_sheet(case, phi_deg=100.0, page="A2", notation="zh")
    assert s.page.size == "A2" and "φ = 100°" in s.title
    with pytest.raises(InputError, match="position 13"):
        force_analysis_sheet(case, position=13)
    with pytest.raises(InputError, match="A1 or A2"):
        force_analysis_sheet(case, position=3, page="A4")
    with pytest.raises(InputError, match="linkage problem"):
        force_analysis_sheet(object())


@pytest.mark.parametrize("name", ["press", "shaper", "six-bar-press", "four-bar", "two-slider"])
@pytest.mark.parametrize("k", [1, 3, 8])
def test_each_link_s_own_polygon_closes_on_its_group_s_plan_with_the_inner_reaction(name, k):
    """R_12 + F_i2 + R_32 = 0 drawn: the inner reaction's vectors are the reactions to μ_F and, with the
    group plan's side F_i2, close (the last tip is the first tail)."""
    case = builtin.case(name)
    fa = case_forces(case, m=12)
    s = force_plans(case, position=k)
    mu = s.scales()[0].per_mm
    vecs = {e.name: e for e in s.elements}
    seen = 0
    for j, pl in enumerate(fa.plans):
        for t, inner in enumerate(pl.polygons[1:]):
            drawn = {n.split("-", 3)[3]: v for n, v in vecs.items() if n.startswith(f"inner-{j}-{t}-")}
            if not drawn:
                continue
            sides = [lbl for lbl, _ in inner.known] + [lbl for lbl, _, _ in inner.closing]
            for lbl, v in drawn.items():
                F = [Fv for lb, Fv in inner.known if lb == lbl] + [Fv for lb, _, Fv in inner.closing if lb == lbl]
                z = complex(F[0][k]) / mu
                assert v.end[0] - v.start[0] == pytest.approx(z.real, abs=1e-9)
                assert v.end[1] - v.start[1] == pytest.approx(-z.imag, abs=1e-9)
                assert v.known is False
            # the chain of the link's sides, the shared ones taken from the group polygon, is closed
            total = sum((complex(Fv[k]) for _, Fv in inner.known), 0j) + sum((complex(Fv[k]) for _, _, Fv in
                                                                              inner.closing), 0j)
            scale = max(abs(complex(Fv[k])) for _, Fv in inner.known)
            assert abs(total) <= 1e-9 * scale
            first, last = drawn.get(sides[0]), drawn[sides[-1]]
            if first is not None:
                assert math.dist(first.start, last.end) < 1e-9
            seen += 1
    assert seen >= 1


def test_russian_and_chinese_force_symbols_as_the_books_write_them():
    case = builtin.case("four-bar")

    def texts(scene):
        return {c.data.text for c in record(scene).calls if c.kind == "text"}

    ru, zh, en = (texts(force_scheme(case, position=3, notation=n)) for n in ("ru", "zh", "en"))
    assert any(t.startswith("Fи2") for t in ru) and any(t.startswith("Mи3") for t in ru) and "Mур" in ru
    assert any(t.startswith("FI2") for t in zh) and "M b" not in zh and "Mb" in zh
    assert any(t.startswith("Fi2") for t in en) and not any("и" in t for t in en)
    sheet_ru = texts(force_analysis_sheet(case, position=3, notation="ru"))
    assert "Fур" in sheet_ru and any("Mур" in t for t in sheet_ru)


@pytest.fixture
def run(capsys):
    def _run(*argv):
        rc = cli.main(["forces", *map(str, argv)])
        out, err = capsys.readouterr()
        return rc, out, err
    return _run


def test_forces_sheet_is_written_and_never_overwritten_without_force(run, tmp_path):
    f = tmp_path / "forces.svg"
    rc, out, err = run("press", "--position", 3, "--sheet", f, "--lang", "ru")
    assert rc == 0 and f.read_bytes().startswith(b"<?xml") and "wrote" in out
    before = f.read_bytes()
    rc, out, err = run("press", "--position", 5, "--sheet", f)
    assert rc == 2 and "--force" in err and len(err.strip().splitlines()) == 1 and f.read_bytes() == before
    rc, _, _ = run("press", "--position", 5, "--sheet", f, "--force")
    assert rc == 0 and f.read_bytes() != before
    pdf = tmp_path / "forces.pdf"
    rc, _, _ = run("shaper", "--position", 3, "--sheet", pdf, "--page", "A2", "--json")
    assert rc == 0 and pdf.read_bytes().startswith(b"%PDF")
    # the same input gives the same bytes
    again = tmp_path / "again.pdf"
    run("shaper", "--position", 3, "--sheet", again, "--page", "A2")
    assert again.read_bytes() == pdf.read_bytes()


@pytest.mark.parametrize("argv, words", [
    (("--position", 3, "--sheet", "x.txt"), "ending in .svg"),
    (("--position", 3, "--sheet", "nowhere/x.svg"), "does not exist"),
    (("--position", 3, "--sheet", ""), "--sheet is empty"),
    (("--position", 3, "--sheet", "x.svg", "--n", 30), "leave out --n"),
])
def test_forces_sheet_bad_input_is_one_line_exit_2_and_no_file(run, tmp_path, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    rc, _, err = run("press", *argv)
    assert rc == 2 and words in err and len(err.strip().splitlines()) == 1
    assert list(tmp_path.iterdir()) == []


# ----------------------------------------------------------------------------- issue 26: the sheet as drawn

def _texts(scene):
    return [c.data.text for c in record(scene).calls if c.kind == "text"]


@pytest.mark.parametrize("name", ["press", "shaper", "two-slider", "triad-six-bar"])
def test_every_plan_has_its_own_panel_and_the_reactions_it_prints_are_the_json_s(name, capsys):
    """One truth: each group's plan prints the reactions it finds (length × its own μ_F = |R|) and every value
    equals ``forces --position 3 --json``'s reaction (round-off below 10⁻⁹ of the largest printed as 0)."""
    import json

    from graphmethods.sheets.force_sheet_plans import plan_sides

    case = builtin.case(name)
    fa = case_forces(case, m=12)
    s = force_analysis_sheet(case, position=3, notation="en")
    assert cli.main(["forces", name, "--position", "3", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    R = {k: math.hypot(*v) for k, v in data["reactions"].items()}             # [R_x, R_y], N
    plans = s.element("plans")
    names = [e.name for e in plans.elements]
    assert names == [f"{kind}-{j}" for j in range(len(fa.plans)) for kind in ("group", "plan")]
    big = max(abs(r.R[3]) for r in fa.reactions.values())
    found = [t for e in _walk(plans.elements) if e.name.startswith("found-") for t in [e.text]]
    assert found
    for line in found:
        label, rest = line.split(" = ", 1)
        mm, mu, value = rest.split(" · ")[0], rest.split(" · ")[1].split(" = ")[0], rest.split(" = ")[-1]
        value_N = _number(value.split()[0])
        key = "R_" + label.split("_")[-1].strip("{}")
        key = key if key in fa.reactions else "R_" + key[2:][::-1]
        exact = float(abs(fa.reactions[key].R[3]))
        assert value_N == pytest.approx(exact if exact > 1e-9 * big else 0.0, rel=1e-4, abs=1e-9 * big)
        assert _number(mm.split()[0]) * _number(mu.split()[0]) == pytest.approx(value_N, rel=2e-3, abs=1e-6 * big)
        assert value_N == pytest.approx(R[key], rel=1e-4, abs=1e-9 * big)
    # the crank's plan is a closed polygon of R_21, F_b (⊥ OA, F_b·l_OA = M_b) and R′_01: not one line
    sides = plan_sides(fa, len(fa.plans) - 1, 3)
    assert abs(sum(F for _, F, _ in sides)) <= 1e-9 * big
    drawn = [F for _, F, _ in sides if abs(F) > 1e-9 * big]
    assert len(drawn) >= 3 and any(abs((a * b.conjugate()).imag) > 1e-6 * abs(a) * abs(b) for a in drawn for b in drawn)
    mo = fa.motion
    OA = complex(mo.z[mo.linkage.crank.pin][3]) - complex(mo.z[mo.linkage.crank.centre][3])
    F_b = {lbl: F for lbl, F, _ in sides}["F_b"]
    assert abs((OA.conjugate() * F_b).real) <= 1e-9 * abs(OA) * abs(F_b)
    assert (OA.conjugate() * F_b).imag == pytest.approx(float(fa.M_balance[3]), rel=1e-9)


def test_round_off_prints_as_zero_and_the_balancing_graph_is_the_plans_m_b():
    from graphmethods.sheets.engine.quality import measure

    for name in ("two-slider", "scotch-yoke"):
        s = force_analysis_sheet(builtin.case(name), position=3, notation="ru")
        assert measure(s).noise == ()
    case = builtin.case("shaper")
    fa = case_forces(case, m=12)
    s = force_analysis_sheet(case, position=3, notation="en")
    graph = s.element("balancing")
    ordinates = [e for e in _walk(graph.elements) if e.name.startswith("ordinate-") and e.name[9:].isdigit()]
    assert len(ordinates) == 13
    mark = next(e for e in _walk(graph.elements) if e.name == "mark-value")
    assert _number(mark.text.split(" = ")[1].split()[0]) == pytest.approx(float(fa.M_balance[3]), rel=1e-6)


def test_a_ternary_link_is_drawn_as_a_hatched_plate_on_the_scheme_and_its_group():
    s = force_analysis_sheet(builtin.case("triad-six-bar"), position=3, notation="zh")
    plates = [e.name for e in _walk(s.elements) if e.name.startswith("plate-")]
    assert plates.count("plate-BCD") == 2 and plates.count("plate-BCD-hatch") == 2
    four_bar = force_analysis_sheet(builtin.case("four-bar"), position=3)
    assert not any(e.name.startswith("plate-") for e in _walk(four_bar.elements))
