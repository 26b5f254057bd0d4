"""The benchmark's measurements are right (not its times: those are reported, never asserted)."""

import importlib.util
import json

import numpy as np
import pytest

from graphmethods import bench
from graphmethods.cli import main


@pytest.fixture(scope="module")
def flywheel_rows():
    return bench.bench_flywheel(m_values=(12, 96), repeat=1, linkages=("four-bar",))


def test_error_estimates_are_within_twice_the_true_error(flywheel_rows):
    ratios = [r.extra["estimate/true"] for r in flywheel_rows if r.method.startswith("Wittenbauer")]
    assert len(ratios) == 8
    assert all(0.5 <= q <= 2.0 for q in ratios), ratios


def test_every_problem_has_an_exact_reference_and_both_methods(flywheel_rows):
    cases = {r.case for r in flywheel_rows}
    assert len(cases) == 5
    for case in cases - {"four-bar"}:
        methods = {r.method for r in flywheel_rows if r.case == case} - {
            "exact: independent scipy solver (bench_reference.py)"}
        assert methods == {"exact", "Wittenbauer (chords)", "ΔW_max method"}
    press_exact = next(r for r in flywheel_rows if r.case.startswith("press") and r.method == "exact")
    assert round(press_exact.extra["J_F"], 2) == 13.94
    four_bar = {r.method: r for r in flywheel_rows if r.case == "four-bar"}
    if importlib.util.find_spec("scipy") is None:       # the bench extra is not installed: its own bound only
        assert set(four_bar) == {"exact"} and four_bar["exact"].error <= 1e-12
        return
    assert set(four_bar) == {"exact", bench.REFERENCE_METHOD}
    exact = four_bar["exact"]
    # its error is against the independent solver's J_F, and the ratio is of interleaved pairs
    J_ref = four_bar[bench.REFERENCE_METHOD].extra["J_F"]
    assert exact.error == pytest.approx(abs(exact.extra["J_F"] - J_ref) / J_ref, rel=1e-9) and exact.error <= 1e-12
    assert exact.extra["ratio to scipy"] > 0 and exact.holds is not None


def test_methods_are_timed_apart(flywheel_rows):
    for case in {r.case for r in flywheel_rows} - {"four-bar"}:
        w = [r.seconds for r in flywheel_rows if r.case == case and r.method.startswith("Wittenbauer")]
        e = [r.seconds for r in flywheel_rows if r.case == case and r.method.startswith("ΔW_max")]
        assert len(w) == len(e) == 2 and w != e


def test_the_independent_scipy_solver_agrees_with_ours():
    pytest.importorskip("scipy")
    from graphmethods.bench_reference import press_flywheel
    from graphmethods.dynamics.study import Study

    for changes in ({}, {"m3": 200.0, "F0": 500.0, "delta": 0.3}):
        s = Study(bench._press_case(**changes))
        assert press_flywheel(bench._press_data(**changes)) == pytest.approx(s.exact.J_F, rel=1e-12)
    rows = bench.bench_flywheel(m_values=(), repeat=1, linkages=())
    exact = [r for r in rows if r.method == "exact" and r.case.startswith(("press", "heavy"))]
    assert len(exact) == 2 and all(r.error <= 1e-12 and "ratio to scipy" in r.extra for r in exact)


@pytest.mark.parametrize("name", sorted(bench.REFERENCES))
def test_the_closed_form_references_agree_with_the_linkage_core(name):
    """Each closed form of bench_reference.py (its own kinematics, load and solver) gives the exact J_F of the
    built-in linkage solved by the Assur-group core, to 1e-12."""
    pytest.importorskip("scipy")
    from graphmethods.dynamics.study import Study
    from graphmethods.problems import builtin

    reference, _ = bench._linkage_reference(name)
    assert reference is not None
    assert reference() == pytest.approx(Study(builtin.case(name)).exact.J_F, rel=1e-12)


def test_a_changed_problem_changes_the_reference_alike():
    """The closed forms read the problem's data: a heavier rocker and a load on half the swing move both."""
    pytest.importorskip("scipy")
    from graphmethods.bench_reference import four_bar_flywheel
    from graphmethods.dynamics.study import Study
    from graphmethods.kinematics import case_from_dict
    from graphmethods.problems import builtin

    path = builtin.DATA / builtin.LINKAGES["four-bar"]
    data = {**json.loads(path.read_text(encoding="utf-8")), "m3": 6.0, "J_S3": 0.05, "moment_from": 0.25,
            "moment_to": 0.75}
    J_core = Study(case_from_dict(data, source=str(path))).exact.J_F
    assert four_bar_flywheel(data) == pytest.approx(J_core, rel=1e-12)
    assert abs(J_core / Study(builtin.case("four-bar")).exact.J_F - 1) > 0.01


#: one link length of each slider linkage changed: (built-in name, the file's keys down to the length, new value)
ALTERED_LENGTHS = [("shaper", ("l_O3B",), 0.60),
                   ("six-bar-press", ("groups", 1, "l"), 0.40),
                   ("whitworth", ("points", "B", "distance"), 0.18),
                   ("slotting-machine", ("points", "B", "distance"), 0.55),
                   ("two-slider", ("crank", "r"), 0.07)]


@pytest.mark.parametrize(("name", "keys", "value"), ALTERED_LENGTHS)
def test_an_altered_link_moves_the_slider_references_and_the_core_alike(name, keys, value):
    """The closed forms read the problem file's lengths: a longer or shorter link moves both J_F alike."""
    pytest.importorskip("scipy")
    import copy

    from graphmethods import bench_reference
    from graphmethods.dynamics.study import Study
    from graphmethods.kinematics import case_from_dict
    from graphmethods.problems import builtin

    path = builtin.DATA / builtin.LINKAGES[name]
    data = copy.deepcopy(json.loads(path.read_text(encoding="utf-8")))
    inner = data
    for k in keys[:-1]:
        inner = inner[k]
    assert inner[keys[-1]] != value
    inner[keys[-1]] = value
    J_core = Study(case_from_dict(data, source=str(path))).exact.J_F
    assert getattr(bench_reference, bench.REFERENCES[name][0])(data) == pytest.approx(J_core, rel=1e-12)
    assert abs(J_core / Study(builtin.case(name)).exact.J_F - 1) > 0.01


def test_paired_timings_interleave_and_take_the_median_ratio():
    calls = []
    pair = bench.paired(lambda: calls.append("a"), lambda: calls.append("b"), repeat=4)
    assert calls == ["a", "b", "b", "a", "a", "b", "b", "a"]
    assert pair.a > 0 and pair.b > 0 and pair.ratio > 0


def test_markdown_shows_targets_and_whether_they_hold():
    rows = [bench.Row("s", "c", "m", target="≤ 2×", holds=False), bench.Row("s", "c", "n", target="≤ 3×", holds=True)]
    md = bench.to_markdown(rows)
    assert "| target | holds |" in md and "| ≤ 2× | **no** |" in md and "| ≤ 3× | yes |" in md


def test_kinematics_rows_agree_with_the_hand_written_closed_forms_and_pair_with_them():
    rows = bench.bench_kinematics(n=2000, repeat=3)
    plans = [r for r in rows if r.method.startswith("velocity plans")]
    assert len(plans) == 4 and all(r.error < 1e-12 for r in plans)
    positions = [r for r in rows if r.method == "positions"]
    assert len(positions) == 4 and all(r.error < 1e-12 for r in positions)
    paired = [r for r in rows if r.method == "positions + velocity plans (core)"]
    assert len(paired) == 4 and all(r.extra["ratio"] > 0 and r.error < 1e-12 for r in paired)
    assert [r.method for r in rows].count("hand-written numpy closed form (point B only)") == 3
    fd = {r.method: r.error for r in rows if r.case == "slider_crank" and r.method.startswith("central")}
    assert fd["central differences h = 0.0001"] < fd["central differences h = 0.01"]


def test_closed_forms_of_the_classic_kinds_are_not_the_core():
    """A wrong closed form would show as a large error: the slider-crank's at another offset differs."""
    phi = np.linspace(0.0, 6.0, 50)
    xy, d = bench.classic_closed_form("slider_crank", {"r": 0.1, "l": 0.4, "e": 0.02}, phi)
    xy0, d0 = bench.classic_closed_form("slider_crank", {"r": 0.1, "l": 0.4, "e": 0.0}, phi)
    assert np.abs(d - d0).max() > 1e-3
    h = 1e-6                                              # its velocity analogue is the derivative of its positions
    up, _ = bench.classic_closed_form("shaper", SHAPER, phi + h)
    dn, _ = bench.classic_closed_form("shaper", SHAPER, phi - h)
    _, ds = bench.classic_closed_form("shaper", SHAPER, phi)
    assert np.abs((up - dn) / (2 * h) - ds).max() < 1e-7
    with pytest.raises(ValueError):
        bench.classic_closed_form("cam", {}, phi)


SHAPER = {"r": 0.11, "l_O1O3": 0.38, "l_O3B": 0.54, "l_BC": 0.135, "y_guide": 0.1484}


def test_areas_numpy_and_shapely_agree():
    rows = bench.bench_areas(sizes=(10**3, 10**4), crossings=(2, 1000), repeat=1)
    assert rows and all(r.error < 1e-9 for r in rows)


def test_bench_command_writes_its_report(tmp_path, capsys):
    assert main(["bench", "--quick", "--only", "areas", "--out", str(tmp_path)]) == 0
    md = (tmp_path / "bench.md").read_text()
    data = json.loads((tmp_path / "bench.json").read_text())
    assert md.startswith("| section |") and data and data[0]["section"] == "areas"
    assert main(["bench", "--quick", "--only", "areas", "--out", str(tmp_path)]) == 2     # no overwrite
    assert "--force" in capsys.readouterr().err
    assert main(["bench", "--only", "nonsense"]) == 2


def test_calculus_rows_shrink_with_more_intervals():
    rows = bench.bench_calculus(ms=(12, 48), repeat=1)
    v = [r for r in rows if r.case == "press: v by chords of s"]
    err = [float(r.note.split()[2]) for r in v]
    assert len(v) == 2 and err[1] < err[0] / 8          # second order: ×16 fewer for ×4 more intervals


def test_sheet_row_builds_only_what_the_sheet_draws():
    row, *kinematic = bench.bench_sheet(repeat=1)
    assert "exact" not in row.note and "wittenbauer" in row.note
    assert kinematic and all(r.case.startswith("kinematic A1 sheet") for r in kinematic)


def test_worksheet_rows_count_the_pages_and_compare_the_pdf_writers():
    rows = bench.bench_worksheet(variants=2, kinds=("indicator",), repeat=1, cli=False)
    assert [(r.method, r.size) for r in rows] == [("build + PDF + SVG + problem files", 4),
                                                  ("PDF: graphmethods.render.pdf", 1), ("PDF: matplotlib backend", 1)]
    assert "4 pages" in rows[0].note
    assert rows[1].extra["speedup_vs_matplotlib"] == pytest.approx(rows[2].extra["ratio_to_ours"])


def test_linkage_rows_core_equals_the_hand_written_linkages_and_carry_their_targets():
    rows = bench.bench_linkage(sizes=(12, 10**4), repeat=3)
    core = {(r.case, r.method, r.size): r for r in rows if r.method.startswith("core")}
    assert set(core) == {("six-bar press", "core: Linkage.motion(phi=) (p + v + a)", 12),
                         ("six-bar press", "core: Linkage.motion(m=12) (p + v + a)", 13),
                         ("slider-crank press", "core: Linkage.motion(m=12) (p + v + a)", 13),
                         ("six-bar press", "core: Linkage.motion(phi=) (p + v + a)", 10**4)}
    assert all(r.error < 1e-12 and r.extra["ratio"] > 0 for r in core.values())
    assert [r.target for r in core.values()].count("≤ 0.5 ms and ≤ 3× closed form") == 3
    assert all(isinstance(r.holds, bool) for r in core.values())
    assert len([r for r in rows if r.method == "hand-written numpy closed form"]) == 4


def test_the_press_closed_form_is_its_own_derivative():
    phi = np.linspace(0.0, 6.0, 40)
    h = 1e-5
    up, dn = (bench.slider_crank_closed_form(phi + s, 1.0, 0.0) for s in (h, -h))
    out = bench.slider_crank_closed_form(phi, 1.0, 0.0)
    assert np.abs((up["B"][0] - dn["B"][0]) / (2 * h) - out["v_B"]).max() < 1e-8
    assert np.abs((up["v_B"] - dn["v_B"]) / (2 * h) - out["a_B"]).max() < 1e-7
    assert np.abs((up["omega_2"] - dn["omega_2"]) / (2 * h) - out["eps_2"]).max() < 1e-7


def test_gallery_rows_name_the_slowest_and_the_label_share():
    rows = bench.bench_gallery(repeat=1, names=("w1_energy_indicator_en", "press_velocity_plan_en"))
    total, share = rows
    assert total.size == 2 and "slowest: " in total.note and share.target == "≤ 10 %"
    assert 0 < float(share.note.split()[0]) < 100


def test_startup_row_reaches_the_periodic_solution_within_its_target():
    rows = bench.bench_motion(rtols=(1e-8,), repeat=1)
    ref, start = rows
    assert ref.method.startswith("motor study") and ref.error < 1e-12
    assert start.error is not None and start.error < bench.STARTUP_TARGET["error"]
    assert "target" in start.note and isinstance(start.extra["target_met"], bool)


def test_the_error_against_time_plot_takes_any_number_of_problems(flywheel_rows, tmp_path):
    extra = [bench.Row("flywheel", f"linkage {i}", "exact", None, 0.01, 1e-13) for i in range(8)]
    bench.plot_error_vs_time(flywheel_rows + extra, tmp_path / "e.svg")
    bench.plot_error_vs_time(flywheel_rows + extra, tmp_path / "e.png")
    assert (tmp_path / "e.svg").read_text().startswith("<?xml") and (tmp_path / "e.png").read_bytes()[:4] == b"\x89PNG"
