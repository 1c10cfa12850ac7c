"""Physical checks in MuJoCo: containers hold, plates stack, supports carry, geoms are built right."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from mujoco_world import TIMESTEP, floor_world, free_body
from shapely.geometry import Point, Polygon

from physcensis.assets.model import Asset
from physcensis.assets.supports import support_asset
from physcensis.physics.mujoco_assets import COLLISION_GROUP, VISUAL_GROUP, add_support_fixture
from physcensis.scene import Support

pytestmark = pytest.mark.physics
SHARES = 4  # the every-asset checks run on interleaved quarters of the catalogue, spread over the test workers


def _drop_sphere_into(asset: Asset) -> tuple[np.ndarray, float]:
    cavity = asset.cavity
    assert cavity is not None
    opening = Polygon(cavity.opening)
    inscribed = opening.exterior.distance(opening.centroid)
    radius = float(min(0.01, 0.3 * inscribed))
    spec = floor_world()
    free_body(spec, "container", asset, (0, 0, 0))
    ball = spec.worldbody.add_body(
        name="ball", pos=[opening.centroid.x, opening.centroid.y, cavity.rim_height + radius + 0.005]
    )
    ball.add_freejoint()
    geom = ball.add_geom(type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[radius, 0, 0], density=1000)
    geom.solref = [0.005, 1]
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, nstep=int(1.5 / TIMESTEP))
    return data.body("ball").xpos.copy(), radius


@pytest.mark.long  # whole-catalogue physics
@pytest.mark.parametrize("share", range(SHARES))
def test_a_small_sphere_comes_to_rest_inside_every_container(all_assets: list[Asset], share: int) -> None:
    containers = [a for a in all_assets if a.cavity is not None]
    assert len(containers) >= 40
    failures = []
    for asset in containers[share::SHARES]:
        pos, _ = _drop_sphere_into(asset)
        cavity = asset.cavity
        assert cavity is not None
        inside = Polygon(cavity.opening).contains(Point(pos[0], pos[1]))
        below_rim = pos[2] < cavity.rim_height
        above_floor = pos[2] > cavity.floor_height - 0.003
        if not (inside and below_rim and above_floor):
            failures.append(
                (asset.id, pos.round(4).tolist(), round(cavity.floor_height, 4), round(cavity.rim_height, 4))
            )
    assert failures == []


@pytest.mark.slow
@pytest.mark.parametrize("share", range(SHARES))
@pytest.mark.long
def test_every_asset_rests_where_it_is_put(all_assets: list[Asset], share: int) -> None:
    """Placed on the floor in its own frame and nudged (tilted 2 deg), each asset settles back within the physics
    check's 1 cm / 10 deg tolerance: no asset may balance on a rounded bottom."""
    moved = []
    tilt = (
        float(np.cos(np.radians(1.0))),
        float(np.sin(np.radians(1.0)) / np.sqrt(2)),
        float(np.sin(np.radians(1.0)) / np.sqrt(2)),
        0.0,
    )
    for asset in all_assets[share::SHARES]:
        spec = floor_world()
        body = free_body(spec, "obj", asset, (0.0, 0.0, 0.003))
        body.quat = list(tilt)
        model = spec.compile()
        data = mujoco.MjData(model)
        mujoco.mj_step(model, data, nstep=int(1.5 / TIMESTEP))
        shift = float(np.linalg.norm(data.body("obj").xpos - (0.0, 0.0, 0.0)))
        turn = float(np.degrees(2 * np.arccos(min(1.0, abs(data.body("obj").xquat[0])))))
        round_body = asset.kind in ("screwdriver", "pen", "pencil", "ball", "candle", "can", "chopstick", "whisk")
        if shift > 0.01 or (turn > 10.0 and not round_body):  # round handles may roll a little about their axis
            moved.append((asset.id, round(shift, 4), round(turn, 1)))
    assert moved == []


@pytest.mark.parametrize("plate_id", ["plate_dinner_white", "ycb_029_plate", "plate_paper_white", "saucer_white"])
def test_five_catalogue_plates_stay_stacked(plate_id: str, by_id: dict[str, Asset]) -> None:
    plate = by_id[plate_id]
    height = plate.size[2]
    spec = floor_world()
    starts = [(0.0, 0.0, k * (height + 0.0005)) for k in range(5)]
    for k, pos in enumerate(starts):
        free_body(spec, f"plate{k}", plate, pos)
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, nstep=int(2.0 / TIMESTEP))
    final = np.array([data.body(f"plate{k}").xpos for k in range(5)])
    assert np.all(np.linalg.norm(final - np.array(starts), axis=1) < 0.01), final
    assert np.all(np.diff(final[:, 2]) > 0.5 * height)  # order preserved, none sank into another


def test_paper_cups_nest(by_id: dict[str, Asset]) -> None:
    cup = by_id["cup_paper_white"]
    spec = floor_world()
    for k in range(3):
        free_body(spec, f"cup{k}", cup, (0.0, 0.0, k * 0.03))
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, nstep=int(3.0 / TIMESTEP))
    heights = [data.body(f"cup{k}").xpos[2] for k in range(3)]
    steps = np.diff(heights)
    assert np.all(steps > 0.003) and np.all(steps < 0.5 * cup.size[2])  # each sits inside the one below
    assert all(np.linalg.norm(data.body(f"cup{k}").xpos[:2]) < 0.005 for k in range(3))


@pytest.mark.parametrize(
    "kind, size", [("table", (1.2, 0.8)), ("shelf", (0.3, 0.9)), ("box", (0.5, 0.4)), ("floor", (3.0, 3.0))]
)
def test_supports_carry_objects_at_their_top(kind: str, size: tuple[float, float], by_id: dict[str, Asset]) -> None:
    support = Support(kind=kind, size=size)
    spec = mujoco.MjSpec()
    spec.option.timestep = TIMESTEP
    add_support_fixture(spec, support)
    block = by_id["toy_block_cube_red"]
    free_body(spec, "block", block, (0.05, -0.05, support.top_height + 0.002))
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, nstep=int(1.0 / TIMESTEP))
    assert data.body("block").xpos[2] == pytest.approx(support.top_height, abs=0.003)
    asset = support_asset(support)
    assert asset.cavity is not None if kind == "box" else asset.cavity is None


def test_asset_geoms_are_built_for_reuse(by_id: dict[str, Asset]) -> None:
    mug = by_id["mug_white"]
    spec = floor_world()
    free_body(spec, "a", mug, (0, 0, 0))
    free_body(spec, "b", mug, (0.3, 0, 0))
    model = spec.compile()
    ncol = len(mug.collision)
    assert model.nmesh == sum(1 for p in mug.collision if p.kind == "mesh") + len(
        mug.part_faces
    )  # shared by both bodies
    assert model.body("a").mass[0] == pytest.approx(mug.mass, rel=1e-6)
    groups = model.geom_group[model.geom_bodyid == model.body("a").id]
    assert (groups == COLLISION_GROUP).sum() == ncol and (groups == VISUAL_GROUP).sum() == len(mug.part_faces)
    visual = np.flatnonzero((model.geom_bodyid == model.body("a").id) & (model.geom_group == VISUAL_GROUP))
    assert np.all(model.geom_contype[visual] == 0) and np.all(model.geom_conaffinity[visual] == 0)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    # the visual mesh is placed where the asset is: its world bounds match the asset's bounds
    verts = []
    for g in visual:
        mesh_id = model.geom_dataid[g]
        start, count = model.mesh_vertadr[mesh_id], model.mesh_vertnum[mesh_id]
        local = model.mesh_vert[start : start + count]
        verts.append(local @ data.geom_xmat[g].reshape(3, 3).T + data.geom_xpos[g])
    allv = np.vstack(verts)
    assert np.allclose(allv.min(axis=0), mug.visual.bounds[0], atol=1e-4)
    assert np.allclose(allv.max(axis=0), mug.visual.bounds[1], atol=1e-4)
