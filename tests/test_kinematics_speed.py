"""Issue 19's small calls and large runs of the kinematics core: what was cut must change no value.

The m-step grid kept per linkage, the read-only constants (fixed joints, crank ω and ε), the extreme
positions found in one pass and the arrays frozen in place instead of copied: each checked against a
computation that does not use it (a fresh solve at the same angles, the formula written out per angle,
the hand-written closed form's memory)."""

import math

import numpy as np
import pytest

from graphmethods import bench
from graphmethods.kinematics.linkage import SHARED_FROM
from graphmethods.kinematics.positions import Strokes, at_extremes
from graphmethods.kinematics.presets import six_bar_press
from graphmethods.problems import builtin

LINKAGES = ("press", "six-bar-press", "shaper", "whitworth", "four-bar")


def _linkage(name):
    return builtin.case(name).linkage


@pytest.mark.parametrize("name", LINKAGES)
def test_the_kept_m_grid_gives_what_a_fresh_solve_at_its_angles_gives(name):
    lk = _linkage(name)
    first = lk.motion(m=12, omega_1=7.0, epsilon_1=-2.0)
    again = lk.motion(m=12, omega_1=7.0, epsilon_1=-2.0)
    assert again.phi is first.phi                            # kept, read-only
    fresh = lk.motion(phi=np.array(first.phi), omega_1=7.0, epsilon_1=-2.0)
    strokes = lk.strokes()
    k = np.arange(13)
    phi = np.mod(strokes.phi_start + lk.sense * (2 * math.pi / 12) * k, 2 * math.pi)
    assert np.allclose(np.angle(np.exp(1j * (first.phi - phi))), 0.0, atol=1e-12)
    assert first.index.tolist() == k.tolist() and first.extreme[0] and first.extreme[12]
    for table in ("z", "v_", "a_", "omega", "epsilon"):
        for key, value in getattr(fresh, table).items():
            assert np.array_equal(getattr(again, table)[key], value), (table, key)
    assert np.array_equal(again.conditioning, fresh.conditioning)


def test_results_are_read_only_and_do_not_share_the_callers_angles():
    lk = six_bar_press()
    phi = np.linspace(0.0, 6.0, 12)
    mo = lk.motion(phi=phi, omega_1=10.0)
    phi[:] = 0.0                                             # the caller's array changes afterwards
    assert mo.phi[5] == pytest.approx(6.0 * 5 / 11)
    for a in (mo.phi, mo.phi_from_start, mo.conditioning, mo.extreme, mo.z["O1"], mo.v_["O2"], mo.omega["1"],
              mo.epsilon["1"], mo.theta["1"]):
        with pytest.raises(ValueError):
            a[0] = 1.0
    st = lk.solve(phi)                                       # a writable φ of the caller is not the crank's angle
    assert st.theta["1"] is not phi and not np.shares_memory(st.theta["1"], phi)


@pytest.mark.parametrize("n", [SHARED_FROM - 1, SHARED_FROM])
def test_constants_are_the_same_values_and_from_shared_from_up_take_no_memory(n):
    lk = six_bar_press()
    st = lk.solve(np.linspace(0.0, 6.0, n), omega_1=3.0, epsilon_1=-1.5)
    for k, c in lk.ground.items():
        assert st.z[k].shape == (n,) and np.all(st.z[k] == c) and not st.z[k].flags.writeable
        assert np.all(st.v[k] == 0) and np.all(st.a[k] == 0)
    assert np.all(st.omega["1"] == 3.0) and np.all(st.epsilon["1"] == -1.5)
    assert (st.z["O1"].strides == (0,)) == (n >= SHARED_FROM)


def test_extreme_positions_found_in_one_pass_as_the_formula_says_angle_by_angle():
    rng = np.random.default_rng(19)
    s = Strokes(phi_start=0.3, phi_end=3.9, working_angle=3.6, return_angle=2 * math.pi - 3.6, K=1.3,
                start_name="a", end_name="b")
    near = [x + d for x in (0.3, 3.9, 0.3 + 2 * math.pi, 3.9 - 2 * math.pi) for d in (0.0, 5e-14, -9e-14, 2e-13)]
    phi = np.concatenate([near, rng.uniform(-10, 10, 200)])

    def direct(x):
        return any(abs(math.fmod(math.fmod(x - p + math.pi, 2 * math.pi) + 2 * math.pi, 2 * math.pi) - math.pi)
                   <= 1e-13 for p in (s.phi_start, s.phi_end))

    assert at_extremes(phi, s).tolist() == [direct(x) for x in phi]
    assert sum(at_extremes(phi, s)) == 12 and not at_extremes(phi, None).any()


def test_peak_memory_of_a_large_run_within_one_and_a_half_times_the_closed_form():
    lk = six_bar_press()
    phi = np.linspace(0.0, 2 * math.pi, 200_000, endpoint=False)
    lk.motion(phi=phi[:10])
    core = bench._peak_bytes(lambda: lk.motion(phi=phi, omega_1=10.0, epsilon_1=3.0))
    hand = bench._peak_bytes(lambda: bench.six_bar_closed_form(phi, 10.0, 3.0))
    assert core <= 1.5 * hand, (core / hand)
