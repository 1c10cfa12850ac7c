"""Behaviour cloning on a recorded demonstration: the checkpoint loads and acts in the environment, training is
deterministic, evaluation writes the paper's measures, and a missing learner or dataset is one clear error line."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.policy import INSTALL, EvalSettings, TrainSettings, evaluate, load_policy, train, wilson
from physcensis.policy.data import file_digest
from physcensis.policy.evaluate import fingers_close_on
from physcensis.policy.features import OBS_KEYS, episode_observations, with_derived
from physcensis.robot.env import PickPlaceEnv
from physcensis.robot.record import read_episode

from .conftest import TASK

pytest.importorskip("robomimic", reason=f"the policy extra: {INSTALL}")
runner = CliRunner()
STEPS = 30


@pytest.fixture(scope="module")
def trained(dataset: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("policy") / "bc"
    train(dataset, out, TrainSettings(steps=STEPS, batch_size=16))
    return out


def _one_error_line(result: object) -> str:
    assert result.exit_code == 2, result.output  # type: ignore[attr-defined]
    lines = result.stderr.strip().splitlines()  # type: ignore[attr-defined]
    assert len(lines) == 1 and lines[0].startswith("error: "), lines
    return lines[0]


@pytest.mark.slow
@pytest.mark.long
def test_the_checkpoint_loads_and_gives_actions_of_the_environments_shape(trained: Path, dataset: Path,
                                                                          scene_dir: Path) -> None:  # fmt: skip
    record = json.loads((trained / "train.json").read_text())
    assert record["steps"] == STEPS and len(record["losses"]) == STEPS and record["episodes_used"] == 1
    assert record["dataset_sha256"] == file_digest(dataset)
    env = PickPlaceEnv(scene_dir, TASK)
    obs, _ = env.reset(seed=0)
    policy = load_policy(trained)
    policy.reset()
    for _ in range(3):
        action = policy.act(obs)
        assert action.shape == env.action_space.shape and np.all(np.isfinite(action))
        obs, *_ = env.step(action)
    env.close()


@pytest.mark.slow
@pytest.mark.long
def test_the_same_seed_gives_the_same_losses(dataset: Path, trained: Path, tmp_path: Path) -> None:
    again = train(dataset, tmp_path / "again", TrainSettings(steps=STEPS, batch_size=16))
    first = json.loads((trained / "train.json").read_text())["losses"]
    assert [round(v, 6) for v in again.losses] == first
    other = train(dataset, tmp_path / "other", TrainSettings(steps=STEPS, batch_size=16, seed=1))
    assert other.losses != again.losses


@pytest.mark.slow
@pytest.mark.long
def test_eval_writes_the_measures_and_a_video(trained: Path, scene_dir: Path, tmp_path: Path) -> None:
    out = tmp_path / "eval"
    result = evaluate(trained, scene_dir, out, EvalSettings(task=TASK, max_steps=12, videos=1))
    record = json.loads((out / "eval.json").read_text())
    assert record["reaching"]["trials"] == record["placing"]["trials"] == 1
    assert len(record["reaching"]["ci95"]) == 2 and record["placing"]["ci95"][1] > 0.7  # 0 or 1 of 1: wide
    (episode,) = record["episodes"]
    assert episode["steps"] == 12 and not episode["placed"]  # twelve steps (0.6 s) cannot pick and place
    assert episode["task"] == TASK and result.episodes[0].video == "episode_0.mp4"
    assert (out / "episode_0.mp4").stat().st_size > 1000


@pytest.mark.slow
@pytest.mark.long
def test_the_dataset_holds_what_the_environment_observes(dataset: Path, scene_dir: Path) -> None:
    """The observations derived from a recorded episode are the environment's at the same step of its replay."""
    episode = read_episode(dataset, 0)
    derived = episode_observations(episode)
    assert set(derived) == set(OBS_KEYS)
    env = PickPlaceEnv(scene_dir, TASK)
    obs, _ = env.reset(seed=0)
    for k, action in enumerate(episode.actions[:40]):
        live = with_derived(obs)
        for key in OBS_KEYS:
            assert np.allclose(live[key], derived[key][k], atol=1e-5), (key, k)
        obs, *_ = env.step(action)
    env.close()


@pytest.mark.slow
@pytest.mark.long
def test_reaching_is_the_fingers_closing_on_the_object_in_a_recorded_demonstration(
    dataset: Path, scene_dir: Path
) -> None:
    episode = read_episode(dataset, 0)
    env = PickPlaceEnv(scene_dir, TASK)
    env.reset(seed=0)
    assert not fingers_close_on(env.world, "cup_0")
    closed = []
    for action in episode.actions:
        env.step(action)
        closed.append(fingers_close_on(env.world, "cup_0"))
    env.close()
    first = closed.index(True)
    assert episode.actions[first, -1] < episode.actions[0, -1]  # it happens once the gripper is told to close
    assert not closed[-1]  # released on the plate at the end
    assert not any(fingers_close_on(env.world, other) for other in ("bowl_0", "plate_0"))


def test_wilson_intervals() -> None:
    assert [round(v, 4) for v in (wilson(0, 10).low, wilson(0, 10).high)] == [0.0, 0.2775]
    assert [round(v, 4) for v in (wilson(10, 10).low, wilson(10, 10).high)] == [0.7225, 1.0]
    assert [round(v, 4) for v in (wilson(5, 10).low, wilson(5, 10).high)] == [0.2366, 0.7634]
    assert wilson(0, 0).trials == 0


@pytest.mark.slow
@pytest.mark.long
def test_a_missing_learner_is_one_line_naming_the_install(
    dataset: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setitem(sys.modules, "robomimic", None)  # `import robomimic` now raises ImportError
    result = runner.invoke(app, ["policy", "train", str(dataset), "--out", str(tmp_path / "bc"), "--steps", "2"])
    line = _one_error_line(result)
    assert "robomimic" in line and "pip install --no-deps robomimic==0.3.0" in line
    assert not (tmp_path / "bc" / "policy.pth").exists()


def test_a_missing_or_invalid_dataset_is_one_error_line(tmp_path: Path) -> None:
    missing = runner.invoke(app, ["policy", "train", str(tmp_path / "none.hdf5"), "--out", str(tmp_path / "a")])
    assert "no such dataset file" in _one_error_line(missing)
    junk = tmp_path / "junk.hdf5"
    junk.write_text("not hdf5")
    invalid = runner.invoke(app, ["policy", "train", str(junk), "--out", str(tmp_path / "b")])
    assert "not a readable HDF5 dataset" in _one_error_line(invalid)
    no_policy = runner.invoke(app, ["policy", "eval", str(tmp_path), "--scenes", str(tmp_path)])
    assert _one_error_line(no_policy)
