"""The one control primitive that execution and replay share: an 8-number action held for one control period.

An action is the 7 arm joint targets (rad) and the gripper opening per finger (m). Applying it writes the position
servos' controls and steps the physics CONTROL_STEPS times, so a recorded list of actions replays the same motion.
"""

from __future__ import annotations

from collections.abc import Callable

import mujoco
import numpy as np

from physcensis.errors import PhyscensisError
from physcensis.robot.world import TIMESTEP, RobotWorld

CONTROL_DT = 0.05  # s: actions at 20 Hz
CONTROL_STEPS = round(CONTROL_DT / TIMESTEP)
ACTION_SIZE = 8

ActionCallback = Callable[[np.ndarray], None]


class ActionError(PhyscensisError, ValueError):
    """An action or waypoint array of the wrong shape, or with numbers that are not finite."""


def control_steps(world: RobotWorld) -> int:
    """Physics steps per action for this world's timestep."""
    return max(1, round(CONTROL_DT / float(world.model.opt.timestep)))


def _actuators(world: RobotWorld) -> np.ndarray:
    return np.append(world.arm_actuators, world.gripper_actuator)


def clip_action(world: RobotWorld, action: np.ndarray) -> np.ndarray:
    """The action limited to the actuators' control ranges."""
    action = np.asarray(action, dtype=float).reshape(-1)
    if action.shape != (ACTION_SIZE,):
        raise ActionError(f"an action has {ACTION_SIZE} numbers (7 joint targets, 1 finger opening), got {action.size}")
    if not np.all(np.isfinite(action)):
        raise ActionError(f"an action holds a number that is not finite: {action.tolist()}")
    ranges = world.model.actuator_ctrlrange[_actuators(world)]
    return np.clip(action, ranges[:, 0], ranges[:, 1])


def apply_action(world: RobotWorld, action: np.ndarray) -> None:
    """Set the arm's and gripper's targets to `action` (clipped) and simulate one control period."""
    world.data.ctrl[_actuators(world)] = clip_action(world, action)
    for _ in range(control_steps(world)):
        mujoco.mj_step(world.model, world.data)


def current_action(world: RobotWorld) -> np.ndarray:
    """The targets the servos hold now (arm joint targets and gripper opening)."""
    return world.data.ctrl[_actuators(world)].copy()


def _run(world: RobotWorld, action: np.ndarray, on_action: ActionCallback | None) -> None:
    action = clip_action(world, action)
    if on_action is not None:
        on_action(action.copy())
    apply_action(world, action)


def follow(world: RobotWorld, qs: np.ndarray, gripper: float, on_action: ActionCallback | None = None) -> float:
    """Feed joint waypoints (already spaced at CONTROL_DT) to the arm; the final tracking error (rad, max |dq|)."""
    qs = np.atleast_2d(np.asarray(qs, dtype=float))
    if qs.shape[1] != len(world.arm_actuators):
        raise ActionError(f"waypoints have {qs.shape[1]} joints; the arm has {len(world.arm_actuators)}")
    for q in qs:
        _run(world, np.append(q, gripper), on_action)
    if len(qs) == 0:
        return 0.0
    return float(np.abs(world.data.qpos[world.arm_qpos] - qs[-1]).max())


def _periods(seconds: float) -> int:
    return max(1, int(np.ceil(seconds / CONTROL_DT - 1e-9)))


def move_gripper(world: RobotWorld, opening: float, seconds: float, on_action: ActionCallback | None = None) -> None:
    """Drive the fingers to `opening` (m per finger) for `seconds` while the arm holds its current target."""
    action = current_action(world)
    action[-1] = opening
    for _ in range(_periods(seconds)):
        _run(world, action, on_action)


def settle(world: RobotWorld, seconds: float, on_action: ActionCallback | None = None) -> None:
    """Hold every target for `seconds`, letting the arm and anything it touches come to rest."""
    action = current_action(world)
    for _ in range(_periods(seconds)):
        _run(world, action, on_action)
