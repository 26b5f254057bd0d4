"""The constructions recomputed at the student's scales, each item judged, and the usual mistakes as
hypotheses: the value recomputed with the mistake made, named when the student's value fits it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.sheets.check.problems import CycleData, LinkageData
from graphmethods.sheets.check.report import Checker, levels_accepted, rel
from graphmethods.sheets.check.tolerances import TOL_MM, TOL_REL
from graphmethods.sheets.worksheets.constructions import region_perimeters_mm
from graphmethods.sheets.worksheets.variants import SEGMENTS
from graphmethods.units import omega_from_n


@dataclass
class _Cycle:
    """What the steps of :func:`check_cycle` hand on: the exact works and their tolerances, and what the
    student's own earlier values imply (their works, levels and tolerances), for the carried verdicts."""

    A: np.ndarray                          # the exact works, J
    names: list[str]                       # the intervals' names ("a–b")
    tol_A: list[float]                     # the work tolerances, J (computed, not drawn; the areas' if measured)
    tol_f: list[float] = field(default_factory=list)     # the student's area tolerances, mm²
    f_student: list[float] | None = None   # the student's areas, mm²
    k_student: float | None = None         # the student's μ_M·μ_φ, J/mm²
    k_base: float | None = None            # the scale the work hypotheses start from
    f_base: np.ndarray | None = None       # the areas they start from, mm²
    own_A: np.ndarray | None = None        # the student's own works, J
    own_tol_A: list[float] = field(default_factory=list)
    tol_dW: float = 0.0                    # the tolerance of ΔW_max, J
    own_E: np.ndarray | None = None        # the student's own energy levels, J
    own_tol_dW: float | None = None
    dW_student: float | None = None        # the ΔW_max the student wrote, J


def check_cycle(ck: Checker, p: CycleData) -> None:
    """Judge a cycle problem's answers in the order a student works: the areas of the moment diagram,
    the works, the arrows of the energy indicator, ΔW_max, where ω_max and ω_min occur, then M_d, the
    ω's and J_F; each step hands on what the student's own values imply (:class:`_Cycle`)."""
    c = p.cycle
    A = np.asarray(c.work, dtype=float)
    st = _Cycle(A, [f"{c.labels[i]}–{c.labels[i + 1]}" for i in range(A.size)], [TOL_REL * abs(a) for a in A])
    _cycle_areas(ck, p, st)
    _cycle_works(ck, p, st)
    _cycle_arrows(ck, st)
    _cycle_delta_W(ck, p, st)
    _cycle_positions(ck, p, st)
    _cycle_flywheel(ck, p, st)


def _cycle_areas(ck: Checker, p: CycleData, st: _Cycle) -> None:
    """The areas of the moment diagram, each within 0.5 mm × its perimeter at the student's scales."""
    c, A, n, names, tol_A = p.cycle, st.A, st.A.size, st.names, st.tol_A
    has_curves = c.M_d is not None
    f_student = ck.numbers("moment_diagram", "areas_mm2")
    tol_f: list[float] = []                              # the student's area tolerances, mm²
    k_student: float | None = None
    if "moment_diagram" in ck.a:
        mu_M = ck.need("moment_diagram", "mu_M", "N·m per mm of the moment diagram")
        if ck.get("moment_diagram", "mu_phi") is not None:
            mu_phi = ck.need("moment_diagram", "mu_phi", "rad per mm")
        elif ck.get("moment_diagram", "mu_phi_deg") is not None:
            mu_phi = math.radians(ck.need("moment_diagram", "mu_phi_deg", "degrees per mm"))
        else:
            raise InputError("the answers give a [moment_diagram] but no mu_phi (rad/mm) or mu_phi_deg (°/mm)")
        k_student = mu_M * mu_phi
        if f_student is not None:
            if len(f_student) != n:
                ck.position("moment_diagram.areas_mm2", "number of intervals", [n], float(len(f_student)))
                f_student = None
            else:
                if has_curves:
                    per = region_perimeters_mm(c, mu_M=mu_M, mu_phi=mu_phi)
                    basis = "0.5 mm × the region's perimeter"
                else:
                    per = 4.0 * np.sqrt(np.abs(A / k_student))
                    basis = "0.5 mm × 4√|f| (region shape not known)"
                tol_f = [TOL_MM * float(x) for x in per]
                for i in range(n):
                    exp = A[i] / k_student
                    ck.value(f"moment_diagram.areas_mm2[{i}]", f"area {names[i]}", "mm²", exp, f_student[i], tol_f[i],
                             hypotheses=[("sign_flipped", -exp)], note=basis)
                    tol_A[i] = tol_f[i] * k_student
    st.f_student, st.k_student, st.tol_f = f_student, k_student, tol_f


def _cycle_works(ck: Checker, p: CycleData, st: _Cycle) -> None:
    """The works from the areas (or computed), with the scale and unit mistakes as hypotheses."""
    c, A, n, names, tol_A, tol_f = p.cycle, st.A, st.A.size, st.names, st.tol_A, st.tol_f
    f_student, k_student = st.f_student, st.k_student
    # the base the work hypotheses start from: the student's areas, or the data's
    if f_student is not None:
        f_base, k_base = np.asarray(f_student), k_student
    elif p.areas_given and c.areas_mm2 is not None and c.mu_M is not None and c.mu_phi is not None:
        f_base, k_base = np.asarray(c.areas_mm2, dtype=float), float(c.mu_M * c.mu_phi)
    else:
        f_base, k_base = None, None
    # ---- works
    w_student = ck.numbers("results", "works_J")
    if w_student is not None and len(w_student) != n:
        ck.position("results.works_J", "number of intervals (works)", [n], float(len(w_student)))
        w_student = None
    if w_student is not None:
        for i in range(n):
            own = None if f_student is None or k_student is None else f_student[i] * k_student
            base = A[i] if own is None else own
            hyps: list[tuple[Any, ...]] = [("sign_flipped", -base), ("degrees_as_radians", base * 180.0 / math.pi),
                    ("degrees_as_radians", base * math.pi / 180.0)]
            if f_base is not None and k_base is not None:
                hyps += [("scale_forgotten", f_base[i]), ("scale_twice", f_base[i] * k_base ** 2)]
            ck.value(f"results.works_J[{i}]", f"work {names[i]}", "J", A[i], w_student[i], rel(tol_A[i], A[i]),
                     own=own, own_tol=rel(tol_A[i], own or 0.0), own_from="the student's area",
                     hypotheses=hyps, hyp_tol=lambda h, i=i: rel(tol_A[i], h),
                     note="from the areas" if f_student is not None else "computed")
    # the student's own works (from what they wrote, else from their areas, else their arrows below)
    if w_student is not None:
        own_A = np.asarray(w_student)
        own_tol_A = [TOL_REL * abs(x) for x in own_A]
    elif f_student is not None and k_student is not None:
        own_A = np.asarray(f_student) * k_student
        own_tol_A = [t * k_student for t in tol_f]
    else:
        own_A, own_tol_A = None, []
    st.f_base, st.k_base, st.own_A, st.own_tol_A = f_base, k_base, own_A, own_tol_A


def _cycle_arrows(ck: Checker, st: _Cycle) -> None:
    """The arrows of the energy indicator, ±0.5 mm each; with no works written, ΔW_max is read off them."""
    A, n, names, own_A, own_tol_A = st.A, st.A.size, st.names, st.own_A, st.own_tol_A
    arrows = ck.numbers("energy_indicator", "arrows_mm")
    if "energy_indicator" in ck.a:
        mu_E = ck.need("energy_indicator", "mu_E", "J per mm of the energy indicator")
        if arrows is not None:
            if len(arrows) != n:
                ck.position("energy_indicator.arrows_mm", "number of arrows", [n], float(len(arrows)))
                arrows = None
            else:
                for i in range(n):
                    own = None if own_A is None else own_A[i] / mu_E
                    base = A[i] / mu_E if own is None else own
                    ck.value(f"energy_indicator.arrows_mm[{i}]", f"arrow {names[i]}", "mm", A[i] / mu_E, arrows[i],
                             TOL_MM, own=own, own_from="the student's work", hypotheses=[("sign_flipped", -base)],
                             note="±0.5 mm")
                if own_A is None:                         # ΔW_max read off the student's staircase
                    own_A = np.asarray(arrows) * mu_E
                    own_tol_A = [TOL_MM * mu_E] * n
    st.own_A, st.own_tol_A = own_A, own_tol_A


def _cycle_delta_W(ck: Checker, p: CycleData, st: _Cycle) -> None:
    """ΔW_max within the sum of the work tolerances between E_max and E_min; a sign flipped in any one
    interval, degrees for radians, the scale forgotten or applied twice as hypotheses."""
    c, A, n, tol_A, own_A, own_tol_A, k_base = p.cycle, st.A, st.A.size, st.tol_A, st.own_A, st.own_tol_A, st.k_base
    E = np.asarray(c.E, dtype=float)
    i_hi, i_lo = int(np.argmax(E)), int(np.argmin(E))
    span = range(min(i_hi, i_lo), max(i_hi, i_lo))
    tol_dW = float(sum(tol_A[i] for i in span))
    own_E = None if own_A is None else np.concatenate(([0.0], np.cumsum(own_A)))
    own_tol_dW = None
    if own_E is not None:
        o_hi, o_lo = int(np.argmax(own_E)), int(np.argmin(own_E))
        own_tol_dW = float(sum(own_tol_A[i] for i in range(min(o_hi, o_lo), max(o_hi, o_lo))))
    dW_student = ck.number("results", "delta_W_max")
    if dW_student is not None:
        own = None if own_E is None else float(own_E.max() - own_E.min())
        base_A = A if own_A is None else own_A
        hyps = []
        for i in range(n):
            flipped = base_A.copy()
            flipped[i] = -flipped[i]
            EE = np.concatenate(([0.0], np.cumsum(flipped)))
            hyps.append(("sign_flipped", float(EE.max() - EE.min())))
        base = float(np.ptp(np.concatenate(([0.0], np.cumsum(base_A)))))
        hyps += [("degrees_as_radians", base * 180 / math.pi), ("degrees_as_radians", base * math.pi / 180)]
        if k_base is not None:
            hyps += [("scale_forgotten", base / k_base), ("scale_twice", base * k_base)]
        base_tol = tol_dW if own_tol_dW is None else own_tol_dW
        ck.value("results.delta_W_max", "ΔW_max", "J", c.delta_W_max, dW_student, rel(tol_dW, c.delta_W_max),
                 own=own, own_tol=rel(base_tol, own or 0.0), own_from="the student's own works",
                 hypotheses=hyps, hyp_tol=lambda h: rel(base_tol, h),
                 note="sum of the work tolerances between E_max and E_min")
    st.tol_dW, st.own_E, st.own_tol_dW, st.dW_student = tol_dW, own_E, own_tol_dW, dW_student


def _cycle_positions(ck: Checker, p: CycleData, st: _Cycle) -> None:
    """Where ω_max and ω_min occur: a point label (every level within the ΔW_max tolerance accepted) or an
    angle (±0.5 mm on the φ axis)."""
    c, L, E = p.cycle, p.cycle.labels, np.asarray(p.cycle.E, dtype=float)
    tol_dW, own_E, own_tol_dW, k_student = st.tol_dW, st.own_E, st.own_tol_dW, st.k_student
    for which, key in (("max", "omega_max_at"), ("min", "omega_min_at")):
        s = ck.get("results", key)
        if s is None:
            continue
        if isinstance(s, tuple) and not all(isinstance(x, str) for x in s):
            raise InputError(f"[results] {key}: give one point label (e.g. \"b\") or one angle in degrees, "
                             f"or a list of labels; got {s!r}")
        if isinstance(s, (str, tuple)):
            acc = levels_accepted(E, L, tol_dW, which)
            own_acc = None if own_E is None or own_tol_dW is None else levels_accepted(own_E, L, own_tol_dW, which)
            ck.position(f"results.{key}", f"point of ω_{which}", acc, s, own_accepted=own_acc,
                        own_from="the student's own levels")
        else:
            if c.phi is None:
                raise InputError(f"[results] {key}: this problem has no angles (no moment curves); give the point "
                                 f"label, e.g. \"b\"")
            idx = [L.index(lab) for lab in levels_accepted(E, L, tol_dW, which)]
            phis = [math.degrees(c.phi[k] - c.phi[0]) for k in idx]
            tol_deg = TOL_MM * math.degrees(k_student / ck.need("moment_diagram", "mu_M", "")) \
                if k_student is not None else 1.0
            best = min(phis, key=lambda x: abs(x - float(s)))
            ck.value(f"results.{key}", f"angle of ω_{which}", "°", best, float(s), tol_deg,
                     note="±0.5 mm on the φ axis" if k_student is not None else "±1°")


def _cycle_flywheel(ck: Checker, p: CycleData, st: _Cycle) -> None:
    """M_d (0.1 %), ω_m, ω_max, ω_min (n used as ω, (1 ± δ) for (1 ± δ/2)) and J_F (the ΔW_max tolerance
    carried through, J_e forgotten), when the problem gives n and [δ]."""
    c, tol_dW, own_tol_dW, dW_student = p.cycle, st.tol_dW, st.own_tol_dW, st.dW_student
    M_d_student = ck.number("results", "M_d")
    if M_d_student is not None:
        if p.M_d is None:
            ck.notes.append("M_d is not checked: this problem gives no constant driving moment")
        else:
            ck.value("results.M_d", "M_d", "N·m", p.M_d, M_d_student, rel(0.0, p.M_d),
                     hypotheses=[("degrees_as_radians", p.M_d * 180 / math.pi),
                                 ("degrees_as_radians", p.M_d * math.pi / 180)], hyp_tol=lambda h: rel(0.0, h),
                     note="0.1 %")
    asks = [k for k in ("omega_m", "omega_max", "omega_min", "J_F") if ck.get("results", k) is not None]
    if asks and (p.n_rpm is None or p.delta is None):
        ck.notes.append(f"{', '.join(asks)} not checked: problem {p.id} gives no n and [δ]")
        return
    if not asks or p.n_rpm is None or p.delta is None:
        return
    n_rpm, d = float(p.n_rpm), float(p.delta)
    w = omega_from_n(n_rpm)
    om_s = ck.number("results", "omega_m")
    factors = (("omega_m", 1.0, 1.0), ("omega_max", 1 + d / 2, 1 + d), ("omega_min", 1 - d / 2, 1 - d))
    for key, f_exact, f_wrong in factors:
        s = ck.number("results", key)
        if s is None:
            continue
        own = None if (om_s is None or key == "omega_m" or not om_s > 0) else om_s * f_exact
        hyps = [("n_as_omega", n_rpm * f_exact), ("degrees_as_radians", 6 * n_rpm * f_exact)]
        if key != "omega_m":
            hyps.append(("delta_not_halved", w * f_wrong))
        ck.value(f"results.{key}", key.replace("omega_", "ω_"), "rad/s", w * f_exact, s, rel(0.0, w * f_exact),
                 own=own, own_from="the student's ω_m", hypotheses=hyps, hyp_tol=lambda h: rel(0.0, h), note="0.1 %")
    J_s = ck.number("results", "J_F")
    if J_s is not None:
        J_exp = c.delta_W_max / (w * w * d) - p.J_e
        tol = rel(tol_dW / (w * w * d), J_exp)
        dW_base = c.delta_W_max if dW_student is None else dW_student
        w_own = w if om_s is None or not om_s > 0 else om_s     # ω_m = 0 written: no result follows from it
        own = None
        if dW_student is not None or om_s is not None:
            own = dW_base / (w_own * w_own * d) - p.J_e
        t_dW = tol_dW if dW_student is None or own_tol_dW is None else max(tol_dW, own_tol_dW)
        hyps_J: list[tuple[str, float, float]] = []
        for code, X2, sub in (("n_as_omega", n_rpm ** 2, p.J_e), ("degrees_as_radians", (6 * n_rpm) ** 2, p.J_e),
                              ("delta_not_halved", 2 * w * w, p.J_e), ("J_e_not_subtracted", w * w, 0.0)):
            if code == "J_e_not_subtracted" and p.J_e <= 0:
                continue
            h = dW_base / (X2 * d) - sub
            hyps_J.append((code, h, t_dW / (X2 * d) + TOL_REL * abs(h)))
        ck.value("results.J_F", "J_F", "kg·m²", J_exp, J_s, tol, own=own,
                 own_tol=rel(t_dW / (w_own * w_own * d), own or 0.0),
                 own_from="the student's own ΔW_max and ω_m", hypotheses=hyps_J,
                 note="from the ΔW_max tolerance, + 0.1 %")


def plan_data(ck: Checker, p: LinkageData) -> tuple[dict[str, np.ndarray], float, float | None, float]:
    """(vectors by label, l_AB, n_rpm or None, ω₁) of the velocity plan the student drew."""
    if p.plan_variant is not None:
        v = p.plan_variant
        if ck.get("velocity_plan", "position") is not None:
            ck.notes.append("velocity_plan.position ignored: this problem has one position")
        return v.vectors(), v.l, None, v.omega_1
    case = p.case
    assert case is not None                  # a linkage problem is a case file or a worksheet variant
    pos_k = ck.get("velocity_plan", "position")
    m = int(ck.get("velocity_plan", "positions", 12))
    if pos_k is None or isinstance(pos_k, (str, tuple)) or not float(pos_k).is_integer() or not 0 <= pos_k <= m:
        raise InputError(f"[velocity_plan] position must be the position number 0…{m} the plan was drawn for")
    mech = case.mechanism
    positions = mech.positions(m=m)
    plan = mech.velocity_plans(positions, omega_1=case.omega_m)
    k = int(pos_k)
    vec: dict[str, np.ndarray] = {}
    for name in plan.order:
        vec.setdefault(plan.label(name), np.asarray(plan.v(name)[k], dtype=float))
    return vec, float(case.mechanism.l), float(case.n_rpm), float(case.omega_m)  # type: ignore[attr-defined]
    # (.l: a slider-crank's connecting rod; the check takes slider-crank cases only)


def check_plan(ck: Checker, p: LinkageData) -> None:
    """Judge a student's velocity plan: the segments measured (mm), the speeds and ω₂ computed from them and
    ω₂'s sense, each against the exact plan at the student's μ_v and drafting tolerance, with the usual
    mistakes tried as hypotheses (n taken as ω, the scale forgotten or applied twice).

    Parameters
    ----------
    ck : Checker
        The report being written, with the student's answers (``[velocity_plan]``).
    p : LinkageData
        The problem: the linkage's lengths, the position and the crank speed.

    See Also
    --------
    graphmethods.sheets.check.check : the public entry, from an answers file.
    """
    vec, l_AB, n_rpm, w1 = plan_data(ck, p)
    mu_v = ck.need("velocity_plan", "mu_v", "(m/s) per mm of the velocity plan")
    seg_exp = {s: float(np.hypot(*(vec[b] - vec[a]))) for s, (a, b) in SEGMENTS.items()}
    ratio = None if n_rpm is None else n_rpm / w1
    seg_student = {}
    for s in SEGMENTS:
        val = ck.number("velocity_plan", f"{s}_mm")
        if val is None:
            continue
        seg_student[s] = val
        exp = seg_exp[s] / mu_v
        hyps = [] if ratio is None else [("n_as_omega", exp * ratio)]
        ck.value(f"velocity_plan.{s}_mm", s, "mm", exp, val, TOL_MM, hypotheses=hyps, note="±0.5 mm")
    tol_v = TOL_MM * mu_v
    for key, s in (("v_A", "pa"), ("v_B", "pb"), ("v_BA", "ab"), ("v_S2", "ps2")):
        val = ck.number("results", key)
        if val is None:
            continue
        own = seg_student[s] * mu_v if s in seg_student else None
        seg = seg_student.get(s, seg_exp[s] / mu_v)
        hyps = [("scale_forgotten", seg), ("scale_twice", seg * mu_v ** 2)]
        if ratio is not None:
            hyps.append(("n_as_omega", seg * mu_v * ratio))
        ck.value(f"results.{key}", key, "m/s", seg_exp[s], val, rel(tol_v, seg_exp[s]), own=own,
                 own_tol=rel(tol_v, own or 0.0), own_from=f"the student's {s}", hypotheses=hyps,
                 hyp_tol=lambda h: rel(tol_v, h), note="0.5 mm × μ_v, + 0.1 %")
    val = ck.number("results", "omega_2")
    if val is not None:
        exp = seg_exp["ab"] / l_AB
        tol = rel(tol_v / l_AB, exp)
        v_ba = ck.number("results", "v_BA")
        own = v_ba / l_AB if v_ba is not None else (seg_student["ab"] * mu_v / l_AB if "ab" in seg_student else None)
        seg = seg_student.get("ab", seg_exp["ab"] / mu_v)
        hyps = [("scale_forgotten", seg / l_AB)] + ([] if ratio is None else [("n_as_omega", exp * ratio)])
        ck.value("results.omega_2", "ω_2", "rad/s", exp, val, tol, own=own, own_tol=rel(tol_v / l_AB, own or 0.0),
                 own_from="the student's v_BA", hypotheses=hyps, hyp_tol=lambda h: rel(tol_v / l_AB, h),
                 note="0.5 mm × μ_v / AB, + 0.1 %")
    sense = ck.get("results", "omega_2_sense")
    if sense is not None:
        if p.plan_variant is not None:
            exp_sense = p.plan_variant.answers()["omega_2_sense"]
        else:
            assert p.case is not None
            k = int(ck.get("velocity_plan", "position"))
            m = int(ck.get("velocity_plan", "positions", 12))
            w2 = float(p.case.mechanism.velocity_plans(p.case.mechanism.positions(m=m),
                                                        omega_1=p.case.omega_m).omega("AB")[k])
            exp_sense = "ccw" if w2 > 0 else "cw"
        ck.position("results.omega_2_sense", "sense of ω_2", [exp_sense], str(sense).strip().lower())


def em_data(ck: Checker, p: LinkageData) -> tuple[np.ndarray, np.ndarray, float, float]:
    """(J_e, ΔT, n_rpm, δ) of the energy–mass diagram the student drew."""
    if p.em_variant is not None:
        v = p.em_variant
        return np.asarray(v.J_e, dtype=float), np.asarray(v.delta_T, dtype=float), v.n_rpm, v.delta_value
    from graphmethods.dynamics.study import Study

    m = ck.get("energy_mass", "positions", 12)
    if isinstance(m, (str, tuple)) or not float(m).is_integer() or m < 3:
        raise InputError("[energy_mass] positions must be the number of positions m (an integer ≥ 3)")
    assert p.case is not None
    study = Study(p.case, positions=int(m), estimate=False)
    return np.asarray(study.J_e, dtype=float), np.asarray(study.delta_T, dtype=float), p.case.n_rpm, p.case.delta


def _support(J, T, a_max: float, a_min: float):
    """Intercepts (J, at J_e = 0) of the support lines of slopes a_max (above) and a_min (below)."""
    return float(np.max(T - a_max * J)), float(np.min(T - a_min * J))


def _touching(J, T, a: float, b: float, *, mu_J: float, mu_T: float, upper: bool) -> list[int]:
    """Vertices within 0.5 mm (on paper) of the line ΔT = b + a·J (positions 0…m−1)."""
    x, y = J / mu_J, T / mu_T
    slope = a * mu_J / mu_T
    dist = np.abs(y - (b / mu_T + slope * x)) / math.hypot(1.0, slope)
    return [int(i) for i in np.flatnonzero(dist[:-1] <= TOL_MM)]


def check_em(ck: Checker, p: LinkageData) -> None:
    """Judge a student's energy–mass (Wittenbauer) diagram: tan ψ_max and tan ψ_min, the intercept kl (mm), the
    positions of ω_max and ω_min and the flywheel's J_F, each against the exact construction at the student's
    μ_J and μ_T, with the usual mistakes tried as hypotheses (δ not halved, n taken as ω, the scale forgotten,
    degrees as radians).

    Parameters
    ----------
    ck : Checker
        The report being written, with the student's answers (``[energy_mass]``).
    p : LinkageData
        The problem: the study's J_e and ΔT, n and [δ].

    See Also
    --------
    graphmethods.sheets.check.check : the public entry, from an answers file.
    """
    J, T, n_rpm, d = em_data(ck, p)
    mu_J = ck.need("energy_mass", "mu_J", "kg·m² per mm of the energy–mass diagram")
    mu_T = ck.need("energy_mass", "mu_T", "J per mm of the energy–mass diagram")
    w = omega_from_n(n_rpm)
    c = mu_J / (2 * mu_T)
    exact = (c * w * w * (1 + d / 2) ** 2, c * w * w * (1 - d / 2) ** 2)
    textbook = (c * w * w * (1 + d), c * w * w * (1 - d))
    wrong_d = (c * w * w * (1 + d) ** 2, c * w * w * (1 - d) ** 2)
    tans_student = []
    for k, key in enumerate(("tan_psi_max", "tan_psi_min")):
        val = ck.number("energy_mass", key)
        tans_student.append(val)
        if val is None:
            continue
        exp = exact[k] if abs(val - exact[k]) <= abs(val - textbook[k]) else textbook[k]
        f = (1 + d / 2) ** 2 if k == 0 else (1 - d / 2) ** 2
        hyps: list[tuple[Any, ...]] = [("delta_not_halved", wrong_d[k]), ("n_as_omega", c * n_rpm ** 2 * f),
                ("scale_forgotten", w * w * f / 2)]
        ck.value(f"energy_mass.{key}", key.replace("tan_psi_", "tan ψ_"), "", exp, val, rel(0.0, exp),
                 hypotheses=hyps, hyp_tol=lambda h: rel(0.0, h), note="0.1 % ((1 ± δ/2)² or (1 ± δ))")
    a_max, a_min = 0.5 * w * w * (1 + d / 2) ** 2, 0.5 * w * w * (1 - d / 2) ** 2     # J/(kg·m²)
    b_up, b_lo = _support(J[:-1], T[:-1], a_max, a_min)
    kl_exp = (b_up - b_lo) / mu_T
    own_slopes = None
    if all(t is not None for t in tans_student):
        own_slopes = (tans_student[0] * mu_T / mu_J, tans_student[1] * mu_T / mu_J)
    kl_s = ck.number("energy_mass", "kl_mm")
    if kl_s is not None:
        own = None
        if own_slopes is not None:
            ou, ol = _support(J[:-1], T[:-1], *own_slopes)
            own = (ou - ol) / mu_T
        base = own_slopes or (a_max, a_min)
        bu, bl = _support(J[:-1], T[:-1], *base)
        J_min = float(J.min())
        hyps = [("J_e_not_subtracted", ((bu + base[0] * J_min) - (bl + base[1] * J_min)) / mu_T)]
        wu, wl = _support(J[:-1], T[:-1], 0.5 * w * w * (1 + d) ** 2, 0.5 * w * w * (1 - d) ** 2)
        hyps.append(("delta_not_halved", (wu - wl) / mu_T))
        ck.value("energy_mass.kl_mm", "kl", "mm", kl_exp, kl_s, TOL_MM, own=own, own_from="the student's tan ψ",
                 hypotheses=hyps, note="±0.5 mm")
    for which, key in (("max", "omega_max_at"), ("min", "omega_min_at")):
        s = ck.get("energy_mass", key)
        if s is None:
            continue
        upper = which == "max"
        a = a_max if upper else a_min
        acc = _touching(J, T, a, b_up if upper else b_lo, mu_J=mu_J, mu_T=mu_T, upper=upper)
        own_acc = None
        if own_slopes is not None:
            ou, ol = _support(J[:-1], T[:-1], *own_slopes)
            own_acc = _touching(J, T, own_slopes[0 if upper else 1], ou if upper else ol, mu_J=mu_J, mu_T=mu_T,
                                upper=upper)
        ck.position(f"energy_mass.{key}", f"position of ω_{which}", acc, s, own_accepted=own_acc,
                    own_from="the student's rays")
    J_s = ck.number("results", "J_F")
    if J_s is not None:
        J_exp = mu_T * kl_exp / (w * w * d)
        tol_abs = mu_T * TOL_MM / (w * w * d)
        kl_base = kl_exp if kl_s is None else kl_s
        own = None if kl_s is None else mu_T * kl_s / (w * w * d)
        hyps = []
        for code, factor in (("n_as_omega", mu_T / (n_rpm ** 2 * d)), ("scale_forgotten", 1.0 / (w * w * d)),
                             ("delta_not_halved", mu_T / (2 * w * w * d)),
                             ("degrees_as_radians", mu_T / ((6 * n_rpm) ** 2 * d))):
            h = factor * kl_base
            hyps.append((code, h, factor * TOL_MM + TOL_REL * abs(h)))
        ck.value("results.J_F", "J_F", "kg·m²", J_exp, J_s, rel(tol_abs, J_exp), own=own,
                 own_tol=rel(tol_abs, own or 0.0), own_from="the student's kl", hypotheses=hyps,
                 note="μ_T·0.5 mm/(ω_m²δ), + 0.1 %")


