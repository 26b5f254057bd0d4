"""What the gallery and a class set pay once a process (issue 30, the gallery row): worksheet kinds loaded on
first use, the ink index filled in bulk, extents compared in bulk, SVG points from the formatter's memo, a
region's hatching found once. Every shortcut gives what the plain code gives, to the bit."""

from __future__ import annotations

import dataclasses
import json
import math
import subprocess
import sys

import numpy as np
import pytest

from graphmethods.scene.elements import Region
from graphmethods.scene.numbers import format_mm, format_points
from graphmethods.sheets import layout
from graphmethods.sheets.ink_index import InkIndex


def _fresh(code: str) -> str:
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True)
    return out.stdout.strip()


def test_a_class_set_of_one_kind_loads_no_other_kinds_module():
    found = json.loads(_fresh(
        "import json, sys\n"
        "from graphmethods.sheets.worksheets import worksheet\n"
        "worksheet('acceleration-plan', variants=1, seed=7)\n"
        "print(json.dumps(sorted(m for m in sys.modules if m.startswith('graphmethods.sheets.worksheets.'))))"))
    assert "graphmethods.sheets.worksheets.acceleration_plan" in found
    assert "graphmethods.sheets.worksheets.cam" not in found


def test_a_kind_in_its_own_module_is_there_when_asked_for_by_any_door():
    code = ("from graphmethods.sheets import worksheets as w\n"
            "from graphmethods.sheets.worksheets.variants import CLASSES, GENERATORS, variant_from_dict\n"
            "from graphmethods.sheets.worksheets.pages import PAGES\n"
            "print('cam' in CLASSES, 'cam' in GENERATORS, 'cam' in PAGES, 'nothing' in CLASSES, w.cam.__name__)\n")
    assert _fresh(code) == "True True True False graphmethods.sheets.worksheets.cam"
    # a problem file of a kind not loaded yet reads as before
    code = ("import json\n"
            "from graphmethods.sheets.worksheets import worksheet\n"
            "from graphmethods.sheets.worksheets.variants import variant_from_dict\n"
            "v = worksheet('cam', variants=1, seed=3).variants[0]\n"
            "print(json.dumps([v.to_dict(), v.id]))\n")
    d, id_ = json.loads(_fresh(code))
    again = _fresh("import json\nfrom graphmethods.sheets.worksheets.variants import variant_from_dict\n"
                   f"v = variant_from_dict(json.loads({json.dumps(json.dumps(d))}))\nprint(v.kind, v.id)")
    assert again == f"cam {id_}"


def test_an_unknown_kind_is_still_refused():
    from graphmethods.errors import InputError
    from graphmethods.sheets.worksheets.variants import CLASSES, variants

    assert "nothing" not in CLASSES
    with pytest.raises(KeyError):
        CLASSES["nothing"]
    with pytest.raises(InputError, match="unknown worksheet kind"):
        variants("nothing", count=1, seed=1)


def _segments(seed: int, n: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    start = rng.uniform(-20.0, 220.0, (n, 2))
    length = rng.choice([0.01, 0.5, 3.0, 7.9, 8.0, 30.0, 900.0], n)
    angle = rng.choice([0.0, 90.0, 45.0, 180.0]) if seed % 2 else rng.uniform(0.0, 360.0, n)
    end = start + length[:, None] * np.column_stack((np.cos(np.radians(angle)), np.sin(np.radians(angle))))
    seg = np.column_stack((start, end))
    seg[::17] = np.round(seg[::17] / 8.0) * 8.0          # corners on the grid's lines
    seg[5, 2] = math.inf                                  # non-finite ends: filed always
    seg[9, 1] = math.nan
    return seg


@pytest.mark.parametrize("seed", range(6))
def test_segments_filed_in_bulk_are_found_as_when_filed_one_by_one(seed):
    seg = _segments(seed, 400)
    bulk, single = InkIndex(), InkIndex()
    bulk.add_segments(0, seg[:300])
    bulk.add_segments(300, seg[300:])
    for k, (x0, y0, x1, y1) in enumerate(seg.tolist()):
        single.add_segment(k, x0, y0, x1, y1)
    rng = np.random.default_rng(100 + seed)
    for x, y, w, h in zip(*rng.uniform([-30, -30, 0, 0], [230, 230, 40, 12], (300, 4)).T):
        box = (x, y, x + w, y + h)
        assert bulk.segments_near(box) == single.segments_near(box)
    assert sorted(bulk._seg_all) == sorted(single._seg_all)


def test_near_segments_compared_in_bulk_are_those_of_the_plain_loop(monkeypatch):
    occ = layout.Occupancy()
    for x0, y0, x1, y1 in _segments(1, 2000).tolist():
        if all(map(math.isfinite, (x0, y0, x1, y1))):
            occ.add_line(((x0, y0), (x1, y1)))
    rng = np.random.default_rng(7)
    boxes = [(x, y, x + w, y + h) for x, y, w, h in zip(*rng.uniform([-30, -30, 0, 0], [230, 230, 90, 60],
                                                                      (200, 4)).T)]
    bulk = [occ._near(b, occ._indexed()) for b in boxes]
    monkeypatch.setattr(layout, "_MANY_NEAR", 10**9)
    plain = [occ._near(b, occ._indexed()) for b in boxes]
    assert bulk == plain
    assert any(len(occ._indexed().segments_near(b)) > 96 for b in boxes)      # the bulk path was taken


def test_points_are_written_as_format_mm_writes_each_number():
    pts = ((0.0, -0.0), (1.23449, 2.0005), (np.float64(3.5), 7), (-0.0004, 1e6 / 3), (np.array(2.25), 1.0))
    assert format_points(pts) == " ".join(f"{format_mm(x)},{format_mm(y)}" for x, y in pts)
    assert format_points(((0.1, 0.2),)) == "0.1,0.2" and format_points(()) == ""


def test_a_regions_hatching_is_found_once_and_handed_out_as_a_fresh_list():
    r = Region(((0, 0), (30, 0), (30, 20), (0, 20)), hatch_angle_deg=45, hatch_spacing_mm=2.0,
               keep_clear=((5.0, 5.0, 12.0, 9.0),))
    first = r.hatch_segments()
    first.clear()                                         # the caller's list: the region keeps its own
    again = r.hatch_segments()
    assert again == r._hatch_segments() and len(again) > 5
    assert again is not r.hatch_segments()
    wider = dataclasses.replace(r, hatch_spacing_mm=4.0)  # a changed region finds its own
    assert wider.hatch_segments() == wider._hatch_segments() and len(wider.hatch_segments()) < len(again)
    assert r.primitives() == r.primitives()
