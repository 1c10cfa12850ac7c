"""PLACE-IN in containers deep enough to stand things in: tall items stand upright side by side on the floor, and
no kept item of several ends with its centre of mass above the rim (what does not fit fails, naming the container);
a container's one item may sit in its opening (an egg in an egg cup)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest
import shapely
from shapely.geometry import Point, Polygon

from physcensis.assets.catalogue import default_catalogue
from physcensis.geometry.voxels import quat_to_matrix
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.profiles import MUJOCO_DEFAULT
from physcensis.program import ItemCount, Relation, lookup
from physcensis.scene import PlacedObject, Scene, Support
from physcensis.solver.layout import PhysicalRequest
from physcensis.solver.packing_in import GAP_M, Footprint, floor_order, plan_floor_spots
from physcensis.solver.pipeline import _place_in_items, solve


def _program(container: str, items: list[list[Any]]) -> dict[str, Any]:
    return {
        "support": {"kind": "table", "size": [1.0, 0.8]},
        "program": [
            ["c_0", container],
            ["c_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
            ["c_0", "FACING-FRONT", "root", {}],
            [items, "PLACE-IN", "c_0", {}],
        ],
    }


def _cavity_in_world(scene: Scene) -> tuple[Polygon, float]:
    """The container's opening in the world and the height of its rim."""
    container = scene.object("c_0")
    cavity = default_catalogue().asset_for(container.asset, container.description).cavity
    assert cavity is not None
    turn = quat_to_matrix(container.quaternion)[:2, :2]
    opening = Polygon(np.asarray(cavity.opening) @ turn.T + np.asarray(container.position[:2]))
    return opening, container.position[2] + cavity.rim_height


def _com(obj: PlacedObject) -> np.ndarray:
    return np.asarray(obj.position) + quat_to_matrix(obj.quaternion) @ np.asarray(obj.com)


def _up(obj: PlacedObject) -> float:
    """Cosine of the tilt of the object's own z axis from the vertical."""
    return float(quat_to_matrix(obj.quaternion)[2, 2])


def _assert_kept_inside_below_rim(scene: Scene) -> list[PlacedObject]:
    opening, rim = _cavity_in_world(scene)
    kept = [o for o in scene.placed if o.id != "c_0"]
    for o in kept:
        com = _com(o)
        assert com[2] < rim, f"{o.id}'s centre of mass is {100 * (com[2] - rim):.1f} cm above the rim"
        assert opening.contains(Point(com[0], com[1])), f"{o.id}'s centre of mass is outside the opening"
    return kept


def test_bottles_and_cans_stand_upright_side_by_side_in_an_open_box() -> None:
    solution = solve(_program("an open cardboard box", [["bottle", 3], ["can", 4]]), seed=0)
    scene = solution.scene
    kept = _assert_kept_inside_below_rim(scene)
    assert len(kept) == 7, solution.feedback()
    catalogue = default_catalogue()
    tall = [o for o in kept if (a := catalogue.asset_for(o.asset, o.description)).size[2] >= max(a.size[:2])]
    assert len(tall) >= 3  # every bottle is taller than wide (and so are round cans)
    for o in tall:
        assert _up(o) > math.cos(math.radians(10)), f"{o.id} is not standing upright ({_up(o):.2f})"
    assert scene.metrics["settle_distance_m"] < 0.003
    assert scene.metrics["max_penetration_mm"] < 3.0


def test_a_small_bin_keeps_what_fits_and_the_rest_fails_naming_the_bin() -> None:
    solution = solve(_program("a small white storage bin", [["water bottle", 9]]), seed=2)
    scene = solution.scene
    kept = _assert_kept_inside_below_rim(scene)
    failed = [o for o in scene.objects if o.status == "failed"]
    assert kept and failed, solution.feedback()
    assert all("c_0" in (o.reason or "") for o in failed), [o.reason for o in failed]
    assert all(_up(o) > math.cos(math.radians(10)) for o in kept)
    assert scene.metrics["settle_distance_m"] < 0.003


def test_floor_spots_are_inside_the_opening_and_apart() -> None:
    opening = shapely.affinity.rotate(shapely.box(-0.2, -0.15, 0.2, 0.15), 30, origin=(0, 0))
    footprints = [Footprint(0.066, 0.066, True)] * 20 + [Footprint(0.045, 0.075, False)] * 5
    spots = plan_floor_spots(opening, footprints)
    shapes = []
    for s in spots:
        fp = footprints[s.index]
        if fp.round:
            shape = Point(s.x, s.y).buffer(fp.sx / 2)
        else:
            shape = shapely.affinity.rotate(
                shapely.box(-fp.sx / 2, -fp.sy / 2, fp.sx / 2, fp.sy / 2), s.yaw, use_radians=True, origin=(0, 0)
            )
            shape = shapely.affinity.translate(shape, s.x, s.y)
        assert opening.buffer(-0.5 * GAP_M).contains(shape)
        assert all(shape.distance(other) > 0.5 * GAP_M for other in shapes)
        shapes.append(shape)
    # 20 cans of 6.6 cm fill a 40 x 30 cm opening (5 x 4 with their gaps), and flat bottles fit in what is left.
    assert sum(1 for s in spots if footprints[s.index].round) == 20
    assert len(spots) > 20


def test_tall_items_get_floor_spots_first() -> None:
    catalogue = default_catalogue()
    bottle, tuna = catalogue.get("bottle_water_plastic"), catalogue.get("ycb_007_tuna_fish_can")
    order = floor_order([tuna, bottle, tuna, bottle])
    assert order[:2] == [1, 3]


def test_items_put_in_something_that_is_not_a_container_are_kept_as_failed_with_the_reason() -> None:
    """A tray or a book has no opening: each item is listed in the scene as failed, naming the target (the items
    used to vanish from the scene while the solve reported nothing wrong)."""
    solution = solve(_program("a serving tray", [["wine bottle", 2]]), seed=0)
    items = [o for o in solution.scene.objects if o.id != "c_0"]
    assert len(items) == 2
    assert all(o.status == "failed" for o in items)
    assert all("c_0" in (o.reason or "") and "not a container" in (o.reason or "") for o in items)
    assert [o.id for o in solution.scene.placed] == ["c_0"]


def test_a_placement_record_agrees_with_the_objects_final_status() -> None:
    """An item kept by PLACE-IN that the final verification fails is failed in its placement record too, with the
    same reason (the record said ok while the object was gone from the scene)."""
    program = _program("a wide shallow wooden fruit bowl", [["apple", 3], ["orange", 2], ["banana", 1]])
    scene = solve(program, seed=6).scene
    assert any(not record["ok"] for record in scene.metrics["placements"])  # the heap fails the final check here
    for record in scene.metrics["placements"]:
        obj = scene.object(record["object"])
        assert record["ok"] == (obj.status == "placed"), record
        if not record["ok"]:
            assert record["reason"] == obj.reason


def test_counted_items_are_what_their_words_name_with_variety_only_among_close_matches() -> None:
    """Six wine bottles are six wine bottles (the bottle category's shampoo and water bottles matched "a wine bottle"
    by a third as well, and came along); a bare "apple" still gets apples of several kinds."""
    catalogue = default_catalogue()
    counts = (ItemCount("a wine bottle", 6), ItemCount("a soda can", 6), ItemCount("apple", 12))
    relation = Relation(4, counts, "PLACE-IN", "c_0", {}, lookup("PLACE-IN"))
    scene = Scene(support=Support(kind="table", size=(1.0, 0.8)))
    made = _place_in_items(PhysicalRequest(relation, (), "c_0"), relation, {}, {}, catalogue, 0, scene)
    kinds = [{asset.id for _, text, asset in made if text.startswith(name)} for name in ("a wine", "a soda", "apple")]
    assert kinds[0] and all(a.startswith("bottle_wine_") for a in kinds[0])  # wine bottles of any kind
    assert kinds[1] and kinds[1] <= {"can_soda_red", "can_soda_silver"}
    assert len(kinds[2]) > 1 and all(catalogue.entry(a).category == "apple" for a in kinds[2])


@pytest.mark.long  # solved and settled under two physics settings
def test_fruit_heaped_in_a_bowl_stays_in_it_and_rests_under_both_settings() -> None:
    """fruit_bowl.json's heap with seed 1 lost fruit (with its banana beside it, all five): the heap took the poses
    it sank to under MuJoCo's defaults, sprang apart under ours, and what moved failed. Heaped things now settle as
    long as the final check watches them under the defaults."""
    program = _program("a wide ceramic fruit bowl", [["apple", 3], ["orange", 2]])  # fruit_bowl.json's bowl
    program["support"]["size"] = [0.6, 0.6]
    scene = solve(program, seed=1).scene
    fruit = [o for o in scene.objects if o.id != "c_0"]
    assert len(fruit) == 5 and all(o.status == "placed" for o in fruit), [(o.id, o.reason) for o in fruit]
    assert len(_assert_kept_inside_below_rim(scene)) == 5
    assert scene.metrics["settle_distance_m"] < 0.001
    assert MujocoEngine(profile=MUJOCO_DEFAULT).settle_distance(scene).mean_m < 0.005


@pytest.mark.parametrize("cup", ["a yellow ceramic egg cup", "a white porcelain egg cup on a short stem"])
def test_an_egg_sits_in_an_egg_cup_above_its_rim_and_rests(cup: str) -> None:
    solution = solve(_program(cup, [["a brown hen's egg", 1]]), seed=0)
    scene = solution.scene
    egg = next(o for o in scene.placed if o.id != "c_0")
    opening, rim = _cavity_in_world(scene)
    com = _com(egg)
    assert solution.ok, solution.feedback()
    assert com[2] > rim and opening.contains(Point(com[0], com[1]))  # held in the opening, above the rim
    assert egg.position[2] < rim  # its bottom in the cup
    assert scene.metrics["settle_distance_m"] < 0.003
    assert MujocoEngine(profile=MUJOCO_DEFAULT).settle_distance(scene).mean_m < 0.003  # and under MuJoCo's defaults


def test_an_egg_cup_holds_one_egg_and_a_second_fails_naming_it() -> None:
    solution = solve(_program("a yellow ceramic egg cup", [["a brown hen's egg", 2]]), seed=0)
    kept = [o for o in solution.scene.placed if o.id != "c_0"]
    assert len(kept) == 1 and not solution.ok and "c_0" in solution.feedback()
