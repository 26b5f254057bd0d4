"""Every figure of every built-in problem, in every language: texts apart, inside the frame, axes with values.

The built-in problems are those of :mod:`graphmethods.problems.builtin` (the four classic kinds and
the course mechanisms as linkage problems, W1–W4 as cycle problems); the figures are every public
function of :mod:`graphmethods.sheets` that draws a problem. A figure a problem cannot have (a
slider's diagrams of a linkage without a slider, a moment graph of a load given as an indicator
diagram) must refuse with the project's :class:`~graphmethods.errors.InputError` saying why; that
list is written out below, so a figure that stops drawing fails here.

What is checked, on the texts the recording renderer receives (their boxes from the width
estimates of :mod:`graphmethods.scene.markup`, :func:`graphmethods.scene.elements.label_bbox`):

- no two texts overlap by more than ``OVERLAP_MM`` = 0.3 mm both across and down (the cells of a
  table and the lines of a block touch; a text set on another is caught);
- no text leaves the frame (the page's inner box), with no tolerance;
- every axis drawn has a value written at one of its ticks at least (its tick labels, or position
  numbers set beside a φ axis): a text within ``NEAR_TICK_MM`` = 4 mm of a tick, the axis's name aside.
"""

import math

import numpy as np
import pytest

from graphmethods import problems, sheets
from graphmethods.dynamics.study import Study
from graphmethods.errors import InputError
from graphmethods.problems import builtin
from graphmethods.render.recording import record
from graphmethods.scene import markup
from graphmethods.scene.elements import Axis, label_bbox

OVERLAP_MM = 0.3
NEAR_TICK_MM = 4.0
LANGS = ("en", "ru", "zh")

LINKAGE_FIGURES = ("kinematic_scheme", "velocity_plan_grid", "velocity_plan", "velocity_table", "inertia_graph",
                   "moment_graph", "delta_T_graph", "speed_graph", "acceleration_graph", "zhukovsky_lever",
                   "wittenbauer_diagram", "dynamic_analysis_sheet", "kinematic_diagrams", "work_diagrams",
                   "force_analysis_sheet", "kinematic_analysis_sheet")
CYCLE_FIGURES = ("moment_diagram", "excess_work_table", "energy_indicator", "energy_graph", "work_diagrams")

_NO_SLIDER = "the slider's diagrams need a linkage with one slider"
_INDICATOR = "indicator diagram"
_NO_CURVES = "needs (the )?moment curves"
#: (problem, figure) -> what the refusal says
NOT_DRAWN = {
    **{(p, "kinematic_diagrams"): _NO_SLIDER for p in ("four-bar", "slotted-lever", "two-slider", "triad-six-bar")},
    ("engine", "zhukovsky_lever"): _INDICATOR,
    **{(p, f): _NO_CURVES for p in ("W1", "W2", "W4") for f in ("moment_diagram", "energy_graph", "work_diagrams")},
}

#: known failures while they are being fixed: (problem, figure, language) -> reason
KNOWN: dict[tuple[str, str, str], str] = {
    **{("triad-six-bar", "velocity_table", lang): "the table of a class III six-bar (9 points, 5 links) is wider "
       "than an A4 page" for lang in LANGS},
}

CASES = [(p, f) for p in builtin.names() if p not in builtin.CAMS
         for f in (CYCLE_FIGURES if p in builtin.CYCLES else LINKAGE_FIGURES)]


@pytest.fixture(scope="module")
def subjects():
    cache = {}

    def get(name):
        if name not in cache:
            cache[name] = (getattr(problems, builtin.CYCLES[name])() if name in builtin.CYCLES
                           else Study(builtin.case(name), positions=12))
        return cache[name]
    return get


def _texts(scene) -> list:
    return [c.data for c in record(scene).calls if c.kind == "text"]


def text_faults(scene, texts=None) -> list[str]:
    """What is wrong with the texts of a scene: overlaps beyond OVERLAP_MM, texts outside the frame."""
    x0, y0, x1, y1 = scene.page.inner_box()
    labels = _texts(scene) if texts is None else texts
    boxes = np.array([label_bbox(lab) for lab in labels], dtype=float).reshape(-1, 4)
    faults = [f"{lab.text!r} leaves the frame: {tuple(round(float(v), 1) for v in b)}"
              for lab, b in zip(labels, boxes)
              if b[0] < x0 - 1e-9 or b[1] < y0 - 1e-9 or b[2] > x1 + 1e-9 or b[3] > y1 + 1e-9]
    ox = np.minimum(boxes[:, None, 2], boxes[None, :, 2]) - np.maximum(boxes[:, None, 0], boxes[None, :, 0])
    oy = np.minimum(boxes[:, None, 3], boxes[None, :, 3]) - np.maximum(boxes[:, None, 1], boxes[None, :, 1])
    for i, j in zip(*np.nonzero(np.triu((ox > OVERLAP_MM) & (oy > OVERLAP_MM), k=1))):
        faults.append(f"{labels[i].text!r} overlaps {labels[j].text!r} by {ox[i, j]:.1f} × {oy[i, j]:.1f} mm")
    return faults


def _axes(elements):
    for e in elements:
        if isinstance(e, Axis):
            yield e
        yield from _axes(getattr(e, "elements", ()) or ())


def bare_axes(scene, texts=None) -> list[str]:
    """The names of the axes with no value written at any tick: no text other than the axis's name
    within ``NEAR_TICK_MM`` of a tick (an axis's own tick labels, or position numbers set beside it)."""
    boxes = [(lab.text, label_bbox(lab)) for lab in (_texts(scene) if texts is None else texts)]
    bare = []
    for ax in _axes(scene.elements):
        name = markup.plain(ax.label)
        near = False
        for v in ax.ticks:
            x, y = ax.pos(v)
            for text, b in boxes:
                dx = max(b[0] - x, 0.0, x - b[2])
                dy = max(b[1] - y, 0.0, y - b[3])
                if text != name and math.hypot(dx, dy) <= NEAR_TICK_MM:
                    near = True
                    break
            if near:
                break
        if not near:
            bare.append(ax.name)
    return bare


def test_the_checks_catch_an_overlap_a_text_off_the_frame_and_a_bare_axis():
    from graphmethods.scene import Page, Scale, Scene, Text

    page = Page("A4", "landscape", frame=True)
    x0, y0, _, _ = page.inner_box()
    good = Scene(page, (Text((x0 + 20, y0 + 20), "M_d = 10", size_mm=3.0, name="a"),
                        Text((x0 + 20, y0 + 30), "M_r = 10", size_mm=3.0, name="b")))
    assert text_faults(good) == []
    on_top = good.add(Text((x0 + 22, y0 + 20.5), "ΔW", size_mm=3.0, name="c"))
    assert any("overlaps" in f for f in text_faults(on_top))
    off = good.add(Text((x0 - 3, y0 + 50), "ΔW", size_mm=3.0, name="d"))
    assert any("leaves the frame" in f for f in text_faults(off))
    mu = Scale("μ_M", "N·m", 1.0)
    assert bare_axes(good.add(Axis((60, 100), mu, "y", max_value=50.0, ticks=(10.0, 20.0), name="ok"))) == []
    assert bare_axes(good.add(Axis((60, 100), mu, "y", max_value=50.0, ticks=(0.0,), skip_zero_label=True,
                                   name="bare"))) == ["bare"]


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("problem, figure", CASES, ids=[f"{p}-{f}" for p, f in CASES])
def test_every_figure_keeps_texts_apart_inside_the_frame_with_values_on_its_axes(problem, figure, lang, subjects,
                                                                                  request):
    draw = getattr(sheets, figure)
    if (problem, figure) in NOT_DRAWN:
        with pytest.raises(InputError, match=NOT_DRAWN[problem, figure]):
            draw(subjects(problem), notation=lang)
        return
    if (problem, figure, lang) in KNOWN:
        request.applymarker(pytest.mark.xfail(strict=True, reason=KNOWN[problem, figure, lang]))
    scene = draw(subjects(problem), notation=lang)
    texts = _texts(scene)
    assert text_faults(scene, texts) == []
    assert bare_axes(scene, texts) == []


A1_PROBLEMS = [p for p in builtin.LINKAGES if (p, "dynamic_analysis_sheet") not in NOT_DRAWN]


@pytest.mark.parametrize("problem", A1_PROBLEMS)
def test_the_A1_diagram_takes_the_width_its_curve_needs_and_its_rays_stay_in_its_own_frame(problem, subjects):
    """The energy–mass diagram's J axis is scaled to the room beside the graphs (not to keep rays steep), and
    its rays run from the ordinate axis (or just left of it, for the marks of ψ) to the curve: never across
    the ΔT graph; O1 is said to lie beyond the sheet in the table whenever it is not drawn."""
    study = subjects(problem)
    scene = sheets.dynamic_analysis_sheet(study)
    rec = record(scene)
    x_axis = scene.element("D-axis-T").origin[0]
    T_curve_right = max(x for x, _ in scene.element("T-curve-dT").points)
    table = scene.element("result")
    curve_x = [x for x, _ in scene.element("D-curve").points]
    J = np.asarray(study.J_e, dtype=float)
    room = table.at[0] - T_curve_right
    # J_e's range is its share of the J axis (0…J_e max, which holds k and l at J = 0); the axis gets the room
    # between the graphs and the table less the gaps and names (~20 %), and a convenient μ_J can cost up to half
    assert max(curve_x) - min(curve_x) >= 0.3 * (J.max() - J.min()) / J.max() * room
    T_ax = scene.element("D-axis-T")
    top, bottom = T_ax.tip[1], T_ax.start[1]
    for key in ("max", "min"):
        (pts,) = [c.data[0] for c in rec.in_group(f"D-ray-{key}", "path")]
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        assert min(xs) > T_curve_right + 5.0 and min(xs) >= x_axis - 40.0
        assert max(xs) <= max(curve_x) + 10.0 + 1e-9
        assert min(ys) >= top - 16.0 and max(ys) <= bottom + 10.0 + 1e-9
    drawn = "D-point-O1" in [e.name for e in scene.elements]
    off = [r for r in table.rows if r[0].startswith("O_1")]
    assert off and (("beyond the sheet" in off[0][1]) != drawn)            # said in words, never "(−46446; …) mm"
    assert drawn or "mm" not in off[0][1]
