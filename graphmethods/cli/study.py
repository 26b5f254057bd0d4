"""``graphmethods study CASE.json --positions M``: the dynamic study of a linkage problem.

CASE is a problem file or a built-in problem's name (``graphmethods study press``; the names:
``graphmethods problems``).

``--sheet FILE.svg|.pdf`` also writes the A1 (or A2) dynamic-analysis sheet: the flywheel by
the Wittenbauer method, drawn to scale (:func:`graphmethods.sheets.wittenbauer.dynamic_analysis_sheet`).
An existing file is kept unless ``--force``; on any error nothing is written.
"""

from __future__ import annotations

import pathlib
import sys

from graphmethods.cli._sheet import check_sheet_target
from graphmethods.errors import InputError
from graphmethods.units import MAX_POSITIONS, check_finite, count, json_text


def add_parser(sub) -> None:
    p = sub.add_parser("study", help="dynamic study of a linkage problem: J_e, M_r, the flywheel three ways",
                       description="Solve a linkage problem (a problem file, or a built-in name such as press: "
                       "see graphmethods problems): "
                       "M_d by work balance, ΔW_max, J_F by the ΔW_max method and by the Wittenbauer diagram at "
                       "M positions, the exact J_F, and where ω_max and ω_min occur. With --sheet, also draw the "
                       "dynamic-analysis sheet (M_e, ΔT, J_e turned 90°, the energy–mass diagram, the result).")
    p.add_argument("case", metavar="CASE", help="problem file (.json) or built-in problem name (graphmethods problems)")
    p.add_argument("--positions", type=int, default=12, metavar="M", help="number of positions (default 12)")
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
    p.add_argument("--sheet", metavar="FILE.svg|.pdf|.dxf", default=None,
                   help="also write the dynamic-analysis sheet (SVG, PDF or DXF, scale-true)")
    p.add_argument("--lang", choices=("en", "ru", "zh"), default="en",
                   help="notation and language of the sheet (default en)")
    p.add_argument("--page", type=str.upper, choices=("A1", "A2"), default="A1", help="sheet size (default A1)")
    p.add_argument("--force", action="store_true", help="overwrite an existing sheet file")
    p.set_defaults(func=run)


def _sheet_bytes(study, path: pathlib.Path, *, page: str, lang: str) -> bytes:
    from graphmethods.errors import NoFlywheelNeeded
    from graphmethods.sheets.wittenbauer import dynamic_analysis_sheet

    try:
        scene = dynamic_analysis_sheet(study, page=page, notation=lang)
    except NoFlywheelNeeded as exc:
        raise InputError(f"--sheet {path}: {exc}; the sheet has no flywheel to construct, so nothing was written "
                         f"(run without --sheet for the numbers)") from None
    from graphmethods.render import formats

    return formats.to_bytes(scene, path.suffix)        # .svg, .pdf or .dxf (checked before any work)


def run(args) -> int:
    from graphmethods.dynamics.study import Study
    from graphmethods.problems import builtin

    count(args.positions, "--positions", low=3, high=MAX_POSITIONS, why="checked before any work")
    sheet = check_sheet_target(args.sheet, args.force) if args.sheet is not None else None
    from graphmethods.kinematics.drawn import require_cycle

    case = builtin.case(args.case)
    require_cycle(case, "the study")
    study = Study(case, positions=args.positions)
    data = _sheet_bytes(study, sheet, page=args.page, lang=args.lang) if sheet is not None else None
    out = study.summary(exact=not args.no_exact)
    if args.eta is not None:
        from graphmethods.dynamics.power import efficiency_series
        from graphmethods.units import parse_number

        etas = [parse_number(x, name="--eta") for x in str(args.eta).split(",")]
        out["power"] = study.power(eta=efficiency_series(etas), reserve=parse_number(args.reserve, name="--reserve"))
    if args.translating is not None:
        tr = study.translating(args.translating or None)
        point = args.translating or str(study.case.load.at)
        out["translating"] = {"point": point, **tr.to_dict()}
    check_finite(out)                        # a result that is not finite is refused, naming it
    if data is not None and sheet is not None:   # written last: an error above leaves no file behind
        from graphmethods.render.files import write_atomic

        write_atomic(sheet, data, overwrite=args.force)
    if args.json:
        print(json_text(out, indent=1))
    else:
        width = max(map(len, out))
        for key, value in out.items():
            if key == "power":
                value = "; ".join(f"{k} {v:.6g}" if isinstance(v, float) else f"{k} {v}" for k, v in value.items())
            elif key == "translating":
                value = (f"point {value['point']}: m_e " + ", ".join(f"{x:.5g}" for x in value["m_e"]) + " kg; F_e "
                         + ", ".join(f"{x:.5g}" for x in value["F_e"]) + " N at positions "
                         + ", ".join(map(str, value["positions"])) + " (dead centres: "
                         + ", ".join(map(str, value["dead_centre_positions"])) + ")")
            elif isinstance(value, float):
                value = f"{value:.6g}"
            print(f"{key.ljust(width)}  {value}")
    if sheet is not None:
        print(f"wrote {sheet} ({args.page}, {args.lang})", file=sys.stderr if args.json else sys.stdout)
    return 0
