"""``graphmethods study CASE.json --positions M``: the dynamic study of a linkage problem."""

from __future__ import annotations

import json


def add_parser(sub) -> None:
    p = sub.add_parser("study", help="dynamic study of a linkage problem: J_e, M_r, the flywheel three ways",
                       description="Solve a linkage problem file (e.g. ../shared/cases/slider_crank_press.json): "
                       "M_d by work balance, ΔW_max, J_F by the ΔW_max method and by the Wittenbauer diagram at "
                       "M positions, the exact J_F, and where ω_max and ω_min occur.")
    p.add_argument("case", metavar="CASE.json", help="problem file")
    p.add_argument("--positions", type=int, default=12, metavar="M", help="number of positions (default 12)")
    p.add_argument("--no-exact", action="store_true", help="skip the exact reference solution (faster)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


def run(args) -> int:
    from graphmethods.dynamics.study import Study
    from graphmethods.kinematics import read_case

    study = Study(read_case(args.case), positions=args.positions)
    out = study.summary(exact=not args.no_exact)
    if args.json:
        print(json.dumps(out, indent=1))
        return 0
    width = max(map(len, out))
    for key, value in out.items():
        if isinstance(value, float):
            value = f"{value:.6g}"
        print(f"{key.ljust(width)}  {value}")
    return 0
