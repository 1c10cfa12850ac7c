"""Demonstrations on a scene and on a folder of scenes: whole outputs or none, the merged dataset and report, a
resumed batch that runs nothing twice, the replay re-check, and output folders that are refused."""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

import h5py
import pytest

from physcensis.errors import PhyscensisError
from physcensis.robot import demos
from physcensis.robot.demos import DATASET, REPORT, SCENES, DemoError, DemoSettings
from physcensis.robot.episode import EpisodeOptions, Outcome
from physcensis.robot.world import RobotWorld

from .demo_runs import FAR, NEAR, TASK, BatchRun, batch_run


@pytest.fixture(scope="module")
def batch(small_scene_dir: Path, tmp_path_factory: pytest.TempPathFactory) -> BatchRun:
    return batch_run(small_scene_dir, tmp_path_factory)


def _failing(world: RobotWorld, task: str, options: EpisodeOptions | None = None) -> Outcome:
    return Outcome(False, "goal", "a stand-in that plans nothing", task, {"planning": 0.01})


def _episodes(dataset: Path) -> list[str]:
    with h5py.File(dataset, "r") as handle:
        return sorted(handle["data"])


def test_a_run_that_stops_half_way_leaves_no_folder_and_the_earlier_run_whole(
    small_scene_dir: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = tmp_path / "demos"
    monkeypatch.setattr(demos, "run_episode", _failing)
    demos.run_scene(small_scene_dir, out, DemoSettings(task=TASK, images=None))
    earlier = {p.name: p.read_bytes() for p in out.iterdir()}
    assert {DATASET, REPORT} <= set(earlier)

    calls: list[int] = []

    def breaks_on_the_second(world: RobotWorld, task: str, options: EpisodeOptions | None = None) -> Outcome:
        calls.append(1)
        if len(calls) == 2:
            raise RuntimeError("killed half way")
        return _failing(world, task, options)

    monkeypatch.setattr(demos, "run_episode", breaks_on_the_second)
    for target in (out, tmp_path / "new"):
        calls.clear()
        with pytest.raises(RuntimeError):
            demos.run_scene(small_scene_dir, target, DemoSettings(task=TASK, episodes=3, images=None))
        assert len(calls) == 2
    assert {p.name: p.read_bytes() for p in out.iterdir()} == earlier
    assert not (tmp_path / "new").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["demos"]  # no staging folder left beside it


def test_a_scene_folder_or_a_stranger_folder_is_not_an_output(
    small_scene_dir: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(demos, "run_episode", _failing)
    settings = DemoSettings(task=TASK, images=None)
    scene_files = sorted(p.name for p in small_scene_dir.iterdir())
    with pytest.raises(DemoError, match="is a scene folder"):
        demos.run_scene(small_scene_dir, small_scene_dir, settings)
    assert sorted(p.name for p in small_scene_dir.iterdir()) == scene_files
    theirs = tmp_path / "theirs"
    theirs.mkdir()
    (theirs / "notes.txt").write_text("mine")
    with pytest.raises(PhyscensisError, match="notes.txt"):
        demos.run_scene(small_scene_dir, theirs, settings)
    demos.run_scene(small_scene_dir, theirs, settings, overwrite=True)  # asked for: written beside, never deleted
    assert (theirs / "notes.txt").read_text() == "mine" and (theirs / REPORT).is_file()


@pytest.mark.long
def test_a_batch_writes_each_scene_then_merges_every_episode(batch: BatchRun) -> None:
    for name in (NEAR, FAR):
        assert (batch.out / SCENES / name / DATASET).is_file() and (batch.out / SCENES / name / REPORT).is_file()
    near = json.loads((batch.out / SCENES / NEAR / REPORT).read_text())
    far = json.loads((batch.out / SCENES / FAR / REPORT).read_text())
    assert (near["succeeded"], near["recorded"], far["succeeded"], far["recorded"]) == (1, 1, 0, 0)
    assert far["episodes"][0]["stage"] == "grasp" and "out of reach" in far["episodes"][0]["reason"]
    assert _episodes(batch.out / SCENES / FAR / DATASET) == []  # nothing recorded, let alone as a success
    merged = _episodes(batch.out / DATASET)
    assert len(merged) == near["recorded"] + far["recorded"] == 1
    with h5py.File(batch.out / DATASET, "r") as handle:
        attrs = handle["data"][merged[0]].attrs
        assert bool(attrs["success"]) and not Path(attrs["scene"]).is_absolute()  # copied with its scenes, it replays
        assert demos.scene_of(batch.out / DATASET, attrs["scene"]).resolve() == batch.root.joinpath(NEAR).resolve()
    report = json.loads((batch.out / REPORT).read_text())
    assert report == batch.summary
    assert (report["attempted"], report["succeeded"], report["success_rate"]) == (2, 1, 0.5)
    assert report["failures_by_stage"] == {"grasp": 1} and report["scenes_failed"] == []
    assert report["seconds"]["planning"] > 0


@pytest.mark.long
def test_a_rerun_runs_no_finished_scene_but_one_with_other_settings(
    batch: BatchRun, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    calls: list[str] = []

    def counting(world: RobotWorld, task: str, options: EpisodeOptions | None = None) -> Outcome:
        calls.append(task)
        return _failing(world, task, options)

    monkeypatch.setattr(demos, "run_episode", counting)
    copy = tmp_path / "out"
    shutil.copytree(batch.out, copy)
    assert demos.run_batch(batch.root, copy, DemoSettings(task=TASK, images=None)) == batch.summary
    assert calls == []
    other = demos.run_batch(batch.root, copy, DemoSettings(task=TASK, seed=5, images=None))
    assert len(calls) == 2 and other["attempted"] == 2 and other["succeeded"] == 0


@pytest.mark.slow
@pytest.mark.long
def test_recheck_confirms_the_success_from_the_file_and_catches_a_forged_one(batch: BatchRun, tmp_path: Path) -> None:
    assert demos.recheck(batch.out / DATASET) == {"checked": 1, "confirmed": 1}
    forged = batch.out / f"forged_{tmp_path.name}.hdf5"  # beside the real one: its scene paths are relative
    shutil.copy(batch.out / DATASET, forged)
    try:
        with h5py.File(forged, "r+") as handle:
            demo = handle["data"][_episodes(forged)[0]]
            demo["final_object_poses"][:, 0] += 0.02  # the file claims poses the actions do not reach
        assert demos.recheck(forged) == {"checked": 1, "confirmed": 0}
    finally:
        forged.unlink()


@pytest.mark.slow
@pytest.mark.long
def test_a_dataset_copied_with_its_scenes_replays_in_its_new_place(batch: BatchRun, tmp_path: Path) -> None:
    with h5py.File(batch.out / DATASET, "r") as handle:
        reference = str(handle["data"][_episodes(batch.out / DATASET)[0]].attrs["scene"])
    out = tmp_path.joinpath(*[f"d{k}" for k in range(reference.count("../"))], "out")  # the same layout, elsewhere
    scene = Path(os.path.normpath(out / reference))
    assert tmp_path in scene.parents
    shutil.copytree(batch.root.joinpath(NEAR).resolve(), scene)
    shutil.copy(batch.out / DATASET, out.mkdir(parents=True) or out / DATASET)
    assert demos.recheck(out / DATASET) == {"checked": 1, "confirmed": 1}


@pytest.mark.slow
@pytest.mark.long
def test_every_successful_episode_of_a_dataset_succeeds_again_through_the_environment(batch: BatchRun) -> None:
    assert demos.replay_in_env(batch.out / DATASET) == {"replayed": 1, "succeeded": 1}


def test_a_batch_refuses_an_output_whose_scenes_folder_holds_the_scenes(small_scene_dir: Path, tmp_path: Path) -> None:
    (tmp_path / SCENES).mkdir()
    (tmp_path / SCENES / "kitchen").symlink_to(small_scene_dir, target_is_directory=True)
    with pytest.raises(DemoError, match="holds the scene folder"):
        demos.run_batch(tmp_path / SCENES, tmp_path, DemoSettings(task=TASK, images=None))
    assert (small_scene_dir / "scene.json").is_file()


@pytest.mark.long
def test_scene_folders_follow_links_once_and_a_folder_without_scenes_is_refused(
    batch: BatchRun, tmp_path: Path
) -> None:
    (batch.root / "loop").symlink_to(batch.root, target_is_directory=True)
    try:
        assert [p.name for p in demos.scene_folders(batch.root)] == [FAR, NEAR]
    finally:
        (batch.root / "loop").unlink()
    (tmp_path / "empty" / "mjcf").mkdir(parents=True)
    with pytest.raises(DemoError, match="no scene folder"):
        demos.scene_folders(tmp_path / "empty")
