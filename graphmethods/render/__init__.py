"""graphmethods.render: backends that draw a scene's primitives.

- :mod:`graphmethods.render.svg`: SVG through svgwrite (the only module importing it):
  scale-true, deterministic, atomic ``save(scene, path, overwrite=False)``.
- :mod:`graphmethods.render.mpl`: PDF (multi-page, deterministic) and PNG through
  matplotlib (the only module importing it, lazily).
- :mod:`graphmethods.render.recording`: a renderer that records primitives, for tests.

Importing this package imports neither svgwrite nor matplotlib.
"""

from graphmethods.render.base import Renderer, draw

__all__ = ["Renderer", "draw"]
