"""Checks every figure test applies: the drawing stays inside the frame, and no two labels overlap."""

import itertools

from graphmethods.scene.elements import label_bbox
from graphmethods.scene.primitives import Label


def assert_fits_and_labels_apart(scene, fid: str, *, overlap_mm: float = 0.3) -> None:
    """Nothing outside the page's inner box; no two labels overlapping by more than ``overlap_mm`` both ways."""
    x0, y0, x1, y1 = scene.page.inner_box()
    bx = scene.bbox()
    assert bx[0] >= x0 - 1e-6 and bx[1] >= y0 - 1e-6 and bx[2] <= x1 + 1e-6 and bx[3] <= y1 + 1e-6, (fid, bx)
    labels = [p for p in scene.primitives() if isinstance(p, Label)]
    boxes = [label_bbox(lab) for lab in labels]
    for (i, a), (j, b) in itertools.combinations(enumerate(boxes), 2):
        ox = min(a[2], b[2]) - max(a[0], b[0])
        oy = min(a[3], b[3]) - max(a[1], b[1])
        assert ox <= overlap_mm or oy <= overlap_mm, f"{fid}: {labels[i].text!r} overlaps {labels[j].text!r}"
