"""One pick-and-place episode end to end: the mug ends resting on the plate and replays from the file to the same
poses; a mug out of reach and a task naming no object fail with their stage and why, and record nothing."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from physcensis.robot import tasks
from physcensis.robot.demos import DATASET, SCENES
from physcensis.robot.episode import run_episode
from physcensis.robot.record import read_episode, replay
from physcensis.robot.world import RobotWorld, build_world

from .demo_runs import FAR, NEAR, TASK, Attempt, batch_run


@pytest.fixture(scope="module")
def near(small_scene_dir: Path, tmp_path_factory: pytest.TempPathFactory) -> Attempt:
    return batch_run(small_scene_dir, tmp_path_factory).attempts[NEAR]


@pytest.fixture(scope="module")
def far(small_scene_dir: Path, tmp_path_factory: pytest.TempPathFactory) -> Attempt:
    return batch_run(small_scene_dir, tmp_path_factory).attempts[FAR]


def _geoms(model: mujoco.MjModel, body: int) -> set[int]:
    return {
        g
        for g in range(model.ngeom)
        if model.geom_bodyid[g] == body and model.geom_contype[g] | model.geom_conaffinity[g]
    }


def _touching(world: RobotWorld, a: str, b: str) -> bool:
    mine, theirs = _geoms(world.model, world.object_bodies[a]), _geoms(world.model, world.object_bodies[b])
    pairs = {(int(c.geom1), int(c.geom2)) for c in world.data.contact[: world.data.ncon] if c.dist < 0.002}
    return any((g1 in mine and g2 in theirs) or (g1 in theirs and g2 in mine) for g1, g2 in pairs)


def _footprint(world: RobotWorld, name: str) -> tuple[np.ndarray, np.ndarray]:
    """(min xy, max xy) of an object's collision geoms' bounding boxes in the world."""
    model, data = world.model, world.data
    corners = []
    for g in _geoms(model, world.object_bodies[name]):
        centre, half = model.geom_aabb[g, :3], model.geom_aabb[g, 3:]
        box = centre + half * np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)])
        corners.append(data.geom_xpos[g] + box @ data.geom_xmat[g].reshape(3, 3).T)
    points = np.concatenate(corners)
    return points[:, :2].min(axis=0), points[:, :2].max(axis=0)


def test_the_mug_ends_resting_on_the_plate_and_nothing_else_moved(near: Attempt, small_scene_dir: Path) -> None:
    world, outcome = near.world, near.outcome
    assert outcome.success and outcome.stage == "done" and outcome.reason is None, outcome.summary()
    mug = world.object_bodies["cup_0"]
    low, high = _footprint(world, "plate_0")
    assert np.all(world.data.xipos[mug][:2] > low) and np.all(world.data.xipos[mug][:2] < high)  # over the plate
    assert _touching(world, "cup_0", "plate_0")
    assert world.data.xipos[mug][2] > world.data.xipos[world.object_bodies["plate_0"]][2]
    speed = np.abs(world.data.qvel[world.model.jnt_dofadr[world.model.body_jntadr[mug]] :][:6])
    assert speed[:3].max() < 0.01 and speed[3:].max() < 0.1  # at rest
    for other in ("plate_0", "bowl_0"):
        start = world.initial_qpos[world.object_qpos[other] :][:3]
        assert np.linalg.norm(world.object_poses()[other][:3] - start) < 0.005, other
    # the hand let go: no finger touches the mug
    fingers = {b for b in world.robot_bodies if "finger" in world.model.body(b).name}
    hand_geoms = {g for g in range(world.model.ngeom) if world.model.geom_bodyid[g] in fingers}
    mug_geoms = _geoms(world.model, mug)
    contacts = world.data.contact[: world.data.ncon]
    assert not any(
        {int(c.geom1), int(c.geom2)} & hand_geoms and {int(c.geom1), int(c.geom2)} & mug_geoms for c in contacts
    )


def test_the_outcome_times_its_stages_and_records_the_run(near: Attempt) -> None:
    outcome = near.outcome
    assert outcome.seconds["planning"] > 0 and outcome.seconds["execution"] > 0
    assert outcome.seconds["rendering"] == 0  # no images asked for
    episode = outcome.episode
    assert episode is not None and episode.attrs["success"] and episode.attrs["task"] == TASK
    assert episode.num_samples > 100 and episode.front_rgb is None
    assert outcome.summary()["steps"] == episode.num_samples
    # the gripper closed on the mug and opened again
    assert episode.actions[:, 7].min() < 0.01 and episode.actions[-1, 7] > 0.03


def test_the_written_episode_replays_to_the_same_final_poses(
    near: Attempt, small_scene_dir: Path, tmp_path_factory: pytest.TempPathFactory
) -> None:
    out = batch_run(small_scene_dir, tmp_path_factory).out
    episode = read_episode(out / SCENES / NEAR / DATASET, 0)
    final = replay(build_world(small_scene_dir), episode)
    for name, pose in near.world.object_poses().items():
        assert np.allclose(final[name], pose, atol=1e-9), name


def test_a_mug_out_of_reach_fails_at_the_grasp_saying_so(far: Attempt) -> None:
    outcome = far.outcome
    assert not outcome.success and outcome.episode is None
    assert outcome.stage == "grasp"
    assert "cup_0" in str(outcome.reason) and "out of reach" in str(outcome.reason)
    assert outcome.seconds["planning"] > 0 and "execution" not in outcome.seconds


def test_a_task_naming_no_object_fails_at_the_task_with_the_parser_reason(far: Attempt) -> None:
    text = "pick the teapot and place it on the plate"
    with pytest.raises(tasks.TaskError) as parsed:
        tasks.parse_task(text, far.world.scene, far.world.base_yaw, base_position=far.world.base_position.tolist())
    outcome = run_episode(far.world, text)
    assert (outcome.success, outcome.stage, outcome.episode) == (False, "task", None)
    assert outcome.reason == str(parsed.value) and "teapot" in outcome.reason
