"""Demonstrations in LeRobot's dataset format: a converter from the robomimic-style HDF5 file a demo run writes.

Each HDF5 step becomes one LeRobot frame at the control rate (20 Hz):

    observation.state               (9,)  arm joint positions (7) and finger positions (2)
    observation.velocity            (7,)  arm joint velocities
    observation.eef_pose            (7,)  gripper centre position and orientation (w, x, y, z), world frame
    observation.environment_state   (14,) pose of the picked object, then of its target (position + wxyz)
    observation.images.front|wrist  (H, W, 3) camera frames, when the run recorded them
    action                          (8,)  arm joint targets (7) and gripper opening (0..1)
    next.reward, next.done          (1,)
    task                                  the task in the user's words

Scenes differ in their number of objects, so only the two objects the task names go into the fixed-size
environment state; the HDF5 file keeps every object's pose. Writing needs the `lerobot` extra (it brings PyTorch).
"""

from __future__ import annotations

import os
import re
import shutil
import tempfile
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from physcensis.errors import PhyscensisError
from physcensis.robot.control import CONTROL_DT
from physcensis.robot.record import IMAGE_SUFFIX, Episode, read_episode

FPS = round(1 / CONTROL_DT)
ROBOT_TYPE = "franka_panda"
CAMERAS = ("front", "wrist")
_EXPLICIT_TASK = re.compile(r"pick (\S+) place-(?:on|in) (\S+)")
_REPO_ID = re.compile(r"[A-Za-z0-9_.-]+/[A-Za-z0-9_.-]+")


class LeRobotExportError(PhyscensisError):
    """A dataset cannot be converted (no episodes to convert, episodes that disagree in shape, lerobot missing)."""


@dataclass(frozen=True)
class ExportSummary:
    out: Path
    episodes: int
    frames: int
    skipped_failed: int


def lerobot_features(image_size: tuple[int, int] | None, cameras: Sequence[str] = CAMERAS) -> dict[str, Any]:
    """The LeRobot feature spec of our frames; camera features only when frames were recorded."""
    joints = [f"joint{i}" for i in range(1, 8)]
    pose = ["x", "y", "z", "qw", "qx", "qy", "qz"]
    features: dict[str, Any] = {
        "observation.state": _vector(joints + ["finger_left", "finger_right"]),
        "observation.velocity": _vector(joints),
        "observation.eef_pose": _vector(pose),
        "observation.environment_state": _vector([f"picked_{n}" for n in pose] + [f"target_{n}" for n in pose]),
        "action": _vector(joints + ["gripper"]),
        "next.reward": _vector(["reward"]),
        "next.done": {"dtype": "bool", "shape": (1,), "names": ["done"]},
    }
    if image_size is not None:
        height, width = image_size
        for camera in cameras:
            features[f"observation.images.{camera}"] = {
                "dtype": "video",
                "shape": (height, width, 3),
                "names": ["height", "width", "channels"],
            }
    return features


def _vector(names: list[str]) -> dict[str, Any]:
    return {"dtype": "float32", "shape": (len(names),), "names": names}


def lerobot_frames(episode: Episode) -> Iterator[dict[str, Any]]:
    """The episode's steps as LeRobot frames (see the module's docstring for the layout)."""
    picked, target = _task_objects(episode)
    obs = episode.obs
    state = np.concatenate([obs["joint_pos"], obs["gripper_qpos"]], axis=1).astype(np.float32)
    eef = np.concatenate([obs["eef_pos"], obs["eef_quat"]], axis=1).astype(np.float32)
    poses = obs["object_poses"]
    environment = np.concatenate([poses[:, picked], poses[:, target]], axis=1).astype(np.float32)
    words = str(episode.attrs.get("instruction") or episode.attrs.get("task") or "")
    for k in range(episode.num_samples):
        frame: dict[str, Any] = {
            "observation.state": state[k],
            "observation.velocity": obs["joint_vel"][k].astype(np.float32),
            "observation.eef_pose": eef[k],
            "observation.environment_state": environment[k],
            "action": episode.actions[k].astype(np.float32),
            "next.reward": np.asarray([episode.rewards[k]], dtype=np.float32),
            "next.done": np.asarray([bool(episode.dones[k])]),
            "task": words,
        }
        for camera in CAMERAS:
            images = obs.get(camera + IMAGE_SUFFIX)
            if images is not None:
                frame[f"observation.images.{camera}"] = images[k]
        yield frame


def _task_objects(episode: Episode) -> tuple[int, int]:
    """Indices (into the episode's object poses) of the picked object and of its target."""
    task = str(episode.attrs.get("task", ""))
    match = _EXPLICIT_TASK.fullmatch(task.strip())
    if match is None:
        raise LeRobotExportError(
            f"episode of scene {episode.attrs.get('scene')!r} has no explicit task (found {task!r})"
        )
    try:
        return episode.object_ids.index(match[1]), episode.object_ids.index(match[2])
    except ValueError:
        raise LeRobotExportError(f"the task {task!r} names an object the episode did not record") from None


def export_lerobot(
    dataset: Path, out: Path, *, repo_id: str = "physcensis/demos", include_failed: bool = False
) -> ExportSummary:
    """Write the episodes of `dataset` (successful ones unless `include_failed`) as a LeRobot dataset at `out`.
    `out` appears only once the whole dataset is written; it must not exist yet, or be an empty folder."""
    if not _REPO_ID.fullmatch(repo_id):
        raise LeRobotExportError(f"repo id {repo_id!r}: give it as owner/name (letters, digits, '_', '-', '.')")
    if out.exists() and (not out.is_dir() or any(out.iterdir())):
        raise LeRobotExportError(f"{out} already exists; give a new folder for the LeRobot dataset")
    chosen, sizes, skipped = _survey(dataset, include_failed)
    if len(sizes) > 1:
        raise LeRobotExportError(f"{dataset}: episodes recorded at different image sizes {sorted(map(str, sizes))}")
    LeRobotDataset = _lerobot_dataset_class()
    out.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=f".{out.name}.", suffix=".tmp", dir=out.parent))
    root = staging / "dataset"  # LeRobot creates its root itself
    try:
        frames = _write(LeRobotDataset, dataset, chosen, sizes.pop(), root, repo_id)
        frames_dir = root / "images"  # LeRobot's scratch frames, already encoded into the videos
        if frames_dir.is_dir() and not any(path.is_file() for path in frames_dir.rglob("*")):
            shutil.rmtree(frames_dir)
        if out.exists():
            out.rmdir()
        os.replace(root, out)
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    return ExportSummary(out, len(chosen), frames, skipped)


def _write(
    LeRobotDataset: Any, dataset: Path, chosen: list[int], size: tuple[int, int] | None, root: Path, repo_id: str
) -> int:
    """Write the chosen episodes with LeRobot at `root`; how many frames. LeRobot's own failures (video encoding,
    a full disk) become one LeRobotExportError naming them."""
    frames = 0
    try:
        writer = LeRobotDataset.create(
            repo_id=repo_id, fps=FPS, features=lerobot_features(size), root=root, robot_type=ROBOT_TYPE
        )
        for k in chosen:
            episode = read_episode(dataset, k)  # one at a time: a batch's frames do not fit in memory together
            for frame in lerobot_frames(episode):
                writer.add_frame(frame)
                frames += 1
            writer.save_episode()
        writer.finalize()
    except PhyscensisError:
        raise
    except KeyError as exc:
        raise LeRobotExportError(f"{dataset}: an episode lacks {exc} (not written by physcensis demo?)") from None
    except Exception as exc:
        raise LeRobotExportError(f"LeRobot could not write the dataset: {type(exc).__name__}: {exc}") from None
    return frames


def _survey(dataset: Path, include_failed: bool) -> tuple[list[int], set[tuple[int, int] | None], int]:
    """The episodes to convert, their image sizes and how many failed ones are left out, from the file's attributes
    and shapes alone."""
    import h5py

    chosen: list[int] = []
    sizes: set[tuple[int, int] | None] = set()
    skipped = 0
    try:
        with h5py.File(dataset, "r") as handle:
            data = handle.get("data")
            if not isinstance(data, h5py.Group):
                raise LeRobotExportError(f"{dataset}: no group 'data' of episodes (not written by physcensis demo?)")
            names = [name for name in data if re.fullmatch(r"demo_\d+", name)]
            for name in sorted(names, key=lambda name: int(name[5:])):
                group = data[name]
                obs = group.get("obs") if isinstance(group, h5py.Group) else None
                if not isinstance(obs, h5py.Group):
                    raise LeRobotExportError(f"{dataset}: data/{name} is not an episode (no obs group)")
                if not (bool(group.attrs.get("success", False)) or include_failed):
                    skipped += 1
                    continue
                chosen.append(int(name[5:]))
                sizes.add(_image_size(obs.get("front" + IMAGE_SUFFIX), f"{dataset}: data/{name}"))
    except (OSError, KeyError, TypeError, ValueError) as exc:
        raise LeRobotExportError(f"{dataset}: not a readable demonstrations dataset ({exc})") from None
    if not chosen:
        raise LeRobotExportError(
            f"{dataset} holds no {'episodes' if include_failed else 'successful episodes'} to convert"
            + (f" ({skipped} failed; --include-failed converts them too)" if skipped else "")
        )
    return chosen, sizes, skipped


def _image_size(frames: Any, where: str) -> tuple[int, int] | None:
    """(height, width) of an episode's recorded frames, None when it has none."""
    if frames is None:
        return None
    shape: tuple[int, ...] = tuple(getattr(frames, "shape", ()))
    if len(shape) != 4 or shape[-1] != 3:
        raise LeRobotExportError(f"{where}: front_rgb has shape {tuple(shape)}, not (steps, height, width, 3)")
    return int(shape[1]), int(shape[2])


def _lerobot_dataset_class() -> Any:
    try:
        from lerobot.datasets.lerobot_dataset import LeRobotDataset
    except ImportError as exc:
        raise LeRobotExportError(
            f"writing LeRobot datasets needs the lerobot package ({exc}): pip install 'physcensis[lerobot]'"
        ) from None
    return LeRobotDataset
