"""The control primitive: deterministic, clipped, and the arm tracks a retimed path."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from physcensis.robot import panda
from physcensis.robot.control import CONTROL_STEPS, ActionError, apply_action, follow, move_gripper, settle
from physcensis.robot.world import RobotWorld, build_world


@pytest.fixture(scope="module")
def world(small_scene_dir: Path) -> RobotWorld:
    return build_world(small_scene_dir)


def test_apply_action_is_deterministic_and_clipped(world: RobotWorld) -> None:
    assert CONTROL_STEPS == 25
    action = np.append(panda.HOME_Q + np.array([0.2, 0.1, -0.1, 0.15, 0.0, -0.1, 0.3]), 9.0)  # gripper beyond range
    runs = []
    for _ in range(2):
        world.reset()
        for _ in range(4):
            apply_action(world, action)
        runs.append(world.data.qpos.copy())
    assert np.array_equal(runs[0], runs[1])
    assert world.data.ctrl[world.gripper_actuator] == panda.FINGER_OPEN
    assert np.abs(world.data.qpos[world.arm_qpos] - panda.HOME_Q).max() > 0.05  # it moved
    with pytest.raises(ActionError, match="not finite"):
        apply_action(world, np.full(8, np.nan))
    with pytest.raises(ActionError, match="8 numbers"):
        apply_action(world, panda.HOME_Q)


def test_follow_tracks_a_smooth_path_and_logs_each_action_first(world: RobotWorld) -> None:
    world.reset()
    goal = panda.HOME_Q + np.array([0.4, 0.2, 0.0, 0.3, 0.2, -0.2, 0.0])
    s = np.linspace(0.0, 1.0, 41)
    blend = 3 * s**2 - 2 * s**3  # 2 s, smooth start and stop
    qs = panda.HOME_Q + blend[:, None] * (goal - panda.HOME_Q)
    logged: list[np.ndarray] = []
    error = follow(world, qs, panda.FINGER_OPEN, on_action=logged.append)
    assert len(logged) == len(qs)
    assert np.allclose(logged[-1][:7], goal)
    settle(world, 0.3)
    assert error < 0.02
    assert np.abs(world.data.qpos[world.arm_qpos] - goal).max() < 0.003
    move_gripper(world, panda.FINGER_CLOSED, 0.5)
    assert world.data.qpos[world.finger_qpos].max() < 0.002
    assert np.abs(world.data.ctrl[world.arm_actuators] - goal).max() < 1e-12  # the arm held its target
