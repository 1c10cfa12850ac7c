"""Up axis and rest pose of imported meshes: the pose they rest in is found, kept, and checked in MuJoCo.

Resting on a floor depends only on the convex hull of the collision, so CoACD stays out of these tests: concave
meshes go through a stand-in decomposition (one hull).
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest
import trimesh
import yaml
from mujoco_world import TIMESTEP, floor_world, free_body

from physcensis.assets import library
from physcensis.assets.library import load_library
from physcensis.assets.model import Asset


def _hull_stand_in(mesh: trimesh.Trimesh, *args: Any, **kwargs: Any) -> list[np.ndarray]:
    return [np.asarray(mesh.convex_hull.vertices)]


@pytest.fixture(autouse=True)
def _no_coacd(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(library, "convex_decomposition", _hull_stand_in)


def _library(folder: Path, meshes: dict[str, trimesh.Trimesh], extra: dict[str, dict] | None = None) -> Path:
    (folder / "meshes").mkdir(parents=True, exist_ok=True)
    entries = []
    for name, mesh in meshes.items():
        mesh.export(folder / "meshes" / f"{name}.stl")
        entries.append({"file": f"meshes/{name}.stl", "id": name, **(extra or {}).get(name, {})})
    (folder / "library.yaml").write_text(yaml.safe_dump({"assets": entries}))
    return folder


def _nudged(asset: Asset, spin: float) -> tuple[float, float]:
    """Dropped on a floor tilted 2 degrees, then shoved (0.1 m/s per rad/s of `spin` about y): how far (m) it went
    and how far (degrees) it turned from the pose it was put in."""
    spec = floor_world()
    body = free_body(spec, "obj", asset, (0.0, 0.0, 0.003))
    half = np.radians(2.0) / 2
    body.quat = [np.cos(half), np.sin(half) / np.sqrt(2), np.sin(half) / np.sqrt(2), 0.0]
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, nstep=int(0.3 / TIMESTEP))
    data.qvel[0], data.qvel[4] = 0.1 * spin, spin
    mujoco.mj_step(model, data, nstep=int(2.0 / TIMESTEP))
    shift = float(np.linalg.norm(data.body("obj").xpos[:2]))
    turn = float(np.degrees(2 * np.arccos(min(1.0, abs(data.body("obj").xquat[0])))))
    return shift, turn


def _rests(asset: Asset, spin: float = 1.0) -> bool:
    shift, turn = _nudged(asset, spin)
    return shift < 0.01 and turn < 10.0


def _lying_cylinder_on_y() -> trimesh.Trimesh:
    """A bottle-like cylinder drawn with +y up (the glTF / OBJ convention), and a flat cap at each end."""
    mesh = trimesh.creation.cylinder(radius=0.03, height=0.16, sections=32)
    mesh.apply_transform(trimesh.transformations.rotation_matrix(-np.pi / 2, (1, 0, 0)))
    return mesh


def test_a_mesh_drawn_y_up_is_stood_on_its_base_and_rests(tmp_path: Path) -> None:
    result = load_library(_library(tmp_path, {"tall": _lying_cylinder_on_y()}))
    (asset,) = result.assets
    assert asset.pose == "+y" and "pose" in asset.guessed and asset.rests
    assert asset.size[2] == pytest.approx(0.16, abs=1e-3)  # the long axis is up
    assert _rests(asset)


def test_a_mesh_that_rests_as_drawn_keeps_its_orientation(tmp_path: Path) -> None:
    box = trimesh.creation.box((0.2, 0.05, 0.1))  # lying on its widest face would be more stable: not chosen
    (asset,) = load_library(_library(tmp_path, {"box": box})).assets
    assert asset.pose.startswith("+z") and asset.rests
    assert "also rests +y up" in asset.pose  # it would stand on its end too: the import says it guessed
    assert asset.size == pytest.approx((0.2, 0.05, 0.1))


def test_an_up_given_in_the_library_is_honoured_and_not_guessed(tmp_path: Path) -> None:
    folder = _library(tmp_path, {"tall": _lying_cylinder_on_y()}, {"tall": {"up": "+z"}})
    (asset,) = load_library(folder).assets
    assert asset.pose == "+z" and "pose" not in asset.guessed
    assert asset.size[1] == pytest.approx(0.16, abs=1e-3)  # lying, as the entry says


def test_a_tipping_figure_is_laid_in_its_most_probable_stable_pose(tmp_path: Path) -> None:
    """A top-heavy T (a thin post under a wide heavy bar) tips on every axis-aligned face it has except ones where
    the bar lies: the pose found rests."""
    post = trimesh.creation.box((0.006, 0.006, 0.12), trimesh.transformations.translation_matrix((0, 0, 0.06)))
    bar = trimesh.creation.box((0.12, 0.05, 0.03), trimesh.transformations.translation_matrix((0, 0, 0.135)))
    figure = trimesh.boolean.union([post, bar], engine="manifold")
    figure.apply_transform(trimesh.transformations.rotation_matrix(0.3, (1, 1, 0)))  # no face is axis-aligned
    (asset,) = load_library(_library(tmp_path, {"tee": figure})).assets
    assert asset.pose == "stable pose" and asset.rests
    assert _rests(asset)


def test_a_ball_rests_nowhere_so_it_is_flagged_and_pressed_flat(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    ball = trimesh.creation.icosphere(subdivisions=3, radius=0.05)
    with caplog.at_level(logging.WARNING, logger="physcensis.assets.library"):
        (asset,) = load_library(_library(tmp_path, {"ball": ball})).assets
    assert not asset.rests and "rests in no pose" in caplog.text
    base = np.vstack([p.vertices for p in asset.collision])
    assert base[:, 2].min() == pytest.approx(0.0, abs=1e-9)  # still on z = 0, its visual sinks a millimetre or two
    assert (base[:, 2] < 1e-9).sum() >= 6  # a flat patch, no longer a facet
    assert _rests(asset)
    unpressed = library.Asset(**{**_fields(asset), "collision": (library.col.hull_part(asset.visual.vertices),)})
    assert not _rests(unpressed)  # the same ball left round rolls away after the same shove


def _fields(asset: Asset) -> dict[str, Any]:
    return {name: getattr(asset, name) for name in asset.__dataclass_fields__}


@pytest.mark.parametrize(
    ("files", "scale"), [(("duck.obj", "duck.mtl", "duckCM.png"), 0.05), (("teddy2_VHACD_CHs.obj",), 0.1)]
)
def test_pybullet_duck_and_teddy_rest_after_a_nudge(tmp_path: Path, files: tuple[str, ...], scale: float) -> None:
    pybullet_data = pytest.importorskip("pybullet_data")
    source = Path(pybullet_data.getDataPath())
    (tmp_path / "meshes").mkdir()
    for name in files:
        (tmp_path / "meshes" / name).write_bytes((source / name).read_bytes())
    entry = {"file": f"meshes/{files[0]}", "id": "toy", "scale": scale}
    (tmp_path / "library.yaml").write_text(yaml.safe_dump({"assets": [entry]}))
    result = load_library(tmp_path)
    assert result.errors == []
    (asset,) = result.assets
    assert asset.rests and "pose" in asset.guessed
    assert _rests(asset)


def test_a_gltf_file_is_read_plus_y_up_and_an_inside_out_mesh_is_turned(tmp_path: Path) -> None:
    """glTF's specification says +y is up: a box that would rest either way stands as the file means. A mesh
    exported inside out (negative volume) gets its faces turned, so it renders as a solid, not its back faces."""
    (tmp_path / "meshes").mkdir()
    crate = trimesh.creation.box((0.1, 0.3, 0.2))  # 30 cm tall along the file's +y
    crate.export(tmp_path / "meshes" / "crate.glb")
    inside_out = trimesh.creation.box((0.2, 0.15, 0.03))
    inside_out.invert()
    inside_out.export(tmp_path / "meshes" / "book.stl")
    entries = [{"file": "meshes/crate.glb", "id": "crate"}, {"file": "meshes/book.stl", "id": "book"}]
    (tmp_path / "library.yaml").write_text(yaml.safe_dump({"assets": entries}))
    assets = {a.id: a for a in load_library(tmp_path).assets}
    assert assets["crate"].pose.startswith("+y") and assets["crate"].size[2] == pytest.approx(0.3)
    assert assets["book"].visual.volume > 0 and assets["book"].mass > 0
