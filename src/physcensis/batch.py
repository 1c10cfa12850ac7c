"""Many scenes: a prompt file times N seeds, on local worker processes or a Ray cluster.

Layout of a batch folder:

    DIR/scenes/<prompt id>_<k>/   one finished scene each (scene.json, report.json, exports, batch.json)
    DIR/manifest.jsonl            one line per finished scene, with its metrics
    DIR/failures.jsonl            one line per scene that could not be made, with the reason

Workers only compute: each returns its scene folder as bytes and the driver writes it
atomically (a killed run leaves no half-written folder) before adding the manifest
line.  Re-running the same command resumes: finished folders are kept, the manifest
is rebuilt from them (so no line is ever duplicated) and only the rest is made.
Workers need no shared file system, which is what lets the same tasks run on Ray.
"""

from __future__ import annotations

import concurrent.futures as futures
import json
import multiprocessing
import os
import re
import shutil
import socket
import tempfile
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from physcensis.errors import PhyscensisError
from physcensis.fileio import atomic_directory, atomic_write_text
from physcensis.scene import Support

SCENES_DIR = "scenes"
MANIFEST = "manifest.jsonl"
FAILURES = "failures.jsonl"
RECORD = "batch.json"  # inside each scene folder: the manifest line of that scene
DEFAULT_SUPPORT = "table:1.2x0.8"
MAX_SETTLE_M = 0.01  # a scene whose objects still move this much after settling is not a valid scene


class BatchError(PhyscensisError):
    """A prompt file or batch folder that cannot be used, named with the line or folder at fault."""


@dataclass(frozen=True)
class PromptSpec:
    id: str
    prompt: str
    support: str = DEFAULT_SUPPORT
    count: int | None = None  # scenes for this prompt (default: --per-prompt)


@dataclass(frozen=True)
class Task:
    key: str  # the scene's folder name
    prompt_id: str
    prompt: str
    support: str
    seed: int


@dataclass(frozen=True)
class Options:
    """What every task of a run shares (plain data: it travels to worker processes and Ray)."""

    exports: tuple[str, ...] = ("all",)
    llm: str | None = None
    base_url: str | None = None
    rounds: int = 1
    min_objects: int = 0


@dataclass
class Outcome:
    task: Task
    record: dict[str, Any]
    files: dict[str, bytes] = field(default_factory=dict)  # relative path -> content; empty when it failed

    @property
    def ok(self) -> bool:
        return bool(self.files)


# ---------------------------------------------------------------------------- reading prompts and planning


def read_prompts(path: str | Path) -> list[PromptSpec]:
    """A .txt file (one prompt per line, # comments) or .jsonl (objects with "prompt" and optionally "id",
    "support" as "table:1.2x0.8" or {"kind", "size", "height"}, and "count"); the prompt suite reads as is."""
    path = Path(path)
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as exc:
        raise BatchError(f"{path}: cannot read the prompt file ({exc.__class__.__name__}: {exc})") from None
    jsonl = path.suffix.lower() in (".jsonl", ".ndjson")
    specs: list[PromptSpec] = []
    for number, line in enumerate(lines, start=1):
        text = line.strip()
        if not text or text.startswith("#"):
            continue
        where = f"{path}:{number}"
        spec = _json_prompt(text, where, len(specs)) if jsonl else PromptSpec(_slug(text, len(specs)), text)
        _check_support(spec.support, where)
        specs.append(spec)
    if not specs:
        raise BatchError(f"{path}: no prompts in the file")
    seen: set[str] = set()
    for spec in specs:
        if spec.id in seen:
            raise BatchError(f"{path}: prompt id {spec.id!r} is used twice; ids name the scene folders")
        seen.add(spec.id)
    return specs


def _json_prompt(text: str, where: str, index: int) -> PromptSpec:
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise BatchError(f"{where}: not valid JSON ({exc.msg})") from None
    if not isinstance(data, dict) or not isinstance(data.get("prompt"), str) or not data["prompt"].strip():
        raise BatchError(f'{where}: each line must be an object with a "prompt" string')
    prompt = data["prompt"].strip()
    support = data.get("support", DEFAULT_SUPPORT)
    if isinstance(support, dict):
        try:
            support = _support_text(Support.model_validate(support))
        except ValueError as exc:
            raise BatchError(f"{where}: support: {exc.errors()[0]['msg']}") from None  # type: ignore[attr-defined]
    elif not isinstance(support, str):
        raise BatchError(f'{where}: "support" must be a string like "table:1.2x0.8" or an object')
    count = data.get("count")
    if count is not None and (not isinstance(count, int) or isinstance(count, bool) or count < 0):
        raise BatchError(f'{where}: "count" must be a whole number >= 0')
    raw_id = data.get("id")
    if raw_id is not None and (not isinstance(raw_id, str) or not re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9_.-]*", raw_id)):
        raise BatchError(f'{where}: "id" must be letters, digits, "-", "_" or "." (it names folders)')
    return PromptSpec(raw_id or _slug(prompt, index), prompt, support, count)


def _check_support(text: str, where: str) -> None:
    try:
        Support.parse(text)
    except ValueError as exc:
        raise BatchError(f"{where}: {exc}") from None


def _support_text(support: Support) -> str:
    height = "" if support.height is None else f"@{support.height:g}"
    return f"{support.kind}:{support.size[0]:g}x{support.size[1]:g}{height}"


def _slug(prompt: str, index: int) -> str:
    words = re.findall(r"[a-z0-9]+", prompt.lower())[:6]
    return f"{index:03d}-" + "-".join(words or ["prompt"])


def plan_tasks(specs: Sequence[PromptSpec], per_prompt: int, seed: int = 0) -> list[Task]:
    """Every scene of the run, in a fixed order, each with its own seed drawn from (seed, prompt, k)."""
    tasks = []
    for index, spec in enumerate(specs):
        for k in range(per_prompt if spec.count is None else spec.count):
            scene_seed = int(np.random.SeedSequence([seed, index, k]).generate_state(1)[0] % 2**31)
            tasks.append(Task(f"{spec.id}_{k:03d}", spec.id, spec.prompt, spec.support, scene_seed))
    return tasks


# ---------------------------------------------------------------------------- one scene (runs in a worker)


def make_scene(task: Task, options: Options) -> Outcome:
    """Generate one scene and return its folder as bytes, or a failure record with the reason. Never raises."""
    start = time.perf_counter()
    base = {**asdict(task), "scene": f"{SCENES_DIR}/{task.key}", "worker": f"{socket.gethostname()}:{os.getpid()}"}
    try:
        from physcensis.api import generate, write_generated

        generated = generate(task.prompt, support=Support.parse(task.support), seed=task.seed, llm=options.llm,
                             base_url=options.base_url, rounds=options.rounds, min_objects=options.min_objects)
        problem = _invalid(generated)
        if problem:
            return Outcome(task, {**base, "ok": False, "reason": problem, "seconds": _since(start)})
        metrics = generated.solution.scene.metrics  # type: ignore[union-attr]
        record = {**base, "ok": True, "seconds": _since(start), "rounds": generated.result.rounds,
                  "objects": metrics.get("objects_placed"), "objects_failed": metrics.get("objects_failed"),
                  "settle_distance_m": metrics.get("settle_distance_m")}
        with tempfile.TemporaryDirectory(prefix="physcensis-batch-") as tmp:
            folder = Path(tmp) / task.key
            write_generated(generated, folder, exports=options.exports)
            (folder / RECORD).write_text(json.dumps(record, indent=2) + "\n")
            files = {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}
        return Outcome(task, record, files)
    except Exception as exc:  # noqa: BLE001 - one failing scene is recorded, it must not stop the run
        reason = str(exc) if isinstance(exc, PhyscensisError) else f"{exc.__class__.__name__}: {exc}"
        return Outcome(task, {**base, "ok": False, "reason": reason, "seconds": _since(start)})


def _invalid(generated: Any) -> str | None:
    solution = generated.solution
    if solution is None:
        last = generated.transcript[-1] if generated.transcript else {}
        detail = last.get("feedback") or last.get("error") or "no program could be solved"
        lines = [line.strip() for line in str(detail).splitlines() if line.strip()]
        return f"no scene could be generated: {' '.join(lines[:3])[:400]}"
    if not solution.scene.placed:
        return "the scene has no placed objects"
    settle = solution.scene.metrics.get("settle_distance_m")
    if settle is not None and settle > MAX_SETTLE_M:
        return f"the scene does not rest: settle distance {settle * 1000:.1f} mm"
    return None


def _since(start: float) -> float:
    return round(time.perf_counter() - start, 3)


# ---------------------------------------------------------------------------- the driver


@dataclass
class BatchSummary:
    planned: int
    already_done: int
    made: int = 0
    failed: int = 0
    seconds: float = 0.0
    failures: list[dict[str, Any]] = field(default_factory=list)

    @property
    def scenes_per_minute(self) -> float:
        return 60.0 * self.made / self.seconds if self.seconds > 0 else 0.0


ProgressCallback = Callable[[Outcome, "BatchSummary"], None]


def run_batch(prompts: str | Path | Sequence[PromptSpec], out_dir: str | Path, *, per_prompt: int = 1, seed: int = 0,
              workers: int = 1, ray_address: str | None = None, use_ray: bool = False, options: Options = Options(),
              retry_failed: bool = True, on_start: Callable[[int, int], None] | None = None,
              on_outcome: ProgressCallback | None = None) -> BatchSummary:
    """Make every planned scene not already in `out_dir`; returns what was done. See the module docstring."""
    specs = read_prompts(prompts) if isinstance(prompts, (str, Path)) else list(prompts)
    if per_prompt < 0 or workers < 1:
        raise BatchError("--per-prompt must be >= 0 and --workers >= 1")
    out = Path(out_dir)
    tasks = plan_tasks(specs, per_prompt, seed)
    done = _resume(out, tasks)
    failed_before = _recorded_failures(out) if not retry_failed else set()
    todo = [t for t in tasks if t.key not in done and t.key not in failed_before]
    summary = BatchSummary(planned=len(tasks), already_done=len(done))
    if on_start:
        on_start(len(tasks), len(tasks) - len(todo))
    start = time.perf_counter()
    runner = _ray_outcomes(todo, options, workers, ray_address) if use_ray else _local_outcomes(todo, options, workers)
    with open(out / FAILURES, "a", encoding="utf-8") as failures, \
            open(out / MANIFEST, "a", encoding="utf-8") as manifest:
        for outcome in runner:
            if outcome.ok:
                _write_scene(out, outcome)
                _append(manifest, outcome.record)
                summary.made += 1
            else:
                _append(failures, outcome.record)
                summary.failed += 1
                summary.failures.append(outcome.record)
            summary.seconds = time.perf_counter() - start
            if on_outcome:
                on_outcome(outcome, summary)
    summary.seconds = time.perf_counter() - start
    return summary


def _resume(out: Path, tasks: Sequence[Task]) -> set[str]:
    """Clear what a killed run left half-done and rebuild the manifest from the finished folders."""
    scenes = out / SCENES_DIR
    scenes.mkdir(parents=True, exist_ok=True)
    for leftover in scenes.glob(".*"):
        if leftover.name.endswith((".partial", ".old")) and leftover.is_dir():
            shutil.rmtree(leftover, ignore_errors=True)
    planned = {t.key: t for t in tasks}
    records: dict[str, dict[str, Any]] = {}
    for folder in sorted(p for p in scenes.iterdir() if p.is_dir() and not p.name.startswith(".")):
        try:
            record = json.loads((folder / RECORD).read_text())
        except (OSError, json.JSONDecodeError):
            continue  # not a scene of a batch; leave it alone
        task = planned.get(folder.name)
        if task is None:
            records[folder.name] = record  # made by a run with more scenes per prompt: still listed
            continue
        if (record.get("prompt"), record.get("seed"), record.get("support")) != (task.prompt, task.seed, task.support):
            raise BatchError(f"{folder}: was made with another prompt, seed or support than this run plans "
                             f"(seed {record.get('seed')} vs {task.seed}); use another --out or the same settings")
        records[folder.name] = record
    order = {t.key: i for i, t in enumerate(tasks)}
    lines = [json.dumps(records[k]) for k in sorted(records, key=lambda k: (order.get(k, len(order)), k))]
    atomic_write_text(out / MANIFEST, "".join(line + "\n" for line in lines))
    return {k for k in records if k in planned}


def _recorded_failures(out: Path) -> set[str]:
    keys = set()
    path = out / FAILURES
    if path.is_file():
        for line in path.read_text(encoding="utf-8").splitlines():
            try:
                keys.add(json.loads(line)["key"])
            except (json.JSONDecodeError, KeyError, TypeError):
                continue  # a line cut short by a killed run
    return keys


def _write_scene(out: Path, outcome: Outcome) -> None:
    with atomic_directory(out / SCENES_DIR / outcome.task.key) as staging:
        for name, content in outcome.files.items():
            target = staging / name
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(content)


def _append(handle: Any, record: dict[str, Any]) -> None:
    handle.write(json.dumps(record) + "\n")
    handle.flush()
    os.fsync(handle.fileno())


def _local_outcomes(tasks: Sequence[Task], options: Options, workers: int) -> Iterator[Outcome]:
    if workers == 1 or len(tasks) <= 1:
        for task in tasks:
            yield make_scene(task, options)
        return
    # spawn: a fresh interpreter per worker; forking a process that holds an OpenGL context is not safe.
    context = multiprocessing.get_context("spawn")
    with futures.ProcessPoolExecutor(max_workers=workers, mp_context=context) as pool:
        pending = {pool.submit(make_scene, task, options): task for task in tasks}
        for future in futures.as_completed(pending):
            task = pending[future]
            try:
                yield future.result()
            except futures.process.BrokenProcessPool as exc:
                yield Outcome(task, {**asdict(task), "ok": False, "reason": f"the worker process died ({exc})"})


def _check_reachable(address: str, timeout_s: float = 5.0) -> None:
    """Fail fast on an address nobody answers at (Ray itself retries for minutes)."""
    host_port = address.removeprefix("ray://")
    if address == "auto" or ":" not in host_port:
        return
    host, _, port = host_port.rpartition(":")
    try:
        with socket.create_connection((host, int(port)), timeout=timeout_s):
            pass
    except (OSError, ValueError) as exc:
        raise BatchError(f"cannot reach the Ray cluster at {address}: {exc}") from None


def _ray_outcomes(tasks: Sequence[Task], options: Options, workers: int, address: str | None) -> Iterator[Outcome]:
    try:
        import ray
    except ImportError:
        raise BatchError("--ray needs the optional extra: pip install 'physcensis[ray]'") from None
    started_here = not ray.is_initialized()
    if started_here:
        if address:
            _check_reachable(address)
        try:
            if address:
                ray.init(address=address, log_to_driver=False)
            else:
                ray.init(num_cpus=workers, include_dashboard=False, log_to_driver=False)
        except Exception as exc:  # noqa: BLE001 - Ray raises many kinds; the user needs one line
            raise BatchError(f"cannot start or join Ray ({address or 'local'}): {exc}") from None
    try:
        remote = ray.remote(num_cpus=1, max_retries=1)(make_scene)
        # Keep a bounded number of tasks in flight: results carry whole scene folders.
        queue = list(tasks)
        in_flight: dict[Any, Task] = {}
        limit = 2 * max(workers, int(ray.cluster_resources().get("CPU", workers)))
        while queue or in_flight:
            while queue and len(in_flight) < limit:
                task = queue.pop(0)
                in_flight[remote.remote(task, options)] = task
            ready, _ = ray.wait(list(in_flight), num_returns=1)
            task = in_flight.pop(ready[0])
            try:
                yield ray.get(ready[0])
            except Exception as exc:  # noqa: BLE001 - a lost worker or node fails that scene, not the run
                yield Outcome(task, {**asdict(task), "ok": False, "reason": f"the Ray task failed: {exc}"})
    finally:
        if started_here:
            ray.shutdown()
