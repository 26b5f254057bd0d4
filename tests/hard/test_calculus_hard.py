"""Hard cases of the graphical calculus: a moment with a jump, the slider's acceleration at the dead
centres, very few intervals (m = 6)."""

import math
import pathlib

import numpy as np
import pytest

from graphmethods import problems
from graphmethods.dynamics import graphical_calculus as gc
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import SliderCrank, read_case
from graphmethods.sheets import calculus
from graphmethods.sheets.work_diagrams import work_diagrams

PI = math.pi
PRESS = pathlib.Path(__file__).resolve().parents[2] / "graphmethods" / "problems" / "data" / "slider_crank_press.json"

pytestmark = pytest.mark.hard


def test_moment_with_a_jump_work_diagram_is_exact_at_interval_ends_and_errs_only_inside():
    """W3: M_r jumps from 60 to 10 N·m at π/4. The chords are exact at every interval end; inside the
    interval holding the jump the chord cuts the corner by jump·h·t(1 − t) (t: where the jump lies)."""
    M_r = problems.w3().excess_work.M_r
    M_d = problems.w3().excess_work.M_d
    for m in (6, 12, 24, 7):
        phi = np.linspace(0, 2 * PI, m + 1)
        wd = gc.work_diagrams(M_d, M_r, phi, mu_phi=PI / 90, mu_M=2.0, exact_d=M_d, exact_r=M_r)
        np.testing.assert_allclose(wd.A_r.values, M_r.integral(phi), atol=1e-12)
        np.testing.assert_allclose(wd.delta_E, (M_d - M_r).integral(phi), atol=1e-12)
        h = 2 * PI / m
        t = (PI / 4) / h % 1.0
        expect = 50.0 * h * t * (1 - t)
        assert wd.A_r.accuracy.inside == pytest.approx(expect, rel=1e-9)
        assert wd.A_r.accuracy.inside_mm == pytest.approx(expect / wd.mu_A, rel=1e-9)
    # the figure draws the chords' ends on the exact integral and says: 0 at the ends, the corner inside
    scene = work_diagrams(problems.w3(), m=12)
    mu_A = scene.scales()[2].per_mm
    pts = np.asarray(scene.element("chords-A_r").points)
    o = scene.element("axis-A").origin
    np.testing.assert_allclose((o[1] - pts[:, 1]) * mu_A, M_r.integral(np.linspace(0, 2 * PI, 13)), atol=1e-3 * mu_A)
    row = {r[0]: r for r in scene.element("accuracy-table").rows[1:]}["A_r"]
    assert row[1] == "0 J" and row[3] == f"{50.0 * PI / 6 * 0.25:.3g} J"


def test_slider_acceleration_at_the_far_dead_centre_closes_across_the_period_and_converges():
    """The far dead centre is position 0, where a is largest: the chord across the period's end gives a
    there (a₀ = a_m), equal to the second difference of s, short of the true peak by O(h²)."""
    case = read_case(PRESS)
    errs, v0 = [], []
    for m in (12, 24, 48):
        sd = gc.slider_diagrams(case.mechanism, m, mu_phi=PI / 90, mu_s=0.004, omega_1=case.omega_m)
        h = 2 * PI / m / case.omega_m
        s = np.asarray(sd.s)
        assert sd.a.values[0] == sd.a.values[-1]
        assert sd.a.values[0] == pytest.approx((s[1] - 2 * s[0] + s[m - 1]) / h**2, rel=1e-9)
        assert 0 < sd.a.values[0] < sd.a_exact[0]                     # the right sign, the peak cut
        err = np.abs(np.asarray(sd.a.values) - sd.a_exact)
        assert int(np.argmax(err)) in (0, m)                          # the largest error is at the dead centre
        assert sd.comparison()[2]["at"] == pytest.approx(0.0, abs=1e-12)
        assert sd.v_plans[0] == 0.0                                   # the plan puts b on the pole
        v0.append(abs(sd.v_at_positions[0]))       # read off v: not 0 with an offset (asymmetric), but → 0
        errs.append(err[0])
    assert 3.8 < errs[0] / errs[1] < 4.2 and 3.8 < errs[1] / errs[2] < 4.2
    assert 0 < v0[2] < v0[1] < v0[0] < 0.01 and 3.5 < v0[0] / v0[1] < 4.5


def test_slider_acceleration_near_the_inner_dead_centre_of_a_short_rod_keeps_its_dip():
    """r/l = 0.45: a has a local maximum at the inner dead centre between two minima near ±117°;
    even from 6 positions the construction shows it, and it converges to the exact value."""
    mech = SliderCrank(r=0.1, l=0.22)
    exact_180 = float(gc.slider_motion(mech, [PI]).d2s[0])
    assert exact_180 == pytest.approx(-0.1 * (1 - 1 / 2.2))            # r(1 − λ) at the inner dead centre
    last = None
    for m in (6, 12, 24, 48):
        sd = gc.slider_diagrams(mech, m, mu_phi=PI / 90, mu_s=0.004)
        k = m // 2
        a = np.asarray(sd.a.values)
        assert a[k] > a[k - 1] and a[k] > a[k + 1]
        err = abs(a[k] - exact_180)
        assert last is None or err < last / 3.5
        last = err


def test_very_few_intervals_m6():
    """m = 6: the second difference of a harmonic is exact up to the factor sinc²(h/2); both figures still
    draw every construction line and report larger errors than at m = 12."""
    x = np.linspace(0, 2 * PI, 7)
    h = x[1] - x[0]
    D = gc.differentiate_by_chords(x, np.sin(x), mu_x=PI / 60, mu_Y=0.01, period=2 * PI)
    DD = gc.differentiate_by_chords(D.x, D.values, mu_x=PI / 60, mu_Y=D.mu, period=2 * PI, x_origin=0.0)
    np.testing.assert_allclose(DD.values, -np.sin(x) * (math.sin(h / 2) / (h / 2)) ** 2, atol=1e-14)
    case = read_case(PRESS)
    kin = calculus.kinematic_diagrams(case, m=6)
    assert {f"ray-v-{k}" for k in range(1, 7)} <= {e.name for e in kin.elements}
    assert {f"dot-a-{k}" for k in range(7)} <= {e.name for e in kin.elements}
    work = work_diagrams(case, m=6)
    assert len(work.element("chords-A_r").points) == 7
    rows6 = gc.accuracy_table(case, ms=(6, 12))
    for name in ("v by chords of s", "a by chords of v"):
        e6, e12 = (r["error"] for r in rows6 if r["construction"] == name)
        assert e6 > e12
    st = Study(case, positions=6)
    wd = gc.study_work_diagrams(st, mu_phi=PI / 90, mu_M=10.0)
    # M_r is drawn as the course draws it (its ordinates, the load's jumps at the switching positions, the
    # smooth curve between): even from 6 points its work at the nodes is the exact one to a fraction of a joule
    assert abs(wd.closure) < 1e-9 and wd.A_r.accuracy.at_nodes < 1.0
    assert st.moments[1].work() == pytest.approx(wd.A_r.values[-1])
