"""GLB export: one node per object at its pose, with its coloured meshes, readable by trimesh."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

from physcensis.assets.catalogue import default_catalogue
from physcensis.export import export_scene
from physcensis.export.bodies import pose_matrix
from physcensis.export.glb import ROOT
from physcensis.scene import Scene


@pytest.fixture(scope="module")
def loaded(desk_scene: Scene, tmp_path_factory: pytest.TempPathFactory) -> trimesh.Scene:
    path = export_scene(desk_scene, tmp_path_factory.mktemp("glb"), ["glb"])["glb"]
    return trimesh.load(path)


def test_one_node_per_object_under_the_scene_root(loaded: trimesh.Scene, desk_scene: Scene) -> None:
    parents = loaded.graph.transforms.parents
    object_nodes = [n for n, parent in parents.items() if parent == ROOT and n not in ("support", "ground")]
    assert sorted(object_nodes) == sorted(o.id for o in desk_scene.placed)


def test_object_nodes_carry_their_pose_and_geometry(loaded: trimesh.Scene, desk_scene: Scene) -> None:
    catalogue = default_catalogue()
    for obj in desk_scene.placed:
        transform, _ = loaded.graph.get(obj.id, frame_from=ROOT)
        assert np.allclose(transform, pose_matrix(np.asarray(obj.position), np.asarray(obj.quaternion)), atol=1e-6)
        children = [n for n, parent in loaded.graph.transforms.parents.items() if parent == obj.id]
        meshes = [loaded.geometry[loaded.graph[n][1]] for n in children]
        merged = trimesh.util.concatenate(meshes)
        visual = catalogue.asset_for(obj.asset, obj.description).visual
        assert np.allclose(merged.bounds, visual.bounds, atol=1e-5)
        assert all(m.visual.material.baseColorFactor is not None for m in meshes)


def test_the_scene_stands_upright_in_y_up_viewers(loaded: trimesh.Scene, desk_scene: Scene) -> None:
    top = desk_scene.support.top_height
    tallest = max(o.position[2] for o in desk_scene.placed)
    bounds = loaded.bounds  # world frame of the file: y is up
    assert bounds[0][1] == pytest.approx(-0.05, abs=1e-3)  # the ground slab's underside
    assert bounds[1][1] > max(top, tallest)


def test_export_writes_nothing_when_it_fails(
    desk_scene: Scene, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def broken(*_: object, **__: object) -> bytes:
        raise RuntimeError("disk full")

    monkeypatch.setattr(trimesh.Scene, "export", broken)
    with pytest.raises(RuntimeError):
        export_scene(desk_scene, tmp_path, ["glb"])
    assert list(tmp_path.iterdir()) == []
