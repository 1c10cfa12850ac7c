"""One scene of a batch, made where the work runs (a local worker process or a Ray task).

`make_scene` writes the scene folder in a private temporary folder and hands it back
as bytes; it never writes into the batch folder, so workers need no shared disk.
"""

from __future__ import annotations

import ctypes
import json
import os
import shutil
import signal
import socket
import sys
import tempfile
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from physcensis.batch.prompts import Task
from physcensis.errors import PhyscensisError
from physcensis.scene import Support

SCENES_DIR = "scenes"
RECORD = "batch.json"  # inside each scene folder: the manifest line of that scene
MAX_SETTLE_M = 0.01  # a scene whose objects still move this much after settling is not a valid scene
TEMP_PREFIX = "physcensis-batch-"
STALE_TEMP_S = 600.0  # a scene takes seconds; a temporary folder this old whose worker is gone was left by a kill
_PR_SET_PDEATHSIG = 1


@dataclass(frozen=True)
class Options:
    """What every task of a run shares (plain data: it travels to worker processes and Ray)."""

    exports: tuple[str, ...] = ("all",)
    llm: str | None = None
    base_url: str | None = None
    rounds: int = 1
    min_objects: int = 0

    @property
    def agent(self) -> str:
        """Who writes the programs, as recorded with every scene."""
        return f"llm:{self.llm}" if self.llm else "offline-planner"


@dataclass
class Outcome:
    task: Task
    record: dict[str, Any]
    files: dict[str, bytes] = field(default_factory=dict)  # relative path -> content; empty when it failed

    @property
    def ok(self) -> bool:
        return bool(self.files)


def failure(task: Task, reason: str, **extra: Any) -> Outcome:
    return Outcome(task, {**asdict(task), "scene": f"{SCENES_DIR}/{task.key}", "ok": False, "reason": reason,
                          **extra})


def make_scene(task: Task, options: Options) -> Outcome:
    """Generate one scene and return its folder as bytes, or a failure record with the reason. Never raises."""
    _sweep_stale_temp_once()
    start = time.perf_counter()
    worker = f"{socket.gethostname()}:{os.getpid()}"
    try:
        from physcensis.api import generate, write_generated

        generated = generate(task.prompt, support=Support.parse(task.support), seed=task.seed, llm=options.llm,
                             base_url=options.base_url, rounds=options.rounds, min_objects=options.min_objects)
        problem = _invalid(generated)
        if problem:
            return failure(task, problem, worker=worker, seconds=_since(start))
        metrics = generated.solution.scene.metrics  # type: ignore[union-attr]
        record = {**asdict(task), "scene": f"{SCENES_DIR}/{task.key}", "agent": options.agent, "worker": worker,
                  "ok": True, "seconds": _since(start), "rounds": generated.result.rounds,
                  "objects": metrics.get("objects_placed"), "objects_failed": metrics.get("objects_failed"),
                  "settle_distance_m": metrics.get("settle_distance_m")}
        with tempfile.TemporaryDirectory(prefix=f"{TEMP_PREFIX}{os.getpid()}-") as tmp:
            folder = Path(tmp) / task.key
            write_generated(generated, folder, exports=options.exports)
            (folder / RECORD).write_text(json.dumps(record, indent=2) + "\n")
            files = {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}
        return Outcome(task, record, files)
    except Exception as exc:  # noqa: BLE001 - one failing scene is recorded, it must not stop the run
        reason = str(exc) if isinstance(exc, PhyscensisError) else f"{exc.__class__.__name__}: {exc}"
        return failure(task, reason, worker=worker, seconds=_since(start))


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


def init_local_worker() -> None:
    """Local pool workers die with the driver: a killed driver must not leave workers running on."""
    if sys.platform.startswith("linux"):
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        if os.getppid() == 1:  # the driver died before prctl took effect
            os._exit(1)
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the driver's to handle


_swept = False


def _sweep_stale_temp_once() -> None:
    """Remove the temporary folders of workers that were killed mid-scene (their pid no longer runs)."""
    global _swept
    if _swept:
        return
    _swept = True
    for folder in Path(tempfile.gettempdir()).glob(f"{TEMP_PREFIX}*-*"):
        pid = folder.name.removeprefix(TEMP_PREFIX).split("-", 1)[0]
        try:
            old = time.time() - folder.stat().st_mtime > STALE_TEMP_S
        except OSError:
            continue
        if old and pid.isdigit() and int(pid) != os.getpid() and not _alive(int(pid)):
            shutil.rmtree(folder, ignore_errors=True)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True
