"""A demonstration dataset (what `physcensis demo` writes) as the training set robomimic reads: the successful
episodes, with the policy's observations and scaled actions (`features.py`), in robomimic's HDF5 layout."""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from physcensis.policy.backend import PolicyError
from physcensis.policy.features import ActionScale, encode_actions, episode_observations, scale_actions
from physcensis.robot.record import Episode, RecordError, read_episode


@dataclass(frozen=True)
class Demonstrations:
    """The successful episodes of a dataset as arrays: per episode, observations (N, ...) per key and encoded
    actions (N, 8)."""

    observations: list[dict[str, np.ndarray]]
    actions: list[np.ndarray]
    tasks: list[str]
    env_args: dict[str, Any]
    episodes_in_file: int

    @property
    def samples(self) -> int:
        return sum(len(a) for a in self.actions)


def file_digest(path: Path) -> str:
    """sha256 of the file's bytes (what a training run records as the dataset it read)."""
    digest = hashlib.sha256()
    with path.open("rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _episode_names(dataset: Path) -> tuple[list[str], dict[str, Any]]:
    """The dataset's episode groups in index order, and its env_args."""
    import h5py

    if not dataset.is_file():
        raise PolicyError(f"{dataset}: no such dataset file (give the demos.hdf5 that `physcensis demo` writes)")
    try:
        with h5py.File(dataset, "r") as handle:
            data = handle.get("data")
            if not isinstance(data, h5py.Group):
                raise PolicyError(f"{dataset}: not a demonstration dataset (it has no data/ group)")
            names = sorted((n for n in data if n.startswith("demo_")), key=lambda n: int(n.split("_")[-1]))
            return names, json.loads(data.attrs.get("env_args", "{}"))
    except OSError as exc:
        raise PolicyError(f"{dataset}: not a readable HDF5 dataset ({exc})") from None


def read_demonstrations(dataset: Path, max_episodes: int | None = None) -> Demonstrations:
    """The successful episodes of `dataset` (the first `max_episodes` of them), or a PolicyError saying what is
    wrong with the file."""
    names, env_args = _episode_names(dataset)
    episodes: list[Episode] = []
    for name in names:
        if max_episodes is not None and len(episodes) >= max_episodes:
            break
        try:
            episode = read_episode(dataset, int(name.split("_")[-1]))
        except RecordError as exc:
            raise PolicyError(str(exc)) from None
        if episode.attrs.get("success") and episode.num_samples > 0:
            episodes.append(episode)
    if not episodes:
        raise PolicyError(f"{dataset}: holds no successful episode to learn from ({len(names)} episodes)")
    observations, actions = [], []
    for episode in episodes:
        try:
            observations.append(episode_observations(episode))
        except (KeyError, ValueError) as exc:
            raise PolicyError(f"{dataset}: an episode lacks what a policy observes ({exc})") from None
        actions.append(encode_actions(episode.actions, episode.obs["joint_pos"]))
    return Demonstrations(observations, actions, [str(e.attrs["task"]) for e in episodes], env_args, len(names))


ObsStats = dict[str, dict[str, np.ndarray]]  # key -> {"mean": (1, D), "std": (1, D)}, robomimic's form


def observation_stats(demos: Demonstrations) -> ObsStats:
    """Per key and number, the mean and standard deviation over every step (plus 1e-3, as robomimic adds)."""
    stats: ObsStats = {}
    for key in demos.observations[0]:
        values = np.concatenate([obs[key] for obs in demos.observations]).astype(np.float64)
        stats[key] = {"mean": values.mean(axis=0, keepdims=True), "std": values.std(axis=0, keepdims=True) + 1e-3}
    return stats


def write_training_file(demos: Demonstrations, scale: ActionScale, stats: ObsStats, path: Path) -> None:
    """The demonstrations in robomimic's layout (data/demo_k/obs/KEY normalised by `stats`, actions in [-1, 1],
    rewards, dones). Normalised here rather than by robomimic's SequenceDataset, whose normalisation of sequences
    (BC-RNN) fails a shape check in 0.3.0."""
    import h5py

    with h5py.File(path, "w") as handle:
        data = handle.create_group("data")
        data.attrs["env_args"] = json.dumps(demos.env_args)
        data.attrs["total"] = demos.samples
        for k, (obs, actions) in enumerate(zip(demos.observations, demos.actions, strict=True)):
            group = data.create_group(f"demo_{k}")
            group.attrs["num_samples"] = len(actions)
            for key, values in obs.items():
                normalised = (values - stats[key]["mean"]) / stats[key]["std"]
                group.create_dataset(f"obs/{key}", data=normalised.astype(np.float32))
            group.create_dataset("actions", data=scale_actions(actions, scale))
            dones = np.zeros(len(actions))
            dones[-1] = 1
            group.create_dataset("rewards", data=dones)
            group.create_dataset("dones", data=dones)
