from __future__ import annotations

import os
import tempfile
from pathlib import Path

import pytest
from hypothesis import settings

os.environ.setdefault("MUJOCO_GL", "egl")
# The suite never reads the developer's own asset libraries or config file (tests that need them set their own).
os.environ.pop("PHYSCENSIS_LIBRARY", None)
# `assets import` writes to the config file: a temporary one (and each test its own, below).
os.environ["PHYSCENSIS_CONFIG"] = os.path.join(tempfile.mkdtemp(prefix="physcensis-test-config-"), "config.yaml")

# Property tests that do not fix their own number of examples run Hypothesis's default 100 in `make test`;
# HYPOTHESIS_PROFILE=thorough runs ten times as many (without it, Hypothesis picks its own default or CI profile).
# `make test` is repeatable: the same examples every run (CI cannot fail on an example no one has seen);
# HYPOTHESIS_PROFILE=thorough searches afresh with many more.
settings.register_profile("repeatable", derandomize=True, database=None)
settings.register_profile("thorough", max_examples=1000)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repeatable"))

REPO = Path(__file__).resolve().parents[1]
EXAMPLES = REPO / "src" / "physcensis" / "examples"
# The shared benchmark material, when it is checked out beside the repository: the package bundles copies of its
# programs (examples/) and prompt suite (bench/prompts.jsonl), and tests compare them with it when it is there.
SHARED_BENCH = REPO.parent / "shared" / "bench"
SHARED_PROGRAMS = SHARED_BENCH / "programs"
SHARED_PROMPTS = SHARED_BENCH / "prompts.jsonl"


@pytest.hookimpl(tryfirst=True)  # before pytest-xdist starts its workers: they find a full cache
def pytest_sessionstart(session: pytest.Session) -> None:
    """A whole-suite run first builds the built-in assets missing from the asset cache, on as many processes as the
    run has workers: a cold cache (a fresh machine, CI) is then built once, in parallel, instead of by whichever
    tests come first, serially and on several workers at once."""
    config = session.config
    if hasattr(config, "workerinput") or config.args_source != pytest.Config.ArgsSource.TESTPATHS:
        return  # an xdist worker, or a run of chosen tests: they build what they use
    from physcensis.assets.catalogue import warm_builtin_cache

    workers = getattr(config.option, "numprocesses", None)
    warm_builtin_cache(workers=workers if isinstance(workers, int) and workers > 0 else os.cpu_count() or 1)


@pytest.fixture
def examples_dir() -> Path:
    return EXAMPLES


@pytest.fixture(autouse=True)
def _own_config_file(tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each test has its own (absent) user config file: a library one test imports is not used by the next."""
    monkeypatch.setenv("PHYSCENSIS_CONFIG", str(tmp_path_factory.mktemp("config") / "config.yaml"))
