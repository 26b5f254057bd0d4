"""The one count of inked cells (engine quality.ink_cells) and the bucketed clash test (boxes_crossed): the
same answers as testing every segment against every cell or label, on random ink and on A1 sheets."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.problems import builtin
from graphmethods.render.recording import record
from graphmethods.scene.elements import label_bbox
from graphmethods.sheets.engine.quality import (
    CELL_MM,
    OVERLAP_MM,
    boxes_crossed,
    cell_grid,
    glyph_box,
    ink_cells,
    measure,
    segments_marked,
)
from graphmethods.sheets.layout import segments_hit_boxes
from graphmethods.sheets.sheet_fill import PartInk, clashes, filled

INNER = (20.0, 10.0, 831.0, 584.0)          # an A1 frame's inside, mm


def _every_pair_cells(seg: np.ndarray, boxes: np.ndarray, inner) -> np.ndarray:
    """The cells by testing every segment against every cell (the measure's count before the buckets)."""
    ox, oy, nx, ny = cell_grid(inner)
    i, j = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    cells = np.column_stack((ox + i.ravel() * CELL_MM, oy + j.ravel() * CELL_MM,
                             ox + (i.ravel() + 1) * CELL_MM, oy + (j.ravel() + 1) * CELL_MM))
    used = np.zeros(len(cells), dtype=bool)
    for chunk in range(0, len(seg), 4000):
        used |= segments_hit_boxes(seg[chunk:chunk + 4000], cells).any(axis=1)
    if len(boxes):
        used |= ((cells[:, None, 0] < boxes[None, :, 2]) & (boxes[None, :, 0] < cells[:, None, 2])
                 & (cells[:, None, 1] < boxes[None, :, 3]) & (boxes[None, :, 1] < cells[:, None, 3])).any(axis=1)
    return used.reshape(nx, ny)


# coordinates on a 0.5 mm lattice: ends on cell lines and on box edges (touching) come often
_coord = st.integers(0, 1700).map(lambda k: k * 0.5)
_segment = st.tuples(_coord, _coord, _coord, _coord)
_box = st.tuples(_coord, _coord, st.integers(0, 60).map(lambda k: k * 0.5),
                 st.integers(0, 20).map(lambda k: k * 0.5)).map(lambda b: (b[0], b[1], b[0] + b[2], b[1] + b[3]))


@settings(max_examples=60, deadline=None)
@given(st.lists(_segment, max_size=40), st.lists(_box, min_size=1, max_size=30))
def test_boxes_crossed_decides_as_every_pair(segs, boxes):
    seg = np.array(segs, dtype=float).reshape(-1, 4)
    b = np.array(boxes, dtype=float)
    expect = segments_hit_boxes(seg, b).any(axis=1) if len(seg) else np.zeros(len(b), dtype=bool)
    assert boxes_crossed(seg, b).tolist() == expect.tolist()


@settings(max_examples=40, deadline=None)
@given(st.lists(_segment, max_size=40), st.lists(_box, max_size=10))
def test_ink_cells_count_as_every_pair(segs, boxes):
    seg = np.array(segs, dtype=float).reshape(-1, 4)
    b = np.array(boxes, dtype=float).reshape(-1, 4)
    assert (ink_cells(seg, b, INNER) == _every_pair_cells(seg, b, INNER)).all()


def test_a_long_line_along_a_cell_line_touches_both_rows():
    ox, oy, nx, ny = cell_grid(INNER)
    seg = np.array([[ox + 1.0, oy + 2 * CELL_MM, ox + 5 * CELL_MM, oy + 2 * CELL_MM]])
    got = ink_cells(seg, np.empty((0, 4)), INNER)
    assert got.sum() == 12 and got[:6, 1:3].all()         # its end on the 6th column's edge touches it too


@pytest.fixture(scope="module")
def press_sheet():
    from graphmethods.sheets.kinematic_analysis_sheet import kinematic_analysis_sheet

    return kinematic_analysis_sheet(builtin.case("press"))


@pytest.mark.parametrize("figure", ["kinematic", "dynamic"])
def test_the_measure_counts_an_a1_sheet_as_every_pair(figure, press_sheet):
    if figure == "kinematic":
        scene = press_sheet
    else:
        from graphmethods.dynamics.study import Study
        from graphmethods.sheets import dynamic_analysis_sheet

        scene = dynamic_analysis_sheet(Study(builtin.case("shaper"), positions=12), notation="ru")
    rec = record(scene)
    seg, in_page = segments_marked(rec, ("page",))
    boxes = np.array([label_bbox(c.data) for c in rec.calls if c.kind == "text"], dtype=float).reshape(-1, 4)
    expect = _every_pair_cells(seg[~in_page], boxes, scene.page.inner_box())
    assert measure(scene).empty_share == float(1.0 - expect.mean())
    ink = PartInk.of(scene, scene.page)                 # the sheets' own count: the same cells
    assert (ink.cells == expect).all() and (filled([ink]) == expect).all()


def test_clashes_of_a_sheets_parts_as_every_pair(press_sheet):
    from graphmethods.scene import Scene
    from graphmethods.sheets.composition import region_page

    bare = region_page(press_sheet.page, press_sheet.page.inner_box())      # no frame, no title block
    parts = [Scene(bare, (g,)) for g in press_sheet.elements[1:]]
    inks = [PartInk.of(s, press_sheet.page) for s in parts]
    labels = [c.data for s in parts for c in record(s).calls if c.kind == "text"]
    glyphs = np.array([glyph_box(lab) for lab in labels])
    boxes = np.array([label_bbox(lab) for lab in labels])
    seg = np.concatenate([segments_marked(record(s))[0] for s in parts])
    hit = np.zeros(len(labels), dtype=bool)
    for chunk in range(0, len(seg), 4000):
        hit |= segments_hit_boxes(seg[chunk:chunk + 4000], glyphs).any(axis=1)
    ox = np.minimum(glyphs[:, None, 2], glyphs[None, :, 2]) - np.maximum(glyphs[:, None, 0], glyphs[None, :, 0])
    oy = np.minimum(boxes[:, None, 3], boxes[None, :, 3]) - np.maximum(boxes[:, None, 1], boxes[None, :, 1])
    expect = int(hit.sum()) + int(np.triu((ox > OVERLAP_MM) & (oy > OVERLAP_MM), k=1).sum())
    assert clashes(inks) == expect == 0
    moved = [PartInk.of(Scene(bare, (g,)), press_sheet.page) for g in press_sheet.elements[1:3]]
    assert clashes(moved + moved[:1]) > 0           # a part set twice: every label on its own twin


@pytest.mark.parametrize("problem, lang", [("press", "en"), ("engine", "ru")])
def test_the_kinematic_sheet_judges_its_division_by_the_measures_count(problem, lang, monkeypatch):
    """The empty share the sheet's search checks (its parts, title and title block) is the measure's of the
    sheet it draws; the engine in ru is the sheet nearest the bound, kept by drawing more divisions."""
    import importlib

    kas = importlib.import_module("graphmethods.sheets.kinematic_analysis_sheet")
    seen: list[float] = []
    judged = kas._empty_share
    monkeypatch.setattr(kas, "_empty_share", lambda sheet, row: seen.append(judged(sheet, row)) or seen[-1])
    scene = kas.kinematic_analysis_sheet(builtin.case(problem), notation=lang)
    q = measure(scene)
    assert seen and seen[-1] == q.empty_share <= 0.5
    assert not q.crossed and not q.overlaps


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(*[st.sampled_from([0.0, 25.5, 45.5, 830.0, 1e6, -1e6, np.inf, -np.inf, np.nan])
                            | st.floats(-50, 900) for _ in range(4)]), max_size=12),
       st.lists(st.tuples(*[st.sampled_from([25.5, 65.5, np.inf, np.nan]) | st.floats(-50, 900)
                            for _ in range(4)]), max_size=6))
def test_ink_cells_count_odd_ink_as_every_pair(segs, boxes):
    """Ink far off the sheet, infinite or not a number (no grid files it), and boxes given either way round
    are counted as testing every pair counts them."""
    seg = np.array(segs, dtype=float).reshape(-1, 4)
    b = np.array(boxes, dtype=float).reshape(-1, 4)
    with np.errstate(all="ignore"):
        assert (ink_cells(seg, b, INNER) == _every_pair_cells(seg, b, INNER)).all()


def test_short_ink_inside_a_cell_marks_that_cell_alone():
    ox, oy, nx, ny = cell_grid(INNER)
    x, y = ox + 3 * CELL_MM, oy + 5 * CELL_MM              # cell (3, 5)'s corner
    seg = np.array([[x + 1.0, y + 1.0, x + 19.0, y + 19.0], [x + 0.0005, y + 4.0, x + 5.0, y + 4.0]])
    got = ink_cells(seg[:1], np.array([[x + 2.0, y + 2.0, x + 8.0, y + 5.0]]), INNER)
    assert got.sum() == 1 and got[3, 5]
    near_edge = ink_cells(seg[1:], np.empty((0, 4)), INNER)    # 0.5 µm from the edge: tested, still one cell
    assert near_edge.sum() == 1 and near_edge[3, 5]
    on_edge = ink_cells(np.array([[x, y + 4.0, x + 5.0, y + 4.0]]), np.empty((0, 4)), INNER)
    assert on_edge.sum() == 2 and on_edge[2, 5] and on_edge[3, 5]
