"""Cross-engine check: the prompt suite's scenes and clutter scenes, made and verified here, settled again under our
contact settings, under MuJoCo's defaults, and in PyBullet (on the URDF export, with PyBullet's defaults).

Reads the bundled prompt suite (`physcensis/bench/prompts.jsonl`); needs the `[bullet]` extra.
"""

from __future__ import annotations

import statistics
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from physcensis.bench.prompt_suite import load_suite
from physcensis.physics.engine import SettleEngine
from physcensis.scene import Scene, Support, save_scene

LIMIT_M = 0.001  # the bar: a scene rests in an engine when its mean settle distance is at most this
ENGINES = ("mujoco", "mujoco_default", "bullet")
CLUTTER_SCENES = 5  # per clutter mode


def _engines() -> dict[str, SettleEngine]:
    """The registered engines the benchmark compares, keyed as its results name them."""
    from physcensis.crosscheck.engines import settle_engine

    return {key: settle_engine(key.replace("_", "-")) for key in ENGINES}


def _suite_scenes(seed: int) -> Iterator[tuple[str, Scene | None]]:
    from physcensis.api import generate

    for case in load_suite():
        support = Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))
        generated = generate(
            case["prompt"], support=support, seed=seed, min_objects=case.get("expect", {}).get("min_objects", 0)
        )
        yield case["id"], generated.solution.scene if generated.solution is not None else None


def _clutter_scenes(scenes: int) -> Iterator[tuple[str, Scene | None]]:
    from physcensis.bench.clutter import run_scene

    for mode in ("no-stack", "with-stack"):
        for seed in range(scenes):
            yield f"clutter {mode} {seed}", run_scene(mode, seed).scene


def crosscheck_scenes(seed: int, clutter_scenes: int) -> Iterator[tuple[str, Scene | None]]:
    """The scenes every cross-engine check measures: the prompt suite's at `seed`, then clutter scenes (None: a
    prompt that gave no scene)."""
    yield from _suite_scenes(seed)
    yield from _clutter_scenes(clutter_scenes)


def measure(name: str, scene: Scene, engines: dict[str, SettleEngine]) -> dict[str, Any]:
    """One scene's settle distance under every engine, and the object that moved most in any of them."""
    row: dict[str, Any] = {"id": name, "objects": len(scene.placed)}
    worst = ("", "", -1.0)
    for key, engine in engines.items():
        distance = engine.settle_distance(scene)
        row[f"{key}_settle_m"] = round(distance.mean_m, 6)
        if distance.diverged:
            row[f"{key}_diverged"] = distance.diverged
        oid = max(distance.per_object, key=distance.per_object.__getitem__)
        if distance.per_object[oid] > worst[2]:
            worst = (oid, key, distance.per_object[oid])
    row.update(worst_object=worst[0], worst_engine=worst[1], worst_m=round(worst[2], 6))
    return row


def run(seed: int = 0, clutter_scenes: int = CLUTTER_SCENES, scenes_out: Path | None = None) -> dict[str, Any]:
    """The table's rows and summary; `scenes_out` also keeps every scene measured (`<id>.json`) to look into."""
    engines = _engines()
    if scenes_out is not None:
        Path(scenes_out).mkdir(parents=True, exist_ok=True)
    rows: list[dict[str, Any]] = []
    for name, scene in crosscheck_scenes(seed, clutter_scenes):
        if scene is None or not scene.placed:
            rows.append({"id": name, "objects": 0, "skipped": "no scene"})
            continue
        if scenes_out is not None:
            save_scene(scene, Path(scenes_out) / f"{name.replace(' ', '_')}.json")
        rows.append(measure(name, scene, engines))
    return summarise(rows)


def summarise(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """How many measured scenes rest within the limit under each engine, with the median and largest settle."""
    measured = [r for r in rows if "skipped" not in r]
    summary = {
        key: {
            "at_most_limit": sum(r[f"{key}_settle_m"] <= LIMIT_M for r in measured),
            "median_settle_m": round(statistics.median(r[f"{key}_settle_m"] for r in measured), 6),
            "max_settle_m": max(r[f"{key}_settle_m"] for r in measured),
        }
        for key in ENGINES
    }
    return {"scenes": len(measured), "limit_m": LIMIT_M, "engines": summary, "results": rows}
