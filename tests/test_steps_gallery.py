"""The lecture build-ups of the gallery (gallery/steps/*.py): rebuilt, each equals its committed outputs.

Each script defines ``build()`` returning the steps of a construction and ``FORMATS``; its committed
``<name>.html`` must equal the page built now, byte for byte, and its ``<name>.pdf`` must have one page per
step at the step figure's page size (its bytes depend on the fonts the PDF writer embeds, so they are
not compared). To rewrite them on purpose: ``GRAPHMETHODS_REGENERATE_STEPS=1 python -m pytest
tests/test_steps_gallery.py``, then commit them.
"""

import importlib.util
import os
import pathlib
import re

import pytest

from graphmethods.render import steps as R

STEPS = pathlib.Path(__file__).resolve().parents[1] / "gallery" / "steps"
SCRIPTS = sorted(p for p in STEPS.glob("*.py") if not p.name.startswith("_"))
REGENERATE = os.environ.get("GRAPHMETHODS_REGENERATE_STEPS") == "1"
HOW = "GRAPHMETHODS_REGENERATE_STEPS=1 python -m pytest tests/test_steps_gallery.py"


def _load(path):
    spec = importlib.util.spec_from_file_location(f"graphmethods_gallery_steps_{path.stem}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_gallery_has_the_press_plan_and_wittenbauer_in_three_languages():
    names = {p.stem for p in SCRIPTS}
    figures = ("velocity_plan", "wittenbauer", "force_plans", "zhukovsky_lever")
    assert names >= {f"press_{fig}_{lang}" for fig in figures for lang in ("en", "ru", "zh")}


@pytest.mark.parametrize("script", SCRIPTS, ids=[p.stem for p in SCRIPTS])
def test_gallery_build_up_equals_its_committed_outputs(script):
    module = _load(script)
    bu = module.build()
    assert set(module.FORMATS) == {"pdf", "html"}
    html, pdf = script.with_suffix(".html"), script.with_suffix(".pdf")
    if REGENERATE:
        R.save(bu, html, "html", overwrite=True)
        R.save(bu, pdf, "pdf", overwrite=True)
    assert html.exists() and pdf.exists(), f"{script.stem}: run `{HOW}` and commit the outputs"
    if html.read_text(encoding="utf-8") != R.html_page(bu):
        pytest.fail(f"{html.name} differs from what {script.name} builds now; if intended, run `{HOW}` and "
                    f"commit", pytrace=False)
    data = pdf.read_bytes()
    assert data.startswith(b"%PDF-") and data.rstrip().endswith(b"%%EOF")
    pages = re.findall(rb"/Type\s*/Page\b(?!s)", data)
    assert len(pages) == len(bu), f"{pdf.name}: {len(pages)} pages for {len(bu)} steps; run `{HOW}`"
    w, h = bu.figure.page.width_mm * 72 / 25.4, bu.figure.page.height_mm * 72 / 25.4
    boxes = re.findall(rb"/MediaBox\s*\[\s*0\s+0\s+([\d.]+)\s+([\d.]+)\s*\]", data)
    assert boxes and all(abs(float(a) - w) < 0.01 and abs(float(b) - h) < 0.01 for a, b in boxes)
