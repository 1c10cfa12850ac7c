"""Benchmark: generating the whole built-in catalogue cold, and loading it from the disk cache.

`run()` returns a JSON-ready dict; `python -m physcensis.bench.assets_speed` prints it.
"""

from __future__ import annotations

import json
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from physcensis.assets.cache import CACHE_ENV, AssetCache
from physcensis.assets.catalogue import Catalogue


def _timed_load(cache: AssetCache) -> tuple[float, int]:
    start = time.perf_counter()
    assets = Catalogue(cache=cache).all()
    return time.perf_counter() - start, len(assets)


def run(repeats: int = 5) -> dict[str, Any]:
    """Cold generation time (empty cache directory) and median cache-hit load time of the full catalogue."""
    with tempfile.TemporaryDirectory(prefix="physcensis-assets-bench-") as tmp:
        previous = os.environ.get(CACHE_ENV)
        os.environ[CACHE_ENV] = tmp
        try:
            cache = AssetCache(Path(tmp))
            cold_s, count = _timed_load(cache)
            warm = [_timed_load(cache)[0] for _ in range(max(1, repeats))]
            catalogue = Catalogue(cache=cache)
            start = time.perf_counter()
            for query in (
                "a white ceramic mug",
                "a stack of books",
                "a ripe banana",
                "a cardboard box",
                "a wine glass",
            ):
                catalogue.resolve(query)
            resolve_s = (time.perf_counter() - start) / 5
        finally:
            if previous is None:
                os.environ.pop(CACHE_ENV, None)
            else:
                os.environ[CACHE_ENV] = previous
    return {
        "benchmark": "assets_speed",
        "assets": count,
        "categories": len(catalogue.categories()),
        "generate_cold_s": round(cold_s, 3),
        "generate_per_asset_ms": round(1000 * cold_s / count, 2),
        "cache_load_median_s": round(statistics.median(warm), 3),
        "cache_load_runs_s": [round(t, 3) for t in warm],
        "resolve_mean_ms": round(1000 * resolve_s, 2),
    }


if __name__ == "__main__":
    sys.stdout.write(json.dumps(run(), indent=2) + "\n")
