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


# The longest tests (ten seconds and more each), longest first. Under pytest-xdist they start the run, so that no
# worker is left running one of them alone at the end while the others idle: worksteal hands the tests out in
# collection order and steals from the back of a worker's queue. A test renamed here only loses its early start.
LONG_TESTS = (
    "tests/solver/test_physical.py::test_every_object_is_placed_and_the_scene_rests[unstable_cup]",
    "tests/bench/test_prompt_suite.py::test_suite_prompt[unstable-cup]",
    "tests/bench/test_prompt_suite.py::test_own_prompt[a fruit stand with a basket of]",
    "tests/bench/test_prompt_suite.py::test_own_prompt[a craft table with a pen holde]",
    "tests/test_batch.py::test_killed_ray_batch_resumes_to_exactly_the_planned_scenes",
    "tests/test_readme.py::test_python_block_runs[python-1]",
    "tests/solver/test_stability.py::test_a_numeric_target_moves_an_object_from_the_middle_of_its_support_to_its_fragility",
    "tests/test_batch.py::test_a_real_batch_from_the_command_line_makes_resting_scenes_with_their_exports",
    "tests/bench/test_prompt_suite.py::test_own_prompt[a coffee table with a tray hol]",
    "tests/bench/test_prompt_suite.py::test_suite_prompt[picnic]",
    "tests/batch/test_hardening_batch.py::test_a_stuck_ray_task_is_cancelled_and_recorded",
    "tests/bench/test_prompt_suite.py::test_suite_prompt[pen-holder]",
    "tests/bench/test_prompt_suite.py::test_suite_prompt[cluttered-tabletop]",
    "tests/bench/test_prompt_suite.py::test_suite_prompt[fruit-bowl]",
)


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    if not hasattr(config, "workerinput"):
        return  # a run in one process keeps the files' order
    first = {nodeid: rank for rank, nodeid in enumerate(LONG_TESTS)}
    items.sort(key=lambda item: first.get(item.nodeid, len(first)))  # stable: the rest keep their order


@pytest.fixture
def examples_dir() -> Path:
    return EXAMPLES


@pytest.fixture(autouse=True)
def _own_config_file(tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each test has its own (absent) user config file: a library one test imports is not used by the next."""
    monkeypatch.setenv("PHYSCENSIS_CONFIG", str(tmp_path_factory.mktemp("config") / "config.yaml"))
