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


# ----------------------------------------------------------------------------- notebooks

def test_a_notebook_shows_the_excess_work_table_as_markdown():
    from graphmethods.dynamics import excess_work as ew

    cyc = ew.from_work([30, -70, 40])
    md = cyc._repr_markdown_()
    assert md == cyc.to_markdown()
    rows = [ln for ln in md.splitlines() if ln.startswith("| ") and "–" in ln]
    assert [r.split("|")[2].strip() for r in rows] == ["30", "-70", "40"]     # the works, in order
    assert [r.split("|")[3].strip() for r in rows] == ["30", "-40", "0"]      # the running energy
    assert "ΔW_max = 70 J" in md


def test_a_notebook_shows_the_study_without_solving_the_exact_motion():
    from graphmethods.dynamics.study import Study

    study = Study(builtin.case("press"), positions=12)
    md = study._repr_markdown_()
    assert "exact" not in study.computed and "J_F_exact" not in md
    cells = {ln.split("|")[1].strip(): ln.split("|")[2].strip() for ln in md.splitlines() if ln.startswith("| ")}
    assert float(cells["J_F_wittenbauer"]) == pytest.approx(study.wittenbauer.J_F, rel=1e-5)
    assert float(cells["delta_W_max"]) == pytest.approx(study.excess_work.delta_W_max, rel=1e-5)
    study.exact  # noqa: B018 - computed on first access
    cells = {ln.split("|")[1].strip(): ln.split("|")[2].strip() for ln in study._repr_markdown_().splitlines()
             if ln.startswith("| ")}
    assert float(cells["J_F_exact"]) == pytest.approx(study.exact.J_F, rel=1e-5)


def test_a_notebook_shows_the_check_report():
    from graphmethods.sheets import check, worksheets

    v = worksheets.variant("wittenbauer", seed=3, number=1)
    a = v.answers()
    rep = check.check(v.id, {"energy_mass": {"mu_J": v.mu_J, "mu_T": v.mu_T, "kl_mm": a["kl_mm"] + 10},
                             "results": {"J_F": a["J_F"]}})
    md = rep._repr_markdown_()
    assert md == rep.to_markdown() and md.startswith(f"### Check of {v.id}")
    assert "**wrong" in md and md.count("\n| ") == len(rep.items) + 1
