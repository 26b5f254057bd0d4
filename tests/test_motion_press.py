"""The press case (shared/cases/slider_crank_press.json) against the exact solver.

The slider-crank reduction belongs to another part of the project; to validate the solver
independently, this file writes the offset slider-crank's J_e(φ) and M_e(φ) in closed form (and
its ΔE(φ) analytically: the force's work is F0 times the slider's travel). Other test files import
``press_model`` from here (``from test_motion_press import press_model``; tests/ is on sys.path).
"""

from __future__ import annotations

import json
import math
import os
import pathlib
from dataclasses import dataclass

import numpy as np
import pytest

from graphmethods.dynamics.motion import ReducedModel, exact_flywheel, periodic_motion

SHARED_CASES = pathlib.Path(os.environ.get("GRAPHMETHODS_SHARED_CASES",
                                           pathlib.Path(__file__).resolve().parents[2] / "shared" / "cases"))


def load_case() -> dict:
    """slider_crank_press.json as it is (skips when ../shared/cases is absent, as conftest does)."""
    path = SHARED_CASES / "slider_crank_press.json"
    if not path.is_file():
        if os.environ.get("CI"):
            pytest.fail(f"reference case not found at {path} (set GRAPHMETHODS_SHARED_CASES)")
        pytest.skip(f"reference case not found at {path} (set GRAPHMETHODS_SHARED_CASES)")
    return json.loads(path.read_text(encoding="utf-8"))


@dataclass(frozen=True)
class Press:
    model: ReducedModel
    M_d: float
    phi_0: float          # far dead centre (position 0)
    phi_near: float       # near dead centre (end of the working stroke)
    phi_on: float         # the force switches on (force_from of the stroke)
    phi_off: float        # and off (force_to)
    omega_m: float
    delta: float
    kin: object
    x_far: float
    F0: float

    def delta_E(self, phi):
        """ΔE(φ) from position 0, analytically: M_d (φ − φ_0) + F0 (x_B(φ) − x_B(φ_on)) while on."""
        u = np.mod(np.asarray(phi, dtype=float) - self.phi_0, 2 * np.pi)
        phi_abs = self.phi_0 + u
        clipped = np.clip(phi_abs, self.phi_on, self.phi_off)
        xB = self.kin(clipped)[0]
        x_on = self.kin(np.array(self.phi_on))[0]
        return self.M_d * u + self.F0 * (xB - x_on)


def press_model(case: dict | None = None, *, declare_breaks: bool = True, m3: float | None = None) -> Press:
    """Closed-form J_e(φ), M_e(φ) of the offset slider-crank press (φ from +x, counterclockwise)."""
    c = dict(load_case() if case is None else case)
    if m3 is not None:
        c["m3"] = m3
    r, l, e, a2 = c["r"], c["l"], c["e"], c["l_AS2"]
    m2, J_S2, m3_, J1, F0 = c["m2"], c["J_S2"], c["m3"], c["J1"], c["F0"]
    x_far = math.sqrt((l + r) ** 2 - e**2)
    x_near = math.sqrt((l - r) ** 2 - e**2)
    H = x_far - x_near
    phi_0 = math.asin(e / (l + r))
    phi_near = math.pi + math.asin(e / (l - r))

    def kin(phi):
        phi = np.asarray(phi, dtype=float)
        th = np.arcsin((e - r * np.sin(phi)) / l)             # rod angle: r sinφ + l sinθ = e
        w2 = -r * np.cos(phi) / (l * np.cos(th))              # ω2/ω
        xB = r * np.cos(phi) + l * np.cos(th)
        vB = -r * np.sin(phi) - l * np.sin(th) * w2           # v_B/ω
        vSx = -r * np.sin(phi) - a2 * np.sin(th) * w2
        vSy = r * np.cos(phi) + a2 * np.cos(th) * w2
        return xB, vB, w2, vSx, vSy

    def J_e(phi):
        _, vB, w2, vSx, vSy = kin(phi)
        return J1 + m2 * (vSx**2 + vSy**2) + J_S2 * w2**2 + m3_ * vB**2

    frac_on, frac_off = c["force_from"], c["force_to"]
    M_d = (frac_off - frac_on) * F0 * H / (2 * math.pi)

    def M_e(phi):
        xB, vB = kin(phi)[:2]
        frac = (x_far - xB) / H
        working = np.mod(phi - phi_0, 2 * math.pi) < phi_near - phi_0
        on = working & (frac >= frac_on) & (frac <= frac_off)
        return M_d + np.where(on, F0 * vB, 0.0)              # v_B < 0 on the working stroke

    def crank_angle_at(fraction):
        lo, hi = phi_0, phi_near
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            if (x_far - kin(mid)[0]) / H < fraction:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)

    phi_on, phi_off = crank_angle_at(frac_on), crank_angle_at(frac_off)
    model = ReducedModel(J_e=J_e, M_e=M_e, phi_0=phi_0,
                         breaks=(phi_on, phi_off) if declare_breaks else ())
    return Press(model=model, M_d=M_d, phi_0=phi_0, phi_near=phi_near, phi_on=phi_on, phi_off=phi_off,
                 omega_m=math.pi * c["n_rpm"] / 30, delta=float(c["delta"]), kin=kin, x_far=x_far, F0=F0)


def brute_force_flywheel(J_e, delta_E, *, omega_m, delta, phi_0, extra=(), n=2_000_001):
    """J_F and the angles of ω_max, ω_min from a dense evaluation of exact ΔE and J_e."""
    phi = np.union1d(phi_0 + 2 * np.pi * np.linspace(0, 1, n), np.asarray(extra, dtype=float))
    E, J = delta_E(phi), J_e(phi)
    a_max, a_min = 0.5 * (omega_m * (1 + delta / 2)) ** 2, 0.5 * (omega_m * (1 - delta / 2)) ** 2
    g1, g2 = E - a_max * J, E - a_min * J
    i, k = int(np.argmax(g1)), int(np.argmin(g2))
    return (g1[i] - g2[k]) / (delta * omega_m**2), phi[i], phi[k]


# ------------------------------------------------------------------------------------------------

def test_closed_form_velocity_analogue_matches_the_derivative_of_the_slider_position():
    p = press_model()
    phi = np.linspace(0, 2 * np.pi, 37)
    h = 1e-6
    xB_plus, xB_minus = p.kin(phi + h)[0], p.kin(phi - h)[0]
    np.testing.assert_allclose(p.kin(phi)[1], (xB_plus - xB_minus) / (2 * h), atol=1e-8)


def test_analytic_delta_E_agrees_with_the_solver_quadrature():
    from graphmethods.dynamics.motion import _balanced_energy

    p = press_model(declare_breaks=False)
    phi = p.model.positions(97)
    np.testing.assert_allclose(_balanced_energy(p.model, 1e-6)(phi), p.delta_E(phi), atol=1e-9)


@pytest.mark.parametrize("declare_breaks", [True, False])
def test_press_exact_flywheel_is_13_94(declare_breaks):
    p = press_model(declare_breaks=declare_breaks)
    fw = exact_flywheel(p.model, omega_m=p.omega_m, delta=p.delta)
    assert round(fw.J_F, 2) == 13.94
    assert abs(math.degrees(fw.phi_omega_max_from_0) - 23) < 1
    assert abs(math.degrees(fw.phi_omega_min_from_0) - 152) < 1
    assert fw.rel_accuracy < 1e-8
    assert fw.delta_check == pytest.approx(p.delta, rel=1e-10)


def test_press_exact_flywheel_agrees_with_a_dense_brute_force_to_1e_9():
    p = press_model()
    fw = exact_flywheel(p.model, omega_m=p.omega_m, delta=p.delta)
    J_bf, phi_max, phi_min = brute_force_flywheel(p.model.J_e_at, p.delta_E, omega_m=p.omega_m,
                                                  delta=p.delta, phi_0=p.phi_0,
                                                  extra=(p.phi_on, p.phi_off))
    assert fw.J_F == pytest.approx(J_bf, rel=1e-9)
    assert fw.phi_omega_max == pytest.approx(phi_max, abs=1e-5)
    assert fw.phi_omega_min == pytest.approx(phi_min, abs=1e-5)


def test_press_omega_max_is_where_the_force_switches_on():
    # The force switches on at 5 % of the stroke: M_e drops from +M_d to M_d + F0 v_B < 0, so ΔE
    # has a corner there and the speed peaks exactly at it.
    p = press_model()
    fw = exact_flywheel(p.model, omega_m=p.omega_m, delta=p.delta)
    assert fw.phi_omega_max == pytest.approx(p.phi_on, abs=1e-9)


def test_press_motion_with_the_exact_flywheel_by_an_independent_rk4_on_omega_squared():
    # Converse check on a different path: d(ω²)/dφ = (2 M_e − ω² J')/J, integrated by RK4 from
    # ω(φ_0), uses neither ΔE nor T = T0 + ΔE.
    p = press_model()
    fw = exact_flywheel(p.model, omega_m=p.omega_m, delta=p.delta)
    J = lambda x: fw.J_F + p.model.J_e_at(x)                               # noqa: E731
    f = lambda x, w2: (2 * p.model.M_e_at(x) - w2 * p.model.dJ_e_at(x)) / J(x)  # noqa: E731
    nodes = np.union1d(p.phi_0 + 2 * np.pi * np.linspace(0, 1, 7201), [p.phi_on, p.phi_off])
    w2 = fw.motion.omega[0] ** 2
    out = [w2]
    for x0, x1 in zip(nodes[:-1], nodes[1:]):
        h = x1 - x0
        a, b = np.nextafter(x0, np.inf), np.nextafter(x1, -np.inf)
        k1 = f(a, w2)
        k2 = f(x0 + h / 2, w2 + h / 2 * k1)
        k3 = f(x0 + h / 2, w2 + h / 2 * k2)
        k4 = f(b, w2 + h * k3)
        w2 = w2 + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        out.append(float(w2))
    w = np.sqrt(out)
    assert w[-1] == pytest.approx(w[0], rel=1e-7)                         # periodic
    assert (w.max() - w.min()) / p.omega_m == pytest.approx(p.delta, rel=1e-4)


def test_press_motion_measures_are_consistent():
    p = press_model()
    fw = exact_flywheel(p.model, omega_m=p.omega_m, delta=p.delta)
    mo = fw.motion
    assert mo.omega_m == pytest.approx(p.omega_m, rel=1e-12)
    assert mo.omega_max == pytest.approx(p.omega_m * (1 + p.delta / 2), rel=1e-12)
    assert mo.omega_min == pytest.approx(p.omega_m * (1 - p.delta / 2), rel=1e-12)
    assert np.all(mo.omega <= mo.omega_max * (1 + 1e-12))
    assert np.all(mo.omega >= mo.omega_min * (1 - 1e-12))
    assert mo.omega_m_time == pytest.approx(2 * np.pi / mo.t_T, rel=1e-12)
    assert mo.omega_min < mo.omega_m_time < mo.omega_max
    assert mo.chi == pytest.approx(abs(mo.epsilon_max) / p.omega_m**2)
    assert np.all(np.diff(mo.t) > 0)
    # ε = ω dω/dφ, checked against the output ω by central differences away from the jumps
    dw = np.gradient(mo.omega, mo.phi)
    away = (np.abs(mo.phi - p.phi_on) > 0.05) & (np.abs(mo.phi - p.phi_off) > 0.05)
    away[[0, -1]] = False
    np.testing.assert_allclose((mo.omega * dw)[away], mo.epsilon[away], rtol=2e-3, atol=0.05)


def test_press_given_flywheel_then_delta_round_trips():
    p = press_model()
    mo = periodic_motion(p.model, J_F=13.94, omega_m=p.omega_m)
    fw = exact_flywheel(p.model, omega_m=p.omega_m, delta=mo.delta)
    assert fw.J_F == pytest.approx(13.94, rel=1e-10)
