"""No fixed costs where a teacher waits (issue 30): the full-turn check and the dead centres once per geometry,
fonts measured from the font file, SVG written once as text; each as exact as what it replaced."""

import importlib.util
import math
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from graphmethods.errors import AssemblyError
from graphmethods.kinematics import linkage as L, presets
from graphmethods.render import fonts, sfnt, svg
from graphmethods.scene import Page, Scene, Text, markup


def _golden_section_minimum(f, lo, hi, steps=80):
    """The golden-section search check_full_turn used before (one angle a solve), for comparison."""
    gr = (math.sqrt(5) - 1) / 2
    for _ in range(steps):
        a, b = hi - gr * (hi - lo), lo + gr * (hi - lo)
        if f(a) < f(b):
            hi = b
        else:
            lo = a
    return 0.5 * (lo + hi)


def test_the_same_numbers_share_one_check_and_other_numbers_do_not():
    a, b = presets.six_bar_press(), presets.six_bar_press()
    assert a.geometry_key() == b.geometry_key() is not None and a._geometry is b._geometry
    c = presets.slider_crank(r=0.1, l=0.4, e=0.02)
    d = presets.slider_crank(r=0.1, l=0.4, e=0.0200001)
    assert c.geometry_key() != d.geometry_key() and c._geometry is not d._geometry
    assert c.strokes() != d.strokes()
    calls = []
    e = presets.slider_crank(r=0.1, l=0.4, e=0.02)
    original = e.solve
    e.solve = lambda *args, **kw: calls.append(1) or original(*args, **kw)
    assert e.strokes() == c.strokes() and calls == []          # a fresh linkage of the same numbers: no solve


def test_a_toggle_is_refused_by_every_fresh_linkage_with_the_same_message():
    messages = []
    for _ in range(2):
        lk = presets.four_bar(l1=0.3, l2=0.1, l3=0.3, l4=0.1)
        with pytest.raises(AssemblyError, match="toggle") as exc:
            lk.check_full_turn()
        messages.append(str(exc.value))
    assert messages[0] == messages[1]


@pytest.mark.parametrize("make", [lambda: presets.six_bar_press(), lambda: presets.slider_crank(r=0.1, l=0.4, e=0.02),
                                  lambda: presets.four_bar(l1=0.3, l2=0.08, l3=0.25, l4=0.2),
                                  lambda: presets.slotted_lever(r=0.1, l_O1O3=0.3, l_O3B=0.5)])
def test_the_batched_refinement_finds_the_smallest_margin_the_golden_section_found(make):
    lk = make()
    samples = 2048
    phi = np.linspace(0.0, 2 * math.pi, samples, endpoint=False)
    st = lk.solve(phi, level=0)
    centres = np.array([phi[int(np.argmin(g.margin(st)))] for g in lk.groups])
    x, best = L._refine_minima(lk._own_margins, centres, 2 * math.pi / samples)
    for k, g in enumerate(lk.groups):
        def f(t, g=g):
            return float(g.margin(lk.solve(np.array([t]), level=0))[0])

        old = _golden_section_minimum(f, centres[k] - 2 * math.pi / samples, centres[k] + 2 * math.pi / samples)
        scale = float(np.max(np.abs(g.margin(st)))) or 1.0
        assert best[k] <= f(old) + 1e-14 * scale                  # as small as the old search's, or smaller
        assert abs(best[k] - f(old)) <= 1e-12 * scale


def test_refine_minima_is_exact_on_a_parabola_and_a_kink():
    x, v = L._refine_minima(lambda a: np.stack([(a[0] - 0.123456789) ** 2, np.abs(a[1] - 2.5)]),
                            np.array([0.12, 2.501]), 0.01)
    assert abs(x[0] - 0.123456789) < 1e-14 and abs(x[1] - 2.5) < 1e-15 and v.max() < 1e-15


@pytest.mark.parametrize("bold", [False, True])
def test_widths_kerning_and_the_character_map_equal_freetypes(bold):
    ft2font = pytest.importorskip("matplotlib.ft2font")
    path = fonts._base_path(bold)
    face = sfnt.Sfnt(path)
    import matplotlib

    old = tuple(int(v) for v in matplotlib.__version__.split(".")[:2]) < (3, 11)
    ft = ft2font.FT2Font(path, hinting_factor=1) if old else ft2font.FT2Font(path)
    cmap = {c: g for c, g in ft.get_charmap().items() if g}
    assert face.cmap == cmap
    no_scale = getattr(getattr(ft2font, "LoadFlags", None), "NO_SCALE", None) or ft2font.LOAD_NO_SCALE
    unscaled = getattr(getattr(ft2font, "Kerning", None), "UNSCALED", None) or ft2font.KERNING_UNSCALED
    for gid in range(0, face.num_glyphs, 7):
        assert face.advances[gid] == ft.load_glyph(gid, no_scale).horiAdvance
    glyphs = [cmap[ord(c)] for c in "AVTWYLPFo.,ayvwДЖΔΣωψ0123456789"]
    for a in glyphs:
        for b in glyphs:
            assert face.kerning.get((a << 16) | b, 0) == ft.get_kerning(a, b, unscaled)


def test_the_pdf_of_latin_cyrillic_and_greek_text_imports_neither_matplotlib_nor_fonttools():
    code = ("import sys; from graphmethods.render import pdf; from graphmethods.scene import Scene, Page, Text;"
            "pdf.to_bytes(Scene(Page('A4'), (Text((20, 20), 'ψ_{max} = 30°; М_д, ΔW', name='t'),)));"
            "print(sorted(m for m in ('matplotlib', 'fontTools') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_a_subset_keeps_composite_glyphs_components_and_reads_back():
    ttlib = pytest.importorskip("fontTools.ttLib")
    import io

    face = sfnt.Sfnt(fonts._base_path(False))
    gid = face.cmap[ord("Ё")]                     # a composite: Е and the diaeresis
    program = sfnt.subset_truetype(face, [gid])
    font = ttlib.TTFont(io.BytesIO(program))
    glyf = font["glyf"]
    g = glyf[font.getGlyphOrder()[gid]]
    assert g.isComposite()
    for comp in g.components:
        assert glyf[comp.glyphName].numberOfContours != 0
    assert font["maxp"].numGlyphs == max([gid] + [font.getGlyphID(c.glyphName) for c in g.components]) + 1


@pytest.mark.parametrize("text", ["a < b & c > d", 'quotes " and \' and a tab\t', "M_{d} & <ω>", "x\x01y"])
def test_svg_text_is_escaped_as_xml_requires_and_reads_back(text):
    from graphmethods.render.recording import record

    scene = Scene(Page("A4"), (Text((20, 20), text, name="t"),), title=f"title {text}")
    root = ET.fromstring(svg.to_string(scene).split("?>", 1)[1])                  # well-formed
    ns = "{http://www.w3.org/2000/svg}"
    assert root.find(f"{ns}title").text == svg.clean_text(markup.plain(f"title {text}"))
    (label,) = [c.data for c in record(scene).calls if c.kind == "text"]
    (elem,) = root.iter(f"{ns}text")
    assert "".join(elem.itertext()) == "".join(svg.clean_text(chunk) for chunk, _ in label.runs)


def test_the_fixed_cost_rows_measure_the_right_things():
    """Their numbers are reported, never asserted; what they compute is checked (here the in-process rows)."""
    from graphmethods import bench

    rows = bench.bench_fixed_costs(repeat=1, n_time=2000, n_memory=20_000, processes=False)
    by = {(r.case, r.method.split(":")[0]): r for r in rows}
    fresh = by[("press read afresh", "exact J_F (file read, linkage built, dead centres found) / the scipy solver")] \
        if importlib.util.find_spec("scipy") else None
    if fresh is not None:
        assert fresh.error < 1e-12 and fresh.target.startswith("≤ 1.25×") and fresh.extra["ratio"] > 0
    core = [r for r in rows if r.case == "slider-crank press"]
    assert [r.size for r in core] == [2000, 20_000]
    assert core[0].error < 1e-13 and core[0].target == "≤ 3× closed form"
    assert core[1].target == "≤ 1.8× closed form" and "MiB" in core[1].note
