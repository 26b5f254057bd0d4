"""``graphmethods problems``: the built-in problems, one line each (name, kind, title).

The name goes wherever a command takes a problem: ``graphmethods study press``,
``graphmethods kinematics shaper``, ``graphmethods check W1 answers.toml``.
"""

from __future__ import annotations

import json


def add_parser(sub) -> None:
    p = sub.add_parser("problems", help="list the built-in problems (their names work in place of a problem file)",
                       description="List the built-in problems: name, kind and title. Give the name wherever a "
                       "command takes a problem file: graphmethods study press, graphmethods kinematics shaper, "
                       "graphmethods check W1 ANSWERS.toml.")
    p.add_argument("--json", action="store_true", help="print one JSON list of {name, kind, title}")
    p.set_defaults(func=run)


def run(args) -> int:
    from graphmethods.problems.builtin import listing

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
