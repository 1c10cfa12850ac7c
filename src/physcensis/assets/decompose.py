"""Convex decomposition of imported meshes with CoACD, cached on disk by mesh hash."""

from __future__ import annotations

import hashlib
import io
import logging

import numpy as np
import trimesh

from physcensis.assets.cache import AssetCache
from physcensis.assets.errors import AssetError
from physcensis.assets.meshfile import first_line
from physcensis.fileio import atomic_write_bytes

log = logging.getLogger(__name__)
COACD_THRESHOLD = 0.05  # concavity threshold (smaller = more, tighter parts)
COACD_SEED = 0


def mesh_hash(mesh: trimesh.Trimesh, threshold: float) -> str:
    digest = hashlib.sha256()
    digest.update(np.ascontiguousarray(mesh.vertices, dtype=np.float64).tobytes())
    digest.update(np.ascontiguousarray(mesh.faces, dtype=np.int64).tobytes())
    digest.update(f"{threshold:.6f}/{COACD_SEED}".encode())
    return digest.hexdigest()[:32]


def _run_coacd(mesh: trimesh.Trimesh, threshold: float) -> list[np.ndarray]:
    try:
        import coacd
    except ImportError as exc:
        raise AssetError("convex decomposition of concave meshes needs the package coacd (pip install coacd)") from exc
    try:
        coacd.set_log_level("error")
        parts = coacd.run_coacd(
            coacd.Mesh(np.asarray(mesh.vertices, dtype=np.float64), np.asarray(mesh.faces, dtype=np.int32)),
            threshold=threshold,
            seed=COACD_SEED,
        )
        return [np.asarray(vertices, dtype=np.float64).reshape(-1, 3) for vertices, _faces in parts]
    except Exception as exc:  # CoACD gives up on some meshes: that mesh's error, not a crash
        raise AssetError(f"convex decomposition (CoACD) failed ({first_line(exc)})") from None


def convex_decomposition(
    mesh: trimesh.Trimesh, threshold: float = COACD_THRESHOLD, cache: AssetCache | None = None
) -> list[np.ndarray]:
    """Vertex arrays of convex parts covering `mesh` (CoACD); cached under `<cache>/coacd/<hash>.npz`."""
    key = mesh_hash(mesh, threshold)
    path = cache.root / "coacd" / f"{key}.npz" if cache is not None else None
    if path is not None and path.exists():
        try:
            with np.load(path, allow_pickle=False) as npz:
                return [npz[f"part_{i}"] for i in range(int(npz["count"]))]
        except Exception as exc:  # damaged cache entry: recompute, and say so
            log.warning("coacd cache: damaged entry %s (%s); recomputing", path, exc)
    parts = _run_coacd(mesh, threshold)
    if not parts:
        raise AssetError("CoACD returned no convex parts")
    if path is not None:
        buffer = io.BytesIO()
        arrays = {f"part_{i}": p for i, p in enumerate(parts)}
        np.savez_compressed(buffer, count=np.array(len(parts)), **arrays)  # type: ignore[arg-type]
        try:
            atomic_write_bytes(path, buffer.getvalue())
        except OSError as exc:
            log.warning("coacd cache: cannot write %s (%s)", path, exc)
    return parts
