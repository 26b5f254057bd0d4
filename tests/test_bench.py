"""The benchmark's measurements are right (not its times: those are reported, never asserted)."""

import json
import math

import pytest

from graphmethods import bench
from graphmethods.cli import main


@pytest.fixture(scope="module")
def flywheel_rows():
    return bench.bench_flywheel(m_values=(12, 96), repeat=1)


def test_error_estimates_are_within_twice_the_true_error(flywheel_rows):
    ratios = [r.extra["estimate/true"] for r in flywheel_rows if r.method.startswith("Wittenbauer")]
    assert len(ratios) == 8
    assert all(0.5 <= q <= 2.0 for q in ratios), ratios


def test_every_problem_has_an_exact_reference_and_both_methods(flywheel_rows):
    cases = {r.case for r in flywheel_rows}
    assert len(cases) == 4
    for case in cases:
        methods = {r.method for r in flywheel_rows if r.case == case}
        assert methods == {"exact", "Wittenbauer (chords)", "ΔW_max method"}
    press_exact = next(r for r in flywheel_rows if r.case.startswith("press") and r.method == "exact")
    assert round(press_exact.extra["J_F"], 2) == 13.94


def test_kinematics_rows_agree_with_the_analytic_derivative():
    rows = bench.bench_kinematics(n=2000, repeat=1)
    plans = [r for r in rows if r.method.startswith("velocity plans")]
    assert len(plans) == 4 and all(r.error < 1e-12 for r in plans)
    fd = {r.method: r.error for r in rows if r.case == "slider_crank" and r.method.startswith("central")}
    assert fd["central differences h = 0.0001"] < fd["central differences h = 0.01"]


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
    (row,) = bench.bench_sheet(repeat=1)
    assert "exact" not in row.note and "wittenbauer" in row.note


def test_worksheet_rows_count_the_pages_and_compare_the_pdf_writers():
    rows = bench.bench_worksheet(variants=2, kinds=("indicator",), repeat=1, cli=False)
    assert [(r.method, r.size) for r in rows] == [("build + PDF + SVG + problem files", 4),
                                                  ("PDF: graphmethods.render.pdf", 1), ("PDF: matplotlib backend", 1)]
    assert "4 pages" in rows[0].note
    assert rows[1].extra["speedup_vs_matplotlib"] == pytest.approx(rows[2].extra["ratio_to_ours"])


def test_linkage_rows_core_equals_the_hand_written_six_bar_and_keeps_pace():
    rows = bench.bench_linkage(sizes=(12, 10**4), repeat=3)
    core = {r.size: r for r in rows if r.method.startswith("core")}
    hand = {r.size: r for r in rows if r.method.startswith("hand")}
    assert set(core) == set(hand) == {12, 10**4} and all(r.error < 1e-12 for r in core.values())
    for n in core:                          # the ratio is of the two medians of the same interleaved runs
        assert core[n].extra["ratio"] == pytest.approx(core[n].seconds / hand[n].seconds)
    # the targets on the best of the interleaved runs (medians swing on a shared machine):
    # within 4× from 10⁴ positions up, and a 12-position call under 0.5 ms
    assert core[10**4].extra["ratio_best"] < bench.LINKAGE_RATIO_MAX
    assert core[12].extra["best_s"] < bench.LINKAGE_FIXED_MAX_S
    assert "target" in core[10**4].note and "fixed cost" in core[12].note
