"""The gallery: one small module per textbook figure, each defining ``build() -> Scene``.

The modules ship with the package, so ``graphmethods gallery --out DIR`` builds every figure from
an installed wheel; a source checkout keeps each figure's committed golden SVG (and the PNGs the
README shows) in its top-level ``gallery/`` folder, and the tests compare them. A module that sets
``PNG = True`` also has its PNG rewritten by ``graphmethods gallery --regenerate``.

>>> names = figure_names()
>>> "w1_energy_indicator_zh" in names and names == sorted(names)
True
"""

from __future__ import annotations

import importlib
import pkgutil
from types import ModuleType


def figure_names() -> list[str]:
    """The names of the built-in figures (the modules of this package), sorted."""
    return sorted(m.name for m in pkgutil.iter_modules(__path__) if not m.name.startswith("_"))


def figure_module(name: str) -> ModuleType:
    """The module of one built-in figure, by name (e.g. ``"press_wittenbauer_en"``)."""
    return importlib.import_module(f"{__name__}.{name}")
