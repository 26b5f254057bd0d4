"""The command line: ``graphmethods COMMAND ...``.

Thin by design: each command lives in a module of this package that defines
``add_parser(subparsers)`` and ``run(args) -> int``; it parses arguments, calls
into the library, and prints. Any :class:`~graphmethods.errors.GraphmethodsError`
becomes one line on stderr and exit status 2, never a traceback.
"""

from __future__ import annotations

import importlib
import sys

from graphmethods.errors import GraphmethodsError

TYPE_CHECKING = False   # typing itself (and the re it loads) costs --help a third of its time
if TYPE_CHECKING:
    import argparse

#: command name -> (module inside graphmethods.cli that implements it, one-line help). The help
#: lines are here so that ``graphmethods --help`` imports no command module (and so no numpy).
COMMANDS = {
    "flywheel": ("flywheel", "excess-work table, ΔW_max and the flywheel (approximate method)"),
    "examples": ("examples", "solve and print the published worked examples W1–W4"),
    "problems": ("problems", "list the built-in problems (their names work in place of a problem file)"),
    "kinematics": ("kinematics", "positions, velocities and accelerations of a linkage (plans, figures, the A1 sheet)"),
    "forces": ("forces", "force (kinetostatic) analysis in one position: reactions and the balancing moment"),
    "study": ("study", "dynamic study of a linkage problem: J_e, M_r, the flywheel three ways"),
    "gallery": ("gallery", "build every gallery figure (SVG, optionally PNG)"),
    "worksheet": ("worksheet", "printable worksheets with answer keys (variants from a seed)"),
    "check": ("check", "check a student's hand drawing (answers file) and diagnose usual mistakes"),
    "check-class": ("check_class", "check a folder of students' answers files and drawings: one class table"),
    "bench": ("bench", "measure speed against error (Markdown table and JSON)"),
    "motion": ("motion", "motion from given initial conditions: start-up, steady running, run-down"),
    "drive": ("drive", "a drive of several masses reduced to one shaft: J', c', natural frequencies"),
    "cam": ("cam", "cam mechanism: base radius from the pressure angle, motion, profile, the A1 cam sheet"),
    "steps": ("steps", "a construction step by step for a lecture: PDF slides, SVG frames, animation, HTML page"),
}


def version() -> str:
    """The installed package's version (from its metadata), or "unknown" when it is run uninstalled."""
    from importlib import metadata

    try:
        return metadata.version("graphmethods")
    except metadata.PackageNotFoundError:
        return "unknown (not installed)"


DESCRIPTION = "Exact, scale-true graphical methods of machine dynamics."


def top_help() -> str:
    """``graphmethods --help``: the commands and their help lines, written without argparse.

    argparse with its formatter (shutil, textwrap, gettext, locale) costs about as much as the
    interpreter's own start-up, so the top-level help, the one a newcomer types first, is
    written from :data:`COMMANDS` directly; a command's own ``--help`` is argparse's.
    """
    width = max(len(name) for name in COMMANDS) + 2
    lines = ["usage: graphmethods [-h] [--version] COMMAND ...", "", DESCRIPTION, "", "commands:"]
    lines += [f"  {name:<{width}}{help_line}" for name, (_, help_line) in COMMANDS.items()]
    lines += ["", "options:", f"  {'-h, --help':<{width}}show this help message and exit",
              f"  {'--version':<{width}}print the version and exit", "",
              "graphmethods COMMAND --help shows a command's own options."]
    return "\n".join(lines) + "\n"


def build_parser(command: str | None = None) -> argparse.ArgumentParser:
    """The argument parser; only ``command``'s module is imported (every one when None, for tests)."""
    from graphmethods.cli._parser import Parser as _Parser, Version as _Version

    parser = _Parser(prog="graphmethods", description=DESCRIPTION)
    parser.add_argument("--version", action=_Version, nargs=0, help="print the version and exit")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for name, (module, help_line) in COMMANDS.items():
        if command is None or name == command:
            importlib.import_module(f"graphmethods.cli.{module}").add_parser(sub)
        else:
            sub.add_parser(name, help=help_line)
    return parser


def _tolerant_streams() -> None:
    """On a terminal that cannot show every character (PYTHONIOENCODING=cp1252), print what it can and
    write the rest as \\u escapes instead of failing with UnicodeEncodeError."""
    for stream in (sys.stdout, sys.stderr):
        enc = (getattr(stream, "encoding", None) or "").lower().replace("-", "").replace("_", "")
        if enc not in ("utf8", "utf8sig") and hasattr(stream, "reconfigure"):
            try:
                stream.reconfigure(errors="backslashreplace")
            except (ValueError, OSError):   # a stream that cannot be reconfigured keeps its rules
                pass


def main(argv: list[str] | None = None) -> int:
    _tolerant_streams()
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv in (["-h"], ["--help"]):
        sys.stdout.write(top_help())
        return 0
    command = argv[0] if argv and argv[0] in COMMANDS else ""
    if command:
        mod = importlib.import_module(f"graphmethods.cli.{COMMANDS[command][0]}")
        argv = getattr(mod, "preprocess_argv", list)(argv)
    args = build_parser(command).parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except BaseException:
        if "graphmethods.cli._progress" in sys.modules:     # a progress line on the terminal ends first
            sys.modules["graphmethods.cli._progress"].clear()
        return _failed(args)


def _failed(args: argparse.Namespace) -> int:
    """The exception being handled as one line on stderr and its exit status (re-raised when not ours)."""
    try:
        raise
    except GraphmethodsError as exc:
        print(f"graphmethods {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        return 1
    except OSError as exc:          # reading or writing refused by the system: one line, what, where, why
        where = f" {exc.filename}" if getattr(exc, "filename", None) else ""
        why = (exc.strerror or str(exc) or type(exc).__name__).lower()
        print(f"graphmethods {args.command}: error: cannot use{where}: {why}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("graphmethods: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
