"""PLACE-ANYWHERE packs a small table without centimetre gaps: its search cells shrink with the table (a 1 cm cell
leaves up to a centimetre between neighbours), and what it packs rests without interpenetrating."""

from __future__ import annotations

import itertools

import pytest

from physcensis.assets.catalogue import default_catalogue
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.program.registry import PlacementKind
from physcensis.scene import Scene, Support
from physcensis.solver.physical import PhysicalSolver, PlaceRequest

CAN = "ycb_010_potted_meat_can"  # 5.0 x 9.7 cm footprint


def _pack(support: Support, count: int, pitch: float | None) -> Scene:
    catalogue = default_catalogue()
    scene = Scene(seed=0, prompt="cans packed on a small table", support=support)
    solver = PhysicalSolver(scene, MujocoEngine(catalogue), seed=0, pitch=pitch)
    asset = catalogue.get(CAN)
    for k in range(count):
        request = PlaceRequest(
            object_id=f"can_{k}", description=asset.description, asset=asset, kind=PlacementKind.ANYWHERE, stack=False
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
