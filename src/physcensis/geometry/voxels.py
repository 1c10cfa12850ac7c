"""Occupancy grids of scenes and objects, and the search for free, supported resting spots.

A cell is occupied when its centre lies inside a collision part grown by `pad`
(a quarter cell by default, so thin objects such as pens still get cells). Free
translations of an object come from one FFT cross-correlation of the two grids;
each column of translations is then dropped from above to its resting height.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np
import scipy.fft
from numpy.typing import NDArray
from scipy.spatial import ConvexHull

from physcensis.assets.model import Asset, CollisionPart

BoolGrid = NDArray[np.bool_]
FFT_WORKERS = -1  # all cores
N_DIRECTIONS = 16
CONTACT_TOLERANCE_M = 0.004  # surface points this close to the lowest one touch once the object has settled
_DIRECTIONS = np.stack(
    [
        np.cos(np.arange(N_DIRECTIONS) * 2 * np.pi / N_DIRECTIONS),
        np.sin(np.arange(N_DIRECTIONS) * 2 * np.pi / N_DIRECTIONS),
    ],
    axis=1,
)


def quat_to_matrix(q: Sequence[float]) -> np.ndarray:
    w, x, y, z = (float(v) for v in q)
    n = np.sqrt(w * w + x * x + y * y + z * z) or 1.0
    w, x, y, z = w / n, x / n, y / n, z / n
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def yaw_matrix(yaw: float) -> np.ndarray:
    c, s = np.cos(yaw), np.sin(yaw)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


@lru_cache(maxsize=4096)
def _hull_equations(key: bytes, shape: tuple[int, int]) -> np.ndarray:
    vertices = np.frombuffer(key, dtype=np.float64).reshape(shape)
    # (F, 4): normal . x + offset <= 0 inside. Qhull gives every triangle of a flat face that face's plane: keep one.
    return np.unique(ConvexHull(vertices).equations, axis=0)


def _part_frame(part: CollisionPart, rotation: np.ndarray, translation: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """World-from-part rotation and translation of a collision part of a posed object."""
    if part.kind == "mesh":
        return rotation, translation
    r_part = quat_to_matrix(part.quat)
    return rotation @ r_part, rotation @ np.asarray(part.pos, dtype=float) + translation


def part_corners(part: CollisionPart) -> np.ndarray:
    """Points whose convex hull bounds the part, in the part's own frame."""
    sx, sy, sz = part.size
    if part.kind == "mesh":
        assert part.vertices is not None
        return np.asarray(part.vertices, dtype=float)
    if part.kind == "box":
        return np.array([[a, b, c] for a in (-sx, sx) for b in (-sy, sy) for c in (-sz, sz)])
    if part.kind in ("cylinder", "capsule"):
        half = sy + (sx if part.kind == "capsule" else 0.0)
        return np.array([[a, b, c] for a in (-sx, sx) for b in (-sx, sx) for c in (-half, half)])
    if part.kind == "sphere":
        return np.array([[a, b, c] for a in (-sx, sx) for b in (-sx, sx) for c in (-sx, sx)])
    return np.array([[a, b, c] for a in (-sx, sx) for b in (-sy, sy) for c in (-0.05, 0.0)])  # plane: a thin slab


def inside_part(part: CollisionPart, local: np.ndarray, pad: float) -> NDArray[np.bool_]:
    """Which points (N, 3), given in the part's frame, lie inside the part grown by `pad`."""
    sx, sy, sz = part.size
    if part.kind == "mesh":
        assert part.vertices is not None
        vertices = np.ascontiguousarray(part.vertices, dtype=np.float64)
        eq = _hull_equations(vertices.tobytes(), vertices.shape)
        return np.all(local @ eq[:, :3].T + eq[:, 3] <= pad, axis=1)
    if part.kind == "box":
        return np.all(np.abs(local) <= np.array([sx, sy, sz]) + pad, axis=1)
    if part.kind == "cylinder":
        return (local[:, 0] ** 2 + local[:, 1] ** 2 <= (sx + pad) ** 2) & (np.abs(local[:, 2]) <= sy + pad)
    if part.kind == "sphere":
        return np.einsum("ij,ij->i", local, local) <= (sx + pad) ** 2
    if part.kind == "capsule":
        z = np.clip(local[:, 2], -sy, sy)
        d2 = local[:, 0] ** 2 + local[:, 1] ** 2 + (local[:, 2] - z) ** 2
        return d2 <= (sx + pad) ** 2
    # plane: everything within its extent and up to 5 cm below it
    return (
        (np.abs(local[:, 0]) <= sx + pad)
        & (np.abs(local[:, 1]) <= sy + pad)
        & (local[:, 2] <= pad)
        & (local[:, 2] >= -0.05)
    )


@dataclass
class Grid:
    """An axis-aligned occupancy grid; cell (i, j, k) has its centre at origin + (i, j, k + 0.5) * pitch."""

    occupied: BoolGrid
    label: NDArray[np.int32]  # which posed body fills each cell (-1: none)
    origin: np.ndarray  # world position of the grid's lower corner
    pitch: float
    # Sides (x-, x+, y-, y+) that are not the support's edge: the grid of a large support is a window of it.
    open_sides: tuple[bool, bool, bool, bool] = (False, False, False, False)
    # FFTs of arrays derived from this grid, by name: every yaw of a search correlates with the same ones.
    spectra: dict[str, Spectrum] = field(default_factory=dict, repr=False, compare=False)

    @property
    def shape(self) -> tuple[int, int, int]:
        return self.occupied.shape

    def spectrum(self, name: str, cells: Callable[[], np.ndarray]) -> Spectrum:
        """The FFT of `cells()` (an array derived from this grid), computed once per name."""
        if name not in self.spectra:
            self.spectra[name] = Spectrum(cells())
        return self.spectra[name]

    def centres(self, axis: int) -> np.ndarray:
        return self.origin[axis] + (np.arange(self.shape[axis]) + 0.5) * self.pitch


def rasterise(
    grid: Grid, parts: Sequence[CollisionPart], rotation: np.ndarray, translation: np.ndarray, label: int, pad: float
) -> None:
    """Mark the cells of a posed set of collision parts in `grid` (in place)."""
    stamp(grid, part_cells(grid, parts, rotation, translation, pad), label)


@dataclass(frozen=True)
class PartCells:
    """The cells of one posed collision part, from cell `lo` of a grid (any height: the grid clips them)."""

    lo: tuple[int, int, int]
    inside: BoolGrid


def part_cells(
    grid: Grid, parts: Sequence[CollisionPart], rotation: np.ndarray, translation: np.ndarray, pad: float
) -> list[PartCells]:
    """The cells of posed parts on `grid`'s lattice (its origin and pitch), within its x and y extent but not clipped
    above: grids of the same lattice differ only in height, so these can be kept and stamped on each."""
    pitch = grid.pitch
    cells = []
    for part in parts:
        r, t = _part_frame(part, rotation, translation)
        corners = part_corners(part) @ r.T + t
        lo = np.maximum(np.floor((corners.min(0) - pad - grid.origin) / pitch).astype(int), 0)
        hi = np.ceil((corners.max(0) + pad - grid.origin) / pitch).astype(int)
        hi[:2] = np.minimum(hi[:2], grid.shape[:2])
        if np.any(hi <= lo):
            continue
        axes = [grid.origin[a] + (np.arange(lo[a], hi[a]) + 0.5) * pitch for a in range(3)]
        inside = _mesh_cells(part, axes, r, t, pad) if part.kind == "mesh" else _cells_inside(part, axes, r, t, pad)
        cells.append(PartCells((int(lo[0]), int(lo[1]), int(lo[2])), inside))
    return cells


def _cells_inside(
    part: CollisionPart, axes: Sequence[np.ndarray], r: np.ndarray, t: np.ndarray, pad: float
) -> BoolGrid:
    """Which cell centres of the block `axes` (world x, y, z) lie inside the posed part grown by `pad`."""
    gx, gy, gz = np.meshgrid(*axes, indexing="ij")
    points = np.stack([gx.ravel(), gy.ravel(), gz.ravel()], axis=1)
    return inside_part(part, (points - t) @ r, pad).reshape(gx.shape)


_SURE_M = 1e-9  # far beyond rounding (~1e-13 m), far below a cell: closer to a face, a centre is tested as before
_LEVEL = 1e-12  # a face whose normal's z is this small is upright: over the grid's heights its nz z is below 1e-10 m


def _mesh_cells(part: CollisionPart, axes: Sequence[np.ndarray], r: np.ndarray, t: np.ndarray, pad: float) -> BoolGrid:
    """`_cells_inside` for a convex mesh, the same cells without testing every face at every centre: along a
    column of cells the inside of a convex hull is one interval, so each face bounds it once per column. Centres
    within `_SURE_M` of a face (rare) are tested one by one, exactly as `_cells_inside` does."""
    assert part.vertices is not None
    vertices = np.ascontiguousarray(part.vertices, dtype=np.float64)
    eq = _hull_equations(vertices.tobytes(), vertices.shape)
    normal = eq[:, :3] @ r.T  # the faces in the world frame: a point p is inside when normal . p + offset <= 0
    offset = eq[:, 3] - normal @ t - pad
    ax, ay, az = axes
    nz = normal[:, 2]
    up, down, level = np.flatnonzero(nz > _LEVEL), np.flatnonzero(nz < -_LEVEL), np.flatnonzero(np.abs(nz) <= _LEVEL)
    inside = np.zeros((len(ax), len(ay), len(az)), dtype=bool)
    rows = max(1, 2_000_000 // max(1, len(ay) * len(eq)))  # bounded memory for the (x, y, face) arrays
    for start in range(0, len(ax), rows):
        x = ax[start : start + rows]
        # (x, y, face): normal . p + offset at z = 0 of each column
        value = x[:, None, None] * normal[:, 0] + ay[None, :, None] * normal[:, 1] + offset
        # A face looking up holds the centres below the height where it crosses the column, one looking down those
        # above it, an upright one all or none; "sure" keeps _SURE_M inside every face, "near" up to _SURE_M outside.
        top, bottom, side = -value[:, :, up] / nz[up], -value[:, :, down] / nz[down], value[:, :, level]
        rise, drop = _SURE_M / nz[up], _SURE_M / -nz[down]
        sure = _between(np.max(bottom + drop, axis=2, initial=-np.inf), np.min(top - rise, axis=2, initial=np.inf), az)
        near = _between(np.max(bottom - drop, axis=2, initial=-np.inf), np.min(top + rise, axis=2, initial=np.inf), az)
        sure &= np.all(side <= -_SURE_M, axis=2)[:, :, None]
        near &= np.all(side <= _SURE_M, axis=2)[:, :, None]
        inside[start : start + rows] = sure
        if (unsure := near & ~sure).any():
            i, j, k = np.nonzero(unsure)
            points = np.stack([x[i], ay[j], az[k]], axis=1)
            inside[start + i, j, k] = inside_part(part, (points - t) @ r, pad)
    return inside


def _between(low: np.ndarray, high: np.ndarray, az: np.ndarray) -> BoolGrid:
    """(x, y, z): whether each height of `az` lies between a column's `low` and `high` (x, y)."""
    return (az >= low[:, :, None]) & (az <= high[:, :, None])


def stamp(grid: Grid, cells: Sequence[PartCells], label: int) -> None:
    """Mark `cells` (from `part_cells` on this grid's lattice) as occupied by `label`, clipped to the grid."""
    grid.spectra.clear()
    for part in cells:
        lo = part.lo
        if lo[2] >= grid.shape[2]:
            continue
        inside = part.inside[:, :, : grid.shape[2] - lo[2]]
        window = tuple(slice(a, a + n) for a, n in zip(lo, inside.shape, strict=True))
        grid.occupied[window] |= inside
        grid.label[window][inside] = label


@dataclass
class ObjectGrid:
    """An object's cells at one yaw, with what the support test needs."""

    grid: Grid
    yaw: float
    origin_offset: np.ndarray  # object origin minus grid origin, world axes
    bottom_i: np.ndarray  # bottom-surface columns (P,)
    bottom_j: np.ndarray
    bottom_k: np.ndarray  # lowest occupied layer of each bottom column
    projections: np.ndarray  # (P, D): direction . (column centre - COM) in the xy plane
    # Resting on the flat support: the columns of the layer-0 cells under the object's lowest surface points too, and
    # (Q, D) how far each column's whole patch (its cell within the footprint) reaches past the COM
    flat_i: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    flat_j: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    flat_projections: np.ndarray = field(default_factory=lambda: np.zeros((0, N_DIRECTIONS)))

    @property
    def occupied(self) -> BoolGrid:
        return self.grid.occupied


def object_grid(
    asset: Asset, yaw: float, pitch: float, *, pad: float, k_bottom: int = 1, com: Sequence[float] | None = None
) -> ObjectGrid:
    """Voxelise an asset turned by `yaw` about its origin."""
    rotation = yaw_matrix(yaw)
    posed = [_posed_points(p, rotation) for p in asset.collision]
    corners = np.vstack([points for points, _ in posed])
    lo = corners.min(0) - pad
    hi = corners.max(0) + pad
    lo[2] = 0.0  # the base sits at z = 0: the grid starts there so layer 0 is the bottom
    shape = tuple(int(v) for v in np.maximum(1, np.ceil((hi - lo) / pitch)))
    grid = Grid(np.zeros(shape, dtype=bool), np.full(shape, -1, dtype=np.int32), lo, pitch)
    rasterise(grid, asset.collision, rotation, np.zeros(3), 0, pad)
    occ = grid.occupied
    if not occ.any():  # smaller than a cell: give it the cell under its origin
        occ[tuple(np.clip(((-lo) / pitch).astype(int), 0, np.array(shape) - 1))] = True
    layers = occ[:, :, : max(1, k_bottom)]
    has_bottom = layers.any(axis=2)
    bottom_i, bottom_j = np.nonzero(has_bottom)
    bottom_k = np.argmax(layers[bottom_i, bottom_j], axis=1)
    centre = np.asarray(asset.com if com is None else com, dtype=float) @ rotation.T
    cx = lo[0] + (bottom_i + 0.5) * pitch - centre[0]
    cy = lo[1] + (bottom_j + 0.5) * pitch - centre[1]
    projections = np.stack([cx, cy], axis=1) @ _DIRECTIONS.T
    flat = occ[:, :, 0] | _contact_point_cells(occ.shape[:2], posed, lo, pitch)
    flat_i, flat_j = np.nonzero(flat)
    footprint = corners[:, :2].min(0), corners[:, :2].max(0)
    patches = _patch_projections(flat_i, flat_j, lo, pitch, footprint, centre[:2])
    return ObjectGrid(grid, yaw, -lo, bottom_i, bottom_j, bottom_k, projections, flat_i, flat_j, patches)


def _posed_points(part: CollisionPart, rotation: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A part's bounding points and points on its surface, both in the object's turned frame."""
    r, t = _part_frame(part, rotation, np.zeros(3))
    return part_corners(part) @ r.T + t, _surface_points(part) @ r.T + t


def _surface_points(part: CollisionPart) -> np.ndarray:
    """Points on a part's surface, among them its lowest however it is turned: mesh vertices, box corners, the rims
    of a cylinder, the rims and poles of a capsule, and a sphere's poles and diagonals."""
    sx, sy, _ = part.size
    if part.kind in ("mesh", "box", "plane"):
        return part_corners(part)
    angles = np.linspace(0.0, 2 * np.pi, 16, endpoint=False)
    if part.kind in ("cylinder", "capsule"):
        rims = [np.stack([sx * np.cos(angles), sx * np.sin(angles), np.full(16, z)], axis=1) for z in (-sy, sy)]
        poles = [[0.0, 0.0, sy + sx], [0.0, 0.0, -sy - sx]] if part.kind == "capsule" else np.zeros((0, 3))
        return np.vstack([*rims, poles])
    directions = np.array(
        [[a, b, c] for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1) if (a, b, c) != (0, 0, 0)]
    )
    return sx * directions / np.linalg.norm(directions, axis=1, keepdims=True)


def _contact_point_cells(
    shape: tuple[int, ...], posed: list[tuple[np.ndarray, np.ndarray]], lo: np.ndarray, pitch: float
) -> BoolGrid:
    """The bottom-layer cells under the object's lowest surface points. Cells count as occupied when their centre is
    inside, so a thin contact (a tilted handle's end, a wire loop, a glass's thin foot) may leave no cell, and the
    contact patch would miss where the object actually rests."""
    points = np.vstack([surface for _, surface in posed])
    low = points[points[:, 2] <= points[:, 2].min() + CONTACT_TOLERANCE_M]
    ij = np.clip(np.floor((low[:, :2] - lo[:2]) / pitch).astype(int), 0, np.array(shape) - 1)
    cells = np.zeros(shape, dtype=bool)
    cells[ij[:, 0], ij[:, 1]] = True
    return cells


def _patch_projections(
    bottom_i: np.ndarray,
    bottom_j: np.ndarray,
    lo: np.ndarray,
    pitch: float,
    footprint: tuple[np.ndarray, np.ndarray],
    com_xy: np.ndarray,
) -> np.ndarray:
    """(P, D): how far each bottom column's patch reaches past the COM along each direction. On the flat support a
    column stands for the part of its cell inside the object's footprint, not for its centre alone: on a coarse grid
    a small object has one column whose centre can lie beside its COM, though it rests squarely on the floor."""
    low_x = np.maximum(lo[0] + bottom_i * pitch, footprint[0][0]) - com_xy[0]
    high_x = np.minimum(lo[0] + (bottom_i + 1) * pitch, footprint[1][0]) - com_xy[0]
    low_y = np.maximum(lo[1] + bottom_j * pitch, footprint[0][1]) - com_xy[1]
    high_y = np.minimum(lo[1] + (bottom_j + 1) * pitch, footprint[1][1]) - com_xy[1]
    dx, dy = _DIRECTIONS[:, 0], _DIRECTIONS[:, 1]
    reach_x = np.where(dx >= 0, high_x[:, None] * dx, low_x[:, None] * dx)
    reach_y = np.where(dy >= 0, high_y[:, None] * dy, low_y[:, None] * dy)
    return np.asarray(reach_x + reach_y)


class Spectrum:
    """The FFT of a scene array, for many 'valid' correlations with smaller kernels (every yaw of an object, every
    count of a search). A circular correlation over the scene's own extent is exact wherever the kernel lies wholly
    inside the scene, which is all that 'valid' keeps, so the scene's transform is computed once."""

    def __init__(self, cells: np.ndarray) -> None:
        self.shape = cells.shape
        self.fft_shape = tuple(scipy.fft.next_fast_len(int(n), real=True) for n in cells.shape)
        with scipy.fft.set_workers(FFT_WORKERS):
            self.transform = scipy.fft.rfftn(np.asarray(cells, dtype=np.float32), self.fft_shape)

    def correlate_valid(self, kernel: np.ndarray) -> NDArray[np.float64]:
        """Like scipy.signal.correlate(cells, kernel, mode="valid"); empty when the kernel is larger than the cells."""
        if kernel.ndim != len(self.shape) or any(k > n for k, n in zip(kernel.shape, self.shape, strict=True)):
            return np.zeros((0,) * len(self.shape))
        flipped = np.asarray(kernel, dtype=np.float32)[(slice(None, None, -1),) * kernel.ndim]
        with scipy.fft.set_workers(FFT_WORKERS):
            full = scipy.fft.irfftn(self.transform * scipy.fft.rfftn(flipped, self.fft_shape), self.fft_shape)
        valid = tuple(slice(k - 1, n) for k, n in zip(kernel.shape, self.shape, strict=True))
        return np.asarray(full[valid])


def collision_counts(scene: BoolGrid, obj: BoolGrid) -> NDArray[np.float64]:
    """For every translation that keeps the object inside the grid, how many cells it shares with the scene."""
    return Spectrum(scene).correlate_valid(obj)


def resting_heights(counts: NDArray[np.float64]) -> tuple[NDArray[np.int64], NDArray[np.bool_]]:
    """Per (x, y) translation, the layer the object comes to rest in when dropped from the top of the grid."""
    free = counts < 0.5
    free_from_top = np.flip(np.cumprod(np.flip(free, axis=2), axis=2), axis=2).astype(bool)
    reachable = free_from_top[:, :, -1]
    rest = np.argmax(free_from_top, axis=2)
    return rest, reachable


@dataclass
class Candidates:
    """Supported resting spots of one object at one yaw, as translations of its grid in the scene grid."""

    tx: np.ndarray
    ty: np.ndarray
    tz: np.ndarray
    n_contact: np.ndarray  # (M,): bottom columns resting on something
    n_support: np.ndarray  # (M,): ... on the support itself (counted only when asked for)
    n_target: np.ndarray  # (M,): ... on the target object (0 when there is none)
    margin: np.ndarray  # (M,): how far inside the contact patch's hull the COM projects (>= 0 means inside)
    bottom: int  # bottom columns of the object
    free_spots: int = 0  # resting spots before the support test: 0 means it fits nowhere at all

    @property
    def ratio(self) -> np.ndarray:
        return self.n_contact / max(1, self.bottom)

    @property
    def target_ratio(self) -> np.ndarray:
        return self.n_target / max(1, self.bottom)

    def subset(self, keep: np.ndarray) -> Candidates:
        return Candidates(
            self.tx[keep],
            self.ty[keep],
            self.tz[keep],
            self.n_contact[keep],
            self.n_support[keep],
            self.n_target[keep],
            self.margin[keep],
            self.bottom,
            self.free_spots,
        )


def _contact_counts(
    occupied: tuple[Grid, str, Callable[[], BoolGrid]],
    obj: ObjectGrid,
    k_search: int,
    tx: np.ndarray,
    ty: np.ndarray,
    tz: np.ndarray,
) -> np.ndarray:
    """For each spot, how many bottom columns have an occupied cell within k_search below them. `occupied`: the
    grid, a name for the cells counted and how to make them (their FFT is kept on the grid for the next yaw)."""
    grid, name, make = occupied
    if k_search == 1:  # one correlation with the layer just under the bottom
        depth = int(obj.bottom_k.max()) + 1
        kernel = np.zeros((*obj.occupied.shape[:2], depth + 1), dtype=np.float32)
        kernel[obj.bottom_i, obj.bottom_j, obj.bottom_k] = 1.0  # index bk + 1 - 1: the cell under the column
        counts = grid.spectrum(name, make).correlate_valid(kernel)
        z = np.clip(tz - 1, 0, counts.shape[2] - 1)
        return np.rint(counts[tx, ty, z]).astype(int)
    cells = make()
    hit = np.zeros((len(tx), len(obj.bottom_i)), dtype=bool)
    for start in range(0, len(tx), 4096):
        rows = slice(start, start + 4096)
        gi = tx[rows, None] + obj.bottom_i[None, :]
        gj = ty[rows, None] + obj.bottom_j[None, :]
        for s in range(1, k_search + 1):
            gk = tz[rows, None] + obj.bottom_k[None, :] - s
            hit[rows] |= cells[gi, gj, np.clip(gk, 0, cells.shape[2] - 1)] & (gk >= 0)
    return hit.sum(axis=1)


def supported_candidates(
    scene: Grid,
    obj: ObjectGrid,
    *,
    k_search: int = 1,
    min_margin: float = 0.0,
    target_label: int | Sequence[int] | None = None,
    support_label: int | None = None,
    max_partial: int = 20000,
    rng: np.random.Generator | None = None,
) -> Candidates:
    """Resting spots whose centre of mass projects inside the convex hull of the contact patch."""
    counts = scene.spectrum("occupied", lambda: scene.occupied).correlate_valid(obj.occupied)  # collision_counts
    p = len(obj.bottom_i)
    if counts.size == 0 or p == 0:
        return _empty(p)
    rest, reachable = resting_heights(counts)
    tx, ty = np.nonzero(reachable)
    tz = rest[tx, ty]
    free_spots = len(tx)
    n_contact = _contact_counts((scene, "occupied", lambda: scene.occupied), obj, k_search, tx, ty, tz)
    n_support = (
        np.zeros_like(n_contact)
        if support_label is None
        else _contact_counts(
            (scene, f"label {support_label}", lambda: scene.label == support_label), obj, k_search, tx, ty, tz
        )
    )
    n_target = _target_contacts(scene, obj, k_search, (tx, ty, tz), target_label)
    margin = np.full(len(tx), _full_margin(obj.projections))
    margin[n_contact == 0] = -np.inf
    partial = np.nonzero((n_contact > 0) & (n_contact < p))[0]
    if len(partial) > max_partial:  # the FFTs did the bulk; sample the expensive exact checks evenly
        drop = (rng or np.random.default_rng(0)).choice(len(partial), len(partial) - max_partial, replace=False)
        margin[partial[drop]] = -np.inf
        partial = np.delete(partial, drop)
    for start in range(0, len(partial), 1024):
        rows = partial[start : start + 1024]
        contact = _touching(scene, tx[rows], ty[rows], tz[rows], obj.bottom_i, obj.bottom_j, obj.bottom_k, k_search)
        margin[rows] = np.where(contact[:, :, None], obj.projections[None, :, :], -np.inf).max(axis=1).min(axis=1)
    if support_label is not None and len(obj.flat_i):
        _flat_support_margins(scene, obj, margin, (tx, ty, tz), (n_contact, n_support), partial, k_search)
    ok = margin >= min_margin
    return Candidates(tx[ok], ty[ok], tz[ok], n_contact[ok], n_support[ok], n_target[ok], margin[ok], p, free_spots)


def _target_contacts(
    scene: Grid,
    obj: ObjectGrid,
    k_search: int,
    spots: tuple[np.ndarray, np.ndarray, np.ndarray],
    target_label: int | Sequence[int] | None,
) -> np.ndarray:
    """Bottom columns resting on the target (on any of several labels: a stack, the target and what it rests on)."""
    tx, ty, tz = spots
    if target_label is None:
        return np.zeros(len(tx), dtype=int)
    labels = sorted({target_label} if isinstance(target_label, int) else set(target_label))
    cells = (scene, f"labels {labels}", lambda: np.isin(scene.label, labels))
    return _contact_counts(cells, obj, k_search, tx, ty, tz)


def _touching(
    scene: Grid,
    tx: np.ndarray,
    ty: np.ndarray,
    tz: np.ndarray,
    ci: np.ndarray,
    cj: np.ndarray,
    ck: np.ndarray,
    k_search: int,
) -> BoolGrid:
    """(rows, columns): which of an object's columns (ci, cj, lowest layer ck) rest on an occupied cell."""
    gi = tx[:, None] + ci[None, :]
    gj = ty[:, None] + cj[None, :]
    contact = np.zeros(gi.shape, dtype=bool)
    for s in range(1, k_search + 1):
        gk = tz[:, None] + ck[None, :] - s
        contact |= scene.occupied[gi, gj, np.clip(gk, 0, scene.shape[2] - 1)] & (gk >= 0)
    return contact


def _flat_support_margins(
    scene: Grid,
    obj: ObjectGrid,
    margin: np.ndarray,
    spots: tuple[np.ndarray, np.ndarray, np.ndarray],
    contacts: tuple[np.ndarray, np.ndarray],
    partial: np.ndarray,
    k_search: int,
) -> None:
    """Spots where the object touches the flat support and nothing else: there a column's whole patch bears (not
    only its centre) and thin contacts count, so a die smaller than a floor cell or a whisk leaning on its handle's
    end is supported. On other objects only a column's centre is sure to rest on something."""
    tx, ty, tz = spots
    n_contact, n_support = contacts
    flat = (n_contact > 0) & (n_support == n_contact)
    whole = flat & (n_contact == len(obj.bottom_i))
    margin[whole] = np.maximum(margin[whole], _full_margin(obj.flat_projections))
    rows = partial[flat[partial]]
    zeros = np.zeros(len(obj.flat_i), dtype=int)
    for start in range(0, len(rows), 1024):
        chunk = rows[start : start + 1024]
        contact = _touching(scene, tx[chunk], ty[chunk], tz[chunk], obj.flat_i, obj.flat_j, zeros, k_search)
        reach = np.where(contact[:, :, None], obj.flat_projections[None, :, :], -np.inf).max(axis=1).min(axis=1)
        margin[chunk] = np.maximum(margin[chunk], reach)


def _full_margin(projections: np.ndarray) -> float:
    return float(projections.max(axis=0).min()) if len(projections) else -np.inf


def _empty(p: int) -> Candidates:
    z = np.zeros(0, dtype=int)
    return Candidates(z, z, z, z, z, z, np.zeros(0), p, 0)


def candidate_origin(scene: Grid, obj: ObjectGrid, tx: int, ty: int, tz: int) -> np.ndarray:
    """World position of the object's origin for a grid translation."""
    return scene.origin + np.array([tx, ty, tz]) * scene.pitch + obj.origin_offset
