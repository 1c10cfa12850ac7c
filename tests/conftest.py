from __future__ import annotations

import os
from pathlib import Path

import pytest

os.environ.setdefault("MUJOCO_GL", "egl")

REPO = Path(__file__).resolve().parents[1]
EXAMPLES = REPO / "src" / "physcensis" / "examples"
# The shared benchmark material, when it is checked out beside the repository: the package bundles copies of its
# programs (examples/) and prompt suite (bench/prompts.jsonl), and tests compare them with it when it is there.
SHARED_BENCH = REPO.parent / "shared" / "bench"
SHARED_PROGRAMS = SHARED_BENCH / "programs"
SHARED_PROMPTS = SHARED_BENCH / "prompts.jsonl"


@pytest.fixture
def examples_dir() -> Path:
    return EXAMPLES
