"""Demonstrations as data: a step-by-step recorder, a robomimic-style HDF5 dataset, and replay of recorded actions.

Layout of the file (robomimic's, plus what an exact replay needs):

    data/                      attrs: total (samples in all episodes), env_args (JSON), state_spec (mjtState bits)
      demo_{k}/                attrs: num_samples, scene, seed, task, success, reason
        obs/joint_pos (N,7)  joint_vel (N,7)  eef_pos (N,3)  eef_quat (N,4 wxyz)  gripper_qpos (N,2)
            object_poses (N,M,7 pos + wxyz; attrs object_ids)  [front_rgb, wrist_rgb (N,H,W,3 uint8, gzip)]
        actions (N,8)  rewards (N,)  dones (N,)  states (N,S: mj_getState, mjSTATE_INTEGRATION)
        final_state (S,)  final_object_poses (M,7)   the world after the last action

Step k holds the observation of the world and the action then applied; `states[0]` restores the start exactly, so
applying `actions` in order with `control.apply_action` reproduces the run bit for bit.
"""

from __future__ import annotations

import json
import os
import tempfile
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from types import TracebackType
from typing import Any

import mujoco
import numpy as np

from physcensis.errors import PhyscensisError
from physcensis.robot.world import FRONT_CAMERA, RobotWorld

STATE_SPEC = mujoco.mjtState.mjSTATE_INTEGRATION  # positions, velocities, controls, warm start: an exact restart
LOW_DIM = ("joint_pos", "joint_vel", "eef_pos", "eef_quat", "gripper_qpos", "object_poses")
IMAGE_SUFFIX = "_rgb"
VLM_IMAGE_SIZE = (480, 640)  # (height, width) of the before/after views a VLM verifier is shown
_ATTRS = ("scene", "seed", "task", "success", "reason")


class RecordError(PhyscensisError):
    """A dataset cannot be written, read or replayed (missing episode, damaged file, empty episode)."""


@dataclass
class Episode:
    """One recorded attempt: N steps of observations and actions, the states to replay it, and its outcome."""

    obs: dict[str, np.ndarray]
    actions: np.ndarray
    rewards: np.ndarray
    dones: np.ndarray
    states: np.ndarray
    object_ids: tuple[str, ...]
    final_state: np.ndarray
    final_poses: np.ndarray  # (M, 7) object poses after the last action, in `object_ids` order
    attrs: dict[str, Any] = field(default_factory=dict)  # scene, seed, task, success, reason

    @property
    def num_samples(self) -> int:
        return int(len(self.actions))

    @property
    def front_rgb(self) -> np.ndarray | None:
        return self.obs.get("front" + IMAGE_SUFFIX)

    @property
    def wrist_rgb(self) -> np.ndarray | None:
        return self.obs.get("wrist" + IMAGE_SUFFIX)

    def final_object_poses(self) -> dict[str, np.ndarray]:
        """Every object's 7-number pose after the last action."""
        return {oid: self.final_poses[i].copy() for i, oid in enumerate(self.object_ids)}


# -- recording ------------------------------------------------------------------------------------------------------


def get_state(world: RobotWorld) -> np.ndarray:
    """The world's full integration state (enough to restart it exactly)."""
    state = np.empty(mujoco.mj_stateSize(world.model, STATE_SPEC))
    mujoco.mj_getState(world.model, world.data, state, STATE_SPEC)
    return state


def set_state(world: RobotWorld, state: np.ndarray) -> None:
    """Put the world into a state from `get_state` and recompute everything derived from it."""
    expected = mujoco.mj_stateSize(world.model, STATE_SPEC)
    if np.shape(state) != (expected,):
        raise RecordError(f"a recorded state has {np.size(state)} numbers; this world's state has {expected}")
    mujoco.mj_setState(world.model, world.data, np.asarray(state, dtype=float), STATE_SPEC)
    mujoco.mj_forward(world.model, world.data)


class EpisodeRecorder:
    """Collects one step per action: call `observe(action)` just before the action is applied (control's
    `on_action`), then `episode(...)` once the run is over."""

    def __init__(
        self,
        world: RobotWorld,
        cameras: tuple[str, ...] = ("front", "wrist"),
        image_size: tuple[int, int] | None = (128, 128),
    ) -> None:
        self.world = world
        self.cameras = tuple(cameras) if image_size is not None else ()
        self.image_size = image_size  # (height, width)
        self.object_ids = tuple(world.object_qpos)
        self.render_seconds = 0.0
        self._steps: dict[str, list[np.ndarray]] = {}
        self._renderers: dict[tuple[int, int], mujoco.Renderer] = {}
        for camera in self.cameras:
            if mujoco.mj_name2id(world.model, mujoco.mjtObj.mjOBJ_CAMERA, camera) < 0:
                raise RecordError(f"the world has no camera {camera!r}")

    def __len__(self) -> int:
        return len(self._steps.get("actions", []))

    def observe(self, action: np.ndarray) -> None:
        """Record the world as it is now and the `action` about to be applied."""
        world = self.world
        mujoco.mj_kinematics(world.model, world.data)  # positions of bodies and sites for the current qpos
        row = {**self._low_dim(world), "actions": np.asarray(action, dtype=float).copy(), "states": get_state(world)}
        for camera in self.cameras:
            assert self.image_size is not None
            row[camera + IMAGE_SUFFIX] = self._render(world.data, camera, self.image_size)
        for name, value in row.items():
            self._steps.setdefault(name, []).append(value)

    def _low_dim(self, world: RobotWorld) -> dict[str, np.ndarray]:
        data = world.data
        quat = np.zeros(4)
        mujoco.mju_mat2Quat(quat, data.site_xmat[world.tcp_site])
        poses = world.object_poses()
        return {
            "joint_pos": data.qpos[world.arm_qpos].copy(),
            "joint_vel": data.qvel[world.arm_dof].copy(),
            "eef_pos": data.site_xpos[world.tcp_site].copy(),
            "eef_quat": quat,
            "gripper_qpos": data.qpos[world.finger_qpos].copy(),
            "object_poses": np.array([poses[oid] for oid in self.object_ids]).reshape(len(self.object_ids), 7),
        }

    def _render(self, data: mujoco.MjData, camera: str, size: tuple[int, int]) -> np.ndarray:
        start = time.perf_counter()
        renderer = self._renderers.get(size)
        if renderer is None:
            renderer = self._renderers[size] = camera_renderer(self.world.model, size, fast=size != VLM_IMAGE_SIZE)
        renderer.update_scene(data, camera=camera)
        frame = renderer.render().copy()
        self.render_seconds += time.perf_counter() - start
        return frame

    def first_frame_png(self, camera: str = FRONT_CAMERA) -> bytes:
        """A PNG of the start of the recording from `camera`, at the size a VLM is shown."""
        if not self._steps:
            raise RecordError("nothing has been recorded yet")
        scratch = mujoco.MjData(self.world.model)
        mujoco.mj_setState(self.world.model, scratch, self._steps["states"][0], STATE_SPEC)
        mujoco.mj_forward(self.world.model, scratch)
        return _png(self._render(scratch, camera, VLM_IMAGE_SIZE))

    def last_frame_png(self, camera: str = FRONT_CAMERA) -> bytes:
        """A PNG of the world now (after the last action) from `camera`, at the size a VLM is shown."""
        mujoco.mj_kinematics(self.world.model, self.world.data)
        return _png(self._render(self.world.data, camera, VLM_IMAGE_SIZE))

    def close(self) -> None:
        for renderer in self._renderers.values():
            renderer.close()
        self._renderers.clear()

    def episode(
        self, task: str = "", success: bool = False, reason: str | None = None, seed: int = 0, scene: str = ""
    ) -> Episode:
        """Everything recorded so far, with the world's state now as the final state, and the outcome's attributes."""
        self.close()
        world = self.world
        n = len(self)
        steps = {name: np.asarray(values) for name, values in self._steps.items()}
        obs = {name: steps.get(name, _empty(name, world, len(self.object_ids))) for name in LOW_DIM}
        obs.update({camera + IMAGE_SUFFIX: steps[camera + IMAGE_SUFFIX] for camera in self.cameras if n})
        rewards, dones = np.zeros(n), np.zeros(n, dtype=np.int64)
        if n:
            rewards[-1] = float(bool(success))
            dones[-1] = 1
        poses = world.object_poses()
        state_size = mujoco.mj_stateSize(world.model, STATE_SPEC)
        return Episode(
            obs=obs,
            actions=steps.get("actions", np.zeros((0, 8))),
            rewards=rewards,
            dones=dones,
            states=steps.get("states", np.zeros((0, state_size))),
            object_ids=self.object_ids,
            final_state=get_state(world),
            final_poses=np.array([poses[oid] for oid in self.object_ids]).reshape(len(self.object_ids), 7),
            attrs={"scene": scene, "seed": int(seed), "task": task, "success": bool(success), "reason": reason or ""},
        )


def _empty(name: str, world: RobotWorld, objects: int) -> np.ndarray:
    widths = {"joint_pos": 7, "joint_vel": 7, "eef_pos": 3, "eef_quat": 4, "gripper_qpos": 2}
    return np.zeros((0, objects, 7)) if name == "object_poses" else np.zeros((0, widths[name]))


MIN_SHADOW_MAP = 512  # texels a side


def camera_renderer(model: mujoco.MjModel, size: tuple[int, int], fast: bool) -> mujoco.Renderer:
    """An offscreen renderer; `fast` drops shadows, reflections and multisampling (with software GL: a tenth of the
    time per frame, then half again)."""
    height, width = size
    if not (16 <= width <= model.vis.global_.offwidth and 16 <= height <= model.vis.global_.offheight):
        raise RecordError(
            f"image size {height}x{width} (height x width) must be between 16x16 and "
            f"{model.vis.global_.offheight}x{model.vis.global_.offwidth}"
        )
    samples, shadow = model.vis.quality.offsamples, model.vis.quality.shadowsize
    if fast:  # multisampling costs half of a small frame with software GL; the buffer is made at creation
        model.vis.quality.offsamples = 0
    # A shadow map twice the frame's size looks the same as MuJoCo's 4096 and costs far less with software GL
    # (a 128 x 96 frame: 52 ms with 4096, 11 ms with none); its buffer too is made at creation.
    model.vis.quality.shadowsize = min(shadow, max(MIN_SHADOW_MAP, 1 << (2 * max(size) - 1).bit_length()))
    try:
        renderer = mujoco.Renderer(model, height, width)
    except Exception as exc:  # any GL failure becomes one clear line
        raise RecordError(
            f"cannot start headless rendering ({exc.__class__.__name__}: {exc}); install libegl1 and set "
            "MUJOCO_GL=egl (or osmesa), or record without images"
        ) from None
    finally:
        model.vis.quality.offsamples, model.vis.quality.shadowsize = samples, shadow
    if fast:
        renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = 0
        renderer.scene.flags[mujoco.mjtRndFlag.mjRND_REFLECTION] = 0
    return renderer


def _png(rgb: np.ndarray) -> bytes:
    import io

    from PIL import Image

    buffer = io.BytesIO()
    Image.fromarray(rgb).save(buffer, format="PNG")
    return buffer.getvalue()


# -- the dataset file -----------------------------------------------------------------------------------------------


class DatasetWriter:
    """Writes episodes to a robomimic-style HDF5 file. The file appears at `path` only when the `with` block ends
    without an error; until then it is a temporary file beside it (removed if anything goes wrong)."""

    def __init__(self, path: str | Path, env_meta: dict[str, Any]) -> None:
        self.path = Path(path)
        self.env_args = json.dumps(env_meta, sort_keys=True, default=str)
        self._file: Any = None
        self._tmp: Path | None = None
        self.count = 0
        self.total = 0

    def __enter__(self) -> DatasetWriter:
        import h5py

        if self.path.is_dir():
            raise RecordError(f"{self.path} is a folder; give the path of the dataset file")
        self.path.parent.mkdir(parents=True, exist_ok=True)
        fd, name = tempfile.mkstemp(prefix=f".{self.path.name}.", suffix=".tmp", dir=self.path.parent)
        os.close(fd)
        self._tmp = Path(name)
        self._file = h5py.File(self._tmp, "w")
        data = self._file.create_group("data")
        data.attrs["env_args"] = self.env_args
        data.attrs["state_spec"] = int(STATE_SPEC)
        data.attrs["total"] = 0
        return self

    def add_episode(self, episode: Episode) -> int:
        """Write `episode` as `data/demo_{k}`; its index k."""
        if self._file is None:
            raise RecordError("the dataset writer is not open: use it in a `with` block")
        k = self.count
        _write_episode(self._file["data"].create_group(f"demo_{k}"), episode)
        self.count += 1
        self.total += episode.num_samples
        self._file["data"].attrs["total"] = self.total
        return k

    def __exit__(
        self, kind: type[BaseException] | None, error: BaseException | None, traceback: TracebackType | None
    ) -> None:
        assert self._tmp is not None
        try:
            self._file.close()
            if kind is None:
                os.chmod(self._tmp, 0o644)
                os.replace(self._tmp, self.path)
        finally:
            self._file = None
            self._tmp.unlink(missing_ok=True)


def _write_episode(group: Any, episode: Episode) -> None:
    obs = group.create_group("obs")
    for name, values in episode.obs.items():
        if name.endswith(IMAGE_SUFFIX):
            obs.create_dataset(name, data=values.astype(np.uint8), compression="gzip", compression_opts=4)
        else:
            obs.create_dataset(name, data=values)
    obs["object_poses"].attrs["object_ids"] = list(episode.object_ids)
    for name in ("actions", "rewards", "dones", "states", "final_state"):
        group.create_dataset(name, data=getattr(episode, name))
    group.create_dataset("final_object_poses", data=episode.final_poses)
    group.attrs["num_samples"] = episode.num_samples
    for key in _ATTRS:
        group.attrs[key] = episode.attrs.get(key, "" if key != "seed" else 0)
    for key, value in episode.attrs.items():  # what the run adds (instruction, mount, ...)
        if key not in _ATTRS and isinstance(value, str | int | float | bool):
            group.attrs[key] = value


def read_episode(path: str | Path, k: int) -> Episode:
    """Episode `data/demo_{k}` of a dataset file."""
    import h5py

    try:
        handle = h5py.File(path, "r")
    except OSError as exc:
        raise RecordError(f"{path}: not a readable HDF5 dataset ({exc})") from None
    with handle:
        data = handle.get("data")
        group = data.get(f"demo_{k}") if data is not None else None
        if group is None:
            count = len(data) if data is not None else 0
            raise RecordError(f"{path} has no episode demo_{k} (it holds {count})")
        try:
            return _read_group(group)
        except KeyError as exc:
            raise RecordError(f"{path}: episode demo_{k} is incomplete ({exc})") from None


def _read_group(group: Any) -> Episode:
    obs = {name: group["obs"][name][()] for name in group["obs"]}
    ids = tuple(
        str(i.decode() if isinstance(i, bytes) else i) for i in group["obs"]["object_poses"].attrs["object_ids"]
    )
    attrs = {key: _plain(value) for key, value in group.attrs.items() if key != "num_samples"}
    return Episode(
        obs=obs,
        actions=group["actions"][()],
        rewards=group["rewards"][()],
        dones=group["dones"][()],
        states=group["states"][()],
        object_ids=ids,
        final_state=group["final_state"][()],
        final_poses=group["final_object_poses"][()],
        attrs=attrs,
    )


def _plain(value: Any) -> Any:
    """An HDF5 attribute as a plain Python value."""
    if isinstance(value, bytes):
        return value.decode()
    if isinstance(value, np.bool_):
        return bool(value)
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, np.floating):
        return float(value)
    return value


# -- replay ---------------------------------------------------------------------------------------------------------


def replay_frames(
    world: RobotWorld, episode: Episode, size: tuple[int, int], camera: str = FRONT_CAMERA
) -> Iterator[np.ndarray]:
    """The episode replayed in `world` (from its first state, action by action) and filmed from `camera` at `size`
    (height, width): a frame before every action and one after the last. Frames are made as they are taken, so a
    video of any length and size costs one frame of memory."""
    from physcensis.robot.control import apply_action

    if episode.num_samples == 0:
        raise RecordError("the episode has no steps to replay")
    set_state(world, episode.states[0])
    renderer = camera_renderer(world.model, size, fast=False)
    try:
        for action in [*episode.actions, None]:
            mujoco.mj_kinematics(world.model, world.data)
            renderer.update_scene(world.data, camera=camera)
            yield renderer.render().copy()
            if action is not None:
                apply_action(world, action)
    finally:
        renderer.close()


def replay(world: RobotWorld, episode: Episode) -> dict[str, np.ndarray]:
    """Restore the episode's first state in `world`, apply every recorded action, and return the final object poses."""
    from physcensis.robot.control import apply_action

    if episode.num_samples == 0:
        raise RecordError("the episode has no steps to replay")
    missing = set(episode.object_ids) - set(world.object_qpos)
    if missing:
        raise RecordError(f"the episode's objects {sorted(missing)} are not in this world: a different scene?")
    set_state(world, episode.states[0])
    for action in episode.actions:
        apply_action(world, action)
    return world.object_poses()
