"""Engines as well as working machines (issue 18 item 4): the indicator diagram as force or pressure,
the engine's moment figures, power, efficiency and the motor."""

import copy
import json
import math

import numpy as np
import pytest

from graphmethods.cli import main
from graphmethods.dynamics.power import (
    IEC_RATED_KW,
    choose_motor,
    efficiency_parallel,
    efficiency_series,
    mean_power,
    moment_with_losses,
)
from graphmethods.dynamics.study import Study
from graphmethods.errors import InputError
from graphmethods.kinematics.linkage_file import linkage_case
from graphmethods.problems.builtin import DATA, case

BORE = 0.08


def _engine_dict():
    return json.loads((DATA / "single_cylinder_engine.json").read_text(encoding="utf-8"))


def test_indicator_diagram_as_pressure_gives_the_same_engine():
    d = _engine_dict()
    area = math.pi * BORE**2 / 4
    for part in d["load"]["diagram"]:
        part["p"] = [F / area for F in part.pop("F")]
        part["bore"] = BORE
    a, b = Study(case("engine")), Study(linkage_case(d, source="pressure.json"))
    assert b.M_d == pytest.approx(a.M_d, rel=1e-12)
    np.testing.assert_allclose(b.M_r, a.M_r, rtol=1e-12, atol=1e-9)
    assert b.exact.J_F == pytest.approx(a.exact.J_F, rel=1e-9)


@pytest.mark.parametrize("change, message", [
    (lambda p: p.update(p=p.pop("F")), "bore"),
    (lambda p: p.update(p=list(p["F"]), bore=BORE), "one of them"),
    (lambda p: p.update(bore=BORE), "goes with a pressure"),
])
def test_indicator_diagram_bad_input(change, message):
    d = _engine_dict()
    change(d["load"]["diagram"][0])
    with pytest.raises(InputError, match=message):
        linkage_case(copy.deepcopy(d), source="bad.json")


def test_engine_moment_graph_draws_the_gas_moment_against_a_constant_resistance():
    from graphmethods.sheets.dynamics import moment_graph

    st = Study(case("engine"))
    s = moment_graph(st)
    s_phi, s_M = s.scales()
    axis_y = s.element("axis-phi").origin[1]
    pts = np.array(s.element("curve-M_d").points)
    drawn = (axis_y - pts[:, 1]) * s_M.per_mm
    # the gas moment is drawn as a dense curve (one truth with the load); it passes through the positions' values
    x_at = s.element("axis-phi").origin[0] + np.asarray(st.phi) / s_phi.per_mm
    at_positions = np.interp(x_at, pts[:, 0], drawn)
    np.testing.assert_allclose(at_positions, -np.asarray(st.M_r), atol=0.5 * s_M.per_mm * 1e-2)   # 3 decimals of a mm
    r = np.array(s.element("curve-M_r").points)
    # the constant balances the drawn curve (one truth: the M_r drawn is the M_r integrated)
    phi_drawn = (pts[:, 0] - pts[0, 0]) * s_phi.per_mm
    curve_mean = float(np.sum(0.5 * np.diff(phi_drawn) * (drawn[1:] + drawn[:-1]))) / (2 * math.pi)
    assert (axis_y - r[0, 1]) * s_M.per_mm == pytest.approx(curve_mean, abs=s_M.per_mm * 1e-2)
    assert drawn.min() < 0 < drawn.max()                     # compression below the axis, expansion above


def test_engine_dynamic_analysis_sheet_and_energy_mass_diagram():
    from graphmethods.sheets.dynamic_analysis_sheet import dynamic_analysis_sheet
    from graphmethods.sheets.wittenbauer import wittenbauer_diagram

    st = Study(case("engine"))
    sheet = dynamic_analysis_sheet(st, page="A2")
    assert any(f"J_F = {st.wittenbauer.J_F:.6g}" in n for n in sheet.notes)
    wittenbauer_diagram(st)                                   # no longer refused


def test_mean_power_and_the_motor():
    st = Study(case("press"))
    phi = np.linspace(0, 2 * math.pi, 200001)
    M_r = st._M_r_exact(phi)
    N = float(np.sum(0.5 * np.diff(phi) * (M_r[1:] + M_r[:-1]))) / (2 * math.pi) * st.omega_m
    p = st.power(eta=0.9, reserve=1.1)
    assert p["N_mean"] == pytest.approx(N, rel=1e-5)          # the trapezoids straddle the load's jumps
    assert p["M_d_with_losses"] == pytest.approx(st.M_d / 0.9, rel=1e-12)
    need = N / 0.9 * 1.1
    assert p["motor_P_rated_kW"] == min(P for P in IEC_RATED_KW if P * 1000 >= need)
    e = Study(case("engine")).power()
    assert "P_rated_kW" not in json.dumps(e) and e["N_mean"] == pytest.approx(-Study(case("engine")).M_d * 50 * math.pi)


def test_efficiency_in_series_and_parallel():
    assert efficiency_series([0.95, 0.9, 0.8]) == pytest.approx(0.684)
    # parallel: output power Σ α_i η_i N over input N
    N, shares, etas = 10.0, [0.2, 0.3, 0.5], [0.9, 0.8, 0.7]
    assert efficiency_parallel(etas, shares=shares) == pytest.approx(sum(N * a * e for a, e in zip(shares, etas)) / N)
    assert moment_with_losses(100.0, eta=0.8) == pytest.approx(125.0)
    with pytest.raises(InputError, match="add up to 1"):
        efficiency_parallel([0.9, 0.9], shares=[0.5, 0.6])
    with pytest.raises(InputError, match="efficiency"):
        efficiency_series([0.9, 0.0])
    assert choose_motor(5500.0).P_rated_kW == 5.5 and choose_motor(5500.1).P_rated_kW == 7.5
    with pytest.raises(InputError, match="largest rated power"):
        choose_motor(400e3)
    assert mean_power(M_m=-10.0, omega_m=2.0) == 20.0


def test_study_power_on_the_command_line(capsys):
    code = main(["study", "press", "--no-exact", "--eta", "0.95,0.9", "--json"])
    out, err = capsys.readouterr()
    assert code == 0, err
    p = json.loads(out)["power"]
    assert p["eta"] == pytest.approx(0.855) and p["motor_P_rated_kW"] == 5.5
    code = main(["study", "press", "--no-exact", "--eta", "0.9", "--reserve", "0.5"])
    out, err = capsys.readouterr()
    assert code == 2 and "reserve" in err and err.count("\n") == 1
