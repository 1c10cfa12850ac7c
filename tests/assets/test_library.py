"""User libraries: normalisation, broken files, escaping paths, CoACD decomposition."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh
import yaml

from physcensis.assets.cache import AssetCache
from physcensis.assets.catalogue import Catalogue
from physcensis.assets.errors import AssetError
from physcensis.assets.library import load_library
from physcensis.physics.mujoco_assets import add_asset_geoms


def _write_library(folder: Path, spec: dict, name: str = "library.yaml") -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    text = json.dumps(spec) if name.endswith(".json") else yaml.safe_dump(spec)
    (folder / name).write_text(text)
    return folder


def _u_shape() -> trimesh.Trimesh:
    """A U-shaped trough (concave), 12 x 8 x 6 cm, open on top."""
    outer = trimesh.creation.box((0.12, 0.08, 0.06))
    inner = trimesh.creation.box((0.1, 0.06, 0.06))
    inner.apply_translation((0, 0, 0.01))
    return trimesh.boolean.difference([outer, inner], engine="manifold")


def test_good_meshes_load_normalised(tmp_path: Path) -> None:
    lib = tmp_path / "lib"
    (lib / "meshes").mkdir(parents=True)
    # a 10 x 4 x 20 (cm) box, authored in centimetres with +y up and off-centre
    box = trimesh.creation.box((10.0, 20.0, 4.0))
    box.apply_translation((50.0, 7.0, -3.0))
    (lib / "meshes" / "crate.obj").write_text(box.export(file_type="obj"))
    ball = trimesh.creation.icosphere(subdivisions=3, radius=0.03)
    (lib / "meshes" / "ball.stl").write_bytes(ball.export(file_type="stl"))
    (lib / "meshes" / "ball2.ply").write_bytes(ball.export(file_type="ply"))
    (lib / "meshes" / "ball3.glb").write_bytes(ball.export(file_type="glb"))
    _write_library(
        lib,
        {
            "unit": "cm",
            "up": "+y",
            "assets": [
                {
                    "file": "meshes/crate.obj",
                    "id": "crate",
                    "category": "box",
                    "description": "a wooden crate",
                    "mass": [0.5, 0.7],
                },
                {"file": "meshes/ball.stl", "unit": "m", "up": "+z", "category": "ball"},
                {"file": "meshes/ball2.ply", "unit": "m", "up": "+z", "height": 0.1},
                {"file": "meshes/ball3.glb", "unit": "m", "up": "+z", "id": "glb_ball"},
            ],
        },
    )
    result = load_library(lib, cache=AssetCache(tmp_path / "cache"))
    assert result.errors == []
    crate, ball_a, ball_b, ball_c = result.assets
    assert np.allclose(crate.size, (0.1, 0.04, 0.2))  # cm -> m, +y up -> +z
    lo, hi = crate.visual.bounds
    assert abs(lo[2]) < 1e-9 and np.allclose((lo[:2] + hi[:2]) / 2, 0)
    assert crate.mass == pytest.approx(0.6) and "mass" not in crate.guessed and len(crate.collision) == 1
    assert (
        ball_a.id == "ball"
        and ball_a.category == "ball"
        and "mass" in ball_a.guessed
        and "description" in ball_a.guessed
    )
    assert ball_b.size[2] == pytest.approx(0.1, rel=1e-6) and "category" in ball_b.guessed
    assert ball_c.id == "glb_ball" and ball_c.visual.is_watertight


def test_broken_and_missing_files_are_named_and_the_rest_loads(tmp_path: Path) -> None:
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "good.stl").write_bytes(trimesh.creation.box((0.1, 0.1, 0.1)).export(file_type="stl"))
    (lib / "broken.glb").write_bytes(b"this is not a glb file")
    _write_library(
        lib,
        {
            "assets": [
                {"file": "broken.glb"},
                {"file": "good.stl", "category": "toy block"},
                {"file": "missing.obj"},
                {"file": "good.stl", "id": "x", "colour": "red"},
            ]
        },
    )
    result = load_library(lib)
    assert [a.id for a in result.assets] == ["good"]
    messages = [str(e) for e in result.errors]
    assert len(messages) == 3
    assert "broken.glb" in messages[0] and "cannot read mesh" in messages[0]
    assert "missing.obj" in messages[1] and "not found" in messages[1]
    assert "colour" in messages[2]


def test_paths_outside_the_library_are_refused(tmp_path: Path) -> None:
    outside = tmp_path / "secret.stl"
    outside.write_bytes(trimesh.creation.box((0.1, 0.1, 0.1)).export(file_type="stl"))
    lib = _write_library(tmp_path / "lib", {"assets": [{"file": "../secret.stl"}, {"file": str(outside)}]})
    result = load_library(lib)
    assert result.assets == []
    assert all("outside the library folder" in str(e) for e in result.errors) and len(result.errors) == 2


def test_missing_or_bad_library_file(tmp_path: Path) -> None:
    with pytest.raises(AssetError, match="no library file"):
        load_library(tmp_path)
    (tmp_path / "library.yaml").write_text("assets: [unclosed")
    with pytest.raises(AssetError, match="cannot read the library file"):
        load_library(tmp_path)


@pytest.mark.skipif(importlib.util.find_spec("coacd") is None, reason="coacd not installed")
def test_concave_mesh_is_decomposed_and_cached(tmp_path: Path) -> None:
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "trough.stl").write_bytes(_u_shape().export(file_type="stl"))
    _write_library(lib, {"assets": [{"file": "trough.stl", "category": "basket", "container": True}]}, "library.json")
    cache = AssetCache(tmp_path / "cache")
    result = load_library(lib, cache=cache)
    assert result.errors == []
    (trough,) = result.assets
    assert len(trough.collision) > 1
    assert trough.cavity is not None and trough.cavity.floor_height == pytest.approx(0.01, abs=1e-3)
    assert len(trough.collision) <= 16  # a base and wall sectors (container_parts.py), no CoACD run needed
    again = load_library(lib, cache=cache).assets[0]
    assert len(again.collision) == len(trough.collision)
    # the imported container holds a ball in MuJoCo like the built-in ones
    spec = mujoco.MjSpec()
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[1, 1, 0.1])
    body = spec.worldbody.add_body(name="trough")
    body.add_freejoint()
    add_asset_geoms(spec, body, trough, "trough")
    ball = spec.worldbody.add_body(name="ball", pos=[0.0, 0.0, 0.08])
    ball.add_freejoint()
    ball.add_geom(type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[0.01, 0, 0], density=1000)
    model = spec.compile()
    data = mujoco.MjData(model)
    for _ in range(600):
        mujoco.mj_step(model, data)
    x, y, z = data.body("ball").xpos
    assert abs(x) < 0.05 and abs(y) < 0.03 and z < 0.04


def test_libraries_join_the_catalogue(tmp_path: Path) -> None:
    lib = tmp_path / "lib"
    lib.mkdir()  # a kind of thing the built-in catalogue does not have
    (lib / "gnome.stl").write_bytes(trimesh.creation.icosphere(radius=0.04).export(file_type="stl"))
    _write_library(
        lib,
        {
            "assets": [
                {
                    "file": "gnome.stl",
                    "id": "garden_gnome",
                    "category": "garden gnome",
                    "description": "a painted ceramic garden gnome with a red hat",
                    "synonyms": ["lawn gnome"],
                }
            ]
        },
    )
    catalogue = Catalogue([lib], cache=False)
    assert "garden gnome" in catalogue.categories()
    assert catalogue.resolve("a garden gnome").id == "garden_gnome"
    assert catalogue.get("garden_gnome").source.endswith("gnome.stl")
