"""On-disk cache of generated assets: one .npz per asset, keyed by id and a generator fingerprint.

The cache lives in the per-user cache directory (`PHYSCENSIS_CACHE_DIR` overrides
it).  The fingerprint hashes GENERATOR_VERSION and the source of the generator
modules, so editing a generator invalidates its cached meshes.  Writes are atomic;
entries are read within bounds (`read_bounded`, then `serialize.asset_from_bytes`),
and a damaged entry is logged and rebuilt.
"""

from __future__ import annotations

import hashlib
import logging
import os
from functools import lru_cache
from pathlib import Path

import platformdirs

from physcensis.assets.model import Asset
from physcensis.assets.serialize import asset_from_bytes, asset_to_bytes
from physcensis.fileio import BoundError, atomic_write_bytes, read_bounded

log = logging.getLogger(__name__)
GENERATOR_VERSION = 1
CACHE_ENV = "PHYSCENSIS_CACHE_DIR"
MAX_ENTRY_BYTES = 512 * 1024 * 1024  # one asset: a 2,000,000-triangle mesh and its hulls
# the code that decides a cached asset's content: the generators, what they import, building and saving
_GENERATOR_SOURCES = (
    "shapes.py",
    "collision.py",
    "palette.py",
    "spec.py",
    "build.py",
    "model.py",
    "serialize.py",
    "gen",
)


def cache_root() -> Path:
    """The cache directory: $PHYSCENSIS_CACHE_DIR, else the platform's user cache dir."""
    override = os.environ.get(CACHE_ENV)
    return Path(override) if override else Path(platformdirs.user_cache_dir("physcensis"))


@lru_cache(maxsize=1)
def generator_fingerprint() -> str:
    """Hash of GENERATOR_VERSION and the generator source files: the Python and the variants' data files."""
    digest = hashlib.sha256(f"v{GENERATOR_VERSION}".encode())
    here = Path(__file__).parent
    for name in _GENERATOR_SOURCES:
        path = here / name
        files = sorted([*path.glob("*.py"), *path.glob("data/*.json")]) if path.is_dir() else [path]
        for file in files:
            digest.update(file.name.encode())
            digest.update(file.read_bytes())
    return digest.hexdigest()[:16]


class AssetCache:
    """Load and store assets by key under `root/assets/`."""

    def __init__(self, root: str | Path | None = None) -> None:
        self.root = Path(root) if root is not None else cache_root()

    @property
    def folder(self) -> Path:
        return self.root / "assets"

    def path(self, key: str) -> Path:
        return self.folder / f"{key}.npz"

    def load(self, key: str) -> Asset | None:
        path = self.path(key)
        try:
            data = read_bounded(path, MAX_ENTRY_BYTES, "entry")
        except BoundError as exc:
            if path.exists() or path.is_symlink():  # a missing entry is just not cached yet
                log.warning("asset cache: cannot read %s (%s); rebuilding", path, exc)
            return None
        try:
            return asset_from_bytes(data)
        except Exception as exc:  # any damage means rebuild, and say so
            log.warning("asset cache: damaged entry %s (%s: %s); rebuilding", path, exc.__class__.__name__, exc)
            return None

    def store(self, key: str, asset: Asset) -> None:
        try:
            atomic_write_bytes(self.path(key), asset_to_bytes(asset))
        except OSError as exc:
            log.warning("asset cache: cannot write %s (%s); continuing without caching", self.path(key), exc)
