"""Hostile user libraries: every broken entry is that entry's error, the library file itself is read within bounds.

CoACD stays out of these tests: concave meshes go through a stand-in decomposition
(one hull) unless a test is about a failing CoACD call.
"""

from __future__ import annotations

import importlib.util
import json
import math
import os
import pickle
import time
import tomllib
from collections.abc import Iterator
from pathlib import Path
from typing import Any
from unittest import mock

import numpy as np
import pytest
import trimesh
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from physcensis.assets import bounded, library, meshfile
from physcensis.assets.library import EntryError, LibraryError, LibraryResult, load_library
from physcensis.cli.assets import assets_app

REPO = Path(__file__).resolve().parents[2]
runner = CliRunner()


def _hull_stand_in(mesh: trimesh.Trimesh, threshold: float = 0.05, cache: Any = None, **_: Any) -> list[np.ndarray]:
    return [np.asarray(mesh.convex_hull.vertices)]


@pytest.fixture(autouse=True)
def no_coacd() -> Iterator[None]:
    with mock.patch.object(library, "convex_decomposition", _hull_stand_in):
        yield


def _obj(vertices: list[list[float]], faces: list[list[int]]) -> str:
    lines = [f"v {x} {y} {z}" for x, y, z in vertices] + ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return "\n".join(lines) + "\n"


def _cube(size: float = 0.1) -> trimesh.Trimesh:
    return trimesh.creation.box((size, size, size))


def _cube_without_top() -> trimesh.Trimesh:
    cube = _cube()
    cube.update_faces(cube.face_normals[:, 2] < 0.9)  # the two triangles facing up are gone: a square hole
    return cube


def _knife_edge_top() -> trimesh.Trimesh:
    """A low slab with a wedge standing on one side: its top is one ridge line (collinear points)."""
    slab = trimesh.creation.box((0.1, 0.1, 0.01))
    slab.apply_translation((0, 0, 0.005))
    ridge = trimesh.Trimesh(
        [[-0.05, -0.05, 0.0], [-0.03, -0.05, 0.0], [-0.04, -0.05, 0.08]]
        + [[-0.05, 0.05, 0.0], [-0.03, 0.05, 0.0], [-0.04, 0.05, 0.08]],
        [[0, 2, 1], [3, 4, 5], [0, 1, 4], [0, 4, 3], [1, 2, 5], [1, 5, 4], [2, 0, 3], [2, 3, 5]],
    )
    ridge.fix_normals()
    return trimesh.boolean.union([slab, ridge], engine="manifold")


def _write(folder: Path, spec: Any, name: str = "library.yaml") -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_text(spec if isinstance(spec, str) else yaml.safe_dump(spec))
    return folder


def _reasons(result: LibraryResult) -> dict[int, str]:
    """Entry index -> reason, from the `(assets[i])` each error names."""
    out = {}
    for err in result.errors:
        assert isinstance(err, EntryError)
        index = int(err.entry.rsplit("(assets[", 1)[1].rstrip("])"))
        out[index] = err.reason
    return out


def _hostile_mesh_library(root: Path) -> Path:
    lib = root / "lib"
    lib.mkdir()
    (lib / "good.stl").write_bytes(_cube().export(file_type="stl"))
    (lib / "flat.obj").write_text(_obj([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 3]]))
    (lib / "diagonal.obj").write_text(_obj([[0, 0, 0], [1, 1, 0], [1, 1, 1], [0, 0, 1]], [[0, 1, 2], [0, 2, 3]]))
    (lib / "line.obj").write_text(_obj([[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]], [[0, 1, 2], [1, 2, 3]]))
    tetra = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]
    (lib / "nan.obj").write_text(_obj([[0, 0, 0], [1, 0, 0], [float("nan"), 1, 0], [0, 0, 1]], tetra))
    (lib / "inf.obj").write_text(_obj([[0, 0, 0], [1, 0, 0], [0, float("inf"), 0], [0, 0, 1]], tetra))
    (lib / "empty.obj").write_text("")
    (lib / "holed.stl").write_bytes(_cube_without_top().export(file_type="stl"))
    (lib / "ridge.stl").write_bytes(_knife_edge_top().export(file_type="stl"))
    (lib / "folder.stl").mkdir()
    os.symlink("/dev/zero", lib / "zero.stl")
    os.symlink("loop_b.stl", lib / "loop_a.stl")
    os.symlink("loop_a.stl", lib / "loop_b.stl")
    entries: list[Any] = [
        {"file": "good.stl", "category": "toy block"},  # 0
        {"file": "flat.obj"},  # 1
        {"file": "diagonal.obj"},  # 2
        {"file": "line.obj"},  # 3
        {"file": "nan.obj"},  # 4
        {"file": "inf.obj"},  # 5
        {"file": "empty.obj"},  # 6
        {"file": "holed.stl", "id": "holed"},  # 7
        {"file": "ridge.stl", "id": "ridge"},  # 8
        {"file": "folder.stl"},  # 9
        {"file": "zero.stl"},  # 10
        {"file": "loop_a.stl"},  # 11
        {"file": "../outside.stl"},  # 12
        {"file": "good.stl", "id": "negative_mass", "mass": -1.0},  # 13
        {"file": "good.stl", "id": "zero_mass", "mass": 0},  # 14
        {"file": "good.stl", "id": "nan_mass", "mass": float("nan")},  # 15
        {"file": "good.stl", "id": "bool_mass", "mass": True},  # 16
        {"file": "good.stl", "id": "zero_friction", "friction": [0.0, 0.5]},  # 17
        {"file": "good.stl", "id": "negative_friction", "friction": [-0.2, 0.5]},  # 18
        {"file": "good.stl", "id": "text_size", "size": "big"},  # 19
        {"file": 7},  # 20
        "just a string",  # 21
        None,  # 22
        {"file": "good.stl", "id": "huge_size", "size": [1e308, 1e308, 1e308]},  # 23
        {"file": "good.stl", "id": "inf_scale", "scale": float("inf")},  # 24
        {"file": "good.stl", "id": "huge_int_mass", "mass": 10**400},  # 25
        {"file": "good.stl", "id": "second"},  # 26
    ]
    return _write(lib, {"assets": entries})


def test_each_hostile_mesh_or_field_is_its_entrys_error(tmp_path: Path) -> None:
    result = load_library(_hostile_mesh_library(tmp_path))
    assert [a.id for a in result.assets] == ["good", "holed", "ridge", "second"]
    holed = result.assets[1]
    assert "watertight" not in holed.guessed and holed.mass == pytest.approx(500 * 0.001, rel=1e-3)  # hole closed
    reasons = _reasons(result)
    expected = {
        1: "flat",
        2: "flat",
        3: "flat",
        4: "NaN or infinite",
        5: "NaN or infinite",
        6: "no triangles",
        9: "folder",
        10: "outside the library",
        11: "symlink loop",
        12: "outside the library",
        13: "mass",
        14: "mass",
        15: "mass",
        16: "mass",
        17: "friction",
        18: "friction",
        19: "size",
        20: "file",
        21: "must be a mapping",
        22: "must be a mapping",
        23: "size",
        24: "scale",
        25: "mass",
    }
    assert set(reasons) == set(expected)
    for index, word in expected.items():
        assert word in reasons[index], (index, reasons[index])
        assert "\n" not in reasons[index]
    negative = next(e for e in result.errors if isinstance(e, EntryError) and e.reason == reasons[13])
    assert negative.entry.endswith("good.stl (assets[13])")
    copy = pickle.loads(pickle.dumps(negative))  # errors cross process boundaries in batch runs
    assert (copy.entry, copy.reason, str(copy)) == (negative.entry, negative.reason, str(negative))


def test_deep_nesting_alias_bombs_and_cycles_fail_alone(tmp_path: Path) -> None:
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "good.stl").write_bytes(_cube().export(file_type="stl"))
    laughs = ", ".join(
        [f"&l0 [{', '.join(['lol'] * 9)}]"] + [f"&l{i} [{', '.join([f'*l{i - 1}'] * 9)}]" for i in range(1, 9)]
    )
    text = (
        "assets:\n"
        "  - {file: good.stl, id: first}\n"
        f"  - {{file: good.stl, id: deep_flow, tags: {'[' * 10_000}{']' * 10_000}}}\n"
        "  - file: good.stl\n    id: deep_block\n    tags:\n      " + "- " * 10_000 + "x\n"
        f"  - {{file: good.stl, id: bomb, tags: [{laughs}]}}\n"
        "  - &me {file: good.stl, id: cycle, tags: [*me]}\n"
        f"  - {{file: good.stl, id: deep_map, tags: {'{a: ' * 80}1{'}' * 80}}}\n"
        "  - {file: good.stl, id: last}\n"
    )
    _write(lib, text)
    start = time.perf_counter()
    result = load_library(lib)
    elapsed = time.perf_counter() - start
    assert [a.id for a in result.assets] == ["first", "last"]
    reasons = _reasons(result)
    assert "nested more than" in reasons[1] and "nested more than" in reasons[2] and "nested more than" in reasons[5]
    assert "alias" in reasons[3] and "contains itself" in reasons[4]
    assert elapsed < 30, f"{elapsed:.1f} s: reading the nesting must stay linear"


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("- file: good.stl\n", "must be a mapping"),
        ("just text\n", "must be a mapping"),
        ("", "must be a mapping"),
        ("assets: {file: good.stl}\n", "assets"),
        ("unit: furlong\nassets: []\n", "unit"),
        ("up: +z\nfront: -z\nassets: []\n", "perpendicular"),
        ("assets: [unclosed\n", "cannot read the library file"),
        ("name: " + "9" * 5000 + "\nassets: []\n", "digits"),
        ("assets: &a [*a, *a]\nname: &n [*n]\n", "contains itself"),
        ("name: " + "[" * 30_000 + "]" * 30_000 + "\nassets: []\n", "levels deep"),
        ("assets:\n  " + "- " * 30_000 + "x\n", "levels deep"),
        ("assets: " + "[" * 100 + "]" * 100 + "\nname: " + "[" * 100 + "]" * 100 + "\n", "levels deep"),
        ("assets: !!python/object/apply:os.system [echo]\n", "cannot read the library file"),
    ],
)
def test_an_unreadable_library_is_one_clear_error(tmp_path: Path, text: str, words: str) -> None:
    _write(tmp_path, text)
    start = time.perf_counter()
    with pytest.raises(LibraryError, match=words) as caught:
        load_library(tmp_path)
    assert time.perf_counter() - start < 20
    assert "\n" not in str(caught.value)


def test_top_level_alias_bomb_is_refused_without_expanding_it(tmp_path: Path) -> None:
    chain = "".join(f"x{i}: &x{i} [{', '.join([f'*x{i - 1}'] * 9)}]\n" for i in range(1, 10))
    _write(tmp_path, "x0: &x0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + chain + "assets: []\n")
    with pytest.raises(LibraryError, match="alias"):
        load_library(tmp_path)


def test_library_files_that_are_not_regular_small_files(tmp_path: Path) -> None:
    cases = {
        "folder": lambda p: p.mkdir(),
        "device": lambda p: os.symlink("/dev/zero", p),
        "loop": lambda p: os.symlink(p.name, p),
        "fifo": lambda p: os.mkfifo(p),
        "binary": lambda p: p.write_bytes(b"\xff\xfe\x00assets"),
    }
    for name, make in cases.items():
        folder = tmp_path / name
        folder.mkdir()
        make(folder / "library.yaml")
        with pytest.raises(LibraryError) as caught:
            load_library(folder)
        assert "library.yaml" in str(caught.value), name
    big = tmp_path / "big"
    _write(big, "assets: []\n" + "#" * 200)
    with mock.patch.object(library, "MAX_LIBRARY_BYTES", 100), pytest.raises(LibraryError, match="over the limit"):
        load_library(big)
    many = tmp_path / "many"
    _write(many, {"assets": [{"file": "x.stl"}] * (library.MAX_ENTRIES + 1)})
    with pytest.raises(LibraryError, match="assets"):
        load_library(many)


def test_referenced_and_oversized_files_stay_inside_their_bounds(tmp_path: Path) -> None:
    lib = tmp_path / "lib"
    lib.mkdir()
    (tmp_path / "secret.bin").write_bytes(b"\0" * 1024)
    gltf = json.loads(_cube().export(file_type="gltf")["model.gltf"])
    for name, uri in (("escape.gltf", "../secret.bin"), ("device.gltf", "/dev/zero")):
        gltf["buffers"][0]["uri"] = uri
        (lib / name).write_text(json.dumps(gltf))
    (lib / "big.stl").write_bytes(trimesh.creation.icosphere(subdivisions=2, radius=0.05).export(file_type="stl"))
    os.mkfifo(lib / "pipe.stl")
    (lib / "good.ply").write_bytes(_cube().export(file_type="ply"))
    _write(lib, {"assets": [{"file": n} for n in ("escape.gltf", "device.gltf", "big.stl", "pipe.stl", "good.ply")]})
    with mock.patch.object(meshfile, "MAX_MESH_BYTES", 4000):
        result = load_library(lib)
    assert [a.id for a in result.assets] == ["good"]
    reasons = _reasons(result)
    assert "outside the library" in reasons[0] and "outside the library" in reasons[1]
    assert "over the limit" in reasons[2] and "not a regular file" in reasons[3]


@pytest.mark.skipif(importlib.util.find_spec("coacd") is None, reason="coacd not installed")
def test_a_failing_coacd_call_falls_back_and_the_entry_still_imports(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    import sys

    from physcensis.assets import decompose
    from physcensis.assets.decompose import convex_decomposition

    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "good.stl").write_bytes(_cube().export(file_type="stl"))
    (lib / "ridge.stl").write_bytes(_knife_edge_top().export(file_type="stl"))  # concave: needs a decomposition
    _write(lib, {"assets": [{"file": "ridge.stl"}, {"file": "good.stl"}]})
    crash = [sys.executable, "-c", "import sys; sys.stderr.write('RuntimeError: qhull gave up'); sys.exit(1)"]
    with (
        mock.patch.object(library, "convex_decomposition", convex_decomposition),
        mock.patch.object(decompose, "_worker_command", return_value=crash),
    ):
        result = load_library(lib)
    assert result.errors == [] and [a.id for a in result.assets] == ["ridge", "good"]
    assert 1 < len(result.assets[0].collision) <= decompose.MAX_PARTS  # the voxel fallback, not one hull
    assert "CoACD" in caplog.text and "qhull gave up" in caplog.text


def test_fill_holes_dependencies_are_declared() -> None:
    declared = tomllib.loads((REPO / "pyproject.toml").read_text())["project"]["dependencies"]
    names = {d.split(">")[0].split("=")[0].split("<")[0].split("[")[0].strip().lower() for d in declared}
    assert {"networkx", "scipy", "trimesh"} <= names  # fill_holes needs networkx, hulls need scipy
    assert importlib.util.find_spec("networkx") is not None


numbers = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(min_value=-(10**6), max_value=10**6),
    st.booleans(),
)
values = st.recursive(
    st.one_of(numbers, st.none(), st.text(max_size=8)),
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=5), inner, max_size=3),
    max_leaves=12,
)
fields = st.sampled_from(
    ["mass", "friction", "size", "height", "scale", "com_shift", "rgba", "support_probability", "unit", "up", "id"]
    + ["category", "tags", "container", "front"]
)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(entries=st.lists(st.dictionaries(fields, values, max_size=3), min_size=1, max_size=4))
def test_any_entry_fields_give_an_asset_or_that_entrys_error(tmp_path: Path, entries: list[dict]) -> None:
    lib = tmp_path / "fuzz"
    lib.mkdir(exist_ok=True)
    (lib / "cube.stl").write_bytes(_cube().export(file_type="stl"))
    raw = [{"file": "cube.stl", **entry} for entry in entries]
    (lib / "library.json").write_text(json.dumps({"assets": raw}))
    result = load_library(lib)
    assert len(result.assets) + len(result.errors) == len(raw)
    assert all(isinstance(e, EntryError) and "\n" not in str(e) for e in result.errors)
    for asset in result.assets:
        assert asset.mass > 0 and math.isfinite(asset.mass) and all(0 < s <= library.MAX_EXTENT for s in asset.size)
        assert 0 < asset.friction_range[0] <= asset.friction_range[1]


coordinates = st.one_of(
    st.floats(min_value=-2, max_value=2, allow_nan=False),
    st.sampled_from([0.0, 1.0, float("nan"), float("inf"), 1e30]),
)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(
    vertices=st.lists(st.tuples(coordinates, coordinates, coordinates), min_size=0, max_size=10),
    faces=st.lists(st.tuples(*[st.integers(min_value=-2, max_value=11)] * 3), min_size=0, max_size=14),
)
def test_any_mesh_gives_an_asset_or_that_entrys_error(
    tmp_path: Path, vertices: list[tuple[float, float, float]], faces: list[tuple[int, int, int]]
) -> None:
    lib = tmp_path / "meshes"
    lib.mkdir(exist_ok=True)
    (lib / "good.stl").write_bytes(_cube().export(file_type="stl"))
    text = "".join(f"v {x!r} {y!r} {z!r}\n" for x, y, z in vertices)
    text += "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in faces)
    (lib / "fuzz.obj").write_text(text)
    _write(lib, {"assets": [{"file": "fuzz.obj"}, {"file": "good.stl"}]})
    result = load_library(lib)
    assert result.assets[-1].id == "good"
    assert len(result.assets) + len(result.errors) == 2
    for asset in result.assets:
        assert np.isfinite(asset.visual.vertices).all() and asset.mass > 0
        assert all(part.volume > 0 for part in asset.collision)


@settings(max_examples=150, deadline=None)
@given(text=st.text(alphabet=st.sampled_from(list("[]{}:,-&*!? \n\tab1.'\"#|>")), max_size=120))
def test_the_bounded_yaml_reader_reads_what_safe_load_reads(text: str) -> None:
    try:
        expected = repr(yaml.safe_load(text))
    except Exception as exc:  # whatever safe_load raises, the bounded reader raises too
        expected = type(exc).__name__
    try:
        data = bounded.load_yaml(text)
    except Exception as exc:
        assert type(exc).__name__ == expected
        return
    assert repr(data) == expected
    bounded.value_problem(data)  # never raises, never recurses without bound


def test_cli_import_lists_each_failure_and_sets_the_exit_code(tmp_path: Path, cache_dir: Path) -> None:
    lib = _hostile_mesh_library(tmp_path)
    result = runner.invoke(assets_app, ["import", str(lib)])
    assert result.exit_code == 1, result.output
    assert "ok  good:" in result.output and "ok  holed:" in result.output
    assert "4 assets imported, 23 failed" in result.output
    failed = [line for line in result.output.splitlines() if line.startswith("failed")]
    assert len(failed) == 23 and any("flat.obj (assets[1]): the mesh is flat" in line for line in failed)
    assert "Traceback" not in result.output
    as_json = runner.invoke(assets_app, ["import", str(lib), "--json"])
    payload = json.loads(as_json.stdout)
    assert as_json.exit_code == 1 and len(payload["imported"]) == 4 and len(payload["failed"]) == 23
    assert {"entry", "reason"} == set(payload["failed"][0])

    good = tmp_path / "good"
    good.mkdir()
    (good / "cube.stl").write_bytes(_cube().export(file_type="stl"))
    _write(good, {"assets": [{"file": "cube.stl"}]})
    assert runner.invoke(assets_app, ["import", str(good)]).exit_code == 0

    bomb = _write(tmp_path / "bomb", "assets: " + "[" * 30_000 + "]" * 30_000 + "\n")
    unreadable = runner.invoke(assets_app, ["import", str(bomb)])
    assert unreadable.exit_code == 2 and "levels deep" in unreadable.output and "Traceback" not in unreadable.output
    assert len(unreadable.output.strip().splitlines()) == 1
