"""Golden files: the MJCF and URDF exports of a fixed scene, compared structurally with what was committed.

`golden/scene.json` is the input: a stack of two books, a bowl holding two apples and a mug on a table (made once by
solving `golden/program.json` with seed 0; it is kept as a file so that a change to the solvers does not change it).
Its exports are compared with `golden/mjcf/scene.xml`, `golden/urdf/*.urdf` and `golden/urdf/bodies.json` element by
element, attribute by attribute and number by number (within NUMBERS_REL / NUMBERS_ABS), and every mesh file with
`golden/meshes.json` by its vertex count and bounds. A mass, a pose, a geom size or a body that changes fails here.

After a deliberate change to an exporter (or to the assets), regenerate the golden files and review their diff:

    PHYSCENSIS_REGEN_GOLDEN=1 .venv/bin/python -m pytest tests/export/test_golden.py
"""

from __future__ import annotations

import json
import math
import os
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from physcensis.export import export_scene
from physcensis.scene import load_scene

GOLDEN = Path(__file__).with_name("golden")
REGENERATE = os.environ.get("PHYSCENSIS_REGEN_GOLDEN") == "1"
FORMATS = ("mjcf", "urdf")
TEXT_SUFFIXES = {".xml", ".urdf", ".json"}  # compared structurally; every other file is a mesh, summarised
MESHES = "meshes.json"
# MJCF writes numbers with 6 significant digits: a value that moved by 1e-7 may round the other way in the last digit.
NUMBERS_REL = 1e-5
NUMBERS_ABS = 1e-9  # for values that are zero up to round-off (MuJoCo's mesh centring leaves 1e-16 m offsets)
MESH_BOUNDS_ABS = 1e-6  # metres; mesh files hold float32 coordinates
# Attributes that may be left out when they hold their default (MJCF omits a zero pos or a unit quat).
DEFAULTS = {"pos": "0 0 0", "quat": "1 0 0 0", "xyz": "0 0 0", "rpy": "0 0 0"}


# -- comparing two export folders -----------------------------------------------------------------------------------


def differences(expected: Path, actual: Path) -> list[str]:
    """How the export in `actual` differs from the golden files in `expected` (empty when it matches)."""
    found: list[str] = []
    expected_files, actual_files = _text_files(expected), _text_files(actual)
    found += [f"{name}: missing" for name in sorted(expected_files - actual_files)]
    found += [f"{name}: not expected" for name in sorted(actual_files - expected_files)]
    for name in sorted(expected_files & actual_files):
        if name.endswith(".json"):
            _compare_json(
                json.loads((expected / name).read_text()), json.loads((actual / name).read_text()), name, found
            )
        else:
            _compare_xml(ET.parse(expected / name).getroot(), ET.parse(actual / name).getroot(), name, found)
    _compare_json(
        json.loads((expected / MESHES).read_text()), mesh_summaries(actual), MESHES, found, abs_tol=MESH_BOUNDS_ABS
    )
    return found


def _text_files(folder: Path) -> set[str]:
    return {
        str(p.relative_to(folder))
        for f in FORMATS
        for p in (folder / f).rglob("*")
        if p.is_file() and p.suffix in TEXT_SUFFIXES
    }


def _compare_xml(expected: ET.Element, actual: ET.Element, where: str, found: list[str]) -> None:
    where = f"{where}/{_label(expected)}"
    if expected.tag != actual.tag:
        found.append(f"{where}: <{actual.tag}> instead")
        return
    for key in sorted(expected.attrib.keys() | actual.attrib.keys()):
        _compare_text(expected.get(key, DEFAULTS.get(key)), actual.get(key, DEFAULTS.get(key)), f"{where}@{key}", found)
    _compare_text((expected.text or "").strip() or None, (actual.text or "").strip() or None, f"{where}#text", found)
    expected_children, actual_children = _children(expected), _children(actual)
    found += [f"{where}/{key}: missing" for key in expected_children if key not in actual_children]
    found += [f"{where}/{key}: not expected" for key in actual_children if key not in expected_children]
    for key, child in expected_children.items():
        if key in actual_children:
            _compare_xml(child, actual_children[key], where, found)


def _label(element: ET.Element) -> str:
    name = element.get("name")
    return f"{element.tag}[{name}]" if name is not None else element.tag


def _children(element: ET.Element) -> dict[str, ET.Element]:
    """Children by tag and name (or position among the unnamed children of that tag): a dropped body is named,
    and does not shift every comparison after it."""
    keyed: dict[str, ET.Element] = {}
    unnamed: dict[str, int] = {}
    for child in element:
        if child.get("name") is not None:
            key = _label(child)
        else:
            unnamed[child.tag] = unnamed.get(child.tag, -1) + 1
            key = f"{child.tag}#{unnamed[child.tag]}"
        keyed[key] = child
    return keyed


def _compare_text(expected: str | None, actual: str | None, where: str, found: list[str]) -> None:
    if expected is None or actual is None:
        if expected != actual:
            found.append(f"{where}: {'missing' if actual is None else 'not expected'}")
        return
    expected_numbers, actual_numbers = _numbers(expected), _numbers(actual)
    if expected_numbers is None or actual_numbers is None:
        if expected != actual:
            found.append(f"{where}: {actual!r}, expected {expected!r}")
    elif not _close(expected_numbers, actual_numbers):
        found.append(f"{where}: {actual}, expected {expected}")


def _numbers(text: str) -> list[float] | None:
    try:
        return [float(word) for word in text.split()]
    except ValueError:
        return None


def _close(expected: list[float], actual: list[float], abs_tol: float = NUMBERS_ABS) -> bool:
    return len(expected) == len(actual) and all(
        math.isclose(e, a, rel_tol=NUMBERS_REL, abs_tol=abs_tol) for e, a in zip(expected, actual, strict=True)
    )


def _compare_json(expected: Any, actual: Any, where: str, found: list[str], abs_tol: float = NUMBERS_ABS) -> None:
    if isinstance(expected, dict) and isinstance(actual, dict):
        found += [f"{where}.{key}: missing" for key in expected if key not in actual]
        found += [f"{where}.{key}: not expected" for key in actual if key not in expected]
        for key in sorted(expected.keys() & actual.keys()):
            _compare_json(expected[key], actual[key], f"{where}.{key}", found, abs_tol)
    elif isinstance(expected, list) and isinstance(actual, list):
        if len(expected) != len(actual):
            found.append(f"{where}: {len(actual)} items, expected {len(expected)}")
            return
        for i, (e, a) in enumerate(zip(expected, actual, strict=True)):
            _compare_json(e, a, f"{where}[{_json_label(e, i)}]", found, abs_tol)
    elif _is_number(expected) and _is_number(actual):
        if not _close([expected], [actual], abs_tol):
            found.append(f"{where}: {actual}, expected {expected}")
    elif expected != actual:
        found.append(f"{where}: {actual!r}, expected {expected!r}")


def _json_label(item: Any, index: int) -> str:
    return str(item["id"]) if isinstance(item, dict) and "id" in item else str(index)


def _is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def mesh_summaries(folder: Path) -> dict[str, dict[str, Any]]:
    """Every mesh file of the exports: its vertex count and bounds ([min xyz, max xyz])."""
    summaries = {}
    for path in sorted(p for f in FORMATS for p in (folder / f).rglob("*") if p.is_file()):
        if path.suffix not in TEXT_SUFFIXES:
            vertices = _vertices(path)
            summaries[str(path.relative_to(folder))] = {
                "vertices": len(vertices),
                "bounds": [
                    [round(float(v), 7) for v in vertices.min(axis=0)],
                    [round(float(v), 7) for v in vertices.max(axis=0)],
                ],
            }
    return summaries


def _vertices(path: Path) -> np.ndarray:
    """The distinct vertices of an OBJ (its `v` lines) or a binary STL file."""
    if path.suffix == ".obj":
        rows = [line.split()[1:4] for line in path.read_text().splitlines() if line.startswith("v ")]
        return np.array(rows, dtype=float).reshape(-1, 3)
    if path.suffix == ".stl":
        triangles = np.frombuffer(
            path.read_bytes(),
            dtype=np.dtype([("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attribute", "<u2")]),
            offset=84,
        )
        return np.unique(triangles["corners"].reshape(-1, 3).astype(float), axis=0)
    raise AssertionError(f"{path}: a mesh format this test does not read; add it to _vertices")


# -- the tests ----------------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def exported(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The MJCF and URDF exports of golden/scene.json, made now (and written over the golden files to regenerate)."""
    out = tmp_path_factory.mktemp("golden_export")
    export_scene(load_scene(GOLDEN / "scene.json"), out, FORMATS)
    if REGENERATE:
        _regenerate(out)
    return out


def _regenerate(out: Path) -> None:
    for fmt in FORMATS:
        shutil.rmtree(GOLDEN / fmt, ignore_errors=True)
        shutil.copytree(
            out / fmt,
            GOLDEN / fmt,
            ignore=lambda folder, names: [
                n for n in names if (Path(folder) / n).is_file() and Path(n).suffix not in TEXT_SUFFIXES
            ],
        )
        for empty in sorted((GOLDEN / fmt).rglob("*"), reverse=True):
            if empty.is_dir() and not any(empty.iterdir()):
                empty.rmdir()
    lines = [f"  {json.dumps(name)}: {json.dumps(summary)}" for name, summary in mesh_summaries(out).items()]
    (GOLDEN / MESHES).write_text("{\n" + ",\n".join(lines) + "\n}\n")  # one mesh a line: diffs that read


def test_the_golden_scene_has_a_stack_and_a_container() -> None:
    scene = load_scene(GOLDEN / "scene.json")
    placements = {o.id: (o.placement.predicate, o.placement.target) for o in scene.placed if o.placement}
    assert placements["book_1"] == ("PLACE-ON", "book_0")
    assert [o for o, p in placements.items() if p == ("PLACE-IN", "bowl_0")] == ["apple_bowl_0_0", "apple_bowl_0_1"]
    assert len(scene.placed) == 6


def test_the_exports_match_the_golden_files(exported: Path) -> None:
    found = differences(GOLDEN, exported)
    assert found == [], "\n".join(found[:40]) + "\n(after a deliberate change: PHYSCENSIS_REGEN_GOLDEN=1, see the top)"


def test_the_golden_files_cover_both_formats_and_every_body() -> None:
    """Not an empty or partial golden folder that would match anything."""
    mjcf = ET.parse(GOLDEN / "mjcf" / "scene.xml").getroot()
    assert {b.get("name") for b in mjcf.iter("body")} == {
        "support",
        "book_0",
        "book_1",
        "bowl_0",
        "mug_0",
        "apple_bowl_0_0",
        "apple_bowl_0_1",
    }
    bodies = json.loads((GOLDEN / "urdf" / "bodies.json").read_text())["bodies"]
    assert all((GOLDEN / "urdf" / b["urdf"]).is_file() for b in bodies) and len(bodies) == 8
    meshes = json.loads((GOLDEN / MESHES).read_text())
    assert any(k.startswith("mjcf/") for k in meshes) and any(k.startswith("urdf/") for k in meshes)


# -- the comparison catches what it is there for: each mutation of a copy of the export is reported ------------------


def _mutated_copy(exported: Path, tmp_path: Path, name: str, mutate: Any) -> Path:
    copy = tmp_path / "copy"
    shutil.copytree(exported, copy)
    tree = ET.parse(copy / name)
    mutate(tree.getroot())
    tree.write(copy / name)
    return copy


def _scale(element: ET.Element | None, key: str, factor: float) -> None:
    assert element is not None
    element.set(key, " ".join(str(float(v) * factor) for v in element.get(key, "").split()))


def _body(root: ET.Element, name: str) -> ET.Element:
    found = root.find(f".//body[@name='{name}']")
    assert found is not None, name
    return found


def _worldbody(root: ET.Element) -> ET.Element:
    found = root.find("worldbody")
    assert found is not None
    return found


MJCF = "mjcf/scene.xml"
MJCF_MUTATIONS = {
    "mass": (lambda root: _scale(_body(root, "mug_0").find("inertial"), "mass", 1.01), "body[mug_0]/inertial@mass"),
    "pose": (lambda root: _scale(_body(root, "book_1"), "pos", 1.001), "body[book_1]@pos"),
    "geom size": (
        lambda root: _scale(_body(root, "book_0").find("geom[@name='book_0_c0']"), "size", 1.02),
        "geom[book_0_c0]@size",
    ),
    "dropped body": (
        lambda root: _worldbody(root).remove(_body(root, "apple_bowl_0_1")),
        "body[apple_bowl_0_1]: missing",
    ),
}


@pytest.mark.parametrize("mutation", MJCF_MUTATIONS)
def test_a_changed_mjcf_fails_naming_what_changed(exported: Path, tmp_path: Path, mutation: str) -> None:
    mutate, expected = MJCF_MUTATIONS[mutation]
    found = differences(GOLDEN, _mutated_copy(exported, tmp_path, MJCF, mutate))
    assert found and all(MJCF in f for f in found) and any(expected in f for f in found), found


def test_a_changed_urdf_mass_or_pose_or_a_dropped_object_fails(exported: Path, tmp_path: Path) -> None:
    copy = _mutated_copy(
        exported, tmp_path, "urdf/mug_0.urdf", lambda root: _scale(root.find("link/inertial/mass"), "value", 1.01)
    )
    assert any("urdf/mug_0.urdf/robot[mug_0]/link[mug_0]/inertial/mass@value" in f for f in differences(GOLDEN, copy))

    index = copy / "urdf" / "bodies.json"
    data = json.loads(index.read_text())
    data["bodies"] = [b for b in data["bodies"] if b["id"] != "apple_bowl_0_0"]
    next(b for b in data["bodies"] if b["id"] == "book_1")["position"][2] += 0.001
    index.write_text(json.dumps(data))
    (copy / "urdf" / "apple_bowl_0_0.urdf").unlink()
    found = differences(GOLDEN, copy)
    assert "urdf/apple_bowl_0_0.urdf: missing" in found
    assert "urdf/bodies.json.bodies: 7 items, expected 8" in found


def test_a_changed_mesh_fails(exported: Path, tmp_path: Path) -> None:
    copy = tmp_path / "copy"
    shutil.copytree(exported, copy)
    obj = next((copy / "urdf" / "meshes").glob("mug_red_visual_0.obj"))
    obj.write_text("".join(line + "\n" for line in obj.read_text().splitlines() if line != _first_vertex(obj)))
    found = differences(GOLDEN, copy)
    assert any(f.startswith("meshes.json.urdf/meshes/mug_red_visual_0.obj.vertices") for f in found), found


def _first_vertex(obj: Path) -> str:
    return next(line for line in obj.read_text().splitlines() if line.startswith("v "))
