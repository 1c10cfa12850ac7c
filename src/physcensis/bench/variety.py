"""Seeded variety over the prompt suites: for every prompt, seeds 0..N-1 at one variety level, how many distinct
scenes and distinct choices of assets and counts they make (evaluation/diversity.py), how many meet the prompt's
`expect` block and how many rest (settle distance <= 3 mm). Distinct choices are asked of a prompt where its words
leave them open: half the seeds, or as many as the planner's first program had open when fewer.

Scenes are generated offline in a pool of worker processes (each loads the catalogue once) and kept in memory; the
result lists every prompt and the (prompt, seed) pairs that missed their block, with what they missed.
"""

from __future__ import annotations

import math
import os
import statistics
import time
from concurrent.futures import ProcessPoolExecutor
from typing import Any

from physcensis.bench.prompt_suite import SUITES, check_expectations, load_suite
from physcensis.evaluation.diversity import prompt_diversity
from physcensis.scene import Scene, Support

DISTINCT_SHARE = 0.95  # 19 of 20 scenes distinct
CHOICES_SHARE = 0.5  # 10 of 20 distinct choices of assets and counts, where the prompt leaves them open


def open_choices(case: dict[str, Any], variety: str) -> int:
    """How many choices of assets and counts the planner's first program of the prompt draws from (seed 0): where
    the words and the catalogue leave fewer open than the share asked of the seeds ("a dozen tennis balls", one
    tennis ball in the catalogue), a prompt is asked for as many as are open."""
    from physcensis.agent.base import AgentContext
    from physcensis.agent.planner import OfflinePlanner

    support = Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))
    planner = OfflinePlanner(variety=variety)
    planner.propose(AgentContext(case["prompt"], support, (), seed=0))
    return planner.open_choices


def _one(case: dict[str, Any], seed: int, variety: str) -> tuple[str | None, list[str], float]:
    """One (prompt, seed): the scene as JSON (None when nothing was made), what it misses, seconds."""
    from physcensis.api import generate

    support = Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))
    start = time.perf_counter()
    generated = generate(
        case["prompt"],
        support=support,
        seed=seed,
        variety=variety,
        min_objects=case.get("expect", {}).get("min_objects", 0),
    )
    seconds = time.perf_counter() - start
    scene = generated.solution.scene if generated.solution else None
    if scene is None:
        return None, ["no scene"], seconds
    added = [row["id"] for row in generated.added]
    return scene.to_json(), check_expectations(scene, case.get("expect", {}), added=added), seconds


def run(
    suites: tuple[str, ...] = ("public", "home"), seeds: int = 20, variety: str = "normal", workers: int = 2
) -> dict[str, Any]:
    cases = [(suite, case) for suite in suites for case in load_suite(SUITES[suite])]
    jobs = [(suite, case, seed) for suite, case in cases for seed in range(seeds)]
    with ProcessPoolExecutor(max_workers=max(1, min(workers, os.cpu_count() or 1))) as pool:
        futures = [pool.submit(_one, case, seed, variety) for _, case, seed in jobs]
        outcomes = [f.result() for f in futures]
    rows, misses = [], []
    for k, (suite, case) in enumerate(cases):
        mine = outcomes[k * seeds : (k + 1) * seeds]
        scenes = [Scene.model_validate_json(text) for text, _, _ in mine if text is not None]
        for seed, (_, problems, _) in enumerate(mine):
            if problems:
                misses.append({"suite": suite, "id": case["id"], "seed": seed, "problems": problems})
        space = open_choices(case, variety)
        row: dict[str, Any] = {
            "suite": suite,
            "id": case["id"],
            "scenes": len(scenes),
            "open_choices": space,
            "choices_target": min(math.ceil(CHOICES_SHARE * seeds), space),
        }
        if scenes:
            summary = prompt_diversity(scenes)
            row |= {
                "distinct_scenes": summary.distinct_scenes,
                "distinct_choices": summary.distinct_asset_choices,
                "mean_layout_distance_m": summary.mean_layout_distance_m,
                "resting": summary.resting,
            }
        row["expectations_met"] = sum(not problems for _, problems, _ in mine)
        row["median_seconds"] = round(statistics.median(s for _, _, s in mine), 2)
        rows.append(row)
    pairs = len(jobs)
    met = sum(r["expectations_met"] for r in rows)
    return {
        "variety": variety,
        "seeds": seeds,
        "prompts": len(rows),
        "pairs": pairs,
        "expectations_met": met,
        "expectations_met_share": round(met / max(1, pairs), 4),
        "prompts_with_distinct_scenes": sum(r.get("distinct_scenes", 0) >= DISTINCT_SHARE * seeds for r in rows),
        "prompts_with_distinct_choices": sum(r.get("distinct_choices", 0) >= CHOICES_SHARE * seeds for r in rows),
        "prompts_reaching_choices_target": sum(r.get("distinct_choices", 0) >= r["choices_target"] for r in rows),
        "prompts_with_fewer_open_choices": sum(r["open_choices"] < CHOICES_SHARE * seeds for r in rows),
        "scenes_resting": sum(r.get("resting", 0) for r in rows),
        "results": rows,
        "misses": misses,
    }


def run_public(seeds: int = 20) -> dict[str, Any]:
    return run(("public",), seeds)


def run_home(seeds: int = 20) -> dict[str, Any]:
    return run(("home",), seeds)
