"""Named hard cases of the kinematics core: each dyad at its dead centre, 1e-9 rad from a toggle, the
rotating slotted lever through the frame line, a branch that would jump, a group that cannot assemble."""

import math
import pathlib
import sys

import numpy as np
import pytest

from graphmethods.errors import AssemblyError
from graphmethods.kinematics import presets
from graphmethods.kinematics.groups import GROUND, RPP, RRP, Guide
from graphmethods.kinematics.linkage import Crank, Linkage

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from test_linkage_core import assert_matches_fd


def test_hard_slider_crank_at_its_dead_centre():
    r, l, w = 0.1, 0.4, 10.0
    mo = presets.slider_crank(r=r, l=l).motion(m=12, omega_1=w)
    assert mo.v("B")[0].tolist() == [0.0, 0.0]
    assert abs(mo.a("B")[0, 0] + w * w * r * (1 + r / l)) <= 1e-12 * w * w * r
    assert abs(mo.a("B")[6, 0] - w * w * r * (1 - r / l)) <= 1e-12 * w * w * r


def test_hard_four_bar_and_slotted_lever_at_their_extremes():
    for lk, link in ((presets.four_bar(l1=0.3, l2=0.08, l3=0.25, l4=0.2), "3"),
                     (presets.slotted_lever(r=0.1, l_O1O3=0.3, l_O3B=0.5), "3")):
        st_ = lk.strokes()
        s = lk.solve(np.array([st_.phi_start, st_.phi_end]), omega_1=5.0)
        assert np.abs(s.omega[link]).max() <= 1e-13 * 5.0
        assert np.all(np.abs(s.epsilon[link]) > 1.0)      # it reverses: ε ≠ 0 at the dead centre
        assert_matches_fd(lk, np.array([st_.phi_start, st_.phi_end]))


def test_hard_scotch_yoke_dead_centre():
    g = RPP(P="A", R="C", coincident="A3", guide=Guide(GROUND, 0j, 0.0), slot_angle=math.pi / 2)
    lk = Linkage(ground={"O": (0, 0)}, crank=Crank("O", "A", 0.1), groups=[g])
    mo = lk.motion(m=4, omega_1=10.0)
    assert mo.v("C")[0].tolist() == [0.0, 0.0]
    assert np.allclose(mo.a("C")[:, 0], -100.0 * 0.1 * np.cos(mo.phi), rtol=0, atol=1e-12)


def test_hard_four_bar_1e_9_rad_from_a_toggle():
    """A double rocker near the angle where coupler and rocker come in line: finite, correct values."""
    l1, l2, l3, l4 = 0.3, 0.25, 0.12, 0.2
    lk = presets.four_bar(l1=l1, l2=l2, l3=l3, l4=l4)
    # |O2A| = l3 + l4 at cos φ = (l1² + l2² − (l3 + l4)²)/(2 l1 l2)
    phi_t = math.acos((l1 * l1 + l2 * l2 - (l3 + l4) ** 2) / (2 * l1 * l2))
    phi = np.array([phi_t - 1e-9])
    s = lk.solve(phi, omega_1=1.0)
    th3, th4 = float(s.theta["2"][0]), float(s.theta["3"][0])
    assert abs(math.sin(th3 - th4)) < 1e-3          # nearly in line
    from graphmethods.kinematics import FourBar  # the old class: ω from h (exact near the toggle)
    _, d_th = FourBar(l1=l1, l2=l2, l3=l3, l4=l4).derivatives(phi)
    assert abs(s.omega["3"][0] - d_th["O2B"][0]) <= 1e-6 * abs(d_th["O2B"][0])
    assert np.isfinite(s.epsilon["3"]).all() and abs(s.omega["3"][0]) > 10
    with pytest.raises(AssemblyError, match="cannot be assembled at angle #0"):
        lk.solve(np.array([phi_t + 1e-6]))
    assert lk.strokes() is None                     # the crank cannot turn fully


def test_hard_rotating_slotted_lever_through_the_frame_line():
    lk = presets.slotted_lever(r=0.45, l_O1O3=0.3, l_O3B=0.9)
    assert lk.strokes() is None                    # the lever turns fully: no dead centres
    mo = lk.motion(m=12, omega_1=3.0)
    assert mo.phi[0] == 0.0
    # through the frame line O1O3 (A straight above and below O1): θ3 wraps, ω3 and ε3 do not
    phi = np.array([math.pi / 2 - 1e-9, math.pi / 2 + 1e-9, 3 * math.pi / 2 - 1e-9, 3 * math.pi / 2 + 1e-9])
    s = assert_matches_fd(lk, phi)
    assert abs(s.omega["3"][0] - s.omega["3"][1]) <= 1e-8 and abs(s.omega["3"][2] - s.omega["3"][3]) <= 1e-8
    assert abs(s.omega["3"][0] - 1.7 * 0.45 / 0.75) <= 1e-8 and abs(s.omega["3"][2] - 1.7 * 0.45 / 0.15) <= 1e-8


def test_hard_a_branch_that_would_jump_is_refused():
    """A parallelogram four-bar folds flat at φ = 0 and π: there its assembly branch can jump."""
    lk = presets.four_bar(l1=0.3, l2=0.1, l3=0.3, l4=0.1)
    with pytest.raises(AssemblyError, match=r"toggle at φ = (0|180)°.*branch|toggle.*jump"):
        lk.motion(m=12)
    with pytest.raises(AssemblyError):
        lk.check_full_turn()


def test_hard_a_group_that_cannot_assemble_at_one_position():
    g = RRP(P="A", C="B", l=0.1, guide=Guide(GROUND, 0.02j, 0.0), links=("2", "3"))
    lk = Linkage(ground={"O": (0, 0)}, crank=Crank("O", "A", 0.1), groups=[g])
    with pytest.raises(AssemblyError) as exc:
        lk.motion(phi=[0.0, 0.5, 4.71238898038469])
    msg = str(exc.value)
    assert "angle #2 (φ = 270°)" in msg and "0.12 m from the guide" in msg and "AB = 0.1 m" in msg
    with pytest.raises(AssemblyError, match=r"RRP \(2, 3\)"):
        lk.motion(m=12)


