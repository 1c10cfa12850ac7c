"""Small things and things that lean on a thin point are placed and rest: a die, a lipstick, a tennis ball and a whisk
on the floor (whose search grid has 3 cm cells) and on a table."""

from __future__ import annotations

import pytest

from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.scene import Support
from physcensis.solver.pipeline import solve

THINGS = ["a red die", "a gold lipstick", "a tennis ball", "a small whisk", "a combination wrench"]


@pytest.mark.parametrize("support", [Support(kind="floor", size=(2.0, 2.0)), Support(kind="table", size=(0.8, 0.8))])
def test_small_things_are_placed_anywhere_and_rest(support: Support) -> None:
    program: list[list[object]] = []
    for k, description in enumerate(THINGS):
        program += [[f"thing_{k}", description], [f"thing_{k}", "PLACE-ANYWHERE", "root", {}]]
    solution = solve(program, support=support, seed=3)
    scene = solution.scene
    assert [o.id for o in scene.placed] == [f"thing_{k}" for k in range(len(THINGS))], solution.feedback()
    assert scene.metrics["settle_distance_m"] < 0.003
    result = MujocoEngine().settle(scene)
    assert not result.failed and result.max_penetration_m < 0.002
    assert all(abs(o.position[2] - support.top_height) < 0.003 for o in scene.placed)  # each rests on the support
