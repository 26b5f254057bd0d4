"""``graphmethods check-class``: a folder of answers files checked at once, one table, each student's report."""

import csv
import html.parser
import io
import pathlib
import shutil

import pytest

from graphmethods import cli
from graphmethods.scene import vocabulary
from graphmethods.sheets.check import check
from graphmethods.sheets.check.classcheck import ClassReport, check_class, class_files, names_from_file_name

ANSWERS = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data" / "answers"
BROKEN = 'problem = "W1"\nstudent = "Broken file"\n[energy_indicator\nmu_E = 5\n'


@pytest.fixture
def klass(tmp_path):
    d = tmp_path / "class"
    d.mkdir()
    for p in sorted(ANSWERS.glob("*.toml")):
        shutil.copy(p, d)
    (d / "zz_broken.toml").write_text(BROKEN, encoding="utf-8")
    return d


def run(capsys, *argv):
    rc = cli.main(["check-class", *map(str, argv)])
    out, err = capsys.readouterr()
    return rc, out, err


def test_the_class_table_agrees_with_each_check(klass, tmp_path, capsys):
    rc, out, err = run(capsys, klass, "--out", tmp_path / "out")
    assert rc == 3                                                      # one file could not be checked
    files = sorted(p.name for p in klass.iterdir())
    assert [ln.split("]")[0] + "]" for ln in err.splitlines() if ln.startswith("[")] == \
        [f"[{i}/{len(files)}]" for i in range(1, len(files) + 1)]     # progress: one line per file
    rows = list(csv.reader(io.StringIO((tmp_path / "out" / "class.csv").read_text(encoding="utf-8-sig"))))
    head, body = rows[0], rows[1:]
    assert [r[0] for r in body] == files
    reports = {f: check(_problem_of(klass / f), klass / f) for f in files if f != "zz_broken.toml"}
    keys = list(dict.fromkeys(it.key for f in files if f in reports for it in reports[f].items))
    assert len(head) == 5 + len(keys) + 1
    for r in body:
        cells = dict(zip(head, r))
        if r[0] == "zz_broken.toml":
            assert "not valid TOML" in cells["error"] and cells["score"] == "—"
            continue
        rep = reports[r[0]]                                                   # the single check of that file
        assert cells["student"] == rep.student and cells["error"] == ""
        ok = sum(1 for i in rep.items if i.verdict == "ok")
        carried = sum(1 for i in rep.items if i.verdict == "carried")
        assert cells["score"] == f"{ok + carried / 2:g}/{len(rep.items)}"
        for it in rep.items:
            col = 5 + keys.index(it.key)
            assert r[col].split(":")[0] == {"ok": "correct", "carried": "carried over", "wrong": "wrong"}[it.verdict]
            assert all(MISTAKE_WORDS[m] in r[col] for m in it.mistakes)      # named in words, not codes
        answered = {it.key for it in rep.items}
        assert all(r[5 + k] == "" for k, key in enumerate(keys) if key not in answered)
        assert (tmp_path / "out" / "students" / f"{r[0]}.md").read_text(encoding="utf-8") == rep.to_markdown()
        assert (tmp_path / "out" / "students" / f"{r[0]}-overlay.svg").exists()
    n_correct = sum(1 for f in files if "_correct" in f)
    n_mistakes = sum(1 for f in files if "_mistakes" in f or ("_acc_" in f and "_correct" not in f))
    assert n_correct + n_mistakes + 1 == len(files)
    assert f"{len(files)} files: {n_correct} all correct, {n_mistakes} with mistakes, 1 could not be checked" in out


MISTAKE_WORDS = {code: words[0] for code, words in vocabulary.family("check").words.items()}
MISTAKE_WORDS["J_e_not_subtracted"] = "not subtracted"


def _problem_of(path):
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("problem"):
            return line.split("=")[1].strip().strip('"')
    raise AssertionError(path)


def test_html_is_self_contained_and_well_formed(klass, tmp_path, capsys):
    run(capsys, klass, "--out", tmp_path / "out", "--no-overlays")
    page = (tmp_path / "out" / "class.html").read_text(encoding="utf-8")
    assert "<script" not in page and "http" not in page and "src=" not in page and "<link" not in page

    class Check(html.parser.HTMLParser):
        def __init__(self):
            super().__init__()
            self.stack, self.rows = [], 0

        def handle_starttag(self, tag, attrs):
            if tag not in ("meta", "br"):
                self.stack.append(tag)
            self.rows += tag == "tr"

        def handle_endtag(self, tag):
            assert self.stack.pop() == tag
    p = Check()
    p.feed(page)
    assert p.stack == [] and p.rows == 1 + len(list(klass.iterdir()))
    assert 'class="wrong"' in page and "Example student (mistakes)" in page and "not valid TOML" in page


def test_exit_status_zero_when_all_right_and_one_with_mistakes(tmp_path, capsys):
    good, bad = tmp_path / "good", tmp_path / "bad"
    good.mkdir()
    bad.mkdir()
    for p in ANSWERS.glob("*_correct.toml"):
        shutil.copy(p, good)
    shutil.copy(ANSWERS / "w1_mistakes.toml", bad)
    assert run(capsys, good, "--out", tmp_path / "o1", "--no-overlays")[0] == 0
    assert run(capsys, bad, "--out", tmp_path / "o2", "--no-overlays")[0] == 1


def test_bad_folder_and_existing_output_exit_2_in_one_line(klass, tmp_path, capsys):
    rc, out, err = run(capsys, tmp_path / "nowhere")
    assert rc == 2 and len(err.strip().splitlines()) == 1 and "not a folder" in err
    run(capsys, klass, "--out", tmp_path / "out", "--no-overlays")
    before = (tmp_path / "out" / "class.csv").read_bytes()
    rc, out, err = run(capsys, klass, "--out", tmp_path / "out", "--no-overlays")
    assert rc == 2 and "--force" in err and len(err.strip().splitlines()) == 1
    assert (tmp_path / "out" / "class.csv").read_bytes() == before
    assert run(capsys, klass, "--out", tmp_path / "out", "--no-overlays", "--force")[0] == 3
    empty = tmp_path / "empty"
    empty.mkdir()
    rc, out, err = run(capsys, empty)
    assert rc == 2 and "no answers files" in err


def test_student_and_problem_from_the_file_name(tmp_path):
    text = (ANSWERS / "w3_correct.toml").read_text(encoding="utf-8")
    body = "\n".join(ln for ln in text.splitlines() if not ln.startswith(("problem", "student")))
    (tmp_path / "ivanov__W3.toml").write_text(body, encoding="utf-8")
    (tmp_path / "petrov.toml").write_text(body, encoding="utf-8")
    rep = check_class(class_files(tmp_path))
    by = {s.path.name: s for s in rep.submissions}
    assert by["ivanov__W3.toml"].student == "ivanov" and by["ivanov__W3.toml"].report.ok
    assert by["petrov.toml"].report is None and "no problem" in by["petrov.toml"].error
    rep = check_class(class_files(tmp_path), problem="W3")            # the problem for the whole class
    assert all(s.report is not None and s.report.ok for s in rep.submissions) and rep.exit_status() == 0
    assert names_from_file_name("a__velocity-plan_7_12.toml") == ("a", "velocity-plan:7:12")


def test_markdown_table_shape(klass):
    rep: ClassReport = check_class(class_files(klass))
    md = rep.to_markdown().splitlines()
    table = [ln for ln in md if ln.startswith("|")]
    assert len(table) == 2 + len(rep.submissions)
    assert len({ln.count(" | ") for ln in table[2:]} | {table[0].count(" | ")}) == 1   # every row as wide
