"""The asset data model: geometry plus the paper's physical and semantic annotations.

Conventions (every asset, built-in or imported): metres and kilograms; the base
rests at z = 0; the footprint (xy bounds of the visual mesh) is centred on the
origin; the object's front faces +x.  Supports are the one exception: their
origin is the centre of the usable top surface (see `supports.py`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Literal

import numpy as np
import trimesh
from scipy.spatial import ConvexHull

from physcensis.ids import ID_RULE, is_valid_id

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]
RGBA = tuple[float, float, float, float]
PartKind = Literal["mesh", "box", "cylinder", "sphere", "capsule", "plane"]
PRIMITIVE_KINDS: tuple[str, ...] = ("box", "cylinder", "sphere", "capsule", "plane")
IDENTITY_QUAT: Quat = (1.0, 0.0, 0.0, 0.0)


@dataclass(frozen=True, eq=False)
class CollisionPart:
    """One convex collision piece: a convex mesh or a MuJoCo primitive.

    `size` follows MuJoCo: box = half extents; cylinder and capsule = (radius,
    half length, 0) along the part's local z; sphere = (radius, 0, 0); plane =
    (half x, half y, grid spacing).  Mesh parts keep their vertices in the asset
    frame (`pos`/`quat` are identity for them).
    """

    kind: PartKind
    size: Vec3 = (0.0, 0.0, 0.0)
    pos: Vec3 = (0.0, 0.0, 0.0)
    quat: Quat = IDENTITY_QUAT
    vertices: np.ndarray | None = None

    def __post_init__(self) -> None:
        if self.kind == "mesh":
            if self.vertices is None or self.vertices.ndim != 2 or self.vertices.shape[1] != 3:
                raise ValueError("a mesh collision part needs an (N, 3) vertex array")
            if len(self.vertices) < 4:
                raise ValueError("a mesh collision part needs at least 4 vertices")
        elif self.kind not in PRIMITIVE_KINDS:
            raise ValueError(f"unknown collision part kind {self.kind!r}")

    @cached_property
    def volume(self) -> float:
        """Volume in m^3 (0 for planes); used to share an asset's mass between parts."""
        sx, sy, sz = self.size
        if self.kind == "mesh":
            assert self.vertices is not None
            try:
                return float(ConvexHull(self.vertices).volume)
            except Exception:  # degenerate (flat) hull has no volume
                return 0.0
        if self.kind == "box":
            return 8.0 * sx * sy * sz
        if self.kind == "cylinder":
            return np.pi * sx * sx * 2.0 * sy
        if self.kind == "sphere":
            return 4.0 / 3.0 * np.pi * sx**3
        if self.kind == "capsule":
            return np.pi * sx * sx * 2.0 * sy + 4.0 / 3.0 * np.pi * sx**3
        return 0.0

    def translated(self, offset: np.ndarray) -> CollisionPart:
        offset = np.asarray(offset, dtype=float)
        if self.kind == "mesh":
            assert self.vertices is not None
            return CollisionPart("mesh", vertices=self.vertices + offset)
        if self.kind == "plane":
            return self
        pos = tuple(float(v) for v in np.asarray(self.pos) + offset)
        return CollisionPart(self.kind, self.size, pos, self.quat)  # type: ignore[arg-type]


@dataclass(frozen=True, eq=False)
class Cavity:
    """The open inside of a container: where dropped objects come to rest."""

    opening: np.ndarray  # (N, 2) polygon of the inner rim, asset frame, counter-clockwise
    floor_height: float  # z of the inner floor (lowest point of the cavity), metres
    depth: float  # rim height minus floor height, metres

    @property
    def rim_height(self) -> float:
        return self.floor_height + self.depth


@dataclass(frozen=True, eq=False)
class Asset:
    """An object the solver can place: geometry plus annotations.

    `category` is the name scene benchmarks match ("box" for cereal, gift,
    cardboard boxes and toolboxes); `kind` names the specific object type
    ("cereal box").  `visual` is one mesh whose faces come in contiguous parts,
    `part_faces[i]` faces coloured `rgba[i]`.
    """

    id: str
    category: str
    kind: str
    description: str
    size: Vec3
    visual: trimesh.Trimesh
    collision: tuple[CollisionPart, ...]
    mass: float
    mass_range: tuple[float, float]
    friction_range: tuple[float, float]
    com: Vec3 = (0.0, 0.0, 0.0)
    com_shift_range: Vec3 = (0.0, 0.0, 0.0)
    support_probability: float = 0.5
    has_front: bool = True
    cavity: Cavity | None = None
    rgba: tuple[RGBA, ...] = ((0.7, 0.7, 0.7, 1.0),)
    part_faces: tuple[int, ...] = ()
    tags: tuple[str, ...] = ()
    synonyms: tuple[str, ...] = ()
    generated: bool = False
    guessed: frozenset[str] = field(default_factory=frozenset)
    source: str = "builtin"
    pose: str = ""  # an imported mesh's up ("+y", "stable pose", ...); "" for built-ins
    rests: bool = True  # False: no pose where it rests (rolls or tips); its collision is pressed flat where it lies

    def __post_init__(self) -> None:
        if not is_valid_id(self.id):
            raise ValueError(f"asset id {self.id!r} is not valid ({ID_RULE})")
        if not self.collision:
            raise ValueError(f"asset {self.id}: needs at least one collision part")
        lo, hi = self.mass_range
        if not 0.0 < lo <= self.mass <= hi:
            raise ValueError(f"asset {self.id}: mass {self.mass:.4g} kg outside its range [{lo:.4g}, {hi:.4g}]")
        if not 0.0 <= self.support_probability <= 1.0:
            raise ValueError(f"asset {self.id}: support_probability must be in [0, 1]")
        parts = self.part_faces or (len(self.visual.faces),)
        if sum(parts) != len(self.visual.faces) or len(parts) != len(self.rgba):
            raise ValueError(f"asset {self.id}: part_faces and rgba must describe every visual face")
        if not self.part_faces:
            object.__setattr__(self, "part_faces", parts)

    @property
    def is_container(self) -> bool:
        return self.cavity is not None

    @property
    def names(self) -> tuple[str, ...]:
        """Category, kind and synonyms: every name the object answers to."""
        return tuple(dict.fromkeys((self.category, self.kind, *self.synonyms)))

    @cached_property
    def _footprint(self) -> np.ndarray:
        points = np.asarray(self.visual.vertices)[:, :2]
        hull = ConvexHull(points)
        return points[hull.vertices].copy()  # scipy orders 2-D hull vertices counter-clockwise

    def footprint(self) -> np.ndarray:
        """Convex hull (K, 2) of the visual mesh's xy projection, counter-clockwise."""
        return self._footprint

    def visual_parts(self) -> list[tuple[trimesh.Trimesh, RGBA]]:
        """The visual mesh split into its coloured parts."""
        out: list[tuple[trimesh.Trimesh, RGBA]] = []
        start = 0
        faces = np.asarray(self.visual.faces)
        vertices = np.asarray(self.visual.vertices)
        for count, color in zip(self.part_faces, self.rgba, strict=True):
            sub = faces[start : start + count]
            used, inverse = np.unique(sub, return_inverse=True)
            out.append((trimesh.Trimesh(vertices[used], inverse.reshape(-1, 3), process=False), color))
            start += count
        return out
