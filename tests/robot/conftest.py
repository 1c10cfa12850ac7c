from __future__ import annotations

from pathlib import Path

import pytest

from tests.robot.programs import solved_folder


@pytest.fixture(scope="session")
def small_scene_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A 0.9 x 0.6 m table with a plate, a mug and a bowl, solved and exported (MJCF) once per test session."""
    return solved_folder("small_scene.json", tmp_path_factory.mktemp("robot-scene") / "scene")
