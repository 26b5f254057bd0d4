"""``graphmethods flywheel``: the excess-work table and the flywheel from areas, works or energy levels.

Examples::

    graphmethods flywheel --areas -50 550 -100 125 -500 25 -50 --n 600 --delta 1/300
    graphmethods flywheel --areas 10,-110,20,-25,100,-5,10 --mu-M 100 --mu-phi-deg 1 --n 600 --delta 1/300
    graphmethods flywheel --levels 0 -50 500 400 525 25 50 0 --omega 12.566 --J 60.69 --json
    graphmethods flywheel --delta-table --lang ru
    graphmethods flywheel --areas -50 550 -100 125 -500 25 -50 --n 600 --machine ac-generator --hyperbola j.svg
"""

from __future__ import annotations

import argparse
import math
import re
from typing import Any

from graphmethods.cli import flywheel_moments
from graphmethods.cli._sheet import check_target, refuse_two_on_stdout, report_stream
from graphmethods.errors import InputError
from graphmethods.units import check_finite, json_text, parse_number

LIST_OPTIONS = ("--areas", "--levels")


def preprocess_argv(argv: list[str]) -> list[str]:
    """Join the values after --areas/--levels (up to the next --option) into one token, so that
    ``--areas -50 550`` and ``--areas -50,550`` both work (argparse would take ``-50`` for an option)."""
    argv = flywheel_moments.join_values(argv)
    out, i = [], 0
    while i < len(argv):
        tok = argv[i]
        if tok in LIST_OPTIONS:
            vals, i = [], i + 1
            while i < len(argv) and not argv[i].startswith("--"):
                vals.append(argv[i])
                i += 1
            out.append(f"{tok}={','.join(vals)}")
            continue
        out.append(tok)
        i += 1
    return out


def parse_list(text: str, name: str) -> list[float]:
    parts = [p for p in re.split(r"[,\s;]+", text.strip()) if p]
    if not parts:
        raise InputError(f"{name}: no values given; list them, e.g. {name} 50 -550 100")
    return [parse_number(p, name=name) for p in parts]


def add_parser(sub) -> None:
    from graphmethods.cli._parser import add_figure_options

    p = sub.add_parser(
        "flywheel",
        help="excess-work table, ΔW_max and the flywheel (approximate method)",
        description="Excess-work table, ΔW_max and the flywheel J_F = ΔW_max/(ω_m²[δ]) − J_e, "
        "or the δ a given inertia gives. The cycle is given as signed areas (mm² with scales, "
        "or work in J without scales) or as running energy levels.",
        epilog="Example: graphmethods flywheel --areas -50 550 -100 125 -500 25 -50 --n 600 --delta 1/300",
    )
    cyc = p.add_mutually_exclusive_group(required=False)      # or --M-d/--M-r (flywheel_moments)
    cyc.add_argument("--areas", metavar="A1,A2,...",
                     help="signed areas between M_d and M_r in order: mm² with --mu-M and "
                     "--mu-phi/--mu-phi-deg, otherwise work in J")
    cyc.add_argument("--levels", metavar="E0,E1,...",
                     help="running energy levels in J, the last returning to the first")
    flywheel_moments.add_arguments(p)
    p.add_argument("--mu-M", help="moment scale of the drawing, N·m per mm")
    p.add_argument("--mu-phi", help="angle scale of the drawing, rad per mm")
    p.add_argument("--mu-phi-deg", help="angle scale of the drawing, degrees per mm")
    speed = p.add_mutually_exclusive_group(required=False)     # required unless --delta-table
    speed.add_argument("--n", help="mean speed of the shaft, rev/min")
    speed.add_argument("--omega", help="mean angular speed of the shaft, rad/s")
    goal = p.add_mutually_exclusive_group(required=False)      # required unless --delta-table
    goal.add_argument("--delta",
                      help="permissible coefficient of fluctuation [δ] (fractions like 1/300 accepted): find J_F")
    goal.add_argument("--J", help="total inertia on the shaft, kg·m²: find the δ it gives")
    goal.add_argument("--machine", metavar="NAME", help="take [δ] from the table of recommended [δ] by machine "
                      "(--delta-table lists the names): its strict end, the smaller δ, unless --machine-end lenient")
    p.add_argument("--machine-end", choices=("strict", "lenient"), default="strict",
                   help="with --machine: the table row's strict end (smaller δ, default) or its lenient end")
    p.add_argument("--delta-table", action="store_true",
                   help="print the table of recommended [δ] by machine (with --lang, --json) and stop")
    p.add_argument("--hyperbola", default=None, metavar="FILE.svg|.pdf|.png|.dxf|-",
                   help="draw the J_F–[δ] hyperbola over the table's range of [δ], the chosen [δ] marked")
    p.add_argument("--J-e", default="0",
                   help="the mechanism's own reduced inertia, kg·m², subtracted from the required total")
    p.add_argument("--closure-tol", default=None, help="allowed closure residual |ΣA|/Σ|A| (default 0.05)")
    p.add_argument("--rim", nargs="?", const="", default=None, metavar="D",
                   help="size a rim (spoked) flywheel for J_F: mean rim diameter D in m (default: the largest the "
                        "rim-speed limit allows)")
    p.add_argument("--disc", default=None, metavar="D", help="size a solid disc flywheel of diameter D (m) for J_F")
    p.add_argument("--material", choices=("cast-iron", "steel"), default=None,
                   help="flywheel material (density, rim-speed limit): default cast iron for a rim, steel for a disc")
    p.add_argument("--H-over-B", default="1.5", help="rim: radial thickness over width (default 1.5)")
    p.add_argument("--figure", default=None, metavar="FILE.svg|.pdf|.png|.dxf|-",
                   help="with --rim or --disc: draw the flywheel(s) to scale, dimensioned, with the table (- for "
                        "standard output in --format)")
    add_figure_options(p, "figure", format_help="file format of the figure that goes to standard output "
                                                "(--figure - or --hyperbola -)")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    p.set_defaults(func=run)


def _sizing(args: argparse.Namespace, J_F: float, n_rpm: float, out: dict):
    """The rim and disc flywheels of --rim/--disc for J_F (kg·m²) at n_rpm, added to ``out``."""
    from graphmethods.dynamics.flywheel import DENSITY, RIM_SPEED_LIMIT, disc_flywheel, rim_flywheel

    if args.rim is None and args.disc is None:
        if args.figure is not None:
            raise InputError("--figure draws the flywheel: add --rim [D] or --disc D")
        return None, None
    if not J_F > 0:
        raise InputError(f"J_F = {J_F:.6g} kg·m²: no flywheel is needed, so there is nothing to size")
    mat = None if args.material is None else args.material.replace("-", " ")
    rim = disc = None
    if args.rim is not None:
        m = mat or "cast iron"
        rim = rim_flywheel(J_F, n_rpm=n_rpm, D=None if args.rim == "" else parse_number(args.rim, name="--rim"),
                           rho=DENSITY[m], H_over_B=parse_number(args.H_over_B, name="--H-over-B"),
                           speed_limit=RIM_SPEED_LIMIT[m])
        out["rim"] = {"material": m, "D": rim.D, "D1": rim.D1, "D2": rim.D2, "H": rim.H, "B": rim.B, "m": rim.m,
                      "J_rim": rim.J_rim, "mD2": rim.flywheel_moment, "QD2_kgf_m2": rim.weight_moment_kgf,
                      "GD2_N_m2": rim.weight_moment_N, "rim_speed": rim.rim_speed,
                      "speed_limit": rim.speed_limit, "speed_ok": rim.speed_ok}
    if args.disc is not None:
        m = mat or "steel"
        disc = disc_flywheel(J_F, D=parse_number(args.disc, name="--disc"), n_rpm=n_rpm, rho=DENSITY[m],
                             speed_limit=RIM_SPEED_LIMIT[m])
        out["disc"] = {"material": m, "D": disc.D, "B": disc.B, "m": disc.m, "mD2": disc.flywheel_moment,
                       "QD2_kgf_m2": disc.weight_moment_kgf, "GD2_N_m2": disc.weight_moment_N,
                       "rim_speed": disc.rim_speed, "speed_limit": disc.speed_limit, "speed_ok": disc.speed_ok}
    return rim, disc


def _figure_bytes(args: argparse.Namespace, rim, disc) -> tuple:
    """The flywheel figure's path and bytes (checked before any file is written), or (None, None)."""
    if args.figure is None:
        return None, None
    path = check_target(args.figure, args.force, option="--figure", fmt=_stdout_format(args, args.figure))
    suffix = path.suffix
    from graphmethods.sheets.flywheel_design import flywheel_design

    if rim is None:              # a disc alone: drawn in the rim's place
        scene = flywheel_design(disc, None, notation=args.lang)
    else:
        scene = flywheel_design(rim, disc, notation=args.lang)
    from graphmethods.render import formats

    return path, formats.to_bytes(scene, suffix)


def _stdout_format(args: argparse.Namespace, text: str) -> str | None:
    """``--format`` for the one figure that goes to standard output (``-``); a file's suffix names its own."""
    return args.format if text == "-" else None


def _delta_table(args: argparse.Namespace) -> int:
    """``--delta-table``: the table of recommended [δ] by machine, as text in --lang or as JSON."""
    from graphmethods.dynamics.permissible_delta import SOURCE, TABLE, table_text

    if args.json:
        print(json_text({"source": SOURCE, "default_end": "strict", "machines": [r.to_dict() for r in TABLE]},
                        indent=1))
    else:
        print(table_text(args.lang))
    return 0


def _hyperbola_bytes(args: argparse.Namespace, delta_W_max: float, omega_m: float, J_e: float, delta: float,
                     machine: str | None) -> tuple:
    """The --hyperbola figure's path and bytes (checked before any file is written), or (None, None)."""
    if args.hyperbola is None:
        return None, None
    path = check_target(args.hyperbola, args.force, option="--hyperbola", fmt=_stdout_format(args, args.hyperbola))
    suffix = path.suffix
    from graphmethods.sheets.flywheel_hyperbola import flywheel_hyperbola

    scene = flywheel_hyperbola(delta_W_max, omega_m=omega_m, J_e=J_e, delta=delta, machine=machine,
                               notation=args.lang)
    from graphmethods.render import formats

    return path, formats.to_bytes(scene, suffix)


def run(args: argparse.Namespace) -> int:
    if args.delta_table:
        return _delta_table(args)
    if args.n is None and args.omega is None:
        raise InputError("give the mean speed: --n (rev/min) or --omega (rad/s)")
    if args.delta is None and args.J is None and args.machine is None:
        raise InputError("give the goal: --delta [δ], --machine NAME (its [δ] from the table) or --J (the δ it gives)")
    if args.format is not None and "-" not in (args.figure, args.hyperbola):
        raise InputError("--format is the format of a figure on standard output: give --figure - or --hyperbola - "
                         "(a file's name ends in its format)")
    machine = _machine(args)
    cycle, mc = _read_cycle(args)
    out, omega_m, J_e = _solve(args, cycle, mc, machine)
    rim, disc = _sizing(args, float(out["J_F"]), float(out["n_rpm"]), out)
    fig_path, fig_data = _figure_bytes(args, rim, disc)
    hyp_path, hyp_data = (_hyperbola_bytes(args, cycle.delta_W_max, omega_m, J_e, float(out["delta"]),
                                           None if machine is None else machine.key)
                          if args.hyperbola is not None else (None, None))
    if (fig_path is not None and hyp_path is not None and fig_path.path is not None and hyp_path.path is not None
            and fig_path.path.resolve() == hyp_path.path.resolve()):
        raise InputError("--figure and --hyperbola name the same file; give two names")
    refuse_two_on_stdout(args.json, fig_path, hyp_path)
    check_finite(out)
    for key, path, data in (("figure", fig_path, fig_data), ("hyperbola", hyp_path, hyp_data)):
        if path is not None and data is not None:
            path.write(data, overwrite=args.force)
            if not path.to_stdout:
                out[key] = str(path)
    if args.json:
        print(json_text(out, indent=1))       # also refuses a result that is not finite, naming it
        return 0
    import contextlib

    with contextlib.redirect_stdout(report_stream(fig_path, hyp_path)):     # a drawing on stdout: report on stderr
        _print_report(args, out, cycle, mc, machine, omega_m=omega_m, J_e=J_e)
    return 0


def _machine(args: argparse.Namespace) -> Any:
    """The machine of ``--machine`` (its [δ] put into ``args.delta``), or None; the goal's options checked."""
    machine = None
    if args.machine is not None:
        from graphmethods.dynamics.permissible_delta import machine_row, permissible_delta

        machine = machine_row(args.machine)
        args.delta = str(permissible_delta(machine.key, args.machine_end))
    elif args.machine_end != "strict":
        raise InputError("--machine-end applies to --machine only")
    if args.hyperbola is not None and args.delta is None:
        raise InputError("--hyperbola marks the chosen [δ] on the curve: give --delta or --machine, not --J")

    return machine


def _read_cycle(args: argparse.Namespace) -> tuple[Any, Any]:
    """The excess-work cycle from --areas, --levels or the moments --M-d/--M-r, and the moment cycle (or None)."""
    from graphmethods.dynamics import excess_work as ew

    tol = ew.CLOSURE_TOL_MEASURED if args.closure_tol is None else parse_number(args.closure_tol, name="--closure-tol")
    mc = None
    if flywheel_moments.given(args) == (args.areas is not None or args.levels is not None):
        raise InputError("give the cycle once: --areas, --levels, or the moments --M-d/--M-r")
    if flywheel_moments.given(args):
        mc = flywheel_moments.cycle(args)
        cycle = mc.excess_work
    elif args.period_deg is not None:
        raise InputError("--period-deg applies to the moments --M-d/--M-r only")
    elif args.areas is not None:
        values = parse_list(args.areas, "--areas")
        scaled = args.mu_M is not None or args.mu_phi is not None or args.mu_phi_deg is not None
        if scaled:
            if args.mu_M is None:
                raise InputError("areas in mm² need both scales: add --mu-M (N·m/mm)")
            cycle = ew.from_areas(
                values, mu_M=parse_number(args.mu_M, name="--mu-M"),
                mu_phi=None if args.mu_phi is None else parse_number(args.mu_phi, name="--mu-phi"),
                mu_phi_deg=None if args.mu_phi_deg is None else parse_number(args.mu_phi_deg, name="--mu-phi-deg"),
                closure_tol=tol,
            )
        else:
            cycle = ew.from_work(values, closure_tol=tol)
    else:
        if args.mu_M or args.mu_phi or args.mu_phi_deg:
            raise InputError("energy levels are in J; scales --mu-M/--mu-phi apply to areas only")
        cycle = ew.from_levels(parse_list(args.levels, "--levels"), closure_tol=tol)
    return cycle, mc


def _solve(args: argparse.Namespace, cycle: Any, mc: Any, machine: Any) -> tuple[dict[str, Any], float, float]:
    """The results as a dict (the cycle's table, ω_m, J_F for [δ] or δ for J, ω at the boundaries, the moment
    cycle's extras), with ω_m (rad/s) and J_e (kg·m²)."""
    from graphmethods.dynamics.flywheel import check_delta, fluctuation, flywheel, level_speeds, mean_speed

    omega_m = mean_speed(
        n_rpm=None if args.n is None else parse_number(args.n, name="--n"),
        omega_m=None if args.omega is None else parse_number(args.omega, name="--omega"),
    )
    J_e = parse_number(args.J_e, name="--J-e")
    if J_e < 0:      # the same rule with --delta and with --J
        raise InputError(f"--J-e = {args.J_e}: the mechanism's own inertia must not be negative (kg·m²)")
    out = cycle.to_dict()
    out.update(omega_m=omega_m, n_rpm=30.0 * omega_m / math.pi, J_e=J_e)
    if args.delta is not None:
        fw = flywheel(cycle.delta_W_max, delta=check_delta(args.delta, "--delta"), omega_m=omega_m, J_e=J_e)
        out.update(delta=fw.delta, J_F=fw.J_F, J_total=fw.J_total, omega_max=fw.omega_max, omega_min=fw.omega_min,
                   flywheel_needed=fw.needed)
        if machine is not None:
            out["machine"] = {"key": machine.key, "name": machine.name(args.lang), "end": args.machine_end,
                              "range": machine.range_text()}
    else:
        J = parse_number(args.J, name="--J")
        if J < J_e:
            raise InputError(f"--J {args.J} kg·m² is the total inertia on the shaft and cannot be less than the "
                             f"mechanism's own --J-e {args.J_e} kg·m²")
        delta = fluctuation(cycle.delta_W_max, J=J, omega_m=omega_m)
        out.update(J=J, delta=delta, J_F=J - J_e)
    J_run = out["J"] if args.delta is None else (fw.J_total if fw.needed else J_e)
    if J_run > 0:        # ω at the boundaries a, b, c, … of the steady cycle (J constant, textbook mean)
        out["omega_at_boundaries"] = [float(w) for w in level_speeds(cycle.E, J=J_run, omega_m=omega_m)]
    if mc is not None:
        J_machine = J if args.delta is None else (fw.J_total if fw.needed else J_e)
        out.update(flywheel_moments.extras(mc, J_machine))
    return out, omega_m, J_e


def _print_report(args: argparse.Namespace, out: dict[str, Any], cycle: Any, mc: Any, machine: Any, *,
                  omega_m: float, J_e: float) -> None:
    """The results as text in ``--lang``: the excess-work table, ω_m, [δ] and J_F (or δ), the flywheel's sizes,
    files written; every number as the figures print it (:mod:`graphmethods.cli.flywheel_report`)."""
    from graphmethods.cli.flywheel_report import report_lines

    check_finite(out)
    print("\n".join(report_lines(out, cycle, lang=args.lang, omega_m=omega_m, J_e=J_e, mc=mc, machine=machine,
                                 machine_end=args.machine_end)))
