"""`physcensis report` over a folder from elsewhere: it reads only regular files inside the folder, follows no link,
and embeds only real images of bounded size.

Each case plants one thing in a folder whose report was written before, and runs the real command line again: exit
code 2, one error line naming the file and what is wrong, no traceback, and the folder as it was (the page unchanged,
nothing added).
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from click.testing import Result
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.gallery import INDEX_NAME
from tests.gallery.folders import results_file, row, scene_folder, tiny_png

SECRET = "SECRET-TOKEN-0451"
runner = CliRunner()


def report(folder: Path, *options: str) -> Result:
    return runner.invoke(app, ["report", str(folder), *options])


def snapshot(folder: Path) -> dict[str, bytes | str]:
    """Every entry under `folder`: a file's bytes, what a link points at, or a folder's mark."""
    entries: dict[str, bytes | str] = {}
    for path in sorted(folder.rglob("*")):
        name = str(path.relative_to(folder))
        if path.is_symlink():
            entries[name] = "-> " + os.readlink(path)
        elif path.is_file():
            entries[name] = path.read_bytes()
        else:
            entries[name] = "folder" if path.is_dir() else "special"
    return entries


def assert_refused(folder: Path, result: Result, before: dict[str, bytes | str], *words: str) -> None:
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert result.exit_code == 2, result.output
    assert len(lines) == 1 and lines[0].startswith("error: "), result.output
    assert all(word in lines[0] for word in words), lines[0]
    assert "Traceback" not in result.output and isinstance(result.exception, SystemExit)
    assert snapshot(folder) == before
    assert SECRET not in (folder / INDEX_NAME).read_text()


@pytest.fixture
def outside(tmp_path: Path) -> Path:
    """Files beside the report's folder that the report must never read: a secret, and a scene folder."""
    folder = tmp_path / "outside"
    folder.mkdir()
    (folder / "secret.txt").write_text(f"{SECRET}\n")
    (folder / "scene.json").write_text(json.dumps({"format": "physcensis.scene/1", "prompt": SECRET}))
    (folder / "render.png").write_bytes(tiny_png(5, 5, (1, 2, 3)))
    return folder


@pytest.fixture
def scenes(tmp_path: Path) -> Path:
    """A folder of two scene folders whose report was written before."""
    folder = tmp_path / "report"
    scene_folder(folder / "a", prompt="a mug on a coaster")
    scene_folder(folder / "b", prompt="two books")
    assert report(folder, "--embed").exit_code == 0
    return folder


@pytest.fixture
def compared(tmp_path: Path) -> Path:
    """eval compare's layout: results.jsonl naming its scene folders, and its report written before."""
    folder = tmp_path / "compared"
    scene_folder(folder / "scenes" / "ours" / "mug" / "seed0")
    results_file(folder, [row("a mug", "ours", 0, "scenes/ours/mug/seed0", {"relation_accuracy": 1.0})])
    assert report(folder, "--embed").exit_code == 0
    return folder


# ---- links ----------------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("embed", [True, False], ids=["embed", "linked"])
def test_a_render_linked_to_a_file_outside_is_refused(scenes: Path, outside: Path, embed: bool) -> None:
    render = scenes / "a" / "render.png"
    render.unlink()
    render.symlink_to(outside / "secret.txt")
    before = snapshot(scenes)
    assert_refused(scenes, report(scenes, *["--embed"] * embed), before, str(render), "symbolic link")


def test_a_link_that_stays_inside_the_folder_is_refused_too(scenes: Path) -> None:
    """physcensis writes no link into a scene folder: one there is nobody's of ours, wherever it leads."""
    layout = scenes / "a" / "layout.png"
    layout.unlink()
    layout.symlink_to(scenes / "b" / "layout.png")
    before = snapshot(scenes)
    assert_refused(scenes, report(scenes, "--embed"), before, str(layout), "symbolic link")


def test_a_scene_file_linked_outside_is_refused(scenes: Path, outside: Path) -> None:
    scene = scenes / "b" / "scene.json"
    scene.unlink()
    scene.symlink_to(outside / "scene.json")
    before = snapshot(scenes)
    assert_refused(scenes, report(scenes), before, str(scene), "symbolic link")


def test_a_linked_results_file_is_refused(compared: Path, tmp_path: Path) -> None:
    results = compared / "results.jsonl"
    elsewhere = tmp_path / "elsewhere.jsonl"
    results.rename(elsewhere)
    results.symlink_to(elsewhere)
    before = snapshot(compared)
    assert_refused(compared, report(compared, "--embed"), before, str(results), "symbolic link")


def test_a_row_through_a_linked_folder_is_refused(compared: Path, outside: Path) -> None:
    (compared / "linked").symlink_to(outside, target_is_directory=True)
    results_file(compared, [row("a mug", "ours", 0, "linked", {})])
    before = snapshot(compared)
    assert_refused(compared, report(compared, "--embed"), before, str(compared / "linked"), "symbolic link")


# ---- paths in results rows ------------------------------------------------------------------------------------------


@pytest.mark.parametrize("how", ["parent", "absolute", "nested-parent"])
def test_a_row_pointing_outside_the_folder_is_refused(compared: Path, outside: Path, how: str) -> None:
    scene_dir = {
        "parent": "../outside",
        "absolute": str(outside),
        "nested-parent": "scenes/../../outside",
    }[how]
    results_file(compared, [row("a mug", "ours", 0, scene_dir, {})])
    before = snapshot(compared)
    result = report(compared, "--embed")
    assert_refused(compared, result, before, "results.jsonl: line 1", "scene_dir", "not a relative path inside")


def test_a_row_whose_scene_dir_is_not_text_is_refused(compared: Path) -> None:
    results_file(compared, [row("a mug", "ours", 0, "x", {}) | {"scene_dir": {"path": "/etc"}}])
    before = snapshot(compared)
    assert_refused(compared, report(compared), before, "results.jsonl: line 1", "scene_dir is not a text")


# ---- what an embedded image is -------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "content",
    [f"{SECRET}\n".encode(), b"<svg xmlns='http://www.w3.org/2000/svg'><script>alert(1)</script></svg>", b""],
    ids=["text", "svg", "empty"],
)
def test_a_render_that_is_not_an_image_is_not_embedded(scenes: Path, content: bytes) -> None:
    render = scenes / "a" / "render.png"
    render.write_bytes(content)
    before = snapshot(scenes)
    assert_refused(scenes, report(scenes, "--embed"), before, str(render), "not a PNG or JPEG")


def test_a_jpeg_is_embedded_as_a_jpeg(scenes: Path) -> None:
    (scenes / "a" / "render.png").write_bytes(b"\xff\xd8\xff\xe0" + b"\x00" * 60)
    assert report(scenes, "--embed").exit_code == 0
    assert "data:image/jpeg;base64,/9j/4" in (scenes / INDEX_NAME).read_text()


def test_an_image_over_the_limit_is_refused(scenes: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("physcensis.gallery.page.MAX_IMAGE_BYTES", 100)
    render = scenes / "a" / "render.png"
    render.write_bytes(tiny_png(200, 200, (9, 9, 9)) + b"\x00" * 100)
    before = snapshot(scenes)
    assert_refused(scenes, report(scenes, "--embed"), before, str(render), "over the limit of 100")


def test_images_adding_up_to_too_much_are_refused(scenes: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("physcensis.gallery.page.MAX_EMBED_BYTES", 200)
    before = snapshot(scenes)
    assert_refused(scenes, report(scenes, "--embed"), before, str(scenes), "add up to more than 200", "without --embed")
    assert report(scenes).exit_code == 0  # linked, the page is small whatever the images


@pytest.mark.timeout(60)  # a FIFO opened for reading without O_NONBLOCK waits for a writer for ever
@pytest.mark.parametrize("embed", [True, False], ids=["embed", "linked"])
def test_a_render_that_is_a_fifo_is_refused_without_hanging(scenes: Path, embed: bool) -> None:
    render = scenes / "a" / "render.png"
    render.unlink()
    os.mkfifo(render)
    before = snapshot(scenes)
    assert_refused(scenes, report(scenes, *["--embed"] * embed), before, str(render), "not a regular file")


# ---- JSON files of scene folders ------------------------------------------------------------------------------------


def test_a_scene_file_too_large_is_refused(scenes: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("physcensis.gallery.cards.MAX_JSON_BYTES", 1000)
    report_json = scenes / "b" / "report.json"
    report_json.write_text(json.dumps({"ok": True, "problems": [{"message": "x" * 2000}]}))
    before = snapshot(scenes)
    assert_refused(scenes, report(scenes), before, str(report_json), "over the limit of 1,000")


def test_a_scene_file_nested_too_deeply_is_a_damaged_card_not_a_traceback(scenes: Path) -> None:
    (scenes / "b" / "scene.json").write_text("[" * 100_000)
    result = report(scenes)
    assert result.exit_code == 0, result.output
    assert "scene.json could not be read" in (scenes / INDEX_NAME).read_text()


def test_too_many_cards_are_refused(compared: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("physcensis.gallery.cards.MAX_CARDS", 2)
    results_file(compared, [row("a mug", "ours", seed, "scenes/ours/mug/seed0", {}) for seed in range(3)])
    before = snapshot(compared)
    assert_refused(compared, report(compared), before, "results.jsonl", "more than 2 rows")
