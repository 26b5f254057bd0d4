"""Excess work (избыточная работа, 盈亏功): intervals, areas, running energy and ΔW_max.

A cycle enters at whatever level the problem gives it, and nothing more is modelled:

* :func:`from_areas` — signed areas f_i (mm²) between the M_d and M_r curves, with the
  drawing's scales: A_i = f_i μ_M μ_φ;
* :func:`from_work` — the excess works A_i directly in J;
* :func:`from_levels` — the running energy levels E_0 … E_n;
* :func:`from_moments` — the moment curves themselves (:class:`~.moments.MomentCurve`):
  the crossings of M_d and M_r are found exactly (inside a chord, at a vertex, at a
  jump), touching without crossing and coincident stretches do not start new
  intervals, and the areas are exact for the chords.

Each gives an :class:`ExcessWork`: the excess-work table (points a, b, c, …, works,
running energy), E_max and E_min with their points, ΔW_max = E_max − E_min, and the
closure residual Σ A_i (zero for a steady cycle; a hand-measured set of areas never
closes exactly, and a residual beyond ``closure_tol`` is refused).

W1 (diesel generator; the staircase goes down first, b is the lowest point, e the highest):

>>> w1 = from_work([-50, 550, -100, 125, -500, 25, -50])
>>> w1.E.tolist()
[0.0, -50.0, 500.0, 400.0, 525.0, 25.0, 50.0, 0.0]
>>> w1.delta_W_max, w1.labels[w1.index_E_max], w1.labels[w1.index_E_min]
(575.0, 'e', 'b')
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from graphmethods.dynamics.moments import MomentCurve, balance
from graphmethods.errors import InputError, UnbalancedCycleError
from graphmethods.units import MAX_POSITIONS_COMPUTED, count, finite_array, real

#: Default closure tolerance for measured data (areas, works, levels): |Σ A_i| / Σ|A_i|.
CLOSURE_TOL_MEASURED = 0.05
#: Default closure tolerance for moment curves, which should balance exactly.
CLOSURE_TOL_CURVES = 1e-6


def point_labels(n: int) -> tuple[str, ...]:
    """Textbook point names a, b, c, …, z, a1, b1, … for n points.

    >>> point_labels(3), point_labels(28)[-2:]
    (('a', 'b', 'c'), ('a1', 'b1'))
    """
    n = count(n, "the number of points n", low=0, high=MAX_POSITIONS_COMPUTED)     # bounded before the loop
    return tuple(chr(97 + i % 26) + (str(i // 26) if i >= 26 else "") for i in range(n))


def _num(v: float) -> str:
    s = f"{v:.6g}"
    return "0" if s in ("-0", "0", "-0.0") else s


@dataclass(frozen=True, eq=False)
class ExcessWork:
    """The excess-work table of one cycle and what follows from it.

    Attributes
    ----------
    work : ndarray, J
        Excess work A_i of each interval, + for a gain (M_d > M_r), − for a loss.
    E : ndarray, J
        Running energy at the interval boundaries, ``E[0] = 0``, ``E[k] = Σ_{i<k} A_i``;
        ``E[-1]`` is the closure residual.
    phi : ndarray or None, rad
        Angles of the boundaries (moment-curve input only).
    areas_mm2 : ndarray or None
        The areas as measured on the drawing (area input only).
    mu_M, mu_phi : float or None
        The drawing's scales, N·m/mm and rad/mm (area input only).
    M_d, M_r : MomentCurve or None
        The moment curves (moment-curve input only).
    closure_tol : float
        The relative closure tolerance the cycle was accepted with.
    """

    work: np.ndarray
    E: np.ndarray
    phi: np.ndarray | None = None
    areas_mm2: np.ndarray | None = None
    mu_M: float | None = None
    mu_phi: float | None = None
    M_d: MomentCurve | None = None
    M_r: MomentCurve | None = None
    closure_tol: float = CLOSURE_TOL_MEASURED

    # ----------------------------------------------------------------- derived values
    @property
    def labels(self) -> tuple[str, ...]:
        """Names of the boundaries: a, b, c, …"""
        return point_labels(self.E.size)

    @property
    def index_E_max(self) -> int:
        """Index (into ``E``/``labels``) of the highest energy level (first one on a tie)."""
        return int(np.argmax(self.E))

    @property
    def index_E_min(self) -> int:
        """Index of the lowest energy level (first one on a tie)."""
        return int(np.argmin(self.E))

    @property
    def E_max(self) -> float:
        """Highest running energy, J."""
        return float(self.E.max())

    @property
    def E_min(self) -> float:
        """Lowest running energy, J."""
        return float(self.E.min())

    @property
    def delta_W_max(self) -> float:
        """Maximum fluctuation of energy ΔW_max = E_max − E_min, J."""
        return self.E_max - self.E_min

    @property
    def residual(self) -> float:
        """Closure residual Σ A_i, J (0 for a steady cycle)."""
        return float(self.E[-1])

    @property
    def period(self) -> float | None:
        """The period φ_T in rad (moment-curve input only)."""
        return None if self.M_d is None else self.M_d.period

    @property
    def phi_E_max(self) -> float | None:
        """φ of the highest energy level, rad (moment-curve input only)."""
        return None if self.phi is None else float(self.phi[self.index_E_max])

    @property
    def phi_E_min(self) -> float | None:
        """φ of the lowest energy level, rad (moment-curve input only)."""
        return None if self.phi is None else float(self.phi[self.index_E_min])

    # ----------------------------------------------------------------- energy along the cycle
    def energy(self, phi: ArrayLike) -> NDArray[np.float64]:
        """ΔE(φ) = ∫ (M_d − M_r) dφ from the start of the period, J (moment-curve input only).

        >>> from math import pi
        >>> ew = from_moments(M_r=MomentCurve.steps([(0, pi / 4, 60.0), (pi / 4, 2 * pi, 10.0)]))
        >>> round(float(ew.energy(pi / 4)), 5)
        -34.36117
        """
        if self.M_d is None:
            raise InputError("ΔE(φ) needs moment curves; this cycle was given as areas, works or levels")
        assert self.M_r is not None                  # both curves, or neither
        return (self.M_d - self.M_r).integral(phi)

    def energy_curve(self, samples: int = 721) -> tuple[np.ndarray, np.ndarray]:
        """Points (φ, ΔE) for drawing the energy graph: the knots, the crossings and
        ``samples`` evenly spaced angles, all exact (ΔE is piecewise quadratic)."""
        if self.M_d is None:
            raise InputError("the energy graph needs moment curves; draw the energy indicator instead")
        assert self.M_r is not None and self.phi is not None
        D = self.M_d - self.M_r
        even = np.linspace(D.phi[0], D.phi[-1], samples)
        phi = np.unique(np.concatenate((D.phi, self.phi, even)))
        return phi, self.energy(phi)

    # ----------------------------------------------------------------- the table
    def rows(self) -> list[dict[str, Any]]:
        """The excess-work table, one row per interval: points, area, work, energy at its end."""
        rows = []
        labels = self.labels                       # once: the table is linear in the number of intervals
        work, E = self.work.tolist(), self.E.tolist()
        areas = None if self.areas_mm2 is None else self.areas_mm2.tolist()
        phi_deg = None if self.phi is None else np.degrees(self.phi).tolist()
        for i, A in enumerate(work):
            row = {"interval": f"{labels[i]}–{labels[i + 1]}", "A_J": A, "E_J": E[i + 1]}
            if areas is not None:
                row["f_mm2"] = areas[i]
            if phi_deg is not None:
                row["phi_from_deg"] = phi_deg[i]
                row["phi_to_deg"] = phi_deg[i + 1]
            rows.append(row)
        return rows

    def _table(self, unit: str = "J") -> tuple[list[str], list[list[str]]]:
        head = ["interval"]
        if self.phi is not None:
            head += ["φ from, °", "φ to, °"]
        if self.areas_mm2 is not None:
            head += ["f, mm²"]
        head += [f"A, {unit}", f"E at end, {unit}"]
        body = []
        for r in self.rows():
            line = [r["interval"]]
            if self.phi is not None:
                line += [_num(round(r["phi_from_deg"], 4)), _num(round(r["phi_to_deg"], 4))]
            if self.areas_mm2 is not None:
                line += [_num(r["f_mm2"])]
            line += [_num(r["A_J"]), _num(r["E_J"])]
            body.append(line)
        return head, body

    def _summary(self, unit: str = "J") -> list[str]:
        i, j = self.index_E_max, self.index_E_min
        out = [
            f"E_max = {_num(self.E_max)} {unit} at {self.labels[i]}"
            + (f" (φ = {_num(round(math.degrees(self.phi[i]), 4))}°)" if self.phi is not None else ""),
            f"E_min = {_num(self.E_min)} {unit} at {self.labels[j]}"
            + (f" (φ = {_num(round(math.degrees(self.phi[j]), 4))}°)" if self.phi is not None else ""),
            f"ΔW_max = {_num(self.delta_W_max)} {unit}",
            f"closure residual ΣA = {_num(self.residual)} {unit}",
        ]
        return out

    def to_markdown(self, *, unit: str = "J") -> str:
        """The excess-work table as Markdown, followed by E_max, E_min, ΔW_max and the residual.

        ``unit`` names the unit of work the data are in (``"kG·m"`` for an old-unit problem)."""
        head, body = self._table(unit)
        lines = ["| " + " | ".join(head) + " |", "|" + "|".join("---" for _ in head) + "|"]
        lines += ["| " + " | ".join(r) + " |" for r in body]
        return "\n".join(lines + [""] + [f"- {s}" for s in self._summary(unit)]) + "\n"

    def _repr_markdown_(self) -> str:          # a notebook shows the table
        return self.to_markdown()

    def to_text(self, *, unit: str = "J") -> str:
        """The excess-work table as aligned plain text; ``unit`` as in :meth:`to_markdown`.

        >>> print(from_work([10, -10]).to_text())
        interval  A, J  E at end, J
        a–b         10           10
        b–c        -10            0
        E_max = 10 J at b
        E_min = 0 J at a
        ΔW_max = 10 J
        closure residual ΣA = 0 J
        """
        head, body = self._table(unit)
        widths = [max(len(r[k]) for r in [head] + body) for k in range(len(head))]

        def fmt(r: list[str]) -> str:
            return "  ".join(c.ljust(w) if k == 0 else c.rjust(w) for k, (c, w) in enumerate(zip(r, widths)))

        return "\n".join([fmt(head)] + [fmt(r) for r in body] + self._summary(unit))

    def to_dict(self) -> dict[str, Any]:
        """A JSON-ready dict of the table and results."""
        d = {
            "labels": list(self.labels),
            "work_J": self.work.tolist(),
            "E": self.E.tolist(),
            "index_E_max": self.index_E_max,
            "index_E_min": self.index_E_min,
            "E_max": self.E_max,
            "E_min": self.E_min,
            "delta_W_max": self.delta_W_max,
            "residual": self.residual,
        }
        if self.areas_mm2 is not None:
            d.update(areas_mm2=self.areas_mm2.tolist(), mu_M=self.mu_M, mu_phi=self.mu_phi)
        if self.phi is not None:
            d.update(phi=self.phi.tolist(), phi_deg=np.degrees(self.phi).tolist())
        return d


# --------------------------------------------------------------------- constructors
def _check_closure(work: np.ndarray, closure_tol: float, what: str) -> None:
    closure_tol = real(closure_tol, "closure_tol", lo=0.0, hint="the allowed residual |ΣA|/Σ|A|, e.g. 0.05")
    total = float(np.abs(work).sum())
    residual = float(work.sum())
    running = np.cumsum(work)
    if not (math.isfinite(total) and np.isfinite(running).all()):
        raise InputError(f"the {what} overflow when summed (their total or a running energy is beyond the float "
                         f"range); give them in a unit that keeps the sums finite, e.g. kJ instead of J")
    if total == 0.0:
        return
    if abs(residual) > closure_tol * total:
        raise UnbalancedCycleError(
            f"the cycle does not close: the {what} sum to {_num(residual)} J, "
            f"{abs(residual) / total:.3g} of their total {_num(total)} J, beyond the tolerance {closure_tol:g}; "
            "check the signs and values (driving and resisting work must balance over a period), "
            "or allow a larger residual with closure_tol (--closure-tol)"
        )


def _from_work_array(work: np.ndarray, closure_tol: float, what: str, **extra: Any) -> ExcessWork:
    if work.size == 0:
        raise InputError(f"no {what} given; give the signed values of the intervals in order")
    closure_tol = real(closure_tol, "closure_tol", lo=0.0, hint="the allowed residual |ΣA|/Σ|A|, e.g. 0.05")
    _check_closure(work, closure_tol, what)
    E = np.concatenate(([0.0], np.cumsum(work)))
    return ExcessWork(work=work, E=E, closure_tol=closure_tol, **extra)


def _positive(value: object, name: str, hint: str) -> float:
    return real(value, name, lo=0.0, lo_open=True, hint=hint)


def from_work(work_J: Sequence[float], *, closure_tol: float = CLOSURE_TOL_MEASURED) -> ExcessWork:
    """A cycle from the excess works A_i of its intervals, in J, in order (+ gain, − loss).

    >>> from_work([-50, 550, -100, 125, -500, 25, -50]).delta_W_max    # W2
    575.0
    """
    return _from_work_array(finite_array(work_J, "work"), closure_tol, "works")


def from_areas(
    areas_mm2: Sequence[float],
    *,
    mu_M: float,
    mu_phi: float | None = None,
    mu_phi_deg: float | None = None,
    closure_tol: float = CLOSURE_TOL_MEASURED,
) -> ExcessWork:
    """A cycle from the signed areas f_i (mm²) measured between the M_d and M_r curves.

    Parameters
    ----------
    areas_mm2 : sequence of float, mm²
        Areas in order along the period, + where M_d > M_r.
    mu_M : float, N·m/mm
        Moment scale of the drawing.
    mu_phi : float, rad/mm
        Angle scale; or ``mu_phi_deg`` in degrees per mm (English textbooks).

    Examples
    --------
    W4 as drawn (μ_M = 1 kG·m/mm, 2π = 80 mm with π taken as 3, so μ_φ = 0.075 rad/mm):

    >>> from_areas([200, -200, -200, 200], mu_M=1.0, mu_phi=0.075).E.tolist()
    [0.0, 15.0, 0.0, -15.0, 0.0]
    """
    mu_M = _positive(mu_M, "mu_M", "give the moment scale in N·m per mm")
    if (mu_phi is None) == (mu_phi_deg is None):
        raise InputError("give the angle scale once: mu_phi (rad/mm) or mu_phi_deg (degrees/mm)")
    if mu_phi is None:
        mu_phi = math.radians(_positive(mu_phi_deg, "mu_phi_deg", "give the angle scale in degrees per mm"))
    mu_phi = _positive(mu_phi, "mu_phi", "give the angle scale in rad per mm")
    areas = finite_array(areas_mm2, "areas")
    work = areas * (mu_M * mu_phi)
    work.setflags(write=False)
    return _from_work_array(work, closure_tol, "areas", areas_mm2=areas, mu_M=mu_M, mu_phi=mu_phi)


def from_levels(E: Sequence[float], *, closure_tol: float = CLOSURE_TOL_MEASURED) -> ExcessWork:
    """A cycle from its running energy levels E_0 … E_n (J), the last returning to the first.

    >>> from_levels([0, -50, 500, 400, 525, 25, 50, 0]).work.tolist()
    [-50.0, 550.0, -100.0, 125.0, -500.0, 25.0, -50.0]
    """
    levels = finite_array(E, "levels")
    if levels.size < 2:
        raise InputError("give at least two energy levels (the cycle's start and its end)")
    work = np.diff(levels)
    return _from_work_array(work, closure_tol, "levels' steps")


def from_moments(
    M_d: MomentCurve | None = None,
    M_r: MomentCurve | None = None,
    *,
    boundaries: Sequence[float] | None = None,
    closure_tol: float = CLOSURE_TOL_CURVES,
) -> ExcessWork:
    """A cycle from the moment curves: intervals between the crossings of M_d and M_r.

    When only one curve is given, the other is the constant that balances the work over
    the period. The intervals start at the start of the period (point a) and end at
    each point where M_d − M_r changes sign: a crossing inside a chord (found exactly),
    at a vertex, or at a jump. Where the curves touch without crossing, or coincide over a
    stretch, no new interval starts (a coincident stretch ends its interval at its start).
    ``boundaries`` adds boundaries at given angles (e.g. the positions 0…m, as Russian
    course sheets split the period).

    Examples
    --------
    W3: step resisting moment, constant driving moment by work balance:

    >>> from math import pi
    >>> ew = from_moments(M_r=MomentCurve.steps([(0, pi / 4, 60.0), (pi / 4, 2 * pi, 10.0)]))
    >>> ew.work.round(4).tolist(), round(ew.delta_W_max, 4)
    ([-34.3612, 34.3612], 34.3612)
    """
    closure_tol = real(closure_tol, "closure_tol", lo=0.0, hint="the allowed relative residual, e.g. 1e-6")
    M_d, M_r = balance(M_d, M_r)
    D = M_d - M_r
    if boundaries is not None:
        forced = finite_array(boundaries, "boundaries")
        if ((forced < D.phi[0] - 1e-12) | (forced > D.phi[-1] + 1e-12)).any():
            raise InputError(f"boundaries must lie within the period {D.phi[0]:g}..{D.phi[-1]:g} rad")
        forced = np.clip(forced, D.phi[0], D.phi[-1])
        D = D.with_knots(forced)
    else:
        forced = np.empty(0)
    p, M = D.phi, D.M
    a, b, s0, s1 = p[:-1], p[1:], M[:-1], M[1:]
    h = b - a                                            # 0 for the chord of a jump
    I = 0.5 * (s0 + s1) * h                              # the work of each chord
    E_knot = np.concatenate(([0.0], np.cumsum(I)))       # running energy at the knots
    # a crossing strictly inside a chord (compared, not multiplied: no underflow); a difference
    # within round-off of zero (1e-12 of the largest |M_d − M_r|) is zero, not a sign: else the
    # last bit of a balanced mean (which differs between numpy versions) splits off a sliver
    tiny = 1e-12 * float(np.abs(M).max(initial=0.0))
    t0, t1 = np.where(np.abs(s0) <= tiny, 0.0, s0), np.where(np.abs(s1) <= tiny, 0.0, s1)
    split = np.flatnonzero((((t0 < 0) & (t1 > 0)) | ((t0 > 0) & (t1 < 0))) & (h > 0))
    x = a[split] + h[split] * s0[split] / (s0[split] - s1[split])
    left = 0.5 * s0[split] * (x - a[split])              # the split chord's work before its crossing
    E_x = E_knot[split] + left

    total = float(np.abs(I).sum() + (np.abs(left) + np.abs(I[split] - left) - np.abs(I[split])).sum())
    residual = float(E_knot[-1])
    # round-off floor: work of a moment 1e-12 of the largest moment over the period
    noise = 1e-12 * float(max(np.abs(M_d.M).max(), np.abs(M_r.M).max())) * D.period
    if abs(residual) > closure_tol * total + noise:
        one_sign = split.size == 0 and ((I >= 0).all() or (I <= 0).all())
        raise UnbalancedCycleError(
            f"the driving and resisting work do not balance over the period: ∫(M_d − M_r)dφ = {_num(residual)} J, "
            f"{abs(residual) / total:.3g} of ∫|M_d − M_r|dφ = {_num(total)} J, beyond the tolerance {closure_tol:g}"
            + ("; M_d − M_r never changes sign, so the speed cannot be steady" if one_sign else "")
            + ". Give only one of M_d, M_r (the other is then balanced), or fix the curves"
        )
    # the sign of each chord's work at its start and its end (they differ only for a split chord);
    # chords doing no work (a jump, a coincident stretch, a touch) have sign 0 and are skipped
    first = np.sign(I)
    first[np.abs(I) <= 1e-13 * total + noise * 1e-3] = 0.0
    last = first.copy()
    first[split] = np.sign(s0[split])
    last[split] = np.sign(s1[split])
    working = first != 0
    if working.all():
        change = np.flatnonzero(last[:-1] != first[1:])  # the sign changes after these chords' ends
    else:
        nz = np.flatnonzero(working)
        f, l = first[working], last[working]
        change = nz[:-1][l[:-1] != f[1:]]
    knots = change + 1
    if forced.size:
        knots = np.union1d(knots, np.searchsorted(p, forced))
    knots = np.append(knots, p.size - 1)
    phi = np.concatenate(([p[0]], p[knots], x))
    E = np.concatenate(([0.0], E_knot[knots], E_x))
    order = np.argsort(phi, kind="stable")
    phi, E = phi[order], E[order]
    # one boundary per angle (a forced boundary at φ = 0 repeats the start)
    keep_b = np.concatenate(([True], phi[1:] > phi[:-1]))
    E, phi = E[keep_b], phi[keep_b]
    work = np.diff(E)
    for arr in (E, phi, work):
        arr.setflags(write=False)
    return ExcessWork(
        work=work, E=E, phi=phi, M_d=M_d, M_r=M_r, closure_tol=closure_tol
    )
