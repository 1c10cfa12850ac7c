"""An object's collision parts as convex pieces (what MuJoCo collides): sampling their surface, casting rays through
their union, and telling which points lie inside.

MuJoCo collides a mesh geom as the convex hull of its vertices, so every collision part is one convex piece here,
described by its hull's vertices, triangles and outward face planes (n . x + d <= 0 inside).
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError

from physcensis.errors import PhyscensisError

_PRIMITIVE_SECTIONS = 24  # sides of the polygon that stands for a cylinder's or capsule's circle


class ConvexGeometryError(PhyscensisError):
    """An object has no collision part this module can describe."""


@dataclass(frozen=True)
class ConvexPiece:
    vertices: np.ndarray  # (V, 3), in the frame the piece was built in
    triangles: np.ndarray  # (F, 3) vertex indices of the hull's triangles, counter-clockwise seen from outside
    planes: np.ndarray  # (F, 4): outward unit normal and offset

    @classmethod
    def hull_of(cls, points: np.ndarray) -> ConvexPiece:
        hull = ConvexHull(np.asarray(points, dtype=float))
        planes = hull.equations.copy()
        triangles = hull.simplices.copy()
        a, b, c = (hull.points[triangles[:, i]] for i in range(3))
        flipped = np.einsum("ij,ij->i", np.cross(b - a, c - a), planes[:, :3]) < 0.0
        triangles[flipped] = triangles[flipped][:, ::-1]
        return cls(hull.points.copy(), triangles, planes)

    def transformed(self, rotation: np.ndarray, translation: np.ndarray) -> ConvexPiece:
        normals = self.planes[:, :3] @ rotation.T
        vertices = self.vertices @ rotation.T + translation
        offsets = self.planes[:, 3] - normals @ translation
        return ConvexPiece(vertices, self.triangles, np.column_stack([normals, offsets]))

    def signed_distance_bound(self, points: np.ndarray) -> np.ndarray:
        """max over face planes of n . x + d: negative inside (minus the depth to the nearest face), positive
        outside (a lower bound of the distance)."""
        return np.max(points @ self.planes[:, :3].T + self.planes[:, 3], axis=1)

    def face_areas(self) -> np.ndarray:
        a, b, c = (self.vertices[self.triangles[:, i]] for i in range(3))
        return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)


def _primitive_points(geom_type: int, size: np.ndarray) -> np.ndarray:
    if geom_type == mujoco.mjtGeom.mjGEOM_BOX:
        return trimesh.creation.box(extents=2.0 * size[:3]).vertices
    if geom_type == mujoco.mjtGeom.mjGEOM_SPHERE:
        return trimesh.creation.icosphere(subdivisions=2, radius=size[0]).vertices
    if geom_type == mujoco.mjtGeom.mjGEOM_ELLIPSOID:
        return trimesh.creation.icosphere(subdivisions=2, radius=1.0).vertices * size[:3]
    if geom_type == mujoco.mjtGeom.mjGEOM_CYLINDER:
        return trimesh.creation.cylinder(radius=size[0], height=2.0 * size[1], sections=_PRIMITIVE_SECTIONS).vertices
    if geom_type == mujoco.mjtGeom.mjGEOM_CAPSULE:
        return trimesh.creation.capsule(height=2.0 * size[1], radius=size[0], count=[12, 12]).vertices
    raise ConvexGeometryError(f"collision geom type {mujoco.mjtGeom(geom_type).name} has no convex description")


def geom_points(model: mujoco.MjModel, geom: int) -> np.ndarray:
    """The points whose hull is the geom's collision shape, in the geom's own frame."""
    if model.geom_type[geom] == mujoco.mjtGeom.mjGEOM_MESH:
        mesh = int(model.geom_dataid[geom])
        start = int(model.mesh_vertadr[mesh])
        return model.mesh_vert[start : start + int(model.mesh_vertnum[mesh])].astype(float)
    return np.asarray(_primitive_points(int(model.geom_type[geom]), model.geom_size[geom]), dtype=float)


def collision_geoms(model: mujoco.MjModel, body: int) -> list[int]:
    """The body's geoms that take part in contacts."""
    return [
        g
        for g in range(model.ngeom)
        if model.geom_bodyid[g] == body and (model.geom_contype[g] or model.geom_conaffinity[g])
    ]


def geom_rotation(quat: np.ndarray) -> np.ndarray:
    matrix = np.zeros(9)
    mujoco.mju_quat2Mat(matrix, np.asarray(quat, dtype=float))
    return matrix.reshape(3, 3)


def body_pieces(model: mujoco.MjModel, body: int) -> list[ConvexPiece]:
    """The body's collision parts as convex pieces in the body's frame."""
    pieces = []
    for geom in collision_geoms(model, body):
        if model.geom_type[geom] == mujoco.mjtGeom.mjGEOM_PLANE:
            continue
        try:
            local = ConvexPiece.hull_of(geom_points(model, geom))
        except QhullError:
            continue  # a flat or degenerate part has no volume to grasp
        pieces.append(local.transformed(geom_rotation(model.geom_quat[geom]), model.geom_pos[geom]))
    if not pieces:
        raise ConvexGeometryError(f"body {model.body(body).name!r} has no collision part with a volume")
    return pieces


def inside_any(pieces: list[ConvexPiece], points: np.ndarray, depth: float = 0.0) -> np.ndarray:
    """Which points lie deeper than `depth` inside at least one piece."""
    inside = np.zeros(len(points), dtype=bool)
    for piece in pieces:
        inside |= piece.signed_distance_bound(points) < -depth
    return inside


def sample_surface(pieces: list[ConvexPiece], count: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Points uniformly on the surface of the union (points buried inside another piece are dropped) and their
    outward normals."""
    areas = np.concatenate([piece.face_areas() for piece in pieces])
    owners = np.concatenate([np.full(len(piece.triangles), k) for k, piece in enumerate(pieces)])
    faces = np.concatenate([np.arange(len(piece.triangles)) for piece in pieces])
    chosen = rng.choice(len(areas), size=count, p=areas / areas.sum())
    u, v = rng.random(count), rng.random(count)
    fold = u + v > 1.0
    u[fold], v[fold] = 1.0 - u[fold], 1.0 - v[fold]
    points = np.empty((count, 3))
    normals = np.empty((count, 3))
    for k, piece in enumerate(pieces):
        mine = owners[chosen] == k
        tri = piece.triangles[faces[chosen[mine]]]
        a, b, c = (piece.vertices[tri[:, i]] for i in range(3))
        points[mine] = a + u[mine, None] * (b - a) + v[mine, None] * (c - a)
        normals[mine] = piece.planes[faces[chosen[mine]], :3]
    on_surface = ~inside_any(pieces, points, depth=1e-4)
    return points[on_surface], normals[on_surface]


def _piece_intervals(piece: ConvexPiece, origins: np.ndarray, directions: np.ndarray) -> tuple[np.ndarray, ...]:
    """Entry and exit parameters of each ray through the piece (entry > exit: missed), and the exit face."""
    along = directions @ piece.planes[:, :3].T  # (N, F)
    level = origins @ piece.planes[:, :3].T + piece.planes[:, 3]
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -level / along
    enter = np.where(along < -1e-12, t, -np.inf).max(axis=1)
    exits = np.where(along > 1e-12, t, np.inf)
    leave_face = exits.argmin(axis=1)
    leave = exits[np.arange(len(origins)), leave_face]
    parallel_outside = np.any((np.abs(along) <= 1e-12) & (level > 0.0), axis=1)
    enter[parallel_outside] = np.inf
    return enter, leave, piece.planes[leave_face, :3]


def exit_through_union(
    pieces: list[ConvexPiece], origins: np.ndarray, directions: np.ndarray, tolerance: float = 1e-4
) -> tuple[np.ndarray, np.ndarray]:
    """Where rays that start on the union's surface and point into it leave it again: the distance along each
    (inf if the ray never entered) and the outward normal there."""
    intervals = [_piece_intervals(piece, origins, directions) for piece in pieces]
    reach = np.zeros(len(origins))
    normal = np.full((len(origins), 3), np.nan)
    entered = np.zeros(len(origins), dtype=bool)
    for _ in range(len(pieces)):
        grew = False
        for enter, leave, exit_normal in intervals:
            extends = (enter <= reach + tolerance) & (leave > reach + tolerance)
            if extends.any():
                reach[extends] = leave[extends]
                normal[extends] = exit_normal[extends]
                entered |= extends
                grew = True
        if not grew:
            break
    reach[~entered] = np.inf
    return reach, normal


def last_exit_through_union(
    pieces: list[ConvexPiece], origins: np.ndarray, directions: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Where rays starting on the union's surface leave it for the last time (across a cup's hollow to the far wall's
    outside): the distance along each (inf if the ray meets nothing ahead) and the outward normal there."""
    last = np.full(len(origins), -np.inf)
    normal = np.full((len(origins), 3), np.nan)
    for enter, leave, exit_normal in (_piece_intervals(piece, origins, directions) for piece in pieces):
        farther = (enter < leave) & (leave > 0.0) & (leave > last)
        last[farther] = leave[farther]
        normal[farther] = exit_normal[farther]
    last[~np.isfinite(last)] = np.inf
    return last, normal
