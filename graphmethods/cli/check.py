"""``graphmethods check PROBLEM ANSWERS.toml``: check a hand drawing against the exact construction.

    graphmethods check W1 graphmethods/problems/data/answers/w1_mistakes.toml
    graphmethods check press answers.toml --report json
    graphmethods check indicator:7:3 answers.toml -o film.pdf
    graphmethods check press plan.dxf -o checked.dxf     # a drawing made in CAD (.dxf or .svg)

PROBLEM is a built-in id (W1, W2, W3, W4, press, slotted-lever, or a cam: shaper-cam, oscillating-cam), a
worksheet variant id (KIND:SEED:N) or a problem
file (a worksheet's problems/*.json, or a slider-crank case file). The report lists each item with
its expected value at the student's scales, the deviation, the tolerance and the verdict, then the
usual mistakes recognised. Exit status 0 when everything is right, 1 when something is wrong.
"""

from __future__ import annotations

import pathlib
import sys

REPORTS = ("text", "markdown", "json")
FIGURES = ("svg", "pdf", "png", "dxf")


def add_parser(sub) -> None:
    from graphmethods.cli._parser import integer, number

    p = sub.add_parser("check", help="check a student's hand drawing (answers file) and diagnose usual mistakes",
                       description="Compare what a student measured and wrote (a TOML answers file) with the exact "
                       "construction at the student's own scales: verdict per item against drafting tolerances, "
                       "diagnosis of the usual mistakes, and an overlay to print 1:1 on film.",
                       epilog="A blank answers file for each worksheet kind is written by graphmethods worksheet "
                       "(KIND-answers.toml); the keys are described in the README.")
    p.add_argument("problem", metavar="PROBLEM",
                   help="W1, W2, W3, W4, press, slotted-lever, a cam (shaper-cam, oscillating-cam), KIND:SEED:N, or a "
                   "problem file")
    p.add_argument("answers", metavar="ANSWERS.toml", help="the student's answers file, or a drawing made in CAD "
                   "(.dxf, .svg: a velocity or acceleration plan, an energy indicator or energy–mass diagram, a cam "
                   "profile, read and measured)")
    p.add_argument("--report", dest="report", choices=REPORTS, default=None, help="report style (default text)")
    p.add_argument("-o", "--out", "--overlay", dest="overlay", metavar="FILE|-",
                   help="write the overlay (.svg, .pdf, .png or .dxf) at the student's page size; - writes it to "
                        "standard output in --format, and the report to standard error (older name --overlay "
                        "still accepted)")
    p.add_argument("--format", dest="format", choices=(*FIGURES, *REPORTS), default=None,
                   help="file format of the overlay on standard output (-o -); text, markdown or json: the report "
                        "style (older name of --report, still accepted)")
    p.add_argument("--lang", choices=("en", "ru", "zh"), default="en",
                   help="language of the report and notation of the overlay")
    p.add_argument("--force", action="store_true", help="replace an existing overlay file")
    drawing = p.add_argument_group("a drawing (.dxf, .svg): what is not written on it")
    drawing.add_argument("--position", type=integer, default=None, metavar="K",
                         help="the position a velocity plan is drawn for")
    drawing.add_argument("--mu-v", type=number, default=None, help="μ_v of the velocity plan, (m/s)/mm")
    drawing.add_argument("--mu-E", type=number, default=None, help="μ_E of the energy indicator, J/mm")
    drawing.add_argument("--mu-a", type=number, default=None, help="μ_a of the acceleration plan, (m/s²)/mm")
    drawing.add_argument("--mu-l", type=number, default=None, help="μ_l of a cam profile, m/mm")
    drawing.add_argument("--point", action="append", default=[], metavar="LABEL=X,Y",
                         help="a point whose letter is missing, in drawing mm (repeat for several)")
    p.set_defaults(func=run)


def _drawing_report(args):
    """The check of a drawing made in CAD (graphmethods.sheets.check.cad), with the options not written on it."""
    from graphmethods.errors import InputError
    from graphmethods.sheets.check import cad

    points = {}
    for spec in args.point:
        try:
            label, xy = spec.split("=", 1)
            x, y = (float(v) for v in xy.split(","))
        except ValueError:
            raise InputError(f"--point {spec!r}: write LABEL=X,Y (drawing mm), e.g. --point b=120.5,80") from None
        points[label.strip()] = (x, y)
    return cad.check_drawing(args.problem, args.answers, position=args.position, mu_v=args.mu_v, mu_E=args.mu_E,
                             mu_a=args.mu_a, points=points or None)


def _styles(args) -> tuple[str, str | None]:
    """The report style and the overlay's file format from ``--report`` and ``--format`` (which names either:
    a file format, or the report style by its older name)."""
    from graphmethods.errors import InputError

    old = args.format if args.format in REPORTS else None
    if old and args.report and old != args.report:
        raise InputError(f"--report {args.report} and --format {old} name two report styles; give one")
    fmt = args.format if args.format in FIGURES else None
    if fmt and args.overlay not in (None, "-") and pathlib.Path(args.overlay).suffix.lower() != f".{fmt}":
        raise InputError(f"--overlay {args.overlay}: the name ends in {pathlib.Path(args.overlay).suffix}, "
                         f"--format says {fmt}; give one of them")
    if args.overlay == "-" and fmt is None:
        raise InputError("-o - writes the overlay to standard output: say its format with --format svg|pdf|png|dxf")
    return args.report or old or "text", fmt


def _overlay_bytes(report, args, is_drawing: bool, suffix: str) -> bytes | None:
    """The overlay in the format ``suffix`` (the check in red over the student's own drawing for a CAD file;
    the drawing's own DXF rewritten when both are DXF); None for a suffix no renderer writes."""
    from graphmethods.render import formats

    if is_drawing:
        from graphmethods.sheets.check import cad

        if suffix == ".dxf" and pathlib.Path(args.answers).suffix.lower() == ".dxf":
            return cad.overlay_dxf(report, notation=args.lang)
        scene = cad.overlay_on_drawing(report, notation=args.lang)
    else:
        scene = report.overlay(notation=args.lang)
    return formats.to_bytes(scene, suffix) if suffix in formats.FORMATS else None


def run(args) -> int:
    from graphmethods.errors import InputError
    from graphmethods.sheets.check import check

    style, fmt = _styles(args)
    to_stdout = args.overlay == "-"
    is_drawing = pathlib.Path(args.answers).suffix.lower() in (".dxf", ".svg")
    if args.overlay and not to_stdout:
        from graphmethods.render.files import not_an_input

        not_an_input(args.overlay, args.answers, args.problem, what="--overlay")
    from graphmethods.sheets.check import cam
    from graphmethods.sheets.check.report import CheckReport

    report: CheckReport
    if cam.is_cam_problem(args.problem):          # a cam profile: drawn in CAD, or typed into cam-answers.toml
        report = (cam.check_drawing(args.problem, args.answers, mu_l=args.mu_l) if is_drawing
                  else cam.check_cam_answers(args.problem, args.answers))
    else:
        report = _drawing_report(args) if is_drawing else check(args.problem, pathlib.Path(args.answers))
    if args.overlay:
        suffix = f".{fmt}" if to_stdout else pathlib.Path(args.overlay).suffix.lower()
        data = _overlay_bytes(report, args, is_drawing, suffix)
        if data is None:
            raise InputError(f"--overlay {args.overlay}: give a file ending in .svg, .pdf, .png or .dxf")
        if to_stdout:
            sys.stdout.flush()
            sys.stdout.buffer.write(data)
            sys.stdout.buffer.flush()
        else:
            from graphmethods.render.files import write_atomic

            write_atomic(pathlib.Path(args.overlay), data, overwrite=args.force)
    out = report.to_json() if style == "json" else (
        report.to_markdown(args.lang) if style == "markdown" else report.to_text(args.lang))
    print(out.rstrip("\n"), file=sys.stderr if to_stdout else sys.stdout)
    if args.overlay:
        where = "standard output" if to_stdout else args.overlay
        print(f"overlay: {where} ({report.page.size} {report.page.orientation}, print at 100 %)", file=sys.stderr)
    return 0 if report.ok else 1
