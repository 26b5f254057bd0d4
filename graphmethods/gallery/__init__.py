"""The gallery: the built-in textbook figures, one row each in :mod:`graphmethods.gallery.catalogue`.

The catalogue ships with the package, so ``graphmethods gallery --out DIR`` builds every figure from
an installed wheel; a source checkout keeps each figure's committed golden SVG (and the PNGs the
README shows) in its top-level ``gallery/`` folder, and the tests compare them. A row with
``png=True`` also has its PNG rewritten by ``graphmethods gallery --regenerate``.

>>> names = figure_names()
>>> "w1_energy_indicator_zh" in names and names == sorted(names)
True
>>> figure("w1_energy_indicator_zh").language
'zh'
"""

from __future__ import annotations

from graphmethods.gallery.catalogue import CATALOGUE, Figure, figure


def figure_names() -> list[str]:
    """The names of the built-in figures, sorted."""
    return sorted(f.name for f in CATALOGUE)


def figure_module(name: str) -> Figure:
    """The catalogue row of one built-in figure (it has ``build()``, as a script of ``--dir`` has)."""
    return figure(name)


__all__ = ["CATALOGUE", "Figure", "figure", "figure_module", "figure_names"]
