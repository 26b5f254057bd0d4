"""The render registry (graphmethods.render.formats): one entry per suffix, the same calls for every format."""

import subprocess
import sys

import pytest

from graphmethods.errors import InputError, OutputExistsError
from graphmethods.render import dxf, formats, mpl, pdf, svg
from graphmethods.scene import Line, Page, Scene, Text


def scene(name: str = "f") -> Scene:
    return Scene(Page("A4"), (Text((10, 12), "M_d = 10 N·m", name="t"), Line((10, 20), (80, 40), name="l")),
                 title="registry", name=name)


def test_each_suffix_gives_exactly_what_its_backend_writes():
    a, b = scene("a"), scene("b")
    assert formats.to_bytes(a, ".svg") == svg.to_bytes(a)
    assert formats.to_bytes([a, b], ".pdf") == pdf.to_bytes([a, b])
    assert formats.to_bytes(a, ".pdf") == pdf.to_bytes([a])
    assert formats.to_bytes([a, b], ".dxf") == dxf.to_bytes([a, b])
    assert formats.to_bytes(a, ".png") == mpl.to_png_bytes(a)


def test_a_png_resolution_is_an_option_of_the_png_format_only():
    a = scene("a")
    small = formats.to_bytes(a, ".png", dpi=50)
    assert small == mpl.to_png_bytes(a, dpi=50) and small != formats.to_bytes(a, ".png")
    assert formats.to_bytes(a, ".svg", dpi=50) == svg.to_bytes(a)       # the other formats have no pixels


def test_progress_hears_of_every_pdf_page_as_it_is_written_and_the_bytes_do_not_change():
    pages = [scene("a"), scene("b"), scene("c")]
    heard: list[tuple[int, int, str]] = []
    data = formats.to_bytes(pages, ".pdf", progress=lambda done, total, what: heard.append((done, total, what)))
    assert data == pdf.to_bytes(pages)
    assert heard == [(1, 3, "PDF pages"), (2, 3, "PDF pages"), (3, 3, "PDF pages")]


def test_the_suffix_is_read_from_a_file_name_in_any_case():
    assert formats.format_for("out/sheet.PDF") is formats.FORMATS[".pdf"]
    assert formats.format_for(".Svg") is formats.FORMATS[".svg"]
    with pytest.raises(InputError, match=r"give a file name ending in \.svg or \.pdf"):
        formats.format_for("a.png", among=(".svg", ".pdf"))


@pytest.mark.parametrize("suffix", [".svg", ".png"])
def test_a_one_figure_format_refuses_several_scenes(suffix):
    with pytest.raises(InputError, match="holds one figure, got 2"):
        formats.to_bytes([scene("a"), scene("b")], suffix)


@pytest.mark.parametrize("bad, message", [([], "no scenes"), ([scene(), "text"], "item 2 is str")])
def test_no_scene_or_a_non_scene_is_refused(bad, message):
    with pytest.raises(InputError, match=message):
        formats.to_bytes(bad, ".pdf")


def test_save_writes_the_format_of_the_suffix_and_keeps_an_existing_file(tmp_path):
    out = formats.save(scene(), tmp_path / "f.svg")
    assert out.read_bytes() == svg.to_bytes(scene())
    other = Scene(Page("A4"), (Text((10, 12), "other", name="t"),), name="g")
    with pytest.raises(OutputExistsError):
        formats.save(other, out)
    assert out.read_bytes() == svg.to_bytes(scene())
    formats.save(other, out, overwrite=True)
    assert out.read_bytes() == svg.to_bytes(other)


def test_an_unknown_suffix_or_too_many_figures_writes_nothing(tmp_path):
    with pytest.raises(InputError, match=r"f\.eps: give a file name ending in"):
        formats.save(scene(), tmp_path / "f.eps")
    with pytest.raises(InputError, match="holds one figure"):
        formats.save([scene("a"), scene("b")], tmp_path / "f.png")
    assert list(tmp_path.iterdir()) == []


def test_the_registry_loads_no_backend_until_a_format_is_used():
    code = ("import sys; import graphmethods.render.formats as f; "
            "print(sorted(m for m in ('matplotlib', 'svgwrite', 'ezdxf') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"
