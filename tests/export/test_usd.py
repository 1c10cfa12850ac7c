"""USD export: a UsdPhysics stage with the support, the floor and one rigid body per object."""

from __future__ import annotations

import dataclasses
import os
from pathlib import Path

import numpy as np
import pytest
import trimesh

from physcensis.assets.model import CollisionPart
from physcensis.assets.supports import support_asset
from physcensis.errors import ExportError
from physcensis.export import export_scene
from physcensis.export import usd as usd_export
from physcensis.export.bodies import ExportScene, export_scene_bodies, part_mesh
from physcensis.export.usd import corner_normals, export_usd, usd_name
from physcensis.scene import Scene, Support

pxr = pytest.importorskip("pxr")
from pxr import Gf, Usd, UsdGeom, UsdPhysics, UsdShade  # noqa: E402

QUARTER_X = (np.cos(np.pi / 4), np.sin(np.pi / 4), 0.0, 0.0)  # +z onto -y
QUARTER_Y = (np.cos(np.pi / 4), 0.0, np.sin(np.pi / 4), 0.0)  # +z onto +x


@pytest.fixture(scope="module")
def export(desk_scene: Scene) -> ExportScene:
    return export_scene_bodies(desk_scene)


@pytest.fixture(scope="module")
def stage(export: ExportScene, tmp_path_factory: pytest.TempPathFactory) -> Usd.Stage:
    path = export_usd(export, tmp_path_factory.mktemp("usd") / "desk.usd")
    opened = Usd.Stage.Open(str(path))
    assert opened is not None
    return opened


def rigid_bodies(stage: Usd.Stage) -> dict[str, Usd.Prim]:
    """Prims with RigidBodyAPI, by the object id they record."""
    prims = [p for p in stage.Traverse() if p.HasAPI(UsdPhysics.RigidBodyAPI)]
    return {p.GetAttribute("physcensis:id").Get(): p for p in prims}


def colliders(stage: Usd.Stage, root: str) -> list[Usd.Prim]:
    return [p for p in Usd.PrimRange(stage.GetPrimAtPath(root)) if p.HasAPI(UsdPhysics.CollisionAPI)]


def world_range(prim: Usd.Prim, purpose: str) -> np.ndarray:
    """(2, 3) world-aligned bounds of `prim` counting only geometry of `purpose`."""
    cache = UsdGeom.BBoxCache(Usd.TimeCode.Default(), [purpose], useExtentsHint=False)
    box = cache.ComputeWorldBound(prim).ComputeAlignedRange()
    return np.array([list(box.GetMin()), list(box.GetMax())])


def test_file_format_follows_the_suffix(export: ExportScene, tmp_path: Path) -> None:
    crate = export_usd(export, tmp_path / "scene.usd")
    text = export_usd(export, tmp_path / "scene.usda")
    assert crate.read_bytes()[:8] == b"PXR-USDC"
    assert text.read_text().startswith("#usda 1.0")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.usd", "scene.usda"]
    with pytest.raises(ExportError, match="usda"):
        export_usd(export, tmp_path / "scene.glb")


def test_export_scene_writes_scene_usd(desk_scene: Scene, tmp_path: Path) -> None:
    path = export_scene(desk_scene, tmp_path, ["usd"])["usd"]
    assert path == tmp_path / "scene.usd"
    opened = Usd.Stage.Open(str(path))
    assert sorted(rigid_bodies(opened)) == sorted(o.id for o in desk_scene.placed)


def test_stage_metadata_and_physics_scene(stage: Usd.Stage) -> None:
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z
    assert UsdPhysics.GetStageKilogramsPerUnit(stage) == 1.0
    assert stage.GetDefaultPrim().GetPath() == "/World"
    scene = UsdPhysics.Scene(stage.GetPrimAtPath("/World/PhysicsScene"))
    assert scene
    assert tuple(scene.GetGravityDirectionAttr().Get()) == (0.0, 0.0, -1.0)
    assert scene.GetGravityMagnitudeAttr().Get() == pytest.approx(9.81)


def test_one_rigid_body_per_object_with_its_mass(stage: Usd.Stage, desk_scene: Scene, export: ExportScene) -> None:
    bodies = rigid_bodies(stage)
    assert sorted(bodies) == sorted(o.id for o in desk_scene.placed)
    for body in export.bodies:
        prim = bodies[body.id]
        assert prim.GetPath() == f"/World/Objects/{body.id}"
        mass = UsdPhysics.MassAPI(prim)
        assert mass.GetMassAttr().Get() == pytest.approx(desk_scene.object(body.id).mass, rel=1e-6)
        assert np.allclose(mass.GetCenterOfMassAttr().Get(), body.com, atol=1e-6)
        axes = Gf.Matrix3d(Gf.Rotation(Gf.Quatd(mass.GetPrincipalAxesAttr().Get()))).GetTranspose()
        rot = np.array(axes)  # Gf matrices are row-vector: the transpose has the axes as columns
        inertia = rot @ np.diag(mass.GetDiagonalInertiaAttr().Get()) @ rot.T
        assert np.allclose(inertia, body.inertia, rtol=1e-4, atol=1e-9)


def test_body_world_transform_is_the_scene_pose(stage: Usd.Stage, export: ExportScene) -> None:
    bodies = rigid_bodies(stage)
    for body in export.bodies:
        matrix = UsdGeom.Xformable(bodies[body.id]).ComputeLocalToWorldTransform(Usd.TimeCode.Default())
        assert np.allclose(np.array(matrix).T, body.transform, atol=1e-7)  # Gf rotates via axis-angle


def test_each_body_has_hidden_colliders_with_its_friction(stage: Usd.Stage, export: ExportScene) -> None:
    bodies = rigid_bodies(stage)
    for body in export.bodies:
        prims = colliders(stage, str(bodies[body.id].GetPath()))
        assert len(prims) == len(body.asset.collision)
        for prim, part in zip(prims, body.asset.collision, strict=True):
            assert UsdGeom.Imageable(prim).ComputePurpose() == UsdGeom.Tokens.guide
            if part.kind == "mesh":
                approximation = UsdPhysics.MeshCollisionAPI(prim).GetApproximationAttr().Get()
                assert approximation == UsdPhysics.Tokens.convexHull
            material, _ = UsdShade.MaterialBindingAPI(prim).ComputeBoundMaterial("physics")
            physics = UsdPhysics.MaterialAPI(material.GetPrim())
            assert physics.GetStaticFrictionAttr().Get() == pytest.approx(body.friction, rel=1e-6)
            assert physics.GetDynamicFrictionAttr().Get() == pytest.approx(body.friction, rel=1e-6)
            assert physics.GetRestitutionAttr().Get() == 0.0


def test_support_and_ground_are_static_colliders(stage: Usd.Stage, export: ExportScene) -> None:
    assert export.ground
    support = stage.GetPrimAtPath("/World/Support")
    assert len(colliders(stage, "/World/Support")) == len(export.support.collision)
    assert not any(p.HasAPI(UsdPhysics.RigidBodyAPI) for p in Usd.PrimRange(support))
    assert np.allclose(world_range(support, UsdGeom.Tokens.guide), export.support.visual.bounds, atol=1e-6)
    ground = stage.GetPrimAtPath("/World/Ground")
    assert len(colliders(stage, "/World/Ground")) == 1
    assert not any(p.HasAPI(UsdPhysics.RigidBodyAPI) for p in Usd.PrimRange(ground))
    lo, hi = world_range(ground, UsdGeom.Tokens.guide)
    assert hi[2] == pytest.approx(0.0, abs=1e-9)
    assert hi[0] == pytest.approx(usd_export.GROUND_HALF_EXTENT)


def test_a_floor_support_is_a_slab_under_z_zero(export: ExportScene, tmp_path: Path) -> None:
    floor = dataclasses.replace(export, support=support_asset(Support(kind="floor", size=(2.0, 1.0))), ground=False)
    opened = Usd.Stage.Open(str(export_usd(floor, tmp_path / "floor.usda")))
    assert not opened.GetPrimAtPath("/World/Ground")
    (prim,) = colliders(opened, "/World/Support")
    lo, hi = world_range(prim, UsdGeom.Tokens.guide)
    assert np.allclose(hi, (1.0, 0.5, 0.0), atol=1e-9)
    assert np.allclose(lo, (-1.0, -0.5, -usd_export.GROUND_THICKNESS), atol=1e-9)


def test_visual_bounds_follow_the_pose(stage: Usd.Stage, export: ExportScene) -> None:
    bodies = rigid_bodies(stage)
    for body in export.bodies:
        expected = body.asset.visual.copy().apply_transform(body.transform).bounds
        assert np.allclose(world_range(bodies[body.id], UsdGeom.Tokens.default_), expected, atol=0.002)


def test_primitive_colliders_match_their_meshes(export: ExportScene, tmp_path: Path) -> None:
    """Boxes, cylinders, capsules and spheres keep MuJoCo's sizes, positions and orientations."""
    parts = (
        CollisionPart("box", (0.03, 0.02, 0.01), (0.1, 0.0, 0.05), QUARTER_X),
        CollisionPart("cylinder", (0.02, 0.05, 0.0), (0.0, 0.1, 0.05), QUARTER_Y),
        CollisionPart("capsule", (0.01, 0.04, 0.0), (-0.1, 0.0, 0.05), QUARTER_X),
        CollisionPart("sphere", (0.025, 0.0, 0.0), (0.0, -0.1, 0.05)),
    )
    body = export.bodies[0]
    body = dataclasses.replace(body, asset=dataclasses.replace(body.asset, collision=parts))
    path = export_usd(dataclasses.replace(export, bodies=[body]), tmp_path / "parts.usda")
    opened = Usd.Stage.Open(str(path))  # keep the stage alive: prims do not
    prims = colliders(opened, f"/World/Objects/{body.id}")
    assert [p.GetTypeName() for p in prims] == ["Cube", "Cylinder", "Capsule", "Sphere"]
    for prim, part in zip(prims, parts, strict=True):
        expected = part_mesh(part).apply_transform(body.transform).bounds
        assert np.allclose(world_range(prim, UsdGeom.Tokens.guide), expected, atol=5e-4), part.kind


def test_a_failed_write_leaves_nothing_behind(
    export: ExportScene, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def fail(src: str, dst: str) -> None:
        raise OSError("disk full")

    monkeypatch.setattr(os, "replace", fail)
    with pytest.raises(OSError, match="disk full"):
        export_usd(export, tmp_path / "out" / "scene.usd")
    assert list((tmp_path / "out").iterdir()) == []


def test_missing_pxr_is_a_clear_error(export: ExportScene, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(usd_export, "HAVE_PXR", False)
    with pytest.raises(ExportError, match=r"physcensis\[usd\]"):
        export_usd(export, tmp_path / "scene.usd")
    assert not (tmp_path / "scene.usd").exists()


def test_prim_names_are_valid_and_unique() -> None:
    taken: set[str] = set()
    names = [usd_name(raw, taken) for raw in ("cup_0", "cup-0", "cup_0", "0cup", "")]
    assert names == ["cup_0", "cup_0_1", "cup_0_2", "_0cup", "_"]
    assert all(pxr.Sdf.Path.IsValidIdentifier(n) for n in names)


def test_visual_normals_are_smooth_across_soft_edges_and_hard_across_creases() -> None:
    cylinder = trimesh.creation.cylinder(radius=0.1, height=0.2, sections=32)
    normals = corner_normals(cylinder)
    corners = cylinder.vertices[cylinder.faces].reshape(-1, 3)
    flat = np.repeat(cylinder.face_normals, 3, axis=0)
    side = np.abs(flat[:, 2]) < 0.5
    radial = corners[side] * [1.0, 1.0, 0.0]
    assert np.allclose(normals[side], radial / np.linalg.norm(radial, axis=1, keepdims=True), atol=1e-9)
    assert np.allclose(normals[~side], flat[~side])
