"""A stand-in for `make_scene` that tests the batch driver in milliseconds instead of seconds per scene.

`stub_scene` is handed to `run_batch(scene_maker=...)` (the seam the driver has for this) or, for the command line,
to `tests.batch.stub_cli`. It is a module-level function, so spawned worker processes and Ray import it by name. It
makes a tiny scene folder at once, and the words of the prompt tell it to misbehave:

* "stuck": hang inside a C call that holds the GIL, as a scene stuck in MuJoCo would: only a kill stops it;
* "dies": kill its own worker process, every time (as the kernel's OOM killer would).

With SECONDS_ENV set (in the environment of a command-line run; spawned workers inherit it) every scene takes that
long, so that a run is still going when a test kills or stops it.

Its record has the fields of a real one (without importing the pipeline: a fresh worker starts in a fraction of a
second), and the same task always gives the same folder, so a resumed run can be compared with an uninterrupted one.
"""

from __future__ import annotations

import ctypes
import json
import os
import signal
import time
from dataclasses import asdict

from physcensis.batch import RECORD, SCENES_DIR, Options, Outcome, Task

STUCK_PID_FILE = "PHYSCENSIS_TEST_STUCK_PID_FILE"  # where a stuck scene writes its worker's pid, if set
STUCK_FOR_S = 120  # far past any timeout used in the tests; a broken kill still ends (and the test fails on time)
SECONDS_ENV = "PHYSCENSIS_TEST_STUB_SECONDS"  # how long each scene takes (default: no time at all)
OBJECTS = 3


def stub_scene(task: Task, options: Options) -> Outcome:
    """A tiny scene folder for `task`, made at once unless SECONDS_ENV is set or its prompt says "stuck" or "dies"."""
    if "dies" in task.prompt:
        os.kill(os.getpid(), signal.SIGKILL)
    if "stuck" in task.prompt:
        _note_stuck_pid()
        ctypes.PyDLL(None).sleep(STUCK_FOR_S)  # C code holding the GIL: no Python-level timeout gets in
    time.sleep(float(os.environ.get(SECONDS_ENV, "0")))
    record = {
        **asdict(task),
        "scene": f"{SCENES_DIR}/{task.key}",
        "agent": options.agent,
        "worker": "stub",
        "ok": True,
        "seconds": 0.0,
        "rounds": 1,
        "exports": named_formats(options),
        "variety": "llm" if options.llm else options.variety,
        "objects": OBJECTS,
        "objects_failed": 0,
        "settle_distance_m": 0.0,
    }
    scene = {"version": "stub", "seed": task.seed, "prompt": task.prompt}
    return Outcome(
        task,
        record,
        {"scene.json": (json.dumps(scene) + "\n").encode(), RECORD: (json.dumps(record, indent=2) + "\n").encode()},
    )


def named_formats(options: Options) -> list[str]:
    """Options.formats for named formats, without importing the export package (seconds in a fresh worker)."""
    assert "all" not in options.exports, "the stub scene maker needs named formats (or none)"
    return sorted(f for f in options.exports if f != "none")


def _note_stuck_pid() -> None:
    path = os.environ.get(STUCK_PID_FILE)
    if path:
        with open(path, "a") as handle:
            handle.write(f"{os.getpid()}\n")
