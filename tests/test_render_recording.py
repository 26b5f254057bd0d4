"""The recording renderer: geometry of what a scene draws, without pixels."""


import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.errors import InputError
from graphmethods.render.base import Renderer, draw
from graphmethods.render.recording import RecordingRenderer, record
from graphmethods.scene import Axis, Group, Page, Scale, Scene, Text, Vector


def test_the_recording_renderer_is_a_renderer():
    assert isinstance(RecordingRenderer(), Renderer)


@given(st.lists(st.floats(min_value=-1000, max_value=1000).filter(lambda v: abs(v) > 1e-2), min_size=1, max_size=8),
       st.sampled_from([2.0, 5.0, 10.0]))
@settings(max_examples=30)
def test_head_to_tail_vectors_have_their_lengths_and_close_like_the_sum(values, per_mm):
    mu = Scale("μ_E", "J", per_mm)
    x, y, els = 100.0, 300.0, []
    for i, v in enumerate(values):
        vec = Vector.of((x, y), value=v, scale=mu, angle_deg=90, name=f"v{i}")
        els.append(vec)
        x, y = vec.end[0] + 5.0, vec.end[1]
    rec = record(Scene(Page("A1"), tuple(els)))
    for i, v in enumerate(values):
        assert rec.vector_length_mm(f"v{i}") == pytest.approx(abs(v) / per_mm, abs=1e-9)
    drop_mm = 300.0 - els[-1].end[1]
    assert drop_mm == pytest.approx(sum(values) / per_mm, abs=1e-9)


def test_groups_nest_and_queries_find_their_primitives():
    mu = Scale("μ_M", "N·m", 2.0)
    scene = Scene(Page("A4"), (Group((Axis((20, 100), mu, "y", max_value=40, ticks=(0, 20), name="ax"),
                                      Text((5, 5), "M_d", name="lab")), name="diagram"),))
    rec = record(scene)
    assert rec.group_ids() == ["diagram", "ax", "lab"]
    assert rec.texts("lab") == ["Md"]
    assert set(rec.texts("diagram")) == {"0", "20", "Md"}
    assert rec.width_mm == 297 and rec.height_mm == 210
    with pytest.raises(InputError, match="no group"):
        rec.in_group("nothing")


def test_draw_returns_what_the_renderer_ends_with():
    assert isinstance(draw(Scene(Page("A4")), RecordingRenderer()), RecordingRenderer)
