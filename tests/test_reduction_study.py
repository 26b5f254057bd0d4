"""The reduced model of a linkage and the lazy study, against independent closed forms."""

import json
import math

import numpy as np
import pytest
from hypothesis import given, strategies as st

from graphmethods.cli import main
from graphmethods.compat import trapezoid
from graphmethods.dynamics import study as study_mod
from graphmethods.dynamics.reduction import (
    Shaft,
    load_switch_angles,
    load_work,
    power_moment,
    reduce_drive,
    reduced_inertia,
    resisting_moment,
    zhukovsky_lever,
)
from graphmethods.dynamics.study import Study
from graphmethods.errors import InputError
from graphmethods.kinematics import SliderCrank, read_case

PI = math.pi


def slider_crank_closed_form(phi, r, l, e, a):
    """Independent closed form of the offset slider-crank (crank angle φ from +x, CCW, ω = 1):
    velocity analogues of B and of S2 (at distance a from A), and ω2."""
    sin, cos = np.sin(phi), np.cos(phi)
    root = np.sqrt(l**2 - (r * sin - e) ** 2)
    dx_B = -r * sin - (r * sin - e) * r * cos / root
    beta = np.arctan2(e - r * sin, root)            # rod angle from A to B
    d_beta = -r * cos / root
    vSx = -r * sin - a * np.sin(beta) * d_beta
    vSy = r * cos + a * np.cos(beta) * d_beta
    return dx_B, vSx, vSy, d_beta


@pytest.fixture(scope="module")
def press(press_case_path):
    return read_case(press_case_path)


def test_J_e_matches_the_closed_form(press):
    mech = press.mechanism
    pos = mech.positions(m=72)
    J = reduced_inertia(mech.velocity_plans(pos), press.inertias)
    v = press.values
    dx_B, vSx, vSy, w2 = slider_crank_closed_form(pos.phi, v["r"], v["l"], v["e"], v["l_AS2"])
    J_ref = v["J1"] + v["m2"] * (vSx**2 + vSy**2) + v["J_S2"] * w2**2 + v["m3"] * dx_B**2
    np.testing.assert_allclose(J.J_e, J_ref, rtol=1e-12)
    assert set(J.parts) == {"J (OA)", "m (S2)", "J (AB)", "m (B)"}
    np.testing.assert_allclose(sum(J.parts.values()), J.J_e, rtol=1e-14)


def test_resisting_moment_and_its_switch_angles(press):
    mech, load = press.mechanism, press.load
    a, b = load_switch_angles(mech, load)
    pos = mech.positions(phi_from_start=np.array([a, b]))
    np.testing.assert_allclose(pos.s / pos.H, [load.start, load.end], atol=1e-12)
    # the work of M_r over a turn equals F0·H·(end − start): integrate the exact M_r finely
    x = np.linspace(a, b, 200_001)
    plans = mech.velocity_plans(mech.positions(phi_from_start=x))
    M_r = resisting_moment(mech.positions(phi_from_start=x), plans, load)
    assert trapezoid(M_r, x) == pytest.approx(load_work(mech, load), rel=1e-8)
    v = press.values
    dx_B = slider_crank_closed_form(mech.positions(phi_from_start=x).phi, v["r"], v["l"], v["e"], v["l_AS2"])[0]
    np.testing.assert_allclose(M_r, v["F0"] * np.abs(dx_B), rtol=1e-10)


@given(st.floats(0.01, 2 * PI), st.floats(-5e3, 5e3), st.floats(-5e3, 5e3), st.floats(-300, 300),
       st.sampled_from([1, -1]))
def test_zhukovsky_lever_equals_the_power_method(phi, Fx, Fy, M2, sense):
    mech = SliderCrank(r=0.1, l=0.35, e=0.01, sense=sense, points={"S2": ("AB", 0.1, 0.2)})
    plans = mech.velocity_plans(mech.positions(phi=np.array([phi, phi + 1.0])), omega_1=7.0)
    forces = {"B": np.array([Fx, 0.0]), "S2": np.array([Fx / 3, Fy])}
    moments = {"AB": np.full(2, M2)}
    lever = zhukovsky_lever(plans, forces=forces, moments=moments)
    power = power_moment(plans, forces=forces, moments=moments)
    np.testing.assert_allclose(lever.moment, power, rtol=1e-10, atol=1e-9)
    # and by definition: power / ω₁
    P = Fx * plans.v("B")[:, 0] + (Fx / 3) * plans.v("S2")[:, 0] + Fy * plans.v("S2")[:, 1] + M2 * plans.omega("AB")
    np.testing.assert_allclose(power, P / 7.0, rtol=1e-10, atol=1e-9)


def test_gear_train_reduction_and_flywheel_transfer():
    from graphmethods.dynamics.flywheel import transfer
    drive = reduce_drive([Shaft("motor", 0.02, 10.0, M=15.0), Shaft("counter", 0.3, 2.5),
                          Shaft("crank", 4.0, 1.0, M=-100)])
    assert drive.J_e == pytest.approx(0.02 * 100 + 0.3 * 6.25 + 4.0)
    assert drive.M_e == pytest.approx(150.0 - 100.0)
    # a flywheel of J_F on the crank equals J_F/100 on the motor shaft (10× faster)
    assert transfer(50.0, omega_from=1.0, omega_to=10.0) == pytest.approx(0.5)
    with pytest.raises(InputError, match="speed ratio"):
        reduce_drive([Shaft("x", 1.0, 0.0)])


# ----------------------------------------------------------------- the study: laziness
def test_drawing_only_the_moment_diagram_does_not_compute_J_e(press):
    s = Study(press, positions=12)
    s.excess_work  # noqa: B018 - computed on access: what a moment diagram draws
    assert "inertia" not in s.computed and "exact" not in s.computed and "model" not in s.computed


def test_asking_for_J_F_twice_computes_it_once(press, monkeypatch):
    calls = []
    real = study_mod.exact_flywheel
    monkeypatch.setattr(study_mod, "exact_flywheel", lambda *a, **k: calls.append(1) or real(*a, **k))
    s = Study(press, positions=12)
    first, second = s.exact.J_F, s.exact.J_F
    assert first == second and len(calls) == 1 and s.computed.count("exact") == 1


# ----------------------------------------------------------------- the press reference
def test_press_exact_flywheel_and_speed_extremes(press):
    s = Study(press, positions=12)
    ex = s.exact
    assert round(ex.J_F, 2) == 13.94
    assert math.degrees(ex.phi_omega_max_from_0) == pytest.approx(23, abs=1.0)
    assert math.degrees(ex.phi_omega_min_from_0) == pytest.approx(152, abs=1.0)
    assert ex.motion.delta == pytest.approx(press.delta, rel=1e-8)


def test_press_wittenbauer_converges_to_the_exact_value(press):
    J_exact = Study(press, positions=12).exact.J_F
    values = [Study(press, positions=m).wittenbauer.J_F for m in (12, 24, 72, 360, 3600)]
    # straight chords between positions cut the corners where the force switches: the construction
    # can only under-estimate, and the error falls as the chords shorten (first order in 1/m at a jump)
    assert all(a < b for a, b in zip(values, values[1:]))
    assert all(v < J_exact for v in values)
    assert abs(values[-1] - J_exact) / J_exact < 1e-3
    assert abs(values[0] - J_exact) / J_exact > 0.03          # "several percent off" at 12 positions


def test_builtin_press_data_is_the_reference_file(press_case_path):
    import pathlib

    from graphmethods import problems
    builtin = pathlib.Path(problems.__file__).parent / "data" / "slider_crank_press.json"
    assert json.loads(builtin.read_text()) == json.loads(press_case_path.read_text())


def test_study_command(capsys, press_case_path):
    code = main(["study", str(press_case_path), "--positions", "24", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == 0
    for key in ("M_d", "delta_W_max", "J_F_energy", "J_F_wittenbauer", "J_F_exact", "phi_omega_max_deg",
                "phi_omega_min_deg", "J_e_min", "J_e_max", "J_e_mean"):
        assert isinstance(out[key], float), key
    v = json.loads(press_case_path.read_text())
    H = Study(read_case(press_case_path)).positions.H
    assert out["M_d"] == pytest.approx(v["F0"] * H * (v["force_to"] - v["force_from"]) / (2 * PI), rel=1e-12)
    assert round(out["J_F_exact"], 2) == 13.94


def test_study_command_bad_file(tmp_path, capsys):
    bad = tmp_path / "bad.json"
    bad.write_text('{"r": 0.1, "l": 0.05}')
    assert main(["study", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err


# ----------------------------------------------------------------- force diagrams
from graphmethods.dynamics.reduction import ForceDiagram, diagram_moment  # noqa: E402


def test_force_diagram_reproduces_the_press_load(press):
    mech, load = press.mechanism, press.load
    cut = ForceDiagram("B", x=(load.start, load.start, load.end, load.end),
                       F=(0.0, load.magnitude, load.magnitude, 0.0))
    pos = mech.positions(m=360)
    plans = mech.velocity_plans(pos)
    np.testing.assert_allclose(diagram_moment(pos, plans, cut), resisting_moment(pos, plans, load), rtol=1e-12,
                               atol=1e-9)
    assert cut.work(H=pos.H) == pytest.approx(load_work(mech, load), rel=1e-12)


def test_indicator_diagram_on_the_return_stroke_against_the_closed_form(press):
    mech = press.mechanism
    v = press.values
    # a compressor's compression: pressure force rising as the piston returns (s/H falling from 1 to 0)
    comp = ForceDiagram("B", x=(0.0, 0.2, 0.6, 1.0), F=(9000.0, 4000.0, 1500.0, 0.0), stroke="return")
    pos = mech.positions(m=720)
    M = diagram_moment(pos, mech.velocity_plans(pos), comp)
    dx_B = slider_crank_closed_form(pos.phi, v["r"], v["l"], v["e"], v["l_AS2"])[0]
    frac = pos.s / pos.H
    F = np.interp(frac, [0.0, 0.2, 0.6, 1.0], [9000.0, 4000.0, 1500.0, 0.0])
    expected = np.where(~pos.working | pos.extreme, F * np.abs(dx_B), 0.0)
    np.testing.assert_allclose(M, expected, rtol=1e-10, atol=1e-8)
    # its work over the return stroke is H × the diagram's area
    x = np.linspace(0, 2 * math.pi, 200_001)
    fine = mech.positions(phi_from_start=x)
    assert trapezoid(diagram_moment(fine, mech.velocity_plans(fine), comp), x) == pytest.approx(
        comp.work(H=fine.H), rel=1e-6)


def test_force_diagram_against_the_crank_angle_and_driving_forces(press):
    mech = press.mechanism
    gas = ForceDiagram("B", x=(math.pi / 2, math.pi), F=(1000.0, 1000.0), against="angle", opposes=False)
    pos = mech.positions(m=12)
    M = diagram_moment(pos, mech.velocity_plans(pos), gas)
    inside = (pos.phi_from_start >= math.pi / 2 - 1e-12) & (pos.phi_from_start <= math.pi + 1e-12)
    speed = np.abs(mech.velocity_plans(pos).v_along_guide("B"))
    np.testing.assert_allclose(M, np.where(inside, -1000.0 * speed, 0.0), atol=1e-9)
    assert (M <= 0).all() and (M[inside] < 0).sum() >= 2


@pytest.mark.parametrize("kw, msg", [
    (dict(x=(0.0, 1.0), F=(-5.0, 1.0)), "F ≥ 0"),
    (dict(x=(0.0, 1.5), F=(1.0, 1.0)), "from 0 to 1"),
    (dict(x=(0.5, 0.2), F=(1.0, 1.0)), "must not decrease"),
    (dict(x=(0.0, 1.0), F=(1.0, 1.0), against="time"), "against"),
    (dict(x=(0.0, 1.0), F=(1.0, 1.0), stroke="both"), "stroke"),
])
def test_force_diagram_bad_input(kw, msg):
    with pytest.raises(InputError, match=msg):
        ForceDiagram("B", **kw)
