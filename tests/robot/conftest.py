from __future__ import annotations

from pathlib import Path

import pytest

from physcensis.output import write_solution
from physcensis.program.parser import load_program
from physcensis.solver.pipeline import solve

SMALL_SCENE = Path(__file__).with_name("small_scene.json")


@pytest.fixture(scope="session")
def small_scene_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A 0.9 x 0.6 m table with a plate, a mug and a bowl, solved and exported (MJCF) once per test session."""
    out = tmp_path_factory.mktemp("robot-scene") / "scene"
    solution = solve(load_program(SMALL_SCENE), seed=0)
    assert solution.ok, solution.report()
    write_solution(solution, out, exports=("mjcf",))
    return out
