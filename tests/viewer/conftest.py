from __future__ import annotations

from pathlib import Path

import pytest

from physcensis.output import write_solution
from physcensis.program.parser import load_program
from physcensis.solver.pipeline import solve

HERE = Path(__file__).parent


@pytest.fixture(scope="session")
def scene_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A mug on a book and a bowl on a 0.8 x 0.6 m table, solved and written with its MJCF export once per session
    (the export is what a robot episode's world is built from)."""
    solution = solve(load_program(HERE / "mug_on_book.json"), seed=0)
    assert solution.ok, solution.report()
    out = tmp_path_factory.mktemp("viewer-scene") / "scene"
    write_solution(solution, out, exports=("mjcf",))
    return out
