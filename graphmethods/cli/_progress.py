"""The progress line of the long jobs (gallery, class sets, worksheets, bench) on standard error.

On a terminal one line is rewritten in place; into a file or a pipe each step is one line. ``--quiet``
turns it off. Standard output keeps the results only.
"""

from __future__ import annotations

import sys


class Progress:
    """``progress(k, n, what)``: step k of n is ``what``; :meth:`done` clears a terminal's line.

    >>> p = Progress(quiet=True)
    >>> p(1, 3, "w1_energy_en")
    >>> p.done()
    """

    def __init__(self, *, quiet: bool = False, label: str = "") -> None:
        self.quiet = quiet
        self.label = label
        self.tty = bool(getattr(sys.stderr, "isatty", lambda: False)())
        self._shown = 0

    def __call__(self, k: int, n: int, what: str) -> None:
        if self.quiet:
            return
        text = f"{self.label}[{k}/{n}] {what}"
        if self.tty:
            pad = max(self._shown - len(text), 0)
            sys.stderr.write("\r" + text + " " * pad)
            self._shown = len(text)
        else:
            sys.stderr.write(text + "\n")
        sys.stderr.flush()

    def done(self) -> None:
        """End the progress: a terminal's rewritten line is cleared."""
        if self.tty and self._shown and not self.quiet:
            sys.stderr.write("\r" + " " * self._shown + "\r")
            sys.stderr.flush()
        self._shown = 0
