"""Output locations: nothing physcensis did not write is ever deleted, and bad locations fail before any work."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.fileio import (
    OWNER_FILE,
    OutputError,
    check_output_dir,
    output_directory,
    owned_entries,
    remove_leftovers,
)
from physcensis.output import write_solution
from physcensis.program import load_program
from physcensis.solver.pipeline import Solution, solve

from .conftest import EXAMPLES

runner = CliRunner()
PROGRAM = EXAMPLES / "books_stack.json"
NOT_A_PID = 99_999_999  # above any pid_max


def _solve_cli(out: Path | str, *extra: str) -> object:
    return runner.invoke(app, ["solve", str(PROGRAM), "--out", str(out), "--no-physics", *extra])


def _one_line_error(result: object) -> str:
    output = result.output  # type: ignore[attr-defined]
    assert "Traceback" not in output
    assert result.exception is None or isinstance(result.exception, SystemExit)  # type: ignore[attr-defined]
    return output


@pytest.fixture(scope="module")
def solution() -> Solution:
    return solve(load_program(PROGRAM), physics=False)


def test_a_users_folder_is_refused_and_left_as_it_was(tmp_path: Path) -> None:
    out = tmp_path / "thesis"
    out.mkdir()
    (out / "chapter1.tex").write_text("precious")
    (out / "figures").mkdir()
    (out / "figures" / "plot.pdf").write_bytes(b"%PDF")
    result = _solve_cli(out)
    assert result.exit_code == 2
    assert "not a physcensis output" in _one_line_error(result) and "--overwrite" in result.output
    assert sorted(p.name for p in out.iterdir()) == ["chapter1.tex", "figures"]
    assert (out / "chapter1.tex").read_text() == "precious"


def test_overwrite_replaces_only_physcensis_files(tmp_path: Path) -> None:
    out = tmp_path / "mixed"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    (out / "scene.json").write_text("an old file of the same name")
    result = _solve_cli(out, "--overwrite")
    assert result.exit_code in (0, 1), result.output
    assert (out / "notes.txt").read_text() == "mine"
    assert json.loads((out / "scene.json").read_text())["format"].startswith("physcensis.scene/")
    owned = json.loads((out / OWNER_FILE).read_text())["entries"]
    assert "scene.json" in owned and "notes.txt" not in owned
    # running again (no --overwrite needed any more? the folder still holds notes.txt, so it is needed)
    assert _solve_cli(out).exit_code == 2
    assert _solve_cli(out, "--overwrite").exit_code in (0, 1)
    assert (out / "notes.txt").read_text() == "mine"


def test_an_earlier_output_is_replaced_whole_and_stale_outputs_go(tmp_path: Path, solution: Solution) -> None:
    out = tmp_path / "scene"
    write_solution(solution, out, physics_outputs=False, extra_files={"transcript.jsonl": "{}\n"})
    assert (out / "transcript.jsonl").exists()
    write_solution(solution, out, physics_outputs=False)
    assert not (out / "transcript.jsonl").exists()  # physcensis wrote it, and this run did not: it is stale
    assert set(json.loads((out / OWNER_FILE).read_text())["entries"]) == {p.name for p in out.iterdir()} - {OWNER_FILE}


def test_a_legacy_output_without_the_owner_file_is_recognised(tmp_path: Path, solution: Solution) -> None:
    out = tmp_path / "old"
    write_solution(solution, out, physics_outputs=False)
    (out / OWNER_FILE).unlink()
    assert check_output_dir(out) == out.resolve()
    (out / "mine.txt").write_text("x")
    with pytest.raises(OutputError, match="mine.txt"):
        check_output_dir(out)


@pytest.mark.parametrize("kind", ["file", "symlink-to-folder", "symlink-to-file", "dangling-symlink"])
def test_out_naming_a_file_or_a_link_is_refused_untouched(tmp_path: Path, kind: str) -> None:
    target = tmp_path / "target"
    if kind == "file" or kind == "symlink-to-file":
        target.write_text("keep me")
    elif kind == "symlink-to-folder":
        target.mkdir()
        (target / "inside.txt").write_text("keep me")
    out = target if kind == "file" else tmp_path / "link"
    if kind != "file":
        out.symlink_to(target)
    result = _solve_cli(out)
    assert result.exit_code == 2
    assert ("symbolic link" in result.output) or ("not a folder" in result.output)
    _one_line_error(result)
    if kind == "file" or kind == "symlink-to-file":
        assert target.read_text() == "keep me"
    if kind == "symlink-to-folder":
        assert [p.name for p in target.iterdir()] == ["inside.txt"]
    if kind != "file":
        assert out.is_symlink()


@pytest.mark.parametrize("where", ["/proc/physcensis-out", "/proc/self/status/x", "FILE/sub", "/"])
def test_unwritable_locations_fail_before_the_solve(tmp_path: Path, where: str) -> None:
    blocker = tmp_path / "a_file"
    blocker.write_text("x")
    out = where.replace("FILE", str(blocker))
    result = runner.invoke(app, ["solve", str(PROGRAM), "--out", out])  # with physics: a solve would take seconds
    assert result.exit_code == 2
    assert "solving" not in result.output
    assert out.split("/")[-1] in result.output or "root" in result.output
    _one_line_error(result)


def test_dot_and_dotdot_are_the_folders_they_name(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    work = tmp_path / "work"
    work.mkdir()
    (work / "data.csv").write_text("1,2")
    monkeypatch.chdir(work)  # the relative names are read from the working folder, as in a shell
    for out in (".", "d/..", str(work) + "/sub/.."):
        result = _solve_cli(out)
        assert result.exit_code == 2, result.output
        _one_line_error(result)
        assert "not a physcensis output" in result.stderr
    result = _solve_cli(".", "--overwrite")
    assert result.exit_code in (0, 1), result.output
    assert (work / "data.csv").read_text() == "1,2" and (work / "scene.json").is_file()
    assert work.is_dir() and not any(p.name.endswith((".old", ".partial")) for p in tmp_path.iterdir())


def test_leftovers_of_a_killed_run_are_removed_by_the_next(tmp_path: Path) -> None:
    out = tmp_path / "scene"
    partial = tmp_path / ".scene.k3j4h5xx.partial"  # an earlier version's staging name
    partial.mkdir()
    (partial / "scene.json").write_text("half")
    old = tmp_path / f".scene.{NOT_A_PID}.old"
    old.mkdir()
    dead_tmp = tmp_path / f".scene.{NOT_A_PID}.ab12cd34.partial"
    dead_tmp.mkdir()
    running = tmp_path / f".scene.{os.getpid()}.zz99zz99.partial"  # a live writer's: kept
    running.mkdir()
    unrelated = tmp_path / ".scene.backup.old"  # not a name physcensis uses: kept
    unrelated.write_text("mine")
    other = tmp_path / ".other.k3j4h5xx.partial"  # another target's: kept
    other.mkdir()
    assert _solve_cli(out).exit_code in (0, 1)
    left = {p.name for p in tmp_path.iterdir()}
    assert partial.name not in left and old.name not in left and dead_tmp.name not in left
    assert {running.name, unrelated.name, other.name, "scene"} <= left


def test_leftovers_inside_an_output_folder_are_removed(tmp_path: Path, solution: Solution) -> None:
    out = tmp_path / "scene"
    write_solution(solution, out, physics_outputs=False)
    (out / f".scene.json.{NOT_A_PID}.abcd1234.tmp").write_text("half")
    (out / f".mjcf.{NOT_A_PID}.old").mkdir()
    removed = remove_leftovers(out)
    assert len(removed) == 2 and not any(p.name.startswith(".scene.json.") for p in out.iterdir())


def test_a_leftover_link_is_unlinked_not_followed(tmp_path: Path) -> None:
    victim = tmp_path / "victim"
    victim.mkdir()
    (victim / "keep.txt").write_text("x")
    link = tmp_path / f".scene.{NOT_A_PID}.old"
    link.symlink_to(victim)
    remove_leftovers(tmp_path / "scene")
    assert not link.is_symlink() and (victim / "keep.txt").read_text() == "x"


def test_a_failed_write_leaves_the_earlier_output_intact(tmp_path: Path, solution: Solution) -> None:
    out = tmp_path / "scene"
    write_solution(solution, out, physics_outputs=False)
    before = {p.name: p.read_bytes() for p in out.iterdir() if p.is_file()}
    with pytest.raises(RuntimeError), output_directory(out) as staging:
        (staging / "scene.json").write_text("half")
        raise RuntimeError("killed")
    assert {p.name: p.read_bytes() for p in out.iterdir() if p.is_file()} == before
    assert not any(p.name.endswith(".partial") for p in tmp_path.iterdir())


def test_export_into_a_scene_folder_keeps_the_scene_and_refuses_foreign_folders(
    tmp_path: Path, solution: Solution
) -> None:
    out = tmp_path / "scene"
    write_solution(solution, out, physics_outputs=False)
    result = runner.invoke(app, ["export", str(out), "--to", "glb", "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert (out / "scene.glb").is_file() and (out / "scene.json").is_file()
    assert "scene.glb" in json.loads((out / OWNER_FILE).read_text())["entries"]
    foreign = tmp_path / "foreign"
    foreign.mkdir()
    (foreign / "a.txt").write_text("x")
    result = runner.invoke(app, ["export", str(out), "--to", "glb", "--out", str(foreign)])
    assert result.exit_code == 2 and [p.name for p in foreign.iterdir()] == ["a.txt"]


def test_render_out_is_checked_before_rendering(tmp_path: Path, solution: Solution) -> None:
    scene = tmp_path / "scene"
    write_solution(solution, scene, physics_outputs=False)
    document = tmp_path / "report.docx"
    document.write_bytes(b"PK\x03\x04 a document")
    result = runner.invoke(app, ["render", str(scene), "--out", str(document)])
    assert result.exit_code == 2 and "--overwrite" in result.output
    assert document.read_bytes() == b"PK\x03\x04 a document"
    for bad in (str(tmp_path), "/proc/physcensis.png"):
        result = runner.invoke(app, ["render", str(scene), "--out", bad])
        assert result.exit_code == 2, result.output
        _one_line_error(result)
    link = tmp_path / "link.png"
    link.symlink_to(document)
    assert runner.invoke(app, ["render", str(scene), "--out", str(link)]).exit_code == 2
    assert document.read_bytes() == b"PK\x03\x04 a document"


_names = st.text(st.sampled_from("abcdefgh._-"), min_size=1, max_size=10).filter(lambda n: n not in (".", ".."))
_ours = st.sampled_from(["scene.json", "report.json", "layout.png", "mjcf", "transcript.jsonl", OWNER_FILE])


@pytest.mark.slow
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(files=st.dictionaries(st.one_of(_names, _ours), st.binary(max_size=20), min_size=1, max_size=6))
@pytest.mark.long
def test_overwrite_never_loses_a_file_it_does_not_own(
    tmp_path_factory: pytest.TempPathFactory,
    solution: Solution,
    files: dict[str, bytes],
) -> None:
    out = tmp_path_factory.mktemp("user")
    for name, content in files.items():
        (out / name).write_bytes(content)
    # Only our own names and a scene.json carrying the scene format: an output of an older version (before the owner
    # file), whose entries are ours to replace; anything else that is there is the user's.
    earlier_output = owned_entries(out) or set()
    try:
        write_solution(solution, out, physics_outputs=False, overwrite=True)
        written = {"scene.json", "report.json", "layout.png", OWNER_FILE} | earlier_output
    except OutputError:  # a file where physcensis writes a folder (mjcf): refused, nothing touched
        assert (out / "mjcf").is_file()
        written = set()
    for name, content in files.items():
        if name not in written:
            assert (out / name).read_bytes() == content, name


def test_gallery_out_is_checked_before_rendering(tmp_path: Path) -> None:
    document = tmp_path / "notes.txt"
    document.write_text("mine")
    result = runner.invoke(app, ["assets", "gallery", "--out", str(document), "-c", "mug"])
    assert result.exit_code == 2 and "--overwrite" in result.output
    assert document.read_text() == "mine"
    result = runner.invoke(app, ["assets", "gallery", "--out", "/proc/gallery.png", "-c", "mug"])
    assert result.exit_code == 2 and "Traceback" not in result.output


def test_names_that_only_look_temporary_are_never_removed(tmp_path: Path) -> None:
    keep = [tmp_path / ".scene.orig.tmp", tmp_path / ".scene.bak.partial", tmp_path / ".scene.backup.old"]
    for path in keep:
        path.write_text("mine")
    out = tmp_path / "scene"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    (out / ".notes.txt.backup.tmp").write_text("mine")
    assert _solve_cli(out, "--overwrite").exit_code in (0, 1)
    assert all(path.read_text() == "mine" for path in keep)
    assert (out / ".notes.txt.backup.tmp").read_text() == "mine"


@pytest.mark.parametrize("clash", ["file-where-a-folder-goes", "folder-where-a-file-goes", "link"])
def test_overwrite_never_deletes_a_users_folder_or_link_of_an_output_name(tmp_path: Path, clash: str) -> None:
    out = tmp_path / "d"
    out.mkdir()
    (out / "notes").write_text("hi")
    if clash == "file-where-a-folder-goes":
        (out / "mjcf").write_text("hi")
    elif clash == "folder-where-a-file-goes":
        (out / "scene.json").mkdir()
        (out / "scene.json" / "x").write_text("hi")
    else:
        (tmp_path / "elsewhere.json").write_text("hi")
        (out / "report.json").symlink_to(tmp_path / "elsewhere.json")
    before = sorted(p.name for p in out.iterdir())
    result = runner.invoke(app, ["solve", str(PROGRAM), "--out", str(out), "--overwrite"])  # refused before solving
    assert result.exit_code == 2 and "move it or give another --out" in result.output
    assert sorted(p.name for p in out.iterdir()) == before
    if clash == "folder-where-a-file-goes":
        assert (out / "scene.json" / "x").read_text() == "hi"
    if clash == "link":
        assert (tmp_path / "elsewhere.json").read_text() == "hi"


def test_markup_in_paths_and_texts_is_printed_as_written(tmp_path: Path, solution: Solution) -> None:
    folder = tmp_path / "q[/b]"  # a folder "q[" holding "b]"
    folder.mkdir(parents=True)
    program = folder / "p.json"
    program.write_text(PROGRAM.read_text())
    result = runner.invoke(app, ["check", str(program)])
    assert result.exit_code == 0 and "q[/b]" in result.output, result.output
    scene = tmp_path / "s[/red]"
    write_solution(solution, scene, physics_outputs=False)
    for args in (
        ["render", str(scene), "--out", str(tmp_path / "r[/red].png"), "--size", "64x48"],
        ["export", str(scene), "--to", "mjcf", "--out", str(tmp_path / "e[/red]")],
        ["stability", str(scene), "--object", "[/x]"],
    ):
        result = runner.invoke(app, args)
        assert "MarkupError" not in repr(result.exception) and "Traceback" not in result.output, args
        assert "[/" in result.output, (args, result.output)
    assert "[category" in runner.invoke(app, ["predicates"]).output  # the table wraps; the bracket stays


def test_bench_clutter_out_follows_the_same_rules(tmp_path: Path) -> None:
    mine = tmp_path / "d"
    mine.mkdir()
    (mine / "mine.txt").write_text("hi")
    result = runner.invoke(app, ["bench", "clutter", "--scenes", "1", "--out", str(mine)])
    assert result.exit_code == 2 and "--overwrite" in result.output
    assert [p.name for p in mine.iterdir()] == ["mine.txt"]
    link = tmp_path / "link"
    link.symlink_to(mine)
    assert runner.invoke(app, ["bench", "clutter", "--scenes", "1", "--out", str(link)]).exit_code == 2


def test_a_file_named_like_an_output_folder_is_never_taken_for_ours(tmp_path: Path, solution: Solution) -> None:
    """A folder holding a scene-looking scene.json and a user's FILE named mjcf (physcensis writes mjcf/ as a folder)
    is not an earlier output: the file is not removed as a stale entry (found by the property test above)."""
    out = tmp_path / "user"
    out.mkdir()
    (out / "scene.json").write_bytes(b"physcensis.scene/")
    (out / "mjcf").write_bytes(b"")
    with pytest.raises(OutputError, match="mjcf"):
        write_solution(solution, out, physics_outputs=False, overwrite=True)
    assert (out / "mjcf").is_file() and (out / "scene.json").read_bytes() == b"physcensis.scene/"
