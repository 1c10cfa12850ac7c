"""Many demonstrations: episodes on one scene folder, or on every scene folder below a folder (in parallel, resumable).

A run writes `demos.hdf5` (robomimic layout: every executed episode, `success` in its attrs), `report.json` (success
rate, the stage and reason of every failed attempt, timings) and, on request, videos of chosen episodes. A batch
keeps one such folder per scene under `scenes/` (a finished scene is never run again) and merges them at the end.
"""

from __future__ import annotations

import functools
import json
import multiprocessing
import os
import statistics
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from physcensis.errors import PhyscensisError
from physcensis.fileio import atomic_write_text, output_directory
from physcensis.robot.episode import EpisodeOptions, Outcome, run_episode
from physcensis.robot.panda import Mount
from physcensis.robot.record import DatasetWriter, Episode, read_episode, replay, replay_frames
from physcensis.robot.tasks import Task
from physcensis.robot.verify import Verdict, verify_vlm
from physcensis.robot.video import write_video
from physcensis.robot.world import RobotWorld, build_world
from physcensis.settings import API_KEY_ENV, DEFAULT_PROVIDER

DATASET = "demos.hdf5"
REPORT = "report.json"
SCENES = "scenes"


class DemoError(PhyscensisError):
    """A demonstration run cannot start (no scene folders, a bad option)."""


@dataclass
class DemoSettings:
    task: str
    episodes: int = 1
    seed: int = 0
    mount: Mount = field(default_factory=Mount)
    images: tuple[int, int] | None = (128, 128)
    videos: tuple[int, ...] = ()  # episode indices to write as MP4
    video_size: tuple[int, int] | None = None  # (height, width) of the MP4s, filmed by replay (None: the frames)
    grasp_candidates: int = 2000
    vlm: str | None = None  # a vision model that must also say yes, or only the primitive verifier
    vlm_base_url: str | None = None
    provider: str = DEFAULT_PROVIDER  # how its server is spoken to (llm/providers.py)
    api_key_env: str = API_KEY_ENV  # where its key is read from


def _env_meta(settings: DemoSettings, scene_dir: Path) -> dict[str, Any]:
    return {
        "env_name": "physcensis_pick_place",
        "type": "mujoco",
        "env_kwargs": {
            "scene": str(scene_dir.resolve()),
            "task": settings.task,
            "robot": "panda",
            "mount": {"edge": settings.mount.edge, "offset": settings.mount.offset},
            "control_freq": 20,
        },
    }


def run_scene(scene_dir: Path, out_dir: Path, settings: DemoSettings, *, overwrite: bool = False) -> dict[str, Any]:
    """`settings.episodes` attempts of the task on one scene folder, written to `out_dir` (atomically, whole).

    `out_dir` is missing, empty or an earlier run's; a folder with other files needs `overwrite` (they are kept);
    a scene folder is refused (its own report.json would be replaced)."""
    refuse_scene_as_out(out_dir)
    world = build_world(scene_dir, settings.mount)
    vlm = _vlm_verifier(settings)
    outcomes: list[Outcome] = []
    with output_directory(out_dir, overwrite=overwrite) as staging:
        with DatasetWriter(staging / DATASET, _env_meta(settings, scene_dir)) as writer:
            for k in range(settings.episodes):
                options = EpisodeOptions(
                    seed=settings.seed + k,
                    images=settings.images,
                    grasp_candidates=settings.grasp_candidates,
                    vlm=vlm,
                )
                outcome = run_episode(world, settings.task, options)
                outcomes.append(outcome)
                if outcome.episode is not None:
                    outcome.episode.attrs.update(
                        scene=scene_reference(scene_dir, out_dir),
                        mount=settings.mount.edge,
                        mount_offset=settings.mount.offset,
                    )
                    writer.add_episode(outcome.episode)
                    if k in settings.videos:
                        _write_episode_video(world, outcome.episode, settings, staging / f"episode_{k}.mp4")
        report = _report(scene_dir, settings, outcomes)
        atomic_write_text(staging / REPORT, json.dumps(report, indent=2) + "\n")
    return report


def _write_episode_video(world: RobotWorld, episode: Episode, settings: DemoSettings, path: Path) -> None:
    """The episode as an MP4: its recorded front frames, or filmed again by replay at `settings.video_size` (a size
    a person can watch; the replay is exact, so it shows the recorded motion)."""
    if settings.video_size is not None:
        write_video(replay_frames(world, episode, settings.video_size), path)
        world.reset()
    elif episode.front_rgb is not None:
        write_video(episode.front_rgb, path)


def _vlm_verifier(settings: DemoSettings) -> Callable[[bytes, bytes, Task], Verdict] | None:
    """The VLM verifier of the settings, on one client for the whole run."""
    if settings.vlm is None:
        return None
    from physcensis.llm.providers import connect

    server = connect(settings.vlm_base_url, settings.api_key_env, settings.provider)
    return functools.partial(verify_vlm, server, settings.vlm)


TIMED_STAGES = ("planning", "execution", "rendering")  # the seconds every report gives, median per episode


def median_seconds(values: Sequence[float]) -> float | None:
    """The median, to the millisecond (None when there are no values)."""
    return round(statistics.median(values), 3) if values else None


def _report(scene_dir: Path, settings: DemoSettings, outcomes: Sequence[Outcome]) -> dict[str, Any]:
    successes = sum(o.success for o in outcomes)
    return {
        "scene": str(scene_dir),
        "task": settings.task,
        "attempted": len(outcomes),
        "succeeded": successes,
        "success_rate": successes / len(outcomes) if outcomes else 0.0,
        "recorded": sum(o.episode is not None for o in outcomes),
        "seconds": {
            stage: median_seconds([o.seconds[stage] for o in outcomes if stage in o.seconds]) for stage in TIMED_STAGES
        },
        "episodes": [o.summary() for o in outcomes],
        "settings": _settings_record(settings),
    }


def scene_folders(root: Path) -> list[Path]:
    """Every scene folder at or below `root` (a folder with scene.json and mjcf/scene.xml), in name order."""
    if (root / "scene.json").is_file():
        return [root]
    found = sorted(_scene_folders_below(root))
    if not found:
        raise DemoError(f"{root}: no scene folder (scene.json with an mjcf/ export) at or below it")
    return found


def _scene_folders_below(root: Path) -> Iterator[Path]:
    """Linked folders are followed (a folder of links is a natural way to choose some scenes); each real folder is
    visited once, so a link to a folder above it ends there."""
    seen: set[str] = set()
    for folder, subfolders, files in os.walk(root, followlinks=True):
        real = os.path.realpath(folder)
        if real in seen:
            subfolders.clear()
            continue
        seen.add(real)
        subfolders.sort()
        if "scene.json" in files and (Path(folder) / "mjcf" / "scene.xml").is_file():
            yield Path(folder)


def _real(path: Path) -> Path:
    return Path(os.path.abspath(path)).resolve()


def refuse_scene_as_out(out_dir: Path) -> None:
    """A scene folder is never an output folder: the run's report.json would replace the scene's."""
    if (out_dir / "scene.json").exists():
        raise DemoError(f"{out_dir}: is a scene folder; give --out a folder of its own for the demonstrations")


def check_batch_out(out_dir: Path, scenes: Sequence[Path]) -> None:
    """Refuse, before any work, a batch output folder that holds what a batch does not write there, or whose
    scenes/ holds one of the scene folders (a scene's run would replace the scene)."""
    refuse_scene_as_out(out_dir)
    if out_dir.is_symlink() or (out_dir.exists() and not out_dir.is_dir()):
        raise DemoError(f"{out_dir}: is not a folder; give --out a new or empty folder, or an earlier run's")
    if out_dir.is_dir():
        foreign = sorted(e.name for e in out_dir.iterdir() if not e.name.startswith(".") and not _batch_entry(e))
        if foreign:
            shown = ", ".join(foreign[:3]) + (" …" if len(foreign) > 3 else "")
            raise DemoError(
                f"{out_dir}: holds files that are not a demonstration batch's ({shown}); give a new or empty folder"
            )
    for scene in scenes:
        if _at_or_below(scene, out_dir / SCENES):
            raise DemoError(f"{out_dir}: its {SCENES}/ holds the scene folder {scene}; give --out another folder")


def _at_or_below(path: Path, folder: Path) -> bool:
    """Where the path is written (a link's own place) or where it leads."""
    for inner, outer in ((Path(os.path.abspath(path)), Path(os.path.abspath(folder))), (_real(path), _real(folder))):
        if inner == outer or outer in inner.parents:
            return True
    return False


def _batch_entry(entry: Path) -> bool:
    if entry.is_symlink():
        return False
    if entry.name == SCENES:
        return entry.is_dir()
    return entry.name in (DATASET, REPORT) and entry.is_file()


def _scene_name(root: Path, scene_dir: Path) -> str:
    relative = scene_dir.relative_to(root) if scene_dir != root else Path(scene_dir.name)
    return "__".join(relative.parts)


def _one(args: tuple[Path, Path, DemoSettings]) -> tuple[str, dict[str, Any] | str]:
    scene_dir, out_dir, settings = args
    try:
        return str(scene_dir), run_scene(scene_dir, out_dir, settings)
    except PhyscensisError as err:
        return str(scene_dir), str(err)


def run_batch(
    root: Path,
    out_dir: Path,
    settings: DemoSettings,
    *,
    workers: int = 1,
    on_scene: Callable[[str, dict[str, Any] | str], None] | None = None,
) -> dict[str, Any]:
    """Every scene folder below `root`, each into out_dir/scenes/NAME (already finished ones are kept), then the
    merged dataset and report at out_dir."""
    scenes = scene_folders(root)
    check_batch_out(out_dir, scenes)
    jobs = [(s, out_dir / SCENES / _scene_name(root, s), settings) for s in scenes]
    pending = [job for job in jobs if not _finished(job[1], settings)]
    (out_dir / SCENES).mkdir(parents=True, exist_ok=True)
    for scene, result in _results(pending, workers):
        if on_scene is not None:
            on_scene(scene, result)
    return merge(out_dir, [job[1] for job in jobs], settings)


def _finished(scene_out: Path, settings: DemoSettings) -> bool:
    """A scene already done with these settings (one done with another task or seed is run again)."""
    report = _scene_report(scene_out)
    return report is not None and report.get("settings") == _settings_record(settings)


def _scene_report(scene_out: Path) -> dict[str, Any] | None:
    """A scene's demonstration report, or None when there is none (or what is there is not one)."""
    try:
        report = json.loads((scene_out / REPORT).read_text())
    except (OSError, ValueError):
        return None
    keys = ("attempted", "succeeded", "episodes", "seconds")
    return report if isinstance(report, dict) and all(k in report for k in keys) else None


def _settings_record(settings: DemoSettings) -> dict[str, Any]:
    return {
        "task": settings.task,
        "episodes": settings.episodes,
        "seed": settings.seed,
        "mount": {"edge": settings.mount.edge, "offset": settings.mount.offset},
        "images": list(settings.images) if settings.images else None,
        "grasp_candidates": settings.grasp_candidates,
        "vlm": settings.vlm,
    }


def _results(jobs: list[tuple[Path, Path, DemoSettings]], workers: int) -> Iterator[tuple[str, dict[str, Any] | str]]:
    if workers <= 1 or len(jobs) <= 1:
        yield from map(_one, jobs)
        return
    context = multiprocessing.get_context("spawn")  # MuJoCo's renderer and OpenMP do not survive a fork
    with context.Pool(workers, initializer=_quiet_threads) as pool:
        yield from pool.imap_unordered(_one, jobs)


def _quiet_threads() -> None:
    os.environ.setdefault("OMP_NUM_THREADS", "1")


def merge(out_dir: Path, scene_outs: Sequence[Path], settings: DemoSettings) -> dict[str, Any]:
    """One dataset and one report over the scenes that finished."""
    import h5py

    read = {d: _scene_report(d) for d in scene_outs}
    reports = [r for r in read.values() if r is not None]
    missing = [str(d) for d, r in read.items() if r is None]
    attempted = sum(r["attempted"] for r in reports)
    succeeded = sum(r["succeeded"] for r in reports)
    reasons: dict[str, int] = {}
    for report in reports:
        for episode in report["episodes"]:
            if not episode["success"]:
                reasons[episode["stage"]] = reasons.get(episode["stage"], 0) + 1
    with DatasetWriter(out_dir / DATASET, {"env_name": "physcensis_pick_place", "task": settings.task}) as writer:
        for scene_out in scene_outs:
            if read[scene_out] is not None and (scene_out / DATASET).is_file():
                with h5py.File(scene_out / DATASET, "r") as source:
                    for name in sorted(source["data"], key=lambda n: int(n.split("_")[-1])):
                        episode = read_episode(scene_out / DATASET, int(name.split("_")[-1]))
                        scene = scene_of(scene_out / DATASET, str(episode.attrs["scene"]))
                        episode.attrs["scene"] = scene_reference(scene, out_dir)  # from the merged dataset's folder
                        writer.add_episode(episode)
    summary = {
        "task": settings.task,
        "scenes": len(reports),
        "scenes_failed": missing,
        "attempted": attempted,
        "succeeded": succeeded,
        "success_rate": succeeded / attempted if attempted else 0.0,
        "failures_by_stage": reasons,
        "seconds": {
            stage: median_seconds([r["seconds"][stage] for r in reports if r["seconds"].get(stage) is not None])
            for stage in TIMED_STAGES
        },
        "per_scene": [{k: r[k] for k in ("scene", "attempted", "succeeded")} for r in reports],
    }
    atomic_write_text(out_dir / REPORT, json.dumps(summary, indent=2) + "\n")
    return summary


def scene_reference(scene_dir: Path, dataset_dir: Path) -> str:
    """The scene folder as an episode records it: relative to the folder of its dataset, so that a dataset copied
    with its scenes (the same layout) replays on another machine; absolute only where no relative path exists."""
    try:
        return Path(os.path.relpath(scene_dir.resolve(), dataset_dir.resolve())).as_posix()
    except ValueError:  # another drive (Windows)
        return str(scene_dir.resolve())


def scene_of(dataset: Path, reference: str) -> Path:
    """The scene folder an episode of `dataset` records: relative to the dataset's folder (absolute in datasets
    written before episodes recorded it so)."""
    path = Path(reference)
    return path if path.is_absolute() else dataset.parent / path


def recheck(dataset: Path) -> dict[str, int]:
    """Replay every episode recorded as successful in a fresh world and verify it again from the file alone."""
    import h5py

    from physcensis.robot import tasks, verify

    with h5py.File(dataset, "r") as handle:
        names = sorted(handle["data"], key=lambda n: int(n.split("_")[-1]))
    checked = confirmed = 0
    worlds: dict[str, Any] = {}
    for name in names:
        episode = read_episode(dataset, int(name.split("_")[-1]))
        if not episode.attrs.get("success"):
            continue
        scene = scene_of(dataset, str(episode.attrs["scene"]))
        mount = Mount(edge=str(episode.attrs["mount"]), offset=float(episode.attrs["mount_offset"]))
        key = f"{scene}|{mount}"
        world = worlds.get(key) or worlds.setdefault(key, build_world(scene, mount))
        world.reset()
        before = world.object_poses()
        final = replay(world, episode)
        task = tasks.parse_task(
            str(episode.attrs["task"]), world.scene, world.base_yaw, base_position=world.base_position.tolist()
        )
        verdict = verify.verify_primitive(world, task, before)
        checked += 1
        confirmed += int(verdict.ok and _same_poses(final, episode))
    return {"checked": checked, "confirmed": confirmed}


def replay_in_env(dataset: Path) -> dict[str, int]:
    """Step every episode recorded as successful through the Gymnasium environment (robot/env.py), from its scene
    folder, task and mount: how many end in the environment's success (its verifier terminates the episode)."""
    import h5py

    from physcensis.robot.env import PickPlaceEnv

    with h5py.File(dataset, "r") as handle:
        names = sorted(handle["data"], key=lambda n: int(n.split("_")[-1]))
    replayed = succeeded = 0
    for name in names:
        episode = read_episode(dataset, int(name.split("_")[-1]))
        if not episode.attrs.get("success"):
            continue
        mount = Mount(edge=str(episode.attrs["mount"]), offset=float(episode.attrs["mount_offset"]))
        env = PickPlaceEnv(scene_of(dataset, str(episode.attrs["scene"])), str(episode.attrs["task"]), mount=mount)
        env.reset(seed=0)
        done = False
        for action in episode.actions:
            _, _, done, _, _ = env.step(action)
            if done:
                break
        env.close()
        replayed += 1
        succeeded += int(done)
    return {"replayed": replayed, "succeeded": succeeded}


def _same_poses(final: dict[str, np.ndarray], episode: Any, tolerance: float = 1e-6) -> bool:
    recorded = episode.final_object_poses()
    return all(np.abs(final[k][:3] - recorded[k][:3]).max() <= tolerance for k in recorded)
