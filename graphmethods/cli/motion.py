"""``graphmethods motion CASE``: the machine's motion from given initial conditions.

Start-up from rest, steady running, run-down after the drive is switched off or a brake applied:
φ(t), ω(t), ε(t) by :func:`graphmethods.dynamics.regimes.run`, with a summary (the time to reach the
steady state, ω_m, δ and the three mean speeds) once steady.

    graphmethods motion press --motor induction:P=5500,n=1440,n_sync=1500,lam=2.2 --until-steady --json
    graphmethods motion W4 --turns 1 --json
    graphmethods motion W3 --omega0 10.47 --drive-off-at 0 --brake 20 --t-end 60
"""

from __future__ import annotations

import argparse
import json
import math
import re

from graphmethods.cli._argv import join_option_values
from graphmethods.errors import InputError
from graphmethods.units import parse_number

#: bounds of a run from the command line: a run past them is refused, not left to go on for hours
MAX_TURNS = 10_000
MAX_STEPS = 20_000


def preprocess_argv(argv: list[str]) -> list[str]:
    """``--moment -0.02*omega**2`` -> ``--moment=-0.02*omega**2`` (argparse would take the value for an option)."""
    return join_option_values(argv, ("--moment", "--omega0", "--phi0", "--t0"))


def add_parser(sub) -> None:
    from graphmethods.cli.kinematics import builtin_names

    p = sub.add_parser(
        "motion", help="motion from given initial conditions: start-up, steady running, run-down",
        description="Integrate J_e(φ)dω/dt + ½ω²dJ_e/dφ = M(φ, ω, t) from φ0, ω0, t0 for a built-in problem "
                    "(W3, W4, W4-exact, " + builtin_names() + ") or a linkage problem file, and print "
                    "t, φ, ω, ε (SI) and a summary.",
        epilog="Example: graphmethods motion press --motor induction:P=5500,n=1440,n_sync=1500,lam=2.2 --until-steady")
    p.add_argument("case", metavar="CASE", help="a built-in problem (W3, W4, W4-exact, " + builtin_names() + ") or a "
                   "linkage problem file (JSON; - reads it from standard input)")
    p.add_argument("--phi0", default=None, metavar="DEG", help="initial crank angle, degrees (default: position 0)")
    p.add_argument("--omega0", default=None, metavar="RAD_S",
                   help="initial speed, rad/s (default: the problem's own ω0, else 0: start from rest)")
    p.add_argument("--t0", default="0", metavar="S", help="initial time, s (default 0)")
    end = p.add_mutually_exclusive_group(required=True)
    end.add_argument("--turns", default=None, metavar="N", help="run N crank turns")
    end.add_argument("--t-end", default=None, metavar="S", help="run until this time, s")
    end.add_argument("--until-steady", action="store_true", help="run until the motion is steady (periodic)")
    p.add_argument("--tol", default="1e-3", help="with --until-steady: the band around the steady ω, relative "
                                                 "to ω_m, that counts as steady (default 1e-3)")
    p.add_argument("--motor", default=None, metavar="SPEC",
                   help="drive by a motor instead of the problem's constant M_d: "
                        "induction:P=W,n=RPM,lam=L,n_sync=RPM|s_nom=S[,ratio=U][,J_rotor=KG_M2] (Kloss) or "
                        "dc:M0=N_M,omega0=RAD_S[,ratio=U][,J_rotor=KG_M2]; the ratio u = ω_motor/ω defaults to "
                        "the motor's rated speed over the problem's mean speed")
    p.add_argument("--drive-off-at", default=None, metavar="S", help="switch the drive off at this time, s")
    p.add_argument("--brake", default=None, metavar="M_B[,C]",
                   help="a brake moment M_B + C·ω (N·m) against the motion")
    p.add_argument("--brake-at", default=None, metavar="S", help="apply the brake at this time, s (default t0)")
    p.add_argument("--moment", default=None, metavar="FORMULA",
                   help="a further moment in phi (rad), omega (rad/s) and t (s), N·m, e.g. \"-0.5*omega\"")
    p.add_argument("--J-F", default=None, metavar="KG_M2",
                   help="flywheel inertia on the crank, kg·m² (default: the problem's J_F for its [δ], else 0)")
    p.add_argument("--rtol", default="1e-10", help="relative tolerance of the integrator (default 1e-10)")
    p.add_argument("--json", action="store_true", help="print one JSON object: arrays t, phi, omega, epsilon "
                                                       "and the summary")
    p.add_argument("-o", "--out", "--figures", dest="figures", default=None, metavar="DIR",
                   help="also draw ω(t), ω(φ) and ε(φ) into DIR (created if missing), scale-true (older name "
                        "--figures still accepted)")
    p.add_argument("--lang", choices=("en", "ru", "zh"), default="en", help="notation of the figures (default en)")
    p.add_argument("--format", choices=("svg", "pdf", "png", "dxf"), default="svg", dest="fig_format",
                   help="file format of the figures (default svg)")
    p.add_argument("--force", action="store_true", help="overwrite existing figure files")
    p.set_defaults(func=run)


def parse_motor(spec: str, *, omega_m: float | None):
    """(motor, J_rotor·u²) from ``induction:...`` or ``dc:...``."""
    from graphmethods.dynamics.motor import DCMotor, InductionMotor

    motor: InductionMotor | DCMotor
    kind, _, rest = spec.partition(":")
    kind = kind.strip().lower()
    fields = {}
    for part in [x for x in re.split(r"[,;]", rest) if x.strip()]:
        key, eq, value = part.partition("=")
        if not eq:
            raise InputError(f"--motor {spec!r}: {part!r} is not KEY=VALUE")
        fields[key.strip()] = parse_number(value, name=f"--motor {key.strip()}")
    J_rotor = fields.pop("J_rotor", 0.0)
    try:
        if kind == "induction":
            need = {"P", "n", "lam"}
            if not need <= set(fields):
                raise InputError(f"--motor induction: give P (W), n (rev/min), lam and n_sync or s_nom; "
                                 f"missing {', '.join(sorted(need - set(fields)))}")
            unknown = set(fields) - {"P", "n", "lam", "n_sync", "s_nom", "ratio"}
            if unknown:
                raise InputError(f"--motor induction: unknown key(s) {', '.join(sorted(unknown))}")
            ratio = fields.get("ratio") or (math.pi * fields["n"] / 30.0 / omega_m if omega_m else 1.0)
            motor = InductionMotor(P_nom=fields["P"], n_nom=fields["n"], lam=fields["lam"], n_sync=fields.get("n_sync"),
                                   s_nom=fields.get("s_nom"), ratio=ratio)
        elif kind == "dc":
            if not {"M0", "omega0"} <= set(fields):
                raise InputError("--motor dc: give M0 (stall torque, N·m) and omega0 (no-load speed, rad/s)")
            unknown = set(fields) - {"M0", "omega0", "ratio"}
            if unknown:
                raise InputError(f"--motor dc: unknown key(s) {', '.join(sorted(unknown))}")
            motor = DCMotor(M_0=fields["M0"], omega_0=fields["omega0"], ratio=fields.get("ratio", 1.0))
        else:
            raise InputError(f"--motor {spec!r}: the kind is induction:... or dc:...")
    except InputError as exc:
        msg = str(exc)
        raise InputError(msg if msg.startswith("--motor") else f"--motor: {msg}") from None
    return motor, J_rotor * motor.ratio**2


def _opt(value, name):
    return None if value is None else parse_number(value, name=name)


def run(args: argparse.Namespace) -> int:
    from graphmethods.dynamics.formula import Formula
    from graphmethods.dynamics.regimes import Brake, ConstantDrive, run as integrate
    from graphmethods.problems.machine import machine

    t0 = parse_number(args.t0, name="--t0")
    turns, t_end = _opt(args.turns, "--turns"), _opt(args.t_end, "--t-end")
    tol, rtol = parse_number(args.tol, name="--tol"), parse_number(args.rtol, name="--rtol")
    if not 0 < tol < 1:
        raise InputError(f"--tol {args.tol}: give a fraction between 0 and 1, e.g. 1e-3")
    if not 1e-14 <= rtol <= 1e-3:
        raise InputError(f"--rtol {args.rtol}: give a value between 1e-14 and 1e-3")
    if turns is not None and not 0 < turns <= MAX_TURNS:
        raise InputError(f"--turns {args.turns}: give a positive number of turns, at most {MAX_TURNS} "
                         f"(checked before any work)")
    if t_end is not None and not t_end > t0:
        raise InputError(f"--t-end {args.t_end}: it must come after --t0 {t0:g} s")
    extra = None
    if args.moment is not None:
        f = Formula(args.moment, variables=("phi", "omega", "t"))

        def extra(phi, omega, t):
            return f(phi=phi, omega=omega, t=t)
    brake = None
    if args.brake is not None:
        parts = [x for x in re.split(r"[,;\s]+", args.brake.strip()) if x]
        if not 1 <= len(parts) <= 2:
            raise InputError(f"--brake {args.brake!r}: give M_B or M_B,C (N·m and N·m·s)")
        vals = [parse_number(x, name="--brake") for x in parts]
        brake = Brake(M_b=vals[0], c=vals[1] if len(vals) > 1 else 0.0,
                      t_on=_opt(args.brake_at, "--brake-at") if args.brake_at is not None else -math.inf)
    elif args.brake_at is not None:
        raise InputError("--brake-at needs --brake M_B")

    J_F_given = _opt(args.J_F, "--J-F")
    if J_F_given is not None and J_F_given < 0:
        raise InputError(f"--J-F {args.J_F}: a flywheel's inertia is 0 or positive, kg·m²")
    m = machine(args.case, J_F=J_F_given)
    J_F = m.J_F
    extra_J = 0.0
    if args.motor is not None:
        drive, extra_J = parse_motor(args.motor, omega_m=m.omega_m)
        model = m.model
    elif m.M_d is not None:
        drive = ConstantDrive(m.M_d)
        model = m.model
    else:
        drive, model = None, m.model
        if args.drive_off_at is not None:
            raise InputError(f"{m.name}: its driving moment is a curve of φ, part of the model; give --motor "
                             f"to have a drive to switch off")
    omega_0 = _opt(args.omega0, "--omega0")
    if omega_0 is None:
        omega_0 = m.omega_0 if m.omega_0 is not None else 0.0
    phi_0 = None if args.phi0 is None else math.radians(parse_number(args.phi0, name="--phi0"))
    speed_dependent = args.motor is not None or (brake is not None and brake.c != 0) or (
        args.moment is not None and "omega" in args.moment.replace("ω", "omega"))
    if args.until_steady and not speed_dependent and omega_0 == 0:
        raise InputError("--until-steady from rest needs a drive whose moment depends on the speed (--motor "
                         "induction:... or dc:...): with the problem's own constant M_d every period gives back the "
                         "energy it started with, so a machine started from rest never settles to a steady speed; "
                         "give --motor, or a starting speed --omega0 (then the motion repeats from there)")
    res = integrate(model, J_F=J_F + extra_J, drive=drive, drive_off_at=_opt(args.drive_off_at, "--drive-off-at"),
                    brake=brake, extra=extra, phi_0=phi_0, omega_0=omega_0, t_0=t0, t_end=t_end, turns=turns,
                    until_steady=args.until_steady, tol=tol, rtol=rtol, omega_ref=m.omega_m, max_steps=MAX_STEPS)
    if args.until_steady and res.ended_by == "stopped":
        raise InputError(f"--until-steady: the machine stopped at t = {res.t[-1]:.6g} s (φ = "
                         f"{math.degrees(res.phi[-1]):.6g}°) before a steady state: a steady state needs the drive to "
                         f"carry the machine through each period's resistance; give a motor (--motor), a larger "
                         f"--omega0 or more flywheel (--J-F)")
    summary = {"case": m.name, "J_F": J_F, "J_rotor_reduced": extra_J,
               "drive": ("motor " + args.motor) if args.motor else
                        (f"constant M_d = {m.M_d:.9g} N·m" if m.M_d is not None else "M_d(φ) of the problem"),
               "phi0_deg": math.degrees(res.phi[0]), "omega0": float(res.omega[0]), "t0": t0}
    if args.motor is not None:
        summary["motor_ratio"] = drive.ratio
    summary.update(res.summary())
    if args.figures is not None:
        summary["figures"] = [str(f) for f in _write_figures(res, args, problem=m.name, cycle=m.problem,
                                                             case=None if m.problem is not None else args.case,
                                                             title=_title(m, args))]
    if args.json:
        out = {"t": res.t.tolist(), "phi": res.phi.tolist(), "omega": res.omega.tolist(),
               "epsilon": res.epsilon.tolist(), "summary": summary}
        print(json.dumps(out))
        return 0
    print("\n".join(report_lines(summary, args.lang, motor=args.motor, M_d=m.M_d)))
    return 0


def _label(key: str, nt) -> tuple[str, int]:
    """A summary key as the text names it in ``nt``'s language, and the significant digits of its value:
    ``omega_max_run`` -> "ω_max_run, рад/с" (6 digits, ω's rule), ``error_estimate_omega`` -> words (3)."""
    from graphmethods.scene import markup

    words = {"steps": "motion.steps", "periods": "motion.periods", "motor_ratio": "motion.motor_ratio",
             "energy_residual": "motion.energy_residual"}
    if key in words:
        return nt.word(words[key]), 6
    errors = {"error_estimate_omega": "motion.error_omega", "error_extremes_omega": "motion.error_extremes",
              "omega_remaining": "motion.error_remaining"}
    if key in errors:
        return nt.quantity(nt.word(errors[key]), "rad/s"), 3
    if key == "J_F":
        return nt.quantity(markup.typed(nt.sym("dynamics.J_F")), "kg·m²"), 4
    if key == "J_rotor_reduced":
        return nt.quantity("J_rotor·u²", "kg·m²"), 4
    from graphmethods.cli._report import label

    return label(key.replace("omega0", "omega_0").replace("phi0", "phi_0").replace("t0", "t_0"), nt), 6


def report_lines(summary: dict, lang: str, *, motor: str | None = None, M_d: float | None = None) -> list[str]:
    """The summary of a run as text in ``lang``: each value named by its symbol and unit in that language,
    written with its decimal sign (the JSON keys are the English identifiers the README lists).

    >>> print("\\n".join(report_lines({"case": "W4", "omega_max_run": 11.80126716, "ended_by": "turns"}, "ru")))
    задача                          W4
    ω_max_run, рад/с                11,8013
    окончание                       заданное число оборотов
    """
    from graphmethods.scene import markup
    from graphmethods.scene.notation import get

    nt = get(lang)
    steady = summary.get("steady")
    rows: list[tuple[str, str]] = []
    Md = markup.typed(nt.sym("M_d"))
    for key, value in summary.items():
        if key == "steady":
            continue
        if key == "case":
            rows.append((nt.word("check.col_problem"), str(value)))
        elif key == "drive":
            text = (nt.word("motion.drive_motor", spec=motor) if motor else
                    nt.word("motion.drive_constant", Md=Md, M=nt.number(M_d, sig=6), u=nt.unit("N·m"))
                    if M_d is not None else nt.word("motion.drive_curve", Md=Md))
            rows.append((nt.word("motion.drive"), text))
        elif key == "ended_by":
            rows.append((nt.word("motion.ended_by"), nt.word(f"motion.ended_{value}")
                         if f"motion.ended_{value}" in nt.words else str(value)))
        else:
            label, sig = _label(key, nt)
            rows.append((label, nt.number(float(value), sig=sig) if isinstance(value, (int, float)) else str(value)))
    width = max(30, max(len(k) for k, _ in rows))
    lines = [f"{k.ljust(width)}  {v}" for k, v in rows]
    if isinstance(steady, dict):
        lines.append(nt.word("motion.steady"))
        for key, value in steady.items():
            label, sig = _label(key, nt)
            shown = nt.number(float(value), sig=sig) if isinstance(value, (int, float)) else str(value)
            lines.append(f"  {label.ljust(width)}{shown}")
    return lines


def _title(m, args) -> str:
    """The problem's name on the figures' title block, in ``--lang`` (the press's "дезаксиальный
    кривошипно-ползунный пресс", not "press"); a cycle problem or a file without a title keeps its name."""
    if m.problem is not None:
        return m.name
    try:
        from graphmethods.problems.builtin import case
        from graphmethods.problems.reference_cases import title_of

        return title_of(case(args.case)).title_in(args.lang) or m.name
    except InputError:                    # a name is only a caption: the problem's own name then
        return m.name


def _write_figures(res, args, *, problem: str, cycle=None, case=None, title: str | None = None) -> list:
    """Build the figures (ω(t), ω(φ), ε(φ); and for a cycle problem or a linkage ``case`` with n and [δ]
    the three-panel figure of its steady cycle), then write them (an existing file is kept unless --force)."""
    import pathlib

    from graphmethods.errors import OutputExistsError
    from graphmethods.render import formats
    from graphmethods.render.files import write_set
    from graphmethods.sheets.motion import motion_figures

    out = pathlib.Path(args.figures)
    if out.exists() and not out.is_dir():
        raise InputError(f"--figures {out}: it is a file; give a directory")
    scenes = motion_figures(res, notation=args.lang, problem=title or problem)
    if cycle is not None:                 # a cycle problem: also M_d/M_r, ΔE and ω on one φ axis
        from graphmethods.sheets.cycle_panels import cycle_panels

        scenes["panels"] = cycle_panels(cycle, notation=args.lang)
    elif case is not None:                # a linkage: the same figure of its steady cycle with the exact J_F
        from graphmethods.dynamics.study import Study
        from graphmethods.errors import NoFlywheelNeeded
        from graphmethods.problems.builtin import case as read_builtin
        from graphmethods.sheets.cycle_panels import linkage_panels

        try:
            scenes["panels"] = linkage_panels(Study(read_builtin(case)), notation=args.lang)
        except NoFlywheelNeeded:          # no flywheel for [δ]: the other figures still tell the motion
            pass
    paths = {out / f"{problem}_{key}.{args.fig_format}": scene for key, scene in scenes.items()}
    if not args.force:
        for path in paths:
            if path.exists():
                raise OutputExistsError(f"{path} exists; use --force to overwrite it")
    blobs = {path.name: formats.to_bytes(scene, path.suffix) for path, scene in paths.items()}
    return write_set(out, blobs, overwrite=args.force, what="figures folder")
