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
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from multiprocessing.queues import SimpleQueue
from pathlib import Path
from typing import TYPE_CHECKING, Any

from physcensis.batch.prompts import Task
from physcensis.errors import PhyscensisError
from physcensis.redaction import Redactor, url_secrets
from physcensis.scene import Scene, Support
from physcensis.settings import RunSettings

if TYPE_CHECKING:
    from physcensis.agent.parse import Parse
    from physcensis.api import Generated

SCENES_DIR = "scenes"
RECORD = "batch.json"  # inside each scene folder: the manifest line of that scene
STAGES = ("plan", "assets", "spatial", "physical", "verify", "settle_distance", "render", "export", "write")
MAX_SETTLE_M = 0.01  # a scene whose objects still move this much after settling is not a valid scene
TEMP_PREFIX = "physcensis-batch-"
STALE_TEMP_S = 600.0  # a scene takes seconds; a temporary folder this old whose worker is gone was left by a kill
_PR_SET_PDEATHSIG = 1


@dataclass(frozen=True)
class Options:
    """What every task of a run shares (plain data: it travels to worker processes and Ray)."""

    settings: RunSettings = field(default_factory=RunSettings)  # what each scene's run is told, as for `generate`
    exports: tuple[str, ...] = ("all",)
    scene_timeout_s: float | None = None  # a scene still running after this is stopped and recorded as failed
    libraries: tuple[str, ...] = ()  # user asset libraries (absolute folders; on Ray, paths every node can read)

    @classmethod
    def of(
        cls,
        exports: tuple[str, ...] = ("all",),
        scene_timeout_s: float | None = None,
        libraries: tuple[str, ...] = (),
        **run_options: Any,
    ) -> Options:
        """Options with the run's settings given by name, as `generate` takes them: `Options.of(llm="m", rounds=2)`."""
        return cls(RunSettings.from_options(**run_options), exports, scene_timeout_s, libraries)

    @property
    def agent(self) -> str:
        """Who writes the programs, as recorded with every scene."""
        return self.settings.models.agent

    @property
    def llm(self) -> str | None:
        return self.settings.models.llm

    @property
    def variety(self) -> str:
        """The variety recorded with every scene: the offline planner's level, or "llm"."""
        return "llm" if self.llm else self.settings.draws.variety

    @property
    def formats(self) -> list[str]:
        """The export formats each scene folder gets, resolved ("all" is what this installation can write)."""
        from physcensis.export import parse_formats

        return sorted(parse_formats(list(self.exports)))

    def redactor(self) -> Redactor:
        """Removes the API key and the base URL's credentials from anything written or printed."""
        models = self.settings.models
        key = os.environ.get(models.api_key_env) if models.llm or models.vlm else None
        return Redactor([key, *url_secrets(models.base_url), *url_secrets(models.vlm_base_url)])


SceneMaker = Callable[[Task, Options], "Outcome"]


@dataclass
class Outcome:
    task: Task
    record: dict[str, Any]
    files: dict[str, bytes] = field(default_factory=dict)  # relative path -> content; empty when it failed

    @property
    def ok(self) -> bool:
        return bool(self.files)


def failure(task: Task, reason: str, **extra: Any) -> Outcome:
    return Outcome(task, {**asdict(task), "scene": f"{SCENES_DIR}/{task.key}", "ok": False, "reason": reason, **extra})


def timed_out(task: Task, timeout_s: float) -> Outcome:
    return failure(task, f"took longer than the scene timeout of {timeout_s:g} s", seconds=round(timeout_s, 3))


def make_scene(task: Task, options: Options) -> Outcome:
    """Generate one scene and return its folder as bytes, or a failure record with the reason. Never raises."""
    _sweep_stale_temp_once()
    start = time.perf_counter()
    worker = f"{socket.gethostname()}:{os.getpid()}"
    redactor = options.redactor()
    try:
        from physcensis.api import generate, write_generated
        from physcensis.assets.catalogue import use_libraries

        use_libraries(options.libraries)  # loaded once per worker process: the same folders keep the catalogue
        began = time.perf_counter()
        generated = generate(
            task.prompt,
            support=Support.parse(task.support),
            seed=task.seed,
            settings=options.settings,
        )
        generate_s = time.perf_counter() - began
        metrics = _usable_scene(generated).metrics
        record = {
            **asdict(task),
            "scene": f"{SCENES_DIR}/{task.key}",
            "agent": options.agent,
            "worker": worker,
            "ok": True,
            "seconds": _since(start),
            "rounds": generated.result.rounds,
            "exports": options.formats,
            "variety": generated.variety,
            "added": [row["id"] for row in generated.added],
            "objects": metrics.get("objects_placed"),
            "objects_failed": metrics.get("objects_failed"),
            "settle_distance_m": metrics.get("settle_distance_m"),
        }
        record = redactor.data(record)
        with tempfile.TemporaryDirectory(prefix=f"{TEMP_PREFIX}{os.getpid()}-") as tmp:
            folder = Path(tmp) / task.key
            began = time.perf_counter()
            write_generated(generated, folder, exports=options.exports)
            record["stage_seconds"] = stage_seconds(generated, generate_s, time.perf_counter() - began)
            (folder / RECORD).write_text(json.dumps(record, indent=2) + "\n")
            files = {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}
        return Outcome(task, record, files)
    except Exception as exc:  # one failing scene is recorded, it must not stop the run
        reason = str(exc) if isinstance(exc, PhyscensisError) else f"{exc.__class__.__name__}: {exc}"
        return failure(task, redactor.text(reason), worker=worker, seconds=_since(start))


def stage_seconds(generated: Generated, generate_s: float, write_s: float) -> dict[str, float]:
    """How long each stage of one scene took (`STAGES`), from the solve's own timings and the two wall times."""
    timings = generated.solution.timings if generated.solution else {}
    shown = timings.get("render", 0.0) + timings.get("export", 0.0)
    stages = {
        "plan": generate_s - timings.get("total", 0.0),  # the agent: the program, and the solves of earlier rounds
        "assets": timings.get("check", 0.0) + timings.get("assets", 0.0),
        "spatial": timings.get("spatial", 0.0),
        "physical": timings.get("physical", 0.0),
        "verify": timings.get("physics", 0.0),
        "settle_distance": timings.get("settle_distance", 0.0),
        "render": timings.get("render", 0.0),
        "export": timings.get("export", 0.0),
        "write": write_s - shown,  # scene.json, report.json, layout.png and the rest of the folder
    }
    return {name: round(max(0.0, value), 4) for name, value in stages.items()}


def run_task(
    task: Task, options: Options, maker: SceneMaker = make_scene, board: Any = None, parsed: Parse | None = None
) -> Outcome:
    """What a pool worker or Ray task runs: say when the task starts (so the driver can time it), then make it.
    `parsed` is the prompt's parse, made once by the driver (see `Parses`)."""
    if parsed is not None:
        from physcensis.agent.parse import remember

        remember(parsed)
    if _starts is not None:
        _starts.put((task.key, os.getpid()))
    if board is not None:
        board.start.remote(task.key)
    return maker(task, options)


class Parses:
    """The driver's parse of each prompt, made once and handed to the workers with its tasks (`run_task`): the
    driver loads spaCy once, while the workers start, instead of every worker loading it for its first scene. A
    prompt the driver cannot parse goes without (the worker parses it, and says what is wrong)."""

    def __init__(self) -> None:
        self._known: dict[str, Parse | None] = {}

    def of(self, prompt: str) -> Parse | None:
        if prompt not in self._known:
            try:
                from physcensis.agent.parse import parse

                self._known[prompt] = parse(prompt)
            except Exception:  # the worker's own parse reports it with the scene
                self._known[prompt] = None
        return self._known[prompt]


class StartBoard:
    """A Ray actor that notes when each task starts, on its own clock: the driver times tasks on any node."""

    def __init__(self) -> None:
        self._started: dict[str, float] = {}

    def start(self, key: str) -> None:
        self._started[key] = time.monotonic()

    def running_for(self, keys: list[str]) -> dict[str, float]:
        now = time.monotonic()
        return {key: now - self._started[key] for key in keys if key in self._started}


class _Unusable(PhyscensisError):
    """A generated scene that does not go into the batch; the message says why (it becomes the failure reason)."""


def _usable_scene(generated: Generated) -> Scene:
    """The generated scene, or _Unusable when there is none, nothing in it is placed, or it does not rest."""
    solution = generated.solution
    if solution is None:
        transcript = generated.transcript
        last = transcript[-1] if transcript else {}
        detail = last.get("feedback") or last.get("error") or "no program could be solved"
        lines = [line.strip() for line in str(detail).splitlines() if line.strip()]
        raise _Unusable(f"no scene could be generated: {' '.join(lines[:3])[:400]}")
    if not solution.scene.placed:
        lines = [line.strip() for line in solution.feedback().splitlines() if line.strip()]
        raise _Unusable(f"no scene could be generated: no object could be placed: {' '.join(lines[:3])[:400]}")
    settle = solution.scene.metrics.get("settle_distance_m")
    if settle is not None and settle > MAX_SETTLE_M:
        raise _Unusable(f"the scene does not rest: settle distance {settle * 1000:.1f} mm")
    return solution.scene


def _since(start: float) -> float:
    return round(time.perf_counter() - start, 3)


_starts: SimpleQueue | None = None  # in a pool worker under a scene timeout: where task starts are reported


def init_local_worker(starts: SimpleQueue | None = None, import_first: bool = False) -> None:
    """Local pool workers die with the driver: a killed driver must not leave workers running on."""
    global _starts
    if sys.platform.startswith("linux"):
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        if os.getppid() == 1:  # the driver died before prctl took effect
            os._exit(1)
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the driver's to handle
    _starts = starts
    if import_first:
        warm_up()


def warm_up() -> None:
    """Import the pipeline before the first task: a pool's first call to each worker (which starts it, importing
    while the driver parses the prompts), and under a scene timeout the worker's initializer (the timeout must not
    count the start-up)."""
    try:
        import physcensis.api  # noqa: F401
    except Exception:  # the task itself will report what is wrong
        pass


def remove_temp_of(pid: int) -> None:
    """The temporary folders of a local worker that was killed (it cannot clean up after itself)."""
    for folder in Path(tempfile.gettempdir()).glob(f"{TEMP_PREFIX}{pid}-*"):
        shutil.rmtree(folder, ignore_errors=True)


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
