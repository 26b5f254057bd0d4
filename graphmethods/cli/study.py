"""``graphmethods study CASE.json --positions M``: the dynamic study of a linkage problem.

CASE is a problem file or a built-in problem's name (``graphmethods study press``; the names:
``graphmethods problems``).

``--sheet FILE.svg|.pdf`` also writes the A1 (or A2) dynamic-analysis sheet: the flywheel by
the Wittenbauer method, drawn to scale (:func:`graphmethods.sheets.dynamic_analysis_sheet.dynamic_analysis_sheet`).
An existing file is kept unless ``--force``; on any error nothing is written.
"""

from __future__ import annotations

import sys

from graphmethods.cli._sheet import check_sheet_target, check_signature, signed
from graphmethods.errors import InputError
from graphmethods.units import MAX_POSITIONS, check_finite, count, json_text


def add_parser(sub) -> None:
    from graphmethods.cli._parser import add_sheet_options, integer, numbers
    from graphmethods.cli.kinematics import add_linkage_case, add_speed, builtin_names

    p = sub.add_parser("study", help="dynamic study of a linkage problem: J_e, M_r, the flywheel three ways",
                       description="Solve a linkage problem (a problem file, or a built-in linkage: "
                       + builtin_names() + "): "
                       "M_d by work balance, ΔW_max, J_F by the ΔW_max method and by the Wittenbauer diagram at "
                       "M positions, the exact J_F, and where ω_max and ω_min occur; with --phi-deg, J_e, M_e, the "
                       "powers, ω and ε at those crank angles. With -o/--sheet, also draw the dynamic-analysis sheet "
                       "(M_e, ΔT, J_e turned 90°, the energy–mass diagram, the result).")
    add_linkage_case(p)
    p.add_argument("--positions", "-m", type=integer, default=12, metavar="M", help="number of positions (default 12)")
    p.add_argument("--phi-deg", type=numbers, default=None, metavar="A[,B,...]",
                   help="also give J_e, dJ_e/dφ, M_d, M_r, M_e, ω, ε and the powers N_d = M_d·ω, N_r = M_r·ω of the "
                        "steady motion (with the exact J_F) at these crank angles (degrees from +x)")
    add_speed(p)
    p.add_argument("--no-exact", action="store_true", help="skip the exact reference solution (faster)")
    p.add_argument("--translating", nargs="?", const="", default=None, metavar="POINT",
                   help="also reduce to a translating link at POINT (default: the point the load acts on): "
                        "m_e (kg) and F_e (N) at every position but the dead centres")
    p.add_argument("--eta", default=None, metavar="ETA[,ETA...]",
                   help="efficiency of the drive between the motor and the crank; several, comma-separated, are "
                        "mechanisms in series (η = η1·η2·…); adds N_mean = M_d·ω_m, M_d/η and the motor's rated power")
    p.add_argument("--reserve", default="1", metavar="K", help="with --eta: reserve factor on the motor's power "
                                                               "(default 1)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    add_sheet_options(p, "the dynamic-analysis sheet", lang_help="notation and language of the sheet (default en)")
    p.set_defaults(func=run)


def _sheet_bytes(study, target, *, page: str, lang: str, args=None) -> bytes:
    from graphmethods.errors import NoFlywheelNeeded
    from graphmethods.sheets.dynamic_analysis_sheet import dynamic_analysis_sheet

    try:
        scene = dynamic_analysis_sheet(study, page=page, notation=lang)
    except NoFlywheelNeeded as exc:
        raise InputError(f"--sheet {target}: {exc}; the sheet has no flywheel to construct, so nothing was written "
                         f"(run without --sheet for the numbers)") from None
    from graphmethods.render import formats

    return formats.to_bytes(signed(scene, args), target.suffix)        # checked before any work


#: the columns of the table at --phi-deg angles: key, header
AT_ANGLE = (("phi_deg", "φ [°]"), ("J_e", "J_e [kg·m²]"), ("dJ_e_dphi", "dJ_e/dφ [kg·m²/rad]"), ("M_d", "M_d [N·m]"),
            ("M_r", "M_r [N·m]"), ("M_e", "M_e [N·m]"), ("omega", "ω [rad/s]"), ("epsilon", "ε [rad/s²]"),
            ("N_d", "N_d [W]"), ("N_r", "N_r [W]"))


def _angle_table(rows: list[dict]) -> list[str]:
    """The table of ``--phi-deg`` for the text output (the same numbers as ``"at_angles"`` in --json)."""
    width = [max(11, len(h)) for _, h in AT_ANGLE]
    lines = [f"at the given crank angles (steady motion with J_F = {rows[0]['J_F']:.6g} kg·m²; M_e = M_d − M_r)",
             "  ".join(h.rjust(w) for (_, h), w in zip(AT_ANGLE, width))]
    for r in rows:
        lines.append("  ".join(f"{r[k]:.{3 if k == 'phi_deg' else 6}g}".rjust(w) if k != "phi_deg"
                               else f"{r[k]:.3f}".rjust(w) for (k, _), w in zip(AT_ANGLE, width)))
    return lines


def run(args) -> int:
    from graphmethods.cli._sheet import refuse_two_on_stdout, report_stream
    from graphmethods.cli.kinematics import speed_rpm
    from graphmethods.dynamics.study import Study
    from graphmethods.problems import builtin

    count(args.positions, "--positions", low=3, high=MAX_POSITIONS, why="checked before any work")
    check_signature(args)
    sheet = check_sheet_target(args.sheet, args.force, args.format) if args.sheet is not None else None
    if sheet is None and args.format is not None:
        raise InputError("--format is the sheet's file format; add -o FILE (or -o - for standard output)")
    refuse_two_on_stdout(args.json, sheet)
    from graphmethods.kinematics.drawn import require_cycle

    case = builtin.case(args.case)
    require_cycle(case, "the study")
    n_rpm = speed_rpm(args)
    from graphmethods.kinematics.drawn import require_cycle

    require_cycle(case, "the study", speed_given=n_rpm is not None)
    if n_rpm is not None:                    # the mean speed of the file replaced, everything else kept
        import dataclasses

        case = dataclasses.replace(case, n_rpm=n_rpm)
    study = Study(case, positions=args.positions)
    data = _sheet_bytes(study, sheet, page=args.page, lang=args.lang, args=args) if sheet is not None else None
    out = study.summary(exact=not args.no_exact)
    if out.get("flywheel_needed", True):     # the A1 sheet's construction: the numbers it, the slides and
        from graphmethods.sheets.dynamic_analysis_sheet import sheet_construction  # the stepper print

        out["sheet"] = sheet_construction(study)
    if args.eta is not None:
        from graphmethods.dynamics.power import efficiency_series
        from graphmethods.units import parse_number

        etas = [parse_number(x, name="--eta") for x in str(args.eta).split(",")]
        out["power"] = study.power(eta=efficiency_series(etas), reserve=parse_number(args.reserve, name="--reserve"))
    if args.translating is not None:
        tr = study.translating(args.translating or None)
        point = args.translating or str(study.case.load.at)
        out["translating"] = {"point": point, **tr.to_dict()}
    if args.phi_deg is not None:
        out["at_angles"] = study.at_angles(args.phi_deg)
    check_finite(out)                        # a result that is not finite is refused, naming it
    if data is not None and sheet is not None:   # written last: an error above leaves no file behind
        sheet.write(data, overwrite=args.force)
    stream = report_stream(sheet)
    if args.json:
        print(json_text(out, indent=1), file=stream)
    else:
        _print_text(out, stream, args.lang)
    if sheet is not None and not sheet.to_stdout:
        print(f"wrote {sheet} ({args.page}, {args.lang})", file=sys.stderr if args.json else sys.stdout)
    return 0


def _print_text(out: dict, stream, lang: str = "en") -> None:
    """The study as ``quantity  value`` lines in ``lang`` (each key by its symbol and unit in the language, the
    values with its decimal sign; the JSON keys are the English names), then the table at the given angles."""
    from graphmethods.cli._report import label, value_text
    from graphmethods.scene.notation import get

    nt = get(lang)
    rows = out.pop("at_angles", None)
    lines: list[tuple[str, str]] = []
    for key, value in out.items():
        if key == "translating":
            value = (f"point {value['point']}: m_e " + ", ".join(f"{x:.5g}" for x in value["m_e"]) + " kg; F_e "
                     + ", ".join(f"{x:.5g}" for x in value["F_e"]) + " N at positions "
                     + ", ".join(map(str, value["positions"])) + " (dead centres: "
                     + ", ".join(map(str, value["dead_centre_positions"])) + ")")
            lines.append((key, value))
        elif key in ("power", "sheet") or not isinstance(value, str):
            lines.append((key if key in ("power", "sheet") else label(key, nt), value_text(value, nt, key=key)))
        else:
            lines.append((key, value))
    width = max(len(k) for k, _ in lines)
    for k, v in lines:
        print(f"{k.ljust(width)}  {v}", file=stream)
    if rows:
        print("\n".join(_angle_table(rows)), file=stream)
