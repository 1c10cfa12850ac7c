"""LeRobot export: the frames carry the recorded steps in LeRobot's layout, and the converter refuses what it
cannot convert. Writing the dataset needs the `lerobot` extra (PyTorch): that test runs only where it is installed."""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest
from typer.testing import CliRunner

from physcensis.cli.app import app
from physcensis.robot import lerobot_export
from physcensis.robot.lerobot_export import LeRobotExportError, export_lerobot, lerobot_features, lerobot_frames
from physcensis.robot.record import Episode, read_episode

from .demo_runs import BatchRun, batch_run

runner = CliRunner()
IDS = ("bowl_0", "cup_0", "plate_0")


def _episode(steps: int = 4, images: tuple[int, int] | None = (16, 24)) -> Episode:
    rng = np.random.default_rng(0)
    obs = {
        "joint_pos": rng.normal(size=(steps, 7)),
        "joint_vel": rng.normal(size=(steps, 7)),
        "eef_pos": rng.normal(size=(steps, 3)),
        "eef_quat": rng.normal(size=(steps, 4)),
        "gripper_qpos": rng.uniform(0, 0.04, size=(steps, 2)),
        "object_poses": rng.normal(size=(steps, len(IDS), 7)),
    }
    if images is not None:
        for camera in ("front", "wrist"):
            obs[f"{camera}_rgb"] = rng.integers(0, 255, size=(steps, *images, 3), dtype=np.uint8)
    return Episode(
        obs=obs,
        actions=rng.normal(size=(steps, 8)),
        rewards=np.r_[np.zeros(steps - 1), 1.0],
        dones=np.r_[np.zeros(steps - 1), 1.0],
        states=np.zeros((steps, 3)),
        object_ids=IDS,
        final_state=np.zeros(3),
        final_poses=np.zeros((len(IDS), 7)),
        attrs={"task": "pick cup_0 place-on plate_0", "instruction": "put the cup on the plate", "success": True},
    )


def test_frames_carry_the_steps_with_the_named_objects_in_the_feature_shapes() -> None:
    episode = _episode()
    frames = list(lerobot_frames(episode))
    features = lerobot_features((16, 24))
    assert len(frames) == episode.num_samples
    for k, frame in enumerate(frames):
        assert set(frame) - {"task"} == set(features)
        for name, spec in features.items():
            if spec["dtype"] == "video":
                assert frame[name].shape == spec["shape"] and frame[name].dtype == np.uint8
            else:
                assert frame[name].shape == spec["shape"] and frame[name].dtype == np.dtype(spec["dtype"])
        assert frame["task"] == "put the cup on the plate"
        np.testing.assert_allclose(frame["observation.state"][:7], episode.obs["joint_pos"][k], rtol=1e-6)
        np.testing.assert_allclose(frame["observation.state"][7:], episode.obs["gripper_qpos"][k], rtol=1e-6)
        poses = episode.obs["object_poses"][k]
        np.testing.assert_allclose(frame["observation.environment_state"][:7], poses[IDS.index("cup_0")], rtol=1e-6)
        np.testing.assert_allclose(frame["observation.environment_state"][7:], poses[IDS.index("plate_0")], rtol=1e-6)
        np.testing.assert_allclose(frame["action"], episode.actions[k], rtol=1e-6)
        assert np.array_equal(frame["observation.images.wrist"], episode.obs["wrist_rgb"][k])
    assert [bool(f["next.done"][0]) for f in frames] == [False, False, False, True]


def test_without_recorded_images_there_are_no_camera_features() -> None:
    frames = list(lerobot_frames(_episode(images=None)))
    assert not any(name.startswith("observation.images") for name in lerobot_features(None))
    assert not any(name.startswith("observation.images") for name in frames[0])


def test_an_episode_whose_task_names_no_recorded_object_is_refused() -> None:
    episode = _episode()
    episode.attrs["task"] = "pick mug_9 place-on plate_0"
    with pytest.raises(LeRobotExportError, match="mug_9"):
        list(lerobot_frames(episode))


@pytest.fixture(scope="module")
def batch(small_scene_dir: Path, tmp_path_factory: pytest.TempPathFactory) -> BatchRun:
    return batch_run(small_scene_dir, tmp_path_factory)


def _only_failures(batch: BatchRun, tmp_path: Path) -> Path:
    dataset = tmp_path / "failed.hdf5"
    shutil.copy(batch.out / "demos.hdf5", dataset)
    with h5py.File(dataset, "r+") as handle:
        for group in handle["data"].values():
            group.attrs["success"] = False
    return dataset


def test_a_dataset_without_successes_or_a_used_folder_is_refused_before_anything_is_written(
    batch: BatchRun, tmp_path: Path
) -> None:
    failed = _only_failures(batch, tmp_path)
    with pytest.raises(LeRobotExportError, match="no successful episodes.*--include-failed"):
        export_lerobot(failed, tmp_path / "lerobot")
    used = tmp_path / "used"
    used.mkdir()
    (used / "mine.txt").write_text("keep")
    with pytest.raises(LeRobotExportError, match="already exists"):
        export_lerobot(batch.out / "demos.hdf5", used)
    assert (used / "mine.txt").read_text() == "keep"
    text = tmp_path / "notes.hdf5"
    text.write_text("not HDF5")
    with pytest.raises(LeRobotExportError, match="not a readable demonstrations dataset"):
        export_lerobot(text, tmp_path / "x")
    with pytest.raises(LeRobotExportError, match="owner/name"):
        export_lerobot(batch.out / "demos.hdf5", tmp_path / "y", repo_id="no slash")
    assert not (tmp_path / "lerobot").exists() and not (tmp_path / "x").exists()


def test_without_the_lerobot_package_the_error_says_which_extra_to_install(
    batch: BatchRun, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setitem(sys.modules, "lerobot", None)  # makes `import lerobot...` fail as if it were not installed
    result = runner.invoke(app, ["demo-export", str(batch.out / "demos.hdf5"), "--out", str(tmp_path / "ds")])
    assert result.exit_code != 0
    assert "physcensis[lerobot]" in result.output and "Traceback" not in result.output
    assert not (tmp_path / "ds").exists() and list(tmp_path.iterdir()) == []


def test_the_export_command_refuses_a_missing_dataset_in_one_line(tmp_path: Path) -> None:
    result = runner.invoke(app, ["demo-export", str(tmp_path / "none.hdf5"), "--out", str(tmp_path / "ds")])
    assert result.exit_code != 0 and "no such dataset file" in result.output and "Traceback" not in result.output


def test_a_lerobot_dataset_holds_every_successful_step(batch: BatchRun, tmp_path: Path) -> None:
    pytest.importorskip("lerobot", reason="the lerobot extra is not installed")
    from lerobot.datasets.lerobot_dataset import LeRobotDataset

    dataset = batch.out / "demos.hdf5"
    summary = export_lerobot(dataset, tmp_path / "ds", repo_id="test/demos")
    episode = read_episode(dataset, 0)
    assert summary.episodes == 1 and summary.frames == episode.num_samples
    loaded = LeRobotDataset("test/demos", root=tmp_path / "ds")
    assert loaded.num_episodes == 1 and loaded.num_frames == episode.num_samples
    assert loaded.fps == lerobot_export.FPS
    last = loaded[episode.num_samples - 1]
    np.testing.assert_allclose(last["action"].numpy(), episode.actions[-1], rtol=1e-6)
    assert [p.name for p in tmp_path.iterdir()] == ["ds"]  # no staging folder left behind


class _StubDataset:
    """Stands in for LeRobot's writer (PyTorch is not in the test environment): keeps the frames, writes one file."""

    frames: list[dict[str, object]] = []
    fail_after: int | None = None

    @classmethod
    def create(cls, *, root: Path, features: dict[str, object], **kwargs: object) -> _StubDataset:
        root.mkdir(parents=True)
        (root / "images").mkdir()  # LeRobot's scratch folder, empty once the videos are made
        writer = cls()
        writer.root, writer.features = root, features
        cls.frames = []
        return writer

    def add_frame(self, frame: dict[str, object]) -> None:
        if self.fail_after is not None and len(self.frames) >= self.fail_after:
            raise RuntimeError("disk full")
        self.frames.append(frame)

    def save_episode(self) -> None:
        (self.root / "meta.json").write_text(str(len(self.frames)))

    def finalize(self) -> None:
        pass


def test_the_dataset_appears_whole_or_not_at_all(
    batch: BatchRun, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(lerobot_export, "_lerobot_dataset_class", lambda: _StubDataset)
    dataset = batch.out / "demos.hdf5"
    summary = export_lerobot(dataset, tmp_path / "ds")
    assert summary.frames == len(_StubDataset.frames) == read_episode(dataset, 0).num_samples
    assert sorted(p.name for p in (tmp_path / "ds").iterdir()) == ["meta.json"]  # the empty scratch folder is gone
    assert [p.name for p in tmp_path.iterdir()] == ["ds"]
    monkeypatch.setattr(_StubDataset, "fail_after", 5)
    with pytest.raises(LeRobotExportError, match="LeRobot could not write the dataset: RuntimeError: disk full"):
        export_lerobot(dataset, tmp_path / "broken")
    assert [p.name for p in tmp_path.iterdir()] == ["ds"]  # no half dataset, no staging folder


@pytest.mark.parametrize("damage", ["data-is-a-dataset", "episode-is-a-dataset", "flat-frames"])
def test_a_damaged_dataset_is_one_clear_error(tmp_path: Path, damage: str) -> None:
    path = tmp_path / "demos.hdf5"
    with h5py.File(path, "w") as handle:
        if damage == "data-is-a-dataset":
            handle.create_dataset("data", data=np.zeros(3))
        elif damage == "episode-is-a-dataset":
            handle.create_group("data").create_dataset("demo_0", data=np.zeros(3))
        else:
            obs = handle.create_group("data/demo_0/obs")
            handle["data/demo_0"].attrs["success"] = True
            obs.create_dataset("front_rgb", data=np.zeros(12, dtype=np.uint8))
    result = runner.invoke(app, ["demo-export", str(path), "--out", str(tmp_path / "ds")])
    assert result.exit_code != 0 and "Traceback" not in result.output
    assert str(path) in " ".join(result.output.split()) or "demos.hdf5" in result.output
    assert not (tmp_path / "ds").exists()
