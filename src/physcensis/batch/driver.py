"""The batch driver: plans the scenes, resumes a stopped run, and is the only writer of the batch folder."""

from __future__ import annotations

import contextlib
import fcntl
import json
import multiprocessing
import os
import shutil
import signal
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, Any

from physcensis.batch.prompts import BatchError, PromptSpec, Task, plan_tasks, read_prompts
from physcensis.batch.runners import check_llm, check_ray, local_outcomes, ray_outcomes
from physcensis.batch.worker import RECORD, SCENES_DIR, Options, Outcome
from physcensis.fileio import atomic_directory, atomic_write_text

MANIFEST = "manifest.jsonl"
FAILURES = "failures.jsonl"
LOCK = ".batch.lock"


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


ProgressCallback = Callable[[Outcome, BatchSummary], None]


def run_batch(prompts: str | Path | Sequence[PromptSpec], out_dir: str | Path, *, per_prompt: int = 1, seed: int = 0,
              workers: int = 1, ray_address: str | None = None, use_ray: bool = False, options: Options | None = None,
              retry_failed: bool = True, on_start: Callable[[int, int], None] | None = None,
              on_outcome: ProgressCallback | None = None) -> BatchSummary:
    """Make every planned scene not already in `out_dir`; returns what was done.

    Scenes go to `out_dir/scenes/<prompt id>_<k>/`, finished ones are listed in `manifest.jsonl`, failures with
    their reason in `failures.jsonl`. Running it again resumes. With `workers` > 1 (local processes) call it
    under `if __name__ == "__main__":`, as for any multiprocessing code.
    """
    specs = read_prompts(prompts) if isinstance(prompts, (str, Path)) else list(prompts)
    options = options or Options()
    if workers < 1:
        raise BatchError("--workers must be at least 1")
    tasks = plan_tasks(specs, per_prompt, seed)
    if not tasks:
        raise BatchError("nothing to make: --per-prompt (or every prompt's count) is 0")
    if workers > 1 and not use_ray and getattr(multiprocessing.current_process(), "_inheriting", False):
        raise BatchError("run_batch with workers > 1 started while a worker process was starting: "
                         "call it under `if __name__ == \"__main__\":`")
    if use_ray:
        check_ray(ray_address)
    check_llm(options, on_ray=use_ray)
    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise BatchError(f"{out}: exists and is not a folder; give --out a folder")
    try:
        with _locked(out), _terminate_as_exit():
            return _run(out, tasks, workers, ray_address if use_ray else None, use_ray, options, retry_failed,
                        on_start, on_outcome)
    except OSError as exc:
        raise BatchError(f"{out}: cannot write the batch folder ({exc.strerror or exc})") from None


def _run(out: Path, tasks: list[Task], workers: int, ray_address: str | None, use_ray: bool, options: Options,
         retry_failed: bool, on_start: Callable[[int, int], None] | None,
         on_outcome: ProgressCallback | None) -> BatchSummary:
    done = _resume(out, tasks, options.agent)
    failed_before = _tidy_failures(out, done)
    skipped = set() if retry_failed else failed_before
    todo = [t for t in tasks if t.key not in done and t.key not in skipped]
    summary = BatchSummary(planned=len(tasks), already_done=len(done))
    if on_start:
        on_start(len(tasks), len(tasks) - len(todo))
    start = time.perf_counter()
    runner = ray_outcomes(todo, options, workers, ray_address) if use_ray else local_outcomes(todo, options, workers)
    with open(out / FAILURES, "a", encoding="utf-8") as failures, \
            open(out / MANIFEST, "a", encoding="utf-8") as manifest:
        for outcome in runner:
            if outcome.ok:
                _write_scene(out, outcome)
                _append(manifest, outcome.record)
                summary.made += 1
                done.add(outcome.task.key)
            else:
                _append(failures, outcome.record)
                summary.failed += 1
                summary.failures.append(outcome.record)
            summary.seconds = time.perf_counter() - start
            if on_outcome:
                on_outcome(outcome, summary)
    summary.seconds = time.perf_counter() - start
    _tidy_failures(out, done)  # scenes that failed before and were made now are no longer failures
    return summary


@contextlib.contextmanager
def _locked(out: Path) -> Iterator[None]:
    """One driver per batch folder (the lock goes with the process, even when it is killed)."""
    out.mkdir(parents=True, exist_ok=True)
    with open(out / LOCK, "w") as handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise BatchError(f"{out}: another batch is writing to this folder") from None
        yield


@contextlib.contextmanager
def _terminate_as_exit() -> Iterator[None]:
    """SIGTERM (what schedulers send) stops the run like Ctrl-C: workers are cancelled, nothing half-written."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def stop(signum: int, frame: object) -> None:
        raise KeyboardInterrupt

    previous = signal.signal(signal.SIGTERM, stop)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def _resume(out: Path, tasks: Sequence[Task], agent: str) -> set[str]:
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
        if record.get("agent", agent) != agent:
            raise BatchError(f"{folder}: was made by {record['agent']}, this run uses {agent}; "
                             "use another --out or the same agent")
        records[folder.name] = record
    order = {t.key: i for i, t in enumerate(tasks)}
    lines = [json.dumps(records[k]) for k in sorted(records, key=lambda k: (order.get(k, len(order)), k))]
    atomic_write_text(out / MANIFEST, "".join(line + "\n" for line in lines))
    return {k for k in records if k in planned}


def _tidy_failures(out: Path, done: set[str]) -> set[str]:
    """Rewrite failures.jsonl with one line per scene that has failed and is not made since (the latest reason);
    returns their keys. Lines cut short by a kill are dropped."""
    path = out / FAILURES
    latest: dict[str, dict[str, Any]] = {}
    if path.is_file():
        for line in path.read_text(encoding="utf-8").splitlines():
            try:
                record = json.loads(line)
                key = record["key"]
            except (json.JSONDecodeError, KeyError, TypeError):
                continue
            if key not in done:
                latest[key] = record
    atomic_write_text(path, "".join(json.dumps(r) + "\n" for r in latest.values()))
    return set(latest)


def _write_scene(out: Path, outcome: Outcome) -> None:
    with atomic_directory(out / SCENES_DIR / outcome.task.key) as staging:
        for name, content in outcome.files.items():
            target = staging / name
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(content)


def _append(handle: IO[str], record: dict[str, Any]) -> None:
    handle.write(json.dumps(record) + "\n")
    handle.flush()
    os.fsync(handle.fileno())
