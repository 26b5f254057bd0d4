"""DXF out (render/dxf.py), read back with ezdxf: true size in mm, vectors as long as value/μ, layers by role,
nothing outside the frame, deterministic bytes; and ``--format dxf`` at the command line."""

import io
import math
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

ezdxf = pytest.importorskip("ezdxf")

from graphmethods import cli  # noqa: E402
from graphmethods.errors import OutputExistsError  # noqa: E402
from graphmethods.kinematics import read_case  # noqa: E402
from graphmethods.render import dxf  # noqa: E402
from graphmethods.scene import Page, Scale, Scene, Text, Vector  # noqa: E402
from graphmethods.sheets import kinematics as ks  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
DATA = ROOT / "graphmethods" / "problems" / "data"


def read(data: bytes):
    return ezdxf.read(io.StringIO(data.decode("utf-8")))


def press_velocities(phi, r, l, e, l_AS2, omega):
    """Offset slider-crank velocities written out by hand (independent of the package): v_A, v_B, v_BA, v_S2."""
    s, c = math.sin(phi), math.cos(phi)
    q = e - r * s
    w = math.sqrt(l * l - q * q)
    v_B = omega * (-r * s + q * r * c / w)
    omega_2 = omega * (-r * c / w)
    v_S2 = math.hypot(omega * (-r * s) + l_AS2 * omega_2 * (-q / l), omega * (r * c) + l_AS2 * omega_2 * (w / l))
    return {"pa": omega * r, "pb": abs(v_B), "ab": abs(omega_2) * l, "ps2": v_S2}


def group_entities(doc, name):
    return list(doc.groups.get(name))


def vector_length_mm(doc, name) -> float:
    """From the shaft's first point to the arrowhead's tip (the SOLID's first corner)."""
    ents = group_entities(doc, name)
    shaft = next(e for e in ents if e.dxftype() == "LWPOLYLINE")
    head = next(e for e in ents if e.dxftype() == "SOLID")
    start = shaft.get_points("xy")[0]
    tip = head.dxf.vtx0
    return math.dist(start, (tip.x, tip.y))


def all_points(doc):
    """Every point an entity reaches (polylines, solids, circles ± r, hatch boundaries), and text insertion points."""
    for e in doc.modelspace():
        t = e.dxftype()
        if t == "LWPOLYLINE":
            yield e.dxf.layer, [tuple(p) for p in e.get_points("xy")]
        elif t == "SOLID":
            yield e.dxf.layer, [(v.x, v.y) for v in (e.dxf.vtx0, e.dxf.vtx1, e.dxf.vtx2)]
        elif t == "CIRCLE":
            c, r = e.dxf.center, e.dxf.radius
            yield e.dxf.layer, [(c.x - r, c.y - r), (c.x + r, c.y + r)]
        elif t == "HATCH":
            pts = []
            for path in e.paths:
                if hasattr(path, "vertices"):
                    pts += [(v[0], v[1]) for v in path.vertices]
                else:
                    for edge in path.edges:
                        c, r = edge.center, edge.radius
                        pts += [(c[0] - r, c[1] - r), (c[0] + r, c[1] + r)]
            yield e.dxf.layer, pts
        elif t == "TEXT":
            p = e.dxf.align_point if e.dxf.halign else e.dxf.insert
            yield e.dxf.layer, [(p.x, p.y)]


@pytest.fixture(scope="module")
def press():
    return read_case(DATA / "slider_crank_press.json")


@pytest.fixture(scope="module")
def plan_dxf(press):
    scene = ks.velocity_plan(press, position=2, notation="en")
    return scene, read(dxf.to_bytes(scene))


def test_every_velocity_vector_is_value_over_mu_v_long(press, plan_dxf):
    scene, doc = plan_dxf
    (mu_v,) = [s for s in scene.scales() if s.symbol == "μ_v"]
    pos = press.mechanism.positions(m=12)
    v = press_velocities(float(pos.phi[2]), 0.1, 0.4, 0.02, 0.13, 2 * math.pi * 300 / 60)
    for seg, value in v.items():
        assert vector_length_mm(doc, f"vector-{seg}") == pytest.approx(value / mu_v.per_mm, abs=1e-4), seg
    assert doc.units == 4 and doc.header["$INSUNITS"] == 4             # millimetres
    assert all(e.dxf.layer == "VECTORS-KNOWN" for e in group_entities(doc, "vector-pa"))
    assert all(e.dxf.layer == "VECTORS-FOUND" for e in group_entities(doc, "vector-pb"))
    found_shaft = next(e for e in group_entities(doc, "vector-pb") if e.dxftype() == "LWPOLYLINE")
    pattern = doc.linetypes.get(found_shaft.dxf.linetype).pattern_tags.tags
    # a standard name (LibreCAD dashes only the linetypes it knows by name), our pattern (AutoCAD, ezdxf draw it)
    assert found_shaft.dxf.linetype == "DASHED" and [t.value for t in pattern if t.code == 49] == [2.5, -1.2]
    assert found_shaft.dxf.lineweight == 35


def test_true_size_page_and_frame(plan_dxf):
    scene, doc = plan_dxf
    polylines = [e for e in group_entities(doc, "page") if e.dxftype() == "LWPOLYLINE"]
    frame = max(polylines, key=lambda e: max(p[0] for p in e.get_points("xy")) - min(p[0] for p in e.get_points("xy")))
    xs, ys = zip(*frame.get_points("xy"))
    x0, y0, x1, y1 = scene.page.inner_box()
    assert (min(xs), max(xs)) == pytest.approx((x0, x1)) and (max(ys) - min(ys)) == pytest.approx(y1 - y0)
    assert min(ys) == pytest.approx(scene.page.height_mm - y1)          # y up, bottom-left corner at 0, 0
    assert frame.dxf.layer == "FRAME" and frame.closed


def test_every_layer_present_and_used():
    press_plan = ks.velocity_plan(read_case(DATA / "slider_crank_press.json"), position=2)
    scenes = [press_plan]
    for name in ("w3_moment_diagram_en", "press_wittenbauer_en", "w1_energy_indicator_en"):
        from graphmethods.cli.gallery import build

        scenes.append(build(name))
    used = set()
    for scene in scenes:
        doc = read(dxf.to_bytes(scene))
        assert [name for name, *_ in dxf.LAYERS.values()] == [n for n in (ly.dxf.name for ly in doc.layers)
                                                                if n not in ("0", "Defpoints")]
        used |= {e.dxf.layer for e in doc.modelspace()}
        assert {s.dxf.name for s in doc.styles} >= set(dxf.TEXT_STYLES)
    assert used == {name for name, *_ in dxf.LAYERS.values()}


def test_hatching_curves_and_axes_on_their_layers():
    from graphmethods.cli.gallery import build

    doc = read(dxf.to_bytes(build("w3_moment_diagram_en")))
    assert {e.dxf.layer for e in doc.groups.get("curve-M_d")} == {"CURVES"}
    assert {e.dxf.layer for e in doc.groups.get("region-1")} == {"HATCHING"}
    assert {e.dxf.layer for e in doc.groups.get("axis-M") if e.dxftype() != "TEXT"} == {"AXES"}


@pytest.mark.parametrize("name", ["press_velocity_plan_en", "w1_energy_indicator_zh", "press_wittenbauer_ru",
                                  "press_kinematic_scheme_en", "w3_moment_diagram_en"])
def test_nothing_outside_the_frame(name):
    from graphmethods.cli.gallery import build

    scene = build(name)
    doc = read(dxf.to_bytes(scene))
    x0, y0, x1, y1 = scene.page.inner_box()
    H = scene.page.height_mm
    box = (x0, H - y1, x1, H - y0)
    n = 0
    for layer, pts in all_points(doc):
        for x, y in pts:
            n += 1
            assert box[0] - 1e-6 <= x <= box[2] + 1e-6 and box[1] - 1e-6 <= y <= box[3] + 1e-6, (layer, x, y)
    assert n > 50


def test_text_is_text_in_a_named_style():
    scene = Scene(Page("A4"), (Text((20, 30), "ΔW_{max} = 575 J", name="t"), Text((100, 30), "Мд", name="u",
                                                                                   anchor="middle")))
    doc = read(dxf.to_bytes(scene))
    texts = [e for e in doc.modelspace() if e.dxftype() == "TEXT"]
    assert [t.dxf.text for t in texts] == ["ΔW", "max", " = 575 J", "Мд"]
    assert {t.dxf.style for t in texts} == {dxf.STYLE_SANS} and doc.styles.get(dxf.STYLE_SANS).dxf.font == "arial.ttf"
    base, sub = texts[0], texts[1]
    assert base.dxf.insert.y == pytest.approx(210 - 30) and sub.dxf.insert.y < base.dxf.insert.y   # subscript lower
    assert sub.dxf.height == pytest.approx(0.7 * base.dxf.height)
    assert texts[3].dxf.halign == 1 and texts[3].dxf.align_point.x == pytest.approx(100)           # centred


def test_deterministic_undated_in_another_process(tmp_path):
    mu = Scale("μ_v", "m/s", 0.05)
    scene = Scene(Page("A4"), (Vector.of((50, 100), value=2.0, scale=mu, angle_deg=30, name="vector-pa"),
                               Text((10, 10), "v_A")))
    a = dxf.to_bytes(scene)
    assert a == dxf.to_bytes(scene)
    code = ("import sys; from graphmethods.render import dxf; from graphmethods.scene import *;"
            "mu = Scale('μ_v', 'm/s', 0.05);"
            "s = Scene(Page('A4'), (Vector.of((50, 100), value=2.0, scale=mu, angle_deg=30, name='vector-pa'),"
            " Text((10, 10), 'v_A')));"
            "sys.stdout.buffer.write(dxf.to_bytes(s))")
    for seed in ("1", "2"):                        # ezdxf keeps some things in sets: the hash seed must not matter
        other = subprocess.run([sys.executable, "-c", code], capture_output=True, check=True,
                               env=dict(os.environ, PYTHONHASHSEED=seed)).stdout
        assert other == a
    tags = a.decode("utf-8").splitlines()                  # the header as written (ezdxf.read would stamp its own)
    header = {tags[i + 1]: tags[i + 3] for i in range(len(tags) - 3) if tags[i].strip() == "9"}
    assert float(header["$TDCREATE"]) == float(header["$TDUPDATE"]) == dxf.FIXED_JULIAN_DATE
    assert header["$FINGERPRINTGUID"] == header["$VERSIONGUID"] == dxf.FIXED_GUID
    import ezdxf as e

    assert e.options.write_fixed_meta_data_for_testing is False          # the option is put back


def test_several_scenes_side_by_side_and_safe_saving(tmp_path):
    mu = Scale("μ_v", "m/s", 0.05)
    s1 = Scene(Page("A4"), (Vector.of((50, 100), value=2.0, scale=mu, angle_deg=0, name="v"),), name="one")
    s2 = Scene(Page("A3"), (Vector.of((50, 100), value=2.0, scale=mu, angle_deg=0, name="v"),), name="two")
    doc = read(dxf.to_bytes([s1, s2]))
    starts = sorted(next(e for e in doc.groups.get(g) if e.dxftype() == "LWPOLYLINE").get_points("xy")[0][0]
                    for g in ("v", "p2-v"))
    assert starts == pytest.approx([50.0, 297 + dxf.PAGE_GAP_MM + 50.0])
    path = tmp_path / "x.dxf"
    dxf.save(s1, path)
    with pytest.raises(OutputExistsError):
        dxf.save(s1, path)
    dxf.save(s2, path, overwrite=True)
    assert [p.name for p in tmp_path.iterdir()] == ["x.dxf"]


def test_cli_kinematics_figures_as_dxf(tmp_path, capsys):
    rc = cli.main(["kinematics", str(DATA / "slider_crank_press.json"), "--figures", str(tmp_path / "f"),
                   "--format", "dxf"])
    capsys.readouterr()
    assert rc == 0
    files = sorted(p.suffix for p in (tmp_path / "f").iterdir())
    assert ".dxf" in files and ".svg" not in files
    for p in (tmp_path / "f").glob("*.dxf"):
        doc = ezdxf.readfile(p)
        assert len(doc.modelspace()) > 10


def test_cli_study_sheet_and_check_overlay_as_dxf(tmp_path, capsys):
    rc = cli.main(["study", str(DATA / "slider_crank_press.json"), "--no-exact", "--sheet", str(tmp_path / "s.dxf")])
    assert rc == 0
    doc = ezdxf.readfile(tmp_path / "s.dxf")
    xs = [p[0] for e in doc.groups.get("page") if e.dxftype() == "LWPOLYLINE" for p in e.get_points("xy")]
    assert max(xs) - min(xs) == pytest.approx(841 - 20 - 10, abs=1e-6)         # an A1 sheet's frame at 1:1
    rc = cli.main(["check", "press", str(DATA / "answers" / "press_plan_mistakes.toml"), "--overlay",
                   str(tmp_path / "o.dxf")])
    capsys.readouterr()
    assert rc == 1
    doc = ezdxf.readfile(tmp_path / "o.dxf")
    red = [e for e in doc.modelspace() if e.dxf.hasattr("true_color") and e.dxf.true_color >> 16 > 150]
    assert red, "the wrong items are drawn in red"


def test_cli_gallery_writes_dxf(tmp_path, capsys):
    d = tmp_path / "g"
    d.mkdir()
    # a figure script of one's own (the built-in figures are rows of the gallery's catalogue now)
    (d / "w1_energy_indicator_en.py").write_text(
        "from graphmethods.gallery import figure_module\n\n\ndef build():\n"
        "    return figure_module('w1_energy_indicator_en').build()\n", encoding="utf-8")
    rc = cli.main(["gallery", "--dir", str(d), "--out", str(tmp_path / "out"), "--dxf"])
    out = capsys.readouterr().out
    assert rc == 0 and "w1_energy_indicator_en.dxf" in out
    doc = ezdxf.readfile(tmp_path / "out" / "w1_energy_indicator_en.dxf")
    assert np.isclose(sum(1 for g in doc.groups if g[0].startswith("vector-")), 7)


# the linetype names LibreCAD draws dashed (RS_FilterDXFRW::nameToLineType); any other name prints solid there
_LIBRECAD_LINETYPES = {"DOT", "DOT2", "DOTX2", "ACAD_ISO07W100", "DASHED", "HIDDEN", "ACAD_ISO02W100", "ACAD_ISO03W100",
                       "DASHED2", "HIDDEN2", "DASHEDX2", "HIDDENX2", "DASHDOT", "ACAD_ISO10W100", "DASHDOT2",
                       "DASHDOTX2", "CENTER", "CENTER2", "CENTERX2", "DIVIDE", "DIVIDE2", "DIVIDEX2", "BORDER",
                       "BORDER2", "BORDERX2"}


def test_every_dash_of_the_gallery_has_a_linetype_name_librecad_draws_and_our_pattern():
    import re

    golden = pathlib.Path(__file__).resolve().parents[1] / "gallery"
    dashes = {tuple(float(v) for v in m.split()) for p in golden.glob("*.svg") if not p.stem.startswith("bench_")
              for m in re.findall(r'stroke-dasharray="([^"]+)"', p.read_text(encoding="utf-8"))}
    assert dashes and dashes <= set(dxf.STANDARD_LINETYPES)
    assert set(dxf.STANDARD_LINETYPES.values()) <= _LIBRECAD_LINETYPES
    assert len(set(dxf.STANDARD_LINETYPES.values())) == len(dxf.STANDARD_LINETYPES)      # one name, one pattern
    doc = read(dxf.to_bytes(Scene(Page("A4"), (Text((20, 20), "x", name="t"),))))
    renderer = dxf.DxfRenderer(doc, 0.0)
    for dash, name in dxf.STANDARD_LINETYPES.items():
        assert renderer._linetype(dash) == name
        tags = [t.value for t in doc.linetypes.get(name).pattern_tags.tags if t.code == 49]
        assert tags == [d if i % 2 == 0 else -d for i, d in enumerate(dash)]


def test_a_drawing_with_its_own_dashed_linetype_keeps_it_and_ours_gets_a_name_of_its_own():
    scene = Scene(Page("A4"), (Text((20, 20), "x", name="t"),))
    doc = read(dxf.to_bytes(scene))
    doc.linetypes.add("DASHED", pattern=[20.0, 12.7, -7.3], description="the student's own")
    renderer = dxf.DxfRenderer(doc, 0.0)
    assert renderer._linetype((2.5, 1.2)) == "GM-DASH-2p5-1p2"
    assert doc.linetypes.get("DASHED").dxf.description == "the student's own"


def test_text_styles_name_fonts_cad_programs_find_and_librecad_fonts():
    # AutoCAD, BricsCAD, nanoCAD, KOMPAS and ezdxf's viewer find a style's font by its file name; LibreCAD takes the
    # style's name for one of its own fonts (standard.lff, without Greek or Cyrillic, when it knows none)
    assert {name: font for name, (font, _, _) in dxf.TEXT_STYLES.items()} == {
        "OpenGostTypeB-Regular": "arial.ttf", "lc_opengost-br": "arialbd.ttf", "kst32b": "NotoSansCJK-Regular.ttc"}
    doc = read(dxf.to_bytes(Scene(Page("A4"), (Text((20, 20), "速度多边形 ω", name="t"),
                                                  Text((20, 40), "План скоростей", name="u", bold=True)))))
    styles = {t.dxf.text: t.dxf.style for t in doc.modelspace() if t.dxftype() == "TEXT"}
    assert styles == {"速度多边形 ω": "kst32b", "План скоростей": "lc_opengost-br"}
    assert doc.styles.get("kst32b").get_extended_font_data()[0] == "Noto Sans CJK SC"
