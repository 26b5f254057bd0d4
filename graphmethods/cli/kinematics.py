"""``graphmethods kinematics CASE.json``: positions and velocities of a linkage problem file.

Prints, per position 0…M (position M = position 0), the crank angle and the velocities at the
mean crank speed n_rpm of the file: for the slider-crank press format at least ``phi_deg``
(crank angle from +x, degrees), ``v_B`` (m/s, signed along +x), ``omega_2`` (rod, rad/s,
counterclockwise +) and ``v_S2`` (m/s, magnitude). Sliders' velocities are signed along +x of
their guide, other points' are magnitudes; ``omega_k`` uses the textbook link numbers (crank
= 1) listed under ``links``. Plain text table by default, one JSON object with ``--json``.
"""

from __future__ import annotations

import json
import math


def add_parser(sub) -> None:
    p = sub.add_parser(
        "kinematics", help="positions and velocity plans of a linkage problem file",
        description="Positions 0…M of a linkage problem file (slider-crank press, four-bar, slotted lever, "
                    "shaper) and its velocities at the file's mean crank speed, from the velocity plans.")
    p.add_argument("case", metavar="CASE.json", help="problem file (see shared/cases/README.md)")
    p.add_argument("--positions", "-m", type=int, default=12, metavar="M",
                   help="number of equal crank steps per turn (default 12; positions 0…M)")
    p.add_argument("--json", action="store_true", help="print one JSON object whose 'positions' is the list")
    p.set_defaults(func=run)


def _clean(x: float) -> float:
    x = float(x)
    return 0.0 if x == 0.0 else x


def table(case, m: int) -> dict:
    """The result as a JSON-ready dict (also used by the text output)."""
    import numpy as np

    mech = case.mechanism
    pos = mech.positions(m=m)
    plan = mech.velocity_plans(pos, omega_1=case.omega_m)
    st = pos.strokes
    cols: dict[str, np.ndarray] = {
        "position": pos.index, "phi_deg": pos.phi_deg, "phi_from_start_deg": np.degrees(pos.phi_from_start)}
    units = {"phi_deg": "°", "phi_from_start_deg": "°"}
    if pos.s is not None:
        slider = next(iter(mech.guides))
        cols[f"s_{slider}"] = pos.s
        units[f"s_{slider}"] = "m"
    if pos.psi is not None:
        cols["psi_deg"] = np.degrees(pos.psi)
        units["psi_deg"] = "°"
    fixed = {c.name for c in plan.constructions.values() if c.method == "pole"}
    for name in plan.vectors:
        if name in fixed:
            continue
        key = f"v_{name}"
        cols[key] = plan.v_along_guide(name) if name in mech.guides else plan.speed(name)
        units[key] = "m/s"
        if case.kind == "slider_crank" and name == "B":
            cols["v_BA"] = np.hypot(*(plan.v_rel("B", "A").T))
            units["v_BA"] = "m/s"
        if name == "A3":
            u = pos.xy("A") - pos.xy("O3")
            u = u / np.hypot(u[:, 0], u[:, 1])[:, None]
            rel = plan.v_rel("A3", "A")
            cols["v_A3A2"] = rel[:, 0] * u[:, 0] + rel[:, 1] * u[:, 1]
            units["v_A3A2"] = "m/s"
    for k, link in mech.link_numbers.items():
        if k >= 2:
            cols[f"omega_{k}"] = plan.omega(link)
            units[f"omega_{k}"] = "rad/s"
    rows = []
    for i in range(pos.n):
        row = {key: (int(v[i]) if key == "position" else _clean(v[i])) for key, v in cols.items()}
        row["ill_conditioned"] = bool(plan.ill_conditioned[i])
        rows.append(row)
    out = {
        "case": case.name, "kind": case.kind, "source": case.source, "n_rpm": case.n_rpm,
        "omega_1": case.omega_m, "sense": "ccw" if mech.sense == 1 else "cw", "m": m,
        "links": {str(k): v for k, v in mech.link_numbers.items()},
    }
    if st is not None:
        out.update(phi_start_deg=math.degrees(st.phi_start), phi_end_deg=math.degrees(st.phi_end),
                   working_angle_deg=math.degrees(st.working_angle), return_angle_deg=math.degrees(st.return_angle),
                   K=st.K, start=st.start_name)
    if pos.H is not None:
        out["stroke_H"] = pos.H
    if pos.psi_max is not None:
        out["psi_max_deg"] = math.degrees(pos.psi_max)
    out["units"] = units
    out["positions"] = rows
    return out


def _text(res: dict) -> str:
    lines = [f"{res['case'] or res['kind']}  ({res['kind']}, {res['source']})",
             f"n = {res['n_rpm']:g} rev/min, ω₁ = {res['omega_1']:.6g} rad/s ({res['sense']}), "
             f"m = {res['m']} positions from {res.get('start', 'φ = 0')}"]
    if "K" in res:
        lines.append(f"working stroke {res['working_angle_deg']:.4f}°, return {res['return_angle_deg']:.4f}°, "
                     f"K = {res['K']:.4f}" + (f", stroke H = {res['stroke_H']:.6g} m" if "stroke_H" in res else "")
                     + (f", swing ψ_max = {res['psi_max_deg']:.4f}°" if "psi_max_deg" in res else ""))
    lines.append("links: " + ", ".join(f"{k} = {v}" for k, v in res["links"].items()))
    keys = [k for k in res["positions"][0] if k != "ill_conditioned"]
    head = [k if k not in res["units"] else f"{k} [{res['units'][k]}]" for k in keys]
    width = [max(10, len(h)) for h in head]
    lines.append("  ".join(h.rjust(w) for h, w in zip(head, width)))
    for row in res["positions"]:
        cells = []
        for k, w in zip(keys, width):
            v = row[k]
            cells.append(str(v).rjust(w) if k == "position" else f"{v:.{3 if k.endswith('_deg') else 5}f}".rjust(w))
        lines.append("  ".join(cells) + ("  ill-conditioned" if row["ill_conditioned"] else ""))
    lines.append(f"position {res['m']} = position 0")
    return "\n".join(lines)


def run(args) -> int:
    from graphmethods.errors import InputError
    from graphmethods.kinematics import read_case

    case = read_case(args.case)
    if args.positions < 3:
        raise InputError(f"--positions must be at least 3, got {args.positions}")
    res = table(case, args.positions)
    if args.json:
        print(json.dumps(res, ensure_ascii=False, indent=1))
    else:
        print(_text(res))
    return 0
