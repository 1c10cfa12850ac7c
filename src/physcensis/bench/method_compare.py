"""Benchmarks `compare` and `compare_crowded`: `eval compare` of every offline method on the public prompt suite, and
on eight of its prompts with supports 0.6 times as long each way (where first programs fail and feedback matters),
one seed; the README shows each method's mean ± std."""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

from physcensis.evaluation.compare import run_compare, summary_record

METHODS = ("ours", "random", "llm-only", "no-feedback", "no-report")
SUITE = Path(__file__).with_name("prompts.jsonl")
CROWDED = Path(__file__).with_name("prompts_crowded.jsonl")


def _compare(prompts: Path, workers: int = 1) -> dict[str, Any]:
    with tempfile.TemporaryDirectory(prefix="physcensis-compare-") as folder:
        rows = run_compare(prompts, Path(folder) / "cmp", list(METHODS), 1, workers=workers)
    return summary_record(rows, list(METHODS))


def run() -> dict[str, Any]:
    return _compare(SUITE)


def run_crowded() -> dict[str, Any]:
    return _compare(CROWDED)
