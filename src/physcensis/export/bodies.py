"""What every exporter needs of a scene: its rigid bodies with pose, mass, centre of mass, inertia and friction, and
the physics of the MuJoCo scene around them (gravity, the floor), one copy for every format.

The inertial properties are read from the compiled MuJoCo model, so every format
carries the same numbers the solver verified the scene with.
"""

from __future__ import annotations

import functools
import hashlib
from collections import OrderedDict
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Generic, TypeVar

import mujoco
import numpy as np
import trimesh

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.assets.model import Asset, CollisionPart
from physcensis.assets.supports import support_asset
from physcensis.physics.mujoco_engine import build_scene
from physcensis.scene import Scene

# The MuJoCo scene's physics, as physics/mujoco_engine.py (gravity) and mujoco_assets.add_support_fixture (the floor
# plane under tables, shelves and boxes) set it; tests/export/test_format_registry.py checks them against a built model.
GRAVITY_M_S2 = 9.81  # along -z
GROUND_FRICTION = 0.8  # sliding; its torsional and rolling friction are every geom's (physics.mujoco_assets)
GROUND_RGBA = (0.55, 0.55, 0.55, 1.0)
GROUND_HALF_EXTENT = 5.0  # metres: MuJoCo's plane is endless, the exports' floor is a slab this wide
GROUND_THICKNESS = 0.05


@dataclass(frozen=True, eq=False)
class ExportBody:
    """One free rigid body of the scene, in the units and frames of the scene file (metres, kg, z up)."""

    id: str
    description: str
    asset: Asset
    position: np.ndarray  # (3,) asset origin in the world
    quaternion: np.ndarray  # (4,) [w, x, y, z]
    mass: float
    friction: float
    com: np.ndarray  # (3,) centre of mass in the body frame
    inertia: np.ndarray  # (3, 3) inertia tensor about the centre of mass, body-frame axes

    @property
    def principal_inertia(self) -> tuple[np.ndarray, np.ndarray]:
        """Principal moments (3,) and the quaternion [w, x, y, z] of the principal axes in the body frame."""
        moments, axes = np.linalg.eigh(self.inertia)
        if np.linalg.det(axes) < 0:
            axes[:, 2] *= -1
        quat = np.zeros(4)
        mujoco.mju_mat2Quat(quat, axes.ravel())
        return moments, quat

    @property
    def transform(self) -> np.ndarray:
        return pose_matrix(self.position, self.quaternion)


@dataclass(frozen=True, eq=False)
class ExportScene:
    """The static support (an asset in world coordinates), whether a floor lies under it, and the bodies."""

    scene: Scene
    support: Asset
    ground: bool
    bodies: list[ExportBody]

    @property
    def support_friction(self) -> float:
        """The support's friction coefficient, as the MuJoCo scene gives a fixture: the middle of its asset's range."""
        return float(np.mean(self.support.friction_range))


def export_scene_bodies(scene: Scene, catalogue: Catalogue | None = None) -> ExportScene:
    catalogue = catalogue or default_catalogue()
    built = build_scene(scene, catalogue, visual=False)
    model = built.model
    bodies = []
    for obj in scene.placed:
        b = built.body[obj.id]
        flat = np.zeros(9)
        mujoco.mju_quat2Mat(flat, model.body_iquat[b])
        rot = flat.reshape(3, 3)
        bodies.append(
            ExportBody(
                id=obj.id,
                description=obj.description,
                asset=built.assets[obj.id],
                position=np.asarray(obj.position, dtype=float),
                quaternion=np.asarray(obj.quaternion, dtype=float),
                mass=float(model.body_mass[b]),
                friction=obj.friction,
                com=model.body_ipos[b].copy(),
                inertia=rot @ np.diag(model.body_inertia[b]) @ rot.T,
            )
        )
    return ExportScene(scene, support_asset(scene.support), scene.support.kind != "floor", bodies)


def pose_matrix(position: np.ndarray, quaternion: np.ndarray) -> np.ndarray:
    """4x4 homogeneous transform of a position and a [w, x, y, z] quaternion."""
    rot = np.zeros(9)
    mujoco.mju_quat2Mat(rot, np.asarray(quaternion, dtype=float))
    matrix = np.eye(4)
    matrix[:3, :3] = rot.reshape(3, 3)
    matrix[:3, 3] = position
    return matrix


def ground_slab() -> trimesh.Trimesh:
    """The floor under tables, shelves and boxes as the exports write it: a slab whose top is z = 0."""
    slab = trimesh.creation.box(extents=(2 * GROUND_HALF_EXTENT, 2 * GROUND_HALF_EXTENT, GROUND_THICKNESS))
    slab.apply_translation((0.0, 0.0, -GROUND_THICKNESS / 2))
    return slab


@functools.lru_cache(maxsize=8192)
def part_mesh(part: CollisionPart) -> trimesh.Trimesh:
    """A collision part as a closed triangle mesh in the asset frame (convex hull for mesh parts).

    Cached per part (assets are shared by many objects and scenes): treat the result as read-only."""
    if part.kind == "mesh":
        assert part.vertices is not None
        return trimesh.Trimesh(part.vertices).convex_hull
    sx, sy, _ = part.size
    if part.kind == "box":
        mesh = trimesh.creation.box(extents=2.0 * np.asarray(part.size))
    elif part.kind == "cylinder":
        mesh = trimesh.creation.cylinder(radius=sx, height=2.0 * sy, sections=32)
    elif part.kind == "sphere":
        mesh = trimesh.creation.icosphere(subdivisions=3, radius=sx)
    elif part.kind == "capsule":
        mesh = trimesh.creation.capsule(height=2.0 * sy, radius=sx, count=[16, 16])
    else:  # plane: a thin slab whose top is the plane, at least as wide as the floor under tables (MuJoCo's is endless)
        half_x, half_y = max(sx, GROUND_HALF_EXTENT), max(sy, GROUND_HALF_EXTENT)
        mesh = trimesh.creation.box(extents=(2.0 * half_x, 2.0 * half_y, GROUND_THICKNESS))
        mesh.apply_translation((0.0, 0.0, -GROUND_THICKNESS / 2))
    mesh.apply_transform(pose_matrix(np.asarray(part.pos), np.asarray(part.quat)))
    return mesh


T = TypeVar("T")


class KeptByContent(Generic[T]):
    """What an export derives from a mesh, kept for the process by a hash of what it was derived from: a batch writes
    the same assets scene after scene. Beyond `limit` values the least recently used goes. Treat values as
    read-only."""

    def __init__(self, limit: int) -> None:
        self.limit = limit
        self._kept: OrderedDict[bytes, T] = OrderedDict()

    def get(self, contents: Iterable[bytes], make: Callable[[], T]) -> T:
        key = hashlib.sha1(b"|".join(contents)).digest()
        if key in self._kept:
            self._kept.move_to_end(key)
            return self._kept[key]
        value = self._kept[key] = make()
        if len(self._kept) > self.limit:
            self._kept.popitem(last=False)
        return value
