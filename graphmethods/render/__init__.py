"""graphmethods.render: backends that draw a scene's primitives.

- :mod:`graphmethods.render.svg`: SVG through svgwrite (the only module importing it):
  scale-true, deterministic, atomic ``save(scene, path, overwrite=False)``.
- :mod:`graphmethods.render.pdf`: PDF written directly (multi-page, deterministic, real
  text in Type 3 fonts of the glyphs used).
- :mod:`graphmethods.render.mpl`: PNG through matplotlib's Agg canvas.
- :mod:`graphmethods.render.fonts`: font files and glyphs (DejaVu Sans, a CJK font for
  Chinese) through matplotlib's FreeType wrapper; :mod:`mpl` and :mod:`fonts` are the only
  modules importing matplotlib, lazily.
- :mod:`graphmethods.render.recording`: a renderer that records primitives, for tests.

Importing this package imports neither svgwrite nor matplotlib.
"""

from graphmethods.render.base import Renderer, draw

__all__ = ["Renderer", "draw"]
