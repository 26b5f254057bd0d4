"""One grammar of options (issue 28): no prefix matching, --position the position number, -o/--out and
- for standard output, the number policy on every numeric option, ASCII-safe JSON, problem files from
standard input and from `problems NAME --file`, every answer printed, help from the registry."""

import argparse
import json
import math
import os
import pathlib
import re
import shlex
import subprocess
import sys

import pytest

from graphmethods.cli import COMMANDS, build_parser, main
from graphmethods.problems import builtin

REPO = pathlib.Path(__file__).resolve().parents[1]


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def gm(*argv, stdin: bytes | None = None, env: dict | None = None) -> subprocess.CompletedProcess:
    """The command line in a real process (stdout as bytes: a drawing may go there)."""
    e = {**os.environ, "PYTHONPATH": str(REPO), **(env or {})}
    return subprocess.run([sys.executable, "-m", "graphmethods", *argv], input=stdin, capture_output=True, env=e,
                          timeout=300)


def _subparsers(parser: argparse.ArgumentParser):
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            yield from action.choices.items()


# ------------------------------------------------------------------ no prefix matching, --position


def test_no_parser_matches_an_option_by_a_prefix():
    parser = build_parser()
    assert parser.allow_abbrev is False
    names = dict(_subparsers(parser))
    assert set(names) == set(COMMANDS)
    assert all(p.allow_abbrev is False for p in names.values())


def test_the_prefix_trap_position_3_is_one_position_not_three(capsys):
    code, out, _ = run(capsys, "kinematics", "press", "--position", "3", "--json")
    assert code == 0
    rows = json.loads(out)["positions"]
    assert len(rows) == 1 and rows[0]["position"] == 3
    assert rows[0]["phi_from_start_deg"] == pytest.approx(90.0)
    with pytest.raises(SystemExit) as exc:                  # a prefix is refused, not guessed
        main(["kinematics", "press", "--positio", "3"])
    assert exc.value.code == 2


def test_position_out_of_range_and_with_phi_deg_is_refused(capsys):
    assert main(["kinematics", "press", "--position", "13"]) == 2
    assert "0 to 12" in capsys.readouterr().err
    assert main(["kinematics", "press", "--position", "3", "--phi-deg", "30"]) == 2


# ------------------------------------------------------------------ - is standard output, and nothing else


@pytest.mark.parametrize("argv, head", [
    (["kinematics", "press", "--sheet", "-", "--format", "svg"], b"<?xml"),
    (["forces", "press", "--position", "3", "-o", "-", "--format", "pdf"], b"%PDF-"),
    (["drive", "--J", "0.08,0.5,12", "--u", "6,2,1", "--c", "2000,40000", "--c-u", "6,1", "-o", "-", "--format",
      "dxf"], b"  0\nSECTION"),
])
def test_a_sheet_on_standard_output_is_the_drawing_alone(argv, head):
    r = gm(*argv)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith(head)
    if head == b"<?xml":
        assert r.stdout.rstrip().endswith(b"</svg>")
    if head == b"%PDF-":
        assert r.stdout.rstrip().endswith(b"%%EOF")
    assert b"wrote" not in r.stdout


def test_standard_output_needs_a_format_and_takes_one_output(capsys):
    assert main(["kinematics", "press", "--sheet", "-"]) == 2
    assert "--format" in capsys.readouterr().err
    assert main(["forces", "press", "--position", "3", "-o", "-", "--format", "svg", "--json"]) == 2
    assert "standard output" in capsys.readouterr().err


def test_steps_to_standard_output():
    r = gm("steps", "W1", "energy-indicator", "--as", "page", "-o", "-")
    assert r.returncode == 0, r.stderr
    assert r.stdout.lstrip().lower().startswith(b"<!doctype html")
    assert b"wrote standard output" in r.stderr


# ------------------------------------------------------------------ the number policy


@pytest.mark.parametrize("argv", [
    ["kinematics", "press", "--n", "inf"], ["kinematics", "press", "--n", "1e200"],
    ["kinematics", "press", "--epsilon-1", "nan"], ["forces", "press", "--phi-deg", "1/0"],
    ["kinematics", "press", "--phi-deg", "30,,60"], ["check", "press", "x.dxf", "--mu-v", "1e-300"],
    ["steps", "W1", "energy-indicator", "--seconds", "-inf"], ["forces", "press", "--omega", "abc", "--position", "1"],
])
def test_non_finite_and_huge_numbers_are_one_line_and_exit_2(capsys, argv):
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err


def test_fractions_are_numbers(capsys):
    code, out, _ = run(capsys, "kinematics", "press", "--phi-deg", "90/2", "--epsilon-1", "1/2", "--json")
    assert code == 0
    res = json.loads(out)
    assert res["positions"][0]["phi_deg"] == pytest.approx(45.0) and res["epsilon_1"] == 0.5


def test_study_takes_the_speed_as_n_or_omega(capsys):
    _, a, _ = run(capsys, "study", "press", "--no-exact", "--n", "150", "--json")
    _, b, _ = run(capsys, "study", "press", "--no-exact", "--omega", "15.707963267948966",
                  "--json")
    ja, jb = json.loads(a), json.loads(b)
    assert ja["n_rpm"] == 150.0 and jb["n_rpm"] == pytest.approx(150.0)
    # J_F + J_e ∝ 1/ω²: half the speed, four times the total inertia
    _, c, _ = run(capsys, "study", "press", "--no-exact", "--json")
    jc = json.loads(c)
    assert ja["J_F_energy"] + ja["J_e_mean"] == pytest.approx(4 * (jc["J_F_energy"] + jc["J_e_mean"]), rel=0.02)


def test_omega_and_n_are_the_same_speed(capsys):
    _, a, _ = run(capsys, "forces", "press", "--phi-deg", "30", "--n", "300", "--json")
    _, b, _ = run(capsys, "forces", "press", "--phi-deg", "30", "--omega", "31.41592653589793", "--json")
    ja, jb = json.loads(a), json.loads(b)
    assert ja["M_balance"] == pytest.approx(jb["M_balance"], rel=1e-12)


# ------------------------------------------------------------------ JSON ASCII-safe


@pytest.mark.parametrize("argv", [["kinematics", "press", "-m", "4", "--json"],
                                  ["forces", "press", "--position", "2", "--json"],
                                  ["problems", "--json"], ["study", "press", "--no-exact", "--json"]])
def test_json_is_ascii_so_any_terminal_encoding_reads_it(argv):
    r = gm(*argv, env={"PYTHONIOENCODING": "ascii"})
    assert r.returncode == 0, r.stderr
    r.stdout.decode("ascii")
    json.loads(r.stdout)


# ------------------------------------------------------------------ every answer printed


def test_kinematics_text_has_the_accelerations_of_the_json(capsys):
    _, text, _ = run(capsys, "kinematics", "press", "-m", "4")
    _, js, _ = run(capsys, "kinematics", "press", "-m", "4", "--json")
    row = json.loads(js)["positions"][1]
    assert "a_B [m/s²]" in text and "epsilon_2 [rad/s²]" in text
    assert f"{row['a_B']:.5f}" in text and f"{row['epsilon_2']:.5f}" in text
    # the flat a_B is the slider's acceleration along its guide (+x), from the vector
    assert row["a_B"] == pytest.approx(row["points"]["B"]["a"][0])


def test_forces_text_shows_the_working_load(capsys):
    code, text, _ = run(capsys, "forces", "press", "--position", "3")
    assert code == 0
    assert "Applied loads" in text and "F_c3" in text and "5000.000" in text
    _, js, _ = run(capsys, "forces", "press", "--position", "3", "--json")
    loads = json.loads(js)["loads"]
    assert [ld["label"] for ld in loads] == ["F_c3"] and loads[0]["force"] == pytest.approx([5000.0, 0.0])
    _, text, _ = run(capsys, "forces", "press", "--position", "8")     # the return stroke: no load
    assert "no external load" in text


def test_plans_at_a_chosen_crank_angle(capsys, tmp_path):
    code, out, _ = run(capsys, "kinematics", "press", "--phi-deg", "30,120", "--figures", str(tmp_path / "f"))
    assert code == 0
    names = sorted(p.name for p in (tmp_path / "f").iterdir())
    for angle in ("30", "120"):
        assert f"press_velocity_plan_{angle}deg.svg" in names and f"press_acceleration_plan_{angle}deg.svg" in names
    svg = (tmp_path / "f" / "press_velocity_plan_30deg.svg").read_text(encoding="utf-8")
    assert "φ = 30°" in svg


def test_study_at_chosen_angles_agrees_with_the_steady_motion(capsys):
    from graphmethods.dynamics.study import Study

    code, out, _ = run(capsys, "study", "press", "--phi-deg", "30,200", "--json")
    assert code == 0
    rows = json.loads(out)["at_angles"]
    assert [r["phi_deg"] for r in rows] == [30.0, 200.0]
    st = Study(builtin.case("press"))
    m = st.exact.motion
    # ω between the steady motion's extremes, and the extremes met where the curve peaks
    for r in rows:
        assert m.omega_min - 1e-9 <= r["omega"] <= m.omega_max + 1e-9
        assert r["M_e"] == pytest.approx(r["M_d"] - r["M_r"])
        assert r["N_d"] == pytest.approx(r["M_d"] * r["omega"])
    assert rows[0]["J_F"] == pytest.approx(m.J_F)
    code, text, _ = run(capsys, "study", "press", "--no-exact", "--phi-deg", "30")
    assert "ω [rad/s]" in text and "ε [rad/s²]" in text and "N_r [W]" in text


def test_study_at_angles_omega_matches_the_periodic_motion_at_its_positions():
    from graphmethods.dynamics.study import Study

    st = Study(builtin.case("press"))
    m = st.exact.motion
    phi0_deg = float(st.positions.phi_deg[0])            # position 0's crank angle from +x
    k = 37
    angle = phi0_deg + math.degrees(float(m.phi[k] - m.phi[0]))
    row = st.at_angles([angle])[0]
    assert row["omega"] == pytest.approx(float(m.omega[k]), rel=1e-7)
    assert row["epsilon"] == pytest.approx(float(m.epsilon[k]), rel=1e-5, abs=1e-6)


# ------------------------------------------------------------------ problem files: --file, standard input


def test_problems_press_file_read_back_gives_the_same_results(capsys, tmp_path):
    code, text, _ = run(capsys, "problems", "press", "--file")
    assert code == 0
    path = tmp_path / "my_press.json"
    path.write_text(text, encoding="utf-8")
    _, a, _ = run(capsys, "study", str(path), "--json")
    _, b, _ = run(capsys, "study", "press", "--json")
    assert json.loads(a) == json.loads(b)
    r = gm("problems", "press", "--file")
    assert r.stdout == (builtin.DATA / builtin.LINKAGES["press"]).read_bytes()


def test_problem_file_on_standard_input():
    data = (builtin.DATA / builtin.LINKAGES["shaper"]).read_bytes()
    a = gm("kinematics", "-", "-m", "6", "--json", stdin=data)
    b = gm("kinematics", "shaper", "-m", "6", "--json")
    assert a.returncode == 0, a.stderr
    ja, jb = json.loads(a.stdout), json.loads(b.stdout)
    assert ja["positions"] == jb["positions"]
    e = gm("study", "-", stdin=b"")
    assert e.returncode == 2 and b"standard input is empty" in e.stderr


def test_example_files_ship_and_print(capsys):
    code, out, _ = run(capsys, "problems", "--examples")
    assert code == 0 and "w1_mistakes.toml" in out.split()
    assert main(["problems", "W1", "--file"]) == 2
    assert "cycle problem" in capsys.readouterr().err


# ------------------------------------------------------------------ help from the registry, old names


@pytest.mark.parametrize("command", ["kinematics", "motion", "forces", "study"])
def test_help_lists_every_built_in_linkage(capsys, command):
    with pytest.raises(SystemExit):
        main([command, "--help"])
    text = " ".join(capsys.readouterr().out.split())
    for name in builtin.LINKAGES:
        assert name in text, (command, name)


def test_older_option_names_still_work(capsys, tmp_path):
    answers = builtin.DATA / "answers" / "w1_mistakes.toml"
    assert main(["check", "W1", str(answers), "--format", "json"]) == 1
    assert json.loads(capsys.readouterr().out)
    assert main(["check", "W1", str(answers), "--report", "json", "--overlay", str(tmp_path / "o.svg")]) == 1
    assert (tmp_path / "o.svg").exists()
    capsys.readouterr()
    assert main(["drive", "--J", "1,2", "--c", "100", "--figure", str(tmp_path / "d.pdf")]) == 0
    assert (tmp_path / "d.pdf").read_bytes().startswith(b"%PDF")
    assert main(["forces", "press", "--position", "1", "--sheet", str(tmp_path / "f.svg")]) == 0
    assert (tmp_path / "f.svg").exists()


def test_every_figure_option_takes_every_format(capsys, tmp_path):
    area = ["--areas=-50,550,-100,125,-500,25,-50", "--n", "600"]
    assert main(["flywheel", *area, "--machine", "ac-generator", "--hyperbola", str(tmp_path / "h.png")]) == 0
    assert main(["flywheel", *area, "--machine", "ac-generator", "--hyperbola", str(tmp_path / "h.dxf")]) == 0
    assert main(["drive", "--J", "1,2", "--c", "100", "-o", str(tmp_path / "d.dxf")]) == 0
    assert main(["motion", "W4", "--turns", "1", "-o", str(tmp_path / "m"), "--format", "dxf"]) == 0
    assert sorted(p.suffix for p in (tmp_path / "m").iterdir()) == [".dxf"] * 4
    assert (tmp_path / "h.png").read_bytes().startswith(b"\x89PNG")


# ------------------------------------------------------------------ Python: save(..., overwrite=True)


def test_scene_save_overwrites_when_asked(tmp_path):
    from graphmethods.errors import OutputExistsError
    from graphmethods.scene import Page, Scene, Text

    s = Scene(Page("A4"), (Text((10, 12), "M_d", name="t"),))
    p = s.save(tmp_path / "a.svg")
    assert p.read_bytes().startswith(b"<?xml")
    with pytest.raises(OutputExistsError):
        s.save(tmp_path / "a.svg")
    s.save(tmp_path / "a.svg", overwrite=True)
    s.save(tmp_path / "a.pdf", overwrite=True)


# ------------------------------------------------------------------ progress on stderr, --quiet


def test_progress_on_a_terminal_is_one_line_rewritten_and_cleared_before_an_error(capsys, tmp_path, monkeypatch):
    import io

    from graphmethods.cli import _progress

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    term = Terminal()
    monkeypatch.setattr(sys, "stderr", term)
    folder = tmp_path / "scripts"
    folder.mkdir()
    (folder / "a_one.py").write_text("from graphmethods.scene import Page, Scene, Text\n"
                                     "def build():\n    return Scene(Page('A4'), (Text((10, 12), 'x', name='t'),))\n",
                                     encoding="utf-8")
    assert main(["gallery", "--dir", str(folder), "-o", str(tmp_path / "out")]) == 0
    shown = term.getvalue()
    assert "\rgallery [1/1] a_one" in shown and "\n" not in shown and shown.endswith("\r")   # cleared
    assert "wrote" in capsys.readouterr().out                 # the results on stdout
    term.seek(0)
    term.truncate()
    (folder / "b_broken.py").write_text("def build():\n    return 1 / 0\n", encoding="utf-8")
    assert main(["gallery", "--dir", str(folder), "-o", str(tmp_path / "out2")]) == 2
    last = term.getvalue().split("\r")[-1]
    assert last.startswith("graphmethods gallery: error: b_broken") and last.count("\n") == 1
    assert not _progress._ACTIVE
    term.seek(0)
    term.truncate()
    assert main(["gallery", "--dir", str(folder), "-o", str(tmp_path / "out3"), "--quiet"]) == 2
    assert "[1/2]" not in term.getvalue()


def test_progress_into_a_file_is_a_line_now_and_then():
    import io

    from graphmethods.cli._progress import Progress

    out = io.StringIO()
    p = Progress(label="bench ", stream=out, tty=False, every=0.0)
    p(1, 2, "flywheel")
    p(2, 2, "kinematics")
    p.done()
    assert out.getvalue() == "bench [1/2] flywheel\nbench [2/2] kinematics\n"
    quiet = io.StringIO()
    Progress(quiet=True, stream=quiet, tty=False, every=0.0)(1, 1, "x")
    assert quiet.getvalue() == ""


# ------------------------------------------------------------------ the README's commands


def _readme_commands():
    sys.path.insert(0, str(REPO / ".ci"))
    try:
        import readme_commands
    finally:
        sys.path.pop(0)
    return readme_commands.commands((REPO / "README.md").read_text(encoding="utf-8"))


def test_readme_commands_use_no_source_paths():
    cmds = _readme_commands()
    assert len(cmds) > 60
    for c in cmds:
        assert not re.search(r"graphmethods/problems/data|shared/|tests/", c.text), (c.line, c.text)


def test_every_readme_command_parses_with_the_grammar():
    """Each `graphmethods ...` of the README parses (options exist, no prefix guessed); CI runs them all."""
    n = 0
    for c in _readme_commands():
        lex = shlex.shlex(c.text, posix=True, punctuation_chars=True)
        lex.whitespace_split = True
        parts: list[list[str]] = [[]]
        for tok in lex:
            if tok in ("&&", "||", ";", "|", ";;"):
                parts.append([])
            else:
                parts[-1].append(tok)
        for words in parts:
            words = [w for w in words if not re.match(r"^[A-Z_]+=", w)]
            if "do" in words:
                words = words[words.index("do") + 1:]
            if len(words) < 2 or words[0] != "graphmethods" or words[1] not in COMMANDS:
                continue
            cut = next((i for i, w in enumerate(words) if w in (">", "<")), len(words))
            argv = [w for w in words[1:cut] if not w.startswith("$")]
            mod = __import__(f"graphmethods.cli.{COMMANDS[argv[0]][0]}", fromlist=["x"])
            argv = getattr(mod, "preprocess_argv", list)(argv)
            build_parser(argv[0]).parse_args(argv)
            n += 1
    assert n > 60
