#!/usr/bin/env python3
"""The README's commands, as CI runs them: every line of every ```sh block, in order.

A block is skipped when the line before its fence is a marker: ``<!-- ci: skip: WHY -->`` (a command
that must not run here, the reason said), or ``<!-- main-command -->`` / ``<!-- test-command -->``
(the set-up commands, which CI's first stage runs from the source). A command whose comment says
``# exits N`` must exit with status N (``check`` exits 1 when the drawing has mistakes); every other
command must exit 0.

    python .ci/readme_commands.py README.md            # list them
    python .ci/readme_commands.py README.md --run      # run them here, in order; stop at the first failure
"""

from __future__ import annotations

import re
import subprocess
import sys
import time
from dataclasses import dataclass

SKIP = re.compile(r"<!--\s*(ci:\s*skip\b.*|main-command|test-command)\s*-->")
EXITS = re.compile(r"#\s*exits\s+(\d+)")


@dataclass(frozen=True)
class Command:
    line: int       # 1-based line in the README
    text: str       # the command as printed
    status: int     # the exit status it must give


def commands(readme: str) -> list[Command]:
    """Every command of the README's ```sh blocks that CI runs (see the module docstring)."""
    out: list[Command] = []
    lines = readme.splitlines()
    i, previous = 0, ""
    while i < len(lines):
        stripped = lines[i].strip()
        if stripped.startswith("```sh"):
            skip = bool(SKIP.search(previous))
            i += 1
            pending, start = "", 0
            while i < len(lines) and not lines[i].strip().startswith("```"):
                text = lines[i].strip()
                if text and not text.startswith("#") and not skip:
                    if not pending:
                        start = i + 1
                    pending += text[:-1] + " " if text.endswith("\\") else text
                    if not text.endswith("\\"):
                        m = EXITS.search(pending)
                        out.append(Command(start, pending, int(m.group(1)) if m else 0))
                        pending = ""
                i += 1
        if stripped:
            previous = stripped
        i += 1
    return out


def main(argv: list[str]) -> int:
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0
    with open(argv[0], encoding="utf-8") as f:
        found = commands(f.read())
    if "--run" not in argv:
        for c in found:
            print(f"{c.line}: {c.text}" + (f"   [exit {c.status}]" if c.status else ""))
        return 0
    for k, c in enumerate(found, start=1):
        t0 = time.perf_counter()
        r = subprocess.run(["bash", "-o", "pipefail", "-c", c.text], capture_output=True, text=True)
        took = time.perf_counter() - t0
        mark = "ok" if r.returncode == c.status else "FAILED"
        print(f"[{k}/{len(found)}] {mark} {took:5.1f} s  README:{c.line}  {c.text}", flush=True)
        if r.returncode != c.status:
            print(f"exit status {r.returncode}, expected {c.status}", file=sys.stderr)
            print((r.stdout[-2000:] + "\n" + r.stderr[-2000:]).strip(), file=sys.stderr)
            return 1
    print(f"all {len(found)} README commands ran as printed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
