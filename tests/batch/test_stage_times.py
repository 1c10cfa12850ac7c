"""Each scene of a batch records how long each stage took, and the summary carries their medians (in summary.json
too), so a slower stage shows in the numbers of the next run."""

from __future__ import annotations

import json
import statistics
from pathlib import Path

import pytest

from physcensis.batch import MANIFEST, STAGES, SUMMARY, Options, PromptSpec, run_batch
from physcensis.batch.driver import BatchSummary, median_stages

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
