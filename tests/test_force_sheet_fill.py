"""The A1 force sheet filled as a course sheet is (issue 26): the result column's tables ruled to one width,
M_b(φ) in a wide box across under the drawings where the graph among them leaves the sheet over 47 % empty,
its box shaped to the finest convenient μ_M that fits, and the fuller arrangement kept."""

import importlib
import math

import pytest

from graphmethods.problems import builtin
from graphmethods.sheets.engine.quality import measure
from graphmethods.sheets.forces import analysed
from graphmethods.units import CONVENIENT

#: the module (the package exports its function under the same name)
FAS = importlib.import_module("graphmethods.sheets.force_analysis_sheet")


def _sheet(name, lang, position=3):
    return FAS.force_analysis_sheet(builtin.case(name), position=position, notation=lang)


@pytest.mark.parametrize("lang", ["en", "zh"])
def test_the_result_column_s_tables_are_ruled_to_one_width(lang):
    s = _sheet("press", lang)
    widths = {n: s.element(n).width_mm for n in ("result", "reactions", "inertia")}
    res = s.element("result").bbox()
    assert max(widths.values()) - min(widths.values()) < 0.01, widths
    cycle = s.element("cycle")
    assert abs(cycle.width_mm - widths["result"]) < 0.01 and abs(cycle.at[0] - res[0]) < 0.01


def test_widths_across_widens_in_proportion_and_never_narrows():
    from graphmethods.scene import Table

    t = Table((0, 0), (("a", "bb"), ("1", "22")), size_mm=5.0)
    w = t.column_widths()
    wide = FAS._widths_across(t, 2 * sum(w))
    assert wide is not None and abs(sum(wide) - 2 * sum(w)) < 1e-9
    assert abs(wide[0] / wide[1] - w[0] / w[1]) < 1e-12
    assert FAS._widths_across(t, 0.5 * sum(w)) is None


@pytest.mark.parametrize("name, lang", [("scotch-yoke", "en"), ("press", "zh"), ("engine", "en")])
def test_m_b_of_phi_goes_across_under_the_drawings_where_the_sheet_was_empty(name, lang):
    s = _sheet(name, lang)
    graph = s.element("balancing").bbox()
    drawn = [s.element(n).bbox() for n in ("scheme", "lever", "plans")]
    left, right = min(b[0] for b in drawn), max(b[2] for b in drawn)
    assert graph[2] - graph[0] > 0.8 * (right - left)           # as wide as the drawings
    assert all(graph[1] >= b[3] for b in drawn)                  # under every one of them
    assert graph[2] < s.element("result").bbox()[0]              # left of the result column
    q = measure(s)
    assert q.empty_share <= 0.48 and not q.crossed and not q.overlaps


def test_the_wide_graph_s_box_is_shaped_to_a_convenient_scale_and_holds_it():
    case = builtin.case("scotch-yoke")
    fa, i = analysed(case, position=3, phi_deg=None, m=12)
    pg = FAS.sheet_page("A1", "force-analysis")
    from graphmethods.scene import notation
    from graphmethods.sheets.balancing_graph import balancing_graph
    from graphmethods.sheets.composition import region_page

    parts = FAS._Parts(case, fa, i, notation("en"), pg, None, 12, False, (), [], ([],), (5.0, 3.5, 5.0, 10.0), "x")
    left = (25.0, 30.0, 640.0, 579.0)
    share = FAS._wide_share(parts, left)
    lo, hi = FAS.WIDE_GRAPH
    assert lo <= share <= hi
    H = left[3] - left[1] - 10.0
    box = (left[0], left[1], left[2], left[1] + share * H)
    g = balancing_graph(fa, i, notation="en", page=region_page(pg, box))
    ink = g.bbox()
    assert ink[3] <= box[3] + 1e-6                              # the graph fits its box, its μ_M convenient
    (mu,) = [sc for sc in g.scales() if sc.symbol == "μ_M"]
    mantissa = mu.per_mm / 10 ** math.floor(math.log10(mu.per_mm) + 1e-12)
    assert any(abs(mantissa - c) < 1e-9 for c in CONVENIENT)


def test_the_shaper_keeps_its_graph_in_the_linkage_s_column():
    s = _sheet("shaper", "en")                       # 45 % empty as composed: no second arrangement
    graph, scheme = s.element("balancing").bbox(), s.element("scheme").bbox()
    assert graph[1] >= scheme[3] and graph[2] <= scheme[2] + 1.0
