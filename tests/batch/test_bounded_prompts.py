"""Prompt files are read within bounds: a FIFO, folder or oversized file is refused with one line, unread."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.batch import BatchError, read_prompts
from physcensis.batch import prompts as prompts_module
from physcensis.batch.prompts import MAX_PROMPT_FILE_BYTES
from physcensis.cli import app

runner = CliRunner()


def test_a_fifo_is_refused_without_blocking(tmp_path: Path) -> None:
    fifo = tmp_path / "prompts.txt"
    os.mkfifo(fifo)  # nothing ever writes to it: reading it would block forever
    with pytest.raises(BatchError, match=r"prompts\.txt: cannot read: .*not a regular file"):
        read_prompts(fifo)


def test_a_folder_is_refused(tmp_path: Path) -> None:
    folder = tmp_path / "prompts.jsonl"
    folder.mkdir()
    with pytest.raises(BatchError, match="cannot read: the prompt file is a folder, not a file"):
        read_prompts(folder)


def test_a_file_over_the_limit_is_refused_naming_the_file_and_the_limit(tmp_path: Path) -> None:
    huge = tmp_path / "huge.txt"
    with huge.open("wb") as handle:
        handle.truncate(MAX_PROMPT_FILE_BYTES + 1)  # sparse: no disk space, never read
    with pytest.raises(BatchError) as caught:
        read_prompts(huge)
    assert str(caught.value).startswith(f"{huge}: cannot read:")
    assert f"over the limit of {MAX_PROMPT_FILE_BYTES:,}" in str(caught.value)


def test_a_file_of_exactly_the_limit_is_read(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    text = "a cup on a book\n"
    monkeypatch.setattr(prompts_module, "MAX_PROMPT_FILE_BYTES", len(text))
    path = tmp_path / "prompts.txt"
    path.write_text(text)
    assert [spec.prompt for spec in read_prompts(path)] == ["a cup on a book"]
    path.write_text(text + "a vase\n")
    with pytest.raises(BatchError, match="over the limit"):
        read_prompts(path)


def test_batch_command_refuses_a_fifo_with_one_line(tmp_path: Path) -> None:
    fifo = tmp_path / "prompts.txt"
    os.mkfifo(fifo)
    result = runner.invoke(app, ["batch", str(fifo), "--out", str(tmp_path / "out")])
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and str(fifo) in lines[0] and "not a regular file" in lines[0], result.output
    assert not (tmp_path / "out").exists()
