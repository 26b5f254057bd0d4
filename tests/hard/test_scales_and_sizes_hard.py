"""Hard cases of scale and size: extreme drawing scales, huge m, an unclosed cycle."""

import math

import numpy as np
import pytest

from graphmethods.dynamics import excess_work as ew
from graphmethods.dynamics.flywheel import flywheel
from graphmethods.dynamics.graphical import chord_flywheels
from graphmethods.dynamics.motion import ReducedModel
from graphmethods.dynamics.wittenbauer import wittenbauer
from graphmethods.errors import UnbalancedCycleError

W1 = [-50, 550, -100, 125, -500, 25, -50]


@pytest.mark.parametrize("mu", [1e-6, 1e6])
def test_extreme_scales_for_areas(mu):
    areas = [w / (mu * mu) for w in W1]                 # μ_M = μ_φ = mu per mm
    cyc = ew.from_areas(areas, mu_M=mu, mu_phi=mu)
    assert cyc.delta_W_max == pytest.approx(575.0, rel=1e-12)
    assert flywheel(cyc.delta_W_max, delta=1 / 300, n_rpm=600).J_F == pytest.approx(43.69476044575817, rel=1e-12)


@pytest.mark.parametrize("mu_J, mu_T", [(1e-6, 1e6), (1e6, 1e-6), (1e-6, 1e-6), (1e6, 1e6)])
def test_extreme_scales_for_the_energy_mass_diagram(mu_J, mu_T):
    J_e = [1.0, 0.8, 1.0, 1.2, 1.0]
    dT = [0.0, 40.0, 0.0, -40.0, 0.0]
    ref = wittenbauer(J_e=J_e, delta_T=dT, omega_m=20.0, delta=0.04, mu_J=0.005, mu_T=1.0)
    res = wittenbauer(J_e=J_e, delta_T=dT, omega_m=20.0, delta=0.04, mu_J=mu_J, mu_T=mu_T)
    assert res.J_F == pytest.approx(ref.J_F, rel=1e-9)
    assert res.index_omega_max == ref.index_omega_max and res.index_omega_min == ref.index_omega_min
    assert np.isfinite(res.kl_mm) and res.kl_mm * mu_T == pytest.approx(ref.kl_mm * 1.0, rel=1e-9)


def test_an_unclosed_cycle_is_refused_with_its_residual():
    with pytest.raises(UnbalancedCycleError, match=r"sum to -575 J.*tolerance 0.05"):
        ew.from_work([-50, 550, -100, 125, -500, 25, -50, -575])
    cyc = ew.from_work([-50, 550, -100, 125, -500, 25, -48])        # 2 J short: reported, accepted
    assert cyc.residual == pytest.approx(2.0)


def test_huge_m():
    model = ReducedModel(J_e=lambda p: 2.0 + 0.4 * np.cos(2 * p), M_e=lambda p: 300.0 * np.sin(p))
    g = chord_flywheels(model, positions=200_000, omega_m=20.0, delta=0.02, estimate=False)
    assert np.isfinite(g.wittenbauer.J_F) and g.wittenbauer.m == 200_000
    fine = chord_flywheels(model, positions=20_000, omega_m=20.0, delta=0.02, estimate=False)
    assert g.wittenbauer.J_F == pytest.approx(fine.wittenbauer.J_F, rel=1e-6)


def test_huge_m_for_a_linkage_study(press_case_path):
    from graphmethods.dynamics.study import Study
    from graphmethods.kinematics import read_case
    s = Study(read_case(press_case_path), positions=100_000)
    wb = s.wittenbauer
    assert np.isfinite(wb.J_F) and abs(wb.error_estimate) < 1e-3 * wb.J_F
    assert math.isfinite(s.excess_work.delta_W_max)
