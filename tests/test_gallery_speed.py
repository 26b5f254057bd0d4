"""The gallery's and the class set's speed-ups change no decision (issue 30): each cheaper path is compared
with the path it replaced, decision by decision or bit by bit. (Times are measured in ``graphmethods bench``,
never asserted here.)"""

import math
import sys

import numpy as np
from hypothesis import given, settings, strategies as st

from graphmethods import bench
from graphmethods.gallery import catalogue
from graphmethods.kinematics.cam import EXAMPLE, cam_from_dict, design
from graphmethods.kinematics.cam.extrema import maximize
from graphmethods.kinematics.cam.geometry import pitch_frame, pressure_angle
from graphmethods.problems.builtin import cam_problem
from graphmethods.scene.elements import Table, label_bbox, make_label
from graphmethods.scene.markup import MIN_TEXT_MM
from graphmethods.sheets.layout import Occupancy

design_module = sys.modules["graphmethods.kinematics.cam.design"]
finite = st.floats(-2.0, 2.0, allow_nan=False)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(finite, finite), min_size=1, max_size=20), st.floats(0.03, 0.2), st.floats(0.05, 0.15))
def test_the_pressure_angle_alone_is_the_pitch_frames_to_the_bit(points, r0, arm):
    s, s1 = (np.array(v) for v in zip(*points))
    pivot = arm + r0 * 0.9                         # r0 reachable: between |a − l| and a + l
    alpha = pressure_angle(r0, s, s1, arm=arm, pivot=pivot)
    full = pitch_frame("oscillating", r0, s, s1, np.zeros_like(s), arm=arm, pivot=pivot).alpha
    assert np.array_equal(alpha, full, equal_nan=True)


@settings(max_examples=150, deadline=None)
@given(st.floats(0.5, 40.0), st.floats(0.0, 6.0), st.floats(-1.5, 1.5))
def test_a_stopped_maximum_answers_is_it_above_as_the_full_one_does(k, phase, threshold):
    def f(t):
        return np.sin(k * t + phase) * np.exp(-0.1 * t)
    full = maximize(f, 0.0, 3.0)
    quick = maximize(f, 0.0, 3.0, stop_above=threshold)
    assert (quick[1] > threshold) == (full[1] > threshold)
    assert quick[1] <= full[1]                     # a grid value, never above the refined maximum
    if not full[1] > threshold or quick == full:
        return
    assert quick[1] > threshold                    # stopped early: still over it


def test_the_oscillating_cams_base_radius_is_the_bisections_to_the_bit():
    # the value the full bisection (every grid radius, every maximum refined) gave before the shortcuts
    assert design_module.design_afresh(cam_problem("oscillating-cam")).pitch_base_radius == 0.03511095122994147


def test_a_design_is_made_once_per_problem_and_equals_a_fresh_one():
    p = cam_from_dict(EXAMPLE)
    assert design(p) is design(cam_from_dict(EXAMPLE))
    assert design_module.design_afresh(p) == design(p)


def _scene(seed: int, n_seg: int, n_box: int) -> Occupancy:
    rng = np.random.default_rng(seed)
    occ = Occupancy()
    for _ in range(n_seg):
        p = rng.uniform(0, 60, 2).round(1)
        q = p + rng.choice([0.0, 1.0], 2) * rng.uniform(-12, 12, 2).round(1)   # axis-parallel, points too
        occ.add_line((p, q))
    for _ in range(n_box):
        x, y = rng.uniform(0, 60, 2).round(1)
        occ.add_box((x, y, x + 6.0, y + 2.5))
    return occ


@settings(max_examples=120, deadline=None)
@given(st.integers(0, 10**6), st.integers(0, 300), st.integers(0, 30), st.integers(1, 16), st.booleans())
def test_free_decides_each_box_as_is_free_does(seed, n_seg, n_box, k, within):
    occ = _scene(seed, n_seg, n_box)
    rng = np.random.default_rng(seed + 1)
    xy = rng.uniform(-5, 60, (k, 2)).round(1)
    boxes = [(x, y, x + w, y + 3.0) for (x, y), w in zip(xy, rng.uniform(1, 25, k).round(1))]
    region = (0.0, 0.0, 55.0, 55.0) if within else None
    got = occ.free(boxes, within=region)
    assert got.tolist() == [occ.is_free(b, within=region) for b in boxes]


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 10**6), st.integers(0, 200), st.integers(0, 20))
def test_first_free_takes_the_first_free_candidate_in_order(seed, n_seg, n_box):
    from graphmethods.scene.elements import place_label

    occ = _scene(seed, n_seg, n_box)
    at = tuple(np.random.default_rng(seed).uniform(5, 55, 2))
    dirs, gaps = ("ne", "nw", "se", "sw", "n", "s", "e", "w"), (1.2, 3.2, 5.7)
    expected = None
    for gap in gaps:
        for d in dirs:
            lab = place_label(at, "v_{B}", d, gap_mm=gap, size_mm=3.5)
            if occ.is_free(label_bbox(lab)):
                expected = lab
                break
        if expected is not None:
            break
    assert occ.first_free(at, "v_{B}", dirs, gaps, 3.5, None) == expected


def test_label_extents_are_measured_as_before():
    lab = make_label((10, 20), "M_{d} = 5^{2}", size_mm=3.5, anchor="middle")
    from graphmethods.scene import markup
    from graphmethods.scene.elements import ASCENT, DESCENT

    w = sum((1.0 if s == 0 else markup.SCRIPT_SCALE) * sum(markup.char_em(c) for c in t) for t, s in lab.runs) * 3.5
    assert label_bbox(lab) == (10 - w / 2, lab.y - (ASCENT + 0.1) * 3.5, 10 - w / 2 + w,
                               lab.y + (DESCENT + markup.SUB_SHIFT) * 3.5)


def test_a_tables_widths_follow_the_lettering_they_are_measured_in():
    t = Table((0, 0), (("i", "A_i, J"), ("1", "50"), ("2", "−550")))
    small = t.column_widths()
    token = MIN_TEXT_MM.set(7.0)
    try:
        big = t.column_widths()
        fresh = Table((0, 0), (("i", "A_i, J"), ("1", "50"), ("2", "−550")))
        assert big == fresh._fitted_widths()
    finally:
        MIN_TEXT_MM.reset(token)
    assert big[1] > small[1] and t.column_widths() == small


def test_the_gallery_reads_a_problem_once_and_problem_afresh_reads_it_again():
    assert catalogue.problem("study:press") is catalogue.problem("study:press")
    assert catalogue.problem_afresh("study:press") is not catalogue.problem("study:press")


def test_paired_processes_time_both_commands_in_turn_and_their_cpu():
    wall, cpu = bench.paired_processes(bench._process("-c", "pass"), bench._process("-c", "pass"), repeat=2)
    assert wall.a > 0 and wall.b > 0
    assert cpu is None or (cpu.a > 0 and cpu.b > 0 and math.isfinite(cpu.ratio))


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 10**6), st.integers(0, 250), st.integers(0, 25), st.booleans())
def test_a_ring_of_leaders_takes_the_first_that_try_leader_takes(seed, n_seg, n_box, strict):
    at = tuple(np.random.default_rng(seed).uniform(10, 50, 2))
    angles = tuple(range(0, 360, 15))
    one, ring = _scene(seed, n_seg, n_box), _scene(seed, n_seg, n_box)
    expected = None
    for ang in angles:
        expected = one.try_leader(at, "F_{21}", 12.0, ang, size_mm=3.5, strict=strict)
        if expected is not None:
            break
    assert ring.try_leaders(at, "F_{21}", 12.0, angles, size_mm=3.5, strict=strict) == expected
    assert ring.boxes == one.boxes and ring.segments == one.segments
