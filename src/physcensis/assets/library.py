"""User asset libraries: a folder with `library.yaml` (or `.json`) listing mesh files and annotations.

Ingest normalises each mesh to the asset conventions (metres, +z up, front +x,
base at z = 0, footprint centred), checks watertightness, builds collision
(one hull for nearly convex meshes, CoACD parts otherwise) and fills missing
annotations from the category's defaults, recording them in `Asset.guessed`.
A broken entry is reported with its file name and the rest still loads.

    unit: cm            # optional library defaults: unit, up, front
    up: +y
    assets:
      - file: meshes/mug.glb
        id: red_mug
        category: mug
        description: a red enamel mug
        size: [0.12, 0.09, 0.1]   # or height: 0.1, or scale: 0.01
        mass: [0.25, 0.35]
"""

from __future__ import annotations

import json
import logging
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

import numpy as np
import trimesh
import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from physcensis.assets import collision as col
from physcensis.assets.build import MASS_SPREAD
from physcensis.assets.builtin import category_defaults
from physcensis.assets.cache import AssetCache
from physcensis.assets.decompose import convex_decomposition
from physcensis.assets.errors import AssetError
from physcensis.assets.model import Asset, Cavity, CollisionPart
from physcensis.ids import is_valid_id

log = logging.getLogger(__name__)
LIBRARY_FILES = ("library.yaml", "library.yml", "library.json")
MESH_SUFFIXES = (".glb", ".gltf", ".obj", ".stl", ".ply")
UNITS = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254}
AXES = {"+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0), "+z": (0, 0, 1), "-z": (0, 0, -1)}
CONVEX_ENOUGH = 0.92  # volume / hull volume above which one hull is the collision
GENERIC_DENSITY = 500.0
MIN_PART_VOLUME = 1e-10  # m^3; flatter convex pieces are dropped (MuJoCo cannot give them inertia)
Axis = Literal["+x", "-x", "+y", "-y", "+z", "-z"]
Unit = Literal["m", "cm", "mm", "in"]


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid")


class EntrySpec(_Model):
    file: str
    id: str | None = None
    category: str | None = None
    kind: str | None = None
    description: str | None = None
    tags: list[str] = Field(default_factory=list)
    synonyms: list[str] = Field(default_factory=list)
    unit: Unit | None = None
    scale: float | None = Field(default=None, gt=0)
    size: tuple[float, float, float] | None = None
    height: float | None = Field(default=None, gt=0)
    up: Axis | None = None
    front: Axis | None = None
    mass: float | tuple[float, float] | None = None
    friction: tuple[float, float] | None = None
    com_shift: tuple[float, float, float] | None = None
    support_probability: float | None = Field(default=None, ge=0, le=1)
    container: bool | None = None
    rgba: tuple[float, float, float, float] | None = None


class LibrarySpec(_Model):
    name: str | None = None
    unit: Unit = "m"
    up: Axis = "+z"
    front: Axis = "+x"
    assets: list[dict] = Field(default_factory=list)


@dataclass
class LibraryResult:
    """What loading a library produced: the good assets and one error per broken entry."""

    folder: Path
    assets: list[Asset] = field(default_factory=list)
    errors: list[AssetError] = field(default_factory=list)


def _library_file(folder: Path) -> Path:
    for name in LIBRARY_FILES:
        if (folder / name).is_file():
            return folder / name
    raise AssetError(f"{folder}: no library file ({' or '.join(LIBRARY_FILES)}) in this folder")


def read_library_spec(folder: str | Path) -> LibrarySpec:
    folder = Path(folder)
    if not folder.is_dir():
        raise AssetError(f"{folder}: asset library folder not found")
    path = _library_file(folder)
    try:
        text = path.read_text(encoding="utf-8")
        data = json.loads(text) if path.suffix == ".json" else yaml.safe_load(text)
    except (OSError, UnicodeDecodeError, json.JSONDecodeError, yaml.YAMLError) as exc:
        raise AssetError(
            f"{path}: cannot read the library file ({exc.__class__.__name__}: {str(exc).splitlines()[0]})"
        ) from None
    if not isinstance(data, dict):
        raise AssetError(f"{path}: the library file must be a mapping with an 'assets' list")
    try:
        return LibrarySpec.model_validate(data)
    except ValidationError as exc:
        first = exc.errors()[0]
        where = ".".join(str(p) for p in first["loc"])
        raise AssetError(f"{path}: {where}: {first['msg']}") from None


def load_library(folder: str | Path, cache: AssetCache | None = None) -> LibraryResult:
    """Ingest every entry of a library; a broken entry becomes an error naming its file, the rest loads."""
    folder = Path(folder)
    spec = read_library_spec(folder)
    result = LibraryResult(folder)
    seen: set[str] = set()
    for index, raw in enumerate(spec.assets):
        label = raw.get("file", f"assets[{index}]") if isinstance(raw, dict) else f"assets[{index}]"
        try:
            entry = EntrySpec.model_validate(raw)
            asset = ingest(folder, entry, spec, cache)
            if asset.id in seen:
                raise AssetError(f"duplicate asset id {asset.id!r}")
            seen.add(asset.id)
            result.assets.append(asset)
        except ValidationError as exc:
            first = exc.errors()[0]
            where = ".".join(str(p) for p in first["loc"])
            result.errors.append(AssetError(f"{folder / str(label)}: {where}: {first['msg']}"))
        except AssetError as exc:
            message = str(exc)
            result.errors.append(
                exc if message.startswith(str(folder)) else AssetError(f"{folder / str(label)}: {message}")
            )
    for err in result.errors:
        log.warning("asset library: %s", err)
    return result


def resolve_inside(folder: Path, relative: str) -> Path:
    """The file's path, refusing any path that leaves the library folder."""
    root = folder.resolve()
    path = (root / relative).resolve()
    if not path.is_relative_to(root):
        raise AssetError(f"path {relative!r} points outside the library folder; refused")
    return path


def _rotation(up: str, front: str) -> np.ndarray:
    u, f = np.asarray(AXES[up], dtype=float), np.asarray(AXES[front], dtype=float)
    if abs(u.dot(f)) > 1e-9:
        raise AssetError(f"up {up} and front {front} must be perpendicular axes")
    return np.stack([f, np.cross(u, f), u])  # rows: new x (front), new y, new z (up)


def _load_mesh(path: Path) -> trimesh.Trimesh:
    if path.suffix.lower() not in MESH_SUFFIXES:
        raise AssetError(f"unsupported mesh format {path.suffix!r} (use {', '.join(MESH_SUFFIXES)})")
    if not path.is_file():
        raise AssetError("mesh file not found")
    try:
        mesh = trimesh.load(path, force="mesh")
    except Exception as exc:  # noqa: BLE001 - any parser failure is the file's fault: report it
        raise AssetError(
            f"cannot read mesh ({exc.__class__.__name__}: {str(exc).splitlines()[0] if str(exc) else 'unreadable'})"
        ) from None
    if not isinstance(mesh, trimesh.Trimesh) or len(mesh.faces) == 0 or not np.all(np.isfinite(mesh.vertices)):
        raise AssetError("the file holds no usable triangle mesh")
    return mesh


def _slug(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_-]+", "_", text).strip("_")[:64] or "asset"


def top_surface_height(mesh: trimesh.Trimesh, x: float = 0.0, y: float = 0.0) -> float | None:
    """Height where a vertical ray from above at (x, y) first meets the mesh (None if it misses)."""
    tri = np.asarray(mesh.triangles)
    a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
    v0, v1 = b[:, :2] - a[:, :2], c[:, :2] - a[:, :2]
    p = np.array([x, y]) - a[:, :2]
    det = v0[:, 0] * v1[:, 1] - v0[:, 1] * v1[:, 0]
    ok = np.abs(det) > 1e-15
    safe = np.where(ok, det, 1.0)
    u = (p[:, 0] * v1[:, 1] - p[:, 1] * v1[:, 0]) / safe
    v = (v0[:, 0] * p[:, 1] - v0[:, 1] * p[:, 0]) / safe
    inside = ok & (u >= -1e-9) & (v >= -1e-9) & (u + v <= 1 + 1e-9)
    if not inside.any():
        return None
    z = a[:, 2] + u * (b[:, 2] - a[:, 2]) + v * (c[:, 2] - a[:, 2])
    return float(z[inside].max())


def _detect_cavity(mesh: trimesh.Trimesh) -> Cavity | None:
    """An open top: looking straight down at the footprint centre, the first surface is well below the top."""
    height = float(mesh.bounds[1][2])
    floor = top_surface_height(mesh)
    if floor is None:
        return None
    if floor > 0.6 * height:
        return None
    top = mesh.vertices[mesh.vertices[:, 2] > height - 0.03 * height][:, :2]
    from scipy.spatial import ConvexHull

    rim = top[ConvexHull(top).vertices]
    opening = rim * 0.85  # inside the outer rim, by a wall's worth
    return Cavity(opening, floor, height - floor)


def ingest(folder: Path, e: EntrySpec, lib: LibrarySpec, cache: AssetCache | None) -> Asset:
    """One library entry -> Asset (raises AssetError with a plain reason)."""
    path = resolve_inside(folder, e.file)
    mesh = _load_mesh(path)
    guessed: set[str] = set()
    scale = UNITS[e.unit or lib.unit] * (e.scale or 1.0)
    mesh.apply_scale(scale)
    rot = np.eye(4)
    rot[:3, :3] = _rotation(e.up or lib.up, e.front or lib.front)
    mesh.apply_transform(rot)
    if e.size is not None or e.height is not None:
        ext = mesh.extents
        target = np.asarray(e.size) if e.size is not None else None
        factor = float(np.median(target / ext)) if target is not None else float(e.height / ext[2])  # type: ignore[operator]
        if target is not None and np.max(np.abs(ext * factor / target - 1)) > 0.1:
            log.warning(
                "%s: size %s differs from the mesh proportions by more than 10%%; scaled uniformly", path, list(target)
            )
        mesh.apply_scale(factor)
    lo, hi = mesh.bounds
    mesh.apply_translation((-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]))
    if not mesh.is_watertight:
        trimesh.repair.fill_holes(mesh)
    watertight = bool(mesh.is_watertight)
    if not watertight:
        log.warning("%s: mesh is not watertight; mass and collision are approximate", path)
        guessed.add("watertight")
    hull = mesh.convex_hull
    volume = float(abs(mesh.volume)) if watertight else 0.5 * float(hull.volume)
    category = e.category or "object"
    if e.category is None:
        guessed.add("category")
    defaults = category_defaults().get(category)
    density = defaults.density if defaults else GENERIC_DENSITY
    if e.mass is None:
        mass = density * volume
        guessed.add("mass")
        mass_range = (mass * (1 - MASS_SPREAD), mass * (1 + MASS_SPREAD))
    elif isinstance(e.mass, tuple):
        mass_range = (float(min(e.mass)), float(max(e.mass)))
        mass = sum(mass_range) / 2
    else:
        mass = float(e.mass)
        mass_range = (mass * (1 - MASS_SPREAD), mass * (1 + MASS_SPREAD))
    if mass <= 0:
        raise AssetError("mass must be positive")
    cavity = None
    if e.container is not False:
        cavity = _detect_cavity(mesh)
        if e.container is None:
            guessed.add("container")
        elif cavity is None:
            raise AssetError("marked as a container but no open cavity was found from above")
    convexity = volume / float(hull.volume) if watertight and hull.volume > 0 else 0.0
    if convexity >= CONVEX_ENOUGH and cavity is None:
        collision: tuple[CollisionPart, ...] = (col.hull_part(hull.vertices),)
    else:
        parts = (col.hull_part(v) for v in convex_decomposition(mesh, cache=cache) if len(v) >= 4)
        collision = tuple(p for p in parts if p.volume > MIN_PART_VOLUME)  # drop degenerate (flat) pieces
        if not collision:
            raise AssetError("convex decomposition gave no solid parts")
    for name, value in (
        ("friction", e.friction),
        ("support_probability", e.support_probability),
        ("com_shift", e.com_shift),
        ("description", e.description),
    ):
        if value is None:
            guessed.add(name)
    ident = e.id or _slug(Path(e.file).stem)
    if not is_valid_id(ident):
        raise AssetError(f"invalid asset id {ident!r}")
    size = tuple(float(v) for v in mesh.extents)
    friction = e.friction or (defaults.friction if defaults else (0.4, 0.8))
    com_fraction = defaults.com_shift if defaults else 0.05
    rgba = e.rgba or (0.7, 0.7, 0.7, 1.0)
    return Asset(
        id=ident,
        category=category,
        kind=e.kind or category,
        description=e.description or f"a {category}",
        size=size,  # type: ignore[arg-type]
        visual=mesh,
        collision=collision,
        mass=mass,
        mass_range=mass_range,
        friction_range=(float(friction[0]), float(friction[1])),
        com=tuple(float(v) for v in (mesh.center_mass if watertight else mesh.centroid)),  # type: ignore[arg-type]
        com_shift_range=e.com_shift or tuple(com_fraction * s for s in size),  # type: ignore[arg-type]
        support_probability=e.support_probability
        if e.support_probability is not None
        else (defaults.support_probability if defaults else 0.5),
        has_front=defaults.has_front if defaults else True,
        cavity=cavity,
        rgba=(rgba,),
        tags=tuple(e.tags),
        synonyms=tuple(e.synonyms),
        guessed=frozenset(guessed),
        source=str(path),
    )
