"""PLACE-ANYWHERE: a random free spot that the seed decides, or, packed, snug against its neighbours. A packed small
table has no centimetre gaps: its search cells shrink with the table (a 1 cm cell leaves up to a centimetre between
neighbours), and what it packs rests without interpenetrating."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from physcensis.assets.catalogue import default_catalogue
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.program.registry import PlacementKind
from physcensis.scene import Scene, Support
from physcensis.solver.physical import PhysicalSolver, PlaceRequest
from physcensis.solver.pipeline import solve

CAN = "ycb_010_potted_meat_can"  # 5.0 x 9.7 cm footprint


def _pack(support: Support, count: int, pitch: float | None) -> Scene:
    catalogue = default_catalogue()
    scene = Scene(seed=0, prompt="cans packed on a small table", support=support)
    solver = PhysicalSolver(scene, MujocoEngine(catalogue), seed=0, pitch=pitch)
    asset = catalogue.get(CAN)
    for k in range(count):
        request = PlaceRequest(
            object_id=f"can_{k}",
            description=asset.description,
            asset=asset,
            kind=PlacementKind.ANYWHERE,
            stack=False,
            pack=True,
        )
        solver.place(request)
    return scene


@pytest.fixture(scope="module")
def packed() -> Scene:
    # 20.5 cm across: three 5 cm cans side by side leave under 5 mm between neighbours and edges.
    return _pack(Support(kind="table", size=(0.205, 0.104)), 3, None)


def test_three_cans_fit_side_by_side_across_a_small_table(packed: Scene) -> None:
    assert len(packed.placed) == 3
    hx, hy = packed.support.half_extents
    for obj in packed.placed:
        assert abs(obj.position[0]) < hx and abs(obj.position[1]) < hy
        assert abs(obj.position[2] - packed.support.top_height) < 0.003  # on the table, not on another can


def test_the_packed_cans_rest_and_do_not_interpenetrate(packed: Scene) -> None:
    engine = MujocoEngine()
    result = engine.settle(packed)
    assert not result.failed
    assert result.max_penetration_m < 0.002
    assert engine.settle_distance(packed).mean_m < 0.001
    for a, b in itertools.combinations(packed.placed, 2):  # 5 cm wide each: centres at least that far apart
        assert abs(a.position[0] - b.position[0]) > 0.049 or abs(a.position[1] - b.position[1]) > 0.049


def test_a_centimetre_grid_fits_fewer_there() -> None:
    """The same table searched with 1 cm cells (a caller's fixed pitch): the cells' rounding leaves no room."""
    assert len(_pack(Support(kind="table", size=(0.205, 0.104)), 3, 0.01).placed) < 3


def _lone_vase(seed: int, params: dict[str, object]) -> tuple[float, float]:
    program = {
        "support": {"kind": "table", "size": [1.2, 0.8]},
        "program": [
            ["vase_0", "a ceramic flower vase"],
            ["vase_0", "PLACE-ANYWHERE", "root", {"stack": False, **params}],
        ],
    }
    solution = solve(program, seed=seed)
    vase = solution.scene.object("vase_0")
    assert vase.status == "placed", vase.reason
    return vase.position[0], vase.position[1]


def test_a_lone_object_goes_to_a_random_spot_that_the_seed_decides() -> None:
    """The paper's PLACE-ANYWHERE: a random free spot. Seeds spread a lone vase over the table (it once went to
    the same corner whatever the seed); the same seed puts it in the same spot."""
    spots = [_lone_vase(seed, {}) for seed in range(6)]
    assert _lone_vase(3, {}) == spots[3]
    assert min(math.dist(a, b) for a, b in itertools.combinations(spots, 2)) > 0.01, spots
    assert np.ptp([x for x, _ in spots]) > 0.3 and np.ptp([y for _, y in spots]) > 0.15, spots


def test_a_packed_lone_object_goes_snug_into_a_corner() -> None:
    for seed in range(2):
        x, y = _lone_vase(seed, {"pack": True})
        vase = default_catalogue().resolve("a ceramic flower vase")
        reach = 0.5 * max(vase.size[:2]) + 0.02  # its centre within 2 cm of its own half-width from both edges
        assert 0.6 - abs(x) < reach and 0.4 - abs(y) < reach, (seed, x, y)
