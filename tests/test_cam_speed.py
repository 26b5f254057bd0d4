"""The cam's fast paths against the scalar ones they replaced (issue 30): many maxima at once
(:func:`maximize_rows`) against one at a time, the k-section against the bisection, the oscillating design
and the rocker zone's boundary against a scalar bisection written out here, each equal to the bit; the
reference base radii; the zone's boundary found once per design."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.kinematics.cam import design
from graphmethods.kinematics.cam.design import _alpha_max, psi_0_rows, smallest_admissible
from graphmethods.kinematics.cam.extrema import maximize, maximize_rows
from graphmethods.kinematics.cam.geometry import pressure_angle, pressure_angle_at, psi_0
from graphmethods.problems.builtin import cam_problem
from graphmethods.sheets import cam_rocker


def _bisection(lo_r, hi_r, admissible):
    """The scalar search the k-section replaced: the first admissible of 64 grid points, then bisection."""
    grid = np.linspace(lo_r, hi_r, 66)[1:-1]
    ok = [float(r) for r in grid if admissible(float(r))]
    if not ok:
        return None
    hi = ok[0]
    i = int(np.searchsorted(grid, hi))
    lo = float(grid[i - 1]) if i > 0 else lo_r
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        lo, hi = (lo, mid) if admissible(mid) else (mid, hi)
    return hi


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(0.5, 12.0), st.floats(-3.0, 3.0), st.floats(-1.0, 1.0)), min_size=1,
                max_size=7),
       st.one_of(st.none(), st.floats(-1.0, 1.5)))
def test_many_maxima_at_once_are_each_the_maximum_alone(rows, stop_above):
    k, p, c = (np.array([[r[i]] for r in rows]) for i in range(3))
    x, v = maximize_rows(lambda t: np.sin(k * t + p) + c * t, 0.0, 2.0, len(rows), stop_above=stop_above)
    for i, (ki, pi, ci) in enumerate(rows):
        alone = maximize(lambda t, ki=ki, pi=pi, ci=ci: np.sin(ki * t + pi) + ci * t, 0.0, 2.0, stop_above=stop_above)
        assert (float(x[i]), float(v[i])) == alone


def test_a_row_maximum_is_exact_to_rounding():
    a = np.array([[0.3], [0.7], [1.9]])
    x, v = maximize_rows(lambda t: -(t - a) ** 2, 0.0, 1.0, 3)       # the last one: at the end x = 1
    assert np.abs(x - [0.3, 0.7, 1.0]).max() < 1e-8 and np.abs(v - [0.0, 0.0, -0.81]).max() < 1e-15


@settings(max_examples=80, deadline=None)
@given(st.floats(-0.5, 1.5), st.floats(0.01, 0.5), st.sampled_from([1, 2, 7, 64]))
def test_the_k_section_finds_the_bisections_float(threshold, lo, per_round):
    def alone(r):
        return r >= threshold

    assert smallest_admissible(lo, 1.0, lambda r: r >= threshold, per_round=per_round) == _bisection(lo, 1.0, alone)


def test_pressure_angle_at_a_column_of_psi0_is_the_bits_of_one_at_a_time():
    p = cam_problem("oscillating-cam")
    s, s1, _, _ = p.motion(np.linspace(0.0, 360.0, 97))
    r0 = np.linspace(abs(p.pivot - p.arm), p.pivot + p.arm, 11)[1:-1]
    psi0, ok = psi_0_rows(r0, p.arm, p.pivot)
    assert ok.all() and psi0.tolist() == [psi_0(r, p.arm, p.pivot) for r in r0.tolist()]
    many = pressure_angle_at(psi0[:, None], s[None, :], s1[None, :], arm=p.arm, pivot=p.pivot)
    for row, r in zip(many, r0.tolist()):
        assert np.array_equal(row, pressure_angle(r, s, s1, arm=p.arm, pivot=p.pivot))


def _scalar_oscillating_r0(p):
    """The oscillating design as it was: a bisection asking the scalar largest |α| of one r₀ at a time."""
    lim = {"rise": math.radians(p.alpha_max_deg), "return": math.radians(p.alpha_return_max_deg)}

    def admissible(r0):
        try:
            if psi_0(r0, p.arm, p.pivot) + p.stroke >= math.pi:
                return False
        except Exception:
            return False
        return all(_alpha_max(p, r0, k)[1] <= lim[k] for k in lim if any(ph.kind == k for ph in p.phases))
    return _bisection(abs(p.pivot - p.arm), p.pivot + p.arm, admissible)


def _variants():
    from test_cam_figures import VARIANTS

    return VARIANTS


@pytest.mark.parametrize("name", ["built-in", "return-binds"])
def test_the_oscillating_design_is_the_scalar_bisections_float(name):
    cam = _variants()[name]()
    assert cam.pitch_base_radius == _scalar_oscillating_r0(cam.problem)


def test_the_reference_base_radii():
    assert round(design(cam_problem("shaper-cam")).base_radius, 5) == 0.01128
    assert round(design(cam_problem("oscillating-cam")).base_radius, 5) == 0.02311


@pytest.mark.parametrize("name", ["built-in", "clockwise"])
def test_the_zone_boundary_is_the_scalar_bisections_centre(name):
    cam = _variants()[name]()
    p, rk = cam.problem, cam_rocker.rocker(cam)

    def centre(r0):
        return cam_rocker.centre_at(rk, rk.psi0 - psi_0(r0, p.arm, p.pivot))

    def inside(r0):                                   # one centre at a time, every maximum refined
        return (psi_0(r0, p.arm, p.pivot) + p.stroke < math.pi
                and float(cam_rocker.excess(cam, rk, centre(r0)[None, :])[0]) <= 0.0)
    r0 = _bisection(abs(p.pivot - p.arm), p.pivot + p.arm, inside)
    assert np.array_equal(cam_rocker._boundary_centre(cam), centre(r0))


def test_the_zone_boundary_is_found_once_per_design_and_handed_out_as_a_copy():
    cam = design(cam_problem("oscillating-cam"))
    first = cam_rocker.boundary_centre(cam)
    first[:] = 7.0
    again = cam_rocker.boundary_centre(cam)
    assert cam in cam_rocker._CENTRES and np.array_equal(again, cam_rocker._boundary_centre(cam))
    assert not np.array_equal(again, first)


def test_the_bench_rows_of_the_rocker_cam_and_the_cam_figures():
    from graphmethods import bench

    design_row, zone, figures = bench._cam_oscillating_rows(1)
    assert design_row.seconds > 0.0 and zone.error < 1e-12
    assert figures.size == 8 and figures.target == "≤ 200 ms a figure" and figures.holds is not None
