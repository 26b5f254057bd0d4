"""The moment-curve input of ``graphmethods flywheel``: ``--M-d``, ``--M-r``, ``--period-deg``.

Each moment is a number (N·m), a formula in ``phi`` (rad) or a CSV file of ``phi_deg,M`` points
(see :mod:`graphmethods.dynamics.moment_cycle`); a missing one balances the work over the period.
With ``--json`` the output adds ``phi_E_max_deg``, ``phi_E_min_deg`` (lists: every angle of a tie)
and, for the machine with a constant inertia (``--J``, or the total inertia once J_F is found),
``epsilon_max``, ``epsilon_min`` (rad/s²) and their angles ``phi_epsilon_max_deg``,
``phi_epsilon_min_deg`` (lists as well).

    graphmethods flywheel --M-r "20000 + 9500*sin(2*phi) - 5700*cos(2*phi)" --n 120 --delta 0.05 --json
"""

from __future__ import annotations

from graphmethods.cli._argv import join_option_values

MOMENT_OPTIONS = ("--M-d", "--M-r")


def add_arguments(p) -> None:
    """The three options, on the flywheel command's parser."""
    p.add_argument("--M-d", dest="M_d", default=None, metavar="M",
                   help="driving moment: a number (N·m), a formula in phi (rad) such as "
                        "\"20000 + 9500*sin(2*phi)\", or a CSV file of phi_deg,M points; "
                        "missing: the balancing constant")
    p.add_argument("--M-r", dest="M_r", default=None, metavar="M",
                   help="resisting moment, in the same forms as --M-d; missing: the balancing constant")
    p.add_argument("--period-deg", default=None, metavar="P",
                   help="period of the moment curves, degrees (default 360; 720 for a four-stroke engine), or "
                        "auto: the common period of the formulas")


def join_values(argv: list[str]) -> list[str]:
    """``--M-r -20*sin(phi)`` -> ``--M-r=-20*sin(phi)`` (argparse would take the value for an option)."""
    return join_option_values(argv, MOMENT_OPTIONS)


def given(args) -> bool:
    """Whether the cycle is given as moment curves."""
    return args.M_d is not None or args.M_r is not None


def cycle(args):
    """The :class:`~graphmethods.dynamics.moment_cycle.MomentCycle` of the options."""
    from graphmethods.dynamics.moment_cycle import moment_cycle
    from graphmethods.errors import InputError

    if args.mu_M or args.mu_phi or args.mu_phi_deg:
        raise InputError("moment curves are in N·m over φ in rad; the scales --mu-M/--mu-phi apply to areas only")
    return moment_cycle(args.M_d, args.M_r, period_deg="360" if args.period_deg is None else args.period_deg)


def extras(mc, J: float | None) -> dict:
    """The JSON keys the moment input adds: energy extremes, and ε for the inertia J (if known)."""
    out = mc.to_dict()
    if J is not None and J > 0:
        out.update(mc.epsilon(J=J).to_dict())
    return out


def text_lines(out: dict) -> list[str]:
    """The same, as lines of the text output."""
    lines = [f"M_d: {out['M_d_given']}, mean {out['M_d_mean']:.6g} N·m; M_r: {out['M_r_given']}, mean "
             f"{out['M_r_mean']:.6g} N·m; period {out['period_deg']:.6g}°",
             "energy highest at φ = " + ", ".join(f"{a:.4f}°" for a in out["phi_E_max_deg"])
             + "; lowest at φ = " + ", ".join(f"{a:.4f}°" for a in out["phi_E_min_deg"])]
    if "epsilon_max" in out:
        lines.append(f"with J = {out['J_epsilon']:.6g} kg·m²: ε_max = {out['epsilon_max']:.6g} rad/s² at φ = "
                     + ", ".join(f"{a:.4f}°" for a in out["phi_epsilon_max_deg"])
                     + f"; ε_min = {out['epsilon_min']:.6g} rad/s² at φ = "
                     + ", ".join(f"{a:.4f}°" for a in out["phi_epsilon_min_deg"]))
    return lines
