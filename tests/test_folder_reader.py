"""`read_in_folder`: the one reader of files that come with a folder from elsewhere."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from physcensis.fileio import BoundError, read_in_folder


def test_a_regular_file_inside_the_folder_is_read(tmp_path: Path) -> None:
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "a.txt").write_bytes(b"hello")
    assert read_in_folder(tmp_path, "sub/a.txt", 10) == b"hello"


@pytest.mark.parametrize("relative", ["../outside.txt", "/etc/passwd", "sub/../../outside.txt", ""])
def test_a_path_that_leaves_the_folder_is_refused(tmp_path: Path, relative: str) -> None:
    folder = tmp_path / "folder"
    folder.mkdir()
    (tmp_path / "outside.txt").write_text("secret")
    with pytest.raises(BoundError, match="not a path inside the folder"):
        read_in_folder(folder, relative, 100)


def test_links_are_refused_and_inside_ones_followed_only_when_allowed(tmp_path: Path) -> None:
    folder = tmp_path / "folder"
    (folder / "sub").mkdir(parents=True)
    (tmp_path / "secret.txt").write_text("secret")
    (folder / "real.txt").write_text("real")
    (folder / "out.txt").symlink_to(tmp_path / "secret.txt")
    (folder / "in.txt").symlink_to(folder / "real.txt")
    (folder / "linked").symlink_to(tmp_path)  # a linked folder on the way
    for relative in ("out.txt", "in.txt", "linked/secret.txt"):
        with pytest.raises(BoundError, match="symbolic link"):
            read_in_folder(folder, relative, 100)
    assert read_in_folder(folder, "in.txt", 100, links_inside=True) == b"real"
    for relative in ("out.txt", "linked/secret.txt"):
        with pytest.raises(BoundError, match="leads outside the folder"):
            read_in_folder(folder, relative, 100, links_inside=True)


def test_size_and_kind_are_bounded(tmp_path: Path) -> None:
    (tmp_path / "big.bin").write_bytes(b"x" * 101)
    with pytest.raises(BoundError, match="over the limit"):
        read_in_folder(tmp_path, "big.bin", 100)
    os.mkfifo(tmp_path / "pipe")
    with pytest.raises(BoundError, match="not a regular file"):
        read_in_folder(tmp_path, "pipe", 100)  # never blocks on the FIFO
    (tmp_path / "dir").mkdir()
    with pytest.raises(BoundError, match="folder"):
        read_in_folder(tmp_path, "dir", 100)
