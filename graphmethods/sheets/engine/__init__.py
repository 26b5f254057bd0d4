"""The layout engine under every figure and sheet (issue 26): panels, composition, lettering, labels, axes.

A figure is a recipe on this engine: compute (or receive) the data, declare panels, add elements.
No millimetre literal in a recipe that the engine could derive.

- **Lettering** (:mod:`.lettering`): one table of text sizes per page format, from the standard series
  (ГОСТ 2.304 / GB/T 14691): :func:`lettering` ``("A1")`` gives labels 3.5 mm, values 5, titles 7; A4
  goes down to 2.5. A figure drawn into a region of an A1 sheet letters as A1 (the region's page keeps
  the sheet's size).
- **Panels** (:mod:`.panel`): :class:`Panel` ``(box, extent, symbol=, unit=)`` states its content in model
  units and gets the largest convenient scale (1, 2, 2.5, 4, 5 × 10ᵏ, :func:`graphmethods.scene.scale.
  pick_scale`) that fits its box; ``panel.to_page(x, y)`` maps model points (y up) to the page, centred;
  ``panel.fill`` says how full it is. :func:`extent_of` gives the extent of points (a plan's tips).
- **Composition** (:mod:`.compose`): :class:`Split` ``("h" | "v", ((name_or_split, share), ...), gap_mm=)``
  divides a box (GridSpec in spirit); :meth:`Split.boxes` gives each panel its box; :func:`shares_for`
  turns what the panels need at a common scale into shares so every drawing fills its box;
  :func:`course_page` is the framed A1/A2 course sheet, the A4 figure page or the 16:9 slide.
- **Axes** (:mod:`.axes`): :func:`nice_ticks` ``(lo, hi, max_n)`` is MaxNLocator's rule (every tick
  labelled, none repeated, the axis clipped to the data); :func:`axis_range` decides whether an axis
  starts at 0 or is broken at a round J₀ when the data sit far from zero, and :func:`broken_axis_mark`
  draws the break.
- **Labels against ink** (:mod:`.labels`): :class:`Ink` registers what is drawn (segments, arrowheads,
  hatching, circles, texts with real extents) and :meth:`Ink.place` puts a label at the first free of its
  candidates (eight compass points, then along its line), with a leader when nothing near is free;
  deterministic (the ``TIE_MM`` quantum of :mod:`graphmethods.sheets.layout`).
- **Quality** (:mod:`.quality`): :func:`measure` a scene as drawn (empty 20 mm cells, smallest text,
  labels crossed by ink, text over text, round-off printed as working) and :func:`faults` against the
  standard; ``tests/test_figure_quality.py`` runs it over every sheet and figure.

>>> from graphmethods.sheets.engine import Panel, Split, course_page, lettering, nice_ticks
>>> page = course_page("A1")
>>> boxes = Split("h", (("scheme", 2), ("plans", 3)), gap_mm=10).boxes(page.inner_box())
>>> p = Panel(boxes["scheme"], (-0.2, -0.1, 0.6, 0.5), symbol="μ_l", unit="m")
>>> p.scale.caption(), lettering(page).label_mm, nice_ticks(0, 770, 5)
('μ_l = 0.0025 m/mm', 3.5, (0.0, 200.0, 400.0, 600.0, 800.0))
"""

from graphmethods.sheets.engine.axes import AxisRange, axis_range, broken_axis_mark, nice_step, nice_ticks
from graphmethods.sheets.engine.compose import GAP_MM, Split, course_page, shares_for
from graphmethods.sheets.engine.labels import COMPASS, Ink
from graphmethods.sheets.engine.lettering import LETTERING, SERIES_MM, Lettering, is_course_sheet, lettered, lettering
from graphmethods.sheets.engine.panel import Panel, extent_of

__all__ = ["COMPASS", "GAP_MM", "LETTERING", "SERIES_MM", "AxisRange", "Ink", "Lettering", "Panel", "Split",
           "axis_range", "broken_axis_mark", "course_page", "extent_of", "is_course_sheet", "lettered", "lettering",
           "nice_step", "nice_ticks", "shares_for"]
