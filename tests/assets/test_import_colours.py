"""Colours of imported meshes: vertex colours, MTL diffuse colours and base-colour textures become coloured parts
that survive into the render and the GLB export."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import trimesh
import yaml
from PIL import Image

from physcensis.assets import library
from physcensis.assets.library import load_library
from physcensis.assets.model import Asset


def _hull_stand_in(mesh: trimesh.Trimesh, *args: Any, **kwargs: Any) -> list[np.ndarray]:
    return [np.asarray(mesh.convex_hull.vertices)]


@pytest.fixture(autouse=True)
def _no_coacd(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(library, "convex_decomposition", _hull_stand_in)


def _import_one(folder: Path, file: str, **entry: Any) -> Asset:
    (folder / "library.yaml").write_text(yaml.safe_dump({"assets": [{"file": file, "id": "thing", **entry}]}))
    result = load_library(folder)
    assert result.errors == []
    return result.assets[0]


def _share(asset: Asset, rgba: tuple[float, ...], tol: float = 0.03) -> float:
    """Share of the visual faces whose part has colour `rgba`."""
    faces = sum(n for n, c in zip(asset.part_faces, asset.rgba, strict=True) if np.allclose(c, rgba, atol=tol))
    return faces / len(asset.visual.faces)


def test_ply_vertex_colour_halves_become_two_parts(tmp_path: Path) -> None:
    halves = []
    for x, colour in ((-0.025, (200, 30, 30, 255)), (0.025, (30, 30, 200, 255))):
        half = trimesh.creation.box((0.05, 0.1, 0.1), trimesh.transformations.translation_matrix((x, 0, 0.05)))
        half.visual = trimesh.visual.ColorVisuals(half, vertex_colors=np.tile(colour, (len(half.vertices), 1)))
        halves.append(half)
    trimesh.util.concatenate(halves).export(tmp_path / "box.ply")
    asset = _import_one(tmp_path, "box.ply")
    expected = [(30 / 255, 30 / 255, 200 / 255, 1.0), (200 / 255, 30 / 255, 30 / 255, 1.0)]
    assert np.allclose(sorted(asset.rgba), expected, atol=1e-3)
    for mesh, colour in asset.visual_parts():  # each part is its half
        assert (mesh.vertices[:, 0].mean() < 0) == (colour[0] > 0.5)


def test_obj_mtl_diffuse_colour_is_kept(tmp_path: Path) -> None:
    box = trimesh.creation.box((0.1, 0.08, 0.06))
    lines = ["mtllib box.mtl", "usemtl green"]
    lines += [f"v {x} {y} {z}" for x, y, z in box.vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in box.faces]
    (tmp_path / "box.obj").write_text("\n".join(lines) + "\n")
    (tmp_path / "box.mtl").write_text("newmtl green\nKd 0.1 0.6 0.2\n")
    asset = _import_one(tmp_path, "box.obj")
    assert np.allclose(asset.rgba, [(0.1, 0.6, 0.2, 1.0)], atol=0.01)


def test_an_explicit_rgba_wins_over_the_file(tmp_path: Path) -> None:
    box = trimesh.creation.box((0.1, 0.08, 0.06))
    box.visual = trimesh.visual.ColorVisuals(box, face_colors=[255, 0, 0, 255])
    box.export(tmp_path / "box.ply")
    asset = _import_one(tmp_path, "box.ply", rgba=[0.0, 0.0, 1.0, 1.0])
    assert asset.rgba == ((0.0, 0.0, 1.0, 1.0),)


def _textured_glb(path: Path, texture: Image.Image) -> None:
    box = trimesh.creation.box((0.1, 0.1, 0.1))
    uv = np.where(box.vertices[:, :2] < 0, 0.25, 0.75)  # left half of the texture for x < 0
    material = trimesh.visual.material.PBRMaterial(baseColorTexture=texture, baseColorFactor=[255, 255, 255, 255])
    box.visual = trimesh.visual.TextureVisuals(uv=uv, material=material)
    box.export(path)


def test_glb_base_colour_texture_is_sampled(tmp_path: Path) -> None:
    image = Image.new("RGB", (8, 8), (240, 200, 20))
    image.paste((20, 40, 220), (0, 0, 4, 8))  # left half blue
    _textured_glb(tmp_path / "box.glb", image)
    asset = _import_one(tmp_path, "box.glb")
    yellow, blue = (240 / 255, 200 / 255, 20 / 255, 1.0), (20 / 255, 40 / 255, 220 / 255, 1.0)
    assert _share(asset, yellow) > 0.2 and _share(asset, blue) > 0.2
    assert _share(asset, yellow) + _share(asset, blue) == pytest.approx(1.0)


def test_an_oversized_texture_falls_back_to_the_base_colour(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from physcensis.assets import colours

    monkeypatch.setattr(colours, "MAX_TEXTURE_SIDE", 4)
    _textured_glb(tmp_path / "box.glb", Image.new("RGB", (8, 8), (240, 200, 20)))
    asset = _import_one(tmp_path, "box.glb")
    assert asset.rgba == ((1.0, 1.0, 1.0, 1.0),)  # the factor alone


def test_a_missing_texture_is_not_fatal(tmp_path: Path) -> None:
    box = trimesh.creation.box((0.1, 0.08, 0.06))
    lines = ["mtllib box.mtl", "usemtl tex"] + [f"v {x} {y} {z}" for x, y, z in box.vertices]
    lines += [f"vt {u} {v}" for u, v in box.vertices[:, :2] + 0.5]
    lines += [f"f {a + 1}/{a + 1} {b + 1}/{b + 1} {c + 1}/{c + 1}" for a, b, c in box.faces]
    (tmp_path / "box.obj").write_text("\n".join(lines) + "\n")
    (tmp_path / "box.mtl").write_text("newmtl tex\nKd 0.8 0.1 0.1\nmap_Kd missing.png\n")
    asset = _import_one(tmp_path, "box.obj")
    assert len(asset.rgba) == 1


@pytest.fixture
def duck(tmp_path: Path) -> Asset:
    pybullet_data = pytest.importorskip("pybullet_data")
    source = Path(pybullet_data.getDataPath())
    for name in ("duck.obj", "duck.mtl", "duckCM.png"):
        (tmp_path / name).write_bytes((source / name).read_bytes())
    return _import_one(tmp_path, "duck.obj", scale=0.05)


def test_the_textured_pybullet_duck_renders_mostly_yellow(duck: Asset, tmp_path: Path) -> None:
    from physcensis.physics.contact_sheet import render_contact_sheet

    png = render_contact_sheet([duck], tmp_path / "duck.png", cols=1, tile=200, labels=False)
    pixels = np.asarray(Image.open(png).convert("RGB"), dtype=float) / 255.0
    saturated = pixels.max(axis=2) - pixels.min(axis=2) > 0.25  # the floor and sky are grey
    assert saturated.mean() > 0.05
    r, g, b = pixels[saturated].mean(axis=0)
    assert r > 0.6 and g > 0.45 and b < 0.3, (r, g, b)


def test_the_glb_export_of_the_duck_has_a_yellow_material(duck: Asset) -> None:
    from physcensis.export.glb import ROOT, _add_asset

    scene = trimesh.Scene()
    scene.graph.update(frame_from=scene.graph.base_frame, frame_to=ROOT, matrix=np.eye(4))
    _add_asset(scene, "duck", duck, np.eye(4))
    data = scene.export(file_type="glb")
    loaded = trimesh.load(io.BytesIO(data), file_type="glb")
    colours = []
    for geometry in loaded.geometry.values():
        factor = getattr(geometry.visual.material, "baseColorFactor", None)
        if factor is not None:
            colours += [np.asarray(factor, dtype=float)[:3] / 255] * len(geometry.faces)
    mean = np.mean(colours, axis=0)
    assert mean[0] > 0.6 and mean[1] > 0.45 and mean[2] < 0.3, mean
