"""Assets to and from a single .npz payload (the on-disk cache, and the copies in scene folders).

Payloads are read back through `npz.read_npz` within `PAYLOAD_BOUNDS` (what an imported mesh at the importer's
triangle limit can need), and their metadata and array shapes are checked before an Asset is made of them: a damaged
or hostile payload is a ValueError saying what is wrong, never an allocation out of proportion to its size.
"""

from __future__ import annotations

import io
import json
import re
import zipfile
from typing import Literal

import numpy as np
import trimesh
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from physcensis.assets.meshfile import MAX_FACES
from physcensis.assets.model import Asset, Cavity, CollisionPart, PartKind, Quat, Vec3
from physcensis.assets.npz import NpzBounds, read_npz
from physcensis.fileio import BoundError

FORMAT = "physcensis.asset/1"
_SCALARS = (
    "id",
    "category",
    "kind",
    "description",
    "size",
    "mass",
    "mass_range",
    "friction_range",
    "com",
    "com_shift_range",
    "support_probability",
    "has_front",
    "rgba",
    "part_faces",
    "tags",
    "synonyms",
    "generated",
    "source",
)
_OPTIONAL = {"pose": "", "rests": True}  # fields newer than the format: older payloads get the defaults
# Bounds of one payload: an imported mesh at the importer's triangle limit, with room for the triangles filling its
# holes adds, every triangle with its own three corners at worst, and as many vertices again in collision parts.
MAX_PAYLOAD_FACES = 2 * MAX_FACES
MAX_PAYLOAD_VERTICES = 3 * MAX_FACES
MAX_PAYLOAD_PARTS = 256  # built-in assets have up to 71
MAX_META_BYTES = 1 << 20
_MAX_ARRAY_BYTES = (MAX_PAYLOAD_FACES * 3 + 2 * MAX_PAYLOAD_VERTICES * 3) * 8 + MAX_META_BYTES
PAYLOAD_BOUNDS = NpzBounds(
    names=re.compile(r"meta|visual_vertices|visual_faces|cavity_opening|part_(?:0|[1-9][0-9]{0,2})"),
    max_members=4 + MAX_PAYLOAD_PARTS,
    max_unpacked=_MAX_ARRAY_BYTES,
    max_ratio=3.0,  # real meshes compress 1.5-5 : 1; a file cannot claim memory far beyond its own size
    small_unpacked=1 << 20,  # every built-in asset unpacks to under 0.5 MB; asset_to_bytes stores what would exceed it
)


def asset_to_bytes(asset: Asset) -> bytes:
    meta = {name: getattr(asset, name) for name in _SCALARS}
    meta["format"] = FORMAT
    meta.update({name: getattr(asset, name) for name in _OPTIONAL})
    meta["guessed"] = sorted(asset.guessed)
    meta["parts"] = [{"kind": p.kind, "size": p.size, "pos": p.pos, "quat": p.quat} for p in asset.collision]
    arrays: dict[str, np.ndarray] = {
        "visual_vertices": np.asarray(asset.visual.vertices, dtype=np.float64),
        "visual_faces": np.asarray(asset.visual.faces, dtype=np.int32),
    }
    for i, part in enumerate(asset.collision):
        if part.vertices is not None:
            arrays[f"part_{i}"] = np.asarray(part.vertices, dtype=np.float64)
    if asset.cavity is not None:
        arrays["cavity_opening"] = asset.cavity.opening
        meta["cavity"] = {"floor_height": asset.cavity.floor_height, "depth": asset.cavity.depth}
    arrays["meta"] = np.frombuffer(json.dumps(meta).encode("utf-8"), dtype=np.uint8)
    data = _saved(arrays, compressed=True)
    if _unpacked_size(data) > PAYLOAD_BOUNDS.unpacked_limit(len(data)):  # compresses beyond what a reader accepts
        data = _saved(arrays, compressed=False)
    return data


def _saved(arrays: dict[str, np.ndarray], compressed: bool) -> bytes:
    buffer = io.BytesIO()
    save = np.savez_compressed if compressed else np.savez
    save(buffer, allow_pickle=False, **arrays)  # numbers only: nothing is pickled
    return buffer.getvalue()


def _unpacked_size(data: bytes) -> int:
    with zipfile.ZipFile(io.BytesIO(data)) as archive:
        return sum(info.file_size for info in archive.infolist())


class _Checked(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False)


class _PartMeta(_Checked):
    kind: PartKind
    size: Vec3
    pos: Vec3
    quat: Quat


class _CavityMeta(_Checked):
    floor_height: float
    depth: float


class _Meta(_Checked):
    """The payload's metadata as `asset_to_bytes` writes it: types and lengths checked, numbers finite."""

    format: Literal["physcensis.asset/1"]
    id: str
    category: str
    kind: str
    description: str
    size: Vec3
    mass: float
    mass_range: tuple[float, float]
    friction_range: tuple[float, float]
    com: Vec3
    com_shift_range: Vec3
    support_probability: float
    has_front: bool
    rgba: tuple[tuple[float, float, float, float], ...]
    part_faces: tuple[int, ...]
    tags: tuple[str, ...]
    synonyms: tuple[str, ...]
    generated: bool
    source: str
    pose: str = ""
    rests: bool = True
    guessed: tuple[str, ...]
    parts: list[_PartMeta] = Field(max_length=MAX_PAYLOAD_PARTS)
    cavity: _CavityMeta | None = None


def _meta(array: np.ndarray | None) -> _Meta:
    if array is None or array.dtype != np.uint8 or array.ndim != 1:
        raise ValueError("no metadata (a uint8 array 'meta')")
    if array.size > MAX_META_BYTES:
        raise BoundError(f"its metadata has {array.size:,} bytes, over the limit of {MAX_META_BYTES:,}")
    try:
        return _Meta.model_validate_json(array.tobytes())
    except ValidationError as exc:
        error = exc.errors()[0]
        where = ".".join(str(part) for part in error["loc"])
        raise ValueError(f"metadata {where + ': ' if where else ''}{error['msg']}") from None


def _array(arrays: dict[str, np.ndarray], name: str, kinds: str, columns: int, max_rows: int) -> np.ndarray:
    """Take array `name` out of `arrays`: an (N, columns) array of integers ("iu") or floats ("f")."""
    array = arrays.pop(name, None)
    if array is None:
        raise ValueError(f"array {name!r} is missing")
    if array.dtype.kind not in kinds:
        raise ValueError(f"array {name!r} holds {array.dtype} values, not {'integers' if 'i' in kinds else 'floats'}")
    if array.ndim != 2 or array.shape[1] != columns:
        raise ValueError(f"array {name!r} has the shape {array.shape}, not (N, {columns})")
    if len(array) > max_rows:
        raise BoundError(f"array {name!r} has {len(array):,} rows, over the limit of {max_rows:,}")
    return array


def _part(meta: _PartMeta, index: int, arrays: dict[str, np.ndarray]) -> CollisionPart:
    vertices = _array(arrays, f"part_{index}", "f", 3, MAX_PAYLOAD_VERTICES) if meta.kind == "mesh" else None
    return CollisionPart(meta.kind, meta.size, meta.pos, meta.quat, vertices)


def asset_from_bytes(data: bytes) -> Asset:
    """Rebuild an Asset; raises ValueError (BoundError for a payload over PAYLOAD_BOUNDS) saying what is wrong."""
    arrays = read_npz(data, PAYLOAD_BOUNDS)
    meta = _meta(arrays.pop("meta", None))
    vertices = _array(arrays, "visual_vertices", "f", 3, MAX_PAYLOAD_VERTICES)
    faces = _array(arrays, "visual_faces", "iu", 3, MAX_PAYLOAD_FACES)
    parts = tuple(_part(part, i, arrays) for i, part in enumerate(meta.parts))
    cavity = None
    if meta.cavity is not None:
        opening = _array(arrays, "cavity_opening", "f", 2, MAX_PAYLOAD_VERTICES)
        cavity = Cavity(opening, meta.cavity.floor_height, meta.cavity.depth)
    if arrays:
        raise ValueError(f"array {sorted(arrays)[0]!r} belongs to nothing in the metadata")
    fields = {name: getattr(meta, name) for name in (*_SCALARS, *_OPTIONAL)}
    visual = trimesh.Trimesh(vertices, faces, process=False)
    return Asset(visual=visual, collision=parts, cavity=cavity, guessed=frozenset(meta.guessed), **fields)
