"""Assets to and from a single .npz payload (used by the on-disk cache)."""

from __future__ import annotations

import io
import json

import numpy as np
import trimesh

from physcensis.assets.model import Asset, Cavity, CollisionPart

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
    buffer = io.BytesIO()
    arrays["meta"] = np.frombuffer(json.dumps(meta).encode("utf-8"), dtype=np.uint8)
    np.savez_compressed(buffer, allow_pickle=False, **arrays)  # numbers only: nothing is pickled
    return buffer.getvalue()


def _tuple(value: object) -> object:
    return tuple(_tuple(v) for v in value) if isinstance(value, list) else value


def asset_from_bytes(data: bytes) -> Asset:
    """Rebuild an Asset; raises ValueError (or KeyError) on a damaged payload."""
    with np.load(io.BytesIO(data), allow_pickle=False) as npz:
        meta = json.loads(npz["meta"].tobytes().decode("utf-8"))
        if meta.get("format") != FORMAT:
            raise ValueError(f"unsupported asset payload format {meta.get('format')!r}")
        visual = trimesh.Trimesh(npz["visual_vertices"], npz["visual_faces"], process=False)
        parts = []
        for i, p in enumerate(meta["parts"]):
            vertices = npz[f"part_{i}"] if p["kind"] == "mesh" else None
            parts.append(CollisionPart(p["kind"], _tuple(p["size"]), _tuple(p["pos"]), _tuple(p["quat"]), vertices))  # type: ignore[arg-type]
        cavity = None
        if "cavity" in meta:
            cavity = Cavity(npz["cavity_opening"], meta["cavity"]["floor_height"], meta["cavity"]["depth"])
    fields = {name: _tuple(meta[name]) for name in _SCALARS}
    fields.update({name: meta.get(name, default) for name, default in _OPTIONAL.items()})
    return Asset(visual=visual, collision=tuple(parts), cavity=cavity, guessed=frozenset(meta["guessed"]), **fields)  # type: ignore[arg-type]
