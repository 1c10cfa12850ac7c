"""Convex collision parts built by construction (no decomposition needed for procedural assets)."""

from __future__ import annotations

import itertools

import numpy as np
import trimesh
from numpy.typing import ArrayLike
from scipy.spatial import ConvexHull

from physcensis.assets.model import CollisionPart, Quat

MAX_HULL_VERTICES = 256


def _fibonacci_directions(count: int) -> np.ndarray:
    i = np.arange(count) + 0.5
    z = 1 - 2 * i / count
    r = np.sqrt(1 - z * z)
    theta = np.pi * (1 + 5**0.5) * i
    return np.stack([r * np.cos(theta), r * np.sin(theta), z], axis=1)


_DIRECTIONS = _fibonacci_directions(MAX_HULL_VERTICES)


def _quat_z_to(axis: ArrayLike) -> Quat:
    """Quaternion [w, x, y, z] turning +z onto `axis`."""
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    z = np.array([0.0, 0.0, 1.0])
    c = float(z.dot(a))
    if c > 1 - 1e-12:
        return (1.0, 0.0, 0.0, 0.0)
    if c < -1 + 1e-12:
        return (0.0, 1.0, 0.0, 0.0)
    v = np.cross(z, a)
    w = 1.0 + c
    q = np.array([w, *v])
    q /= np.linalg.norm(q)
    return tuple(float(x) for x in q)  # type: ignore[return-value]


def quat_about_z(yaw: float) -> Quat:
    return (float(np.cos(yaw / 2)), 0.0, 0.0, float(np.sin(yaw / 2)))


def hull_part(points: ArrayLike | trimesh.Trimesh) -> CollisionPart:
    """One convex mesh part: the hull of the points, thinned to its hull vertices."""
    pts = np.asarray(points.vertices if isinstance(points, trimesh.Trimesh) else points, dtype=float)
    hull = ConvexHull(pts)
    verts = pts[hull.vertices]
    if len(verts) > MAX_HULL_VERTICES:
        # Keep the extreme points along a fixed set of directions: deterministic and shape-preserving.
        dirs = _DIRECTIONS
        picks = np.unique(np.argmax(verts @ dirs.T, axis=0))
        verts = verts[picks]
    return CollisionPart("mesh", vertices=np.ascontiguousarray(verts))


def segment_hulls(
    points: ArrayLike | trimesh.Trimesh, pieces: int = 3, overlap: float = 0.002
) -> tuple[CollisionPart, ...]:
    """Hulls of `pieces` consecutive slabs of a long, bent object along x (each `overlap` into the next). One hull
    of a fork touches the table on its narrow neck, where MuJoCo's default soft contacts let it creep away; a hull
    per slab keeps the head and the handle touching apart and the fork still."""
    pts = np.asarray(points.vertices if isinstance(points, trimesh.Trimesh) else points, dtype=float)
    x = pts[:, 0]
    edges = np.linspace(float(x.min()), float(x.max()), pieces + 1)
    slabs = [pts[(x >= lo - overlap) & (x <= hi + overlap)] for lo, hi in zip(edges, edges[1:], strict=False)]
    return tuple(hull_part(slab) for slab in slabs)


def box_part(extents: ArrayLike, center: ArrayLike = (0.0, 0.0, 0.0), yaw: float = 0.0) -> CollisionPart:
    half = tuple(float(v) / 2 for v in np.asarray(extents, dtype=float))
    pos = tuple(float(v) for v in np.asarray(center, dtype=float))
    return CollisionPart("box", half, pos, quat_about_z(yaw))  # type: ignore[arg-type]


def cylinder_part(
    radius: float, length: float, center: ArrayLike = (0.0, 0.0, 0.0), axis: ArrayLike = (0, 0, 1)
) -> CollisionPart:
    pos = tuple(float(v) for v in np.asarray(center, dtype=float))
    return CollisionPart("cylinder", (radius, length / 2, 0.0), pos, _quat_z_to(axis))  # type: ignore[arg-type]


def capsule_part(radius: float, start: ArrayLike, end: ArrayLike) -> CollisionPart:
    """A capsule whose segment runs from `start` to `end` (the caps extend `radius` beyond)."""
    p0, p1 = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    centre = tuple(float(v) for v in (p0 + p1) / 2)
    half = float(np.linalg.norm(p1 - p0) / 2)
    return CollisionPart("capsule", (radius, half, 0.0), centre, _quat_z_to(p1 - p0))  # type: ignore[arg-type]


def sphere_part(radius: float, center: ArrayLike = (0.0, 0.0, 0.0)) -> CollisionPart:
    pos = tuple(float(v) for v in np.asarray(center, dtype=float))
    return CollisionPart("sphere", (radius, 0.0, 0.0), pos)  # type: ignore[arg-type]


def _ring(r: float, z: float, angles: np.ndarray) -> np.ndarray:
    return np.stack([r * np.cos(angles), r * np.sin(angles), np.full_like(angles, z)], axis=1)


def shell_parts(outer: ArrayLike, inner: ArrayLike, segments: int = 16, base_z: float = 0.0) -> list[CollisionPart]:
    """Collision of a revolved thin-walled vessel: one base disc plus a ring of convex wall pieces per band.

    `outer` and `inner` are matching (r, z) stations from the floor corner up to the
    rim.  The base fills from `base_z` to the inner floor; each wall piece spans one
    band between two stations and one angular segment, so the cavity stays open.
    """
    out = np.asarray(outer, dtype=float)
    inn = np.asarray(inner, dtype=float)
    if out.shape != inn.shape:
        raise ValueError("outer and inner stations must match")
    full = np.linspace(0.0, 2 * np.pi, 2 * segments, endpoint=False)
    base = np.vstack(
        [_ring(out[0, 0], out[0, 1], full), _ring(out[0, 0], base_z, full), _ring(inn[0, 0], inn[0, 1], full)]
    )
    parts = [hull_part(base)]
    edges = np.linspace(0.0, 2 * np.pi, segments + 1)
    for j in range(len(out) - 1):
        for k in range(segments):
            ang = edges[k : k + 2]
            pts = np.vstack(
                [
                    _ring(out[j, 0], out[j, 1], ang),
                    _ring(out[j + 1, 0], out[j + 1, 1], ang),
                    _ring(inn[j, 0], inn[j, 1], ang),
                    _ring(inn[j + 1, 0], inn[j + 1, 1], ang),
                ]
            )
            parts.append(hull_part(pts))
    return parts


def open_box_parts(
    x: float, y: float, z: float, wall: float, floor: float, center: ArrayLike = (0.0, 0.0, 0.0)
) -> list[CollisionPart]:
    """Five slabs of an open-topped box with outer size x, y, z; `center` is the centre of its base."""
    cx, cy, cz = (float(v) for v in np.asarray(center, dtype=float))
    h = z - floor
    zc = cz + floor + h / 2
    return [
        box_part((x, y, floor), (cx, cy, cz + floor / 2)),
        box_part((wall, y, h), (cx + x / 2 - wall / 2, cy, zc)),
        box_part((wall, y, h), (cx - x / 2 + wall / 2, cy, zc)),
        box_part((x - 2 * wall, wall, h), (cx, cy + y / 2 - wall / 2, zc)),
        box_part((x - 2 * wall, wall, h), (cx, cy - y / 2 + wall / 2, zc)),
    ]


def tube_parts(path: ArrayLike, radii: float | ArrayLike, pieces: int, sides: int = 10) -> list[CollisionPart]:
    """A curved tube as `pieces` convex hulls of consecutive sections (banana, handles)."""
    pts = np.asarray(path, dtype=float)
    rad = np.broadcast_to(np.asarray(radii, dtype=float), (len(pts),))
    from physcensis.assets.shapes import tube_frames

    _, normals, binormals = tube_frames(pts)
    phi = np.linspace(0, 2 * np.pi, sides, endpoint=False) + np.pi / sides  # flat facets at top and bottom
    rings = pts[:, None, :] + rad[:, None, None] * (
        np.cos(phi)[None, :, None] * normals[:, None, :] + np.sin(phi)[None, :, None] * binormals[:, None, :]
    )
    cuts = np.linspace(0, len(pts) - 1, pieces + 1).round().astype(int)
    parts = []
    for a, b in itertools.pairwise(cuts):
        chunk = np.vstack([rings[a : b + 1].reshape(-1, 3), pts[a : b + 1]])
        parts.append(hull_part(chunk))
    return parts
