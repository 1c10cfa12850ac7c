"""Safe writes: a crash never leaves a half-written output behind, and nothing physcensis did not write is deleted.

Files are written under a temporary name and renamed into place. Output folders are filled in a staging folder
beside them and then published: swapped in whole when the target is new or holds only what physcensis wrote before,
or entry by entry when the user keeps other files there (those are left alone). Every output folder carries
`.physcensis.json`, the list of entries physcensis owns in it. Temporary names carry the writer's PID
(`.NAME.PID.XXXX.partial`, `.NAME.PID.old`, `.NAME.PID.XXXX.tmp`), so the next run on the same target removes what
a killed run left and never what a running one is still writing.

Untrusted input files (programs, prompt files, asset libraries, meshes) are read with `read_bounded`: regular files
only, never more than a given number of bytes. A file of a folder that may come from elsewhere (a scene folder, a
batch folder, a report's folder) is read with `read_in_folder`: the same bounds, a path that stays inside the folder,
and no symbolic link unless the caller allows links that stay inside it.
"""

from __future__ import annotations

import contextlib
import errno
import json
import os
import re
import shutil
import stat
import tempfile
from collections.abc import Iterable, Iterator
from pathlib import Path

from physcensis.errors import PhyscensisError

OWNER_FILE = ".physcensis.json"
OWNER_FORMAT = "physcensis.output/1"
# What the export formats write into a scene folder, by name: the records of the export registry
# (physcensis.export.EXPORT_FORMATS) name the same entries; this module sits below export/ and may not read them, and
# tests/export/test_format_registry.py keeps the two in step. A new format adds its folder or file here.
EXPORT_FOLDERS = frozenset({"mjcf", "urdf"})
EXPORT_FILES = frozenset({"scene.glb", "scene.usd"})
# The other files physcensis writes into scene folders.
SCENE_FILES = frozenset(
    {"scene.json", "exports.json", "report.json", "render.png", "layout.png", "transcript.jsonl", "batch.json"}
)
_ALSO_OURS = frozenset({"scene.usda"})  # USD as text: `export_usd` writes it when given that name
# What physcensis writes into scene folders: a folder of these alone (written before folders carried OWNER_FILE,
# or copied without it) is still recognised.
LEGACY_OUTPUTS = SCENE_FILES | EXPORT_FOLDERS | EXPORT_FILES | _ALSO_OURS
# `.NAME.PID.XXXXXXXX.partial|tmp` (older versions: `.NAME.XXXXXXXX.partial|tmp`) and `.NAME.PID.old`, where
# XXXXXXXX is tempfile's 8-character suffix: only these exact shapes are ours, any other name is left alone.
_LEFTOVER = re.compile(r"^\.(?P<base>.+?)\.(?:(?:(?P<pid>\d+)\.)?[a-z0-9_]{8}\.(?:partial|tmp)|(?P<old>\d+)\.old)$")
# What a folder output may hold, as physcensis writes it: these are folders (the exports' and the scene's asset copies,
# output/scene_assets.py), every other entry is a file.
FOLDER_OUTPUTS = EXPORT_FOLDERS | {"assets"}


class OutputError(PhyscensisError):
    """An output location that cannot or may not be written."""


class BoundError(PhyscensisError, ValueError):
    """Input over one of the bounds (size, depth, expanded size); the message says which."""


def read_bounded(path: Path, limit: int, what: str = "file", *, follow_links: bool = True) -> bytes:
    """The bytes of a regular file no larger than `limit`; folders, devices, FIFOs and loops are refused, and with
    `follow_links=False` a symbolic link too.

    The file is opened once and checked through its descriptor, so a file swapped or
    grown after the check is still never read beyond `limit` bytes.
    """
    fd = _open_for_reading(path, what, follow_links)
    try:
        info = os.fstat(fd)
        if stat.S_ISDIR(info.st_mode):
            raise BoundError(f"the {what} is a folder, not a file")
        if not stat.S_ISREG(info.st_mode):
            raise BoundError(f"the {what} is not a regular file (device, FIFO or socket); refused")
        if info.st_size > limit:
            raise BoundError(f"the {what} has {info.st_size:,} bytes, over the limit of {limit:,}")
        data = _read_at_most(fd, limit + 1)
    except OSError as exc:
        raise BoundError(f"cannot read the {what} ({exc.strerror or exc.__class__.__name__})") from None
    finally:
        os.close(fd)
    if len(data) > limit:
        raise BoundError(f"the {what} is over the limit of {limit:,} bytes")
    return data


def _open_for_reading(path: Path, what: str, follow_links: bool) -> int:
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0)  # a FIFO must not block the open
    if not follow_links:
        flags |= getattr(os, "O_NOFOLLOW", 0)
    try:
        return os.open(path, flags)
    except IsADirectoryError:
        raise BoundError(f"the {what} is a folder, not a file") from None
    except FileNotFoundError:
        raise BoundError(f"{what} not found") from None
    except OSError as exc:
        if not follow_links and exc.errno == errno.ELOOP:
            raise BoundError(f"the {what} is a symbolic link; refused") from None
        raise BoundError(f"cannot open the {what} ({exc.strerror or exc.__class__.__name__})") from None


def read_in_folder(
    folder: Path, relative: str | Path, limit: int, what: str | None = None, *, links_inside: bool = False
) -> bytes:
    """The bytes of `folder/relative`, a regular file no larger than `limit`, that stays inside `folder`.

    `relative` must be a plain relative path (no `..`, not absolute). A symbolic link on the way is refused, or with
    `links_inside` followed only when where it leads is still inside the folder. Refusals raise `BoundError` naming
    the file as `relative` (or `what`).
    """
    shown = what or str(relative)
    parts = Path(relative).parts
    if not parts or Path(relative).is_absolute() or any(part in ("..", "") for part in parts):
        raise BoundError(f"{shown}: not a path inside the folder")
    root = folder.resolve()
    path = root
    for part in parts:
        path = path / part
        if path.is_symlink():
            if not links_inside:
                raise BoundError(f"{shown}: is a symbolic link; refused")
            try:
                path.resolve(strict=True).relative_to(root)
            except (OSError, ValueError):
                raise BoundError(f"{shown}: is a symbolic link that leads outside the folder; refused") from None
    return read_bounded(path, limit, shown, follow_links=links_inside)


def _read_at_most(fd: int, count: int) -> bytes:
    chunks: list[bytes] = []
    while count > 0:
        chunk = os.read(fd, min(count, 1 << 20))
        if not chunk:
            break
        chunks.append(chunk)
        count -= len(chunk)
    return b"".join(chunks)


def atomic_write_bytes(path: str | Path, data: bytes) -> None:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    if path.is_symlink() or path.is_dir():
        raise OutputError(
            f"{path}: is a {'symbolic link' if path.is_symlink() else 'folder'}; give the path of a regular file"
        )
    fd, tmp_name = tempfile.mkstemp(prefix=f".{path.name}.{os.getpid()}.", suffix=".tmp", dir=path.parent)
    try:
        os.chmod(tmp_name, 0o666 & ~_umask())  # mkstemp makes the file private; outputs are ordinary files
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(tmp_name, path)
    except BaseException:
        Path(tmp_name).unlink(missing_ok=True)
        raise


def atomic_write_text(path: str | Path, text: str) -> None:
    atomic_write_bytes(path, text.encode("utf-8"))


@contextlib.contextmanager
def atomic_directory(path: str | Path) -> Iterator[Path]:
    """Fill a temporary sibling folder, then swap it in for `path` (a folder physcensis owns whole, such as an
    export's `mjcf/`); on error nothing is left behind."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    remove_leftovers(path)
    staging = _staging_dir(path)
    try:
        yield staging
        _swap_in(staging, path)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise


def check_output_file(path: str | Path, *, overwrite: bool = False, suffixes: Iterable[bytes] = ()) -> Path:
    """Refuse, before any work, an output file that cannot be written or would replace something unasked.

    An existing file is replaced only with `overwrite`, or when it starts with one of `suffixes`' magic bytes
    (a PNG over a PNG).
    """
    path = Path(path)
    if path.is_symlink():
        raise OutputError(f"{path}: is a symbolic link; give the path of a regular file (the link is left alone)")
    if path.exists():
        if not path.is_file():
            raise OutputError(f"{path}: exists and is not a regular file")
        if not overwrite and not _starts_with(path, tuple(suffixes)):
            raise OutputError(f"{path}: exists and was not written by physcensis; use --overwrite to replace it")
    parent = _usable_parent(path)
    _probe_writable(parent, path)
    remove_leftovers(path)
    return path


def check_output_dir(path: str | Path, *, overwrite: bool = False) -> Path:
    """Refuse, before any work, an output folder that cannot be written or holds files that are not ours.

    A folder is fine when it is missing, empty, or a physcensis output; any other non-empty folder needs
    `overwrite` (and even then only physcensis's own entries in it are replaced). Returns the resolved folder.
    """
    given = Path(path)
    if given.is_symlink():
        raise OutputError(f"{given}: is a symbolic link; give a real folder (the link is left alone)")
    target = Path(os.path.abspath(given)).resolve()
    if target.parent == target:
        raise OutputError(f"{given}: is the file system's root; give a folder to write into")
    if target.exists() and not target.is_dir():
        raise OutputError(f"{given}: exists and is not a folder; give --out a folder")
    if target.is_dir():
        foreign = _foreign_entries(target)
        if foreign and not overwrite:
            shown = ", ".join(sorted(foreign)[:3]) + (" …" if len(foreign) > 3 else "")
            raise OutputError(
                f"{given}: is not empty and not a physcensis output (holds {shown}); give an empty or "
                "new folder, or --overwrite to write physcensis's files into it and keep the rest"
            )
        _refuse_clashes(target, foreign, given)
    parent = _usable_parent(target)
    _probe_writable(parent, given)
    if target.is_dir():
        _probe_writable(target, given)
    remove_leftovers(target)
    return target


@contextlib.contextmanager
def output_directory(path: str | Path, *, overwrite: bool = False, replace_owned: bool = True) -> Iterator[Path]:
    """Fill a staging folder, then publish it at `path` without deleting anything physcensis did not write.

    With `replace_owned`, entries physcensis wrote there before and did not write again are removed (a scene folder
    rewritten by `solve`); without it they stay (`export` adding formats to a scene folder).
    """
    target = check_output_dir(path, overwrite=overwrite)
    staging = _staging_dir(target)
    try:
        yield staging
        _publish(staging, target, replace_owned)
    finally:
        shutil.rmtree(staging, ignore_errors=True)


def _refuse_clashes(target: Path, foreign: set[str], given: Path) -> None:
    """Even with --overwrite, a user's folder, link or other thing where physcensis writes an output is refused:
    replacing it would delete what is inside or behind it."""
    for name in sorted(foreign & LEGACY_OUTPUTS):
        entry = target / name
        wanted = "folder" if name in FOLDER_OUTPUTS else "file"
        if entry.is_symlink() or (entry.is_dir() != (wanted == "folder")) or not (entry.is_dir() or entry.is_file()):
            kind = "a symbolic link" if entry.is_symlink() else "a folder" if entry.is_dir() else "not a regular file"
            raise OutputError(
                f"{given / name}: is {kind} of yours where physcensis writes its {name} {wanted}; "
                "move it or give another --out"
            )


def owned_entries(folder: Path) -> set[str] | None:
    """The entries physcensis owns in `folder`, or None when it is not a physcensis output."""
    marker = folder / OWNER_FILE
    if marker.is_file() and not marker.is_symlink():
        try:
            data = json.loads(marker.read_text(encoding="utf-8"))
            entries = data.get("entries") if isinstance(data, dict) and data.get("format") == OWNER_FORMAT else None
            if isinstance(entries, list) and all(isinstance(e, str) for e in entries):
                return {e for e in entries if _plain_name(e) and _as_we_write_it(folder / e, missing_ok=True)}
        except (OSError, ValueError):
            pass
    present = {e.name for e in folder.iterdir() if not _is_temporary(e.name, LEGACY_OUTPUTS)}
    looks_ours = all(_as_we_write_it(folder / name) for name in present)
    if present and present <= LEGACY_OUTPUTS and looks_ours and _is_scene_file(folder / "scene.json"):
        return present
    return None


def _as_we_write_it(entry: Path, missing_ok: bool = False) -> bool:
    """Whether an entry is of the kind physcensis writes under its name (mjcf/, urdf/ and assets/ folders, other names
    regular files), never a link: a user's file named `mjcf` is not an output of ours, whatever else is there."""
    if entry.is_symlink():
        return False
    if not entry.exists():
        return missing_ok
    return entry.is_dir() if entry.name in FOLDER_OUTPUTS else entry.is_file()


def remove_leftovers(target: Path) -> list[Path]:
    """Remove what killed runs left beside `target` (and inside it, for a folder): `.NAME.*.partial`,
    `.NAME.PID.old` and `.NAME.*.tmp` whose PID is not running. Links are unlinked, never followed."""
    removed: list[Path] = []
    places = [(target.parent, {target.name})]
    if target.is_dir() and not target.is_symlink():
        inside = {e.name for e in target.iterdir() if not e.name.startswith(".")}
        places.append((target, inside | LEGACY_OUTPUTS | {OWNER_FILE}))
    for folder, names in places:
        with contextlib.suppress(OSError):
            for leftover in folder.iterdir():
                found = _leftover_of(leftover.name)
                if found is None or found[0] not in names or (found[1] is not None and _alive(found[1])):
                    continue
                _remove(leftover)
                removed.append(leftover)
    return removed


def _leftover_of(name: str) -> tuple[str, int | None] | None:
    """(the name it was written for, the writer's PID if known) of a temporary name, else None."""
    match = _LEFTOVER.match(name)
    if match is None:
        return None
    pid = match["pid"] or match["old"]
    return match["base"], int(pid) if pid else None


def _publish(staging: Path, target: Path, replace_owned: bool) -> None:
    new = {e.name for e in staging.iterdir()}
    if not target.exists():
        _write_owner(staging, new)
        _swap_in(staging, target)
        return
    owned = owned_entries(target) or set()
    present = {e.name for e in target.iterdir() if e.name != OWNER_FILE and not _is_temporary(e.name, owned)}
    if replace_owned and present <= owned and not _holds_cwd(target):
        _write_owner(staging, new)
        _swap_in(staging, target)
        return
    for name in sorted(new):
        _replace_entry(staging / name, target / name)
    stale = (owned - new) if replace_owned else set()
    for name in stale:
        _remove(target / name)
    _write_owner(target, (owned - stale) | new)


def _replace_entry(source: Path, dest: Path) -> None:
    if dest.is_dir() and not dest.is_symlink():
        _swap_in(source, dest)
    else:
        os.replace(source, dest)  # a file or a link at dest is replaced itself; a link's target is never touched


def _swap_in(staging: Path, path: Path) -> None:
    backup = None
    if path.exists() or path.is_symlink():
        backup = path.with_name(f".{path.name}.{os.getpid()}.old")
        _remove(backup)
        os.replace(path, backup)
    os.replace(staging, path)
    if backup is not None:
        _remove(backup)


def _write_owner(folder: Path, entries: set[str]) -> None:
    text = json.dumps({"format": OWNER_FORMAT, "entries": sorted(entries - {OWNER_FILE})}, indent=1) + "\n"
    atomic_write_text(folder / OWNER_FILE, text)


def _staging_dir(target: Path) -> Path:
    staging = Path(tempfile.mkdtemp(prefix=f".{target.name}.{os.getpid()}.", suffix=".partial", dir=target.parent))
    os.chmod(staging, 0o777 & ~_umask())
    return staging


def _foreign_entries(folder: Path) -> set[str]:
    owned = owned_entries(folder)
    present = {e.name for e in folder.iterdir() if e.name != OWNER_FILE and not _is_temporary(e.name, owned)}
    return present - owned if owned is not None else present


def _usable_parent(path: Path) -> Path:
    parent = Path(os.path.abspath(path)).parent
    try:
        parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"{path}: cannot create the folder it goes in ({exc.strerror or exc})") from None
    return parent


def _probe_writable(folder: Path, shown: Path) -> None:
    """Create and remove a temporary folder: the only test that also catches read-only and virtual file systems."""
    try:
        probe = tempfile.mkdtemp(prefix=f".physcensis.{os.getpid()}.", suffix=".partial", dir=folder)
        os.rmdir(probe)
    except OSError as exc:
        raise OutputError(f"{shown}: cannot write there ({exc.strerror or exc})") from None


def _holds_cwd(folder: Path) -> bool:
    """Swapping out the working folder (or one above it) would leave the process in a deleted folder."""
    try:
        cwd = Path.cwd().resolve()
    except OSError:
        return False
    return cwd == folder or folder in cwd.parents


def _is_temporary(name: str, owned: Iterable[str] | None) -> bool:
    """A temporary name physcensis uses for one of `owned` (or for any output it may write)."""
    found = _leftover_of(name)
    return found is not None and found[0] in {*(owned or ()), *LEGACY_OUTPUTS, OWNER_FILE}


def _plain_name(name: str) -> bool:
    return bool(name) and "/" not in name and "\0" not in name and name not in (".", "..")


def _is_scene_file(path: Path) -> bool:
    if not path.is_file() or path.is_symlink():
        return False
    with contextlib.suppress(OSError), open(path, "rb") as handle:
        return b"physcensis.scene/" in handle.read(4096)
    return False


def _starts_with(path: Path, magics: tuple[bytes, ...]) -> bool:
    if not magics:
        return False
    with contextlib.suppress(OSError), open(path, "rb") as handle:
        head = handle.read(max(len(m) for m in magics))
        return any(head.startswith(m) for m in magics)
    return False


def _remove(path: Path) -> None:
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path, ignore_errors=True)
    else:
        with contextlib.suppress(FileNotFoundError):
            path.unlink()


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError):
        return pid > 0
    return True


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
