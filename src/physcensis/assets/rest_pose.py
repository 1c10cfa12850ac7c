"""The resting pose of an imported mesh whose library entry does not say which way is up.

A rigid body on a flat floor touches it with a facet of its convex hull; it rests there when
its centre of mass projects inside that facet with a margin, so that a small tilt (the nudge
of the physics tests) brings it back rather than over.  The file's own orientation is kept
when it rests; otherwise the other axis-aligned ups are tried (+y first: the glTF and OBJ
convention), then the hull's largest facets as bases (the one with the widest margin).  A mesh
that rests in none of them (a ball, a figure that tips) is reported as `rests=False`: the import
warns and flags it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError
from shapely.geometry import Point, Polygon

from physcensis.assets.model import CollisionPart

FILE_UP = "+z"
AXIS_UPS = ("+z", "+y", "-y", "-z", "+x", "-x")  # the file's orientation first, then glTF/OBJ's +y
GLTF_UPS = ("+y", "+z", "-y", "-z", "+x", "-x")  # glTF files are +y up by their specification
CONVENTIONS = ("+z", "+y")  # the ups files are written in
BASE_TOLERANCE = 0.002  # of the largest side: how far above the lowest point a vertex still touches the floor
MIN_TIP_DEGREES = 6.0  # the tilt that must not topple a resting body (the physics tests nudge it by 2 degrees)
MIN_PATCH_FRACTION = 0.05  # the base patch's narrowest width over the body's footprint: a patch, not a point
MAX_FACETS = 64  # the largest hull facets tried as bases once no axis-aligned up rests
FLATTEN_STEPS = (0.005, 0.01, 0.02, 0.04, 0.06)  # of the height: how deep a body that rests nowhere is pressed flat


@dataclass(frozen=True)
class Pose:
    """A rotation (3x3, applied to the file's coordinates) and how it was chosen."""

    rotation: np.ndarray
    up: str  # "+y", ..., or "stable pose" for a hull facet as the base
    rests: bool
    margin: float  # metres the centre of mass lies inside the base patch (negative: outside)
    also: tuple[str, ...] = ()  # other axis-aligned ups it would rest in too (the choice was a guess among them)


def axis_rotation(up: str) -> np.ndarray:
    """The rotation that turns file axis `up` onto +z (a quarter or half turn about x or y)."""
    turns = {
        "+z": (np.eye(3)),
        "-z": _turn((1, 0, 0), np.pi),
        "+y": _turn((1, 0, 0), np.pi / 2),
        "-y": _turn((1, 0, 0), -np.pi / 2),
        "+x": _turn((0, 1, 0), -np.pi / 2),
        "-x": _turn((0, 1, 0), np.pi / 2),
    }
    return turns[up]


def _turn(axis: tuple[float, float, float], angle: float) -> np.ndarray:
    return np.asarray(trimesh.transformations.rotation_matrix(angle, axis)[:3, :3])


def base_patch(points: np.ndarray) -> Polygon | None:
    """The convex patch (xy) of the points that touch the floor, None when they touch it at a point or a line."""
    low = float(points[:, 2].min())
    tolerance = BASE_TOLERANCE * float(np.ptp(points, axis=0).max())
    touching = points[points[:, 2] <= low + tolerance][:, :2]
    if len(touching) < 3:
        return None
    try:
        hull = ConvexHull(touching)
    except (QhullError, ValueError):  # collinear: an edge, no area
        return None
    return Polygon(touching[hull.vertices])


def rest_margin(points: np.ndarray, com: np.ndarray) -> float:
    """How far (m) the centre of mass lies inside the base patch beyond what a small tilt asks; < 0: it tips."""
    patch = base_patch(points)
    if patch is None:
        return -np.inf
    footprint = float(min(np.ptp(points[:, :2], axis=0)))
    if _narrowest_width(patch) < MIN_PATCH_FRACTION * footprint:
        return -np.inf
    inside = patch.exterior.distance(Point(com[:2])) * (1.0 if patch.contains(Point(com[:2])) else -1.0)
    height = float(com[2] - points[:, 2].min())
    return float(inside - height * np.tan(np.radians(MIN_TIP_DEGREES)))


def _narrowest_width(patch: Polygon) -> float:
    rectangle = patch.minimum_rotated_rectangle
    corners = np.asarray(rectangle.exterior.coords)[:3]
    if len(corners) < 3:
        return 0.0
    return float(min(np.linalg.norm(corners[1] - corners[0]), np.linalg.norm(corners[2] - corners[1])))


def centre_of_mass(mesh: trimesh.Trimesh) -> np.ndarray:
    """The solid's centre of mass when it is closed, else its surface centroid (as the import computes it)."""
    com = np.asarray(mesh.center_mass if mesh.is_watertight else mesh.centroid, dtype=float)
    return com if np.isfinite(com).all() else np.asarray(mesh.centroid, dtype=float)


def choose_pose(mesh: trimesh.Trimesh, order: tuple[str, ...] = AXIS_UPS) -> Pose:
    """The pose an imported mesh rests in: the first axis-aligned up of `order` it rests in (the file's own first),
    or the hull facet it rests on best."""
    hull = np.asarray(mesh.convex_hull.vertices, dtype=float)
    com = centre_of_mass(mesh)
    tried = []
    for up in order:
        rotation = axis_rotation(up)
        margin = rest_margin(hull @ rotation.T, rotation @ com)
        tried.append(Pose(rotation, up, margin > 0, margin))
    resting = [pose for pose in tried if pose.rests]
    if resting:
        # the other common convention (+z or +y up) when the mesh rests that way too: the choice was a guess
        others = tuple(pose.up for pose in resting[1:] if pose.up in CONVENTIONS and resting[0].up in CONVENTIONS)
        return Pose(resting[0].rotation, resting[0].up, True, resting[0].margin, others)
    facets = [pose for pose in _facet_poses(mesh.convex_hull, hull, com) if pose.rests]
    if facets:
        return max(facets, key=lambda pose: pose.margin)
    return max(tried, key=lambda pose: pose.margin)


def _facet_poses(convex: trimesh.Trimesh, hull: np.ndarray, com: np.ndarray) -> list[Pose]:
    """A pose for each of the largest hull facets (coplanar faces together) turned face down onto the floor.

    Written instead of trimesh's `compute_stable_poses`, which can run without end on degenerate hulls: this is
    at most MAX_FACETS margin tests."""
    normals = np.asarray(convex.face_normals, dtype=float)
    areas = np.asarray(convex.area_faces, dtype=float)
    grouped = {int(i) for facet in convex.facets for i in facet}
    groups = [list(f) for f in convex.facets] + [[i] for i in range(len(normals)) if i not in grouped]
    groups.sort(key=lambda g: -float(areas[g].sum()))
    poses = []
    for group in groups[:MAX_FACETS]:
        normal = normals[group].T @ areas[group]
        if not np.linalg.norm(normal) > 0:
            continue
        rotation = np.asarray(trimesh.geometry.align_vectors(normal, [0.0, 0.0, -1.0]))[:3, :3]
        margin = rest_margin(hull @ rotation.T, rotation @ com)
        poses.append(Pose(rotation, "stable pose", margin > 0, margin))
    return poses


def pose_of(mesh: trimesh.Trimesh, up: str) -> Pose:
    """The pose a mesh already turned by the library's `up` is in, and whether it rests that way."""
    hull = np.asarray(mesh.convex_hull.vertices, dtype=float)
    margin = rest_margin(hull, centre_of_mass(mesh))
    return Pose(np.eye(3), up, margin > 0, margin)


def flattened_base(
    collision: tuple[CollisionPart, ...], com: np.ndarray, height: float
) -> tuple[tuple[CollisionPart, ...], float]:
    """The collision pressed flat where it lies, as the built-in eggs and paper balls are, so that it does not roll:
    cut at the shallowest depth (at most MAX_FLATTEN of the height) that gives a resting patch, and lowered by it
    so its base stays at z = 0. Returns the parts and the depth (m)."""
    points = np.vstack([p.vertices for p in collision if p.vertices is not None])
    depth = 0.0
    for fraction in FLATTEN_STEPS:
        depth = fraction * height
        pressed = np.column_stack([points[:, :2], np.maximum(points[:, 2], depth)])
        if rest_margin(pressed, np.asarray(com, dtype=float)) > 0:
            break
    return tuple(_pressed(part, depth) for part in collision), depth


def _pressed(part: CollisionPart, depth: float) -> CollisionPart:
    if part.vertices is None or part.vertices[:, 2].min() >= depth:
        return part.translated(np.array([0.0, 0.0, -depth]))
    vertices = np.column_stack([part.vertices[:, :2], np.maximum(part.vertices[:, 2], depth) - depth])
    return CollisionPart("mesh", vertices=vertices)
