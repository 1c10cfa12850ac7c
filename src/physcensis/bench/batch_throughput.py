"""Throughput of `physcensis batch`: scenes per minute for the dining prompt with 1 and 2 local workers.

Wall time of the whole run (worker start-up included) with the default exports, as a user sees it, and with 2 workers
and `--export none` (the scenes alone: what issue 39 measured), for 16 scenes and for a longer run; each run also
keeps the rate after its start-up (every worker's first scene, when it imports the pipeline and loads its models)
and its stage medians (`BatchSummary`).
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

from physcensis.batch import Options, PromptSpec, run_batch

PROMPT = "a dining table set up for four people"
SCENES = 16
RUNS = ((1, "all", SCENES), (2, "all", SCENES), (2, "none", SCENES), (2, "none", 4 * SCENES))  # workers, --export, n


def run(scenes: int = SCENES, runs: tuple[tuple[int, str, int], ...] = RUNS) -> dict[str, Any]:
    """Each run of `runs`; `scenes` scales their counts (16, the default, runs them as written)."""
    rows = []
    for workers, exports, count in runs:
        count = max(workers + 1, count * scenes // SCENES)
        with tempfile.TemporaryDirectory(prefix="physcensis-bench-batch-") as tmp:
            summary = run_batch(
                [PromptSpec("dining", PROMPT, "table:1.2x0.8")],
                Path(tmp),
                per_prompt=count,
                workers=workers,
                options=Options(exports=(exports,)),
            )
        written = summary.to_dict()  # what summary.json says of the run
        rows.append(
            {
                "workers": workers,
                "exports": exports,
                "scenes": count,
                "scenes_per_min": round(summary.scenes_per_minute, 2),
                "seconds": round(summary.seconds, 2),
                "start_up_s": written["start_up_seconds"],
                "scenes_per_min_after_start_up": written["scenes_per_minute_after_start_up"],
                "failures": summary.failed,
                "stage_seconds": summary.stage_seconds,
            }
        )
    return {"prompt": PROMPT, "scenes": scenes, "runs": rows}
