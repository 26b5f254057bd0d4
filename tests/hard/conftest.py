"""The hard-case suite: every test here is a named numerically hard case.

Each is marked ``hard`` (run them alone with ``pytest -m hard``) and any warning fails it: a hard
case must give the right answer or a clear error, with no NaN and no warning spam.
"""

import pytest


def pytest_collection_modifyitems(items):
    for item in items:
        if "/tests/hard/" in str(item.fspath).replace("\\", "/"):
            item.add_marker(pytest.mark.hard)
            item.add_marker(pytest.mark.filterwarnings("error"))
