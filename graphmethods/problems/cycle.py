"""A cycle problem: a machine's cycle given as areas, works or moment curves, with its speed data.

>>> from graphmethods.problems import w1
>>> p = w1()
>>> round(p.flywheel().J_F, 2)
43.69
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

from graphmethods.dynamics import excess_work as ew
from graphmethods.dynamics.flywheel import Flywheel, flywheel
from graphmethods.dynamics.kinetic_energy import KineticEnergy, kinetic_energy
from graphmethods.dynamics.moments import MomentCurve
from graphmethods.errors import InputError
from graphmethods.titles import Title


@dataclass(frozen=True, eq=False)
class CycleProblem:
    """A cycle problem at the level its textbook states it; nothing more is modelled.

    Give exactly one of: ``work_J`` (excess works, J); ``areas_mm2`` with ``mu_M``,
    ``mu_phi`` (measured areas); ``M_d``/``M_r`` moment curves (one may be omitted and is
    then balanced). Speed data: ``n_rpm`` and ``delta`` for a flywheel; ``J_e`` and
    ``omega_0`` for a kinetic-energy graph. ``work_unit`` and ``inertia_unit`` name the units the
    problem is stated in (``"kG·m"`` and ``"kG·m·s²"`` for an old-unit problem; the numbers are
    taken as they are). ``title`` is a :class:`~graphmethods.titles.Title`;
    plain text (used for every language) or a mapping by language is turned into one.

    >>> p = CycleProblem(id="P1", title={"en": "Press", "ru": "Пресс"}, work_J=(10, -10))
    >>> p.title.title_in("ru"), p.title.title_in("zh"), CycleProblem(id="P2", title="Pump").title.title_in("zh")
    ('Пресс', 'Press', 'Pump')
    """

    id: str
    title: Title
    source: str = ""
    work_J: tuple[float, ...] | None = None
    areas_mm2: tuple[float, ...] | None = None
    mu_M: float | None = None
    mu_phi: float | None = None
    M_d: MomentCurve | None = None
    M_r: MomentCurve | None = None
    boundaries: tuple[float, ...] | None = None
    n_rpm: float | None = None
    delta: float | None = None
    J_e: float = 0.0
    omega_0: float | None = None
    note: str = ""
    work_unit: str = "J"
    inertia_unit: str = "kg·m²"

    def __post_init__(self):
        object.__setattr__(self, "title", Title.of(self.title, where=f"problem {self.id}: title"))

    @cached_property
    def excess_work(self) -> ew.ExcessWork:
        """The excess-work table (computed once, on first use)."""
        if self.work_J is not None:
            return ew.from_work(self.work_J)
        if self.areas_mm2 is not None:
            if self.mu_M is None:
                raise InputError(f"{self.id}: areas_mm2 need mu_M (N·m per mm of the moment axis) to become works")
            return ew.from_areas(self.areas_mm2, mu_M=self.mu_M, mu_phi=self.mu_phi)
        if self.M_d is not None or self.M_r is not None:
            return ew.from_moments(self.M_d, self.M_r, boundaries=self.boundaries)
        raise InputError(f"problem {self.id}: give works, areas or moment curves")

    def flywheel(self) -> Flywheel:
        """The approximate-method flywheel for the problem's n and [δ]."""
        if self.n_rpm is None or self.delta is None:
            raise InputError(f"problem {self.id} gives no n and [δ]; it has no flywheel question")
        return flywheel(self.excess_work.delta_W_max, delta=self.delta, n_rpm=self.n_rpm, J_e=self.J_e)

    def kinetic_energy(self) -> KineticEnergy:
        """T and ω at the boundaries, from ω0 and a constant J_e."""
        if self.omega_0 is None:
            raise InputError(f"problem {self.id} gives no starting speed omega_0")
        return kinetic_energy(self.excess_work, J_e=self.J_e, omega_0=self.omega_0)
