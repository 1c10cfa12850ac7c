"""The variety experiment: does a policy learn more from N demonstrations in N varied scenes than from N
demonstrations in one scene? `python -m physcensis.policy.experiment` or `physcensis policy experiment`.

1. scenes: N scenes of the dining prompt (seeds 0..N-1, the default seeded variety), M unseen ones (seeds 1000..) and M
   of another prompt (seeds 2000..), MJCF export only;
2. demonstrations of the task, without camera frames: one in each of the N varied scenes, and N (seeds 0..N-1) in
   the first of them;
3. the same BC training (`TrainSettings`) on each, from as many successful episodes each (the smaller count);
4. both policies rolled out on the same unseen dining scenes and the other prompt's scenes; reaching and placing
   with Wilson 95 % intervals.

Every stage keeps its outputs under the work folder and is skipped when they are there, so a stopped run resumes.
"""

from __future__ import annotations

import argparse
import json
import logging
import time
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from physcensis.fileio import atomic_write_text
from physcensis.machine import machine_info
from physcensis.policy.backend import PolicyError
from physcensis.policy.evaluate import DEFAULT_TASK, EvalResult, EvalSettings, evaluate
from physcensis.policy.train import POLICY, TrainSettings, train
from physcensis.robot import demos

PROMPT = "a dining table set up for four people"
OTHER_PROMPT = "a coffee table with three cups, two plates and a vase of flowers"
RESULT = Path("bench/results/policy_variety.json")
TRAIN_SEED, EVAL_SEED, OTHER_SEED = 0, 1000, 2000  # first scene seed of each set
VARIED, ONE = "varied", "one-scene"

Log = Callable[[str], None]
_LOG = logging.getLogger(__name__)


@dataclass(frozen=True)
class ExperimentSettings:
    demos: int = 20  # N
    eval_scenes: int = 10  # M, per prompt
    task: str = DEFAULT_TASK
    variety: str = "normal"
    training: TrainSettings = field(default_factory=TrainSettings)
    max_steps: int = 600
    videos: int = 1  # filmed rollouts per evaluation
    workers: int = 2  # demonstration recording in parallel


def _scenes(root: Path, prompt: str, seeds: Sequence[int], variety: str, log: Log) -> dict[str, str]:
    """A scene folder per seed under root (seed_NNNN), made when missing; the seeds that failed, with why."""
    from physcensis import api

    failed: dict[str, str] = {}
    for seed in seeds:
        folder = root / f"seed_{seed:04d}"
        if (folder / "scene.json").is_file() and (folder / "mjcf" / "scene.xml").is_file():
            continue
        log(f"scene {prompt!r} seed {seed}")
        generated = api.generate(prompt, seed=seed, variety=variety)
        if generated.solution is None:
            failed[str(seed)] = str(generated.result.failure or "no scene")
            continue
        api.write_generated(generated, folder, exports=("mjcf",))
    return failed


def _demos(work: Path, settings: ExperimentSettings, log: Log) -> dict[str, dict[str, Any]]:
    """The two demonstration sets' reports (their datasets beside them)."""
    varied_scenes = work / "scenes" / VARIED
    record = demos.DemoSettings(task=settings.task, episodes=1, seed=0, images=None)
    log(f"demonstrations: one in each of {settings.demos} varied scenes")
    varied = demos.run_batch(varied_scenes, work / "demos" / VARIED, record, workers=settings.workers)
    one_out = work / "demos" / ONE
    repeated = demos.DemoSettings(task=settings.task, episodes=settings.demos, seed=0, images=None)
    first = demos.scene_folders(varied_scenes)[0]
    report_path = one_out / demos.REPORT
    if report_path.is_file() and json.loads(report_path.read_text()).get("attempted") == settings.demos:
        one = json.loads(report_path.read_text())
    else:
        log(f"demonstrations: {settings.demos} in one scene ({first.name})")
        one = demos.run_scene(first, one_out, repeated, overwrite=True)
    return {VARIED: varied, ONE: one}


def run(work: str | Path, settings: ExperimentSettings | None = None, log: Log = _LOG.info) -> dict[str, Any]:
    """The whole experiment under `work`; the result record (also written to work/policy_variety.json)."""
    settings = settings or ExperimentSettings()
    work = Path(work)
    started = time.perf_counter()
    n, m = settings.demos, settings.eval_scenes
    failed = {
        VARIED: _scenes(work / "scenes" / VARIED, PROMPT, range(TRAIN_SEED, TRAIN_SEED + n), settings.variety, log),
        "dining": _scenes(work / "scenes" / "dining", PROMPT, range(EVAL_SEED, EVAL_SEED + m), settings.variety, log),
        "other": _scenes(
            work / "scenes" / "other", OTHER_PROMPT, range(OTHER_SEED, OTHER_SEED + m), settings.variety, log
        ),
    }
    scene_seconds = time.perf_counter() - started
    reports = _demos(work, settings, log)
    usable = min(int(r["succeeded"]) for r in reports.values())
    if usable == 0:
        raise PolicyError("a demonstration set has no successful episode; nothing to compare")
    training = TrainSettings(**{**asdict(settings.training), "max_episodes": usable})
    rows: list[dict[str, Any]] = []
    trained: dict[str, Any] = {}
    for name in (VARIED, ONE):
        policy_dir = work / "policies" / name
        if not (policy_dir / POLICY).is_file():
            log(f"training on {name} ({usable} episodes, {training.steps} steps)")
            result = train(work / "demos" / name / demos.DATASET, policy_dir, training)
            trained[name] = {"seconds": result.seconds, "final_loss": round(result.final_loss, 5)}
        else:
            trained[name] = json.loads((policy_dir / "train.json").read_text())
            trained[name] = {"seconds": trained[name]["seconds"], "final_loss": round(trained[name]["final_loss"], 5)}
        for scenes in ("dining", "other"):
            out = work / "eval" / f"{name}__{scenes}"
            log(f"evaluating {name} on {scenes}")
            evaluation = evaluate(
                policy_dir,
                work / "scenes" / scenes,
                out,
                EvalSettings(task=settings.task, max_steps=settings.max_steps, videos=settings.videos),
                overwrite=True,
            )
            rows.append(_row(name, scenes, evaluation))
    record = {
        "experiment": "policy variety (issue 43)",
        "task": settings.task,
        "prompts": {"train and dining": PROMPT, "other": OTHER_PROMPT},
        "settings": {**asdict(settings), "training": {**asdict(training), "hidden": list(training.hidden)}},
        "scene_seeds": {
            VARIED: [TRAIN_SEED, TRAIN_SEED + n - 1],
            "dining": [EVAL_SEED, EVAL_SEED + m - 1],
            "other": [OTHER_SEED, OTHER_SEED + m - 1],
        },
        "scenes_failed": failed,
        "demonstrations": {
            name: {"attempted": r["attempted"], "succeeded": r["succeeded"], "used": usable}
            for name, r in reports.items()
        },
        "training": trained,
        "table": rows,
        "seconds": {"scenes": round(scene_seconds, 1), "total": round(time.perf_counter() - started, 1)},
        "machine": machine_info(),
    }
    atomic_write_text(work / "policy_variety.json", json.dumps(record, indent=2) + "\n")
    return record


def _row(name: str, scenes: str, evaluation: EvalResult) -> dict[str, Any]:
    return {
        "trained_on": name,
        "evaluated_on": scenes,
        "reaching": evaluation.reaching.to_dict(),
        "placing": evaluation.placing.to_dict(),
        "median_steps": sorted(e.steps for e in evaluation.episodes)[len(evaluation.episodes) // 2],
    }


def table(record: dict[str, Any]) -> str:
    """The result as a Markdown table."""
    lines = ["| trained on | evaluated on | reaching | placing |", "|---|---|---|---|"]
    for row in record["table"]:
        cells = [_rate(row[measure]) for measure in ("reaching", "placing")]
        lines.append(f"| {row['trained_on']} | {row['evaluated_on']} | {cells[0]} | {cells[1]} |")
    return "\n".join(lines)


def _rate(rate: dict[str, Any]) -> str:
    low, high = rate["ci95"]
    return f"{rate['successes']}/{rate['trials']} ({rate['rate']:.0%}; 95 % CI {low:.0%}–{high:.0%})"


def main(argv: Sequence[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--work", type=Path, default=Path("out/policy_variety"), help="scenes, demos, policies")
    parser.add_argument("--out", type=Path, default=RESULT, help="the result JSON")
    parser.add_argument("--demos", type=int, default=ExperimentSettings.demos)
    parser.add_argument("--eval-scenes", type=int, default=ExperimentSettings.eval_scenes)
    parser.add_argument("--steps", type=int, default=TrainSettings.steps)
    parser.add_argument("--rnn", action="store_true")
    args = parser.parse_args(argv)
    training = TrainSettings(steps=args.steps, rnn=args.rnn, hidden=(400,) if args.rnn else TrainSettings.hidden)
    settings = ExperimentSettings(demos=args.demos, eval_scenes=args.eval_scenes, training=training)
    logging.basicConfig(level=logging.INFO, format="%(asctime)s %(message)s")
    record = run(args.work, settings)
    atomic_write_text(args.out, json.dumps(record, indent=2) + "\n")
    _LOG.info("\n%s", table(record))


if __name__ == "__main__":
    main()
