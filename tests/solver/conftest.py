"""Bundled examples solved with physics once per test run, for the modules that only read them."""

from __future__ import annotations

import fcntl
import os
import pickle
from collections.abc import Callable
from pathlib import Path

import pytest

from physcensis.program import load_program
from physcensis.solver.pipeline import Solution, solve

from ..conftest import EXAMPLES


@pytest.fixture(scope="session")
def solved_example(tmp_path_factory: pytest.TempPathFactory) -> Callable[[str], Solution]:
    """`solved_example(name)`: examples/<name>.json solved with physics at seed 0, the same object for every test
    of the process (the unstable cup's stability search alone takes seconds). Tests read it and never change it.
    Under pytest-xdist the workers share it too: the first to ask solves it and leaves it pickled in the run's
    folder, one that asks meanwhile waits for it, and the others load it."""
    if os.environ.get("PYTEST_XDIST_WORKER"):  # the run's folder, above each worker's own
        shared = tmp_path_factory.getbasetemp().parent / "solved-examples"
        shared.mkdir(exist_ok=True)
    else:
        shared = tmp_path_factory.mktemp("solved-examples")
    solutions: dict[str, Solution] = {}

    def solved(name: str) -> Solution:
        if name not in solutions:
            solutions[name] = _solved_once(
                shared / f"{name}.pickle", lambda: solve(load_program(EXAMPLES / f"{name}.json"), seed=0)
            )
        return solutions[name]

    return solved


def _solved_once(path: Path, solution: Callable[[], Solution]) -> Solution:
    """The solution pickled at `path`, made and written there first by whichever process asks first."""
    with open(path.with_suffix(".lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # released when the file closes
        if path.is_file():
            loaded: Solution = pickle.loads(path.read_bytes())
            return loaded
        made = solution()
        partial = path.with_suffix(".partial")
        partial.write_bytes(pickle.dumps(made))
        partial.replace(path)
        return made
