"""Long things dropped into a deep holder, or into one too narrow for them to lie in, stand in it, and the holder's
room is counted by what is below its rim: toothbrushes in a tumbler, pens in a pen holder, spatulas in a utensil
crock, spoons in a mug."""

from __future__ import annotations

import numpy as np
import pytest
from shapely.geometry import Point, Polygon

from physcensis.assets.catalogue import default_catalogue
from physcensis.assets.model import Asset, Cavity
from physcensis.geometry.voxels import quat_to_matrix
from physcensis.scene import PlacedObject
from physcensis.solver.pipeline import solve


def _cavity_of(holder: PlacedObject) -> tuple[Cavity, Polygon]:
    """A placed holder's cavity and its opening in the world."""
    cavity = default_catalogue().asset_for(holder.asset, holder.description).cavity
    assert cavity is not None
    return cavity, Polygon(np.asarray(cavity.opening) + np.asarray(holder.position[:2]))


def _pose_of(obj: PlacedObject) -> tuple[Asset, np.ndarray, np.ndarray]:
    """An object's asset, its rotation matrix and its long axis in the world."""
    asset = default_catalogue().asset_for(obj.asset, obj.description)
    turn = quat_to_matrix(obj.quaternion)
    return asset, turn, turn[:, int(np.argmax(asset.size))]


@pytest.mark.slow
@pytest.mark.parametrize(
    ("holder", "item", "count", "upright_cos", "seed"),
    [
        # Five toothbrushes leaning in a tumbler settle chaotically: over seeds 0-39 all five stay at 27 seeds (29
        # when verification wrote the poses of one settle more); seed 0 keeps them with either.
        pytest.param("a glass tumbler", "a bamboo toothbrush", 5, 0.7, 0, marks=pytest.mark.long),  # 6 s
        ("a pen holder cup", "a ballpoint pen", 5, 0.7, 1),
        ("a pen holder cup", "a toothbrush", 4, 0.7, 1),
        # Wider than deep: the spoons lay across its rim; standing in it, they lean on its wall.
        ("a white enamel camping mug", "a small teaspoon", 3, 0.5, 1),
    ],
)
def test_long_items_stand_inside_a_holder(holder: str, item: str, count: int, upright_cos: float, seed: int) -> None:
    solution = solve(
        {
            "support": {"kind": "table", "size": [0.6, 0.6]},
            "program": [
                ["holder_0", holder],
                ["holder_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
                ["holder_0", "FACING-FRONT", "root", {}],
                [[[item, count]], "PLACE-IN", "holder_0", {}],
            ],
        },
        seed=seed,
    )
    scene = solution.scene
    holder_obj = scene.object("holder_0")
    cavity, opening = _cavity_of(holder_obj)
    items = [o for o in scene.objects if o.id != "holder_0"]
    assert len(items) == count and all(o.status == "placed" for o in items), solution.feedback()
    rim = holder_obj.position[2] + cavity.rim_height
    for o in items:
        asset, turn, long_axis = _pose_of(o)
        assert abs(long_axis[2]) > upright_cos, f"{o.id} is not standing: long axis {long_axis.round(2)}"
        middle = np.asarray(o.position) + turn @ np.array([0.0, 0.0, asset.size[2] / 2])
        low_end = middle - np.sign(long_axis[2]) * long_axis * max(asset.size) / 2
        assert opening.buffer(0.005).contains(Point(low_end[0], low_end[1])), f"{o.id} does not stand in the holder"
        assert low_end[2] < rim, f"{o.id}'s lower end is above the rim"
    assert scene.metrics["settle_distance_m"] < 0.003


PENCILS = [
    "a short blue pencil",
    "a green graphite pencil",
    "a black drawing pencil",
    "a yellow HB pencil",
    "a red pencil with an eraser",
    "a flat carpenter pencil",
    "a short blue pencil",
    "a green graphite pencil",
]


@pytest.mark.slow
@pytest.mark.parametrize("seed", [0, 1])
@pytest.mark.long
def test_eight_pencils_leaning_in_a_coffee_mug_all_stay_in_it(seed: int) -> None:
    """The planner's "a mug of pencils". Pencils leaning in a wide mug creep into each other under MuJoCo's
    defaults; written as they crept, they sprang apart under ours and took their neighbours out (7 and 3 of the 8
    were kept with these seeds). Contents now settle under the defaults first and ours last, and what crept together
    is put back together."""
    ids = [f"pencil_{k}" for k in range(len(PENCILS))]
    solution = solve(
        {
            "support": {"kind": "table", "size": [0.6, 1.0]},
            "program": [
                ["mug_0", "a classic white ceramic coffee mug"],
                ["mug_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.2}],
                ["mug_0", "FACING-FRONT", "root", {}],
                *[[oid, text] for oid, text in zip(ids, PENCILS, strict=True)],
                [ids, "PLACE-IN", "mug_0", {}],
            ],
        },
        seed=seed,
    )
    scene = solution.scene
    _, opening = _cavity_of(scene.object("mug_0"))
    assert all(scene.object(oid).status == "placed" for oid in ids), solution.feedback()
    for oid in ids:
        pencil = scene.object(oid)
        _, turn, long_axis = _pose_of(pencil)
        com = np.asarray(pencil.position) + turn @ np.asarray(pencil.com)
        assert opening.buffer(0.01).contains(Point(com[0], com[1])), f"{oid} is not over the mug"
        assert abs(long_axis[2]) > 0.5, f"{oid} is not standing in the mug"
    assert scene.metrics["settle_distance_m"] < 0.001
