"""Grasps of the small scene's mug and bowl: they hold when lifted and shaken, a grasp on air does not, the cache
answers a second call, and the open hand at every scene grasp is free of the scene's collision geoms."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import mujoco
import numpy as np
import pytest

from physcensis.robot import grasps
from physcensis.robot import hand as free_hand
from physcensis.robot.convex import body_pieces
from physcensis.robot.world import RobotWorld, build_world

CANDIDATES = 600
LIFT_TESTS = 16


@pytest.fixture(scope="module")
def grasp_cache(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    folder = tmp_path_factory.mktemp("grasp-cache")
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("PHYSCENSIS_CACHE_DIR", str(folder))
        yield folder


@pytest.fixture(scope="module")
def world(small_scene_dir: Path) -> RobotWorld:
    return build_world(small_scene_dir)


@pytest.fixture(scope="module")
def held(world: RobotWorld, grasp_cache: Path) -> dict[str, list[grasps.Grasp]]:
    return {
        name: grasps.grasps_for(world, name, n_candidates=CANDIDATES, seed=0, lift_tests=LIFT_TESTS)
        for name in ("cup_0", "bowl_0")
    }


def _rig(world: RobotWorld, name: str) -> grasps._LiftRig:
    body = world.object_bodies[name]
    return grasps._LiftRig(world.model, body, body_pieces(world.model, body))


@pytest.mark.parametrize("name", ["cup_0", "bowl_0"])
def test_kept_grasps_lift_the_object_and_keep_it_between_the_fingers(
    world: RobotWorld, held: dict[str, list[grasps.Grasp]], name: str
) -> None:
    kept = held[name]
    assert len(kept) >= 3, f"{name}: only {len(kept)} grasps held"
    again = grasps.lift_test(_rig(world, name), kept[:3])  # re-run: the object rises with the hand, no slip
    assert again.held.all()
    assert (again.rise > 0.1).all()
    assert (again.slip < grasps.HELD_SLIP).all()
    for grasp in kept:
        assert 0.0 < grasp.width < 0.08
        assert np.allclose(grasp.object_T_tcp[:3, :3].T @ grasp.object_T_tcp[:3, :3], np.eye(3), atol=1e-6)


def test_jaws_closed_on_air_beside_the_object_are_rejected(world: RobotWorld) -> None:
    rig = _rig(world, "cup_0")
    beside = np.eye(4)
    beside[:3, :3] = np.diag([1.0, -1.0, -1.0])  # approach straight down
    beside[:3, 3] = [0.16, 0.0, 0.05]  # 16 cm to the side of the mug's axis, at mid-height
    result = grasps.lift_test(rig, [grasps.Grasp(beside, 0.05, 1.0)])
    assert not result.held[0]
    assert result.rise[0] < 0.01  # the mug stayed on the floor


def test_second_call_reads_the_cache(
    world: RobotWorld, held: dict[str, list[grasps.Grasp]], monkeypatch: pytest.MonkeyPatch
) -> None:
    def no_sampling(*args: object, **kwargs: object) -> list[grasps.Grasp]:
        raise AssertionError("sampled again although the asset's grasps are cached")

    monkeypatch.setattr(grasps, "sample_antipodal", no_sampling)
    monkeypatch.setattr(grasps, "lift_test", no_sampling)
    again = grasps.grasps_for(world, "cup_0", n_candidates=CANDIDATES, seed=0, lift_tests=LIFT_TESTS)
    assert len(again) == len(held["cup_0"])
    for a, b in zip(again, held["cup_0"], strict=True):
        assert np.allclose(a.object_T_tcp, b.object_T_tcp) and a.score == pytest.approx(b.score)
    assert Path(grasps.cache_path(world, "cup_0", CANDIDATES, 0, LIFT_TESTS)).is_file()


def _independent_hand_contacts(scene_dir: Path, world_T_tcp: np.ndarray) -> float:
    """Deepest penetration of the open hand with the scene loaded afresh from its MJCF (no robot)."""
    spec = mujoco.MjSpec.from_file(str(scene_dir / "mjcf" / "scene.xml"))
    free_hand.add_free_hand(spec)
    model = spec.compile()
    data = mujoco.MjData(model)
    index = free_hand.HandIndex.of(model)
    free_hand.place_hand(model, data, index, world_T_tcp, 0.04)
    mujoco.mj_forward(model, data)
    depths = [-float(c.dist) for c in data.contact[: data.ncon] if c.geom[0] in index.geoms or c.geom[1] in index.geoms]
    return max(depths, default=0.0)


def test_scene_grasps_are_free_of_collisions_and_from_above_first(
    world: RobotWorld, held: dict[str, list[grasps.Grasp]], small_scene_dir: Path
) -> None:
    into_table = np.eye(4)
    into_table[:3, :3] = np.diag([1.0, -1.0, -1.0])
    into_table[2, 3] = -0.03  # the TCP 3 cm under the mug's base: the fingers are in the table
    offered = [*held["cup_0"], grasps.Grasp(into_table, 0.05, 99.0)]
    in_scene = grasps.grasps_in_scene(world, "cup_0", offered)
    assert in_scene and all(grasp.score < 99.0 for grasp, _ in in_scene)
    above = [-tcp[2, 2] >= grasps.FROM_ABOVE for _, tcp in in_scene]
    assert above == sorted(above, reverse=True)
    for _, tcp in in_scene[:4]:
        assert _independent_hand_contacts(small_scene_dir, tcp) < 1e-3
