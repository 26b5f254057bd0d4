"""Every output option of the CLI (``--sheet``, ``--figure``, ``--hyperbola``) refuses a file it cannot or
must not write the same way, before any work: one line on stderr, exit 2, nothing written or replaced."""

import pytest

from graphmethods.cli import main

W1 = ["--areas", "-50", "550", "-100", "125", "-500", "25", "-50", "--n", "600"]
# (command line before the option, the option, the endings it takes)
TARGETS = [
    (["drive", "--J", "1,2", "--c", "5"], "--figure", (".svg", ".pdf", ".png")),
    (["flywheel", *W1, "--delta", "1/300", "--rim", "0.75"], "--figure", (".svg", ".pdf", ".png")),
    (["flywheel", *W1, "--delta", "1/300"], "--hyperbola", (".svg", ".pdf")),
    (["study", "press", "--positions", "12", "--no-exact"], "--sheet", (".svg", ".pdf", ".dxf")),
]
IDS = [f"{argv[0]}{option}" for argv, option, _ in TARGETS]


def _refused(capsys, argv: list[str]) -> str:
    code = main(argv)
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err, err
    return err


@pytest.mark.parametrize("argv,option,endings", TARGETS, ids=IDS)
def test_a_wrong_ending_names_the_endings_the_option_takes(capsys, tmp_path, argv, option, endings):
    err = _refused(capsys, [*argv, option, str(tmp_path / "out.txt")])
    assert option in err and all(e in err for e in endings) and not (tmp_path / "out.txt").exists()
    err = _refused(capsys, [*argv, option, " "])
    assert f"{option} is empty" in err


@pytest.mark.parametrize("argv,option,endings", TARGETS, ids=IDS)
def test_a_missing_directory_a_directory_and_an_existing_file_are_refused(capsys, tmp_path, argv, option, endings):
    name = "out" + endings[0]
    err = _refused(capsys, [*argv, option, str(tmp_path / "nowhere" / name)])
    assert "does not exist" in err and not (tmp_path / "nowhere").exists()
    folder = tmp_path / ("dir" + endings[0])
    folder.mkdir()
    assert "it is a directory" in _refused(capsys, [*argv, option, str(folder), "--force"])
    kept = tmp_path / name
    kept.write_bytes(b"kept")
    assert "--force" in _refused(capsys, [*argv, option, str(kept)])
    assert kept.read_bytes() == b"kept"
