"""PLACE-IN: spots on a container's floor for the items that stand on it, packed side by side.

Items that stand (bottles, cans, jars, boxes on end) are set on the cavity's floor upright before anything is
dropped: tallest first, each at the bottom-left-most free spot of the opening seen in its own axes, on a raster of
the opening (round footprints nest into the gaps of the row before, which packs them hexagonally). What finds no spot
is dropped on top, and nothing may end with its centre of mass above the rim.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
import shapely.affinity

from physcensis.assets.model import Asset

CELL_M = 0.0025  # raster of the opening
GAP_M = 0.004  # clearance between neighbours and from the walls
RIM_MARGIN_M = 0.005  # a standing item's centre of mass must be this far below the rim
ON_FLOOR_M = 0.01  # a lowered item whose bottom stops higher than this above the floor is not standing on it


@dataclass(frozen=True)
class Footprint:
    """An item's outline on the floor: a disc of diameter `sx` when round, else an sx x sy rectangle."""

    sx: float
    sy: float
    round: bool


@dataclass(frozen=True)
class FloorSpot:
    """Where one item stands: its index in the planned list, its centre and its yaw, in the world."""

    index: int
    x: float
    y: float
    yaw: float


def is_tall(asset: Asset) -> bool:
    """Taller than wide as it stands (a bottle, a can, a jar, a cereal box)."""
    sx, sy, sz = asset.size
    return sz >= max(sx, sy)


def footprint_of(asset: Asset) -> Footprint:
    sx, sy, _ = asset.size
    if not asset.has_front and abs(sx - sy) < 0.05 * max(sx, sy):
        return Footprint(max(sx, sy), max(sx, sy), True)
    return Footprint(sx, sy, False)


def com_height(asset: Asset) -> float:
    """Height of the centre of mass above the item's bottom as it stands."""
    return float(asset.com[2])


def stands_below_rim(asset: Asset, floor_z: float, rim_z: float) -> bool:
    """Whether, standing on the floor, its centre of mass is below the rim."""
    return floor_z + com_height(asset) < rim_z - RIM_MARGIN_M


def floor_order(assets: Sequence[Asset]) -> list[int]:
    """The order items are given floor spots: tall ones first (tallest first), then the rest by footprint area."""
    return sorted(
        range(len(assets)),
        key=lambda k: (not is_tall(assets[k]), -assets[k].size[2] if is_tall(assets[k]) else 0.0, _area(assets[k])),
    )


def _area(asset: Asset) -> float:
    return -float(asset.size[0] * asset.size[1])


def plan_floor_spots(opening: shapely.Polygon, footprints: Sequence[Footprint]) -> list[FloorSpot]:
    """Spots in the opening, in the given order, for as many footprints as fit (a footprint that does not fit is
    skipped; later, smaller ones may still fit). Footprints keep GAP_M from the walls and from each other."""
    theta = _principal_angle(opening)
    centre = opening.centroid
    local = shapely.affinity.rotate(opening, -theta, origin=centre, use_radians=True)
    raster = _Raster(local.buffer(-GAP_M))
    spots: list[FloorSpot] = []
    for index, fp in enumerate(footprints):
        best = raster.best_spot(fp)
        if best is None:
            continue
        x, y, turned = best
        raster.block(fp, x, y, turned)
        wx, wy = _rotate_about(x, y, theta, centre.x, centre.y)
        spots.append(FloorSpot(index, wx, wy, theta + (math.pi / 2 if turned else 0.0)))
    return spots


def _principal_angle(opening: shapely.Polygon) -> float:
    """The direction of the longest side of the opening's minimum rotated rectangle (0 for a round opening)."""
    rect = np.asarray(opening.minimum_rotated_rectangle.exterior.coords)[:4]
    edges = np.diff(np.vstack([rect, rect[:1]]), axis=0)
    longest = edges[int(np.argmax(np.hypot(edges[:, 0], edges[:, 1])))]
    angle = math.atan2(longest[1], longest[0])
    return (angle + math.pi / 2) % math.pi - math.pi / 2  # the same side either way round


def _rotate_about(x: float, y: float, theta: float, cx: float, cy: float) -> tuple[float, float]:
    c, s = math.cos(theta), math.sin(theta)
    dx, dy = x - cx, y - cy
    return cx + c * dx - s * dy, cy + s * dx + c * dy


class _Raster:
    """The opening as cells: free where a footprint's centre region may go, blocked outside and where placed."""

    def __init__(self, region: shapely.Geometry) -> None:
        minx, miny, maxx, maxy = region.bounds if not region.is_empty else (0.0, 0.0, 0.0, 0.0)
        self.x = np.arange(minx + CELL_M / 2, maxx, CELL_M)
        self.y = np.arange(miny + CELL_M / 2, maxy, CELL_M)
        gx, gy = np.meshgrid(self.x, self.y, indexing="ij")
        inside = shapely.contains_xy(region, gx, gy) if not region.is_empty else np.zeros(gx.shape, dtype=bool)
        self.blocked = ~inside

    def best_spot(self, fp: Footprint) -> tuple[float, float, bool] | None:
        """The bottom-left-most cell where the footprint fits (lowest y, then lowest x), at yaw 0 or turned."""
        best: tuple[float, float, float, bool] | None = None
        for turned in (False,) if fp.round or fp.sx == fp.sy else (False, True):
            kernel = _kernel(fp, turned, 0.0)
            free = self._free_centres(kernel)
            if not free.any():
                continue
            i, j = np.nonzero(free)
            order = np.lexsort((i, j))  # by j (y) first, then i (x)
            k = order[0]
            key = float(j[k]) + 1e-3 * float(i[k])
            if best is None or key < best[0]:
                best = (key, float(self.x[i[k]]), float(self.y[j[k]]), turned)
        return None if best is None else best[1:]

    def _free_centres(self, kernel: np.ndarray) -> np.ndarray:
        hx, hy = kernel.shape[0] // 2, kernel.shape[1] // 2
        if self.blocked.shape[0] == 0 or self.blocked.shape[1] == 0:
            return np.zeros(self.blocked.shape, dtype=bool)
        from scipy.signal import fftconvolve  # here: scipy.signal's import is 0.5 s of every process's start

        padded = np.pad(self.blocked, ((hx, hx), (hy, hy)), constant_values=True).astype(np.float32)
        hits = fftconvolve(padded, kernel[::-1, ::-1].astype(np.float32), mode="valid")
        return hits < 0.5

    def block(self, fp: Footprint, x: float, y: float, turned: bool) -> None:
        """Mark the footprint at (x, y), grown by the gap, as taken."""
        gx, gy = np.meshgrid(self.x - x, self.y - y, indexing="ij")
        self.blocked |= _covers(fp, turned, gx, gy, GAP_M)


def _kernel(fp: Footprint, turned: bool, grow: float) -> np.ndarray:
    """The footprint as an odd-sized boolean stencil of cells centred on its middle."""
    reach = 0.5 * math.hypot(fp.sx, fp.sy) + grow
    n = int(math.ceil(reach / CELL_M))
    offsets = np.arange(-n, n + 1) * CELL_M
    gx, gy = np.meshgrid(offsets, offsets, indexing="ij")
    return _covers(fp, turned, gx, gy, grow)


def _covers(fp: Footprint, turned: bool, dx: np.ndarray, dy: np.ndarray, grow: float) -> np.ndarray:
    if fp.round:
        return np.hypot(dx, dy) <= fp.sx / 2 + grow
    hx, hy = (fp.sy, fp.sx) if turned else (fp.sx, fp.sy)
    return (np.abs(dx) <= hx / 2 + grow) & (np.abs(dy) <= hy / 2 + grow)


def com_above_rim_reason(com_z: float, rim_z: float, container_id: str) -> str:
    """The agent's feedback for an item whose centre of mass ended above the rim."""
    return (
        f"its centre of mass came to rest {100 * (com_z - rim_z):.1f} cm above the rim of {container_id} "
        f"(the rim is at {rim_z:.3f} m): it does not fit inside, standing or lying, with what is already there"
    )
