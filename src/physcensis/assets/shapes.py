"""Watertight visual meshes from a few parametric primitives (plain functions returning trimesh)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import cast

import numpy as np
import trimesh
from numpy.typing import ArrayLike
from shapely.geometry import Polygon
from shapely.geometry import box as shapely_box

SECTIONS = 40  # angular resolution of revolved visual meshes


def _oriented(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """Flip faces of a closed mesh built inside out (negative volume)."""
    if mesh.volume < 0:
        mesh.invert()
    return mesh


def lathe(profile: ArrayLike, sections: int = SECTIONS) -> trimesh.Trimesh:
    """Revolve an (r, z) profile about +z; a profile starting and ending on the axis gives a closed solid."""
    points = np.asarray(profile, dtype=float)
    if points[0, 0] != 0.0 or points[-1, 0] != 0.0:
        raise ValueError("a lathe profile must start and end on the axis (r = 0)")
    keep = np.concatenate([[True], np.linalg.norm(np.diff(points, axis=0), axis=1) > 1e-9])
    mesh = trimesh.creation.revolve(points[keep], sections=sections)
    return _oriented(mesh)


def box(extents: ArrayLike, center: ArrayLike = (0.0, 0.0, 0.0)) -> trimesh.Trimesh:
    mesh = trimesh.creation.box(extents=np.asarray(extents, dtype=float))
    mesh.apply_translation(np.asarray(center, dtype=float))
    return mesh


def rounded_rect(x: float, y: float, radius: float, center: tuple[float, float] = (0.0, 0.0)) -> Polygon:
    """A rectangle x by y with corners rounded to `radius` (xy plane)."""
    radius = min(radius, 0.499 * min(x, y))
    core = shapely_box(-x / 2 + radius, -y / 2 + radius, x / 2 - radius, y / 2 - radius)
    poly = core.buffer(radius, quad_segs=6) if radius > 0 else shapely_box(-x / 2, -y / 2, x / 2, y / 2)
    from shapely import affinity

    return affinity.translate(poly, center[0], center[1])


def extrude(polygon: Polygon, height: float, z0: float = 0.0) -> trimesh.Trimesh:
    """Extrude an xy polygon from z0 up by `height`."""
    mesh = trimesh.creation.extrude_polygon(polygon, height)
    mesh.apply_translation((0.0, 0.0, z0))
    return _oriented(mesh)


def slab(x: float, y: float, z: float, radius: float = 0.0, center: ArrayLike = (0.0, 0.0, 0.0)) -> trimesh.Trimesh:
    """A box whose vertical edges are rounded (cutting boards, phones, trays); `center` is the box centre."""
    cx, cy, cz = (float(v) for v in np.asarray(center, dtype=float))
    if radius <= 0.0:
        return box((x, y, z), center)
    return extrude(rounded_rect(x, y, radius, (cx, cy)), z, cz - z / 2)


def rounded_box(extents: ArrayLike, radius: float, center: ArrayLike = (0.0, 0.0, 0.0)) -> trimesh.Trimesh:
    """A box with every edge rounded: the convex hull of eight corner spheres."""
    ext = np.asarray(extents, dtype=float)
    radius = min(radius, 0.499 * float(ext.min()))
    ball = trimesh.creation.icosphere(subdivisions=2, radius=radius).vertices
    corners = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]) * (ext / 2 - radius)
    points = (corners[:, None, :] + ball[None, :, :]).reshape(-1, 3)
    mesh = trimesh.convex.convex_hull(points)
    mesh.apply_translation(np.asarray(center, dtype=float))
    return mesh


def hull(points: ArrayLike) -> trimesh.Trimesh:
    return trimesh.convex.convex_hull(np.asarray(points, dtype=float))


def cylinder(
    radius: float, height: float, center: ArrayLike = (0.0, 0.0, 0.0), axis: str = "z", sections: int = 32
) -> trimesh.Trimesh:
    mesh = trimesh.creation.cylinder(radius=radius, height=height, sections=sections)
    return _place_axis(mesh, axis, center, sections)


def cone(
    radius_bottom: float,
    radius_top: float,
    height: float,
    center: ArrayLike = (0.0, 0.0, 0.0),
    axis: str = "z",
    sections: int = 32,
) -> trimesh.Trimesh:
    """A frustum centred on `center`, its axis along `axis`, bottom radius at the negative end."""
    if radius_top < 1e-4:
        mesh = lathe([(0, -height / 2), (radius_bottom, -height / 2), (0, height / 2)], sections)
    else:
        mesh = lathe(
            [(0, -height / 2), (radius_bottom, -height / 2), (radius_top, height / 2), (0, height / 2)], sections
        )
    return _place_axis(mesh, axis, center, sections)


def ellipsoid(radii: ArrayLike, center: ArrayLike = (0.0, 0.0, 0.0), subdivisions: int = 3) -> trimesh.Trimesh:
    mesh = trimesh.creation.icosphere(subdivisions=subdivisions, radius=1.0)
    mesh.apply_scale(np.asarray(radii, dtype=float))
    mesh.apply_translation(np.asarray(center, dtype=float))
    return mesh


def sphere(radius: float, center: ArrayLike = (0.0, 0.0, 0.0), subdivisions: int = 3) -> trimesh.Trimesh:
    return ellipsoid((radius, radius, radius), center, subdivisions)


def _place_axis(mesh: trimesh.Trimesh, axis: str, center: ArrayLike, sections: int = 0) -> trimesh.Trimesh:
    """Turn a z-axis solid onto `axis`; lying solids get a flat facet at the bottom so they do not roll."""
    if axis != "z" and sections:
        mesh.apply_transform(trimesh.transformations.rotation_matrix(np.pi / sections, (0, 0, 1)))
    if axis == "x":
        mesh.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, (0, 1, 0)))
    elif axis == "y":
        mesh.apply_transform(trimesh.transformations.rotation_matrix(-np.pi / 2, (1, 0, 0)))
    elif axis != "z":
        raise ValueError(f"axis must be x, y or z, got {axis!r}")
    mesh.apply_translation(np.asarray(center, dtype=float))
    return mesh


def tube_frames(path: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Tangents, normals and binormals along a polyline (parallel transport: no twisting)."""
    tangents = np.gradient(path, axis=0)
    tangents /= np.linalg.norm(tangents, axis=1, keepdims=True)
    seed = np.array([0.0, 0.0, 1.0]) if abs(tangents[0, 2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    normals = np.zeros_like(path)
    normal = seed - seed.dot(tangents[0]) * tangents[0]
    for i, tangent in enumerate(tangents):
        normal = normal - normal.dot(tangent) * tangent
        normal /= np.linalg.norm(normal)
        normals[i] = normal
    return tangents, normals, np.cross(tangents, normals)


def tube(path: ArrayLike, radii: float | ArrayLike, sides: int = 16, squash: float = 1.0) -> trimesh.Trimesh:
    """A closed tube of circular (or, with `squash` < 1, elliptical) section along a polyline.

    Both ends are capped with a fan to the end point, so radii near zero give pointed tips.
    """
    pts = np.asarray(path, dtype=float)
    rad = np.broadcast_to(np.asarray(radii, dtype=float), (len(pts),))
    _, normals, binormals = tube_frames(pts)
    phi = np.linspace(0.0, 2 * np.pi, sides, endpoint=False) + np.pi / sides  # facets, not edges, face up and down
    ring = (
        np.cos(phi)[None, :, None] * normals[:, None, :] + squash * np.sin(phi)[None, :, None] * binormals[:, None, :]
    )
    rings = pts[:, None, :] + rad[:, None, None] * ring
    vertices = np.vstack([rings.reshape(-1, 3), pts[0], pts[-1]])
    n = len(pts)
    faces: list[list[int]] = []
    for i in range(n - 1):
        for j in range(sides):
            a, b = i * sides + j, i * sides + (j + 1) % sides
            c, d = a + sides, b + sides
            faces += [[a, b, d], [a, d, c]]
    start, end = n * sides, n * sides + 1
    for j in range(sides):
        faces.append([start, (j + 1) % sides, j])
        last = (n - 1) * sides
        faces.append([end, last + j, last + (j + 1) % sides])
    return _oriented(trimesh.Trimesh(vertices, np.array(faces), process=False))


def offset_inward(outer: np.ndarray, thickness: float) -> np.ndarray:
    """Offset an (r, z) wall profile (bottom to rim) by `thickness` towards the inside of the vessel."""
    d = np.gradient(outer, axis=0)
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    inward = np.stack([-d[:, 1], d[:, 0]], axis=1)  # left of the upward direction = towards the axis
    return outer + thickness * inward


def concatenate(meshes: Sequence[trimesh.Trimesh]) -> trimesh.Trimesh:
    # trimesh types the result as any geometry; joined meshes are a mesh
    return cast(trimesh.Trimesh, trimesh.util.concatenate(list(meshes)))


def resample_polyline(points: ArrayLike, count: int) -> np.ndarray:
    """`count` points evenly spaced by arc length along a 3-D polyline."""
    pts = np.asarray(points, dtype=float)
    seg = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(seg)]) / seg.sum()
    t = np.linspace(0.0, 1.0, count)
    return np.stack([np.interp(t, s, pts[:, k]) for k in range(pts.shape[1])], axis=1)
