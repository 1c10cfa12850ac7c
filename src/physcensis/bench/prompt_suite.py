"""The public prompt suite: generate each prompt offline and check its `expect` block."""

from __future__ import annotations

import json
import time
from collections import Counter
from pathlib import Path
from typing import Any

from physcensis.scene import Scene, Support

SUITE = Path(__file__).resolve().parents[3].parent / "shared" / "bench" / "prompts.jsonl"
SETTLE_LIMIT_M = 0.003


def load_suite(path: Path | None = None) -> list[dict[str, Any]]:
    path = path or SUITE
    return [json.loads(line) for line in path.read_text().splitlines() if line.strip()]


def _support_height(scene: Scene, object_id: str, on: dict[str, str]) -> int:
    height, seen = 1, {object_id}
    while object_id in on and on[object_id] not in seen:
        object_id = on[object_id]
        seen.add(object_id)
        height += 1
    return height


def check_expectations(scene: Scene, expect: dict[str, Any]) -> list[str]:
    """What the scene misses of an `expect` block (empty when it meets it)."""
    placed = scene.placed
    by_id = {o.id: o for o in placed}
    problems = []
    if len(placed) < expect.get("min_objects", 0):
        problems.append(f"{len(placed)} objects placed, expected at least {expect['min_objects']}")
    counts = Counter(o.category for o in placed)
    for category, need in expect.get("categories", {}).items():
        if counts[category] < need:
            problems.append(f"{counts[category]} x {category}, expected at least {need}")
    on = {o.id: o.placement.target for o in placed
          if o.placement and o.placement.predicate == "PLACE-ON" and o.placement.target in by_id}
    inside = {o.id: o.placement.target for o in placed
              if o.placement and o.placement.predicate == "PLACE-IN" and o.placement.target in by_id}
    for subject, relation, target in expect.get("relations", []):
        links = on if relation == "on" else inside
        if not any(o.category == subject and o.id in links and by_id[links[o.id]].category == target
                   for o in placed):
            problems.append(f"no {subject} {relation} a {target}")
    if "stack_height" in expect:
        tallest = max((_support_height(scene, oid, on) for oid in by_id), default=0)
        if tallest < expect["stack_height"]:
            problems.append(f"tallest stack has {tallest} objects, expected {expect['stack_height']}")
    placements = {p["object"]: p for p in scene.metrics.get("placements", [])}
    for category in expect.get("fragile", []):
        fragile = [o for o in placed if o.category == category and o.id in placements
                   and placements[o.id].get("stability_target") == "unstable"]
        if not fragile:
            problems.append(f"no {category} placed with a fragile (unstable) placement")
        elif any((placements[o.id].get("p_fail") or 0.0) < 0.5 for o in fragile):
            values = [placements[o.id].get("p_fail") for o in fragile]
            problems.append(f"{category} is not fragile enough (p_fail {values})")
    distance = scene.metrics.get("settle_distance_m")
    if distance is None or distance >= SETTLE_LIMIT_M:
        problems.append(f"settle distance {distance} m is not below {SETTLE_LIMIT_M} m")
    return problems


def run_prompt(case: dict[str, Any], seed: int = 0, out_dir: Path | None = None) -> dict[str, Any]:
    from physcensis.api import generate, write_generated

    support = Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))
    start = time.perf_counter()
    generated = generate(case["prompt"], support=support, seed=seed,
                         min_objects=case.get("expect", {}).get("min_objects", 0))
    seconds = time.perf_counter() - start
    scene = generated.solution.scene if generated.solution else None
    problems = check_expectations(scene, case.get("expect", {})) if scene else ["no scene"]
    if out_dir is not None and generated.solution is not None:
        write_generated(generated, out_dir / case["id"])
    return {
        "id": case["id"], "ok": not problems, "problems": problems, "seconds": round(seconds, 2),
        "objects": len(scene.placed) if scene else 0, "rounds": generated.result.rounds,
        "settle_distance_m": scene.metrics.get("settle_distance_m") if scene else None,
    }


def run(seed: int = 0, out_dir: Path | None = None) -> dict[str, Any]:
    if not SUITE.is_file():
        return {"skipped": f"{SUITE} not found"}
    rows = [run_prompt(case, seed, out_dir) for case in load_suite()]
    return {"prompts": len(rows), "passed": sum(r["ok"] for r in rows), "results": rows}
