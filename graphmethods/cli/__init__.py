"""The command line: ``graphmethods COMMAND ...``.

Thin by design: each command lives in a module of this package that defines
``add_parser(subparsers)`` and ``run(args) -> int``; it parses arguments, calls
into the library, and prints. Any :class:`~graphmethods.errors.GraphmethodsError`
becomes one line on stderr and exit status 2, never a traceback.
"""

from __future__ import annotations

import argparse
import importlib
import sys

from graphmethods.errors import GraphmethodsError

#: command name -> module (inside graphmethods.cli) that implements it
COMMANDS = {
    "flywheel": "flywheel",
    "examples": "examples",
    "problems": "problems",
    "kinematics": "kinematics",
    "study": "study",
    "gallery": "gallery",
    "worksheet": "worksheet",
    "check": "check",
    "bench": "bench",
}


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2, like every other error
        self.exit(2, f"graphmethods: error: {message} (see graphmethods --help)\n")


def version() -> str:
    """The installed package's version (from its metadata), or "unknown" when it is run uninstalled."""
    from importlib import metadata

    try:
        return metadata.version("graphmethods")
    except metadata.PackageNotFoundError:
        return "unknown (not installed)"


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="graphmethods", description="Exact, scale-true graphical methods of machine dynamics.")
    parser.add_argument("--version", action="version", version=f"%(prog)s {version()}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for name, module in COMMANDS.items():
        mod = importlib.import_module(f"graphmethods.cli.{module}")
        mod.add_parser(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv and argv[0] in COMMANDS:
        mod = importlib.import_module(f"graphmethods.cli.{COMMANDS[argv[0]]}")
        argv = getattr(mod, "preprocess_argv", list)(argv)
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except GraphmethodsError as exc:
        print(f"graphmethods {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        return 1
    except KeyboardInterrupt:
        print("graphmethods: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
