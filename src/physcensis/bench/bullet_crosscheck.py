"""Cross-engine check: the prompt suite's scenes (made and verified in MuJoCo) settled again in PyBullet.

Reads the bundled prompt suite (`physcensis/bench/prompts.jsonl`); needs the `[bullet]` extra.
"""

from __future__ import annotations

import statistics
from typing import Any

from physcensis.bench.prompt_suite import load_suite
from physcensis.scene import Support

LIMIT_M = 0.005


def run(seed: int = 0) -> dict[str, Any]:
    from physcensis.api import generate
    from physcensis.crosscheck.bullet_engine import BulletEngine, require_pybullet

    require_pybullet()
    bullet = BulletEngine()
    rows = []
    for case in load_suite():
        support = Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))
        generated = generate(
            case["prompt"], support=support, seed=seed, min_objects=case.get("expect", {}).get("min_objects", 0)
        )
        if generated.solution is None:
            rows.append({"id": case["id"], "objects": 0, "skipped": "no scene"})
            continue
        scene = generated.solution.scene
        distance = bullet.settle_distance(scene)
        worst = max(distance.per_object, key=distance.per_object.__getitem__)
        rows.append(
            {
                "id": case["id"],
                "objects": len(scene.placed),
                "mujoco_settle_m": scene.metrics.get("settle_distance_m"),
                "bullet_settle_m": round(distance.mean_m, 6),
                "worst_object": worst,
                "worst_m": round(distance.per_object[worst], 6),
            }
        )
    measured = [r["bullet_settle_m"] for r in rows if "bullet_settle_m" in r]
    return {
        "scenes": len(measured),
        "limit_m": LIMIT_M,
        "below_limit": sum(m < LIMIT_M for m in measured),
        "median_bullet_settle_m": round(statistics.median(measured), 6),
        "results": rows,
    }
