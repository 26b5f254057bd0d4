"""Issue 31: hostile input, round two. Each reproducer of the issue is a test here: a clean refusal (exit 2,
one line on stderr naming the file, the place or the limit) or a result, never a traceback or a hang; no
temporary folder after SIGTERM; a forced set equals a fresh one; no input overwritten; CSV cells that cannot
become formulas."""

from __future__ import annotations

import json
import math
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import textwrap

import numpy as np
import pytest

from graphmethods import cli
from graphmethods.errors import GraphmethodsError, InputError

ROOT = pathlib.Path(__file__).resolve().parents[1]
DATA = ROOT / "graphmethods" / "problems" / "data"
DRAWINGS = DATA / "drawings"
PRESS = json.loads((DATA / "slider_crank_press.json").read_text(encoding="utf-8"))


def run(capsys, *argv) -> tuple[int, str, str]:
    try:
        code = cli.main([str(a) for a in argv])
    except SystemExit as exc:
        code = exc.code
    out, err = capsys.readouterr()
    assert "Traceback" not in err, err
    return code, out, err


def refused(capsys, *argv, says: str) -> str:
    code, out, err = run(capsys, *argv)
    assert code == 2 and err.count("\n") == 1 and err.startswith("graphmethods"), (code, out, err)
    assert says in err, err
    return err


# ----------------------------------------------------------------------------- bounded reads

def test_a_device_or_a_fifo_is_refused_before_it_is_read(capsys, tmp_path):
    refused(capsys, "check", "W1", "/dev/zero", says="not a regular file")
    for name, argv in (("a.toml", ["check", "W1"]), ("a.dxf", ["check", "W1"]), ("m.csv", None)):
        fifo = tmp_path / name
        os.mkfifo(fifo)
        if argv is None:
            refused(capsys, "flywheel", "--M-r", fifo, "--n", "100", "--delta", "0.05", says="not a regular file")
        else:
            refused(capsys, *argv, fifo, says="not a regular file")


def test_an_input_larger_than_the_cap_is_refused_by_its_size(tmp_path, monkeypatch):
    from graphmethods import units

    p = tmp_path / "a.toml"
    p.write_text("x" * 100, encoding="utf-8")
    monkeypatch.setattr(units, "MAX_INPUT_BYTES", 50)
    with pytest.raises(InputError, match="MAX_INPUT_BYTES"):
        units.read_text(p)


def test_a_csv_with_a_byte_order_mark_reads_as_excel_writes_it(capsys, tmp_path):
    p = tmp_path / "m.csv"
    p.write_bytes("\ufeffphi_deg,M\n0,10\n180,20\n360,10\n".encode())
    code, out, _ = run(capsys, "flywheel", "--M-r", p, "--omega", "10", "--J", "0.8")
    assert code == 0 and "δ" in out


# ----------------------------------------------------------------------------- bounded work

def _nested_blocks(path: pathlib.Path, levels: int, copies: int) -> None:
    import ezdxf

    doc = ezdxf.new()
    for lvl in range(levels, 0, -1):
        b = doc.blocks.new(f"B{lvl}")
        if lvl == levels:
            b.add_line((0, 0), (1, 1))
        else:
            for i in range(copies):
                b.add_blockref(f"B{lvl + 1}", (i, 0))
    for i in range(copies):
        doc.modelspace().add_blockref("B1", (i, 0))
    doc.saveas(str(path))


def test_dxf_blocks_are_counted_in_copies_not_only_in_depth(capsys, tmp_path):
    p = tmp_path / "nested.dxf"
    _nested_blocks(p, 6, 10)              # 10⁶ lines from 27 KB, within the depth limit
    assert p.stat().st_size < 40_000
    refused(capsys, "check", "W1", p, says="MAX_DXF_ENTITIES")
    q = tmp_path / "deep.dxf"
    _nested_blocks(q, 10, 2)
    refused(capsys, "check", "W1", q, says="MAX_DXF_DEPTH")


def test_a_formula_that_oscillates_too_fast_is_refused_by_its_limit(capsys):
    refused(capsys, "flywheel", "--M-r", "100+sin(1e15*phi)", "--n", "100", "--delta", "0.05",
            says="MAX_QUADRATURE_INTERVALS")


def _chain(n: int) -> dict:
    fixed = {"O1": [0.0, 0.0]}
    groups, prev = [], "A"
    for k in range(n):
        fixed[f"F{k}"] = [0.3 * (k + 1), 0.0]
        groups.append({"type": "RRR", "links": [2 * k + 2, 2 * k + 3], "P": prev, "Q": f"F{k}", "C": f"B{k}",
                       "l_PC": 0.3, "l_QC": 0.06, "branch": 1})
        prev = f"B{k}"
    return {"kind": "linkage", "fixed": fixed, "crank": {"centre": "O1", "pin": "A", "r": 0.02}, "sense": "ccw",
            "groups": groups, "n_rpm": 60}


def test_groups_per_linkage_are_capped_and_checked_in_linear_time(capsys, tmp_path):
    from graphmethods.kinematics.linkage import MAX_GROUPS
    from graphmethods.kinematics.linkage_file import build_linkage

    p = tmp_path / "chain.json"
    p.write_text(json.dumps(_chain(150)), encoding="utf-8")
    refused(capsys, "kinematics", p, "--positions", "4", says="MAX_GROUPS")
    lk = build_linkage(_chain(40), source="chain")           # under the cap: the full-turn check is one pass
    lk.check_full_turn()
    assert MAX_GROUPS < 150


# ----------------------------------------------------------------------------- tracebacks on ordinary input

def test_a_disc_flywheel_alone_is_drawn(capsys, tmp_path):
    code, out, err = run(capsys, "flywheel", "--areas=-50,550,-100,125,-500,25,-50", "--n", "600", "--delta",
                         "1/300", "--disc", "0.75", "--figure", tmp_path / "disc.svg")
    assert code == 0 and (tmp_path / "disc.svg").stat().st_size > 1000


def test_masses_on_the_crank_only_give_a_sheet(capsys, tmp_path):
    case = {k: v for k, v in PRESS.items() if k not in ("about",)}
    case.update(m2=0.0, m3=0.0, J_S2=0.0)
    p = tmp_path / "crank_only.json"
    p.write_text(json.dumps(case), encoding="utf-8")
    code, out, err = run(capsys, "study", p, "--no-exact", "--sheet", tmp_path / "s.svg")
    assert code == 0 and (tmp_path / "s.svg").exists()


def test_all_masses_zero_are_named_as_the_users_input(capsys, tmp_path):
    case = dict(PRESS, m2=0.0, m3=0.0, J_S2=0.0, J1=0.0)
    p = tmp_path / "zero.json"
    p.write_text(json.dumps(case), encoding="utf-8")
    err = refused(capsys, "study", p, "--no-exact", says="J_e is zero")
    assert "convenient number" not in err


def test_a_tiny_load_runs_in_motion(capsys, tmp_path):
    p = tmp_path / "tiny.json"
    p.write_text(json.dumps(dict(PRESS, F0=1e-90)), encoding="utf-8")
    code, out, err = run(capsys, "motion", p, "--turns", "1")
    assert code == 0 and "RuntimeWarning" not in err


@pytest.mark.parametrize("where", ["link", "masses"])
def test_a_superscript_two_is_no_link_number(capsys, tmp_path, where):
    data = json.loads((DATA / "six_bar_press.json").read_text(encoding="utf-8"))
    if where == "link":
        data["groups"][0]["links"] = ["²", 3]
    else:
        data["masses"]["²"] = data["masses"].pop("2")
    p = tmp_path / "case.json"
    p.write_text(json.dumps(data, ensure_ascii=False), encoding="utf-8")
    code, out, err = run(capsys, "kinematics", p, "--positions", "4")
    assert code == 2 and err.count("\n") == 1


# ----------------------------------------------------------------------------- malformed files

SVG_HEAD = '<svg xmlns="http://www.w3.org/2000/svg" width="210mm" height="297mm" viewBox="0 0 210 297">'


@pytest.mark.parametrize("body, says", [
    ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 0 0"><line x1="0" y1="0" x2="1" y2="1"/></svg>', "viewBox"),
    (SVG_HEAD + '<line x1="a" y1="0" x2="1" y2="1"/></svg>', "line 1, column"),
    (SVG_HEAD + '<rect x="0" y="0" width="wide" height="2"/></svg>', "not a length"),
    (SVG_HEAD + '<text x="1" y="1" font-size="big">p</text></svg>', "not a length"),
    (SVG_HEAD + "<g>" * 10_000 + "</g>" * 10_000 + "</svg>", "MAX_SVG_DEPTH"),
    ('<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;">]>'
     + SVG_HEAD + "<text>&b;</text></svg>", "ENTITY"),
    ('<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY x SYSTEM "file:///etc/passwd">]>' + SVG_HEAD
     + "<text>&x;</text></svg>", "ENTITY"),
    (SVG_HEAD + "<line", "not a readable SVG drawing"),
])
def test_a_malformed_svg_drawing_is_refused_naming_the_file_and_place(capsys, tmp_path, body, says):
    p = tmp_path / "bad.svg"
    p.write_text(body, encoding="utf-8")
    err = refused(capsys, "check", "W1", p, says=says)
    assert "bad.svg" in err


def test_use_copies_are_counted(capsys, tmp_path):
    s = ('<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink"><defs>'
         '<g id="g0"><line x1="0" y1="0" x2="1" y2="1"/></g>')
    for i in range(1, 7):
        s += f'<g id="g{i}">' + "".join(f'<use xlink:href="#g{i - 1}"/>' for _ in range(10)) + "</g>"
    p = tmp_path / "uses.svg"
    p.write_text(s + '</defs><use xlink:href="#g6"/></svg>', encoding="utf-8")
    refused(capsys, "check", "W1", p, says="MAX_SVG_ELEMENTS")


def test_deeply_nested_toml_answers_are_refused(capsys, tmp_path):
    p = tmp_path / "deep.toml"
    p.write_text("a = " + "[" * 3000 + "]" * 3000 + "\n", encoding="utf-8")
    refused(capsys, "check", "W1", p, says="MAX_TOML_DEPTH")


def test_a_dxf_parse_error_is_one_line(capsys, tmp_path):
    p = tmp_path / "cut.dxf"
    p.write_bytes((DRAWINGS / "w1_mistakes.dxf").read_bytes()[:3000])
    refused(capsys, "check", "W1", p, says="cut.dxf")


def test_a_class_with_bad_drawings_still_gets_its_report(capsys, tmp_path):
    klass = tmp_path / "class"
    klass.mkdir()
    shutil.copy(DRAWINGS / "w1_correct.svg", klass / "ann.svg")
    (klass / "bob.svg").write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 0 0"/>', encoding="utf-8")
    (klass / "carl.svg").write_text(SVG_HEAD + "<g>" * 10_000 + "</g>" * 10_000 + "</svg>", encoding="utf-8")
    (klass / "dan.toml").write_text("a = " + "[" * 3000 + "]" * 3000, encoding="utf-8")
    code, out, err = run(capsys, "check-class", klass, "--problem", "W1", "--out", tmp_path / "rep", "--no-overlays")
    assert code == 3
    table = (tmp_path / "rep" / "class.csv").read_text(encoding="utf-8-sig")
    for name in ("ann.svg", "bob.svg", "carl.svg", "dan.toml"):
        assert name in table


def test_a_name_that_is_not_utf8_is_refused(capsys, tmp_path):
    name = os.fsdecode(b"\xff")
    refused(capsys, "drive", "--J", "0.08,0.5,12", "--u", "6,2,1", "--c", "2000,40000", "--c-u", "6,1", "--names",
            f"{name},b,c", "--figure", tmp_path / "f.svg", says="not UTF-8")
    assert not (tmp_path / "f.svg").exists()


# ----------------------------------------------------------------------------- files and faults

SIGTERM_SCRIPT = textwrap.dedent("""
    import os, signal, sys
    from graphmethods.render.files import write_set

    class Files(dict):
        def items(self):
            for k, (name, data) in enumerate(super().items()):
                if k == 2:
                    os.kill(os.getpid(), signal.SIGTERM)      # while the set is staged
                yield name, data

    write_set(sys.argv[1], Files({f"f{i}.svg": b"x" for i in range(6)}), overwrite=True)
""")


@pytest.mark.parametrize("existing", [False, True])
def test_sigterm_during_a_set_write_leaves_no_staging_folder(tmp_path, existing):
    out = tmp_path / "set"
    if existing:
        out.mkdir()
        (out / "f0.svg").write_bytes(b"old")
    proc = subprocess.run([sys.executable, "-c", SIGTERM_SCRIPT, str(out)], capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=str(ROOT)), timeout=60)
    assert proc.returncode == 128 + signal.SIGTERM and "Traceback" not in proc.stderr, proc.stderr
    left = sorted(p.name for p in tmp_path.rglob("*"))
    assert not [n for n in left if n.endswith(".tmp")], left
    assert left == (["f0.svg", "set"] if existing else [])


def test_a_set_is_staged_inside_an_existing_folder(tmp_path, monkeypatch):
    """The root of a mounted file system: its parent lies on another device, so nothing is staged there."""
    from graphmethods.render import files

    out = tmp_path / "usb"
    out.mkdir()
    seen = []
    real_mkdir = pathlib.Path.mkdir

    def mkdir(self, *a, **k):
        seen.append(self)
        return real_mkdir(self, *a, **k)

    monkeypatch.setattr(pathlib.Path, "mkdir", mkdir)
    files.write_set(out, {"a.pdf": b"1"}, overwrite=True)
    assert seen and all(p.parent == out for p in seen if p.name.endswith(".tmp")), seen
    assert sorted(p.name for p in out.iterdir()) == ["a.pdf"]


def test_forced_steps_frames_replace_a_longer_build_whole(capsys, tmp_path):
    out = tmp_path / "frames.svg"
    code, *_ = run(capsys, "steps", "W1", "energy-indicator", "--format", "svg", "--out", out)
    first = sorted(p.name for p in tmp_path.iterdir())
    (tmp_path / "notes.txt").write_text("mine", encoding="utf-8")
    code2, *_ = run(capsys, "steps", "press", "velocity-plan", "--format", "svg", "--out", out, "--force")
    fresh = tmp_path / "fresh"
    fresh.mkdir()
    code3, *_ = run(capsys, "steps", "press", "velocity-plan", "--format", "svg", "--out", fresh / "frames.svg")
    assert code == code2 == code3 == 0
    forced = sorted(p.name for p in tmp_path.iterdir() if p.name.endswith(".svg"))
    assert forced == sorted(p.name for p in fresh.iterdir()) and len(first) != len(forced)
    assert (tmp_path / "notes.txt").exists()


def test_forced_class_report_drops_students_no_longer_there(capsys, tmp_path):
    klass = tmp_path / "class"
    klass.mkdir()
    for name in ("w1_correct.toml", "w1_mistakes.toml"):
        shutil.copy(DATA / "answers" / name, klass / name)
    rep = tmp_path / "rep"
    run(capsys, "check-class", klass, "--out", rep)
    (klass / "w1_mistakes.toml").unlink()
    run(capsys, "check-class", klass, "--out", rep, "--force")
    assert sorted(p.name for p in (rep / "students").iterdir()) == ["w1_correct.toml-overlay.svg",
                                                                     "w1_correct.toml.md"]


def test_an_overlay_never_overwrites_the_students_drawing(capsys, tmp_path):
    p = tmp_path / "in.svg"
    shutil.copy(DRAWINGS / "w1_mistakes.svg", p)
    before = p.read_bytes()
    refused(capsys, "check", "W1", p, "--overlay", p, "--force", says="is an input")
    link = tmp_path / "link.svg"
    link.symlink_to(p)
    refused(capsys, "check", "W1", p, "--overlay", link, "--force", says="is an input")
    assert p.read_bytes() == before


def test_gallery_regenerate_is_refused_outside_a_source_checkout(capsys, tmp_path, monkeypatch):
    (tmp_path / "gallery").mkdir()
    mine = tmp_path / "gallery" / "w1_energy_indicator_en.svg"
    mine.write_text("mine", encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    refused(capsys, "gallery", "--regenerate", says="source checkout")
    assert mine.read_text(encoding="utf-8") == "mine"


def test_class_csv_cells_never_become_formulas_and_open_in_excel(capsys, tmp_path):
    klass = tmp_path / "class"
    klass.mkdir()
    text = (DATA / "answers" / "w1_correct.toml").read_text(encoding="utf-8")
    text = "\n".join(line for line in text.splitlines() if not line.startswith("student"))
    (klass / "=HYPERLINK(1)__W1.toml").write_text('student = "@SUM(A1)"\n' + text, encoding="utf-8")
    (klass / "Иванова__W1.toml").write_text(text, encoding="utf-8")
    run(capsys, "check-class", klass, "--out", tmp_path / "rep", "--lang", "ru", "--no-overlays")
    for name, sep in (("class.csv", ","), ("class-semicolon.csv", ";")):
        raw = (tmp_path / "rep" / name).read_bytes()
        assert raw.startswith(b"\xef\xbb\xbf")                        # Excel reads UTF-8 by its BOM
        import csv
        import io

        rows = list(csv.reader(io.StringIO(raw.decode("utf-8-sig")), delimiter=sep))
        assert rows[0][0] == "файл" and len({len(r) for r in rows}) == 1
        cells = [c for r in rows for c in r]
        assert "Иванова" in cells and all(not c.startswith(("=", "+", "@")) for c in cells), cells
        assert "'@SUM(A1)" in cells


# ----------------------------------------------------------------------------- numbers at the API

def test_numbers_at_the_api_follow_the_policy():
    from graphmethods.dynamics.multimass import Mass, Shaft, reduce_chain
    from graphmethods.kinematics.presets import six_bar_press
    from graphmethods.sheets.check import validate_answers

    lk = six_bar_press()
    for bad in (1e300, 10**400, math.nan):
        with pytest.raises(InputError):
            lk.motion(m=12, omega_1=bad)
    with pytest.raises(InputError, match="above the limit"):
        lk.motion(m=np.int64(2**62), omega_1=1.0)
    assert np.isfinite(lk.motion(m=12, omega_1=1e100).a("D")).all()
    mech_case = __import__("graphmethods.kinematics", fromlist=["case_from_dict"]).case_from_dict(PRESS)
    with pytest.raises(InputError):
        mech_case.mechanism.velocity_plans(mech_case.mechanism.positions(m=8), omega_1=10**400)
    with pytest.raises(GraphmethodsError):
        reduce_chain([Mass("a", 1.0, 1.0, 0.0), Mass("b", 1.0, 1.0, 0.0)], [Shaft("s", 1e-300, 1.0)])
    a = validate_answers({"results": {"J_F": np.float64(1.5), "works_J": np.array([1.0, 2.0])}})
    assert a["results"] == {"J_F": 1.5, "works_J": (1.0, 2.0)}
