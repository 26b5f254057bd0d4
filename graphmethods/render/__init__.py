"""graphmethods.render: backends that draw a scene's primitives.

- :mod:`graphmethods.render.svg`: SVG written as text from the primitives (no SVG library):
  scale-true, deterministic, atomic ``save(scene, path, overwrite=False)``.
- :mod:`graphmethods.render.pdf`: PDF written directly (multi-page, deterministic, real
  text in embedded subsets of the fonts: Type 0 / CID fonts with ToUnicode maps).
- :mod:`graphmethods.render.mpl`: PNG through matplotlib's Agg canvas.
- :mod:`graphmethods.render.fonts`: font files and glyphs (DejaVu Sans, the Simplified
  Chinese face of a CJK font), measured and subset from the font file's bytes by
  :mod:`graphmethods.render.sfnt` (fontTools only for CFF outlines, matplotlib only to find a CJK font);
  :mod:`mpl` and :mod:`fonts` are the only modules importing matplotlib, lazily.
- :mod:`graphmethods.render.recording`: a renderer that records primitives, for tests.

Importing this package imports no drawing library (matplotlib, ezdxf).
"""

from graphmethods.render.base import Renderer, draw

__all__ = ["Renderer", "draw"]
