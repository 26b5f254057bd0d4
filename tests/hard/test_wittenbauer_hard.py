"""Named hard cases and the accuracy of the Wittenbauer construction (issue 6)."""

from __future__ import annotations

import math
import pathlib
import sys

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.dynamics.motion import ReducedModel, exact_flywheel
from graphmethods.dynamics.wittenbauer import wittenbauer, wittenbauer_from_model

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from test_motion_press import press_model

pytestmark = pytest.mark.hard

@pytest.fixture(scope="module")
def press():
    p = press_model()
    return p, exact_flywheel(p.model, omega_m=p.omega_m, delta=p.delta)


@pytest.mark.parametrize("delta", [1 / 300, 1 / 1000])
def test_small_delta_puts_O1_hundreds_of_sheets_away_without_harm(delta):
    p = press_model()
    exact = exact_flywheel(p.model, omega_m=p.omega_m, delta=delta)
    # scales that make the curve ~100 mm wide and ~200 mm tall, as on a sheet
    res = wittenbauer_from_model(p.model, positions=3600, omega_m=p.omega_m, delta=delta,
                                 mu_J=0.002, mu_T=10.0)
    assert abs(res.O1_mm[0]) > 100 * 841                    # more than a hundred A1 widths
    assert res.J_F <= exact.J_F * (1 + 1e-12)
    assert res.J_F == pytest.approx(exact.J_F, rel=1e-3)
    assert exact.J_F - res.J_F <= res.error_estimate * (1 + 1e-9)
    # both rays touch where the exact solver puts ω_max and ω_min (to the grid step)
    step = 2 * np.pi / 3600
    assert min(abs(np.array(res.phi_omega_max) - exact.phi_omega_max)) <= step
    assert min(abs(np.array(res.phi_omega_min) - exact.phi_omega_min)) <= step


def test_constant_J_e_equals_the_delta_W_max_method_exactly(worked_examples):
    from graphmethods.dynamics.flywheel import flywheel

    w1 = worked_examples["W1"]
    E = np.array(w1["expect"]["E"], dtype=float)             # running energy, positions 0…7
    omega_m = math.pi * w1["n_rpm"] / 30
    delta = 1 / 300
    for J_e in (0.0, 2.5):
        res = wittenbauer(J_e=np.full(E.size, J_e), delta_T=E, omega_m=omega_m, delta=delta,
                          mu_J=0.1, mu_T=5.0)
        delta_W_max = E.max() - E.min()
        assert res.J_F == delta_W_max / (omega_m**2 * delta) - J_e      # the same number, bit for bit
        assert res.J_F == pytest.approx(flywheel(delta_W_max, delta=delta, omega_m=omega_m, J_e=J_e).J_F,
                                        rel=1e-15)                      # the project's ΔW_max method
        assert res.index_omega_max == (w1["expect"]["index_E_max"],)
        assert res.index_omega_min == (w1["expect"]["index_E_min"],)
    assert wittenbauer(J_e=np.zeros(E.size), delta_T=E, omega_m=omega_m, delta=delta, mu_J=0.1,
                       mu_T=5.0).J_F == pytest.approx(w1["expect"]["J_F"], rel=1e-12)


def test_a_straight_stretch_parallel_to_a_ray_touches_along_a_segment():
    # positions 3…6 lie on one line of slope ½ω_max² in the (J_e, ΔT) plane: the upper ray must
    # touch along all of it (one "segment" of four vertices), not at one arbitrary vertex
    omega_m, delta = 20.0, 0.05
    a_max = 0.5 * (omega_m * (1 + delta / 2)) ** 2
    m = 12
    phi = np.linspace(0, 2 * np.pi, m + 1)
    J = 2.0 + 0.3 * np.cos(phi)
    dT = 100 * np.sin(phi) - 300.0
    dT[3:7] = 50.0 + a_max * (J[3:7] - J[3])                 # the straight stretch, above the rest
    res = wittenbauer(J_e=J, delta_T=dT, omega_m=omega_m, delta=delta, mu_J=0.005, mu_T=2.0)
    assert len(res.upper) == 1
    assert res.upper[0].kind == "segment"
    assert res.upper[0].indices == (3, 4, 5, 6)
    assert res.index_omega_max == (3, 4, 5, 6)
    upper = res.k_mm + res.tan_psi_max * res.x_mm
    np.testing.assert_allclose(res.y_mm[3:7], upper[3:7], rtol=1e-12)


def test_a_segment_across_the_closing_point_is_one_segment():
    omega_m, delta = 20.0, 0.05
    a_min = 0.5 * (omega_m * (1 - delta / 2)) ** 2
    phi = np.linspace(0, 2 * np.pi, 13)
    J = 2.0 + 0.3 * np.sin(phi)
    dT = 100 * np.cos(phi) + 300.0
    for k in (11, 0, 1):
        dT[k] = -50.0 + a_min * (J[k] - J[0])
    dT[12] = dT[0]
    res = wittenbauer(J_e=J, delta_T=dT, omega_m=omega_m, delta=delta, mu_J=0.005, mu_T=2.0)
    assert [t.indices for t in res.lower] == [(11, 0, 1)]
    assert res.lower[0].kind == "segment"


def test_huge_delta():
    model = ReducedModel(J_e=lambda p: 2 + 0.6 * np.cos(p + 0.7), M_e=lambda p: 300 * np.cos(p))
    exact = exact_flywheel(model, omega_m=20.0, delta=0.5)
    res = wittenbauer_from_model(model, positions=3600, omega_m=20.0, delta=0.5, mu_J=0.01, mu_T=5.0)
    assert res.J_F == pytest.approx(exact.J_F, rel=1e-5)
    assert res.omega.max() == pytest.approx(20.0 * 1.25, rel=1e-5)
    assert res.omega.min() == pytest.approx(20.0 * 0.75, rel=1e-5)
    # the textbook's (1 ± δ) is a different construction at δ = 0.5, and says so
    assert abs(res.tangents_difference) > 0.01


@settings(deadline=None, max_examples=40)
@given(mu_J=st.floats(min_value=1e-6, max_value=1e3), mu_T=st.floats(min_value=1e-3, max_value=1e5),
       lag=st.floats(min_value=0.0, max_value=2 * np.pi))
def test_the_same_J_F_for_any_scales(mu_J, mu_T, lag):
    phi = np.linspace(0, 2 * np.pi, 25)
    J = 2.0 + 0.4 * np.cos(phi + lag)
    dT = 300 * np.sin(phi) + 80 * np.cos(3 * phi)
    ref = wittenbauer(J_e=J, delta_T=dT, omega_m=20.0, delta=0.05, mu_J=0.01, mu_T=1.0)
    res = wittenbauer(J_e=J, delta_T=dT, omega_m=20.0, delta=0.05, mu_J=mu_J, mu_T=mu_T)
    assert res.J_F == pytest.approx(ref.J_F, rel=1e-12)
    assert res.kl_mm * mu_T == pytest.approx(ref.kl_mm * 1.0, rel=1e-12)
    assert res.index_omega_max == ref.index_omega_max
    assert res.index_omega_min == ref.index_omega_min
    assert res.O1_mm[0] * mu_J == pytest.approx(ref.O1_mm[0] * 0.01, rel=1e-12)


def test_press_converges_monotonically_to_the_exact_flywheel(press):
    # m = 12, 24, 72, 360, 3600 are nested position sets (each divides the next), so the touching
    # vertices of a coarser set are also vertices of the finer one: J_F(m) cannot decrease, and it
    # never exceeds the exact J_F (vertices lie on the continuous curve, below its support lines).
    # The only slack is rounding of ΔT(φ_k), integrated to ~1e-12 of ∫|M_e|dφ: a tolerance of
    # 1e-9 J_F is a thousand times that, and a millionth of the smallest step seen (1e-3 J_F).
    p, exact = press
    tol = 1e-9 * exact.J_F
    values = []
    for m in (12, 24, 72, 360, 3600):
        res = wittenbauer_from_model(p.model, positions=m, omega_m=p.omega_m, delta=p.delta,
                                     mu_J=0.002, mu_T=10.0)
        values.append(res.J_F)
        assert res.J_F <= exact.J_F + tol
        # the reported estimate covers the true sampling error
        assert exact.J_F - res.J_F <= res.error_estimate + tol
    assert all(b >= a - tol for a, b in zip(values, values[1:]))
    assert values[0] < 0.97 * exact.J_F                      # 12 positions: several percent off
    assert values[-1] == pytest.approx(exact.J_F, rel=1e-3)


def test_press_at_12_positions_touches_at_the_textbook_positions(press):
    p, exact = press
    res = wittenbauer_from_model(p.model, positions=12, omega_m=p.omega_m, delta=p.delta,
                                 mu_J=0.002, mu_T=10.0)
    assert res.index_omega_max == (1,)       # 30° after position 0 (exact: 23.2°)
    assert res.index_omega_min == (5,)       # 150° (exact: 151.8°)
    assert [t.kind for t in res.upper + res.lower] == ["point", "point"]
