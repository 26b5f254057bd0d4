"""``graphmethods problems``: the built-in problems, one line each (name, kind, title).

The name goes wherever a command takes a problem: ``graphmethods study press``,
``graphmethods kinematics shaper``, ``graphmethods check W1 answers.toml``.
"""

from __future__ import annotations

import json
import sys


def add_parser(sub) -> None:
    p = sub.add_parser("problems", help="list the built-in problems (their names work in place of a problem file)",
                       description="List the built-in problems: name, kind and title. Give the name wherever a "
                       "command takes a problem file: graphmethods study press, graphmethods kinematics shaper, "
                       "graphmethods check W1 ANSWERS.toml.")
    p.add_argument("name", metavar="NAME", nargs="?", default=None,
                   help="with --file: the built-in linkage or cam problem (or example file, see --examples) to print")
    p.add_argument("--file", action="store_true",
                   help="print NAME's problem file as it ships, to redirect and edit (graphmethods problems press "
                        "--file > my_press.json; then graphmethods study my_press.json)")
    p.add_argument("--examples", action="store_true",
                   help="list the example students' files that ship (answers files, drawings); print one with "
                        "graphmethods problems FILE --file > FILE")
    p.add_argument("--json", action="store_true", help="print one JSON list of {name, kind, title}")
    p.set_defaults(func=run)


def run(args) -> int:
    from graphmethods.errors import InputError
    from graphmethods.problems.builtin import example_files, file_text, listing

    if args.examples:
        names = list(example_files())
        if args.json:
            print(json.dumps(names, indent=1))
        else:
            print("\n".join(names))
        return 0

    if args.name is not None or args.file:
        if args.name is None or not args.file:
            raise InputError("give a name and --file to print a built-in problem's file, e.g. graphmethods problems "
                             "press --file > press.json; or neither, for the list")
        if args.json:
            raise InputError("--file prints the problem file (JSON itself); leave out --json")
        text = file_text(args.name)       # read (and checked as text) as it ships, written byte for byte
        data = text.encode("utf-8")
        sys.stdout.flush()
        sys.stdout.buffer.write(data if data.endswith(b"\n") else data + b"\n")
        sys.stdout.buffer.flush()
        return 0

    rows = listing()
    if args.json:
        print(json.dumps([{"name": r.name, "kind": r.kind, "title": r.title} for r in rows], indent=1))
        return 0
    print(f"{'name':<18}{'kind':<15}title")
    for r in rows:
        print(r.line())
    print("cycle problems: graphmethods examples, graphmethods check NAME ANSWERS.toml; "
          "linkages: graphmethods kinematics NAME, graphmethods study NAME (press also: check)")
    return 0
