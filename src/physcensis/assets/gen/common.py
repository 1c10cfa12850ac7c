"""Building blocks shared by generators: revolved vessels, handles, spouts, cavities."""

from __future__ import annotations

import numpy as np
import trimesh

from physcensis.assets import collision as col
from physcensis.assets import shapes
from physcensis.assets.model import Cavity, CollisionPart
from physcensis.assets.spec import Geometry


def circle(radius: float, count: int = 32) -> np.ndarray:
    t = np.linspace(0, 2 * np.pi, count, endpoint=False)
    return np.stack([radius * np.cos(t), radius * np.sin(t)], axis=1)


def rectangle(x: float, y: float, center: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    cx, cy = center
    return np.array(
        [[cx - x / 2, cy - y / 2], [cx + x / 2, cy - y / 2], [cx + x / 2, cy + y / 2], [cx - x / 2, cy + y / 2]]
    )


def resample(stations: list[tuple[float, float]] | np.ndarray, count: int) -> np.ndarray:
    """`count` points evenly spaced by arc length along an (r, z) polyline."""
    pts = np.asarray(stations, dtype=float)
    seg = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(seg)]) / seg.sum()
    t = np.linspace(0.0, 1.0, count)
    return np.stack([np.interp(t, s, pts[:, 0]), np.interp(t, s, pts[:, 1])], axis=1)


def rotate_z(points: np.ndarray, yaw: float) -> np.ndarray:
    c, s = np.cos(yaw), np.sin(yaw)
    out = np.array(points, dtype=float)
    x, y = out[..., 0].copy(), out[..., 1].copy()
    out[..., 0] = c * x - s * y
    out[..., 1] = s * x + c * y
    return out


class Vessel:
    """A revolved thin-walled vessel: visual lathe, open collision walls, cavity.

    `outer` runs from the base corner (r, z0) up to the rim; the wall is `wall`
    thick and the floor `floor` thick.  `base` optionally prepends solid profile
    points (foot, stem) below the vessel, from the axis.
    """

    def __init__(
        self,
        outer: np.ndarray,
        wall: float,
        floor: float,
        *,
        stations: int = 4,
        base: list[tuple[float, float]] | None = None,
    ) -> None:
        self.outer = np.asarray(outer, dtype=float)
        self.wall, self.floor = wall, floor
        inner = shapes.offset_inward(self.outer, wall)
        floor_z = self.outer[0, 1] + floor
        inner[:, 1] = np.maximum(inner[:, 1], floor_z)
        inner[-1, 1] = self.outer[-1, 1]
        inner[:, 0] = np.minimum(inner[:, 0], self.outer[:, 0] - 0.5 * wall)
        self.inner = inner
        self.floor_z = floor_z
        self.base = base or [(0.0, float(self.outer[0, 1]))]
        self.stations = stations

    def profile(self) -> np.ndarray:
        pts = [*self.base, *map(tuple, self.outer), *map(tuple, self.inner[::-1]), (0.0, self.floor_z)]
        return np.asarray(pts)

    def mesh(self, sections: int = shapes.SECTIONS) -> trimesh.Trimesh:
        return shapes.lathe(self.profile(), sections)

    def collision(self, segments: int = 16) -> list[CollisionPart]:
        idx = np.unique(np.linspace(0, len(self.outer) - 1, self.stations + 1).round().astype(int))
        return col.shell_parts(self.outer[idx], self.inner[idx], segments, base_z=float(self.outer[0, 1]))

    def cavity(self) -> Cavity:
        rim = float(self.inner[-1, 0])
        return Cavity(circle(rim), self.floor_z, float(self.outer[-1, 1] - self.floor_z))


def loop_handle(
    attach_r: float,
    z_top: float,
    z_bottom: float,
    reach: float,
    thickness: float,
    yaw: float = -np.pi / 2,
    squareness: float = 0.6,
    pieces: int = 3,
) -> tuple[trimesh.Trimesh, list[CollisionPart]]:
    """A D-shaped handle on the side of a vessel; `reach` is how far it sticks out beyond `attach_r`.

    Built on +x and turned by `yaw` (default: the object's right, -y).
    """
    inset = min(0.004, thickness)
    a = reach + inset - thickness
    t = np.linspace(0.0, np.pi, 17)
    zc, b = (z_top + z_bottom) / 2, (z_top - z_bottom) / 2
    radial = (attach_r - inset) + a * np.sign(np.sin(t)) * np.abs(np.sin(t)) ** squareness
    path = np.stack([radial, np.zeros_like(t), zc + b * np.cos(t)], axis=1)
    path = rotate_z(path, yaw)
    mesh = shapes.tube(path, thickness, sides=12)
    return mesh, col.tube_parts(path, thickness, pieces)


def spout(
    start: np.ndarray, end: np.ndarray, lift: float, r_start: float, r_end: float
) -> tuple[trimesh.Trimesh, list[CollisionPart]]:
    """A tapering curved spout from `start` (inside the body) to `end` (the tip), bulging by `lift` up."""
    t = np.linspace(0, 1, 12)[:, None]
    mid = (start + end) / 2 + np.array([0.0, 0.0, lift])
    path = (1 - t) ** 2 * start + 2 * (1 - t) * t * mid + t**2 * end
    radii = r_start + (r_end - r_start) * t[:, 0]
    return shapes.tube(path, radii, sides=14), col.tube_parts(path, radii, 2)


def fit_to_size(geometry: Geometry, size: tuple[float, float, float]) -> Geometry:
    """Scale a geometry whose collision is convex meshes only so its visual bounds equal `size` exactly.

    For generators whose shape is easier to draw than to dimension exactly (bent
    cutlery, tools); the correction is a few per cent per axis.
    """
    meshes = [m for m, _ in geometry.parts]
    lo = np.min([m.bounds[0] for m in meshes], axis=0)
    hi = np.max([m.bounds[1] for m in meshes], axis=0)
    scale = np.asarray(size, dtype=float) / (hi - lo)
    parts = []
    for mesh, color in geometry.parts:
        scaled = mesh.copy()
        scaled.vertices = (scaled.vertices - lo) * scale + lo
        parts.append((scaled, color))
    collision = []
    for p in geometry.collision:
        if p.kind != "mesh" or p.vertices is None:
            raise ValueError("fit_to_size supports convex mesh collision parts only")
        collision.append(CollisionPart("mesh", vertices=(p.vertices - lo) * scale + lo))
    return Geometry(tuple(parts), tuple(collision), geometry.cavity)
