"""Each scene of a batch records how long each stage took, and the summary carries their medians (in summary.json
too), so a slower stage shows in the numbers of the next run."""

from __future__ import annotations

import json
import statistics
import time
from pathlib import Path

import pytest

from physcensis.batch import MANIFEST, STAGES, SUMMARY, Options, Outcome, PromptSpec, Task, run_batch
from physcensis.batch.driver import BatchSummary, median_stages
from tests.batch.stub_scenes import stub_scene

NO_EXPORTS = Options(exports=("none",))


def test_stage_medians_are_taken_per_stage_over_the_scenes_that_timed_it() -> None:
    records = [
        {"stage_seconds": {"verify": 0.3, "plan": 0.1, "write": 0.2}},
        {"stage_seconds": {"verify": 0.1, "plan": 0.2, "write": 0.4}},
        {"stage_seconds": {"verify": 0.2, "plan": 0.3}},
        {"reason": "no scene"},  # a record without times (an older batch) counts for nothing
    ]
    medians = median_stages(records)
    assert list(medians) == ["plan", "verify", "write"]  # in the order of STAGES
    assert medians == {"plan": 0.2, "verify": 0.2, "write": pytest.approx(0.3)}
    summary = BatchSummary(planned=3, already_done=0, made=3, seconds=6.0, stage_seconds=medians)
    assert summary.stages_line() == "plan 0.20 s, verify 0.20 s, write 0.30 s"
    assert summary.to_dict()["scenes_per_minute"] == 30.0


def _slow_first(task: Task, options: Options) -> Outcome:
    """A scene that takes 1 s the first time (as a worker's first imports the pipeline), 0.02 s after: far apart
    enough to be told apart on a loaded machine."""
    time.sleep(1.0 if task.key.endswith("_000") else 0.02)
    return stub_scene(task, options)


def test_the_summary_tells_the_start_up_from_the_rate_after_it(tmp_path: Path) -> None:
    specs = [PromptSpec("books", "a stack of 3 books", "table:0.6x0.5")]
    summary = run_batch(specs, tmp_path / "out", per_prompt=6, options=NO_EXPORTS, scene_maker=_slow_first)
    assert summary.made == 6 and summary.made_after_start_up == 5
    assert summary.start_up_s is not None and 1.0 <= summary.start_up_s < summary.seconds
    after = summary.scenes_per_minute_after_start_up
    assert after is not None and after > 2 * summary.scenes_per_minute  # the first scene's 1 s is left out
    assert after == pytest.approx(60 * 5 / (summary.seconds - summary.start_up_s))
    written = json.loads((tmp_path / "out" / SUMMARY).read_text())
    assert written["start_up_seconds"] == pytest.approx(summary.start_up_s, abs=1e-3)
    assert "after a start-up of" in summary.rate_line()


def test_a_batch_of_one_scene_has_no_rate_after_its_start_up() -> None:
    summary = BatchSummary(planned=1, already_done=0, made=1, seconds=3.0, start_up_s=3.0)
    assert summary.scenes_per_minute_after_start_up is None
    assert summary.rate_line() == "20.0 scenes/min"


@pytest.mark.slow
@pytest.mark.physics
def test_a_batch_records_each_scenes_stage_times_and_their_medians(tmp_path: Path) -> None:
    specs = [PromptSpec("books", "a stack of 3 books", "table:0.6x0.5")]
    summary = run_batch(specs, tmp_path / "out", per_prompt=2, options=NO_EXPORTS)
    assert summary.made == 2
    records = [json.loads(line) for line in (tmp_path / "out" / MANIFEST).read_text().splitlines()]
    for record in records:
        stages = record["stage_seconds"]
        assert list(stages) == list(STAGES) and all(v >= 0 for v in stages.values())
        assert stages["verify"] > 0 and stages["settle_distance"] > 0 and stages["render"] > 0
        assert stages["export"] < 0.1  # --export none: nothing is written
    assert list(summary.stage_seconds) == list(STAGES)
    verify = statistics.median(r["stage_seconds"]["verify"] for r in records)
    assert summary.stage_seconds["verify"] == pytest.approx(verify, abs=1e-4)
    assert json.loads((tmp_path / "out" / SUMMARY).read_text()) == summary.to_dict()
    assert "verify" in summary.stages_line()
