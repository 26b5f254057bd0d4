"""Every gallery figure is a test: rebuilt, it must equal its committed SVG (after C14N).

The figures are the rows of graphmethods.gallery.catalogue (they ship with the package); their golden
SVGs stay in the source checkout's gallery/ folder."""

import argparse
import importlib
import pathlib
import re

import pytest

import graphmethods.gallery as builtin
from graphmethods.cli import gallery
from graphmethods.errors import InputError, OutputExistsError
from graphmethods.render import svg

GALLERY = pathlib.Path(__file__).resolve().parents[1] / "gallery"          # the golden files
SOURCES = pathlib.Path(builtin.__file__).parent                            # the catalogue
NAMES = builtin.figure_names()
REGENERATE = "graphmethods gallery --regenerate"


def _args(*argv):
    p = argparse.ArgumentParser()
    sub = p.add_subparsers()
    gallery.add_parser(sub)
    return p.parse_args(["gallery", *argv])


@pytest.mark.parametrize("name", NAMES)
def test_gallery_figure_equals_its_committed_svg(name):
    golden = GALLERY / f"{name}.svg"
    assert golden.exists(), f"{golden.name} is missing: run `{REGENERATE}` and commit it"
    built = svg.to_string(gallery.build(name))
    diff = gallery.svg_diff(golden.read_text(encoding="utf-8"), built, name=golden.name)
    if diff is not None:
        shown = "\n".join(diff.splitlines()[:80])
        pytest.fail(f"{golden.name} differs from what graphmethods.gallery.{name} builds now; if the change is "
                    f"intended, run `{REGENERATE}` and commit the new files.\n{shown}", pytrace=False)


def test_every_golden_file_has_its_figure_and_the_gallery_folder_holds_no_scripts():
    figures = set(NAMES)
    goldens = {p.stem for p in GALLERY.glob("*.svg") if not p.stem.startswith("bench_")}
    assert goldens == figures, f"golden files without a figure: {sorted(goldens - figures)}"
    assert not list(GALLERY.glob("*.py"))          # the scripts live in graphmethods/gallery/ (they ship)


def test_a_changed_svg_fails_the_comparison_with_a_readable_diff():
    golden = (GALLERY / f"{NAMES[0]}.svg").read_text(encoding="utf-8")
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
    names = set(NAMES)
    for case, figs in {"w1": ("energy_indicator", "excess_work_table"), "w2": ("energy_indicator", "excess_work_table"),
                       "w3": ("moment_diagram", "excess_work_table", "energy_indicator", "energy_graph"),
                       "w4": ("moment_diagram", "excess_work_table", "energy_indicator", "energy_graph")}.items():
        for fig in figs:
            for nt in ("en", "ru", "zh"):
                assert f"{case}_{fig}_{nt}" in names
    for name in NAMES:
        row = builtin.figure(name)
        module, function = row.figure.rsplit(".", 1)
        assert row.about and callable(getattr(importlib.import_module(f"graphmethods.sheets.{module}"), function))
        assert row.language in ("en", "ru", "zh") and row.problem.partition(":")[1] == ":"
        if row.png:
            assert (GALLERY / f"{name}.png").exists(), f"{name}.png (shown by the README) is missing"


def test_the_gallery_is_one_catalogue_not_a_module_per_figure():
    assert sorted(p.name for p in SOURCES.glob("*.py")) == ["__init__.py", "catalogue.py"]
    assert len(builtin.CATALOGUE) == len(NAMES) == len(set(NAMES))


def _script(folder: pathlib.Path, name: str) -> None:
    """A gallery script of one's own (as --dir takes them) that draws a catalogue figure."""
    (folder / f"{name}.py").write_text(f'"""{name}."""\n\nfrom graphmethods.gallery import figure\n\n\n'
                                       f"def build():\n    return figure({name!r}).build()\n", encoding="utf-8")


def test_cli_builds_into_a_folder_and_refuses_to_overwrite(tmp_path, capsys):
    src = tmp_path / "gal"
    src.mkdir()
    for name in ("w1_energy_indicator_zh", "w3_moment_diagram_ru"):
        _script(src, name)
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
    _script(src, "w4_energy_graph_ru")
    assert gallery.run(_args("--dir", str(src), "--out", str(tmp_path / "o"), "--png")) == 0
    assert (tmp_path / "o" / "w4_energy_graph_ru.png").read_bytes()[:4] == b"\x89PNG"


def test_regenerate_rewrites_the_gallery_folder_itself(tmp_path):
    src = tmp_path / "gal"
    src.mkdir()
    _script(src, "w2_excess_work_table_en")
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


def test_the_built_in_gallery_builds_every_figure_without_a_source_folder(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)                    # no gallery/ here, as after pip install
    subset = NAMES[:3]
    monkeypatch.setattr(builtin, "figure_names", lambda: subset)
    assert gallery.run(_args("--out", "figs")) == 0
    assert sorted(p.stem for p in (tmp_path / "figs").iterdir()) == subset
    assert f"{len(subset)} figures in figs" in capsys.readouterr().out
    for name in subset:
        assert (tmp_path / "figs" / f"{name}.svg").read_bytes() == (GALLERY / f"{name}.svg").read_bytes()
    with pytest.raises(InputError, match="run it from the project folder"):
        gallery.run(_args("--regenerate"))
    with pytest.raises(InputError, match="no built-in figure"):
        gallery.build("w9_nothing")
