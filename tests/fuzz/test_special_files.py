"""Every reader, with a special file where it expects a file it reads (or a folder it walks): a FIFO, a link out of
the folder, a link that stays inside it, a folder, an empty file, a sparse file of a terabyte. Each is read or refused
like any input (`read_safely`): one line, no traceback, no hang, no allocation out of proportion."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from physcensis.batch import FAILURES, MANIFEST, RECORD, SCENES_DIR
from tests.fuzz.conftest import COPY
from tests.fuzz.harness import copy_folder, read_safely, size_on_disk
from tests.fuzz.readers import reader_for
from tests.fuzz.test_mjcf_reader import XML

pytestmark = [pytest.mark.fuzz, pytest.mark.timeout(60, method="thread")]
KINDS = ["fifo", "link-out", "link-in", "folder", "empty", "sparse"]
BATCH_SCENE = f"{SCENES_DIR}/000-a-cup_000"
# target -> (the seed fixture, the files and folders to replace)
PLACES = {
    "program": ("example_program_folder", ["desk_basic.json"]),
    "scene": ("scene_seed", ["scene.json", COPY, "assets"]),
    "mjcf": ("scene_seed", ["scene.json", "exports.json", XML, "mjcf", "mjcf/meshes/lib_block__v0.stl"]),
    "batch": ("batch_seed", [f"{BATCH_SCENE}/{RECORD}", MANIFEST, FAILURES, BATCH_SCENE, SCENES_DIR]),
    "report": ("report_seed", ["results.jsonl", "ours/s0/render.png", "ours/s0/layout.png", "ours"]),
    "report-folders": ("report_seed", ["ours/s0/scene.json", "ours/s0/report.json", "ours/s0/batch.json", "ours/s0"]),
}
CASES = [(target, place, kind) for target, (_, places) in PLACES.items() for place in places for kind in KINDS]


def _remove(path: Path) -> None:
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path)
    else:
        path.unlink()


def make_special(folder: Path, place: str, kind: str, outside: Path) -> None:
    """Put a special `kind` of file at `folder/place`; a link leads to the original, moved out or aside."""
    path = folder / place
    if kind in ("link-out", "link-in"):
        moved = outside / path.name if kind == "link-out" else path.with_name(f"moved-{path.name}")
        path.rename(moved)
        path.symlink_to(moved if kind == "link-out" else moved.name)
        return
    was_folder = path.is_dir()
    _remove(path)
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "folder" and not was_folder:
        path.mkdir()
    elif kind == "sparse":
        with path.open("wb") as handle:
            handle.truncate(2**40)  # no disk space used; reading it whole would need a terabyte
    else:  # empty, or "folder" where a folder was: an empty one
        path.mkdir() if was_folder else path.touch()


@pytest.mark.parametrize(("target", "place", "kind"), CASES, ids=[f"{t}:{p}:{k}" for t, p, k in CASES])
def test_a_special_file_is_read_or_refused(
    request: pytest.FixtureRequest, tmp_path: Path, target: str, place: str, kind: str
) -> None:
    seed: Path = request.getfixturevalue(PLACES[target][0])
    folder = copy_folder(seed, tmp_path / "folder")
    (tmp_path / "outside").mkdir()
    try:
        make_special(folder, place, kind, tmp_path / "outside")
    except OSError as exc:
        pytest.skip(f"this file system cannot hold a {kind} ({exc})")
    if target == "report-folders":  # without results.jsonl, the cards come from the scene folders' files
        (folder / "results.jsonl").unlink()
    read_safely(reader_for(target.removesuffix("-folders"), folder, seed), size_on_disk([folder]), keep=folder)
