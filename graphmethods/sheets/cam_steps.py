"""The cam profile by inversion of motion, step by step, for a lecture (``graphmethods steps shaper-cam
inversion``).

The finished figure is :func:`graphmethods.sheets.cam_sheet.cam_inversion`; its elements are split by
name into the textbook's steps: the centre and the base circle; the follower turned back by −φ at each
division point; the pitch points B_k (s_k laid off on each position); the pitch curve through them; the
rollers (or the flat face) in each position; their envelope, the profile; the follower in position 0
and the largest pressure angle.

>>> from graphmethods.problems.builtin import cam_problem
>>> bu = inversion_steps(cam_problem("shaper-cam"), page="A4")
>>> len(bu), bu.captions()[5][:11]
(7, 'The profile')
"""

from __future__ import annotations

from typing import Any

from graphmethods.kinematics.cam import CamDesign, CamProblem, design
from graphmethods.scene.steps import BuildUp, Rule
from graphmethods.sheets.cam_sheet import cam_inversion
from graphmethods.sheets.step_rules import _build, _kept, step_start


def inversion_steps(cam: CamDesign | CamProblem, *, notation: Any = "en", page: Any = "slide") -> BuildUp:
    """The inversion, step by step (see the module docstring).

    Parameters
    ----------
    cam : CamDesign or CamProblem
        A designed cam (a problem is designed first).
    notation : {"en", "ru", "zh"}
    page : "slide", "A4" … "A1" or Page
        As every step source takes it (:func:`graphmethods.sheets.steps.step_page`).
    """
    if isinstance(cam, CamProblem):
        cam = design(cam)
    nt, (pg, box, cap_mm, tb) = step_start(notation, page)
    figure = cam_inversion(cam, notation=nt, page=pg, title_block=tb)
    mu = figure.scales()[0]
    sym_a = nt.sym("cam.alpha")
    rise = cam.alpha_max_rise_deg >= cam.alpha_max_return_deg
    alpha = f"{sym_a}_{{max}} = {nt.number(cam.alpha_max_rise_deg if rise else cam.alpha_max_return_deg)}°"
    rb = f"{nt.number(cam.base_radius, sig=4)} {nt.unit('m')}"
    rules: list[tuple[str, Rule]] = [
        (nt.word("cam.step_base", mu=mu.caption(nt)),
         lambda n: n.startswith(("profile-title", "base-circle", "pitch-base-circle", "offset-circle",
                                 "pivot-circle", "O")) or n in ("title", "scale-captions")),
        (nt.word("cam.step_lines"), lambda n: n.startswith("follower-")),
        (nt.word("cam.step_points"), lambda n: n.startswith(("B-", "number-"))),
        (nt.word("cam.step_pitch"), "pitch-curve"),
        (nt.word("cam.step_rollers"), lambda n: n == "rollers" or n.startswith("face-")),
        (nt.word("cam.step_profile", rb=rb), "profile"),
        (nt.word("cam.step_alpha", alpha=alpha), lambda n: n.startswith(("stem-0", "roller-0", "pivot-0", "alpha-"))),
    ]
    return _build(figure, _kept(rules, figure), box, cap_mm, rest=len(_kept(rules, figure)))


__all__ = ["inversion_steps"]
