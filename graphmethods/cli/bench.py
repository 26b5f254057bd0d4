"""``graphmethods bench``: speed against error, as a Markdown table and JSON."""

from __future__ import annotations

import pathlib

from graphmethods.errors import InputError, OutputExistsError


def add_parser(sub) -> None:
    p = sub.add_parser("bench", help="measure speed against error (Markdown table and JSON)",
                       description="Measure each method's time (median of repeats) and error against the exact "
                       "solution, in one run. --quick finishes in well under a minute.")
    p.add_argument("--quick", action="store_true", help="small sizes, for CI")
    p.add_argument("--only", action="append", metavar="SECTION", help="run only this section (repeatable)")
    p.add_argument("--quiet", action="store_true", help="no progress line on stderr")
    p.add_argument("-o", "--out", metavar="DIR", help="also write bench.md, bench.json and the error-against-time plot "
                   "(error_vs_time.svg, when the flywheel section runs) into DIR")
    p.add_argument("--force", action="store_true", help="overwrite existing files in --out")
    p.set_defaults(func=run)


def run(args) -> int:
    from graphmethods import bench

    if args.only:
        unknown = sorted(set(args.only) - set(bench.SECTIONS))
        if unknown:
            raise InputError(f"unknown section {', '.join(unknown)}; choose from {', '.join(bench.SECTIONS)}")
    if args.out is not None and args.out.strip() == "":
        raise InputError("--out is empty; give a folder (it is created if missing)")
    out = pathlib.Path(args.out) if args.out else None
    if out is not None:                  # checked before the run, not after it
        if out.exists() and not out.is_dir():
            raise InputError(f"--out {out} is a file; give a folder (it is created if missing)")
        targets = [out / "bench.md", out / "bench.json", out / "error_vs_time.svg"]
        in_way = [str(t) for t in targets if t.is_dir()]
        if in_way:
            raise InputError(f"cannot write {in_way[0]}: a folder is in the way")
        existing = [str(t) for t in targets if t.exists()]
        if existing and not args.force:
            raise OutputExistsError(f"{', '.join(existing)} exist; add --force to overwrite")
    from graphmethods.cli._progress import Progress

    line, done = Progress(quiet=args.quiet, label="bench "), [0]

    def progress(name: str) -> None:
        done[0] += 1
        line(done[0], len(args.only or bench.SECTIONS), name)

    rows = bench.run_all(quick=args.quick, sections=args.only, progress=progress)
    line.done()
    md = bench.to_markdown(rows)
    print(md)
    if out is not None:
        import tempfile

        from graphmethods.render.files import write_set
        from graphmethods.units import json_text

        files = {"bench.md": md.encode("utf-8"), "bench.json": json_text(bench.to_json(rows), indent=1).encode("utf-8")}
        if any(r.section == "flywheel" for r in rows):
            with tempfile.TemporaryDirectory() as tmp:
                plot = pathlib.Path(tmp) / "error_vs_time.svg"
                bench.plot_error_vs_time(rows, plot)
                files["error_vs_time.svg"] = plot.read_bytes()
        write_set(out, files, overwrite=args.force, what="--out folder")
    return 0
