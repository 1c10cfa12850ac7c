"""Any small thing finds a spot anywhere on a large empty support: a ball, a marble, a coin, a pen, a die on floors
(3 cm search cells, windowed past 9 m) of 1 to 10 m and large tables."""

from __future__ import annotations

import pytest

from physcensis.assets.catalogue import default_catalogue
from physcensis.assets.fallback import stand_in
from physcensis.assets.model import Asset
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.program.registry import PlacementKind
from physcensis.scene import Scene, Support
from physcensis.solver.physical import PhysicalSolver, PlaceRequest, Spots

SIZES_M = {"floor": (1.0, 3.7, 10.0), "table": (1.3,)}


def _small_things() -> list[Asset]:
    catalogue = default_catalogue()
    built = [catalogue.get(i) for i in ("ball_tennis", "pen_ballpoint_blue")]
    return built + [stand_in(d) for d in ("a 1.5 cm glass marble", "a 2 cm coin", "a 0.8 cm ball bearing")]


def _request(asset: Asset) -> PlaceRequest:
    return PlaceRequest(object_id="thing_0", description=asset.description, asset=asset, kind=PlacementKind.ANYWHERE)


@pytest.mark.parametrize("kind", ["floor", "table"])
def test_small_things_find_supported_spots_on_large_empty_supports(kind: str) -> None:
    engine = MujocoEngine()
    for size in SIZES_M[kind]:
        for seed, asset in enumerate(_small_things()):
            scene = Scene(seed=seed, prompt="", support=Support(kind=kind, size=(size, size * 0.7)))
            spots = PhysicalSolver(scene, engine, seed=seed).search(_request(asset))
            assert isinstance(spots, Spots), (kind, size, asset.id, getattr(spots, "reason", None))
            assert spots.total > 0


def test_a_marble_and_a_tennis_ball_rest_on_a_ten_metre_floor() -> None:
    engine = MujocoEngine()
    scene = Scene(seed=5, prompt="", support=Support(kind="floor", size=(10.0, 10.0)))
    solver = PhysicalSolver(scene, engine, seed=5)
    for k, asset in enumerate([stand_in("a 1.5 cm glass marble"), default_catalogue().get("ball_tennis")]):
        request = _request(asset)
        request.object_id = f"thing_{k}"
        outcome = solver.place(request)
        assert outcome.ok, outcome.reason
    result = engine.settle(scene)
    assert not result.failed
    assert all(abs(o.position[2] - scene.support.top_height) < 0.003 for o in scene.placed)
