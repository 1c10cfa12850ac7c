"""Bathroom, bedroom and living room assets in MuJoCo: holders hold what they are for, soft folded things stack."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from mujoco_world import TIMESTEP, floor_world, free_body
from shapely.geometry import Point, Polygon

from physcensis.assets.catalogue import Catalogue
from physcensis.physics.mujoco_assets import add_asset_geoms

pytestmark = pytest.mark.physics


def _settle(spec: mujoco.MjSpec, seconds: float) -> tuple[mujoco.MjModel, mujoco.MjData]:
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, nstep=int(seconds / TIMESTEP))
    return model, data


def _tilt_degrees(quat: np.ndarray) -> float:
    """How far a body's z axis leans from vertical."""
    w, x, y, _ = quat
    return float(np.degrees(np.arccos(np.clip(1 - 2 * (x * x + y * y), -1.0, 1.0))))


@pytest.mark.parametrize(
    "holder_id, item_id",
    [
        ("soap_dish_white_ceramic", "soap_bar_white"),
        ("soap_dish_round_white", "soap_bar_pink_oval"),
        ("candle_holder_clear_votive", "candle_tealight"),
        ("candle_holder_hurricane", "candle_pillar_red"),
        ("jewelry_box_wood_lid", "jewelry_diamond_ring"),
        ("storage_bin_grey_plastic", "toilet_paper_single"),
        ("trash_can_round_grey", "soap_bar_white"),
    ],
)
def test_an_item_dropped_into_its_holder_rests_inside(holder_id: str, item_id: str, catalogue: Catalogue) -> None:
    holder, item = catalogue.get(holder_id), catalogue.get(item_id)
    cavity = holder.cavity
    assert cavity is not None
    opening = Polygon(cavity.opening)
    spec = floor_world()
    free_body(spec, "holder", holder, (0.0, 0.0, 0.0))
    free_body(spec, "item", item, (opening.centroid.x, opening.centroid.y, cavity.rim_height + 0.005))
    _, data = _settle(spec, 2.0)
    pos = data.body("item").xpos
    assert opening.contains(Point(pos[0], pos[1]))
    assert cavity.floor_height - 0.003 < pos[2] < cavity.rim_height  # its base is below the rim, on the floor or ribs
    assert _tilt_degrees(data.body("item").xquat) < 10.0  # it lands the right way up
    assert np.linalg.norm(data.body("holder").xpos) < 0.01  # and the holder does not tip over


@pytest.mark.parametrize(
    "asset_id", ["clothes_white_shirt", "blanket_red_folded", "magazine_glossy_red", "cushion_grey_square"]
)
def test_four_soft_or_flat_things_stay_stacked(asset_id: str, catalogue: Catalogue) -> None:
    asset = catalogue.get(asset_id)
    height = asset.size[2]
    starts = [(0.0, 0.0, k * (height + 0.001)) for k in range(4)]
    spec = floor_world()
    for k, pos in enumerate(starts):
        free_body(spec, f"layer{k}", asset, pos)
    _, data = _settle(spec, 2.0)
    final = np.array([data.body(f"layer{k}").xpos for k in range(4)])
    assert np.all(np.linalg.norm(final - np.array(starts), axis=1) < 0.01), final
    assert np.all(np.diff(final[:, 2]) > 0.9 * height)  # none sank into the one below


@pytest.mark.parametrize("asset_id", ["plunger_red_wood", "toilet_brush_white_round", "suitcase_navy_hard"])
def test_tall_things_stand_after_a_push(asset_id: str, catalogue: Catalogue) -> None:
    """A tall object on a small base stands up again after being tipped by 3 degrees."""
    asset = catalogue.get(asset_id)
    spec = floor_world()
    body = spec.worldbody.add_body(name="obj", pos=[0.0, 0.0, 0.004])
    body.add_freejoint()
    body.quat = [float(np.cos(np.radians(1.5))), float(np.sin(np.radians(1.5))), 0.0, 0.0]
    add_asset_geoms(spec, body, asset, "obj")
    _, data = _settle(spec, 2.0)
    assert _tilt_degrees(data.body("obj").xquat) < 1.0
