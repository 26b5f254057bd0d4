"""Label placement's free-space test, vectorised, decides exactly as the plain clipping test, and its
ties do not hang on the last bit.

:meth:`Occupancy.is_free` and :meth:`Occupancy.crossings` run over numpy arrays with a
bounding-box prefilter; here they are compared, decision by decision, with the scalar
Liang–Barsky test :func:`graphmethods.sheets.layout._segment_hits_box` and the scalar box test
written out below, on random scenes and on the hard cases (axis-parallel and zero-length
segments, segments that end on a box edge, boxes that touch).
"""

from hypothesis import given, settings, strategies as st

from graphmethods.sheets import layout
from graphmethods.sheets.layout import Occupancy, _segment_hits_box


def plain_is_free(occ: Occupancy, box, *, within=None, lines=True) -> bool:
    """The rule written out: padded boxes clear of each other unless they overlap by more than the tie
    quantum; a line within the tie quantum of the padded box crosses it; a box may pass its region by it."""
    pad, tie = occ.pad, layout.TIE_MM
    if within is not None and not (box[0] >= within[0] - tie and box[1] >= within[1] - tie
                                   and box[2] <= within[2] + tie and box[3] <= within[3] + tie):
        return False
    g = (box[0] - (pad - tie), box[1] - (pad - tie), box[2] + (pad - tie), box[3] + (pad - tie))
    if any(g[0] < b[2] and b[0] < g[2] and g[1] < b[3] and b[1] < g[3] for b in occ.boxes):
        return False
    g = (box[0] - (pad + tie), box[1] - (pad + tie), box[2] + (pad + tie), box[3] + (pad + tie))
    return not lines or not any(_segment_hits_box(p, q, g) for p, q in occ.segments)


def plain_crossings(occ: Occupancy, boxes) -> list[int]:
    d = occ.pad + layout.TIE_MM
    return [sum(_segment_hits_box(p, q, (b[0] - d, b[1] - d, b[2] + d, b[3] + d)) for p, q in occ.segments)
            for b in boxes]


# coordinates on a 0.5 mm grid make ties (a segment ending on an edge, boxes touching) common
coord = st.integers(0, 80).map(lambda i: i * 0.5)
fine = st.floats(0.0, 40.0, allow_nan=False)
point = st.tuples(st.one_of(coord, fine), st.one_of(coord, fine))
box = st.tuples(point, st.floats(0.0, 6.0), st.floats(0.0, 4.0)).map(
    lambda t: (t[0][0], t[0][1], t[0][0] + t[1], t[0][1] + t[2]))


@settings(max_examples=300, deadline=None)
@given(st.lists(st.lists(point, min_size=1, max_size=5), max_size=12), st.lists(box, max_size=6),
       st.lists(box, min_size=1, max_size=12), st.sampled_from([0.0, 0.6]))
def test_is_free_and_crossings_decide_as_the_plain_test(lines, boxes, probes, pad):
    occ = Occupancy(pad_mm=pad)
    for pts in lines:
        occ.add_line(pts)
    for b in boxes:
        occ.add_box(b)
    within = (2.0, 2.0, 38.0, 38.0)
    few = layout._FEW
    try:
        for layout._FEW in (0, few):            # the numpy path for every query, then the hybrid one
            for b in probes:
                assert occ.is_free(b) == plain_is_free(occ, b)
                assert occ.is_free(b, lines=False) == plain_is_free(occ, b, lines=False)
                assert occ.is_free(b, within=within) == plain_is_free(occ, b, within=within)
    finally:
        layout._FEW = few
    assert occ.crossings(probes).tolist() == plain_crossings(occ, probes)
    for kw in ({}, {"lines": False}, {"within": within}):      # all candidates at once, the same decisions
        assert occ.free(probes, **kw).tolist() == [plain_is_free(occ, b, **kw) for b in probes], kw


def test_registering_after_a_query_is_seen_by_the_next_one():
    occ = Occupancy()
    assert occ.is_free((10, 10, 20, 12))
    occ.add_line(((0, 11), (100, 11)))
    assert not occ.is_free((10, 10, 20, 12)) and occ.crossings([(10, 10, 20, 12), (10, 20, 20, 22)]).tolist() == [1, 0]
    occ.add_box((30, 30, 31, 31))
    assert not occ.is_free((30.5, 30.5, 40, 40), lines=False)
    assert occ._line_blocked((25, 25), (35, 35)) and not occ._line_blocked((25, 40), (35, 40))


def test_hard_cases_decide_as_the_plain_test():
    occ = Occupancy(pad_mm=0.0)
    occ.add_line(((10.0, 0.0), (10.0, 5.0)))          # vertical, ends on the probe's edge below
    occ.add_line(((0.0, 20.0), (5.0, 20.0)))          # horizontal, ends on the probe's left edge
    occ.add_line(((50.0, 50.0), (50.0, 50.0)))        # a point
    for b in ((8.0, 5.0, 12.0, 7.0), (5.0, 18.0, 9.0, 22.0), (49.0, 49.0, 51.0, 51.0), (50.0, 50.0, 52.0, 52.0),
              (10.0 + 1e-12, 0.0, 11.0, 1.0), (0.0, 20.0 + 1e-12, 5.0, 21.0)):
        assert occ.is_free(b) == plain_is_free(occ, b), b
        assert occ.free([b]).tolist() == [plain_is_free(occ, b)], b


def test_a_tie_is_settled_the_same_way_whatever_the_last_bits():
    """A line's label placed at the line's end with a gap equal to the padding touches the line exactly;
    numpy versions differ in the last bit of such coordinates. Every spelling of the touch within 1e-9 mm
    decides alike: the line crosses the label, a box touching another is clear of it, a box on its region's
    edge is inside; beyond the quantum the plain geometry decides."""
    occ = Occupancy(pad_mm=0.6)
    occ.add_line(((0.0, 10.0), (30.0, 10.0)))              # ends at x = 30
    occ.add_box((50.0, 0.0, 60.0, 5.0))
    x = 30.0 + 0.6                                          # the label's left edge, padded, on the line's end
    within = (x, 0.0, 100.0, 100.0)
    for ulp in (-3, -1, 0, 1, 3):
        e = ulp * 2.0 ** -44                                # a few last bits at this size (≈ 6e-14 mm each)
        label = (x + e, 8.0, x + 6.0 + e, 12.0)
        assert not occ.is_free(label) and occ.crossings([label]).tolist() == [1], ulp
        assert occ.is_free(label, lines=False), ulp
        assert occ.is_free((x + e, 1.0, 49.4 + e, 4.0), within=within), ulp        # padded, touches the box
        assert not occ.is_free((x - 1e-8, 1.0, 40.0, 4.0), within=within)            # beyond the quantum: out
    assert occ.is_free((x + 1e-8, 8.0, x + 6.0, 12.0))                             # beyond it: clear of the line
    assert not occ.is_free((40.0, 1.0, 49.4 + 1e-8, 4.0))                          # and into the box


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(st.floats(-1e4, 1e4), st.floats(-1e4, 1e4), st.floats(-1e4, 1e4), st.floats(-1e4, 1e4)),
                max_size=30),
       st.lists(st.tuples(st.floats(-1e4, 1e4), st.floats(-1e4, 1e4), st.floats(0, 3e3), st.floats(0, 3e3)),
                max_size=10),
       st.lists(st.tuples(st.floats(-1e4, 1e4), st.floats(-1e4, 1e4), st.floats(-2.0, 40.0), st.floats(-2.0, 40.0)),
                min_size=1, max_size=8))
def test_the_grid_index_misses_nothing_far_long_or_inverted(segs, boxes, probes):
    """Long lines across many cells, big boxes, boxes given inverted: the indexed tests decide as the plain one."""
    occ = Occupancy()
    for x0, y0, x1, y1 in segs:
        occ.add_line(((x0, y0), (x1, y1)))
    for x, y, w, h in boxes:
        occ.add_box((x, y, x + w, y + h))
    cand = [(x, y, x + w, y + h) for x, y, w, h in probes]
    assert occ.free(cand).tolist() == [plain_is_free(occ, b) for b in cand]
    assert [occ.is_free(b) for b in cand] == [plain_is_free(occ, b) for b in cand]
    assert occ.crossings(cand).tolist() == plain_crossings(occ, cand)


def test_non_finite_ink_is_looked_at_by_every_query():
    occ = Occupancy()
    occ.add_line(((float("nan"), 0.0), (5.0, 5.0)))
    occ.add_line(((0.0, 0.0), (float("inf"), 0.0)))
    occ.add_box((float("-inf"), 0.0, 1.0, 1.0))
    probes = [(2.0, -1.0, 4.0, 1.0), (0.0, 0.2, 0.5, 0.8), (50.0, 50.0, 52.0, 53.0)]
    assert occ.free(probes).tolist() == [plain_is_free(occ, b) for b in probes]


def test_lists_cut_by_hand_are_indexed_anew():
    occ = Occupancy()
    occ.add_line(((0.0, 10.0), (100.0, 10.0)))
    occ.add_box((40.0, 20.0, 60.0, 22.0))
    assert occ.free([(40, 9, 60, 11), (41, 20.5, 45, 21.5)]).tolist() == [False, False]
    occ.segments.clear()
    occ.boxes.clear()
    occ.add_box((0.0, 0.0, 1.0, 1.0))
    assert occ.free([(40, 9, 60, 11), (41, 20.5, 45, 21.5)]).tolist() == [True, True]
    assert occ.is_free((0.5, 0.5, 0.8, 0.8)) is False


@settings(max_examples=200, deadline=None)
@given(st.lists(st.lists(point, min_size=1, max_size=8), max_size=16), st.lists(box, max_size=6),
       st.lists(box, min_size=1, max_size=12), st.sampled_from([0.0, 0.6]), st.sampled_from([0, 48]))
def test_free_over_numpy_arrays_decides_as_the_plain_test(lines, boxes, probes, pad, few):
    """Many boxes against many near segments (``free`` compares them over numpy arrays): the same decisions."""
    occ = Occupancy(pad_mm=pad)
    for pts in lines:
        occ.add_line(pts)
    for b in boxes:
        occ.add_box(b)
    many, was_few = layout._MANY_PAIRS, layout._FEW
    try:
        layout._MANY_PAIRS, layout._FEW = 0, few
        assert occ.free(probes).tolist() == [plain_is_free(occ, b) for b in probes]
        assert occ.free(probes, within=(2.0, 2.0, 38.0, 38.0)).tolist() == \
            [plain_is_free(occ, b, within=(2.0, 2.0, 38.0, 38.0)) for b in probes]
    finally:
        layout._MANY_PAIRS, layout._FEW = many, was_few
