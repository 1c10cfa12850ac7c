"""Shared fixtures: one catalogue, in a temporary cache of the test run's own.

The temporary cache starts with the built-in assets already in the asset cache (a whole-suite run builds the missing
ones first, see ../conftest.py; a cached asset is the generated one, bit for bit, and its key covers the generators'
source).  Under pytest-xdist the workers share it: each worker starts at its own share of the catalogue and then
loads what the others have written.
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterator
from pathlib import Path

import pytest

from physcensis.assets.cache import CACHE_ENV, AssetCache
from physcensis.assets.catalogue import Catalogue, builtin_cache_paths
from physcensis.assets.model import Asset

if not os.environ.get("DISPLAY"):
    os.environ.setdefault("MUJOCO_GL", "egl")


@pytest.fixture(scope="session")
def cache_dir(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    """A private cache directory, also exported as PHYSCENSIS_CACHE_DIR for code that reads the default."""
    if os.environ.get("PYTEST_XDIST_WORKER"):  # the run's folder, above each worker's own
        path = tmp_path_factory.getbasetemp().parent / "asset-cache"
        path.mkdir(exist_ok=True)
    else:
        path = tmp_path_factory.mktemp("asset-cache")
    _link_builtin_entries(AssetCache(), AssetCache(path))
    previous = os.environ.get(CACHE_ENV)
    os.environ[CACHE_ENV] = str(path)
    yield path
    if previous is None:
        os.environ.pop(CACHE_ENV, None)
    else:
        os.environ[CACHE_ENV] = previous


def _link_builtin_entries(source: AssetCache, target: AssetCache) -> None:
    """The built-in assets `source` holds, in `target` too (hard links, else copies; entries are replaced, never
    written in place, so `source` never changes)."""
    target.folder.mkdir(parents=True, exist_ok=True)
    for entry in builtin_cache_paths(source).values():
        copy = target.folder / entry.name
        if entry.is_file() and not copy.exists():
            try:
                os.link(entry, copy)
            except FileExistsError:  # another worker linked it first
                pass
            except OSError:  # another file system
                shutil.copyfile(entry, copy)


@pytest.fixture(scope="session")
def catalogue(cache_dir: Path) -> Catalogue:
    return Catalogue(cache=AssetCache(cache_dir))


def _worker() -> tuple[int, int]:
    """This pytest-xdist worker's number and the number of workers; (0, 1) without xdist."""
    name = os.environ.get("PYTEST_XDIST_WORKER", "gw0")
    return int(name.removeprefix("gw")), int(os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1"))


@pytest.fixture(scope="session")
def all_assets(catalogue: Catalogue) -> list[Asset]:
    index, count = _worker()
    ids = catalogue.ids()
    start = len(ids) * index // count
    for asset_id in ids[start:] + ids[:start]:  # workers that start together generate different assets
        catalogue.get(asset_id)
    return catalogue.all()


@pytest.fixture(scope="session")
def by_id(all_assets: list[Asset]) -> dict[str, Asset]:
    return {a.id: a for a in all_assets}
