"""What every linkage shares: extra points on links, numbering of positions, building the plans.

A concrete linkage (:class:`~graphmethods.kinematics.SliderCrank`, ``FourBar``,
``SlottedLever``, ``Shaper``) is a frozen dataclass of its dimensions (m) that implements a few
hooks: its geometry at crank angles φ, its extreme positions in closed form, the textbook
construction of its velocity plan, and the analytic derivative of its position equations.
This module turns those into :class:`Positions` and :class:`VelocityPlans`.

Extra points (centres of mass, coupler points) are given per link by the distance from a
joint and the angle to the link line: ``points={"S2": ("AB", 0.13, 0.0)}`` puts S2 on AB,
0.13 m from A, on the line A→B; ``("AB", 0.1, math.pi/2)`` would be 0.1 m from A at 90°
counterclockwise from A→B; ``("BA", ...)`` measures from B toward A.

>>> p = PointOnLink.of("S2", ("AB", 0.13))
>>> p.link, p.distance, p.angle
('AB', 0.13, 0.0)
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from classic_reference import vectors as V
from graphmethods.errors import AssemblyError, InputError
from graphmethods.kinematics.plans import ConstructionLine, PointConstruction, VelocityPlans
from graphmethods.kinematics.positions import Positions, Strokes, build_positions
from graphmethods.units import MAX_POSITIONS_COMPUTED, count, real


@dataclass(frozen=True)
class PointOnLink:
    """An extra point of a link: ``distance`` (m) from the link's first joint, at ``angle`` (rad,
    counterclockwise) from the line first joint → second joint.

    Attributes
    ----------
    name : str
        The point's name (``"S2"``, ``"K"``); must not be a joint name.
    link : str
        The link by its joints, first joint first (``"AB"``, ``"BA"``, ``"O2B"``).
    distance : float
        Distance from the first joint, m (≥ 0).
    angle : float
        Angle from the link line, rad.
    """

    name: str
    link: str
    distance: float
    angle: float = 0.0

    @classmethod
    def of(cls, name: str, spec) -> PointOnLink:
        """Normalise ``(link, distance)``, ``(link, distance, angle)`` or a PointOnLink."""
        if isinstance(spec, PointOnLink):
            return spec if spec.name == name else cls(name, spec.link, spec.distance, spec.angle)
        if not isinstance(spec, (tuple, list)) or len(spec) not in (2, 3) or not isinstance(spec[0], str):
            raise InputError(f"point {name!r}: give (link, distance_m) or (link, distance_m, angle_rad), "
                             f"e.g. ('AB', 0.13, 0.0); got {spec!r}")
        vals = []
        for what, x in zip(("distance", "angle"), spec[1:]):
            if isinstance(x, bool) or not isinstance(x, (int, float, np.floating, np.integer)):
                raise InputError(f"point {name!r}: {what} must be a finite number, got {x!r}")
            vals.append(real(x, f"point {name!r}: {what}", tiny_ok=True))
        if vals[0] < 0:
            raise InputError(f"point {name!r}: distance must be ≥ 0 m (turn the angle by π instead), got {vals[0]}")
        return cls(name, spec[0], *vals)


#: Largest angle in rad the API takes (files give degrees, reduced exactly modulo 360 when read).
MAX_ANGLE_RAD = 1e6


def _check_length(name: str, value, *, positive: bool = True, allow_zero: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise InputError(f"{name} must be a number in m, got {value!r}")
    # the toolkit's number policy: finite, magnitudes up to 1e100, and a length (a divisor) at least 1e-100;
    # an offset or an angle is only a term: tiny is fine
    value = real(value, name, tiny_ok=not positive)
    if positive and (value < 0 or (value == 0 and not allow_zero)):
        raise InputError(f"{name} must be {'≥' if allow_zero else '>'} 0 m, got {value!r}")
    if name.startswith(("theta", "ground_angle")) and abs(value) > MAX_ANGLE_RAD:
        raise InputError(f"{name} = {value:g} rad is beyond ±{MAX_ANGLE_RAD:g} rad; reduce it modulo 2π first "
                         f"(or give degrees in a problem file, which are reduced exactly)")
    return value


def _fmt(x: float) -> str:
    return f"{x:.6g}"


def _deg(phi: float) -> str:
    return f"{math.degrees(phi) % 360.0:.4g}°"


class Mechanism:
    """Base of the linkages (not instantiated itself). See the module docstring."""

    #: joint names, in drawing order
    joints: tuple[str, ...] = ()
    #: the crank pin (its velocity is the known vector pa)
    crank_pin: str = "A"
    #: canonical moving links that can carry extra points -> (first joint, second joint)
    link_joints: Mapping[str, tuple[str, str]] = {}
    #: textbook link numbers (crank = 1) -> canonical link name
    link_numbers: Mapping[int, str] = {}
    #: allowed values of ``working_stroke``
    working_strokes: tuple[str, ...] = ("slow", "fast")
    #: mechanism name for messages
    kind: str = "linkage"

    # ---------------------------------------------------------------- validation
    def _validate_common(self) -> None:
        if self.sense not in (1, -1) or isinstance(self.sense, bool):
            raise InputError(f"{self.kind}: sense must be +1 (counterclockwise) or -1 (clockwise), got {self.sense!r}")
        if hasattr(self, "assembly") and (self.assembly not in (1, -1) or isinstance(self.assembly, bool)):
            raise InputError(f"{self.kind}: assembly must be +1 or -1, got {self.assembly!r}")
        if self.working_stroke not in self.working_strokes:
            raise InputError(f"{self.kind}: working_stroke must be one of {', '.join(self.working_strokes)}; "
                             f"got {self.working_stroke!r}")
        raw = self.points
        if isinstance(raw, Mapping):
            items = list(raw.items())
        elif isinstance(raw, (tuple, list)):
            items = [(p.name, p) if isinstance(p, PointOnLink) else (None, p) for p in raw]
            if any(k is None for k, _ in items):
                raise InputError(f"{self.kind}: points must be a mapping name -> (link, distance, angle), "
                                 f"e.g. {{'S2': ('AB', 0.13, 0.0)}}")
        else:
            raise InputError(f"{self.kind}: points must be a mapping name -> (link, distance, angle), got {raw!r}")
        specs = []
        for name, spec in items:
            if not isinstance(name, str) or not name or not name.isidentifier():
                raise InputError(f"{self.kind}: point names must be identifiers like 'S2', got {name!r}")
            if name in self.joints:
                raise InputError(f"{self.kind}: point {name!r} clashes with a joint name ({', '.join(self.joints)})")
            p = PointOnLink.of(name, spec)
            self._resolve_link(p.link, what=f"point {name!r}")
            specs.append(p)
        object.__setattr__(self, "points", tuple(specs))

    def _resolve_link(self, link: str, *, what: str = "link") -> tuple[str, str, str, bool]:
        """(first joint, second joint, canonical name, reversed?) of a link written as joints."""
        for canon, (x, y) in self.link_joints.items():
            if link == x + y:
                return x, y, canon, False
            if link == y + x:
                return y, x, canon, True
        raise InputError(f"{self.kind}: {what}: unknown link {link!r}; the moving links are "
                         f"{', '.join(self.link_joints)} (either order, first joint = where the distance starts)")

    def link_name(self, link) -> str:
        """Canonical name of a link given by joints (``"BA"`` -> ``"AB"``) or textbook number."""
        if isinstance(link, (int, np.integer)) and not isinstance(link, bool):
            try:
                return self.link_numbers[int(link)]
            except KeyError:
                raise InputError(f"{self.kind}: no link number {link}; links: "
                                 + ", ".join(f"{k} = {v}" for k, v in self.link_numbers.items())) from None
        if isinstance(link, str):
            if link in self.omega_links:
                return link
            for canon in self.omega_links:
                x, y = self._omega_joints(canon)
                if link in (x + y, y + x):
                    return canon
        raise InputError(f"{self.kind}: unknown link {link!r}; links: "
                         + ", ".join(f"{k} = {v}" for k, v in self.link_numbers.items()))

    @property
    def omega_links(self) -> tuple[str, ...]:
        """Canonical names of the links whose angular velocities the plans report."""
        return tuple(self.link_numbers.values())

    def _omega_joints(self, canon: str) -> tuple[str, str]:
        return self.link_joints.get(canon, (canon, ""))

    @property
    def guides(self) -> dict[str, tuple[float, float]]:
        """Slider points -> unit direction (+) of their guide."""
        return {}

    # ---------------------------------------------------------------- strokes
    def _extremes(self):
        """((φ_a, name_a), (φ_b, name_b)) of the two extreme positions, or None (hook)."""
        return None

    def _start_is_a(self, t_ab: float) -> bool:
        ws = self.working_stroke
        if abs(t_ab - math.pi) < 1e-12:  # equal strokes: start at the first extreme
            return True
        if ws == "slow":
            return t_ab > math.pi
        return t_ab < math.pi

    def strokes(self) -> Strokes | None:
        """The extreme positions (exact, closed form), stroke angles and time ratio K, or None for a
        linkage whose output turns fully (no extreme positions)."""
        ext = self._extremes()
        if ext is None:
            return None
        (pa, na), (pb, nb) = ext
        t_ab = float(V.travel(pa, pb, self.sense))
        if self._start_is_a(t_ab):
            start, end, w, ns, ne = pa, pb, t_ab, na, nb
        else:
            start, end, w, ns, ne = pb, pa, 2.0 * math.pi - t_ab, nb, na
        start = float(V.norm_angle(start))
        end = float(V.norm_angle(end))
        return Strokes(phi_start=start, phi_end=end, working_angle=w, return_angle=2.0 * math.pi - w,
                       K=w / (2.0 * math.pi - w), start_name=ns, end_name=ne)

    def _default_start(self) -> float:
        return 0.0

    # ---------------------------------------------------------------- positions
    def positions(self, m: int | None = None, *, phi=None, phi_from_start=None) -> Positions:
        """The linkage in m + 1 positions 0…m (or at given crank angles).

        Parameters
        ----------
        m : int, optional
            Number of equal steps of the crank per turn (≥ 3), starting at the extreme position
            that starts the working stroke and going in the crank's sense; position m is
            position 0 again. Default 12 when neither ``phi`` nor ``phi_from_start`` is given.
        phi : array_like, optional
            Crank angles (rad, from +x, counterclockwise) instead of m.
        phi_from_start : array_like, optional
            Crank rotation (rad) from position 0 in the crank's sense instead of m.

        Returns
        -------
        Positions

        Raises
        ------
        AssemblyError
            If the linkage cannot be assembled at some position (the message names it).
        """
        given = sum(x is not None for x in (m, phi, phi_from_start))
        if given > 1:
            raise InputError("give only one of m, phi or phi_from_start")
        strokes = self.strokes()
        start = strokes.phi_start if strokes is not None else self._default_start()
        if phi is None and phi_from_start is None:
            m = 12 if m is None else m
            m = count(m, "the number of positions m", low=3, high=MAX_POSITIONS_COMPUTED,
                      why="checked before any work; textbooks use 8 to 48")
            self._check_full_turn()
            k = np.arange(m + 1)
            tr = (2.0 * math.pi / m) * k
            tr[m] = 2.0 * math.pi
            ang = V.norm_angle(start + self.sense * tr)
            ang[m] = ang[0]
            labels = k
        else:
            tr = None
            if phi_from_start is not None:
                tr = self._angles(phi_from_start, "phi_from_start")
                ang = V.norm_angle(start + self.sense * tr)
            else:
                ang = self._angles(phi, "phi")
            labels = None
            m = None
        self._check_positions(ang, labels)
        geom, theta = self._geometry(ang)
        self._add_point_geometry(geom, theta)
        out = self._output(geom, theta, strokes)
        return build_positions(self, ang, m=m, phi_start=start, strokes=strokes, geom=geom, theta=theta,
                               phi_from_start=tr, output=out)

    @staticmethod
    def _angles(values, name: str) -> np.ndarray:
        if isinstance(values, (bool, str, bytes)) or (isinstance(values, np.ndarray) and values.dtype == bool):
            raise InputError(f"{name}: crank angles must be numbers in rad, got {values!r}")
        try:
            a = np.array(values, dtype=float).reshape(-1)
        except (TypeError, ValueError, OverflowError):
            raise InputError(f"{name}: crank angles must be numbers in rad, got {values!r}") from None
        if a.size == 0:
            raise InputError(f"{name}: give at least one crank angle")
        if a.size > MAX_POSITIONS_COMPUTED:
            raise InputError(f"{name}: {a.size} angles is above the limit {MAX_POSITIONS_COMPUTED}")
        bad = ~np.isfinite(a)
        if bad.any():
            raise InputError(f"{name}: angle #{int(np.argmax(bad))} is {a[bad][0]!r}; angles must be finite (rad)")
        big = np.abs(a) > MAX_ANGLE_RAD
        if big.any():
            raise InputError(f"{name}: angle #{int(np.argmax(big))} = {a[big][0]:g} rad is beyond ±{MAX_ANGLE_RAD:g} rad; "
                             f"reduce it modulo 2π first")
        return a

    def _check_full_turn(self) -> None:
        """Raise AssemblyError if the crank cannot make a full turn (hook; default: it can)."""

    def _check_positions(self, phi: np.ndarray, labels) -> None:
        """Raise AssemblyError naming the first position that cannot be assembled (hook)."""

    @staticmethod
    def _where(phi: np.ndarray, labels, i: int) -> str:
        pos = f"position {int(labels[i])}" if labels is not None else f"angle #{i}"
        return f"{pos} (φ = {_deg(float(phi[i]))})"

    def _add_point_geometry(self, geom: dict, theta: dict) -> None:
        for p in self.points:
            x, y, canon, rev = self._resolve_link(p.link)
            th = theta[canon] + (math.pi if rev else 0.0) + p.angle
            gx, gy = geom[x]
            geom[p.name] = (gx + p.distance * np.cos(th), gy + p.distance * np.sin(th))

    def _output(self, geom: dict, theta: dict, strokes: Strokes | None) -> dict:
        """s/H/stroke_direction or psi/psi_max for the output (hook)."""
        return {}

    def _rocker_output(self, theta: dict, strokes: Strokes | None, link: str) -> dict:
        if strokes is None:
            return {}
        th_s, th_e = self._link_angle_at([strokes.phi_start, strokes.phi_end], link)
        swing = float(V.wrap(th_e - th_s))
        sign = 1.0 if swing >= 0 else -1.0
        psi = sign * V.wrap(theta[link] - th_s)
        psi = np.where(np.abs(psi) < 1e-15, 0.0, psi)
        return {"psi": psi, "psi_max": abs(swing)}

    def _slider_output(self, geom_n: dict, strokes: Strokes | None, point: str) -> dict:
        if strokes is None:
            return {}
        geom, _ = self._geometry(np.array([strokes.phi_start, strokes.phi_end]))
        xs, xe = geom[point][0]
        d = 1.0 if xe >= xs else -1.0
        s = d * (geom_n[point][0] - xs)
        return {"s": s, "H": float(abs(xe - xs)), "stroke_direction": np.array([d, 0.0])}

    def _link_angle_at(self, phi, link: str) -> np.ndarray:
        _, theta = self._geometry(np.asarray(phi, dtype=float))
        return theta[link]

    # ---------------------------------------------------------------- velocity plans
    def velocity_plans(self, positions: Positions | int | None = None, *, omega_1: float = 1.0,
                       sin_threshold: float = 1e-3) -> VelocityPlans:
        """Velocity plans in every position, built as the textbook builds them.

        Parameters
        ----------
        positions : Positions or int, optional
            Positions of this linkage (default ``self.positions(12)``; an int m means
            ``self.positions(m)``).
        omega_1 : float
            Crank speed, rad/s (> 0; the crank turns in ``self.sense``). With 1 (default) the
            plans give the velocity analogues (m/rad) and angular velocity ratios.
        sin_threshold : float
            Positions where two construction lines meet with |sin| below this are marked
            ``ill_conditioned`` and take the analytic derivative instead of the intersection.

        Returns
        -------
        VelocityPlans

        Raises
        ------
        AssemblyError
            At a position where the two lines are exactly parallel (a toggle: the velocity
            would be infinite for a turning crank).
        """
        if positions is None or isinstance(positions, (int, np.integer)):
            positions = self.positions(positions)
        if not isinstance(positions, Positions) or positions.mechanism != self:
            raise InputError("velocity_plans needs Positions of this same linkage (from self.positions(...))")
        if isinstance(omega_1, bool) or not isinstance(omega_1, (int, float, np.floating, np.integer)) \
                or not math.isfinite(real(omega_1, "omega_1")) or omega_1 <= 0:
            raise InputError(f"omega_1 is the crank speed in rad/s and must be > 0 (use sense=-1 for a "
                             f"clockwise crank), got {omega_1!r}")
        if not (0.0 <= sin_threshold < 1.0):
            raise InputError(f"sin_threshold must be in [0, 1), got {sin_threshold!r}")
        Om = self.sense * float(omega_1)
        vel, omegas, cons = self._construct(positions, Om)
        n = positions.n
        sins = [np.abs(c.sin_between) for c in cons if c.sin_between is not None]
        sin_min = np.minimum.reduce(sins) if sins else np.ones(n)
        exact_zero = (sin_min == 0.0) & ~positions.extreme
        if exact_zero.any():
            self._raise_toggle(positions, int(np.argmax(exact_zero)))
        ill = sin_min < sin_threshold
        if ill.any():
            with np.errstate(divide="ignore", invalid="ignore"):
                d_xy, d_th = self.derivatives(positions.phi[ill])
            finite = np.logical_and.reduce([np.isfinite(a).all(axis=-1) for a in d_xy.values()]
                                           + [np.isfinite(a) for a in d_th.values()])
            if not finite.all():
                self._raise_toggle(positions, int(np.flatnonzero(ill)[np.argmin(finite)]))
            for name, (x, y) in vel.items():
                if name in d_xy:
                    x[ill] = Om * d_xy[name][:, 0]
                    y[ill] = Om * d_xy[name][:, 1]
            for link, w in omegas.items():
                w[ill] = Om * d_th[link]
            self._snap_extremes(vel, omegas, positions.extreme & ill)
        cons = self._add_point_plans(positions, vel, cons)
        vectors = {name: V.stack(x, y, n) for name, (x, y) in vel.items()}
        return VelocityPlans(
            positions=positions, omega_1=float(omega_1), sense=self.sense,
            vectors=MappingProxyType(vectors),
            omegas=MappingProxyType({k: V.frozen(np.asarray(w, dtype=float)) for k, w in omegas.items()}),
            constructions=MappingProxyType({c.name: c for c in cons}),
            sin_min=V.frozen(sin_min), ill_conditioned=V.frozen(ill), sin_threshold=float(sin_threshold),
        )

    def _raise_toggle(self, positions: Positions, i: int):
        raise AssemblyError(f"{self.kind}: {self._where(positions.phi, positions.index, i)}: "
                            f"{self._toggle_text()}; the two construction lines are parallel and the "
                            f"velocity is infinite for a turning crank; move the position off the toggle")

    def _toggle_text(self) -> str:
        return "the linkage is at a toggle"

    def _snap_extremes(self, vel: dict, omegas: dict, mask: np.ndarray) -> None:
        """At the extreme positions the output stands still: put its points at the pole (hook)."""

    def _add_point_plans(self, positions: Positions, vel: dict, cons: list) -> list:
        cons = list(cons)
        for p in self.points:
            x, y, canon, rev = self._resolve_link(p.link)
            L = self._link_length(canon)
            k = p.distance / L
            c, s = math.cos(p.angle), math.sin(p.angle)
            vx, vy = vel[x]
            wx, wy = vel[y]
            dx, dy = wx - vx, wy - vy
            vel[p.name] = (vx + k * (c * dx - s * dy), vy + k * (s * dx + c * dy))
            ang = "" if p.angle == 0.0 else f", turned {math.degrees(p.angle):.6g}°"
            cons.append(PointConstruction(
                name=p.name, method="similarity", on=x + y,
                equation=f"{p.name.lower()} on {x.lower()}{y.lower()}: {x.lower()}{p.name.lower()}/"
                         f"{x.lower()}{y.lower()} = {x}{p.name}/{x}{y}{ang} (similarity theorem)"))
        return cons

    def _link_length(self, canon: str) -> float:
        raise NotImplementedError

    # ---------------------------------------------------------------- analytic derivative
    def derivatives(self, phi) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray]]:
        """Analytic derivatives of the position equations with respect to φ (counterclockwise).

        Independent of the plan construction (closed forms / the differentiated loop
        equations), used to check the plans and at ill-conditioned positions.

        Parameters
        ----------
        phi : array_like
            Crank angles, rad.

        Returns
        -------
        dxy : dict name -> ndarray (n, 2)
            dX/dφ of every point, m/rad.
        dtheta : dict link -> ndarray (n,)
            dθ/dφ of every moving link (ratio of angular velocities for a counterclockwise crank).

        Velocities follow as v = sense · ω₁ · dX/dφ.
        """
        phi = self._angles(phi, "phi")
        dxy, dth, theta, geom = self._derivatives(phi)
        self._add_point_geometry(geom, theta)
        for p in self.points:
            x, y, canon, rev = self._resolve_link(p.link)
            th = theta[canon] + (math.pi if rev else 0.0) + p.angle
            w = dth[canon]
            dX = dxy[x]
            dxy[p.name] = (dX[0] - p.distance * w * np.sin(th), dX[1] + p.distance * w * np.cos(th))
        out = {}
        for name, (x, y) in dxy.items():
            out[name] = np.stack(np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float)), axis=-1)
        return out, dth

    def _derivatives(self, phi):  # pragma: no cover - hook
        raise NotImplementedError

    def _geometry(self, phi):  # pragma: no cover - hook
        raise NotImplementedError

    def _construct(self, positions, Om):  # pragma: no cover - hook
        raise NotImplementedError


def pole(name: str) -> PointConstruction:
    """Construction record of a fixed point (its image is the pole p)."""
    return PointConstruction(name=name, method="pole", equation=f"v_{name} = 0")


def known(name: str, centre: str, link: str) -> PointConstruction:
    """Construction record of the crank pin: pa ⟂ OA, |pa| = ω₁·OA, in the sense of ω₁."""
    return PointConstruction(name=name, method="known",
                             equation=f"v_{name} = ω₁·l_{link}, ⟂ {link}, in the sense of ω₁")


def line(through: str, relation: str, to: str, px, py, dx, dy, n: int) -> ConstructionLine:
    """A frozen ConstructionLine from arrays/scalars."""
    return ConstructionLine(through=through, relation=relation, to=to, point=V.stack(px, py, n),
                            direction=V.stack(dx, dy, n))


def fail(msg: str):
    """Raise AssemblyError(msg) (helper for the linkages)."""
    raise AssemblyError(msg)

