"""Many scenes: a prompt file times N seeds, on local worker processes or a Ray cluster.

Layout of a batch folder:

    DIR/scenes/<prompt id>_<k>/   one finished scene each (scene.json, report.json, exports, batch.json)
    DIR/manifest.jsonl            one line per finished scene, with its metrics
    DIR/failures.jsonl            one line per scene that could not be made, with the reason
    DIR/summary.json              the last run: scenes made and failed, scenes per minute, each stage's median time

Workers only compute (`worker.py`): each returns its scene folder as bytes and the
driver (`driver.py`) writes it atomically (a killed run leaves no half-written
folder) before adding the manifest line. Re-running the same command resumes:
finished folders are kept, the manifest is rebuilt from them (so no line is ever
duplicated) and only the rest is made. Workers need no shared file system, which is
what lets the same tasks run on Ray (`runners.py`).
"""

from physcensis.batch.driver import FAILURES, MANIFEST, SUMMARY, BatchSummary, run_batch
from physcensis.batch.prompts import BatchError, PromptSpec, Task, plan_tasks, read_prompts
from physcensis.batch.worker import RECORD, SCENES_DIR, STAGES, Options, Outcome, make_scene

__all__ = [
    "FAILURES",
    "MANIFEST",
    "RECORD",
    "SCENES_DIR",
    "STAGES",
    "SUMMARY",
    "BatchError",
    "BatchSummary",
    "Options",
    "Outcome",
    "PromptSpec",
    "Task",
    "make_scene",
    "plan_tasks",
    "read_prompts",
    "run_batch",
]
