"""The SVG backend: scale-true page, one number formatter, explicit ids, escaping, determinism, safe saving."""

import hashlib
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.errors import InputError, OutputExistsError
from graphmethods.render import svg
from graphmethods.scene import (
    Axis,
    Dimension,
    Page,
    Point,
    Region,
    Scale,
    ScaleCaptions,
    Scene,
    Table,
    Text,
    TitleBlock,
    Vector,
    markup,
)

NS = {"svg": "http://www.w3.org/2000/svg"}


def demo_scene(size="A4", orientation="landscape", user_text="W1 <diesel> & \"gen\"") -> Scene:
    mu_E = Scale("μ_E", "J", 10.0)
    mu_M = Scale("μ_M", "N·m", 2.0)
    tb = TitleBlock("Energy indicator", user_text, (mu_E.caption(),))
    page = Page(size, orientation, frame=True, title_block=tb)
    return Scene(page, (
        Vector.of((50, 100), value=-550.0, scale=mu_E, angle_deg=90, name="vector-bc"),
        Vector.of((60, 100), value=123.456, scale=mu_E, angle_deg=30, known=False, name="vector-cd"),
        Axis((20, 150), mu_M, "y", min_value=-10, max_value=40, ticks=(0, 20, 40), label="M, N·m", name="axis-M"),
        Region(((100, 50), (150, 50), (150, 80), (100, 90)), name="region-1"),
        Dimension((180, 150), (180, 100), "ΔW_{max} = 575 J", offset_mm=5, name="dim"),
        Point((100, 120), "a", "nw", name="point-a"),
        Table((200, 20), (("i", "A, J"), ("1", "+50")), name="table"),
        Text((20, 20), user_text, markup=False, name="user"),
        ScaleCaptions((20, 190), (mu_E, mu_M), name="captions"),
    ), title="Demo <figure>", name="demo")


def parse(text: str) -> ET.Element:
    return ET.fromstring(text.encode("utf-8"))


def text_of(elem) -> str:
    return "".join(elem.itertext())


@pytest.mark.parametrize("size", ["A4", "A3", "A2", "A1"])
@pytest.mark.parametrize("orientation", ["portrait", "landscape"])
def test_page_size_in_mm_equals_the_viewbox(size, orientation):
    root = parse(svg.to_string(demo_scene(size, orientation)))
    page = Page(size, orientation)
    w, h = root.get("width"), root.get("height")
    assert w.endswith("mm") and h.endswith("mm")
    vb = [float(v) for v in root.get("viewBox").split()]
    assert vb == [0.0, 0.0, float(w[:-2]), float(h[:-2])] == [0.0, 0.0, page.width_mm, page.height_mm]


def _group(root, gid):
    (g,) = [e for e in root.iter("{http://www.w3.org/2000/svg}g") if e.get("id") == gid]
    return g


def _points(elem):
    return [tuple(float(v) for v in p.split(",")) for p in elem.get("points").split()]


@given(st.floats(min_value=-3000, max_value=3000).filter(lambda v: abs(v) > 0.5),
       st.sampled_from([1.0, 2.5, 5.0, 10.0, 20.0]), st.floats(min_value=0, max_value=360))
@settings(max_examples=40)
def test_a_vector_of_value_v_is_v_over_mu_long_in_the_svg(value, per_mm, angle):
    mu = Scale("μ_E", "J", per_mm)
    scene = Scene(Page("A1"), (Vector.of((300, 400), value=value, scale=mu, angle_deg=angle, name="v"),))
    g = _group(parse(svg.to_string(scene)), "v")
    shaft = g.find("svg:polyline", NS)
    head = g.find("svg:polygon", NS)
    start, tip = _points(shaft)[0], _points(head)[0]
    assert math.dist(start, tip) == pytest.approx(abs(value) / per_mm, abs=0.001 + 1e-9)


def test_every_number_goes_through_the_formatter():
    text = svg.to_string(demo_scene())
    numbers = re.findall(r' (?:points|x|y|cx|cy|r|dy|font-size|stroke-width|stroke-dasharray)="([^"]*)"', text)
    assert numbers
    for attr in numbers:
        for num in re.split(r"[ ,]+", attr.strip()):
            assert re.fullmatch(r"-?\d+(\.\d{1,3})?", num), num
            assert num != "-0" and not (("." in num) and num.endswith("0"))


def test_ids_come_from_element_names_and_are_unique():
    root = parse(svg.to_string(demo_scene()))
    ids = [e.get("id") for e in root.iter() if e.get("id") is not None]
    assert len(ids) == len(set(ids))
    assert {"demo", "page", "vector-bc", "vector-cd", "axis-M", "region-1", "dim", "point-a", "table", "user",
            "captions"} <= set(ids)
    assert not any(re.fullmatch(r"id\d+", i) for i in ids)          # never svgwrite's counter


def test_user_text_is_escaped_and_reads_back_exactly():
    nasty = 'a < b && c > "d" \'e\' </text><script>alert(1)</script> \x00\x07 end'
    text = svg.to_string(demo_scene(user_text=nasty))
    assert "<script>" not in text
    root = parse(text)                                                   # well-formed XML
    user = _group(root, "user")
    assert text_of(user.find("svg:text", NS)) == nasty.replace("\x00", "\ufffd").replace("\x07", "\ufffd")
    assert root.find("svg:title", NS).text == "Demo <figure>"


def test_subscripts_are_baseline_shifted_smaller_runs():
    scene = Scene(Page("A4"), (Text((10, 20), "ψ_{max} = 30°", size_mm=4.0, name="t"),))
    t = _group(parse(svg.to_string(scene)), "t").find("svg:text", NS)
    spans = t.findall("svg:tspan", NS)
    assert [s.text for s in spans] == ["ψ", "max", " = 30°"]
    assert float(spans[1].get("dy")) > 0 and float(spans[1].get("font-size")) < 4.0
    assert float(spans[2].get("dy")) == -float(spans[1].get("dy"))


def test_scale_captions_are_in_the_svg():
    text = svg.to_string(demo_scene())
    texts = {text_of(e) for e in parse(text).iter("{http://www.w3.org/2000/svg}text")}
    assert markup.plain(Scale("μ_E", "J", 10.0).caption()) in texts
    assert markup.plain(Scale("μ_M", "N·m", 2.0).caption()) in texts


def test_no_dates_and_same_bytes_twice():
    a, b = svg.to_bytes(demo_scene()), svg.to_bytes(demo_scene())
    assert a == b
    assert not re.search(rb"20\d\d-\d\d-\d\d", a)


def test_same_bytes_in_a_fresh_process_with_another_hash_seed():
    here = hashlib.sha256(svg.to_bytes(demo_scene())).hexdigest()
    code = (f"import hashlib, sys; sys.path.insert(0, {os.path.dirname(__file__)!r}); import test_render_svg as t;"
            "from graphmethods.render import svg;"
            "print(hashlib.sha256(svg.to_bytes(t.demo_scene())).hexdigest())")
    for seed in ("1", "4242"):
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                             env={**os.environ, "PYTHONHASHSEED": seed})
        assert out.stdout.strip() == here


def test_save_refuses_to_overwrite_and_writes_atomically(tmp_path):
    path = tmp_path / "fig.svg"
    svg.save(demo_scene(), path)
    first = path.read_bytes()
    with pytest.raises(OutputExistsError, match="overwrite=True"):
        svg.save(demo_scene("A3"), path)
    assert path.read_bytes() == first
    svg.save(demo_scene("A3"), path, overwrite=True)
    assert path.read_bytes() != first
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fig.svg"]        # no temporary file left


def test_an_error_while_writing_leaves_no_file(tmp_path, monkeypatch):
    path = tmp_path / "fig.svg"

    def broken_link(src, dst):
        raise RuntimeError("disk fell off")

    monkeypatch.setattr(os, "link", broken_link)
    with pytest.raises(RuntimeError):
        svg.save(demo_scene(), path)
    assert list(tmp_path.iterdir()) == []


def test_save_into_a_missing_directory_says_so(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        svg.save(demo_scene(), tmp_path / "nope" / "fig.svg")


def test_non_finite_coordinates_are_refused_not_written():
    from graphmethods.render.base import draw
    from graphmethods.scene.primitives import Path as PPath

    class Bad(Text):
        def primitives(self):
            return (PPath(((0.0, 0.0), (math.nan, 1.0))),)

    with pytest.raises(InputError, match="non-finite"):
        svg.to_string(Scene(Page("A4"), (Bad((0, 0), "x"),)))
    assert draw  # the same path every backend takes


def test_repr_svg_for_notebooks():
    assert demo_scene()._repr_svg_() == svg.to_string(demo_scene())
