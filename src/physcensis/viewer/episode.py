"""A recorded robot demonstration as the viewer plays it: the objects' poses (and the hand's) at every control step,
read from the dataset the robot code writes (robot/record.py: data/demo_K/obs/object_poses, eef_pos, ...)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from physcensis.viewer.scene_view import Pose, ViewerError

CONTROL_S = 0.05  # robot/control.py's CONTROL_DT: one recorded step is one 20 Hz action


@dataclass(frozen=True)
class EpisodeRef:
    """`DATASET[:INDEX]` of the command line: a dataset file and the episode in it (data/demo_INDEX)."""

    dataset: Path
    index: int = 0

    @classmethod
    def parse(cls, text: str) -> EpisodeRef:
        path, colon, index = text.rpartition(":")
        if colon and index.isdigit() and path:
            return cls(Path(path), int(index))
        if colon and path and index and not Path(text).exists():
            raise ViewerError(
                f"--episode {text!r}: the episode index after ':' must be a whole number, e.g. data.hdf5:0"
            )
        return cls(Path(text), 0)

    def __str__(self) -> str:
        return f"{self.dataset}:{self.index}"


@dataclass(frozen=True, eq=False)
class EpisodeTrack:
    """T = steps + 1 frames: the world before each recorded action, then after the last."""

    ref: EpisodeRef
    object_ids: tuple[str, ...]
    object_poses: np.ndarray  # (T, M, 7) position and wxyz quaternion
    eef_pos: np.ndarray  # (T, 3) the tool centre point
    eef_quat: np.ndarray  # (T, 4) wxyz
    states: np.ndarray  # (T, S) the full MuJoCo state of the robot world (mj_getState), for the arm's links
    frame_s: float = CONTROL_S
    attrs: dict[str, Any] = field(default_factory=dict)

    @property
    def frames(self) -> int:
        return int(len(self.object_poses))

    @property
    def duration_s(self) -> float:
        return (self.frames - 1) * self.frame_s

    def poses(self, frame: int) -> dict[str, Pose]:
        k = min(max(frame, 0), self.frames - 1)
        return {oid: self.object_poses[k, i].copy() for i, oid in enumerate(self.object_ids)}

    def frame_at(self, seconds: float) -> int:
        return min(self.frames - 1, max(0, int(seconds / self.frame_s)))


def read_episode_track(ref: EpisodeRef) -> EpisodeTrack:
    """The episode's recorded poses; a missing file, episode or field is one ViewerError naming it."""
    try:
        import h5py  # noqa: F401 - the robot extra's; read_episode imports it too
    except ImportError:
        raise ViewerError("playing a recorded episode needs h5py: pip install 'physcensis[robot]'") from None
    from physcensis.robot.record import RecordError, read_episode

    if not ref.dataset.is_file():
        raise ViewerError(f"--episode: {ref.dataset}: no such dataset file")
    try:
        episode = read_episode(ref.dataset, ref.index)
    except RecordError as exc:
        raise ViewerError(f"--episode: {exc}") from None
    if episode.num_samples == 0:
        raise ViewerError(f"--episode: {ref}: the episode has no steps")
    poses = np.asarray(episode.obs["object_poses"], dtype=float)
    steps, objects = episode.num_samples, len(episode.object_ids)
    if poses.shape != (steps, objects, 7) or np.shape(episode.final_poses) != (objects, 7):
        raise ViewerError(f"--episode: {ref}: object_poses has shape {poses.shape}, not ({steps}, {objects}, 7)")
    eef_pos = _with_last(np.asarray(episode.obs.get("eef_pos", np.zeros((steps, 3))), dtype=float), None)
    eef_quat = _with_last(
        np.asarray(episode.obs.get("eef_quat", np.tile([1.0, 0, 0, 0], (steps, 1))), dtype=float), None
    )
    return EpisodeTrack(
        ref=ref,
        object_ids=tuple(episode.object_ids),
        object_poses=np.concatenate([poses, np.asarray(episode.final_poses, dtype=float)[None]]),
        eef_pos=eef_pos,
        eef_quat=eef_quat,
        states=_with_last(np.asarray(episode.states, dtype=float), np.asarray(episode.final_state, dtype=float)),
        attrs=dict(episode.attrs),
    )


def _with_last(rows: np.ndarray, last: np.ndarray | None) -> np.ndarray:
    """`rows` with one more row: `last`, or the last row again (what the file does not record after the end)."""
    extra = rows[-1:] if last is None else np.reshape(last, (1, *rows.shape[1:]))
    return np.concatenate([rows, extra])


def recorded_scene(track: EpisodeTrack) -> Path | None:
    """The scene folder the episode says it was recorded in (relative to its dataset's folder), if it says."""
    reference = str(track.attrs.get("scene") or "")
    if not reference:
        return None
    path = Path(reference)
    return path if path.is_absolute() else track.ref.dataset.parent / path


def check_objects(track: EpisodeTrack, scene_ids: list[str]) -> list[str]:
    """The episode's objects that the scene holds; none in common is an error (another scene's episode)."""
    shared = [oid for oid in track.object_ids if oid in scene_ids]
    if not shared:
        raise ViewerError(
            f"--episode {track.ref}: none of its objects ({', '.join(track.object_ids[:6])}) is in this scene; "
            "was it recorded in another scene?"
        )
    return shared
