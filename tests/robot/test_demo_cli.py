"""`physcensis demo` and `physcensis demo-batch`: a run on the small scene writes its outputs and says how it went;
every hostile input is one `error:` line and exit code 2, before any work and without writing anything."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner, Result

from physcensis.cli import app
from physcensis.fileio import OWNER_FILE
from physcensis.robot import demos
from physcensis.robot.demos import DATASET, REPORT, SCENES
from physcensis.robot.episode import EpisodeOptions, Outcome
from physcensis.robot.record import read_episode
from physcensis.robot.world import RobotWorld

from .demo_runs import NEAR, TASK, batch_run

runner = CliRunner()


@pytest.fixture(scope="module")
def demo_out(small_scene_dir: Path, tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Result]:
    out = tmp_path_factory.mktemp("demo-cli") / "out"
    args = ["demo", str(small_scene_dir), "--task", TASK, "--images", "none", "--out", str(out)]
    result = runner.invoke(app, [*args, "--video", "0", "--video-size", "96x128"])  # the video test reads its film
    return out, result


def _one_error_line(result: Result) -> str:
    assert result.exit_code == 2, result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), result.output
    assert "Traceback" not in result.output and result.exception is None or isinstance(result.exception, SystemExit)
    return lines[0]


@pytest.mark.slow
@pytest.mark.long
def test_demo_writes_the_dataset_and_report_and_prints_the_success_line(demo_out: tuple[Path, Result]) -> None:
    out, result = demo_out
    assert result.exit_code == 0, result.output
    assert "1/1 episodes succeeded (100 %)" in result.stdout
    assert {DATASET, REPORT, OWNER_FILE} <= {p.name for p in out.iterdir()}
    report = json.loads((out / REPORT).read_text())
    assert (report["attempted"], report["succeeded"], report["task"]) == (1, 1, TASK)
    assert read_episode(out / DATASET, 0).attrs["success"]


@pytest.mark.slow
@pytest.mark.long
def test_the_same_seed_gives_the_same_episode(
    demo_out: tuple[Path, Result], small_scene_dir: Path, tmp_path_factory: pytest.TempPathFactory
) -> None:
    """The command's run and the library's batch run of the same scene, task and seed act identically."""
    from_cli = read_episode(demo_out[0] / DATASET, 0)
    from_batch = batch_run(small_scene_dir, tmp_path_factory).attempts[NEAR].outcome.episode
    assert from_batch is not None and from_cli.actions.shape == from_batch.actions.shape
    assert (from_cli.actions == from_batch.actions).all()
    assert (from_cli.final_poses == from_batch.final_poses).all()


@pytest.mark.long
def test_demo_runs_again_into_its_own_folder(
    demo_out: tuple[Path, Result], small_scene_dir: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def failing(world: RobotWorld, task: str, options: EpisodeOptions | None = None) -> Outcome:
        return Outcome(False, "goal", "no room on plate_0 (a stand-in)", task, {"planning": 0.01})

    monkeypatch.setattr(demos, "run_episode", failing)
    out = tmp_path / "out"
    shutil.copytree(demo_out[0], out)
    result = runner.invoke(app, ["demo", str(small_scene_dir), "--task", TASK, "--images", "none", "--out", str(out)])
    assert result.exit_code == 1, result.output  # ran to the end, nothing succeeded
    assert "0/1 episodes succeeded" in result.stdout and "no room on plate_0" in result.stdout
    assert json.loads((out / REPORT).read_text())["succeeded"] == 0


def _not_a_scene(tmp: Path, scene: Path) -> tuple[Path, dict[str, str]]:
    (tmp / "folder" / "a").mkdir(parents=True)
    return tmp / "folder", {}


def _folder_of_scenes(tmp: Path, scene: Path) -> tuple[Path, dict[str, str]]:
    (tmp / "many").mkdir()
    (tmp / "many" / "a").symlink_to(scene, target_is_directory=True)
    return tmp / "many", {}


def _no_mjcf(tmp: Path, scene: Path) -> tuple[Path, dict[str, str]]:
    (tmp / "bare").mkdir()
    shutil.copy(scene / "scene.json", tmp / "bare")
    return tmp / "bare", {}


def _out_is_a_file(tmp: Path, scene: Path) -> tuple[Path, dict[str, str]]:
    (tmp / "out").write_text("not a folder")
    return scene, {}


def _out_holds_strangers_files(tmp: Path, scene: Path) -> tuple[Path, dict[str, str]]:
    (tmp / "out").mkdir()
    (tmp / "out" / "notes.txt").write_text("mine")
    return scene, {}


HOSTILE = {
    "not a scene": (_not_a_scene, "no scene folder"),
    "a folder of scenes": (_folder_of_scenes, "use demo-batch"),
    "the scene file": (lambda tmp, scene: (scene / "scene.json", {}), "no scene folder"),
    "no mjcf": (_no_mjcf, "mjcf"),
    "missing scene": (lambda tmp, scene: (tmp / "nowhere", {}), "no scene folder"),
    "empty task": (lambda tmp, scene: (scene, {"task": "   "}), "--task is empty"),
    "huge images": (lambda tmp, scene: (scene, {"images": "5x5000"}), "--images"),
    "mount sideways": (lambda tmp, scene: (scene, {"mount": "sideways"}), "--mount 'sideways'"),
    "video beyond": (lambda tmp, scene: (scene, {"video": "3", "episodes": "1"}), "--video 3"),
    "huge video": (lambda tmp, scene: (scene, {"video": "0", "video-size": "480x9000"}), "--video-size"),
    "zero episodes": (lambda tmp, scene: (scene, {"episodes": "0"}), "--episodes"),
    "out is a file": (_out_is_a_file, "not a folder"),
    "out holds strangers' files": (_out_holds_strangers_files, "notes.txt"),
    "out is the scene": (lambda tmp, scene: (scene, {"out": str(scene)}), "is a scene folder"),
}


@pytest.mark.parametrize("case", list(HOSTILE))
def test_demo_refuses_hostile_input_with_one_line(case: str, small_scene_dir: Path, tmp_path: Path) -> None:
    make, expected = HOSTILE[case]
    scene, changes = make(tmp_path, small_scene_dir)
    args = {"task": TASK, "images": "none", "out": str(tmp_path / "out"), **changes}
    before = {p.name: p.stat().st_mtime_ns for p in tmp_path.iterdir()}
    scene_files = sorted(p.name for p in small_scene_dir.iterdir())
    result = runner.invoke(app, ["demo", str(scene), *[f"--{k}={v}" for k, v in args.items()]])
    assert expected in _one_error_line(result)
    assert {p.name: p.stat().st_mtime_ns for p in tmp_path.iterdir()} == before  # nothing written
    assert sorted(p.name for p in small_scene_dir.iterdir()) == scene_files


def test_demo_batch_refuses_a_folder_without_scenes_and_an_output_over_the_scenes(
    small_scene_dir: Path, tmp_path: Path
) -> None:
    (tmp_path / "empty").mkdir()
    no_scenes = runner.invoke(
        app, ["demo-batch", str(tmp_path / "empty"), "--task", TASK, "--out", str(tmp_path / "o")]
    )
    assert "no scene folder" in _one_error_line(no_scenes)
    assert not (tmp_path / "o").exists()
    (tmp_path / "made" / SCENES).mkdir(parents=True)  # as `physcensis batch` lays out its scenes
    (tmp_path / "made" / SCENES / "dining_0").symlink_to(small_scene_dir, target_is_directory=True)
    over = runner.invoke(
        app, ["demo-batch", str(tmp_path / "made" / SCENES), "--task", TASK, "--out", str(tmp_path / "made")]
    )
    assert "holds the scene folder" in _one_error_line(over)
    (tmp_path / "theirs").mkdir()
    (tmp_path / "theirs" / "notes.txt").write_text("mine")
    stranger = runner.invoke(
        app, ["demo-batch", str(tmp_path / "made"), "--task", TASK, "--out", str(tmp_path / "theirs")]
    )
    assert "notes.txt" in _one_error_line(stranger)


@pytest.mark.slow
@pytest.mark.long
def test_a_video_is_filmed_again_by_replay_at_a_size_a_person_can_watch(
    demo_out: tuple[Path, Result], small_scene_dir: Path, tmp_path_factory: pytest.TempPathFactory
) -> None:
    import imageio_ffmpeg

    from physcensis.robot.record import replay_frames
    from physcensis.robot.world import build_world

    episode = batch_run(small_scene_dir, tmp_path_factory).attempts[NEAR].outcome.episode
    assert episode is not None
    world = build_world(small_scene_dir)
    frames = list(replay_frames(world, episode, (96, 128)))
    assert len(frames) == episode.num_samples + 1 and frames[0].shape == (96, 128, 3)
    final = world.object_poses()  # the replay is the recorded motion, exactly
    assert all((final[k][:3] == pose[:3]).all() for k, pose in episode.final_object_poses().items())
    out, result = demo_out
    assert result.exit_code == 0, result.output
    reader = imageio_ffmpeg.read_frames(str(out / "episode_0.mp4"))
    meta = next(reader)
    assert meta["size"] == (128, 96) and sum(1 for _ in reader) == episode.num_samples + 1
