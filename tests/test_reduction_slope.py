"""dJ_e/dφ from the core's accelerations (reduction.reduced_inertia_slope) against differences of J_e."""

import numpy as np
import pytest

from graphmethods.dynamics.reduction import reduced_inertia, reduced_inertia_slope
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import Inertia, SliderCrank
from graphmethods.problems import builtin


def _richardson(J, x, h=1e-3):
    """A fourth-order central difference of J at x (error O(h⁴), ~1e-12 relative here)."""
    return (8 * (J(x + h) - J(x - h)) - (J(x + 2 * h) - J(x - 2 * h))) / (12 * h)


@pytest.mark.parametrize("name", sorted(builtin.LINKAGES))
def test_the_slope_of_every_linkage_is_the_derivative_of_its_J_e(name):
    s = Study(builtin.case(name))
    x = np.linspace(0.05, 6.2, 41)
    exact = s.model.dJ_e_at(x)
    fd = _richardson(s.model.J_e_at, x)
    assert np.abs(exact - fd).max() <= 1e-8 * np.abs(fd).max()
    assert s.model.dJ_e is not None                    # the model carries it: ε uses no difference


def test_each_part_counts_masses_and_link_inertias():
    """m v·a and J ω ε each: a slider-crank with its slider mass alone, then its coupler inertia alone."""
    mech = SliderCrank(r=0.1, l=0.4, points={"S2": ("AB", 0.13, 0.0)})
    x = np.linspace(0.1, 6.0, 13)

    def J_e(parts):
        return lambda p: reduced_inertia(mech.velocity_plans(mech.positions(phi_from_start=p)), parts).J_e

    for parts in ([Inertia(None, "B", 12.0, 0.0)], [Inertia("AB", "S2", 0.0, 0.3)], [Inertia("AB", "S2", 4.0, 0.3)]):
        slope = reduced_inertia_slope(mech, x, parts)
        assert np.abs(slope - _richardson(J_e(parts), x)).max() <= 1e-8 * np.abs(slope).max()
    # the closed form of the slider alone: x_B' x_B'' times 2 m
    r, l, m = 0.1, 0.4, 12.0
    phi = mech.positions(phi_from_start=x).phi
    lam = r / l
    w = np.sqrt(1 - (lam * np.sin(phi)) ** 2)
    v = -r * (np.sin(phi) + lam * np.sin(2 * phi) / (2 * w))
    # d/dφ of v, by the quotient rule
    dw = -(lam**2) * np.sin(phi) * np.cos(phi) / w
    a = -r * (np.cos(phi) + lam * (2 * np.cos(2 * phi) * w - np.sin(2 * phi) * dw) / (2 * w * w))
    slope = reduced_inertia_slope(mech, x, [Inertia(None, "B", m, 0.0)])
    assert slope == pytest.approx(2 * m * v * a, rel=1e-10, abs=1e-14)
