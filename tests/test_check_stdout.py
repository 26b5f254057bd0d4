"""`check -o -`: the overlay on standard output in --format, the report on standard error."""

from __future__ import annotations

import pathlib

import pytest

import graphmethods
from graphmethods.cli import main

ANSWERS = pathlib.Path(graphmethods.__file__).parent / "problems" / "data" / "answers"


@pytest.mark.parametrize("fmt", ["svg", "dxf"])
def test_the_overlay_goes_to_standard_output_and_the_report_to_stderr(fmt, capsysbinary, tmp_path) -> None:
    assert main(["check", "W1", str(ANSWERS / "w1_mistakes.toml"), "-o", "-", "--format", fmt]) == 1
    out, err = capsysbinary.readouterr()
    main(["check", "W1", str(ANSWERS / "w1_mistakes.toml"), "-o", str(tmp_path / f"o.{fmt}")])
    assert out == (tmp_path / f"o.{fmt}").read_bytes()          # the same bytes as the file
    assert "Check of W1" in err.decode() and "overlay: standard output" in err.decode()


def test_the_old_report_style_name_still_works_beside_the_file_format(capsys) -> None:
    assert main(["check", "W1", str(ANSWERS / "w1_mistakes.toml"), "--format", "markdown"]) == 1
    assert capsys.readouterr().out.startswith("### Check of W1")


@pytest.mark.parametrize("argv", [["-o", "-"], ["-o", "-", "--format", "text"],
                                  ["--report", "json", "--format", "text"], ["-o", "x.pdf", "--format", "svg"]])
def test_an_overlay_on_standard_output_needs_its_format(argv, capsys, tmp_path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["check", "W1", str(ANSWERS / "w1_mistakes.toml"), *argv]) == 2
    out, err = capsys.readouterr()
    assert out == "" and len(err.strip().splitlines()) == 1 and not list(tmp_path.iterdir())
