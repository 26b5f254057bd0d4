"""``graphmethods check-class DIR``: check a whole class, a folder of answers files and drawings.

    graphmethods check-class answers/ --out class-report
    graphmethods check-class drawings/ --problem press --out class-report --lang ru

Every ``*.toml`` answers file and every ``*.dxf`` / ``*.svg`` drawing in DIR is checked as
``graphmethods check`` would (the student and problem named inside the file or in its name
``STUDENT__PROBLEM.ext``, or ``--problem`` for all). Written into ``--out``, in the language of ``--lang``:
``class.csv`` (UTF-8 with a byte-order mark, comma-separated), ``class-semicolon.csv`` (the same, separated
by ``;`` for the locales whose Excel splits on ``;``: ru, de, fr …), ``class.md`` and ``class.html`` (one
table of students × items with verdicts in words and scores, the HTML self-contained with each student's
report), and per student ``students/<file>.md`` (the report) and
``students/<file>-overlay.svg`` (for a drawing also ``-overlay.dxf``: the check drawn in red over the
student's own drawing). Progress goes to stderr, the summary to stdout.

Exit status: 0 every item of every student is right; 1 some items are wrong (or carried over);
3 some file could not be read or checked (its row says why; the other files are checked);
2 the command itself could not run (no such folder, output files exist without --force).
"""

from __future__ import annotations

import pathlib
import sys


def add_parser(sub) -> None:
    p = sub.add_parser("check-class", help="check a folder of students' answers files and drawings: one class table",
                       description="Check every answers file (*.toml) and drawing (*.dxf, *.svg) in a folder; write "
                       "one table of students × items (CSV, Markdown, HTML) and each student's report and overlay.",
                       epilog="Exit status: 0 all right, 1 some items wrong, 3 some file could not be checked, "
                       "2 the command could not run.")
    p.add_argument("directory", metavar="DIR", help="the folder of the students' files")
    p.add_argument("--problem", default=None, help="the problem for every file (else named inside or in the file name)")
    p.add_argument("-o", "--out", default="class-report",
                   help="folder to write the table and reports (default class-report)")
    p.add_argument("--quiet", action="store_true", help="no progress line on stderr")
    p.add_argument("--lang", choices=("en", "ru", "zh"), default="en",
                   help="language of the table, the reports and the overlays")
    p.add_argument("--no-overlays", action="store_true", help="write no overlays (faster)")
    p.add_argument("--force", action="store_true", help="replace existing output files")
    p.set_defaults(func=run)


def _overlays(sub, lang: str) -> dict:
    """file name -> bytes of the student's overlays (empty when it cannot be drawn)."""
    from graphmethods.errors import GraphmethodsError
    from graphmethods.render import formats

    stem = sub.path.name
    out = {}
    try:
        if sub.path.suffix.lower() in (".dxf", ".svg"):
            from graphmethods.sheets.check import cad

            scene = cad.overlay_on_drawing(sub.report, notation=lang)
            out[f"{stem}-overlay.svg"] = formats.to_bytes(scene, ".svg")
            if sub.path.suffix.lower() == ".dxf":
                out[f"{stem}-overlay.dxf"] = cad.overlay_dxf(sub.report, notation=lang)
        else:
            out[f"{stem}-overlay.svg"] = formats.to_bytes(sub.report.overlay(notation=lang), ".svg")
    except GraphmethodsError as exc:
        print(f"  {sub.path.name}: no overlay ({exc})", file=sys.stderr)
    return out


def run(args) -> int:
    from graphmethods.errors import OutputExistsError
    from graphmethods.render.files import write_set
    from graphmethods.sheets.check.classcheck import check_class, class_files

    files = class_files(args.directory)
    out = pathlib.Path(args.out)
    fixed = [out / "class.csv", out / "class.md", out / "class.html", out / "class-semicolon.csv"]
    if not args.force:
        existing = [str(p) for p in fixed if p.exists()]
        if existing:
            raise OutputExistsError(f"{', '.join(existing)} exist; use --force to overwrite, or another --out")

    from graphmethods.cli._progress import Progress

    line = Progress(quiet=args.quiet, every=0.0)      # into a file: one line per student, with its verdict

    def progress(i, n, s):
        what = s.report.summary() if s.report is not None else f"could not be checked: {s.error}"   # stderr: en
        line(i, n, f"{s.path.name}: {what}")

    report = check_class(files, problem=args.problem, progress=progress)
    line.done()
    lang = args.lang
    blobs = {fixed[0]: report.csv_bytes(lang), fixed[1]: report.to_markdown(lang).encode("utf-8"),
             fixed[2]: report.to_html(lang=lang).encode("utf-8"), fixed[3]: report.csv_bytes(lang, sep=";")}
    for s in report.submissions:
        if s.report is None:
            continue
        blobs[out / "students" / f"{s.path.name}.md"] = s.report.to_markdown(lang).encode("utf-8")
        if not args.no_overlays:
            for name, data in _overlays(s, args.lang).items():
                blobs[out / "students" / name] = data
    if not args.force:
        existing = [str(p) for p in blobs if p.exists()]
        if existing:
            more = f" and {len(existing) - 2} more" if len(existing) > 2 else ""
            raise OutputExistsError(f"{', '.join(existing[:2])}{more} exist; use --force to overwrite, "
                                    f"or another --out")
    names = {str(path.relative_to(out)): data for path, data in blobs.items()}
    # --force replaces the report whole: reports and overlays of students no longer in the folder go
    stale = [str(p.relative_to(out)) for p in sorted((out / "students").glob("*")) if p.is_file()] if args.force else []
    write_set(out, names, overwrite=args.force, stale=stale, what="class report folder")
    print(f"{report.summary()}; wrote {fixed[0]}, {fixed[3].name}, {fixed[1].name}, {fixed[2].name} and "
          f"{len(blobs) - len(fixed)} files in "
          f"{out / 'students'}")
    return report.exit_status()
