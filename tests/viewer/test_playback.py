"""The settle as the viewer plays it: the scene's MuJoCo model stepped from the written poses."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from physcensis.output import open_scene
from physcensis.viewer.playback import FRAME_S, SettlePlayback, moved_m

ONE_SECOND = round(1.0 / FRAME_S)


def test_a_resting_scene_stays_at_rest_for_a_second(scene_dir: Path) -> None:
    scene, catalogue = open_scene(scene_dir)
    playback = SettlePlayback(scene, catalogue)
    start = playback.reset()
    np.testing.assert_allclose(start["mug_0"], [*scene.object("mug_0").position, *scene.object("mug_0").quaternion])
    for _ in range(ONE_SECOND):
        playback.step()
    assert playback.time >= 1.0 - 1e-9 and playback.diverged is None
    moved = moved_m(start, playback.poses())
    assert set(moved) == {"book_0", "mug_0", "bowl_0"}
    assert max(moved.values()) < 0.003, moved


def test_a_lifted_object_falls_back_onto_what_carried_it_and_reset_returns_to_the_start(scene_dir: Path) -> None:
    scene, catalogue = open_scene(scene_dir)
    written = scene.object("mug_0")
    x, y, z = written.position
    lifted = [o.model_copy(update={"position": (x, y, z + 0.10)}) if o.id == "mug_0" else o for o in scene.placed]
    playback = SettlePlayback(scene, catalogue, objects=lifted)
    start = playback.reset()
    assert start["mug_0"][2] == z + 0.10
    for _ in range(ONE_SECOND):
        playback.step()
    now = playback.poses()
    assert now["mug_0"][2] < z + 0.005  # fell the 10 cm back down ...
    assert now["mug_0"][2] > z - 0.01  # ... onto the book, not through it
    assert np.linalg.norm(now["book_0"][:3] - start["book_0"][:3]) < 0.01
    again = playback.reset()
    np.testing.assert_array_equal(again["mug_0"], start["mug_0"])
    assert playback.time == 0.0


def test_set_pose_moves_one_object_and_the_simulation_carries_on_from_there(scene_dir: Path) -> None:
    scene, catalogue = open_scene(scene_dir)
    playback = SettlePlayback(scene, catalogue)
    pose = playback.reset()["bowl_0"].copy()
    pose[2] += 0.10
    playback.set_pose("bowl_0", pose)
    assert playback.poses()["bowl_0"][2] == pose[2]
    for _ in range(ONE_SECOND):
        playback.step()
    assert playback.poses()["bowl_0"][2] < pose[2] - 0.095
