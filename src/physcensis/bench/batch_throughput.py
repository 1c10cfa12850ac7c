"""Throughput of `physcensis batch`: scenes per minute for the dining prompt with 1 and 2 local workers.

Wall time of the whole run (worker start-up included) with the default exports, as a user sees it, and with 2 workers
and `--export none` (the scenes alone: what issue 39 measured); each run keeps its stage medians (`BatchSummary`).
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

from physcensis.batch import Options, PromptSpec, run_batch

PROMPT = "a dining table set up for four people"
RUNS = ((1, "all"), (2, "all"), (2, "none"))  # (workers, --export)


def run(scenes: int = 16, runs: tuple[tuple[int, str], ...] = RUNS) -> dict[str, Any]:
    rows = []
    for workers, exports in runs:
        with tempfile.TemporaryDirectory(prefix="physcensis-bench-batch-") as tmp:
            summary = run_batch(
                [PromptSpec("dining", PROMPT, "table:1.2x0.8")],
                Path(tmp),
                per_prompt=scenes,
                workers=workers,
                options=Options(exports=(exports,)),
            )
        rows.append(
            {
                "workers": workers,
                "exports": exports,
                "scenes_per_min": round(summary.scenes_per_minute, 2),
                "seconds": round(summary.seconds, 2),
                "failures": summary.failed,
                "stage_seconds": summary.stage_seconds,
            }
        )
    return {"prompt": PROMPT, "scenes": scenes, "runs": rows}
