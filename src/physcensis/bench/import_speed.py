"""Benchmark: importing a library of real third-party meshes with a cold cache.

Uses pybullet_data's mug, duck, teddy and soccer ball (the `bullet` extra) and, when PHYSCENSIS_BENCH_ROBOSUITE
names robosuite's `models/assets/objects/meshes` folder, its bottle, bread, can, cereal, lemon and milk. Per mesh:
seconds (timed alone, cold), convex parts, surface deviation of the hulls in mm both ways, whether a cavity stays
open; then the whole library with `load_library`'s default workers, cold and warm.
`python -m physcensis.bench --only import`.
"""

from __future__ import annotations

import json
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path
from typing import Any
from unittest import mock

import numpy as np

from physcensis.assets.cache import CACHE_ENV, AssetCache
from physcensis.assets.decompose import blocks_cavity
from physcensis.assets.hulls import surface_deviation
from physcensis.assets.library import load_library
from physcensis.assets.model import Asset

ROBOSUITE_ENV = "PHYSCENSIS_BENCH_ROBOSUITE"
SOURCES = {"pb": "pybullet_data", "rs": "robosuite"}
PYBULLET = (  # file in pybullet_data, its name here, entry fields, files it references
    ("objects/mug.obj", "mug.obj", {"id": "pb_mug", "category": "mug"}, ()),
    ("duck.obj", "duck.obj", {"id": "pb_duck", "category": "toy duck", "scale": 0.05}, ("duck.mtl", "duckCM.png")),
    ("teddy2_VHACD_CHs.obj", "teddy.obj", {"id": "pb_teddy", "category": "teddy bear", "scale": 0.1}, ()),
    ("soccerball.obj", "soccerball.obj", {"id": "pb_ball", "category": "ball", "scale": 0.2}, ("soccerball.mtl",)),
)
ROBOSUITE: tuple[tuple[str, str], ...] = (("bottle", "bottle"), ("bread", "bread"), ("can", "can"))
ROBOSUITE += (("cereal", "cereal box"), ("lemon", "lemon"), ("milk", "milk carton"))


def _copy_pybullet(meshes: Path) -> list[dict[str, Any]]:
    try:
        import pybullet_data
    except ImportError:
        return []
    source = Path(pybullet_data.getDataPath())
    entries = []
    for original, name, fields, extras in PYBULLET:
        shutil.copy(source / original, meshes / name)
        for file in extras:
            shutil.copy(source / file, meshes / file)
        entries.append({"file": f"meshes/{name}", **fields})
    return entries


def _copy_robosuite(meshes: Path) -> list[dict[str, Any]]:
    folder = os.environ.get(ROBOSUITE_ENV)
    if not folder or not Path(folder).is_dir():
        return []
    entries = []
    for name, category in ROBOSUITE:
        if (Path(folder) / f"{name}.stl").is_file():
            shutil.copy(Path(folder) / f"{name}.stl", meshes / f"rs_{name}.stl")
            entries.append({"file": f"meshes/rs_{name}.stl", "id": f"rs_{name}", "category": category})
    return entries


def _write_library(folder: Path, entries: list[dict[str, Any]]) -> Path:
    (folder / "library.json").write_text(json.dumps({"name": "bench", "assets": entries}))
    return folder


def _mesh_figures(asset: Asset, seconds: float) -> dict[str, Any]:
    parts = [np.asarray(p.vertices) for p in asset.collision if p.vertices is not None]
    deviation = surface_deviation(asset.visual, parts)
    return {
        "id": asset.id,
        "seconds": round(seconds, 2),
        "hulls": len(asset.collision),
        "mesh_outside_hulls_mm": round(1000 * deviation.mesh_max, 1),
        "hull_from_mesh_max_mm": round(1000 * deviation.hull_max, 1),
        "hull_from_mesh_p95_mm": round(1000 * deviation.hull_p95, 1),
        "cavity": None if asset.cavity is None else not blocks_cavity(parts, asset.cavity),
    }


def _per_mesh(folder: Path, cache: AssetCache) -> list[dict[str, Any]]:
    """Entries one after another (one worker, cold): each one's seconds, parts and deviation."""
    last = [time.perf_counter()]
    seconds: dict[int, float] = {}  # id of the imported asset -> its seconds (a failed entry takes its lap too)

    def lap(_label: str, outcome: object) -> None:
        now = time.perf_counter()
        seconds[id(outcome)] = now - last[0]
        last[0] = now

    result = load_library(folder, cache=cache, workers=1, progress=lap)
    rows = [_mesh_figures(asset, seconds[id(asset)]) for asset in result.assets]
    return rows + [{"id": str(err), "error": str(err)} for err in result.errors]


def _timed_library(folder: Path, cache: AssetCache) -> tuple[float, int]:
    start = time.perf_counter()
    result = load_library(folder, cache=cache)
    return time.perf_counter() - start, len(result.assets)


def run() -> dict[str, Any]:
    """Per-mesh cold import figures, then the whole library cold and warm (fresh cache directories)."""
    with tempfile.TemporaryDirectory(prefix="physcensis-import-bench-") as tmp:
        root = Path(tmp)
        folder, cache_root = root / "lib", root / "cache"
        (folder / "meshes").mkdir(parents=True)
        entries = _copy_robosuite(folder / "meshes") + _copy_pybullet(folder / "meshes")
        _write_library(folder, entries)
        with mock.patch.dict(os.environ, {CACHE_ENV: str(cache_root / "env")}):  # no user cache is touched
            meshes = _per_mesh(folder, AssetCache(cache_root / "one_by_one"))
            library_cache = AssetCache(cache_root / "library")
            cold_s, count = _timed_library(folder, library_cache)
            warm_s, _ = _timed_library(folder, library_cache)
    return {
        "benchmark": "import_speed",
        "sources": sorted({SOURCES[e["id"].split("_")[0]] for e in entries}),
        "meshes": meshes,
        "library_assets": count,
        "library_cold_s": round(cold_s, 2),
        "library_warm_s": round(warm_s, 3),
    }


if __name__ == "__main__":
    json.dump(run(), sys.stdout, indent=1)
    sys.stdout.write("\n")
