"""Bundled examples solved with physics once per test process, for the modules that only read them."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from physcensis.program import load_program
from physcensis.solver.pipeline import Solution, solve

from ..conftest import EXAMPLES


@pytest.fixture(scope="session")
def solved_example() -> Callable[[str], Solution]:
    """`solved_example(name)`: examples/<name>.json solved with physics at seed 0, the same object for every test
    of the process (the unstable cup's stability search alone takes seconds). Tests read it and never change it."""
    solutions: dict[str, Solution] = {}

    def solved(name: str) -> Solution:
        if name not in solutions:
            solutions[name] = solve(load_program(EXAMPLES / f"{name}.json"), seed=0)
        return solutions[name]

    return solved
