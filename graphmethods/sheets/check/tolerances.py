"""The drafting tolerances a hand drawing is checked against, defined once for every check (typed answers,
acceleration plans, drawings read from SVG or DXF).

A length or a position is right within :data:`TOL_MM` on paper (plus :data:`TOL_REL` of a value read off
it), a direction within :data:`TOL_DEG` plus the angle :data:`TOL_MM` subtends at the line's length.

>>> TOL_MM, TOL_DEG, TOL_REL
(0.5, 0.5, 0.001)
"""

from __future__ import annotations

#: drafting tolerance of a length or a point on paper, mm
TOL_MM = 0.5
#: drafting tolerance of a direction, degrees (plus the angle TOL_MM subtends at the line's length)
TOL_DEG = 0.5
#: relative tolerance of a value computed from the drawing (a scale stated, a value read off), 0.1 %
TOL_REL = 1e-3
