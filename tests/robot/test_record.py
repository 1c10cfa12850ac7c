"""Recording a run, the HDF5 dataset's layout and round trip, exact replay, and videos of the frames."""

from __future__ import annotations

import json
from pathlib import Path

import h5py
import imageio_ffmpeg
import numpy as np
import pytest
from PIL import Image

from physcensis.robot import control
from physcensis.robot.panda import FINGER_CLOSED
from physcensis.robot.record import (
    LOW_DIM,
    DatasetWriter,
    Episode,
    EpisodeRecorder,
    RecordError,
    get_state,
    read_episode,
    replay,
)
from physcensis.robot.video import VideoError, write_video
from physcensis.robot.world import RobotWorld, build_world

IMAGE = (48, 64)  # (height, width): not square, so a swapped axis shows


def _scripted_run(world: RobotWorld, recorder: EpisodeRecorder) -> None:
    """The mug starts 3 cm up and falls while the arm turns a little and the gripper closes."""
    world.reset()
    address = world.object_qpos["cup_0"]
    world.data.qpos[address + 2] += 0.03
    start = world.data.qpos[world.arm_qpos].copy()
    waypoints = np.linspace(start, start + np.array([0.25, 0.1, 0.0, 0.1, 0.0, 0.0, 0.2]), 8)
    control.follow(world, waypoints, 0.04, recorder.observe)
    control.move_gripper(world, FINGER_CLOSED, 0.3, recorder.observe)


@pytest.fixture(scope="module")
def world(small_scene_dir: Path) -> RobotWorld:
    return build_world(small_scene_dir)


@pytest.fixture(scope="module")
def recorded(world: RobotWorld) -> tuple[Episode, Episode]:
    """The same run recorded with images (a success) and without (a failure)."""
    with_images = EpisodeRecorder(world, image_size=IMAGE)
    _scripted_run(world, with_images)
    first = with_images.episode(task="pick cup_0 place-on plate_0", success=True, seed=7, scene="small")
    plain = EpisodeRecorder(world, image_size=None)
    _scripted_run(world, plain)
    second = plain.episode(task="pick cup_0 place-in bowl_0", success=False, reason="cup_0 moved 3.0 cm", seed=8)
    return first, second


def test_each_step_is_the_world_before_its_action(recorded: tuple[Episode, Episode], world: RobotWorld) -> None:
    episode, plain = recorded
    n = episode.num_samples
    assert n == 8 + 6  # 8 waypoints, then 0.3 s of closing at 20 Hz
    shapes = {name: episode.obs[name].shape for name in LOW_DIM}
    assert shapes == {
        "joint_pos": (n, 7),
        "joint_vel": (n, 7),
        "eef_pos": (n, 3),
        "eef_quat": (n, 4),
        "gripper_qpos": (n, 2),
        "object_poses": (n, 3, 7),
    }
    assert episode.front_rgb is not None and episode.front_rgb.shape == (n, *IMAGE, 3)
    assert episode.wrist_rgb is not None and episode.front_rgb.dtype == np.uint8
    assert episode.front_rgb[0].std() > 5  # a picture, not a blank
    assert plain.front_rgb is None and plain.num_samples == n
    # The first row is the start: the arm at home, the mug still 3 cm up, the first action the first waypoint.
    assert np.allclose(episode.obs["joint_pos"][0], world.initial_qpos[world.arm_qpos])
    cup = episode.object_ids.index("cup_0")
    assert episode.obs["object_poses"][0, cup, 2] == pytest.approx(
        world.initial_qpos[world.object_qpos["cup_0"] + 2] + 0.03
    )
    assert episode.obs["object_poses"][-1, cup, 2] < episode.obs["object_poses"][0, cup, 2] - 0.02  # it fell
    assert np.allclose(np.linalg.norm(episode.obs["eef_quat"], axis=1), 1.0)
    assert episode.actions.shape == (n, 8) and episode.actions[-1, 7] == FINGER_CLOSED
    assert np.linalg.norm(episode.obs["eef_pos"][-1] - episode.obs["eef_pos"][0]) > 0.05  # the hand moved
    assert episode.dones.tolist() == [0] * (n - 1) + [1]
    assert episode.rewards[-1] == 1.0 and plain.rewards.sum() == 0.0


def _same(a: Episode, b: Episode) -> None:
    assert a.obs.keys() == b.obs.keys()
    for name in a.obs:
        assert np.array_equal(a.obs[name], b.obs[name]), name
    for name in ("actions", "rewards", "dones", "states", "final_state", "final_poses"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert a.object_ids == b.object_ids
    assert a.attrs == b.attrs


def test_hdf5_round_trip_and_layout(recorded: tuple[Episode, Episode], tmp_path: Path) -> None:
    path = tmp_path / "demos.hdf5"
    with DatasetWriter(path, {"env_name": "physcensis_pick_place", "env_kwargs": {"scene": "small"}}) as writer:
        assert [writer.add_episode(e) for e in recorded] == [0, 1]
    for k, episode in enumerate(recorded):
        _same(read_episode(path, k), episode)
    with h5py.File(path, "r") as handle:
        data = handle["data"]
        assert sorted(data) == ["demo_0", "demo_1"]
        assert data.attrs["total"] == sum(e.num_samples for e in recorded)
        assert json.loads(data.attrs["env_args"])["env_kwargs"] == {"scene": "small"}
        demo = data["demo_0"]
        assert {"obs", "actions", "rewards", "dones", "states"} <= set(demo)
        assert demo["obs"]["front_rgb"].compression == "gzip" and demo["obs"]["front_rgb"].dtype == np.uint8
        assert list(demo["obs"]["object_poses"].attrs["object_ids"]) == ["plate_0", "cup_0", "bowl_0"]
        assert demo["states"].shape[0] == demo.attrs["num_samples"] == recorded[0].num_samples
        assert (demo.attrs["success"], demo.attrs["task"], demo.attrs["seed"]) == (
            True,
            "pick cup_0 place-on plate_0",
            7,
        )
        assert data["demo_1"].attrs["reason"] == "cup_0 moved 3.0 cm" and "front_rgb" not in data["demo_1"]["obs"]
    with pytest.raises(RecordError, match="has no episode demo_2"):
        read_episode(path, 2)


def test_an_interrupted_writer_leaves_no_file(recorded: tuple[Episode, Episode], tmp_path: Path) -> None:
    path = tmp_path / "demos.hdf5"
    with pytest.raises(RuntimeError), DatasetWriter(path, {}) as writer:
        writer.add_episode(recorded[0])
        raise RuntimeError("the machine went down")
    assert list(tmp_path.iterdir()) == []
    # An older dataset at the path survives a failed rewrite.
    with DatasetWriter(path, {}) as writer:
        writer.add_episode(recorded[1])
    with pytest.raises(RuntimeError), DatasetWriter(path, {}) as writer:
        writer.add_episode(recorded[0])
        raise RuntimeError("again")
    assert [p.name for p in tmp_path.iterdir()] == ["demos.hdf5"]
    _same(read_episode(path, 0), recorded[1])


def test_replay_restores_the_start_and_reproduces_the_final_poses(
    recorded: tuple[Episode, Episode], small_scene_dir: Path
) -> None:
    episode = recorded[0]
    fresh = build_world(small_scene_dir)
    fresh.data.qpos[fresh.object_qpos["bowl_0"]] += 0.1  # a world left somewhere else must not matter
    final = replay(fresh, episode)
    expected = episode.final_object_poses()
    assert final.keys() == expected.keys()
    for oid in expected:
        assert np.array_equal(final[oid], expected[oid]), oid
    assert np.array_equal(get_state(fresh), episode.final_state)
    cup = episode.object_ids.index("cup_0")
    assert final["cup_0"][2] < episode.obs["object_poses"][0, cup, 2] - 0.02  # the replay really moved it


def test_replay_refuses_an_empty_episode(world: RobotWorld) -> None:
    empty = EpisodeRecorder(world, image_size=None).episode(task="nothing")
    assert empty.num_samples == 0 and empty.obs["object_poses"].shape == (0, 3, 7)
    with pytest.raises(RecordError, match="no steps"):
        replay(world, empty)


def test_write_video_mp4_and_gif(recorded: tuple[Episode, Episode], tmp_path: Path) -> None:
    frames = recorded[0].front_rgb
    assert frames is not None
    mp4 = write_video(frames, tmp_path / "episode.mp4", fps=20)
    reader = imageio_ffmpeg.read_frames(str(mp4))
    meta = next(reader)
    decoded = [np.frombuffer(f, np.uint8).reshape(IMAGE[0], IMAGE[1], 3) for f in reader]
    assert meta["size"] == (IMAGE[1], IMAGE[0]) and meta["codec"] == "h264" and len(decoded) == len(frames)
    assert np.abs(decoded[3].astype(int) - frames[3]).mean() < 12  # the same picture, up to compression
    gif = write_video(iter(frames), tmp_path / "episode.gif", fps=10)
    with Image.open(gif) as image:
        frame_count = image.n_frames  # type: ignore[attr-defined]  # Pillow's GIF reader has it
        assert (frame_count, image.size, image.info["duration"]) == (len(frames), (IMAGE[1], IMAGE[0]), 100)
    odd = write_video([f[:-1, :-1] for f in frames[:3]], tmp_path / "odd.mp4")  # 47 x 63: padded to even sides
    assert next(imageio_ffmpeg.read_frames(str(odd)))["size"] == (IMAGE[1], IMAGE[0])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["episode.gif", "episode.mp4", "odd.mp4"]


@pytest.mark.parametrize(
    ("frames", "name", "message"),
    [
        ([np.zeros((8, 8, 3), np.uint8)], "clip.avi", "as .mp4 or .gif, not '.avi'"),
        ([], "clip.mp4", "no frames"),
        ([], "clip.gif", "no frames"),
        ([np.zeros((8, 8, 3), np.uint8), np.zeros((8, 10, 3), np.uint8)], "clip.gif", "frame 1 is 10x8; the first"),
        ([np.zeros((8, 8, 3), np.float32)], "clip.mp4", "frame 0 is float32"),
    ],
)
def test_write_video_refuses_what_it_cannot_write(
    frames: list[np.ndarray], name: str, message: str, tmp_path: Path
) -> None:
    with pytest.raises(VideoError, match=message.replace("(", r"\(").replace(".", r"\.")):
        write_video(frames, tmp_path / name)
    assert list(tmp_path.iterdir()) == []
