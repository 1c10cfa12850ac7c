"""URDF export: one URDF per object plus `bodies.json`, the list of (urdf, pose, fixed) to load.

URDF has no free joints that every loader honours, so the scene is a list rather
than one world URDF: PyBullet's `loadURDF(path, position, orientation_xyzw,
useFixedBase=fixed)` or Isaac's URDF importer takes each entry as it is.  Every
object link carries its mass, centre of mass, full inertia tensor (load it in
PyBullet with `URDF_USE_INERTIA_FROM_FILE`) and friction (`<contact>`, read by
PyBullet).  Boxes and spheres stay primitives; convex parts, cylinders and
capsules are OBJ meshes shared by every object that uses the same asset.

PyBullet multiplies the frictions of two touching links where MuJoCo, which the scene was made and checked in, takes
the larger: written as they are, a pen (0.34) leaning on its holder's rim (0.5) grips with 0.17 instead of 0.5 and
slides. So `lateral_friction` is the square root of the body's coefficient: the product is then the pair's geometric
mean, between the smaller and the larger, never more than MuJoCo's; the coefficient itself is in `bodies.json`.

PyBullet's URDF loader wraps every convex mesh in a fixed 1 mm collision margin (primitives keep theirs inside),
so a mesh that touches the table exactly would be pushed up 1 mm (2 mm for the second layer of a stack ...). The
convex meshes are therefore written inset by that margin, and the surface PyBullet collides is the scene's own.
A part thinner than 2 mm (a paper cup's wall) is inset to a 0.02 mm core: it collides 2.02 mm thick, about the
least PyBullet's margin allows. A URDF `<cylinder>` is no exception: the loader turns it into a 32-point convex
hull with the same margin (a can 1 mm wider and 2 mm taller), so cylinders are written as inset meshes too. Boxes
and spheres keep the margin inside their own size.

Bullet recomputes a resting contact's friction point every step, and a pile of heavy boxes creeps on that (five
0.9 kg books: 0.3 mm a second, 2.4 mm over 4 s). A link's `<friction_anchor/>` keeps the point where it was while
the contact lasts, and the stack stands still. Anchored contacts throw thin things (pens, chopsticks, a knife) off
what they lie on, and Bullet anchors a contact when either body asks; so the anchor is written for an object at least
FRICTION_ANCHOR_MIN_M thick in its thinnest direction that no thinner object touches (bounds within
ANCHOR_CLEARANCE_M), and never for the support.
"""

from __future__ import annotations

import json
import math
import xml.etree.ElementTree as ET
from collections.abc import Callable, Iterable, Sequence
from functools import partial
from pathlib import Path

import numpy as np
import trimesh
from scipy.optimize import linprog
from scipy.spatial import HalfspaceIntersection, QhullError

from physcensis.assets.model import RGBA, Asset, CollisionPart
from physcensis.export.bodies import (
    GRAVITY_M_S2,
    GROUND_FRICTION,
    GROUND_HALF_EXTENT,
    GROUND_RGBA,
    GROUND_THICKNESS,
    ExportBody,
    ExportScene,
    KeptByContent,
    part_mesh,
)
from physcensis.fileio import atomic_directory
from physcensis.physics.mujoco_assets import ROLLING_FRICTION, TORSIONAL_FRICTION

URDF_SCENE_FORMAT = "physcensis.urdf_scene/1"
MESH_DIR = "meshes"
INDEX = "bodies.json"  # not scene.json: tools that look for scene files must not take this one
FRICTION_ANCHOR_MIN_M = 0.015  # thinner objects (pens, chopsticks, cutlery) keep Bullet's own friction points
ANCHOR_CLEARANCE_M = 0.003  # ... and so does whatever they might touch
BULLET_URDF_MARGIN_M = 0.001  # the collision margin PyBullet's URDF loader puts around every convex mesh
_THIN_CORE_M = 0.00002  # what is left of a part thinner than twice the margin (Qhull and Bullet need a body)
_PRIMITIVES = ("box", "sphere")  # shapes PyBullet keeps exact; cylinders become margin-padded hulls


def export_urdf(export: ExportScene, out_dir: str | Path) -> Path:
    """Write `out_dir/` with `bodies.json`, `<id>.urdf` per object, `support.urdf`, `ground.urdf` and `meshes/`."""
    out_dir = Path(out_dir)
    with atomic_directory(out_dir) as staging:
        (staging / MESH_DIR).mkdir()
        meshes = _MeshWriter(staging / MESH_DIR)
        entries = []
        support_friction = export.support_friction
        support = _robot("support", export.support, meshes, friction=support_friction, inertial=None, anchor=False)
        _write_xml(staging / "support.urdf", support)
        origin, upright = np.zeros(3), np.array([1.0, 0, 0, 0])
        entries.append(_entry("support", "support.urdf", origin, upright, fixed=True, friction=support_friction))
        if export.ground:
            _write_xml(staging / "ground.urdf", _ground())
            entries.append(_entry("ground", "ground.urdf", origin, upright, fixed=True, friction=GROUND_FRICTION))
        anchored = anchored_bodies(export.bodies)
        for body in export.bodies:
            robot = _robot(
                body.id, body.asset, meshes, friction=body.friction, inertial=body, anchor=body.id in anchored
            )
            _write_xml(staging / f"{body.id}.urdf", robot)
            entries.append(
                _entry(body.id, f"{body.id}.urdf", body.position, body.quaternion, fixed=False, friction=body.friction)
            )
        index = {
            "format": URDF_SCENE_FORMAT,
            "units": "metres, kilograms",
            "up": "z",
            "gravity": [0.0, 0.0, -GRAVITY_M_S2],
            "bodies": entries,
        }
        (staging / INDEX).write_text(json.dumps(index, indent=2) + "\n")
    return out_dir / INDEX


def _entry(
    body_id: str, urdf: str, position: np.ndarray, quaternion: np.ndarray, *, fixed: bool, friction: float
) -> dict:
    w, x, y, z = (float(v) for v in quaternion)
    return {
        "id": body_id,
        "urdf": urdf,
        "position": [float(v) for v in position],
        "quaternion_wxyz": [w, x, y, z],
        "quaternion_xyzw": [x, y, z, w],
        "fixed": fixed,
        "friction": float(friction),
    }


def bullet_lateral_friction(friction: float) -> float:
    """What a link's `<lateral_friction>` says for a body of this friction coefficient: PyBullet multiplies the two
    links' values, so a pair meets with the geometric mean of its coefficients (MuJoCo: the larger of the two)."""
    return math.sqrt(friction)


class _MeshWriter:
    """Writes each OBJ once (assets shared by several objects share their files); a mesh given as a function is
    made only for its first file (an inset hull is a linear program and a hull: four plates need it once)."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder
        self.written: set[str] = set()

    def __call__(self, name: str, mesh: trimesh.Trimesh | Callable[[], trimesh.Trimesh]) -> str:
        file_name = f"{name}.obj"
        if file_name not in self.written:
            made = mesh() if callable(mesh) else mesh
            (self.folder / file_name).write_text(trimesh.exchange.obj.export_obj(made, include_texture=False))
            self.written.add(file_name)
        return f"{MESH_DIR}/{file_name}"


def anchored_bodies(bodies: Sequence[ExportBody]) -> set[str]:
    """The objects whose links ask Bullet to keep their contacts' friction points (see the module's text): thick
    ones that no thin one touches."""
    bounds = {b.id: _world_bounds(b) for b in bodies}
    thin = [b.id for b in bodies if min(b.asset.size) < FRICTION_ANCHOR_MIN_M]
    anchored = set()
    for body in bodies:
        if body.id in thin:
            continue
        low, high = bounds[body.id]
        touched = any(
            np.all(low - ANCHOR_CLEARANCE_M <= bounds[t][1]) and np.all(bounds[t][0] <= high + ANCHOR_CLEARANCE_M)
            for t in thin
        )
        if not touched:
            anchored.add(body.id)
    return anchored


def _world_bounds(body: ExportBody) -> tuple[np.ndarray, np.ndarray]:
    """The axis-aligned bounds of the body's collision parts where it stands."""
    transform = body.transform
    points = np.vstack([part_mesh(part).vertices for part in body.asset.collision])
    world = points @ transform[:3, :3].T + transform[:3, 3]
    return world.min(axis=0), world.max(axis=0)


def _robot(
    name: str,
    asset: Asset,
    meshes: _MeshWriter,
    *,
    friction: float,
    inertial: ExportBody | None,
    anchor: bool,
) -> ET.Element:
    robot = ET.Element("robot", name=name)
    link = ET.SubElement(robot, "link", name=name)
    contact = ET.SubElement(link, "contact")
    ET.SubElement(contact, "lateral_friction", value=_num(bullet_lateral_friction(friction)))
    ET.SubElement(contact, "spinning_friction", value=_num(TORSIONAL_FRICTION))  # MuJoCo's torsional friction
    ET.SubElement(contact, "rolling_friction", value=_num(ROLLING_FRICTION))
    if anchor:
        ET.SubElement(contact, "friction_anchor")
    _inertial(link, inertial)
    for k, (mesh, color) in enumerate(asset.visual_parts()):
        visual = ET.SubElement(link, "visual", name=f"{name}_visual_{k}")
        ET.SubElement(visual, "origin", xyz="0 0 0", rpy="0 0 0")
        geometry = ET.SubElement(visual, "geometry")
        ET.SubElement(geometry, "mesh", filename=meshes(f"{asset.id}_visual_{k}", mesh))
        _material(visual, f"{asset.id}_{k}", color)
    for i, part in enumerate(asset.collision):
        collision = ET.SubElement(link, "collision", name=f"{name}_collision_{i}")
        _collision_geometry(collision, part, partial(meshes, f"{asset.id}_collision_{i}"))
    return robot


def _inertial(link: ET.Element, body: ExportBody | None) -> None:
    """The body's mass properties; static links (support, ground) get mass 0, which loaders read as static."""
    inertial = ET.SubElement(link, "inertial")
    ET.SubElement(inertial, "origin", xyz=_vec(body.com if body else (0, 0, 0)), rpy="0 0 0")
    ET.SubElement(inertial, "mass", value=_num(body.mass if body else 0.0))
    i = body.inertia if body else np.zeros((3, 3))
    ET.SubElement(
        inertial,
        "inertia",
        ixx=_num(i[0, 0]),
        ixy=_num(i[0, 1]),
        ixz=_num(i[0, 2]),
        iyy=_num(i[1, 1]),
        iyz=_num(i[1, 2]),
        izz=_num(i[2, 2]),
    )


def _collision_geometry(
    element: ET.Element, part: CollisionPart, write_mesh: Callable[[Callable[[], trimesh.Trimesh]], str]
) -> None:
    geometry_parent = element
    if part.kind in _PRIMITIVES:
        ET.SubElement(geometry_parent, "origin", xyz=_vec(part.pos), rpy=_vec(_quat_to_rpy(part.quat)))
        geometry = ET.SubElement(geometry_parent, "geometry")
        sx, sy, sz = part.size
        if part.kind == "box":
            ET.SubElement(geometry, "box", size=_vec((2 * sx, 2 * sy, 2 * sz)))
        else:
            ET.SubElement(geometry, "sphere", radius=_num(sx))
        return
    # Convex meshes, cylinders and capsules (not in the URDF standard) go as meshes already in the link frame.
    ET.SubElement(geometry_parent, "origin", xyz="0 0 0", rpy="0 0 0")
    geometry = ET.SubElement(geometry_parent, "geometry")
    ET.SubElement(geometry, "mesh", filename=write_mesh(lambda: _inset_part(part)))


def _inset_part(part: CollisionPart) -> trimesh.Trimesh:
    """The part's inset hull, kept for the process by the part's shape (a dining scene's 115 parts take 1 s)."""
    vertices = b"" if part.vertices is None else np.ascontiguousarray(part.vertices, dtype=float).tobytes()
    shape = repr((part.kind, part.size, part.pos, part.quat)).encode()
    return _INSETS.get((shape, vertices), lambda: inset_hull(part_mesh(part), BULLET_URDF_MARGIN_M))


_INSETS: KeptByContent[trimesh.Trimesh] = KeptByContent(4096)  # inset hulls (a few kilobytes each)


def inset_hull(mesh: trimesh.Trimesh, margin: float) -> trimesh.Trimesh:
    """The convex hull of `mesh` with every face moved `margin` inwards; a part too thin for that (a cup's wall, a
    plate's rim) is inset as far as it goes, down to a core `_THIN_CORE_M` thick, so that PyBullet's margin adds as
    little as it can to it. The hull itself when nothing can be taken off."""
    hull = mesh.convex_hull
    normals = hull.face_normals
    offsets = np.einsum("ij,ij->i", normals, hull.vertices[hull.faces[:, 0]])
    centre, inscribed_radius = _deepest_point(normals, offsets)
    inset = min(margin, inscribed_radius - _THIN_CORE_M / 2)
    if inset <= 1e-6:
        return hull
    try:
        halfspaces = np.hstack([normals, -(offsets - inset)[:, None]])
        corners = HalfspaceIntersection(halfspaces, centre).intersections
        return trimesh.Trimesh(corners).convex_hull
    except (QhullError, ValueError):
        return hull


def _deepest_point(normals: np.ndarray, offsets: np.ndarray) -> tuple[np.ndarray, float]:
    """The centre and radius of the largest ball inside {x : normals @ x <= offsets} (its Chebyshev centre): how far
    the faces can move in before the hull vanishes, and a point that stays inside while they do."""
    cost = np.zeros(4)
    cost[3] = -1.0
    bounds = [(None, None)] * 3 + [(0.0, None)]
    result = linprog(cost, A_ub=np.hstack([normals, np.ones((len(normals), 1))]), b_ub=offsets, bounds=bounds)
    if not result.success:
        return np.zeros(3), 0.0
    return result.x[:3], float(result.x[3])


def _ground() -> ET.Element:
    robot = ET.Element("robot", name="ground")
    link = ET.SubElement(robot, "link", name="ground")
    contact = ET.SubElement(link, "contact")
    ET.SubElement(contact, "lateral_friction", value=_num(bullet_lateral_friction(GROUND_FRICTION)))
    _inertial(link, None)
    size = _vec((2 * GROUND_HALF_EXTENT, 2 * GROUND_HALF_EXTENT, GROUND_THICKNESS))
    for tag in ("visual", "collision"):
        element = ET.SubElement(link, tag, name=f"ground_{tag}")
        ET.SubElement(element, "origin", xyz=_vec((0.0, 0.0, -GROUND_THICKNESS / 2)), rpy="0 0 0")
        ET.SubElement(ET.SubElement(element, "geometry"), "box", size=size)
        if tag == "visual":
            _material(element, "ground", GROUND_RGBA)
    return robot


def _material(visual: ET.Element, name: str, color: RGBA) -> None:
    material = ET.SubElement(visual, "material", name=name)
    ET.SubElement(material, "color", rgba=" ".join(_num(c) for c in color))


def _quat_to_rpy(quat: tuple[float, float, float, float]) -> tuple[float, float, float]:
    """[w, x, y, z] to URDF's fixed-axis roll, pitch, yaw."""
    from scipy.spatial.transform import Rotation

    w, x, y, z = quat
    roll, pitch, yaw = Rotation.from_quat([x, y, z, w]).as_euler("xyz")
    return float(roll), float(pitch), float(yaw)


def _write_xml(path: Path, robot: ET.Element) -> None:
    ET.indent(robot)
    path.write_text('<?xml version="1.0"?>\n' + ET.tostring(robot, encoding="unicode") + "\n")


def _num(value: float) -> str:
    return f"{float(value):.9g}"


def _vec(values: Iterable[float]) -> str:
    return " ".join(_num(v) for v in values)
