"""IK for the Panda's TCP on a real scene: reaches what it can, explains what it cannot."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from physcensis.robot.collision import CollisionChecker
from physcensis.robot.ik import linear_path, solve_ik
from physcensis.robot.world import RobotWorld, build_world

DOWN = np.diag([1.0, -1.0, -1.0])  # the hand's approach axis (+z) pointing at the floor


@pytest.fixture(scope="module")
def world(small_scene_dir: Path) -> RobotWorld:
    return build_world(small_scene_dir)


def _world_fk(world: RobotWorld, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    data = mujoco.MjData(world.model)
    data.qpos[:] = world.data.qpos
    data.qpos[world.arm_qpos] = q
    mujoco.mj_kinematics(world.model, data)
    return data.site_xpos[world.tcp_site].copy(), data.site_xmat[world.tcp_site].reshape(3, 3)


def _yawed(angle: float) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return DOWN @ np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def test_ik_reaches_a_pose_above_the_mug(world: RobotWorld) -> None:
    cup, _ = world.object_pose("cup_0")
    target, rotation = cup + np.array([0.0, 0.0, 0.18]), _yawed(0.7)
    result = solve_ik(world, target, rotation, checker=CollisionChecker(world))
    assert result.q is not None, result.reason
    position, reached = _world_fk(world, result.q)
    assert np.linalg.norm(position - target) < 0.005
    assert np.degrees(np.arccos(np.clip((np.trace(rotation.T @ reached) - 1) / 2, -1, 1))) < 2.0
    limits = world.arm_limits
    assert np.all(result.q >= limits[:, 0]) and np.all(result.q <= limits[:, 1])
    again = solve_ik(world, target, rotation, checker=CollisionChecker(world))
    assert again.q is not None and np.array_equal(again.q, result.q)  # deterministic


def test_ik_says_why_it_fails(world: RobotWorld) -> None:
    far = solve_ik(world, world.base_position + np.array([0.0, 2.0, 0.2]), DOWN)
    assert far.q is None and far.reason is not None and far.reason.startswith("out of reach")
    assert far.position_error > 1.0
    inside = world.object_pose("plate_0")[0] + np.array([0.05, 0.0, -0.03])  # 3 cm into the table top
    sunk = solve_ik(world, inside, DOWN, checker=CollisionChecker(world), restarts=3)
    assert sunk.q is None and sunk.reason is not None
    assert sunk.reason.startswith("every solution collides") and "support" in sunk.reason
    assert solve_ik(world, inside, DOWN).q is not None  # reachable without the checker: the table is the reason


def test_linear_path_keeps_the_tcp_on_a_straight_line(world: RobotWorld) -> None:
    cup, _ = world.object_pose("cup_0")
    above = solve_ik(world, cup + np.array([0.0, 0.0, 0.2]), DOWN)
    assert above.q is not None
    start, rotation = _world_fk(world, above.q)
    path = linear_path(world, above.q, np.array([0.0, 0.0, -0.06]), 6, checker=CollisionChecker(world))
    assert isinstance(path, np.ndarray), path
    assert path.shape == (7, 7) and np.array_equal(path[0], above.q)
    for k, q in enumerate(path):
        position, reached = _world_fk(world, q)
        assert np.linalg.norm(position - (start + np.array([0.0, 0.0, -0.01 * k]))) < 0.003
        assert np.abs(reached - rotation).max() < 0.01
    into_table = linear_path(world, above.q, np.array([0.0, 0.0, -0.35]), 10, checker=CollisionChecker(world))
    assert isinstance(into_table, str) and "cup_0" in into_table
