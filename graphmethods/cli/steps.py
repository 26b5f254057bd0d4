"""``graphmethods steps CASE FIGURE``: a construction step by step, for a lecture.

    graphmethods steps press velocity-plan --as slides -o press_plan.pdf
    graphmethods steps press wittenbauer --as page --lang ru -o wittenbauer_ru.html
    graphmethods steps W1 energy-indicator --as animation -o w1.svg
    graphmethods steps shaper velocity-plan --position 3 --as frames -o frames/shaper.svg
    graphmethods steps slotted-lever acceleration-plan --position 2 --as page --lang ru
    graphmethods steps press force-plans --position 3 --as slides --lang zh -o - > press.pdf

CASE is a built-in problem (press, four-bar, slotted-lever, shaper, the other built-in linkages of
``graphmethods problems``, W1…W4) or a linkage problem file; FIGURE is velocity-plan,
acceleration-plan, force-plans, zhukovsky-lever (every force of the force analysis, M_b),
zhukovsky-load (the working load alone, M_r), energy-indicator, wittenbauer, kinematic-diagrams,
work-diagrams or kinematic-scheme. ``--as slides`` (PDF) writes one page
per step (a 16:9 slide by default, its drawing enlarged z : 1 for a projector, up to 1.9 : 1 so the
smallest text is 1/40 of the slide's height where the figure's layout allows; ``--page A4`` …
``A1`` for sheets), ``frames`` one numbered SVG frame
per step (``STEM-01.svg`` …), ``animation`` one SVG that plays the steps by itself in a
browser, ``page`` one self-contained HTML page stepped with buttons and the arrow keys. Every file is
built before the first is written; an existing file is kept unless ``--force``.
"""

from __future__ import annotations

import pathlib
import sys

HELP = "a construction step by step for a lecture: PDF slides, SVG frames, animation, HTML page"
SUFFIX = {"pdf": ".pdf", "svg": ".svg", "html": ".html", "animated-svg": ".svg"}
#: ``--as`` KIND -> the file format it is written in
KINDS = {"slides": "pdf", "frames": "svg", "page": "html", "animation": "animated-svg"}


def add_parser(sub) -> None:
    from graphmethods.cli._parser import integer, number
    from graphmethods.cli.kinematics import builtin_names

    p = sub.add_parser("steps", help=HELP,
                       description="Build a textbook construction step by step: each step adds its lines and "
                       "points, in colour over the earlier steps in grey, with a caption saying what is drawn "
                       "and why.")
    p.add_argument("case", metavar="CASE",
                   help="a built-in linkage (" + builtin_names() + "), W1, W2, W3, W4, or a linkage problem file "
                        "(- reads it from standard input)")
    p.add_argument("figure", metavar="FIGURE",
                   help="velocity-plan, acceleration-plan, force-plans, zhukovsky-lever (every force, M_b), "
                        "zhukovsky-load (the load alone, M_r), energy-indicator, wittenbauer, kinematic-diagrams, "
                        "inversion (a cam problem's profile), "
                        "work-diagrams or kinematic-scheme")
    p.add_argument("--position", type=integer, default=None, metavar="K",
                   help="the position of a velocity, acceleration or force plan or of Zhukovsky's lever "
                        "(default: chosen by the figure)")
    kind = p.add_mutually_exclusive_group()
    kind.add_argument("--as", choices=tuple(KINDS), default=None, dest="kind",
                      help="what to make: slides (a PDF, one page per step; default), frames (numbered SVG files), "
                           "page (one HTML page stepped with buttons), animation (one SVG that plays by itself)")
    kind.add_argument("--format", choices=tuple(KINDS.values()), default=None, dest="out_format",
                      help="older name of --as: pdf, svg, html, animated-svg (still accepted)")
    p.add_argument("--lang", choices=("en", "ru", "zh"), default="en", help="language and notation (default en)")
    p.add_argument("--page", default="slide", metavar="PAGE",
                   help="slide (16:9, default: the drawing enlarged z : 1 so its text reads on a projector; scales "
                        "as at 1 : 1), A4, A3, A2 or A1 (landscape, with frame and title block)")
    p.add_argument("--positions", "-m", type=integer, default=12, metavar="M",
                   help="positions per crank turn of a linkage's dynamic study (default 12)")
    p.add_argument("--seconds", type=number, default=3.0, metavar="S",
                   help="animation: seconds each step is shown (default 3)")
    p.add_argument("-o", "--out", default=None, metavar="PATH",
                   help="the file to write, or a folder for the default name (frames: PATH-01.svg, …); "
                        "default CASE_FIGURE_LANG.EXT; - writes slides, a page or an animation to standard output "
                        "(the captions then go to stderr)")
    p.add_argument("--force", action="store_true", help="overwrite existing files")
    p.set_defaults(func=run)


def run(args) -> int:
    from graphmethods.errors import InputError
    from graphmethods.render import steps as render_steps
    from graphmethods.sheets import steps

    if not 3 <= args.positions <= 720:
        raise InputError(f"--positions {args.positions}: give from 3 to 720 positions per turn")
    fmt = args.out_format or KINDS[args.kind or "slides"]
    if args.out == "-" and fmt == "svg":
        raise InputError("-o -: frames are one file per step; write them to files, or use --as slides, page or "
                         "animation for standard output")
    bu = steps.build(args.case, args.figure, position=args.position, notation=args.lang, page=args.page,
                     m=args.positions)
    stem = "stdin" if args.case == "-" else pathlib.Path(str(args.case)).stem.lower().replace("-", "_")
    figure = str(args.figure).lower().replace("-", "_")
    extra = "_animated" if fmt == "animated-svg" else ""
    default = f"{stem}_{figure}_{args.lang}{extra}{SUFFIX[fmt]}"
    stream = sys.stdout
    if args.out == "-":                   # one file to standard output, the report to stderr
        ((_, data),) = render_steps.outputs(bu, fmt, default, seconds=args.seconds)
        sys.stdout.flush()
        sys.stdout.buffer.write(data)
        sys.stdout.buffer.flush()
        stream, shown = sys.stderr, "standard output"
    else:
        out = pathlib.Path(default if args.out is None else args.out)
        if out.is_dir():                      # a folder: the default name inside it
            out = out / default
        written = render_steps.save(bu, out, fmt, overwrite=args.force, seconds=args.seconds)
        shown = str(written[0]) if len(written) == 1 else f"{written[0]} … {written[-1].name}"
    print(f"wrote {shown}: {len(bu)} steps ({bu.figure.page.size.lower()} {bu.figure.page.width_mm:g} × "
          f"{bu.figure.page.height_mm:g} mm)", file=stream)
    for k, caption in enumerate(bu.captions(), start=1):
        print(f"  {k}. {terminal_text(caption)}", file=stream)
    return 0


def terminal_text(caption: str) -> str:
    """A caption's markup as a terminal shows it: ``v_{BA}`` -> ``v_BA``.

    >>> terminal_text("ψ_{max} and ω_m^{2}")
    'ψ_max and ω_m^2'
    """
    from graphmethods.scene import markup

    return "".join(t if s == 0 else ("_" if s < 0 else "^") + t for t, s in markup.parse(caption))
