"""graphmethods.scene: scale-true figures in paper millimetres, independent of any backend.

A :class:`Scene` is a :class:`Page` and a tuple of frozen elements (:class:`Axis`,
:class:`Curve`, :class:`Region`, :class:`Vector`, :class:`Point`, :class:`Dimension`,
:class:`Table`, :class:`Text`, :class:`ScaleCaptions` ...). Physical values reach the
paper only through a :class:`Scale`. Notation profiles (:func:`notation`) give the
symbols and words of the en / ru / zh textbook traditions. Backends in
:mod:`graphmethods.render` draw the scene's primitives.

Importing this package loads numpy only (shapely is imported when a region is hatched).

>>> from graphmethods import scene
>>> mu_E = scene.Scale("μ_E", "J", 10.0)
>>> v = scene.Vector.of((50, 100), value=-550.0, scale=mu_E, angle_deg=90, name="bc")
>>> v.end
(50.0, 155.0)
>>> s = scene.Scene(scene.Page("A4"), (v,), extra_scales=(mu_E,))
>>> s.scales()[0].caption("ru")
'μ_E = 10 Дж/мм'
"""

from graphmethods.scene import markup
from graphmethods.scene.elements import (
    Axis,
    Curve,
    Dimension,
    Element,
    Frame,
    Group,
    Line,
    Point,
    Polyline,
    Region,
    ScaleCaptions,
    SignMark,
    Table,
    Text,
    Vector,
    bbox,
    label_bbox,
    pi_ticks,
)
from graphmethods.scene.notation import NOTATIONS, Notation, get as notation, in_language
from graphmethods.scene.numbers import format_mm, format_value
from graphmethods.scene.page import PAPER, Page, TitleBlock
from graphmethods.scene.primitives import Style
from graphmethods.scene.scale import Scale, pick_angle_scale, pick_scale
from graphmethods.scene.scene import Scene
from graphmethods.scene.ticks import axis_ticks

__all__ = [
    "Axis", "Curve", "Dimension", "Element", "Frame", "Group", "Line", "Point", "Polyline", "Region",
    "ScaleCaptions", "SignMark", "Table", "Text", "Vector", "bbox", "label_bbox", "axis_ticks", "pi_ticks",
    "NOTATIONS", "Notation", "notation", "in_language", "format_mm", "format_value", "PAPER", "Page", "TitleBlock",
    "Style", "Scale", "pick_scale", "pick_angle_scale", "Scene", "markup",
]
