"""Checking a student's cam profile (issue 29): drawings made in CAD (DXF, SVG) with planted mistakes, typed
answers, the overlay, and bad files refused in one line."""

import json
import os
import pathlib
import shutil
import subprocess

import pytest

from graphmethods.cli import main
from graphmethods.errors import InputError
from graphmethods.sheets import worksheets as ws
from graphmethods.sheets.check import cam as cc

DRAWINGS = pathlib.Path(cc.__file__).parents[2] / "problems" / "data" / "drawings"


def verdicts(rep):
    return {i.key: (i.verdict, i.mistakes) for i in rep.items}


@pytest.fixture(scope="module")
def correct():
    return {ext: cc.check_drawing("shaper-cam", DRAWINGS / f"shaper_cam_correct.{ext}") for ext in ("dxf", "svg")}


def test_a_correct_drawing_is_correct_in_dxf_and_svg(correct):
    for rep in correct.values():
        assert rep.ok, rep.to_text()
        keys = [i.key for i in rep.items]
        assert "cam.base_radius" in keys and "cam.pitch_base_radius" in keys
        assert sum(k.startswith("cam.s_mm[") for k in keys) == 18            # 8 parts per rise and return
        assert "cam.profile_dev_mm" in keys and "cam.pitch_dev_mm" in keys
    dxf, svg = (correct[e] for e in ("dxf", "svg"))
    for a, b in zip(dxf.items, svg.items):                                   # the same drawing, read alike
        assert a.key == b.key and abs(a.student - b.student) <= 0.15 if isinstance(a.student, float) else True


def test_the_follower_turned_with_the_cam_is_named():
    rep = cc.check_drawing("shaper-cam", DRAWINGS / "shaper_cam_mistakes.dxf")
    v = verdicts(rep)
    assert v["cam.base_radius"][0] == "ok" and v["cam.pitch_base_radius"][0] == "ok"
    assert v["cam.profile_dev_mm"] == ("wrong", ("inversion_same_sense",))
    assert v["cam.pitch_dev_mm"] == ("wrong", ("inversion_same_sense",))
    assert v["cam.alpha_max_return_deg"] == ("wrong", ())                  # 20° written: no usual mistake
    s_items = [x for k, x in v.items() if k.startswith("cam.s_mm[")]
    assert all(x[1] == ("inversion_same_sense",) for x in s_items if x[0] == "wrong")
    assert sum(x[0] == "wrong" for x in s_items) >= 15
    assert [m.code for m in rep.mistakes] == ["inversion_same_sense"]


def test_a_base_radius_too_small_is_wrong_and_what_follows_is_carried():
    rep = cc.check_drawing("shaper-cam", DRAWINGS / "shaper_cam_small.svg")
    v = verdicts(rep)
    assert v["cam.base_radius"] == ("wrong", ()) and v["cam.pitch_base_radius"] == ("wrong", ())
    for key in ("cam.alpha_max_rise_deg", "cam.alpha_max_return_deg", "cam.profile_dev_mm", "cam.pitch_dev_mm"):
        assert v[key][0] == "carried", key
    assert all(x[0] == "ok" for k, x in v.items() if k.startswith("cam.s_mm["))     # s does not depend on r₀


def test_typed_answers_of_a_worksheet_variant_and_the_usual_mistakes():
    v = ws.variant("cam", seed=3, number=2)
    a = v.answers()
    good = {k: a[k] for k in ("mu_l", "base_radius", "pitch_base_radius", "s_mm", "alpha_max_rise_deg",
                              "alpha_max_return_deg")}
    assert cc.check_cam(v.id, {"cam": good}).ok
    s0_mm = (v.cam.pitch_base_radius ** 2 - v.offset ** 2) ** 0.5 / v.mu_l
    bad = dict(good, base_radius=a["pitch_base_radius"], s_mm=[s0_mm + s for s in a["s_mm"]])
    rep = cc.check_cam(v.id, {"cam": bad})
    codes = verdicts(rep)
    assert codes["cam.base_radius"] == ("wrong", ("pitch_for_profile",))
    assert all(codes[f"cam.s_mm[{k}]"] == ("wrong", ("s_from_centre",)) for k in range(len(a["s_mm"])))
    assert codes["cam.alpha_max_rise_deg"][0] == "ok"


def test_typed_answers_file_through_the_command_line(tmp_path, capsys):
    v = ws.variant("cam", seed=3, number=2)
    a = v.answers()
    text = ws.answers.template("cam").replace('base_radius = ""', f"base_radius = {a['base_radius']}", 1)
    text = text.replace("s_mm = []", "s_mm = [" + ", ".join(f"{x:.2f}" for x in a["s_mm"]) + "]")
    text = text.replace('mu_l = ""', f"mu_l = {v.mu_l}")
    f = tmp_path / "ivanova.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["check", v.id, str(f), "--report", "json"]) == 0
    rep = json.loads(capsys.readouterr().out)
    assert rep["ok"] and len(rep["items"]) == 1 + len(a["s_mm"])
    assert main(["check", v.id, str(f), "--lang", "zh", "-o", str(tmp_path / "film.svg")]) == 0
    assert (tmp_path / "film.svg").stat().st_size > 1000


@pytest.mark.parametrize("lang, word", [("en", "follower turned with the cam"), ("ru", "толкатель повёрнут"),
                                        ("zh", "从动件按凸轮转向")])
def test_command_line_report_and_overlays(tmp_path, capsys, lang, word):
    src = DRAWINGS / "shaper_cam_mistakes.dxf"
    assert main(["check", "shaper-cam", str(src), "--lang", lang, "-o", str(tmp_path / "c.svg")]) == 1
    out = capsys.readouterr().out
    assert word in out
    svg = (tmp_path / "c.svg").read_text(encoding="utf-8")
    assert "#d01818" in svg                                   # the exact construction in red
    assert main(["check", "shaper-cam", str(src), "-o", str(tmp_path / "c.dxf")]) == 1
    assert b"CHECK" in (tmp_path / "c.dxf").read_bytes()


def test_svg_as_inkscape_writes_it_reads_alike(tmp_path):
    text = (DRAWINGS / "shaper_cam_correct.svg").read_text(encoding="utf-8")
    head, body = text.split("\n", 1)
    body = body.replace("</svg>\n", "")
    moved = (head.replace('viewBox="0 0 210 297"', 'viewBox="0 0 793.7 1122.5"') + "\n"
             '<g transform="scale(3.7795276)">' + body + "</g></svg>\n")
    f = tmp_path / "inkscape.svg"
    f.write_text(moved, encoding="utf-8")
    rep = cc.check_drawing("shaper-cam", f)
    assert rep.ok and len(rep.items) == 24


def test_bad_drawings_are_refused_in_one_line(tmp_path, capsys):
    junk = tmp_path / "junk.dxf"
    junk.write_text("this is not a drawing", encoding="utf-8")
    assert main(["check", "shaper-cam", str(junk)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "junk.dxf" in err
    empty = tmp_path / "lines.svg"
    empty.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">'
                     '<line x1="10" y1="10" x2="90" y2="90" stroke="#000"/>'
                     '<text x="5" y="95" font-size="4">μl = 0,001 m/mm</text></svg>', encoding="utf-8")
    assert main(["check", "shaper-cam", str(empty)]) == 2
    assert "no circle about the cam centre" in capsys.readouterr().err
    noscale = tmp_path / "noscale.svg"
    noscale.write_text((DRAWINGS / "shaper_cam_correct.svg").read_text(encoding="utf-8").replace("μl = 0,0005 m/mm",
                                                                                                "scale 2:1"))
    assert main(["check", "shaper-cam", str(noscale)]) == 2
    assert "no scale" in capsys.readouterr().err
    assert main(["check", "shaper-cam", str(noscale), "--mu-l", "0.0005"]) == 0


def test_a_cam_answers_file_with_a_wrong_key_is_refused():
    with pytest.raises(InputError, match="unknown key"):
        cc.check_cam("shaper-cam", {"cam": {"mu_l": 0.0005, "r_b": 0.011}})
    with pytest.raises(InputError, match="phi_deg"):
        cc.check_cam("shaper-cam", {"cam": {"mu_l": 0.0005, "s_mm": [0.0, 1.0]}})
    with pytest.raises(InputError, match="no scale"):
        cc.check_cam("shaper-cam", {"cam": {"base_radius": 0.011}})


@pytest.mark.skipif(not (shutil.which("librecad") and shutil.which("pdftocairo")), reason="needs librecad, poppler")
def test_a_drawing_printed_through_librecad_reads_alike(tmp_path):
    """LibreCAD prints the DXF (dxf2pdf, scale 1:1), poppler writes that PDF as SVG: every spline becomes many
    short separate paths, every text glyph outlines; the pieces are joined back, the scale given."""
    src = tmp_path / "cam.dxf"
    src.write_bytes((DRAWINGS / "shaper_cam_correct.dxf").read_bytes())
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    subprocess.run(["librecad", "dxf2pdf", "-s", "1", "-t", str(tmp_path), str(src)], env=env, check=True,
                   capture_output=True, timeout=120)
    subprocess.run(["pdftocairo", "-svg", str(tmp_path / "cam.pdf"), str(tmp_path / "cam.svg")], check=True,
                   timeout=120)
    rep = cc.check_drawing("shaper-cam", tmp_path / "cam.svg", mu_l=0.0005)
    assert rep.ok and len(rep.items) == 22                 # no α: LibreCAD's texts come back as outlines


def test_check_class_routes_cam_drawings(tmp_path, capsys):
    inbox = tmp_path / "inbox"
    inbox.mkdir()
    (inbox / "petrov__shaper-cam.dxf").write_bytes((DRAWINGS / "shaper_cam_mistakes.dxf").read_bytes())
    (inbox / "ivanova__shaper-cam.svg").write_bytes((DRAWINGS / "shaper_cam_correct.svg").read_bytes())
    assert main(["check-class", str(inbox), "-o", str(tmp_path / "rep"), "--quiet"]) == 1
    table = (tmp_path / "rep" / "class.md").read_text(encoding="utf-8")
    assert "| ivanova | shaper-cam | 24/24 |" in table and "petrov" in table
    assert (tmp_path / "rep" / "students" / "petrov__shaper-cam.dxf-overlay.dxf").exists()
