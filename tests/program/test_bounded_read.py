"""Program files are read within bounds: a device, FIFO, folder or oversized file is refused with one line, unread."""

from __future__ import annotations

import os
import resource
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.errors import ProgramParseError
from physcensis.program import load_program
from physcensis.program import parser as parser_module
from physcensis.program.parser import MAX_PROGRAM_BYTES

PROGRAM = '[["cup_0", "a white mug"], ["cup_0", "PLACE-ANYWHERE", "root", {}]]'
runner = CliRunner()


def _fifo(tmp_path: Path) -> Path:
    path = tmp_path / "program.json"
    os.mkfifo(path)  # nothing ever writes to it: reading it would block forever
    return path


def _sparse(tmp_path: Path, size: int) -> Path:
    path = tmp_path / "huge.json"
    with path.open("wb") as handle:
        handle.truncate(size)  # a sparse file: no disk space, and never read if the size is checked first
    return path


def test_a_fifo_is_refused_without_blocking(tmp_path: Path) -> None:
    fifo = _fifo(tmp_path)
    with pytest.raises(ProgramParseError, match=r"program\.json: cannot read: .*not a regular file"):
        load_program(fifo)


def test_a_folder_is_refused(tmp_path: Path) -> None:
    with pytest.raises(ProgramParseError, match="cannot read: the program file is a folder, not a file"):
        load_program(tmp_path)


def test_a_file_over_the_limit_is_refused_naming_the_file_and_the_limit(tmp_path: Path) -> None:
    huge = _sparse(tmp_path, MAX_PROGRAM_BYTES + 1)
    with pytest.raises(ProgramParseError) as caught:
        load_program(huge)
    message = str(caught.value)
    assert message.startswith(f"{huge}: cannot read:")
    assert f"over the limit of {MAX_PROGRAM_BYTES:,}" in message


def test_a_file_of_exactly_the_limit_is_read(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(parser_module, "MAX_PROGRAM_BYTES", len(PROGRAM.encode()))
    path = tmp_path / "program.json"
    path.write_text(PROGRAM)
    assert [d.object_id for d in load_program(path).declarations] == ["cup_0"]
    path.write_text(PROGRAM + " ")
    with pytest.raises(ProgramParseError, match="over the limit"):
        load_program(path)


@pytest.mark.parametrize("kind", ["fifo", "folder", "huge"])
def test_check_refuses_with_one_error_line_and_exit_two(tmp_path: Path, kind: str) -> None:
    path = {
        "fifo": lambda: _fifo(tmp_path),
        "folder": lambda: tmp_path,
        "huge": lambda: _sparse(tmp_path, MAX_PROGRAM_BYTES + 1),
    }[kind]()
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and str(path) in lines[0] and "cannot read" in lines[0], result.output


def _limit_memory() -> None:  # if the bound ever regressed, the child fails on its own, not the machine
    resource.setrlimit(resource.RLIMIT_AS, (2 * 2**30, 2 * 2**30))


def test_check_of_dev_zero_is_refused_not_read() -> None:
    """Run in a child with a timeout and a memory cap: without the bound this reads /dev/zero until killed."""
    done = subprocess.run(
        [sys.executable, "-m", "physcensis", "check", "/dev/zero"],
        capture_output=True,
        text=True,
        timeout=120,
        preexec_fn=_limit_memory,
        check=False,
    )
    assert done.returncode == 2, done.stderr
    output = (done.stdout + done.stderr).strip().splitlines()
    assert output == [
        "error: /dev/zero: cannot read: the program file is not a regular file (device, FIFO or socket); refused"
    ]
