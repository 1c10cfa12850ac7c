"""Behaviour cloning with robomimic 0.3.0 on a demonstration dataset: `physcensis policy train`.

The dataset is rewritten as robomimic's training set (`data.py`, observations normalised), read by robomimic's own
SequenceDataset, and robomimic's BC learns from it: an MLP by default, or BC-RNN. The run is
seeded (torch, numpy, the batch order) and deterministic on a CPU. It writes POLICY (a robomimic-style checkpoint
with what physcensis adds to turn outputs into actions) and TRAIN_RECORD, each atomically.
"""

from __future__ import annotations

import contextlib
import io
import json
import random
import tempfile
import time
from collections.abc import Callable, Iterator
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np

from physcensis.fileio import atomic_write_bytes, atomic_write_text, check_output_dir, output_directory
from physcensis.policy.backend import PolicyError, load_learner
from physcensis.policy.data import file_digest, observation_stats, read_demonstrations, write_training_file
from physcensis.policy.features import OBS_KEYS, ActionScale

POLICY = "policy.pth"
TRAIN_RECORD = "train.json"
FORMAT = "physcensis-bc/1"


@dataclass(frozen=True)
class TrainSettings:
    """How long and how to learn. The defaults are what the variety experiment uses (docs/BENCHMARKS.md)."""

    steps: int = 5000  # gradient steps
    batch_size: int = 64
    seed: int = 0
    rnn: bool = False  # BC-RNN (an LSTM over `horizon` steps) instead of BC with an MLP
    horizon: int = 10  # the RNN's sequence length in training
    hidden: tuple[int, ...] = (256, 256)  # the MLP's layers (BC) or (RNN hidden size,) for BC-RNN
    learning_rate: float = 1e-3
    max_episodes: int | None = None  # learn from the first K successful episodes only

    def __post_init__(self) -> None:
        if self.steps < 1 or self.batch_size < 1 or self.horizon < 1 or not self.hidden:
            raise PolicyError("steps, batch size and horizon must be 1 or more, and hidden must name a size")
        if self.max_episodes is not None and self.max_episodes < 1:
            raise PolicyError(f"max_episodes {self.max_episodes}: give 1 or more")


@dataclass(frozen=True)
class TrainResult:
    """What a training run did: where it wrote, its losses, and what it read."""

    out: Path
    steps: int
    episodes: int
    samples: int
    seconds: float
    first_loss: float
    final_loss: float  # the mean of the last 1 % of steps' losses (at least one)
    losses: tuple[float, ...]  # one per step
    dataset_sha256: str

    @property
    def policy_path(self) -> Path:
        return self.out / POLICY


StepCallback = Callable[[int, float], None]  # (steps done, that step's loss)


def train(
    dataset: str | Path,
    out: str | Path,
    settings: TrainSettings | None = None,
    on_step: StepCallback | None = None,
    *,
    overwrite: bool = False,
) -> TrainResult:
    """Learn a policy from the successful episodes of `dataset`; write out/policy.pth and out/train.json (`out` is
    missing, empty or a physcensis output; another folder needs `overwrite`, and keeps its other files)."""
    settings = settings or TrainSettings()
    dataset, out = Path(dataset), Path(out)
    check_output_dir(out, overwrite=overwrite)
    demos = read_demonstrations(dataset, settings.max_episodes)
    load_learner()
    import torch

    scale = ActionScale.fit(np.concatenate(demos.actions))
    shapes = {key: list(demos.observations[0][key].shape[1:]) for key in OBS_KEYS}
    started = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="physcensis-train-") as scratch:
        training_file = Path(scratch) / "train.hdf5"
        stats = observation_stats(demos)
        write_training_file(demos, scale, stats, training_file)
        with _seeded(settings.seed):
            config = _config(settings, training_file)
            dataset_obj, model = _dataset_and_model(config, shapes)
            losses = _fit(model, dataset_obj, settings, on_step)
    seconds = time.perf_counter() - started
    checkpoint = {
        "algo_name": config.algo_name,
        "config": json.dumps(config),
        "model": model.serialize(),
        "shape_metadata": {"all_shapes": shapes, "ac_dim": 8, "all_obs_keys": list(OBS_KEYS), "use_images": False},
        "obs_normalization_stats": {k: {n: np.asarray(v).tolist() for n, v in s.items()} for k, s in stats.items()},
        "env_metadata": demos.env_args,
        "physcensis": {"format": FORMAT, "action_scale": scale.to_dict(), "obs_keys": list(OBS_KEYS)},
    }
    buffer = io.BytesIO()
    torch.save(checkpoint, buffer)
    tail = max(1, len(losses) // 100)
    result = TrainResult(
        out=out,
        steps=len(losses),
        episodes=len(demos.actions),
        samples=demos.samples,
        seconds=round(seconds, 2),
        first_loss=losses[0],
        final_loss=float(np.mean(losses[-tail:])),
        losses=tuple(losses),
        dataset_sha256=file_digest(dataset),
    )
    record = {
        "dataset": str(dataset),
        "dataset_sha256": result.dataset_sha256,
        "episodes_in_dataset": demos.episodes_in_file,
        "episodes_used": result.episodes,
        "samples": result.samples,
        "tasks": sorted(set(demos.tasks)),
        "algorithm": "BC-RNN" if settings.rnn else "BC (MLP)",
        "settings": {**asdict(settings), "hidden": list(settings.hidden)},
        "steps": result.steps,
        "seconds": result.seconds,
        "first_loss": result.first_loss,
        "final_loss": result.final_loss,
        "losses": [round(v, 6) for v in losses],
    }
    with output_directory(out, overwrite=overwrite) as staging:
        atomic_write_bytes(staging / POLICY, buffer.getvalue())
        atomic_write_text(staging / TRAIN_RECORD, json.dumps(record, indent=2) + "\n")
    return result


@contextlib.contextmanager
def _seeded(seed: int) -> Iterator[None]:
    """Seed every generator training draws from, on one thread (small networks gain nothing from more, and the sums
    come out the same on every machine); torch's global state is restored afterwards."""
    import torch

    state, threads = torch.random.get_rng_state(), torch.get_num_threads()
    torch.manual_seed(seed)
    torch.set_num_threads(1)
    random.seed(seed)
    np.random.seed(seed)
    try:
        yield
    finally:
        torch.random.set_rng_state(state)
        torch.set_num_threads(threads)


def _config(settings: TrainSettings, training_file: Path) -> Any:
    from robomimic.config import config_factory

    config = config_factory(algo_name="bc")
    with config.values_unlocked():
        config.train.data = str(training_file)
        config.train.seed = settings.seed
        config.train.cuda = False
        config.train.num_data_workers = 0
        config.train.hdf5_cache_mode = "all"
        config.train.hdf5_normalize_obs = False  # the training file is normalised already
        config.train.batch_size = settings.batch_size
        config.train.seq_length = settings.horizon if settings.rnn else 1
        config.observation.modalities.obs.low_dim = list(OBS_KEYS)
        config.observation.modalities.obs.rgb = []
        config.algo.optim_params.policy.learning_rate.initial = settings.learning_rate
        config.algo.rnn.enabled = settings.rnn
        if settings.rnn:
            config.algo.rnn.horizon = settings.horizon
            config.algo.rnn.hidden_dim = settings.hidden[0]
            config.algo.actor_layer_dims = ()
        else:
            config.algo.actor_layer_dims = list(settings.hidden)
    return config


def _dataset_and_model(config: Any, shapes: dict[str, list[int]]) -> tuple[Any, Any]:
    import robomimic.utils.obs_utils as obs_utils
    import robomimic.utils.train_utils as train_utils

    with quiet():  # robomimic prints what it loads and draws tqdm bars
        obs_utils.initialize_obs_utils_with_config(config)  # the dataset reads which keys are low-dimensional
        dataset = train_utils.dataset_factory(config, obs_keys=list(OBS_KEYS))
    return dataset, make_model(config, shapes)


def make_model(config: Any, shapes: dict[str, list[int]]) -> Any:
    """robomimic's algorithm for `config`, on the CPU, for observations of these shapes and 8-number actions."""
    import robomimic.utils.obs_utils as obs_utils
    import torch
    from robomimic.algo import algo_factory

    with quiet():
        obs_utils.initialize_obs_utils_with_config(config)
        return algo_factory(config.algo_name, config, obs_key_shapes=shapes, ac_dim=8, device=torch.device("cpu"))


def _fit(model: Any, dataset: Any, settings: TrainSettings, on_step: StepCallback | None) -> list[float]:
    import torch
    from torch.utils.data import DataLoader

    generator = torch.Generator().manual_seed(settings.seed)
    loader = DataLoader(
        dataset, batch_size=settings.batch_size, shuffle=True, num_workers=0, drop_last=False, generator=generator
    )
    losses: list[float] = []
    epoch = 0
    model.set_train()
    while len(losses) < settings.steps:
        epoch += 1
        for batch in loader:
            prepared = model.postprocess_batch_for_training(
                model.process_batch_for_training(batch), obs_normalization_stats=None
            )
            info = model.train_on_batch(prepared, epoch, validate=False)
            losses.append(float(info["losses"]["action_loss"]))
            if on_step is not None:
                on_step(len(losses), losses[-1])
            if len(losses) >= settings.steps:
                break
        model.on_epoch_end(epoch)
    return losses


@contextlib.contextmanager
def quiet() -> Iterator[None]:
    """robomimic reports to stdout and stderr as it works; a command keeps its own output."""
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        yield
