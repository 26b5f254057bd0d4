"""Issue 28, item 4 (input): drawings read as other programs write them.

Each shipped SVG drawing, rewritten the way Inkscape and browsers write SVG (a style sheet of classes,
lengths in mm on a viewBox in px, groups with transforms that include skew and rotation, an arrow placed
by ``<use>``), gives the same check as the original; each shipped DXF drawing whose texts store μ, Δ, ω …
as ``\\U+03BC`` escapes (DXF 2004 and older) gives the same check as the original.
"""

from __future__ import annotations

import math
import pathlib
import re
import xml.etree.ElementTree as ET

import ezdxf
import pytest

from graphmethods.sheets.check import cad
from graphmethods.sheets.check.svg_reader import read_svg

DRAWINGS = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data" / "drawings"
SVG_NS = "http://www.w3.org/2000/svg"
XLINK = "http://www.w3.org/1999/xlink"
PX_PER_MM = 96 / 25.4
PROBLEM = {"w1": "W1", "press": "press", "slotted": "slotted-lever"}


def _problem(path: pathlib.Path) -> str:
    return PROBLEM[path.stem.split("_")[0]]


def _verdicts(rep) -> list[tuple]:
    return [(i.key, i.verdict, tuple(i.mistakes), i.student if isinstance(i.student, str) else round(i.student, 1))
            for i in rep.items]


def _translate_of(el_path: list[ET.Element]) -> tuple[float, float]:
    """The accumulated translation of a text's ancestors (the shipped drawings translate their layer only)."""
    x = y = 0.0
    for el in el_path:
        t = el.get("transform")
        if not t:
            continue
        m = re.fullmatch(r"\s*translate\(\s*([-\d.e]+)[\s,]+([-\d.e]+)\s*\)\s*", t)
        assert m, f"a transform the test does not rewrite: {t}"
        x, y = x + float(m.group(1)), y + float(m.group(2))
    return x, y


def inkscape_style(src: bytes) -> bytes:
    """The drawing as Inkscape or a browser may write it: classes in a <style> sheet instead of style
    attributes, a viewBox in px with the shapes scaled into it (and wrapped in a skew, a rotation and their
    inverses), texts placed in mm units (x="56.6mm"), the first arrow defined in <defs> and placed by <use>."""
    ET.register_namespace("", SVG_NS)
    ET.register_namespace("xlink", XLINK)
    root = ET.fromstring(src)
    W, H = (float(v) for v in root.get("viewBox", "").split()[2:])
    classes: dict[str, str] = {}
    parents = {c: p for p in root.iter() for c in p}

    def ancestors(el):
        out = []
        while el in parents:
            el = parents[el]
            out.append(el)
        return out[::-1]

    texts = []
    for el in list(root.iter()):
        style = el.get("style")
        if style and el.tag != f"{{{SVG_NS}}}tspan":
            cls = classes.setdefault(style, f"s{len(classes)}")
            del el.attrib["style"]
            el.set("class", cls)
        if el.tag == f"{{{SVG_NS}}}text":
            texts.append((el, _translate_of(ancestors(el))))
    for el, _ in texts:
        parents[el].remove(el)
    defs = root.find(f"{{{SVG_NS}}}defs")
    shapes = [c for c in list(root) if c is not defs]
    for c in shapes:
        root.remove(c)
    root.set("viewBox", f"0 0 {W * PX_PER_MM:.6f} {H * PX_PER_MM:.6f}")
    sheet = ET.SubElement(root, f"{{{SVG_NS}}}style")
    sheet.text = "\n".join(f".{cls}{{{style}}}" for style, cls in classes.items())
    root.remove(sheet)
    root.insert(0, sheet)
    outer = ET.SubElement(root, f"{{{SVG_NS}}}g", {"transform": f"scale({PX_PER_MM:.10f})"})
    skew = ET.SubElement(outer, f"{{{SVG_NS}}}g", {"transform": "skewX(20) rotate(30)"})
    unskew = ET.SubElement(skew, f"{{{SVG_NS}}}g", {"transform": "rotate(-30) skewX(-20)"})
    for c in shapes:
        unskew.append(c)
    arrow = next(el for el in unskew.iter(f"{{{SVG_NS}}}path") if "marker" in (
        [s for s, cls in classes.items() if cls == el.get("class")] or [""])[0])
    host = next(p for p in unskew.iter() if arrow in list(p))
    i = list(host).index(arrow)
    host.remove(arrow)
    arrow.set("id", "arrow-0")
    defs.append(arrow)
    host.insert(i, ET.Element(f"{{{SVG_NS}}}use", {f"{{{XLINK}}}href": "#arrow-0"}))
    layer = ET.SubElement(root, f"{{{SVG_NS}}}g")
    for el, (tx, ty) in texts:
        for node in [el] + [c for c in el.iter() if c is not el]:
            for key in ("x", "y"):
                if node.get(key) is not None:
                    v = float(node.get(key)) + (tx if key == "x" else ty)
                    node.set(key, f"{v:.4f}mm")
        cls = el.get("class")
        style = next(s for s, c in classes.items() if c == cls)
        size = re.search(r"font-size:\s*([\d.]+)px", style)
        el.set("style", f"font-size:{size.group(1)}mm" if size else "")
        layer.append(el)
    return ET.tostring(root, xml_declaration=True, encoding="utf-8")


# the cam drawings (shaper_cam_*) are curves, not arrows: tests/test_cam_check.py rewrites and reads them
@pytest.mark.parametrize("path", sorted(p for p in DRAWINGS.glob("*.svg") if "_cam_" not in p.name),
                         ids=lambda p: p.name)
def test_an_inkscape_style_rewrite_gives_the_same_check(tmp_path, path):
    rewritten = tmp_path / path.name
    rewritten.write_bytes(inkscape_style(path.read_bytes()))
    text = rewritten.read_text(encoding="utf-8")
    assert "<style>" in text and 'mm"' in text and "skewX" in text and "<use" in text and 'style="fill' not in text
    original, again = read_svg(path), read_svg(rewritten)
    assert len(again.segments) == len(original.segments) and len(again.texts) == len(original.texts)
    for (a, b), (c, d) in zip(sorted(original.segments), sorted(again.segments)):
        assert math.dist(a, c) < 1e-3 and math.dist(b, d) < 1e-3
    assert _verdicts(cad.check_drawing(_problem(path), rewritten)) == _verdicts(cad.check_drawing(_problem(path), path))


def test_compact_arc_flags_and_units_are_read_as_svg_means_them(tmp_path):
    p = tmp_path / "arc.svg"
    p.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">'
                 '<path style="fill:none;stroke:#000" d="M10 10a5 5 0 106 6l1-1"/>'
                 '<line x1="1cm" y1="0" x2="2cm" y2="0" stroke="black"/></svg>', encoding="utf-8")
    d = read_svg(p)
    ends = sorted(b for _, b in d.segments)
    # the arc ends at (16, 16) (flags 1, 0 and the end 6 6 run together), then the line to (17, 15) (y up: 84, 85)
    assert any(math.dist(e, (16.0, 84.0)) < 1e-6 for e in ends) and any(math.dist(e, (17.0, 85.0)) < 1e-6 for e in ends)
    # 1cm in user space is 37.8 user units (CSS: 96 px to the inch), which this viewBox prints as 37.8 mm
    assert any(math.dist(a, (10 * PX_PER_MM, 100.0)) < 1e-3 and math.dist(b, (20 * PX_PER_MM, 100.0)) < 1e-3
               for a, b in d.segments)


def _escaped(text: str) -> str:
    return "".join(ch if ord(ch) < 128 else f"\\U+{ord(ch):04X}" for ch in text)


@pytest.mark.parametrize("path", sorted(p for p in DRAWINGS.glob("*.dxf") if "_cam_" not in p.name),
                         ids=lambda p: p.name)
def test_dxf_texts_with_unicode_escapes_give_the_same_check(tmp_path, path):
    doc = ezdxf.readfile(str(path))
    n = 0
    for e in doc.modelspace():
        if e.dxftype() == "TEXT" and any(ord(c) > 127 for c in e.dxf.text):
            e.dxf.text = _escaped(e.dxf.text)
            n += 1
        elif e.dxftype() == "MTEXT" and any(ord(c) > 127 for c in e.text):
            e.text = _escaped(e.text)
            n += 1
    escaped = tmp_path / path.name
    doc.saveas(str(escaped))
    assert n and "\\U+" in escaped.read_text(encoding="utf-8", errors="replace")
    problem = _problem(path)
    assert _verdicts(cad.check_drawing(problem, escaped)) == _verdicts(cad.check_drawing(problem, path))
