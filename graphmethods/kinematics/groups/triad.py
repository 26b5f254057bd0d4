"""The class III Assur group (triad) of revolute pairs: a basic ternary link and three binary links.

The basic link ``t`` carries the inner joints B1, B2, B3; binary link ``k_i`` (i = 1, 2, 3) joins the
outer joint P_i (a point already known: on the frame or on a link solved before) to B_i. Six revolute
pairs, four links: W = 3·4 − 2·6 = 0. The group is given as drawn: the six joints at one position of
the mechanism, from which the lengths l_i = |P_iB_i| and the shape of the basic link follow.

Positions (no closed form: the triad's closure has up to six assemblies). Unknowns q = (x_B1,
y_B1, θ_t), B_i = B1 + c_i·e^(iθ_t) with c_i the joint in the basic link's own frame (x along B1→B2);
closure ``f_i = (|B_i − P_i|² − l_i²)/(2 l_i) = 0``, solved by Newton's method. The assembly is the
drawn one, continued over the crank's motion: a *track* is marched from the drawn crank angle in steps
of 1° (each position from the previous, the step halved where Newton fails, the Jacobian's sign kept:
no jump to another assembly across a fold), and any crank angle is then solved by Newton from the
track. A crank angle the track does not reach is refused with the angle of the dead position (the
lines of the three binary links meet in one point, det J = 0).

Velocities and accelerations are exact, from the linearised closure with the same matrix J:
``r_i·(v_B1 + iω_t ρ_i) = r_i·v_Pi`` and
``r_i·(a_B1 + iε_t ρ_i) = r_i·a_Pi + ω_t² r_i·ρ_i − |v_Bi − v_Pi|²`` (r_i = B_i − P_i,
ρ_i = B_i − B1), then ω_i = r_i × (v_Bi − v_Pi)/l_i², ε_i = r_i × (a_Bi − a_Pi)/l_i².

The plans are built as the textbooks do it, by Assur's special point (особая точка Ассура) K: the
intersection of the lines of two binary links k_j, k_k, a point of the basic link. Its velocity lies
on the line through p_j ⟂ P_jB_j and on the line through p_k ⟂ P_kB_k (the projections of v_K and
v_Bj on the line P_jB_j are equal); then b_i on ⟂ KB_i through k and ⟂ P_iB_i through p_i; then b_j, b_k.
The acceleration plan the same way, each line shifted by the normal components.

>>> import numpy as np
>>> from graphmethods.kinematics.groups.base import State
>>> drawn = {"P1": 0j, "P2": 3 + 0j, "P3": 1.2 + 3j, "B1": 1 + 1j, "B2": 2 + 1j, "B3": 1.5 + 2j}
>>> g = Triad(outer=("P1", "P2", "P3"), inner=("B1", "B2", "B3"), drawn=tuple(drawn.items()),
...           links=("3", "2", "4", "5"))
>>> def fixed(phi):                  # the outer joints, here on the frame, at crank angles phi
...     s = State(phi=np.asarray(phi, dtype=float))
...     s.z.update({k: np.full(s.n, drawn[k]) for k in ("P1", "P2", "P3")})
...     return s
>>> st = fixed([0.0, 1.0])
>>> st.track[g.name] = g.track(fixed, phi_0=0.0)
>>> g.positions(st); complex(np.round(st.z["B3"][1], 12))      # all outer joints fixed: it stands
(1.5+2j)
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.errors import AssemblyError, InputError
from graphmethods.kinematics.groups.base import Group, Joints, Pair, Record, State, cross, dot, fmt
from graphmethods.kinematics.vectors import ComplexArray, FloatArray

#: the march's step along the crank angle, rad (each position from the previous)
STEP = math.radians(1.0)
#: the smallest step the march halves down to before it calls a crank angle unreachable, rad
STEP_MIN = math.radians(1.0) / 2 ** 14
#: |det J| / (size of the basic link) at or below which the triad is at a dead position
DEAD = 1e-9
#: how far (relative to the group's size) a drawn outer joint may be from where the mechanism puts it
DRAWN_TOL = 1e-3


def det3(rows: tuple[tuple[Any, Any, Any], ...]) -> Any:
    """The determinant of the 3×3 matrix given by its rows (vectorised)."""
    (a1, b1, c1), (a2, b2, c2), (a3, b3, c3) = rows
    return a1 * (b2 * c3 - c2 * b3) - b1 * (a2 * c3 - c2 * a3) + c1 * (a2 * b3 - b2 * a3)


def solve3(rows: tuple[tuple[Any, Any, Any], ...], rhs: tuple[Any, Any, Any]) -> tuple[Any, Any, Any, Any]:
    """x, y, z with ``rows[i] · (x, y, z) = rhs[i]`` (Cramer's rule, vectorised), and the determinant."""
    (a1, b1, c1), (a2, b2, c2), (a3, b3, c3) = rows
    d1, d2, d3 = rhs
    m1 = b2 * c3 - c2 * b3
    m2 = a2 * c3 - c2 * a3
    m3 = a2 * b3 - b2 * a3
    det = a1 * m1 - b1 * m2 + c1 * m3
    x = (d1 * m1 - b1 * (d2 * c3 - c2 * d3) + c1 * (d2 * b3 - b2 * d3)) / det
    y = (a1 * (d2 * c3 - c2 * d3) - d1 * m2 + c1 * (a2 * d3 - d2 * a3)) / det
    z = (a1 * (b2 * d3 - d2 * b3) - b1 * (a2 * d3 - d2 * a3) + d1 * m3) / det
    return x, y, z, det


@dataclass(frozen=True)
class Track:
    """The drawn assembly continued over the crank's motion (see the module docstring).

    Attributes
    ----------
    phi_0 : float
        The drawn crank angle, rad.
    u : ndarray
        Crank angle from ``phi_0`` at the track's points, rad, increasing.
    B1 : complex ndarray
        B1 at those points, m.
    e : complex ndarray
        The basic link's direction e^(iθ_t) there.
    full_turn : bool
        The track covers a whole turn (and closes on the drawn assembly).
    ends : tuple of str
        Why the track stops at its lower and upper end (empty for a full turn).
    sign : float
        The sign of det J on this assembly.
    """

    phi_0: float
    u: FloatArray
    B1: ComplexArray
    e: ComplexArray
    full_turn: bool
    ends: tuple[str, str]
    sign: float


@dataclass(frozen=True, eq=False)
class Triad(Group):
    """Class III group RRR-RRR (see the module docstring).

    Parameters
    ----------
    outer : (str, str, str)
        The known outer joints P1, P2, P3.
    inner : (str, str, str)
        The joints B1, B2, B3 of the basic link (found).
    drawn : tuple of (name, complex)
        The six joints at the drawn position, m (x + iy); the lengths follow from them.
    links : (str, str, str, str)
        Textbook numbers: the basic link t, then k1, k2, k3 (k_i joins P_i to B_i).
    """

    outer: tuple[str, str, str]
    inner: tuple[str, str, str]
    drawn: tuple[tuple[str, complex], ...]
    links: tuple[str, str, str, str] = ("2", "3", "4", "5")  # type: ignore[assignment]

    kind = "triad"
    cls = 3
    order = 3

    def __post_init__(self) -> None:
        names = [*self.outer, *self.inner]
        if len(self.outer) != 3 or len(self.inner) != 3 or len(self.links) != 4:
            raise InputError(f"triad: give three outer joints, three inner joints and four links; got "
                             f"{self.outer!r}, {self.inner!r}, {self.links!r}")
        for k in names:
            if not isinstance(k, str) or not k:
                raise InputError(f"triad: joint names must be text, got {k!r}")
        if len(set(names)) != 6:
            raise InputError(f"triad {self.name}: the six joints must have six different names, got {names}")
        if len(set(self.links)) != 4:
            raise InputError(f"triad {self.name}: the four links must have four different numbers, got {self.links}")
        pos = dict(self.drawn)
        missing = [k for k in names if k not in pos]
        if missing:
            raise InputError(f"triad {self.name}: the drawn position lacks {', '.join(missing)}")
        for k in names:
            z = complex(pos[k])
            if not (math.isfinite(z.real) and math.isfinite(z.imag)):
                raise InputError(f"triad {self.name}: the drawn position of {k} must be finite, got {pos[k]!r}")
        size = self.size
        for P, B in zip(self.outer, self.inner):
            if abs(pos[B] - pos[P]) <= 1e-9 * size:
                raise InputError(f"triad {self.name}: {P} and {B} are drawn at the same place: the link {P}{B} has "
                                 f"no length")
        B1, B2, B3 = (complex(pos[k]) for k in self.inner)
        if abs(B2 - B1) <= 1e-9 * size:
            raise InputError(f"triad {self.name}: {self.inner[0]} and {self.inner[1]} are drawn at the same place: "
                             f"the basic link has no direction")
        if min(abs(B3 - B1), abs(B3 - B2)) <= 1e-9 * size:
            raise InputError(f"triad {self.name}: {self.inner[2]} is drawn on another joint of the basic link")

    @property
    def name(self) -> str:
        """'triad (2, 3, 4, 5)'."""
        return f"triad ({', '.join(self.links)})"

    @functools.cached_property
    def size(self) -> float:
        """The largest distance between two drawn joints, m (the scale of tolerances)."""
        z = [complex(v) for _, v in self.drawn]
        return float(max(abs(a - b) for a in z for b in z)) or 1.0

    @functools.cached_property
    def lengths(self) -> tuple[float, float, float]:
        """l_i = |P_iB_i|, m."""
        pos = dict(self.drawn)
        return tuple(abs(complex(pos[B]) - complex(pos[P])) for P, B in zip(self.outer, self.inner))  # type: ignore[return-value]

    @functools.cached_property
    def shape(self) -> tuple[complex, complex, complex]:
        """c_i: the inner joints in the basic link's own frame (B1 at 0, B2 on +x), m."""
        pos = dict(self.drawn)
        B1, B2, B3 = (complex(pos[k]) for k in self.inner)
        e = (B2 - B1) / abs(B2 - B1)
        return 0j, (B2 - B1) / e, (B3 - B1) / e

    @property
    def base_size(self) -> float:
        """The largest |c_i|: the size of the basic link, m."""
        return max(abs(c) for c in self.shape)

    @property
    def pairs(self) -> tuple[Pair, ...]:
        t = self.links[0]
        return (*(("R", "?", k, P) for k, P in zip(self.links[1:], self.outer)),
                *(("R", k, t, B) for k, B in zip(self.links[1:], self.inner)))

    def joints(self) -> Joints:
        return Joints(known=tuple(self.outer), found=tuple(self.inner))

    def outputs(self) -> tuple[tuple[Any, ...], tuple[str, ...]]:  # type: ignore[override]
        return tuple(self.inner), tuple(self.links)

    # ------------------------------------------------------------------ the closure and Newton
    def _closure(self, P: tuple[Any, Any, Any], B1: Any, e: Any) -> tuple[list[Any], list[Any], Any]:
        """(f_i, Jacobian rows, det) at (B1, e) for the outer joints P (arrays or numbers)."""
        f, rows = [], []
        for c, l, Pi in zip(self.shape, self.lengths, P):
            rho = c * e
            r = B1 + rho - Pi
            f.append((r.real * r.real + r.imag * r.imag - l * l) / (2.0 * l))
            rows.append((r.real / l, r.imag / l, -cross(r, rho) / l))
        return f, rows, det3(tuple(rows))

    def _newton(self, P: tuple[Any, Any, Any], B1: Any, e: Any, iterations: int = 40) -> tuple[Any, Any, Any, bool]:
        """Newton's method from (B1, e): (B1, e, det J, converged everywhere)."""
        tol = 1e-13 * self.size
        polish = 0
        det: Any = None
        for _ in range(iterations):
            f, rows, _ = self._closure(P, B1, e)
            with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
                dx, dy, dth, det = solve3(tuple(rows), (-f[0], -f[1], -f[2]))
            step = np.abs(dx) + np.abs(dy) + self.base_size * np.abs(dth)
            if not np.all(np.isfinite(step)):
                return B1, e, det, False
            B1 = B1 + (dx + 1j * dy)
            e = e * np.exp(1j * dth)
            e = e / np.abs(e)
            if np.all(step <= tol):
                polish += 1
                if polish == 2:
                    return B1, e, det, True
        f, _, _ = self._closure(P, B1, e)
        ok = bool(np.all(np.abs(np.asarray(f)) <= 1e-11 * self.size))
        return B1, e, det, ok

    # ------------------------------------------------------------------ the track
    def track(self, upstream: Callable[[Any], State], *, phi_0: float | None = None, full_turn: bool = True,
              limit: float = 2 * math.pi) -> Track:
        """March the drawn assembly over the crank's motion (see the module docstring).

        Parameters
        ----------
        upstream : callable
            Crank angles (rad, array) -> a State holding the outer joints there.
        phi_0 : float, optional
            The drawn crank angle, rad; found by matching the drawn outer joints when not given.
        full_turn : bool
            March a whole turn (the crank turns fully); else only to ``limit`` either way.
        limit : float
            How far to march each way when not a full turn, rad.
        """
        if phi_0 is None:
            phi_0 = self._drawn_angle(upstream)
        pos = dict(self.drawn)
        st0 = upstream(np.array([phi_0]))
        P0 = tuple(complex(st0.z[k][0]) for k in self.outer)
        B1_d = complex(pos[self.inner[0]])
        e_d = (complex(pos[self.inner[1]]) - B1_d) / abs(complex(pos[self.inner[1]]) - B1_d)
        B1, e, det, ok = self._newton(P0, B1_d, e_d)                  # type: ignore[arg-type]
        if not ok or not abs(det) > DEAD * self.base_size:
            dead = ok or not abs(self._closure(P0, B1_d, e_d)[2]) > 1e-6 * self.base_size  # type: ignore[arg-type]
            why = "the lines of its binary links meet in one point (a dead position)" if dead else \
                "Newton's method does not converge from the drawing"
            raise AssemblyError(f"group {self.name}: cannot be assembled at the drawn position (φ = "
                                f"{math.degrees(phi_0) % 360:.6g}°): {why}")
        if abs(B1 - B1_d) + self.base_size * abs(e - e_d) > 10 * DRAWN_TOL * self.size:
            raise AssemblyError(f"group {self.name}: the drawn joints do not fit the drawn lengths at φ = "
                                f"{math.degrees(phi_0) % 360:.6g}° (the nearest assembly is {fmt(abs(B1 - B1_d))} m "
                                f"away); check the drawn coordinates")
        sign = 1.0 if det > 0 else -1.0
        span = 2 * math.pi if full_turn else limit
        fwd_u, fwd_B, fwd_e, why_hi = self._march(upstream, phi_0, B1, e, sign, +1.0, span)
        if full_turn and why_hi == "":
            if abs(fwd_B[-1] - B1) + self.base_size * abs(fwd_e[-1] - e) > 1e-9 * self.size:
                raise AssemblyError(f"group {self.name}: after a full crank turn from the drawn position it does not "
                                    f"come back to its drawn assembly; the crank cannot turn fully on it")
            return Track(phi_0, np.array(fwd_u), np.array(fwd_B), np.array(fwd_e), True, ("", ""), sign)
        back_u, back_B, back_e, why_lo = self._march(upstream, phi_0, B1, e, sign, -1.0,
                                                     span - (fwd_u[-1] if full_turn else 0.0))
        u = np.array(back_u[:0:-1] + fwd_u)
        Bs = np.array(back_B[:0:-1] + fwd_B)
        es = np.array(back_e[:0:-1] + fwd_e)
        return Track(phi_0, u, Bs, es, False, (why_lo, why_hi), sign)

    def _march(self, upstream: Callable[[Any], State], phi_0: float, B1: complex, e: complex, sign: float,
               direction: float, span: float) -> tuple[list[float], list[complex], list[complex], str]:
        """Continue the assembly from (B1, e) at φ_0 in steps of :data:`STEP` over ``span`` (rad) in
        ``direction``; returns the points reached and why it stopped ("" if it went the whole span)."""
        n = max(1, math.ceil(span / STEP - 1e-9))
        grid = phi_0 + direction * np.linspace(0.0, span, n + 1)
        st = upstream(grid)
        P_grid = [np.asarray(st.z[k]) for k in self.outer]
        us, Bs, es = [0.0], [B1], [e]
        prev: tuple[float, complex, complex] | None = None
        u, h = 0.0, span / n
        k = 0
        while k < n:
            target = (k + 1) * h
            du = target - u
            while True:
                uu = u + du
                if abs(uu - target) < 1e-15:
                    P = tuple(complex(Pg[k + 1]) for Pg in P_grid)
                else:
                    s1 = upstream(np.array([phi_0 + direction * uu]))
                    P = tuple(complex(s1.z[x][0]) for x in self.outer)
                # the predictor: the tangent from the last two points
                if prev is not None and prev[0] != u:
                    w = du / (u - prev[0])
                    gB, ge = B1 + w * (B1 - prev[1]), e * (e / prev[2]) ** w if prev[2] != 0 else e
                    ge = ge / abs(ge)
                else:
                    gB, ge = B1, e
                nB, ne, det, ok = self._newton(P, gB, ge)        # type: ignore[arg-type]
                jump = abs(nB - gB) + self.base_size * abs(ne - ge)
                good = ok and math.isfinite(det) and det * sign > DEAD * self.base_size \
                    and jump <= 0.05 * self.size + 4 * (abs(gB - B1) + self.base_size * abs(ge - e))
                if good:
                    break
                du /= 2
                if abs(du) < STEP_MIN:
                    where = math.degrees(phi_0 + direction * u) % 360
                    return us, Bs, es, (f"the lines of its binary links {', '.join(self.links[1:])} meet in one point "
                                        f"at φ ≈ {where:.6g}° (a dead position of the triad): the drawn assembly "
                                        f"cannot be continued past it")
            prev = (u, B1, e)
            u, B1, e = uu, nB, ne
            if abs(u - target) < 1e-15:
                us.append(direction * target)
                Bs.append(B1)
                es.append(e)
                k += 1
        return us, Bs, es, ""

    def _drawn_angle(self, upstream: Callable[[Any], State]) -> float:
        """The crank angle (rad) at which the mechanism puts the outer joints where they are drawn."""
        pos = dict(self.drawn)
        D = [complex(pos[k]) for k in self.outer]

        def miss(phi: Any) -> Any:
            st = upstream(np.asarray(phi, dtype=float))
            return sum(np.abs(np.asarray(st.z[k]) - d) ** 2 for k, d in zip(self.outer, D))

        grid = np.linspace(0.0, 2 * math.pi, 720, endpoint=False)
        m = miss(grid)
        i = int(np.argmin(m))
        lo, hi = grid[i] - math.pi / 360, grid[i] + math.pi / 360
        g = (math.sqrt(5) - 1) / 2
        for _ in range(90):
            a, b = hi - g * (hi - lo), lo + g * (hi - lo)
            ma, mb = miss([a, b])
            if ma < mb:
                hi = b
            else:
                lo = a
        phi = 0.5 * (lo + hi)
        off = math.sqrt(float(miss([phi])[0]))
        if off > DRAWN_TOL * self.size:
            raise AssemblyError(f"group {self.name}: its outer joints {', '.join(self.outer)} are drawn where the "
                                f"mechanism never puts them (nearest at φ = {math.degrees(phi) % 360:.6g}°, "
                                f"{fmt(off)} m off); check the drawn coordinates")
        return float(phi) % (2 * math.pi)

    # ------------------------------------------------------------------ the group protocol
    def _guess(self, st: State) -> tuple[ComplexArray, ComplexArray]:
        """(B1, e) over the positions, interpolated on the track; refuses a crank angle it does not reach."""
        tr: Track = st.track[self._name()]
        u = np.asarray(st.phi, dtype=float) - tr.phi_0
        if tr.full_turn:
            u = np.mod(u, 2 * math.pi)
        else:
            u = np.mod(u + math.pi, 2 * math.pi) - math.pi
            lo, hi = tr.u[0], tr.u[-1]
            bad = (u < lo - 1e-12) | (u > hi + 1e-12)

            def why(i: int) -> str:
                return tr.ends[0] if u[i] < lo else tr.ends[1]

            self.fail(st, bad, why)
            u = np.clip(u, lo, hi)
        j = np.clip(np.searchsorted(tr.u, u) - 1, 0, len(tr.u) - 2)
        w = (u - tr.u[j]) / (tr.u[j + 1] - tr.u[j])
        B1 = tr.B1[j] + w * (tr.B1[j + 1] - tr.B1[j])
        e = tr.e[j] + w * (tr.e[j + 1] - tr.e[j])
        return B1, e / np.abs(e)

    def positions(self, st: State) -> None:
        P = tuple(np.asarray(st.z[k]) for k in self.outer)
        gB, ge = self._guess(st)
        tr: Track = st.track[self._name()]
        B1, e, det, _ = self._newton(P, gB, ge)                         # type: ignore[arg-type]
        f, _, _ = self._closure(P, B1, e)                              # type: ignore[arg-type]
        res = np.max(np.abs(np.asarray(f)), axis=0)
        jump = np.abs(B1 - gB) + self.base_size * np.abs(e - ge)
        bad = ~np.isfinite(res) | (res > 1e-11 * self.size) | ~(det * tr.sign > DEAD * self.base_size) \
            | (jump > 0.05 * self.size)
        self.fail(st, bad, lambda i: "Newton's method does not converge on the drawn assembly there (a dead "
                                     "position: the lines of its binary links meet in one point)")
        st.z[self.inner[0]] = B1
        for c, Bn in zip(self.shape[1:], self.inner[1:]):
            st.z[Bn] = B1 + c * e
        st.e[self.links[0]] = e
        for k, Pn, Bn, l in zip(self.links[1:], self.outer, self.inner, self.lengths):
            st.e[k] = (st.z[Bn] - st.z[Pn]) / l

    def margin(self, st: State) -> FloatArray:
        out: FloatArray = np.abs(self._matrix(st)[2]) / self.base_size
        return out

    def _matrix(self, st: State) -> tuple[list[Any], list[Any], Any]:
        """(r_i, rows of J, det J) at the solved positions."""
        B1 = st.z[self.inner[0]]
        rs, rows = [], []
        for Pn, Bn, l in zip(self.outer, self.inner, self.lengths):
            r = st.z[Bn] - st.z[Pn]
            rho = st.z[Bn] - B1
            rs.append(r)
            rows.append((r.real / l, r.imag / l, -cross(r, rho) / l))
        return rs, rows, det3(tuple(rows))

    def velocities(self, st: State) -> None:
        rs, rows, det = self._matrix(st)
        self.check_det(st, det, "the lines of its binary links meet in one point (a dead position of the triad)")
        rhs = tuple(dot(r, st.v[Pn]) / l for r, Pn, l in zip(rs, self.outer, self.lengths))
        vx, vy, w, _ = solve3(tuple(rows), rhs)                        # type: ignore[arg-type]
        st.conditioning[self._name()] = np.abs(det) / self.base_size
        self._rigid(st, "v", vx + 1j * vy, w)
        st.omega[self.links[0]] = w
        for k, r, Pn, Bn, l in zip(self.links[1:], rs, self.outer, self.inner, self.lengths):
            st.omega[k] = cross(r, st.v[Bn] - st.v[Pn]) / (l * l)

    def accelerations(self, st: State) -> None:
        rs, rows, _ = self._matrix(st)
        w = st.omega[self.links[0]]
        B1 = st.z[self.inner[0]]
        rhs = []
        for r, Pn, Bn, l in zip(rs, self.outer, self.inner, self.lengths):
            dv = st.v[Bn] - st.v[Pn]
            rhs.append((dot(r, st.a[Pn]) + w * w * dot(r, st.z[Bn] - B1) - (dv.real ** 2 + dv.imag ** 2)) / l)
        ax, ay, eps, _ = solve3(tuple(rows), tuple(rhs))              # type: ignore[arg-type]
        self._rigid(st, "a", ax + 1j * ay, eps)
        st.epsilon[self.links[0]] = eps
        for k, r, Pn, Bn, l in zip(self.links[1:], rs, self.outer, self.inner, self.lengths):
            st.epsilon[k] = cross(r, st.a[Bn] - st.a[Pn]) / (l * l)

    def _rigid(self, st: State, which: str, x1: ComplexArray, rate: FloatArray) -> None:
        """Velocities (``which`` = "v", ``rate`` = ω_t) or accelerations ("a", ε_t) of B1, B2, B3."""
        B1 = st.z[self.inner[0]]
        table = st.v if which == "v" else st.a
        table[self.inner[0]] = x1
        for Bn in self.inner[1:]:
            rho = st.z[Bn] - B1
            if which == "v":
                table[Bn] = x1 + 1j * rate * rho
            else:
                w = st.omega[self.links[0]]
                table[Bn] = x1 + (1j * rate - w * w) * rho

    # ------------------------------------------------------------------ Assur's special point and the plans
    @property
    def special(self) -> str:
        """The name of Assur's special point of this triad: ``"K"`` and the basic link's number."""
        return f"K{self.links[0]}"

    def special_pair(self, st: State) -> tuple[int, int, int]:
        """(i, j, k): the special point K lies on the lines of binary links j and k (0-based), chosen so
        the two lines cross at the largest angle over the positions; link i is the third."""
        us = [st.e[k] for k in self.links[1:]]
        best = max(((j, k) for j, k in ((1, 2), (0, 2), (0, 1))),
                   key=lambda p: float(np.min(np.abs(cross(us[p[0]], us[p[1]])))))
        i = ({0, 1, 2} - set(best)).pop()
        return i, best[0], best[1]

    def special_point(self, st: State) -> tuple[ComplexArray, tuple[int, int, int]]:
        """Where Assur's special point K is (complex (n,), m) and the links (i, j, k) that define it."""
        i, j, k = self.special_pair(st)
        Pj, Pk = st.z[self.outer[j]], st.z[self.outer[k]]
        uj, uk = st.e[self.links[1 + j]], st.e[self.links[1 + k]]
        with np.errstate(divide="ignore", invalid="ignore"):
            s = cross(Pk - Pj, uk) / cross(uj, uk)
        return Pj + s * uj, (i, j, k)

    def records(self, st: State) -> tuple[Record, ...]:
        K, (i, j, k) = self.special_point(st)
        t = self.links[0]
        Pn, Bn, kn = self.outer, self.inner, self.links[1:]
        Kn = self.special

        def u(a: Any, b: Any) -> Any:
            with np.errstate(divide="ignore", invalid="ignore"):
                return 1j * (b - a) / np.abs(b - a)

        z = st.z
        nJ, nK, nI = u(z[Pn[j]], z[Bn[j]]), u(z[Pn[k]], z[Bn[k]]), u(z[Pn[i]], z[Bn[i]])
        vK = _meet(st.v[Pn[j]], nJ, st.v[Pn[k]], nK)          # constructed: K is not a joint of the core
        out = [Record(point=Kn, plan="velocity",
                      equation=f"v_{Kn} = v_{Pn[j]} + v_{Kn}{Pn[j]} = v_{Pn[k]} + v_{Kn}{Pn[k]}; "
                               f"v_{Kn}{Pn[j]} ⟂ {Pn[j]}{Bn[j]}, v_{Kn}{Pn[k]} ⟂ {Pn[k]}{Bn[k]} (Assur's point)",
                      known=((f"v_{Pn[j]}", st.v[Pn[j]]), (f"v_{Pn[k]}", st.v[Pn[k]])),
                      lines=((f"⟂ {Pn[j]}{Bn[j]}", st.v[Pn[j]], nJ), (f"⟂ {Pn[k]}{Bn[k]}", st.v[Pn[k]], nK)),
                      meet=vK, sin_between=cross(nJ, nK))]
        uKI = u(K, z[Bn[i]])
        out.append(Record(point=Bn[i], plan="velocity",
                          equation=f"v_{Bn[i]} = v_{Kn} + v_{Bn[i]}{Kn} = v_{Pn[i]} + v_{Bn[i]}{Pn[i]}",
                          known=((f"v_{Kn}", vK), (f"v_{Pn[i]}", st.v[Pn[i]])),
                          lines=((f"⟂ {Kn}{Bn[i]}", vK, uKI), (f"⟂ {Pn[i]}{Bn[i]}", st.v[Pn[i]], nI)),
                          meet=st.v[Bn[i]], sin_between=cross(uKI, nI)))
        for x, nX in ((j, nJ), (k, nK)):
            uIX = u(z[Bn[i]], z[Bn[x]])
            out.append(Record(point=Bn[x], plan="velocity",
                              equation=f"v_{Bn[x]} = v_{Bn[i]} + v_{Bn[x]}{Bn[i]} = v_{Pn[x]} + v_{Bn[x]}{Pn[x]}",
                              known=((f"v_{Bn[i]}", st.v[Bn[i]]), (f"v_{Pn[x]}", st.v[Pn[x]])),
                              lines=((f"⟂ {Bn[i]}{Bn[x]}", st.v[Bn[i]], uIX),
                                     (f"⟂ {Pn[x]}{Bn[x]}", st.v[Pn[x]], nX)),
                              meet=st.v[Bn[x]], sin_between=cross(uIX, nX)))
        if Bn[0] not in st.a:
            return tuple(out)
        w_t = st.omega[t]

        def an(link: str, frm: Any, to: Any) -> Any:
            """a^n of ``to`` about ``frm`` on ``link``: −ω²·(to − frm)."""
            w = st.omega[link]
            return -w * w * (to - frm)

        shifts = {}
        for x in (j, k):
            n1 = an(kn[x], z[Pn[x]], z[Bn[x]])
            n2 = -w_t * w_t * (K - z[Bn[x]])
            shifts[x] = (n1, n2)
        aK = _meet(st.a[Pn[j]] + shifts[j][0] + shifts[j][1], nJ, st.a[Pn[k]] + shifts[k][0] + shifts[k][1], nK)
        out.append(Record(
            point=Kn, plan="acceleration",
            equation=f"a_{Kn} = a_{Pn[j]} + a^n_{Bn[j]}{Pn[j]} + a^n_{Kn}{Bn[j]} + a^τ = a_{Pn[k]} + "
                     f"a^n_{Bn[k]}{Pn[k]} + a^n_{Kn}{Bn[k]} + a^τ; a^τ ⟂ {Pn[j]}{Bn[j]}, ⟂ {Pn[k]}{Bn[k]}",
            known=((f"a_{Pn[j]}", st.a[Pn[j]]), (f"a^n_{Bn[j]}{Pn[j]}", shifts[j][0]),
                   (f"a^n_{Kn}{Bn[j]}", shifts[j][1]), (f"a_{Pn[k]}", st.a[Pn[k]]),
                   (f"a^n_{Bn[k]}{Pn[k]}", shifts[k][0]), (f"a^n_{Kn}{Bn[k]}", shifts[k][1])),
            lines=((f"⟂ {Pn[j]}{Bn[j]}", st.a[Pn[j]] + shifts[j][0] + shifts[j][1], nJ),
                   (f"⟂ {Pn[k]}{Bn[k]}", st.a[Pn[k]] + shifts[k][0] + shifts[k][1], nK)),
            meet=aK, sin_between=cross(nJ, nK)))
        nIK = -w_t * w_t * (z[Bn[i]] - K)
        nIP = an(kn[i], z[Pn[i]], z[Bn[i]])
        out.append(Record(
            point=Bn[i], plan="acceleration",
            equation=f"a_{Bn[i]} = a_{Kn} + a^n_{Bn[i]}{Kn} + a^τ_{Bn[i]}{Kn} = a_{Pn[i]} + a^n_{Bn[i]}{Pn[i]} + "
                     f"a^τ_{Bn[i]}{Pn[i]}",
            known=((f"a_{Kn}", aK), (f"a^n_{Bn[i]}{Kn}", nIK), (f"a_{Pn[i]}", st.a[Pn[i]]),
                   (f"a^n_{Bn[i]}{Pn[i]}", nIP)),
            lines=((f"⟂ {Kn}{Bn[i]}", aK + nIK, uKI), (f"⟂ {Pn[i]}{Bn[i]}", st.a[Pn[i]] + nIP, nI)),
            meet=st.a[Bn[i]], sin_between=cross(uKI, nI)))
        for x, nX in ((j, nJ), (k, nK)):
            uIX = u(z[Bn[i]], z[Bn[x]])
            nXI = -w_t * w_t * (z[Bn[x]] - z[Bn[i]])
            nXP = an(kn[x], z[Pn[x]], z[Bn[x]])
            out.append(Record(
                point=Bn[x], plan="acceleration",
                equation=f"a_{Bn[x]} = a_{Bn[i]} + a^n_{Bn[x]}{Bn[i]} + a^τ_{Bn[x]}{Bn[i]} = a_{Pn[x]} + "
                         f"a^n_{Bn[x]}{Pn[x]} + a^τ_{Bn[x]}{Pn[x]}",
                known=((f"a_{Bn[i]}", st.a[Bn[i]]), (f"a^n_{Bn[x]}{Bn[i]}", nXI), (f"a_{Pn[x]}", st.a[Pn[x]]),
                       (f"a^n_{Bn[x]}{Pn[x]}", nXP)),
                lines=((f"⟂ {Bn[i]}{Bn[x]}", st.a[Bn[i]] + nXI, uIX), (f"⟂ {Pn[x]}{Bn[x]}", st.a[Pn[x]] + nXP, nX)),
                meet=st.a[Bn[x]], sin_between=cross(uIX, nX)))
        return tuple(out)


def _meet(p1: Any, d1: Any, p2: Any, d2: Any) -> Any:
    """Where the line through p1 along d1 meets the line through p2 along d2 (complex, vectorised)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return p1 + cross(p2 - p1, d2) / cross(d1, d2) * d1


def from_drawn(drawn: dict[str, tuple[float, float]]) -> tuple[tuple[str, complex], ...]:
    """The ``drawn`` mapping of a problem file (name -> [x, y], m) as the group takes it."""
    return tuple((k, complex(float(x), float(y))) for k, (x, y) in drawn.items())


__all__ = ["Track", "Triad", "from_drawn", "solve3"]
