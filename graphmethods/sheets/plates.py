"""Links with three or more joints drawn as plates (ГОСТ 2.770: a ternary link is a rigid triangle, its
outline a main line, its interior hatched), shared by the figures that draw a linkage in a position.

:func:`triangles` finds the plates of a linkage drawn as segments between points (three points joined
pairwise: a triad's basic link); :func:`plate` draws one.

>>> triangles([("B", "C"), ("C", "D"), ("B", "D"), ("A", "B")])
[('B', 'C', 'D')]
>>> [e.name for e in plate([(0.0, 0.0), (30.0, 0.0), (10.0, 20.0)], name="plate-BCD")]
['plate-BCD-hatch', 'plate-BCD']
>>> plate([(0.0, 0.0), (10.0, 0.0), (20.0, 0.0)], name="p")       # joints in a line: a bar, not a plate
[]
"""

from __future__ import annotations

from collections.abc import Sequence

from graphmethods.scene import Element, Polyline
from graphmethods.scene.elements import Region
from graphmethods.scene.primitives import Style

#: the plate's outline: a main line, as the links (ГОСТ 2.303)
OUTLINE = Style(width_mm=0.6)
#: the smallest area (mm²) a plate's outline must enclose: three joints nearly in a line draw as a bar
MIN_AREA_MM2 = 4.0


def triangles(segments: Sequence[tuple[str, str]]) -> list[tuple[str, str, str]]:
    """The triples of points joined pairwise by ``segments`` (each sorted, the list sorted): the plates."""
    pairs = {frozenset(s) for s in segments if s[0] != s[1]}
    names = sorted({p for s in segments for p in s})
    out = []
    for a_i, a in enumerate(names):
        for b_i in range(a_i + 1, len(names)):
            b = names[b_i]
            if frozenset((a, b)) not in pairs:
                continue
            out += [(a, b, c) for c in names[b_i + 1:] if frozenset((a, c)) in pairs and frozenset((b, c)) in pairs]
    return out


def plate(points: Sequence[tuple[float, float]], *, name: str, spacing_mm: float = 3.0) -> list[Element]:
    """A plate through ``points`` (mm, in order round it): its interior hatched at 45° (thin lines
    ``spacing_mm`` apart) and its outline a main line; none when the points enclose no area.

    Parameters
    ----------
    points : sequence of (x, y), mm
        The joints of the link, in order round it.
    name : str
        The outline's element name; the hatching is ``name + "-hatch"``.
    """
    pts = [(float(x), float(y)) for x, y in points]
    area = 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1])))
    if len(pts) < 3 or area < MIN_AREA_MM2:
        return []
    return [Region(tuple(pts), hatch_angle_deg=45.0, hatch_spacing_mm=spacing_mm, name=f"{name}-hatch"),
            Polyline(tuple(pts), style=OUTLINE, closed=True, name=name)]


__all__ = ["plate", "triangles"]
