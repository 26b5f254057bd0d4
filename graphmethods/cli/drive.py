"""``graphmethods drive``: a drive of several masses reduced to one shaft (two-, three-, n-mass models).

    graphmethods drive --J 0.08,0.5,12 --u 6,2,1 --c 2000,40000 --c-u 6,1 --M 30,0,-160
    graphmethods drive ... --json --figure drive.svg --lang ru

Each mass J_i (kg·m²) turns at u_i·ω, each elastic shaft between two masses has the stiffness c_j
(N·m/rad) and turns at its own u_j·ω; the reduced chain has J_i' = J_i u_i², c_j' = c_j u_j²,
M_i' = M_i u_i, and its natural frequencies. An existing figure file is kept unless --force.
"""

from __future__ import annotations

import argparse

from graphmethods.cli._sheet import check_target, refuse_two_on_stdout, report_stream
from graphmethods.cli.flywheel import parse_list
from graphmethods.errors import InputError
from graphmethods.units import check_text, json_text


def add_parser(sub) -> None:
    from graphmethods.cli._parser import DRAWING_TARGET, add_figure_options, add_output

    p = sub.add_parser("drive", help="a drive of several masses reduced to one shaft: J', c', natural frequencies",
                       description="Reduce a chain of masses and elastic shafts (a motor, gears, the machine) to one "
                                   "shaft by the squares of the speed ratios, and find its natural frequencies.",
                       epilog="Example: graphmethods drive --J 0.08,0.5,12 --u 6,2,1 --c 2000,40000 --c-u 6,1")
    p.add_argument("--J", required=True, metavar="J1,J2,...", help="the masses' inertias in order, kg·m²")
    p.add_argument("--u", default=None, metavar="U1,U2,...",
                   help="their speed ratios ω_i/ω to the shaft reduced to (default all 1)")
    p.add_argument("--c", required=True, metavar="C1,...", help="the stiffnesses of the shafts between them, N·m/rad")
    p.add_argument("--c-u", default=None, metavar="U1,...", help="the shafts' speed ratios (default all 1)")
    p.add_argument("--M", default=None, metavar="M1,M2,...", help="moments on the masses, N·m (+ driving)")
    p.add_argument("--names", default=None, metavar="NAME1,NAME2,...", help="names of the masses")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    add_output(p, "--figure", dest="figure", metavar=DRAWING_TARGET,
               help="also draw the reduced scheme; - writes it to standard output in --format, and nothing else")
    add_figure_options(p, "figure")
    p.set_defaults(func=run)


def _list(text: str | None, name: str, n: int, default: float) -> list[float]:
    if text is None:
        return [default] * n
    values = parse_list(text, name)
    if len(values) != n:
        raise InputError(f"{name}: give {n} values, one per {'mass' if name in ('--u', '--M') else 'shaft'}; "
                         f"got {len(values)}")
    return values


def run(args: argparse.Namespace) -> int:
    from graphmethods.dynamics.multimass import Mass, Shaft, reduce_chain

    J = parse_list(args.J, "--J")
    n = len(J)
    u = _list(args.u, "--u", n, 1.0)
    M = _list(args.M, "--M", n, 0.0)
    c = parse_list(args.c, "--c")
    cu = _list(args.c_u, "--c-u", len(c), 1.0)
    names = [check_text(s.strip(), "--names") for s in args.names.split(",")] if args.names else \
        [str(i + 1) for i in range(n)]
    if len(names) != n:
        raise InputError(f"--names: give {n} names, one per mass; got {len(names)}")
    chain = reduce_chain([Mass(nm, j, ui, mi) for nm, j, ui, mi in zip(names, J, u, M)],
                         [Shaft(f"{i + 1}", ci, ui) for i, (ci, ui) in enumerate(zip(c, cu))])
    path = None if args.figure is None else check_target(args.figure, args.force, option="-o/--figure",
                                                         fmt=args.format)
    if path is None and args.format is not None:
        raise InputError("--format is the figure's file format; add -o FILE (or -o - for standard output)")
    refuse_two_on_stdout(args.json, path)
    blob = None
    if path is not None:
        from graphmethods.render import formats
        from graphmethods.sheets.drive_scheme import drive_scheme

        blob = formats.to_bytes(drive_scheme(chain, notation=args.lang), path.suffix)
    out = chain.to_dict()
    if path is not None and blob is not None:
        path.write(blob, overwrite=args.force)
        if not path.to_stdout:
            out["figure"] = str(path)
    stream = report_stream(path)
    if args.json:
        print(json_text(out, indent=1), file=stream)
        return 0
    print("\n".join(report_lines(chain, args.lang, None if path is None or path.to_stdout else str(path))), file=stream)
    return 0


def report_lines(chain, lang: str, figure: str | None = None) -> list[str]:
    """The reduced chain as text in ``lang``: the figure's symbols (J', c', J_п in Russian), units and digits
    (J and c to 5 significant digits, u and the frequencies to 4, as its table and notes print them).

    >>> from graphmethods.dynamics.multimass import Mass, Shaft, reduce_chain
    >>> d = reduce_chain([Mass("1", 0.08, 6.0, 30.0), Mass("2", 12.0)], [Shaft("1", 2000.0, 6.0)])
    >>> print("\\n".join(report_lines(d, "ru")[:2]))
    массы                          1; 2
    J', кг·м²                      2,88; 12
    """
    import math

    from graphmethods.scene import markup
    from graphmethods.scene.notation import get

    nt = get(lang)
    sep = nt.list_separator

    def nums(values, sig: int) -> str:
        return sep.join(nt.number(float(v), sig=sig) for v in values)

    sym = markup.typed
    rows = [(nt.word("drive.masses"), sep.join(chain.names)),
            (nt.quantity("J'", "kg·m²"), nums(chain.J, 5)),
            (nt.word("drive.shafts"), sep.join(chain.shaft_names)),
            (nt.quantity("c'", "N·m/rad"), nums(chain.c, 5)),
            (nt.quantity("M'", "N·m"), nums(chain.M, 5)),
            (nt.quantity(sym(nt.sym("dynamics.J_e")) + " = ΣJ'", "kg·m²"), nt.number(chain.J_e, sig=5)),
            (nt.quantity(sym(nt.sym("dynamics.M_e")) + " = ΣM'", "N·m"), nt.number(chain.M_e, sig=5)),
            (nt.quantity(f"{nt.word('drive.freq')} ω", "rad/s"), nums(chain.natural_frequencies, 4)),
            (nt.quantity(f"{nt.word('drive.freq')} f", "Hz"),
             nums([w / (2 * math.pi) for w in chain.natural_frequencies], 4))]
    width = max(30, max(len(k) for k, _ in rows))
    lines = [f"{k.ljust(width)} {v}" for k, v in rows]
    if figure is not None:
        lines.append(nt.word("flywheel.report_wrote", f=figure))
    return lines
