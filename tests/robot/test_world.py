"""The Panda mounted on a scene: a real arm that holds its pose and leaves the scene at rest."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from physcensis.robot import panda
from physcensis.robot.panda import Mount, RobotModelError
from physcensis.robot.world import FRONT_CAMERA, WRIST_CAMERA, build_world


def test_panda_holds_home_and_its_gripper_opens_and_closes() -> None:
    spec = panda.panda_spec()
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    model = spec.compile()
    data = mujoco.MjData(model)
    arm = [model.joint(name).qposadr[0] for name in panda.ARM_JOINTS]
    fingers = [model.joint(name).qposadr[0] for name in panda.FINGER_JOINTS]
    data.qpos[arm] = panda.HOME_Q
    data.ctrl[:7] = panda.HOME_Q
    data.ctrl[7] = panda.FINGER_OPEN
    for _ in range(500):
        mujoco.mj_step(model, data)
    assert np.abs(data.qpos[arm] - panda.HOME_Q).max() < 1e-3  # gravity compensated, servoed
    assert data.qpos[fingers] == pytest.approx([panda.FINGER_OPEN] * 2, abs=1e-3)
    data.ctrl[7] = panda.FINGER_CLOSED
    for _ in range(500):
        mujoco.mj_step(model, data)
    assert data.qpos[fingers] == pytest.approx([0.0, 0.0], abs=1e-3)  # both fingers, coupled
    # Realistic link masses (the URDF's, about 18 kg in all), not the URDF's placeholder inertias.
    assert 16.0 < model.body_mass.sum() < 20.0
    assert model.body_inertia[1:].max() < 0.05


def test_world_mounts_the_arm_at_a_long_edge_facing_the_table(small_scene_dir: Path) -> None:
    world = build_world(small_scene_dir)
    top = world.scene.support.top_height
    assert world.scene.support.size[0] > world.scene.support.size[1]  # deeper (x) than wide (y): the right edge
    assert world.base_position[1] < -world.scene.support.size[1] / 2  # outside the table's right (-y) edge
    assert world.base_position[2] == pytest.approx(top)
    tcp, rotation = world.tcp_pose()
    assert tcp[1] > world.base_position[1] + 0.3  # the hand reaches over the table
    assert rotation[:, 2] @ np.array([0.0, 0.0, -1.0]) > 0.95  # pointing down
    half_x, half_y = (extent / 2 for extent in world.scene.support.size)
    for edge, outside in (("front", (0, half_x)), ("back", (0, -half_x)), ("left", (1, half_y))):
        other = build_world(small_scene_dir, Mount(edge=edge))
        axis, limit = outside
        assert abs(other.base_position[axis]) > abs(limit) and np.sign(other.base_position[axis]) == np.sign(limit)
        reach = other.tcp_pose()[0] - other.base_position
        assert reach[axis] * np.sign(limit) < -0.3  # the hand is over the table, not behind the base


def test_scene_rests_with_the_arm_idle_and_nothing_touches_it(small_scene_dir: Path) -> None:
    world = build_world(small_scene_dir)
    before = world.object_poses()
    assert set(before) == {"plate_0", "cup_0", "bowl_0"}
    for _ in range(1000):  # 2 s
        mujoco.mj_step(world.model, world.data)
    after = world.object_poses()
    assert max(np.linalg.norm(after[k][:3] - before[k][:3]) for k in before) < 1e-3
    assert np.abs(world.data.qpos[world.arm_qpos] - panda.HOME_Q).max() < 1e-3
    bodies = world.model.geom_bodyid
    for contact in world.data.contact[: world.data.ncon]:
        assert bodies[contact.geom1] not in world.robot_bodies and bodies[contact.geom2] not in world.robot_bodies


def test_both_cameras_see_something(small_scene_dir: Path) -> None:
    world = build_world(small_scene_dir)
    with mujoco.Renderer(world.model, 96, 128) as renderer:
        for camera in (FRONT_CAMERA, WRIST_CAMERA):
            renderer.update_scene(world.data, camera=camera)
            image = renderer.render()
            assert image.std() > 10.0, camera  # not a blank frame


def test_bad_mounts_are_refused_with_the_reason(small_scene_dir: Path) -> None:
    with pytest.raises(RobotModelError, match="edge 'north'"):
        build_world(small_scene_dir, Mount(edge="north"))
    with pytest.raises(RobotModelError, match="off the 0.9 m right edge"):
        build_world(small_scene_dir, Mount(offset=2.0))
    with pytest.raises(RobotModelError, match="no mjcf/scene.xml"):
        empty = small_scene_dir.parent / "no-mjcf"
        empty.mkdir(exist_ok=True)
        (empty / "scene.json").write_text((small_scene_dir / "scene.json").read_text())
        build_world(empty)
