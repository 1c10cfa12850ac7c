"""How full the support is and where its empty regions are, in numbers and in words."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely
from scipy.ndimage import distance_transform_edt, maximum_filter

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.geometry.footprints import rotate
from physcensis.scene import Scene
from physcensis.solver.objects import quaternion_yaw

CELL_M = 0.01
MIN_REGION_M = 0.08  # smaller gaps are not worth reporting


@dataclass(frozen=True)
class EmptyRegion:
    x: float  # centre, metres
    y: float
    size_x: float  # extent of the free box around the centre
    size_y: float

    @property
    def area(self) -> float:
        return self.size_x * self.size_y


def footprints(scene: Scene, catalogue: Catalogue | None = None) -> dict[str, shapely.Polygon]:
    """Top-down footprint of every placed object."""
    catalogue = catalogue or default_catalogue()
    out = {}
    for o in scene.placed:
        hull = catalogue.asset_for(o.asset, o.description).footprint()
        out[o.id] = shapely.Polygon(rotate(hull, np.array([quaternion_yaw(o.quaternion)]))[0] + o.position[:2])
    return out


def coverage(scene: Scene, catalogue: Catalogue | None = None) -> float:
    """Share of the support's top covered by object footprints."""
    hx, hy = scene.support.half_extents
    table = shapely.box(-hx, -hy, hx, hy)
    prints = list(footprints(scene, catalogue).values())
    if not prints:
        return 0.0
    return float(shapely.union_all(prints).intersection(table).area / table.area)


def compactness(scene: Scene, catalogue: Catalogue | None = None) -> float:
    """Covered area over the area of the convex hull of everything: 1 is a tight cluster."""
    prints = list(footprints(scene, catalogue).values())
    if not prints:
        return 0.0
    union = shapely.union_all(prints)
    hull = union.convex_hull
    return float(union.area / hull.area) if hull.area > 0 else 0.0


def crowding_words(covered: float) -> str:
    if covered < 0.2:
        return "sparse"
    if covered < 0.45:
        return "moderately filled"
    if covered < 0.65:
        return "crowded"
    return "packed"


def empty_regions(scene: Scene, catalogue: Catalogue | None = None, limit: int = 3) -> list[EmptyRegion]:
    """The largest free patches of the support top, biggest first."""
    hx, hy = scene.support.half_extents
    nx, ny = max(1, int(2 * hx / CELL_M)), max(1, int(2 * hy / CELL_M))
    xs = -hx + (np.arange(nx) + 0.5) * CELL_M
    ys = -hy + (np.arange(ny) + 0.5) * CELL_M
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    prints = list(footprints(scene, catalogue).values())
    occupied = np.zeros((nx, ny), dtype=bool)
    if prints:
        union = shapely.union_all(prints)
        occupied = shapely.contains_xy(union, gx.ravel(), gy.ravel()).reshape(nx, ny)
    room = distance_transform_edt(np.pad(~occupied, 1))[1:-1, 1:-1]  # the support's edge is a wall
    peaks = (room == maximum_filter(room, size=9)) & (room * CELL_M * 2 >= MIN_REGION_M)
    regions: list[EmptyRegion] = []
    taken = np.zeros_like(occupied)
    for i, j in sorted(zip(*np.nonzero(peaks), strict=True), key=lambda ij: -room[ij]):
        if taken[i, j]:
            continue
        free = ~occupied
        i0, i1, j0, j1 = _grow_box(free, i, j)
        taken[i0:i1, j0:j1] = True
        region = EmptyRegion(
            float((xs[i0] + xs[i1 - 1]) / 2),
            float((ys[j0] + ys[j1 - 1]) / 2),
            float((i1 - i0) * CELL_M),
            float((j1 - j0) * CELL_M),
        )
        if min(region.size_x, region.size_y) >= MIN_REGION_M:
            regions.append(region)
        if len(regions) >= limit:
            break
    return sorted(regions, key=lambda r: -r.area)


def _grow_box(free: np.ndarray, i: int, j: int) -> tuple[int, int, int, int]:
    """Largest free axis-aligned box grown greedily from a free cell."""
    i0, i1, j0, j1 = i, i + 1, j, j + 1
    grew = True
    while grew:
        grew = False
        if i0 > 0 and free[i0 - 1, j0:j1].all():
            i0 -= 1
            grew = True
        if i1 < free.shape[0] and free[i1, j0:j1].all():
            i1 += 1
            grew = True
        if j0 > 0 and free[i0:i1, j0 - 1].all():
            j0 -= 1
            grew = True
        if j1 < free.shape[1] and free[i0:i1, j1].all():
            j1 += 1
            grew = True
    return i0, i1, j0, j1


def where_words(x: float, y: float, half_x: float, half_y: float) -> str:
    """'the back left', 'the front', 'the middle' of a support (front = +x, left = +y)."""
    fb = "front" if x > half_x / 3 else "back" if x < -half_x / 3 else ""
    lr = "left" if y > half_y / 3 else "right" if y < -half_y / 3 else ""
    words = " ".join(w for w in (fb, lr) if w)
    return f"the {words}" if words else "the middle"


def describe_region(region: EmptyRegion, scene: Scene, catalogue: Catalogue | None = None) -> str:
    """e.g. 'an empty region of about 30 x 20 cm at the back left of the table, behind laptop_0'."""
    hx, hy = scene.support.half_extents
    place = where_words(region.x, region.y, hx, hy)
    text = (
        f"an empty region of about {region.size_x * 100:.0f} x {region.size_y * 100:.0f} cm "
        f"(x {region.x - region.size_x / 2:+.2f} to {region.x + region.size_x / 2:+.2f} m, "
        f"y {region.y - region.size_y / 2:+.2f} to {region.y + region.size_y / 2:+.2f} m) "
        f"at {place} of the {scene.support.kind}"
    )
    nearest = _nearest(region, scene)
    if nearest:
        text += f", {nearest}"
    return text


def _nearest(region: EmptyRegion, scene: Scene) -> str:
    best, best_d = None, np.inf
    for o in scene.placed:
        d = float(np.hypot(o.position[0] - region.x, o.position[1] - region.y))
        if d < best_d:
            best, best_d = o, d
    if best is None:
        return ""
    dx, dy = region.x - best.position[0], region.y - best.position[1]
    if abs(dx) >= abs(dy):
        relation = "in front of" if dx > 0 else "behind"
    else:
        relation = "to the left of" if dy > 0 else "to the right of"
    return f"{relation} {best.id}"
