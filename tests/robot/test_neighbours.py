"""Picking one mug of two standing a few centimetres apart: the grasp must not close on the neighbour too (a finger
that goes down inside the other mug pulls its wall along, and both leave the table together)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from physcensis.robot.episode import EpisodeOptions, run_episode
from physcensis.robot.world import build_world

from .programs import solved_folder


@pytest.fixture(scope="module")
def mugs_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return solved_folder("mugs_scene.json", tmp_path_factory.mktemp("mugs") / "scene")


@pytest.mark.slow
@pytest.mark.long
def test_picking_a_mug_leaves_its_neighbour_standing(mugs_dir: Path) -> None:
    world = build_world(mugs_dir)
    start = world.object_poses()["mug_1"]
    gap = np.linalg.norm(start[:2] - world.object_poses()["mug_0"][:2])
    assert gap < 0.11  # centres under 11 cm apart: the open hand (8 cm) straddles the gap between them
    outcome = run_episode(world, "pick mug_0 place-in bowl_0", EpisodeOptions(seed=0, images=None))
    moved = float(np.linalg.norm(world.object_poses()["mug_1"][:3] - start[:3]))
    assert moved < 0.02, f"mug_1 moved {moved * 100:.1f} cm ({outcome.stage}: {outcome.reason})"
