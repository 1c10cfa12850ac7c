"""Closed-loop evaluation: a trained policy rolled out in the Gymnasium environment on scene folders, with the
paper's two measures per episode and in total (`physcensis policy eval`).

* reaching: the gripper closes on the task's pick object, i.e. at some step both fingers touch it at once while the
  gripper is told to close (its target below fully open). Fingers that merely brush it while open do not count.
* placing: the environment terminates with success: the verifier that judges the demonstrations
  (`robot/verify.py`) finds the object on or in its target, released, and the rest of the scene in place.

Each rate has a Wilson 95 % interval. Episode k runs on scene folder k mod S (in name order) with `reset(seed=seed +
k)`; the first `videos` episodes are filmed from the front camera (`robot/video.py`).
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable, Iterator
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np

from physcensis.fileio import atomic_write_text, output_directory
from physcensis.policy.backend import PolicyError
from physcensis.policy.checkpoint import Policy, load_policy
from physcensis.robot import panda
from physcensis.robot.env import DEFAULT_MAX_STEPS, EnvError, PickPlaceEnv, scene_folders
from physcensis.robot.video import write_video
from physcensis.robot.world import PREFIX, RobotWorld

EVAL_RECORD = "eval.json"
DEFAULT_TASK = "pick up the leftmost cup and place it on the rightmost plate"
Z_95 = 1.959964  # the normal quantile of a two-sided 95 % interval


@dataclass(frozen=True)
class EvalSettings:
    task: str = DEFAULT_TASK
    episodes: int | None = None  # None: one per scene folder
    max_steps: int = DEFAULT_MAX_STEPS
    seed: int = 0
    videos: int = 2  # film the first K episodes

    def __post_init__(self) -> None:
        if self.max_steps < 1 or self.videos < 0 or (self.episodes is not None and self.episodes < 1):
            raise PolicyError("episodes and max_steps must be 1 or more, videos 0 or more")


@dataclass(frozen=True)
class Rate:
    """k successes of n, with the Wilson 95 % interval."""

    successes: int
    trials: int
    low: float
    high: float

    @property
    def rate(self) -> float:
        return self.successes / self.trials if self.trials else 0.0

    def to_dict(self) -> dict[str, Any]:
        return {"successes": self.successes, "trials": self.trials, "rate": round(self.rate, 4),
                "ci95": [round(self.low, 4), round(self.high, 4)]}  # fmt: skip


def wilson(successes: int, trials: int, z: float = Z_95) -> Rate:
    """The Wilson score interval of a binomial proportion (sound at 0 of n and n of n, unlike the normal one)."""
    if trials == 0:
        return Rate(0, 0, 0.0, 1.0)
    p = successes / trials
    centre = (p + z * z / (2 * trials)) / (1 + z * z / trials)
    half = z * math.sqrt(p * (1 - p) / trials + z * z / (4 * trials * trials)) / (1 + z * z / trials)
    return Rate(successes, trials, max(0.0, centre - half), min(1.0, centre + half))


@dataclass(frozen=True)
class EpisodeResult:
    scene: str
    task: str  # explicit, as the scene resolved it
    seed: int
    reached: bool
    reached_step: int | None
    placed: bool
    steps: int
    seconds: float
    video: str | None


@dataclass(frozen=True)
class EvalResult:
    out: Path
    episodes: tuple[EpisodeResult, ...]
    reaching: Rate
    placing: Rate

    def to_dict(self) -> dict[str, Any]:
        return {
            "reaching": self.reaching.to_dict(),
            "placing": self.placing.to_dict(),
            "episodes": [asdict(e) for e in self.episodes],
        }


def fingers_close_on(world: RobotWorld, object_id: str) -> bool:
    """Both fingers touch the object now while the gripper is told to close."""
    model, data = world.model, world.data
    if data.ctrl[world.gripper_actuator] >= panda.FINGER_OPEN - 1e-4:
        return False
    body = world.object_bodies[object_id]
    fingers = {int(model.body(PREFIX + name).id) for name in panda.FINGER_BODIES}
    touching: set[int] = set()
    for contact in data.contact[: data.ncon]:
        pair = {int(model.geom_bodyid[contact.geom1]), int(model.geom_bodyid[contact.geom2])}
        if body in pair and contact.dist <= 1e-3:
            touching |= pair & fingers
    return touching == fingers


def evaluate(
    policy_dir: str | Path,
    scenes: str | Path,
    out: str | Path,
    settings: EvalSettings | None = None,
    *,
    overwrite: bool = False,
    on_episode: Callable[[EpisodeResult], None] | None = None,
) -> EvalResult:
    """Roll the policy in `policy_dir` out on the scene folders `scenes` names; write out/eval.json and videos."""
    settings = settings or EvalSettings()
    try:
        folders = scene_folders(scenes)
    except EnvError as exc:
        raise PolicyError(str(exc)) from None
    episodes = settings.episodes if settings.episodes is not None else len(folders)
    policy = load_policy(policy_dir)
    out = Path(out)
    results: list[EpisodeResult] = []
    with output_directory(out, overwrite=overwrite) as staging:
        for k in range(episodes):
            video = staging / f"episode_{k}.mp4" if k < settings.videos else None
            result = _episode(policy, folders[k % len(folders)], settings, settings.seed + k, video)
            results.append(result)
            if on_episode is not None:
                on_episode(result)
        evaluation = EvalResult(
            out=out,
            episodes=tuple(results),
            reaching=wilson(sum(r.reached for r in results), len(results)),
            placing=wilson(sum(r.placed for r in results), len(results)),
        )
        record = {
            "policy": str(policy_dir),
            "scenes": str(scenes),
            "settings": asdict(settings),
            "measures": {
                "reaching": "both fingers touch the pick object while the gripper is told to close",
                "placing": "the environment's verifier finds the task done (terminated)",
            },
            **evaluation.to_dict(),
        }
        atomic_write_text(staging / EVAL_RECORD, json.dumps(record, indent=2) + "\n")
    return evaluation


def _episode(policy: Policy, folder: Path, settings: EvalSettings, seed: int, video: Path | None) -> EpisodeResult:
    import torch

    started = time.perf_counter()
    try:
        env = PickPlaceEnv(folder, settings.task, max_steps=settings.max_steps, render_mode="rgb_array")
    except EnvError as exc:
        raise PolicyError(str(exc)) from None
    outcome = _Outcome()
    try:
        torch.manual_seed(seed)
        frames = _rollout(policy, env, settings.max_steps, seed, outcome, filming=video is not None)
        if video is not None:
            write_video(frames, video)  # frames are made as they are written: a long film costs one frame
        else:
            for _ in frames:
                pass
    finally:
        env.close()
    return EpisodeResult(
        scene=str(folder),
        task=env.task.explicit,
        seed=seed,
        reached=outcome.reached_step is not None,
        reached_step=outcome.reached_step,
        placed=outcome.placed,
        steps=outcome.steps,
        seconds=round(time.perf_counter() - started, 2),
        video=video.name if video is not None else None,
    )


@dataclass
class _Outcome:
    reached_step: int | None = None
    placed: bool = False
    steps: int = 0


def _rollout(
    policy: Policy, env: PickPlaceEnv, max_steps: int, seed: int, outcome: _Outcome, *, filming: bool
) -> Iterator[np.ndarray]:
    """Run one episode, filling `outcome`; yields the front camera's frame before every action and after the last
    when filming, else nothing."""
    obs, _ = env.reset(seed=seed)
    policy.reset()
    if filming:
        yield _frame(env)
    for step in range(1, max_steps + 1):
        obs, _, terminated, truncated, _ = env.step(policy.act(obs))
        outcome.steps = step
        if filming:
            yield _frame(env)
        # the step's verifier ran mj_forward: the contacts are the state's now
        if outcome.reached_step is None and fingers_close_on(env.world, env.task.pick):
            outcome.reached_step = step
        if terminated or truncated:
            outcome.placed = bool(terminated)
            return


def _frame(env: PickPlaceEnv) -> np.ndarray:
    frame = env.render()
    if frame is None:  # render_mode is rgb_array: never
        raise PolicyError("the environment did not render")
    return frame
