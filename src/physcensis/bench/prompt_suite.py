"""The public prompt suites: generate each prompt offline and check its `expect` block.

`prompts.jsonl` beside this file is the suite of `../shared/bench/prompts.jsonl`, bundled so that the package and its
tests do not depend on where the repository is checked out (a test checks the copy against the shared folder).
`prompts_home.jsonl` is our own, larger suite of a home, office, kitchen, bathroom, kids' room and workshop: containers
and carriers, several stacks and groups, counts on plurals, everyday objects; its `expect` blocks also use the
arrangement keys of `bench/arrangement.py` (inside, on, stacks, rows, around). `prompts_reading.jsonl`, also our
own, asks for sentences to be read as a person reads them: head nouns, containers of their contents, carriers, one
per holder, sides and "between" as the viewer of the default render sees them, stacks with something on top, counts;
its blocks also bound what must not be there (`max_categories`: "a jug of lemonade" is one jug).
"""

from __future__ import annotations

import json
import time
from collections import Counter
from collections.abc import Sequence
from functools import partial
from pathlib import Path
from typing import Any

from physcensis.assets.catalogue import default_catalogue
from physcensis.assets.model import Asset
from physcensis.bench.arrangement import AssetOf, check_arrangements
from physcensis.errors import PhyscensisError
from physcensis.evaluation.diversity import ExpectCheck, normalise_prompt
from physcensis.fileio import BoundError, read_bounded
from physcensis.program.registry import PlacementKind, placement_spec
from physcensis.scene import PlacedObject, Scene, Support

SUITE = Path(__file__).with_name("prompts.jsonl")
HOME_SUITE = Path(__file__).with_name("prompts_home.jsonl")
READING_SUITE = Path(__file__).with_name("prompts_reading.jsonl")  # sentences read as a person reads them (issue 40)
SUITES = {"public": SUITE, "home": HOME_SUITE, "reading": READING_SUITE}
SETTLE_LIMIT_M = 0.003
MAX_EXPECT_FILE_BYTES = 16 * 2**20


def load_suite(path: Path | None = None) -> list[dict[str, Any]]:
    path = path or SUITE
    return [json.loads(line) for line in path.read_text().splitlines() if line.strip()]


def suite_expectations(paths: Sequence[Path] = tuple(SUITES.values())) -> dict[str, ExpectCheck]:
    """The check of each bundled suite prompt's expect block, by its `normalise_prompt`d text (`eval diversity`)."""
    return {
        normalise_prompt(case["prompt"]): expectation_check(case.get("expect", {}))
        for p in paths
        for case in load_suite(p)
    }


def read_expectations(path: Path) -> dict[str, ExpectCheck]:
    """`--expect FILE`: JSON lines of {"prompt": text, "expect": {...}} (a suite file reads as is)."""
    try:
        text = read_bounded(path, MAX_EXPECT_FILE_BYTES, "expect file").decode("utf-8")
    except (BoundError, UnicodeDecodeError) as exc:
        raise PhyscensisError(f"{path}: {exc}") from None
    checks = {}
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        try:
            case = json.loads(line)
        except ValueError:
            raise PhyscensisError(f"{path}:{number}: not valid JSON") from None
        if not (
            isinstance(case, dict) and isinstance(case.get("prompt"), str) and isinstance(case.get("expect"), dict)
        ):
            raise PhyscensisError(
                f'{path}:{number}: each line must be an object with a "prompt" string and an "expect" object'
            )
        checks[normalise_prompt(case["prompt"])] = expectation_check(case["expect"])
    return checks


def expectation_check(expect: dict[str, Any]) -> ExpectCheck:
    """check_expectations with this expect block, as a function of the scene."""
    return partial(check_expectations, expect=expect)


def check_expectations(
    scene: Scene, expect: dict[str, Any], asset_of: AssetOf | None = None, added: Sequence[str] = ()
) -> list[str]:
    """What the scene misses of an `expect` block (empty when it meets it). `asset_of` gives an object's asset
    (for cavities and sizes); by default the built-in catalogue's. `added` are the ids of context objects the run
    says it added unasked (`generate.added`): `max_categories` bounds only what the words asked for."""
    placed = scene.placed
    on = _placed_on(placed, placement_spec(PlacementKind.ON).name)
    return [
        *_missing_counts(placed, expect, set(added)),
        *_missing_relations(placed, on, expect.get("relations", [])),
        *_short_stack(placed, on, expect),
        *check_arrangements(scene, expect, asset_of or _catalogue_asset),
        *_not_fragile(scene, expect.get("fragile", [])),
        *_not_resting(scene),
    ]


def _catalogue_asset(placed: PlacedObject) -> Asset:
    return default_catalogue().asset_for(placed.asset, placed.description)


def _placed_on(placed: list[PlacedObject], predicate: str) -> dict[str, str]:
    """Object id -> the id of the placed object it was put on (or in) by `predicate`."""
    ids = {o.id for o in placed}
    return {
        o.id: o.placement.target
        for o in placed
        if o.placement and o.placement.predicate == predicate and o.placement.target in ids
    }


def _missing_counts(placed: list[PlacedObject], expect: dict[str, Any], added: set[str]) -> list[str]:
    problems = []
    if len(placed) < expect.get("min_objects", 0):
        problems.append(f"{len(placed)} objects placed, expected at least {expect['min_objects']}")
    counts = Counter(o.category for o in placed)
    for category, need in expect.get("categories", {}).items():
        if counts[category] < need:
            problems.append(f"{counts[category]} x {category}, expected at least {need}")
    asked = Counter(o.category for o in placed if o.id not in added)
    for category, most in expect.get("max_categories", {}).items():
        if asked[category] > most:
            problems.append(f"{asked[category]} x {category}, expected at most {most}")
    return problems


def _missing_relations(placed: list[PlacedObject], on: dict[str, str], relations: list[list[str]]) -> list[str]:
    """`[subject, "on" | "in", target]` (categories) that no placed object shows."""
    by_id = {o.id: o for o in placed}
    links = {"on": on, "in": _placed_on(placed, placement_spec(PlacementKind.IN).name)}
    problems = []
    for subject, relation, target in relations:
        link = links["on" if relation == "on" else "in"]
        if not any(o.category == subject and o.id in link and by_id[link[o.id]].category == target for o in placed):
            problems.append(f"no {subject} {relation} a {target}")
    return problems


def _short_stack(placed: list[PlacedObject], on: dict[str, str], expect: dict[str, Any]) -> list[str]:
    if "stack_height" not in expect:
        return []
    tallest = max((_stack_height(o.id, on) for o in placed), default=0)
    if tallest < expect["stack_height"]:
        return [f"tallest stack has {tallest} objects, expected {expect['stack_height']}"]
    return []


def _stack_height(object_id: str, on: dict[str, str]) -> int:
    """How many objects the stack holds from `object_id` down (it included)."""
    height, seen = 1, {object_id}
    while object_id in on and on[object_id] not in seen:
        object_id = on[object_id]
        seen.add(object_id)
        height += 1
    return height


def _not_fragile(scene: Scene, categories: list[str]) -> list[str]:
    """Categories that must have an object placed to fall easily (PLACE-ON stability "unstable", p_fail >= 0.5)."""
    placements = {p["object"]: p for p in scene.metrics.get("placements", [])}
    problems = []
    for category in categories:
        fragile = [
            o
            for o in scene.placed
            if o.category == category and o.id in placements and placements[o.id].get("stability_target") == "unstable"
        ]
        if not fragile:
            problems.append(f"no {category} placed with a fragile (unstable) placement")
        elif any((placements[o.id].get("p_fail") or 0.0) < 0.5 for o in fragile):
            values = [placements[o.id].get("p_fail") for o in fragile]
            problems.append(f"{category} is not fragile enough (p_fail {values})")
    return problems


def _not_resting(scene: Scene) -> list[str]:
    distance = scene.metrics.get("settle_distance_m")
    if distance is None or distance >= SETTLE_LIMIT_M:
        return [f"settle distance {distance} m is not below {SETTLE_LIMIT_M} m"]
    return []


def run_prompt(case: dict[str, Any], seed: int = 0, out_dir: Path | None = None) -> dict[str, Any]:
    from physcensis.api import generate, write_generated

    support = Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))
    start = time.perf_counter()
    generated = generate(
        case["prompt"], support=support, seed=seed, min_objects=case.get("expect", {}).get("min_objects", 0)
    )
    seconds = time.perf_counter() - start
    scene = generated.solution.scene if generated.solution else None
    added = [row["id"] for row in generated.added]
    problems = check_expectations(scene, case.get("expect", {}), added=added) if scene else ["no scene"]
    share = _support_share(scene) if scene is not None and scene.placed else None
    if out_dir is not None and generated.solution is not None:
        write_generated(generated, out_dir / case["id"])
    return {
        "id": case["id"],
        "ok": not problems,
        "problems": problems,
        "seconds": round(seconds, 2),
        "objects": len(scene.placed) if scene else 0,
        "rounds": generated.result.rounds,
        "settle_distance_m": scene.metrics.get("settle_distance_m") if scene else None,
        "support_in_render": None if share is None else round(share, 3),  # of render.png's area
        "requested": generated.requested,  # per category, the fewest the words ask for
        "missing": generated.missing,  # what the words ask for and the scene lacks (the report says it too)
        "elsewhere": generated.elsewhere,  # what the words put in or on a holder and the scene placed elsewhere
    }


def _support_share(scene: Scene) -> float:
    from physcensis.physics.mujoco_engine import MujocoEngine
    from physcensis.physics.render import support_share

    return support_share(MujocoEngine().build(scene), scene)


def run(seed: int = 0, out_dir: Path | None = None, suite: str = "public") -> dict[str, Any]:
    """Every prompt of a suite (`SUITES`: "public", "home" or "reading"), with how many meet their expect block."""
    rows = [run_prompt(case, seed, out_dir) for case in load_suite(SUITES[suite])]
    return {"suite": suite, "prompts": len(rows), "passed": sum(r["ok"] for r in rows), "results": rows}


def run_home(seed: int = 0, out_dir: Path | None = None) -> dict[str, Any]:
    return run(seed, out_dir, suite="home")


def run_reading(seed: int = 0, out_dir: Path | None = None) -> dict[str, Any]:
    return run(seed, out_dir, suite="reading")
