"""Resuming a batch over a folder from elsewhere: what is under scenes/ is read with bounds and checked.

Each case plants one thing in a finished batch folder and resumes it through the real command line (its scenes made
by `stub_scene`): exit code 2, one error line naming the file, no traceback, and the manifest and failures file as
they were. A FIFO must not hang the run, so its test has a timeout of its own.
"""

from __future__ import annotations

import functools
import json
import os
from collections.abc import Callable
from pathlib import Path

import pytest
from click.testing import Result
from typer.testing import CliRunner

import physcensis.batch
from physcensis.batch import FAILURES, MANIFEST, RECORD, SCENES_DIR, Options, read_prompts, run_batch
from physcensis.batch.records import MAX_RECORD_BYTES
from physcensis.cli import app
from tests.batch.stub_scenes import SECONDS_ENV, stub_scene

SCENE = "000-a-cup_000"  # the first of the batch's two scenes


@pytest.fixture
def batch(tmp_path: Path) -> Path:
    """A finished batch of two scenes of "a cup", made by the stub, with an old failure on record."""
    out = tmp_path / "out"
    (tmp_path / "prompts.txt").write_text("a cup\n")
    specs = read_prompts(tmp_path / "prompts.txt")
    run_batch(specs, out, per_prompt=2, options=Options(exports=("none",)), scene_maker=stub_scene)
    (out / FAILURES).write_text(json.dumps({"key": "000-a-cup_009", "ok": False, "reason": "an old failure"}) + "\n")
    return out


def resume(out: Path, monkeypatch: pytest.MonkeyPatch) -> Result:
    """The same command again, over the same folder: a resume."""
    monkeypatch.setattr(physcensis.batch, "run_batch", functools.partial(run_batch, scene_maker=stub_scene))
    monkeypatch.delenv(SECONDS_ENV, raising=False)
    args = ["batch", str(out.parent / "prompts.txt"), "--out", str(out), "--per-prompt", "2", "--export", "none"]
    return CliRunner().invoke(app, args)


def assert_refused(out: Path, result: Result, before: dict[str, str], *words: str) -> None:
    """Exit 2, one line naming the record and what is wrong, no traceback, the batch's own files unchanged."""
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert result.exit_code == 2, result.output
    assert len(lines) == 1 and lines[0].startswith("error: "), result.output
    assert f"{SCENES_DIR}/{SCENE}" in lines[0] and all(word in lines[0] for word in words), lines[0]
    assert "Traceback" not in result.output and isinstance(result.exception, SystemExit)
    assert own_files(out) == before


def own_files(out: Path) -> dict[str, str]:
    return {name: (out / name).read_text() for name in (MANIFEST, FAILURES)}


def record_path(out: Path) -> Path:
    return out / SCENES_DIR / SCENE / RECORD


def test_an_untouched_batch_resumes_with_nothing_to_make(batch: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    before = own_files(batch)
    result = resume(batch, monkeypatch)
    assert result.exit_code == 0, result.output
    assert "0 scene(s) made, 2 already there" in result.output
    assert own_files(batch)[MANIFEST] == before[MANIFEST]


@pytest.mark.timeout(60)  # today's code waits on the FIFO for ever: the test fails instead of hanging the run
def test_a_fifo_record_is_refused_without_hanging(batch: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    before = own_files(batch)
    record_path(batch).unlink()
    os.mkfifo(record_path(batch))
    assert_refused(batch, resume(batch, monkeypatch), before, "not a regular file")


def _huge(path: Path) -> None:
    """Valid JSON of the record's shape, one byte over the limit."""
    record = json.loads(path.read_text())
    record["worker"] = ""
    record["worker"] = "x" * (MAX_RECORD_BYTES + 1 - len(json.dumps(record)))
    path.write_text(json.dumps(record))
    assert path.stat().st_size == MAX_RECORD_BYTES + 1


def _sparse_terabyte(path: Path) -> None:
    with path.open("r+b") as handle:
        handle.truncate(2**40)  # no disk space used; reading it whole would need a terabyte of memory


@pytest.mark.parametrize("make_huge", [_huge, _sparse_terabyte], ids=["over-the-limit", "sparse-terabyte"])
def test_a_huge_record_is_refused_unread(
    batch: Path, monkeypatch: pytest.MonkeyPatch, make_huge: Callable[[Path], None]
) -> None:
    before = own_files(batch)
    try:
        make_huge(record_path(batch))
    except OSError as exc:
        pytest.skip(f"this file system has no room for the file ({exc})")
    assert_refused(batch, resume(batch, monkeypatch), before, "over the limit")


def _wrong_type(record: dict) -> object:
    return {**record, "objects": "many"}


def _extra_field(record: dict) -> object:
    return {**record, "script": "<img src=x onerror=alert(1)>"}


def _not_an_object(record: dict) -> object:
    return [record]


def _missing_field(record: dict) -> object:
    return {k: v for k, v in record.items() if k != "prompt_id"}


def _another_folders(record: dict) -> object:
    return {**record, "key": "000-a-cup_001", "scene": f"{SCENES_DIR}/../../elsewhere"}


@pytest.mark.parametrize(
    ("change", "words"),
    [
        (_wrong_type, ["objects", "valid integer"]),
        (_extra_field, ["script", "Extra inputs are not permitted"]),
        (_not_an_object, ["not an object"]),
        (_missing_field, ["prompt_id", "Field required"]),
        (_another_folders, ["record of '000-a-cup_001'"]),
    ],
    ids=["wrong-type", "extra-field", "not-an-object", "missing-field", "another-folders"],
)
def test_a_record_of_the_wrong_shape_is_refused_not_copied_into_the_manifest(
    batch: Path, monkeypatch: pytest.MonkeyPatch, change: Callable[[dict], object], words: list[str]
) -> None:
    before = own_files(batch)
    record_path(batch).write_text(json.dumps(change(json.loads(record_path(batch).read_text()))))
    assert_refused(batch, resume(batch, monkeypatch), before, *words)


@pytest.mark.parametrize("text", ["", '{"key": "p0_0', "[" * 60_000, "\udcff"], ids=["empty", "torn", "deep", "bytes"])
def test_a_record_that_is_not_json_is_refused(batch: Path, monkeypatch: pytest.MonkeyPatch, text: str) -> None:
    before = own_files(batch)
    record_path(batch).write_bytes(text.encode("utf-8", "surrogateescape"))
    assert_refused(batch, resume(batch, monkeypatch), before, "not a scene record")


def test_a_record_of_an_unplanned_scene_is_checked_too(batch: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A folder no planned scene has (a run with more scenes per prompt) is listed in the manifest as it is: its
    record must be one."""
    before = own_files(batch)
    stray = batch / SCENES_DIR / "zz_999"
    stray.mkdir()
    (stray / RECORD).write_text(json.dumps({"key": "zz_999", "anything": ["at", "all"]}))
    result = resume(batch, monkeypatch)
    assert result.exit_code == 2 and f"{SCENES_DIR}/zz_999/{RECORD}" in result.output, result.output
    assert own_files(batch) == before


def test_a_symlinked_record_is_refused_and_not_read(batch: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The link leads to a record of the right shape outside the folder: a resume still reads only the folder."""
    before = own_files(batch)
    outside = batch.parent / "elsewhere.json"
    outside.write_text(record_path(batch).read_text())
    record_path(batch).unlink()
    record_path(batch).symlink_to(outside)
    assert_refused(batch, resume(batch, monkeypatch), before, "symbolic link")


def test_a_symlinked_scene_folder_is_refused(batch: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    before = own_files(batch)
    folder = batch / SCENES_DIR / SCENE
    folder.rename(batch.parent / "moved")
    folder.symlink_to(batch.parent / "moved", target_is_directory=True)
    assert_refused(batch, resume(batch, monkeypatch), before, "symbolic link")


def test_a_symlinked_scenes_folder_is_refused_and_nothing_written_through_it(
    batch: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    elsewhere = batch.parent / "elsewhere"
    elsewhere.mkdir()
    (batch / SCENES_DIR).rename(batch.parent / "old-scenes")
    (batch / SCENES_DIR).symlink_to(elsewhere, target_is_directory=True)
    before = own_files(batch)
    result = resume(batch, monkeypatch)
    assert result.exit_code == 2 and "symbolic link" in result.output, result.output
    assert own_files(batch) == before and not any(elsewhere.iterdir())


def test_a_folder_without_a_record_is_made_again(batch: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    record_path(batch).unlink()
    result = resume(batch, monkeypatch)
    assert result.exit_code == 0, result.output
    assert "1 scene(s) made, 1 already there" in result.output
    assert json.loads(record_path(batch).read_text())["key"] == SCENE


def test_too_many_entries_in_scenes_are_refused(batch: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("physcensis.batch.driver.MAX_SCENE_ENTRIES", 3)
    for k in range(5):
        (batch / SCENES_DIR / f"notes_{k}.txt").write_text("")
    before = own_files(batch)
    result = resume(batch, monkeypatch)
    assert result.exit_code == 2 and "more than 5 entries" in result.output, result.output
    assert own_files(batch) == before


def test_a_huge_failures_file_is_refused(batch: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    with (batch / FAILURES).open("r+b") as handle:
        handle.truncate(2**40)
    before_manifest = (batch / MANIFEST).read_text()
    result = resume(batch, monkeypatch)
    assert result.exit_code == 2 and f"{FAILURES} has" in result.output and "over the limit" in result.output
    assert (batch / MANIFEST).read_text() == before_manifest
