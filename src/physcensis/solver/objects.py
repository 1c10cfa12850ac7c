"""Objects of a program: which asset each one is, and its physical properties."""

from __future__ import annotations

import math
import zlib
from collections.abc import Mapping

import numpy as np

from physcensis.assets.catalogue import Catalogue
from physcensis.assets.model import Asset
from physcensis.program.model import Program


def resolve_assets(program: Program, catalogue: Catalogue) -> dict[str, Asset]:
    """The asset of every declared object, retrieved from its description."""
    return {decl.object_id: catalogue.resolve(decl.description) for decl in program.declarations}


def object_rng(seed: int, object_id: str) -> np.random.Generator:
    """A generator for one object that does not depend on the other objects."""
    return np.random.default_rng([seed, zlib.crc32(object_id.encode("utf-8"))])


def physical_properties(asset: Asset, object_id: str, seed: int) -> tuple[float, float, tuple[float, float, float]]:
    """(mass, friction, centre of mass) drawn, seeded, from the asset's ranges; the COM starts at its nominal."""
    rng = object_rng(seed, object_id)
    mass = float(rng.uniform(*asset.mass_range))
    friction = float(rng.uniform(*asset.friction_range))
    return mass, friction, tuple(float(c) for c in asset.com)  # type: ignore[return-value]


def yaw_quaternion(yaw: float) -> tuple[float, float, float, float]:
    return (math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2))


def compose_yaw(quat: tuple[float, ...], yaw: float) -> tuple[float, float, float, float]:
    """A world turn of `yaw` about the vertical applied after orientation `quat` (w, x, y, z)."""
    w1, z1 = math.cos(yaw / 2), math.sin(yaw / 2)
    w2, x2, y2, z2 = quat
    return (w1 * w2 - z1 * z2, w1 * x2 - z1 * y2, w1 * y2 + z1 * x2, w1 * z2 + z1 * w2)


def quaternion_yaw(quat: tuple[float, float, float, float] | list[float]) -> float:
    w, x, y, z = quat
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


def copy_assets(assets: Mapping[str, Asset], copies: Mapping[str, str]) -> dict[str, Asset]:
    """Assets for copied group members: the same as their originals'."""
    return {**assets, **{copy: assets[original] for copy, original in copies.items() if original in assets}}
