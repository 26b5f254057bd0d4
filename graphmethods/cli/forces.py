"""``graphmethods forces CASE (--phi-deg A | --position K)``: the force analysis in one position.

CASE is a problem file or a built-in problem's name (``graphmethods forces shaper --position 3``).
The crank turns at the file's mean speed (or ``--n``, rev/min) with ``--epsilon-1`` (rad/s², +
speeding up); the working load is the file's at that position; ``--gravity`` adds the weights
(g = 9.81 m/s² along −y of the file's frame).

With ``--json`` one JSON object: ``"links"`` (per link number the inertia force ``"F_i"`` [Fx, Fy]
in N at the centre of mass, the inertia moment ``"M_i"`` in N·m, counterclockwise +, and ``"h"``,
the distance F_i is moved to replace both, m), ``"reactions"`` (per pair ``"R_ij"``, the force
link i exerts on link j, [Rx, Ry] in N, frame = 0), ``"M_balance"`` (the balancing moment on the
crank from the force plans, N·m, counterclockwise +), ``"M_balance_lever"`` (Zhukovsky's lever),
``"M_balance_power"`` (the power balance) and their differences in per cent, and ``"pairs"``
(where each reaction acts; a prismatic pair's couple and the offset h of its normal force).
Without ``--json`` the same as a table, in ``--lang en|ru|zh``.

``--sheet FILE.svg|.pdf|.dxf`` also writes the A1 (``--page A2``) force-analysis sheet of that
position, in ``--lang``: the scheme with every force, the force plans, Zhukovsky's lever and the
result table (:func:`graphmethods.sheets.force_analysis_sheet.force_analysis_sheet`), at the file's
mean speed with ε₁ = 0. An existing file is kept unless ``--force``; on any error nothing is written.
"""

from __future__ import annotations

import math
from typing import Any

from graphmethods.cli import _sheet
from graphmethods.units import MAX_POSITIONS, check_finite, count, json_text


def add_parser(sub) -> None:
    from graphmethods.cli._parser import add_sheet_options, integer, number
    from graphmethods.cli.kinematics import add_linkage_case, add_speed

    p = sub.add_parser(
        "forces", help="force (kinetostatic) analysis in one position: reactions and the balancing moment",
        description="The force analysis of a linkage problem in one position: inertia forces and moments, the "
                    "applied loads, the reaction in every pair group by group, the balancing moment on the crank "
                    "from the force plans, checked by Zhukovsky's lever and the power balance.")
    add_linkage_case(p)
    where = p.add_mutually_exclusive_group(required=True)
    where.add_argument("--phi-deg", type=number, default=None, metavar="A",
                       help="the crank angle, degrees from +x, counterclockwise (one angle: one force analysis)")
    where.add_argument("--position", type=integer, default=None, metavar="K",
                       help="position K of 0…M, counted from the start of the working stroke")
    p.add_argument("--positions", "-m", type=integer, default=12, metavar="M",
                   help="equal crank steps per turn for --position (default 12)")
    p.add_argument("--gravity", action="store_true", help="add the weights (g = 9.81 m/s² along −y)")
    add_speed(p)
    p.add_argument("--epsilon-1", type=number, default=0.0, metavar="E",
                   help="crank angular acceleration, rad/s², + when the crank speeds up (default 0)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    add_sheet_options(p, "the force-analysis sheet of this position",
                      lang_help="language of the table and the sheet (default en)")
    p.set_defaults(func=run)


def _v(z: complex) -> list[float]:
    return [float(z.real) + 0.0, float(z.imag) + 0.0]


def _f(x: float) -> float:
    return float(x) + 0.0


def result(case, *, phi_deg: float | None = None, position: int | None = None, m: int = 12,
           gravity: bool = False, n_rpm: float | None = None, epsilon_1: float = 0.0) -> dict:
    """The force analysis as a JSON-ready dict (see the module docstring)."""
    from graphmethods.dynamics.forces import case_forces
    from graphmethods.kinematics.drawn import driver_angles_deg
    from graphmethods.units import omega_from_n

    omega_1 = case.omega_m if n_rpm is None else omega_from_n(n_rpm)
    if phi_deg is not None:
        fa = case_forces(case, phi_deg=[phi_deg], omega_1=omega_1, epsilon_1=epsilon_1, gravity=gravity)
        i = 0
    else:
        fa = case_forces(case, m=m, omega_1=omega_1, epsilon_1=epsilon_1, gravity=gravity)
        i = int(position or 0)
    mo = fa.motion
    lk = mo.linkage
    links: dict[str, dict[str, Any]] = {}
    for k in lk.links:
        F, M = fa.inertia_of(k)
        Fi, Mi = complex(F[i]), float(M[i])
        h = 0.0 if Mi == 0.0 else (abs(Mi) / abs(Fi) if Fi != 0 else None)
        links[k] = {"F_i": _v(Fi), "M_i": _f(Mi), "h": h}
    reactions: dict[str, list[float]] = {}
    pairs: dict[str, dict[str, Any]] = {}
    for key, r in sorted(fa.reactions.items(), key=lambda kv: (len(kv[0]), kv[0])):
        reactions[key] = _v(complex(r.R[i]))
        info: dict[str, Any] = {"kind": "revolute" if r.kind == "R" else "prismatic", "at": _v(complex(r.at[i]))}
        if r.kind == "P":
            info["M"] = _f(r.M[i])
            hh = float(r.h[i])
            info["h"] = _f(hh) if math.isfinite(hh) else None
        pairs[key] = info
    loads = []                      # every external load at this position: the working load, weights, the file's
    for k, forces in fa.applied.items():
        for f in forces:
            if f.label.startswith("F_i"):
                continue
            Fz, Mf = complex(f.F[i]), float(f.M[i])
            if Fz != 0:
                loads.append({"label": f.label, "link": int(k), "at": _v(complex(f.at[i])), "force": _v(Fz)})
            if Mf != 0:
                loads.append({"label": f.label, "link": int(k), "moment": _f(Mf)})
    Mb, Ml, Mp = (float(x[i]) for x in (fa.M_balance, fa.M_balance_lever, fa.M_balance_power))
    drawn = getattr(case, "drawn", None)
    extra: dict[str, Any] = {}
    if drawn is not None:
        extra = {"structure": drawn.structure.as_json()}
    return {
        "case": case.name, "kind": case.kind, "source": case.source,
        "position": None if phi_deg is not None else int(position or 0), "m": None if phi_deg is not None else m,
        "phi_deg": _f(math.degrees(float(mo.phi[i])) % 360.0 if lk.swing is None else
                      driver_angles_deg(case.drawn, mo, None if phi_deg is None else [phi_deg])[i]),
        "n_rpm": case.n_rpm if n_rpm is None else n_rpm, "omega_1": omega_1, "epsilon_1": epsilon_1,
        "sense": "ccw" if lk.sense == 1 else "cw", "gravity": 9.81 if gravity else 0.0,
        "structure": lk.structure().formula,
        "links": links, "loads": loads, "reactions": reactions, "pairs": pairs,
        "M_balance": _f(Mb), "M_balance_lever": _f(Ml), "M_balance_power": _f(Mp),
        "difference_lever_percent": _f(fa.difference_percent(fa.M_balance_lever)[i]),
        "difference_power_percent": _f(fa.difference_percent(fa.M_balance_power)[i]),
        **extra,
    }


def _text(res: dict[str, Any], lang: str, title: str | None = None) -> str:
    """The force analysis as the table ``graphmethods forces`` prints, in the words of ``lang``; ``title`` is
    the problem's title in that language (the sheet's), else the problem's name."""
    from graphmethods.scene.notation import get
    from graphmethods.scene.numbers import within_roundoff

    nt = get(lang)
    sep = "，" if lang == "zh" else ", "                     # a Chinese line takes full-width commas
    N, Nm, m_ = nt.unit("N"), nt.unit("N·m"), nt.unit("m")
    i = nt.word("forces.sub_inertia")                      # F_и in ru, F_I in zh: as the drawings write them
    sense = nt.word(f"kinematics.{res['sense']}") if res["sense"] in ("cw", "ccw") else res["sense"]
    where = (f"{nt.word('dynamics.position')} {res['position']} / {res['m']}{sep}"
             if res["position"] is not None else "")
    weights = nt.word("forces.gravity_yes") if res["gravity"] else nt.word("forces.gravity_no")
    lines = [f"{nt.word('forces.report_title')}{nt.colon}{title or res['case'] or res['kind']}  ({res['source']})",
             (f"{where}{nt.word('forces.crank_angle')} = {res['phi_deg']:.4f}°{sep}"
              f"{nt.word('forces.omega_1')} = {res['omega_1']:.6g} {nt.unit('rad/s')} ({sense}){sep}"
              f"{nt.word('forces.epsilon_1')} = {res['epsilon_1']:g} {nt.unit('rad/s²')}{sep}"
              f"{res['structure']['formula'] if isinstance(res['structure'], dict) else res['structure']}"),
             f"{nt.word('forces.gravity')}{nt.colon}{weights}", "", nt.word("forces.inertia_loads"),
             (f"{nt.word('forces.link'):>6}  {f'F_{i}x [{N}]':>12}  {f'F_{i}y [{N}]':>12}  {f'|F_{i}| [{N}]':>12}  "
              f"{f'M_{i} [{Nm}]':>12}  {f'h [{m_}]':>10}")]
    for k, d in res["links"].items():
        fx, fy = d["F_i"]
        h = "-" if d["h"] is None else f"{d['h']:.5f}"
        lines.append(f"{k:>6}  {fx:12.3f}  {fy:12.3f}  {math.hypot(fx, fy):12.3f}  {d['M_i']:12.4f}  {h:>10}")
    lines += ["", nt.word("forces.applied_loads")]
    if not res["loads"]:
        lines.append(f"  {nt.word('forces.no_load')}")
    else:
        lines.append(f"{nt.word('forces.load'):>8}  {nt.word('forces.link'):>6}  {f'x [{m_}]':>10}  {f'y [{m_}]':>10}  "
                     f"{f'F_x [{N}]':>12}  {f'F_y [{N}]':>12}  {f'|F| [{N}]':>12}  {f'M [{Nm}]':>12}")
    for d in res["loads"]:
        if "force" in d:
            (x, y), (fx, fy) = d["at"], d["force"]
            lines.append(f"{d['label']:>8}  {d['link']:>6}  {x:10.5f}  {y:10.5f}  {fx:12.3f}  {fy:12.3f}  "
                         f"{math.hypot(fx, fy):12.3f}  {'-':>12}")
        else:
            lines.append(f"{d['label']:>8}  {d['link']:>6}  {'-':>10}  {'-':>10}  {'-':>12}  {'-':>12}  {'-':>12}  "
                         f"{d['moment']:12.4f}")
    lines += ["", nt.word("forces.reactions"),
              f"{nt.word('forces.pair'):>8}  {f'R_x [{N}]':>12}  {f'R_y [{N}]':>12}  {f'|R| [{N}]':>12}"]
    for k, (rx, ry) in res["reactions"].items():
        lines.append(f"{k:>8}  {rx:12.3f}  {ry:12.3f}  {math.hypot(rx, ry):12.3f}")
    diff = nt.word("forces.diff")

    def percent(p: float) -> str:                          # round-off of the two methods' agreement reads 0
        return "0" if within_roundoff(p, 100.0) else f"{p:.2e}"

    lines += ["", nt.word("forces.balancing"),
              f"  {nt.word('forces.from_plans'):<28} {res['M_balance']:14.6f} {Nm}",
              (f"  {nt.word('forces.from_lever'):<28} {res['M_balance_lever']:14.6f} {Nm}   {diff} "
               f"{percent(res['difference_lever_percent'])} %"),
              (f"  {nt.word('forces.from_power'):<28} {res['M_balance_power']:14.6f} {Nm}   {diff} "
               f"{percent(res['difference_power_percent'])} %")]
    return "\n".join(lines)


def run(args) -> int:
    from graphmethods.cli._sheet import check_sheet_target, refuse_two_on_stdout, report_stream
    from graphmethods.cli.kinematics import speed_rpm
    from graphmethods.errors import InputError
    from graphmethods.problems import builtin

    m = count(args.positions, "--positions", low=3, high=MAX_POSITIONS, why="checked before any work")
    if args.position is not None and not 0 <= args.position <= m:
        raise InputError(f"--position {args.position}: give a position from 0 to {m} (--positions {m})")
    n_rpm = speed_rpm(args)
    _sheet.check_signature(args)
    sheet = None
    if args.sheet is not None:
        if n_rpm is not None or args.epsilon_1 != 0.0:
            raise InputError("--sheet draws the file's mean speed with ε₁ = 0; leave out --n/--omega and --epsilon-1 "
                             "(or run them without --sheet)")
        sheet = check_sheet_target(args.sheet, args.force, args.format)
    elif args.format is not None:
        raise InputError("--format is the sheet's file format; add -o FILE (or -o - for standard output)")
    refuse_two_on_stdout(args.json, sheet)
    case = builtin.case(args.case)
    data = None
    if sheet is not None:
        from graphmethods.cli._sheet import scene_bytes, signed
        from graphmethods.sheets.force_analysis_sheet import force_analysis_sheet

        scene = force_analysis_sheet(case, args.position, phi_deg=args.phi_deg, m=m, gravity=args.gravity,
                                     page=args.page, notation=args.lang)
        data = scene_bytes(signed(scene, args), sheet)
    res = result(case, phi_deg=args.phi_deg, position=args.position, m=m, gravity=args.gravity, n_rpm=n_rpm,
                 epsilon_1=args.epsilon_1)
    out = report_stream(sheet)
    if args.json:
        print(json_text(res, indent=1), file=out)
    else:
        check_finite({k: v for k, v in res.items() if k != "pairs"})
        from graphmethods.problems.reference_cases import title_of

        print(_text(res, args.lang, title_of(case).title_in(args.lang)), file=out)
    if data is not None and sheet is not None:     # written last: an error above leaves no file behind
        import sys

        sheet.write(data, overwrite=args.force)
        if not sheet.to_stdout:
            print(f"wrote {sheet} ({args.page}, {args.lang})", file=sys.stderr if args.json else sys.stdout)
    return 0
