"""Print pip constraints that pin every runtime dependency of pyproject.toml to its declared floor.

    python .ci/floors.py > floors.txt && pip install -c floors.txt '.[test]'

A requirement "name>=X[; marker]" becomes "name==X[; marker]"; CI installs them in a fresh virtual
environment (on the oldest Python we support) and runs the tests, so the floors we declare are tested.
"""

import pathlib
import re
import sys

try:
    import tomllib
except ModuleNotFoundError:          # Python 3.10
    import tomli as tomllib

project = tomllib.loads((pathlib.Path(__file__).parents[1] / "pyproject.toml").read_text(encoding="utf-8"))["project"]
for req in project["dependencies"]:
    spec, _, marker = req.partition(";")
    m = re.fullmatch(r"\s*([A-Za-z0-9_.-]+)\s*>=\s*([0-9][0-9A-Za-z.]*)\s*", spec)
    if not m:
        sys.exit(f"{req!r}: every runtime dependency needs a floor (name>=X) for the floors test")
    print(f"{m.group(1)}=={m.group(2)}" + (f"; {marker.strip()}" if marker.strip() else ""))
