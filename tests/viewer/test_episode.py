"""A recorded robot demonstration of the scene, played by the viewer: its object poses, the arm along it, and the
command line's check of both."""

from __future__ import annotations

import os
import time
from pathlib import Path

import numpy as np
import pytest

from physcensis.viewer.episode import EpisodeRef, check_objects, read_episode_track
from physcensis.viewer.scene_view import ViewerError, open_scene_view

h5py = pytest.importorskip("h5py")  # the robot extra


@pytest.fixture(scope="module")
def dataset(scene_dir: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Episode 0: the mug starts 3 cm up and falls while the arm turns and the gripper closes (recorded as the robot
    code records a demonstration, written as its datasets are)."""
    from physcensis.robot import control
    from physcensis.robot.panda import FINGER_CLOSED
    from physcensis.robot.record import DatasetWriter, EpisodeRecorder
    from physcensis.robot.world import build_world

    world = build_world(scene_dir)
    recorder = EpisodeRecorder(world, image_size=None)
    world.reset()
    world.data.qpos[world.object_qpos["mug_0"] + 2] += 0.03
    start = world.data.qpos[world.arm_qpos].copy()
    control.follow(
        world, np.linspace(start, start + np.array([0.3, 0.1, 0, 0.1, 0, 0, 0.2]), 8), 0.04, recorder.observe
    )
    control.move_gripper(world, FINGER_CLOSED, 0.3, recorder.observe)
    path = tmp_path_factory.mktemp("episodes") / "demos.hdf5"
    with DatasetWriter(path, {}) as writer:
        writer.add_episode(recorder.episode(task="scripted", scene=os.path.relpath(scene_dir, path.parent)))
    return path


def test_the_reference_reads_dataset_and_index() -> None:
    assert EpisodeRef.parse("out/demos.hdf5:3") == EpisodeRef(Path("out/demos.hdf5"), 3)
    assert EpisodeRef.parse("out/demos.hdf5") == EpisodeRef(Path("out/demos.hdf5"), 0)
    with pytest.raises(ViewerError, match="whole number"):
        EpisodeRef.parse("out/demos.hdf5:last")


def test_the_track_holds_every_recorded_step_and_the_end(dataset: Path) -> None:
    track = read_episode_track(EpisodeRef(dataset, 0))
    with h5py.File(dataset) as handle:
        group = handle["data/demo_0"]
        steps = int(group.attrs["num_samples"])
        recorded = group["obs/object_poses"][()]
        final = group["final_object_poses"][()]
    assert track.frames == steps + 1 and track.object_poses.shape == (steps + 1, 3, 7)
    mug = track.object_ids.index("mug_0")
    np.testing.assert_array_equal(track.poses(0)["mug_0"], recorded[0, mug])
    np.testing.assert_array_equal(track.poses(track.frames - 1)["mug_0"], final[mug])
    assert track.poses(0)["mug_0"][2] - track.poses(track.frames - 1)["mug_0"][2] > 0.02  # it fell
    assert track.frame_at(track.duration_s + 5.0) == track.frames - 1
    assert sorted(check_objects(track, ["mug_0", "book_0", "plate_9"])) == ["book_0", "mug_0"]


def test_another_scenes_episode_a_missing_one_and_a_file_that_is_no_dataset_are_clear_errors(
    dataset: Path, tmp_path: Path
) -> None:
    track = read_episode_track(EpisodeRef(dataset, 0))
    with pytest.raises(ViewerError, match="another scene"):
        check_objects(track, ["plate_0"])
    with pytest.raises(ViewerError, match="no episode demo_7"):
        read_episode_track(EpisodeRef(dataset, 7))
    with pytest.raises(ViewerError, match="no such dataset"):
        read_episode_track(EpisodeRef(tmp_path / "none.hdf5", 0))
    junk = tmp_path / "junk.hdf5"
    junk.write_text("not a dataset")
    with pytest.raises(ViewerError, match="not a readable HDF5"):
        read_episode_track(EpisodeRef(junk, 0))


def test_the_arm_follows_the_recorded_states(scene_dir: Path, dataset: Path) -> None:
    from physcensis.robot.record import read_episode
    from physcensis.viewer.robot_view import robot_view

    track = read_episode_track(EpisodeRef(dataset, 0))
    robot = robot_view(scene_dir, track)
    names = [link.name for link in robot.links]
    assert {"link0", "link7", "hand", "left_finger", "right_finger"} <= set(names)
    assert robot.poses.shape == (track.frames, len(names), 7) and len(robot.fixed) == 1  # and the pedestal
    base = robot.link_poses(0)["link0"]
    assert base[2] == pytest.approx(open_scene_view(scene_dir)[0].scene.support.top_height)
    # The hand's origin is the recorded tool centre point less the TCP offset along the hand's z axis.
    episode = read_episode(dataset, 0)
    for k in (0, track.frames - 2):
        hand = robot.link_poses(k)["hand"]
        assert np.linalg.norm(hand[:3] - episode.obs["eef_pos"][k]) == pytest.approx(0.1034, abs=1e-3)
    assert not np.allclose(robot.link_poses(0)["link7"], robot.link_poses(track.frames - 1)["link7"])


def test_the_server_plays_the_episode_to_its_recorded_end(scene_dir: Path, dataset: Path) -> None:
    pytest.importorskip("viser")
    from physcensis.viewer.playback import SettlePlayback
    from physcensis.viewer.robot_view import robot_view
    from physcensis.viewer.server import ViewerServer

    view, catalogue = open_scene_view(scene_dir)
    track = read_episode_track(EpisodeRef(dataset, 0))
    robot = robot_view(scene_dir, track)
    server = ViewerServer(view, SettlePlayback(view.scene, catalogue), track=track, robot=robot)
    try:
        assert server.server.scene.get_handle_by_name("/robot/hand") is not None
        server.play_episode()
        end = time.monotonic() + 10.0
        while server.playing != "idle" and time.monotonic() < end:
            time.sleep(0.05)
        mug = server.server.scene.get_handle_by_name("/objects/mug_0")
        assert mug is not None
        np.testing.assert_allclose(mug.position, track.poses(track.frames - 1)["mug_0"][:3], atol=1e-4)
        hand = server.server.scene.get_handle_by_name("/robot/hand")
        np.testing.assert_allclose(hand.position, robot.link_poses(track.frames - 1)["hand"][:3], atol=1e-4)
        assert "episode" in server.status.content
    finally:
        server.close()


def test_the_commands_check_plays_the_episode_with_the_arm(scene_dir: Path, dataset: Path) -> None:
    from typer.testing import CliRunner

    from physcensis.cli import app

    result = CliRunner().invoke(app, ["view", str(scene_dir), "--check", "--steps", "3", "--episode", f"{dataset}:0"])
    assert result.exit_code == 0, result.output
    out = " ".join(result.output.split())
    assert f"episode: {dataset}:0" in out and "3 objects" in out and "the arm's 11 links" in out
    assert "warning" not in out  # recorded in this very scene
