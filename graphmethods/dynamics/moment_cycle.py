"""A cycle given by its moment curves as numbers, formulas or point lists: energy extremes and ε.

Each of M_d and M_r (N·m) is given as text, as on the command line
(``graphmethods flywheel --M-d ... --M-r ... --period-deg P``):

* a number: a constant moment;
* a formula in ``phi`` (rad), read safely by :class:`~graphmethods.dynamics.formula.Formula`,
  e.g. ``"20000 + 9500*sin(2*phi) - 5700*cos(2*phi)"``;
* a CSV file of ``phi_deg,M`` points, joined by straight lines (an optional header line; a
  repeated angle is a jump; the first point is at 0°, and points stopping short of the period
  are closed by a straight line back to the first value).

A missing one is the constant that balances the work over the period. The excess work follows
from :func:`~graphmethods.dynamics.excess_work.from_moments` (formulas are sampled into chords to
1e-10 of their largest value). The energy is highest and lowest at crossings of M_d and M_r;
every angle where it ties with the extreme (within 1e-9 of ΔW_max) is listed. With a constant
inertia J the angular acceleration is ε = (M_d − M_r)/J (domain.md §3, dJ/dφ = 0); its extremes
are refined on the formulas themselves (golden section), so their angles are exact to ~1e-7 rad.

>>> cyc = moment_cycle(M_r="20000 + 9500*sin(2*phi)")
>>> round(cyc.M_d_mean, 6), round(cyc.excess_work.delta_W_max, 5)     # the chords' error is ~1e-10
(20000.0, 9500.0)
>>> [round(a, 6) for a in cyc.phi_E_max_deg], [round(a, 6) for a in cyc.phi_E_min_deg]
([0.0, 180.0], [90.0, 270.0])
>>> eps = cyc.epsilon(J=10.0)
>>> round(eps.epsilon_max, 6), [round(a, 4) for a in eps.phi_epsilon_max_deg]
(950.0, [135.0, 315.0])
"""

from __future__ import annotations

import math
import os
import pathlib
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.dynamics import excess_work as ew
from graphmethods.dynamics.formula import Formula, looks_like_formula
from graphmethods.dynamics.moments import MomentCurve, balance
from graphmethods.errors import InputError
from graphmethods.kinematics.vectors import FloatArray
from graphmethods.units import is_finite, parse_number, read_text

__all__ = ["MomentInput", "moment_input", "read_points_csv", "MomentCycle", "moment_cycle", "Acceleration",
           "common_period_deg"]

#: Relative tolerance of a tie between energy levels (of ΔW_max) and between moments (of max |M|).
TIE_RTOL = 1e-9
#: Sampling tolerance of a formula into chords (relative to its largest value).
SAMPLING_TOL = 1e-10
_GOLD = (math.sqrt(5.0) - 1.0) / 2.0

#: a moment as a function of φ (rad), vectorised: φ ↦ M (N·m)
MomentFunction = Callable[[FloatArray], FloatArray]


@dataclass(frozen=True, eq=False)
class MomentInput:
    """One moment curve as the user gave it.

    Attributes
    ----------
    kind : {"constant", "formula", "points"}
    text : str
        What was given (the number, the formula, or the file name).
    curve : MomentCurve
        The curve over one period (chords for a formula).
    function : callable or None
        φ ↦ M (vectorised) for a formula or a constant, the exact curve; None for points.
    """

    kind: str
    text: str
    curve: MomentCurve
    function: MomentFunction | None


def read_points_csv(path: str | os.PathLike[str], *, period: float, name: str = "M") -> MomentCurve:
    """A piecewise-linear moment curve from a CSV file of ``phi_deg,M`` rows.

    Parameters
    ----------
    path : str or path-like
        The file: one ``phi_deg,M`` pair per line (comma, semicolon or blanks between them); an
        optional header line; ``#`` starts a comment.
    period : float
        The period, rad. The first point must be at 0°; points stopping short of the period are
        closed by a straight line back to the first value.
    name : str
        What the curve is, for messages.

    Examples
    --------
    >>> import tempfile, os
    >>> with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
    ...     _ = f.write("phi_deg,M\\n0,0\\n180,40\\n360,0\\n")
    >>> c = read_points_csv(f.name, period=2 * math.pi)
    >>> round(c.mean(), 9); os.unlink(f.name)
    20.0
    """
    p = pathlib.Path(path)
    text = read_text(p, missing="no such file (a CSV file of phi_deg,M points)", prefix=f"{name}: ")
    phi_deg: list[float] = []
    M: list[float] = []
    for lineno, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        cells = [c for c in re.split(r"[,;\s]+", line) if c]
        if len(cells) != 2:
            raise InputError(f"{name}: {p}, line {lineno}: expected two values phi_deg,M, got {line!r}")
        try:
            a, m = float(cells[0]), float(cells[1])
        except ValueError:
            if not phi_deg:          # a header line
                continue
            raise InputError(f"{name}: {p}, line {lineno}: {line!r} is not two numbers phi_deg,M") from None
        if not (is_finite(a) and is_finite(m)):
            raise InputError(f"{name}: {p}, line {lineno}: {line!r} is not finite")
        phi_deg.append(a)
        M.append(m)
    if len(phi_deg) < 2:
        raise InputError(f"{name}: {p}: give at least two phi_deg,M points")
    if abs(phi_deg[0]) > 1e-12:
        raise InputError(f"{name}: {p}: the first point must be at phi_deg = 0 (the start of the period), "
                         f"not {phi_deg[0]:g}")
    try:
        return MomentCurve.points(np.radians(phi_deg).tolist(), M, period=period)
    except InputError as exc:
        raise InputError(f"{name}: {p}: {exc}") from None


def moment_input(text: object, *, period: float = 2 * math.pi, name: str = "M") -> MomentInput:
    """Read one moment given as a number, a formula in ``phi`` or a CSV file of points.

    A value ending in ``.csv``, or naming an existing file, is read as points; a plain number
    (fractions like ``1/3`` accepted) is a constant; anything else is a formula.

    >>> moment_input("1/4").kind, float(moment_input("1/4").curve(1.0))
    ('constant', 0.25)
    >>> m = moment_input("10 + 5*sin(phi)")
    >>> m.kind, round(m.curve.mean(), 9)
    ('formula', 10.0)
    """
    if not (isinstance(period, (int, float)) and is_finite(period) and period > 0):
        raise InputError(f"the period must be a positive angle, got {period!r} rad")
    s = str(text).strip()
    if not s:
        raise InputError(f"{name}: empty; give a number (N·m), a formula in phi or a CSV file of phi_deg,M points")
    if s.lower().endswith(".csv") or (len(s) < 4096 and pathlib.Path(s).is_file()):
        return MomentInput("points", s, read_points_csv(s, period=period, name=name), None)
    if not looks_like_formula(s):
        c = parse_number(s, name=name)
        return MomentInput("constant", s, MomentCurve.constant(c, period=period),
                           lambda phi: np.full(np.shape(phi), c))
    try:
        f = Formula(s, variables=("phi",))
    except InputError as exc:
        raise InputError(f"{name}: {exc}") from None

    def fn(phi: FloatArray) -> FloatArray:
        return f(phi=phi)

    try:
        curve = MomentCurve.function(fn, period=period, tol=SAMPLING_TOL)
    except InputError as exc:
        raise InputError(f"{name}: {exc}") from None
    return MomentInput("formula", s, curve, fn)


@dataclass(frozen=True)
class Acceleration:
    """Extremes of ε = (M_d − M_r)/J for a constant inertia J (kg·m²); angles in degrees, all ties."""

    J: float
    epsilon_max: float
    epsilon_min: float
    phi_epsilon_max_deg: list[float]
    phi_epsilon_min_deg: list[float]

    def to_dict(self) -> dict[str, Any]:
        """The keys the command line reports (floats and lists of angles in degrees)."""
        return {"J_epsilon": self.J, "epsilon_max": self.epsilon_max, "epsilon_min": self.epsilon_min,
                "phi_epsilon_max_deg": list(self.phi_epsilon_max_deg),
                "phi_epsilon_min_deg": list(self.phi_epsilon_min_deg)}


@dataclass(frozen=True, eq=False)
class MomentCycle:
    """A cycle from moment curves: the excess-work table, where the energy is extreme, and M_e's extremes.

    Attributes
    ----------
    M_d, M_r : MomentInput
        The two curves (a missing one is the balancing constant, kind ``"constant"``).
    excess_work : ExcessWork
        The table between the crossings of M_d and M_r.
    phi_E_max_deg, phi_E_min_deg : list of float
        Every angle (deg, in [0, period)) where the energy is highest / lowest.
    M_e_max, M_e_min : float
        Largest and smallest M_d − M_r, N·m; ``phi_M_e_max_deg``, ``phi_M_e_min_deg`` their angles.
    """

    M_d: MomentInput
    M_r: MomentInput
    excess_work: ew.ExcessWork
    phi_E_max_deg: list[float]
    phi_E_min_deg: list[float]
    M_e_max: float
    M_e_min: float
    phi_M_e_max_deg: list[float]
    phi_M_e_min_deg: list[float]

    @property
    def period(self) -> float:
        """The period, rad."""
        return self.M_d.curve.period

    @property
    def M_d_mean(self) -> float:
        """The driving moment's mean, N·m."""
        return self.M_d.curve.mean()

    @property
    def M_r_mean(self) -> float:
        """The resisting moment's mean, N·m."""
        return self.M_r.curve.mean()

    def epsilon(self, *, J: float) -> Acceleration:
        """ε extremes for a machine of constant total inertia J (kg·m²) on the reduced shaft."""
        if not (isinstance(J, (int, float)) and is_finite(J) and J > 0):
            raise InputError(f"the inertia J = {J!r} kg·m² must be positive to give an angular acceleration")
        return Acceleration(float(J), self.M_e_max / J, self.M_e_min / J,
                            list(self.phi_M_e_max_deg), list(self.phi_M_e_min_deg))

    def to_dict(self) -> dict[str, Any]:
        """The keys the command line adds to the excess-work table's."""
        return {"period_deg": math.degrees(self.period),
                "M_d_given": self.M_d.text, "M_r_given": self.M_r.text,
                "M_d_mean": self.M_d_mean, "M_r_mean": self.M_r_mean,
                "phi_E_max_deg": list(self.phi_E_max_deg), "phi_E_min_deg": list(self.phi_E_min_deg),
                "M_e_max": self.M_e_max, "M_e_min": self.M_e_min}


def _distinct_angles(phi: FloatArray, period: float) -> list[float]:
    """Angles (rad) reduced to [0, period), merged within 1e-6 rad, in degrees, sorted."""
    x = np.sort(np.mod(np.asarray(phi, dtype=float), period))
    x[np.abs(x - period) < 1e-6] = 0.0
    out: list[float] = []
    for v in np.sort(x):
        if not out or v - out[-1] > 1e-6:
            out.append(float(v))
    if len(out) > 1 and period - out[-1] + out[0] <= 1e-6:
        out.pop()
    return [math.degrees(v) for v in out]


def _golden(fun: MomentFunction, lo: FloatArray, hi: FloatArray, iters: int = 80) -> tuple[FloatArray, FloatArray]:
    """Vectorised golden-section maximisation of fun on brackets [lo, hi]."""
    c = hi - _GOLD * (hi - lo)
    d = lo + _GOLD * (hi - lo)
    fc, fd = fun(c), fun(d)
    for _ in range(iters):
        left = fc >= fd
        hi = np.where(left, d, hi)
        lo = np.where(left, lo, c)
        nc = np.where(left, hi - _GOLD * (hi - lo), d)
        nd = np.where(left, c, lo + _GOLD * (hi - lo))
        fn = fun(np.where(left, nc, nd))
        fc, fd = np.where(left, fn, fd), np.where(left, fc, fn)
        c, d = nc, nd
    x = np.where(fc >= fd, c, d)
    return x, np.maximum(fc, fd)


def _moment_extremes(D: MomentCurve, fn: MomentFunction | None, sense: float) -> tuple[float, list[float]]:
    """Largest (sense=+1) or smallest (−1) value of M_e = M_d − M_r and every angle where it is reached."""
    v = sense * D.M
    scale = max(float(np.abs(D.M).max()), 1e-300)
    best = float(v.max())
    if fn is None:                    # piecewise linear: the extremes are at knots, exactly
        tie = TIE_RTOL * scale
        return sense * best, _distinct_angles(D.phi[v >= best - tie], D.period)
    # a formula: each run of neighbouring knots near the best is one candidate extremum (the chords
    # are within SAMPLING_TOL of the function), refined by golden section on the function itself
    # over the run's bracket; a run where the function is flat is a plateau, reported by its ends
    tie = TIE_RTOL * scale
    cand = np.flatnonzero(v >= best - tie - 4 * SAMPLING_TOL * scale)
    breaks = np.flatnonzero(np.diff(cand) > 1)
    first = cand[np.concatenate(([0], breaks + 1))]
    last = cand[np.concatenate((breaks, [cand.size - 1]))]
    lo = D.phi[np.maximum(first - 1, 0)]
    hi = D.phi[np.minimum(last + 1, D.phi.size - 1)]
    x, fx = _golden(lambda p: sense * fn(p), lo, hi)
    angles: list[float] = []
    values: list[float] = []
    ends: list[bool] = []
    for i, (f, l_) in enumerate(zip(first, last)):
        run = v[f:l_ + 1]
        if l_ - f >= 2 and float(run.max() - run.min()) <= 1e-12 * scale:
            angles += [D.phi[f], D.phi[l_]]
            values += [float(run.max())] * 2
            ends += [False, l_ == D.phi.size - 1]
        else:
            angles.append(float(x[i]))
            values.append(float(fx[i]))
            ends.append(False)
    vals = np.array(values)
    top = float(vals.max())
    best_ = vals >= top - tie
    at, end = np.array(angles)[best_], np.array(ends)[best_]
    inner = _distinct_angles(at[~end], D.period)
    if end.any() and 0.0 not in inner:      # a plateau ending at the period's end
        inner.append(math.degrees(D.period))
    return sense * top, inner


def _of_phi(f: Formula) -> MomentFunction:
    """The formula as a function of φ alone."""
    return lambda p: f(phi=p)


def _auto_period(M_d: object, M_r: object) -> float:
    """The common period (degrees) of the formulas (360° for constants only); a points file needs
    its period said."""
    fns: list[MomentFunction] = []
    for text, name in ((M_d, "--M-d"), (M_r, "--M-r")):
        if text is None:
            continue
        s = str(text).strip()
        if s.lower().endswith(".csv") or (len(s) < 4096 and pathlib.Path(s).is_file()):
            raise InputError(f"{name}: a points file is given over a period of its own; give --period-deg with it")
        if looks_like_formula(s):
            f = Formula(s, variables=("phi",))
            fns.append(_of_phi(f))
    if not fns:
        return 360.0
    return common_period_deg(*fns)


def _exact_work(f: MomentFunction, P: float) -> float:
    """∫_0^P f dφ by adaptive Gauss–Kronrod quadrature (J)."""
    from graphmethods.dynamics.motion import _Primitive

    residual: float = _Primitive(f, 0.0, P).residual
    return residual


def _exact_table(table: ew.ExcessWork, f_d: MomentFunction, f_r: MomentFunction, P: float) -> ew.ExcessWork:
    """The table of chords with its crossings found again by Brent's method on M_d − M_r itself and its
    energies integrated from the formulas, (adaptive Gauss–Kronrod, ~1e-12 of ∫|M_d − M_r|dφ)."""
    from dataclasses import replace

    from graphmethods.dynamics.motion import _brent_root, _Primitive

    def D(p: FloatArray) -> FloatArray:
        return f_d(p) - f_r(p)

    assert table.phi is not None and table.M_d is not None and table.M_r is not None
    phi = np.array(table.phi, dtype=float)
    knots = (table.M_d - table.M_r).phi

    def D1(x: float) -> float:
        return float(D(np.array([x]))[0])

    for k in range(1, phi.size - 1):                   # the crossings: Brent's method on M_d − M_r itself,
        j = int(np.searchsorted(knots, phi[k]))        # in the chords around the chords' crossing
        lo, hi = knots[max(j - 1, 0)], knots[min(j + 1, knots.size - 1)]
        f_lo, f_hi = D1(lo), D1(hi)
        if hi > lo and f_lo * f_hi < 0:
            phi[k] = _brent_root(D1, lo, hi, f_lo, f_hi)
    E = _Primitive(D, 0.0, P, breaks=tuple(phi[1:-1]))(phi)
    E[0] = 0.0
    return replace(table, phi=phi, E=E, work=np.diff(E))


#: The longest period :func:`moment_cycle` accepts, in turns: a machine's cycle repeats within a few turns
#: of the shaft its moments are reduced to (a four-stroke engine's in two), and the quadrature of ΔE costs
#: time in proportion to the period, so a longer one (a mistyped 1e9°) is refused, not integrated for seconds
MAX_PERIOD_TURNS = 100


#: Candidate periods for ``period_deg="auto"``: 360°·k/q, q = 1…12, up to four turns (degrees).
def _candidate_periods(max_turns: int = 4) -> list[float]:
    from fractions import Fraction

    c = {Fraction(360 * k, q) for q in range(1, 13) for k in range(1, 12 * max_turns + 1)
         if Fraction(360 * k, q) <= 360 * max_turns}
    return [float(x) for x in sorted(c)]


def common_period_deg(*functions: MomentFunction, max_turns: int = 4, rtol: float = 1e-9) -> float:
    """The common period (degrees) of moments given as functions of φ (rad): the smallest of
    360°·k/q (q ≤ 12, up to ``max_turns`` turns) over which every one repeats.

    A function repeats over P when |f(φ + P) − f(φ)| ≤ rtol·max|f| at 257 angles spread over
    [0, max_turns·360°] (a constant repeats over any P). For a four-stroke engine's gas moment and a
    pump's moment of period 360° it gives 720°.

    >>> import numpy as np
    >>> common_period_deg(lambda p: np.sin(2 * p), lambda p: np.cos(3 * p))
    360.0
    >>> common_period_deg(lambda p: 5 + np.sin(p / 2), lambda p: np.sin(2 * p))
    720.0
    """
    x = np.radians(np.linspace(0.0, 360.0 * max_turns, 257)) + 0.1234567
    vals = [np.asarray(f(x), dtype=float) for f in functions]
    scale = max([float(np.max(np.abs(v))) for v in vals] + [1e-300])
    for P in _candidate_periods(max_turns):
        if all(float(np.max(np.abs(np.asarray(f(x + math.radians(P)), dtype=float) - v))) <= rtol * scale
               for f, v in zip(functions, vals)):
            return P
    raise InputError(f"no common period of the moments up to {max_turns} turns (tried 360°·k/q, q ≤ 12); "
                     f"give --period-deg")


def moment_cycle(M_d: object = None, M_r: object = None, *, period_deg: float | str = 360.0) -> MomentCycle:
    """The cycle of two moments given as text (numbers, formulas in phi, CSV files); one may be missing.

    (Over 80 lines only through this docstring, which documents every parameter; the code is 55 lines.)

    Parameters
    ----------
    M_d, M_r : str or None
        The driving and the resisting moment (N·m): a number, a formula in ``phi`` (rad) or the
        name of a CSV file of ``phi_deg,M`` points. A missing one balances the other's work.
    period_deg : float or "auto"
        The period, degrees (360: one turn; 720: a four-stroke engine), or ``"auto"``: the common
        period of the formulas (:func:`common_period_deg`; not with a points file).

    Returns
    -------
    MomentCycle

    Raises
    ------
    InputError
        A bad number, formula or file; both moments missing; UnbalancedCycleError when both are
        given and their works differ.

    Examples
    --------
    >>> cyc = moment_cycle(M_d="16.25", M_r=None)
    >>> cyc.excess_work.delta_W_max
    0.0
    """
    if M_d is None and M_r is None:
        raise InputError("give the driving moment --M-d, the resisting moment --M-r, or both")
    if str(period_deg).strip().lower() == "auto":
        period_deg = _auto_period(M_d, M_r)
    P = math.radians(parse_number(period_deg, name="--period-deg"))
    if not P > 0:
        raise InputError(f"--period-deg {period_deg!r}: the period must be a positive angle (360 for one turn)")
    if P > 2 * math.pi * MAX_PERIOD_TURNS:
        raise InputError(f"--period-deg {period_deg!r}: a machine's cycle repeats within {MAX_PERIOD_TURNS} turns "
                         f"({360 * MAX_PERIOD_TURNS}°, MAX_PERIOD_TURNS) of the shaft its moments are reduced to; "
                         f"give the period of one cycle (360 for one turn, 720 for a four-stroke engine)")
    d = None if M_d is None else moment_input(M_d, period=P, name="--M-d")
    r = None if M_r is None else moment_input(M_r, period=P, name="--M-r")
    exact = ((d is None or d.function is not None) and (r is None or r.function is not None)
             and any(m is not None and m.kind == "formula" for m in (d, r)))
    if exact:      # balance against the exact work of a formula, not that of its chords
        if d is None and r is not None:
            assert r.function is not None                # exact: each moment given has its function
            c = _exact_work(r.function, P) / P
            d = MomentInput("constant", f"{c!r} (balances M_r)", MomentCurve.constant(c, period=P),
                            lambda phi: np.full(np.shape(phi), c))
        elif r is None and d is not None:
            assert d.function is not None
            c = _exact_work(d.function, P) / P
            r = MomentInput("constant", f"{c!r} (balances M_d)", MomentCurve.constant(c, period=P),
                            lambda phi: np.full(np.shape(phi), c))
    cd, cr = balance(None if d is None else d.curve, None if r is None else r.curve)
    # a balancing constant that is round-off of zero (a moment of zero mean) is zero
    scale = max(float(np.abs(cd.M).max()), float(np.abs(cr.M).max()))
    if d is None and abs(cd.mean()) <= 1e-12 * scale:
        cd = MomentCurve.constant(0.0, period=P)
    if r is None and abs(cr.mean()) <= 1e-12 * scale:
        cr = MomentCurve.constant(0.0, period=P)
    if d is None:
        c = cd.mean()
        d = MomentInput("constant", f"{c!r} (balances M_r)", cd, lambda phi: np.full(np.shape(phi), c))
    if r is None:
        c = cr.mean()
        r = MomentInput("constant", f"{c!r} (balances M_d)", cr, lambda phi: np.full(np.shape(phi), c))
    table = ew.from_moments(cd, cr)
    if exact:
        assert d.function is not None and r.function is not None
        table = _exact_table(table, d.function, r.function, P)
    E, phi = table.E, np.asarray(table.phi, dtype=float)
    tie = TIE_RTOL * max(table.delta_W_max, 1e-300)
    phi_E_max = _distinct_angles(phi[E >= table.E_max - tie], P)
    phi_E_min = _distinct_angles(phi[E <= table.E_min + tie], P)
    D = cd - cr
    fn: MomentFunction | None = None
    if d.function is not None and r.function is not None:
        f_d, f_r = d.function, r.function

        def difference(p: FloatArray) -> FloatArray:
            return f_d(p) - f_r(p)
        fn = difference
    M_max, at_max = _moment_extremes(D, fn, +1.0)
    M_min, at_min = _moment_extremes(D, fn, -1.0)
    return MomentCycle(d, r, table, phi_E_max, phi_E_min, M_max, M_min, at_max, at_min)
