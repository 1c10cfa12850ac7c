from __future__ import annotations

import os
from pathlib import Path

import pytest

os.environ.setdefault("MUJOCO_GL", "egl")

REPO = Path(__file__).resolve().parents[1]
EXAMPLES = REPO / "src" / "physcensis" / "examples"
SHARED_PROGRAMS = REPO.parent / "shared" / "bench" / "programs"


@pytest.fixture
def examples_dir() -> Path:
    return EXAMPLES
