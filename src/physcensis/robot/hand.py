"""The Panda hand alone, free-floating: for grasp tests without the arm.

The hand and its fingers come from `panda.panda_spec()` (meshes, the finger coupling, the `gripper` actuator). The hand
body has a free joint and a mocap body pulls it through a stiff weld, so a test moves the hand by moving the mocap and
the fingers still meet the object with ordinary contact forces. Gravity is compensated on the hand, like on the arm.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import mujoco
import numpy as np

from physcensis.robot import panda

PREFIX = "gripper/"
MOCAP_BODY = "hand_target"
WELD_SOLREF = (0.01, 1.0)  # a stiff but soft weld: the hand follows the target within millimetres


def tcp_T_hand() -> np.ndarray:
    """The hand body's frame seen from the TCP (same orientation, the TCP sits on the hand's +z)."""
    matrix = np.eye(4)
    matrix[2, 3] = -panda.TCP_OFFSET
    return matrix


def add_free_hand(spec: mujoco.MjSpec) -> None:
    """Add the hand under `PREFIX`, a free joint on it, and the mocap body `MOCAP_BODY` welded to it."""
    source = panda.panda_spec()
    frame = spec.worldbody.add_frame()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        hand = frame.attach_body(source.body(panda.HAND_BODY), PREFIX, "")
    hand.pos = [0.0, 0.0, 0.0]
    hand.quat = [1.0, 0.0, 0.0, 0.0]
    hand.add_freejoint(name=PREFIX + "free")
    spec.worldbody.add_body(name=MOCAP_BODY, mocap=True)
    weld = spec.add_equality(
        type=mujoco.mjtEq.mjEQ_WELD,
        objtype=mujoco.mjtObj.mjOBJ_BODY,
        name1=MOCAP_BODY,
        name2=PREFIX + panda.HAND_BODY,
        data=[0.0, 0.0, 0.0] + [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0] + [1.0, 0.0],
    )
    weld.solref = list(WELD_SOLREF)


@dataclass(frozen=True)
class HandIndex:
    """Where the free hand lives in a compiled model."""

    hand_body: int
    mocap: int  # index into data.mocap_pos
    hand_qpos: int  # address of the hand's free joint (7 numbers)
    finger_qpos: np.ndarray
    gripper: int  # actuator id
    geoms: frozenset[int]  # the hand's and fingers' collision geoms

    @classmethod
    def of(cls, model: mujoco.MjModel) -> HandIndex:
        hand = int(model.body(PREFIX + panda.HAND_BODY).id)
        fingers = [int(model.joint(PREFIX + name).id) for name in panda.FINGER_JOINTS]
        bodies = {hand, *(int(model.body(PREFIX + name).id) for name in panda.FINGER_BODIES)}
        geoms = frozenset(g for g in range(model.ngeom) if int(model.geom_bodyid[g]) in bodies)
        return cls(
            hand_body=hand,
            mocap=int(model.body_mocapid[model.body(MOCAP_BODY).id]),
            hand_qpos=int(model.jnt_qposadr[model.body_jntadr[hand]]),
            finger_qpos=model.jnt_qposadr[fingers].copy(),
            gripper=int(model.actuator(PREFIX + panda.GRIPPER_ACTUATOR).id),
            geoms=geoms,
        )


def pose_to_qpos(matrix: np.ndarray) -> np.ndarray:
    """A 4x4 pose as 7 numbers: position and wxyz quaternion."""
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.ascontiguousarray(matrix[:3, :3]).ravel())
    return np.concatenate([matrix[:3, 3], quat])


def qpos_to_pose(values: np.ndarray) -> np.ndarray:
    """7 numbers (position, wxyz quaternion) as a 4x4 pose."""
    matrix = np.eye(4)
    rotation = np.zeros(9)
    mujoco.mju_quat2Mat(rotation, np.asarray(values[3:7], dtype=float))
    matrix[:3, :3] = rotation.reshape(3, 3)
    matrix[:3, 3] = values[:3]
    return matrix


def place_hand(
    model: mujoco.MjModel, data: mujoco.MjData, index: HandIndex, world_T_tcp: np.ndarray, opening: float
) -> None:
    """Put the hand (and its mocap target) with its TCP at `world_T_tcp`, each finger `opening` metres out, at rest."""
    pose = pose_to_qpos(world_T_tcp @ tcp_T_hand())
    data.qpos[index.hand_qpos : index.hand_qpos + 7] = pose
    data.qpos[index.finger_qpos] = opening
    data.mocap_pos[index.mocap] = pose[:3]
    data.mocap_quat[index.mocap] = pose[3:]
    data.ctrl[index.gripper] = opening
