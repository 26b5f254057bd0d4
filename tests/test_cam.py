"""Cam mechanisms: the laws against their closed forms, the design against direct minimisation, the
profile against the pitch curve, and the ``graphmethods cam`` command's contract."""

from __future__ import annotations

import copy
import json
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.errors import InputError
from graphmethods.kinematics.cam import EXAMPLE, LAWS, cam_from_dict, design, unit_law
from graphmethods.kinematics.cam.extrema import maximize

X = np.linspace(0.0, 1.0, 41)

CLOSED = {    # f, f', f'', f''' written out again, independently of the module
    "uniform": (lambda x: x, lambda x: 1 + 0 * x, lambda x: 0 * x, lambda x: 0 * x),
    "parabolic": (lambda x: np.where(x < 0.5, 2 * x**2, 1 - 2 * (1 - x)**2),
                  lambda x: np.where(x < 0.5, 4 * x, 4 * (1 - x)),
                  lambda x: np.where(x < 0.5, 4.0, -4.0), lambda x: 0 * x),
    "harmonic": (lambda x: (1 - np.cos(np.pi * x)) / 2, lambda x: np.pi / 2 * np.sin(np.pi * x),
                 lambda x: np.pi**2 / 2 * np.cos(np.pi * x), lambda x: -np.pi**3 / 2 * np.sin(np.pi * x)),
    "cycloidal": (lambda x: x - np.sin(2 * np.pi * x) / (2 * np.pi), lambda x: 1 - np.cos(2 * np.pi * x),
                  lambda x: 2 * np.pi * np.sin(2 * np.pi * x), lambda x: 4 * np.pi**2 * np.cos(2 * np.pi * x)),
    "polynomial_345": (lambda x: 10 * x**3 - 15 * x**4 + 6 * x**5, lambda x: 30 * x**2 - 60 * x**3 + 30 * x**4,
                       lambda x: 60 * x - 180 * x**2 + 120 * x**3, lambda x: 60 - 360 * x + 360 * x**2),
}


@pytest.mark.parametrize("law", LAWS)
def test_each_law_equals_its_closed_form_to_1e_12(law):
    got = unit_law(law, X)
    for k in range(4):
        np.testing.assert_allclose(got[k], CLOSED[law][k](X), rtol=0, atol=1e-12)
    assert got[0][0] == 0.0 and abs(got[0][-1] - 1.0) < 1e-15


@pytest.mark.parametrize("law", LAWS)
def test_each_law_derivatives_are_those_of_its_displacement(law):
    x = np.array([0.13, 0.31, 0.47, 0.58, 0.77, 0.91])
    h = 1e-6
    for k in range(3):
        lo, hi = unit_law(law, x - h)[k], unit_law(law, x + h)[k]
        np.testing.assert_allclose((hi - lo) / (2 * h), unit_law(law, x)[k + 1], rtol=0, atol=1e-6)


def _problem(**over):
    d = copy.deepcopy(EXAMPLE)
    d.update(over)
    return cam_from_dict(d)


def test_return_is_h_minus_the_rise_and_v_a_are_omega_times_the_analogues():
    p = _problem()
    cam = design(p)
    phi = np.array([10.0, 60.0, 100.0, 200.0, 240.0, 290.0])
    st_ = cam.state(phi)
    x_ret = (phi[3:] - 180.0) / 120.0
    f = CLOSED["harmonic"][0](x_ret)
    np.testing.assert_allclose(st_.s[3:], 0.02 * (1 - f), rtol=0, atol=1e-15)
    np.testing.assert_allclose(st_.v, p.omega * st_.ds, rtol=1e-15)
    np.testing.assert_allclose(st_.a, p.omega**2 * st_.d2s, rtol=1e-15)


def test_maximize_finds_interior_and_end_maxima():
    x, v = maximize(lambda t: -(t - 0.3) ** 2, 0.0, 1.0)
    assert abs(x - 0.3) < 1e-7 and v > -1e-15
    assert maximize(lambda t: t ** 3, -1.0, 2.0) == (2.0, 8.0)


def _direct_s0(p, n=400_001):
    """The designed pitch base radius by brute force: a dense grid of φ over each phase."""
    e, best = p.offset, -np.inf
    for ph in p.phases:
        if ph.kind == "dwell":
            continue
        lim = p.alpha_max_deg if ph.kind == "rise" else p.alpha_return_max_deg
        s, s1, _, _ = ph.values(np.linspace(0.0, 1.0, n))
        best = max(best, float(np.max(np.abs(s1 - e) / math.tan(math.radians(lim)) - s)))
    return math.hypot(best, e)


@pytest.mark.parametrize("law", ["cycloidal", "harmonic", "polynomial_345", "parabolic"])
@pytest.mark.parametrize("offset", [0.0, 0.006, -0.004])
def test_designed_base_radius_matches_a_direct_minimisation(law, offset):
    d = copy.deepcopy(EXAMPLE)
    d["follower"]["offset"] = offset
    d["motion"][0]["law"] = law
    p = cam_from_dict(d)
    cam = design(p)
    assert abs(cam.pitch_base_radius - _direct_s0(p)) < 1e-9
    # at the designed radius the binding phase sits exactly on its permissible angle
    assert max(cam.alpha_max_rise_deg - 30.0, cam.alpha_max_return_deg - 70.0) == pytest.approx(0.0, abs=1e-9)
    assert cam.base_radius == pytest.approx(cam.pitch_base_radius - 0.01, abs=1e-15)


def test_a_positive_offset_lowers_the_rise_pressure_angle():
    r = {e: design(_problem(base_radius=0.03, follower={**EXAMPLE["follower"], "offset": e}))
         for e in (-0.005, 0, 0.005)}
    assert r[0.005].alpha_max_rise_deg < r[0].alpha_max_rise_deg < r[-0.005].alpha_max_rise_deg
    assert r[0.005].alpha_max_return_deg > r[0].alpha_max_return_deg


def test_pressure_angle_and_curvature_against_dense_sampling():
    cam = design(_problem(base_radius=0.025))
    phi = np.linspace(0.0, 360.0, 720_001)
    st_ = cam.state(phi)
    rise, ret = phi < 120.0, (phi >= 180.0) & (phi < 300.0)
    assert abs(np.abs(st_.alpha_deg[rise]).max() - cam.alpha_max_rise_deg) < 1e-6
    assert abs(np.abs(st_.alpha_deg[ret]).max() - cam.alpha_max_return_deg) < 1e-6
    s, s1, s2, _ = cam.problem.motion(phi)
    k = cam.frame(s, s1, s2).kappa
    assert abs(1.0 / k.max() - cam.rho_pitch_min) < 1e-9


def test_curvature_formula_against_finite_differences_of_the_pitch_curve():
    for sense in ("ccw", "cw"):
        cam = design(_problem(base_radius=0.02, cam={"sense": sense, "n_rpm": 120}))
        phi, h = np.array([30.0, 50.0, 200.0, 250.0]), 1e-3
        P = [cam.state(phi + k * h).pitch for k in (-1, 0, 1)]
        r = math.radians(h)
        d1, d2 = (P[2] - P[0]) / (2 * r), (P[2] - 2 * P[1] + P[0]) / r**2
        k_fd = np.abs(d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.hypot(*d1.T) ** 3
        s, s1, s2, _ = cam.problem.motion(phi)
        np.testing.assert_allclose(k_fd, np.abs(cam.frame(s, s1, s2).kappa), rtol=1e-5)


def test_envelope_lies_at_the_roller_radius_from_the_pitch_curve():
    cam = design(_problem(base_radius=0.03))
    phi = np.linspace(0.0, 360.0, 3600, endpoint=False)
    st_ = cam.state(phi)
    np.testing.assert_allclose(np.hypot(*(st_.pitch - st_.profile).T), 0.01, rtol=0, atol=1e-12)
    # the profile touches each roller circle and cuts none: inversion's follower positions on the profile
    far = np.hypot(st_.profile[:, None, 0] - st_.pitch[None, ::36, 0],
                   st_.profile[:, None, 1] - st_.pitch[None, ::36, 1])
    assert far.min() > 0.01 - 1e-9
    # the profile point is the contact: the normal from the roller centre is perpendicular to the profile there
    d = np.gradient(st_.profile, axis=0)
    n = st_.pitch - st_.profile
    cos = np.abs(np.sum(d * n, axis=1)) / np.hypot(*d.T) / 0.01
    assert cos[5:-5].max() < 1e-3


def test_flat_face_design_keeps_the_curvature_at_rho_min_and_width_is_twice_max_analogue():
    d = copy.deepcopy(EXAMPLE)
    d["follower"] = {"type": "translating", "contact": "flat"}
    d["rho_min_allowed"] = 0.005
    cam = design(cam_from_dict(d))
    phi = np.linspace(0.0, 360.0, 360_001)
    s, s1, s2, _ = cam.problem.motion(phi)
    rho = cam.base_radius + s + s2
    assert rho.min() == pytest.approx(0.005, abs=1e-8) and cam.rho_pitch_min == pytest.approx(0.005, abs=1e-12)
    assert cam.face_width_min == pytest.approx(2 * np.abs(s1).max(), abs=1e-9)
    assert cam.alpha_max_rise_deg == 0.0


def test_oscillating_design_keeps_the_limits_and_is_the_smallest():
    from graphmethods.problems.builtin import cam_problem

    p = cam_problem("oscillating-cam")
    cam = design(p)
    assert max(cam.alpha_max_rise_deg - 40.0, cam.alpha_max_return_deg - 70.0) == pytest.approx(0.0, abs=1e-8)
    smaller = design(cam_from_dict({**json.loads(_data("oscillating_roller_cam.json")),
                                    "base_radius": cam.base_radius * (1 - 1e-6)}))
    assert max(smaller.alpha_max_rise_deg - 40.0, smaller.alpha_max_return_deg - 70.0) > 0.0


def _data(name):
    from graphmethods.problems.builtin import DATA

    return (DATA / name).read_text(encoding="utf-8")


@st.composite
def phase_tables(draw):
    n = draw(st.integers(1, 3))
    laws = st.sampled_from(["parabolic", "harmonic", "cycloidal", "polynomial_345"])
    parts = [draw(st.integers(10, 60)) for _ in range(2 * n + 1)]
    scale = 360.0 / sum(parts)
    angles = [p * scale for p in parts]
    angles[-1] = 360.0 - sum(angles[:-1])
    motion = []
    for i in range(n):
        lift = draw(st.floats(0.002, 0.05))
        motion += [{"phase": "rise", "angle_deg": angles[2 * i], "lift": lift, "law": draw(laws)},
                   {"phase": "return", "angle_deg": angles[2 * i + 1], "lift": lift, "law": draw(laws)}]
    motion.append({"phase": "dwell", "angle_deg": angles[-1]})
    return motion


@settings(max_examples=40, deadline=None)
@given(phase_tables())
def test_s_and_v_are_continuous_over_random_phase_tables(motion):
    d = copy.deepcopy(EXAMPLE)
    d["motion"] = motion
    p = cam_from_dict(d)
    h = 1e-9
    for ph in p.phases:
        b = ph.start_deg
        s_lo, v_lo, _, _ = p.motion([b - h])
        s_hi, v_hi, _, _ = p.motion([b + h])
        assert abs(s_hi[0] - s_lo[0]) < 1e-9
        assert abs(v_hi[0] - v_lo[0]) < 1e-6
    s = p.motion(np.linspace(0, 360, 3601))[0]
    assert s.min() >= -1e-15 and abs(s[0] - s[-1]) < 1e-15


def test_impacts_are_named_by_the_law():
    d = copy.deepcopy(EXAMPLE)
    d["motion"][0]["law"] = "uniform"
    cam = design(cam_from_dict({**d, "base_radius": 0.03}))
    assert [(i.phi_deg, i.kind) for i in cam.impacts][:2] == [(0.0, "hard"), (120.0, "hard")]
    assert cam.rho_pitch_min == 0.0 and cam.undercut
    d["motion"][0]["law"] = "cycloidal"
    d["motion"][2]["law"] = "polynomial_345"
    assert design(cam_from_dict({**d, "base_radius": 0.03})).impacts == ()


@pytest.mark.parametrize("bad, words", [
    ({"motion": [{"phase": "rise", "angle_deg": 100, "lift": 0.02, "law": "cycloidal"}]}, "sum to 360"),
    ({"motion": [{"phase": "rise", "angle_deg": 180, "lift": 0.02, "law": "cycloidal"},
                 {"phase": "return", "angle_deg": 180, "lift": 0.01, "law": "cycloidal"}]}, "balance"),
    ({"motion": [{"phase": "rise", "angle_deg": 180, "lift": 0.02, "law": "sine"},
                 {"phase": "return", "angle_deg": 180, "lift": 0.02, "law": "cycloidal"}]}, "law"),
    ({"follower": {"type": "translating", "contact": "roller"}}, "roller_radius"),
    ({"cam": {"sense": "ccw"}}, "n_rpm"),
    ({"pressure_angle_max_deg": None}, "pressure_angle_max_deg"),
])
def test_bad_problem_files_are_refused_with_the_key_named(bad, words):
    d = copy.deepcopy(EXAMPLE)
    d.update(bad)
    if d.get("pressure_angle_max_deg", 1) is None:
        del d["pressure_angle_max_deg"]
    with pytest.raises(InputError, match=words):
        cam_from_dict(d)


def test_cli_json_has_every_key_of_the_contract(tmp_path, capsys):
    from graphmethods.cli import main

    f = tmp_path / "cam.json"
    f.write_text(json.dumps(EXAMPLE), encoding="utf-8")
    assert main(["cam", str(f), "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    for key in ("base_radius", "pitch_base_radius", "offset", "pressure_angle_max_rise_deg",
                "pressure_angle_max_return_deg", "rho_pitch_min", "undercut", "face_width_min", "positions"):
        assert key in res
    assert len(res["positions"]) == 360
    row = res["positions"][60]
    assert set(row) >= {"phi_deg", "s", "v", "a", "pressure_angle_deg", "pitch", "profile"}
    assert res["pitch_base_radius"] == pytest.approx(res["base_radius"] + 0.01, abs=1e-15)
    assert main(["cam", str(f), "--json", "--phi-deg", "30,45"]) == 0
    rows = json.loads(capsys.readouterr().out)["positions"]
    p = cam_from_dict(EXAMPLE)
    s, s1, s2, _ = p.motion([30.0, 45.0])
    assert [r["s"] for r in rows] == pytest.approx(list(s), abs=1e-15)
    assert [r["v"] for r in rows] == pytest.approx(list(p.omega * s1), rel=1e-14)


@pytest.mark.parametrize("argv, words", [
    (["cam", "no-such-cam"], "no such problem file"),
    (["cam", "shaper-cam", "--positions", "0"], "--positions"),
    (["cam", "shaper-cam", "--phi-deg", "x"], "--phi-deg"),
    (["cam", "shaper-cam", "--lang", "ru"], "--sheet"),
])
def test_cli_bad_input_is_one_line_and_exit_2(argv, words, capsys):
    from graphmethods.cli import main

    try:
        code = main(argv)
    except SystemExit as exc:           # refused by argparse's shared number type (issue 28's one policy)
        code = exc.code
    assert code == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1


def test_the_bench_rows_of_the_cam():
    from graphmethods import bench

    rows = bench.bench_cam(n=360, repeat=1, rocker=False)
    profile, r0 = rows[0], rows[1]
    assert profile.error < 1e-12 and r0.error < 1e-9
    assert [r.size for r in rows[3:]] == [11, 19, 35]
    assert rows[3].error > rows[4].error > rows[5].error        # the chords converge as Δφ²
    assert len(rows) == 6                                         # the rocker's rows: test_cam_speed
