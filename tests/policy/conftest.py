from __future__ import annotations

from pathlib import Path

import pytest

from physcensis.robot import demos
from tests.robot.programs import solved_folder

TASK = "pick cup_0 place-on plate_0"


@pytest.fixture(scope="session")
def scene_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The robot tests' small scene (a plate, a mug, a bowl on a 0.9 x 0.6 m table), solved once per session."""
    return solved_folder("small_scene.json", tmp_path_factory.mktemp("policy-scene") / "scene")


@pytest.fixture(scope="session")
def dataset(scene_dir: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """One recorded, verified demonstration of the task on the small scene, without camera frames."""
    out = tmp_path_factory.mktemp("policy-demo") / "demo"
    report = demos.run_scene(scene_dir, out, demos.DemoSettings(task=TASK, images=None))
    assert report["succeeded"] == 1, report
    return out / demos.DATASET
