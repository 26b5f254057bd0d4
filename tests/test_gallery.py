"""Every gallery figure is a test: rebuilt, it must equal its committed SVG (after C14N)."""

import argparse
import pathlib
import re
import shutil

import pytest

from graphmethods.cli import gallery
from graphmethods.errors import InputError, OutputExistsError
from graphmethods.render import svg

GALLERY = pathlib.Path(__file__).resolve().parents[1] / "gallery"
SCRIPTS = gallery.scripts(GALLERY)
REGENERATE = "graphmethods gallery --regenerate"


def _args(*argv):
    p = argparse.ArgumentParser()
    sub = p.add_subparsers()
    gallery.add_parser(sub)
    return p.parse_args(["gallery", *argv])


@pytest.mark.parametrize("script", SCRIPTS, ids=[p.stem for p in SCRIPTS])
def test_gallery_figure_equals_its_committed_svg(script):
    golden = script.with_suffix(".svg")
    assert golden.exists(), f"{golden.name} is missing: run `{REGENERATE}` and commit it"
    built = svg.to_string(gallery.build(script))
    diff = gallery.svg_diff(golden.read_text(encoding="utf-8"), built, name=golden.name)
    if diff is not None:
        shown = "\n".join(diff.splitlines()[:80])
        pytest.fail(f"{golden.name} differs from what {script.name} builds now; if the change is intended, "
                    f"run `{REGENERATE}` and commit the new files.\n{shown}", pytrace=False)


def test_a_changed_svg_fails_the_comparison_with_a_readable_diff():
    golden = SCRIPTS[0].with_suffix(".svg").read_text(encoding="utf-8")
    changed = re.sub(r'points="(\d+)', lambda m: f'points="{int(m.group(1)) + 1}', golden, count=1)
    assert changed != golden
    diff = gallery.svg_diff(golden, changed, name="fig.svg")
    assert diff is not None
    lines = diff.splitlines()
    assert lines[0].startswith("--- fig.svg (committed)") and lines[1].startswith("+++ fig.svg (built now)")
    minus = [ln for ln in lines if ln.startswith("-") and not ln.startswith("---")]
    plus = [ln for ln in lines if ln.startswith("+") and not ln.startswith("+++")]
    assert len(minus) == len(plus) == 1 and "points=" in minus[0]      # one line: exactly the change


def test_canonicalisation_ignores_attribute_order_and_quoting_only():
    a = '<svg xmlns="http://www.w3.org/2000/svg" width="1mm" height="2mm"><g id="x"/></svg>'
    b = "<svg height='2mm' width='1mm' xmlns='http://www.w3.org/2000/svg'><g id='x'></g></svg>"
    assert gallery.svg_diff(a, b) is None
    assert gallery.svg_diff(a, a.replace('id="x"', 'id="y"')) is not None


def test_the_gallery_covers_w1_to_w4_in_three_notations():
    names = {p.stem for p in SCRIPTS}
    for case, figs in {"w1": ("energy_indicator", "excess_work_table"), "w2": ("energy_indicator", "excess_work_table"),
                       "w3": ("moment_diagram", "excess_work_table", "energy_indicator", "energy_graph"),
                       "w4": ("moment_diagram", "excess_work_table", "energy_indicator", "energy_graph")}.items():
        for fig in figs:
            for nt in ("en", "ru", "zh"):
                assert f"{case}_{fig}_{nt}" in names
    for p in SCRIPTS:
        module = gallery.load(p)
        assert module.__doc__ and len(p.read_text(encoding="utf-8").splitlines()) < 25   # small, readable
        if getattr(module, "PNG", False):
            assert p.with_suffix(".png").exists(), f"{p.stem}.png (shown by the README) is missing"


def test_cli_builds_into_a_folder_and_refuses_to_overwrite(tmp_path, capsys):
    src = tmp_path / "gal"
    src.mkdir()
    for name in ("w1_energy_indicator_zh.py", "w3_moment_diagram_ru.py"):
        shutil.copy(GALLERY / name, src / name)
    out = tmp_path / "out"
    assert gallery.run(_args("--dir", str(src), "--out", str(out))) == 0
    assert sorted(p.name for p in out.iterdir()) == ["w1_energy_indicator_zh.svg", "w3_moment_diagram_ru.svg"]
    assert "2 figures" in capsys.readouterr().out
    before = (out / "w1_energy_indicator_zh.svg").read_bytes()
    (out / "w3_moment_diagram_ru.svg").unlink()
    with pytest.raises(OutputExistsError, match="--force"):
        gallery.run(_args("--dir", str(src), "--out", str(out), "--png"))
    assert sorted(p.name for p in out.iterdir()) == ["w1_energy_indicator_zh.svg"]   # nothing written
    assert gallery.run(_args("--dir", str(src), "--out", str(out), "--force")) == 0
    assert (out / "w1_energy_indicator_zh.svg").read_bytes() == before               # deterministic
    assert (out / "w1_energy_indicator_zh.svg").read_bytes() == (GALLERY / "w1_energy_indicator_zh.svg").read_bytes()


def test_cli_writes_pngs_on_request(tmp_path):
    src = tmp_path / "gal"
    src.mkdir()
    shutil.copy(GALLERY / "w4_energy_graph_ru.py", src)
    assert gallery.run(_args("--dir", str(src), "--out", str(tmp_path / "o"), "--png")) == 0
    assert (tmp_path / "o" / "w4_energy_graph_ru.png").read_bytes()[:4] == b"\x89PNG"


def test_regenerate_rewrites_the_gallery_folder_itself(tmp_path):
    src = tmp_path / "gal"
    src.mkdir()
    shutil.copy(GALLERY / "w2_excess_work_table_en.py", src)
    (src / "w2_excess_work_table_en.svg").write_text("stale", encoding="utf-8")
    assert gallery.run(_args("--dir", str(src), "--regenerate")) == 0
    assert (src / "w2_excess_work_table_en.svg").read_bytes() == (GALLERY / "w2_excess_work_table_en.svg").read_bytes()
    with pytest.raises(InputError, match="leave out --out"):
        gallery.run(_args("--dir", str(src), "--regenerate", "--out", str(tmp_path)))


def test_cli_errors_name_the_problem(tmp_path):
    with pytest.raises(InputError, match="not found"):
        gallery.run(_args("--dir", str(tmp_path / "none")))
    (tmp_path / "bad.py").write_text("x = 1\n", encoding="utf-8")
    with pytest.raises(InputError, match="must define build"):
        gallery.run(_args("--dir", str(tmp_path), "--out", str(tmp_path / "o")))
