"""The disk cache: the second run loads instead of rebuilding; damaged entries are rebuilt."""

from __future__ import annotations

import ast
import logging
import shutil
from pathlib import Path

import numpy as np
import pytest

import physcensis.assets.catalogue as catalogue_module
from physcensis.assets.cache import _GENERATOR_SOURCES, CACHE_ENV, AssetCache, cache_root
from physcensis.assets.catalogue import Catalogue, builtin_cache_paths, warm_builtin_cache
from physcensis.assets.serialize import asset_from_bytes, asset_to_bytes


def test_cache_root_honours_the_environment(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(CACHE_ENV, str(tmp_path))
    assert cache_root() == tmp_path
    monkeypatch.delenv(CACHE_ENV)
    assert "physcensis" in str(cache_root())


def test_second_run_loads_from_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    cache = AssetCache(tmp_path)
    first = Catalogue(cache=cache).get("mug_red")
    assert list((tmp_path / "assets").glob("mug_red-*.npz"))

    def no_build(*_args: object) -> None:
        raise AssertionError("rebuilt instead of loading from the cache")

    monkeypatch.setattr(catalogue_module, "build_asset", no_build)
    second = Catalogue(cache=cache).get("mug_red")
    assert np.array_equal(first.visual.vertices, second.visual.vertices)
    assert first.mass == second.mass and len(first.collision) == len(second.collision)
    assert second.cavity is not None and np.allclose(first.cavity.opening, second.cavity.opening)  # type: ignore[union-attr]


def test_damaged_entry_is_rebuilt_and_reported(tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    cache = AssetCache(tmp_path)
    Catalogue(cache=cache).get("apple_red")
    (path,) = (tmp_path / "assets").glob("apple_red-*.npz")
    path.write_bytes(b"not an npz")
    with caplog.at_level(logging.WARNING):
        asset = Catalogue(cache=cache).get("apple_red")
    assert asset.id == "apple_red"
    assert "damaged entry" in caplog.text
    assert asset_from_bytes(path.read_bytes()).id == "apple_red"  # rewritten


@pytest.mark.long  # builds the whole built-in catalogue
def test_warming_builds_only_the_missing_built_in_assets(tmp_path: Path, all_assets: list, cache_dir: Path) -> None:
    """What a whole-suite run does first (tests/conftest.py): the missing entries are built, on two processes, into
    entries the catalogue loads as the assets it would build; the entries already there are kept as they are."""
    full, warmed = builtin_cache_paths(AssetCache(cache_dir)), AssetCache(tmp_path)
    missing = ["mug_red", "apple_red", "book_flat_hardcover_red"]
    warmed.folder.mkdir(parents=True)
    for ident, entry in full.items():
        if ident not in missing:
            (warmed.folder / entry.name).hardlink_to(entry)
    assert warm_builtin_cache(warmed, workers=2) == len(missing)
    kept = {ident: path for ident, path in builtin_cache_paths(warmed).items() if ident not in missing}
    assert all(path.samefile(full[ident]) for ident, path in kept.items())
    for ident in missing:
        built, expected = Catalogue(cache=warmed).get(ident), Catalogue(cache=False).get(ident)
        assert np.array_equal(built.visual.vertices, expected.visual.vertices) and built.mass == expected.mass
    assert warm_builtin_cache(warmed, workers=2) == 0


def test_round_trip_keeps_every_field(by_id: dict) -> None:
    for ident in ("wine_glass_red_wine", "ball_tennis", "toolbox_red_metal", "ycb_030_fork"):
        a = by_id[ident]
        b = asset_from_bytes(asset_to_bytes(a))
        for name in (
            "id",
            "category",
            "kind",
            "description",
            "size",
            "mass",
            "mass_range",
            "friction_range",
            "com",
            "rgba",
            "part_faces",
            "tags",
            "synonyms",
            "support_probability",
            "has_front",
            "generated",
            "guessed",
            "source",
        ):
            assert getattr(a, name) == getattr(b, name), (ident, name)
        assert [p.kind for p in a.collision] == [p.kind for p in b.collision]


def _imported_asset_files(source: Path, package: Path) -> set[Path]:
    """The files of `physcensis.assets` modules a source file imports."""
    files = set()
    for node in ast.walk(ast.parse(source.read_text())):
        if not isinstance(node, ast.ImportFrom) or not (node.module or "").startswith("physcensis.assets"):
            continue
        assert node.module is not None
        if node.module == "physcensis.assets":
            files |= {package / f"{alias.name}.py" for alias in node.names}
        else:
            files.add(package.joinpath(*node.module.split(".")[2:]).with_suffix(".py"))
    return files


def test_the_cache_key_covers_every_module_the_generators_import() -> None:
    """Editing any of them (a builder's defaults, the options reader, a colour) changes the key: no stale assets."""
    package = Path(catalogue_module.__file__).parent
    covered = {package / name for name in _GENERATOR_SOURCES}
    imported = set().union(*(_imported_asset_files(f, package) for f in (package / "gen").glob("*.py")))
    assert {package / "spec.py", package / "palette.py", package / "gen" / "common.py"} <= imported
    assert not {f for f in imported if f not in covered and f.parent not in covered}


def test_the_cache_key_covers_the_variants_data_files(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A colour or a size edited in gen/data/*.json is another asset: the key changes, no stale copy is served."""
    import physcensis.assets.cache as cache

    package = Path(catalogue_module.__file__).parent
    copy = tmp_path / "assets"
    for name in _GENERATOR_SOURCES:
        source = package / name
        target = copy / name
        if source.is_dir():
            shutil.copytree(source, target, ignore=shutil.ignore_patterns("__pycache__"))
        else:
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy(source, target)
    monkeypatch.setattr(cache, "__file__", str(copy / "cache.py"))
    fingerprint = cache.generator_fingerprint.__wrapped__  # the uncached function: it is computed once per process
    before = fingerprint()
    data = sorted((copy / "gen" / "data").glob("*.json"))
    assert data, "the variants' data files are under gen/data"
    data[0].write_text(data[0].read_text().replace("0.", "0.0", 1))
    assert fingerprint() != before
