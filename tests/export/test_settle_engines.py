"""`SettleEngine`: MuJoCo and the PyBullet cross-check (on the URDF export) measure the settle distance alike."""

from __future__ import annotations

import pytest

from physcensis.crosscheck.bullet_engine import BulletEngine
from physcensis.physics.engine import SettleEngine
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.scene import Scene


@pytest.mark.parametrize("make_engine", [MujocoEngine, BulletEngine], ids=["mujoco", "bullet"])
def test_either_engine_sees_the_resting_scene_rest_and_a_raised_cup_fall(
    desk_scene: Scene, make_engine: type[SettleEngine]
) -> None:
    if make_engine is BulletEngine:
        pytest.importorskip("pybullet")
    engine = make_engine()
    assert isinstance(engine, SettleEngine)
    resting = engine.settle_distance(desk_scene)
    assert resting.diverged is None
    assert set(resting.per_object) == {o.id for o in desk_scene.placed}
    assert resting.mean_m < 0.005, resting.per_object

    raised = desk_scene.model_copy(deep=True)
    cup = next(o for o in raised.objects if o.category == "cup")
    cup.position = (cup.position[0], cup.position[1], cup.position[2] + 0.2)
    fallen = engine.settle_distance(raised)
    assert fallen.per_object[cup.id] == pytest.approx(0.2, abs=0.01)
