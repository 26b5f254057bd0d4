"""The scene model: scales, numbers, markup, notation, elements, pages, scenes (no backend)."""

import math
import subprocess
import sys

import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.errors import InputError
from graphmethods.scene import (
    NOTATIONS,
    Axis,
    Dimension,
    Frame,
    Line,
    Notation,
    Page,
    Point,
    Region,
    Scale,
    ScaleCaptions,
    Scene,
    SignMark,
    Table,
    Text,
    TitleBlock,
    Vector,
    axis_ticks,
    format_mm,
    format_value,
    in_language,
    markup,
    notation,
    pi_ticks,
    pick_angle_scale,
    pick_scale,
)
from graphmethods.scene.primitives import Circle, Group, Label, Path, Polygon, walk
from graphmethods.scene.ticks import nice_ticks

# ----------------------------------------------------------------------------- numbers

@pytest.mark.parametrize("x, text", [(0.0, "0"), (-0.0, "0"), (-0.0004, "0"), (-0.0005, "-0.001"), (12.5, "12.5"),
                                     (3.14159, "3.142"), (100.0, "100"), (210.0, "210"), (1e-9, "0"),
                                     (-2.0, "-2"), (0.1 + 0.2, "0.3")])
def test_format_mm_cases(x, text):
    assert format_mm(x) == text


@given(st.floats(min_value=-1e4, max_value=1e4, allow_nan=False))
def test_format_mm_is_within_half_a_micron_and_tidy(x):
    s = format_mm(x)
    assert abs(float(s) - x) <= 0.0005 + 1e-9
    assert s != "-0" and not s.endswith(".") and not ("." in s and s.endswith("0"))
    assert len(s.partition(".")[2]) <= 3


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_format_mm_refuses_non_finite(bad):
    with pytest.raises(InputError, match="not finite|non-finite"):
        format_mm(bad)


def test_format_value_style():
    assert format_value(-550.0) == "−550"           # typographic minus
    assert format_value(34.36116964863836) == "34.36"
    assert format_value(15.0, plus=True) == "+15"
    assert format_value(0.025, decimal=",") == "0,025"
    assert format_value(9.99996) == "10"
    assert format_value(1.5e-7) == "1.5·10⁻⁷"


# ----------------------------------------------------------------------------- scales

def test_scale_caption_and_conversions():
    mu_M = Scale("μ_M", "N·m", 100.0)
    assert mu_M.caption() == "μ_M = 100 N·m/mm"
    assert mu_M.caption("ru") == "μ_M = 100 Н·м/мм"
    assert mu_M.caption("zh") == "μ_M = 100 N·m/mm"
    assert Scale("μ_φ", "rad", 0.025).caption("ru") == "μ_φ = 0,025 рад/мм"
    assert mu_M.to_mm(2500.0) == 25.0 and mu_M.to_value(25.0) == 2500.0


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf, "x"])
def test_scale_refuses_a_bad_value(bad):
    with pytest.raises(InputError, match="scale μ_M"):
        Scale("μ_M", "N·m", bad)


@given(st.floats(min_value=1e-6, max_value=1e9), st.floats(min_value=5.0, max_value=800.0), st.booleans())
@settings(max_examples=200)
def test_pick_scale_is_the_smallest_convenient_scale_that_fits(span, span_mm, extra):
    s = pick_scale(span, span_mm, symbol="μ_X", unit="u", allow_15_3=extra)
    allowed = {1.0, 2.0, 2.5, 4.0, 5.0} | ({1.5, 3.0} if extra else set())
    exponent = math.floor(math.log10(s.per_mm) + 1e-12)
    mantissa = round(s.per_mm / 10.0**exponent, 9)
    assert mantissa in allowed
    assert s.to_mm(span) <= span_mm * (1 + 1e-9)                     # it fits
    smaller = [m * 10.0**e for e in (exponent - 1, exponent) for m in allowed if m * 10.0**e < s.per_mm * (1 - 1e-9)]
    assert all(span / c > span_mm for c in smaller)                     # nothing smaller fits
    assert s.note.startswith("picked:") and "chose" in s.note


def test_pick_scale_reports_and_handles_edges():
    s = pick_scale(575.0, 120.0, symbol="μ_E", unit="J")
    assert s.per_mm == 5.0 and "4.792" in s.note and "chose 5 J/mm" in s.note
    assert pick_scale(100.0, 100.0).per_mm == 1.0                    # exact fit is a fit
    assert pick_scale(0.0, 100.0).per_mm == 1.0
    with pytest.raises(InputError, match="paper length positive"):
        pick_scale(10.0, 0.0)
    with pytest.raises(InputError):
        pick_scale(math.nan, 10.0)


def test_pick_angle_scale_uses_round_degrees_and_says_both():
    s = pick_angle_scale(2 * math.pi, 250.0)
    assert s.alt_per_mm == 1.5 and s.to_mm(2 * math.pi) == pytest.approx(240.0)
    assert s.caption() == "μ_φ = 0.02618 rad/mm (1.5°/mm)"
    assert s.caption("ru") == "μ_φ = 0,02618 рад/мм (1,5°/мм)"


# ----------------------------------------------------------------------------- markup

def test_markup_runs():
    assert markup.parse("ψ_{max}") == (("ψ", 0), ("max", -1))
    assert markup.parse("M_д") == (("M", 0), ("д", -1))
    assert markup.parse("f, mm^2") == (("f, mm", 0), ("2", 1))
    assert markup.parse("plain text") == (("plain text", 0),)
    assert markup.parse("x_{open") == (("x_{open", 0),)               # unbalanced brace: literal


@given(st.text(max_size=40))
def test_literal_user_text_draws_exactly_as_typed(s):
    assert markup.plain(markup.literal(s)) == s
    assert all(shift == 0 for _, shift in markup.parse(markup.literal(s)))


def test_text_width_estimate_grows_with_text_and_cjk_is_full_width():
    assert markup.text_width_mm("盈功", 4.0) == pytest.approx(8.0)
    assert markup.text_width_mm("M_d", 3.5) < markup.text_width_mm("Md", 3.5)


# ----------------------------------------------------------------------------- notation

def test_profiles_have_the_same_keys_and_differ_where_traditions_do():
    en, ru, zh = (NOTATIONS[c] for c in ("en", "ru", "zh"))
    assert set(en.symbols) == set(ru.symbols) == set(zh.symbols)
    assert set(en.words) == set(ru.words) == set(zh.words)
    assert (en.sym("M_d"), ru.sym("M_d"), zh.sym("M_d")) == ("M_d", "M_д", "M_{ed}")
    assert (en.sym("M_r"), ru.sym("M_r"), zh.sym("M_r")) == ("M_r", "M_с", "M_{er}")
    assert (en.sym("delta_W_max"), ru.sym("delta_W_max")) == ("ΔW_{max}", "A_{изб}")
    assert (zh.word("gain"), zh.word("loss"), zh.word("energy_indicator")) == ("盈功", "亏功", "能量指示图")
    assert ru.word("excess_work") == "избыточная работа"
    assert en.quantity("M", "N·m") == "M, N·m" and zh.quantity("E", "J") == "E/J"
    assert ru.number(-0.5) == "−0,5"
    with pytest.raises(InputError, match="unknown notation"):
        notation("fr")


def test_in_language_picks_the_notations_text_and_fills_placeholders():
    words = ("position {k}", "положение {k}", "位置{k}")
    assert [in_language(words, code) for code in ("en", "ru", "zh")] == list(words)
    assert in_language(words, NOTATIONS["ru"], k=3) == "положение 3"
    assert in_language(words, None, k="B") == "position B"            # None means en, as notation() takes it
    assert in_language(("ψ_{{max}} = {p}",) * 3, "zh", p="30°") == "ψ_{max} = 30°"
    assert in_language(("ψ_{max}",) * 3, "en") == "ψ_{max}"           # nothing to fill: markup kept as written
    with pytest.raises(InputError, match="unknown notation 'fr'"):
        in_language(words, "fr", k=3)
    odd = Notation("fr", symbols={}, words={}, units={})      # a profile built by hand, not by notation()
    with pytest.raises(InputError, match="unknown notation 'fr'; use one of en, ru, zh"):
        in_language(words, odd)


# ----------------------------------------------------------------------------- elements

@given(st.floats(min_value=-1e5, max_value=1e5).filter(lambda v: abs(v) > 1e-3),
       st.sampled_from([0.5, 1.0, 2.5, 10.0, 40.0]), st.floats(min_value=0, max_value=360))
def test_vector_of_a_value_is_value_over_mu_long(value, per_mm, angle):
    mu = Scale("μ_E", "J", per_mm)
    v = Vector.of((100.0, 100.0), value=value, scale=mu, angle_deg=angle)
    assert v.length_mm == pytest.approx(abs(value) / per_mm, rel=1e-12, abs=1e-9)
    shaft, head = v.primitives()
    assert head.points[0] == v.end and shaft.points[0] == v.start
    assert math.dist(shaft.points[0], head.points[0]) == pytest.approx(abs(value) / per_mm)


def test_unknown_vector_is_dashed_known_is_solid():
    assert Vector((0, 0), (10, 0)).primitives()[0].style.dash is None
    assert Vector((0, 0), (10, 0), known=False).primitives()[0].style.dash is not None


def test_frame_maps_values_through_the_scales():
    f = Frame((30.0, 120.0), Scale("μ_φ", "rad", 0.025), Scale("μ_M", "N·m", 2.0))
    assert f.pt(0.5, 40.0) == (50.0, 100.0)
    assert f.pts([0, 1], [0, -10]) == ((30.0, 120.0), (70.0, 125.0))


def test_region_hatching_stays_inside_and_off_the_kept_clear_box():
    from shapely.geometry import LineString, Polygon as SPolygon, box

    outline = ((0, 0), (40, 0), (40, 20), (10, 30))
    clear = (15.0, 5.0, 25.0, 12.0)
    r = Region(outline, hatch_angle_deg=45, hatch_spacing_mm=2.0, keep_clear=(clear,))
    segs = r.hatch_segments()
    assert len(segs) > 10
    poly = SPolygon(outline)
    for a, b in segs:
        line = LineString([a, b])
        assert poly.buffer(1e-6).covers(line)
        assert line.intersection(box(*clear)).length < 1e-6
        dx, dy = b[0] - a[0], b[1] - a[1]
        assert abs(abs(dx) - abs(dy)) < 1e-6          # 45°
    assert all(isinstance(p, Path) for p in r.primitives())


def test_region_of_a_jump_spike_is_repaired_not_an_error():
    # a boundary that runs up and back down along a jump (zero-width spike)
    r = Region(((0, 0), (10, 0), (10, -5), (10, 0), (20, 0), (20, 10), (0, 10)), hatch_spacing_mm=3)
    assert r.hatch_segments()


def test_sign_mark_strokes():
    plus = SignMark((10, 10), "+", size_mm=4)
    minus = SignMark((10, 10), "−", size_mm=4)
    assert len(plus.primitives()) == 2 and len(minus.primitives()) == 1
    assert minus.primitives()[0].points == ((8.0, 10.0), (12.0, 10.0))
    with pytest.raises(InputError):
        SignMark((0, 0), "x")


def test_dimension_line_is_offset_and_measures_its_points():
    d = Dimension((0, 50), (0, 10), "ΔW_{max} = 575 J", offset_mm=5)
    assert d.line_start == (5.0, 50.0) and d.line_end == (5.0, 10.0)
    heads = [p for p in d.primitives() if isinstance(p, Polygon)]
    assert {h.points[0] for h in heads} == {(5.0, 50.0), (5.0, 10.0)}   # arrow tips on the extension lines
    label = next(p for p in d.primitives() if isinstance(p, Label))
    assert label.anchor == "start" and label.x > 5.0


def test_axis_ticks_sit_where_the_scale_puts_them():
    mu = Scale("μ_M", "N·m", 2.0)
    ax = Axis((20, 100), mu, "y", min_value=-10, max_value=40, ticks=(0, 20, 40), label="M, N·m")
    assert ax.pos(20) == (20.0, 90.0) and ax.tip == (20.0, 74.0)
    ticks = [p for p in ax.primitives() if isinstance(p, Path)][1:]
    assert [t.points[1][1] for t in ticks] == [100.0, 90.0, 80.0]
    labels = [p.text for p in ax.primitives() if isinstance(p, Label)]
    assert labels == ["0", "20", "40", "M, N·m"]
    with pytest.raises(InputError, match="empty"):
        Axis((0, 0), mu, "x", min_value=5, max_value=5)


def test_nice_and_pi_ticks():
    mu = Scale("μ_M", "N·m", 0.5)
    ticks = axis_ticks(-60, 20, mu, min_gap_mm=8)
    assert ticks[0] == -60 and ticks[-1] == 20 and all(mu.to_mm(b - a) >= 8 for a, b in zip(ticks, ticks[1:]))
    assert ticks == nice_ticks(-60, 20, 20)         # one rule: the engine's (MaxNLocator's), 160 mm / 8 mm intervals
    values, labels = pi_ticks(2 * math.pi, Scale("μ_φ", "rad", 0.025), min_gap_mm=40)
    assert labels == ("0", "π/2", "π", "3π/2", "2π") and values[-1] == pytest.approx(2 * math.pi)


def test_table_fits_its_texts_and_draws_a_grid():
    t = Table((10, 10), (("Interval", "A, J"), ("a–b", "+50"), ("b–c", "−550")), align="cr")
    w = t.column_widths()
    assert w[0] >= markup.text_width_mm("Interval", t.size_mm) and t.height_mm == 21.0
    texts = [p.text for p in t.primitives() if isinstance(p, Label)]
    assert texts == ["Interval", "A, J", "a–b", "+50", "b–c", "−550"]
    with pytest.raises(InputError, match="row 1 has 1 cells"):
        Table((0, 0), (("a", "b"), ("c",)))


def test_point_label_sits_beside_the_point():
    p = Point((50, 50), "b", label_dir="ne")
    dot, lab = p.primitives()
    assert isinstance(dot, Circle) and lab.anchor == "start" and lab.x > 50 and lab.y < 50


def test_text_subscripts_are_runs():
    (lab,) = Text((0, 0), "ψ_{max} = 30°").primitives()
    assert lab.runs == (("ψ", 0), ("max", -1), (" = 30°", 0))
    (lab,) = Text((0, 0), "W1_diesel", markup=False).primitives()
    assert lab.runs == (("W1_diesel", 0),)


# ----------------------------------------------------------------------------- page and scene

@pytest.mark.parametrize("size, w, h", [("A4", 210, 297), ("A3", 297, 420), ("A2", 420, 594), ("A1", 594, 841)])
def test_page_sizes(size, w, h):
    assert (Page(size, "portrait").width_mm, Page(size, "portrait").height_mm) == (w, h)
    assert (Page(size, "landscape").width_mm, Page(size, "landscape").height_mm) == (h, w)


def test_page_refuses_unknown_size_and_bad_margins():
    with pytest.raises(InputError, match="A4, A3, A2, A1"):
        Page("Letter")
    with pytest.raises(InputError, match="margins"):
        Page("A4", margins_mm=(200, 0, 200, 0))


def test_title_block_sits_in_the_frame_corner_and_shrinks_the_content_box():
    tb = TitleBlock("Energy indicator", "W1_diesel", ("μ_E = 5 J/mm",))
    page = Page("A4", "landscape", frame=True, title_block=tb)
    x0, y0, x1, y1 = page.content_box()
    table = tb.table(*page.inner_box()[2:])
    assert table.top_right[0] == pytest.approx(287.0) and table.bottom_left[1] == pytest.approx(200.0)
    assert y1 < table.at[1]
    texts = [p.text for p in walk(page.primitives()) if isinstance(p, Label)]
    assert "W1_diesel" in texts                                   # user text drawn literally


def test_scene_is_immutable_ids_unique_and_scales_collected():
    mu = Scale("μ_M", "N·m", 2.0)
    s0 = Scene(Page("A4"), name="demo")
    s1 = s0.add(Axis((20, 100), mu, "y", max_value=40, name="axis"), Line((0, 0), (1, 1), name="axis"),
                ScaleCaptions((10, 200), (Scale("μ_E", "J", 5.0),)))
    assert s0.elements == () and len(s1.elements) == 3
    ids = [g.name for g in walk(s1.groups()) if isinstance(g, Group)]
    assert ids[:2] == ["axis", "axis-2"] and len(ids) == len(set(ids))
    assert [s.symbol for s in s1.scales()] == ["μ_M", "μ_E"]
    with pytest.raises(InputError, match="not a figure element"):
        Scene(Page("A4"), ("text",))


def test_importing_scene_loads_no_backend_and_no_shapely():
    code = ("import sys, graphmethods.scene, graphmethods.render;"
            "print(','.join(m for m in ('matplotlib', 'svgwrite', 'shapely') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""
