"""A plain PLACE-ANYWHERE spot on a table top that touches nothing is set down in the object's rest pose without a
settle of its own; the scene's final verification confirms it. A spot against a neighbour is still settled there."""

from __future__ import annotations

from typing import Any

import pytest
import shapely

import physcensis.solver.physical as physical
from physcensis.assets.catalogue import default_catalogue
from physcensis.geometry.footprints import placed_hull
from physcensis.physics.engine import AT_REST
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.solver.objects import quaternion_yaw
from physcensis.solver.pipeline import AT_REST_M, Solution, solve

pytestmark = pytest.mark.physics

PLATE = [
    ["plate_0", "a dinner plate"],
    ["plate_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
    ["plate_0", "FACING-FRONT", "root", {}],
]


def solved(
    program: list[list[Any]], size: tuple[float, float], monkeypatch: pytest.MonkeyPatch, seed: int = 3
) -> tuple[int, Solution]:
    """The solution and how many confirming settles the physical solver ran."""
    tries = []
    real = physical.PhysicalSolver._try

    def counted(self: physical.PhysicalSolver, *args: Any) -> tuple[bool, str | None]:
        tries.append(1)
        return real(self, *args)

    monkeypatch.setattr(physical.PhysicalSolver, "_try", counted)
    solution = solve({"support": {"kind": "table", "size": list(size)}, "program": program}, seed=seed)
    return len(tries), solution


def footprint(solution: Solution, oid: str) -> shapely.Polygon:
    o = solution.scene.object(oid)
    hull = default_catalogue().asset_for(o.asset, o.description).footprint()
    return shapely.Polygon(placed_hull(hull, o.position[0], o.position[1], quaternion_yaw(o.quaternion)))


def test_things_with_room_all_round_are_set_down_unsettled_and_the_scene_rests(monkeypatch: pytest.MonkeyPatch) -> None:
    free = {"stack": False}
    program = [*PLATE, ["vase_0", "a flower vase"], ["vase_0", "PLACE-ANYWHERE", "root", free]]
    program += [["salt_0", "a salt shaker"], ["salt_0", "PLACE-ANYWHERE", "root", free]]
    tries, solution = solved(program, (0.8, 0.6), monkeypatch, seed=0)
    assert tries == 0 and solution.ok and len(solution.scene.placed) == 3
    for oid in ("vase_0", "salt_0"):
        assert solution.scene.object(oid).position[2] == pytest.approx(solution.scene.support.top_height, abs=1e-3)
    # set down at least APART_M from each other; the final verification's settle moves things a fraction of a mm
    prints = [footprint(solution, oid) for oid in ("plate_0", "vase_0", "salt_0")]
    assert min(a.distance(b) for k, a in enumerate(prints) for b in prints[k + 1 :]) >= physical.APART_M - 0.001
    fresh = MujocoEngine(default_catalogue()).settle_distance(solution.scene, rest=AT_REST)
    assert max(fresh.per_object.values()) < AT_REST_M  # the scene as written rests, under a fresh engine too
    assert MujocoEngine(default_catalogue()).settle_distance(solution.scene).mean_m < AT_REST_M  # and for the full 4 s


@pytest.mark.parametrize(
    "params", [{"stack": True}, {"stack": False, "pack": True}], ids=["may stack", "packs against neighbours"]
)
def test_placements_that_may_touch_others_are_still_settled_where_they_go(
    params: dict[str, Any], monkeypatch: pytest.MonkeyPatch
) -> None:
    program = [*PLATE, ["mug_0", "a mug"], ["mug_0", "PLACE-ANYWHERE", "root", params]]
    tries, solution = solved(program, (0.6, 0.5), monkeypatch)
    assert tries >= 1 and solution.ok and len(solution.scene.placed) == 2
