"""Convex decomposition of imported meshes: budgeted CoACD in a child process, cached on disk by mesh hash.

CoACD's defaults spend minutes on one mesh (a soda can: 40 slivers in 8 minutes). `COACD_SETTINGS` were tuned on
real meshes (robosuite objects, pybullet_data's mug, duck and teddy): at most 16 parts, a coarser concavity
threshold and a short tree search give a few seconds per mesh and parts within a few millimetres of the surface
(`python -m physcensis.bench --only import` measures it). CoACD runs in a child process killed after
`TIME_LIMIT` seconds; then, or when CoACD fails or its parts fill the cavity, `voxel_boxes` stands in: boxes
merged from a voxelisation of the solid, which keeps openings wider than a voxel open.
"""

from __future__ import annotations

import hashlib
import io
import json
import logging
import subprocess
import sys
from pathlib import Path

import numpy as np
import trimesh

from physcensis.assets.cache import AssetCache
from physcensis.assets.container_parts import container_parts
from physcensis.assets.errors import AssetError
from physcensis.assets.hulls import hull_deviation, inside_any
from physcensis.assets.meshfile import first_line
from physcensis.assets.model import Cavity
from physcensis.fileio import atomic_write_bytes

log = logging.getLogger(__name__)
MAX_PARTS = 16
COACD_THRESHOLD = 0.08  # concavity threshold (smaller = more, tighter parts)
COACD_SEED = 0
COACD_SETTINGS = {
    "max_convex_hull": MAX_PARTS,
    "preprocess_resolution": 30,
    "resolution": 400,
    "mcts_nodes": 6,
    "mcts_iterations": 15,
    "mcts_max_depth": 1,
}
DENSE_FACES = 20_000  # above this CoACD always remeshes the input first (its cost grows with the faces)
TIME_LIMIT = 15.0  # seconds of CoACD per mesh before the voxel fallback (thin-walled cups and bowls need it)
VOXELS = 24  # voxels along the longest side in the fallback decomposition
_WORKER = Path(__file__).with_name("coacd_worker.py")


def mesh_hash(mesh: trimesh.Trimesh, threshold: float) -> str:
    digest = hashlib.sha256()
    digest.update(np.ascontiguousarray(mesh.vertices, dtype=np.float64).tobytes())
    digest.update(np.ascontiguousarray(mesh.faces, dtype=np.int64).tobytes())
    digest.update(f"{threshold:.6f}/{COACD_SEED}/{json.dumps(COACD_SETTINGS, sort_keys=True)}".encode())
    return digest.hexdigest()[:32]


def _settings(mesh: trimesh.Trimesh, threshold: float) -> dict[str, object]:
    settings: dict[str, object] = {**COACD_SETTINGS, "threshold": threshold, "seed": COACD_SEED}
    if len(mesh.faces) > DENSE_FACES:
        settings["preprocess_mode"] = "on"  # the voxel remesh is the decimation
    return settings


def _worker_command() -> list[str]:
    return [sys.executable, str(_WORKER)]


def _pack_request(mesh: trimesh.Trimesh, settings: dict[str, object]) -> bytes:
    buffer = io.BytesIO()
    np.savez(
        buffer,
        vertices=np.asarray(mesh.vertices, dtype=np.float64),
        faces=np.asarray(mesh.faces, dtype=np.int32),
        settings=np.frombuffer(json.dumps(settings).encode(), dtype=np.uint8),
    )
    return buffer.getvalue()


def _unpack_parts(data: bytes) -> list[np.ndarray]:
    with np.load(io.BytesIO(data), allow_pickle=False) as npz:
        return [np.asarray(npz[f"part_{i}"], dtype=np.float64).reshape(-1, 3) for i in range(int(npz["count"]))]


def _run_coacd(mesh: trimesh.Trimesh, threshold: float, time_limit: float) -> list[np.ndarray]:
    """CoACD's parts, computed in a child process; AssetError when it fails or runs over `time_limit`."""
    try:
        done = subprocess.run(
            _worker_command(),
            input=_pack_request(mesh, _settings(mesh, threshold)),
            capture_output=True,
            timeout=time_limit,
            check=False,
        )
    except subprocess.TimeoutExpired:
        raise AssetError(f"convex decomposition (CoACD) took over {time_limit:g} s") from None
    if done.returncode != 0:
        message = done.stderr.decode(errors="replace").strip().splitlines()
        raise AssetError(f"convex decomposition (CoACD) failed ({message[-1] if message else done.returncode})")
    try:
        return _unpack_parts(done.stdout)
    except Exception as exc:  # a garbled answer is CoACD's failure, not a crash
        raise AssetError(f"convex decomposition (CoACD) gave no readable parts ({first_line(exc)})") from None


def cavity_probe_points(cavity: Cavity) -> np.ndarray:
    """Points well inside a cavity: its opening shrunk towards the centre, from just above the floor to the rim."""
    centre = cavity.opening.mean(axis=0)
    heights = cavity.floor_height + cavity.depth * np.linspace(0.25, 0.95, 5)
    rings = [centre + (cavity.opening - centre) * s for s in (0.0, 0.5)]
    return np.array([[x, y, z] for z in heights for ring in rings for x, y in ring])


def blocks_cavity(parts: list[np.ndarray], cavity: Cavity | None) -> bool:
    """Whether some part fills the inside of the cavity (an item dropped in would land on it)."""
    if cavity is None:
        return False
    return bool(inside_any(cavity_probe_points(cavity), parts).any())


def _greedy_boxes(grid: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """Cover the filled voxels with boxes (first and last voxel index), growing each along x, then y, then z."""
    free = grid.copy()
    boxes = []
    for start in np.argwhere(grid):
        if not free[tuple(start)]:
            continue
        end = start.copy()
        for axis in range(3):
            while end[axis] + 1 < grid.shape[axis]:
                lo, hi = start.copy(), end.copy() + 1
                lo[axis], hi[axis] = end[axis] + 1, end[axis] + 2
                if not free[lo[0] : hi[0], lo[1] : hi[1], lo[2] : hi[2]].all():
                    break
                end[axis] += 1
        free[start[0] : end[0] + 1, start[1] : end[1] + 1, start[2] : end[2] + 1] = False
        boxes.append((start, end))
    return boxes


def _box_corners(start: np.ndarray, end: np.ndarray, transform: np.ndarray) -> np.ndarray:
    lo, hi = start - 0.5, end + 0.5
    corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
    return trimesh.transform_points(corners, transform)


def _clipped(corners: np.ndarray, surface: np.ndarray, margin: float) -> np.ndarray:
    """The surface points within a box (and `margin`) when they span a solid, else the box: parts hug the mesh."""
    lo, hi = corners.min(axis=0) - margin, corners.max(axis=0) + margin
    inside = surface[np.all((surface >= lo) & (surface <= hi), axis=1)]
    if len(inside) >= 8 and np.all(np.ptp(inside, axis=0) > margin):
        return inside
    return corners


def _filled_counter(grid: np.ndarray) -> np.ndarray:
    """Summed-volume table: filled voxels of any index box in eight lookups."""
    table = np.zeros(tuple(n + 1 for n in grid.shape), dtype=np.int64)
    table[1:, 1:, 1:] = grid.astype(np.int64).cumsum(0).cumsum(1).cumsum(2)
    return table


def _empty_voxels(table: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Empty voxels inside index boxes [lo, hi] (rows of lo and hi, inclusive)."""
    a, b = lo, hi + 1
    filled = np.zeros(len(lo), dtype=np.int64)
    for corner in range(8):
        pick = [(corner >> axis) & 1 for axis in range(3)]
        index = tuple(np.where(pick[axis], b[:, axis], a[:, axis]) for axis in range(3))
        filled += (-1) ** (3 - sum(pick)) * table[index]
    return np.prod(b - a, axis=1) - filled


def _merge_boxes(grid: np.ndarray, boxes: list[tuple[np.ndarray, np.ndarray]], max_parts: int) -> list:
    """Merge the pair of boxes whose bounding box takes in the fewest empty voxels, until `max_parts` remain:
    neighbours along a wall merge first, boxes across an opening last."""
    table = _filled_counter(grid)
    lo = np.array([b[0] for b in boxes])
    hi = np.array([b[1] for b in boxes])
    while len(lo) > max_parts:
        i, j = np.triu_indices(len(lo), k=1)
        cost = _empty_voxels(table, np.minimum(lo[i], lo[j]), np.maximum(hi[i], hi[j]))
        best = int(np.argmin(cost))
        a, b = int(i[best]), int(j[best])
        lo[a], hi[a] = np.minimum(lo[a], lo[b]), np.maximum(hi[a], hi[b])
        lo, hi = np.delete(lo, b, axis=0), np.delete(hi, b, axis=0)
    return list(zip(lo, hi, strict=True))


def voxel_boxes(mesh: trimesh.Trimesh, max_parts: int = MAX_PARTS) -> list[np.ndarray]:
    """At most `max_parts` boxes covering the voxelised solid, each shrunk to the hull of the surface points it
    holds: openings wider than a few voxels stay open."""
    pitch = float(mesh.extents.max()) / VOXELS
    voxels = mesh.voxelized(pitch).fill()
    grid = np.asarray(voxels.matrix, dtype=bool)
    boxes = _merge_boxes(grid, _greedy_boxes(grid), max_parts)
    surface, _ = trimesh.sample.sample_surface(mesh, 20_000, seed=COACD_SEED)
    surface = np.concatenate([surface, mesh.vertices])
    transform = np.asarray(voxels.transform)
    return [_clipped(_box_corners(start, end, transform), surface, pitch / 4) for start, end in boxes]


def _load_cached(path: Path) -> list[np.ndarray] | None:
    try:
        with np.load(path, allow_pickle=False) as npz:
            return [npz[f"part_{i}"] for i in range(int(npz["count"]))]
    except FileNotFoundError:
        return None
    except Exception as exc:  # damaged cache entry: recompute, and say so
        log.warning("coacd cache: damaged entry %s (%s); recomputing", path, first_line(exc))
        return None


def _store(path: Path, parts: list[np.ndarray]) -> None:
    buffer = io.BytesIO()
    arrays = {f"part_{i}": p for i, p in enumerate(parts)}
    np.savez_compressed(buffer, count=np.array(len(parts)), **arrays)  # type: ignore[arg-type]
    try:
        atomic_write_bytes(path, buffer.getvalue())
    except OSError as exc:
        log.warning("coacd cache: cannot write %s (%s)", path, exc)


def _coacd_or_fallback(
    mesh: trimesh.Trimesh, threshold: float, cavity: Cavity | None, time_limit: float
) -> tuple[list[np.ndarray], bool]:
    """CoACD's parts (and True), or the voxel boxes (and False) when CoACD fails, overruns or fills the cavity."""
    try:
        parts = _run_coacd(mesh, threshold, time_limit)
        if not parts:
            raise AssetError("CoACD returned no convex parts")
        if blocks_cavity(parts, cavity):
            raise AssetError("CoACD's parts fill the cavity")
        return parts, True
    except AssetError as exc:
        log.warning("%s; using a voxel decomposition instead", exc)
    return voxel_boxes(mesh), False


SECTORS_P95 = 0.005  # m: wall sectors must keep 95 % of their surface this close to the mesh (else CoACD)
SECTORS_MAX = 0.010  # ... and all of it this close: a mug's handle would fill its loop


def _hugs(mesh: trimesh.Trimesh, parts: list[np.ndarray]) -> bool:
    hull_max, hull_p95 = hull_deviation(mesh, parts, samples=1500)  # the mesh side is not needed here
    return hull_p95 <= SECTORS_P95 and hull_max <= SECTORS_MAX


def convex_decomposition(
    mesh: trimesh.Trimesh,
    threshold: float = COACD_THRESHOLD,
    cache: AssetCache | None = None,
    cavity: Cavity | None = None,
    time_limit: float | None = None,
) -> list[np.ndarray]:
    """Vertex arrays of at most MAX_PARTS convex parts covering `mesh`, none inside `cavity`: an open container's
    base and wall sectors (`container_parts.py`) when they leave its cavity open and hug the mesh (no handle
    loop filled), else CoACD's parts.

    CoACD's parts are cached under `<cache>/coacd/<hash>.npz`; the voxel fallback is not (a slow machine today
    should not fix a coarse collision for good: the imported asset's own cache keeps it meanwhile).
    """
    if cavity is not None:
        walls = [p for p in container_parts(mesh, cavity) if len(p) >= 4]
        if walls and not blocks_cavity(walls, cavity) and _hugs(mesh, walls):
            return walls
    key = mesh_hash(mesh, threshold)
    path = cache.root / "coacd" / f"{key}.npz" if cache is not None else None
    cached = _load_cached(path) if path is not None else None
    if cached and not blocks_cavity(cached, cavity):
        return cached
    parts, from_coacd = _coacd_or_fallback(mesh, threshold, cavity, TIME_LIMIT if time_limit is None else time_limit)
    if path is not None and from_coacd:
        _store(path, parts)
    return parts
