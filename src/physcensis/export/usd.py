"""USD export: one stage holding the support, an optional floor slab and every object as a UsdPhysics rigid body.

Layout (metres, kilograms, z up; default prim `/World`)::

    /World/PhysicsScene                 UsdPhysics.Scene, gravity 9.81 m/s^2 along -z
    /World/PhysicsMaterials/<name>      UsdShade.Material + UsdPhysics.MaterialAPI (friction), one per body
    /World/Ground                       static floor slab whose top is z = 0 (only when the export has one)
    /World/Support                      static support: Visual/part_NN meshes, Collision/part_NN colliders
    /World/Objects/<id>                 Xform (translate + orient) with RigidBodyAPI and MassAPI
        Visual/part_NN                  one coloured UsdGeom.Mesh per visual part
        Collision/part_NN               one collider per collision part, purpose `guide`

`pxr` (the `usd-core` package) is optional: it is imported here when present and
`export_usd` raises an `ExportError` saying how to install it when it is not.
"""

from __future__ import annotations

import os
import re
import uuid
from pathlib import Path
from typing import Any

import numpy as np
import trimesh

from physcensis.assets.model import Asset, CollisionPart
from physcensis.errors import ExportError
from physcensis.export.bodies import (
    GRAVITY_M_S2,
    GROUND_FRICTION,
    GROUND_HALF_EXTENT,
    GROUND_RGBA,
    GROUND_THICKNESS,
    ExportBody,
    ExportScene,
    KeptByContent,
    ground_slab,
    part_mesh,
)

try:
    from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics, UsdShade, Vt

    HAVE_PXR = True
except ImportError:  # pragma: no cover - depends on the environment
    HAVE_PXR = False

MISSING_PXR = "USD export needs the optional extra: pip install 'physcensis[usd]'"
FILE_FORMATS = {".usd": "usdc", ".usdc": "usdc", ".usda": "usda"}
CREASE_ANGLE_DEG = 30.0  # visual normals are smoothed across edges flatter than this
_INVALID = re.compile(r"[^A-Za-z0-9_]")


def export_usd(export: ExportScene, path: str | Path) -> Path:
    """Write `export` as one USD file (`.usd`/`.usdc` binary crate, `.usda` text), atomically; returns the path."""
    if not HAVE_PXR:
        raise ExportError(MISSING_PXR)
    path = Path(path)
    file_format = FILE_FORMATS.get(path.suffix.lower())
    if file_format is None:
        raise ExportError(f"USD export writes .usd, .usdc or .usda files, not {path.name!r}")
    stage = build_stage(export)
    path.parent.mkdir(parents=True, exist_ok=True)
    # A fresh name (not mkstemp) so the file gets the usual permissions; the real suffix picks the format.
    tmp_name = str(path.with_name(f".{path.name}.{uuid.uuid4().hex}.tmp{path.suffix.lower()}"))
    try:
        args = {"format": file_format} if path.suffix.lower() == ".usd" else {}
        if not stage.GetRootLayer().Export(tmp_name, args=args):
            raise OSError(f"could not write {path}")
        os.replace(tmp_name, path)
    except BaseException:
        Path(tmp_name).unlink(missing_ok=True)
        raise
    return path


def build_stage(export: ExportScene) -> Usd.Stage:
    """The whole scene as an in-memory stage."""
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdPhysics.SetStageKilogramsPerUnit(stage, 1.0)
    scene = export.scene
    stage.GetRootLayer().documentation = f"physcensis scene, seed {scene.seed}" + (
        f": {scene.prompt}" if scene.prompt else ""
    )
    world = UsdGeom.Xform.Define(stage, "/World").GetPrim()
    stage.SetDefaultPrim(world)
    physics_scene = UsdPhysics.Scene.Define(stage, "/World/PhysicsScene")
    physics_scene.CreateGravityDirectionAttr(Gf.Vec3f(0.0, 0.0, -1.0))
    physics_scene.CreateGravityMagnitudeAttr(GRAVITY_M_S2)
    materials = stage.DefinePrim("/World/PhysicsMaterials", "Scope").GetPath()
    if export.ground:
        _add_ground(stage, materials.AppendChild("Ground"))
    support = UsdGeom.Xform.Define(stage, "/World/Support").GetPrim()
    _tag(support, export.support.id, export.support.description, export.support.id)
    _add_visuals(stage, support.GetPath(), export.support)
    material = _physics_material(stage, materials.AppendChild("Support"), export.support_friction)
    _add_colliders(stage, support.GetPath(), export.support.collision, material)
    objects = UsdGeom.Xform.Define(stage, "/World/Objects").GetPath()
    names: set[str] = set()
    for body in export.bodies:
        name = usd_name(body.id, names)
        material = _physics_material(stage, materials.AppendChild(name), body.friction)
        _add_body(stage, objects.AppendChild(name), body, material)
    return stage


def usd_name(raw: str, taken: set[str] | None = None) -> str:
    """A valid USD prim name for `raw` (letters, digits, '_', not starting with a digit), unique within `taken`."""
    name = _INVALID.sub("_", raw) or "_"
    if name[0].isdigit():
        name = f"_{name}"
    if taken is not None:
        base, k = name, 1
        while name in taken:
            name = f"{base}_{k}"
            k += 1
        taken.add(name)
    return name


def _tag(prim: Usd.Prim, object_id: str, description: str, asset_id: str) -> None:
    """Record where a prim came from, in custom attributes (prim names may have been sanitised)."""
    for key, value in (("id", object_id), ("description", description), ("asset", asset_id)):
        prim.CreateAttribute(f"physcensis:{key}", Sdf.ValueTypeNames.String, custom=True).Set(value)


def _add_body(stage: Usd.Stage, path: Sdf.Path, body: ExportBody, material: UsdShade.Material) -> None:
    """A rigid body: pose, mass properties, visual meshes and colliders."""
    xform = UsdGeom.Xform.Define(stage, path)
    _set_pose(xform, body.position, body.quaternion)
    prim = xform.GetPrim()
    _tag(prim, body.id, body.description, body.asset.id)
    UsdPhysics.RigidBodyAPI.Apply(prim)
    mass_api = UsdPhysics.MassAPI.Apply(prim)
    moments, axes = body.principal_inertia
    mass_api.CreateMassAttr(float(body.mass))
    mass_api.CreateCenterOfMassAttr(_vec3f(body.com))
    mass_api.CreateDiagonalInertiaAttr(_vec3f(moments))
    mass_api.CreatePrincipalAxesAttr(_quatf(axes))
    _add_visuals(stage, path, body.asset)
    _add_colliders(stage, path, body.asset.collision, material)


def _add_ground(stage: Usd.Stage, material_path: Sdf.Path) -> None:
    """The floor under tables, shelves and boxes: a static slab whose top is z = 0."""
    ground = UsdGeom.Xform.Define(stage, "/World/Ground").GetPath()
    half = (GROUND_HALF_EXTENT, GROUND_HALF_EXTENT, GROUND_THICKNESS / 2)
    UsdGeom.Xform.Define(stage, ground.AppendChild("Visual"))
    _visual_mesh(stage, ground.AppendPath("Visual/part_00"), ground_slab(), GROUND_RGBA)
    material = _physics_material(stage, material_path, GROUND_FRICTION)
    part = CollisionPart("box", half, (0.0, 0.0, -GROUND_THICKNESS / 2))
    _add_colliders(stage, ground, (part,), material)


def _add_visuals(stage: Usd.Stage, parent: Sdf.Path, asset: Asset) -> None:
    group = UsdGeom.Xform.Define(stage, parent.AppendChild("Visual")).GetPath()
    for k, (mesh, rgba) in enumerate(asset.visual_parts()):
        _visual_mesh(stage, group.AppendChild(f"part_{k:02d}"), mesh, rgba)


def _visual_mesh(stage: Usd.Stage, path: Sdf.Path, mesh: trimesh.Trimesh, rgba: tuple[float, ...]) -> None:
    """One coloured triangle mesh with crease-aware face-varying normals."""
    usd_mesh = _triangle_mesh(stage, path, mesh)
    usd_mesh.CreateNormalsAttr(Vt.Vec3fArray.FromNumpy(_kept_corner_normals(mesh)))
    usd_mesh.SetNormalsInterpolation(UsdGeom.Tokens.faceVarying)
    usd_mesh.CreateDisplayColorPrimvar(UsdGeom.Tokens.constant).Set(Vt.Vec3fArray([_vec3f(rgba[:3])]))
    usd_mesh.CreateDisplayOpacityPrimvar(UsdGeom.Tokens.constant).Set(Vt.FloatArray([float(rgba[3])]))


def _triangle_mesh(stage: Usd.Stage, path: Sdf.Path, mesh: trimesh.Trimesh) -> UsdGeom.Mesh:
    usd_mesh = UsdGeom.Mesh.Define(stage, path)
    points = np.asarray(mesh.vertices, dtype=np.float32)
    faces = np.asarray(mesh.faces, dtype=np.int32)
    usd_mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(points))
    usd_mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(faces), 3, dtype=np.int32)))
    usd_mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(faces.ravel()))
    usd_mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    usd_mesh.CreateExtentAttr(Vt.Vec3fArray([_vec3f(points.min(axis=0)), _vec3f(points.max(axis=0))]))
    return usd_mesh


def _kept_corner_normals(mesh: trimesh.Trimesh) -> np.ndarray:
    """`corner_normals` as float32, kept for the process by the mesh's contents (a dining scene's take 0.2 s)."""
    vertices = np.ascontiguousarray(mesh.vertices, dtype=float).tobytes()
    faces = np.ascontiguousarray(mesh.faces, dtype=np.int64).tobytes()
    return _NORMALS.get((vertices, faces), lambda: corner_normals(mesh).astype(np.float32))


_NORMALS: KeptByContent[np.ndarray] = KeptByContent(1024)  # visual meshes' normals


def corner_normals(mesh: trimesh.Trimesh, crease_deg: float = CREASE_ANGLE_DEG) -> np.ndarray:
    """(3F, 3) unit normals per face corner: the angle-weighted mean normal of the faces around the corner's
    vertex that lie within `crease_deg` of the corner's own face (so hard edges stay hard)."""
    faces = np.asarray(mesh.faces)
    face_normals = np.asarray(mesh.face_normals, dtype=float)
    corner_angle = np.nan_to_num(np.asarray(mesh.face_angles, dtype=float)).ravel()
    corner_vertex = faces.ravel()
    corner_face = np.repeat(np.arange(len(faces)), 3)
    order = np.argsort(corner_vertex, kind="stable")
    sorted_vertex = corner_vertex[order]
    starts = np.searchsorted(sorted_vertex, sorted_vertex, side="left")
    ends = np.searchsorted(sorted_vertex, sorted_vertex, side="right")
    sizes = ends - starts
    # Every (corner, corner sharing its vertex) pair, in sorted-corner indices.
    mine = np.repeat(np.arange(len(order)), sizes)
    offsets = np.arange(len(mine)) - np.repeat(np.cumsum(sizes) - sizes, sizes)
    theirs = np.repeat(starts, sizes) + offsets
    f_mine, f_theirs = corner_face[order[mine]], corner_face[order[theirs]]
    smooth = np.einsum("ij,ij->i", face_normals[f_mine], face_normals[f_theirs]) >= np.cos(np.radians(crease_deg))
    sums = np.zeros((len(order), 3))
    weights = corner_angle[order[theirs[smooth]]][:, None]
    np.add.at(sums, mine[smooth], weights * face_normals[f_theirs[smooth]])
    normals = np.empty_like(sums)
    normals[order] = sums
    length = np.linalg.norm(normals, axis=1)
    flat = length < 1e-12
    normals[flat] = face_normals[corner_face[flat]]
    normals[~flat] /= length[~flat, None]
    return normals


def _add_colliders(
    stage: Usd.Stage, parent: Sdf.Path, parts: tuple[CollisionPart, ...], material: UsdShade.Material
) -> None:
    """One collider per part under `parent`/Collision, hidden from rendering and bound to `material`."""
    group = UsdGeom.Xform.Define(stage, parent.AppendChild("Collision")).GetPath()
    for k, part in enumerate(parts):
        gprim = _collider_geometry(stage, group.AppendChild(f"part_{k:02d}"), part)
        gprim.CreatePurposeAttr(UsdGeom.Tokens.guide)
        prim = gprim.GetPrim()
        UsdPhysics.CollisionAPI.Apply(prim)
        if part.kind == "mesh":
            UsdPhysics.MeshCollisionAPI.Apply(prim).CreateApproximationAttr(UsdPhysics.Tokens.convexHull)
        UsdShade.MaterialBindingAPI.Apply(prim).Bind(material, UsdShade.Tokens.weakerThanDescendants, "physics")


def _collider_geometry(stage: Usd.Stage, path: Sdf.Path, part: CollisionPart) -> UsdGeom.Gprim:
    """The UsdGeom prim of one collision part (MuJoCo size conventions, part pose as xform ops)."""
    sx, sy, sz = (float(v) for v in part.size)
    if part.kind == "mesh":
        return _triangle_mesh(stage, path, part_mesh(part))
    pos, quat = np.asarray(part.pos, dtype=float), np.asarray(part.quat, dtype=float)
    if part.kind in ("box", "plane"):
        if part.kind == "plane":  # a thin slab whose top is the plane, as in `part_mesh`
            sz = GROUND_THICKNESS / 2
            pos = pos + _rotate(quat, np.array([0.0, 0.0, -sz]))
        gprim: Any = UsdGeom.Cube.Define(stage, path)
        gprim.CreateSizeAttr(2.0)
        _set_pose(gprim, pos, quat).AddScaleOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(sx, sy, sz))
    elif part.kind == "sphere":
        gprim = UsdGeom.Sphere.Define(stage, path)
        gprim.CreateRadiusAttr(sx)
        _set_pose(gprim, pos, quat)
    else:  # cylinder or capsule: radius and half length along the local z
        gprim = (UsdGeom.Cylinder if part.kind == "cylinder" else UsdGeom.Capsule).Define(stage, path)
        gprim.CreateRadiusAttr(sx)
        gprim.CreateHeightAttr(2.0 * sy)
        gprim.CreateAxisAttr(UsdGeom.Tokens.z)
        _set_pose(gprim, pos, quat)
    extent = UsdGeom.Boundable.ComputeExtentFromPlugins(gprim, Usd.TimeCode.Default())
    gprim.CreateExtentAttr(extent)
    return gprim


def _set_pose(xformable: UsdGeom.Xformable, position: np.ndarray, quaternion: np.ndarray) -> UsdGeom.Xformable:
    """Translate and orient ops (double precision) from a position and a [w, x, y, z] quaternion."""
    q = np.asarray(quaternion, dtype=float)
    q = q / np.linalg.norm(q)
    xformable.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*np.asarray(position, dtype=float).tolist()))
    xformable.AddOrientOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Quatd(float(q[0]), Gf.Vec3d(*q[1:].tolist())))
    return xformable


def _vec3f(values: Any) -> Gf.Vec3f:
    """Gf.Vec3f of three numbers (Gf does not take numpy scalars)."""
    return Gf.Vec3f(*np.asarray(values, dtype=float).tolist())


def _quatf(quaternion: np.ndarray) -> Gf.Quatf:
    """Gf.Quatf (real first, then the imaginary vector) of a [w, x, y, z] quaternion, normalised."""
    q = np.asarray(quaternion, dtype=float)
    q = q / np.linalg.norm(q)
    return Gf.Quatf(float(q[0]), Gf.Vec3f(*q[1:].tolist()))


def _rotate(quaternion: np.ndarray, vector: np.ndarray) -> np.ndarray:
    w, x, y, z = np.asarray(quaternion, dtype=float) / np.linalg.norm(quaternion)
    u = np.array([x, y, z])
    return vector + 2.0 * np.cross(u, np.cross(u, vector) + w * vector)


def _physics_material(stage: Usd.Stage, path: Sdf.Path, friction: float) -> UsdShade.Material:
    """A physics-only material: static and dynamic friction `friction`, no restitution.

    MuJoCo combines the frictions of two touching geoms by taking the larger one; the
    PhysX combine mode is authored to match (other engines ignore the attribute).
    """
    material = UsdShade.Material.Define(stage, path)
    prim = material.GetPrim()
    api = UsdPhysics.MaterialAPI.Apply(prim)
    api.CreateStaticFrictionAttr(float(friction))
    api.CreateDynamicFrictionAttr(float(friction))
    api.CreateRestitutionAttr(0.0)
    prim.AddAppliedSchema("PhysxMaterialAPI")
    combine = prim.CreateAttribute(
        "physxMaterial:frictionCombineMode", Sdf.ValueTypeNames.Token, custom=False, variability=Sdf.VariabilityUniform
    )
    combine.Set("max")
    return material
