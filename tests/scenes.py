"""Scenes built by hand for physics tests."""

from __future__ import annotations

import numpy as np

from physcensis.assets import default_catalogue
from physcensis.scene import PlacedObject
from physcensis.solver.objects import yaw_quaternion


def placed_object(oid: str, asset_id: str, x: float, y: float, z: float, yaw: float = 0.0) -> PlacedObject:
    """A catalogue asset at a pose, with its nominal mass, mid-range friction and annotated centre of mass."""
    asset = default_catalogue().get(asset_id)
    return PlacedObject(
        id=oid,
        description=asset.description,
        asset=asset_id,
        category=asset.category,
        position=(x, y, z),
        quaternion=yaw_quaternion(yaw),
        mass=asset.mass,
        friction=float(np.mean(asset.friction_range)),
        com=asset.com,
    )
