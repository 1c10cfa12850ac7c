"""Fuzz the scene folder reader: `open_scene(folder)` (what render, export, stability and eval settle call) and
`load_scene`, on a real scene folder whose scene.json, or whose asset copy `assets/lib_block.npz`, is damaged.

A damaged copy is recorded in scene.json with its own hash, as a folder crafted on purpose would be. A scene that is
accepted is also built into a MuJoCo model (what `render` does next): the reader's checks must have refused whatever
the engine cannot use.
"""

from __future__ import annotations

import hashlib
import json
import tempfile
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from physcensis.scene import load_scene
from tests.fuzz.conftest import ASSET_ID, COPY
from tests.fuzz.harness import FUZZ, TIMEOUT, Blob, copy_folder, read_safely, size_on_disk
from tests.fuzz.mutations import mutated_json
from tests.fuzz.npz_mutations import NpzSeed, mutated_npz
from tests.fuzz.readers import NPZ_READER, open_and_build

pytestmark = [pytest.mark.fuzz, TIMEOUT]
NOT_READ_HERE = ("mjcf", "exports.json", "layout.png", "report.json")


@pytest.fixture(scope="module")
def scene_document(scene_seed: Path) -> dict[str, Any]:
    return json.loads((scene_seed / "scene.json").read_text())


@pytest.fixture(scope="module")
def npz_seed(scene_seed: Path) -> NpzSeed:
    return NpzSeed.of((scene_seed / COPY).read_bytes())


@FUZZ
@given(data=st.data())
def test_a_damaged_scene_file_is_read_or_refused(
    scene_seed: Path, scene_document: dict[str, Any], data: st.DataObject
) -> None:
    raw = data.draw(mutated_json(scene_document).map(Blob), label="scene.json")
    with tempfile.TemporaryDirectory() as tmp:
        folder = copy_folder(scene_seed, Path(tmp) / "scene", skip=NOT_READ_HERE)
        (folder / "scene.json").write_bytes(raw)
        size = size_on_disk([folder])
        read_safely(lambda: open_and_build(folder), size, keep=folder)
        read_safely(lambda: load_scene(folder / "scene.json"), size, keep=folder)


def _with_copy(folder: Path, document: dict[str, Any], payload: bytes) -> None:
    """The folder's copy of the library asset replaced by `payload`, its hash recorded in scene.json."""
    (folder / COPY).write_bytes(payload)
    document = json.loads(json.dumps(document))
    document["assets"][ASSET_ID]["sha256"] = hashlib.sha256(payload).hexdigest()
    (folder / "scene.json").write_text(json.dumps(document))


@pytest.mark.skipif(not NPZ_READER, reason="the bounded reader of asset copies (assets/npz.py) is not there yet")
@FUZZ
@given(data=st.data())
def test_a_damaged_asset_copy_is_read_or_refused(
    scene_seed: Path, scene_document: dict[str, Any], npz_seed: NpzSeed, data: st.DataObject
) -> None:
    payload = data.draw(mutated_npz(npz_seed).map(Blob), label=COPY)
    with tempfile.TemporaryDirectory() as tmp:
        folder = copy_folder(scene_seed, Path(tmp) / "scene", skip=NOT_READ_HERE)
        _with_copy(folder, scene_document, payload)
        read_safely(lambda: open_and_build(folder), size_on_disk([folder]), keep=folder)
