"""Throughput of `physcensis batch`: scenes per minute for the dining prompt with 1 and 2 local workers.

Wall time of the whole run (worker start-up included) with the default exports, as a user sees it.
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

from physcensis.batch import PromptSpec, run_batch

PROMPT = "a dining table set up for four people"


def run(scenes: int = 16, workers: tuple[int, ...] = (1, 2)) -> dict[str, Any]:
    runs = []
    for count in workers:
        with tempfile.TemporaryDirectory(prefix="physcensis-bench-batch-") as tmp:
            summary = run_batch(
                [PromptSpec("dining", PROMPT, "table:1.2x0.8")], Path(tmp), per_prompt=scenes, workers=count
            )
        runs.append(
            {
                "workers": count,
                "scenes_per_min": round(summary.scenes_per_minute, 2),
                "seconds": round(summary.seconds, 2),
                "failures": summary.failed,
            }
        )
    return {"prompt": PROMPT, "scenes": scenes, "runs": runs}
