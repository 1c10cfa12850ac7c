"""The whole loop against a real HTTP server speaking the OpenAI chat API (real `openai` client)."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from physcensis.agent.llm import LLMAgent
from physcensis.agent.loop import generate_scene
from physcensis.api import Generated, write_generated
from physcensis.scene import Support

from .fake_server import MUG_AND_BOOK, FakeOpenAI

pytestmark = pytest.mark.physics
SUPPORT = Support(kind="table", size=(0.6, 0.6))

BAD_GRAMMAR = """Sure, here is the scene:
```json
[
  ["mug_0", "a white coffee mug"]
  ["mug_0", "PLACE-ON-BAS", "root", {"x": 0.0, "y": 0.0}],
  ["book_0", "PLACE-ON", "root", {}],
]
```"""
OVERFULL = json.dumps(
    [
        ["mug_0", "a white coffee mug"],
        ["mug_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["mug_0", "FACING-FRONT", "root", {}],
    ]
    + [
        e
        for i in range(8)
        for e in (
            [f"pot_{i}", "a large stainless steel cooking pot"],
            [f"pot_{i}", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
            [f"pot_{i}", "FACING-FRONT", "root", {}],
        )
    ]
)
VALID = MUG_AND_BOOK


@pytest.mark.slow
@pytest.mark.long
def test_loop_recovers_from_grammar_then_solver_failures(
    fake_openai: Callable[..., FakeOpenAI], tmp_path: Path
) -> None:
    server = fake_openai(BAD_GRAMMAR, OVERFULL, VALID)
    agent = LLMAgent("test-model", base_url=server.base_url, backoff_s=0.01, hint="off")
    result = generate_scene("a mug and a book on a small table", agent, support=SUPPORT, seed=0, retries=3)
    assert result.ok and result.solution is not None
    assert {o.id for o in result.solution.scene.placed} == {"mug_0", "book_0"}
    assert [row["feedback_kind"] for row in result.transcript] == ["grammar", "solver", "success"]
    requests = server.messages
    assert len(requests) == 3
    second_user = requests[1][-1]["content"]
    assert "PLACE-ON-BAS" in second_user and "PLACE-ON-BASE" in second_user  # unknown name and the fix
    assert "PLACE-ON cannot target root" in second_user
    third_user = requests[2][-1]["content"]
    assert "pot_" in third_user and "could not be placed" in third_user  # the solver names the failed objects
    assert requests[2][-2]["role"] == "assistant" and requests[2][-2]["content"] == OVERFULL
    out = write_generated(Generated(result, "a mug and a book", SUPPORT), tmp_path / "scene", exports=("mjcf",))
    rows = [json.loads(line) for line in (out / "transcript.jsonl").read_text().splitlines()]
    assert [r["feedback_kind"] for r in rows] == ["grammar", "solver", "success"]
    assert "sk-test" not in (out / "transcript.jsonl").read_text()
    assert {"scene.json", "report.json", "render.png", "mjcf", "transcript.jsonl"} <= {p.name for p in out.iterdir()}


def test_unparsable_replies_become_grammar_feedback_not_a_crash(fake_openai: Callable[..., FakeOpenAI]) -> None:
    server = fake_openai("I cannot help with that.", "still no list", repeat_last=True)
    agent = LLMAgent("test-model", base_url=server.base_url, backoff_s=0.01, hint="off")
    result = generate_scene("a mug", agent, support=SUPPORT, retries=1)
    assert not result.ok
    assert all(row["feedback_kind"] == "grammar" for row in result.transcript)
    assert "could not be read as a program" in server.messages[1][-1]["content"]


def test_enrichment_rounds_ask_for_more_objects(fake_openai: Callable[..., FakeOpenAI]) -> None:
    bigger: list[Any] = json.loads(VALID) + [["apple_0", "a red apple"], ["apple_0", "PLACE-ANYWHERE", "root", {}]]
    server = fake_openai(VALID, json.dumps(bigger))
    agent = LLMAgent("test-model", base_url=server.base_url, backoff_s=0.01, hint="off")
    result = generate_scene("a mug and a book", agent, support=SUPPORT, rounds=2)
    assert result.ok and result.solution is not None and len(result.solution.scene.placed) == 3
    enrich_request = server.messages[1][-1]["content"]
    assert "empty region" in enrich_request and "Add more objects" in enrich_request


def test_a_refused_request_counts_no_tokens_but_an_unreported_count_is_unknown() -> None:
    from physcensis.agent.loop import _summed_usage

    answered = {"usage": {"prompt_tokens": 10, "completion_tokens": 5, "total_tokens": 15}, "error": None}
    refused = {"usage": None, "error": "HTTP 500: json_schema"}
    assert _summed_usage([refused, answered, answered]) == {
        "prompt_tokens": 20,
        "completion_tokens": 10,
        "total_tokens": 30,
    }
    silent = {"usage": {"prompt_tokens": 7, "completion_tokens": None, "total_tokens": None}, "error": None}
    assert _summed_usage([answered, silent]) == {"prompt_tokens": 17, "completion_tokens": None, "total_tokens": None}
    assert _summed_usage([refused]) is None


class _SlowAgent:
    """Writes one program whose mug sticks off the table, and takes longer than the run's time budget to do it."""

    name = "slow"

    def __init__(self, program: str, seconds: float) -> None:
        self.program, self.seconds, self.proposals = program, seconds, 0

    def propose(self, context: Any) -> str:
        import time

        self.proposals += 1
        time.sleep(self.seconds)
        return self.program


@pytest.mark.slow
@pytest.mark.long
def test_when_the_budget_ends_the_run_the_loop_frees_what_failed_once() -> None:
    """The agent had no round left to fix what failed (six pots and a mug all asked for the middle of a small
    table): the loop frees the failing objects itself, once, recorded as its own round, without asking the agent
    again; the kept scene is the one with more objects placed."""
    crowded = json.dumps(
        [
            ["mug_0", "a white coffee mug"],
            ["mug_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
            ["mug_0", "FACING-FRONT", "root", {}],
        ]
        + [
            e
            for i in range(6)
            for e in (
                [f"pot_{i}", "a large stainless steel cooking pot"],
                [f"pot_{i}", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
                [f"pot_{i}", "FACING-FRONT", "root", {}],
            )
        ]
    )
    agent = _SlowAgent(crowded, seconds=0.5)
    result = generate_scene("a mug and pots", agent, support=SUPPORT, time_budget_s=0.3)
    assert agent.proposals == 1 and result.stop_reason == "time-budget"
    rounds = [row for row in result.transcript if "program" in row]
    assert [row["agent"] for row in rounds] == ["slow", "loop-repair"]
    assert rounds[0]["feedback_kind"] == "solver" and "5 object(s) could not be placed" in rounds[0]["feedback"]
    assert "PLACE-ANYWHERE" in rounds[1]["program"]  # what failed is placed anywhere with room
    assert result.solution is not None
    assert len(result.solution.scene.placed) >= 4  # the agent's own program placed 2 of 7
