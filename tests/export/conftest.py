from __future__ import annotations

import pytest

from physcensis.scene import Scene
from physcensis.solver.pipeline import solve
from tests.conftest import EXAMPLES


@pytest.fixture(scope="session")
def desk_scene() -> Scene:
    """`desk_basic.json` solved with physics: a laptop, a notebook and a mug resting on a table."""
    solution = solve(EXAMPLES / "desk_basic.json", seed=0)
    assert solution.ok and len(solution.scene.placed) == 3
    return solution.scene
