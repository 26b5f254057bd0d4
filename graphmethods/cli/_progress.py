"""The progress line of the long jobs (gallery, class sets, bench) on standard error.

On a terminal one line is rewritten in place, and cleared when the job ends or fails (so an error is
still one line). Into a file or a pipe a line is written at most every ``every`` seconds, the first
after that long: a quick job, or one that fails at once, writes none. ``--quiet`` turns it off.
Standard output keeps the results only.
"""

from __future__ import annotations

import sys
import time
from typing import TextIO

#: the progress line shown now on a terminal (cleared before an error is printed)
_ACTIVE: list[Progress] = []


class Progress:
    """``progress(k, n, what)``: step k of n is ``what``; :meth:`done` ends it.

    >>> import io
    >>> out = io.StringIO()
    >>> p = Progress(label="gallery ", stream=out, tty=False, every=0.0)
    >>> p(1, 3, "w1_energy_en"); p.done()
    >>> out.getvalue()
    'gallery [1/3] w1_energy_en\\n'
    """

    def __init__(self, *, quiet: bool = False, label: str = "", stream: TextIO | None = None,
                 tty: bool | None = None, every: float = 2.0) -> None:
        self.quiet = quiet
        self.label = label
        self.stream = stream if stream is not None else sys.stderr
        self.tty = bool(getattr(self.stream, "isatty", lambda: False)()) if tty is None else tty
        self.every = every
        self._t0 = self._last = time.perf_counter()
        self._shown = 0

    def __call__(self, k: int, n: int, what: str) -> None:
        if self.quiet:
            return
        text = f"{self.label}[{k}/{n}] {what}"
        if self.tty:
            pad = max(self._shown - len(text), 0)
            self.stream.write("\r" + text + " " * pad)
            self._shown = len(text)
            if self not in _ACTIVE:
                _ACTIVE.append(self)
        else:
            now = time.perf_counter()
            if now - self._last < self.every:
                return
            self._last = now
            self.stream.write(f"{text} ({now - self._t0:.0f} s)\n" if self.every else text + "\n")
        self.stream.flush()

    def done(self) -> None:
        """End the progress: a terminal's rewritten line is cleared."""
        if self.tty and self._shown and not self.quiet:
            self.stream.write("\r" + " " * self._shown + "\r")
            self.stream.flush()
        self._shown = 0
        if self in _ACTIVE:
            _ACTIVE.remove(self)


def clear() -> None:
    """Clear any progress line on the terminal (before an error is printed on its own line)."""
    for p in list(_ACTIVE):
        p.done()
