"""A Gymnasium environment on generated scenes: the Panda of the demonstrations picks one object and puts it on or in
another, `physcensis/PickPlace-v0`.

    import gymnasium, physcensis.robot.env
    task = "pick the leftmost cup place-on the rightmost plate"
    env = gymnasium.make("physcensis/PickPlace-v0", scenes="data/tabletops/scenes", task=task)
    obs, info = env.reset(seed=0)

`scenes` is one scene folder (with its `mjcf/` export) or a folder of them; with several, each `reset(seed=...)` draws
one, so a seeded run sees the same scenes in the same order. The task is read in each scene as the demonstrations read
it (`robot/tasks.py`: ids, or words such as "the leftmost cup"). Actions are what the recorded demonstrations hold: the
7 arm joint targets (rad) and the gripper opening per finger (m), held for one 20 Hz control period
(`robot/control.py`), so a dataset's actions replay here. Observations are the demonstrations' low-dimensional
channels, with the poses of the two task objects instead of every object's (a policy then sees the same shape in every
scene), and optionally the front and wrist cameras. The reward is 1 on the step the task's verifier (the one that
judges the demonstrations, `robot/verify.py`) first finds it done, which terminates the episode; `max_steps` truncates.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, cast

import gymnasium
import mujoco
import numpy as np
from gymnasium import spaces

from physcensis.errors import PhyscensisError
from physcensis.robot import tasks
from physcensis.robot.control import ACTION_SIZE, apply_action, current_action
from physcensis.robot.panda import Mount
from physcensis.robot.record import camera_renderer
from physcensis.robot.verify import verify_primitive
from physcensis.robot.world import FRONT_CAMERA, WRIST_CAMERA, RobotWorld, build_world

ENV_ID = "physcensis/PickPlace-v0"
DEFAULT_MAX_STEPS = 600  # 30 s at 20 Hz: a recorded demonstration takes 10 to 20 s
CAMERAS = (FRONT_CAMERA, WRIST_CAMERA)
RENDER_SIZE = (480, 640)  # (height, width) of `render()` for people


class EnvError(PhyscensisError):
    """An environment that cannot be made: no scene folder, a task no scene can do."""


def scene_folders(scenes: str | Path) -> list[Path]:
    """The scene folders `scenes` names: itself when it holds a scene.json, else the folders below it that do."""
    root = Path(scenes)
    if (root / "scene.json").is_file():
        return [root]
    found = sorted(p.parent for p in root.glob("*/scene.json")) if root.is_dir() else []
    if not found:
        raise EnvError(f"{root}: no scene.json there or in the folders below it")
    return found


class PickPlaceEnv(gymnasium.Env[dict[str, np.ndarray], np.ndarray]):
    """Pick-and-place on generated scenes (see the module's description)."""

    metadata = {"render_modes": ["rgb_array"], "render_fps": 20}

    def __init__(
        self,
        scenes: str | Path,
        task: str,
        *,
        max_steps: int = DEFAULT_MAX_STEPS,
        images: tuple[int, int] | None = None,
        render_mode: str | None = None,
        mount: Mount | None = None,
    ) -> None:
        if render_mode not in (None, "rgb_array"):
            raise EnvError(f"render_mode {render_mode!r}: give rgb_array or none")
        if max_steps < 1:
            raise EnvError(f"max_steps {max_steps}: give 1 or more")
        self.folders = scene_folders(scenes)
        self.task_text = task
        self.max_steps = max_steps
        self.images = images  # (height, width) of the camera observations; None: none
        self.render_mode = render_mode
        self.mount = mount  # where the arm stands (robot/panda.py's Mount; None: as `demo` puts it by default)
        self._worlds: dict[Path, RobotWorld] = {}
        self.folder = self.folders[0]  # the scene folder of the world in use
        self.world = self._world(self.folder)
        self.task = self._task(self.world, self.folder)
        ranges = self.world.model.actuator_ctrlrange[np.append(self.world.arm_actuators, self.world.gripper_actuator)]
        self.action_space = spaces.Box(ranges[:, 0], ranges[:, 1], (ACTION_SIZE,), np.float64)
        self.observation_space = cast("spaces.Space[dict[str, np.ndarray]]", self._observation_space())
        self.steps = 0
        self._before: dict[str, np.ndarray] = {}
        self._renderers: dict[tuple[int, tuple[int, int]], mujoco.Renderer] = {}  # (world, size): one per model

    # -- the Gymnasium API ---------------------------------------------------------------------------------------------

    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[dict[str, np.ndarray], dict[str, Any]]:
        super().reset(seed=seed)
        folder = self.folders[int(self.np_random.integers(len(self.folders)))] if len(self.folders) > 1 else None
        if folder is not None:
            self.folder = folder
            self.world = self._world(folder)
            self.task = self._task(self.world, folder)
        self.world.reset()
        self.steps = 0
        self._before = self.world.object_poses()
        return self._observation(), self._info(done=False)

    def step(self, action: np.ndarray) -> tuple[dict[str, np.ndarray], float, bool, bool, dict[str, Any]]:
        apply_action(self.world, np.asarray(action, dtype=float))
        self.steps += 1
        done = verify_primitive(self.world, self.task, self._before).ok
        truncated = not done and self.steps >= self.max_steps
        return self._observation(), float(done), done, truncated, self._info(done)

    def render(self) -> np.ndarray | None:
        if self.render_mode != "rgb_array":
            return None
        return self._camera(FRONT_CAMERA, RENDER_SIZE)

    def close(self) -> None:
        for renderer in self._renderers.values():
            renderer.close()
        self._renderers.clear()

    # -- the parts -----------------------------------------------------------------------------------------------------

    def _world(self, folder: Path) -> RobotWorld:
        if folder not in self._worlds:
            self._worlds[folder] = build_world(folder, self.mount)
        return self._worlds[folder]

    def _task(self, world: RobotWorld, folder: Path) -> tasks.Task:
        try:
            return tasks.parse_task(
                self.task_text, world.scene, world.base_yaw, base_position=world.base_position.tolist()
            )
        except tasks.TaskError as exc:
            raise EnvError(f"{folder}: {exc}") from None

    def _observation_space(self) -> spaces.Dict:
        def box(*shape: int) -> spaces.Box:
            return spaces.Box(-np.inf, np.inf, shape, np.float64)

        channels: dict[str, spaces.Space[Any]] = {
            "joint_pos": box(7),
            "joint_vel": box(7),
            "eef_pos": box(3),
            "eef_quat": box(4),
            "gripper_qpos": box(2),
            "gripper_target": box(1),
            "pick_pose": box(7),
            "target_pose": box(7),
        }
        if self.images is not None:
            for camera in CAMERAS:
                channels[f"{camera}_rgb"] = spaces.Box(0, 255, (*self.images, 3), np.uint8)
        return spaces.Dict(channels)

    def _observation(self) -> dict[str, np.ndarray]:
        world, data = self.world, self.world.data
        mujoco.mj_kinematics(world.model, data)
        quat = np.zeros(4)
        mujoco.mju_mat2Quat(quat, data.site_xmat[world.tcp_site])
        poses = world.object_poses()
        obs = {
            "joint_pos": data.qpos[world.arm_qpos].copy(),
            "joint_vel": data.qvel[world.arm_dof].copy(),
            "eef_pos": data.site_xpos[world.tcp_site].copy(),
            "eef_quat": quat,
            "gripper_qpos": data.qpos[world.finger_qpos].copy(),
            "gripper_target": current_action(world)[-1:].copy(),
            "pick_pose": np.asarray(poses[self.task.pick], dtype=np.float64),
            "target_pose": np.asarray(poses[self.task.target], dtype=np.float64),
        }
        if self.images is not None:
            for camera in CAMERAS:
                obs[f"{camera}_rgb"] = self._camera(camera, self.images)
        return obs

    def _info(self, done: bool) -> dict[str, Any]:
        return {"task": self.task.explicit, "scene": str(self.folder), "success": done, "steps": self.steps}

    def _camera(self, camera: str, size: tuple[int, int]) -> np.ndarray:
        key = (id(self.world), size)
        renderer = self._renderers.get(key)
        if renderer is None:
            renderer = self._renderers[key] = camera_renderer(self.world.model, size, fast=True)
        renderer.update_scene(self.world.data, camera=camera)
        return renderer.render().copy()


gymnasium.register(id=ENV_ID, entry_point="physcensis.robot.env:PickPlaceEnv")
