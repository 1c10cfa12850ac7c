"""What a policy sees and what it outputs, the same for recorded demonstrations and for the Gymnasium environment.

Observations are the environment's low-dimensional channels (`robot/env.py`): the arm's joints, the end effector,
the fingers, the gripper's target and the two task objects' poses, plus two differences that a policy would otherwise
have to learn to subtract: the pick object from the end effector and the target from the pick object. A recorded
episode holds every object's pose and the actions; its pick and target poses, and the gripper's target before each
action, are derived from them here, so the training data and a rollout are the same function of the world.

Actions are the environment's (7 joint targets in rad, the finger opening in m). The policy predicts the joint
targets relative to the joints now (the step a position servo is asked to make) and the finger opening as it is,
each scaled to [-1, 1] over the training data's range: robomimic's BC squashes its outputs with tanh.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from physcensis.robot.panda import FINGER_OPEN
from physcensis.robot.record import Episode

ENV_KEYS = (
    "joint_pos",
    "joint_vel",
    "eef_pos",
    "eef_quat",
    "gripper_qpos",
    "gripper_target",
    "pick_pose",
    "target_pose",
)
DERIVED_KEYS = ("pick_from_eef", "target_from_pick")
OBS_KEYS = ENV_KEYS + DERIVED_KEYS
ARM = 7  # joint targets; the 8th number is the finger opening
_EXPLICIT_TASK = re.compile(r"^pick (\S+) place-(?:on|in) (\S+)$")


def with_derived(obs: Mapping[str, np.ndarray]) -> dict[str, np.ndarray]:
    """The environment's channels (one step, or N steps stacked on the first axis) and the derived differences, as
    float32 arrays."""
    out = {key: np.asarray(obs[key], dtype=np.float32) for key in ENV_KEYS}
    out["pick_from_eef"] = out["pick_pose"][..., :3] - out["eef_pos"]
    out["target_from_pick"] = out["target_pose"][..., :3] - out["pick_pose"][..., :3]
    return out


def task_objects(explicit_task: str) -> tuple[str, str]:
    """(pick, target) ids of a task in its explicit form, as an episode records it: 'pick cup_0 place-on plate_2'."""
    match = _EXPLICIT_TASK.match(explicit_task.strip())
    if match is None:
        raise ValueError(f"{explicit_task!r} is not a task in explicit form ('pick A place-on B')")
    return match[1], match[2]


def episode_observations(episode: Episode) -> dict[str, np.ndarray]:
    """The observations the environment would have given at each of the episode's steps, (N, ...) per key."""
    pick, target = task_objects(str(episode.attrs["task"]))
    missing = {pick, target} - set(episode.object_ids)
    if missing:
        raise ValueError(f"the episode's task names {sorted(missing)}, which its object poses do not hold")
    poses = episode.obs["object_poses"]
    targets = np.concatenate([[FINGER_OPEN], episode.actions[:-1, ARM]]) if episode.num_samples else np.zeros(0)
    channels = {key: episode.obs[key] for key in ("joint_pos", "joint_vel", "eef_pos", "eef_quat", "gripper_qpos")}
    channels["gripper_target"] = targets[:, None]
    channels["pick_pose"] = poses[:, episode.object_ids.index(pick)]
    channels["target_pose"] = poses[:, episode.object_ids.index(target)]
    return with_derived(channels)


@dataclass(frozen=True)
class ActionScale:
    """The affine map between environment actions and the policy's outputs in [-1, 1] (per action number)."""

    centre: tuple[float, ...]
    half_range: tuple[float, ...]

    @classmethod
    def fit(cls, encoded: np.ndarray, margin: float = 0.05) -> ActionScale:
        """The scale that puts the encoded actions (N, 8) inside [-1 + margin, 1 - margin]-ish."""
        low, high = encoded.min(axis=0), encoded.max(axis=0)
        half = np.maximum((high - low) / 2 * (1 + margin), 1e-6)
        return cls(tuple(((high + low) / 2).tolist()), tuple(half.tolist()))

    def to_dict(self) -> dict[str, Any]:
        return {"centre": list(self.centre), "half_range": list(self.half_range)}

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> ActionScale:
        return cls(tuple(data["centre"]), tuple(data["half_range"]))


def encode_actions(actions: np.ndarray, joint_pos: np.ndarray) -> np.ndarray:
    """Environment actions (N, 8) as the policy predicts them before scaling: joint steps and the finger opening."""
    encoded = np.asarray(actions, dtype=np.float64).copy()
    encoded[..., :ARM] -= joint_pos
    return encoded


def decode_action(scaled: np.ndarray, joint_pos: np.ndarray, scale: ActionScale) -> np.ndarray:
    """The environment action for one policy output in [-1, 1] at the joints `joint_pos`."""
    encoded = np.asarray(scaled, dtype=np.float64) * np.asarray(scale.half_range) + np.asarray(scale.centre)
    encoded[:ARM] += joint_pos
    return encoded


def scale_actions(encoded: np.ndarray, scale: ActionScale) -> np.ndarray:
    return ((encoded - np.asarray(scale.centre)) / np.asarray(scale.half_range)).astype(np.float32)
