"""Named hard cases of the linkage study (reduction + flywheel three ways)."""

import json
import math

import numpy as np
import pytest

from graphmethods.dynamics.flywheel import flywheel
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import case_from_dict

pytestmark = pytest.mark.hard


@pytest.fixture(scope="module")
def press_values(press_case_path):
    return json.loads(press_case_path.read_text())


def _study(values, m=12, **changes):
    return Study(case_from_dict({**values, **changes}), positions=m)


def test_heavy_slider_whose_J_e_varies_as_much_as_the_flywheel(press_values):
    # the slider's own inertia makes the speed fluctuate: J_F ≳ ΔJ_e/(2δ), so for J_e to vary as much
    # as the flywheel, δ must be large
    s = _study(press_values, m=360, m3=200.0, F0=500.0, delta=0.3)
    ex = s.exact
    assert np.ptp(s.J_e) > 0.5 * ex.J_F
    assert ex.motion.delta == pytest.approx(0.3, rel=1e-8)
    assert abs(s.wittenbauer.J_F - ex.J_F) / ex.J_F < 5e-3      # the energy–mass diagram still gets it
    # the approximate method, blind to the variation, is far off here
    assert abs(s.flywheel_energy.J_F - ex.J_F) / ex.J_F > 0.3


def test_delta_one_in_a_thousand(press_values):
    s = _study(press_values, m=3600, delta=0.001)
    ex, wb = s.exact, s.wittenbauer
    assert np.isfinite(ex.J_F) and ex.motion.delta == pytest.approx(0.001, rel=1e-8)
    assert abs(wb.J_F - ex.J_F) / ex.J_F < 1e-3
    assert abs(wb.O1_mm[0]) > 1e4                       # O1 is far off the sheet, and not needed


def test_constant_J_e_gives_the_delta_W_max_method_exactly(press_values):
    s = _study(press_values, m=24, m2=0.0, J_S2=0.0, m3=0.0)
    assert np.ptp(s.J_e) == 0.0
    # the vertical curve's support lines touch its top and bottom points: ΔW_max over the positions
    fw = flywheel(float(np.ptp(s.delta_T)), delta=s.delta, omega_m=s.omega_m, J_e=float(s.J_e[0]))
    assert s.wittenbauer.J_F == pytest.approx(fw.J_F, rel=1e-12)
    # the excess-work table also finds the crossings between positions, so it sees at least as much
    assert s.flywheel_energy.J_F >= s.wittenbauer.J_F


def test_load_switching_between_positions(press_values):
    # the force switches on at ~23° and off at ~152°, neither a multiple of 30°: the exact solver
    # puts ω_max and ω_min exactly at the switches, the 12-position construction cannot
    s = _study(press_values, m=12)
    a, b = s.switch_angles
    assert min(abs(math.degrees(a) - 30 * k) for k in range(13)) > 1
    assert s.exact.phi_omega_max_from_0 == pytest.approx(a, abs=1e-9)
    assert s.exact.phi_omega_min_from_0 == pytest.approx(b, abs=1e-9)
