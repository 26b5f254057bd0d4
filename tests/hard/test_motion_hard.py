"""Named hard cases of the exact periodic motion solver (issue 5)."""

from __future__ import annotations

import math
import pathlib
import sys

import numpy as np
import pytest

from graphmethods.dynamics.motion import ReducedModel, exact_flywheel, periodic_motion
from graphmethods.dynamics.motor import DCMotor, motor_motion
from graphmethods.errors import MotionError

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from test_motion_press import brute_force_flywheel, press_model

pytestmark = pytest.mark.hard


def test_loads_with_jumps_between_positions_not_declared():
    # three steps of M_r at angles that are no grid points, and a varying J_e: the solver has to
    # find the jumps itself; the brute force knows them and evaluates ΔE (piecewise linear) exactly.
    jumps = np.array([0.3141, 2.0001, 4.4444])
    levels = np.array([-40.0, 90.0, -10.0, -40.0])           # M_e on the four stretches
    widths = np.diff(np.concatenate([[0.0], jumps, [2 * np.pi]]))
    levels[-1] -= np.dot(levels, widths) / widths[-1]        # balance the cycle on the last stretch
    M_e = lambda p: levels[np.searchsorted(jumps, p, side="right")]                 # noqa: E731
    starts = np.concatenate([[0.0], jumps])
    E_start = np.concatenate([[0.0], np.cumsum(levels[:-1] * widths[:-1])])

    def delta_E(p):
        k = np.searchsorted(jumps, p, side="right")
        return E_start[k] + levels[k] * (p - starts[k])

    J_e = lambda p: 1.0 + 0.3 * np.sin(p) ** 2                                       # noqa: E731
    model = ReducedModel(J_e=J_e, M_e=M_e)
    fw = exact_flywheel(model, omega_m=25.0, delta=0.02)
    J_bf, p1, p2 = brute_force_flywheel(J_e, delta_E, omega_m=25.0, delta=0.02, phi_0=0.0, extra=jumps)
    assert fw.J_F == pytest.approx(J_bf, rel=1e-9)
    assert fw.rel_accuracy < 1e-8
    step = 2 * np.pi / 2e6                                   # the brute force's resolution
    assert fw.phi_omega_max == pytest.approx(p1, abs=step)
    assert fw.phi_omega_min == pytest.approx(p2, abs=1e-12)   # at a jump: a corner of ΔE
    assert fw.delta_check == pytest.approx(0.02, rel=1e-9)


def test_J_e_nearly_constant():
    # a gear train only: J_e varies by 1e-9 of itself. The answer moves off the closed form
    # ΔW_max/(ω_m² δ) − J_e by about a·ΔJ_e/(ω_m² δ) ~ 1e-6 kg·m² (real, not error): it must
    # follow the brute force to 1e-10 and the closed form to 1e-7.
    J_e = lambda p: 5.0 * (1 + 1e-9 * np.sin(3 * p))                                  # noqa: E731
    model = ReducedModel(J_e=J_e, M_e=lambda p: 400 * np.cos(p))
    fw = exact_flywheel(model, omega_m=50.0, delta=1 / 200)
    J_bf = brute_force_flywheel(J_e, lambda p: 400 * np.sin(p), omega_m=50.0, delta=1 / 200,
                                phi_0=0.0)[0]
    assert fw.J_F == pytest.approx(J_bf, rel=1e-10)
    assert fw.J_F == pytest.approx(800 / (2500 / 200) - 5.0, rel=1e-7)
    assert fw.phi_omega_max == pytest.approx(np.pi / 2, abs=1e-4)
    assert fw.delta_check == pytest.approx(1 / 200, rel=1e-9)


def test_heavy_slider_whose_J_e_varies_as_much_as_the_flywheel():
    p = press_model(m3=400.0)
    fw = exact_flywheel(p.model, omega_m=p.omega_m, delta=0.3)
    J = p.model.J_e_at(p.model.positions(3600))
    assert np.ptp(J) > 0.75 * fw.J_F                        # the slider's inertia matters
    J_bf, p1, p2 = brute_force_flywheel(p.model.J_e_at, p.delta_E, omega_m=p.omega_m, delta=0.3,
                                        phi_0=p.phi_0, extra=(p.phi_on, p.phi_off))
    assert fw.J_F == pytest.approx(J_bf, rel=1e-9)
    assert fw.phi_omega_max == pytest.approx(p1, abs=1e-5)
    assert fw.phi_omega_min == pytest.approx(p2, abs=1e-5)
    # the speed limits are no longer where ΔE peaks: the slider's inertia moves them
    assert math.degrees(fw.phi_omega_max_from_0) < 5
    assert fw.delta_check == pytest.approx(0.3, rel=1e-10)
    # the constant-J_e method (ΔW_max with the mean J_e) is far off here: the case is hard
    E = p.delta_E(p.model.positions(3600))
    approx = np.ptp(E) / (p.omega_m**2 * 0.3) - J.mean()
    assert abs(approx - fw.J_F) > 0.1 * fw.J_F


@pytest.mark.parametrize("delta", [1 / 300, 1 / 1000])
def test_small_delta(delta):
    p = press_model()
    fw = exact_flywheel(p.model, omega_m=p.omega_m, delta=delta)
    J_bf = brute_force_flywheel(p.model.J_e_at, p.delta_E, omega_m=p.omega_m, delta=delta,
                                phi_0=p.phi_0, extra=(p.phi_on, p.phi_off))[0]
    assert fw.J_F == pytest.approx(J_bf, rel=1e-9)
    assert fw.delta_check == pytest.approx(delta, rel=1e-9)
    assert fw.rel_accuracy < 1e-8


def test_driving_work_less_than_resisting_press():
    p = press_model()
    weak = ReducedModel(J_e=p.model.J_e, M_e=lambda x: p.model.M_e_at(x) - 0.01 * p.M_d,
                        phi_0=p.phi_0, breaks=p.model.breaks)
    short = 0.01 * p.M_d * 2 * np.pi                         # 9.012 J
    with pytest.raises(MotionError, match=rf"cannot be sustained.*by {short:.4f}"):
        exact_flywheel(weak, omega_m=p.omega_m, delta=p.delta)
    with pytest.raises(MotionError, match="cannot be sustained"):
        periodic_motion(weak, J_F=13.94, omega_m=p.omega_m)


def test_motor_that_cannot_carry_the_press():
    p = press_model()
    load = ReducedModel(J_e=p.model.J_e, M_e=lambda x: p.model.M_e_at(x) - p.M_d,
                        phi_0=p.phi_0, breaks=p.model.breaks)
    with pytest.raises(MotionError, match="short by"):
        motor_motion(load, DCMotor(M_0=0.9 * p.M_d, omega_0=40.0), J_F=13.94)
