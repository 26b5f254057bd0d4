"""The graphical methods at m positions, as a student draws them, for any reduced model.

At positions 0…m the student knows J_e(φ_k) and M_e(φ_k) and joins the values by straight
chords. From the chords (M_e's mean subtracted, as the driving moment is balanced against the
drawn curve) come the excess-work table, ΔW_max and ΔT at the positions; hence the two graphical
flywheels: the ΔW_max method (J_e taken as its mean) and the Wittenbauer diagram. Their errors
against :func:`~graphmethods.dynamics.motion.exact_flywheel` are those of the m positions and the
chords.

>>> import numpy as np
>>> from graphmethods.dynamics.motion import ReducedModel
>>> model = ReducedModel(J_e=1.0, M_e=lambda p: 40.0 * np.cos(p))
>>> g = chord_flywheels(model, positions=12, omega_m=20.0, delta=0.04)
>>> round(g.wittenbauer.J_F, 4) == round(g.energy.J_F, 4)       # J_e constant: the same method
True
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from graphmethods.dynamics import excess_work as ew
from graphmethods.dynamics.flywheel import Flywheel, flywheel
from graphmethods.dynamics.moments import MomentCurve
from graphmethods.dynamics.motion import ReducedModel
from graphmethods.dynamics.wittenbauer import WittenbauerResult, wittenbauer
from graphmethods.errors import InputError
from graphmethods.units import MAGNITUDE_MIN, convenient_at_least


@dataclass(frozen=True, eq=False)
class ChordFlywheels:
    """The two graphical flywheels at m positions, with what they were built from."""

    phi: np.ndarray
    J_e: np.ndarray
    M_e: np.ndarray
    delta_T: np.ndarray
    excess_work: ew.ExcessWork
    energy: Flywheel
    wittenbauer: WittenbauerResult


def diagram_scales(J_e: np.ndarray, delta_T: np.ndarray, *, span_mm: float = 150.0) -> tuple[float, float]:
    """Convenient μ_J, μ_T for an energy–mass diagram about ``span_mm`` across."""
    J_max = float(J_e.max())
    if not J_max > 0:
        raise InputError("the reduced moment of inertia J_e is zero in every position (every mass and moment of "
                         "inertia of the problem is zero): an energy–mass diagram needs them; give the masses")
    span_T = float(np.ptp(delta_T)) or 1.0
    if span_T / span_mm < MAGNITUDE_MIN or J_max / span_mm < MAGNITUDE_MIN:
        raise InputError(f"the kinetic energy varies by {span_T:.3g} J and J_e reaches {J_max:.3g} kg·m² over the "
                         f"cycle: too small to draw at any scale (the loads or masses of the problem are below "
                         f"{MAGNITUDE_MIN:g} in their units)")
    return convenient_at_least(J_max / span_mm), convenient_at_least(span_T / span_mm)


#: The finer construction that estimates the error at m positions has REFINE·m positions, at most FINE_CAP.
REFINE = 16
FINE_CAP = 2**21


def with_refined_estimate(wb: WittenbauerResult, J_F_fine: float, m_fine: int) -> WittenbauerResult:
    """``wb`` with its error estimate replaced by J_F(m_fine) − J_F(m) from a finer construction.

    With REFINE = 16 the finer construction's own error is about 1/16 of the first's where a load
    jumps between positions (first order) and 1/256 on smooth curves (second order), so the
    estimate is within a few percent of the true sampling error; the chord-extension estimate of
    :func:`~graphmethods.dynamics.wittenbauer.wittenbauer`, which can only over-estimate smooth
    touches, is kept for data given without a model.
    """
    return replace(wb, error_estimate=J_F_fine - wb.J_F,
                   error_method=f"J_F at {m_fine} positions minus J_F at {wb.m} "
                                f"(same construction, {m_fine // wb.m}× finer)")


def chord_flywheels(model: ReducedModel, *, positions: int, omega_m: float, delta: float,
                    mu_J: float | None = None, mu_T: float | None = None, estimate: bool = True) -> ChordFlywheels:
    """J_F by the ΔW_max method and by Wittenbauer from the values at positions 0…m joined by chords.

    With ``estimate`` the Wittenbauer error estimate comes from the same construction at 16m positions.
    """
    phi = model.positions(positions)
    J_e = model.J_e_at(phi)
    M_e = model.M_e_at(phi)
    drawn = MomentCurve.points(phi, M_e)
    balanced = drawn - MomentCurve.constant(drawn.mean(), period=drawn.period, start=drawn.start)
    cycle = ew.from_moments(M_d=balanced, M_r=MomentCurve.constant(0.0, period=drawn.period, start=drawn.start))
    delta_T = balanced.integral(phi)
    if mu_J is None or mu_T is None:
        mu_J, mu_T = diagram_scales(J_e, delta_T)
    energy = flywheel(cycle.delta_W_max, delta=delta, omega_m=omega_m, J_e=float(np.mean(J_e[:-1])))
    wb = wittenbauer(J_e=J_e, delta_T=delta_T, omega_m=omega_m, delta=delta, mu_J=mu_J, mu_T=mu_T, phi=phi,
                     phi_0=model.phi_0, phi_T=model.phi_T)
    m_fine = min(REFINE * positions, FINE_CAP)
    if estimate and m_fine > positions:
        fine = chord_flywheels(model, positions=m_fine, omega_m=omega_m, delta=delta, estimate=False)
        wb = with_refined_estimate(wb, fine.wittenbauer.J_F, m_fine)
    return ChordFlywheels(phi=phi, J_e=J_e, M_e=M_e, delta_T=delta_T, excess_work=cycle, energy=energy, wittenbauer=wb)
