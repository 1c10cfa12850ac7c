"""Scene files an engine cannot use are refused by the loader, with the file and the field named."""

from __future__ import annotations

import json
import math
import tempfile
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from physcensis.bounded_json import json_shape
from physcensis.errors import SceneFormatError
from physcensis.scene import (
    MAX_NESTING,
    MAX_SCENE_BYTES,
    Scene,
    Support,
    load_scene,
    save_scene,
    scene_from_data,
    scene_from_json,
)

from .test_scene import scene_data

CUP = r"objects\[0\] \(cup_0\)"


def write(tmp_path: Path, data: Any, name: str = "bad.json") -> Path:
    path = tmp_path / name
    path.write_text(data if isinstance(data, str) else json.dumps(data))
    return path


def with_object_field(field: str, value: Any) -> dict[str, Any]:
    data = scene_data()
    data["objects"][0][field] = value
    return data


def refused(tmp_path: Path, data: Any, pattern: str) -> str:
    """Load `data` from a file; it must be refused with the file and `pattern` (the field) in the message."""
    path = write(tmp_path, data)
    with pytest.raises(SceneFormatError, match=pattern) as info:
        load_scene(path)
    message = str(info.value)
    assert message.startswith(f"{path}: ") and "\n" not in message
    return message


# -- masses, friction, coordinates, quaternions ----------------------------------------------------------------
@pytest.mark.parametrize("mass", [0, 0.0, -1.0, 1e-9, 1e-12, 5e-10, 1e4 + 1, 1e7, 1e300, 10**30])
def test_masses_no_engine_can_use_are_refused(tmp_path: Path, mass: float) -> None:
    message = refused(tmp_path, with_object_field("mass", mass), rf"{CUP}\.mass: ")
    assert "kg is not a usable mass" in message


def test_the_mass_message_says_what_is_usable(tmp_path: Path) -> None:
    message = refused(tmp_path, with_object_field("mass", 0), rf"{CUP}\.mass")
    assert "0 kg is not a usable mass (must be > 1e-09 kg" in message


@pytest.mark.parametrize("literal", ["NaN", "Infinity", "-Infinity", "1e999", "-1e999"])
def test_non_finite_masses_are_refused(tmp_path: Path, literal: str) -> None:
    text = json.dumps(scene_data()).replace('"mass": 0.3', f'"mass": {literal}')
    path = write(tmp_path, text)
    with pytest.raises(SceneFormatError, match=str(path)):
        load_scene(path)


@pytest.mark.parametrize("friction", [-0.1, -1e-12, 10.5, 1e308])
def test_unusable_friction_is_refused(tmp_path: Path, friction: float) -> None:
    refused(tmp_path, with_object_field("friction", friction), rf"{CUP}\.friction: .*not a usable friction")


@pytest.mark.parametrize("position", [[1001.0, 0.0, 0.75], [0.0, -1e6, 0.75], [0.0, 0.0, 2e3], [1e308, 0, 0]])
def test_positions_far_outside_any_scene_are_refused(tmp_path: Path, position: list[float]) -> None:
    refused(tmp_path, with_object_field("position", position), rf"{CUP}\.position: .*far outside any scene")


def test_positions_up_to_the_bound_are_accepted(tmp_path: Path) -> None:
    scene = load_scene(write(tmp_path, with_object_field("position", [1000.0, -1000.0, 999.5])))
    assert scene.objects[0].position == (1000.0, -1000.0, 999.5)


@pytest.mark.parametrize("com", [[11.0, 0.0, 0.0], [0.0, 0.0, -1e9]])
def test_a_centre_of_mass_far_outside_the_object_is_refused(tmp_path: Path, com: list[float]) -> None:
    refused(tmp_path, with_object_field("com", com), rf"{CUP}\.com: .*centre of mass far outside")


@pytest.mark.parametrize("component", ["1", "1.0", None, True, False, [1.0], {"w": 1.0}, "NaN"])
def test_quaternion_components_that_are_not_numbers_are_refused(tmp_path: Path, component: Any) -> None:
    message = refused(
        tmp_path,
        with_object_field("quaternion", [component, 0.0, 0.0, 0.0]),
        rf"{CUP}\.quaternion\[0\]: must be a number",
    )
    assert "not a" in message or "not null" in message


@pytest.mark.parametrize("field", ["mass", "friction"])
@pytest.mark.parametrize("value", ["0.3", True, None, [0.3]])
def test_numbers_must_be_numbers(tmp_path: Path, field: str, value: Any) -> None:
    refused(tmp_path, with_object_field(field, value), rf"{CUP}\.{field}: must be a number")


@pytest.mark.parametrize("seed", [True, "3", 1.5, 2**64])
def test_the_seed_must_be_a_plain_integer(tmp_path: Path, seed: Any) -> None:
    refused(tmp_path, scene_data() | {"seed": seed}, r"seed: ")


# -- supports -----------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("size", [[100.0, 100.0], [50.001, 1.0], [0.0, 1.0], [-1.0, 1.0], [1.0, 1e308]])
def test_support_sizes_beyond_sane_bounds_are_refused_in_scene_files(tmp_path: Path, size: list[float]) -> None:
    data = scene_data()
    data["support"]["size"] = size
    refused(tmp_path, data, r"support\.size\[?\d?\]?: .*not a usable extent.*\(0, 50\] metres")


@pytest.mark.parametrize(
    "text",
    [
        "floor:100x100",
        "table:51x1",
        "floor:0x1",
        "floor:-2x2",
        "floor:nanx1",
        "floor:infx1",
        "table:1x1e400",
        "table:1x1@nan",
        "table:1x1@11",
    ],
)
def test_support_parse_refuses_unusable_sizes(text: str) -> None:
    with pytest.raises(ValueError, match=r"support '.*'") as info:
        Support.parse(text)
    assert "\n" not in str(info.value)


def test_the_largest_allowed_support_parses() -> None:
    assert Support.parse("floor:50x50").size == (50.0, 50.0)


# -- the document itself -------------------------------------------------------------------------------------------
@pytest.mark.parametrize("depth", [MAX_NESTING + 1, 1000, 100_000])
def test_deep_nesting_is_refused_before_parsing(tmp_path: Path, depth: int) -> None:
    nested = "[" * depth + "]" * depth
    text = json.dumps(scene_data()).replace('"program": [', f'"program": [{nested}, ', 1)
    if depth >= 100_000:
        with pytest.raises(RecursionError):  # what the guard is for
            json.loads(text)
    message = refused(tmp_path, text, "levels deep")
    assert f"nested {depth + 2} levels deep" in message


def test_deep_nesting_in_already_parsed_data_is_refused_without_recursion() -> None:
    deep: list[Any] = []
    node = deep
    for _ in range(100_000):
        node.append([])
        node = node[0]
    with pytest.raises(SceneFormatError, match=r"program.*nested more than"):
        scene_from_data(scene_data() | {"program": deep}, "data")


def test_brackets_inside_strings_do_not_count_as_nesting() -> None:
    data = scene_data()
    data["objects"][0]["description"] = "a mug [[[[" * 100 + '\\"{{{{'
    assert json_shape(json.dumps(data)).depth <= 4
    assert _load(data).objects[0].description == data["objects"][0]["description"]


def test_huge_files_are_refused_with_the_limit(tmp_path: Path) -> None:
    path = tmp_path / "huge.json"
    path.write_text(json.dumps(scene_data() | {"prompt": "x" * (MAX_SCENE_BYTES + 10)}))
    with pytest.raises(SceneFormatError, match=rf"{path}: a scene file may hold at most 32 MB"):
        load_scene(path)


def test_things_that_are_not_files_are_refused(tmp_path: Path) -> None:
    with pytest.raises(SceneFormatError, match="not a regular file"):
        load_scene("/dev/zero")
    with pytest.raises(SceneFormatError, match="cannot read scene file"):
        load_scene(tmp_path)  # a folder without scene.json


@pytest.mark.parametrize("where", ["program", "metrics", "objects"])
def test_integers_of_thousands_of_digits_are_refused_with_the_field(tmp_path: Path, where: str) -> None:
    data = scene_data()
    text = json.dumps(data)
    huge = "7" * 5000
    if where == "program":
        text = text.replace('"program": [', f'"program": [{huge}, ', 1)
    elif where == "metrics":
        text = text.replace('"metrics": {', f'"metrics": {{"n": {huge}, ', 1)
    else:
        text = text.replace('"mass": 0.3', f'"mass": {huge}')
    message = refused(tmp_path, text, "an integer of 5000 digits")
    assert {"program": "program[0]", "metrics": "metrics.n", "objects": "objects[0] (cup_0).mass"}[where] in message


def test_infinite_numbers_anywhere_are_refused_so_the_scene_can_always_be_saved(tmp_path: Path) -> None:
    text = json.dumps(scene_data()).replace('"program": [', '"program": [1e999, ', 1)
    refused(tmp_path, text, r"program\[0\]: inf is not a finite number")


@pytest.mark.parametrize("field", ["description", "category", "asset"])
def test_text_that_cannot_be_written_back_is_refused(tmp_path: Path, field: str) -> None:
    text = json.dumps(with_object_field(field, "PLACEHOLDER")).replace("PLACEHOLDER", "a \\ud800 mug")
    refused(tmp_path, text, rf"objects\[0\].*{field}: not valid unicode")


def test_too_long_texts_are_refused(tmp_path: Path) -> None:
    refused(tmp_path, with_object_field("description", "a mug " * 5000), rf"{CUP}\.description")


def _load(data: dict[str, Any]) -> Scene:
    return scene_from_json(json.dumps(data), "s.json")


# -- property: whatever a mutated scene holds, the loader answers with a Scene or a SceneFormatError ----------------
JSON_SCALARS = (
    st.none()
    | st.booleans()
    | st.integers()
    | st.integers(min_value=-(10**60), max_value=10**60)
    | st.floats(allow_nan=True, allow_infinity=True)
    | st.text(max_size=20)
)
JSON_VALUES = st.recursive(
    JSON_SCALARS,
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=8), inner, max_size=4),
    max_leaves=12,
)
NUMBERS = (
    st.floats(allow_nan=True, allow_infinity=True)
    | st.integers(min_value=-(10**6), max_value=10**6)
    | st.sampled_from([0, 1e-9, 1.0000001e-9, 1e4, 1e4 + 1e-9, 1e3, -1e3, 1000.0001, 50, 50.0001, 10, 1e-300])
)


def paths_of(data: Any, prefix: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    """Every key and index path inside a JSON-like value."""
    out = []
    if isinstance(data, dict):
        items = list(data.items())
    elif isinstance(data, list):
        items = list(enumerate(data))
    else:
        return out
    for key, value in items:
        out.append((*prefix, key))
        out.extend(paths_of(value, (*prefix, key)))
    return out


def mutated(data: dict[str, Any], path: tuple[Any, ...], action: str, value: Any) -> dict[str, Any]:
    parent: Any = data
    for key in path[:-1]:
        parent = parent[key]
    last = path[-1]
    if action == "drop" and isinstance(parent, dict):
        del parent[last]
    elif action == "drop":
        parent.pop(last)
    else:
        parent[last] = value
    return data


SCENE_PATHS = paths_of(scene_data())


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    edits=st.lists(
        st.tuples(st.sampled_from(SCENE_PATHS), st.sampled_from(["drop", "replace"]), JSON_VALUES),
        min_size=1,
        max_size=3,
    )
)
def test_mutated_scenes_load_or_are_refused_cleanly(edits: list[tuple[tuple[Any, ...], str, Any]]) -> None:
    data = scene_data()
    for path, action, value in edits:
        try:
            data = mutated(data, path, action, value)
        except (KeyError, IndexError, TypeError, AttributeError):
            continue  # an earlier edit removed or replaced what this one would change
    text = json.dumps(data, allow_nan=True)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "scene.json"
        path.write_text(text)
        try:
            scene = load_scene(path)
        except SceneFormatError as exc:
            assert str(exc).startswith(f"{path}: ") and "\n" not in str(exc)
            return
        # What loads can be written back and reads the same.
        assert load_scene(save_scene(scene, Path(tmp) / "again.json")) == scene


def _physical_fields() -> list[tuple[Any, ...]]:
    fields = [
        ("support", "size", 0),
        ("support", "size", 1),
        ("support", "height"),
        ("objects", 0, "mass"),
        ("objects", 0, "friction"),
    ]
    fields += [("objects", 0, name, i) for name in ("position", "com") for i in range(3)]
    fields += [("objects", 0, "quaternion", i) for i in range(4)]
    return fields


@pytest.mark.physics
@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    edits=st.lists(st.tuples(st.sampled_from(_physical_fields()), NUMBERS), min_size=1, max_size=4),
    kind=st.sampled_from(["table", "shelf", "floor", "box"]),
)
def test_what_loads_builds_in_mujoco(edits: list[tuple[tuple[Any, ...], float]], kind: str) -> None:
    from physcensis.physics.mujoco_engine import MujocoEngine

    data = scene_data()
    data["objects"][0]["asset"] = "mug_white"
    data["objects"][0]["com"] = [0.0, 0.0, 0.0]
    data["support"]["kind"] = kind
    for path, value in edits:
        data = mutated(data, path, "replace", value)
    try:
        scene = scene_from_json(json.dumps(data, allow_nan=True), "s.json")
    except SceneFormatError:
        return
    assert all(math.isfinite(v) for v in scene.objects[0].position)
    MujocoEngine().build(scene, visual=False)


def test_a_scene_file_with_a_byte_order_mark_loads(tmp_path: Path) -> None:
    from physcensis.scene import Scene, Support, load_scene, save_scene

    plain = save_scene(Scene(support=Support(kind="table", size=(1.0, 1.0))), tmp_path / "plain.json")
    marked = tmp_path / "marked.json"
    marked.write_bytes(b"\xef\xbb\xbf" + plain.read_bytes())
    assert load_scene(marked) == load_scene(plain)


@pytest.mark.parametrize("kind", ["table", "shelf", "box", "floor"])
@pytest.mark.parametrize("height", [0.0, 0.005, 0.02, 0.04, 0.06])
def test_every_support_the_model_accepts_builds(kind: str, height: float) -> None:
    from pydantic import ValidationError

    from physcensis.physics.mujoco_engine import MujocoEngine
    from physcensis.scene import Scene, Support

    try:
        support = Support(kind=kind, size=(0.8, 0.6), height=height)
    except ValidationError as exc:
        assert "cannot be built" in str(exc)
        return
    MujocoEngine().build(Scene(support=support))


def test_a_folders_scene_json_that_is_a_link_is_refused_not_followed(tmp_path: Path) -> None:
    outside = tmp_path / "outside.json"
    save_scene(Scene.model_validate(scene_data()), outside)
    folder = tmp_path / "folder"
    folder.mkdir()
    (folder / "scene.json").symlink_to(outside)
    with pytest.raises(SceneFormatError, match=r"folder/scene\.json: is a symbolic link; refused"):
        load_scene(folder)
    assert load_scene(outside).objects  # a file named by the user is read where it is
