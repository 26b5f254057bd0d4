"""``graphmethods cam CASE``: a cam mechanism designed and analysed, and its A1 sheet.

CASE is a ``"kind": "cam"`` problem file or a built-in cam problem's name (``graphmethods cam
shaper-cam``). Prints the base radius (designed, or the file's), the pitch curve's base radius, the
largest pressure angles of the rise and of the return, the smallest radius of curvature of the
pitch curve, the undercut check, the flat face's width, the impacts, and per position the cam
angle, s, v, a, the pressure angle and the pitch and profile points in the cam's own frame:
plain text by default, one JSON object with ``--json`` (keys of the contract in
``shared/cases/README.md``, "Cam mechanisms").

    graphmethods cam shaper-cam --positions 12
    graphmethods cam shaper-cam --json --phi-deg 30,45

``-o FILE.svg|.pdf|.png|.dxf`` (older name ``--sheet``; ``-`` with ``--format`` for standard output)
also writes the A1 cam sheet in ``--lang en|ru|zh``; ``--figures DIR`` the A4 figures of the
construction (``<case>_motion_diagrams``, ``_combined_diagram``, ``_pressure_angle``, ``_profile``, in
``--format``, svg by default) as ``kinematics --figures`` does. An existing file is kept unless
``--force``; on any error nothing is written.

    graphmethods cam shaper-cam --figures out --lang ru
"""

from __future__ import annotations

import math
import sys
from typing import Any

from graphmethods.units import MAX_POSITIONS, count, json_text


def add_parser(sub) -> None:
    from graphmethods.cli._parser import DRAWING_TARGET, add_figure_options, add_output, integer, numbers

    p = sub.add_parser(
        "cam", help="cam mechanism: base radius from the pressure angle, motion, profile, the A1 cam sheet",
        description="Design and analyse a cam mechanism problem file (\"kind\": \"cam\"): the base radius, the "
                    "largest pressure angles, the radius of curvature and undercut, s, v, a, the pitch curve and "
                    "the profile by inversion; optionally the A1 cam sheet.")
    p.add_argument("case", metavar="CASE", help="cam problem file (.json) or built-in cam problem name "
                   "(graphmethods problems)")
    p.add_argument("--positions", "-m", type=integer, default=360, metavar="M",
                   help="number of equal cam steps per turn listed (default 360; φ = 360·k/M, k = 0…M−1)")
    p.add_argument("--phi-deg", type=numbers, default=None, metavar="A[,B,...]",
                   help="list these cam angles (degrees from the start of the first phase) instead of M positions")
    p.add_argument("--json", action="store_true", help="print one JSON object (the contract's keys)")
    add_output(p, "--sheet", dest="sheet", metavar=DRAWING_TARGET,
               help="also write the A1 cam sheet (motion diagrams by graphical integration, the combined ds/dφ–s "
                    "diagram, the profile by inversion); - writes it to standard output in --format, and nothing else")
    p.add_argument("--figures", metavar="DIR", default=None,
                   help="also write the A4 figures (motion diagrams, combined diagram, pressure angle, profile by "
                        "inversion) into DIR (created if missing)")
    add_figure_options(p, "sheet and the figures", format_help="file format of the sheet (default: the file name's "
                       "suffix; needed with -o -) and of the figures (default svg)")
    p.set_defaults(func=run)


def _num(x: float) -> float | None:
    """A JSON number (−0 written 0), or None for an infinite value (no convex point, say)."""
    x = float(x)
    if not math.isfinite(x):
        return None
    return 0.0 if x == 0.0 else x


def _angles(args) -> list[float]:
    if args.phi_deg is not None:
        return list(args.phi_deg)
    m = count(args.positions, "--positions", low=1, high=MAX_POSITIONS)
    return [360.0 * k / m for k in range(m)]


def _snap(values) -> None:
    """Rounding noise (|x| below 1e-13 of the column's largest) written as the exact 0 it stands for."""
    if len(values):
        values[abs(values) < 1e-13 * float(abs(values).max())] = 0.0


def table(cam, phi_deg: list[float]) -> dict[str, Any]:
    """The JSON-ready result: the cam's extremes and, per angle, its state (the ``--json`` contract)."""
    p = cam.problem
    st = cam.state(phi_deg)
    for name in ("s", "ds", "d2s", "d3s", "v", "a", "jerk", "alpha_deg"):
        _snap(getattr(st, name))
    rows = [{"phi_deg": _num(st.phi_deg[i]), "s": _num(st.s[i]), "v": _num(st.v[i]), "a": _num(st.a[i]),
             "jerk": _num(st.jerk[i]), "ds_dphi": _num(st.ds[i]), "d2s_dphi2": _num(st.d2s[i]),
             "pressure_angle_deg": _num(st.alpha_deg[i]),
             "pitch": [_num(st.pitch[i, 0]), _num(st.pitch[i, 1])],
             "profile": [_num(st.profile[i, 0]), _num(st.profile[i, 1])]} for i in range(len(st.s))]
    return {
        "kind": "cam", "follower": p.follower_type, "contact": p.contact,
        "displacement_unit": "rad" if p.oscillating else "m",
        "base_radius": _num(cam.base_radius), "pitch_base_radius": _num(cam.pitch_base_radius),
        "base_radius_designed": cam.designed, "offset": _num(p.offset), "roller_radius": _num(p.roller_radius),
        "omega": _num(p.omega), "stroke": _num(p.stroke),
        "pressure_angle_max_rise_deg": _num(cam.alpha_max_rise_deg),
        "pressure_angle_max_return_deg": _num(cam.alpha_max_return_deg),
        "phi_pressure_angle_max_rise_deg": _num(cam.phi_alpha_max_rise_deg),
        "phi_pressure_angle_max_return_deg": _num(cam.phi_alpha_max_return_deg),
        "rho_pitch_min": _num(cam.rho_pitch_min), "phi_rho_pitch_min_deg": _num(cam.phi_rho_min_deg),
        "undercut": bool(cam.undercut),
        "face_width_min": None if cam.face_width_min is None else _num(cam.face_width_min),
        "impacts": [{"phi_deg": _num(i.phi_deg), "kind": i.kind, "jump": _num(i.jump)} for i in cam.impacts],
        "positions": rows,
    }


def _text(res: dict[str, Any]) -> str:
    from graphmethods.scene.numbers import format_value

    def f(x: float | None, unit: str = "") -> str:
        return "—" if x is None else f"{format_value(x)}{'' if unit in ('', '°') else ' '}{unit}"

    unit = res["displacement_unit"]
    how = "designed" if res["base_radius_designed"] else "given"
    lines = [f"cam: {res['follower']} {res['contact']} follower, "
             f"base radius r_b = {f(res['base_radius'], 'm')} ({how})"
             f", pitch base radius r_0 = {f(res['pitch_base_radius'], 'm')}",
             f"largest pressure angle: rise {f(res['pressure_angle_max_rise_deg'], '°')} at φ = "
             f"{f(res['phi_pressure_angle_max_rise_deg'], '°')}, return {f(res['pressure_angle_max_return_deg'], '°')}"
             f" at φ = {f(res['phi_pressure_angle_max_return_deg'], '°')}",
             f"smallest convex radius of curvature of the pitch curve ρ_min = {f(res['rho_pitch_min'], 'm')}; "
             f"undercut: {'yes' if res['undercut'] else 'no'}"]
    if res["face_width_min"] is not None:
        lines.append(f"flat face width at least {f(res['face_width_min'], 'm')}")
    imp = ", ".join(f"{i['kind']} at {f(i['phi_deg'], '°')}" for i in res["impacts"]) or "none"
    lines.append(f"impacts: {imp}")
    lines.append(f"{'phi_deg':>8} {'s (' + unit + ')':>13} {'v':>13} {'a':>13} {'alpha_deg':>10}")
    for r in res["positions"]:
        lines.append(f"{f(r['phi_deg']):>8} {f(r['s']):>13} {f(r['v']):>13} {f(r['a']):>13} "
                     f"{f(r['pressure_angle_deg']):>10}")
    return "\n".join(lines)


def _stem(case: str) -> str:
    """A file stem for the figures: the built-in name, or the problem file's name without its suffix."""
    import pathlib

    return pathlib.Path(case).stem if case.lower().endswith(".json") else pathlib.Path(case).name


def run(args) -> int:
    from graphmethods.cli._sheet import check_sheet_target, refuse_two_on_stdout, report_stream
    from graphmethods.errors import InputError
    from graphmethods.kinematics.cam import design
    from graphmethods.problems.builtin import cam_problem

    sheet = None
    if args.sheet is not None:
        sheet = check_sheet_target(args.sheet, args.force, args.format)
    elif args.figures is None and (args.force or args.lang != "en" or args.format is not None):
        raise InputError("--lang, --format and --force apply to the sheet and the figures; add -o FILE (older name "
                         "--sheet), -o - with --format, or --figures DIR")
    if args.figures is not None and not str(args.figures).strip():
        raise InputError("--figures is empty; give a folder (it is created if missing)")
    refuse_two_on_stdout(args.json, sheet)
    angles = _angles(args)
    cam = design(cam_problem(args.case))
    res = table(cam, angles)
    data = None
    if sheet is not None:
        from graphmethods.cli._sheet import scene_bytes
        from graphmethods.sheets.cam_sheet import cam_sheet

        data = scene_bytes(cam_sheet(cam, notation=args.lang), sheet)
    written: list = []
    if args.figures is not None:
        from graphmethods.cli._sheet import write_scene_set
        from graphmethods.sheets.cam_figures import cam_figures

        stem = _stem(args.case)
        written = write_scene_set(cam_figures(cam, notation=args.lang), args.figures, stem=stem,
                                  fmt=args.format or "svg", overwrite=args.force)
        res["figures"] = [str(w) for w in written]
    out = json_text(res, indent=1) if args.json else _text(res)
    print(out, file=report_stream(sheet))
    if written and not args.json:
        print(f"wrote {len(written)} figures into {args.figures} (A4, {args.lang})", file=report_stream(sheet))
    if sheet is not None and data is not None:       # written last: an error above leaves no file behind
        sheet.write(data, overwrite=args.force)
        if not sheet.to_stdout:
            print(f"wrote {sheet} (A1, {args.lang})", file=sys.stderr if args.json else sys.stdout)
    return 0
