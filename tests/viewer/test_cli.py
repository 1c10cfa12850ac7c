"""`physcensis view`: the check mode that needs no browser, the live server it starts, and its errors."""

from __future__ import annotations

import re
import signal
import socket
import subprocess
import sys
import urllib.request
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.cli import app
from tests.child_processes import ctrl_c_as_in_a_terminal

runner = CliRunner()


def _one_line(text: str) -> str:
    return " ".join(text.split())


def test_the_check_builds_everything_plays_the_settle_and_prints_what_would_be_shown(scene_dir: Path) -> None:
    result = runner.invoke(app, ["view", str(scene_dir), "--check", "--steps", "15"])
    assert result.exit_code == 0, result.output
    out = _one_line(result.output)
    assert "objects: 3 placed, 0 failed" in out
    assert all(oid in out for oid in ("book_0", "mug_0", "bowl_0")) and "PLACE-ON book_0" in out
    assert "settle: 15 frames" in out and "camera: at" in out
    moved = re.search(r"largest move ([0-9.]+) mm", out)
    assert moved is not None and float(moved.group(1)) < 3.0
    assert runner.invoke(app, ["view", str(scene_dir / "scene.json"), "--check"]).exit_code == 0


@pytest.mark.parametrize(
    ("make", "expected"),
    [
        (lambda tmp: tmp / "missing", "cannot read scene file"),
        (lambda tmp: tmp, "no scene.json in this folder"),
        (lambda tmp: _write(tmp / "scene.json", "{ not json"), "scene.json"),
    ],
    ids=["missing path", "folder without a scene", "bad scene file"],
)
def test_a_missing_or_bad_scene_is_one_error_line_and_exit_two(tmp_path: Path, make, expected: str) -> None:  # type: ignore[no-untyped-def]
    result = runner.invoke(app, ["view", str(make(tmp_path)), "--check"])
    assert result.exit_code == 2
    assert expected in _one_line(result.output) and "Traceback" not in result.output
    assert result.output.startswith("error:")


def _write(path: Path, text: str) -> Path:
    path.write_text(text)
    return path


def test_a_missing_viser_names_the_extra_to_install(scene_dir: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "viser", None)  # `import viser` raises ImportError
    result = runner.invoke(app, ["view", str(scene_dir)])
    assert result.exit_code == 2
    assert "pip install 'physcensis[view]'" in _one_line(result.output)
    assert runner.invoke(app, ["view", str(scene_dir), "--check"]).exit_code == 0  # the check needs no server


def test_an_address_that_cannot_be_served_on_is_one_error_line(scene_dir: Path) -> None:
    pytest.importorskip("viser")
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        result = runner.invoke(app, ["view", str(scene_dir), "--port", str(port)])
    assert result.exit_code == 2 and f"cannot serve the viewer on 127.0.0.1:{port}" in _one_line(result.output)
    result = runner.invoke(app, ["view", str(scene_dir), "--host", "no.such.host.invalid"])
    assert result.exit_code == 2 and "'no.such.host.invalid' is not an address" in _one_line(result.output)


def test_a_bad_episode_is_one_error_line(scene_dir: Path, tmp_path: Path) -> None:
    pytest.importorskip("h5py")
    result = runner.invoke(app, ["view", str(scene_dir), "--check", "--episode", str(tmp_path / "none.hdf5:2")])
    assert result.exit_code == 2 and "no such dataset file" in _one_line(result.output)


@pytest.mark.long  # a fresh interpreter that loads the catalogue, MuJoCo and viser: 5-8 s here
def test_the_command_serves_the_viewer_on_127_0_0_1_until_interrupted(scene_dir: Path) -> None:
    pytest.importorskip("viser")
    exe = Path(sys.executable).with_name("physcensis")
    process = subprocess.Popen(
        [str(exe), "view", str(scene_dir), "--port", "0"],
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        preexec_fn=ctrl_c_as_in_a_terminal,  # a pytest-xdist worker ignores SIGINT, and its children inherit that
    )
    try:
        assert process.stdout is not None
        line = process.stdout.readline()
        found = re.search(r"at (http://127\.0\.0\.1:\d+)", line)
        assert found is not None, line + (process.stderr.read() if process.stderr and process.poll() else "")
        with urllib.request.urlopen(found.group(1) + "/", timeout=10) as response:
            assert response.status == 200 and b"<html" in response.read().lower()
        assert "3 objects" in line
    finally:
        process.send_signal(signal.SIGINT)  # Ctrl-C
        try:
            process.wait(timeout=90)  # a loaded machine: two test workers and more
        except subprocess.TimeoutExpired:
            process.kill()
            raise
    assert process.returncode == 0
