"""The command line's argparse pieces, imported only when arguments are parsed (not for ``--help``)."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from typing import Any, NoReturn


class Parser(argparse.ArgumentParser):
    """An argument parser whose errors are one line and exit status 2, like every other error."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"graphmethods: error: {message} (see graphmethods --help)\n")


class Version(argparse.Action):
    """``--version``: the metadata is read only when asked (it costs start-up time otherwise)."""

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace,
                 values: str | Sequence[Any] | None, option_string: str | None = None) -> None:
        from graphmethods.cli import version

        print(f"graphmethods {version()}")
        parser.exit(0)
