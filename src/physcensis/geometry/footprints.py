"""2-D footprints: convex hulls of assets seen from above, turned, moved and intersected in batches.

A hull is a (K, 2) array of counter-clockwise vertices in the asset frame. Batched
functions take B yaws or poses and return arrays with a leading B axis.
"""

from __future__ import annotations

import numpy as np
import shapely
from numpy.typing import NDArray

Array = NDArray[np.float64]


def rotate(hull: Array, yaw: Array) -> Array:
    """Hull turned by each yaw: (K, 2), (B,) -> (B, K, 2)."""
    c, s = np.cos(yaw)[:, None], np.sin(yaw)[:, None]
    hx, hy = hull[None, :, 0], hull[None, :, 1]
    return np.stack([c * hx - s * hy, s * hx + c * hy], axis=-1)


def pad_hull(hull: Array, size: int) -> Array:
    """Repeat the last vertex so hulls of different lengths stack into one array."""
    if len(hull) >= size:
        return hull[:size]
    return np.vstack([hull, np.repeat(hull[-1:], size - len(hull), axis=0)])


def placed_polygons(hulls: Array, x: Array, y: Array, yaw: Array) -> NDArray[np.object_]:
    """Shapely polygons of N hulls (N, K, 2) at poses (N,) each."""
    c, s = np.cos(yaw)[:, None], np.sin(yaw)[:, None]
    hx, hy = hulls[..., 0], hulls[..., 1]
    coords = np.stack([c * hx - s * hy + x[:, None], s * hx + c * hy + y[:, None]], axis=-1)
    return shapely.polygons(coords)


def overlap_areas(polys_a: NDArray[np.object_], polys_b: NDArray[np.object_]) -> Array:
    """Intersection area of each pair of polygons, elementwise."""
    if len(polys_a) == 0:
        return np.zeros(0)
    return shapely.area(shapely.intersection(polys_a, polys_b))


def hull_area(hull: Array) -> float:
    x, y = hull[:, 0], hull[:, 1]
    return float(0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def placed_hull(hull: Array, x: float, y: float, yaw: float) -> Array:
    """One hull turned by `yaw` and moved to (x, y): (K, 2)."""
    return rotate(hull, np.array([yaw]))[0] + np.array([x, y])


def outline(points: Array) -> Array:
    """The convex hull (K, 2) of xy points, counter-clockwise (a few points in a line give their bounding box)."""
    hull = shapely.convex_hull(shapely.multipoints(points))
    if not isinstance(hull, shapely.Polygon):
        hull = shapely.box(*hull.bounds).buffer(1e-9)
    return np.asarray(hull.exterior.coords)[:-1]


def min_distance(hull: Array, others: list[Array]) -> float:
    """The least distance from one hull to any of `others` (0 where they touch or overlap; inf when none)."""
    if not others:
        return float("inf")
    polygons = np.array([shapely.Polygon(other) for other in others], dtype=object)
    return float(shapely.distance(shapely.Polygon(hull), polygons).min())
