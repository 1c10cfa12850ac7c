"""Shared fixtures: one catalogue, generated once per test session into a temporary cache."""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

import pytest

from physcensis.assets.cache import CACHE_ENV, AssetCache
from physcensis.assets.catalogue import Catalogue
from physcensis.assets.model import Asset

if not os.environ.get("DISPLAY"):
    os.environ.setdefault("MUJOCO_GL", "egl")


@pytest.fixture(scope="session")
def cache_dir(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    """A private cache directory, also exported as PHYSCENSIS_CACHE_DIR for code that reads the default."""
    path = tmp_path_factory.mktemp("asset-cache")
    previous = os.environ.get(CACHE_ENV)
    os.environ[CACHE_ENV] = str(path)
    yield path
    if previous is None:
        os.environ.pop(CACHE_ENV, None)
    else:
        os.environ[CACHE_ENV] = previous


@pytest.fixture(scope="session")
def catalogue(cache_dir: Path) -> Catalogue:
    return Catalogue(cache=AssetCache(cache_dir))


@pytest.fixture(scope="session")
def all_assets(catalogue: Catalogue) -> list[Asset]:
    return catalogue.all()


@pytest.fixture(scope="session")
def by_id(all_assets: list[Asset]) -> dict[str, Asset]:
    return {a.id: a for a in all_assets}
