"""The translating equivalent link (issue 18 item 3): m_e and F_e against the sine mechanism's closed
forms, the force form of the equation of motion against the rotating solution, and the command line."""

import json
import math

import numpy as np
import pytest

from graphmethods.cli import main
from graphmethods.dynamics.study import Study
from graphmethods.dynamics.translating import from_rotating, translating_acceleration
from graphmethods.errors import InputError
from graphmethods.problems.builtin import case

R, J1, M2, M3, F = 0.1, 0.2, 0.5, 10.0, 2000.0     # the pump's data (scotch_yoke_pump.json)
M_D = F * R / math.pi                                 # work balance: F·2r over one turn


def test_the_pump_is_an_RPP_linkage_with_the_textbook_reduced_model():
    st = Study(case("scotch-yoke"), positions=24)
    phi = st.phi
    np.testing.assert_allclose(st.J_e, J1 + M2 * R**2 + M3 * (R * np.sin(phi)) ** 2, rtol=1e-12, atol=1e-15)
    assert st.M_d == pytest.approx(M_D, rel=1e-9)


def test_equivalent_mass_and_force_of_the_sine_mechanism():
    st = Study(case("scotch-yoke"), positions=24)
    tr = st.translating()
    phi = tr.phi
    assert tr.dead_centres.tolist() == [0, 12, 24]                 # φ = 0, π: the yoke stands still
    np.testing.assert_allclose(tr.v_q, R * np.sin(phi), rtol=1e-12)
    np.testing.assert_allclose(tr.m_e, M3 + (M2 + J1 / R**2) / np.sin(phi) ** 2, rtol=1e-10)
    working = phi < math.pi
    np.testing.assert_allclose(tr.F_e, M_D / (R * np.sin(phi)) - F * working, rtol=1e-9)
    # kinetic energy and power kept: ½ m_e v² = ½ J_e ω², F_e v = M_e ω
    np.testing.assert_allclose(tr.m_e * tr.v_q**2, st.J_e[tr.index], rtol=1e-12)


def test_force_form_of_the_equation_of_motion_agrees_with_the_rotating_solution():
    from graphmethods.dynamics.motion import periodic_motion

    st = Study(case("scotch-yoke"), positions=12)
    J_F = 5.0
    mo = periodic_motion(st.model, J_F=J_F, omega_m=st.omega_m, positions=36)
    K = M2 + (J1 + J_F) / R**2
    for k in (2, 5, 7, 13, 16, 22, 29, 33):                       # away from the dead centres and the jumps
        phi, w, eps = float(mo.phi[k] - mo.phi_0), float(mo.omega[k]), float(mo.epsilon[k])
        s, c = math.sin(phi), math.cos(phi)
        v_q = R * s
        m_e = M3 + K / s**2
        dm_e_ds = (-2 * K * c / s**3) / v_q                      # dm_e/dφ over ds/dφ = v_q
        F_e = M_D / v_q - F * (phi < math.pi)
        a = translating_acceleration(m_e=m_e, dm_e_ds=dm_e_ds, F_e=F_e, v=v_q * w)
        assert a == pytest.approx(R * c * w**2 + v_q * eps, rel=1e-6, abs=1e-6 * R * w**2)


def test_press_equivalent_mass_keeps_the_kinetic_energy():
    st = Study(case("press"), positions=36)
    tr = st.translating("B")
    np.testing.assert_allclose(tr.m_e * tr.v_q**2, st.J_e[tr.index], rtol=1e-10)
    np.testing.assert_allclose(tr.F_e * tr.v_q, (st.M_d - st.M_r)[tr.index], rtol=1e-10, atol=1e-9)


def test_dead_centres_are_reported_not_given_a_value():
    t = from_rotating(J_e=[1.0, 2.0], M_e=[1.0, 1.0], v_q=[0.0, 0.1])
    assert t.dead_centres.tolist() == [0] and np.all(np.isfinite(t.m_e))
    with pytest.raises(InputError, match="does not move"):
        from_rotating(J_e=[1.0], M_e=[1.0], v_q=[0.0])
    with pytest.raises(InputError, match="positive"):
        translating_acceleration(m_e=0.0, dm_e_ds=0.0, F_e=1.0, v=1.0)


def test_study_translating_on_the_command_line(capsys):
    code = main(["study", "scotch-yoke", "--no-exact", "--translating", "--json"])
    out, err = capsys.readouterr()
    assert code == 0, err
    t = json.loads(out)["translating"]
    assert t["point"] == "C" and t["dead_centre_positions"] == [0, 6, 12]
    phi = np.radians(t["phi_deg"])
    np.testing.assert_allclose(t["m_e"], M3 + (M2 + J1 / R**2) / np.sin(phi) ** 2, rtol=1e-10)
    code = main(["study", "four-bar", "--no-exact", "--translating"])
    out, err = capsys.readouterr()
    assert code == 2 and "name the point" in err and err.count("\n") == 1
    code = main(["study", "press", "--no-exact", "--translating", "S2"])
    out, err = capsys.readouterr()
    assert code == 2 and "straight line" in err


def test_equivalent_mass_graph_draws_the_closed_form():
    from graphmethods.sheets.translating_graph import equivalent_mass_graph

    s = equivalent_mass_graph(Study(case("scotch-yoke"), positions=12))
    s_phi, s_m = s.scales()
    axis_y = s.element("axis-phi").origin[1]
    x0 = s.element("axis-Y").origin[0]
    branches = [s.element(f"curve-m_e-{k}") for k in (1, 2)]
    m_min = M3 + M2 + J1 / R**2
    for b in branches:
        pts = np.array(b.points)
        phi = (pts[:, 0] - x0) * s_phi.per_mm
        m_e = (axis_y - pts[:, 1]) * s_m.per_mm
        np.testing.assert_allclose(m_e, M3 + (M2 + J1 / R**2) / np.sin(phi) ** 2, rtol=2e-3, atol=2e-3 * s_m.per_mm)
        assert m_e.max() <= 6 * m_min * (1 + 1e-9)
