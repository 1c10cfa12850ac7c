"""The offline path stops at the run's bounds: `max_objects` cuts the plan (said in a note), the time budget stops
the solve's search and placements (each object left says why)."""

from __future__ import annotations

import json

import pytest

from physcensis import api
from physcensis.agent.base import AgentContext
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.reading import read_prompt
from physcensis.program import check_program, parse_program
from physcensis.scene import Support
from physcensis.solver.physical import OUT_OF_TIME
from physcensis.solver.pipeline import solve

LONG_PROMPT = " ".join(["a red mug and a plate and"] * 40) + " a fork"  # about 1 KB, 81 things
TABLE = Support(kind="table", size=(1.2, 0.8))


def _objects(program_text: str) -> int:
    entries = json.loads(program_text)
    return sum(len(entry) == 2 for entry in entries)


def test_the_offline_plan_keeps_at_most_max_objects_and_says_so() -> None:
    planner = OfflinePlanner(variety="none")
    text = planner.propose(AgentContext(LONG_PROMPT, TABLE, (), seed=0, max_objects=12))
    assert _objects(text) == 12
    assert check_program(parse_program(text), TABLE, max_objects=12).ok
    assert any("max-objects" in note and "12" in note for note in planner.transcript_notes)


@pytest.mark.slow
@pytest.mark.long
def test_a_run_with_a_small_max_objects_gives_a_scene_not_a_refusal() -> None:
    generated = api.generate(LONG_PROMPT, seed=0, max_objects=10, variety="none")
    assert generated.solution is not None and 0 < len(generated.solution.scene.objects) <= 10
    assert any("max-objects" in row.get("note", "") for row in generated.transcript)


def test_a_solve_past_its_time_limit_tries_nothing_more_and_says_why() -> None:
    planner = OfflinePlanner(variety="none")
    program = json.loads(planner.propose(AgentContext(LONG_PROMPT, TABLE, (), seed=0)))
    solution = solve(program, support=TABLE, seed=0, time_limit_s=0.0)
    assert solution.spatial is not None and "time budget" in solution.spatial.stop_reason
    physical = [o for o in solution.scene.objects if o.placement.predicate != "PLACE-ON-BASE"]
    assert physical and all(o.status == "failed" and o.reason == OUT_OF_TIME for o in physical)


@pytest.mark.slow
@pytest.mark.long
def test_the_time_budget_reaches_into_the_solve() -> None:
    generated = api.generate(LONG_PROMPT, seed=0, time_budget_s=1.0, variety="none")
    assert generated.result.stop_reason == "time-budget"
    first = next(row for row in generated.transcript if row.get("round") == 1 and "feedback" in row)
    assert "time budget ran out before its turn" in first["feedback"]


@pytest.mark.long
def test_a_prompt_of_thousands_of_things_is_read_whole() -> None:
    lexicon = OfflinePlanner().lexicon
    few, many = (read_prompt(" ".join(["a mug and a plate and"] * n), lexicon) for n in (50, 4000))
    assert len(few.mentions) == 100 and len(many.mentions) == 8000
