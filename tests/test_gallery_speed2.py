"""Issue 30, second round: the gallery's cheaper paths are the paths they replaced, field by field and bit by
bit. (Times are measured in ``graphmethods bench``, never asserted here.)"""

import dataclasses
import inspect

import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.render import svg
from graphmethods.render.recording import Call
from graphmethods.scene import primitives as P
from graphmethods.scene.elements import label_bbox
from graphmethods.scene.markup import SCRIPT_SCALE, baseline_shift_mm
from graphmethods.scene.numbers import format_mm as fmt, format_points

PRIMITIVES = (P.Style, P.Path, P.Polygon, P.Circle, P.Label, P.Group, Call)


@pytest.mark.parametrize("cls", PRIMITIVES, ids=lambda c: c.__name__)
def test_a_primitives_written_init_takes_its_fields_in_order_with_their_defaults(cls):
    params = list(inspect.signature(cls.__init__).parameters.values())[1:]
    fields = dataclasses.fields(cls)
    assert [p.name for p in params] == [f.name for f in fields]
    assert [p.default for p in params] == [inspect.Parameter.empty if f.default is dataclasses.MISSING
                                          else f.default for f in fields]


def test_a_primitive_is_still_frozen_compared_and_hashed_by_its_fields():
    a = P.Label(1.0, 2.0, (("M", 0), ("d", -1)), 3.5, "middle")
    b = dataclasses.replace(a, anchor="middle")
    assert a == b and hash(a) == hash(b) and a is not b
    assert dataclasses.replace(a, x=3.0) != a
    with pytest.raises(dataclasses.FrozenInstanceError):
        a.x = 5.0  # type: ignore[misc]
    assert repr(P.Group("g", ())) == "Group(name='g', children=())"
    assert P.Path(((0.0, 0.0), (1.0, 0.0))).style is P.THIN and P.Polygon(()).style is P.SOLID_FILL


# ------------------------------------------------------------------ the SVG writer's text, as _tag wrote it
def _old_text(label):
    """SvgRenderer.text as it was: a dict of attributes through _tag."""
    size, x, anchor = label.size_mm, label.x, label.anchor
    if label.stretch != 1.0:
        x, anchor = label_bbox(label)[0], "start"
        transform = f"matrix({fmt(label.stretch)} 0 0 1 {fmt(x * (1.0 - label.stretch))} 0)"
    attrs = {"x": fmt(x), "y": fmt(label.y), "font-size": fmt(size), "xml:space": "preserve"}
    if anchor != "start":
        attrs["text-anchor"] = anchor
    if label.bold:
        attrs["font-weight"] = "bold"
    if label.color != "#000000":
        attrs["fill"] = label.color
    if label.stretch != 1.0:
        attrs["transform"] = transform
    runs = label.runs
    if len(runs) == 1 and runs[0][1] == 0:
        return svg._tag("text", attrs, svg.clean_text(runs[0][0]).translate(svg._CDATA))
    spans, offset = [], 0.0
    for chunk, shift in runs:
        target = baseline_shift_mm(shift, size)
        span = {}
        if abs(target - offset) > 1e-12:
            span["dy"] = fmt(target - offset)
            offset = target
        if shift:
            span["font-size"] = fmt(size * SCRIPT_SCALE)
        spans.append(svg._tag("tspan", span, svg.clean_text(chunk).translate(svg._CDATA)))
    return svg._tag("text", attrs, "".join(spans))


def _written(draw):
    r = svg.SvgRenderer()
    r.begin(100.0, 100.0, title="", name="t")
    draw(r)
    return r._out[-1].strip()


coord = st.floats(-500.0, 500.0, allow_nan=False)
texts = st.text(alphabet="aM_<&>\"'\x01 ψ₁", max_size=6)
runs = st.lists(st.tuples(texts, st.sampled_from((0, -1, 1))), max_size=4).map(tuple)
colours = st.sampled_from(("#000000", "#ff0000", 'a"b<'))
styles = st.builds(P.Style, st.sampled_from((None, "#000000", "#a<b")), st.sampled_from((0.0, 0.18, 0.35)),
                   st.sampled_from((None, (), (2.0, 1.0), (0.5, 1.25, 3.0))), st.sampled_from((None, "#ffffff", "")))


@settings(max_examples=300, deadline=None)
@given(coord, coord, runs, st.sampled_from((2.5, 3.5, 7.0)), st.sampled_from(("start", "middle", "end")),
       st.booleans(), colours, st.sampled_from((1.0, 0.8)))
def test_a_label_is_written_as_the_attribute_dict_wrote_it(x, y, r, size, anchor, bold, colour, stretch):
    label = P.Label(x, y, r, size, anchor, bold, colour, stretch)
    assert _written(lambda w: w.text(label)) == _old_text(label)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(coord, coord), min_size=1, max_size=5).map(tuple), styles, st.booleans(), coord)
def test_paths_polygons_and_circles_are_written_as_the_attribute_dict_wrote_them(points, style, closed, r):
    old = svg.SvgRenderer._stroke
    pts = format_points(points)
    assert _written(lambda w: w.path(points, style, closed)) == svg._tag(
        "polygon" if closed else "polyline", old({"points": pts}, style, False))
    assert _written(lambda w: w.polygon(points, style)) == svg._tag("polygon", old({"points": pts}, style, True))
    assert _written(lambda w: w.circle(points[0][0], points[0][1], abs(r), style)) == svg._tag(
        "circle", old({"cx": fmt(points[0][0]), "cy": fmt(points[0][1]), "r": fmt(abs(r))}, style, True))


# ------------------------------------------------------------------ Occupancy's segments as an array
@settings(max_examples=200, deadline=None)
@given(st.lists(st.lists(st.tuples(coord, coord), min_size=0, max_size=14), max_size=8), st.integers(0, 8))
def test_the_segment_array_holds_the_segments_added_as_their_list_does(lines, asked_after):
    import numpy as np

    from graphmethods.sheets.layout import Occupancy

    occ = Occupancy()
    for i, pts in enumerate(lines):
        occ.add_line(np.array(pts).reshape(-1, 2) if i % 2 else pts)
        if i == asked_after:
            occ.segment_array()                  # asked for part way: the rest appended later
    assert np.array_equal(occ.segment_array(), np.asarray(occ.segments, dtype=float).reshape(-1, 4))
    assert all(type(c) is float for s in occ.segments for p in s for c in p)
    if occ.segments:                             # the list edited by hand: read from it
        occ.segments.append(((1.5, 2.5), (3.5, 4.5)))
        assert occ.segment_array()[-1].tolist() == [1.5, 2.5, 3.5, 4.5] and occ._flat is None


def test_slider_diagrams_from_shared_references_are_those_computed_alone():
    import numpy as np

    from graphmethods.dynamics import graphical_calculus as gc
    from graphmethods.problems import builtin

    for name in ("press", "shaper"):
        case = builtin.case(name)
        mech, w = case.mechanism, float(case.omega_m)
        refs = gc.slider_references(mech, 12, omega_1=w)
        for mu in (1.0, 0.004):
            a = gc.slider_diagrams(mech, 12, mu_phi=mu, mu_s=mu, omega_1=w, references=refs)
            b = gc.slider_diagrams(mech, 12, mu_phi=mu, mu_s=mu, omega_1=w)
            for f in ("phi", "s", "v_plans", "a_plans", "v_exact", "a_exact"):
                assert np.array_equal(getattr(a, f), getattr(b, f)), f
            assert np.array_equal(a.v.values, b.v.values) and np.array_equal(a.a.values, b.a.values)
        other = gc.slider_diagrams(mech, 8, mu_phi=1.0, mu_s=1.0, omega_1=w, references=refs)    # not its refs
        assert len(other.phi) == len(gc.slider_diagrams(mech, 8, mu_phi=1.0, mu_s=1.0, omega_1=w).phi)
