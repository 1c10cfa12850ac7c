"""Cache keys for whole imported assets: the entry, the bytes of its files, and the code that ingests them.

Loading a configured library happens on every command (solve, generate, render ...), so an entry whose mesh file,
referenced material and texture files, entry fields, library defaults and import code are all unchanged is read
back from the asset cache instead of being ingested again. The key hashes all of them; any change is a new key.
"""

from __future__ import annotations

import hashlib
import json
import re
from functools import lru_cache
from pathlib import Path

from physcensis.fileio import read_bounded

KEY_VERSION = 1
_OBJ_MTLLIB = re.compile(rb"^\s*mtllib\s+(.+?)\s*$", re.MULTILINE)
_MTL_MAP = re.compile(rb"^\s*(?:map_\w+|bump|disp|decal|refl|norm)\s+(.+?)\s*$", re.MULTILINE)
_GLTF_URI = re.compile(rb'"uri"\s*:\s*"([^"]+)"')
MAX_REFERENCED = 64  # files one mesh may pull in (materials, textures, buffers)
MAX_HASHED_BYTES = 200_000_000


@lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """Hash of the asset package's source and CoACD's version: new import code means new keys."""
    digest = hashlib.sha256(f"v{KEY_VERSION}".encode())
    for file in sorted(Path(__file__).parent.rglob("*.py")):
        digest.update(file.name.encode())
        digest.update(file.read_bytes())
    try:
        from importlib.metadata import version

        digest.update(version("coacd").encode())
    except Exception:  # no coacd: concave meshes fail anyway, the key only needs to differ
        digest.update(b"no coacd")
    return digest.hexdigest()[:16]


def _names(pattern: re.Pattern[bytes], data: bytes) -> list[str]:
    return [m.group(1).decode("utf-8", errors="replace").strip() for m in pattern.finditer(data)]


def _referenced(path: Path, data: bytes) -> list[str]:
    suffix = path.suffix.lower()
    if suffix == ".obj":
        return [name for line in _names(_OBJ_MTLLIB, data) for name in line.split()]
    if suffix == ".mtl":
        return [line.split()[-1] for line in _names(_MTL_MAP, data)]  # options come before the file name
    if suffix == ".gltf":
        return [uri for uri in _names(_GLTF_URI, data) if not uri.startswith("data:")]
    return []


def _read(path: Path) -> bytes | None:
    try:
        return read_bounded(path, MAX_HASHED_BYTES, "mesh file")
    except Exception:  # a missing or unreadable referenced file: its absence is part of the key
        return None


def mesh_files_digest(path: Path) -> str:
    """Hash of the mesh file and the files it references (OBJ -> MTL -> textures, glTF -> buffers, images)."""
    digest = hashlib.sha256()
    todo, seen = [path], set[Path]()
    while todo and len(seen) < MAX_REFERENCED:
        current = todo.pop(0)
        if current in seen:
            continue
        seen.add(current)
        data = _read(current)
        digest.update(str(current.name).encode() + b"\0" + (data if data is not None else b"<missing>") + b"\0")
        if data is not None:
            todo.extend(current.parent / name for name in _referenced(current, data))
    return digest.hexdigest()


def asset_key(entry: dict, defaults: dict, path: Path) -> str:
    """The asset cache key of one library entry (`lib-` + hash)."""
    digest = hashlib.sha256()
    digest.update(json.dumps({"entry": entry, "defaults": defaults, "path": str(path)}, sort_keys=True).encode())
    digest.update(mesh_files_digest(path).encode())
    digest.update(code_fingerprint().encode())
    return "lib-" + digest.hexdigest()[:32]
