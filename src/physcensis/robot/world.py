"""A scene folder with the Panda mounted at its support's edge: one MuJoCo model, and the indices every stage needs.

The scene comes from the folder's own MJCF export (what a user loads elsewhere), so the objects keep the masses,
friction and collision parts they were solved with; the robot is attached with MjSpec under the `panda/` prefix.
The folder is untrusted: its files are read with bounds and the export must belong to its scene.json (the same
objects at the same poses, and unchanged since it was written when exports.json records it), else it is refused.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TypeVar

import mujoco
import numpy as np

from physcensis.errors import ExportMismatchError
from physcensis.export.manifest import Pose, read_folder_scene
from physcensis.export.mjcf_read import XML_FILE, MjcfExport, check_poses, read_mjcf
from physcensis.robot import panda
from physcensis.robot.panda import Mount, RobotModelError
from physcensis.scene import Scene
from physcensis.solver.objects import yaw_quaternion

T = TypeVar("T")
PREFIX = "panda/"
FRONT_CAMERA = "front"
WRIST_CAMERA = "wrist"
TIMESTEP = 0.002  # the arm's position servos need a finer step than the scene's settle


@dataclass
class RobotWorld:
    """The compiled scene-plus-robot and where each part lives in it."""

    model: mujoco.MjModel
    data: mujoco.MjData
    scene: Scene
    base_position: np.ndarray
    base_yaw: float
    arm_qpos: np.ndarray  # qpos addresses of the 7 arm joints
    arm_dof: np.ndarray  # dof addresses of the 7 arm joints
    arm_actuators: np.ndarray
    gripper_actuator: int
    finger_qpos: np.ndarray  # qpos addresses of the two finger joints
    tcp_site: int
    hand_body: int
    robot_bodies: frozenset[int]
    object_bodies: dict[str, int]  # scene object id -> body id
    object_qpos: dict[str, int]  # scene object id -> qpos address of its free joint (7 numbers)
    initial_qpos: np.ndarray = field(repr=False)

    @property
    def arm_limits(self) -> np.ndarray:
        """(7, 2) joint ranges of the arm."""
        joints = self.model.dof_jntid[self.arm_dof]
        return self.model.jnt_range[joints].copy()

    def reset(self) -> None:
        """Objects back to the scene's poses, arm at home, gripper open, nothing moving."""
        mujoco.mj_resetData(self.model, self.data)
        self.data.qpos[:] = self.initial_qpos
        self.data.ctrl[self.arm_actuators] = panda.HOME_Q
        self.data.ctrl[self.gripper_actuator] = panda.FINGER_OPEN
        mujoco.mj_forward(self.model, self.data)

    def object_pose(self, object_id: str) -> tuple[np.ndarray, np.ndarray]:
        """(position, wxyz quaternion) of a scene object now."""
        address = self.object_qpos[object_id]
        return self.data.qpos[address : address + 3].copy(), self.data.qpos[address + 3 : address + 7].copy()

    def object_poses(self) -> dict[str, np.ndarray]:
        """Every scene object's 7-number pose now."""
        return {name: self.data.qpos[a : a + 7].copy() for name, a in self.object_qpos.items()}

    def tcp_pose(self) -> tuple[np.ndarray, np.ndarray]:
        """(position, 3x3 rotation) of the tool centre point between the fingertips."""
        return self.data.site_xpos[self.tcp_site].copy(), self.data.site_xmat[self.tcp_site].reshape(3, 3).copy()


def _mount(spec: mujoco.MjSpec, position: np.ndarray, yaw: float) -> None:
    half = panda.PEDESTAL_SIZE
    if position[2] > 0.0:
        spec.worldbody.add_geom(
            name="panda_pedestal",
            type=mujoco.mjtGeom.mjGEOM_BOX,
            size=[half[0], half[1], position[2] / 2.0],
            pos=[position[0], position[1], position[2] / 2.0],
            quat=list(yaw_quaternion(yaw)),
            rgba=[0.35, 0.36, 0.38, 1.0],
        )
    frame = spec.worldbody.add_frame(pos=position.tolist(), quat=list(yaw_quaternion(yaw)))
    robot = panda.panda_spec()
    spec.attach(robot, prefix=PREFIX, frame=frame)


def _look_quat(forward: np.ndarray, up_hint: np.ndarray) -> list[float]:
    """A camera's wxyz quaternion looking along `forward` (its -z) with `up_hint` roughly up in the image."""
    back = -forward / np.linalg.norm(forward)
    right = np.cross(up_hint, back)
    right /= np.linalg.norm(right)
    up = np.cross(back, right)
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.column_stack([right, up, back]).ravel())
    return quat.tolist()


def _cameras(spec: mujoco.MjSpec, scene: Scene, position: np.ndarray, yaw: float) -> None:
    top = scene.support.top_height
    # Across the support from the robot, looking at the work area and the arm.
    facing = np.array([np.cos(yaw), np.sin(yaw), 0.0])
    across = abs(facing[0]) * scene.support.size[0] + abs(facing[1]) * scene.support.size[1]
    eye = position + facing * (across + 0.6) + np.array([0.0, 0.0, 0.8])
    target = np.array([position[0], position[1], top + 0.2]) + facing * (across * 0.4)
    spec.worldbody.add_camera(
        name=FRONT_CAMERA, pos=eye.tolist(), quat=_look_quat(target - eye, np.array([0.0, 0.0, 1.0])), fovy=60.0
    )
    # On the hand, behind the fingers, looking along the approach axis (the hand's +z) and slightly inwards.
    hand = spec.body(PREFIX + panda.HAND_BODY)
    view = _look_quat(np.array([-0.25, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]))
    hand.add_camera(name=WRIST_CAMERA, pos=[0.07, 0.0, 0.03], quat=view, fovy=80.0)


def read_scene_folder(scene_dir: str | Path) -> tuple[Scene, MjcfExport]:
    """The folder's scene and MJCF export, read with bounds and refused (one line naming the file) unless they belong
    together: what a command checks before it plans or writes anything."""
    folder = Path(scene_dir)
    scene = read_folder_scene(folder)
    if not os.path.lexists(folder / XML_FILE):
        raise RobotModelError(f"{folder} has no mjcf/scene.xml: write the scene with its exports first")
    return scene, read_mjcf(folder, scene)


def build_world(scene_dir: str | Path, mount: Mount | None = None) -> RobotWorld:
    """The scene folder's MJCF with the Panda mounted on its support's edge, compiled and at home."""
    folder = Path(scene_dir)
    scene, export = read_scene_folder(folder)
    spec = _mujoco(folder, lambda: mujoco.MjSpec.from_string(export.xml))
    spec.option.timestep = TIMESTEP
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    position, yaw = (mount or Mount()).pose(scene.support.size, scene.support.top_height)
    _mount(spec, position, yaw)
    _cameras(spec, scene, position, yaw)
    spec.assets = export.assets  # every file the export names, as bytes; given after the arm (MuJoCo warns before)
    model = _mujoco(folder, spec.compile)
    joints = _free_joints(model)
    check_poses(folder, {name: _initial_pose(model, address) for name, address in joints.items()}, scene)
    data = mujoco.MjData(model)
    return _index(model, data, scene, position, yaw, joints)


def _mujoco(folder: Path, load: Callable[[], T]) -> T:
    """MuJoCo's parse or compile of the folder's export, its complaint as one line naming the file."""
    try:
        return load()
    except ValueError as exc:
        reason = " ".join(str(exc).split())[:300]
        raise ExportMismatchError(f"{folder / XML_FILE}: MuJoCo cannot load it ({reason})") from None


def _free_joints(model: mujoco.MjModel) -> dict[str, int]:
    """The qpos address of every free joint outside the arm, by its body's name (the scene's objects, if the export
    is the scene's)."""
    joints = {}
    for joint in np.flatnonzero(model.jnt_type == mujoco.mjtJoint.mjJNT_FREE):
        body = int(model.jnt_bodyid[joint])
        name = model.body(body).name or f"#{body}"
        if not name.startswith(PREFIX):
            joints[name] = int(model.jnt_qposadr[joint])
    return joints


def _initial_pose(model: mujoco.MjModel, address: int) -> Pose:
    """Where the compiled model puts a free body at reset, as MuJoCo reads the file (not as the file is written)."""
    return Pose(tuple(model.qpos0[address : address + 3]), tuple(model.qpos0[address + 3 : address + 7]))


def _index(
    model: mujoco.MjModel, data: mujoco.MjData, scene: Scene, position: np.ndarray, yaw: float, joints: dict[str, int]
) -> RobotWorld:
    def joint(name: str) -> int:
        return int(model.joint(PREFIX + name).id)

    arm_joints = [joint(name) for name in panda.ARM_JOINTS]
    finger_joints = [joint(name) for name in panda.FINGER_JOINTS]
    robot_bodies = frozenset(i for i in range(model.nbody) if model.body(i).name.startswith(PREFIX))
    object_bodies: dict[str, int] = {}
    object_qpos: dict[str, int] = {}
    for placed in scene.placed:  # check_poses made sure each is a free body of the model
        object_bodies[placed.id] = int(model.body(placed.id).id)
        object_qpos[placed.id] = joints[placed.id]
    qpos = data.qpos.copy()
    qpos[model.jnt_qposadr[arm_joints]] = panda.HOME_Q
    qpos[model.jnt_qposadr[finger_joints]] = panda.FINGER_OPEN
    world = RobotWorld(
        model=model,
        data=data,
        scene=scene,
        base_position=position,
        base_yaw=yaw,
        arm_qpos=model.jnt_qposadr[arm_joints].copy(),
        arm_dof=model.jnt_dofadr[arm_joints].copy(),
        arm_actuators=np.array([model.actuator(PREFIX + name).id for name in panda.ARM_ACTUATORS]),
        gripper_actuator=int(model.actuator(PREFIX + panda.GRIPPER_ACTUATOR).id),
        finger_qpos=model.jnt_qposadr[finger_joints].copy(),
        tcp_site=int(model.site(PREFIX + panda.TCP_SITE).id),
        hand_body=int(model.body(PREFIX + panda.HAND_BODY).id),
        robot_bodies=robot_bodies,
        object_bodies=object_bodies,
        object_qpos=object_qpos,
        initial_qpos=qpos,
    )
    world.reset()
    return world
