"""Reduced models of machines for the benchmark and for users: smooth loads, a four-stroke engine.

Each returns a :class:`~graphmethods.dynamics.motion.ReducedModel` with its mean speed and
permissible [δ]. The data are in the style of textbook problems (not taken from one source).

>>> p = four_stroke_engine()
>>> round(p.model.phi_T / 3.141592653589793, 6), p.delta
(4.0, 0.02)
>>> p.name, p.title.title_in("ru"), p.title.title_in("zh")
('four-stroke engine', 'четырёхтактный двигатель', '四冲程发动机')
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from graphmethods.compat import trapezoid
from graphmethods.dynamics.motion import ReducedModel
from graphmethods.titles import Title
from graphmethods.units import omega_from_n

PI = math.pi


@dataclass(frozen=True)
class ReducedProblem:
    """A machine given by its reduced model, mean speed (rad/s) and permissible δ.

    ``name`` is its key in tables (the benchmark's rows); ``title`` the name to print, by language
    (a :class:`~graphmethods.titles.Title`; plain text or a mapping by language is turned into
    one; by default the name).
    """

    name: str
    about: str
    model: ReducedModel
    omega_m: float
    delta: float
    title: Title | str | Mapping[str, str] | None = None

    def __post_init__(self):
        object.__setattr__(self, "title", Title.of(self.name if self.title is None else self.title,
                                                   where=f"problem {self.name}: title"))


def smooth_machine() -> ReducedProblem:
    """A machine with smooth loads: J_e = 2 + 0.4 cos 2φ kg·m², M_e = 300 (sin φ + 0.4 sin 3φ) N·m, 200 rev/min,
    [δ] = 1/50."""
    model = ReducedModel(
        J_e=lambda p: 2.0 + 0.4 * np.cos(2 * p),
        M_e=lambda p: 300.0 * (np.sin(p) + 0.4 * np.sin(3 * p)),
        dJ_e=lambda p: -0.8 * np.sin(2 * p),
    )
    return ReducedProblem("smooth machine", "smooth moment and inertia, both harmonic", model, omega_from_n(200.0),
                          1 / 50,
                          title={"en": "machine with smooth loads", "ru": "машина с плавно изменяющимися нагрузками",
                                 "zh": "载荷平稳变化的机器"})


def four_stroke_engine(*, r: float = 0.06, lam: float = 0.25, m_p: float = 2.5, J0: float = 0.35,
                       F_gas: float = 30e3, n_rpm: float = 1500.0, delta: float = 0.02) -> ReducedProblem:
    """A single-cylinder four-stroke engine over its period of two turns (φ_T = 4π).

    Piston mass m_p on a crank of radius r with λ = r/l: J_e = J0 + m_p (r (sin φ + λ/2 sin 2φ))²
    (the usual first-order approximation of the piston's velocity analogue). Gas force: a power
    stroke decaying as F_gas e^(−3φ/π) on [0, π], compression rising to F_gas/4 on [3π, 4π],
    nothing on exhaust and intake; the consumer's moment is constant (work balance).
    """
    def analogue(p):
        return r * (np.sin(p) + 0.5 * lam * np.sin(2 * p))

    def gas_force(p):
        p = np.mod(p, 4 * PI)
        power = np.where(p < PI, F_gas * np.exp(-3.0 * p / PI), 0.0)
        compression = np.where(p >= 3 * PI, -0.25 * F_gas * (p - 3 * PI) / PI, 0.0)
        return power + compression

    # the consumer's constant moment balances the gas work over the period (computed once, finely)
    x = np.linspace(0.0, 4 * PI, 400_001)
    M_gas = gas_force(x) * analogue(x)
    M_c = float(trapezoid(M_gas, x) / (4 * PI))
    model = ReducedModel(
        J_e=lambda p: J0 + m_p * analogue(p) ** 2,
        M_e=lambda p: gas_force(p) * analogue(p) - M_c,
        phi_T=4 * PI,
        breaks=(PI, 3 * PI),
    )
    return ReducedProblem("four-stroke engine", "one cylinder, period 4π, gas force with a jump at φ = 0/4π",
                          model, omega_from_n(n_rpm), delta,
                          title={"en": "four-stroke engine", "ru": "четырёхтактный двигатель", "zh": "四冲程发动机"})
