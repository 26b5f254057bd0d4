"""`graphmethods motion` through the command line (issue 18, Interface)."""

import json
import math

import numpy as np
import pytest

from graphmethods.cli import main


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_W4_one_turn_json_arrays_and_summary(capsys):
    code, out, err = run(capsys, "motion", "W4", "--turns", "1", "--json")
    assert code == 0, err
    res = json.loads(out)
    t, phi, omega, eps = (np.array(res[k]) for k in ("t", "phi", "omega", "epsilon"))
    assert t.size == phi.size == omega.size == eps.size > 10
    assert omega[0] == 10.0 and phi[-1] == pytest.approx(2 * math.pi)
    # the energy form with J_e = 0.8 and the W4 moments: ΔE(φ) = ∫(20 − M_r)dφ
    M_r_int = np.where(phi <= math.pi, 20 * phi**2 / math.pi,
                       40 * math.pi - 20 * (2 * math.pi - phi) ** 2 / math.pi)
    np.testing.assert_allclose(omega, np.sqrt(100 + 2 * (20 * phi - M_r_int) / 0.8), rtol=1e-8)
    s = res["summary"]
    assert s["ended_by"] == "turns" and s["case"] == "W4-exact" and s["energy_residual"] < 1e-9


def test_W3_run_down_with_a_brake_stops(capsys):
    code, out, err = run(capsys, "motion", "W3", "--omega0", "10", "--drive-off-at", "0", "--brake", "20",
                         "--t-end", "100", "--json")
    assert code == 0, err
    s = json.loads(out)["summary"]
    assert s["ended_by"] == "stopped" and s["omega_end"] == 0.0
    # the energy form: ½ J ω0² = ∫ (20 + M_r) dφ up to the stop, M_r = 60 on [0, π/4), 10 after (W3)
    T0 = 0.5 * s["J_F"] * 100.0
    phi = math.radians(s["phi_end_deg"])
    turns, rest = divmod(phi, 2 * math.pi)
    per_turn = 80 * math.pi / 4 + 30 * 7 * math.pi / 4
    part = 80 * min(rest, math.pi / 4) + 30 * max(rest - math.pi / 4, 0.0)
    assert turns * per_turn + part == pytest.approx(T0, rel=1e-9)


def test_dc_motor_until_steady_reports_the_three_means(capsys):
    code, out, err = run(capsys, "motion", "W4", "--omega0", "0", "--phi0", "10", "--motor", "dc:M0=80,omega0=20",
                         "--until-steady", "--json")
    assert code == 0, err
    s = json.loads(out)["summary"]
    st = s["steady"]
    assert s["ended_by"] == "steady" and st["t_steady"] > 0
    assert st["omega_m"] == pytest.approx(0.5 * (st["omega_max"] + st["omega_min"]))
    # ∫M_d dφ = ∫M_r dφ over the period with M_d = 80(1 − ω/20): the φ-average of ω is 20(1 − 20/80) = 15
    assert st["omega_m_integral"] == pytest.approx(15.0, rel=1e-7)
    assert st["omega_m_time"] <= st["omega_m_integral"]        # harmonic ≤ arithmetic mean over φ
    assert 0 <= st["phi_omega_max_deg"] < 360 and 0 <= st["phi_omega_min_deg"] < 360


@pytest.mark.parametrize("argv, match", [
    (["W1", "--turns", "1"], "areas or works"),
    (["nonesuch", "--turns", "1"], "not a built-in"),
    (["W4", "--turns", "-1"], "--turns"),
    (["W4", "--t-end", "1", "--motor", "ac:P=1"], "induction:"),
    (["W4", "--t-end", "1", "--motor", "induction:P=1000,n=1400"], "missing"),
    (["W4", "--t-end", "1", "--moment", "2^omega"], "'^'"),
    (["W4", "--t-end", "1", "--brake-at", "2"], "--brake"),
    (["W4", "--omega0", "0", "--phi0", "270", "--t-end", "1", "--J-F", "1"], "cannot start"),
])
def test_bad_input_one_line_exit_2(capsys, argv, match):
    code, out, err = run(capsys, "motion", *argv)
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and match in err


def test_figures_are_written_scale_true_and_never_overwritten(capsys, tmp_path):
    out = tmp_path / "fig"
    code, _, err = run(capsys, "motion", "W4", "--turns", "2", "--figures", str(out), "--json")
    assert code == 0, err
    names = sorted(p.name for p in out.iterdir())
    assert names == ["W4-exact_epsilon_phi.svg", "W4-exact_omega_phi.svg", "W4-exact_omega_t.svg",
                     "W4-exact_panels.svg"]
    svg = (out / "W4-exact_omega_t.svg").read_text(encoding="utf-8")
    assert 'width="297mm"' in svg and 'viewBox="0 0 297 210"' in svg
    before = (out / "W4-exact_omega_phi.svg").read_bytes()
    code, _, err = run(capsys, "motion", "W4", "--turns", "1", "--figures", str(out))
    assert code == 2 and "--force" in err and (out / "W4-exact_omega_phi.svg").read_bytes() == before
    # deterministic: the same run draws the same bytes
    code, _, _ = run(capsys, "motion", "W4", "--turns", "2", "--figures", str(out), "--force")
    assert code == 0 and (out / "W4-exact_omega_phi.svg").read_bytes() == before


def test_motion_graph_draws_omega_to_scale():
    from graphmethods.dynamics.motion import ReducedModel
    from graphmethods.dynamics.regimes import run as integrate
    from graphmethods.sheets.motion import motion_graph

    res = integrate(ReducedModel(J_e=0.025, M_e=30.0), t_end=1.5)
    scene = motion_graph(res, x="t", y="omega", problem="gear train")
    s_t, s_w = scene.scales()
    curve = scene.element("curve-omega")
    (x0, y0), (x1, y1) = curve.points[0], curve.points[-1]
    assert (x1 - x0) * s_t.per_mm == pytest.approx(1.5, rel=1e-9)          # 1.5 s drawn at μ_t
    assert (y0 - y1) * s_w.per_mm == pytest.approx(1800.0, rel=1e-9)       # ω = 1800 s⁻¹ at μ_ω


def test_a_moment_formula_of_speed_starting_with_a_minus(capsys):
    # J dω/dt = −a ω² from ω0 (M_d − M_r of W4 integrate to zero each turn, so after whole turns only the
    # drag has acted): check one turn against the energy form d(½Jω²)/dφ = M_W4(φ) − a ω²
    code, out, err = run(capsys, "motion", "W4", "--moment", "-0.02*omega**2", "--turns", "1", "--json")
    assert code == 0, err
    s = json.loads(out)["summary"]
    assert s["omega_end"] < 10.0 and s["energy_residual"] < 1e-9


def test_cycle_motion_and_the_three_panel_figure_W3():
    # W3 with its approximate flywheel: J constant, so ω_max, ω_min = ω_m(1 ± δ/2) exactly
    from graphmethods.problems import w3
    from graphmethods.problems.cycle_motion import cycle_motion
    from graphmethods.sheets.cycle_panels import cycle_panels

    cm = cycle_motion(w3())
    phi = np.linspace(0, 2 * math.pi, 20001)
    w = cm.omega_at(phi)
    w_m = math.pi * 100 / 30
    assert w.max() == pytest.approx(w_m * (1 + 0.025), rel=1e-9) and w.min() == pytest.approx(w_m * (1 - 0.025),
                                                                                                rel=1e-9)
    assert phi[np.argmin(w)] == pytest.approx(math.pi / 4, abs=1e-3)      # where the step load ends
    np.testing.assert_allclose(cm.epsilon_at(np.array([0.1, 1.0])), (16.25 - np.array([60.0, 10.0])) / cm.J)
    scene = cycle_panels(w3())
    s_phi, s_M, s_E, s_w = scene.scales()
    # one φ scale for the three panels: each curve spans the period at μ_φ
    for name in ("curve-M_r", "curve-delta_E", "curve-omega"):
        pts = scene.element(name).points
        assert (pts[-1][0] - pts[0][0]) * s_phi.per_mm == pytest.approx(2 * math.pi, rel=1e-9)
    # the ΔE curve's lowest point is ΔW_max = 34.36 J below its start, at μ_E
    pts = np.array(scene.element("curve-delta_E").points)
    assert (pts[:, 1].max() - pts[0, 1]) * s_E.per_mm == pytest.approx(43.75 * math.pi / 4, rel=1e-6)


def test_open_energy_mass_curve_of_a_start_up():
    from graphmethods.dynamics.motion import ReducedModel
    from graphmethods.dynamics.motor import DCMotor
    from graphmethods.dynamics.regimes import run as integrate
    from graphmethods.sheets.motion import energy_mass_curve, motion_figures

    model = ReducedModel(J_e=lambda p: 1.0 + 0.3 * np.cos(2 * p), M_e=lambda p: -20 - 10 * np.sin(p),
                         dJ_e=lambda p: -0.6 * np.sin(2 * p))
    res = integrate(model, J_F=0.5, drive=DCMotor(M_0=100.0, omega_0=20.0), until_steady=True)
    assert res.T[0] == 0.0
    np.testing.assert_allclose(res.J, 0.5 + model.J_e_at(res.phi), rtol=1e-15)
    scene = energy_mass_curve(res)
    s_J, s_T = scene.scales()
    pts = np.array(scene.element("curve-T").points)
    # T drawn to μ_T from the J axis; the start on it (T = 0), the end on the steady loop
    axis_y = scene.element("axis-J").origin[1]
    np.testing.assert_allclose((axis_y - pts[:, 1]) * s_T.per_mm, res.T[np.unique(
        np.linspace(0, res.T.size - 1, min(res.T.size, 6000)).round().astype(int))], rtol=1e-9, atol=1e-9)
    assert "energy_mass" in motion_figures(res)


def test_a_run_too_long_is_refused_before_any_work_and_every_built_in_name_is_known(capsys):
    from graphmethods.cli import main
    from graphmethods.cli.motion import MAX_TURNS
    from graphmethods.problems.builtin import LINKAGES

    assert main(["motion", "W3", "--omega0", "10", "--turns", "1e20"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"at most {MAX_TURNS}" in err
    assert main(["motion", "nosuch", "--turns", "1"]) == 2
    err = capsys.readouterr().err
    assert all(name in err for name in LINKAGES)
