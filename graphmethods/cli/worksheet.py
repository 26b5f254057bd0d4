"""``graphmethods worksheet KIND``: printable worksheets with answer keys for a class.

    graphmethods worksheet indicator --variants 30 --seed 7 --lang ru --out class-7

writes ``class-7/indicator-ru.pdf`` (the students' pages, then the keys), an SVG per page in
``class-7/svg/``, a problem file per variant in ``class-7/problems/`` (``graphmethods check``
reads them, or the variant's id ``indicator:7:N``) and the blank answers file
``class-7/indicator-answers.toml``. Existing files are kept unless ``--force``;
nothing is left behind on an error. Progress goes to stderr (``--quiet`` turns it off).
"""

from __future__ import annotations

import os
import pathlib
import re
import sys
import time
from collections.abc import Callable
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from graphmethods.sheets.worksheets import Worksheet

KINDS = ("indicator", "step-moment", "velocity-plan", "wittenbauer", "acceleration-plan", "cam")


class Progress:
    """Progress lines on a stream: every tenth of a batch, and at its end."""

    def __init__(self, stream=None):
        self.stream = stream if stream is not None else sys.stderr
        self.t0 = time.perf_counter()

    def __call__(self, done: int, total: int, what: str) -> None:
        step = max(1, total // 10)
        if done == total or done % step == 0:
            print(f"worksheet: {what} {done}/{total} ({time.perf_counter() - self.t0:.1f} s)", file=self.stream,
                  flush=True)


def write_worksheet(sheet: Worksheet, out_dir: str | os.PathLike[str], *, overwrite: bool = False,
                    progress: Callable[[int, int, str], None] | None = None, dxf: bool = False) -> list[pathlib.Path]:
    """Write a class set into ``out_dir``: its files (:func:`graphmethods.sheets.worksheets.contents`: one
    PDF, an SVG per page in ``svg/``, a problem file per variant in ``problems/``, the blank answers
    file, and with ``dxf`` every page as DXF in ``dxf/``) through :func:`graphmethods.render.files.write_set`.

    Everything is built first, then written into a temporary folder beside ``out_dir`` and moved in, so
    an error leaves nothing behind; existing files are never replaced unless ``overwrite`` (the files
    of an old, larger set of the same kind go then too).

    Returns
    -------
    list of pathlib.Path
        The PDF, SVG, problem and answers files written, in :func:`~graphmethods.sheets.worksheets.output_names`
        order (the DXF pages are not listed).

    Raises
    ------
    OutputExistsError
        If a file to be written exists and ``overwrite`` is false (nothing is written then).

    Examples
    --------
    >>> import tempfile
    >>> from graphmethods.sheets.worksheets import worksheet
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "class"
    >>> [p.name for p in write_worksheet(worksheet("wittenbauer", variants=1, seed=3), out)][:3]
    ['wittenbauer-en.pdf', 'wittenbauer-01-student.svg', 'wittenbauer-01-key.svg']
    """
    from graphmethods.errors import InputError, OutputExistsError
    from graphmethods.render.files import write_set
    from graphmethods.sheets import worksheets as ws

    if str(out_dir).strip() == "":
        raise InputError("the worksheet folder name is empty; give a folder (it is created if missing)")
    out = pathlib.Path(out_dir)
    if out.exists() and not out.is_dir():
        raise InputError(f"{out} is a file; give a folder for the worksheet")
    names = ws.output_names(sheet.kind, sheet.notation, len(sheet.variants))
    existing = [name for name in names if (out / name).exists()]
    if existing and not overwrite:           # refused before anything is rendered
        more = f" and {len(existing) - 3} more" if len(existing) > 3 else ""
        raise OutputExistsError(f"{', '.join(str(out / e) for e in existing[:3])}{more} exist; use --force "
                                f"(overwrite=True) to replace them, or another folder")
    blobs = ws.contents(sheet, progress=progress, dxf=dxf)
    stale = [f"{sub}/{p.name}" for sub, pattern in ws.classset.stale_names(sheet.kind)
             for p in sorted((out / sub).glob(pattern))
             if re.fullmatch(ws.classset.VARIANT_FILE.format(kind=sheet.kind), p.name)]
    write_set(out, blobs, overwrite=overwrite, stale=stale if overwrite else (), what="worksheet folder")
    return [out / name for name in names]


def add_parser(sub) -> None:
    from graphmethods.cli._parser import integer

    p = sub.add_parser("worksheet", help="printable worksheets with answer keys (variants from a seed)",
                       description="Variants of a worksheet for a class, reproducible from a seed: a student page "
                       "and an answer-key page each, in one PDF (students, then keys), an SVG per page, and a "
                       "problem file per variant for `graphmethods check`.",
                       epilog="Example: graphmethods worksheet indicator --variants 30 --seed 7 --lang ru "
                       "--out class-7")
    p.add_argument("kind", choices=KINDS, help="indicator (W1 style), step-moment (W3 style), velocity-plan "
                   "(slider-crank in one position), wittenbauer (slider-crank press), acceleration-plan "
                   "(slider-crank or slotted lever in one position), cam (disc cam: base radius, profile by inversion)")
    p.add_argument("--variants", type=integer, default=1, metavar="N", help="number of variants (default 1)")
    p.add_argument("--seed", type=integer, default=0, metavar="S", help="seed; the same seed gives the same variants")
    p.add_argument("--lang", choices=("en", "ru", "zh"), default="en", help="language and notation (default en)")
    p.add_argument("-o", "--out", required=True, metavar="DIR", help="output folder (created if missing)")
    p.add_argument("--force", action="store_true", help="replace existing files")
    p.add_argument("--quiet", action="store_true", help="no progress on stderr")
    p.add_argument("--dxf", action="store_true", help="also write each page as DXF in DIR/dxf/ (students draw on it in "
                   "CAD; graphmethods check-class reads their drawings back)")
    p.set_defaults(func=run)


def run(args) -> int:
    from graphmethods.errors import InputError, OutputExistsError
    from graphmethods.sheets import worksheets as ws
    from graphmethods.units import MAX_VARIANTS, count

    t0 = time.perf_counter()
    count(args.variants, "--variants", low=1, high=MAX_VARIANTS, why="checked before any variant is built")
    if args.out.strip() == "":
        raise InputError("--out is empty; give a folder (it is created if missing)")
    if not args.force:                    # refuse before building anything
        existing = ws.existing_outputs(args.out, args.kind, args.lang, args.variants)
        if getattr(args, "dxf", False):
            existing += [p for p in map(pathlib.Path(args.out).joinpath, ws.dxf_names(args.kind, args.variants))
                         if p.exists()]
        if existing:
            more = f" and {len(existing) - 3} more" if len(existing) > 3 else ""
            raise OutputExistsError(f"{', '.join(map(str, existing[:3]))}{more} exist; use --force to replace them, "
                                    f"or another --out")
    progress = None if args.quiet else Progress()
    sheet = ws.worksheet(args.kind, variants=args.variants, seed=args.seed, notation=args.lang, progress=progress)
    paths = write_worksheet(sheet, args.out, overwrite=args.force, progress=progress,
                            dxf=getattr(args, "dxf", False))
    n = len(sheet.variants)
    if getattr(args, "dxf", False):
        print(f"wrote {2 * n} DXF pages in {paths[0].parent / 'dxf'} (1 unit = 1 mm)")
    print(f"wrote {paths[0]} ({2 * n} pages: {n} students', then {n} keys), {2 * n} SVG in "
          f"{paths[0].parent / 'svg'}, {n} problem files in {paths[0].parent / 'problems'} "
          f"in {time.perf_counter() - t0:.1f} s")
    print(f"blank answers file: {paths[-1]} (copy it for each student, fill it in)")
    print(f"check a student: graphmethods check {sheet.variants[0].id} ANSWERS.toml   "
          f"(or {paths[0].parent / 'problems'}/{args.kind}-NN.json)")
    return 0
