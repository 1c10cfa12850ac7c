"""Robot demonstrations on generated dining scenes (issue 17's numbers).

Generates `SCENES` scenes of the dining prompt (seeds 0, 1, ... with the default seeded variety, so the cups and
plates stand elsewhere, and are other cups and plates, in every scene; MJCF export only), records one episode of the
paper's task in each with one worker and 128 x 128 camera frames, as a real dataset would be recorded, then replays
every episode recorded as successful in a fresh world (`recheck`). The figures: success rate (goal: at least 80 %),
failures by stage with their reasons, the re-check (goal: every success confirmed), per-episode median seconds of
planning, simulation and rendering, and the dataset's size.
"""

from __future__ import annotations

import json
import os
import subprocess
import tempfile
import time
from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from physcensis.assets.cache import CACHE_ENV, cache_root
from physcensis.robot import demos

PROMPT = "a dining table set up for four people"
VARIETY = "normal"
TASK = "pick up the leftmost cup and place it on the rightmost plate"
SCENES = 20
IMAGES = (128, 128)
SUCCESS_GOAL = 0.8

SceneMaker = Callable[[Path, Sequence[int]], dict[str, str]]
GRASPS = "grasps"  # the grasp cache's folder in the cache root


def generate_scenes(root: Path, seeds: Sequence[int]) -> dict[str, str]:
    """One scene folder per seed under `root` (`seed_NNN`); the seeds whose generation failed, with why."""
    from physcensis import api

    failed: dict[str, str] = {}
    for seed in seeds:
        generated = api.generate(PROMPT, seed=seed, variety=VARIETY)
        if generated.solution is None:
            failed[str(seed)] = str(generated.result.failure or "no scene")
            continue
        api.write_generated(generated, root / f"seed_{seed:03d}", exports=("mjcf",))
    return failed


def _commit() -> str | None:
    """The source tree's commit (with "+dirty" when it has changes), None outside a git checkout."""
    here = Path(__file__).parents[1]  # the package: any uncommitted change in it makes the run "+dirty"
    try:
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=here, capture_output=True, text=True)
        dirty = subprocess.run(["git", "status", "--porcelain", "--", "."], cwd=here, capture_output=True, text=True)
    except OSError:
        return None
    if head.returncode != 0:
        return None
    return head.stdout.strip() + ("+dirty" if dirty.stdout.strip() else "")


@contextmanager
def _fresh_grasp_cache(folder: Path) -> Iterator[None]:
    """The user's caches (assets, convex parts) but an empty grasp cache while the block runs: the times are a first
    run's, where the first scene picking an asset samples and lift-tests its grasps (the later ones reuse them)."""
    real = cache_root()
    folder.mkdir(parents=True)
    for entry in real.iterdir() if real.is_dir() else []:
        if entry.name != GRASPS:
            (folder / entry.name).symlink_to(entry.resolve(), target_is_directory=entry.is_dir())
    before = os.environ.get(CACHE_ENV)
    os.environ[CACHE_ENV] = str(folder)
    try:
        yield
    finally:
        if before is None:
            os.environ.pop(CACHE_ENV, None)
        else:
            os.environ[CACHE_ENV] = before


def _scene_reports(out_dir: Path) -> list[dict[str, Any]]:
    return [json.loads(path.read_text()) for path in sorted((out_dir / demos.SCENES).glob(f"*/{demos.REPORT}"))]


def _failures(episodes: Iterable[dict[str, Any]]) -> dict[str, dict[str, Any]]:
    """stage -> how many episodes failed there and each one's reason."""
    by_stage: dict[str, dict[str, Any]] = {}
    for episode in episodes:
        if episode["success"]:
            continue
        entry = by_stage.setdefault(episode["stage"], {"count": 0, "reasons": []})
        entry["count"] += 1
        entry["reasons"].append(f"{episode.get('scene', '?')}: {episode['reason']}")
    return by_stage


def _median_seconds(episodes: Sequence[dict[str, Any]]) -> dict[str, float | None]:
    """Per stage, the median over the episodes that reached it."""
    medians: dict[str, float | None] = {}
    for stage in demos.TIMED_STAGES:
        medians[stage] = demos.median_seconds([e["seconds"][stage] for e in episodes if stage in e.get("seconds", {})])
    return medians


def _episodes(reports: Sequence[dict[str, Any]]) -> list[dict[str, Any]]:
    """Every attempted episode of every scene, with its scene's folder name."""
    return [{**episode, "scene": Path(r["scene"]).name} for r in reports for episode in r["episodes"]]


def distinct_scenes(root: Path) -> int | None:
    """How many of the generated scenes differ (evaluation/diversity.py): varied scenes, not one scene repeated."""
    from physcensis.evaluation.diversity import distinct_scenes as count_distinct
    from physcensis.scene import load_scene

    scenes = [load_scene(path) for path in sorted(root.glob("*/scene.json"))]
    return count_distinct(scenes) if scenes else None


def summarize(
    summary: dict[str, Any],
    reports: Sequence[dict[str, Any]],
    checked: dict[str, int],
    dataset: Path,
    generation_failed: dict[str, str],
    seconds: dict[str, float],
) -> dict[str, Any]:
    """The benchmark's figures from the merged report, the per-scene reports and the re-check."""
    episodes = _episodes(reports)
    recorded = sum(1 for e in episodes if e.get("steps", 0) > 0)
    size = dataset.stat().st_size if dataset.is_file() else 0
    return {
        "prompt": PROMPT,
        "task": TASK,
        "scenes": summary["scenes"],
        "scenes_not_generated": generation_failed,
        "scenes_failed": summary["scenes_failed"],
        "attempted": summary["attempted"],
        "succeeded": summary["succeeded"],
        "success_rate": round(summary["success_rate"], 4),
        "success_goal": SUCCESS_GOAL,
        "failures_by_stage": _failures(episodes),
        "recheck": {**checked, "all_confirmed": checked["checked"] == checked["confirmed"]},
        "median_seconds_per_episode": _median_seconds(episodes),
        "dataset": {
            "episodes": recorded,
            "bytes": size,
            "mb_per_episode": round(size / recorded / 1e6, 2) if recorded else None,
            "images": list(IMAGES) if IMAGES else None,
        },
        "seconds": {k: round(v, 1) for k, v in seconds.items()},
    }


def run(scenes: int = SCENES, make_scenes: SceneMaker = generate_scenes) -> dict[str, Any]:
    """Generate the scenes, record one episode in each (starting from an empty grasp cache), re-check the merged
    dataset; the figures as a dict."""
    commit, load_before = _commit(), os.getloadavg()[0]
    with tempfile.TemporaryDirectory(prefix="physcensis-bench-demos-") as tmp:
        root, out = Path(tmp) / "scenes", Path(tmp) / "demos"
        start = time.perf_counter()
        generation_failed = make_scenes(root, range(scenes))
        generated = time.perf_counter()
        settings = demos.DemoSettings(task=TASK, episodes=1, seed=0, images=IMAGES)
        with _fresh_grasp_cache(Path(tmp) / "cache"):
            summary = demos.run_batch(root, out, settings, workers=1)
        recorded = time.perf_counter()
        checked = demos.recheck(out / demos.DATASET)
        env_replay = demos.replay_in_env(out / demos.DATASET)
        seconds = {
            "generation": generated - start,
            "demonstrations": recorded - generated,
            "recheck": time.perf_counter() - recorded,
        }
        result = summarize(summary, _scene_reports(out), checked, out / demos.DATASET, generation_failed, seconds)
        result.update(variety=VARIETY, distinct_scenes=distinct_scenes(root), env_replay=env_replay)
    # Times on a shared machine mean little without how busy it was (1-minute load average, at the start and end).
    result.update(
        commit=commit, load_average=[round(load_before, 2), round(os.getloadavg()[0], 2)], grasp_cache="fresh"
    )
    return result
