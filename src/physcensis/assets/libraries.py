"""Which user asset libraries are in use: one list that every command, worker and API default honours.

A library is named by (in this order, duplicates dropped): the `--library` options of a command (or
`use_libraries` from Python), the `PHYSCENSIS_LIBRARY` environment variable (folders separated by the platform's
path separator, `:` on Linux and macOS) and the `libraries` list of the user config file
(`~/.config/physcensis/config.yaml` on Linux; `PHYSCENSIS_CONFIG` names another file).  `physcensis assets import`
adds the folder it imports to that list and `physcensis assets forget` removes it.

    # ~/.config/physcensis/config.yaml
    libraries:
      - ~/objects/ycb          # ~ and paths relative to this file are allowed
      - /data/scans
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

import platformdirs

from physcensis.assets.bounded import load_yaml, value_problem
from physcensis.assets.errors import AssetError
from physcensis.fileio import BoundError, atomic_write_text, read_bounded

LIBRARY_ENV = "PHYSCENSIS_LIBRARY"
CONFIG_ENV = "PHYSCENSIS_CONFIG"
MAX_CONFIG_BYTES = 100_000
MAX_LIBRARIES = 100

_chosen: tuple[Path, ...] = ()  # the running command's --library folders


class ConfigError(AssetError):
    """The user config file cannot be read or written; the message names the file and what is wrong."""


def config_path() -> Path:
    """The user config file: $PHYSCENSIS_CONFIG, else config.yaml in the platform's user config folder."""
    override = os.environ.get(CONFIG_ENV)
    return Path(override).expanduser() if override else Path(platformdirs.user_config_dir("physcensis")) / "config.yaml"


def read_config(path: Path | None = None) -> dict[str, Any]:
    """The config file as a mapping ({} when there is none); ConfigError when it is unreadable or malformed."""
    path = path or config_path()
    if not path.exists() and not path.is_symlink():
        return {}
    try:
        data = load_yaml(read_bounded(path, MAX_CONFIG_BYTES, "config file").decode("utf-8"))
    except (BoundError, OSError) as exc:
        raise ConfigError(f"{path}: {exc}") from None
    except Exception as exc:  # syntax, encoding: the file's fault, said on one line
        raise ConfigError(f"{path}: cannot read the config file ({str(exc).splitlines()[0]})") from None
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise ConfigError(f"{path}: the config file must be a mapping such as 'libraries: [folder, ...]'")
    if problem := value_problem(data):
        raise ConfigError(f"{path}: {problem}")
    return data


_read: dict[tuple[Path, int, int], list[Path]] = {}  # (file, mtime, size) -> its libraries: read once per change


def _config_libraries(path: Path) -> list[Path]:
    try:
        stat = path.stat()
    except OSError:
        return []  # no config file (a broken link or an unreadable folder is read_config's to report)
    key = (path, stat.st_mtime_ns, stat.st_size)
    if key not in _read:
        _read.clear()
        _read[key] = _parse_config_libraries(path)
    return list(_read[key])


def _parse_config_libraries(path: Path) -> list[Path]:
    listed = read_config(path).get("libraries", [])
    if not isinstance(listed, list) or not all(isinstance(item, str) and item.strip() for item in listed):
        raise ConfigError(f"{path}: 'libraries' must be a list of folder paths")
    if len(listed) > MAX_LIBRARIES:
        raise ConfigError(f"{path}: 'libraries' lists {len(listed)} folders; at most {MAX_LIBRARIES}")
    return [_absolute(item, path.parent) for item in listed]


def _absolute(text: str, base: Path) -> Path:
    path = Path(text.strip()).expanduser()
    return path if path.is_absolute() else base / path


def _environment_libraries() -> list[Path]:
    text = os.environ.get(LIBRARY_ENV, "")
    return [_absolute(part, Path.cwd()) for part in text.split(os.pathsep) if part.strip()]


def _unique(paths: Iterable[Path]) -> list[Path]:
    seen: set[Path] = set()
    out = []
    for path in paths:
        key = path.resolve()
        if key not in seen:
            seen.add(key)
            out.append(path)
    return out


def configured_libraries() -> list[Path]:
    """Every library in use: the command's own, the environment's, the config file's (each once)."""
    return _unique([*_chosen, *_environment_libraries(), *_config_libraries(config_path())])


def choose_libraries(folders: Sequence[str | Path]) -> None:
    """Add the running command's `--library` folders to the configured ones (replacing earlier choices)."""
    global _chosen
    _chosen = tuple(Path(f).expanduser().absolute() for f in folders)


def _write_libraries(path: Path, libraries: list[str]) -> None:
    import yaml

    data = read_config(path)
    data["libraries"] = libraries
    try:
        atomic_write_text(path, yaml.safe_dump(data, sort_keys=False, allow_unicode=True))
    except OSError as exc:
        raise ConfigError(f"{path}: cannot write the config file ({exc.strerror or exc})") from None


def register_library(folder: str | Path) -> bool:
    """Add `folder` (absolute) to the config file's libraries; False when it was already there."""
    path = config_path()
    folder = Path(folder).expanduser().resolve()
    current = _config_libraries(path)
    if any(p.resolve() == folder for p in current):
        return False
    _write_libraries(path, [*(str(p) for p in current), str(folder)])
    return True


def forget_library(folder: str | Path) -> bool:
    """Remove `folder` from the config file's libraries; False when it was not there."""
    path = config_path()
    folder = Path(folder).expanduser().resolve()
    current = _config_libraries(path)
    kept = [p for p in current if p.resolve() != folder]
    if len(kept) == len(current):
        return False
    _write_libraries(path, [str(p) for p in kept])
    return True
