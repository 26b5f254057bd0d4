"""The exact flywheel's fixed costs cut without changing a bit (issue 30): M_r solved only inside the load's
switch window (:meth:`Study._M_r_in_window`), the switch angles' stroke fraction from the core's motion alone
(:func:`graphmethods.dynamics.reduction._fraction_at`), and a kinematic symbol's hatching clipped once."""

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.dynamics.reduction import _fraction_at, _stroke_fraction
from graphmethods.dynamics.study import LOAD_WINDOW_MARGIN, Study
from graphmethods.kinematics.case import DiagramLoad
from graphmethods.problems import builtin

LINKAGES = [p for p in builtin.names() if p not in builtin.CAMS and p not in builtin.CYCLES]
_studies: dict[str, Study] = {}


def _study(name: str) -> Study:
    if name not in _studies:
        _studies[name] = Study(builtin.case(name))
    return _studies[name]


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    return a.shape == b.shape and bool(np.array_equal(a, b)) and bool(np.array_equal(np.signbit(a), np.signbit(b)))


@pytest.mark.parametrize("name", LINKAGES)
def test_M_r_in_the_load_window_is_M_r_everywhere_bit_for_bit(name):
    s = _study(name)
    on, off = s.switch_angles
    near = [a + d for a in (on, off, 0.0, 2 * math.pi) for d in (0.0, -1e-13, 1e-13, -1e-9, 1e-9, -1e-7, 1e-7,
                                                                   -2 * LOAD_WINDOW_MARGIN, 2 * LOAD_WINDOW_MARGIN)]
    phi = np.concatenate([np.linspace(0.0, 2 * math.pi, 1441), [p for p in near if 0.0 <= p <= 2 * math.pi]])
    assert _same(s._M_r_in_window(phi), s._M_r_exact(phi))
    grid = phi[:1440].reshape(36, 40)                   # any shape, as the quadratures ask
    assert _same(s._M_r_in_window(grid), s._M_r_exact(grid))
    if not isinstance(s.case.load, DiagramLoad):        # the window leaves out more than half the turn somewhere
        assert (s._M_r_exact(phi) != 0).mean() < 0.75


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(0.0, 2 * math.pi), min_size=1, max_size=30))
def test_M_r_in_the_window_at_any_angles(angles):
    s = _study("six-bar-press")
    phi = np.array(angles)
    assert _same(s._M_r_in_window(phi), s._M_r_exact(phi))


@pytest.mark.parametrize("name", LINKAGES)
def test_the_switch_angles_stroke_fraction_from_the_motion_is_the_positions_one(name):
    case = builtin.case(name)
    if isinstance(case.load, DiagramLoad):
        return
    t = np.linspace(0.0, case.mechanism.strokes().working_angle, 62)
    assert _same(_fraction_at(case.mechanism, t, case.load),
                 _stroke_fraction(case.mechanism.positions(phi_from_start=t), case.load))


def test_the_exact_flywheel_of_a_fresh_press_is_the_same_through_the_window():
    from graphmethods.dynamics.motion import ReducedModel, exact_flywheel

    s = Study(builtin.case("press"))
    plain = ReducedModel(J_e=s._J_e_exact, M_e=lambda p: s.M_d - s._M_r_exact(p), dJ_e=s._dJ_e_exact,
                         breaks=s.switch_angles)
    a, b = s.exact, exact_flywheel(plain, omega_m=s.omega_m, delta=s.delta)
    assert (a.J_F, a.phi_omega_max, a.phi_omega_min, a.b_max, a.b_min, a.T0) == \
        (b.J_F, b.phi_omega_max, b.phi_omega_min, b.b_max, b.b_min, b.T0)


def test_a_symbols_hatching_is_clipped_once_however_often_it_is_drawn():
    from graphmethods.sheets.kinematic_symbols import FixedPivot, Guide

    pivot, guide = FixedPivot((50.0, 50.0)), Guide((10.0, 80.0), (90.0, 80.0))
    assert pivot.hatch_region() is pivot.hatch_region()
    assert pivot.primitives() == pivot.primitives() and guide.primitives() == guide.primitives()
    assert guide._hatch_region() is guide._hatch_region()
    assert FixedPivot((50.0, 50.0)) == pivot            # the kept region is no field: equality as before
