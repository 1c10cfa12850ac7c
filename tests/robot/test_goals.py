"""Goal poses: on the plate the mug stands near the plate's centre, touching it and at rest in the full scene; a
mandarin goes into the bowl below its rim; a plate on a mug finds no room and says why."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from physcensis.robot import goals
from physcensis.robot.hand import qpos_to_pose
from physcensis.robot.world import RobotWorld, build_world
from tests.robot.programs import solved_folder

FRUIT_SCENE = Path(__file__).with_name("fruit_scene.json")


@pytest.fixture(scope="module")
def world(small_scene_dir: Path) -> RobotWorld:
    return build_world(small_scene_dir)


@pytest.fixture(scope="module")
def fruit_scene_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return solved_folder(FRUIT_SCENE.name, tmp_path_factory.mktemp("fruit-scene") / "scene")


def _scene_at(scene_dir: Path, object_id: str, pose: np.ndarray) -> tuple[mujoco.MjModel, mujoco.MjData]:
    """The scene loaded afresh (every object free), the object moved to the pose."""
    model = mujoco.MjModel.from_xml_path(str(scene_dir / "mjcf" / "scene.xml"))
    data = mujoco.MjData(model)
    address = model.jnt_qposadr[model.body_jntadr[model.body(object_id).id]]
    data.qpos[address : address + 7] = pose
    mujoco.mj_forward(model, data)
    return model, data


def _contacts(model: mujoco.MjModel, data: mujoco.MjData, object_id: str) -> dict[str, float]:
    body = model.body(object_id).id
    found: dict[str, float] = {}
    for c in data.contact[: data.ncon]:
        owners = model.geom_bodyid[c.geom[0]], model.geom_bodyid[c.geom[1]]
        if body in owners:
            other = model.body(owners[1] if owners[0] == body else owners[0]).name
            found[other] = max(found.get(other, 0.0), -float(c.dist))
    return found


def _collision_vertices(model: mujoco.MjModel, data: mujoco.MjData, object_id: str) -> np.ndarray:
    body = model.body(object_id).id
    points = []
    for g in range(model.ngeom):
        if model.geom_bodyid[g] == body and model.geom_contype[g] and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH:
            mesh = model.geom_dataid[g]
            local = model.mesh_vert[model.mesh_vertadr[mesh] : model.mesh_vertadr[mesh] + model.mesh_vertnum[mesh]]
            points.append(local @ data.geom_xmat[g].reshape(3, 3).T + data.geom_xpos[g])
    return np.concatenate(points)


def _rests(model: mujoco.MjModel, data: mujoco.MjData, object_id: str, seconds: float = 0.5) -> float:
    address = model.jnt_qposadr[model.body_jntadr[model.body(object_id).id]]
    start = data.qpos[address : address + 3].copy()
    for _ in range(int(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)
    return float(np.linalg.norm(data.qpos[address : address + 3] - start))


def test_mug_on_plate_stands_near_the_centre_touching_and_at_rest(world: RobotWorld, small_scene_dir: Path) -> None:
    poses = goals.goal_poses(world, "cup_0", "on", "plate_0", n=6, rng=np.random.default_rng(0))
    assert len(poses) == 6, poses.reason
    plate = world.object_poses()["plate_0"]
    for pose in poses:
        model, data = _scene_at(small_scene_dir, "cup_0", pose)
        points = _collision_vertices(model, data, "cup_0")
        base = points[points[:, 2] < points[:, 2].min() + 0.005, :2]
        assert np.linalg.norm(base - plate[:2], axis=1).max() < 0.135  # the plate's radius
        assert np.linalg.norm(base.mean(axis=0) - plate[:2]) < 0.1
        assert qpos_to_pose(pose)[2, 2] > 0.999  # upright as it stands now (only turned about z)
        model, data = _scene_at(small_scene_dir, "cup_0", pose)
        assert max(_contacts(model, data, "cup_0").values(), default=0.0) < 1e-3  # no penetration
        lowered = pose.copy()
        lowered[2] -= 0.0015
        model, data = _scene_at(small_scene_dir, "cup_0", lowered)
        assert set(_contacts(model, data, "cup_0")) == {"plate_0"}  # what is just under it is the plate
        model, data = _scene_at(small_scene_dir, "cup_0", pose)
        assert _rests(model, data, "cup_0") < 0.005


def test_mandarin_in_bowl_sits_below_the_rim(fruit_scene_dir: Path) -> None:
    world = build_world(fruit_scene_dir)
    poses = goals.goal_poses(world, "fruit_0", "in", "bowl_0", n=4, rng=np.random.default_rng(1))
    assert poses, poses.reason
    model, data = _scene_at(fruit_scene_dir, "fruit_0", world.object_poses()["fruit_0"])
    rim = _collision_vertices(model, data, "bowl_0")[:, 2].max()
    for pose in poses:
        model, data = _scene_at(fruit_scene_dir, "fruit_0", pose)
        assert _collision_vertices(model, data, "fruit_0")[:, 2].min() < rim - 0.01
        assert np.linalg.norm(pose[:2] - data.xpos[model.body("bowl_0").id][:2]) < 0.05
        assert _rests(model, data, "fruit_0") < 0.005


def test_no_room_on_a_mug_for_a_plate_says_why(world: RobotWorld) -> None:
    poses = goals.goal_poses(world, "plate_0", "on", "cup_0", n=4, rng=np.random.default_rng(0))
    assert poses == []
    assert poses.reason and "cup_0" in poses.reason and "plate_0" in poses.reason and "tried" in poses.reason


def test_unknown_target_is_refused(world: RobotWorld) -> None:
    with pytest.raises(goals.GoalError, match="no_such"):
        goals.goal_poses(world, "cup_0", "on", "no_such", rng=np.random.default_rng(0))
