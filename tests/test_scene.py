from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest

from physcensis.errors import SceneFormatError
from physcensis.scene import SCENE_FORMAT, Scene, Support, load_scene, save_scene, scene_from_json


def scene_data() -> dict[str, Any]:
    return {
        "format": SCENE_FORMAT,
        "seed": 3,
        "prompt": "a cup on a table",
        "support": {"kind": "table", "size": [0.8, 0.6], "height": 0.75},
        "objects": [
            {
                "id": "cup_0",
                "description": "a white mug",
                "asset": "mug_01",
                "category": "mug",
                "position": [0.1, 0.0, 0.75],
                "quaternion": [1.0, 0.0, 0.0, 0.0],
                "mass": 0.3,
                "friction": 0.6,
                "com": [0.0, 0.0, 0.04],
                "placement": {"predicate": "PLACE-ON-BASE", "target": "root"},
                "status": "placed",
                "reason": None,
            }
        ],
        "program": [["cup_0", "a white mug"]],
        "metrics": {"settle_distance": 0.001},
    }


def test_round_trip_is_exact(tmp_path: Path) -> None:
    scene = Scene.model_validate(scene_data())
    path = save_scene(scene, tmp_path / "out" / "scene.json")
    assert load_scene(path) == scene
    assert load_scene(path.parent) == scene  # a scene folder works too
    assert json.loads(path.read_text())["format"] == "physcensis.scene/1"
    assert [p.name for p in path.parent.iterdir()] == ["scene.json"]  # no temp files left


def _load(data: dict[str, Any]) -> Scene:
    return scene_from_json(json.dumps(data), "s.json")


def test_unknown_format_version_is_refused() -> None:
    data = scene_data() | {"format": "physcensis.scene/2"}
    with pytest.raises(SceneFormatError, match="unsupported scene format 'physcensis.scene/2'"):
        _load(data)


def test_nan_and_infinity_are_refused_with_the_field() -> None:
    text = json.dumps(scene_data()).replace('"mass": 0.3', '"mass": NaN')
    with pytest.raises(SceneFormatError, match="NaN"):
        scene_from_json(text)
    data = scene_data()
    data["objects"][0]["position"] = [0.1, math.inf, 0.75]
    with pytest.raises(SceneFormatError, match=r"objects\[0\] \(cup_0\)\.position"):
        _load_raw(data)


def _load_raw(data: dict[str, Any]) -> Scene:
    from physcensis.scene import scene_from_data

    return scene_from_data(data)


def test_non_finite_metrics_are_refused() -> None:
    data = scene_data()
    data["metrics"] = {"per_object": {"cup_0": float("nan")}}
    with pytest.raises(SceneFormatError, match=r"metrics\.per_object\.cup_0"):
        _load_raw(data)


def test_duplicate_ids_are_refused() -> None:
    data = scene_data()
    data["objects"].append(dict(data["objects"][0]))
    with pytest.raises(SceneFormatError, match="duplicate object id 'cup_0'"):
        _load(data)


def test_non_unit_quaternion_is_refused_naming_the_field() -> None:
    data = scene_data()
    data["objects"][0]["quaternion"] = [1.0, 0.2, 0.0, 0.0]
    with pytest.raises(SceneFormatError, match=r"objects\[0\] \(cup_0\)\.quaternion: .*unit quaternion"):
        _load(data)


@pytest.mark.parametrize(
    ("path", "value", "field"),
    [
        (("objects", 0, "mass"), -1.0, "mass"),
        (("objects", 0, "id"), "cup 0", "id"),
        (("objects", 0, "status"), "lost", "status"),
        (("support", "kind"), "ceiling", "support.kind"),
        (("support", "size"), [0.0, 1.0], "support.size"),
    ],
)
def test_bad_fields_are_named(path: tuple[Any, ...], value: Any, field: str) -> None:
    data = scene_data()
    node: Any = data
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    with pytest.raises(SceneFormatError, match=field.replace(".", r"\.")):
        _load(data)


def test_failed_object_needs_a_reason() -> None:
    data = scene_data()
    data["objects"][0]["status"] = "failed"
    with pytest.raises(SceneFormatError, match="reason"):
        _load(data)


def test_not_json_and_missing_file(tmp_path: Path) -> None:
    with pytest.raises(SceneFormatError, match="not valid JSON"):
        scene_from_json("{nope")
    with pytest.raises(SceneFormatError, match="cannot read"):
        load_scene(tmp_path / "none.json")


def test_support_parse_and_defaults() -> None:
    assert Support.parse("table:0.7x1.4").size == (0.7, 1.4)
    assert Support.parse("table:0.7x1.4").top_height == pytest.approx(0.75)
    assert Support.parse("floor:3x3").top_height == 0.0
    assert Support.parse("shelf:0.3x1.0@1.2").top_height == pytest.approx(1.2)
    for bad in ("table", "desk:1x1", "table:1", "table:ax1", "table:0x1"):
        with pytest.raises(ValueError, match="support"):
            Support.parse(bad)


def test_scene_refuses_object_ids_reserved_for_its_own_parts() -> None:
    from physcensis.errors import SceneFormatError
    from physcensis.scene import scene_from_data

    data = {
        "format": "physcensis.scene/1",
        "support": {"size": [1.0, 1.0]},
        "objects": [
            {
                "id": "Ground",
                "description": "a cup",
                "asset": "cup",
                "category": "cup",
                "position": [0, 0, 0.75],
                "mass": 0.2,
                "friction": 0.5,
            }
        ],
    }
    with pytest.raises(SceneFormatError, match=r"objects\[0\] \(Ground\)\.id: 'Ground' is reserved"):
        scene_from_data(data)
