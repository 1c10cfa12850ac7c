"""The cross-engine check in Genesis, the paper's engine: the same kinds of scenes as `crosscheck` (the prompt suite
at seed 0, clutter seeds 0-4 of both modes), made and verified here, then settled for the paper's 4 s in Genesis on
the MJCF export, beside our own settle of the same scene. Its own benchmark (`--only crosscheck_genesis`), because
it needs the `[genesis]` extra: without it `make bench` skips it, as it skips any benchmark whose module cannot be
imported.
"""

from __future__ import annotations

import importlib.util
import statistics
import time
from typing import Any

from physcensis.bench.bullet_crosscheck import CLUTTER_SCENES, crosscheck_scenes

if importlib.util.find_spec("genesis") is None:  # the extra is missing: the benchmark runner skips this module
    raise ModuleNotFoundError("Genesis is not installed: pip install 'physcensis[genesis]'", name="genesis")

LIMIT_M = 0.003  # the bar for Genesis: every scene settles at most 3 mm


def run(seed: int = 0, clutter_scenes: int = CLUTTER_SCENES) -> dict[str, Any]:
    """One row per scene: our settle and Genesis's (mean and the object that moved most), Genesis's seconds."""
    from physcensis.crosscheck.engines import settle_engine

    ours, genesis = settle_engine("mujoco"), settle_engine("genesis")
    rows: list[dict[str, Any]] = []
    for name, scene in crosscheck_scenes(seed, clutter_scenes):
        if scene is None or not scene.placed:
            rows.append({"id": name, "objects": 0, "skipped": "no scene"})
            continue
        start = time.perf_counter()
        distance = genesis.settle_distance(scene)
        seconds = time.perf_counter() - start
        worst = max(distance.per_object, key=distance.per_object.__getitem__)
        row: dict[str, Any] = {
            "id": name,
            "objects": len(scene.placed),
            "mujoco_settle_m": round(ours.settle_distance(scene).mean_m, 6),
            "genesis_settle_m": round(distance.mean_m, 6),
            "genesis_worst_object": worst,
            "genesis_worst_m": round(distance.per_object[worst], 6),
            "genesis_seconds": round(seconds, 2),
        }
        if distance.diverged:
            row["genesis_diverged"] = distance.diverged
        rows.append(row)
    measured = [r for r in rows if "skipped" not in r]
    return {
        "scenes": len(measured),
        "limit_m": LIMIT_M,
        "at_most_limit": sum(r["genesis_settle_m"] <= LIMIT_M for r in measured),
        "median_settle_m": round(statistics.median(r["genesis_settle_m"] for r in measured), 6) if measured else None,
        "max_settle_m": max((r["genesis_settle_m"] for r in measured), default=None),
        "median_seconds": statistics.median(r["genesis_seconds"] for r in measured) if measured else None,
        "genesis": _version(),
        "results": rows,
    }


def _version() -> str:
    from importlib.metadata import version

    return f"genesis-world {version('genesis-world')}, torch {version('torch')}"
