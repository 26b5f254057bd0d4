"""The command line's argparse pieces, imported only when arguments are parsed (not for ``--help``)."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from typing import Any, NoReturn


class Formatter(argparse.HelpFormatter):
    """argparse's help, but a line never breaks inside a hyphenated name (``slotted-lever``, ``--phi-deg``)."""

    def _split_lines(self, text: str, width: int) -> list[str]:
        import textwrap

        return textwrap.wrap(self._whitespace_matcher.sub(" ", text).strip(), width, break_on_hyphens=False)

    def _fill_text(self, text: str, width: int, indent: str) -> str:
        import textwrap

        return textwrap.fill(self._whitespace_matcher.sub(" ", text).strip(), width, initial_indent=indent,
                             subsequent_indent=indent, break_on_hyphens=False)


class Parser(argparse.ArgumentParser):
    """An argument parser whose errors are one line and exit status 2, like every other error; no
    option is ever matched by a prefix of its name (``allow_abbrev=False``)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs.setdefault("allow_abbrev", False)    # --position must never be read as --positions
        kwargs.setdefault("formatter_class", Formatter)
        super().__init__(*args, **kwargs)

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


class Version(argparse.Action):
    """``--version``: the metadata is read only when asked (it costs start-up time otherwise)."""

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace,
                 values: str | Sequence[Any] | None, option_string: str | None = None) -> None:
        from graphmethods.cli import version

        print(f"graphmethods {version()}")
        parser.exit(0)


def number(text: str) -> float:
    """The argparse type of every numeric option: the project's number policy (:func:`graphmethods.units.real`).

    Fractions such as ``1/300`` are accepted; NaN, infinities and magnitudes beyond 1e100 (or below
    1e-100, zero apart) are refused with one line and exit status 2.

    >>> number("1/4")
    0.25
    """
    from graphmethods.errors import InputError
    from graphmethods.units import parse_number

    try:
        return parse_number(text, name="the value")
    except InputError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def numbers(text: str) -> list[float]:
    """A comma-separated list of numbers (``--phi-deg 0,90,180``), each under :func:`number`.

    >>> numbers("0, 90,1/2")
    [0.0, 90.0, 0.5]
    """
    parts = str(text).split(",")
    if not any(p.strip() for p in parts) or any(not p.strip() for p in parts):
        raise argparse.ArgumentTypeError(f"{text!r}: give numbers separated by commas, e.g. 0,90,180")
    return [number(p.strip()) for p in parts]


def integer(text: str) -> int:
    """A whole number (a position number, a count); its range is checked by the command before any work.

    >>> integer(" 7 ")
    7
    """
    s = str(text).strip()
    if not s.lstrip("+-").isdigit() or len(s) > 30:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number")
    return int(s)


#: the metavar of a drawing written to one file, or to standard output (``-``)
DRAWING_TARGET = "FILE.svg|.pdf|.png|.dxf|-"


def add_output(p: argparse.ArgumentParser, *aliases: str, metavar: str, help: str, dest: str = "out") -> None:
    """``-o/--out`` for a command's one output (file or folder), with its older names kept as aliases.

    ``-`` stands for standard output where the output is one file (then ``--format`` names its format).
    """
    old = f" (older name{'s' if len(aliases) > 1 else ''} {', '.join(aliases)} still accepted)" if aliases else ""
    p.add_argument("-o", "--out", *aliases, dest=dest, default=None, metavar=metavar, help=help + old)


def add_figure_options(p: argparse.ArgumentParser, what: str, format_help: str | None = None,
                       lang_help: str | None = None) -> None:
    """``--format``, ``--lang`` and ``--force`` of a command that draws one ``what`` ("sheet", "figure").

    ``format_help`` and ``lang_help`` replace the usual help of ``--format`` (the file format of
    ``-o -``) and of ``--lang``.
    """
    p.add_argument("--format", choices=("svg", "pdf", "png", "dxf"), default=None,
                   help=format_help or f"file format of the {what} (default: the file name's suffix; needed with -o -)")
    p.add_argument("--lang", choices=("en", "ru", "zh"), default="en",
                   help=lang_help or f"notation of the {what} (default en)")
    p.add_argument("--force", action="store_true", help=f"overwrite an existing {what} file")


def add_sheet_options(p: argparse.ArgumentParser, what: str, lang_help: str | None = None) -> None:
    """The options of a command that draws one A1 or A2 course sheet, the same on every such command.

    ``-o/--out`` (older name ``--sheet``; ``-`` for standard output), ``--format``, ``--lang``,
    ``--page``, ``--force`` and the main inscription's ``--student``, ``--group``, ``--sheet-no``.
    ``what`` names the sheet in the help of ``-o`` (``"the dynamic-analysis sheet"``); ``lang_help``
    replaces the usual help of ``--lang``.
    """
    from graphmethods.cli._sheet import add_signature_options

    add_output(p, "--sheet", dest="sheet", metavar=DRAWING_TARGET,
               help=f"also write {what} (scale-true); - writes it to standard output in --format, and nothing else")
    add_figure_options(p, "sheet", lang_help=lang_help)
    p.add_argument("--page", type=str.upper, choices=("A1", "A2"), default="A1", help="sheet size (default A1)")
    add_signature_options(p)
