"""The robot demonstration benchmark's figures and benchmark table, on a faked two-scene run (the real one takes
minutes: `python -m physcensis.bench --only demos`)."""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import pytest

from physcensis.bench import robot_demos
from physcensis.bench.report import Result, demos_block
from physcensis.robot import demos

DATASET_BYTES = 3_000_000


def _fake_scenes(root: Path, seeds: Sequence[int]) -> dict[str, str]:
    for seed in seeds:
        (root / f"seed_{seed:03d}").mkdir(parents=True)
    return {"7": "the planner placed nothing"}


def _episode(success: bool, stage: str, reason: str | None, planning: float, steps: int) -> dict[str, Any]:
    seconds = {"planning": planning, "execution": 2 * planning, "rendering": 0.5} if steps else {"planning": planning}
    return {"success": success, "stage": stage, "reason": reason, "seconds": seconds, "steps": steps}


EPISODES = {
    "seed_000": _episode(True, "done", None, 1.0, 400),
    "seed_001": _episode(False, "goal", "no free pose on plate_0 for cup_0", 3.0, 0),
}


def _fake_batch(root: Path, out: Path, settings: demos.DemoSettings, *, workers: int = 1) -> dict[str, Any]:
    assert (settings.task, settings.episodes, settings.images, workers) == (robot_demos.TASK, 1, (128, 128), 1)
    cache = robot_demos.cache_root()
    assert (cache / "assets" / "cup.npz").is_file() and not (cache / "grasps").exists()  # an empty grasp cache
    for name, episode in EPISODES.items():
        folder = out / demos.SCENES / name
        folder.mkdir(parents=True)
        report = {"scene": str(root / name), "episodes": [episode]}
        (folder / demos.REPORT).write_text(json.dumps(report))
    (out / demos.DATASET).write_bytes(b"\0" * DATASET_BYTES)
    return {"scenes": 2, "scenes_failed": [], "attempted": 2, "succeeded": 1, "success_rate": 0.5}


@pytest.fixture
def result(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> dict[str, Any]:
    for folder in ("assets", "grasps"):
        (tmp_path / "cache" / folder).mkdir(parents=True)
        (tmp_path / "cache" / folder / "cup.npz").write_bytes(b"")
    monkeypatch.setenv("PHYSCENSIS_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(demos, "run_batch", _fake_batch)
    monkeypatch.setattr(demos, "recheck", lambda dataset: {"checked": 1, "confirmed": 1})
    monkeypatch.setattr(demos, "replay_in_env", lambda dataset: {"replayed": 1, "succeeded": 1})
    figures = robot_demos.run(scenes=2, make_scenes=_fake_scenes)
    assert robot_demos.cache_root() == tmp_path / "cache"  # the user's cache again
    return figures


def test_figures_of_a_run(result: dict[str, Any]) -> None:
    assert (result["scenes"], result["attempted"], result["succeeded"], result["success_rate"]) == (2, 2, 1, 0.5)
    assert result["scenes_not_generated"] == {"7": "the planner placed nothing"}
    assert result["failures_by_stage"] == {
        "goal": {"count": 1, "reasons": ["seed_001: no free pose on plate_0 for cup_0"]}
    }
    assert result["recheck"] == {"checked": 1, "confirmed": 1, "all_confirmed": True}
    # planning is timed in both episodes, simulation and rendering only in the one that ran
    assert result["median_seconds_per_episode"] == {"planning": 2.0, "execution": 2.0, "rendering": 0.5}
    assert result["dataset"] == {"episodes": 1, "bytes": DATASET_BYTES, "mb_per_episode": 3.0, "images": [128, 128]}
    assert len(result["load_average"]) == 2 and result["grasp_cache"] == "fresh"
    assert set(result["seconds"]) == {"generation", "demonstrations", "recheck"}


def test_benchmark_table_from_the_result(result: dict[str, Any]) -> None:
    machine = {"cpu": "Test CPU", "cores": 2, "system": "Linux", "python": "3.11"}
    figures = {**result, "commit": "abc1234", "load_average": [1.5, 2.25]}
    block = demos_block({"demos": Result("demos", {"machine": machine, "result": figures})})
    context = "grasps sampled from an empty cache; load average 1.5 at the start, 2.25 at the end"
    assert f"one worker ({context})." in block and "abc1234" not in block  # the tables name no commit
    assert "| succeeded (primitive verifier) | 1 (50 %); failed: goal 1 | ≥ 80 % |" in block
    assert "| 1 of 1 | all |" in block
    assert "2.0 s / 2.0 s / 0.50 s" in block
    assert "Measured on: Test CPU, 2 cores, Linux, Python 3.11." in block
    assert "not measured yet" in demos_block({})
