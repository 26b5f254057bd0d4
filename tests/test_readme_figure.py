"""The README's "Adding a figure" example runs as written and draws what it says."""

import pathlib

import pytest

README = pathlib.Path(__file__).resolve().parent.parent / "README.md"


def _block(heading: str) -> str:
    text = README.read_text(encoding="utf-8")
    after = text[text.index(heading):]
    start = after.index("```python") + len("```python")
    return after[start:after.index("```", start)]


@pytest.mark.skipif(not README.exists(), reason="the README is not shipped in the sdist's test run")
def test_the_adding_a_figure_example_runs_and_draws_the_slope(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    exec(compile(_block("### Adding a figure"), "README.md", "exec"), namespace)
    assert (tmp_path / "inertia_slope.pdf").read_bytes().startswith(b"%PDF")
    from graphmethods.dynamics.study import Study
    from graphmethods.problems.builtin import case

    study = Study(case("press"), positions=12)
    scene = namespace["inertia_slope_graph"](study)
    # the curve's extreme ordinates are the slope's extremes at the drawing's scale
    s_Y = scene.scales()[1]
    ys = [y for x, y in scene.element("curve-dJ").points]
    slope = namespace["reduced_inertia_slope"](study.mechanism, namespace["np"].linspace(0, 6.283185307179586, 721),
                                               study.case.inertias)
    assert (max(ys) - min(ys)) * s_Y.per_mm == pytest.approx(float(slope.max() - slope.min()), rel=1e-9)
