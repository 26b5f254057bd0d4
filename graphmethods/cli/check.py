"""``graphmethods check PROBLEM ANSWERS.toml``: check a hand drawing against the exact construction.

    graphmethods check W1 graphmethods/problems/data/answers/w1_mistakes.toml
    graphmethods check press answers.toml --format json
    graphmethods check indicator:7:3 answers.toml --overlay film.pdf

PROBLEM is a built-in id (W1, W2, W3, W4, press), a worksheet variant id (KIND:SEED:N) or a problem
file (a worksheet's problems/*.json, or a slider-crank case file). The report lists each item with
its expected value at the student's scales, the deviation, the tolerance and the verdict, then the
usual mistakes recognised. Exit status 0 when everything is right, 1 when something is wrong.
"""

from __future__ import annotations

import pathlib
import sys


def add_parser(sub) -> None:
    p = sub.add_parser("check", help="check a student's hand drawing (answers file) and diagnose usual mistakes",
                       description="Compare what a student measured and wrote (a TOML answers file) with the exact "
                       "construction at the student's own scales: verdict per item against drafting tolerances, "
                       "diagnosis of the usual mistakes, and an overlay to print 1:1 on film.",
                       epilog="A blank answers file for each worksheet kind is written by graphmethods worksheet "
                       "(KIND-answers.toml); the keys are described in the README.")
    p.add_argument("problem", metavar="PROBLEM", help="W1, W2, W3, W4, press, KIND:SEED:N, or a problem file")
    p.add_argument("answers", metavar="ANSWERS.toml", help="the student's answers file")
    p.add_argument("--format", choices=("text", "markdown", "json"), default="text", help="report format")
    p.add_argument("--overlay", metavar="FILE", help="write the overlay (.svg, .pdf or .png) at the student's page size")
    p.add_argument("--lang", choices=("en", "ru", "zh"), default="en",
                   help="notation and language of the overlay (the report stays English)")
    p.add_argument("--force", action="store_true", help="replace an existing overlay file")
    p.set_defaults(func=run)


def run(args) -> int:
    from graphmethods.errors import InputError
    from graphmethods.sheets.check import check

    report = check(args.problem, pathlib.Path(args.answers))
    if args.overlay:
        path = pathlib.Path(args.overlay)
        scene = report.overlay(notation=args.lang)
        suffix = path.suffix.lower()
        if suffix == ".svg":
            from graphmethods.render import svg

            svg.save(scene, path, overwrite=args.force)
        elif suffix == ".pdf":
            from graphmethods.render import pdf

            pdf.save(scene, path, overwrite=args.force)
        elif suffix == ".png":
            from graphmethods.render import mpl

            mpl.save_png(scene, path, overwrite=args.force)
        else:
            raise InputError(f"--overlay {path}: give a file ending in .svg, .pdf or .png")
    out = {"text": report.to_text, "markdown": report.to_markdown, "json": report.to_json}[args.format]()
    print(out.rstrip("\n"))
    if args.overlay:
        print(f"overlay: {args.overlay} ({report.page.size} {report.page.orientation}, print at 100 %)",
              file=sys.stderr)
    return 0 if report.ok else 1
