"""The Gymnasium environment: it passes Gymnasium's own checker, a recorded demonstration replays through it step for
step to the same success, and it refuses what it cannot use in one line."""

from __future__ import annotations

from pathlib import Path

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

from physcensis.robot.env import ENV_ID, EnvError, PickPlaceEnv
from tests.robot.demo_runs import NEAR, TASK, batch_run


def test_the_environment_passes_gymnasiums_checker(small_scene_dir: Path) -> None:
    env = PickPlaceEnv(small_scene_dir, TASK, images=(32, 48), render_mode="rgb_array", max_steps=5)
    check_env(env, skip_render_check=False)
    obs, info = env.reset(seed=3)
    assert obs["front_rgb"].shape == (32, 48, 3) and obs["pick_pose"].shape == (7,)
    assert info == {"task": "pick cup_0 place-on plate_0", "scene": str(small_scene_dir), "success": False, "steps": 0}
    frame = env.render()
    assert frame is not None and frame.shape == (480, 640, 3) and frame.std() > 0  # a picture, not a blank
    env.close()


def test_it_is_registered_and_truncates_at_its_step_limit(small_scene_dir: Path) -> None:
    env = gymnasium.make(ENV_ID, scenes=small_scene_dir, task=TASK, max_steps=3)
    obs, _ = env.reset(seed=0)
    hold = np.append(obs["joint_pos"], obs["gripper_target"])  # keep the arm where it is
    results = [env.step(hold) for _ in range(3)]
    assert [r[2:4] for r in results] == [(False, False), (False, False), (False, True)]
    assert all(r[1] == 0.0 for r in results)
    cup = results[-1][0]["pick_pose"]
    assert np.allclose(cup, obs["pick_pose"], atol=1e-3)  # holding still moves nothing
    env.close()


@pytest.mark.slow
@pytest.mark.long
def test_a_recorded_demonstration_replays_through_the_environment_to_its_success(
    small_scene_dir: Path, tmp_path_factory: pytest.TempPathFactory
) -> None:
    episode = batch_run(small_scene_dir, tmp_path_factory).attempts[NEAR].outcome.episode
    assert episode is not None and episode.attrs["success"]
    env = PickPlaceEnv(small_scene_dir, TASK)
    obs, _ = env.reset(seed=0)
    assert np.array_equal(obs["joint_pos"], episode.obs["joint_pos"][0])
    rewards = []
    for k, action in enumerate(episode.actions):
        if k:  # the world before action k is the world the recording saw before it
            assert np.allclose(obs["joint_pos"], episode.obs["joint_pos"][k], atol=1e-9), k
        obs, reward, terminated, truncated, info = env.step(action)
        rewards.append(reward)
        if terminated:
            break
    assert terminated and info["success"] and not truncated and rewards[-1] == 1.0 and sum(rewards) == 1.0
    env.close()


def test_a_folder_of_scenes_is_drawn_from_by_the_seed(small_scene_dir: Path, tmp_path: Path) -> None:
    for name in ("a", "b", "c"):
        (tmp_path / name).symlink_to(small_scene_dir, target_is_directory=True)
    env = PickPlaceEnv(tmp_path, TASK)
    drawn = [env.reset(seed=seed)[1]["scene"] for seed in range(8)]
    again = [env.reset(seed=seed)[1]["scene"] for seed in range(8)]
    assert drawn == again and len(set(drawn)) > 1
    env.close()


def test_what_it_cannot_use_is_refused_in_one_line(small_scene_dir: Path, tmp_path: Path) -> None:
    with pytest.raises(EnvError, match=r"no scene.json there or in the folders below it"):
        PickPlaceEnv(tmp_path, TASK)
    with pytest.raises(EnvError, match=r"scene: .*teapot"):
        PickPlaceEnv(small_scene_dir, "pick the teapot place-on plate_0")
    with pytest.raises(EnvError, match="render_mode 'human'"):
        PickPlaceEnv(small_scene_dir, TASK, render_mode="human")
