"""Shared fixtures: the reference cases in ../shared/cases, read as they are."""

import json
import os
import pathlib

import pytest
from hypothesis import settings

REPO = pathlib.Path(__file__).resolve().parents[1]
SHARED_CASES = pathlib.Path(os.environ.get("GRAPHMETHODS_SHARED_CASES", REPO.parent / "shared" / "cases"))

settings.register_profile("project", deadline=None, max_examples=60)
# In CI (.ci/run sets CI=1) the examples are the same on every run, so a change lands or not on its
# own merits; on a developer's machine they are random, to keep exploring.
settings.register_profile("project-ci", settings.get_profile("project"), derandomize=True, database=None)
settings.load_profile("project-ci" if os.environ.get("CI") else "project")


def _need_shared():
    if not SHARED_CASES.is_dir():
        msg = f"reference cases not found at {SHARED_CASES} (set GRAPHMETHODS_SHARED_CASES)"
        if os.environ.get("CI"):
            pytest.fail(msg)          # in CI the cases must be there
        pytest.skip(msg)


@pytest.fixture(scope="session")
def shared_cases() -> pathlib.Path:
    """The folder ../shared/cases (skips outside CI when absent, fails in CI)."""
    _need_shared()
    return SHARED_CASES


@pytest.fixture(scope="session")
def worked_examples(shared_cases) -> dict:
    """worked_examples.json as a dict id -> entry."""
    data = json.loads((shared_cases / "worked_examples.json").read_text(encoding="utf-8"))
    return {entry["id"]: entry for entry in data}


@pytest.fixture(scope="session")
def press_case_path(shared_cases) -> pathlib.Path:
    """Path of slider_crank_press.json."""
    return shared_cases / "slider_crank_press.json"
