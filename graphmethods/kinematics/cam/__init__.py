"""Cam mechanisms: the follower's motion laws, the base radius from the pressure angle, the profile.

numpy only, SI in, frozen results out; no paper. Read a ``"kind": "cam"`` problem file with
:func:`read_cam` (or build one from a dict with :func:`cam_from_dict`), then :func:`design` gives a
:class:`CamDesign`: the base radius (given, or the smallest that keeps the pressure angle within
[α] on the rise and [α]_return on the return; for a flat face, the smallest that keeps the profile's
radius of curvature ≥ ρ_min), the largest pressure angles, the smallest radius of curvature of the
pitch curve, the undercut check, the flat face's width and the impacts; ``CamDesign.state(phi_deg)``
gives s, v, a, jerk, α and the pitch and profile points by inversion at any cam angles.
Conventions (the offset's side, where φ starts, the cam's own frame) are in
:mod:`graphmethods.kinematics.cam.geometry`.

>>> from graphmethods.kinematics.cam import EXAMPLE, cam_from_dict, design
>>> cam = design(cam_from_dict(EXAMPLE))
>>> round(cam.base_radius, 6), round(cam.alpha_max_return_deg, 4)
(0.00641, 41.0904)
"""

from graphmethods.kinematics.cam.design import CamDesign, CamState, Impact, design
from graphmethods.kinematics.cam.laws import LAWS, law_impacts, unit_law
from graphmethods.kinematics.cam.problem import EXAMPLE, CamProblem, Phase, cam_from_dict, read_cam

__all__ = ["EXAMPLE", "LAWS", "CamDesign", "CamProblem", "CamState", "Impact", "Phase", "cam_from_dict", "design",
           "law_impacts", "read_cam", "unit_law"]
