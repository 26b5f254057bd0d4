"""The command line as a user of the installed package meets it: --version, the list of built-in
problems, built-in names wherever a problem file is taken, and help that names no file they lack."""

import json
import re
from importlib import metadata

import pytest

from graphmethods.cli import COMMANDS, build_parser, main
from graphmethods.kinematics import read_case
from graphmethods.problems import builtin


def test_version_is_the_installed_packages(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0
    assert capsys.readouterr().out.strip() == f"graphmethods {metadata.version('graphmethods')}"


def test_problems_lists_every_built_in_problem_with_kind_and_title(capsys):
    assert main(["problems"]) == 0
    lines = capsys.readouterr().out.splitlines()
    for name in ("W1", "W2", "W3", "W4", "press", "shaper", "four-bar", "slotted-lever"):
        row = [ln for ln in lines if ln.split()[:1] == [name]]
        assert len(row) == 1, name
    assert main(["problems", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [r["name"] for r in rows] == builtin.names()
    kinds = {r["name"]: r["kind"] for r in rows}
    for name, file in builtin.LINKAGES.items():            # kind and title as the problem file gives them
        case = read_case(builtin.DATA / file)
        assert kinds[name] == case.kind
    assert kinds["W1"] == "cycle"
    assert all(r["title"] for r in rows)


@pytest.mark.parametrize("name", ["press", "shaper", "four-bar", "slotted_lever", "PRESS"])
def test_kinematics_takes_a_built_in_name_as_it_takes_the_file(name, capsys):
    assert main(["kinematics", name, "--positions", "6", "--json"]) == 0
    by_name = json.loads(capsys.readouterr().out)
    path = builtin.case_path(name)
    assert path.parent == builtin.DATA
    assert main(["kinematics", str(path), "--positions", "6", "--json"]) == 0
    assert json.loads(capsys.readouterr().out) == by_name


def test_study_takes_a_built_in_name(capsys):
    assert main(["study", "press", "--positions", "12", "--no-exact", "--json"]) == 0
    by_name = json.loads(capsys.readouterr().out)
    assert main(["study", str(builtin.DATA / "slider_crank_press.json"), "--positions", "12", "--no-exact",
                 "--json"]) == 0
    assert json.loads(capsys.readouterr().out) == by_name


@pytest.mark.parametrize("command", [["kinematics"], ["study"]])
def test_a_name_that_is_neither_a_file_nor_built_in_gets_one_line_naming_the_choices(command, capsys, tmp_path,
                                                                                   monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main([*command, "pres"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "pres: no such problem file" in err
    assert all(n in err for n in builtin.LINKAGES) and "graphmethods problems" in err
    assert main([*command, "W1"]) == 2
    assert "cycle problem" in capsys.readouterr().err


def test_a_file_wins_over_a_built_in_name(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "press").write_text("{}", encoding="utf-8")      # a file named like a built-in problem
    assert main(["kinematics", "press"]) == 2
    assert "press" in capsys.readouterr().err                   # read (and refused) as the file


def test_no_help_names_a_file_a_user_of_the_installed_package_lacks():
    parser = build_parser()
    sub = next(a for a in parser._actions if a.choices and "study" in a.choices)
    texts = [parser.format_help()] + [sub.choices[c].format_help() for c in COMMANDS]
    for text in texts:
        text = re.sub(r"\s+", " ", text)
        for bad in ("shared/", "domain.md", "graphmethods/problems", "tests/", "cases/README", ".md §"):
            assert bad not in text, (bad, text[:80])
