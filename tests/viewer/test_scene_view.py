"""What the viewer shows of a scene folder: one pickable node per placed object at its written pose, with the facts a
click shows; the support; the first camera where the default render's viewer stands."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from physcensis.errors import SceneFormatError
from physcensis.scene import load_scene
from physcensis.viewer.scene_view import build_scene_view, object_node_name, open_scene_view


def test_one_pickable_node_per_placed_object_at_its_written_pose_with_its_facts(scene_dir: Path) -> None:
    view, catalogue = open_scene_view(scene_dir)
    scene = load_scene(scene_dir)
    assert [node.id for node in view.objects] == [o.id for o in scene.placed]
    assert sorted(node.id for node in view.objects) == ["book_0", "bowl_0", "mug_0"]
    assert all(node.pickable for node in view.objects)
    assert not view.support.pickable and view.ground is not None and not view.ground.pickable
    for obj in scene.placed:
        node = view.node(obj.id)
        assert node.name == object_node_name(obj.id) == f"/objects/{obj.id}"
        np.testing.assert_allclose(node.pose, [*obj.position, *obj.quaternion])
        info = node.info
        assert info is not None
        assert (info.asset, info.mass_kg, info.friction, info.com) == (obj.asset, obj.mass, obj.friction, obj.com)
        # The meshes are the catalogue's visual mesh, one part per colour, with the colours of the asset.
        asset = catalogue.asset_for(obj.asset, obj.description)
        assert sum(len(p.faces) for p in node.parts) == len(asset.visual.faces)
        assert {p.rgb for p in node.parts} == {tuple(round(255 * c) for c in rgba[:3]) for rgba in asset.rgba}
    mug = view.node("mug_0").info
    assert mug is not None and [p.text() for p in mug.placements] == ["PLACE-ON book_0"]
    assert mug.p_fail is None
    text = mug.markdown()
    assert "mug_0" in text and mug.asset in text and "PLACE-ON book_0" in text and "not measured" in text


def test_the_support_mesh_is_the_table_top_where_the_objects_stand(scene_dir: Path) -> None:
    view, _ = open_scene_view(scene_dir)
    top = view.scene.support.top_height
    vertices = np.vstack([p.vertices for p in view.support.parts])
    assert vertices[:, 2].max() == pytest.approx(top, abs=1e-4)
    assert vertices[:, 0].max() == pytest.approx(0.4, abs=1e-3) and vertices[:, 1].max() == pytest.approx(0.3, abs=1e-3)
    assert all(node.pose[2] >= top - 1e-3 for node in view.objects)


def test_the_first_camera_stands_in_front_above_the_table_looking_back(scene_dir: Path) -> None:
    view, _ = open_scene_view(scene_dir)
    eye, target = np.array(view.camera.position), np.array(view.camera.look_at)
    towards = target - eye
    assert eye[0] > 0.5 and towards[0] < 0  # in front (+x), looking towards -x
    assert eye[2] > target[2] > view.scene.support.top_height - 0.01  # above, looking down at the top
    assert abs(towards[0]) > abs(towards[1])  # mostly from the front, as the default render
    assert 0.5 < np.linalg.norm(towards) < 5.0


def test_p_fail_and_placements_come_from_the_report_when_it_has_them(scene_dir: Path) -> None:
    scene = load_scene(scene_dir)
    view, catalogue = open_scene_view(scene_dir)
    report = {
        "metrics": {
            "placements": [
                {"object": "mug_0", "predicate": "PLACE-ON", "target": "book_0", "ok": True, "p_fail": 0.42},
                {"object": "bowl_0", "predicate": "PLACE-ON-BASE", "target": "root", "ok": False},
            ]
        }
    }
    view = build_scene_view(scene, catalogue, scene_dir, report)
    mug, bowl = view.node("mug_0").info, view.node("bowl_0").info
    assert mug is not None and bowl is not None
    assert mug.p_fail == 0.42 and "0.420" in mug.markdown()
    assert bowl.p_fail is None and [p.text() for p in bowl.placements] == ["PLACE-ON-BASE root - not met"]


def test_an_unreadable_report_is_a_note_and_the_scene_is_still_shown(scene_dir: Path, tmp_path: Path) -> None:
    folder = tmp_path / "scene"
    folder.mkdir()
    (folder / "scene.json").write_text((scene_dir / "scene.json").read_text())
    (folder / "report.json").write_text("{not json")
    view, _ = open_scene_view(folder)
    assert len(view.objects) == 3
    assert len(view.notes) == 1 and "report.json" in view.notes[0]


def test_a_bad_scene_file_is_one_clear_error(tmp_path: Path) -> None:
    bad = tmp_path / "scene.json"
    bad.write_text(json.dumps({"support": {"kind": "table", "size": [1, 1]}, "objects": [{"id": "x"}]}))
    with pytest.raises(SceneFormatError, match="scene.json"):
        open_scene_view(bad)
