"""Fuzz the MJCF export reader: `read_scene_folder` (scene.json, exports.json and mjcf/ read with bounds and checked
against each other), then `build_world` (what `demo` does next: MuJoCo compiles the export with the robot).

The seed is a real scene folder exported to MJCF. One of its files is damaged: mjcf/scene.xml (attributes, tags,
lines, hostile snippets, bytes), exports.json or scene.json (JSON structure, bytes), or a mesh (bytes). Half the
examples drop exports.json, as a folder written before exports carried one: the files' hashes are then not checked,
so damaged XML and meshes reach the XML walk and MuJoCo.
"""

from __future__ import annotations

import json
import tempfile
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.fuzz.harness import FUZZ, TIMEOUT, Blob, copy_folder, read_safely, size_on_disk
from tests.fuzz.mutations import mutated_bytes, mutated_json, mutated_xml
from tests.fuzz.readers import read_and_build

pytestmark = [pytest.mark.fuzz, TIMEOUT]
XML = "mjcf/scene.xml"
NOT_READ_HERE = ("assets", "layout.png", "report.json")


def _damaged(draw: st.DrawFn, seed: Path, target: str) -> bytes:
    data = (seed / target).read_bytes()
    if target == XML:
        return draw(mutated_xml(data))
    if target.endswith(".json"):
        return draw(mutated_json(json.loads(data)))
    return draw(mutated_bytes(data))


@st.composite
def damaged_folders(draw: st.DrawFn, seed: Path) -> tuple[str, bytes, bool]:
    """(the file damaged, its new content, whether exports.json is dropped)."""
    meshes = sorted(p.relative_to(seed).as_posix() for p in (seed / "mjcf" / "meshes").iterdir())
    target = draw(st.sampled_from([XML, XML, XML, "exports.json", "scene.json"]) | st.sampled_from(meshes))
    drop_manifest = target != "exports.json" and draw(st.booleans())
    return target, Blob(_damaged(draw, seed, target)), drop_manifest


@FUZZ
@given(data=st.data())
def test_a_damaged_export_is_read_or_refused(scene_seed: Path, data: st.DataObject) -> None:
    target, content, drop_manifest = data.draw(damaged_folders(scene_seed), label="damage")
    with tempfile.TemporaryDirectory() as tmp:
        skip = (*NOT_READ_HERE, "exports.json") if drop_manifest else NOT_READ_HERE
        folder = copy_folder(scene_seed, Path(tmp) / "scene", skip=skip)
        (folder / target).write_bytes(content)
        read_safely(lambda: read_and_build(folder), size_on_disk([folder]), keep=folder)
