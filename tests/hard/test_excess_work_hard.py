"""Named hard cases of the excess-work core (the hard-case suite)."""

import math

import numpy as np
import pytest

from graphmethods.dynamics import excess_work as ew
from graphmethods.dynamics.moments import MomentCurve
from graphmethods.errors import InputError, UnbalancedCycleError

pytestmark = pytest.mark.hard
PI = math.pi


def test_curves_touching_without_crossing():
    # D = M_d − M_r touches 0 inside a chord's neighbourhood and at a vertex without changing sign
    phi = [0, PI / 2, PI, 3 * PI / 2, 2 * PI]
    M_r = MomentCurve.points(phi, [0, 10, 20, 10, 0])          # M_d = 10 by balance
    cyc = ew.from_moments(M_r=M_r)
    assert cyc.phi.tolist() == pytest.approx([0, PI / 2, 3 * PI / 2, 2 * PI])
    # a curve that only touches M_d (never crosses) is unbalanced and refused
    touch = MomentCurve.points([0, PI, 2 * PI], [10, 0, 10])
    with pytest.raises(UnbalancedCycleError, match="never changes sign"):
        ew.from_moments(M_d=MomentCurve.constant(10.0), M_r=touch)


def test_touch_at_a_vertex_does_not_split():
    # D = M_d − M_r: +, down to 0 at π/2, back +, then − ; the touch at π/2 is not a boundary
    phi = [0, PI / 2, PI, 3 * PI / 2, 2 * PI]
    D = [2, 0, 2, -4, 2]                                     # balanced: chord means 1, 1, −1, −1
    M_r = MomentCurve.points(phi, [-v for v in D])
    cyc = ew.from_moments(M_d=MomentCurve.constant(0.0), M_r=M_r)
    assert PI / 2 not in cyc.phi.tolist()
    assert len(cyc.work) == 3          # a–b (+), b–c (−), c–d (+)
    assert np.sign(cyc.work).tolist() == [1, -1, 1]


def test_jump_exactly_at_a_sample_point():
    # W3 with the jump at a knot of M_d too
    M_r = MomentCurve.steps([(0, PI / 4, 60.0), (PI / 4, 2 * PI, 10.0)])
    M_d = MomentCurve.points([0, PI / 4, 2 * PI], [16.25, 16.25, 16.25])
    cyc = ew.from_moments(M_d=M_d, M_r=M_r)
    assert cyc.phi.tolist() == pytest.approx([0, PI / 4, 2 * PI])
    assert cyc.delta_W_max == pytest.approx((60 - 16.25) * PI / 4, rel=1e-12)


def test_crossing_exactly_at_a_vertex():
    M_r = MomentCurve.points([0, PI, 2 * PI], [0, 20, 0])   # M_d = 10 by balance; crossing at π/2 mid-chord
    # the same curve, a vertex at the crossing
    M_r_v = MomentCurve.points([0, PI / 2, PI, 3 * PI / 2, 2 * PI], [0, 10, 20, 10, 0])
    a, b = ew.from_moments(M_r=M_r), ew.from_moments(M_r=M_r_v)
    np.testing.assert_allclose(a.phi, b.phi, atol=1e-12)
    np.testing.assert_allclose(a.work, b.work, atol=1e-12)
    assert b.phi.tolist() == pytest.approx([0, PI / 2, 3 * PI / 2, 2 * PI])


def test_1e5_crossings():
    n = 100_000
    phi = np.linspace(0, 2 * PI, 2 * n + 1)
    M = np.where(np.arange(phi.size) % 2 == 0, 1.0, -1.0)      # zigzag through 0: 2n crossings
    cyc = ew.from_moments(M_d=MomentCurve.constant(0.0, period=2 * PI), M_r=MomentCurve(phi, -M), closure_tol=1e-6)
    # 2n crossings; the period start splits one lobe in two, so 2n + 1 intervals
    assert cyc.work.size == 2 * n + 1
    h = phi[1] - phi[0]
    np.testing.assert_allclose(np.abs(cyc.work[1:-1]), h / 2, rtol=1e-6)
    assert cyc.work[0] == pytest.approx(h / 4) and cyc.work[-1] == pytest.approx(h / 4)
    assert np.isfinite(cyc.E).all()
    assert cyc.delta_W_max == pytest.approx(h / 2, rel=1e-6)      # levels swing between ±h/4


def test_4pi_period():
    # four-stroke engine: one power stroke in two turns
    M_d = MomentCurve.points([0, PI / 4, PI, 4 * PI], [0, 400, 0, 0])
    cyc = ew.from_moments(M_d=M_d)
    assert cyc.period == pytest.approx(4 * PI)
    assert cyc.M_r.mean() == pytest.approx(M_d.work() / (4 * PI))
    assert cyc.residual == pytest.approx(0.0, abs=1e-9)
    assert cyc.phi[-1] == pytest.approx(4 * PI)
    with pytest.raises(InputError, match="different periods"):
        ew.from_moments(M_d=M_d, M_r=MomentCurve.constant(10.0, period=2 * PI))


def test_zero_area_intervals():
    cyc = ew.from_work([0.0, 50.0, 0.0, -50.0, 0.0])
    assert cyc.delta_W_max == 50.0 and cyc.E.tolist() == [0, 0, 50, 50, 0, 0]
    # a coincident stretch (D ≡ 0 on [1, 3]) between a gain and a loss: one boundary, at its start
    phi = [0, 1, 3, 4, 2 * PI]
    D = [1, 0, 0, -1, 1]
    c = ew.from_moments(M_d=MomentCurve.constant(0.0), M_r=MomentCurve.points(phi, [-v for v in D]), closure_tol=1.0)
    assert c.phi.tolist()[:2] == pytest.approx([0, 1])
    assert not (np.abs(c.work) < 1e-12).any()


def test_constant_difference_cycle_is_refused():
    with pytest.raises(UnbalancedCycleError, match="never changes sign"):
        ew.from_moments(M_d=MomentCurve.constant(20.0), M_r=MomentCurve.constant(15.0))
    # and a zero difference is a steady cycle with no fluctuation at all
    flat = ew.from_moments(M_d=MomentCurve.constant(15.0), M_r=MomentCurve.constant(15.0))
    assert flat.delta_W_max == 0.0
