"""The line styles several sheets draw with, each defined once (widths and dashes in mm).

A sheet module keeps a style of its own only when no other sheet draws it.

>>> PROJECTION.width_mm, PROJECTION.dash
(0.13, (1.2, 0.8))
"""

from __future__ import annotations

from graphmethods.scene.primitives import Style

#: thin dashed projection lines (from a graph's point to an axis, between graphs)
PROJECTION = Style(width_mm=0.13, dash=(1.2, 0.8))
#: a graph's parts drawn dashed (the driving and resisting parts of a moment graph, a second curve)
PART = Style(width_mm=0.25, dash=(3.0, 1.2))
#: a level line across a graph (a mean value)
LEVEL = Style(width_mm=0.18, dash=(4.0, 1.5))
#: the rules of a table's cells
CELL = Style(width_mm=0.18)
#: a centre line, dash-dot (an axis of symmetry; a circle or curve of centres: a cam's pitch curve and base
#: circle, a rocker's arc of roller centres)
CENTRE_LINE = Style(width_mm=0.18, dash=(6.0, 1.2, 1.0, 1.2))

__all__ = ["CELL", "CENTRE_LINE", "LEVEL", "PART", "PROJECTION"]
