"""Fonts of PNG and PDF text: the Simplified Chinese face of a CJK collection, a clear refusal (and nothing
written) when no font draws the text, and PDF text that poppler's tools read: named, embedded CID fonts and
words in reading order."""

import io
import os
import pathlib
import re
import shutil
import subprocess

import pytest
from matplotlib import font_manager as fm
from pdf_reading import Pdf

from graphmethods.cli import main
from graphmethods.errors import MissingFontError
from graphmethods.render import fonts, mpl, pdf
from graphmethods.render.recording import record
from graphmethods.scene import Page, Scene, Text
from graphmethods.sheets.worksheets import worksheet

PRESS = str(pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data"
            / "slider_crank_press.json")


def _clear_font_caches():
    fonts.find_cjk_font.cache_clear()
    fonts.check_drawable.cache_clear()
    cached = getattr(fm.fontManager, "_findfont_cached", None)
    if cached is not None:
        cached.cache_clear()


@pytest.fixture
def stale_font_list(monkeypatch):
    """matplotlib's font list as a cache made before any CJK font was installed (no font in it covers Chinese),
    no ``GRAPHMETHODS_CJK_FONT``, no mplfonts; rebuilding the list is recorded, not done. Yields the list of
    rebuilds and the full font list (to put back, as a rebuild that finds the installed font would)."""
    full = list(fm.fontManager.ttflist)
    chinese = {e.fname for e in full if fonts._covers(e.fname)} | {e.fname for e in full if e.fname.endswith(".ttc")}
    monkeypatch.setattr(fm.fontManager, "ttflist", [e for e in full if e.fname not in chinese])
    monkeypatch.delenv("GRAPHMETHODS_CJK_FONT", raising=False)
    monkeypatch.setattr(fonts, "_mplfonts_font", lambda: None)
    monkeypatch.setattr(fonts, "_rebuilt", False)
    rebuilds = []
    monkeypatch.setattr(fonts, "_rebuild_font_list", lambda: rebuilds.append(1))
    _clear_font_caches()
    yield rebuilds, full
    monkeypatch.undo()
    _clear_font_caches()


def zh_scene(text="盈亏功 ΔW_{max} = 575 J", name="zh") -> Scene:
    return Scene(Page("A4"), (Text((20, 20), "Energy indicator", name="en"), Text((20, 40), text, name="t")),
                 name=name)


# ----------------------------------------------------------------- no CJK font: one clear error, nothing written
def test_without_a_cjk_font_png_and_pdf_refuse_after_one_rebuild(stale_font_list):
    rebuilds, _ = stale_font_list
    for render in (lambda: mpl.to_png_bytes(zh_scene()), lambda: pdf.to_bytes(zh_scene()), fonts.require_cjk):
        with pytest.raises(MissingFontError) as caught:
            render()
        message = str(caught.value)
        assert "\n" not in message
        assert "apt-get install fonts-noto-cjk" in message and "pip install 'graphmethods[cjk]'" in message
        assert "GRAPHMETHODS_CJK_FONT" in message
    assert rebuilds == [1]                                   # the font list is rebuilt once, not per figure
    assert mpl.to_png_bytes(Scene(Page("A4"), (Text((10, 10), "Мд, ψ_{max}"),)), dpi=20)[:4] == b"\x89PNG"


def test_a_stale_font_list_is_rebuilt_once_and_then_chinese_is_drawn(stale_font_list, monkeypatch):
    rebuilds, full = stale_font_list
    if not any(fonts._covers(e.fname) for e in full):
        pytest.skip("no CJK font on this machine to find after the rebuild")

    def rebuild():                          # what a rebuild does when the font was installed after the cache
        rebuilds.append(1)
        monkeypatch.setattr(fm.fontManager, "ttflist", full)
        _clear_font_caches()

    monkeypatch.setattr(fonts, "_rebuild_font_list", rebuild)
    doc = Pdf(pdf.to_bytes(zh_scene()))
    assert [s.text for s in doc.shown(doc.pages()[0])] == ["Energy indicator", "盈亏功 ΔW", "max", " = 575 J"]
    assert rebuilds == [1]


def test_the_command_line_refuses_in_one_line_and_writes_nothing(stale_font_list, tmp_path, capsys):
    sheet = tmp_path / "sheet.pdf"
    assert main(["study", PRESS, "--no-exact", "--sheet", str(sheet), "--lang", "zh"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "fonts-noto-cjk" in err and "GRAPHMETHODS_CJK_FONT" in err
    assert not sheet.exists() and list(tmp_path.iterdir()) == []
    # a gallery of an English and a Chinese figure with --png: refused before the first file is written
    scripts = tmp_path / "scripts"
    scripts.mkdir()
    for name, text in (("a_en", "Energy indicator"), ("b_zh", "能量指示图")):
        (scripts / f"{name}.py").write_text(
            "from graphmethods.scene import Page, Scene, Text\n"
            f"def build():\n    return Scene(Page('A4'), (Text((10, 10), {text!r}),), name={name!r})\n",
            encoding="utf-8")
    out = tmp_path / "out"
    assert main(["gallery", "--dir", str(scripts), "--out", str(out), "--png"]) == 2
    assert "fonts-noto-cjk" in capsys.readouterr().err
    assert not out.exists()                           # the set writer writes nothing, not even the folder
    # SVG needs no font: the viewer renders its text
    assert main(["gallery", "--dir", str(scripts), "--out", str(out)]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["a_en.svg", "b_zh.svg"]


def test_a_bad_font_path_in_the_environment_is_an_error_naming_it(monkeypatch, tmp_path):
    bogus = tmp_path / "not-a-font.otf"
    bogus.write_bytes(b"nothing")
    monkeypatch.setenv("GRAPHMETHODS_CJK_FONT", str(bogus))
    _clear_font_caches()
    try:
        with pytest.raises(MissingFontError, match=f"GRAPHMETHODS_CJK_FONT={re.escape(str(bogus))} is not a font"):
            mpl.to_png_bytes(zh_scene(), dpi=20)
    finally:
        monkeypatch.undo()
        _clear_font_caches()


def test_characters_no_font_has_are_refused_in_png_and_pdf():
    scene = Scene(Page("A4"), (Text((10, 10), "ok"), Text((10, 20), "नमस्ते")))
    for render in (mpl.to_png_bytes, pdf.to_bytes):
        with pytest.raises(MissingFontError, match=r"'न' \(U\+0928\).*DejaVu Sans has no glyph"):
            render(scene)


# ----------------------------------------------------------------- the Simplified Chinese face, regular weight
def _collection_with_jp_and_sc():
    """(file, JP face, SC face) of a Noto Sans CJK (or Source Han Sans) collection on this machine, or a skip."""
    from fontTools.ttLib import TTCollection

    for path in sorted({str(p) for p in fm.findSystemFonts()} | {e.fname for e in fm.fontManager.ttflist}):
        if not path.lower().endswith(".ttc"):
            continue
        coll = TTCollection(path, lazy=True)
        try:
            names = [(f["name"].getDebugName(1), f["OS/2"].usWeightClass) for f in coll.fonts]
        finally:
            coll.fonts[0].close()
        for jp_name, sc_name in (("Noto Sans CJK JP", "Noto Sans CJK SC"), ("Source Han Sans", "Source Han Sans SC")):
            if (jp_name, 400) in names and (sc_name, 400) in names:
                return path, names.index((jp_name, 400)), names.index((sc_name, 400))
    pytest.skip("no Noto Sans CJK collection with Japanese and Chinese faces (apt-get install fonts-noto-cjk)")


def _outline(path: str, index: int, char: str):
    """The outline of ``char`` in a face, read with fontTools: pen operations in font units."""
    from fontTools.pens.recordingPen import RecordingPen
    from fontTools.ttLib import TTFont

    font = TTFont(path, fontNumber=index, lazy=True)
    pen = RecordingPen()
    font.getGlyphSet()[font.getBestCmap()[ord(char)]].draw(pen)
    return pen.value, font["head"].unitsPerEm


def test_the_cjk_face_is_simplified_chinese_and_regular():
    path, _, sc = _collection_with_jp_and_sc()
    font = fonts.find_cjk_font()
    from fontTools.ttLib import TTFont

    chosen = TTFont(font.path, fontNumber=font.index, lazy=True)
    assert chosen["name"].getDebugName(1) == "Noto Sans CJK SC" and chosen["OS/2"].usWeightClass == 400
    assert "Bold" not in (chosen["name"].getDebugName(2) or "")
    # matplotlib resolves the family PNG text asks for to that face (the one the PDF embeds)
    assert fonts.families("直") == ["DejaVu Sans", font.family]
    got = fm.findfont(fm.FontProperties(family=[font.family], weight="normal"), fallback_to_default=False)
    assert (os.path.realpath(got), getattr(got, "face_index", 0)) == (os.path.realpath(font.path), font.index)


def test_a_collection_named_in_the_environment_gives_its_chinese_face(monkeypatch):
    from fontTools.ttLib import TTFont

    path, _, sc = _collection_with_jp_and_sc()
    want = TTFont(path, fontNumber=sc, lazy=True)["name"].getDebugName(6)
    monkeypatch.setenv("GRAPHMETHODS_CJK_FONT", path)
    _clear_font_caches()
    try:
        font = fonts.find_cjk_font()
        assert TTFont(font.path, fontNumber=font.index, lazy=True)["name"].getDebugName(6) == want
        face = fonts.faces("直", bold=False)[1]
        assert face.glyph("直") == TTFont(path, fontNumber=sc, lazy=True).getGlyphID(
            TTFont(path, fontNumber=sc, lazy=True).getBestCmap()[ord("直")])
    finally:
        monkeypatch.undo()
        _clear_font_caches()


@pytest.mark.parametrize("char", ["直", "骨"])
def test_the_pdf_embeds_the_simplified_chinese_glyph(char):
    from fontTools.cffLib import CFFFontSet
    from fontTools.pens.recordingPen import RecordingPen

    path, jp, sc = _collection_with_jp_and_sc()
    sc_outline, _ = _outline(path, sc, char)
    jp_outline, _ = _outline(path, jp, char)
    assert sc_outline != jp_outline                       # the two forms differ, so the test can tell them apart
    doc = Pdf(pdf.to_bytes(Scene(Page("A4"), (Text((10, 20), f"ΔW {char}", size_mm=8.0),))))
    page = doc.pages()[0]
    (name, num), = [(n, f) for n, f in doc.fonts(page).items() if b"CJK" in doc.dict(f)]
    code = {ch: c for c, ch in doc.to_unicode(num).items()}[char]
    cid = int(re.search(rb"/DescendantFonts \[(\d+) 0 R\]", doc.dict(num)).group(1))
    desc = int(re.search(rb"/FontDescriptor (\d+) 0 R", doc.dict(cid)).group(1))
    program = int(re.search(rb"/FontFile3 (\d+) 0 R", doc.dict(desc)).group(1))
    assert b"/Subtype /CIDFontType0C" in doc.dict(program)
    cff = CFFFontSet()
    cff.decompile(io.BytesIO(doc.stream(program)), None)
    pen = RecordingPen()
    cff[cff.fontNames[0]].CharStrings[f"cid{code:05d}"].draw(pen)
    assert pen.value == sc_outline and pen.value != jp_outline


def _ink(png: bytes):
    import matplotlib.image as mi

    return mi.imread(io.BytesIO(png))[..., :3].mean(axis=-1) < 0.5


def _raster_outline(outline, upem: int, *, x_mm: float, y_mm: float, size_mm: float, page_mm, dpi: float):
    """An outline from fontTools filled by matplotlib's Agg at its place on the page (independent of the font
    lookup): font units to mm, y up to y down."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path

    verts, codes, k = [], [], size_mm / upem
    for op, pts in outline:
        pts = [(x_mm + u * k, y_mm - v * k) for u, v in pts]
        if op == "moveTo":
            verts += pts
            codes += [Path.MOVETO]
        elif op == "lineTo":
            verts += pts
            codes += [Path.LINETO]
        elif op == "curveTo":
            verts += pts
            codes += [Path.CURVE4] * 3
        elif op == "qCurveTo":
            verts += pts
            codes += [Path.CURVE3] * 2
        elif op == "closePath":
            verts.append(verts[-1])
            codes.append(Path.CLOSEPOLY)
    fig = Figure(figsize=(page_mm[0] / 25.4, page_mm[1] / 25.4), dpi=dpi)
    FigureCanvasAgg(fig)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, page_mm[0])
    ax.set_ylim(page_mm[1], 0)
    ax.set_axis_off()
    ax.add_patch(PathPatch(Path(verts, codes), facecolor="black", edgecolor="none"))
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi)
    return _ink(buf.getvalue())


@pytest.mark.parametrize("char", ["直", "骨"])
def test_the_png_draws_the_simplified_chinese_glyph(char):
    path, jp, sc = _collection_with_jp_and_sc()
    dpi, place = 100.0, dict(x_mm=20.0, y_mm=60.0, size_mm=40.0, page_mm=(297.0, 210.0))
    ours = _ink(mpl.to_png_bytes(Scene(Page("A4"), (Text((20.0, 60.0), char, size_mm=40.0),)), dpi=dpi))
    refs = {}
    for face in (jp, sc):
        outline, upem = _outline(path, face, char)
        ref = _raster_outline(outline, upem, dpi=dpi, **place)
        h, w = min(ours.shape[0], ref.shape[0]), min(ours.shape[1], ref.shape[1])
        refs[face] = (ours[:h, :w] ^ ref[:h, :w]).sum() / ref.sum()      # pixels that differ, per inked pixel
    assert refs[sc] < 0.2 and refs[sc] < 0.5 * refs[jp], refs


# ----------------------------------------------------------------- PDF text as poppler reads it
needs_poppler = pytest.mark.skipif(shutil.which("pdftotext") is None or shutil.which("pdffonts") is None,
                                   reason="needs poppler's pdftotext and pdffonts (apt-get install poppler-utils)")


def _class_page_pdf(lang: str, tmp_path):
    if lang == "zh" and fonts.find_cjk_font() is None:
        pytest.skip("no CJK font on this machine (apt-get install fonts-noto-cjk); .ci/run installs one")
    ws = worksheet("wittenbauer", variants=1, seed=7, notation=lang)
    path = tmp_path / f"{lang}.pdf"
    pdf.save([ws.students[0], ws.keys[0]], path)
    return ws, path


@needs_poppler
@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_pdffonts_lists_embedded_named_subset_fonts_and_no_type3(lang, tmp_path):
    _, path = _class_page_pdf(lang, tmp_path)
    out = subprocess.run(["pdffonts", str(path)], capture_output=True, text=True, check=True).stdout
    rows = out.splitlines()[2:]
    assert rows and "Type 3" not in out
    names = []
    for row in rows:
        name, *_, emb, sub, uni, _obj, _gen = row.split()
        assert (emb, sub, uni) == ("yes", "yes", "yes"), row
        assert re.fullmatch(r"[A-Z]{6}\+[A-Za-z0-9._-]+", name), row
        assert "Identity-H" in row and ("CID TrueType" in row or "CID Type 0C" in row), row
        names.append(name.split("+")[1].removesuffix("-Identity-H"))
    assert "DejaVuSans" in names and "DejaVuSans-Bold" in names
    if lang == "zh":
        from fontTools.ttLib import TTFont

        cjk = fonts.find_cjk_font()
        assert TTFont(cjk.path, fontNumber=cjk.index, lazy=True)["name"].getDebugName(6) in names


@needs_poppler
@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_pdftotext_reads_every_label_word_for_word_in_reading_order(lang, tmp_path):
    ws, path = _class_page_pdf(lang, tmp_path)
    for number, scene in enumerate((ws.students[0], ws.keys[0]), 1):
        text = subprocess.run(["pdftotext", "-f", str(number), "-l", str(number), str(path), "-"],
                              capture_output=True, text=True, check=True).stdout
        words = text.split()
        labels = [c.data for c in record(scene).calls if c.kind == "text"]
        title = labels[0].text
        assert text.splitlines()[0] == title                                  # the title comes first
        columns: dict = {}
        for label in labels:
            want = label.text.split()
            at = [i for i in range(len(words)) if words[i:i + len(want)] == want]
            assert at, f"{lang} page {number}: {label.text!r} is not read word for word"
            if len(want) > 1 and label.anchor == "start":
                columns.setdefault(round(label.x, 2), []).append((label.y, at, label.text))
        # lines of running text (labels one under another at the same left edge) are read top to bottom
        lines = [col for col in columns.values() if len(col) > 1]
        assert sum(len(col) for col in lines) >= 8
        for col in lines:
            pos = -1
            for _, at, label_text in sorted(col):
                later = [i for i in at if i > pos]
                assert later, f"{lang} page {number}: {label_text!r} is read out of order"
                pos = later[0]


def test_a_real_stale_font_cache_is_rebuilt_and_the_chinese_sheet_written(tmp_path):
    """matplotlib's own cache file, with the CJK fonts taken out (as if made before they were installed), in a
    fresh process: the command rebuilds it once, finds the SC face, writes the sheet, and the cache is fixed."""
    import json
    import sys

    import matplotlib

    if fonts.find_cjk_font() is None:
        pytest.skip("no CJK font on this machine (apt-get install fonts-noto-cjk)")
    cache = next(pathlib.Path(matplotlib.get_cachedir()).glob(f"fontlist-v{fm.FontManager.__version__}.json"), None)
    if cache is None:
        pytest.skip("matplotlib keeps no font cache file here")
    data = json.loads(cache.read_text(encoding="utf-8"))
    data["ttflist"] = [e for e in data["ttflist"] if not fonts._covers(e["fname"]) and not e["fname"].endswith(".ttc")]
    config = tmp_path / "mplconfig"
    config.mkdir()
    (config / cache.name).write_text(json.dumps(data), encoding="utf-8")
    sheet = tmp_path / "sheet.pdf"
    env = dict(os.environ, MPLCONFIGDIR=str(config))
    env.pop("GRAPHMETHODS_CJK_FONT", None)
    run = subprocess.run([sys.executable, "-m", "graphmethods", "study", PRESS, "--no-exact", "--sheet", str(sheet),
                          "--lang", "zh"], capture_output=True, text=True, env=env)
    assert run.returncode == 0, run.stderr
    doc = Pdf(sheet.read_bytes())
    assert any(b"CJK" in doc.dict(f) for f in doc.fonts(doc.pages()[0]).values())
    rebuilt = json.loads((config / cache.name).read_text(encoding="utf-8"))
    assert any(fonts._covers(e["fname"]) for e in rebuilt["ttflist"])
