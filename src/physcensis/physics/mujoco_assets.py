"""Add assets and supports to a MuJoCo MjSpec.

Collision parts become geoms (convex meshes are registered once per asset id and
shared by every instance); the visual mesh is added as display-only geoms
(contype = conaffinity = 0, group 2), one per coloured part.  Collision geoms sit
in group 3, hidden by MuJoCo's default rendering.
"""

from __future__ import annotations

from collections.abc import Sequence

import mujoco
import numpy as np

from physcensis.assets.model import RGBA, Asset, CollisionPart
from physcensis.assets.supports import support_asset
from physcensis.physics.profiles import OURS
from physcensis.scene import Support

VISUAL_GROUP = 2
COLLISION_GROUP = 3
DEFAULT_SOLREF = OURS.solref
TORSIONAL_FRICTION = 0.005
ROLLING_FRICTION = 0.0001

_GEOM_TYPES = {
    "box": mujoco.mjtGeom.mjGEOM_BOX,
    "cylinder": mujoco.mjtGeom.mjGEOM_CYLINDER,
    "sphere": mujoco.mjtGeom.mjGEOM_SPHERE,
    "capsule": mujoco.mjtGeom.mjGEOM_CAPSULE,
    "plane": mujoco.mjtGeom.mjGEOM_PLANE,
}


def _mesh(spec: mujoco.MjSpec, name: str, vertices: np.ndarray, faces: np.ndarray | None = None) -> str:
    """Register a mesh asset once; vertices only make MuJoCo use their convex hull."""
    if spec.mesh(name) is None:
        mesh = spec.add_mesh(name=name)
        mesh.uservert = np.asarray(vertices, dtype=np.float32).ravel().tolist()
        if faces is not None:
            mesh.userface = np.asarray(faces, dtype=np.int32).ravel().tolist()
            mesh.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL
    return name


MIN_PART_MASS_KG = 1e-6  # the least mass a collision part is given (a part's share of a light object can be less)


def part_masses(parts: Sequence[CollisionPart], mass: float) -> list[float]:
    """Share `mass` between collision parts in proportion to their volumes."""
    volumes = np.array([p.volume for p in parts], dtype=float)
    if volumes.sum() <= 0:
        volumes = np.array([0.0 if p.kind == "plane" else 1.0 for p in parts])
    return list(mass * volumes / volumes.sum())


def add_collision_geoms(
    spec: mujoco.MjSpec,
    body: mujoco.MjsBody,
    asset: Asset,
    name_prefix: str,
    *,
    mass: float | None = None,
    friction: float | None = None,
    solref: tuple[float, float] | None = DEFAULT_SOLREF,
    static: bool = False,
) -> list[mujoco.MjsGeom]:
    mu = float(np.mean(asset.friction_range)) if friction is None else friction
    masses = (
        [0.0] * len(asset.collision) if static else part_masses(asset.collision, asset.mass if mass is None else mass)
    )
    geoms = []
    for i, (part, part_mass) in enumerate(zip(asset.collision, masses, strict=True)):
        geom = body.add_geom(name=f"{name_prefix}_c{i}")
        if part.kind == "mesh":
            assert part.vertices is not None
            geom.type = mujoco.mjtGeom.mjGEOM_MESH
            geom.meshname = _mesh(spec, f"{asset.id}__c{i}", part.vertices)
        else:
            geom.type = _GEOM_TYPES[part.kind]
            geom.size = list(part.size)
            geom.pos = list(part.pos)
            geom.quat = list(part.quat)
        if not static:
            geom.mass = max(float(part_mass), MIN_PART_MASS_KG)
        geom.friction = [mu, TORSIONAL_FRICTION, ROLLING_FRICTION]
        if solref is not None:  # None keeps MuJoCo's default
            geom.solref = list(solref)
        geom.group = COLLISION_GROUP
        geom.rgba = [0.9, 0.3, 0.3, 0.4]
        geoms.append(geom)
    return geoms


def add_visual_geoms(
    spec: mujoco.MjSpec, body: mujoco.MjsBody, asset: Asset, name_prefix: str, *, rgba: RGBA | None = None
) -> list[mujoco.MjsGeom]:
    geoms = []
    for k, (mesh, color) in enumerate(asset.visual_parts()):
        geom = body.add_geom(name=f"{name_prefix}_v{k}")
        geom.type = mujoco.mjtGeom.mjGEOM_MESH
        geom.meshname = _mesh(spec, f"{asset.id}__v{k}", mesh.vertices, mesh.faces)
        geom.contype = 0
        geom.conaffinity = 0
        geom.group = VISUAL_GROUP
        geom.mass = 0.0
        geom.density = 0.0
        geom.rgba = list(rgba if rgba is not None else color)
        geoms.append(geom)
    return geoms


def add_asset_geoms(
    spec: mujoco.MjSpec,
    body: mujoco.MjsBody,
    asset: Asset,
    name_prefix: str,
    *,
    rgba: RGBA | None = None,
    mass: float | None = None,
    friction: float | None = None,
    solref: tuple[float, float] | None = DEFAULT_SOLREF,
    visual: bool = True,
    static: bool = False,
) -> list[mujoco.MjsGeom]:
    """Add an asset's collision parts and (optionally) its visual mesh to `body`.

    The body's mass is `mass` (default the asset's nominal mass) spread over the
    collision parts by volume; friction defaults to the middle of the asset's range.
    `static` bodies (fixtures) get no masses.  Returns the collision geoms.
    """
    geoms = add_collision_geoms(
        spec, body, asset, name_prefix, mass=mass, friction=friction, solref=solref, static=static
    )
    if visual:
        add_visual_geoms(spec, body, asset, name_prefix, rgba=rgba)
    return geoms


def add_support_fixture(
    spec: mujoco.MjSpec,
    support: Support,
    *,
    name: str = "support",
    floor: bool = True,
    solref: tuple[float, float] | None = DEFAULT_SOLREF,
) -> mujoco.MjsBody:
    """Add the static support (table, shelf, open box or floor) to the world; its top is centred at x = y = 0.

    With `floor`, a ground plane at z = 0 is added under tables, shelves and boxes
    so that objects that fall off come to rest instead of falling for ever.
    """
    asset = support_asset(support)
    body = spec.worldbody.add_body(name=name)
    add_asset_geoms(spec, body, asset, name, static=True, solref=solref)
    if floor and support.kind != "floor":
        ground = spec.worldbody.add_geom(name=f"{name}_ground", type=mujoco.mjtGeom.mjGEOM_PLANE)
        ground.size = [0.0, 0.0, 0.05]
        ground.rgba = [0.55, 0.55, 0.55, 1.0]
        ground.friction = [0.8, TORSIONAL_FRICTION, ROLLING_FRICTION]
    return body
