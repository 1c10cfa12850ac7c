"""The batch driver: plans the scenes, resumes a stopped run, and is the only writer of the batch folder.

A resume reads the folder as untrusted input (it may come from another machine) and reads all of it before writing
anything: at most MAX_SCENE_ENTRIES entries of `scenes/` beyond the planned scenes, each record as `records.py`
reads it, failures.jsonl within MAX_FAILURES_BYTES. A symbolic link in `scenes/` (or `scenes/` itself a link) is
refused: the driver writes none, and one would lead the resume to read, or the run to write, outside the folder.
"""

from __future__ import annotations

import contextlib
import dataclasses
import fcntl
import json
import multiprocessing
import os
import re
import shutil
import signal
import stat
import statistics
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, Any

from physcensis.agent.base import AgentError
from physcensis.batch.prompts import BatchError, PromptSpec, Task, plan_tasks, read_prompts
from physcensis.batch.records import Record, SceneRecord, read_record
from physcensis.batch.runners import check_llm, check_ray, local_outcomes, ray_outcomes
from physcensis.batch.worker import RECORD, SCENES_DIR, STAGES, Options, Outcome, SceneMaker, make_scene
from physcensis.bounded_json import check_values, load_json
from physcensis.errors import PhyscensisError
from physcensis.fileio import BoundError, atomic_directory, atomic_write_text, read_in_folder
from physcensis.redaction import Redactor

MANIFEST = "manifest.jsonl"
FAILURES = "failures.jsonl"
SUMMARY = "summary.json"  # the last run's counts, rate and stage medians
LOCK = ".batch.lock"
MAX_SCENE_ENTRIES = 100_000  # entries of scenes/ a resume looks at, beyond the planned scenes
MAX_FAILURES_BYTES = 64 * 2**20  # failures.jsonl keeps one line (about a kilobyte) per scene still failing
# What atomic_write_text leaves beside the manifest or failures file when a run is killed mid-write:
# `.NAME.RANDOM.tmp`, or `.NAME.PID.RANDOM.tmp`. Only the driver holding the lock writes them, so any is a leftover.
_ATOMIC_LEFTOVER = re.compile(
    rf"\.(?:{re.escape(MANIFEST)}|{re.escape(FAILURES)}|{re.escape(SUMMARY)})\.(?:\d+\.)?[A-Za-z0-9_]+\.tmp"
)
_OPEN_NO_LINKS = os.O_NOFOLLOW | os.O_CLOEXEC | os.O_NONBLOCK  # O_NONBLOCK: a planted FIFO must not hang the run


@dataclass
class BatchSummary:
    planned: int
    already_done: int
    made: int = 0
    failed: int = 0
    seconds: float = 0.0
    failures: list[dict[str, Any]] = field(default_factory=list)
    stage_seconds: dict[str, float] = field(default_factory=dict)  # each stage's median over the scenes made (STAGES)
    # The run's start-up: until each worker had handed in its first scene (it imports the pipeline and loads its
    # models with it), and the scenes made after that: what a long run makes a minute.
    start_up_s: float | None = None
    made_after_start_up: int = 0

    @property
    def scenes_per_minute(self) -> float:
        return 60.0 * self.made / self.seconds if self.seconds > 0 else 0.0

    @property
    def scenes_per_minute_after_start_up(self) -> float | None:
        """Scenes made a minute once every worker has made its first (None until some were made after that)."""
        if self.start_up_s is None or not self.made_after_start_up or self.seconds <= self.start_up_s:
            return None
        return 60.0 * self.made_after_start_up / (self.seconds - self.start_up_s)

    def rate_line(self) -> str:
        """The rate as printed: "24.9 scenes/min", and the rate after the start-up when there is one."""
        after = self.scenes_per_minute_after_start_up
        started = "" if after is None else f"; {after:.1f} after a start-up of {self.start_up_s:.1f} s"
        return f"{self.scenes_per_minute:.1f} scenes/min{started}"

    def stages_line(self) -> str:
        """The stage medians on one line, e.g. "plan 0.21 s, verify 0.30 s, ..." (empty when none was made)."""
        return ", ".join(f"{name} {seconds:.2f} s" for name, seconds in self.stage_seconds.items())

    def to_dict(self) -> dict[str, Any]:
        """What `summary.json` holds: the counts, the rate and the stage medians of the last run."""
        return {
            "planned": self.planned,
            "already_done": self.already_done,
            "made": self.made,
            "failed": self.failed,
            "seconds": round(self.seconds, 3),
            "scenes_per_minute": round(self.scenes_per_minute, 2),
            "start_up_seconds": None if self.start_up_s is None else round(self.start_up_s, 3),
            "scenes_per_minute_after_start_up": _rounded(self.scenes_per_minute_after_start_up),
            "stage_seconds": self.stage_seconds,
        }


def _rounded(value: float | None) -> float | None:
    return None if value is None else round(value, 2)


def median_stages(records: Sequence[dict[str, Any]]) -> dict[str, float]:
    """The median of each stage (in `STAGES` order) over the records that timed it."""
    times: dict[str, list[float]] = {}
    for record in records:
        for name, seconds in (record.get("stage_seconds") or {}).items():
            if isinstance(seconds, (int, float)):
                times.setdefault(name, []).append(float(seconds))
    order = {name: k for k, name in enumerate(STAGES)}
    return {
        name: round(statistics.median(times[name]), 4) for name in sorted(times, key=lambda n: order.get(n, len(order)))
    }


ProgressCallback = Callable[[Outcome, BatchSummary], None]


def run_batch(
    prompts: str | Path | Sequence[PromptSpec],
    out_dir: str | Path,
    *,
    per_prompt: int = 1,
    seed: int = 0,
    workers: int = 1,
    ray_address: str | None = None,
    use_ray: bool = False,
    options: Options | None = None,
    retry_failed: bool = True,
    on_start: Callable[[int, int], None] | None = None,
    on_outcome: ProgressCallback | None = None,
    scene_timeout_s: float | None = None,
    scene_maker: SceneMaker = make_scene,
    overwrite: bool = False,
) -> BatchSummary:
    """Make every planned scene not already in `out_dir`; returns what was done.

    Scenes go to `out_dir/scenes/<prompt id>_<k>/`, finished ones are listed in `manifest.jsonl`, failures with
    their reason in `failures.jsonl`. Running it again resumes. With `workers` > 1 (local processes) call it
    under `if __name__ == "__main__":`, as for any multiprocessing code.

    `scene_timeout_s` (or `options.scene_timeout_s`) stops a scene that runs longer and records it as failed;
    the scenes then run in worker processes even with one worker, so a stuck one can be killed. `scene_maker`
    replaces `make_scene` (a module-level function, as it is sent to worker processes).

    A non-empty `out_dir` that is not a batch folder is refused unless `overwrite`; the batch then adds its own
    entries (scenes/, manifest.jsonl, failures.jsonl) and leaves everything else there alone.
    """
    specs = read_prompts(prompts) if isinstance(prompts, (str, Path)) else list(prompts)
    options = _checked_options(options or Options(), scene_timeout_s)
    if workers < 1:
        raise BatchError("--workers must be at least 1")
    tasks = plan_tasks(specs, per_prompt, seed)
    if not tasks:
        raise BatchError("nothing to make: --per-prompt (or every prompt's count) is 0")
    if workers > 1 and not use_ray and getattr(multiprocessing.current_process(), "_inheriting", False):
        raise BatchError(
            "run_batch with workers > 1 started while a worker process was starting: "
            'call it under `if __name__ == "__main__":`'
        )
    if use_ray:
        check_ray(ray_address)
    check_llm(options, on_ray=use_ray)
    out = Path(out_dir)
    if out.is_symlink():
        raise BatchError(f"{out}: is a symbolic link; give a real folder (the link is left alone)")
    if out.exists() and not out.is_dir():
        raise BatchError(f"{out}: exists and is not a folder; give --out a folder")
    if out.is_dir() and not overwrite and not _is_batch_folder(out):
        raise BatchError(
            f"{out}: is not empty and not a batch folder; give an empty or new folder, or --overwrite "
            "to add the batch's scenes/, manifest.jsonl and failures.jsonl beside what is there"
        )
    if out.is_dir():
        _refuse_links(out)  # before the lock is made: a refused folder is left as it was
    try:
        with _locked(out), _terminate_as_exit():
            _refuse_links(out)
            return _run(
                out,
                tasks,
                workers,
                ray_address if use_ray else None,
                use_ray,
                options,
                retry_failed,
                on_start,
                on_outcome,
                scene_maker,
            )
    except OSError as exc:
        raise BatchError(f"{out}: cannot write the batch folder ({exc.strerror or exc})") from None


def _is_batch_folder(out: Path) -> bool:
    """Empty, or made by `physcensis batch` (its manifest or scenes folder is there; anything else may be too)."""
    entries = {e.name for e in out.iterdir()}
    return not entries or bool(entries & {MANIFEST, FAILURES, SCENES_DIR, LOCK})


def _checked_options(options: Options, scene_timeout_s: float | None) -> Options:
    """Refuse, before anything runs, settings every scene would fail on."""
    if scene_timeout_s is not None:
        options = dataclasses.replace(options, scene_timeout_s=scene_timeout_s)
    if options.scene_timeout_s is not None:
        # Imported only here: it brings the OpenAI client (a second of the driver's start), which neither the driver
        # nor its workers need otherwise.
        from physcensis.llm.client import positive_seconds

        try:
            positive_seconds(options.scene_timeout_s, "--scene-timeout")
        except (AgentError, PhyscensisError) as exc:
            raise BatchError(str(exc)) from None
    try:
        options.formats  # noqa: B018 - resolves the formats: unknown or unavailable ones are refused here
    except PhyscensisError as exc:
        raise BatchError(f"--export: {exc}") from None
    return options


def _run(
    out: Path,
    tasks: list[Task],
    workers: int,
    ray_address: str | None,
    use_ray: bool,
    options: Options,
    retry_failed: bool,
    on_start: Callable[[int, int], None] | None,
    on_outcome: ProgressCallback | None,
    maker: SceneMaker,
) -> BatchSummary:
    records = _read_records(out, tasks, options)  # everything is read and checked before anything is written
    failures = _read_failures(out)
    done = _resume(out, tasks, records)
    failed_before = _tidy_failures(out, done, failures)
    skipped = set() if retry_failed else failed_before
    todo = [t for t in tasks if t.key not in done and t.key not in skipped]
    summary = BatchSummary(planned=len(tasks), already_done=len(done))
    if on_start:
        on_start(len(tasks), len(tasks) - len(todo))
    start = time.perf_counter()
    runner = (
        ray_outcomes(todo, options, workers, ray_address, maker)
        if use_ray
        else local_outcomes(todo, options, workers, maker)
    )
    redactor = options.redactor()
    made: list[dict[str, Any]] = []
    handed_in = 0  # outcomes so far: the start-up ends with the one that makes each worker's first
    with _open_append(out / FAILURES) as failures_file, _open_append(out / MANIFEST) as manifest:
        for outcome in runner:
            _redact(outcome, redactor)
            handed_in += 1
            if handed_in == min(workers, len(todo)):
                summary.start_up_s = time.perf_counter() - start
            if outcome.ok:
                _write_scene(out, outcome)
                _append(manifest, outcome.record)
                summary.made += 1
                if handed_in > workers:
                    summary.made_after_start_up += 1
                made.append(outcome.record)
                done.add(outcome.task.key)
            else:
                _append(failures_file, outcome.record)
                failures[outcome.task.key] = outcome.record
                summary.failed += 1
                summary.failures.append(outcome.record)
            summary.seconds = time.perf_counter() - start
            if on_outcome:
                on_outcome(outcome, summary)
    summary.seconds = time.perf_counter() - start
    summary.stage_seconds = median_stages(made)
    _tidy_failures(out, done, failures)  # scenes that failed before and were made now are no longer failures
    atomic_write_text(out / SUMMARY, json.dumps(summary.to_dict(), indent=2) + "\n")
    return summary


def _redact(outcome: Outcome, redactor: Redactor) -> None:
    """The record as written to the manifest, failures and batch.json, and as shown: without credentials."""
    outcome.record = redactor.data(outcome.record)
    if outcome.ok:
        outcome.files[RECORD] = (json.dumps(outcome.record, indent=2) + "\n").encode()


@contextlib.contextmanager
def _locked(out: Path) -> Iterator[None]:
    """One driver per batch folder (the lock goes with the process, even when it is killed). The lock file is
    never followed if it is a link, nor truncated: a planted link cannot make the run touch another file."""
    out.mkdir(parents=True, exist_ok=True)
    path = out / LOCK
    try:
        fd = os.open(path, os.O_RDWR | os.O_CREAT | _OPEN_NO_LINKS, 0o644)
    except OSError as exc:
        if path.is_symlink():
            raise BatchError(f"{path}: is a symbolic link; remove it (the batch lock is not followed)") from None
        raise BatchError(f"{path}: cannot open the batch lock ({exc.strerror or exc})") from None
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise BatchError(f"{path}: is not a regular file; remove it")
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise BatchError(f"{out}: another batch is writing to this folder") from None
        yield
    finally:
        os.close(fd)


def _refuse_links(out: Path) -> None:
    """manifest.jsonl, failures.jsonl and summary.json are the batch's own: never follow a link there to another
    file."""
    for name in (MANIFEST, FAILURES, SUMMARY):
        path = out / name
        if path.is_symlink():
            raise BatchError(f"{path}: is a symbolic link; remove it (the batch writes only its own files)")
        if path.exists() and not path.is_file():
            raise BatchError(f"{path}: is not a regular file; remove it")
    scenes = out / SCENES_DIR
    if scenes.is_symlink():
        raise BatchError(f"{scenes}: is a symbolic link; the batch writes its scenes only into a real folder")
    if scenes.exists() and not scenes.is_dir():
        raise BatchError(f"{scenes}: is not a folder; remove it")


@contextlib.contextmanager
def _open_append(path: Path) -> Iterator[IO[str]]:
    fd = os.open(path, os.O_WRONLY | os.O_APPEND | os.O_CREAT | _OPEN_NO_LINKS, 0o666)
    with os.fdopen(fd, "a", encoding="utf-8") as handle:
        yield handle


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


def _clear_leftovers(out: Path) -> None:
    """What a killed run left half-written: staging and replaced scene folders, temporary manifest files."""
    scenes = out / SCENES_DIR
    for leftover in scenes.glob(".*"):
        if leftover.name.endswith((".partial", ".old")) and leftover.is_dir() and not leftover.is_symlink():
            shutil.rmtree(leftover, ignore_errors=True)
    for leftover in out.glob(".*.tmp"):
        if _ATOMIC_LEFTOVER.fullmatch(leftover.name) and leftover.is_file() and not leftover.is_symlink():
            leftover.unlink(missing_ok=True)


def _read_records(out: Path, tasks: Sequence[Task], options: Options) -> dict[str, Record]:
    """The record of every finished scene folder, checked against this run's plan (the same prompt, seed, support,
    agent, variety and formats); a record that is refused or was made otherwise stops the run."""
    planned = {t.key: t for t in tasks}
    records: dict[str, Record] = {}
    for name in _scene_names(out / SCENES_DIR, MAX_SCENE_ENTRIES + len(tasks)):
        record = read_record(out, name)
        if record is None:
            continue  # not a finished scene of a batch: made again if planned, else left alone
        task = planned.get(name)
        if task is not None:
            _check_made_alike(out / SCENES_DIR / name, record.fields, task, options)
        records[name] = record  # one made by a run with more scenes per prompt is still listed
    return records


def _scene_names(scenes: Path, limit: int) -> list[str]:
    """The folders in `scenes/` (hidden ones are a killed run's staging, cleared later), sorted; a link is refused,
    and so are more than `limit` entries."""
    if not scenes.is_dir():
        return []
    names = []
    with os.scandir(scenes) as entries:
        for count, entry in enumerate(entries, start=1):
            if count > limit:
                raise BatchError(f"{scenes}: holds more than {limit:,} entries; a resume reads no more")
            if entry.name.startswith("."):
                continue
            if entry.is_symlink():
                raise BatchError(f"{entry.path}: is a symbolic link; a resume follows no link (remove it)")
            if entry.is_dir(follow_symlinks=False):
                names.append(entry.name)
    return sorted(names)


def _check_made_alike(folder: Path, record: SceneRecord, task: Task, options: Options) -> None:
    agent = options.agent
    variety = options.variety
    if (record.prompt, record.seed, record.support) != (task.prompt, task.seed, task.support):
        raise BatchError(
            f"{folder}: was made with another prompt, seed or support than this run plans "
            f"(seed {record.seed} vs {task.seed}); use another --out or the same settings"
        )
    if record.agent is not None and record.agent != agent:
        raise BatchError(
            f"{folder}: was made by {record.agent}, this run uses {agent}; use another --out or the same agent"
        )
    if record.variety is not None and record.variety != variety:
        raise BatchError(
            f"{folder}: was made with --variety {record.variety}, this run asks for --variety {variety}; "
            "use another --out or the same --variety"
        )
    formats = options.formats
    made_with = record.exports if record.exports is not None else Options().formats  # older records: the default
    if sorted(made_with) != formats:
        raise BatchError(
            f"{folder}: was made with --export {_formats_text(made_with)}, this run asks for "
            f"--export {_formats_text(formats)}; use another --out or the same --export"
        )


def _resume(out: Path, tasks: Sequence[Task], records: dict[str, Record]) -> set[str]:
    """Clear what a killed run left half-done and rebuild the manifest from the finished folders' records."""
    (out / SCENES_DIR).mkdir(parents=True, exist_ok=True)
    _clear_leftovers(out)
    order = {t.key: i for i, t in enumerate(tasks)}
    lines = [json.dumps(records[k].data) for k in sorted(records, key=lambda k: (order.get(k, len(order)), k))]
    atomic_write_text(out / MANIFEST, "".join(line + "\n" for line in lines))
    return {k for k in records if k in order}


def _formats_text(formats: Any) -> str:
    if not isinstance(formats, list) or not all(isinstance(f, str) for f in formats):
        return repr(formats)
    return ",".join(formats) or "none"


def _read_failures(out: Path) -> dict[str, dict[str, Any]]:
    """The latest failure of each scene in failures.jsonl; lines cut short by a kill (or not a failure) are dropped."""
    if not (out / FAILURES).is_file():
        return {}
    try:
        text = read_in_folder(out, FAILURES, MAX_FAILURES_BYTES, str(out / FAILURES)).decode("utf-8", "replace")
        check_values(text)  # all the lines together: what they hold is kept
    except BoundError as exc:
        raise BatchError(f"{exc}; remove it or use another --out") from None
    latest: dict[str, dict[str, Any]] = {}
    for line in text.splitlines():
        try:
            record = load_json(line)
        except ValueError:  # BoundError (nested too deeply) is one too
            continue
        if isinstance(record, dict) and isinstance(record.get("key"), str):
            latest[record["key"]] = record
    return latest


def _tidy_failures(out: Path, done: set[str], latest: dict[str, dict[str, Any]]) -> set[str]:
    """Rewrite failures.jsonl with one line per scene that has failed and is not made since (the latest reason);
    returns their keys."""
    kept = {key: record for key, record in latest.items() if key not in done}
    atomic_write_text(out / FAILURES, "".join(json.dumps(r) + "\n" for r in kept.values()))
    return set(kept)


def _write_scene(out: Path, outcome: Outcome) -> None:
    """The scene folder, published whole; its files are on disk before it is, so that even a power cut leaves no
    record half-written (a resume refuses one that is)."""
    with atomic_directory(out / SCENES_DIR / outcome.task.key) as staging:
        for name, content in outcome.files.items():
            target = staging / name
            target.parent.mkdir(parents=True, exist_ok=True)
            with target.open("wb") as handle:
                handle.write(content)
                handle.flush()
                os.fsync(handle.fileno())


def _append(handle: IO[str], record: dict[str, Any]) -> None:
    handle.write(json.dumps(record) + "\n")
    handle.flush()
    os.fsync(handle.fileno())
