"""The PDF writer: a valid file read back by its own cross-reference table; text that is text, where the
scene puts it, as wide as matplotlib lays it out; paths in millimetres; deterministic; safe saving."""

import io
import shutil
import subprocess
from pathlib import Path

import pytest
from pdf_reading import Pdf

from graphmethods import problems, sheets
from graphmethods.errors import InputError, OutputExistsError
from graphmethods.render import fonts, pdf
from graphmethods.render.recording import record
from graphmethods.scene import Page, Scale, Scene, Text, Vector
from graphmethods.scene.elements import Polyline
from graphmethods.scene.markup import SCRIPT_SCALE, SUB_SHIFT
from graphmethods.scene.primitives import Style

PT_PER_MM = 72 / 25.4


def small_scene(text="ψ_{max} = 30°; M_д, M_с; ΔW_{max}", name="small") -> Scene:
    mu = Scale("μ_E", "J", 10.0)
    return Scene(Page("A4"), (Vector.of((50, 150), value=500.0, scale=mu, angle_deg=90, name="v"),
                              Text((20, 20), text, name="t")), name=name)


needs_cjk = pytest.mark.skipif(fonts.find_cjk_font() is None,
                               reason="no CJK font on this machine (apt-get install fonts-noto-cjk, or pip install "
                                      "mplfonts); .ci/run installs one")


def _mpl_width_mm(text: str, size_mm: float, bold: bool = False) -> float:
    """Width of ``text`` as matplotlib's own text layout measures it (an independent computation)."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextToPath

    prop = FontProperties(family=fonts.families(text), size=100.0, weight="bold" if bold else "normal")
    return TextToPath().get_text_width_height_descent(text, prop, ismath=False)[0] / 100.0 * size_mm


def test_pdf_is_deterministic_undated_and_valid():
    a, b = pdf.to_bytes(small_scene()), pdf.to_bytes(small_scene())
    assert a == b and a.startswith(b"%PDF-1.4")
    assert b"CreationDate" not in a and b"ModDate" not in a
    doc = Pdf(a)                                   # every object where the xref says, every /Length right
    for num in doc.offsets:
        if b"\nstream\n" in doc.raw(num):
            doc.stream(num)
    assert b"/Title <FEFF" in doc.dict(doc.info)


def test_one_page_per_scene_at_the_page_size():
    doc = Pdf(pdf.to_bytes([small_scene(), small_scene("second"), Scene(Page("A3", "portrait"), ())]))
    pages = doc.pages()
    assert len(pages) == 3
    assert doc.media_box(pages[0]) == pytest.approx([0, 0, 297 * PT_PER_MM, 210 * PT_PER_MM], abs=1e-3)
    assert doc.media_box(pages[2]) == pytest.approx([0, 0, 297 * PT_PER_MM, 420 * PT_PER_MM], abs=1e-3)
    assert [s.text for s in doc.shown(pages[1])] == ["second"]


def test_text_is_searchable_and_stands_at_the_scene_coordinates():
    scene = Scene(Page("A4"), (Text((20, 30), "M_д = 5", size_mm=5.0, name="a"),
                               Text((100, 60), "ΔW_{max}", size_mm=4.0, anchor="middle", name="b"),
                               Text((200, 90), "Мс, 10^{-3}", size_mm=3.0, anchor="end", name="c")))
    doc = Pdf(pdf.to_bytes(scene))
    shown = doc.shown(doc.pages()[0])
    assert [s.text for s in shown] == ["M", "д", " = 5", "ΔW", "max", "Мс, 10", "-3"]
    # a: start anchor; the subscript follows the width of "M", smaller and lower
    assert (shown[0].x, shown[0].y, shown[0].size) == (20, 30, 5)
    assert shown[1].x == pytest.approx(20 + _mpl_width_mm("M", 5.0), abs=2e-3)
    assert shown[1].y == pytest.approx(30 + SUB_SHIFT * 5.0, abs=1e-3)
    assert shown[1].size == pytest.approx(5.0 * SCRIPT_SCALE, abs=1e-3)
    # b: centred on x = 100 by the widths matplotlib measures
    total = _mpl_width_mm("ΔW", 4.0) + _mpl_width_mm("max", 4.0 * SCRIPT_SCALE)
    assert shown[3].x == pytest.approx(100 - total / 2, abs=3e-3)
    # c: ends at x = 200
    total = _mpl_width_mm("Мс, 10", 3.0) + _mpl_width_mm("-3", 3.0 * SCRIPT_SCALE)
    assert shown[5].x == pytest.approx(200 - total, abs=3e-3)


@pytest.mark.parametrize("text", ["AVATAR Ty", "ψ_max = 30°; M_д = −550 N·m", "Динамический анализ: маховик",
                                  "0123456789 ΔT, Дж", "kl = 52.92 mm"])
@pytest.mark.parametrize("bold", [False, True])
def test_widths_and_kerning_agree_with_matplotlib_layout(text, bold):
    width_em, _ = pdf._Fonts().run(text, bold)
    assert width_em * 10.0 == pytest.approx(_mpl_width_mm(text, 10.0, bold), rel=2e-4)


def test_kerning_tucks_a_and_v_together():
    f = pdf._Fonts()
    assert f.run("AV", False)[0] < f.run("A", False)[0] + f.run("V", False)[0] - 0.05


def test_every_label_of_real_figures_is_shown_as_its_text():
    scenes = [sheets.energy_indicator(problems.w1(), notation="ru"),
              sheets.moment_diagram(problems.w3(), notation="en")]
    doc = Pdf(pdf.to_bytes(scenes))
    for scene, page in zip(scenes, doc.pages()):
        labels = [c.data for c in record(scene).calls if c.kind == "text"]
        shown = iter(doc.shown(page))
        for label in labels:
            runs = [next(shown) for _ in label.runs]
            assert [r.text for r in runs] == [chunk for chunk, _ in label.runs]
            assert runs[0].y == pytest.approx(label.y + (SUB_SHIFT * label.size_mm if label.runs[0][1] < 0 else 0),
                                              abs=1e-3)
            if label.anchor == "start":
                assert runs[0].x == pytest.approx(label.x, abs=1e-3)
        assert next(shown, None) is None


def test_hundreds_of_glyphs_of_one_face_are_one_font_with_two_byte_codes():
    chars = "".join(chr(c) for c in list(range(0x21, 0x7F)) + list(range(0x410, 0x450)) + list(range(0x391, 0x3A2))
                    + list(range(0x3A3, 0x3AA)) + list(range(0x3B1, 0x3CA)) + list(range(0xC0, 0x100)))
    assert len(set(chars)) > 256
    text = chars.replace("_", "").replace("^", "").replace("\\", "")
    doc = Pdf(pdf.to_bytes(Scene(Page("A3"), (Text((10, 10), text, size_mm=2.0),))))
    page = doc.pages()[0]
    assert len(doc.fonts(page)) == 1
    assert "".join(s.text for s in doc.shown(page)) == text


def _embedded(doc: Pdf, font: int):
    """(BaseFont, the descendant CID font's dictionary, the font program's bytes) of a Type 0 font."""
    import re

    base = re.search(rb"/BaseFont /(\S+)", doc.dict(font)).group(1).decode()
    cid = int(re.search(rb"/DescendantFonts \[(\d+) 0 R\]", doc.dict(font)).group(1))
    desc = int(re.search(rb"/FontDescriptor (\d+) 0 R", doc.dict(cid)).group(1))
    program = int(re.search(rb"/FontFile[23] (\d+) 0 R", doc.dict(desc)).group(1))
    return base, doc.dict(cid), doc.stream(program)


def _w_array(cid_dict: bytes) -> dict[int, float]:
    """The W array of a CID font as code -> width (1/1000 em)."""
    import re

    body = re.search(rb"/W \[(.*?)\]\s*(?:/|>>)", cid_dict + b" >>").group(1).decode()
    out = {}
    for start, widths in re.findall(r"(\d+) \[([^\]]*)\]", body):
        for k, w in enumerate(widths.split()):
            out[int(start) + k] = float(w)
    return out


def test_the_embedded_program_is_a_subset_of_the_font_with_its_outlines_and_widths():
    import re

    from fontTools.pens.boundsPen import BoundsPen
    from fontTools.ttLib import TTFont

    doc = Pdf(pdf.to_bytes(Scene(Page("A4"), (Text((10, 10), "MA", size_mm=5.0),))))
    font = doc.fonts(doc.pages()[0])["F1"]
    assert b"/Subtype /Type0" in doc.dict(font) and b"/Encoding /Identity-H" in doc.dict(font)
    base, cid, program = _embedded(doc, font)
    assert re.fullmatch(r"[A-Z]{6}\+DejaVuSans", base) and b"/CIDToGIDMap /Identity" in cid
    original = TTFont(fonts._base_path(False))                  # the font file, read independently
    sub = TTFont(io.BytesIO(program))
    widths = _w_array(cid)
    content = doc.content(doc.pages()[0])
    for ch in "MA":
        gname = original.getBestCmap()[ord(ch)]
        gid = original.getGlyphID(gname)
        assert f"{gid:04X}" in content                        # shown by its glyph index
        bounds = []
        for font_ in (original, sub):
            pen = BoundsPen(font_.getGlyphSet())
            font_.getGlyphSet()[font_.getGlyphOrder()[gid]].draw(pen)
            bounds.append(pen.bounds)
        assert bounds[0] == bounds[1] and bounds[0][2] > bounds[0][0]     # the same outline, not empty
        assert widths[gid] == pytest.approx(1000 * original["hmtx"][gname][0] / original["head"].unitsPerEm, abs=1e-3)
    # only the glyphs used (and .notdef) keep outlines
    drawn = [g for g in sub.getGlyphOrder() if sub["glyf"][g].numberOfContours != 0]
    assert len(drawn) == 3 and len(program) < 60_000 < len(Path(fonts._base_path(False)).read_bytes())


def test_paths_are_drawn_in_page_millimetres():
    style = Style(stroke="#d01818", width_mm=0.35, dash=(2.0, 1.0))
    mu = Scale("μ_E", "J", 10.0)
    scene = Scene(Page("A4"), (Polyline(((10.0, 10.0), (60.0, 10.0), (60.0, 42.5)), style, closed=True),
                               Vector.of((50, 150), value=500.0, scale=mu, angle_deg=90, name="v")))
    doc = Pdf(pdf.to_bytes(scene))
    content = doc.content(doc.pages()[0])
    assert content.startswith(f"{PT_PER_MM:.6f} 0 0 {-PT_PER_MM:.6f} 0 {210 * PT_PER_MM:.4f} cm")
    assert "0.8157 0.0941 0.0941 RG" in content and "0.35 w" in content and "[2 1] 0 d" in content
    assert "10 10 m 60 10 l 60 42.5 l h S" in content
    # the vector of 500 J at μ = 10 J/mm: its shaft and head reach 50 mm up from (50, 150)
    rec = record(scene)
    assert rec.vector_length_mm("v") == pytest.approx(50.0)
    for call in rec.calls:
        if call.kind == "path":
            pts = call.data[0]
            assert f"{pts[0][0]:g} {pts[0][1]:g} m" in content


def test_bad_input_is_refused_clearly(tmp_path):
    with pytest.raises(InputError, match="#rrggbb"):
        pdf.to_bytes(Scene(Page("A4"), (Polyline(((0, 0), (1, 1)), Style(stroke="reddish")),)))
    with pytest.raises(InputError, match="at least one page"):
        pdf.to_bytes([])


def test_save_refuses_to_overwrite(tmp_path):
    path = tmp_path / "f.pdf"
    pdf.save([small_scene(), small_scene()], path)
    before = path.read_bytes()
    with pytest.raises(OutputExistsError):
        pdf.save(small_scene("other"), path)
    assert path.read_bytes() == before
    pdf.save(small_scene("other"), path, overwrite=True)
    assert path.read_bytes() != before and [p.name for p in tmp_path.iterdir()] == ["f.pdf"]


@needs_cjk
def test_a_russian_and_a_chinese_figure_make_one_deterministic_pdf():
    scenes = [sheets.energy_graph(problems.w4_exact(), J_e=0.8, omega_0=10.0, notation="ru", work_unit="kG·m"),
              sheets.energy_indicator(problems.w1(), notation="zh")]
    a, b = pdf.to_bytes(scenes), pdf.to_bytes(scenes)
    assert a == b and len(Pdf(a).pages()) == 2


def _raster(data: bytes, tmp_path, dpi: int):
    import matplotlib.image as mi

    (tmp_path / "r.pdf").write_bytes(data)
    subprocess.run(["pdftoppm", "-r", str(dpi), "-png", "-singlefile", str(tmp_path / "r.pdf"), str(tmp_path / "r")],
                   check=True)
    return mi.imread(str(tmp_path / "r.png"))[..., :3].mean(axis=-1) < 0.5


needs_pdftoppm = pytest.mark.skipif(shutil.which("pdftoppm") is None, reason="needs poppler's pdftoppm to rasterise")


@needs_pdftoppm
def test_rasterised_pdf_draws_the_geometry_the_png_draws(tmp_path, monkeypatch):
    import matplotlib.image as mi
    import numpy as np

    from graphmethods.render import mpl

    # text aside (matplotlib's PNG hints glyph advances to pixels, so long lines drift by design)
    monkeypatch.setattr(pdf.PdfRenderer, "text", lambda self, label: None)
    monkeypatch.setattr(mpl.MplRenderer, "text", lambda self, label: None)
    scene = sheets.energy_indicator(problems.w1(), notation="ru")
    ours = _raster(pdf.to_bytes(scene), tmp_path, 100)
    ref = mi.imread(io.BytesIO(mpl.to_png_bytes(scene, dpi=100)))[..., :3].mean(axis=-1) < 0.5
    h, w = min(ours.shape[0], ref.shape[0]), min(ours.shape[1], ref.shape[1])   # rounding of the page size
    ours, ref = ours[:h, :w], ref[:h, :w]
    grow = np.zeros_like(ref)                       # the PNG's ink, widened by one pixel (anti-aliasing)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            grow |= np.roll(np.roll(ref, dy, 0), dx, 1)
    assert ours.sum() > 10000 and (ours & ~grow).sum() < 0.005 * ours.sum()
    assert abs(int(ours.sum()) - int(ref.sum())) < 0.05 * ref.sum()


@needs_pdftoppm
def test_rasterised_text_stands_where_the_scene_puts_it(tmp_path):
    import numpy as np

    dpi = 300
    mm = 25.4 / dpi
    scene = Scene(Page("A4"), (Text((30.0, 20.0), "MMMM", size_mm=6.0, name="a"),
                               Text((100.0, 150.0), "MMMM", size_mm=6.0, anchor="end", name="b")))
    ink = _raster(pdf.to_bytes(scene), tmp_path, dpi)
    rows, cols = np.flatnonzero(ink[: int(100 / mm)].any(axis=1)), np.flatnonzero(ink[: int(100 / mm)].any(axis=0))
    cap = 0.729 * 6.0                               # DejaVu Sans cap height, em
    assert (rows[-1] + 1) * mm == pytest.approx(20.0, abs=0.15) and rows[0] * mm == pytest.approx(20.0 - cap, abs=0.15)
    assert cols[0] * mm == pytest.approx(30.0 + 201 / 2048 * 6.0, abs=0.15)      # M's left side bearing
    cols = np.flatnonzero(ink[int(100 / mm):].any(axis=0))
    assert (cols[-1] + 1) * mm == pytest.approx(100.0 - (1767 - 1567) / 2048 * 6.0, abs=0.15)


def test_third_party_drawing_libraries_are_imported_in_one_place_each():
    import ast
    import pathlib

    pkg = pathlib.Path(pdf.__file__).resolve().parents[1]
    where: dict[str, set[str]] = {"matplotlib": set(), "svgwrite": set()}
    for path in pkg.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else \
                [node.module or ""] if isinstance(node, ast.ImportFrom) else []
            for name in names:
                if name.split(".")[0] in where:
                    where[name.split(".")[0]].add(path.relative_to(pkg).as_posix())
    # bench.py plots its log-log chart of error against time with pyplot: a chart, not a scene
    # SVG is written as text by render/svg.py: no module imports svgwrite (no longer a dependency)
    assert where == {"matplotlib": {"render/mpl.py", "render/fonts.py", "bench.py"}, "svgwrite": set()}
