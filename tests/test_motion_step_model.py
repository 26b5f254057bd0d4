"""The exact flywheel's extremum search on the step model (issue 19): the same J_F as a brute-force search on
the analytic functions, whatever the grid, the functions called a few times in batches, ties decided alike."""

import math

import numpy as np
import pytest

from graphmethods.dynamics.motion import ReducedModel, exact_flywheel, periodic_motion
from graphmethods.dynamics.study import Study
from graphmethods.problems import builtin

OMEGA, DELTA = 20.0, 0.04


def _M(p):
    return 300.0 * (np.sin(p) + 0.4 * np.sin(3 * p))


def _E(p):
    """ΔE = ∫_0^φ M_e, analytically."""
    return 300.0 * ((1 - np.cos(p)) + 0.4 * (1 - np.cos(3 * p)) / 3)


def _brute_J_F(J_e):
    """J_F from the support-line identity, the intercepts found on 2·10⁶ points then by parabolas on the
    analytic functions (independent of the toolkit's quadrature, grid and search)."""
    x = np.linspace(0.0, 2 * math.pi, 2_000_001)
    a_max, a_min = 0.5 * (OMEGA * (1 + DELTA / 2)) ** 2, 0.5 * (OMEGA * (1 - DELTA / 2)) ** 2

    def best(alpha, sense):
        g = lambda p: sense * (_E(p) - alpha * J_e(p))          # noqa: E731
        gx = g(x)
        i = int(np.argmax(gx))
        lo, hi = x[max(i - 1, 0)], x[min(i + 1, x.size - 1)]
        for _ in range(4):                                       # zoom: 1001 points a round
            s = np.linspace(lo, hi, 1001)
            j = int(np.argmax(g(s)))
            lo, hi = s[max(j - 1, 0)], s[min(j + 1, 1000)]
        return sense * float(g(np.array([0.5 * (lo + hi)]))[0])

    return (best(a_max, +1) - best(a_min, -1)) / (DELTA * OMEGA**2)


@pytest.mark.parametrize("J_e", [
    lambda p: 2.0 + 0.4 * np.cos(2 * p),                          # smooth
    lambda p: 2.0 + 0.3 * np.abs(np.sin(p - 0.123456789)),        # kinks inside grid steps: the model is off there
], ids=["smooth", "kinked"])
def test_J_F_is_the_brute_force_one_on_every_grid(J_e):
    model = ReducedModel(J_e=J_e, M_e=_M)
    expected = _brute_J_F(J_e)
    for n_search in (64, 1024, 4096):
        fw = exact_flywheel(model, omega_m=OMEGA, delta=DELTA, n_search=n_search)
        assert fw.J_F == pytest.approx(expected, rel=1e-12), n_search
        assert fw.rel_accuracy < 1e-11
        assert fw.motion.delta == pytest.approx(DELTA, rel=1e-11)


def test_the_linkage_is_called_a_few_times_in_batches():
    """J_e and M_e of the press (each call a run of the kinematics) are called a handful of times, not once
    or more per search step."""
    s = Study(builtin.case("press"))
    calls = []

    def counted(f, name):
        def g(p):
            calls.append((name, np.size(p)))
            return f(p)
        return g

    model = ReducedModel(J_e=counted(s.model.J_e, "J_e"), M_e=counted(s.model.M_e, "M_e"), breaks=s.model.breaks)
    calls.clear()
    fw = exact_flywheel(model, omega_m=s.omega_m, delta=s.delta)
    assert fw.J_F == pytest.approx(s.exact.J_F, rel=1e-12)
    assert len(calls) <= 12, calls
    assert sum(n for _, n in calls) < 40_000


def test_a_tie_of_the_largest_acceleration_goes_to_the_first_after_position_0():
    """Odd M_e and even J_e: ε(−φ) = −ε(φ), so |ε_max| = |ε_min|; the one met first after position 0 is
    reported, whichever position 0 is."""
    model = ReducedModel(J_e=lambda p: 2.0 + 0.4 * np.cos(2 * p), M_e=_M)
    first = periodic_motion(model, J_F=10.0, omega_m=OMEGA)
    turned = periodic_motion(ReducedModel(J_e=lambda p: 2.0 + 0.4 * np.cos(2 * p), M_e=_M, phi_0=math.pi),
                             J_F=10.0, omega_m=OMEGA)
    for mo in (first, turned):
        assert np.mod(mo.phi_epsilon_max - mo.phi_0, mo.phi_T) < math.pi   # ε's extremes are φ* and 2π − φ*
    assert first.epsilon_max == pytest.approx(-turned.epsilon_max, rel=1e-9)
