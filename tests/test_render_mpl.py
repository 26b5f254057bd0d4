"""The matplotlib backend: PNG of a scene; deterministic; fonts; safe saving; text where the scene puts it."""

import subprocess
import sys
import warnings

import pytest

from graphmethods.errors import OutputExistsError
from graphmethods.render import mpl
from graphmethods.scene import Page, Scale, Scene, Text, Vector

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def small_scene(text="ψ_{max} = 30°; M_д, M_с; ΔW_{max}") -> Scene:
    mu = Scale("μ_E", "J", 10.0)
    return Scene(Page("A4"), (Vector.of((50, 150), value=500.0, scale=mu, angle_deg=90, name="v"),
                              Text((20, 20), text, name="t")), name="small")


def test_png_has_the_page_size_in_pixels():
    png = mpl.to_png_bytes(small_scene(), dpi=50)
    assert png.startswith(PNG_MAGIC)
    width = int.from_bytes(png[16:20], "big")
    height = int.from_bytes(png[20:24], "big")
    assert abs(width - 297 / 25.4 * 50) < 1 and abs(height - 210 / 25.4 * 50) < 1


def test_png_is_deterministic():
    assert mpl.to_png_bytes(small_scene(), dpi=40) == mpl.to_png_bytes(small_scene(), dpi=40)


def test_greek_and_cyrillic_draw_without_missing_glyph_warnings():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mpl.to_png_bytes(small_scene("Мд Мс A_{изб} ψ φ Δ μ"), dpi=30)


def test_a_found_cjk_font_is_a_real_one():
    font = mpl.find_cjk_font()
    if font is None:
        pytest.skip("no CJK font on this machine (apt-get install fonts-noto-cjk, or pip install mplfonts)")
    from matplotlib import ft2font

    kwargs = {"face_index": font.index} if font.index else {}
    cmap = ft2font.FT2Font(font.path, **kwargs).get_charmap()
    probe = "盈亏功能量指示图"
    assert "LastResort" not in font.path and all(ord(c) in cmap for c in probe)
    assert len({cmap[ord(c)] for c in probe}) == len(probe)          # distinct glyphs, not one placeholder


def test_save_refuses_to_overwrite(tmp_path):
    png = tmp_path / "f.png"
    mpl.save_png(small_scene(), png, dpi=30)
    before = png.read_bytes()
    with pytest.raises(OutputExistsError):
        mpl.save_png(small_scene("other"), png, dpi=30)
    assert png.read_bytes() == before
    mpl.save_png(small_scene("other"), png, dpi=30, overwrite=True)
    assert png.read_bytes() != before and [p.name for p in tmp_path.iterdir()] == ["f.png"]


def test_drawing_touches_no_global_matplotlib_state():
    code = ("import matplotlib; before = matplotlib.get_backend();"
            "import sys; sys.path.insert(0, {!r}); import test_render_mpl as t;"
            "from graphmethods.render import mpl; mpl.to_png_bytes(t.small_scene(), dpi=20);"
            "print('pyplot' in sys.modules, matplotlib.get_backend() == before)").format(__file__.rsplit("/", 1)[0])
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["False", "True"]


def _ink_rows_mm(png: bytes, dpi: float):
    import io

    import matplotlib.image as mi
    import numpy as np

    img = mi.imread(io.BytesIO(png))
    dark = img[..., :3].sum(axis=-1) < 1.5
    rows = np.flatnonzero(dark.any(axis=1))
    cols = np.flatnonzero(dark.any(axis=0))
    return rows * 25.4 / dpi, cols * 25.4 / dpi


def test_png_text_stands_where_the_scene_puts_it():
    """Labels are drawn by a batch artist: their y must not be mirrored (Agg counts y from the top)."""
    dpi = 60.0
    page = Page("A4", "portrait")
    top = mpl.to_png_bytes(Scene(page, (Text((30.0, 20.0), "MMMM", size_mm=6.0),)), dpi=dpi)
    rows, cols = _ink_rows_mm(top, dpi)
    assert 14.0 < rows.min() and rows.max() < 21.5          # cap height above the 20 mm baseline
    assert 29.0 < cols.min() < 31.5                          # anchored at its start, x = 30 mm
    end = mpl.to_png_bytes(Scene(page, (Text((100.0, 250.0), "MMMM", size_mm=6.0, anchor="end"),)), dpi=dpi)
    rows, cols = _ink_rows_mm(end, dpi)
    assert 244.0 < rows.min() and rows.max() < 251.5 and 98.5 < cols.max() < 101.0


def test_png_subscripts_sit_below_the_baseline():
    dpi = 100.0
    page = Page("A4", "portrait")
    base = _ink_rows_mm(mpl.to_png_bytes(Scene(page, (Text((30.0, 40.0), "MM", size_mm=6.0),)), dpi=dpi), dpi)[0]
    sub = _ink_rows_mm(mpl.to_png_bytes(Scene(page, (Text((30.0, 40.0), "MM_{MM}", size_mm=6.0),)), dpi=dpi), dpi)[0]
    assert sub.max() > base.max() + 0.5                       # the subscript's ink goes lower on the page
