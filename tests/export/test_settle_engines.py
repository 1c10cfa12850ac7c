"""`SettleEngine`: MuJoCo and the PyBullet cross-check (on the URDF export) measure the settle distance alike."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from physcensis.crosscheck.bullet_engine import BulletEngine
from physcensis.physics.engine import SettleEngine
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.profiles import MUJOCO_DEFAULT
from physcensis.scene import Scene


def _mujoco_defaults() -> MujocoEngine:
    return MujocoEngine(profile=MUJOCO_DEFAULT)


@pytest.mark.parametrize(
    "make_engine", [MujocoEngine, _mujoco_defaults, BulletEngine], ids=["mujoco", "mujoco-default", "bullet"]
)
def test_every_engine_sees_the_resting_scene_rest_and_a_raised_cup_fall_for_as_long_as_asked(
    desk_scene: Scene, make_engine: Callable[[], SettleEngine]
) -> None:
    if make_engine is BulletEngine:
        pytest.importorskip("pybullet")
    engine = make_engine()
    assert isinstance(engine, SettleEngine)
    resting = engine.settle_distance(desk_scene)
    assert resting.diverged is None
    assert set(resting.per_object) == {o.id for o in desk_scene.placed}
    # Under a millimetre in each: PyBullet's 1 mm margin around convex meshes is taken out of the URDF's meshes.
    assert resting.mean_m < 0.001, resting.per_object

    raised = desk_scene.model_copy(deep=True)
    cup = next(o for o in raised.objects if o.category == "cup")
    cup.position = (cup.position[0], cup.position[1], cup.position[2] + 0.2)
    fallen = engine.settle_distance(raised)
    assert fallen.per_object[cup.id] == pytest.approx(0.2, abs=0.01)
    falling = engine.settle_distance(raised, duration_s=0.05)  # mid-fall: ½ g t², 1.2 cm (+ the steps' Euler error)
    assert falling.per_object[cup.id] == pytest.approx(0.0135, abs=0.002)
