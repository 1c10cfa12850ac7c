"""A MuJoCo world for asset physics tests: a floor, and assets dropped in as free bodies."""

from __future__ import annotations

import mujoco

from physcensis.assets.model import Asset
from physcensis.physics.mujoco_assets import add_asset_geoms

TIMESTEP = 0.002


def floor_world() -> mujoco.MjSpec:
    spec = mujoco.MjSpec()
    spec.option.timestep = TIMESTEP
    floor = spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[2, 2, 0.1])
    floor.friction = [0.8, 0.005, 0.0001]
    return spec


def free_body(spec: mujoco.MjSpec, name: str, asset: Asset, pos: tuple[float, float, float]) -> mujoco.MjsBody:
    body = spec.worldbody.add_body(name=name, pos=list(pos))
    body.add_freejoint()
    add_asset_geoms(spec, body, asset, name)
    return body
