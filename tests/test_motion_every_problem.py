"""ω and ε for every problem (issue 18 item 2): the speeds at the boundaries of a cycle given as
areas, and the three-panel figure of a linkage's steady cycle (working machine and engine)."""

import json
import math

import numpy as np
import pytest

from graphmethods.cli import main
from graphmethods.errors import InputError


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("name, n, delta", [("w1", 600.0, 1 / 300), ("w2", 120.0, 0.06)])
def test_boundary_speeds_of_an_areas_problem(name, n, delta):
    from graphmethods import problems
    from graphmethods.problems.cycle_motion import boundary_speeds

    p = getattr(problems, name)()
    b = boundary_speeds(p)
    w_m = math.pi * n / 30
    # the levels of W1/W2 (domain.md §9): lowest at b, highest at e
    E = np.array([0, -50, 500, 400, 525, 25, 50, 0], dtype=float)
    np.testing.assert_allclose(b.E - b.E[0], E, atol=1e-9)
    # J = ΔW_max/(ω_m²[δ]) by hand, and the energy form between every two boundaries
    J = 575.0 / (w_m**2 * delta)
    assert b.J == pytest.approx(J, rel=1e-12)
    np.testing.assert_allclose(0.5 * J * (b.omega**2 - b.omega[0] ** 2), E, atol=1e-8)
    assert b.omega[1] == pytest.approx(w_m * (1 - delta / 2), rel=1e-12)
    assert b.omega[4] == pytest.approx(w_m * (1 + delta / 2), rel=1e-12)
    assert b.delta == pytest.approx(delta, rel=1e-12)


def test_boundary_speeds_refuse_what_is_not_defined():
    from graphmethods import problems
    from graphmethods.problems.cycle_motion import boundary_speeds, cycle_motion

    with pytest.raises(InputError, match="areas or works"):
        cycle_motion(problems.w1())             # ε between the boundaries needs the moments
    with pytest.raises(InputError, match="larger J"):
        boundary_speeds(problems.w1(), J=0.01)  # ΔW_max = 575 J would stop 0.01 kg·m² at 600 rev/min


def test_flywheel_cli_prints_the_speeds_at_the_boundaries(capsys):
    code, out, err = run(capsys, "flywheel", "--areas=-50,550,-100,125,-500,25,-50", "--n", "600",
                         "--J", "50", "--json")
    assert code == 0, err
    d = json.loads(out)
    w = np.array(d["omega_at_boundaries"])
    assert (w.max() + w.min()) / 2 == pytest.approx(20 * math.pi, rel=1e-12)      # the textbook mean
    np.testing.assert_allclose(0.5 * 50 * (w**2 - w[0] ** 2), d["E"], atol=1e-8)
    assert (w.max() - w.min()) / (20 * math.pi) == pytest.approx(d["delta"], rel=1e-9)


@pytest.mark.parametrize("name", ["press", "engine"])
def test_linkage_panels_draw_the_exact_steady_cycle(name):
    from graphmethods.dynamics.study import Study
    from graphmethods.problems.builtin import case
    from graphmethods.sheets.cycle_panels import linkage_panels

    st = Study(case(name))
    scene = linkage_panels(st)
    s_phi, _, s_E, s_w = scene.scales()
    ex = st.exact
    # ΔE panel: the drawn curve against an independent trapezoid integral of M_d − M_r
    pts = np.array(scene.element("curve-delta_E").points)
    phi = (pts[:, 0] - pts[0, 0]) * s_phi.per_mm
    dE_drawn = (pts[0, 1] - pts[:, 1]) * s_E.per_mm          # up is positive; the curve starts at ΔE = 0
    fine = np.unique(np.concatenate([np.linspace(0, 2 * math.pi, 200001), list(st.switch_angles)]))
    M_d, M_r = st.moment_curves(fine)
    dE = np.concatenate([[0.0], np.cumsum(0.5 * np.diff(fine) * ((M_d - M_r)[1:] + (M_d - M_r)[:-1]))])
    np.testing.assert_allclose(dE_drawn, np.interp(phi, fine, dE), atol=2e-3 * np.ptp(dE))
    # ω panel: its extremes are the exact flywheel's, and δ = [δ]
    w_pts = np.array(scene.element("curve-omega").points)
    w_span = (w_pts[:, 1].max() - w_pts[:, 1].min()) * s_w.per_mm
    assert w_span == pytest.approx(ex.omega_max - ex.omega_min, rel=2e-3)
    assert w_span / st.omega_m == pytest.approx(st.delta, rel=2e-3)
    assert (pts[-1, 0] - pts[0, 0]) * s_phi.per_mm == pytest.approx(2 * math.pi, rel=1e-9)


def test_engine_moments_are_named_as_an_engine_has_them():
    from graphmethods.dynamics.study import Study
    from graphmethods.problems.builtin import case

    st = Study(case("engine"))
    assert st.is_engine and not Study(case("press")).is_engine
    phi = np.linspace(0, 2 * math.pi, 100001)
    M_d, M_r = st.moment_curves(phi)
    assert np.ptp(M_r) == 0 and M_r[0] > 0                     # the generator: a constant resistance
    # the gas moment's work over a turn is what the generator takes (work balance)
    work = float(np.sum(0.5 * np.diff(phi) * (M_d[1:] + M_d[:-1])))
    assert work == pytest.approx(M_r[0] * 2 * math.pi, rel=1e-6)
    assert M_d[np.argmin(np.abs(phi - 0.5))] > 0 > M_d[np.argmin(np.abs(phi - 4.0))]   # expansion, compression


def test_motion_figures_of_a_linkage_include_the_panels(capsys, tmp_path):
    code, out, err = run(capsys, "motion", "press", "--turns", "1", "--omega0", "31.4", "--figures",
                         str(tmp_path), "--json")
    assert code == 0, err
    figs = json.loads(out)["summary"]["figures"]
    assert any(f.endswith("press_panels.svg") for f in figs)
    assert (tmp_path / "press_panels.svg").read_text(encoding="utf-8").count("curve-omega") >= 1
