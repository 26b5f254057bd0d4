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
    p.add_argument("--report", "--format", dest="format", choices=("text", "markdown", "json"), default="text",
                   help="report style (default text; older name --format still accepted)")
    p.add_argument("-o", "--out", "--overlay", dest="overlay", metavar="FILE",
                   help="write the overlay (.svg, .pdf, .png or .dxf) at the student's page size (older name --overlay "
                        "still accepted)")
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


def run(args) -> int:
    from graphmethods.errors import InputError
    from graphmethods.sheets.check import check

    is_drawing = pathlib.Path(args.answers).suffix.lower() in (".dxf", ".svg")
    if args.overlay:
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
        path = pathlib.Path(args.overlay)
        suffix = path.suffix.lower()
        if is_drawing:                  # the check in red over the student's own drawing
            from graphmethods.sheets.check import cad

            scene = cad.overlay_on_drawing(report, notation=args.lang)
        else:
            scene = report.overlay(notation=args.lang)
        if suffix == ".dxf" and is_drawing and pathlib.Path(args.answers).suffix.lower() == ".dxf":
            from graphmethods.render.files import write_atomic

            write_atomic(path, cad.overlay_dxf(report, notation=args.lang), overwrite=args.force)
        else:
            from graphmethods.render import formats

            if suffix not in formats.FORMATS:
                raise InputError(f"--overlay {path}: give a file ending in .svg, .pdf, .png or .dxf")
            formats.save(scene, path, overwrite=args.force)
    out = report.to_json() if args.format == "json" else (
        report.to_markdown(args.lang) if args.format == "markdown" else report.to_text(args.lang))
    print(out.rstrip("\n"))
    if args.overlay:
        print(f"overlay: {args.overlay} ({report.page.size} {report.page.orientation}, print at 100 %)",
              file=sys.stderr)
    return 0 if report.ok else 1
