"""The cam sheet's constructions as stand-alone A4 figures (``graphmethods cam CASE --figures DIR``).

Each figure is one panel of the A1 cam sheet (:mod:`graphmethods.sheets.cam_sheet`) drawn alone on an A4
page with its title block (the figure, the problem, its scales), by the same recipes, so every number
is the sheet's and ``graphmethods cam --json``'s:

- :func:`cam_motion_diagrams` (A4 portrait): the acceleration analogue with its strips and pole, the
  velocity analogue and the displacement by the method of chords (for a uniform phase, the impulses to
  ∞ at its ends, the hard impacts);
- :func:`cam_combined_diagram`: the combined ds/dφ–s diagram of a translating follower, or the rocker's
  construction (:mod:`graphmethods.sheets.cam_rocker`), with the tangents at [α] and the zone of the cam
  centre;
- :func:`cam_pressure_angle`: α(φ) over the cycle with the limits (a flat face: its radius of
  curvature ρ(φ));
- :func:`graphmethods.sheets.cam_sheet.cam_inversion`: the profile by inversion of motion.

>>> from graphmethods.problems.builtin import cam_problem
>>> s = cam_motion_diagrams(cam_problem("shaper-cam"))
>>> s.page.size, s.page.orientation
('A4', 'portrait')
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.kinematics.cam import CamDesign, CamProblem, design
from graphmethods.scene import Page, Scale, Scene, TitleBlock, notation as get_notation
from graphmethods.scene.elements import Element
from graphmethods.scene.notation import Notation
from graphmethods.sheets.cam_diagrams import alpha_graph, combined_diagram, motion_column, nodes, rho_graph
from graphmethods.sheets.cam_rocker import rocker_diagram
from graphmethods.sheets.engine import lettering
from graphmethods.sheets.frame import FastOccupancy
from graphmethods.sheets.layout import Box, Occupancy

#: a figure's drawing: (box, occupancy, notation) -> (elements, scales)
Draw = Callable[[Box, Occupancy, Notation], tuple[list[Element], list[Scale]]]


def _designed(cam: CamDesign | CamProblem) -> CamDesign:
    return design(cam) if isinstance(cam, CamProblem) else cam


def a4_figure(cam: CamDesign, nt: Notation, title: str, draw: Draw, *, orientation: str = "landscape",
              name: str) -> Scene:
    """One cam construction on an A4 page with its title block (figure, problem, every scale it drew) in the
    A4 lettering (:func:`graphmethods.sheets.engine.lettering`)."""
    head = (nt.word("figure"), nt.word("problem"), nt.word("scales"))
    problem = cam.problem.title.title_in(nt.code)
    page = Page("A4", orientation, frame=True)
    size = lettering("A4").label_mm
    block = TitleBlock(title, problem, ("μ",) * 2, headings=head, size_mm=size)
    els, scales = draw(page.with_(title_block=block).content_box(), FastOccupancy(), nt)
    captions = [s.caption(nt) for s in scales]
    more = tuple(";  ".join(captions[i:i + 2]) for i in range(2, len(captions), 2))    # a row per two more
    page = page.with_(title_block=replace(block, scales=tuple(captions[:2]), scale_rows=more))
    return Scene(page, tuple(els), title=title, notation=nt.code, name=name, extra_scales=tuple(scales))


def cam_motion_diagrams(cam: CamDesign | CamProblem, *, notation: Any = "en", n_div: int = 8,
                        name: str = "cam-motion-diagrams") -> Scene:
    """The motion diagrams by graphical integration, on A4 portrait (see the module docstring).

    Parameters
    ----------
    cam : CamDesign or CamProblem
    notation : {"en", "ru", "zh"}
    n_div : int
        Strips per rise and per return.
    """
    cam = _designed(cam)
    nt = get_notation(notation)

    def draw(box: Box, occ: Occupancy, nt: Notation) -> tuple[list[Element], list[Scale]]:
        els, scales, _ = motion_column(cam, box, occ, nt, n_div=n_div)
        return els, scales
    return a4_figure(cam, nt, nt.word("cam.fig_motion"), draw, orientation="portrait", name=name)


def cam_combined_diagram(cam: CamDesign | CamProblem, *, notation: Any = "en", n_div: int = 8,
                         name: str = "cam-combined-diagram") -> Scene:
    """The combined diagram (translating) or the rocker's construction (oscillating), on A4 landscape.

    >>> from graphmethods.problems.builtin import cam_problem
    >>> s = cam_combined_diagram(cam_problem("oscillating-cam"))
    >>> "c-zone" in [e.name for e in s.elements]
    True
    """
    cam = _designed(cam)
    nt = get_notation(notation)
    if cam.problem.contact == "flat":
        raise InputError("a flat-faced follower has no combined ds/dφ–s diagram (its base radius comes from the "
                         "radius of curvature: see the pressure-angle figure, which draws ρ(φ))")

    def draw(box: Box, occ: Occupancy, nt: Notation) -> tuple[list[Element], list[Scale]]:
        if cam.problem.oscillating:
            phi_k = np.degrees(nodes(cam, n_div)[:-1])
            els, mu = rocker_diagram(cam, box, occ, nt, phi_k_deg=phi_k, heading_share=0.6)
        else:
            els, mu = combined_diagram(cam, box, occ, nt)
        return els, [mu]
    title = nt.word("cam.fig_rocker" if cam.problem.oscillating else "cam.fig_combined")
    return a4_figure(cam, nt, title, draw, name=name)


def cam_pressure_angle(cam: CamDesign | CamProblem, *, notation: Any = "en",
                       name: str = "cam-pressure-angle") -> Scene:
    """α(φ) over the cycle with ±[α] (a flat face: ρ(φ) with ρ_min), on A4 landscape."""
    cam = _designed(cam)
    nt = get_notation(notation)
    flat = cam.problem.contact == "flat"

    def draw(box: Box, occ: Occupancy, nt: Notation) -> tuple[list[Element], list[Scale]]:
        return (rho_graph if flat else alpha_graph)(cam, box, occ, nt)
    return a4_figure(cam, nt, nt.word("cam.rho_graph" if flat else "cam.alpha_graph"), draw, name=name)


#: the figures ``--figures`` writes: file key -> figure function (name under :mod:`graphmethods.sheets`)
FIGURES = {"motion_diagrams": "cam_figures.cam_motion_diagrams", "combined_diagram": "cam_figures.cam_combined_diagram",
           "pressure_angle": "cam_figures.cam_pressure_angle", "profile": "cam_sheet.cam_inversion"}


def cam_figures(cam: CamDesign | CamProblem, *, notation: Any = "en") -> dict[str, Scene]:
    """Every A4 cam figure of a problem, by file key (a flat face has no combined diagram).

    >>> from graphmethods.problems.builtin import cam_problem
    >>> sorted(cam_figures(cam_problem("shaper-cam")))
    ['combined_diagram', 'motion_diagrams', 'pressure_angle', 'profile']
    """
    import importlib

    cam = _designed(cam)
    out = {}
    for key, where in FIGURES.items():
        if key == "combined_diagram" and cam.problem.contact == "flat":
            continue
        module, function = where.rsplit(".", 1)
        out[key] = getattr(importlib.import_module(f"graphmethods.sheets.{module}"), function)(cam, notation=notation)
    return out


__all__ = ["FIGURES", "a4_figure", "cam_combined_diagram", "cam_figures", "cam_motion_diagrams",
           "cam_pressure_angle"]
