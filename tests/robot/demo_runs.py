"""Demonstration runs shared by the episode, demos and CLI tests, each made once per test session (an episode takes
seconds): a batch over two scene folders, the small scene (the mug is within reach) and a far scene (a 1.6 x 1.1 m
table whose mug stands at the back, beyond the Panda's reach from the front edge)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from physcensis.robot import demos
from physcensis.robot.episode import EpisodeOptions, Outcome, run_episode
from physcensis.robot.world import RobotWorld
from tests.robot.programs import solved_folder

TASK = "pick cup_0 place-on plate_0"
FAR_SCENE = Path(__file__).with_name("far_scene.json")
NEAR, FAR = "near", "far"  # the batch's scene folder names


@dataclass
class Attempt:
    world: RobotWorld  # as the episode left it
    outcome: Outcome


@dataclass
class BatchRun:
    root: Path  # the scene folders (links to the solved scenes)
    out: Path
    summary: dict[str, Any]
    attempts: dict[str, Attempt]  # by scene folder name


_made: dict[str, Any] = {}


def far_scene_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    if "far" not in _made:
        _made["far"] = solved_folder(FAR_SCENE.name, tmp_path_factory.mktemp("far-scene") / "scene")
    return _made["far"]


def batch_run(small_scene_dir: Path, tmp_path_factory: pytest.TempPathFactory) -> BatchRun:
    """`run_batch` of the task over the near and the far scene, one episode each, no images."""
    if "batch" not in _made:
        root = tmp_path_factory.mktemp("demo-scenes")
        (root / NEAR).symlink_to(small_scene_dir, target_is_directory=True)
        (root / FAR).symlink_to(far_scene_dir(tmp_path_factory), target_is_directory=True)
        out = tmp_path_factory.mktemp("demo-batch") / "out"
        calls: list[Attempt] = []

        def keeping_the_world(world: RobotWorld, task: str, options: EpisodeOptions | None = None) -> Outcome:
            outcome = run_episode(world, task, options)
            calls.append(Attempt(world, outcome))
            return outcome

        with pytest.MonkeyPatch.context() as patch:
            patch.setattr(demos, "run_episode", keeping_the_world)
            summary = demos.run_batch(root, out, demos.DemoSettings(task=TASK, images=None))
        names = [folder.name for folder in demos.scene_folders(root)]  # run in this order, one worker
        _made["batch"] = BatchRun(root, out, summary, dict(zip(names, calls, strict=True)))
    run: BatchRun = _made["batch"]
    return run
