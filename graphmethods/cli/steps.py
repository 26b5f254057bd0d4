"""``graphmethods steps CASE FIGURE``: a construction step by step, for a lecture.

    graphmethods steps press velocity-plan --format pdf --out press_plan.pdf
    graphmethods steps press wittenbauer --format html --lang ru --out wittenbauer_ru.html
    graphmethods steps W1 energy-indicator --format animated-svg --out w1.svg
    graphmethods steps shaper velocity-plan --position 3 --format svg --out frames/shaper.svg
    graphmethods steps slotted-lever acceleration-plan --position 2 --format html --lang ru
    graphmethods steps press force-plans --position 3 --format pdf --lang zh

CASE is a built-in problem (press, four-bar, slotted-lever, shaper, the other built-in linkages of
``graphmethods problems``, W1…W4) or a linkage problem file; FIGURE is velocity-plan,
acceleration-plan, force-plans, zhukovsky-lever (every force of the force analysis, M_b),
zhukovsky-load (the working load alone, M_r), energy-indicator, wittenbauer, kinematic-diagrams,
work-diagrams or kinematic-scheme. ``--format pdf`` writes one page
per step (a 16:9 slide by default, its drawing enlarged z : 1 for a projector, up to 1.9 : 1 so the
smallest text is 1/40 of the slide's height where the figure's layout allows; ``--page A4`` …
``A1`` for sheets), ``svg`` one numbered frame
per step (``STEM-01.svg`` …), ``animated-svg`` one SVG that plays the steps by itself in a
browser, ``html`` one self-contained page stepped with buttons and the arrow keys. Every file is
built before the first is written; an existing file is kept unless ``--force``.
"""

from __future__ import annotations

import pathlib
import sys

HELP = "a construction step by step for a lecture: PDF slides, SVG frames, animation, HTML page"
SUFFIX = {"pdf": ".pdf", "svg": ".svg", "html": ".html", "animated-svg": ".svg"}


def add_parser(sub) -> None:
    p = sub.add_parser("steps", help=HELP,
                       description="Build a textbook construction step by step: each step adds its lines and "
                       "points, in colour over the earlier steps in grey, with a caption saying what is drawn "
                       "and why.")
    p.add_argument("case", metavar="CASE",
                   help="press, four-bar, slotted-lever, shaper (or another built-in linkage), W1, W2, W3, W4, or a "
                        "linkage problem file")
    p.add_argument("figure", metavar="FIGURE",
                   help="velocity-plan, acceleration-plan, force-plans, zhukovsky-lever (every force, M_b), "
                        "zhukovsky-load (the load alone, M_r), energy-indicator, wittenbauer, kinematic-diagrams, "
                        "inversion (a cam problem's profile), "
                        "work-diagrams or kinematic-scheme")
    p.add_argument("--position", type=int, default=None, metavar="K",
                   help="the position of a velocity, acceleration or force plan or of Zhukovsky's lever "
                        "(default: chosen by the figure)")
    p.add_argument("--format", choices=("pdf", "svg", "html", "animated-svg"), default="pdf", dest="out_format",
                   help="pdf (one page per step, default), svg (numbered frames), html (one page), animated-svg")
    p.add_argument("--lang", choices=("en", "ru", "zh"), default="en", help="language and notation (default en)")
    p.add_argument("--page", default="slide", metavar="PAGE",
                   help="slide (16:9, default: the drawing enlarged z : 1 so its text reads on a projector; scales "
                        "as at 1 : 1), A4, A3, A2 or A1 (landscape, with frame and title block)")
    p.add_argument("--positions", "-m", type=int, default=12, metavar="M",
                   help="positions per crank turn of a linkage's dynamic study (default 12)")
    p.add_argument("--seconds", type=float, default=3.0, metavar="S",
                   help="animated-svg: seconds each step is shown (default 3)")
    p.add_argument("--out", default=None, metavar="PATH",
                   help="the file to write, or a folder for the default name (svg: the frames are PATH-01.svg, …); "
                        "default CASE_FIGURE_LANG.EXT")
    p.add_argument("--force", action="store_true", help="overwrite existing files")
    p.set_defaults(func=run)


def run(args) -> int:
    from graphmethods.errors import InputError
    from graphmethods.render import steps as render_steps
    from graphmethods.sheets import steps

    if not 3 <= args.positions <= 720:
        raise InputError(f"--positions {args.positions}: give from 3 to 720 positions per turn")
    bu = steps.build(args.case, args.figure, position=args.position, notation=args.lang, page=args.page,
                     m=args.positions)
    stem = pathlib.Path(str(args.case)).stem.lower().replace("-", "_")
    figure = str(args.figure).lower().replace("-", "_")
    extra = "_animated" if args.out_format == "animated-svg" else ""
    default = f"{stem}_{figure}_{args.lang}{extra}{SUFFIX[args.out_format]}"
    out = pathlib.Path(default if args.out is None else args.out)
    if out.is_dir():                      # a folder: the default name inside it
        out = out / default
    written = render_steps.save(bu, out, args.out_format, overwrite=args.force, seconds=args.seconds)
    shown = str(written[0]) if len(written) == 1 else f"{written[0]} … {written[-1].name}"
    print(f"wrote {shown}: {len(bu)} steps ({bu.figure.page.size.lower()} {bu.figure.page.width_mm:g} × "
          f"{bu.figure.page.height_mm:g} mm)")
    for k, caption in enumerate(bu.captions(), start=1):
        print(f"  {k}. {terminal_text(caption)}", file=sys.stdout)
    return 0


def terminal_text(caption: str) -> str:
    """A caption's markup as a terminal shows it: ``v_{BA}`` -> ``v_BA``.

    >>> terminal_text("ψ_{max} and ω_m^{2}")
    'ψ_max and ω_m^2'
    """
    from graphmethods.scene import markup

    return "".join(t if s == 0 else ("_" if s < 0 else "^") + t for t, s in markup.parse(caption))
