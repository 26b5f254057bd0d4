"""Issue 14: every bad input gets a clear answer, every fault leaves the files whole.

One named test per reported defect. The command line is called in-process
(graphmethods.cli.main); a clean refusal is exit 2 with one line on stderr and nothing on stdout.
"""

from __future__ import annotations

import errno
import json
import math
import os
import pathlib
import re
import time

import pytest

from graphmethods import cli
from graphmethods.dynamics import excess_work as ew
from graphmethods.dynamics.flywheel import check_delta, fluctuation, flywheel, mean_speed
from graphmethods.errors import GraphmethodsError, InputError, OutputError
from graphmethods.kinematics import case_from_dict
from graphmethods.render.files import write_atomic, write_set
from graphmethods.units import MAX_POSITIONS, MAX_VARIANTS, angle_deg, json_text, real

DATA = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data"
PRESS = json.loads((DATA / "slider_crank_press.json").read_text(encoding="utf-8"))
FOUR = json.loads((DATA / "four_bar_rocker.json").read_text(encoding="utf-8"))
SLOT = json.loads((DATA / "slotted_lever.json").read_text(encoding="utf-8"))
W1_ANSWERS = '[energy_indicator]\nmu_E = 5.0\narrows_mm = [10.0, -110.0, 20.0, -25.0, 100.0, -5.0, 10.0]\n'
NONFINITE = re.compile(r"\b(inf|nan|Infinity|NaN)\b")


def run(capsys, *argv):
    code = cli.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def refused(capsys, *argv, says=""):
    code, out, err = run(capsys, *argv)
    assert code == 2, (code, out, err)
    assert err.count("\n") == 1 and "Traceback" not in err and err.startswith("graphmethods"), err
    assert says in err, err
    return err


def case_file(tmp_path, base=PRESS, name="case.json", **changes):
    d = dict(base)
    d.update(changes)
    p = tmp_path / name
    p.write_text(json.dumps(d), encoding="utf-8")
    return p


def answers(tmp_path, text, name="answers.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


# ----------------------------------------------------------------------------- check: the students' entries

def test_check_omega_m_zero_is_judged_not_a_crash(tmp_path, capsys):
    typed = W1_ANSWERS + "[results]\nomega_m = 0\nomega_max = 63\nJ_F = 40\n"
    code, out, err = run(capsys, "check", "W1", answers(tmp_path, typed))
    assert code == 1 and err == ""                      # judged: wrong
    assert re.search(r"ω_m\s+62\.83\s+0\s.*wrong", out)


def test_check_accepts_a_list_of_positions_as_study_prints_it(tmp_path, capsys):
    text = (DATA / "answers" / "press_wittenbauer_correct.toml").read_text(encoding="utf-8")
    good = re.search(r"(?m)^omega_max_at\s*=\s*(\d+)", text).group(1)
    listed = re.sub(r"(?m)^omega_max_at\s*=.*$", f"omega_max_at = [{good}]", text)
    code, out, _ = run(capsys, "check", "press", answers(tmp_path, listed))
    assert code == 0 and "position of ω_max" in out
    wrong = re.sub(r"(?m)^omega_max_at\s*=.*$", f"omega_max_at = [{good}, 6]", text)
    code, out, _ = run(capsys, "check", "press", answers(tmp_path, wrong, "b.toml"))
    assert code == 1 and re.search(r"position of ω_max.*wrong", out)


@pytest.mark.parametrize("entry, says", [
    ('positions = "12.5"', "must be a number"),
    ("positions = 12.7", "an integer ≥ 3"),
])
def test_check_positions_must_be_a_whole_number(tmp_path, capsys, entry, says):
    text = (DATA / "answers" / "press_wittenbauer_correct.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^positions\s*=.*$", entry, text)
    refused(capsys, "check", "press", answers(tmp_path, text), says=says)


def test_check_nested_arrows_refused(tmp_path, capsys):
    refused(capsys, "check", "W1", answers(tmp_path, "[energy_indicator]\nmu_E = 5.0\narrows_mm = [[10.0], -110.0]\n"),
            says="arrows_mm[0] must be a number")


@pytest.mark.parametrize("step, says", [('"abc"', "must be a number"), ("0", "must be positive"),
                                        ("-5", "must be positive")])
def test_check_step_mm_refused_before_the_overlay(tmp_path, capsys, step, says):
    refused(capsys, "check", "W1", answers(tmp_path, W1_ANSWERS + f"step_mm = {step}\n"), "--overlay",
            tmp_path / "o.svg", says=says)
    assert not (tmp_path / "o.svg").exists()


def test_check_tiny_scale_refused_not_expected_inf(tmp_path, capsys):
    refused(capsys, "check", "W1", answers(tmp_path, W1_ANSWERS.replace("5.0", "1e-320")), says="mu_E")


def test_check_huge_variant_number_refused_at_once(tmp_path, capsys):
    t0 = time.perf_counter()
    refused(capsys, "check", "indicator:7:99999999999999999999", answers(tmp_path, W1_ANSWERS),
            says=f"above the limit {MAX_VARIANTS}")
    assert time.perf_counter() - t0 < 2


# ----------------------------------------------------------------------------- silent infinities

@pytest.mark.parametrize("argv, says", [
    (["--delta", "1e-320"], "--delta"),
    (["--J", "1e-320"], "--J"),
    (["--J", "1e-10", "--json"], "too small for steady running"),
])
def test_flywheel_no_silent_infinity(capsys, argv, says):
    refused(capsys, "flywheel", "--areas", "50", "-50", "--n", "600", *argv, says=says)


def test_flywheel_huge_omega_refused(capsys):
    refused(capsys, "flywheel", "--areas", "50", "-50", "--omega", "1e308", "--delta", "0.1", says="--omega")


def test_study_tiny_delta_refused(tmp_path, capsys):
    refused(capsys, "study", case_file(tmp_path, delta=1e-320), says="'delta'")


def test_slotted_lever_huge_length_refused(tmp_path, capsys):
    refused(capsys, "kinematics", case_file(tmp_path, SLOT, l_O3B=1e308), says="'l_O3B'")


def test_api_from_work_huge_refused_and_flywheel_huge_speed():
    with pytest.raises(InputError):
        ew.from_work([1e308, 1e308, -1e308, -1e308])
    with pytest.raises(InputError):
        flywheel(575.0, delta=0.05, n_rpm=1e308)
    # inside the range the answer is finite and right (independent formula, domain.md §6)
    fw = flywheel(575.0, delta=0.05, n_rpm=1e40)
    assert fw.J_F == pytest.approx(900 * 575 / (math.pi ** 2 * 1e80 * 0.05), rel=1e-12) and fw.J_F > 0


# ----------------------------------------------------------------------------- extreme magnitudes

def test_flywheel_tiny_speed_refused(capsys):
    refused(capsys, "flywheel", "--areas", "50", "-50", "--n", "1e-200", "--delta", "0.1", says="--n")


@pytest.mark.parametrize("changes, says", [
    ({"n_rpm": 1e200}, "'n_rpm'"), ({"l": 1e308}, "'l'"), ({"n_rpm": 10 ** 400}, "'n_rpm'"),
    ({"kind": ["four_bar"]}, "unknown kind"), ({"name": "\ud800"}, "surrogate"), ({"delta": True}, "'delta'"),
])
def test_problem_file_extremes_refused(tmp_path, capsys, changes, says):
    p = tmp_path / "case.json"
    d = dict(PRESS)
    d.update(changes)
    p.write_text(json.dumps(d), encoding="utf-8")          # json writes \ud800 as an escape, as a user would
    refused(capsys, "study", p, says=says)
    refused(capsys, "kinematics", p, says=says)


def test_deep_json_refused(tmp_path, capsys):
    p = tmp_path / "deep.json"
    p.write_text("[" * 100_000 + "]" * 100_000, encoding="utf-8")
    refused(capsys, "study", p, says="nested")


def test_huge_integer_in_toml_and_fraction(tmp_path, capsys):
    refused(capsys, "check", "W1", answers(tmp_path, W1_ANSWERS.replace("5.0", "1" + "0" * 400)), says="mu_E")
    refused(capsys, "flywheel", "--areas", "50", "-50", "--n", "600", "--delta", "1/" + "1" * 400, says="--delta")


def test_ground_angle_reduced_mod_360(tmp_path, capsys):
    # 1e20 = 2^20·5^20 is 10^20 exactly; 10^20 mod 360 = 280 (integer arithmetic, independent of the code)
    assert 10 ** 20 % 360 == 280
    code, out_big, _ = run(capsys, "kinematics", case_file(tmp_path, FOUR, ground_angle_deg=1e20), "--json")
    assert code == 0
    code, out_0, _ = run(capsys, "kinematics", case_file(tmp_path, FOUR, "b.json", ground_angle_deg=280), "--json")
    big, zero = json.loads(out_big), json.loads(out_0)
    assert [r["v_B"] for r in big["positions"]] == [r["v_B"] for r in zero["positions"]]
    assert angle_deg(1e15 + 90, "a") == math.fmod(1e15 + 90, 360.0)
    assert angle_deg(10 ** 30 + 45, "a") == (10 ** 30 + 45) % 360


def test_non_utf8_terminal(tmp_path):
    import subprocess
    import sys

    env = dict(os.environ, PYTHONIOENCODING="cp1252")
    r = subprocess.run([sys.executable, "-m", "graphmethods", "flywheel", "--areas", "50", "-50", "--n", "600",
                        "--delta", "0.1"], capture_output=True, env=env, cwd=tmp_path)
    assert r.returncode == 0 and b"Traceback" not in r.stderr and b"J_F = 0.1267" in r.stdout


@pytest.mark.parametrize("m", ["99999999999999999999", "100000000"])
def test_huge_positions_refused_before_work(capsys, m):
    t0 = time.perf_counter()
    refused(capsys, "kinematics", DATA / "slider_crank_press.json", "--positions", m, says=f"limit {MAX_POSITIONS}")
    refused(capsys, "study", DATA / "slider_crank_press.json", "--positions", m, says=f"limit {MAX_POSITIONS}")
    assert time.perf_counter() - t0 < 2


# ----------------------------------------------------------------------------- hangs

def test_text_table_is_linear():
    def t(n):
        c = ew.from_work([5.0, -5.0] * (n // 2))
        t0 = time.perf_counter()
        c.to_text()
        return time.perf_counter() - t0
    small, big = t(10_000), t(40_000)
    assert big < 12 * small + 0.05          # quadratic would be 16 times


def test_worksheet_huge_variants_refused_at_once(tmp_path, capsys):
    t0 = time.perf_counter()
    refused(capsys, "worksheet", "indicator", "--variants", "99999999999999999999", "--out", tmp_path / "w",
            says=f"limit {MAX_VARIANTS}")
    assert time.perf_counter() - t0 < 2 and not (tmp_path / "w").exists()


# ----------------------------------------------------------------------------- inconsistent checks

def test_one_delta_rule_for_cli_files_and_api(tmp_path, capsys):
    refused(capsys, "flywheel", "--areas", "50", "-50", "--n", "600", "--delta", "1.5", says="between 0 and 1")
    refused(capsys, "study", case_file(tmp_path, delta=1.5), says="between 0 and 1")
    with pytest.raises(InputError):
        check_delta(1.5)
    with pytest.raises(InputError):
        check_delta(True)


@pytest.mark.parametrize("argv, says", [
    (["--J", "0.00001"], "too small for steady running"),     # δ = 145.6 before
    (["--J", "1", "--J-e", "10"], "cannot be less than"),     # J_F = -9 before
    (["--J", "1", "--J-e", "-10"], "must not be negative"),
])
def test_flywheel_J_refuses_what_delta_refuses(capsys, argv, says):
    refused(capsys, "flywheel", "--areas", "50", "-50", "--n", "600", *argv, says=says)


def test_study_no_flywheel_needed_is_an_answer(tmp_path, capsys):
    p = case_file(tmp_path, F0=0, m2=0, J_S2=0, m3=0)       # no load, constant J_e: the speed never varies
    code, out, err = run(capsys, "study", p, "--json")
    res = json.loads(out)
    assert code == 0 and res["flywheel_needed"] is False and res["J_F_wittenbauer"] == 0.0
    assert res["delta_W_max"] == 0.0 and "no flywheel is needed" in res["note"]


def test_study_sheet_without_load(tmp_path, capsys):
    code, out, err = run(capsys, "study", case_file(tmp_path, F0=0), "--sheet", tmp_path / "s.svg", "--no-exact")
    assert code == 0 and (tmp_path / "s.svg").stat().st_size > 1000


def test_four_bar_change_point_message_is_filled_in():
    d = dict(FOUR)
    d.update(l1=0.4, l2=0.1, l3=0.35, l4=0.15)             # s + l = p + q: a change-point linkage
    try:
        case_from_dict(d)
    except InputError as exc:
        msg = str(exc)
        assert "fails for ." not in msg and "for ;" not in msg
        assert re.search(r"assembly fails for \S", msg) and "0.35" in msg
    else:                                                   # it may assemble; then it must run
        pass


def test_kinematics_figures_limit_names_a_real_option(tmp_path, capsys):
    err = refused(capsys, "kinematics", DATA / "slider_crank_press.json", "--positions", "36", "--figures",
                  tmp_path / "f")
    assert "--positions 30 or fewer" in err and "page" not in err.split("(")[0]
    code, _, _ = run(capsys, "kinematics", DATA / "slider_crank_press.json", "--positions", "30", "--figures",
                     tmp_path / "g")
    assert code == 0 and len(list((tmp_path / "g").iterdir())) == 8


def test_empty_output_names_refused(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    refused(capsys, "worksheet", "indicator", "--out", "", "--quiet", says="--out is empty")
    refused(capsys, "study", DATA / "slider_crank_press.json", "--sheet", "", says="--sheet is empty")
    assert list(tmp_path.iterdir()) == []


def test_worksheet_out_creates_missing_parents(tmp_path, capsys):
    code, out, err = run(capsys, "worksheet", "indicator", "--out", tmp_path / "a" / "b" / "c", "--quiet")
    assert code == 0 and (tmp_path / "a" / "b" / "c" / "indicator-en.pdf").exists()
    assert sorted(p.name for p in (tmp_path / "a" / "b").iterdir()) == ["c"]       # no temporary folder left


# ----------------------------------------------------------------------------- the API

@pytest.mark.parametrize("call", [
    lambda: flywheel(575.0, delta=True, n_rpm=600.0),
    lambda: flywheel(575.0, delta=0.05, n_rpm=True),
    lambda: flywheel(True, delta=0.05, n_rpm=600.0),
    lambda: mean_speed(n_rpm=1e-200),
    lambda: fluctuation(575.0, J=1e-320, n_rpm=600.0),
    lambda: ew.from_work([True, -1.0]),
    lambda: ew.from_work([[1.0], [-1.0]]),
    lambda: ew.from_work("12"),
    lambda: ew.from_areas([10, -10], mu_M=1e-320, mu_phi=0.1),
    lambda: ew.from_levels([0, 10 ** 400, 0]),
    lambda: case_from_dict({**PRESS, "r": None}),
    lambda: case_from_dict({**PRESS, "kind": {"a": 1}}),
    lambda: case_from_dict([1, 2]),
    lambda: real(float("nan"), "x"),
])
def test_api_raises_our_errors_only(call):
    with pytest.raises(GraphmethodsError):
        call()


def test_json_text_refuses_infinity():
    with pytest.raises(InputError, match="J_F"):
        json_text({"J_F": math.inf})
    assert json.loads(json_text({"a": [1.0, 2.0]})) == {"a": [1.0, 2.0]}


# ----------------------------------------------------------------------------- writers and OS errors

def _failing(err_no):
    def fail(*args, **kwargs):
        raise OSError(err_no, os.strerror(err_no))
    return fail


@pytest.mark.parametrize("err_no, why", [(errno.EROFS, "read-only file system"), (errno.EACCES, "permission denied"),
                                         (errno.ENOSPC, "no space left")])
def test_write_atomic_os_error_is_one_clean_error(tmp_path, monkeypatch, err_no, why):
    monkeypatch.setattr(os, "open", _failing(err_no))
    with pytest.raises(OutputError, match=why) as info:
        write_atomic(tmp_path / "a.svg", b"x")
    assert info.value.__context__ is None or not isinstance(info.value.__context__, FileNotFoundError)
    monkeypatch.undo()
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("argv", [
    ["study", DATA / "slider_crank_press.json", "--sheet", "{tmp}/s.svg", "--positions", "12", "--no-exact"],
    ["check", "W1", "{answers}", "--overlay", "{tmp}/o.svg"],
])
def test_single_file_writers_read_only(tmp_path, capsys, monkeypatch, argv):
    a = answers(tmp_path, W1_ANSWERS)
    argv = [str(x).replace("{tmp}", str(tmp_path / "out")).replace("{answers}", str(a)) for x in argv]
    (tmp_path / "out").mkdir()
    monkeypatch.setattr(os, "open", _failing(errno.EROFS))
    refused(capsys, *argv, says="read-only file system")
    assert list((tmp_path / "out").iterdir()) == []


@pytest.mark.parametrize("argv", [
    ["worksheet", "indicator", "--out", "{out}", "--quiet"],
    ["kinematics", DATA / "slider_crank_press.json", "--figures", "{out}"],
])
def test_set_writers_full_disk(tmp_path, capsys, monkeypatch, argv):
    import builtins

    real_open = builtins.open

    def full(file, mode="r", *a, **k):
        if "x" in mode or ("w" in mode and "b" in mode):
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return real_open(file, mode, *a, **k)

    monkeypatch.setattr(builtins, "open", full)
    argv = [str(x).replace("{out}", str(tmp_path / "set")) for x in argv]
    refused(capsys, *argv, says="no space left")
    assert list(tmp_path.iterdir()) == []                   # no set, no temporary folder


def test_existing_out_file_refused(tmp_path, capsys):
    f = tmp_path / "file"
    f.write_text("keep", encoding="utf-8")
    refused(capsys, "worksheet", "indicator", "--out", f, "--quiet", says="is a file")
    refused(capsys, "kinematics", DATA / "slider_crank_press.json", "--figures", f, says="is a file")
    refused(capsys, "gallery", "--out", f, says="is a file")
    refused(capsys, "bench", "--quick", "--only", "flywheel", "--out", f, says="is a file")
    assert f.read_text(encoding="utf-8") == "keep"


def test_force_replace_is_all_or_nothing(tmp_path, monkeypatch):
    """An error (or an interrupt) at any rename of the commit leaves the old set, byte for byte."""
    out = tmp_path / "set"
    old = {"a.svg": b"old a", "svg/b.svg": b"old b", "svg/c.svg": b"old c"}
    write_set(out, old)
    new = {"a.svg": b"new a", "svg/b.svg": b"new b", "svg/d.svg": b"new d"}
    real_rename = os.rename
    for fail_at in range(1, 8):
        calls = [0]

        def rename(src, dst, _n=fail_at, calls=calls):
            calls[0] += 1
            if calls[0] == _n:
                raise KeyboardInterrupt if _n % 2 else OSError(errno.EIO, "I/O error")
            return real_rename(src, dst)

        monkeypatch.setattr(os, "rename", rename)
        try:
            write_set(out, new, overwrite=True, stale=["svg/c.svg"])
        except (OutputError, KeyboardInterrupt):
            pass
        monkeypatch.setattr(os, "rename", real_rename)
        got = {str(p.relative_to(out)): p.read_bytes() for p in out.rglob("*") if p.is_file()}
        if got != old:       # the failure came after the last rename: the whole new set is in
            assert got == new, (fail_at, got)
            write_set(out, old, overwrite=True, stale=["svg/d.svg"])
        assert sorted(p.name for p in tmp_path.iterdir()) == ["set"]


def test_gallery_with_a_failing_script_writes_nothing(tmp_path, capsys):
    gal = tmp_path / "gal"
    gal.mkdir()
    (gal / "a_blank.py").write_text("from graphmethods.scene import Scene\n\ndef build():\n    return Scene()\n",
                                    encoding="utf-8")
    code, out, _ = run(capsys, "gallery", "--dir", gal, "--out", tmp_path / "ok")
    assert code == 0 and (tmp_path / "ok" / "a_blank.svg").exists()       # the good script alone is written
    (gal / "zz_broken.py").write_text("def build():\n    return 1 / 0\n", encoding="utf-8")
    refused(capsys, "gallery", "--dir", gal, "--out", tmp_path / "out", says="nothing was written")
    assert not (tmp_path / "out").exists()
    (gal / "zz_broken.py").write_text("def build(:\n", encoding="utf-8")
    refused(capsys, "gallery", "--dir", gal, "--out", tmp_path / "out", says="does not load")
    assert not (tmp_path / "out").exists()


def test_bench_out_checked_before_the_run(tmp_path, capsys):
    (tmp_path / "bench.md").write_text("old", encoding="utf-8")
    t0 = time.perf_counter()
    refused(capsys, "bench", "--quick", "--only", "flywheel", "--out", tmp_path, says="--force")
    assert time.perf_counter() - t0 < 2


def test_worksheet_force_replaces_the_whole_set_and_keeps_other_files(tmp_path, capsys):
    out = tmp_path / "class"
    assert run(capsys, "worksheet", "indicator", "--variants", "3", "--out", out, "--quiet")[0] == 0
    (out / "svg" / "notes.txt").write_text("mine", encoding="utf-8")
    assert run(capsys, "worksheet", "indicator", "--variants", "1", "--out", out, "--quiet", "--force")[0] == 0
    files = sorted(str(p.relative_to(out)) for p in out.rglob("*") if p.is_file())
    # no variant 2 or 3 left over
    assert files == ["indicator-answers.toml", "indicator-en.pdf", "problems/indicator-01.json",
                     "svg/indicator-01-key.svg", "svg/indicator-01-student.svg", "svg/notes.txt"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["class"]
